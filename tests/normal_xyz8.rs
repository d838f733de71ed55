//! `wgsl/normal_xyz8.wgsl` on the adapter: round trip over 2^24 spherical-Fibonacci directions
//! and the adversarial set, all 2^24 codes decoded, bad input and the render-target form —
//! against the Rust twin `src/normal/xyz8.rs` and f64 references.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::assert_within;
use prepass::normal::xyz8;
use prepass::sweep::normal::{bad_inputs, codec, decode_codes, decode_range};

#[test]
fn round_trip_meets_target_and_twin_is_bit_identical() {
    let rt = common::assert_linear_round_trip(
        "xyz8",
        0xff_ffff,
        xyz8::max_angle_deg(),
        "normal::xyz8::max_angle_deg(), asin(√3/255)",
    );
    // The rule: no worse than its float64 reproduction by more than 2%.
    let (mean_t, max_t) = codec("xyz8").target.unwrap();
    let rule = "Codec::target: within 2% of the f64 reproduction (comment above)";
    assert_within!(
        rt.error.mean(),
        mean_t * 1.02,
        rule,
        "fibonacci 2^24: mean degrees"
    );
    assert_within!(
        rt.error.max,
        max_t * 1.02,
        rule,
        "fibonacci 2^24: max degrees"
    );
}

#[test]
fn every_code_decodes_to_a_unit_vector_and_byte_3_is_ignored() {
    let c = codec("xyz8");
    let d = decode_range(gpu(), c, 0, 1 << 24).unwrap();
    let junk: Vec<u32> = (0u32..1 << 16)
        .map(|p| (p * 251) & 0xff_ffff | (p << 24))
        .collect();
    let dj = decode_codes(gpu(), c, &junk).unwrap();
    for (name, d) in [("all 2^24", &d), ("byte 3 junk", &dj)] {
        common::assert_decoder(&format!("xyz8 {name}"), d);
    }
    common::assert_high_bits_ignored(c.source, c.decode, &junk, 0xff_ffff);
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("xyz8", &bad, &good);
    // +z: bytes round(127.5) = 128 (half to even), 128, 255.
    assert_eq!(xyz8::encode_normal_xyz8(Vec3::ZERO), 0x00ff_8080);
}

#[test]
fn render_target_form_matches_the_code_path() {
    let inputs = common::render_target_inputs();
    common::assert_unorm_forms(
        "xyz8",
        "encode_normal_xyz8_unorm",
        "decode_normal_xyz8_unorm",
        4,
        &inputs,
    );
    common::assert_twin_unorm_form(
        &inputs,
        xyz8::encode_normal_xyz8_unorm,
        xyz8::decode_normal_xyz8_unorm,
        xyz8::encode_normal_xyz8,
        xyz8::decode_normal_xyz8,
    );
    assert_eq!(
        xyz8::decode_normal_xyz8_unorm([f32::NAN, 2.0, -1.0, 0.5]),
        xyz8::decode_normal_xyz8(0x0000_ff00)
    );
}
