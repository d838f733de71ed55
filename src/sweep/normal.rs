//! Sweeps for the normal encodings (`wgsl/normal_*.wgsl`): round-trip angular error over a
//! direction set, exhaustive and stratified decoder checks, the precise encoder's optimality,
//! a streaming sweep of all 2^32 oct32 codes, and the Killzone xy-FP16 "myth" numbers.
//! The tests assert on these; `errplot` and `examples/normal_tables.rs` tabulate them.

use crate::harness::{Arg, Gpu, HarnessError};
use crate::normal::{hemioct, oct, xy_fp16, xyz8};
use crate::precision::metrics::{ErrorStats, Mismatches, angle_degrees, widen3};
use crate::wgsl::{NORMAL_HEMIOCT, NORMAL_OCT, NORMAL_XY_FP16, NORMAL_XYZ8};
use glam::Vec3;

/// One encoding: its WGSL functions, its Rust twins and its f64 reference encoder.
#[derive(Clone, Copy)]
pub struct Codec {
    /// Short name for tables (`oct24`, `oct24 fast`, …).
    pub name: &'static str,
    /// Bits of the code.
    pub bits: u32,
    /// The WGSL file holding both functions.
    pub source: &'static str,
    /// WGSL encoder `fn(n: vec3<f32>) -> u32`.
    pub encode: &'static str,
    /// WGSL decoder `fn(p: u32) -> vec3<f32>`.
    pub decode: &'static str,
    /// Rust twin of the encoder.
    pub twin_encode: fn(Vec3) -> u32,
    /// Rust twin of the decoder.
    pub twin_decode: fn(u32) -> Vec3,
    /// The same algorithm in f64 (the survey's, for the octahedral codes).
    pub reference_encode: fn([f64; 3]) -> u32,
    /// The exact direction a code stands for, in f64.
    pub reference_decode: fn(u32) -> [f64; 3],
    /// The targets (mean°, max°) from its float64 reproduction, where it gives them.
    pub target: Option<(f64, f64)>,
}

fn xyfp16_ref_encode(n: [f64; 3]) -> u32 {
    let u = crate::normal::exact::unit(n).unwrap_or([0.0, 0.0, 1.0]);
    let h = |x: f64| u32::from(half::f16::from_f64(x.clamp(-1.0, 1.0)).to_bits());
    h(u[0]) | (h(u[1]) << 16)
}

fn xyfp16_ref_decode(p: u32) -> [f64; 3] {
    let h = |b: u32| f64::from(half::f16::from_bits(b as u16).to_f32());
    let (x, y) = (h(p).clamp(-1.0, 1.0), h(p >> 16).clamp(-1.0, 1.0));
    let (x, y) = (
        if x.is_nan() { 0.0 } else { x },
        if y.is_nan() { 0.0 } else { y },
    );
    crate::normal::exact::unit([x, y, (1.0 - x * x - y * y).max(0.0).sqrt()])
        .unwrap_or([0.0, 0.0, 1.0])
}

macro_rules! oct_refs {
    ($bits:literal, $p:ident, $r:ident, $d:ident) => {
        fn $p(n: [f64; 3]) -> u32 {
            oct::exact::encode_precise(n, $bits)
        }
        fn $r(n: [f64; 3]) -> u32 {
            oct::exact::encode_round(n, $bits)
        }
        fn $d(p: u32) -> [f64; 3] {
            oct::exact::decode(p, $bits)
        }
    };
}
oct_refs!(8, oct16_ref_p, oct16_ref_r, oct16_ref_d);
oct_refs!(12, oct24_ref_p, oct24_ref_r, oct24_ref_d);
oct_refs!(16, oct32_ref_p, oct32_ref_r, oct32_ref_d);

macro_rules! oct_codec {
    ($name:literal, $bits:literal, $enc:ident, $dec:ident, $twin:path, $twin_dec:path, $r:ident, $d:ident, $t:expr) => {
        Codec {
            name: $name,
            bits: 2 * $bits,
            source: NORMAL_OCT,
            encode: stringify!($enc),
            decode: stringify!($dec),
            twin_encode: $twin,
            twin_decode: $twin_dec,
            reference_encode: $r,
            reference_decode: $d,
            target: Some($t),
        }
    };
}

