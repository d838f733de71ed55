//! `wgsl/normal_signed_oct.wgsl` on the adapter: O3DE's signed octahedron in RGB10A2. Every one
//! of the 2^21 texels O3DE writes decoded, every B read as O3DE reads it (against the Rust twin `src/normal/signed_oct.rs`, the exact
//! direction, and O3DE's own reader on the texel), the precise and rounding encoders' round trips
//! over 2^20 spherical-Fibonacci directions, the adversarial set and the equator against a
//! derived bound, the precise encoder against the f64 best of its candidates and a brute-force
//! search, near ties, the render-target form, bad input, and O3DE's encoder and decoder as the
//! peer (`tests/baselines/peer_o3de.wgsl`): the codes it writes, and each side reading the other.

mod common;

use common::gpu;
use prepass::assert_within;
use prepass::harness::Arg;
use prepass::normal::F32_SLACK_DEG;
use prepass::normal::signed_oct::{self, B_MASK, M, SIGN_BIT, exact};
use prepass::precision::metrics::{angle_degrees, widen3};
use prepass::sweep::normal::{
    RenderTarget, adversarial_directions, bad_inputs, codec, decode_angle_deg, decode_codes,
    fibonacci_directions, near_tie_directions, optimality_tolerance_deg, precise_optimality,
    round_trip,
};
use prepass::wgsl::NORMAL_SIGNED_OCT;
use std::sync::OnceLock;

/// O3DE's writer and reader (`tests/baselines/peer_o3de.wgsl`).
const PEER: &str = include_str!("baselines/peer_o3de.wgsl");

fn fibonacci() -> &'static [[f32; 3]] {
    static F: OnceLock<Vec<[f32; 3]>> = OnceLock::new();
    F.get_or_init(|| fibonacci_directions(1 << 20))
}

/// The f32 error of the continuous coordinates `(R, G)`, in units of R (`R ≤ 1`): `p = s.xy/|s|₁`
/// within `3·2^-24·|p|` (two additions, a division), so `p.x/2 + p.y/2` within `1.5·2^-24`;
/// `y0` and `R` rounded (`2^-25` each); the scaling by 1023 (`2^-24` of R): `≤ 3.5·2^-24`, taken
/// as `4·2^-24`.
const COORD_EPS: f64 = 4.0 / 16_777_216.0;

/// The round trip's worst angle when R and G are each off by at most `h` (exact) plus
/// [`COORD_EPS`], in degrees. Derivation: the L1-normalised vector is `v = (x, y, 1 − |x| − |y|)`
/// (z's sign fixed by bit 20) with `x = R − G`, `y = R + G − 1`, so `|Δx| + |Δy| = 2·max(|ΔR|,
/// |ΔG|) ≤ 2h'` and `Δx² + Δy² = 2(ΔR² + ΔG²) ≤ 4h'²`; `|Δz| ≤ |Δx| + |Δy|`, so
/// `|Δv|² ≤ 8h'²` along the straight segment between the input's and the code's coordinates
/// (both in the square, one hemisphere); vectors of L1 norm 1 have length `≥ 1/√3`, and
/// `sin∠ ≤ |a − b|/max(|a|, |b|)`: `sin∠ ≤ √3·2√2·h' = 2√6·h'`; then the decoder's rounding
/// ([`F32_SLACK_DEG`]). Rounding: `h = 1/2046` (half a code), 0.1373°.
fn bound_deg(h: f64) -> f64 {
    (2.0 * 6f64.sqrt() * (h + COORD_EPS)).asin().to_degrees() + F32_SLACK_DEG
}

/// The rounding encoder's (and O3DE's) bound: half a code step.
fn round_bound_deg() -> f64 {
    bound_deg(1.0 / 2046.0)
}

/// The precise encoder's bound: its choice is within `optimality_tolerance_deg` of the best of
/// its four candidates, which include the rounded code.
fn precise_bound_deg() -> f64 {
    round_bound_deg() + optimality_tolerance_deg()
}

