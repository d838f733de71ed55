//! 24-bit depth codes in RGBA8 texels (`wgsl/depth24.wgsl`): recovery from sampled channels and
//! the hyperbolic depth of every code, against the textbook baselines.

use crate::ctx::{Ctx, NEEDS_ADAPTER, num};
use crate::variant::{TimedArg, Variant, Wgsl, twin_timer};
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::precision::inputs::{ChannelError, rgb8_channels};
use prepass::precision::metrics::ErrorStats;
use prepass::sweep::depth24::{
    CODES, Hyperbolic, RECOVERY_CASES, hyperbolic_all, measure_hyperbolic, recover_all,
};
use std::fmt::Write as _;

/// The textbook forms the crate's functions are compared with.
const BASELINES: &str = include_str!("../../../tests/baselines/depth24.wgsl");

/// Values per timing tile (see `Kernel::time`).
const TILE: u32 = 1 << 16;

fn source() -> String {
    format!("{}\n{BASELINES}", prepass::wgsl::DEPTH24)
}

/// Perturbed channels of `TILE` codes spread over the whole range, as timing input.
fn timing_channels() -> Vec<u32> {
    (0..TILE)
        .flat_map(|k| {
            let code = k.wrapping_mul(0x9e37_79b1) & DEPTH24_MAX;
            rgb8_channels(code, ChannelError::Ulps(3), false).map(f32::to_bits)
        })
        .collect()
}

