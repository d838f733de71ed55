//! The batch twins (`prepass::batch`) beside meshoptimizer's octahedral vertex filter, in one
//! run, on the same 65,536 unit normals (a spherical Fibonacci lattice):
//!
//! ```text
//! bash .ci/bench          # writes docs/batch_bench.md (both overflow-check settings)
//! cargo bench --bench batch -- --warm-up-time 1 --measurement-time 2
//! ```
//!
//! meshopt's filter at 8, 12 and 16 bits per component stores the same information as
//! prepass's oct16, oct24 and oct32 (2 × bits); its encoder rounds, as prepass's `_fast` one
//! does; prepass's precise encoder tries four codes. prepass runs at `Level::detected()` on one
//! thread (the `_with` forms: no rayon split), meshopt is single-threaded C.
//!
//! **Criterion** measures every function (normals per second). **Then the summary** — a
//! separate timing in the same binary, not criterion's estimates — times each batch 101 times,
//! prepass and meshopt runs interleaved, and takes each one's median. It prints, per codec and
//! operation, exactly one line `ratio <codec> <encode|decode> prepass/meshopt = X` (normals per
//! second of prepass over meshopt's; `oct16` is the precise encoder, `oct16_fast` the rounding
//! one, and both share `oct16 decode`), then the memory cap: a plain copy of the larger buffer
//! of each operation (the 12-byte-per-normal `Vec3` side), and each prepass function's rate as
//! a fraction of it, and prepass's rates at the baseline level (SSE2, NEON) for comparison. 65,536 normals keep every buffer (≤ 1 MiB) in L2, so the cap is the
//! cache's, not DRAM's. Set `PREPASS_BENCH_SUMMARY_ONLY=1` to skip criterion.

use criterion::{BatchSize, Criterion, Throughput};
use glam::Vec3;
use prepass::batch::{Level, normal as bn};
use std::hint::black_box;
use std::time::{Duration, Instant};

const N: usize = 1 << 16;

/// meshopt's filter and prepass's octahedral twins at one size.
struct Size {
    /// meshopt's bits per component.
    bits: i32,
    /// meshopt's bytes per normal (8-bit snorm ×4 or 16-bit ×4).
    stride: usize,
    /// prepass's name for the same information.
    name: &'static str,
    precise: fn(Level, &[Vec3], &mut [u32]),
    fast: fn(Level, &[Vec3], &mut [u32]),
    decode: fn(Level, &[u32], &mut [Vec3]),
}

const SIZES: [Size; 3] = [
    Size {
        bits: 8,
        stride: 4,
        name: "oct16",
        precise: bn::encode_normal_oct16_with,
        fast: bn::encode_normal_oct16_fast_with,
        decode: bn::decode_normal_oct16_with,
    },
    Size {
        bits: 12,
        stride: 8,
        name: "oct24",
        precise: bn::encode_normal_oct24_with,
        fast: bn::encode_normal_oct24_fast_with,
        decode: bn::decode_normal_oct24_with,
    },
    Size {
        bits: 16,
        stride: 8,
        name: "oct32",
        precise: bn::encode_normal_oct32_with,
        fast: bn::encode_normal_oct32_fast_with,
        decode: bn::decode_normal_oct32_with,
    },
];

/// The benchmark's normals, four floats each (w = 0) for meshopt and as `Vec3` for prepass.
/// Point `i` at `z = 1 − (2i + 1)/N`, azimuth `i·π(3 − √5)`, in f64 rounded to f32 (the
/// formula of `prepass::sweep::normal::fibonacci_directions`, which needs the `harness`
/// feature).
fn normals() -> (Vec<f32>, Vec<Vec3>) {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let dirs: Vec<[f32; 3]> = (0..N)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / N as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let (s, c) = (golden * i as f64).sin_cos();
            [(r * c) as f32, (r * s) as f32, z as f32]
        })
        .collect();
    let flat = dirs.iter().flat_map(|d| [d[0], d[1], d[2], 0.0]).collect();
    (flat, dirs.into_iter().map(Vec3::from_array).collect())
}

fn meshopt_encode(out: &mut [u8], flat: &[f32], size: &Size) {
    assert!(out.len() == N * size.stride && flat.len() == N * 4);
    // SAFETY: `out` holds N·stride bytes and `flat` N·4 floats (checked above), as the function
    // requires; stride is 4 or 8 and bits ≤ 16.
    unsafe {
        meshopt::ffi::meshopt_encodeFilterOct(
            out.as_mut_ptr().cast(),
            N,
            size.stride,
            size.bits,
            flat.as_ptr(),
        );
    }
}

fn meshopt_decode(buf: &mut [u8], size: &Size) {
    assert!(buf.len() == N * size.stride);
    // SAFETY: `buf` holds N·stride bytes of this filter's encoding (checked above).
    unsafe { meshopt::ffi::meshopt_decodeFilterOct(buf.as_mut_ptr().cast(), N, size.stride) };
}