/// How far O3DE's f32 reader of a texel may turn from prepass's decode of the same code, in
/// degrees. Derivation: the sampled channels `k/1023` are within `2^-25` of exact (half an ULP
/// below 1; 1 is exact); `x = R − G` adds one rounding (`2^-25`, `|x| ≤ 1`): `|Δx| ≤ 1.5·2^-24`;
/// `R + G` (`2^-24`, below 2) then `− 1` (`2^-25`): `|Δy| ≤ 2.5·2^-24`; `z = ±((1 − |x|) − |y|)`
/// (`2B − 1 = ±1` exact) adds two roundings (`2^-25` each): `|Δz| ≤ 5·2^-24`. So
/// `|Δv| ≤ √33.5·2^-24 < 5.8·2^-24`, and with `|v| ≥ 1/√3`, `sin∠ ≤ √3·5.8·2^-24 < 11·2^-24` rad;
/// then both decoders' final rounding (`decode_angle_deg` each).
fn o3de_read_deg() -> f64 {
    (11.0 * 2f64.powi(-24)).to_degrees() + 2.0 * decode_angle_deg()
}

/// O3DE's `DecodeNormalSignedOctahedron` (`Gems/Atom/RPI/Assets/ShaderLib/Atom/RPI/Math.azsli`)
/// of a texel in f64, transcribed here from O3DE's source (not from prepass's code): the
/// channels `k/1023`, `x = R − G`, `y = (R + G) − 1`, `z = (2B − 1)(1 − |x| − |y|)`, normalised.
fn o3de_read_f64(t: u32) -> [f64; 3] {
    let c = [0, 10, 20].map(|k| f64::from((t >> k) & 0x3ff) / 1023.0);
    let (x, y) = (c[0] - c[1], (c[0] + c[1]) - 1.0);
    let z = (2.0 * c[2] - 1.0) * (1.0 - x.abs() - y.abs());
    let l = (x * x + y * y + z * z).sqrt();
    [x / l, y / l, z / l]
}

/// Directions on and near the equator (`z = ±0`, `±2^-k`, a few codes' worth either side) all
/// round the square's edge, and near the edges' corners: where the two hemispheres meet.
fn equator_directions() -> Vec<[f32; 3]> {
    let mut v = Vec::new();
    for t in 0..4096 {
        let a = f64::from(t) * std::f64::consts::TAU / 4096.0 + 1e-3;
        for z in [
            0.0f64,
            -0.0,
            1e-7,
            -1e-7,
            0.3 / 1023.0,
            -0.3 / 1023.0,
            0.7 / 1023.0,
            -0.7 / 1023.0,
            2.0 / 1023.0,
            -2.0 / 1023.0,
        ] {
            let r = (1.0 - z * z).sqrt();
            v.push([(r * a.cos()) as f32, (r * a.sin()) as f32, z as f32]);
        }
    }
    v
}

fn inputs() -> Vec<[f32; 3]> {
    let mut v = fibonacci().to_vec();
    v.extend(adversarial_directions());
    v.extend(equator_directions());
    v
}

