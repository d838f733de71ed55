//! Arithmetic error of linear (view) depth against distance.
//!
//! [`chart`] takes any number of series of `(view distance in m, max relative error)`; the
//! section feeds it the textbook standard-Z form evaluated in f32 on the CPU. The stable forms
//! of `wgsl/depth.wgsl` (linear-depth issue) add their adapter-measured series here: compute
//! them with the sweep in `src/sweep/`, bin them with [`max_per_bin`], push a [`Series`].

use crate::ctx::Ctx;
use crate::plot::{Chart, LineChart, Series};
use prepass::depth::{DEPTH24_MAX, hyperbolic_depth_from_depth24};
use std::fmt::Write as _;

/// Near plane of every configuration here, metres.
pub const NEAR: f64 = 0.1;

/// far/near ratios plotted.
pub const RATIOS: [f64; 3] = [1e3, 1e5, 1e7];

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

/// The textbook `z = 1 / (w·a + b)` with `a = 1/f − 1/n`, `b = 1/n`, all in f32, over every
/// code; its relative error per distance bin.
fn textbook_series(far_over_near: f64) -> Vec<(f64, f64)> {
    let far = NEAR * far_over_near;
    let a = (1.0 / far - 1.0 / NEAR) as f32;
    let b = (1.0 / NEAR) as f32;
    let samples = (0..=DEPTH24_MAX).map(|code| {
        let w = hyperbolic_depth_from_depth24(code);
        let got = 1.0f32 / (w * a + b);
        let exact = exact_view(code, NEAR, far);
        (exact, (f64::from(got) - exact).abs() / exact)
    });
    max_per_bin(NEAR, far, samples)
}

/// The plot, its CSV, and the note on what arrives with the stable forms.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let bar = ctx.progress(RATIOS.len() as u64, "linear depth (CPU)");
    let mut series = Vec::new();
    let mut csv = String::from("form,where,near_m,far_m,distance_m,max_relative_error\n");
    for ratio in RATIOS {
        let points = textbook_series(ratio);
        for &(z, e) in &points {
            let _ = writeln!(csv, "textbook_f32,cpu,{NEAR},{},{z},{e}", NEAR * ratio);
        }
        series.push(Series {
            label: format!("textbook 1/(w·a+b), f32 CPU, far/near = {ratio:.0e}"),
            points,
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    ctx.csv("linear_depth_error.csv", &csv)?;
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