/// Every encoding: xyz8, xy FP16, octahedral 16/24/32 precise and fast, then hemi-octahedral 24
/// precise and fast (errors of the hemisphere-only codes are measured over `z ≥ 0`).
pub const CODECS: [Codec; 10] = [
    Codec {
        name: "xyz8",
        bits: 24,
        source: NORMAL_XYZ8,
        encode: "encode_normal_xyz8",
        decode: "decode_normal_xyz8",
        twin_encode: xyz8::encode_normal_xyz8,
        twin_decode: xyz8::decode_normal_xyz8,
        reference_encode: xyz8::exact::encode,
        reference_decode: xyz8::exact::decode,
        target: Some((0.170, 0.390)),
    },
    Codec {
        name: "xy fp16",
        bits: 32,
        source: NORMAL_XY_FP16,
        encode: "encode_normal_xy_fp16",
        decode: "decode_normal_xy_fp16",
        twin_encode: xy_fp16::encode_normal_xy_fp16,
        twin_decode: xy_fp16::decode_normal_xy_fp16,
        reference_encode: xyfp16_ref_encode,
        reference_decode: xyfp16_ref_decode,
        target: None,
    },
    oct_codec!(
        "oct16",
        8,
        encode_normal_oct16,
        decode_normal_oct16,
        oct::encode_normal_oct16,
        oct::decode_normal_oct16,
        oct16_ref_p,
        oct16_ref_d,
        (0.315, 0.636)
    ),
    oct_codec!(
        "oct16 fast",
        8,
        encode_normal_oct16_fast,
        decode_normal_oct16,
        oct::encode_normal_oct16_fast,
        oct::decode_normal_oct16,
        oct16_ref_r,
        oct16_ref_d,
        (0.337, 0.951)
    ),
    oct_codec!(
        "oct24",
        12,
        encode_normal_oct24,
        decode_normal_oct24,
        oct::encode_normal_oct24,
        oct::decode_normal_oct24,
        oct24_ref_p,
        oct24_ref_d,
        (0.0195, 0.0395)
    ),
    oct_codec!(
        "oct24 fast",
        12,
        encode_normal_oct24_fast,
        decode_normal_oct24,
        oct::encode_normal_oct24_fast,
        oct::decode_normal_oct24,
        oct24_ref_r,
        oct24_ref_d,
        (0.0209, 0.0591)
    ),
    oct_codec!(
        "oct32",
        16,
        encode_normal_oct32,
        decode_normal_oct32,
        oct::encode_normal_oct32,
        oct::decode_normal_oct32,
        oct32_ref_p,
        oct32_ref_d,
        (0.00122, 0.00246)
    ),
    oct_codec!(
        "oct32 fast",
        16,
        encode_normal_oct32_fast,
        decode_normal_oct32,
        oct::encode_normal_oct32_fast,
        oct::decode_normal_oct32,
        oct32_ref_r,
        oct32_ref_d,
        (0.00131, 0.00369)
    ),
    Codec {
        name: "hemioct24",
        bits: 24,
        source: NORMAL_HEMIOCT,
        encode: "encode_normal_hemioct24",
        decode: "decode_normal_hemioct24",
        twin_encode: hemioct::encode_normal_hemioct24,
        twin_decode: hemioct::decode_normal_hemioct24,
        reference_encode: hemioct::exact::encode_precise,
        reference_decode: hemioct::exact::decode,
        target: None,
    },
    Codec {
        name: "hemioct24 fast",
        bits: 24,
        source: NORMAL_HEMIOCT,
        encode: "encode_normal_hemioct24_fast",
        decode: "decode_normal_hemioct24",
        twin_encode: hemioct::encode_normal_hemioct24_fast,
        twin_decode: hemioct::decode_normal_hemioct24,
        reference_encode: hemioct::exact::encode_round,
        reference_decode: hemioct::exact::decode,
        target: None,
    },
];

/// The codec named `name` in [`CODECS`].
pub fn codec(name: &str) -> &'static Codec {
    CODECS
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no codec {name}"))
}

/// `n` spherical-Fibonacci directions (uniform on the sphere): point `i` at
/// `z = 1 − (2i + 1)/n`, azimuth `i·π(3 − √5)`, computed in f64 and rounded to f32.
pub fn fibonacci_directions(n: u32) -> Vec<[f32; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * f64::from(i) + 1.0) / f64::from(n);
            let r = (1.0 - z * z).max(0.0).sqrt();
            let (s, c) = (golden * f64::from(i)).sin_cos();
            [(r * c) as f32, (r * s) as f32, z as f32]
        })
        .collect()
}