/// Every 2^21 texel O3DE writes (B = 0 or 1023) decoded on the adapter (A's bits carrying
/// noise): bit-identical to the Rust twin, unit length, in the code's exact direction to the
/// decoder's rounding; that direction is O3DE's reading of the same texel in f64 (transcribed
/// above, to the f64 angle's rounding); and O3DE's f32 reader on the adapter
/// (`peer_o3de_signed_oct_decode` of the texel) agrees with prepass's decode within
/// [`o3de_read_deg`]. A is ignored; on the equator B = 0 gives −0.
#[test]
fn decodes_every_code_as_o3de_reads_it() {
    let c = codec("signed oct");
    let words: Vec<u32> = (0..1u32 << 21)
        .map(|k| signed_oct::texel_of_index(k) | (k.wrapping_mul(2_654_435_761) & 0xc000_0000))
        .collect();
    let d = decode_codes(gpu(), c, &words).unwrap();
    common::assert_decoder("signed oct all 2^21", &d);
    common::assert_high_bits_ignored(c.source, c.decode, &words[..1 << 16], 0x3fff_ffff);
    let worst_f64 = (0..1u32 << 21)
        .map(|p| {
            angle_degrees(
                exact::decode(signed_oct::texel_of_index(p)),
                o3de_read_f64(signed_oct::texel_of_index(p)),
            )
        })
        .fold(0f64, f64::max);
    assert_within!(
        worst_f64,
        1e-12,
        "the f64 angle's own rounding (about 1e-15°), as in sweep::normal::decode_angle_deg",
        "angle between prepass's and O3DE's (f64) reading of the same code, degrees"
    );
    let texels: Vec<u32> = (0..1u32 << 21).map(signed_oct::texel_of_index).collect();
    let n = texels.len() as u64;
    let ours = common::run_kernel(NORMAL_SIGNED_OCT, c.decode, &[Arg::column(&texels)], n);
    let theirs = common::run_kernel(
        PEER,
        "peer_o3de_signed_oct_decode",
        &[Arg::column(&texels)],
        n,
    );
    let (mut worst, mut at) = (0f64, 0usize);
    for i in 0..texels.len() {
        let e = angle_degrees(widen3(ours.as_vec3()[i]), widen3(theirs.as_vec3()[i]));
        if e > worst {
            (worst, at) = (e, i);
        }
    }
    eprintln!(
        "O3DE's f32 reader against prepass's decoder over all 2^21 texels: at most {worst:.3e}° \
         (code {at:#x}; bound {:.3e}°)",
        o3de_read_deg()
    );
    assert_within!(
        worst,
        o3de_read_deg(),
        "o3de_read_deg in this file: the reader's f32 channel arithmetic + both normalisations",
        "O3DE's reading of texel {:#x} against prepass's decode, degrees",
        texels[at]
    );
    // The equator with B = 0 decodes with z = −0, with B = 1023 +0, as O3DE's reader.
    for p in [M, M << 10, 0, M | (M << 10)] {
        let lo = ours.as_vec3()[p as usize];
        let hi = ours.as_vec3()[(p | SIGN_BIT) as usize];
        assert_eq!(lo[2].to_bits(), (-0.0f32).to_bits(), "code {p:#x}");
        assert_eq!(hi[2].to_bits(), 0, "code {:#x}", p | SIGN_BIT);
        assert_eq!([lo[0], lo[1]], [hi[0], hi[1]]);
    }
}

/// Every B: O3DE reads z's factor `2B − 1` from any B its texel holds, and so does prepass
/// (issue 60: it read B's lowest bit). On every 16th R and G code (and the last) with each of the
/// 1024 B codes, on the adapter: prepass's decode is O3DE's f64 reading (transcribed above) to
/// the decoder's rounding, and z's sign is that of O3DE's f32 reader on the adapter off the
/// equator. The texels: R = 600, G = 400, B = 1022 (z = +0.78 to O3DE; before, prepass
/// read z = −0.97), and B = 512 (O3DE's z > 0, small: its factor is 1/1023).
#[test]
fn reads_every_b_as_o3de_does() {
    let rg: Vec<u32> = (0..=M).step_by(16).chain([M]).collect();
    let mut texels: Vec<u32> = Vec::new();
    for b in 0..=M {
        for &u in &rg {
            for &v in &rg {
                texels.push(u | (v << 10) | (b << 20));
            }
        }
    }
    texels.extend([600 | 400 << 10 | 1022 << 20, 600 | 400 << 10 | 512 << 20]);
    let n = texels.len() as u64;
    let ours = common::run_kernel(
        NORMAL_SIGNED_OCT,
        "decode_normal_signed_oct",
        &[Arg::column(&texels)],
        n,
    );
    let theirs = common::run_kernel(
        PEER,
        "peer_o3de_signed_oct_decode",
        &[Arg::column(&texels)],
        n,
    );
    let (mut worst, mut flips) = (0f64, 0usize);
    for (i, &t) in texels.iter().enumerate() {
        let (a, o) = (ours.as_vec3()[i], theirs.as_vec3()[i]);
        worst = worst.max(angle_degrees(widen3(a), o3de_read_f64(t)));
        // Off the equator: O3DE's `1 − |x| − |y|` times 1023, from the codes (on the equator
        // its f32 z is rounding noise of either sign).
        let (u, v) = ((t & 0x3ff) as i32, ((t >> 10) & 0x3ff) as i32);
        let off_equator = 1023 - (u - v).abs() - (u + v - 1023).abs() != 0;
        if off_equator && (a[2] > 0.0) != (o[2] > 0.0) {
            flips += 1;
        }
    }
    eprintln!(
        "{n} texels, every B: prepass's decode against O3DE's f64 reading at most {worst:.3e}°; \
         z's sign against O3DE's f32 reader differs on {flips}"
    );
    assert_within!(
        worst,
        decode_angle_deg() + 1e-12,
        "sweep::normal::decode_angle_deg: the decoder's rounding of an exact integer direction",
        "prepass's decode against O3DE's f64 reading, degrees"
    );
    assert_eq!(flips, 0, "z's sign differs from O3DE's reader");
    let last = &ours.as_vec3()[texels.len() - 2..];
    assert!(
        last[0][2] > 0.7,
        "R = 600, G = 400, B = 1022: {:?}",
        last[0]
    );
    assert!(last[1][2] > 0.0, "R = 600, G = 400, B = 512: {:?}", last[1]);
}

