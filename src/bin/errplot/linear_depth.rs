//! Arithmetic error of linear (view) depth against distance.
//!
//! [`chart`] takes any number of series of `(view distance in m, max relative error)`; the
//! section feeds it the textbook standard-Z form `1/(w·a + b)` evaluated in f32 on the CPU and
//! (with an adapter) in WGSL on the adapter, and registers it as a cost-table variant. The
//! stable forms of `wgsl/depth.wgsl` (linear-depth issue) add their series the same way:
//! compute them with the sweep in `src/sweep/`, bin them with [`max_per_bin`], push a
//! [`Series`] and a `Variant` in the same family.

use crate::cost::{TimedArg, Variant, Wgsl, twin_timer};
use crate::ctx::Ctx;
use crate::plot::{Chart, LineChart, Series};
use prepass::depth::{DEPTH24_MAX, hyperbolic_depth_from_depth24};
use prepass::harness::Arg;
use prepass::precision::metrics::ErrorStats;
use std::fmt::Write as _;

/// Near plane of every configuration here, metres.
pub const NEAR: f64 = 0.1;

/// far/near ratios plotted.
pub const RATIOS: [f64; 3] = [1e3, 1e5, 1e7];

/// The far/near ratio whose textbook form enters the cost table.
pub const VARIANT_RATIO: f64 = 1e5;

/// Bins per curve (log-spaced in distance).
pub const BINS: usize = 120;

/// The chart of error against distance for the given series.
pub fn chart(series: Vec<Series>) -> Chart {
    Chart::Lines(LineChart {
        title: format!("Linear depth from a D24 code: arithmetic error, near {NEAR} m"),
        x_label: "view distance (m, log scale)".into(),
        y_label: "max relative error |z − z_exact| / z_exact (log scale)".into(),
        series,
    })
}

/// Fold `(distance, error)` samples into [`BINS`] log-spaced bins between `near` and `far`,
/// keeping each bin's maximum; bins with no sample are left out.
pub fn max_per_bin(
    near: f64,
    far: f64,
    samples: impl Iterator<Item = (f64, f64)>,
) -> Vec<(f64, f64)> {
    let mut bins = vec![f64::NAN; BINS];
    let span = (far / near).ln();
    for (z, e) in samples {
        let k = (((z / near).ln() / span) * BINS as f64).floor();
        if (0.0..BINS as f64).contains(&k) && e.is_finite() {
            let b = &mut bins[k as usize];
            *b = if b.is_nan() { e } else { b.max(e) };
        }
    }
    bins.iter()
        .enumerate()
        .filter(|(_, e)| !e.is_nan())
        .map(|(k, &e)| (near * (far / near).powf((k as f64 + 0.5) / BINS as f64), e))
        .collect()
}

/// Exact view distance of a 24-bit standard-Z code, f64.
fn exact_view(code: u32, near: f64, far: f64) -> f64 {
    let w = f64::from(code) / f64::from(DEPTH24_MAX);
    near * far / (far - w * (far - near))
}

/// The textbook form in WGSL, measured on the adapter beside its f32 CPU evaluation. Kept in
/// errplot (not `wgsl/`): it is the baseline the crate's stable forms are compared with.
pub const TEXTBOOK_WGSL: &str = "fn errplot_textbook_linear_depth(w: f32, a: f32, b: f32) -> f32 {\n\
    return 1.0 / (w * a + b);\n}\n";

/// The textbook `z = 1 / (w·a + b)` with `a = 1/f − 1/n`, `b = 1/n` (standard Z) in f32.
fn textbook_uniforms(far: f64) -> (f32, f32) {
    ((1.0 / far - 1.0 / NEAR) as f32, (1.0 / NEAR) as f32)
}

/// `(exact distance, relative error)` of `got[code]` for every code.
fn errors(got: impl Fn(u32) -> f32, far: f64) -> impl Iterator<Item = (f64, f64)> {
    (0..=DEPTH24_MAX).map(move |code| {
        let exact = exact_view(code, NEAR, far);
        (exact, (f64::from(got(code)) - exact).abs() / exact)
    })
}