/// Adversarial unit directions: the six axes with every sign of zero, the octahedron's folds
/// (`|x| + |y| = 1` at `z = ±0` and `z = ±tiny`), the poles and the equator approached in ULP
/// steps, the body diagonals, and points just either side of the oct code cells' edges.
pub fn adversarial_directions() -> Vec<[f32; 3]> {
    let mut v = Vec::new();
    let zs = [0.0f32, -0.0];
    for a in 0..3 {
        for s in [1.0f32, -1.0] {
            for z1 in zs {
                for z2 in zs {
                    let mut d = [z1, z2, z1];
                    d[(a + 1) % 3] = z2;
                    d[a] = s;
                    v.push(d);
                }
            }
        }
    }
    let tiny = [0.0f32, -0.0, 1e-7, -1e-7, 1e-30, -1e-30, 1e-3, -1e-3];
    // Folds and equator: the square |x| + |y| = 1 (and circle) in the plane z ~ 0.
    for i in 0..4096 {
        let t = f64::from(i) / 4096.0 * std::f64::consts::TAU;
        let (s, c) = t.sin_cos();
        let l1 = s.abs() + c.abs();
        for &z in &tiny {
            v.push([(c / l1) as f32, (s / l1) as f32, z]);
            v.push([c as f32, s as f32, z]);
        }
    }
    // Poles approached in ULP-sized and code-sized steps.
    for k in 0..2048 {
        let e = 2f64.powi(-(k % 40)) * (1.0 + f64::from(k / 40) / 64.0);
        for (sx, sy, sz) in [
            (1.0, 1.0, 1.0),
            (-1.0, 1.0, 1.0),
            (1.0, -1.0, -1.0),
            (-1.0, -1.0, -1.0),
        ] {
            let d = [sx * e, sy * e * 0.5, sz];
            if let Some(u) = crate::normal::exact::unit(d) {
                v.push(u.map(|x| x as f32));
            }
        }
    }
    for d in [
        [1.0f32, 1.0, 1.0],
        [-1.0, 1.0, -1.0],
        [1.0, -1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ] {
        v.push(d.map(|x| x / 3f32.sqrt()));
    }
    // Cell edges of every oct size: continuous coordinate k + 1/2 (the rounding encoder's tie)
    // and k + 0 (a code exactly), on both hemispheres, through a seeded walk over the square.
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    for bits in [8u32, 12, 16] {
        let m = f64::from(oct::max_code(bits));
        for _ in 0..16384 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let u = (seed >> 40) as f64 / 2f64.powi(24) * m;
            let w = (seed & 0xff_ffff) as f64 / 2f64.powi(24) * m;
            for (cu, cw) in [(u.floor() + 0.5, w.floor() + 0.5), (u.floor(), w)] {
                let p = [2.0 * cu / m - 1.0, 2.0 * cw / m - 1.0];
                let z = 1.0 - p[0].abs() - p[1].abs();
                let d = if seed & 1 == 0 || z < 0.0 {
                    [p[0], p[1], z]
                } else {
                    // The same point folded to the lower hemisphere.
                    let s = |x: f64| if x >= 0.0 { 1.0 } else { -1.0 };
                    [
                        (1.0 - p[1].abs()) * s(p[0]),
                        (1.0 - p[0].abs()) * s(p[1]),
                        -z,
                    ]
                };
                if let Some(u) = crate::normal::exact::unit(d) {
                    v.push(u.map(|x| x as f32));
                }
            }
        }
    }
    v
}

/// What one encoding did to a set of directions, encoded and decoded on the adapter.
#[derive(Clone, Debug)]
pub struct RoundTrip {
    /// Angle in degrees between each input (widened to f64) and its decoded vector.
    pub error: ErrorStats,
    /// The same restricted to inputs with `z ≥ 0` (the hemisphere xy FP16 can represent).
    pub error_upper: ErrorStats,
    /// Codes where the Rust encoder differs from the adapter's.
    pub twin_encode: Mismatches<u32>,
    /// Decoded vectors (bits) where the Rust decoder differs from the adapter's.
    pub twin_decode: Mismatches<u32>,
    /// Decoded vectors whose length is off 1 by more than [`UNIT_TOLERANCE`] or not finite.
    pub not_unit: u64,
    /// The adapter's codes, in input order.
    pub codes: Vec<u32>,
    /// The adapter's decoded vectors, in input order.
    pub decoded: Vec<[f32; 3]>,
}

