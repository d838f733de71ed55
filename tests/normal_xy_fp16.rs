//! `wgsl/normal_xy_fp16.wgsl` (Killzone 2's view-space xy as two FP16 in RGBA8) on the adapter:
//! round trip over the tier's spherical-Fibonacci directions (2^20; 2^24 in the full tier) (split at z = 0) and the adversarial set,
//! a stratified 2^26 sample of the 2^32 codes decoded, the perspective "myth" measured, bad input
//! and the render-target form — against the Rust twin `src/normal/xy_fp16.rs` and f64.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::normal::{F32_SLACK_DEG, xy_fp16};
use prepass::sweep::normal::{
    UNIT_TOLERANCE, adversarial_directions, bad_inputs, codec, decode_codes, killzone_myth,
    round_trip, stratified_codes32,
};
use prepass::{assert_at_least, assert_within, assert_within_abs};

#[test]
fn round_trip_upper_hemisphere_and_the_mirror_below() {
    let c = codec("xy fp16");
    for (set, inputs) in [
        common::tier::fibonacci_set(),
        ("adversarial".to_string(), adversarial_directions()),
    ] {
        let set = set.as_str();
        let rt = round_trip(gpu(), c, &inputs).unwrap();
        eprintln!(
            "xy fp16 {set}: z >= 0 mean {:.6}° max {:.6}° (bound {:.4}°); all mean {:.3}° max {:.3}°",
            rt.error_upper.mean(),
            rt.error_upper.max,
            xy_fp16::max_angle_upper_deg(),
            rt.error.mean(),
            rt.error.max
        );
        common::assert_round_trip_matches_twins(set, c, &inputs, &rt);
        assert_within!(
            rt.error_upper.max,
            xy_fp16::max_angle_upper_deg() + F32_SLACK_DEG,
            "normal::xy_fp16::max_angle_upper_deg() + normal::F32_SLACK_DEG",
            "{set}: z >= 0 max degrees at input {}",
            rt.error_upper.argmax
        );
        // Below z = 0 the decode is the mirror image: error 2·asin(|z|), checked per input
        // (the f16 rounding moves it by at most the upper bound).
        for (i, v) in inputs
            .iter()
            .enumerate()
            .filter(|(_, v)| v[2] < 0.0)
            .step_by(97)
        {
            let want = 2.0 * f64::from(-v[2]).min(1.0).asin().to_degrees();
            let got = prepass::precision::metrics::angle_degrees(
                v.map(f64::from),
                rt.decoded[i].map(f64::from),
            );
            assert_within_abs!(
                got,
                want,
                xy_fp16::max_angle_upper_deg() + F32_SLACK_DEG,
                "the mirror's 2·asin(|z|), moved ≤ max_angle_upper_deg() + F32_SLACK_DEG (normal::xy_fp16)",
                "{v:?}: degrees"
            );
        }
    }
}

/// Resistance 2's "viewspace normal myth", measured through Killzone 2's encoding: off the
/// optical axis a visible surface can face away from the view axis (z < 0), and xy FP16 then
/// decodes its mirror image.
#[test]
fn perspective_myth_negative_z_is_visible_and_decodes_mirrored() {
    let normals = 1024;
    for fov in [60.0, 90.0] {
        let m = killzone_myth(gpu(), fov, 16, normals).unwrap();
        eprintln!("{m:?}");
        // An even grid has no pixel on the axis: every pixel can see a normal with z < 0.
        assert_eq!(m.pixels_with_negative_z, m.pixels);
        // Fibonacci sampling of the lune between the two hemispheres: each boundary point is
        // within one point spacing s = √(4π/N) (N = sphere points) of a sample, so the fraction
        // is off by at most the boundary band's share, 2s·(2π)/(2π) = 2s.
        let s = (4.0 * std::f64::consts::PI / f64::from(2 * normals)).sqrt();
        assert_within_abs!(
            m.visible_fraction_negative_z,
            m.visible_fraction_analytic,
            2.0 * s,
            "comment above: the boundary band's share, 2s (s the Fibonacci spacing)",
            "fov {fov}°: visible fraction with z < 0"
        );
        // The worst sampled error approaches 2θ at the corner pixel (θ its angle off axis),
        // never exceeds the screen corner's 2θ by more than the f16 bound, and is at least the
        // corner pixel centre's 2θ less the sample spacing (twice: the mirror doubles it).
        let t = (fov / 2.0f64).to_radians().tan();
        let corner_px = (2f64.sqrt() * t * 15.0 / 16.0).atan().to_degrees();
        assert_within!(
            m.worst_error_deg,
            m.worst_error_analytic_deg + xy_fp16::max_angle_upper_deg(),
            "comment above: the screen corner's 2θ + xy_fp16::max_angle_upper_deg()",
            "fov {fov}°: worst sampled error, degrees"
        );
        assert_at_least!(
            m.worst_error_deg,
            2.0 * corner_px - 2.0 * s.to_degrees(),
            "comment above: the corner pixel's 2θ less twice the sample spacing",
            "fov {fov}°: worst sampled error, degrees"
        );
    }
}

