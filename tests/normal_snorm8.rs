//! `wgsl/normal_snorm8.wgsl` on the adapter: round trip over 2^24 spherical-Fibonacci directions
//! and the adversarial set, all 2^24 codes decoded (−128 read as −127, as the format defines),
//! bad input, the rgba8snorm form, and interop with Unity URP's `R8G8B8A8_SNorm` normals —
//! against the Rust twin `src/normal/snorm8.rs` and f64 references.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::assert_within;
use prepass::normal::snorm8;
use prepass::precision::metrics::angle_degrees;
use prepass::sweep::normal::{RenderTarget, bad_inputs, codec, decode_codes, decode_range};

#[test]
fn round_trip_meets_the_bound_and_twin_is_bit_identical() {
    let rt = common::assert_linear_round_trip(
        "snorm8",
        0xff_ffff,
        snorm8::max_angle_deg(),
        "normal::snorm8::max_angle_deg(), asin(√3/254)",
    );
    assert!(
        rt.codes
            .iter()
            .all(|p| p.to_le_bytes()[..3].iter().all(|&b| b != 0x80)),
        "the encoder never writes −128"
    );
}

#[test]
fn every_code_decodes_to_a_unit_vector_and_byte_3_is_ignored() {
    let c = codec("snorm8");
    let d = decode_range(gpu(), c, 0, 1 << 24).unwrap();
    let junk: Vec<u32> = (0u32..1 << 16)
        .map(|p| (p * 251) & 0xff_ffff | (p << 24))
        .collect();
    let dj = decode_codes(gpu(), c, &junk).unwrap();
    for (name, d) in [("all 2^24", &d), ("byte 3 junk", &dj)] {
        common::assert_decoder(&format!("snorm8 {name}"), d);
    }
    common::assert_high_bits_ignored(c.source, c.decode, &junk, 0xff_ffff);
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("snorm8", &bad, &good);
    assert_eq!(snorm8::encode_normal_snorm8(Vec3::ZERO), 0x007f_0000);
}

#[test]
fn render_target_form_matches_the_code_path() {
    common::assert_render_target_form(
        "snorm8",
        ("encode_normal_snorm8_snorm", "decode_normal_snorm8_snorm"),
        RenderTarget::Rgba8Snorm,
        (
            snorm8::encode_normal_snorm8_snorm,
            snorm8::decode_normal_snorm8_snorm,
        ),
    );
    assert_eq!(
        snorm8::decode_normal_snorm8_snorm([f32::NAN, f32::NEG_INFINITY, 2.0, 0.5]),
        snorm8::decode_normal_snorm8(0x7f81 << 8)
    );
}

/// Interop with Unity URP, whose shader writes a unit `n` to an `R8G8B8A8_SNorm` target (the
/// format stores `round(127·n)`) and reads `max(b/127, −1)`: (1) prepass's encoder writes URP's
/// bytes for unit inputs, except where URP's own value lies within `RENORMALISE_CHANNEL` of a
/// rounding tie; (2) every code but the zero vector (where URP's normalise gives NaN and prepass
/// +z) decodes in the direction URP reads.
#[test]
fn reads_and_writes_urps_snorm_normals() {
    common::assert_writes_like_the_engine("snorm8", |n| n, &[(0, 8), (8, 8), (16, 8)], 127.0, true);
    // (2) The adapter's decode is within decode_angle_deg of exact::decode (checked over every
    // code by every_code_decodes_...), so it suffices that URP's reading is that direction.
    let mut worst = 0f64;
    for p in 0u32..1 << 24 {
        match snorm8::exact::engine_decode(p) {
            Some(u) => worst = worst.max(angle_degrees(snorm8::exact::decode(p), u)),
            None => assert_eq!(p, 0, "only the zero vector has no direction"),
        }
    }
    assert_eq!(snorm8::exact::decode(0), [0.0, 0.0, 1.0]);
    assert_within!(
        worst,
        1e-12,
        "the f64 angle's own rounding (about 1e-15°), as in sweep::normal::decode_angle_deg",
        "angle between the code's direction and URP's max(b/127, −1), degrees"
    );
}