/// How far a decoded vector's length may be from 1: WGSL's `normalize` is `v·inverseSqrt(v·v)`
/// with `inverseSqrt` 2 ULP, the dot product's 3 roundings (≤ 1.5 ULP relative to `v·v`, so
/// ≤ 0.75 ULP on the length), and the final multiply 0.5 ULP per component: ≤ 3.25·2^-23,
/// rounded up to 4·2^-23 (lavapipe's measured worst is listed in the README).
pub const UNIT_TOLERANCE: f64 = 4.0 / 8_388_608.0;

fn is_unit(v: [f32; 3]) -> bool {
    let l = widen3(v).iter().map(|x| x * x).sum::<f64>().sqrt();
    l.is_finite() && (l - 1.0).abs() <= UNIT_TOLERANCE
}

/// Split `0..n` over the available cores and fold each part with `f`.
fn par_fold<T: Send>(n: usize, f: impl Fn(std::ops::Range<usize>) -> T + Sync) -> Vec<T> {
    let threads = std::thread::available_parallelism()
        .map_or(1, |p| p.get())
        .min(8);
    let step = n.div_ceil(threads).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..n)
            .step_by(step)
            .map(|a| {
                let f = &f;
                s.spawn(move || f(a..(a + step).min(n)))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("worker"))
            .collect()
    })
}

/// Encode every input with `codec`'s WGSL encoder, decode with its WGSL decoder, and measure
/// against the input and against the Rust twins.
pub fn round_trip(
    gpu: &Gpu,
    codec: &Codec,
    inputs: &[[f32; 3]],
) -> Result<RoundTrip, HarnessError> {
    let n = inputs.len() as u64;
    let codes = gpu
        .kernel(codec.source, codec.encode)?
        .run(&[Arg::column(inputs)], n)?
        .into_words();
    let decoded = gpu
        .kernel(codec.source, codec.decode)?
        .run(&[Arg::column(&codes)], n)?
        .as_vec3()
        .to_vec();
    let parts = par_fold(inputs.len(), |r| {
        let base = r.start as u64;
        let mut e = ErrorStats::default();
        let mut up = ErrorStats::default();
        let mut not_unit = 0;
        for i in r.clone() {
            let a = angle_degrees(widen3(inputs[i]), widen3(decoded[i]));
            e.add(i as u64, a);
            if inputs[i][2] >= 0.0 {
                up.add(i as u64, a);
            }
            not_unit += u64::from(!is_unit(decoded[i]));
        }
        let enc = Mismatches::count(&codes[r.clone()], |k| {
            (codec.twin_encode)(Vec3::from(inputs[r.start + k]))
        });
        let dec_bits: Vec<u32> = decoded[r.clone()]
            .iter()
            .flatten()
            .map(|x| x.to_bits())
            .collect();
        let dec = Mismatches::count(&dec_bits, |k| {
            (codec.twin_decode)(codes[r.start + k / 3]).to_array()[k % 3].to_bits()
        });
        (base, e, up, not_unit, enc, dec)
    });
    let mut rt = RoundTrip {
        error: ErrorStats::default(),
        error_upper: ErrorStats::default(),
        twin_encode: Mismatches::default(),
        twin_decode: Mismatches::default(),
        not_unit: 0,
        codes,
        decoded,
    };
    for (base, e, up, nu, enc, dec) in parts {
        rt.error.merge(&e);
        rt.error_upper.merge(&up);
        rt.not_unit += nu;
        rt.twin_encode.merge(enc, base);
        rt.twin_decode.merge(dec, base * 3);
    }
    Ok(rt)
}

/// The f64 reproduction of `codec`'s algorithm on the same inputs: reference encoder, exact
/// decode, angle to the input. The row the targets come from.
pub fn reference_error(codec: &Codec, inputs: &[[f32; 3]]) -> ErrorStats {
    let parts = par_fold(inputs.len(), |r| {
        let mut e = ErrorStats::default();
        for i in r {
            let n = widen3(inputs[i]);
            e.add(
                i as u64,
                angle_degrees(n, (codec.reference_decode)((codec.reference_encode)(n))),
            );
        }
        e
    });
    parts.iter().fold(ErrorStats::default(), |mut a, p| {
        a.merge(p);
        a
    })
}

/// How close the precise octahedral encoder's choices are to the best of the four neighbours.
#[derive(Clone, Copy, Debug, Default)]
pub struct Optimality {
    /// Largest `angle(chosen) − min over neighbours angle(neighbour)`, degrees (≤ 0 is optimal).
    pub worst_excess_deg: f64,
    /// Inputs whose code is not (one of) the f64-best of its neighbours.
    pub not_best: u64,
    /// Index of the input with the worst excess.
    pub argworst: u64,
}

