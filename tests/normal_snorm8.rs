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

/// URP's depth-normals writer, transcribed: the fragment writes
/// `half4(NormalizeNormalPerPixel(normalWS), 0)` (com.unity.render-pipelines.universal
/// `Shaders/DepthNormalsPass.hlsl`, `DepthNormalsFragment`, outside `_GBUFFER_NORMALS_OCT`) to
/// the R8G8B8A8_SNorm target, which stores `round(127·clamp(c, −1, 1))` (ties away from zero
/// here; the format leaves them to the implementation). `normalize` in f32 as `n/√(n·n)`, and
/// `half4` as f32 (desktop; where `half` is f16 the channels round to f16 first, not modelled).
fn urp_write(n: [f32; 3]) -> u32 {
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let b = n.map(|c| ((c / l).clamp(-1.0, 1.0) * 127.0).round() as i32 as u32 & 0xff);
    b[0] | (b[1] << 8) | (b[2] << 16)
}

/// URP's reader in f64: `LoadSceneNormals`/`SampleSceneNormals` (`ShaderLibrary/
/// DeclareNormalsTexture.hlsl`) return the sampled channels as they are, which the SNorm format
/// gives as `max(b/127, −1)`; their direction (None for the zero vector, which has none).
fn urp_read_f64(p: u32) -> Option<[f64; 3]> {
    let c = [p, p >> 8, p >> 16].map(|b| (f64::from(b as u8 as i8) / 127.0).max(-1.0));
    let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    (l > 0.0).then(|| c.map(|a| a / l))
}

/// URP's R8G8B8A8_SNorm normals, both ways, from URP's code transcribed above (issue 60):
/// - **reads exact:** every 2^24 texel but the zero vector (URP's reader has no direction there;
///   prepass reads +z) decodes with `decode_normal_snorm8` on the adapter in URP's direction, to
///   the decoder's rounding;
/// - **writes:** over `common::interop_directions`, `encode_normal_snorm8` on the adapter and
///   URP's writer are compared texel for texel (published as `interop-urp-snorm`, with each one's
///   max error as URP reads it); every texel that differs is one where URP's `127·c` lies within
///   `sweep::normal::interop::RENORMALISE_CHANNEL` of a half (a tie the two roundings may break
///   apart).
#[test]
fn urp_snorm_texel_both_ways() {
    use prepass::harness::Arg;
    use prepass::precision::metrics::widen3;
    use prepass::sweep::normal::interop::RENORMALISE_CHANNEL;
    use prepass::wgsl::NORMAL_SNORM8;
    let texels: Vec<u32> = (0..1u32 << 24)
        .map(|p| p | ((p * 59) & 0xff) << 24)
        .collect();
    let worst_read = common::assert_reads_like_the_engine(
        NORMAL_SNORM8,
        "decode_normal_snorm8",
        &texels,
        |p| {
            let u = urp_read_f64(p);
            assert!(
                u.is_some() || p & 0xff_ffff == 0,
                "only the zero vector has no direction"
            );
            u
        },
        "URP's reader (f64)",
    );
    let dirs = common::interop_directions();
    let m = dirs.len() as u64;
    let ours: Vec<u32> = common::run_kernel(
        NORMAL_SNORM8,
        "encode_normal_snorm8",
        &[Arg::column(&dirs)],
        m,
    )
    .into_words()
    .into_iter()
    .map(|p| p & 0xff_ffff)
    .collect();
    let urp: Vec<u32> = dirs.iter().map(|&v| urp_write(v)).collect();
    let err = |w: &[u32]| {
        dirs.iter()
            .zip(w)
            .map(|(v, &p)| angle_degrees(widen3(*v), urp_read_f64(p).unwrap()))
            .fold(0f64, f64::max)
    };
    let differ: Vec<usize> = (0..dirs.len()).filter(|&i| ours[i] != urp[i]).collect();
    let fib = differ.iter().filter(|&&i| i < 1 << 20).count();
    for &i in &differ {
        let v = dirs[i].map(f64::from);
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let near_tie = v
            .iter()
            .any(|c| ((127.0 * c / l).abs().fract() - 0.5).abs() <= RENORMALISE_CHANNEL * 127.0);
        assert!(
            near_tie,
            "{:?}: prepass {:#08x}, URP {:#08x}, away from a tie (window RENORMALISE_CHANNEL)",
            dirs[i], ours[i], urp[i]
        );
    }
    let (eu, eo) = (err(&urp), err(&ours));
    let body = format!(
        "| form | engine | reads the engine's texels | writes |\n|---|---|---|---|\n\
         | `decode_normal_snorm8` | Unity URP depth-normals, R8G8B8A8_SNorm (`LoadSceneNormals`) | exact: every texel but the zero vector (no direction to URP; +z to prepass) within {worst_read:.2e}° of URP's reading (f64) | — |\n\
         | `encode_normal_snorm8` | URP (`DepthNormalsFragment`: the normalised normal, the target's rounding) | — | URP's texels but at ties: differs from URP's writer on {fib} of 2^20 ({} of all {m} inputs, each with a channel within 2^-22 of a tie); max {eo:.4}° read by URP against URP's writer's {eu:.4}° |\n",
        differ.len()
    );
    eprintln!("{body}");
    common::publish_measured("docs/figures.md", "interop-urp-snorm", &body);
}
