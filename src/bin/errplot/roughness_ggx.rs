//! GGX perceptual roughness in 8 bits (`wgsl/roughness_ggx.wgsl`): the relative error of the GGX
//! lobe `D(n·h, α)` (its worst over every `n·h`, `roughness_ggx::bounds::lobe_relative`) when
//! `r` is stored linearly as the engines store it, in Godot's 7 bits + flag, or on prepass's log
//! curve, over the clamped range each engine shades. Measured through the Rust twins, which
//! `tests/roughness_ggx.rs` proves bit-identical to the WGSL on the adapter; the encoders are
//! registered for the cost table.

use crate::ctx::{Ctx, num};
use crate::variant::{TimedArg, Variant, Wgsl, twin_timer};
use prepass::precision::metrics::ErrorStats;
use prepass::roughness_ggx as ggx;
use std::fmt::Write as _;

/// A form: label, WGSL encoder, the round trip `r → r̂` through the twins.
type Form = (&'static str, &'static str, fn(f32) -> f32);

const FORMS: [Form; 3] = [
    (
        "linear r (Bevy, Unreal, HDRP, URP)",
        "encode_roughness_ggx8",
        |r| ggx::decode_roughness_ggx8(ggx::encode_roughness_ggx8(r)),
    ),
    ("Godot 7 bits + flag", "encode_roughness_godot8", |r| {
        ggx::decode_roughness_godot8(ggx::encode_roughness_godot8(r, 0))
    }),
    (
        "log r, [2^-6, 1] (prepass)",
        "encode_roughness_ggx8_log",
        |r| ggx::decode_roughness_ggx8_log(ggx::encode_roughness_ggx8_log(r)),
    ),
];

/// The engines' clamps on perceptual roughness (Bevy's `perceptualRoughnessToRoughness`,
/// Unreal's `View.MinRoughness`).
const RANGES: [(&str, f64); 2] = [("Bevy, r ≥ 0.089", 0.089), ("Unreal, r ≥ 0.02", 0.02)];

/// The lobe error of every `stride`-th `f32` `r ∈ [r_min, 1]` (true and decoded `r` clamped to
/// `r_min`, as the engines do).
fn lobe(round_trip: fn(f32) -> f32, r_min: f64, stride: usize) -> ErrorStats {
    let mut s = ErrorStats::default();
    let start = (r_min as f32).to_bits() + 1;
    for bits in (start..=0x3f80_0000u32).step_by(stride) {
        let r = f64::from(f32::from_bits(bits));
        let rh = f64::from(round_trip(f32::from_bits(bits))).max(r_min);
        s.add(u64::from(bits), ggx::bounds::lobe_relative(r * r, rh * rh));
    }
    s
}

/// The table, CSV and cost-table variants.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let stride = if ctx.opts.quick() { 61 } else { 1 };
    let every = if stride == 1 { "every" } else { "every 61st" };
    ctx.line("## GGX roughness in 8 bits: the lobe's error");
    ctx.line("");
    ctx.line(format!(
        "Perceptual roughness `r` (`α = r²`) through each 8-bit form's encoder and decoder \
         (Rust twins, bit-identical to the WGSL: tests/roughness_ggx.rs), {every} f32 `r` in \
         the engine's clamped range; error: the worst relative error of the GGX lobe \
         `D(n·h, α)` over every `n·h`. Data: `roughness_ggx_error.csv`."
    ));
    ctx.line("");
    ctx.line("| range | form | max relative lobe error | mean | rms |");
    ctx.line("|---|---|---|---|---|");
    let mut csv = String::from("range,form,r_min,max_relative_lobe_error,mean,rms\n");
    let mut stats = Vec::new();
    for (range, r_min) in RANGES {
        for (label, function, rt) in FORMS {
            let s = lobe(rt, r_min, stride);
            ctx.line(format!(
                "| {range} | {label} | {} | {} | {} |",
                num(s.max),
                num(s.mean()),
                num(s.rms())
            ));
            let _ = writeln!(
                csv,
                "{range},{label},{r_min},{},{},{}",
                s.max,
                s.mean(),
                s.rms()
            );
            stats.push((range, r_min, label, function, s));
        }
    }
    ctx.line("");
    ctx.csv("roughness_ggx_error.csv", &csv)?;
    // Cost-table variants: the encoders, with the error over the wider (Unreal) range.
    let tile: Vec<u32> = (0..1u32 << 16)
        .map(|k| k.wrapping_mul(0x9e37_79b1) % 0x3f80_0001)
        .collect();
    for (range, r_min, label, function, s) in stats.into_iter().filter(|x| x.1 == 0.02) {
        let mut args = vec![TimedArg::Column(tile.clone())];
        if function == "encode_roughness_godot8" {
            args.push(TimedArg::Splat([0, 0, 0, 0]));
        }
        let inputs: Vec<f32> = tile.iter().map(|&b| f32::from_bits(b)).collect();
        let twin = match function {
            "encode_roughness_ggx8" => twin_timer(inputs, ggx::encode_roughness_ggx8),
            "encode_roughness_godot8" => twin_timer(inputs, |r| ggx::encode_roughness_godot8(r, 0)),
            _ => twin_timer(inputs, ggx::encode_roughness_ggx8_log),
        };
        ctx.variants.push(Variant {
            family: "GGX roughness in 8 bits (encode)",
            unit: "relative (GGX lobe)",
            name: format!("{function} ({label})"),
            bits: 8,
            error: Some(s),
            error_from: format!("Rust twins: {every} f32 r in [{r_min}, 1] ({range})"),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: prepass::wgsl::ROUGHNESS_GGX.to_string(),
                function: function.into(),
                args,
            }),
            twin: Some(twin),
        });
    }
    Ok(())
}
