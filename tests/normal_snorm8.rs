//! `wgsl/normal_snorm8.wgsl` on the adapter: round trip over 2^24 spherical-Fibonacci directions
//! and the adversarial set, all 2^24 codes decoded (−128 read as −127, as the format defines),
//! bad input, the rgba8snorm form, and interop with Unity URP's `R8G8B8A8_SNorm` normals —
//! against the Rust twin `src/normal/snorm8.rs` and f64 references.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::assert_within;
use prepass::normal::{F32_SLACK_DEG, snorm8};
use prepass::precision::metrics::angle_degrees;
use prepass::sweep::normal::interop::{RENORMALISE_CHANNEL, engine_write};
use prepass::sweep::normal::{
    RenderTarget, adversarial_directions, bad_inputs, codec, decode_codes, decode_range,
    fibonacci_directions, render_target_forms, round_trip,
};

#[test]
fn round_trip_meets_the_bound_and_twin_is_bit_identical() {
    let c = codec("snorm8");
    for (set, inputs) in [
        ("fibonacci 2^24", fibonacci_directions(1 << 24)),
        ("adversarial", adversarial_directions()),
    ] {
        let rt = round_trip(gpu(), c, &inputs).unwrap();
        eprintln!(
            "snorm8 {set}: mean {:.6}° max {:.6}° (bound {:.4}°)",
            rt.error.mean(),
            rt.error.max,
            snorm8::max_angle_deg()
        );
        common::assert_round_trip_matches_twins(set, c, &inputs, &rt);
        assert_eq!(rt.error.nan_count, 0);
        assert!(rt.codes.iter().all(|p| p >> 24 == 0), "byte 3 stays zero");
        assert!(
            rt.codes
                .iter()
                .all(|p| [p & 0xff, (p >> 8) & 0xff, (p >> 16) & 0xff]
                    .iter()
                    .all(|&b| b != 0x80)),
            "the encoder never writes −128"
        );
        assert_within!(
            rt.error.max,
            snorm8::max_angle_deg() + F32_SLACK_DEG,
            "normal::snorm8::max_angle_deg(), asin(√3/254), + normal::F32_SLACK_DEG",
            "{set}: max degrees at input {}",
            rt.error.argmax
        );
    }
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
    let inputs = common::render_target_inputs();
    let c = codec("snorm8");
    let f = render_target_forms(
        gpu(),
        c,
        "encode_normal_snorm8_snorm",
        "decode_normal_snorm8_snorm",
        RenderTarget::Rgba8Snorm,
        &inputs,
    )
    .unwrap();
    assert_eq!(f.encode.count, 0, "channels: {:?}", f.encode.first);
    // Bound: 0. Every channel is within 0.45/127 of b/127, so round(127 c) is the byte.
    assert_eq!(f.decode.count, 0, "decode: {:?}", f.decode.first);
    common::assert_twin_unorm_form(
        &inputs,
        snorm8::encode_normal_snorm8_snorm,
        snorm8::decode_normal_snorm8_snorm,
        snorm8::encode_normal_snorm8,
        snorm8::decode_normal_snorm8,
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
    let c = codec("snorm8");
    let inputs = fibonacci_directions(1 << 20);
    let rt = round_trip(gpu(), c, &inputs).unwrap();
    let (mut ties, mut differ) = (0u64, Vec::new());
    for (n, &p) in inputs.iter().zip(&rt.codes) {
        let engine = engine_write(*n, 127.0, true);
        for (k, e) in engine.iter().enumerate() {
            let ours = i64::from(((p >> (8 * k)) & 0xff) as u8 as i8);
            match e {
                None => ties += 1,
                Some(e) if *e != ours => differ.push((*n, p)),
                _ => {}
            }
        }
    }
    eprintln!("snorm8 interop: {ties} lanes within the tie window of {RENORMALISE_CHANNEL:e}");
    assert!(
        differ.is_empty(),
        "{} inputs where prepass writes other bytes than URP's round(127·n), away from a tie \
         (window: sweep::normal::interop::RENORMALISE_CHANNEL); first {:?}",
        differ.len(),
        differ.first()
    );
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
