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

/// Bevy's normal prepass writer, transcribed: `out.normal = vec4(normal·0.5 + vec3(0.5), 1.0)`
/// (bevy_pbr `src/prepass/prepass.wgsl`, `fragment`; the normal as the material gives it, not
/// renormalised where no normal map is applied) to the `Rgb10a2Unorm` target
/// (`NORMAL_PREPASS_FORMAT`), which stores `round(1023·clamp(c, 0, 1))` per channel (ties away
/// from zero here; the format leaves them to the implementation) and alpha 1 as 3 in bits 30–31.
fn bevy_prepass_write(n: [f32; 3]) -> u32 {
    let k = n.map(|x| ((x * 0.5 + 0.5).clamp(0.0, 1.0) * 1023.0).round() as u32);
    k[0] | (k[1] << 10) | (k[2] << 20) | (3 << 30)
}

/// Bevy's reader in f64: `prepass_normal` (bevy_pbr `src/prepass/prepass_utils.wgsl`):
/// `normalize(c·2 − 1)` of the loaded channels `c = k/1023`; alpha ignored.
fn bevy_prepass_read_f64(p: u32) -> [f64; 3] {
    let c = [p, p >> 10, p >> 20].map(|k| f64::from(k & 0x3ff) / 1023.0 * 2.0 - 1.0);
    let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    c.map(|a| a / l)
}

/// Bevy's normal prepass, both ways, from Bevy's code transcribed above (issue 60):
/// - **reads exact:** the 2^24 sampled texels ([`sampled_codes`], alpha 3 as Bevy writes it)
///   decode with `decode_normal_xyz10` on the adapter in Bevy's direction, to the decoder's
///   rounding;
/// - **writes:** over `common::interop_directions` (made unit) and the same at length 0.9
///   (an interpolated normal Bevy writes unnormalised), `encode_normal_xyz10` on the adapter and
///   Bevy's writer are compared: on unit inputs x, y, z differ only where Bevy's `1023·c` lies
///   within `RENORMALISE_CHANNEL`·1023 of a half; prepass writes alpha 0 where Bevy writes 3;
///   on the shortened inputs prepass normalises first, so its max error read by Bevy's reader is
///   no more than Bevy's own. Published as `interop-bevy-prepass`.
#[test]
fn bevy_normal_prepass_both_ways() {
    use prepass::harness::Arg;
    use prepass::precision::metrics::widen3;
    use prepass::sweep::normal::interop::RENORMALISE_CHANNEL;
    use prepass::wgsl::NORMAL_XYZ10;
    let texels: Vec<u32> = sampled_codes().iter().map(|p| p | (3 << 30)).collect();
    let worst_read = common::assert_reads_like_the_engine(
        NORMAL_XYZ10,
        "decode_normal_xyz10",
        &texels,
        |p| Some(bevy_prepass_read_f64(p)),
        "Bevy's prepass_normal (f64)",
    );
    // Made unit in f64 (the adversarial set's folds are not), each component rounded once.
    let unit: Vec<[f32; 3]> = common::interop_directions()
        .iter()
        .map(|v| {
            let w = v.map(f64::from);
            let l = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
            w.map(|x| (x / l) as f32)
        })
        .collect();
    let short: Vec<[f32; 3]> = unit.iter().map(|v| v.map(|x| x * 0.9)).collect();
    let fib = 1usize << 20;
    let mut rows = Vec::new();
    for (label, dirs) in [("unit inputs", &unit), ("inputs of length 0.9", &short)] {
        let m = dirs.len() as u64;
        let ours = common::run_kernel(NORMAL_XYZ10, "encode_normal_xyz10", &[Arg::column(dirs)], m)
            .into_words();
        let bevy: Vec<u32> = dirs.iter().map(|&v| bevy_prepass_write(v)).collect();
        let err = |w: &[u32]| {
            dirs.iter()
                .zip(w)
                .map(|(v, &p)| angle_degrees(widen3(*v), bevy_prepass_read_f64(p)))
                .fold(0f64, f64::max)
        };
        let rgb = 0x3fff_ffff;
        let differ: Vec<usize> = (0..dirs.len())
            .filter(|&i| ours[i] & rgb != bevy[i] & rgb)
            .collect();
        let alpha = (0..dirs.len())
            .filter(|&i| ours[i] >> 30 != bevy[i] >> 30)
            .count();
        if label == "unit inputs" {
            for &i in &differ {
                let near_tie = dirs[i].iter().any(|&x| {
                    let c = 1023.0 * (f64::from(x) * 0.5 + 0.5);
                    (c.fract() - 0.5).abs() <= RENORMALISE_CHANNEL * 1023.0
                });
                assert!(
                    near_tie,
                    "{:?}: prepass {:#010x}, Bevy {:#010x}, away from a tie",
                    dirs[i], ours[i], bevy[i]
                );
            }
        }
        let (eb, eo) = (err(&bevy), err(&ours));
        if label != "unit inputs" {
            assert!(
                eo <= eb,
                "{label}: prepass's max {eo}° read by Bevy exceeds Bevy's writer's {eb}°"
            );
        }
        rows.push(format!(
            "on {label}, x, y, z differ from Bevy's writer on {} of 2^20 ({} of all {m} inputs), alpha on {alpha}; max {eo:.4}° read by Bevy against Bevy's writer's {eb:.4}°",
            differ.iter().filter(|&&i| i < fib).count(),
            differ.len()
        ));
    }
    let body = format!(
        "| form | engine | reads the engine's texels | writes |\n|---|---|---|---|\n\
         | `decode_normal_xyz10` | Bevy normal prepass, Rgb10a2Unorm (`prepass_normal`) | exact: 2^24 sampled texels (a stride through all 2^30, alpha 3) within {worst_read:.2e}° of Bevy's reader (f64), alpha ignored | — |\n\
         | `encode_normal_xyz10` | Bevy (`prepass.wgsl` `fragment`: `normal·0.5 + 0.5`, alpha 1) | — | prepass normalises first and writes alpha 0 (bits 30–31) where Bevy writes 3; {}; {} |\n",
        rows[0], rows[1]
    );
    eprintln!("{body}");
    common::publish_measured("docs/figures.md", "interop-bevy-prepass", &body);
}