/// The slack the precise encoder's choice may have over the best neighbour, in degrees: twice
/// its f32 score error (`(2√3 + 3)·2^-24` rad, see [`oct::encode_precise`]) plus twice the
/// decoder's rounding of each direction (`√2·2^-24` rad: only the final per-component
/// multiply turns the direction; the length's error does not).
pub fn optimality_tolerance_deg() -> f64 {
    let ulp = 2f64.powi(-24);
    (2.0 * (2.0 * 3f64.sqrt() + 3.0) * ulp + 2.0 * 2f64.sqrt() * ulp).to_degrees()
}

/// `sin²` of the angle between `a` and `b` in f64 (`|a×b|²/(|a|²|b|²)`): ranks small angles
/// as `angle_degrees` does, at a fraction of the cost.
fn sin2_f64(a: [f64; 3], b: [f64; 3]) -> f64 {
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    dot(c, c) / (dot(a, a) * dot(b, b))
}

/// Check every chosen code of a precise (hemi-)octahedral encoder against the four neighbours of
/// the input's exact (f64) continuous coordinates, each decoded as the shipped decoder does (the Rust twin, bit-identical to the
/// adapter's decoder — checked by [`round_trip`]), all angles measured in f64. Neighbours are
/// ranked by f64 `sin²` (every error here is far below 90°); the excess is then measured with
/// [`angle_degrees`].
pub fn precise_optimality(codec: &Codec, inputs: &[[f32; 3]], rt: &RoundTrip) -> Optimality {
    let bits = codec.bits / 2;
    let parts = par_fold(inputs.len(), |r| {
        let mut o = Optimality {
            worst_excess_deg: f64::NEG_INFINITY,
            ..Default::default()
        };
        for i in r {
            let n = widen3(inputs[i]);
            let chosen = widen3(rt.decoded[i]);
            let mut best = (f64::INFINITY, chosen);
            let neighbours = if codec.source == NORMAL_HEMIOCT {
                hemioct::exact::neighbours(n)
            } else {
                oct::exact::neighbours(n, bits)
            };
            for p in neighbours {
                let d = widen3((codec.twin_decode)(p).to_array());
                let s = sin2_f64(n, d);
                if s < best.0 {
                    best = (s, d);
                }
            }
            let excess = if sin2_f64(n, chosen) > best.0 {
                o.not_best += 1;
                angle_degrees(n, chosen) - angle_degrees(n, best.1)
            } else {
                0.0
            };
            if excess > o.worst_excess_deg {
                o.worst_excess_deg = excess;
                o.argworst = i as u64;
            }
        }
        o
    });
    parts.into_iter().fold(
        Optimality {
            worst_excess_deg: f64::NEG_INFINITY,
            ..Default::default()
        },
        |a, p| Optimality {
            not_best: a.not_best + p.not_best,
            ..if p.worst_excess_deg > a.worst_excess_deg {
                p
            } else {
                a
            }
        },
    )
}

/// A decoder run over a set of codes.
#[derive(Clone, Debug, Default)]
pub struct DecoderCheck {
    /// Codes decoded.
    pub codes: u64,
    /// Results not finite or with `|len − 1|` above [`UNIT_TOLERANCE`].
    pub not_unit: u64,
    /// Largest `|len − 1|` seen (f64 length of the f32 result).
    pub max_len_error: f64,
    /// Largest angle (degrees) between a result and the code's exact direction.
    pub max_angle_deg: f64,
    /// Results (bits) where the Rust twin differs.
    pub twin: Mismatches<u32>,
}

impl DecoderCheck {
    /// Fold in another part's results (its twin mismatch indices already absolute).
    pub fn merge(&mut self, p: DecoderCheck) {
        self.codes += p.codes;
        self.not_unit += p.not_unit;
        self.max_len_error = self.max_len_error.max(p.max_len_error);
        self.max_angle_deg = self.max_angle_deg.max(p.max_angle_deg);
        self.twin.merge(p.twin, 0);
    }