fn criterion_groups(c: &mut Criterion) {
    let (flat, vecs) = normals();
    let level = Level::detected();
    for size in &SIZES {
        let mut encoded = vec![0u8; N * size.stride];
        meshopt_encode(&mut encoded, &flat, size);
        let mut codes = vec![0u32; N];
        (size.precise)(level, &vecs, &mut codes);
        let mut decoded = vec![Vec3::ZERO; N];
        let mut g = c.benchmark_group(format!("batch_{}_vs_meshopt_{}bit", size.name, size.bits));
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("meshopt encodeFilterOct", |b| {
            b.iter(|| meshopt_encode(&mut encoded, black_box(&flat), size))
        });
        g.bench_function("meshopt decodeFilterOct", |b| {
            // The filter decodes in place: each run gets a fresh copy (not timed).
            b.iter_batched_ref(
                || encoded.clone(),
                |buf| meshopt_decode(buf, size),
                BatchSize::LargeInput,
            )
        });
        let mut out = vec![0u32; N];
        g.bench_function(
            format!("prepass {} encode (precise, {level})", size.name),
            |b| b.iter(|| (size.precise)(level, black_box(&vecs), &mut out)),
        );
        g.bench_function(
            format!("prepass {} encode (fast, {level})", size.name),
            |b| b.iter(|| (size.fast)(level, black_box(&vecs), &mut out)),
        );
        g.bench_function(format!("prepass {} decode ({level})", size.name), |b| {
            b.iter(|| (size.decode)(level, black_box(&codes), &mut decoded))
        });
        g.bench_function(
            format!("prepass {} encode (precise, scalar)", size.name),
            |b| b.iter(|| (size.precise)(Level::Scalar, black_box(&vecs), &mut out)),
        );
        g.bench_function("copy 12 bytes per normal (cap)", |b| {
            b.iter(|| decoded.copy_from_slice(black_box(&vecs)))
        });
        g.finish();
    }
}

/// The other batch families at the detected level beside [`Level::Scalar`] (the scalar twin per
/// element): roughness at the tests' range 8192, GGX roughness (linear r and the log curve), and
/// 24-bit depth recovery from RGB8 channels.
fn criterion_others(c: &mut Criterion) {
    use prepass::batch::{depth24 as bd, roughness as br, roughness_ggx as bg};
    let level = Level::detected();
    let powers: Vec<f32> = (0..N)
        .map(|i| (i as f32 / N as f32 * 13.0).exp2())
        .collect();
    let codes: Vec<u32> = (0..N as u32)
        .map(|i| i.wrapping_mul(0x9e37_79b1) & 0xff)
        .collect();
    let rgb: Vec<Vec3> = (0..N as u32)
        .map(|i| {
            let p = prepass::depth24::pack_depth24(i.wrapping_mul(0x9e37_79b1) & 0xff_ffff);
            let [r, g, b, _] = prepass::depth24::unpack4x8unorm(p);
            Vec3::new(r, g, b)
        })
        .collect();
    let rough: Vec<f32> = (0..N).map(|i| i as f32 / N as f32).collect();
    let (mut out_u32, mut out_f32) = (vec![0u32; N], vec![0f32; N]);
    let mut g = c.benchmark_group("batch_others");
    g.throughput(Throughput::Elements(N as u64));
    for l in [level, Level::Scalar] {
        g.bench_function(format!("roughness encode (max 8192, {l})"), |b| {
            b.iter(|| br::encode_log_roughness_with(l, 8192.0, black_box(&powers), &mut out_u32))
        });
        g.bench_function(format!("roughness decode (max 8192, {l})"), |b| {
            b.iter(|| br::decode_log_roughness_with(l, 8192.0, black_box(&codes), &mut out_f32))
        });
        g.bench_function(format!("GGX roughness encode, linear r ({l})"), |b| {
            b.iter(|| bg::encode_roughness_ggx8_with(l, black_box(&rough), &mut out_u32))
        });
        g.bench_function(format!("GGX roughness encode, log r ({l})"), |b| {
            b.iter(|| bg::encode_roughness_ggx8_log_with(l, black_box(&rough), &mut out_u32))
        });
        g.bench_function(format!("GGX roughness decode, log r ({l})"), |b| {
            b.iter(|| bg::decode_roughness_ggx8_log_with(l, black_box(&codes), &mut out_f32))
        });
        g.bench_function(format!("depth24_from_rgb8 ({l})"), |b| {
            b.iter(|| bd::depth24_from_rgb8_with(l, black_box(&rgb), &mut out_u32))
        });
    }
    g.finish();
}

/// Seconds `f` takes.
fn timed(f: impl FnOnce()) -> f64 {
    let start = Instant::now();
    f();
    start.elapsed().as_secs_f64()
}

/// Median of `runs` results of each closure (each returns the seconds its timed part took),
/// the closures' runs interleaved so a change of machine load hits all of them alike.
fn medians(runs: usize, fs: &mut [&mut dyn FnMut() -> f64]) -> Vec<f64> {
    let mut t = vec![Vec::with_capacity(runs); fs.len()];
    for _ in 0..runs {
        for (k, f) in fs.iter_mut().enumerate() {
            t[k].push(f());
        }
    }
    t.into_iter()
        .map(|mut v| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        })
        .collect()
}

