//! `wgsl/roughness_ggx.wgsl` on the adapter: GGX perceptual roughness in 8 bits — linear `r` as
//! Bevy, Unreal, HDRP, URP and Substrate store it, Godot's 7 bits + dynamic flag, and the log-r
//! curve — bit-identical to the twins (`src/roughness_ggx.rs`) over every code and a dense grid
//! of inputs, interoperable with the engines' own formulas (`tests/baselines/
//! roughness_ggx_engines.wgsl`), and measured where a renderer sees the roughness: `α`, the GGX
//! peak `1/(π α²)` and the whole lobe over `(n·h, α)`, beside prepass's log-range specular power
//! mapped to `α` and a searched alternative curve. Publishes docs/figures.md's `roughness-ggx`.

mod common;

use common::run_kernel;
use prepass::harness::Arg;
use prepass::roughness_ggx::{self as ggx, bounds, exact};
use prepass::wgsl::ROUGHNESS_GGX;
use prepass::{assert_at_least, assert_within, assert_within_abs};

const ENGINES: &str = include_str!("baselines/roughness_ggx_engines.wgsl");
const U: f64 = 1.0 / 16_777_216.0; // 2^-24, unit roundoff of f32

/// A WGSL function's name and its twin.
type Decoder = (&'static str, fn(u32) -> f32);
type Encoder = (&'static str, fn(f32) -> u32);
/// A decoder and how far from its twin it may land.
type DecoderWithin = (&'static str, fn(u32) -> f32, f64);
/// A render-target function's name, its twin, and the byte form it writes or reads.
type UnormEncoder = (&'static str, fn(f32) -> f32, fn(f32) -> u32);
type UnormDecoder = (&'static str, fn(f32) -> f32, fn(u32) -> f32);

/// Codes a decoder is run on: every byte, then out-of-range codes.
fn all_codes() -> Vec<u32> {
    (0..=255u32)
        .chain([256, 257, 1000, 1 << 31, u32::MAX])
        .collect()
}

/// Encoder inputs: every 61st `f32` in `[0, 1]` (odd stride: every code, at many significands),
/// every `f32` within 64 ULP of every boundary of the three curves (where an encoder can go
/// wrong), and the bad inputs.
fn encoder_inputs() -> Vec<f32> {
    let mut v: Vec<f32> = (0..=0x3f80_0000u32)
        .step_by(61)
        .map(f32::from_bits)
        .collect();
    let mut near = |b: f64| {
        let c = (b as f32).to_bits() as i64;
        for d in -64..=64 {
            let x = f32::from_bits((c + d).clamp(0, 0x3f80_0000) as u32);
            v.push(x);
        }
    };
    for j in 0..255 {
        near((f64::from(j) + 0.5) / 255.0);
        near((f64::from(2 * j + 1) * 6.0 / 510.0 - 6.0).exp2());
    }
    for j in 0..127 {
        near((f64::from(j) + 0.5) / 127.0);
    }
    v.extend([
        f32::NAN,
        -f32::NAN,
        f32::from_bits(0x7f80_0001),
        f32::INFINITY,
        f32::NEG_INFINITY,
        -0.0,
        -1.0,
        -f32::MIN_POSITIVE,
        f32::from_bits(1),
        f32::from_bits(0x007f_ffff),
        1.0,
        1.5,
        f32::MAX,
        0.5,
        1.0 / 64.0,
    ]);
    v
}

/// The log curve's code boundaries `2^((2j + 1)·6/510 − 6)` in `f64`, for an exact encoder by
/// bisection (the reference `exact::log_code` searches linearly; both are checked below).
fn log_boundaries() -> Vec<f64> {
    (0..255)
        .map(|j| (f64::from(2 * j + 1) * 6.0 / 510.0 - 6.0).exp2())
        .collect()
}

fn log_code_fast(b: &[f64], r: f32) -> u32 {
    if r.is_nan() || r >= 1.0 {
        return 255;
    }
    if r <= 1.0 / 64.0 {
        return 0;
    }
    b.partition_point(|&t| t <= f64::from(r)) as u32
}

/// A WGSL table (`var<private> NAME: array<u32, N> = array<u32, N>(…);`) as numbers.
fn wgsl_table(name: &str) -> Vec<u32> {
    let start = ROUGHNESS_GGX
        .find(&format!("var<private> {name}"))
        .unwrap_or_else(|| panic!("{name} not in roughness_ggx.wgsl"));
    let body = &ROUGHNESS_GGX[start..];
    let body = &body[body.find(">(").unwrap() + 2..body.find(");").unwrap()];
    body.split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| u32::from_str_radix(s.trim_start_matches("0x").trim_end_matches('u'), 16).unwrap())
        .collect()
}

#[test]
fn wgsl_tables_are_the_log_range_tables() {
    assert_eq!(
        wgsl_table("GGX_LOG_EXP2_STEPS"),
        prepass::roughness::EXP2_STEPS.to_vec()
    );
    assert_eq!(
        wgsl_table("GGX_LOG_BOUNDARY_STEPS"),
        prepass::roughness::BOUNDARY_STEPS.to_vec()
    );
}

/// Every code through every decoder on the adapter: bit-identical to the twin, and against the
/// exact value — linear `b/255` and the log curve correctly rounded, Godot within
/// `bounds::GODOT_DECODE` of `k/127`, the flag bit 7.
#[test]
fn every_code_decodes_like_the_twin_and_the_exact_value() {
    let codes = all_codes();
    let n = codes.len() as u64;
    let run = |f: &str| run_kernel(ROUGHNESS_GGX, f, &[Arg::column(&codes)], n);
    let twins: [Decoder; 5] = [
        ("decode_roughness_ggx8", ggx::decode_roughness_ggx8),
        (
            "decode_roughness_ggx8_alpha",
            ggx::decode_roughness_ggx8_alpha,
        ),
        ("decode_roughness_godot8", ggx::decode_roughness_godot8),
        ("decode_roughness_ggx8_log", ggx::decode_roughness_ggx8_log),
        (
            "decode_roughness_ggx8_log_alpha",
            ggx::decode_roughness_ggx8_log_alpha,
        ),
    ];
    for (name, twin) in twins {
        let got = run(name);
        for (&c, &g) in codes.iter().zip(got.as_f32()) {
            assert_eq!(g.to_bits(), twin(c).to_bits(), "{name}({c}): adapter {g:e}");
            assert!(g.is_finite());
        }
    }
    for &c in &codes {
        let b = c.min(255);
        let lin = exact::linear_value(b, 255);
        assert_eq!(ggx::decode_roughness_ggx8(c), lin as f32, "code {c}");
        let a = f64::from(ggx::decode_roughness_ggx8_alpha(c));
        assert_within!(
            (a - lin * lin).abs(),
            3.0 * U * lin * lin,
            "two roundings of 2^-24, the first doubled by the square (bounds in the twin's docs)",
            "decode_roughness_ggx8_alpha({c})"
        );
        assert_eq!(
            ggx::decode_roughness_ggx8_log(c),
            exact::log_value(b) as f32,
            "code {c}"
        );
        let k = if b > 127 { 255 - b } else { b };
        assert_within!(
            (f64::from(ggx::decode_roughness_godot8(c)) - f64::from(k) / 127.0).abs(),
            bounds::GODOT_DECODE,
            "bounds::GODOT_DECODE (c's rounding kept by 1 − c, the constant's and the quotient's)",
            "decode_roughness_godot8({c}) against k/127"
        );
    }
    let flags = run("roughness_godot8_is_dynamic");
    for (&c, &f) in codes.iter().zip(flags.as_u32()) {
        assert_eq!(f, u32::from(c.min(255) >= 128), "code {c}");
        assert_eq!(f, ggx::roughness_godot8_is_dynamic(c));
    }
}

/// Every encoder on the grid of [`encoder_inputs`] on the adapter: bit-identical to the twin,
/// and the twin is the exact nearest code. On the CPU, every `f32` in `[0, 1]` (all 1 065 353 217
/// of them) for the linear encoders, every 7th for the log curve.
#[test]
fn encoders_give_the_exact_code_on_the_adapter_and_every_f32_in_the_twin() {
    let rs = encoder_inputs();
    let n = rs.len() as u64;
    let lb = log_boundaries();
    let lin = run_kernel(
        ROUGHNESS_GGX,
        "encode_roughness_ggx8",
        &[Arg::column(&rs)],
        n,
    );
    let log = run_kernel(
        ROUGHNESS_GGX,
        "encode_roughness_ggx8_log",
        &[Arg::column(&rs)],
        n,
    );
    for (i, &r) in rs.iter().enumerate() {
        let want = ggx::encode_roughness_ggx8(r);
        assert_eq!(lin.as_u32()[i], want, "encode_roughness_ggx8({r:e})");
        assert_eq!(want, exact::linear_code(f64::from(r), 255), "r {r:e}");
        let want = ggx::encode_roughness_ggx8_log(r);
        assert_eq!(log.as_u32()[i], want, "encode_roughness_ggx8_log({r:e})");
        assert_eq!(want, log_code_fast(&lb, r), "r {r:e}");
    }
    for flag in [0u32, 1, 0x8000_0000] {
        let got = run_kernel(
            ROUGHNESS_GGX,
            "encode_roughness_godot8",
            &[Arg::column(&rs), Arg::splat_u32(flag)],
            n,
        );
        for (i, &r) in rs.iter().enumerate() {
            let want = ggx::encode_roughness_godot8(r, flag);
            assert_eq!(
                got.as_u32()[i],
                want,
                "encode_roughness_godot8({r:e}, {flag})"
            );
            let k = exact::linear_code(f64::from(r), 127);
            assert_eq!(want, if flag != 0 { 255 - k } else { k }, "r {r:e}");
        }
    }
    // The references agree with each other where both are cheap.
    for &r in rs.iter().step_by(97) {
        assert_eq!(
            exact::log_code(f64::from(r)),
            log_code_fast(&lb, r),
            "r {r:e}"
        );
    }
    // Every f32 in [0, 1] on the CPU.
    let mut wrong = 0u64;
    for bits in 0..=0x3f80_0000u32 {
        let r = f32::from_bits(bits);
        let x = f64::from(r);
        wrong += u64::from(ggx::encode_roughness_ggx8(r) != exact::linear_code(x, 255));
        wrong += u64::from(ggx::encode_roughness_godot8(r, 0) != exact::linear_code(x, 127));
        if bits % 7 == 0 {
            wrong += u64::from(ggx::encode_roughness_ggx8_log(r) != log_code_fast(&lb, r));
        }
    }
    assert_eq!(wrong, 0, "twin codes that are not the exact nearest code");
}

/// The render-target forms: the channel an encoder writes is a byte's exact `b/255`
/// (`unpack4x8unorm`, rounded back to the same byte), and a sampled channel anywhere within
/// ±0.49/255 of `b/255` — or `unpack4x8unorm`'s 3-ULP neighbours — decodes like the byte.
#[test]
fn render_target_forms_round_trip_on_the_adapter() {
    let rs: Vec<f32> = encoder_inputs().into_iter().step_by(16).collect();
    let n = rs.len() as u64;
    let enc: [UnormEncoder; 2] = [
        (
            "encode_roughness_ggx8_unorm",
            ggx::encode_roughness_ggx8_unorm,
            ggx::encode_roughness_ggx8,
        ),
        (
            "encode_roughness_ggx8_log_unorm",
            ggx::encode_roughness_ggx8_log_unorm,
            ggx::encode_roughness_ggx8_log,
        ),
    ];
    for (name, twin, code) in enc {
        let got = run_kernel(ROUGHNESS_GGX, name, &[Arg::column(&rs)], n);
        for (&r, &c) in rs.iter().zip(got.as_f32()) {
            let b = code(r);
            assert_within!(
                (f64::from(c) - f64::from(b) / 255.0).abs(),
                3.0 * 2.0 * U,
                "unpack4x8unorm's 3 ULP (values ≤ 1: an ULP ≤ 2^-23)",
                "{name}({r:e})"
            );
            assert_eq!((c * 255.0).round() as u32, b, "{name}({r:e}): channel {c}");
            assert_eq!(twin(r).to_bits(), (b as f32 / 255.0).to_bits());
        }
    }
    for flag in [0u32, 1] {
        let got = run_kernel(
            ROUGHNESS_GGX,
            "encode_roughness_godot8_unorm",
            &[Arg::column(&rs), Arg::splat_u32(flag)],
            n,
        );
        for (&r, &c) in rs.iter().zip(got.as_f32()) {
            let b = ggx::encode_roughness_godot8(r, flag);
            assert_eq!((c * 255.0).round() as u32, b, "godot8_unorm({r:e}, {flag})");
            assert_eq!(
                ggx::encode_roughness_godot8_unorm(r, flag),
                b as f32 / 255.0
            );
        }
    }
    // Sampled channels: each byte's value, ±0.49/255, and ±3 ULP.
    let mut cs = Vec::new();
    let mut bytes = Vec::new();
    for b in 0..=255u32 {
        let c = b as f32 / 255.0;
        for x in [
            c,
            c + 0.49 / 255.0,
            c - 0.49 / 255.0,
            f32::from_bits(c.to_bits() + 3),
            f32::from_bits(c.to_bits().saturating_sub(3)),
        ] {
            cs.push(x);
            bytes.push(b);
        }
    }
    let n = cs.len() as u64;
    let dec: [UnormDecoder; 3] = [
        (
            "decode_roughness_ggx8_unorm",
            ggx::decode_roughness_ggx8_unorm,
            ggx::decode_roughness_ggx8,
        ),
        (
            "decode_roughness_godot8_unorm",
            ggx::decode_roughness_godot8_unorm,
            ggx::decode_roughness_godot8,
        ),
        (
            "decode_roughness_ggx8_log_unorm",
            ggx::decode_roughness_ggx8_log_unorm,
            ggx::decode_roughness_ggx8_log,
        ),
    ];
    for (name, twin, byte) in dec {
        let got = run_kernel(ROUGHNESS_GGX, name, &[Arg::column(&cs)], n);
        for ((&c, &b), &g) in cs.iter().zip(&bytes).zip(got.as_f32()) {
            assert_eq!(g.to_bits(), byte(b).to_bits(), "{name}({c:e}) for byte {b}");
            assert_eq!(twin(c).to_bits(), g.to_bits(), "{name}({c:e}): twin");
        }
    }
}

/// Interoperability with the engines' own formulas, run on the adapter
/// (`tests/baselines/roughness_ggx_engines.wgsl`):
/// - every byte an engine can write decodes with prepass exactly as the engine decodes it
///   (Bevy's `f32(b)/255`; a unorm8 texture read, `b/255` correctly rounded; Godot's
///   `normal_roughness_compatibility` on that channel, flag included);
/// - prepass's encoders' bytes decode with the engines' decoders within the stated bound
///   (`1/510` for 8 bits, `1/254 + GODOT_DECODE` for Godot, plus the decode's rounding), and
///   prepass's codes are never farther from `r` than the engine's own.
///
/// The counts of sampled `r` where an engine's encoder picks another byte than prepass's are
/// printed.
#[test]
fn engines_bytes_and_prepass_bytes_interoperate() {
    let src = format!("{ROUGHNESS_GGX}\n{ENGINES}");
    let bytes: Vec<u32> = (0..=255).collect();
    let channels: Vec<f32> = bytes.iter().map(|&b| b as f32 / 255.0).collect();
    let nb = bytes.len() as u64;
    // Decoders, byte by byte.
    let bevy = run_kernel(
        &src,
        "engine_bevy_roughness_read",
        &[Arg::column(&bytes)],
        nb,
    );
    let target = run_kernel(
        &src,
        "engine_unorm8_target_read",
        &[Arg::column(&bytes)],
        nb,
    );
    let godot = run_kernel(
        &src,
        "engine_godot_roughness_read",
        &[Arg::column(&channels)],
        nb,
    );
    let ours = run_kernel(&src, "decode_roughness_ggx8", &[Arg::column(&bytes)], nb);
    let ours_godot = run_kernel(&src, "decode_roughness_godot8", &[Arg::column(&bytes)], nb);
    let mut unpack_differs = 0;
    for (b, &channel) in channels.iter().enumerate() {
        let mine = ours.as_f32()[b];
        assert_eq!(
            mine.to_bits(),
            bevy.as_f32()[b].to_bits(),
            "Bevy's read of byte {b}"
        );
        assert_eq!(
            mine,
            (b as f64 / 255.0) as f32,
            "a unorm8 texture read of byte {b} (correctly rounded)"
        );
        let t = target.as_f32()[b];
        unpack_differs += usize::from(t.to_bits() != mine.to_bits());
        assert_within!(
            (f64::from(t) - f64::from(mine)).abs(),
            3.0 * 2.0 * U,
            "unpack4x8unorm's 3 ULP allowance (values ≤ 1)",
            "unpack4x8unorm of byte {b} against decode_roughness_ggx8"
        );
        assert_eq!(
            ours_godot.as_f32()[b].to_bits(),
            godot.as_f32()[b].to_bits(),
            "Godot's read of byte {b}"
        );
        assert_eq!(
            ggx::roughness_godot8_is_dynamic(b as u32) == 1,
            channel > 0.5,
            "Godot's flag test (c > 0.5) on byte {b}"
        );
    }
    eprintln!("unpack4x8unorm differs from b/255 on {unpack_differs} of 256 bytes here");
    // Encoders over the grid.
    let rs: Vec<f32> = (0..=0x3f80_0000u32)
        .step_by(61)
        .map(f32::from_bits)
        .collect();
    let n = rs.len() as u64;
    let bevy_w = run_kernel(&src, "engine_bevy_roughness_write", &[Arg::column(&rs)], n);
    let target_w = run_kernel(&src, "engine_unorm8_target_write", &[Arg::column(&rs)], n);
    let (mut bevy_diff, mut target_diff, mut godot_diff) = (0, 0, 0);
    let (mut ours_max, mut bevy_max) = (0.0f64, 0.0f64);
    for (i, &r) in rs.iter().enumerate() {
        let x = f64::from(r);
        let b = ggx::encode_roughness_ggx8(r);
        let e = (f64::from(bevy.as_f32()[b as usize]) - x).abs();
        ours_max = ours_max.max(e);
        assert_within!(
            e,
            bounds::linear_half_step(255) + U,
            "bounds::linear_half_step(255) = 1/510, + the decode's rounding (≤ 2^-25 of a value ≤ 1, doubled for margin)",
            "Bevy's decoder on prepass's byte for r = {r:e}"
        );
        let eb = bevy_w.as_u32()[i];
        bevy_max = bevy_max.max((f64::from(eb) / 255.0 - x).abs());
        bevy_diff += usize::from(eb != b);
        target_diff += usize::from(target_w.as_u32()[i] != b);
    }
    assert_within!(
        ours_max,
        bevy_max,
        "prepass's encoder is at least as accurate as the engine's (exact nearest byte)",
        "max |decode(encode(r)) − r|, prepass against Bevy's encoder"
    );
    for flag in [0u32, 1] {
        let gw = run_kernel(
            &src,
            "engine_godot_roughness_write",
            &[Arg::column(&rs), Arg::splat_u32(flag)],
            n,
        );
        for (i, &r) in rs.iter().enumerate() {
            let b = ggx::encode_roughness_godot8(r, flag);
            godot_diff += usize::from(gw.as_u32()[i] != b);
            let e = (f64::from(godot.as_f32()[b as usize]) - f64::from(r)).abs();
            assert_within!(
                e,
                bounds::linear_half_step(127) + bounds::GODOT_DECODE,
                "bounds::linear_half_step(127) = 1/254 + bounds::GODOT_DECODE",
                "Godot's decoder on prepass's byte for r = {r:e}, flag {flag}"
            );
            assert_eq!(
                channels[b as usize] > 0.5,
                flag != 0,
                "flag survives, r = {r:e}"
            );
        }
    }
    eprintln!(
        "of {} sampled r: Bevy's encoder differs from prepass's on {bevy_diff}, the unorm8 \
         target rounding on {target_diff}, Godot's (static + dynamic) on {godot_diff}",
        rs.len()
    );
}

/// URP's smoothness and Unreal Substrate's truncated byte (issue 60, findings 3 and 4), against
/// the engines' own formulas on the adapter (`tests/baselines/roughness_ggx_engines.wgsl`,
/// transcribed from `UnityGBuffer.hlsl`/`CommonMaterial.hlsl` and Unreal's `PackR8`/`UnpackR8`):
/// - URP: every byte reads with `decode_roughness_urp8` as URP's `1 − s` does, within `2^-24`
///   (prepass rounds `(255 − b)/255` once; URP rounds `b/255`, then `1 − s`), where
///   `decode_roughness_ggx8` reads `1 − r` (the finding, printed); prepass's bytes read by URP's
///   reader are within `1/510` of `r`, and URP's own bytes differ from prepass's on the printed
///   count of the grid;
/// - Substrate: every byte reads with `decode_roughness_substrate8` bit for bit as `UnpackR8`
///   (and differs from `b/255` on the printed count), and `encode_roughness_substrate8` writes
///   `PackR8`'s bytes bit for bit over the grid, the boundaries and `r = 0.618034` (157, where
///   the nearest byte is 158); the twins agree with the adapter.
#[test]
fn urp_smoothness_and_substrate_bytes_are_the_engines() {
    let src = format!("{ROUGHNESS_GGX}\n{ENGINES}");
    let bytes: Vec<u32> = (0..=255).collect();
    let nb = bytes.len() as u64;
    let run = |f: &str, a: &[u32]| run_kernel(&src, f, &[Arg::column(a)], a.len() as u64);
    let urp_read = run("engine_urp_smoothness_read", &bytes);
    let ours_urp = run("decode_roughness_urp8", &bytes);
    let plain = run("decode_roughness_ggx8", &bytes);
    let ue_read = run("engine_substrate_roughness_read", &bytes);
    let ours_ue = run("decode_roughness_substrate8", &bytes);
    let mut ulp_apart = 0;
    // UnpackR8's worst relative error over the bytes: above one rounding's 2^-24, so the
    // promise needs both roundings (its rustdoc).
    let mut worst_substrate_rel = 0.0f64;
    for b in 0..nb as usize {
        let (u, o) = (urp_read.as_f32()[b], ours_urp.as_f32()[b]);
        assert_within!(
            (f64::from(u) - f64::from(o)).abs(),
            U,
            "URP's 1 − fl(b/255) rounds twice (2^-25 each, values ≤ 1), prepass's (255 − b)/255 once",
            "URP's read of smoothness byte {b} against decode_roughness_urp8"
        );
        assert_eq!(
            o.to_bits(),
            ggx::decode_roughness_urp8(b as u32).to_bits(),
            "twin, byte {b}"
        );
        let (e, m) = (ue_read.as_f32()[b], ours_ue.as_f32()[b]);
        assert_eq!(m.to_bits(), e.to_bits(), "Unreal's UnpackR8 of byte {b}");
        assert_eq!(
            m.to_bits(),
            ggx::decode_roughness_substrate8(b as u32).to_bits(),
            "twin, byte {b}"
        );
        let exact = b as f64 / 255.0;
        if b > 0 {
            worst_substrate_rel = worst_substrate_rel.max((f64::from(m) - exact).abs() / exact);
        }
        assert_within_abs!(
            f64::from(m),
            exact,
            exact * ggx::bounds::SUBSTRATE_DECODE_REL,
            "roughness_ggx::bounds::SUBSTRATE_DECODE_REL, relative (two f32 roundings)",
            "decode_roughness_substrate8's promise, byte {b}"
        );
        ulp_apart += usize::from(m.to_bits() != plain.as_f32()[b].to_bits());
    }
    assert_at_least!(
        worst_substrate_rel,
        > 2f64.powi(-24),
        "one f32 rounding, 2^-24: decode_roughness_substrate8's rustdoc says some byte exceeds it",
        "UnpackR8's worst relative error over the 256 bytes"
    );
    let mut rs: Vec<f32> = (0..=0x3f80_0000u32)
        .step_by(61)
        .map(f32::from_bits)
        .collect();
    for j in 0..=255 {
        let c = (j as f32 / 255.0).to_bits() as i64;
        rs.extend((-8..=8).map(|d| f32::from_bits((c + d).clamp(0, 0x3f80_0000) as u32)));
    }
    rs.push(0.618_034);
    let n = rs.len() as u64;
    let col = |f: &str| run_kernel(&src, f, &[Arg::column(&rs)], n).into_words();
    let (urp_w, ours_w, ue_w, ours_ue_w) = (
        col("engine_urp_smoothness_write"),
        col("encode_roughness_urp8"),
        col("engine_substrate_roughness_write"),
        col("encode_roughness_substrate8"),
    );
    let (mut urp_diff, mut ue_vs_nearest) = (0, 0);
    for (i, &r) in rs.iter().enumerate() {
        let b = ours_w[i];
        assert_eq!(b, ggx::encode_roughness_urp8(r), "twin, r = {r:e}");
        assert_within!(
            (f64::from(urp_read.as_f32()[b as usize]) - f64::from(r)).abs(),
            bounds::linear_half_step(255) + U,
            "bounds::linear_half_step(255) = 1/510, + URP's read's rounding (≤ 2^-24)",
            "URP's reader on prepass's smoothness byte for r = {r:e}"
        );
        urp_diff += usize::from(urp_w[i] != b);
        assert_eq!(ours_ue_w[i], ue_w[i], "Unreal's PackR8 of r = {r:e}");
        assert_eq!(
            ours_ue_w[i],
            ggx::encode_roughness_substrate8(r),
            "twin, r = {r:e}"
        );
        ue_vs_nearest += usize::from(ue_w[i] != ggx::encode_roughness_ggx8(r));
    }
    let last = rs.len() - 1;
    assert_eq!(
        (ue_w[last], ggx::encode_roughness_ggx8(0.618_034)),
        (157, 158),
        "the issue's r = 0.618034"
    );
    // Over uniform r (the grid above is every 61st f32, most of them tiny): 2^20 cell centres.
    let uniform = (0..1u32 << 20)
        .map(|i| (i as f32 + 0.5) / 1_048_576.0)
        .filter(|&r| ggx::encode_roughness_substrate8(r) != ggx::encode_roughness_ggx8(r))
        .count();
    let r3 = ggx::encode_roughness_urp8(0.3);
    eprintln!(
        "URP: r = 0.3 writes smoothness byte {r3}, read back {} by decode_roughness_urp8 and {} by \
         decode_roughness_ggx8 (the finding); URP's writer differs from prepass's on {urp_diff} of \
         {n} sampled r. Substrate: UnpackR8 differs from b/255 on {ulp_apart} of 256 bytes; PackR8 \
         differs from the nearest byte on {ue_vs_nearest} of {n} sampled r, {uniform} of 2^20 \
         uniform r",
        ggx::decode_roughness_urp8(r3),
        ggx::decode_roughness_ggx8(r3)
    );
    let body = format!(
        "| form | engine | reads the engine's bytes | writes |\n|---|---|---|---|\n\
         | `decode_roughness_urp8` | URP GBuffer2 alpha (smoothness) | `(255 − b)/255`: within 2^-24 of URP's `1 − b/255` on all 256 bytes (one rounding against URP's two) | — |\n\
         | `encode_roughness_urp8` | URP | — | the nearest byte (exact): differs from URP's target-rounded `1 − r` on {urp_diff} of {n} sampled `r` |\n\
         | `decode_roughness_substrate8` | Unreal Substrate (`UnpackR8`) | the engine's value bit for bit on all 256 bytes (`b·(1/255)`, which differs from `b/255` on {ulp_apart}) | — |\n\
         | `encode_roughness_substrate8` | Unreal Substrate (`PackR8`) | — | the engine's bytes bit for bit on all {n} sampled `r` (truncation: below the nearest byte on {ue_vs_nearest} of them, {uniform} of 2^20 uniform `r`) |\n"
    );
    common::publish_measured("docs/figures.md", "interop-roughness", &body);
    assert!(
        ue_vs_nearest > 0 && ulp_apart > 0,
        "the findings: truncation and the reciprocal"
    );
}

/// One 8-bit curve, as a renderer reads it: each code's roughness, and the cell of `r` each code
/// takes (`bounds[k]` is the boundary between codes `k` and `k + 1`).
struct Curve {
    value: Vec<f64>,
    bound: Vec<f64>,
}

impl Curve {
    fn power(gamma: f64) -> Self {
        Curve {
            value: (0..=255)
                .map(|k| (f64::from(k) / 255.0).powf(gamma))
                .collect(),
            bound: (0..255)
                .map(|k| ((f64::from(k) + 0.5) / 255.0).powf(gamma))
                .collect(),
        }
    }
    fn log(lo: f64) -> Self {
        Curve {
            value: (0..=255)
                .map(|k| lo.powf(1.0 - f64::from(k) / 255.0))
                .collect(),
            bound: (0..255)
                .map(|k| lo.powf(1.0 - (f64::from(k) + 0.5) / 255.0))
                .collect(),
        }
    }
}

/// Worst errors over `r ∈ [r_min, 1]` where the renderer clamps both the true and the decoded
/// roughness to `r_min` (as Bevy's `clamp(r, 0.089, 1)` and Unreal's `max(r, View.MinRoughness)`
/// do).
#[derive(Clone, Copy, Debug, Default)]
struct Errors {
    /// max `|α − α̂|`.
    alpha: f64,
    /// max relative error of the peak `1/(π α²)`.
    peak: f64,
    /// max relative error of `D(n·h, α)` over every `n·h` ([`bounds::lobe_relative`]).
    lobe: f64,
}

impl Errors {
    fn add(&mut self, r: f64, rh: f64, r_min: f64) {
        let (a, ah) = (r * r, rh.max(r_min).powi(2));
        self.alpha = self.alpha.max((a - ah).abs());
        self.peak = self.peak.max(((a / ah).powi(2) - 1.0).abs());
        self.lobe = self.lobe.max(bounds::lobe_relative(a, ah));
    }
}

/// The supremum over the continuum: each metric grows with `|r − r̂|` on either side of a code's
/// value, so its worst in a cell is at an end of the cell (clipped to `[r_min, 1]`).
fn cell_sup(c: &Curve, r_min: f64) -> Errors {
    let mut e = Errors::default();
    for k in 0..=255 {
        let lo = if k == 0 { 0.0 } else { c.bound[k - 1] };
        let hi = if k == 255 { 1.0 } else { c.bound[k] };
        let (lo, hi) = (lo.max(r_min), hi.min(1.0));
        if lo > hi {
            continue;
        }
        e.add(lo, c.value[k], r_min);
        e.add(hi, c.value[k], r_min);
    }
    e
}

/// Every `f32` `r ∈ [r_min, 1]` through an f32 encoder and decoder.
fn exhaustive(r_min: f64, rt: impl Fn(f32) -> f64) -> Errors {
    let mut e = Errors::default();
    let start = (r_min as f32).to_bits() + u32::from(f64::from(r_min as f32) < r_min);
    for bits in start..=0x3f80_0000u32 {
        let r = f32::from_bits(bits);
        e.add(f64::from(r), rt(r), r_min);
    }
    e
}

/// prepass's log-range specular power, as a GGX renderer would use it: `α → s = 2/α² − 2`
/// (Walter et al. 2007), `encode_log_roughness(s, 8192)`, back through `α = sqrt(2/(s + 2))`.
fn log_range_power_round_trip(r: f32) -> f64 {
    let a = f64::from(r).powi(2);
    let s = exact::power_from_alpha(a) as f32;
    let k = prepass::roughness::encode_log_roughness(s, 8192.0);
    let sh = f64::from(prepass::roughness::decode_log_roughness(k, 8192.0));
    exact::alpha_from_power(sh).sqrt()
}

/// The measured errors of every curve over the clamped ranges the engines shade, the searched
/// alternatives, and the winner, published as docs/figures.md's `roughness-ggx` block. Shipped
/// curves are measured exhaustively (every `f32` `r` in the range through the twins, which the
/// tests above prove bit-identical to the WGSL) and must agree with the cell supremum; every
/// figure is held to its derived bound.
#[test]
fn ggx_error_table() {
    use std::fmt::Write as _;
    // Engine clamps on perceptual roughness: Bevy (crates/bevy_pbr/src/render/pbr_lighting.wgsl,
    // perceptualRoughnessToRoughness: clamp(r, 0.089, 1)), Unreal (View.MinRoughness, clamped to
    // [0.02, 1] in Engine/Source/Runtime/Engine/Private/SceneView.cpp and applied as
    // max(Roughness, View.MinRoughness) in Engine/Shaders/Private/CapsuleLightIntegrate.ush).
    let ranges = [("Bevy, r ≥ 0.089", 0.089f64), ("Unreal, r ≥ 0.02", 0.02)];
    let spirv = |f: &str| {
        prepass::wgsl::spirv_instruction_count(ROUGHNESS_GGX, f)
            .unwrap()
            .total
    };
    let spirv_log = |f: &str| {
        prepass::wgsl::spirv_instruction_count(prepass::wgsl::ROUGHNESS, f)
            .unwrap()
            .total
    };
    let mut table = String::from(
        "Worst errors over every `f32` perceptual roughness `r` in the range (true and decoded \
         roughness clamped to the range's start, as the engine does), f64 references. Peak: \
         `D(1) = 1/(π α²)`; lobe: `D(n·h, α)` over every `n·h ∈ [0, 1]` (its worst is at `n·h = 1` \
         or `n·h → 0`, `bounds::lobe_relative`; checked on a 1024 × 2048 grid below). Cost: \
         SPIR-V instructions, encode / decode (device-independent; real-ISA figures are in the \
         `isa-costs` block).\n\n\
         | range | form | bits | max abs error in α | peak D, max relative error | lobe D, max relative error | derived bound (lobe) | SPIR-V encode / decode |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    let mut search = String::from(
        "\n| range | searched family | best parameter | lobe D, max relative error (cell supremum) | linear r's error ÷ this |\n|---|---|---|---|---|\n",
    );
    let mut winners = Vec::new();
    for (label, r_min) in ranges {
        let h8 = bounds::linear_half_step(255);
        let h7 = bounds::linear_half_step(127);
        // (a) linear r, 8 bits.
        let lin = exhaustive(r_min, |r| {
            f64::from(ggx::decode_roughness_ggx8(ggx::encode_roughness_ggx8(r)))
        });
        // Derived: |r − r̂| ≤ h + the decode's half ULP; at r_min, r/r̂ ≤ r_min/(r_min − h).
        let linear_bound = |h: f64| (r_min / (r_min - h - U)).powi(4) - 1.0;
        // (b) Godot, 7 bits (static byte; the dynamic byte decodes within GODOT_DECODE of it).
        let godot = exhaustive(r_min, |r| {
            f64::from(ggx::decode_roughness_godot8(ggx::encode_roughness_godot8(
                r, 0,
            )))
        });
        // (c) prepass's log-range specular power mapped to α.
        let power = exhaustive(r_min, log_range_power_round_trip);
        // ... and over the range it covers: s ∈ [1, 8192] ⇔ α ∈ [sqrt(2/8194), sqrt(2/3)].
        let lo_p = exact::alpha_from_power(8192.0).sqrt().max(r_min);
        let hi_p = exact::alpha_from_power(1.0).sqrt();
        let mut power_in = Errors::default();
        let start = (lo_p as f32).to_bits() + 1;
        for bits in start..(hi_p as f32).to_bits() {
            let r = f32::from_bits(bits);
            power_in.add(f64::from(r), log_range_power_round_trip(r), r_min);
        }
        // α² ∝ 1/(s + 2): half a step of 2^(13/255) in s moves α² by less than 2^(13/510), plus
        // the f32 rounding of s and of the decoded power.
        let power_bound = (13.0f64 / 510.0).exp2() * (1.0 + 4.0 * U) - 1.0;
        // (d) the log-r curve (shipped).
        let log = exhaustive(r_min, |r| {
            f64::from(ggx::decode_roughness_ggx8_log(
                ggx::encode_roughness_ggx8_log(r),
            ))
        });
        let log_bound = (1.0 + bounds::log_relative()).powi(4) * (1.0 + 4.0 * U) - 1.0;
        let rows = [
            (
                "linear r (Bevy, Unreal GBuffer, HDRP; URP stores the same values as 1 − r)",
                8,
                lin,
                linear_bound(h8),
                format!(
                    "{} / {}",
                    spirv("encode_roughness_ggx8"),
                    spirv("decode_roughness_ggx8")
                ),
                Curve::power(1.0),
            ),
            (
                "Godot 4: 7 bits + dynamic flag",
                7,
                godot,
                (r_min / (r_min - h7 - 4.0 * U)).powi(4) - 1.0,
                format!(
                    "{} / {}",
                    spirv("encode_roughness_godot8"),
                    spirv("decode_roughness_godot8")
                ),
                Curve {
                    value: (0..=255).map(|k| f64::from(k.min(127)) / 127.0).collect(),
                    bound: (0..255).map(|k| (f64::from(k) + 0.5) / 127.0).collect(),
                },
            ),
            (
                "log r, r ∈ [2^-6, 1] (prepass, `_log`)",
                8,
                log,
                log_bound,
                format!(
                    "{} / {}",
                    spirv("encode_roughness_ggx8_log"),
                    spirv("decode_roughness_ggx8_log")
                ),
                Curve::log(1.0 / 64.0),
            ),
        ];
        for (name, bits, e, bound, cost, curve) in &rows {
            // The exhaustive sweep and the supremum over the continuum agree (the sweep is
            // dense: neighbouring f32s differ by ≤ 2^-23 relative, which moves the lobe
            // error by ≤ 4·2^-23·(1 + error)).
            let sup = cell_sup(curve, r_min);
            assert_within!(
                (e.lobe - sup.lobe).abs(),
                1e-5 * (1.0 + sup.lobe),
                "the f32 sweep reaches the supremum within a few f32 steps (4·2^-23 per step, 1e-5 with margin)",
                "{label}, {name}: exhaustive lobe {} against the cell supremum {}",
                e.lobe,
                sup.lobe
            );
            assert_within!(
                e.lobe,
                *bound,
                "derived: half a step at the range's start, to the 4th power (see the row's derivation in this test)",
                "{label}, {name}: lobe"
            );
            assert!(e.peak <= e.lobe && e.alpha < 1.0);
            let _ = writeln!(
                table,
                "| {label} | {name} | {bits} | {:.3e} | {:.3} % | {:.3} % | {:.3} % | {cost} |",
                e.alpha,
                100.0 * e.peak,
                100.0 * e.lobe,
                100.0 * bound
            );
        }
        assert_within!(
            power_in.lobe,
            power_bound,
            "2^(13/510) − 1: half a log step of the power, + 4u for f32 s and the decode",
            "{label}: log-range power within its range"
        );
        let cost_p = format!(
            "{} / {} (+ α ↔ s)",
            spirv_log("encode_log_roughness"),
            spirv_log("decode_log_roughness")
        );
        let _ = writeln!(
            table,
            "| {label} | prepass log-range power (`roughness.wgsl`, 8192) as α = √(2/(s + 2)), whole range | 8 | {:.3e} | {:.3} % | {:.3} % | — (s ∈ [1, 8192] holds r ∈ [{lo_p:.3}, {hi_p:.3}] only) | {cost_p} |",
            power.alpha,
            100.0 * power.peak,
            100.0 * power.lobe
        );
        let _ = writeln!(
            table,
            "| {label} | the same, r ∈ [{lo_p:.3}, {hi_p:.3}] (the r it can hold) | 8 | {:.3e} | {:.3} % | {:.3} % | {:.3} % | {cost_p} |",
            power_in.alpha,
            100.0 * power_in.peak,
            100.0 * power_in.lobe,
            100.0 * power_bound
        );
        // The lobe on a (n·h, α) grid, directly from D: its worst equals bounds::lobe_relative
        // at the same α (so the published column is the grid's).
        for (name, _, _, _, _, curve) in &rows {
            let mut grid = 0.0f64;
            let mut formula = 0.0f64;
            for i in 0..2048 {
                let r = r_min + (1.0 - r_min) * f64::from(i) / 2047.0;
                let k = curve
                    .bound
                    .partition_point(|&b| b <= r)
                    .min(curve.value.len() - 1);
                let (a, ah) = (r * r, curve.value[k].max(r_min).powi(2));
                formula = formula.max(bounds::lobe_relative(a, ah));
                for j in 0..1024 {
                    let nh = f64::from(j) / 1023.0;
                    let d = exact::ggx_d(nh, a);
                    grid = grid.max((exact::ggx_d(nh, ah) / d - 1.0).abs());
                }
            }
            assert_within!(
                (grid - formula).abs(),
                1e-9 * (1.0 + formula),
                "bounds::lobe_relative: the worst n·h is 0 or 1 (grid holds both), f64 rounding",
                "{label}, {name}: lobe on the grid against the formula"
            );
        }
        // The search: r = (k/255)^γ, and log r from r_lo (continuous), by the cell supremum.
        let best_power = (25..=600)
            .map(|g| {
                let g = f64::from(g) / 100.0;
                (g, cell_sup(&Curve::power(g), r_min).lobe)
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        let best_log = (100..=1200)
            .map(|l| {
                let l = f64::from(l) / 100.0;
                (l, cell_sup(&Curve::log((-l).exp2()), r_min).lobe)
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        let alpha_linear = cell_sup(&Curve::power(0.5), r_min).lobe;
        let linear = lin.lobe;
        // The best log range starts at the clamp itself: uniform relative steps over exactly
        // the range shaded.
        assert_within!(
            ((-best_log.0).exp2() / r_min).log2().abs(),
            0.011,
            "the optimum log range is [r_min, 1]: one search step of 0.01 in log2",
            "{label}: best log range start"
        );
        assert_at_least!(
            linear / best_log.1,
            > 1.0,
            "the log curve beats linear r over the clamped range",
            "{label}"
        );
        for (family, param, e) in [
            (
                "r = (k/255)^γ",
                format!("γ = {:.2}", best_power.0),
                best_power.1,
            ),
            (
                "α linear: r = (k/255)^(1/2)",
                "γ = 1/2".into(),
                alpha_linear,
            ),
            (
                "log r, r ∈ [2^-L, 1]",
                format!("L = {:.2} (r_lo = {:.4})", best_log.0, (-best_log.0).exp2()),
                best_log.1,
            ),
            (
                "log r, r ∈ [2^-6, 1] (shipped: one table for every engine's clamp)",
                "L = 6".into(),
                log.lobe,
            ),
        ] {
            let _ = writeln!(
                search,
                "| {label} | {family} | {param} | {:.3} % | {:.2} |",
                100.0 * e,
                linear / e
            );
        }
        winners.push(format!(
            "{label}: the log curve wins — shipped `_log` {:.3} % against linear r's {:.3} % \
             ({:.1}× smaller; the best power curve, γ = {:.2}, {:.3} %; Godot's 7 bits {:.3} %), \
             at {} SPIR-V instructions to decode against linear's {}",
            100.0 * log.lobe,
            100.0 * linear,
            linear / log.lobe,
            best_power.0,
            100.0 * best_power.1,
            100.0 * godot.lobe,
            spirv("decode_roughness_ggx8_log"),
            spirv("decode_roughness_ggx8"),
        ));
    }
    // The engines' own encoders against prepass's exact one, in f32 as the engines write them
    // (no fusion: a GPU may fuse 255·r + ½, which moves a code only at these same near-ties).
    let unorm8 = |w: f32| (w.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u32;
    let godot_write = |r: f32, dynamic: bool| {
        let w = r * (127.0f32 / 255.0);
        unorm8(if dynamic { 1.0 - w } else { w })
    };
    let mut engines = String::from(
        "\n| encoder | codes ≠ prepass's exact code (of every 7th `f32` in [0, 1]) | max abs error in r: the engine's encoder | prepass's encoder |\n|---|---|---|---|\n",
    );
    let (mut n, mut bevy_diff, mut godot_diff) = (0u64, 0u64, 0u64);
    let (mut bevy_max, mut ours_max, mut godot_max, mut ours_godot_max) = (0f64, 0f64, 0f64, 0f64);
    for bits in (0..=0x3f80_0000u32).step_by(7) {
        let r = f32::from_bits(bits);
        let x = f64::from(r);
        n += 1;
        let (e, o) = (unorm8(r), ggx::encode_roughness_ggx8(r));
        bevy_diff += u64::from(e != o);
        bevy_max = bevy_max.max((f64::from(e) / 255.0 - x).abs());
        ours_max = ours_max.max((f64::from(o) / 255.0 - x).abs());
        for dynamic in [false, true] {
            let (e, o) = (
                godot_write(r, dynamic),
                ggx::encode_roughness_godot8(r, u32::from(dynamic)),
            );
            godot_diff += u64::from(e != o);
            let k = |b: u32| f64::from(if b > 127 { 255 - b } else { b }) / 127.0;
            godot_max = godot_max.max((k(e) - x).abs());
            ours_godot_max = ours_godot_max.max((k(o) - x).abs());
        }
    }
    assert_within!(
        ours_max,
        bounds::linear_half_step(255),
        "bounds::linear_half_step(255): the exact nearest code",
        "prepass's 8-bit encoder"
    );
    assert_within!(
        ours_godot_max,
        bounds::linear_half_step(127),
        "bounds::linear_half_step(127): the exact nearest code",
        "prepass's Godot encoder"
    );
    assert!(ours_max <= bevy_max && ours_godot_max <= godot_max);
    let _ = writeln!(
        engines,
        "| Bevy `u32(saturate(r)·255 + 0.5)`, a unorm8 target's `⌊255·r + ½⌋` (Unreal, HDRP, URP) | {bevy_diff} of {n} | {bevy_max:.6e} | {ours_max:.6e} |"
    );
    let _ = writeln!(
        engines,
        "| Godot `r·(127/255)`, `1 − w` if dynamic, to unorm8 (both flags) | {godot_diff} of {} | {godot_max:.6e} | {ours_godot_max:.6e} |",
        2 * n
    );
    let body = format!("{table}{search}\n{}.\n{engines}", winners.join(".\n"));
    eprintln!("{body}");
    common::publish("docs/figures.md", "roughness-ggx", &body);
}

/// The promise on every conforming adapter, under the emulated worst adapter
/// (`prepass::conforming`, `Policy::WORST`: upper, lower and three seeds): the encoders' codes
/// are the twin's exact codes (every operation that decides them is exact; see the twin's
/// "Exact encoders"), the log decoders are bit-identical (integer table constructions), and the
/// linear and Godot decoders stay within WGSL's 2.5-ULP division (Godot: its three operations,
/// `bounds::GODOT_DECODE` widened by the division's and the constant's allowances). Inputs: every
/// boundary neighbourhood and every 977th `f32` of [`encoder_inputs`]; every code.
#[test]
fn promises_hold_on_the_emulated_worst_conforming_adapter() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    let all = encoder_inputs();
    let grid = (0x3f80_0000usize / 61) + 1;
    let rs: Vec<f32> = all[..grid]
        .iter()
        .step_by(977)
        .chain(&all[grid..])
        .copied()
        .collect();
    let codes = all_codes();
    let gpu = common::gpu();
    for policy in Policy::WORST {
        let emu = Emulation::new(policy);
        let run = |name: &str, args: &[Arg<'_>], n: usize| {
            let k = EmulatedKernel::new(gpu, ROUGHNESS_GGX, name, &emu)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            let (out, flags) = k.run(args, n as u64).unwrap();
            assert!(
                flags.iter().all(|f| !f),
                "{name} {policy}: an operation left the spec's domain"
            );
            out
        };
        let encoders: [Encoder; 2] = [
            ("encode_roughness_ggx8", ggx::encode_roughness_ggx8),
            ("encode_roughness_ggx8_log", ggx::encode_roughness_ggx8_log),
        ];
        for (name, twin) in encoders {
            let got = run(name, &[Arg::column(&rs)], rs.len());
            for (&r, &c) in rs.iter().zip(got.as_u32()) {
                assert_eq!(c, twin(r), "{name}({r:e}) under {policy}");
            }
        }
        let got = run(
            "encode_roughness_godot8",
            &[Arg::column(&rs), Arg::splat_u32(1)],
            rs.len(),
        );
        for (&r, &c) in rs.iter().zip(got.as_u32()) {
            assert_eq!(
                c,
                ggx::encode_roughness_godot8(r, 1),
                "godot8({r:e}) under {policy}"
            );
        }
        let decoders: [DecoderWithin; 4] = [
            (
                "decode_roughness_ggx8_log",
                ggx::decode_roughness_ggx8_log,
                0.0,
            ),
            (
                "decode_roughness_ggx8_log_alpha",
                ggx::decode_roughness_ggx8_log_alpha,
                0.0,
            ),
            // WGSL's / is 2.5 ULP: of a value ≤ 1, 2.5·2^-23 absolute.
            ("decode_roughness_ggx8", ggx::decode_roughness_ggx8, 5.0 * U),
            // Godot: 2.5 ULP for each division (c, and the quotient ≤ 1) where the twin has
            // 0.5, both carried to the result (the first through 1 − c and /(127/255)).
            (
                "decode_roughness_godot8",
                ggx::decode_roughness_godot8,
                bounds::GODOT_DECODE + 2.0 * 2.0 * U * 255.0 / 127.0 + 2.0 * 2.0 * U,
            ),
        ];
        for (name, twin, tol) in decoders {
            let got = run(name, &[Arg::column(&codes)], codes.len());
            for (&c, &v) in codes.iter().zip(got.as_f32()) {
                assert_within!(
                    (f64::from(v) - f64::from(twin(c))).abs(),
                    tol,
                    "0 for the table decoders; WGSL's 2.5-ULP division otherwise (comment above)",
                    "{name}({c}) under {policy}"
                );
            }
        }
    }
}