#[test]
fn stratified_codes_decode_to_unit_vectors() {
    let c = codec("xy fp16");
    // All 2^32 do not fit the suite's budget on lavapipe; the full sweep is
    // sweep::normal::decode_all_32. NaN, Inf and out-of-range halves are in the sample.
    let mut codes = stratified_codes32();
    for h in [
        0x7c00u32, 0xfc00, 0x7e00, 0xfe01, 0x3c01, 0xbc01, 0x7bff, 0x0001, 0x8000,
    ] {
        for o in [0u32, 0x3c00, 0xbc00, 0x7c00, 0x7e00, 0x3bff] {
            codes.push(h | (o << 16));
            codes.push(o | (h << 16));
        }
    }
    let d = decode_codes(gpu(), c, &codes).unwrap();
    eprintln!(
        "xy fp16 stratified: {} codes, max |len-1| {:.3e}, twin differs {}",
        d.codes, d.max_len_error, d.twin.count
    );
    // The twins' promise: bit identity and UNIT_TOLERANCE where the adapter evaluates like
    // them; on any conforming adapter, unit within UNIT_TOLERANCE_CONFORMING.
    if common::evaluates_like_the_twins() {
        assert_eq!(d.not_unit, 0, "not unit within {UNIT_TOLERANCE}");
        assert_eq!(d.twin.count, 0, "{:?}", d.twin.first);
    } else {
        use prepass::sweep::conforming::UNIT_TOLERANCE_CONFORMING;
        assert_within!(
            d.max_len_error,
            UNIT_TOLERANCE_CONFORMING,
            "sweep::conforming::UNIT_TOLERANCE_CONFORMING",
            "xy fp16 stratified: |len − 1|"
        );
    }
    // The f64 reference decode of the same half pair: the f32 path's rounding only (sqrt of a
    // value with ≤ 3 roundings, then normalise): ≤ 2^-11 rad is generous and far below an f16 step.
    assert_within!(
        d.max_angle_deg,
        2f64.powi(-11).to_degrees(),
        "comment above: ≤ 3 roundings, sqrt and normalise; 2^-11 rad is generous",
        "xy fp16 stratified: max angle to the f64 decode, degrees"
    );
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("xy fp16", &bad, &good);
    assert_eq!(xy_fp16::encode_normal_xy_fp16(Vec3::ZERO), 0);
    // Decoder: NaN halves count as 0, infinities clamp.
    assert_eq!(xy_fp16::decode_normal_xy_fp16(0x7e00_7e00), Vec3::Z);
    assert_eq!(xy_fp16::decode_normal_xy_fp16(0x0000_fc00), Vec3::NEG_X);
}

#[test]
fn render_target_form_matches_the_code_path() {
    let inputs = common::render_target_inputs();
    common::assert_unorm_forms(
        "xy fp16",
        "encode_normal_xy_fp16_unorm",
        "decode_normal_xy_fp16_unorm",
        4,
        &inputs,
    );
    common::assert_twin_unorm_form(
        &inputs,
        xy_fp16::encode_normal_xy_fp16_unorm,
        xy_fp16::decode_normal_xy_fp16_unorm,
        xy_fp16::encode_normal_xy_fp16,
        xy_fp16::decode_normal_xy_fp16,
    );
}