    /// Check one chunk of results (`out[k]` decoded from `code(k)`), on every core.
    fn add(
        &mut self,
        codec: &Codec,
        code: impl Fn(u64) -> u32 + Sync,
        out: &[[f32; 3]],
        base: u64,
    ) {
        for part in par_fold(out.len(), |r| {
            let mut c = DecoderCheck {
                codes: r.len() as u64,
                ..Default::default()
            };
            for k in r {
                let (p, v) = (code(k as u64), out[k]);
                let l = widen3(v).iter().map(|x| x * x).sum::<f64>().sqrt();
                c.not_unit += u64::from(!is_unit(v));
                if l.is_finite() {
                    c.max_len_error = c.max_len_error.max((l - 1.0).abs());
                }
                let a = angle_degrees(widen3(v), (codec.reference_decode)(p));
                c.max_angle_deg = c
                    .max_angle_deg
                    .max(if a.is_nan() { f64::INFINITY } else { a });
                let t = (codec.twin_decode)(p).to_array();
                c.twin.total += 1;
                if t.map(f32::to_bits) != v.map(f32::to_bits) {
                    c.twin.count += 1;
                    if c.twin.first.len() < 8 {
                        c.twin
                            .first
                            .push((base + k as u64, v[0].to_bits(), t[0].to_bits()));
                    }
                }
            }
            c
        }) {
            self.merge(part);
        }
    }
}

/// Decode `count` consecutive codes from `start` (streamed in chunks; `count` up to 2^32).
pub fn decode_range(
    gpu: &Gpu,
    codec: &Codec,
    start: u32,
    count: u64,
) -> Result<DecoderCheck, HarnessError> {
    let k = gpu.kernel(codec.source, codec.decode)?;
    let mut check = DecoderCheck::default();
    k.run_chunks(&[Arg::Index { start }], count, |first, out| {
        let s = start.wrapping_add(first as u32);
        check.add(codec, |i| s.wrapping_add(i as u32), out.as_vec3(), first);
        Ok(())
    })?;
    Ok(check)
}

/// The documented stratified sample of a 32-bit code space: one code from each of the 2^26
/// blocks of 64 consecutive codes (offset in the block from a hash of the block number), plus
/// every code with a coordinate (either 16-bit half) at 0, 1, 2^15 − 1, 2^15, 2^16 − 2 or
/// 2^16 − 1 — the folds, the axes and the square's edges.
pub fn stratified_codes32() -> Vec<u32> {
    let mut v: Vec<u32> = (0u32..1 << 26)
        .map(|b| (b << 6) | (b.wrapping_mul(0x9e37_79b9) >> 26))
        .collect();
    for h in [0u32, 1, 0x7fff, 0x8000, 0xfffe, 0xffff] {
        for o in 0u32..1 << 16 {
            v.push(h | (o << 16));
            v.push(o | (h << 16));
        }
    }
    v
}

/// Decode the given codes with `codec`'s WGSL decoder and check them (see [`DecoderCheck`]);
/// results are streamed chunk by chunk.
pub fn decode_codes(gpu: &Gpu, codec: &Codec, codes: &[u32]) -> Result<DecoderCheck, HarnessError> {
    let k = gpu.kernel(codec.source, codec.decode)?;
    let mut check = DecoderCheck::default();
    k.run_chunks(&[Arg::column(codes)], codes.len() as u64, |first, out| {
        let f = first as usize;
        check.add(codec, |i| codes[f + i as usize], out.as_vec3(), first);
        Ok(())
    })?;
    Ok(check)
}

/// All 2^32 codes of `codec` (a 32-bit one: oct32 or xy fp16) through its WGSL decoder, streamed
/// (memory bounded by one chunk). Minutes on lavapipe: for `errplot`, not for the test suite.
pub fn decode_all_32(gpu: &Gpu, codec: &Codec) -> Result<DecoderCheck, HarnessError> {
    decode_range(gpu, codec, 0, 1u64 << 32)
}

/// The Killzone 2 xy-FP16 "myth" for one field of view (square viewport, `fov_deg` across both
/// axes): which visible normals have view-space `z < 0`, and what decoding them costs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Myth {
    /// Field of view, degrees.
    pub fov_deg: f64,
    /// Pixel centres sampled (a `grid × grid` screen).
    pub pixels: u64,
    /// Pixels where some visible normal has `z < 0` (every pixel off the optical axis).
    pub pixels_with_negative_z: u64,
    /// Of the visible normals (uniform over each pixel's visible hemisphere), the fraction with
    /// `z < 0`, averaged over the screen (exactly `θ/π` per pixel, θ = angle off axis).
    pub visible_fraction_negative_z: f64,
    /// The same, analytic: mean of `θ/π` over the pixel centres.
    pub visible_fraction_analytic: f64,
    /// Worst angular error (degrees) of `decode(encode(n))` on the adapter over the sampled
    /// visible normals with `z < 0`.
    pub worst_error_deg: f64,
    /// Mean error (degrees) over the sampled visible normals with `z < 0`.
    pub mean_error_negative_deg: f64,
    /// The analytic worst case, `2·θ_corner` (a normal at grazing incidence at the corner).
    pub worst_error_analytic_deg: f64,
}