/// Round trip of the precise and rounding encoders over 2^20 Fibonacci directions, the
/// adversarial set and the equator directions: the encoder and decoder are the Rust twins bit
/// for bit, every result unit length, the max error within the derived bound ([`bound_deg`]);
/// the precise choice is optimal among its four candidates up to `optimality_tolerance_deg`
/// (the same candidates as the f64 reference's) and never worse than the rounding encoder's
/// code by more than that; and z's sign bit is set exactly for inputs whose z is positive.
#[test]
fn round_trip_within_the_derived_bound() {
    let all = inputs();
    let mut codes = Vec::new();
    for (name, bound) in [
        ("signed oct", precise_bound_deg()),
        ("signed oct fast", round_bound_deg()),
    ] {
        let c = codec(name);
        let rt = round_trip(gpu(), c, &all).unwrap();
        let fib = round_trip(gpu(), c, fibonacci()).unwrap();
        eprintln!(
            "{name}: 2^20 Fibonacci mean {:.6}° max {:.6}°; with adversarial and equator inputs max {:.6}° (bound {bound:.6}°)",
            fib.error.mean(),
            fib.error.max,
            rt.error.max
        );
        common::assert_round_trip_matches_twins(name, c, &all, &rt);
        assert_eq!(rt.error.nan_count, 0);
        assert_within!(
            rt.error.max,
            bound,
            "bound_deg in this file: sin ≤ 2√6 (h + ε) over the hemi-octahedral square",
            "{name}: max degrees at input {}",
            rt.error.argmax
        );
        for (v, &p) in all.iter().zip(&rt.codes) {
            let s = prepass::normal::sanitize(glam::Vec3::from(*v)).unwrap_or(glam::Vec3::Z);
            assert_eq!(p >> 30, 0, "{name}: A's bits at {v:?}");
            let b = if s.z > 0.0 { B_MASK } else { 0 };
            assert_eq!(p & B_MASK, b, "{name}: B (z's sign) at {v:?}");
        }
        if name == "signed oct" {
            let o = precise_optimality(c, &all, &rt);
            eprintln!(
                "  precise choice vs best of its four candidates: worst excess {:.3e}°, {} of {} not the f64-best",
                o.worst_excess_deg,
                o.not_best,
                all.len()
            );
            assert_within!(
                o.worst_excess_deg,
                optimality_tolerance_deg(),
                "sweep::normal::optimality_tolerance_deg: f32 score error + decoder rounding",
                "input {}, degrees worse than its best candidate",
                o.argworst
            );
        }
        codes.push(rt.codes);
    }
    let (mut worse, mut at) = (f64::NEG_INFINITY, 0usize);
    for (i, v) in all.iter().enumerate() {
        let n = widen3(*v);
        let e = |p: u32| angle_degrees(n, exact::decode(p));
        let d = e(codes[0][i]) - e(codes[1][i]);
        if d > worse {
            (worse, at) = (d, i);
        }
    }
    eprintln!("  precise minus rounding, per input: at most {worse:.3e}° (input {at})");
    assert_within!(
        worse,
        optimality_tolerance_deg(),
        "sweep::normal::optimality_tolerance_deg: the rounded code is one of the precise \
         encoder's candidates, so only the f32 score error can make it the nearer",
        "precise encoder's error over the rounding encoder's at input {at} ({:?}), degrees",
        all[at]
    );
}