/// The recovery and hyperbolic-depth tables.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let src = source();
    let quick = ctx.opts.quick();
    // Quick runs keep one sign pattern per perturbation; every case stays exhaustive (2^24 codes).
    let cases: Vec<(ChannelError, bool)> = RECOVERY_CASES
        .iter()
        .copied()
        .filter(|&(_, flip)| !quick || !flip)
        .collect();
    ctx.line("## 24-bit depth from an RGBA8 texel");
    ctx.line("");
    ctx.line(format!(
        "Every one of the {CODES} codes, channels perturbed as a sampler may return them{}.",
        if quick {
            " (quick run: one sign pattern per perturbation)"
        } else {
            " (both directions per channel)"
        }
    ));
    ctx.line("");
    ctx.line("| function | channels | codes wrong (adapter) | max code error |");
    ctx.line("|---|---|---|---|");
    let mut csv = String::from("function,channel_error,flip,codes,mismatches,max_code_error\n");
    let functions = ["depth24_from_rgb8", "baseline_depth24_from_rgb8_unrounded"];
    let bar = ctx.progress((functions.len() * cases.len()) as u64, "depth24 recovery");
    for f in functions {
        let mut stats = ErrorStats::default();
        for &(error, flip) in &cases {
            bar.set_message(format!("{f} {error}"));
            let measured = match ctx.gpu() {
                Some(g) => {
                    let r = recover_all(g, &src, f, error, flip).map_err(|e| e.to_string())?;
                    let mut s = ErrorStats::default();
                    for (i, &c) in r.codes.iter().enumerate() {
                        s.add(i as u64, (f64::from(c) - i as f64).abs());
                    }
                    stats.merge(&s);
                    Some((r.mismatches.count, s.max))
                }
                None => None,
            };
            bar.inc(1);
            let dir = if flip { "flipped signs" } else { "signs" };
            let (wrong, max) = measured.map_or((NEEDS_ADAPTER.into(), NEEDS_ADAPTER.into()), |m| {
                (m.0.to_string(), num(m.1))
            });
            ctx.line(format!("| `{f}` | {error} ({dir}) | {wrong} | {max} |"));
            let _ = writeln!(
                csv,
                "{f},{error},{flip},{CODES},{},{}",
                measured.map_or(String::new(), |m| m.0.to_string()),
                measured.map_or(String::new(), |m| m.1.to_string())
            );
        }
        ctx.variants.push(Variant {
            family: "24-bit code from RGBA8 channels",
            unit: "codes",
            name: f.into(),
            bits: 24,
            error: ctx.gpu().map(|_| stats),
            error_from: format!("adapter: 2^24 codes × {} channel cases", cases.len()),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: src.clone(),
                function: f.into(),
                args: vec![TimedArg::Column(timing_channels())],
            }),
            twin: (f == "depth24_from_rgb8").then(|| {
                let inputs: Vec<glam::Vec3> = timing_channels()
                    .chunks(3)
                    .map(|c| {
                        glam::Vec3::new(
                            f32::from_bits(c[0]),
                            f32::from_bits(c[1]),
                            f32::from_bits(c[2]),
                        )
                    })
                    .collect();
                twin_timer(inputs, depth24::depth24_from_rgb8)
            }),
        });
    }
    bar.finish_and_clear();
    ctx.csv("depth24_recovery.csv", &csv)?;

    ctx.line("");
    ctx.line("### Hyperbolic depth d/(2^24−1) as f32");
    ctx.line("");
    ctx.line("| formulation | where | max ULP | mean ULP | exact round-trip failures | f32 round-trip failures | codes sharing a float |");
    ctx.line("|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "function,where,max_ulp,mean_ulp,rms_ulp,exact_roundtrip_failures,f32_roundtrip_failures,collisions\n",
    );
    let mut row = |ctx: &mut Ctx, name: &str, place: &str, h: &Hyperbolic| {
        ctx.line(format!(
            "| `{name}` | {place} | {:.3} | {:.4} | {} | {} | {} |",
            h.ulps.max,
            h.ulps.mean(),
            h.exact_roundtrip_failures,
            h.f32_roundtrip_failures,
            h.collisions
        ));
        let _ = writeln!(
            csv,
            "{name},{place},{},{},{},{},{},{}",
            h.ulps.max,
            h.ulps.mean(),
            h.ulps.rms(),
            h.exact_roundtrip_failures,
            h.f32_roundtrip_failures,
            h.collisions
        );
    };
    let twin = measure_hyperbolic(
        (0..=DEPTH24_MAX)
            .map(depth24::hyperbolic_depth_from_depth24)
            .collect(),
    );
    row(
        ctx,
        "hyperbolic_depth_from_depth24",
        "Rust twin (CPU)",
        &twin,
    );
    let functions = [
        "hyperbolic_depth_from_depth24",
        "baseline_hyperbolic_divide",
        "baseline_hyperbolic_reciprocal",
    ];
    let bar = ctx.progress(functions.len() as u64, "hyperbolic depth");
    for f in functions {
        bar.set_message(f);
        let h = match ctx.gpu() {
            Some(g) => Some(hyperbolic_all(g, &src, f).map_err(|e| e.to_string())?),
            None => None,
        };
        bar.inc(1);
        match &h {
            Some(h) => row(ctx, f, "adapter", h),
            None => ctx.line(format!("| `{f}` | adapter | {NEEDS_ADAPTER} | | | | |")),
        }
        ctx.variants.push(Variant {
            family: "hyperbolic depth from a 24-bit code",
            unit: "f32 ULP",
            name: f.into(),
            bits: 24,
            // Without an adapter the crate's function still has its twin's exhaustive CPU
            // measurement (the twin is bit-identical to the WGSL: tests/depth24.rs).
            error: h
                .as_ref()
                .map(|h| h.ulps)
                .or_else(|| (f == "hyperbolic_depth_from_depth24").then_some(twin.ulps)),
            error_from: if h.is_none() && f == "hyperbolic_depth_from_depth24" {
                "Rust twin (CPU): all 2^24 codes".into()
            } else {
                "adapter: all 2^24 codes".into()
            },
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: src.clone(),
                function: f.into(),
                args: vec![TimedArg::Index(0)],
            }),
            twin: (f == "hyperbolic_depth_from_depth24").then(|| {
                let codes: Vec<u32> = (0..TILE)
                    .map(|k| k.wrapping_mul(0x9e37_79b1) & DEPTH24_MAX)
                    .collect();
                twin_timer(codes, depth24::hyperbolic_depth_from_depth24)
            }),
        });
    }
    bar.finish_and_clear();
    ctx.csv("depth24_hyperbolic.csv", &csv)?;
    ctx.line("");
    Ok(())
}