/// Measure [`Myth`] on a `grid × grid` screen with `normals` Fibonacci normals per pixel's
/// visible hemisphere (the hemisphere facing the camera along that pixel's view ray), each
/// encoded and decoded by the WGSL xy-FP16 functions.
pub fn killzone_myth(
    gpu: &Gpu,
    fov_deg: f64,
    grid: u32,
    normals: u32,
) -> Result<Myth, HarnessError> {
    let t = (fov_deg.to_radians() / 2.0).tan();
    let sphere: Vec<[f64; 3]> = fibonacci_directions(2 * normals)
        .into_iter()
        .map(widen3)
        .filter(|d| d[2] > 0.0)
        .collect();
    let mut m = Myth {
        fov_deg,
        ..Default::default()
    };
    let enc = gpu.kernel(NORMAL_XY_FP16, "encode_normal_xy_fp16")?;
    let dec = gpu.kernel(NORMAL_XY_FP16, "decode_normal_xy_fp16")?;
    let (mut frac_sum, mut analytic_sum, mut neg_err) = (0.0, 0.0, ErrorStats::default());
    for py in 0..grid {
        let mut inputs: Vec<[f32; 3]> = Vec::new();
        let mut row_neg = vec![0u64; grid as usize];
        for px in 0..grid {
            let sx = (2.0 * (f64::from(px) + 0.5) / f64::from(grid) - 1.0) * t;
            let sy = (2.0 * (f64::from(py) + 0.5) / f64::from(grid) - 1.0) * t;
            // w: towards the camera from the surface (minus the view ray), unit.
            let w = crate::normal::exact::unit([-sx, -sy, 1.0]).expect("finite");
            let theta = w[2].clamp(-1.0, 1.0).acos();
            analytic_sum += theta / std::f64::consts::PI;
            // Rotate the +z hemisphere onto the one around w (Rodrigues, axis z × w).
            let axis = [-w[1], w[0], 0.0];
            let s = (axis[0] * axis[0] + axis[1] * axis[1]).sqrt();
            let k = if s > 0.0 {
                [axis[0] / s, axis[1] / s, 0.0]
            } else {
                [1.0, 0.0, 0.0]
            };
            let c = w[2];
            for d in &sphere {
                let kd = k[0] * d[0] + k[1] * d[1];
                let kxd = [k[1] * d[2], -k[0] * d[2], k[0] * d[1] - k[1] * d[0]];
                let r: [f64; 3] =
                    std::array::from_fn(|j| d[j] * c + kxd[j] * s + k[j] * kd * (1.0 - c));
                if r[2] < 0.0 {
                    row_neg[px as usize] += 1;
                    inputs.push(r.map(|x| x as f32));
                }
            }
        }
        for &c in &row_neg {
            m.pixels += 1;
            frac_sum += c as f64 / sphere.len() as f64;
            m.pixels_with_negative_z += u64::from(c > 0);
        }
        if inputs.is_empty() {
            continue;
        }
        let codes = enc
            .run(&[Arg::column(&inputs)], inputs.len() as u64)?
            .into_words();
        let out = dec.run(&[Arg::column(&codes)], codes.len() as u64)?;
        for (i, v) in out.as_vec3().iter().enumerate() {
            neg_err.add(i as u64, angle_degrees(widen3(inputs[i]), widen3(*v)));
        }
    }
    let corner_theta = (2f64.sqrt() * t).atan();
    m.visible_fraction_negative_z = frac_sum / m.pixels as f64;
    m.visible_fraction_analytic = analytic_sum / m.pixels as f64;
    m.worst_error_deg = neg_err.max;
    m.mean_error_negative_deg = neg_err.mean();
    m.worst_error_analytic_deg = 2.0 * corner_theta.to_degrees();
    Ok(m)
}