/// The plot, its CSV, and the textbook variant for the cost table.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let steps = RATIOS.len() as u64 * if ctx.gpu().is_some() { 2 } else { 1 };
    let bar = ctx.progress(steps, "linear depth");
    let mut series = Vec::new();
    let mut csv = String::from("form,where,near_m,far_m,distance_m,max_relative_error\n");
    let w_of: Vec<f32> = (0..=DEPTH24_MAX)
        .map(hyperbolic_depth_from_depth24)
        .collect();
    let mut variant_error = None;
    for ratio in RATIOS {
        let far = NEAR * ratio;
        let (a, b) = textbook_uniforms(far);
        let mut sides = vec![(
            "cpu",
            "f32 CPU",
            errors(|c| 1.0f32 / (w_of[c as usize] * a + b), far).collect::<Vec<_>>(),
        )];
        bar.inc(1);
        if let Some(g) = ctx.gpu() {
            let out = g
                .kernel(TEXTBOOK_WGSL, "errplot_textbook_linear_depth")
                .and_then(|k| {
                    k.run(
                        &[Arg::column(&w_of), Arg::splat_f32(a), Arg::splat_f32(b)],
                        w_of.len() as u64,
                    )
                })
                .map_err(|e| e.to_string())?;
            let z = out.as_f32();
            sides.push((
                "adapter",
                "adapter",
                errors(|c| z[c as usize], far).collect(),
            ));
            bar.inc(1);
        }
        for (place, label, samples) in sides {
            if ratio == VARIANT_RATIO && (place == "adapter" || ctx.gpu().is_none()) {
                let mut stats = ErrorStats::default();
                for (k, &(_, e)) in samples.iter().enumerate() {
                    stats.add(k as u64, e);
                }
                variant_error = Some((stats, place));
            }
            let points = max_per_bin(NEAR, far, samples.into_iter());
            for &(z, e) in &points {
                let _ = writeln!(csv, "textbook_f32,{place},{NEAR},{far},{z},{e}");
            }
            series.push(Series {
                label: format!("textbook 1/(w·a+b), {label}, far/near = {ratio:.0e}"),
                points,
            });
        }
    }
    bar.finish_and_clear();
    ctx.csv("linear_depth_error.csv", &csv)?;
    let (a, b) = textbook_uniforms(NEAR * VARIANT_RATIO);
    let tile: Vec<u32> = (0..1u32 << 16)
        .map(|k| w_of[(k.wrapping_mul(0x9e37_79b1) & DEPTH24_MAX) as usize].to_bits())
        .collect();
    let twin_inputs: Vec<f32> = tile.iter().map(|&w| f32::from_bits(w)).collect();
    ctx.variants.push(Variant {
        family: "view depth from a standard-Z D24 code, far/near 1e5",
        unit: "relative",
        name: "errplot_textbook_linear_depth".into(),
        bits: 24,
        error: variant_error.map(|(s, _)| s),
        error_from: match variant_error {
            Some((_, "adapter")) => "adapter: all 2^24 codes".into(),
            _ => "f32 on the CPU: all 2^24 codes".into(),
        },
        wgsl: Some(Wgsl {
            source: TEXTBOOK_WGSL.into(),
            function: "errplot_textbook_linear_depth".into(),
            args: vec![
                TimedArg::Column(tile),
                TimedArg::Splat([a.to_bits(), 0, 0, 0]),
                TimedArg::Splat([b.to_bits(), 0, 0, 0]),
            ],
        }),
        twin: Some(twin_timer(twin_inputs, move |w: f32| 1.0f32 / (w * a + b))),
    });
    ctx.line("## Arithmetic error of linear depth");
    ctx.line("");
    ctx.line(
        "Relative error of view depth computed from every standard-Z D24 code (hyperbolic depth \
         correctly rounded to f32), maximum per distance bin, against the exact f64 distance of \
         the code. The textbook form loses about (far/near)·2^-24 near the far plane through \
         cancellation in `w·a + b`. Data: `linear_depth_error.csv`.",
    );
    ctx.line("");
    ctx.chart(
        &chart(series),
        "linear_depth_error",
        "linear depth error against distance",
    )
}
