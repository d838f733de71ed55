//! `wgsl/normal_xyz10.wgsl` on the adapter: round trip over 2^24 spherical-Fibonacci directions
//! and the adversarial set, 2^24 of the 2^30 codes decoded (a stride through all of them, and
//! every code built from the edge values of each field), bad input, the rgb10a2unorm form, and
//! interop with Unreal's and Bevy's `n·0.5 + 0.5` — against the Rust twin `src/normal/xyz10.rs`
//! and f64 references.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::assert_within;
use prepass::normal::xyz10;
use prepass::precision::metrics::angle_degrees;
use prepass::sweep::normal::{RenderTarget, bad_inputs, codec, decode_codes};

/// 2^24 codes: a stride through all 2^30 (an odd step visits distinct codes and every field
/// value), then every code whose fields are each one of {0, 1, 511, 512, 1022, 1023}.
fn sampled_codes() -> Vec<u32> {
    let edges = [0u32, 1, 511, 512, 1022, 1023];
    let mut codes: Vec<u32> = (0u32..1 << 24)
        .map(|i| i.wrapping_mul(0x2f_f8a5) & 0x3fff_ffff)
        .collect();
    for x in edges {
        for y in edges {
            for z in edges {
                codes.push(x | (y << 10) | (z << 20));
            }
        }
    }
    codes
}

#[test]
fn round_trip_meets_the_bound_and_twin_is_bit_identical() {
    common::assert_linear_round_trip(
        "xyz10",
        0x3fff_ffff,
        xyz10::max_angle_deg(),
        "normal::xyz10::max_angle_deg(), asin(√3/1023)",
    );
}

#[test]
fn sampled_codes_decode_to_unit_vectors_and_the_alpha_bits_are_ignored() {
    let c = codec("xyz10");
    let codes = sampled_codes();
    let d = decode_codes(gpu(), c, &codes).unwrap();
    let junk: Vec<u32> = (0u32..1 << 16)
        .map(|p| (p.wrapping_mul(0x9e37_79b9) & 0x3fff_ffff) | (p << 30))
        .collect();
    let dj = decode_codes(gpu(), c, &junk).unwrap();
    for (name, d) in [("2^24 sampled", &d), ("alpha junk", &dj)] {
        common::assert_decoder(&format!("xyz10 {name}"), d);
    }
    common::assert_high_bits_ignored(c.source, c.decode, &junk, 0x3fff_ffff);
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("xyz10", &bad, &good);
    // +z: fields round(511.5) = 512 (half to even), 512, 1023.
    assert_eq!(xyz10::encode_normal_xyz10(Vec3::ZERO), 0x3ff8_0200);
}

#[test]
fn render_target_form_matches_the_code_path() {
    common::assert_render_target_form(
        "xyz10",
        ("encode_normal_xyz10_unorm", "decode_normal_xyz10_unorm"),
        RenderTarget::Rgb10a2Unorm,
        (
            xyz10::encode_normal_xyz10_unorm,
            xyz10::decode_normal_xyz10_unorm,
        ),
    );
    assert_eq!(
        xyz10::decode_normal_xyz10_unorm([f32::NAN, f32::INFINITY, -1.0, 0.5]),
        xyz10::decode_normal_xyz10(0x3ff << 10)
    );
}

/// Interop with Unreal's GBufferA and Bevy's prepass, which write `n·0.5 + 0.5` of a unit `n` to
/// an rgb10a2unorm target and read `normalize(c·2 − 1)`: (1) prepass's encoder writes the
/// engines' codes for unit inputs, except where the engine's own value lies within
/// `RENORMALISE_CHANNEL` of a rounding tie (there the format may round either way); (2) every
/// code decodes with prepass in the direction the engines' decoder gives, to the decoder's
/// rounding.
#[test]
fn reads_and_writes_the_engines_rgb10a2_normals() {
    common::assert_writes_like_the_engine(
        "xyz10",
        |n| n.map(|x| x * 0.5 + 0.5),
        &[(0, 10), (10, 10), (20, 10)],
        1023.0,
        false,
    );
    // (2) The adapter's decode is within decode_angle_deg of exact::decode (checked over these
    // codes by sampled_codes_decode_to_unit_vectors...), so it suffices that the engines'
    // reading is the same direction in f64.
    let worst = sampled_codes()
        .iter()
        .map(|&p| angle_degrees(xyz10::exact::decode(p), xyz10::exact::engine_decode(p)))
        .fold(0f64, f64::max);
    assert_within!(
        worst,
        1e-12,
        "the f64 angle's own rounding (about 1e-15°), as in sweep::normal::decode_angle_deg",
        "angle between the code's direction and the engines' normalize(c·2 − 1), degrees"
    );
}
