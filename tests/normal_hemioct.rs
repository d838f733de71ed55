//! `wgsl/normal_hemioct.wgsl` (view-space normals, z ≥ 0, 24 bits) on the adapter: round trip
//! over the upper half of the tier's spherical-Fibonacci directions (2^20; 2^24 in the full tier) and the adversarial set against
//! the f64 reproduction, precise-encoder optimality, all 2^24 codes decoded, bad input and the
//! render-target form — against the Rust twin `src/normal/hemioct.rs`; and the vouched-input
//! encoders, the robust codes bit for bit on inputs across their contract.

mod common;

use common::{gpu, run_kernel};
use prepass::assert_within;
use prepass::harness::Arg;
use prepass::normal::hemioct;
use prepass::sweep::normal::{
    adversarial_directions, bad_inputs, codec, decode_range, fibonacci_directions,
    near_tie_directions, optimality_tolerance_deg, precise_optimality, reference_error, round_trip,
};

/// The upper half (`z ≥ 0`) of the tier's Fibonacci directions (`common::tier::fibonacci_set`:
/// 2^20, 2^24 in the full tier) and of the adversarial set.
fn upper_sets() -> [(&'static str, Vec<[f32; 3]>); 2] {
    let upper = |v: Vec<[f32; 3]>| v.into_iter().filter(|v| v[2] >= 0.0).collect();
    [
        ("fibonacci z >= 0", upper(common::tier::fibonacci_set().1)),
        ("adversarial z >= 0", upper(adversarial_directions())),
    ]
}

#[test]
fn round_trip_matches_the_f64_reproduction_and_is_optimal() {
    let sets = upper_sets();
    for name in common::HEMIOCTAHEDRAL {
        check(codec(name), &sets);
    }
}

/// The vouched encoders pass the robust ones' round-trip suite on their own (`check`: the WGSL
/// equals the vouched twin, the error agrees with the f64 reproduction, the precise choice is
/// optimal among its neighbours) over the same directions, all inside the vouched contract.
#[test]
fn vouched_encoders_round_trip_like_the_robust_ones() {
    let sets = upper_sets();
    for (set, inputs) in &sets {
        assert!(
            inputs.iter().all(|&n| hemioct::is_vouched(n.into())),
            "{set}"
        );
    }
    for name in common::HEMIOCTAHEDRAL {
        check(&common::vouched_codec(name), &sets);
    }
}

/// Round trip of `c` over `sets`: the WGSL equals the twins, the statistics agree with the f64
/// reproduction within the derived tolerance, and a precise encoder's choice is optimal.
fn check(c: &prepass::sweep::normal::Codec, sets: &[(&str, Vec<[f32; 3]>)]) {
    let name = c.name;
    for (set, inputs) in sets {
        let rt = round_trip(gpu(), c, inputs).unwrap();
        common::assert_round_trip_matches_twins(&format!("{name} {set}"), c, inputs, &rt);
        let r = reference_error(c, inputs);
        eprintln!(
            "{name} {set}: mean {:.6}° max {:.6}° (f64 reproduction {:.6} / {:.6})",
            rt.error.mean(),
            rt.error.max,
            r.mean(),
            r.max
        );
        // Bound: per input the f32 encoder's choice is within optimality_tolerance_deg of
        // the f64 choice (precise), or the same code up to f32 rounding of the continuous
        // coordinate (fast: 2^-24 relative of M, far below one code); decoding adds
        // √2·2^-24 rad. So the statistics agree within that tolerance.
        let tol = optimality_tolerance_deg();
        let why = "sweep::normal::optimality_tolerance_deg over the f64 reproduction (above)";
        assert_within!(rt.error.max, r.max + tol, why, "{name} {set}: max, degrees");
        assert_within!(
            rt.error.mean(),
            r.mean() + tol,
            why,
            "{name} {set}: mean, degrees"
        );
        if !name.ends_with("fast") {
            let o = precise_optimality(c, inputs, &rt);
            eprintln!(
                "  worst excess {:.3e}°, {} not the f64-best",
                o.worst_excess_deg, o.not_best
            );
            assert_within!(
                o.worst_excess_deg,
                tol,
                "sweep::normal::optimality_tolerance_deg",
                "{name} {set}: worst excess over the best neighbour at input {}",
                o.argworst
            );
        }
    }
}

#[test]
fn every_code_decodes_to_a_unit_vector_in_the_upper_hemisphere() {
    let c = codec("hemioct24");
    let d = decode_range(gpu(), c, 0, 1 << 24).unwrap();
    common::assert_decoder("hemioct24 all 2^24", &d);
    // z >= 0 for every code, and bits 24-31 are ignored.
    let codes: Vec<u32> = (0u32..1 << 16)
        .map(|i| i.wrapping_mul(0x9e37_79b9))
        .collect();
    let out = run_kernel(
        c.source,
        c.decode,
        &[Arg::column(&codes)],
        codes.len() as u64,
    );
    assert!(out.as_vec3().iter().all(|v| v[2] >= 0.0));
    common::assert_high_bits_ignored(c.source, c.decode, &codes, 0xff_ffff);
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let mut bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let mut good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    // Negative z clamps to the equator; straight down becomes the zero vector, so +z.
    bad.extend([
        [0.6, 0.0, -0.8],
        [0.0, 0.0, -1.0],
        [0.0, -f32::from_bits(1), -3.0],
    ]);
    good.extend([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]);
    for name in ["hemioct24", "hemioct24 fast"] {
        let got = common::assert_encodes_like(name, &bad, &good);
        assert!(
            got.iter().all(|&p| p >> 24 == 0),
            "{name}: byte 3 must stay 0"
        );
    }
}

#[test]
fn render_target_form_matches_the_code_path() {
    let inputs = common::render_target_inputs();
    common::assert_unorm_forms(
        "hemioct24",
        "encode_normal_hemioct24_unorm",
        "decode_normal_hemioct24_unorm",
        4,
        &inputs,
    );
    common::assert_twin_unorm_form(
        &inputs,
        hemioct::encode_normal_hemioct24_unorm,
        hemioct::decode_normal_hemioct24_unorm,
        hemioct::encode_normal_hemioct24,
        hemioct::decode_normal_hemioct24,
    );
}

/// 2^18 cells of near-tie directions (`sweep::normal::near_tie_directions`), 9 inputs each.
fn near_ties() -> Vec<[f32; 3]> {
    near_tie_directions(12, hemioct::M, hemioct::exact::decode, 1 << 18, 0x2112)
}

/// The precise encoder's WGSL equals the twin bit for bit where two candidates' scores nearly
/// tie, on an adapter that evaluates the scores as the twin does (see `tests/normal_oct.rs`,
/// `precise_encoders_equal_the_twin_at_near_ties`).
#[test]
fn precise_encoder_equals_the_twin_at_near_ties() {
    common::assert_near_ties(codec("hemioct24"), &near_ties());
}

/// The vouched precise encoder equals its twin where the candidates' scores nearly tie, as the
/// robust one does (`precise_encoder_equals_the_twin_at_near_ties`).
#[test]
fn vouched_precise_encoder_equals_the_twin_at_near_ties() {
    common::assert_near_ties(&common::vouched_codec("hemioct24"), &near_ties());
}

/// Inputs inside the vouched contract (`hemioct::is_vouched`) that the unit upper directions do
/// not reach: 2^16 Fibonacci directions of the whole sphere (`z < 0` is clamped, as the robust
/// encoders clamp it) scaled by powers of two across the contract (2^-120 … 2^124) and by 3 and
/// 0.3 (rounded), kept where still inside it (a scaled-down direction loses the components that
/// became subnormal); the same directions with `z` replaced by a negative of every size (the
/// contract lets a negative `z` be any finite value, and its scale is then `(x, y, 0)`'s); all
/// the near-tie directions; the adversarial set; and the contract's edges (components exactly
/// 2^-126 · max(1, ‖c‖∞), the largest exactly 2^124), with the zero vectors and the `−z`
/// half-axis, outside the contract, filtered out.
fn vouched_inputs() -> Vec<[f32; 3]> {
    let base = fibonacci_directions(1 << 16);
    let mut v: Vec<[f32; 3]> = Vec::new();
    for k in [-120, -100, -64, -20, -1, 0, 1, 3, 20, 64, 100, 123, 124] {
        let f = 2f32.powi(k);
        v.extend(base.iter().map(|n| n.map(|x| x * f)));
    }
    for f in [3.0f32, 0.3] {
        v.extend(base.iter().map(|n| n.map(|x| x * f)));
    }
    for (i, z) in [-f32::MAX, -1e30, -1.0, -1e-30, -f32::from_bits(1)]
        .into_iter()
        .enumerate()
    {
        let f = 2f32.powi([-110, -3, 0, 7, 120][i]);
        v.extend(base.iter().map(|n| [n[0] * f, n[1] * f, z]));
    }
    v.extend(near_ties());
    v.extend(adversarial_directions());
    let tiny = f32::MIN_POSITIVE;
    let big = prepass::normal::oct::VOUCHED_MAX;
    for sx in [1.0f32, -1.0] {
        for sz in [1.0f32, -1.0] {
            v.extend([
                [0.0 * sx, -0.0, 0.0 * sz],
                [0.0 * sx, -0.0, -sz.abs()],
                [tiny * sx, 1.0, 0.5 * sz],
                [tiny * sx, -tiny, sz],
                [big * sx, big, big * sz],
                [big * sx, tiny * 2f32.powi(124), sz * big * 0.5],
                [tiny * sx, 0.0, tiny * sz],
                [tiny * sx, 0.0, -big * sz.abs()],
                [0.5 * sx, 0.25, tiny * sz],
            ]);
        }
    }
    let before = v.len();
    v.retain(|&n| hemioct::is_vouched(n.into()));
    eprintln!(
        "vouched inputs: {} of {before} inside the contract",
        v.len()
    );
    v
}

/// Inside their contract the vouched encoders return the robust encoders' codes bit for bit:
/// the WGSL of each pair on the adapter (where it evaluates like the twins, the correctly
/// rounded case the identity is promised for; elsewhere the mismatches are only counted) and
/// the Rust twins, over `vouched_inputs` (scaled directions of both hemispheres, negative `z` of
/// every size, near ties, the contract's edges). So every bound of the robust encoders holds
/// for the vouched ones.
#[test]
fn vouched_encoders_give_the_robust_codes_inside_their_contract() {
    common::assert_vouched_codes_are_the_robust_ones(&common::HEMIOCTAHEDRAL, &vouched_inputs());
}

/// The encoders before issue 21 (continuous coordinates clamped to `[0, M]` and `floor`
/// clamped to `M − 1`; the lattice by halving `a ± b`; the score `common::old_sin2_to`), kept
/// verbatim as the reference the twins must equal bit for bit; the WGSL equals the twins (the
/// tests above).
mod replaced {
    use glam::{IVec3, UVec2, Vec2, Vec3};
    use prepass::normal::hemioct::{M, sanitize};

    fn continuous(s: Vec3) -> Vec2 {
        let l1 = (s.x.abs() + s.y.abs()) + s.z;
        let p = Vec2::new(s.x / l1, s.y / l1);
        let q = Vec2::new(p.x + p.y, p.x - p.y);
        (q * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::ONE) * M as f32
    }

    pub fn lattice(uv: UVec2) -> IVec3 {
        let m = M as i32;
        let a = 2 * uv.x as i32 - m;
        let b = 2 * uv.y as i32 - m;
        IVec3::new((a + b) / 2, (a - b) / 2, m - a.abs().max(b.abs()))
    }

    fn sin2(s: Vec3, uv: UVec2) -> f32 {
        crate::common::old_sin2_to(s, lattice(uv))
    }

    pub fn encode_precise(n: Vec3) -> u32 {
        let s = sanitize(n);
        let c = continuous(s);
        let base = UVec2::new(
            (c.x.floor() as u32).min(M - 1),
            (c.y.floor() as u32).min(M - 1),
        );
        let mut best = base;
        let mut best_s2 = sin2(s, base);
        for k in 1..4u32 {
            let cand = base + UVec2::new(k & 1, k >> 1);
            let s2 = sin2(s, cand);
            if s2 < best_s2 {
                best = cand;
                best_s2 = s2;
            }
        }
        best.x | (best.y << 12)
    }

    pub fn encode_round(n: Vec3) -> u32 {
        let c = continuous(sanitize(n));
        (c.x.round_ties_even() as u32) | ((c.y.round_ties_even() as u32) << 12)
    }
}

/// Issue 21's encoders (continuous coordinates stopping below M, no clamp of `floor`, the
/// lattice as `(u + v − M, u − v, M − |x| − |y|)`) return the codes of the ones they replaced
/// for every input tried: the tier's Fibonacci directions (both hemispheres: z < 0 is clamped),
/// the adversarial set, the bad inputs, 2^20 random vectors in [−1, 1]^3 and 2^20 random f32 bit
/// patterns (2^22 each in the full tier) and the near-tie directions; and the lattice equals the old one on all 2^24 codes.
/// CPU only (no adapter): the twins.
#[test]
fn encoders_equal_the_ones_they_replaced() {
    // 2^20 random vectors of each kind in the default tier, 2^22 in the full tier (the rule of
    // `common::tier::fibonacci_log2`).
    let r = common::tier::by_tier(20, 22);
    let (cube, raw) = common::random_cube_and_bits(0x21, 1 << r);
    let bad: Vec<[f32; 3]> = bad_inputs().iter().map(|c| c.0).collect();
    let (fib_label, fib) = common::tier::fibonacci_set();
    let labels = [format!("random cube 2^{r}"), format!("random bits 2^{r}")];
    let sets: [(&str, Vec<[f32; 3]>); 6] = [
        (&fib_label, fib),
        ("adversarial", adversarial_directions()),
        ("bad inputs", bad),
        (&labels[0], cube),
        (&labels[1], raw),
        ("near ties", near_ties()),
    ];
    for (set, inputs) in &sets {
        let differ: Vec<usize> = (0..inputs.len())
            .filter(|&i| {
                let v = glam::Vec3::from(inputs[i]);
                hemioct::encode_normal_hemioct24(v) != replaced::encode_precise(v)
                    || hemioct::encode_normal_hemioct24_fast(v) != replaced::encode_round(v)
            })
            .collect();
        assert!(
            differ.is_empty(),
            "{set}: {} inputs encode differently, first {:?} ({:?})",
            differ.len(),
            differ.first(),
            differ.first().map(|&i| inputs[i])
        );
    }
    for p in 0u32..1 << 24 {
        let uv = glam::UVec2::new(p & 0xfff, p >> 12);
        assert_eq!(hemioct::lattice(uv), replaced::lattice(uv), "code {p:#x}");
    }
}