/// Brute force over neighbouring codes: for each input, every code within 3 steps per axis of
/// the precise choice, on both hemispheres, angles in f64. Reports how often a code outside the
/// four candidates is closer than the f64-best candidate and by how much; asserts that the f64
/// precise encoder's error stays within the precise bound whatever it finds. (The map has no
/// fold inside a hemisphere and the other hemisphere's codes are mirror images, at least as far,
/// so none is expected beyond ties.)
#[test]
fn brute_force_over_neighbouring_codes() {
    let all = inputs();
    let (mut beaten, mut worst_excess, mut worst_at, mut worst_total) =
        (0usize, 0f64, 0usize, 0f64);
    for (i, &v) in all.iter().enumerate() {
        let n = widen3(v);
        if prepass::normal::exact::unit(n).is_none() {
            continue;
        }
        let chosen = exact::encode_precise(n);
        let e_chosen = angle_degrees(n, exact::decode(chosen));
        let k = signed_oct::codes(chosen).as_ivec2();
        let mut best = e_chosen;
        for du in -3..=3 {
            for dv in -3..=3 {
                let (u, w) = (k.x + du, k.y + dv);
                if !(0..=M as i32).contains(&u) || !(0..=M as i32).contains(&w) {
                    continue;
                }
                for pos in [false, true] {
                    let p = signed_oct::word_of(glam::UVec2::new(u as u32, w as u32), pos);
                    best = best.min(angle_degrees(n, exact::decode(p)));
                }
            }
        }
        worst_total = worst_total.max(e_chosen);
        let excess = e_chosen - best;
        if excess > 1e-12 {
            beaten += 1;
            if excess > worst_excess {
                (worst_excess, worst_at) = (excess, i);
            }
        }
    }
    eprintln!(
        "brute force over {} inputs: a code outside the four candidates is closer for {beaten} \
         (worst by {worst_excess:.3e}° at input {worst_at}: {:?}); the f64 precise encoder's \
         worst error {worst_total:.6}°",
        all.len(),
        all[worst_at]
    );
    assert_within!(
        worst_total,
        precise_bound_deg(),
        "precise_bound_deg in this file",
        "the f64 precise encoder's worst error, degrees"
    );
}

/// 2^17 cells of near-tie directions on each hemisphere (`sweep::normal::near_tie_directions`),
/// 9 inputs each: the precise encoder's WGSL equals the twin bit for bit where two candidates'
/// scores nearly tie, on an adapter that evaluates the scores as the twin does.
#[test]
fn precise_encoder_equals_the_twin_at_near_ties() {
    let mut v = near_tie_directions(10, M, exact::decode, 1 << 17, 0x3d0);
    v.extend(near_tie_directions(
        10,
        M,
        |p| exact::decode(p | B_MASK),
        1 << 17,
        0x3d1,
    ));
    common::assert_near_ties(codec("signed oct"), &v);
}

/// Bad input gets the documented code on the adapter and in the twin (NaN, zero, all-subnormal
/// → +z's code, B = 1023; infinities win; any finite length); z = ±0 writes O3DE's `B = 0`;
/// A's bits stay zero.
#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let mut bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let mut good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    bad.extend([
        [0.6, 0.0, -0.0],
        [0.0, -3.0, -f32::from_bits(1)],
        [1.0, 1.0, -f32::INFINITY],
    ]);
    good.extend([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]);
    for name in ["signed oct", "signed oct fast"] {
        let got = common::assert_encodes_like(name, &bad, &good);
        assert!(
            got.iter().all(|&p| p >> 30 == 0),
            "{name}: A's bits must stay 0"
        );
        let nan = (codec(name).twin_encode)(glam::Vec3::new(f32::NAN, 0.0, 0.0));
        assert_eq!(nan, (codec(name).twin_encode)(glam::Vec3::Z));
        assert_eq!(nan & B_MASK, B_MASK, "{name}: +z writes B = 1023");
        let eq = (codec(name).twin_encode)(glam::Vec3::new(0.6, 0.8, -0.0));
        assert_eq!(eq & B_MASK, 0, "{name}: z = −0 writes B = 0");
    }
}

