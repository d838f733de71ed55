//! `wgsl/normal_hemioct.wgsl` (view-space normals, z ≥ 0, 24 bits) on the adapter: round trip
//! over the upper half of 2^24 spherical-Fibonacci directions and the adversarial set against
//! the f64 reproduction, precise-encoder optimality, all 2^24 codes decoded, bad input and the
//! render-target form — against the Rust twin `src/normal/hemioct.rs`.

mod common;

use common::{gpu, run_kernel};
use prepass::assert_within;
use prepass::harness::Arg;
use prepass::normal::hemioct;
use prepass::sweep::normal::{
    adversarial_directions, bad_inputs, codec, decode_range, fibonacci_directions,
    optimality_tolerance_deg, precise_optimality, reference_error, round_trip,
};

#[test]
fn round_trip_matches_the_f64_reproduction_and_is_optimal() {
    let upper: Vec<[f32; 3]> = fibonacci_directions(1 << 24)
        .into_iter()
        .filter(|v| v[2] >= 0.0)
        .collect();
    let adv: Vec<[f32; 3]> = adversarial_directions()
        .into_iter()
        .filter(|v| v[2] >= 0.0)
        .collect();
    for name in ["hemioct24", "hemioct24 fast"] {
        let c = codec(name);
        for (set, inputs) in [("fibonacci z >= 0", &upper), ("adversarial z >= 0", &adv)] {
            let rt = round_trip(gpu(), c, inputs).unwrap();
            common::assert_round_trip_matches_twins(&format!("{name} {set}"), &rt);
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
    for (i, v) in out.as_vec3().iter().enumerate() {
        assert!(v[2] >= 0.0);
        assert_eq!(
            *v,
            hemioct::decode_normal_hemioct24(codes[i] & 0xff_ffff).to_array()
        );
    }
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
