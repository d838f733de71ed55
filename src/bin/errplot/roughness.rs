//! Log-range roughness (`wgsl/roughness.wgsl`): relative error of `decode(encode(p))` against
//! the specular power, beside linear and affine 8-bit storage (`tests/baselines/roughness.wgsl`).

use crate::ctx::{Ctx, NEEDS_ADAPTER, num};
use crate::plot::{Chart, LineChart, Series};
use crate::variant::{TimedArg, Variant, Wgsl, twin_timer};
use prepass::roughness;
use prepass::sweep::roughness::{
    ONE_BITS, RoundTrip, log_roughness_all_powers, profile_bin_start, roundtrip_all_powers,
};
use std::fmt::Write as _;

const BASELINES: &str = include_str!("../../../tests/baselines/roughness.wgsl");

/// An (encoder, decoder) pair of WGSL baseline functions.
type Pair = (&'static str, &'static str);

/// The 8-bit storages compared: label, encoder, decoder (`None` = the shipped pair).
const STORAGES: [(&str, Option<Pair>); 3] = [
    ("log range (shipped)", None),
    (
        "linear round(255·p/max)",
        Some(("baseline_linear8_encode", "baseline_linear8_decode")),
    ),
    (
        "affine round(255·(p−1)/(max−1))",
        Some(("baseline_affine8_encode", "baseline_affine8_decode")),
    ),
];

/// The plot, table, CSV and cost-table variants.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    // Every f32 power in [1, max] is swept: 1.1e8 of them for the full run's 8192 (about 20 s
    // per storage on lavapipe), 5.0e7 for the default run's 64 (the sweep has no sampled form:
    // a smaller range is the lever, and 64 keeps six octaves of the log curve), 1.7e7 for the
    // quick run's 4.
    let max_power: f32 = ctx.opts.pick(4.0, 64.0, 8192.0);
    ctx.line("## Specular power in 8 bits: log range against linear storage");
    ctx.line("");
    let Some(g) = ctx.gpu() else {
        ctx.line(format!(
            "Every power is encoded and decoded by the WGSL: {NEEDS_ADAPTER}."
        ));
        ctx.line("");
        return Ok(());
    };
    let src = format!("{}\n{BASELINES}", prepass::wgsl::ROUGHNESS);
    let bar = ctx.progress(STORAGES.len() as u64, "roughness");
    let mut results: Vec<(&str, Option<Pair>, RoundTrip)> = Vec::new();
    for (label, pair) in STORAGES {
        bar.set_message(label);
        let r = match pair {
            None => log_roughness_all_powers(g, max_power),
            Some((enc, dec)) => roundtrip_all_powers(g, &src, enc, dec, max_power, None, false),
        }
        .map_err(|e| e.to_string())?;
        results.push((label, pair, r));
        bar.inc(1);
    }
    bar.finish_and_clear();
    let limit = (f64::from(max_power).log2() / (2.0 * 255.0)).exp2() - 1.0;
    ctx.line(format!(
        "Every f32 power in [1, {max_power}] ({} values) encoded and decoded on the adapter, \
         relative error `|decode(encode(p)) − p| / p` against p. The log-range code's \
         quantisation limit is `2^(log2(max)/(2·255)) − 1` = {}. Data: `roughness_error.csv`.{}",
        results[0].2.count,
        num(limit),
        if ctx.opts.full() {
            ""
        } else {
            " This run's range is smaller than the full run's [1, 8192] (every f32 power there, \
             1.1e8 values, about a minute on lavapipe); `--full` for it."
        }
    ));
    ctx.line("");
    ctx.line("| storage | max relative error | mean | at p = 1 | max for p ≤ 2 |");
    ctx.line("|---|---|---|---|---|");
    let mut csv =
        String::from("storage,max_power,power_bin_start,max_relative_error,mean_relative_error\n");
    let mut series = Vec::new();
    for (label, _, r) in &results {
        ctx.line(format!(
            "| {label} | {} | {} | {} | {} |",
            num(r.relative.max),
            num(r.relative.mean()),
            num(r.at_one),
            num(r.max_below_two)
        ));
        let mut points = Vec::new();
        for (b, &(max, mean)) in r.profile.iter().enumerate() {
            let p = profile_bin_start(b);
            let _ = writeln!(csv, "{label},{max_power},{p},{max},{mean}");
            if max > 0.0 {
                points.push((p, max));
            }
        }
        series.push(Series {
            label: label.to_string(),
            points,
        });
    }
    ctx.line("");
    ctx.csv("roughness_error.csv", &csv)?;
    ctx.chart(
        &Chart::Lines(LineChart {
            title: format!("Specular power in 8 bits, max {max_power}: round-trip error"),
            x_label: "specular power p (log scale)".into(),
            y_label: "max relative error per 1/16 octave (log scale)".into(),
            series,
        }),
        "roughness_error",
        "log-range roughness error against power",
    )?;

    // Cost-table variants: the encoders (what a G-buffer pass runs per pixel).
    let tile: Vec<u32> = (0..1u32 << 16)
        .map(|k| {
            let span = max_power.to_bits() - ONE_BITS;
            ONE_BITS + (k.wrapping_mul(0x9e37_79b1) % span.max(1))
        })
        .collect();
    for (label, pair, r) in results {
        let (source, function, twin) = match pair {
            None => (
                prepass::wgsl::ROUGHNESS.to_string(),
                "encode_log_roughness",
                Some(twin_timer(
                    tile.iter().map(|&b| f32::from_bits(b)).collect::<Vec<_>>(),
                    move |p| roughness::encode_log_roughness(p, max_power),
                )),
            ),
            Some((enc, _)) => (src.clone(), enc, None),
        };
        ctx.variants.push(Variant {
            family: "specular power in 8 bits (encode)",
            unit: "relative",
            name: format!("{function} ({label})"),
            bits: 8,
            error: Some(r.relative),
            error_from: format!("adapter: every f32 power in [1, {max_power}]"),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source,
                function: function.into(),
                args: vec![
                    TimedArg::Column(tile.clone()),
                    TimedArg::Splat([max_power.to_bits(), 0, 0, 0]),
                ],
            }),
            twin,
        });
    }
    Ok(())
}