/// Bad inputs for the encoders, each with the well-formed input it must encode exactly like
/// (the documented answer): NaN anywhere, zero and all-subnormal vectors → `+z`; infinities →
/// the vector of their signs; subnormal components → zero; any finite length → the same
/// direction at unit length (huge, tiny and plain non-unit vectors).
pub fn bad_inputs() -> Vec<([f32; 3], [f32; 3])> {
    let (nan, inf, sub) = (f32::NAN, f32::INFINITY, f32::from_bits(0x0040_0000));
    let qnan_neg = f32::from_bits(0xffc0_0001);
    let z = [0.0, 0.0, 1.0];
    let r = std::f32::consts::FRAC_1_SQRT_2;
    vec![
        ([0.0, 0.0, 0.0], z),
        ([-0.0, -0.0, -0.0], z),
        ([nan, 0.0, 1.0], z),
        ([0.5, qnan_neg, 0.5], z),
        ([1.0, 1.0, nan], z),
        ([nan, inf, 1.0], z),
        ([sub, -sub, sub], z),
        ([f32::from_bits(1), 0.0, 0.0], z),
        ([inf, 1.0, 0.0], [1.0, 0.0, 0.0]),
        ([-inf, 5.0, 3.0], [-1.0, 0.0, 0.0]),
        ([0.0, 0.0, -inf], [0.0, 0.0, -1.0]),
        ([inf, -inf, 7.0], [r, -r, 0.0]),
        ([sub, 1.0, -sub], [0.0, 1.0, 0.0]),
        ([sub, -0.6, 0.8], [0.0, -0.6, 0.8]),
        ([2.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        ([3.0e38, 3.0e38, 0.0], [r, r, 0.0]),
        (
            [f32::MAX, -f32::MAX, f32::MAX],
            [1.0, -1.0, 1.0].map(|x: f32| x / 3f32.sqrt()),
        ),
        ([1.0e-37, 0.0, -1.0e-37], [r, 0.0, -r]),
        ([0.0, -4.0, 0.0], [0.0, -1.0, 0.0]),
        ([-0.0, 0.0, -2.5], [-0.0, 0.0, -1.0]),
    ]
}

/// Checks of one encoding's render-target (unorm channel) form.
#[derive(Clone, Debug, Default)]
pub struct UnormForms {
    /// Channels from the WGSL `encode_*_unorm` that differ (bits) from `unpack4x8unorm` of the
    /// Rust encoder's code.
    pub encode: Mismatches<u32>,
    /// Decodes of perturbed channels (exact, ±3 ULP, ±0.45/255, each both ways) whose bits differ
    /// from the WGSL decoder's result for the code itself.
    pub decode: Mismatches<u32>,
}

/// Check `encode_unorm(n) -> vecL<f32>` and `decode_unorm(c: vecL<f32>) -> vec3<f32>` (L = 2 or 4
/// channels) of `codec` against its code path over `inputs`.
pub fn unorm_forms(
    gpu: &Gpu,
    codec: &Codec,
    encode_unorm: &str,
    decode_unorm: &str,
    lanes: usize,
    inputs: &[[f32; 3]],
) -> Result<UnormForms, HarnessError> {
    use crate::precision::inputs::{sign_pattern, unorm8_channel};
    let n = inputs.len() as u64;
    let mut f = UnormForms::default();
    let channels = gpu
        .kernel(codec.source, encode_unorm)?
        .run(&[Arg::column(inputs)], n)?
        .into_words();
    let codes: Vec<u32> = inputs
        .iter()
        .map(|v| (codec.twin_encode)(Vec3::from(*v)))
        .collect();
    f.encode = Mismatches::count(&channels, |k| {
        crate::depth24::unpack4x8unorm(codes[k / lanes])[k % lanes].to_bits()
    });
    let want = gpu
        .kernel(codec.source, codec.decode)?
        .run(&[Arg::column(&codes)], n)?
        .into_words();
    let dec = gpu.kernel(codec.source, decode_unorm)?;
    for (error, flip) in crate::sweep::depth24::RECOVERY_CASES {
        let c: Vec<f32> = codes
            .iter()
            .flat_map(|&p| {
                let signs = sign_pattern(p, flip);
                (0..lanes).map(move |k| {
                    unorm8_channel((p >> (8 * k)) & 0xff, error, (signs >> (k % 3)) & 1 == 1)
                })
            })
            .collect();
        let got = dec.run(&[Arg::column(&c)], n)?.into_words();
        f.decode.merge(Mismatches::count(&got, |k| want[k]), 0);
    }
    Ok(f)
}