/// The summary: ratio lines, then the copy cap.
fn summary() {
    let (flat, vecs) = normals();
    let level = Level::detected();
    // The baseline vector level, for comparison: SSE2 on x86_64, NEON on aarch64.
    let base = if cfg!(target_arch = "x86_64") {
        Level::Sse2
    } else if cfg!(target_arch = "aarch64") {
        Level::Neon
    } else {
        Level::Scalar
    };
    let runs = 101;
    let rate = |secs: f64| N as f64 / secs / 1e6;
    let mut ratios = Vec::new();
    let mut caps = Vec::new();
    for (k, size) in SIZES.iter().enumerate() {
        // Progress on stderr (stdout is the summary that .ci/bench files).
        eprintln!(
            "summary: {} ({}/{}), {runs} interleaved runs of 9 timings…",
            size.name,
            k + 1,
            SIZES.len()
        );
        let mut encoded = vec![0u8; N * size.stride];
        meshopt_encode(&mut encoded, &flat, size);
        let pristine = encoded.clone();
        let mut buf = encoded.clone();
        let mut codes = vec![0u32; N];
        (size.precise)(level, &vecs, &mut codes);
        let mut out = vec![0u32; N];
        let mut out_fast = vec![0u32; N];
        let mut decoded = vec![Vec3::ZERO; N];
        let mut copy_dst = vec![Vec3::ZERO; N];
        let (mut out_b, mut out_fast_b, mut decoded_b) =
            (out.clone(), out.clone(), decoded.clone());
        let t = medians(
            runs,
            &mut [
                &mut || timed(|| meshopt_encode(&mut encoded, black_box(&flat), size)),
                &mut || {
                    buf.copy_from_slice(&pristine); // untimed: the filter decodes in place
                    timed(|| meshopt_decode(black_box(&mut buf), size))
                },
                &mut || timed(|| (size.precise)(level, black_box(&vecs), &mut out)),
                &mut || timed(|| (size.fast)(level, black_box(&vecs), &mut out_fast)),
                &mut || timed(|| (size.decode)(level, black_box(&codes), &mut decoded)),
                &mut || timed(|| copy_dst.copy_from_slice(black_box(&vecs))),
                &mut || timed(|| (size.precise)(base, black_box(&vecs), &mut out_b)),
                &mut || timed(|| (size.fast)(base, black_box(&vecs), &mut out_fast_b)),
                &mut || timed(|| (size.decode)(base, black_box(&codes), &mut decoded_b)),
            ],
        );
        black_box((&out, &out_fast, &decoded, &copy_dst, &buf));
        black_box((&out_b, &out_fast_b, &decoded_b));
        let [
            m_enc,
            m_dec,
            p_precise,
            p_fast,
            p_dec,
            copy,
            s_precise,
            s_fast,
            s_dec,
        ] = t[..]
        else {
            unreachable!()
        };
        let name = size.name;
        ratios.push(format!(
            "ratio {name} encode prepass/meshopt = {:.2}",
            m_enc / p_precise
        ));
        ratios.push(format!(
            "ratio {name}_fast encode prepass/meshopt = {:.2}",
            m_enc / p_fast
        ));
        ratios.push(format!(
            "ratio {name} decode prepass/meshopt = {:.2}",
            m_dec / p_dec
        ));
        caps.push(format!(
            "{name}/{}-bit: M normals/s: meshopt encode {:.0}, decode {:.0}; prepass encode {:.0} \
             (precise), {:.0} (fast), decode {:.0} (at {base}: {:.0}, {:.0}, {:.0}); copy {:.0} (cap); \
             prepass/copy: encode {:.2} (precise), {:.2} (fast), decode {:.2}",
            size.bits,
            rate(m_enc),
            rate(m_dec),
            rate(p_precise),
            rate(p_fast),
            rate(p_dec),
            rate(s_precise),
            rate(s_fast),
            rate(s_dec),
            rate(copy),
            copy / p_precise,
            copy / p_fast,
            copy / p_dec,
        ));
    }
    let checks = if cfg!(debug_assertions) || overflow_checks_on() {
        "on"
    } else {
        "off"
    };
    println!(
        "\nsummary: {N} normals, median of {runs} interleaved runs each, prepass at level {level} \
         on one thread, overflow checks {checks}"
    );
    for c in caps {
        println!("rates {c}");
    }
    for r in ratios {
        println!("{r}");
    }
}

/// Whether this build checks integer overflow (the bench profile's setting).
fn overflow_checks_on() -> bool {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let on = std::panic::catch_unwind(|| {
        let x: u8 = black_box(255);
        black_box(x + black_box(1))
    })
    .is_err();
    std::panic::set_hook(hook);
    on
}

fn main() {
    if std::env::var_os("PREPASS_BENCH_SUMMARY_ONLY").is_none() {
        let mut c = Criterion::default()
            .warm_up_time(Duration::from_secs(1))
            .measurement_time(Duration::from_secs(2))
            .configure_from_args();
        criterion_groups(&mut c);
        criterion_others(&mut c);
        c.final_summary();
    }
    summary();
}