/// The rgb10a2unorm forms: `encode_normal_signed_oct_unorm` writes `u/1023, v/1023, B, 0` of the
/// twin's code, and `decode_normal_signed_oct_unorm` returns the code path's decode bit for bit
/// from exact channels, channels 3 ULPs off and 0.45 of a step off, each both ways (alpha
/// anything); the Rust forms likewise. Non-finite channels read from their bits, and B's sign is
/// O3DE's: B ≥ 512/1023 positive, B ≤ 511/1023 negative.
#[test]
fn render_target_form_matches_the_code_path() {
    common::assert_render_target_form(
        "signed oct",
        (
            "encode_normal_signed_oct_unorm",
            "decode_normal_signed_oct_unorm",
        ),
        RenderTarget::Rgb10a2SignedOct,
        (
            signed_oct::encode_normal_signed_oct_unorm,
            signed_oct::decode_normal_signed_oct_unorm,
        ),
    );
    let k = |x: u32| x as f32 / 1023.0;
    let channels: Vec<[f32; 4]> = vec![
        [f32::NAN, f32::INFINITY, 0.7, -3.0],
        [f32::NEG_INFINITY, -0.0, f32::INFINITY, f32::NAN],
        [k(300), k(700), k(511), 1.0],
        [k(300), k(700), k(512), 0.0],
        [k(300), k(700), -f32::NAN, 0.0],
    ];
    // The texels the channels round to (B = round(1023·0.7) = 716 for 0.7).
    let want = [
        M << 10 | 716 << 20,
        B_MASK,
        300 | 700 << 10 | 511 << 20,
        300 | 700 << 10 | 512 << 20,
        300 | 700 << 10,
    ];
    let got = common::run_kernel(
        NORMAL_SIGNED_OCT,
        "decode_normal_signed_oct_unorm",
        &[Arg::column(&channels)],
        channels.len() as u64,
    );
    for (i, c) in channels.iter().enumerate() {
        let w = signed_oct::decode_normal_signed_oct(want[i]);
        assert_eq!(signed_oct::decode_normal_signed_oct_unorm(*c), w, "{c:?}");
        assert_eq!(
            got.as_vec3()[i].map(f32::to_bits),
            w.to_array().map(f32::to_bits),
            "adapter: {c:?}"
        );
    }
}

/// O3DE's encoder (`peer_o3de_signed_oct_encode`: `EncodeNormalSignedOctahedron` and a
/// round-to-nearest RGB10A2 write) as the peer, and interop:
/// (1) its texels are `encode_normal_signed_oct_fast`'s words bit for bit (R, G and B; the word
/// is the texel since issue 60) on every direction whose nonzero components are at least 2^-100 (the same arithmetic;
/// nearer the subnormals O3DE's `z·FLT_MAX` meets values an adapter may flush);
/// (2) prepass reads its texels as O3DE's reader does (all 2^21 texels:
/// `decodes_every_code_as_o3de_reads_it`), here on the directions O3DE writes, within
/// [`o3de_read_deg`]; (3) prepass's precise codes, written as texels and read by O3DE's f32
/// reader, are within the precise bound plus that reader's error; (4) the precise encoder's
/// max and mean are no worse than O3DE's encoder's on the same directions (printed).
#[test]
fn o3de_encoder_is_the_peer() {
    let dirs: Vec<[f32; 3]> = fibonacci()
        .iter()
        .copied()
        .chain(adversarial_directions())
        .chain(equator_directions())
        .filter(|v| v.iter().all(|&x| x == 0.0 || x.abs() >= 2f32.powi(-100)))
        .collect();
    let n = dirs.len() as u64;
    let peer = common::run_kernel(
        PEER,
        "peer_o3de_signed_oct_encode",
        &[Arg::column(&dirs)],
        n,
    )
    .into_words();
    let fast = round_trip(gpu(), codec("signed oct fast"), &dirs).unwrap();
    let precise = round_trip(gpu(), codec("signed oct"), &dirs).unwrap();
    let differ: Vec<usize> = (0..dirs.len())
        .filter(|&i| {
            let (t, f) = (peer[i], fast.codes[i]);
            let b = (t >> 20) & 0x3ff;
            assert!(
                b == 0 || b == 0x3ff,
                "O3DE's B is 0 or 1023 here: {:?}",
                dirs[i]
            );
            t != f
        })
        .collect();
    assert!(
        differ.is_empty(),
        "{} of {n} directions where O3DE's writer and encode_normal_signed_oct_fast differ, \
         first {:?}: O3DE {:#x}, prepass {:#x}",
        differ.len(),
        differ.first().map(|&i| dirs[i]),
        differ.first().map_or(0, |&i| peer[i]),
        differ.first().map_or(0, |&i| fast.codes[i])
    );
    // (2) prepass's decoder on O3DE's texels against O3DE's reader.
    let ours = common::run_kernel(
        NORMAL_SIGNED_OCT,
        "decode_normal_signed_oct",
        &[Arg::column(&peer)],
        n,
    );
    let theirs = common::run_kernel(
        PEER,
        "peer_o3de_signed_oct_decode",
        &[Arg::column(&peer)],
        n,
    );
    let mut read_diff = 0f64;
    for i in 0..dirs.len() {
        let a = ours.as_vec3()[i];
        read_diff = read_diff.max(angle_degrees(widen3(a), widen3(theirs.as_vec3()[i])));
    }
    assert_within!(
        read_diff,
        o3de_read_deg(),
        "o3de_read_deg in this file",
        "prepass's and O3DE's reading of O3DE's texels, degrees"
    );
    // (3) prepass's precise words, stored as the texels they are, read by O3DE's reader.
    let read = common::run_kernel(
        PEER,
        "peer_o3de_signed_oct_decode",
        &[Arg::column(&precise.codes)],
        n,
    );
    let mut worst_read = 0f64;
    for (v, r) in dirs.iter().zip(read.as_vec3()) {
        worst_read = worst_read.max(angle_degrees(widen3(*v), widen3(*r)));
    }
    assert_within!(
        worst_read,
        precise_bound_deg() + o3de_read_deg(),
        "precise_bound_deg + o3de_read_deg in this file",
        "prepass's precise codes read by O3DE's reader, max degrees"
    );
    // (4) The figures, over the 2^20 Fibonacci directions (exact directions of the codes).
    let fib = fibonacci().len();
    let stats = |codes: &[u32], decode: &dyn Fn(u32) -> [f64; 3]| {
        let e: Vec<f64> = dirs[..fib]
            .iter()
            .zip(codes)
            .map(|(&v, &p)| angle_degrees(widen3(v), decode(p)))
            .collect();
        (
            e.iter().sum::<f64>() / e.len() as f64,
            e.iter().copied().fold(0f64, f64::max),
        )
    };
    let (pm, px) = stats(&precise.codes, &exact::decode);
    let (fm, fx) = stats(&fast.codes, &exact::decode);
    let (om, ox) = stats(&peer, &o3de_read_f64);
    eprintln!(
        "signed octahedron, 2^20 Fibonacci directions (f64 directions of the codes): prepass \
         precise mean {pm:.6}° max {px:.6}°, rounding mean {fm:.6}° max {fx:.6}°, O3DE's encoder \
         mean {om:.6}° max {ox:.6}° (bound {:.6}°); O3DE's reader of precise texels, all inputs, \
         max {worst_read:.6}°; prepass's and O3DE's f32 readers of O3DE's texels differ by at \
         most {read_diff:.3e}°",
        round_bound_deg()
    );
    assert!(
        px <= ox && pm <= om,
        "prepass's precise encoder (max {px}°, mean {pm}°) should err no more than O3DE's \
         (max {ox}°, mean {om}°)"
    );
    let precise_differ = (0..fib).filter(|&i| precise.codes[i] != peer[i]).count();
    let body = format!(
        "| form | engine | reads the engine's texels | writes |\n|---|---|---|---|\n\
         | `decode_normal_signed_oct` | O3DE (`DecodeNormalSignedOctahedron`, RGB10A2) | exact: every texel O3DE writes (B = 0 or 1023) in O3DE's direction to the decoder's rounding, and every B with O3DE's z sign (`reads_every_b_as_o3de_does`); O3DE's f32 reader within {read_diff:.2e}° on O3DE's texels here | — |\n\
         | `encode_normal_signed_oct_fast` | O3DE (`EncodeNormalSignedOctahedron` + a round-to-nearest RGB10A2 write) | — | the engine's texels: equal to O3DE's on every one of the {n} inputs (components 0 or at least 2^-100) |\n\
         | `encode_normal_signed_oct` | O3DE | — | prepass's precise code, O3DE's layout: differs from O3DE's texel on {precise_differ} of 2^20, max {px:.4}° (mean {pm:.4}°) against O3DE's writer's {ox:.4}° ({om:.4}°); O3DE's reader of these texels max {worst_read:.4}° |\n"
    );
    common::publish_measured("docs/figures.md", "interop-o3de", &body);
}
