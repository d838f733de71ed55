//! Depth resolution against distance: how far apart in view space two neighbouring stored depth
//! values are, for each depth format and convention. Pure projection maths in f64 — it needs no
//! adapter and no shader, and it is exact up to f64 rounding (relative 1e-16, far below the
//! steps shown).
//!
//! Window depth `w` as a function of view distance `z` (near `n`, far `f`, D3D/WebGPU range
//! `[0, 1]`):
//! - standard: `w = f(z − n) / (z(f − n))`, so `z = n·f / (f − w(f − n))`;
//! - reversed: `w = n(f − z) / (z(f − n))`, so `z = n·f / (w(f − n) + n)`;
//! - reversed infinite (`f → ∞`): `w = n / z`, so `z = n / w`.
//!
//! D24 stores `round(w · (2^24 − 1))`: neighbours are `1/(2^24 − 1)` apart in `w`. D32F stores
//! `w` rounded to f32: neighbours are one f32 ULP apart. The resolution at `z` is the distance
//! between the view depths of the stored value at `z` and of its neighbour further away.

use crate::ctx::Ctx;
use crate::plot::{Chart, LineChart, Series};
use std::fmt::Write as _;

const NEAR: f64 = 0.1;
const FAR: f64 = 10_000.0;
const D24_MAX: f64 = 16_777_215.0;

/// A depth format and convention.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Layout {
    D24Standard,
    D24Reversed,
    F32Standard,
    F32Reversed,
    F32ReversedInfinite,
}

impl Layout {
    const ALL: [Layout; 5] = [
        Layout::D24Standard,
        Layout::D24Reversed,
        Layout::F32Standard,
        Layout::F32Reversed,
        Layout::F32ReversedInfinite,
    ];

    fn label(self) -> &'static str {
        match self {
            Layout::D24Standard => "D24 unorm, standard Z",
            Layout::D24Reversed => "D24 unorm, reversed Z",
            Layout::F32Standard => "D32 float, standard Z",
            Layout::F32Reversed => "D32 float, reversed Z",
            Layout::F32ReversedInfinite => "D32 float, reversed infinite far",
        }
    }

    fn csv(self) -> (&'static str, &'static str) {
        match self {
            Layout::D24Standard => ("d24", "standard"),
            Layout::D24Reversed => ("d24", "reversed"),
            Layout::F32Standard => ("d32f", "standard"),
            Layout::F32Reversed => ("d32f", "reversed"),
            Layout::F32ReversedInfinite => ("d32f", "reversed_infinite"),
        }
    }

    fn window(self, z: f64) -> f64 {
        match self {
            Layout::D24Standard | Layout::F32Standard => FAR * (z - NEAR) / (z * (FAR - NEAR)),
            Layout::D24Reversed | Layout::F32Reversed => NEAR * (FAR - z) / (z * (FAR - NEAR)),
            Layout::F32ReversedInfinite => NEAR / z,
        }
    }

    fn view(self, w: f64) -> f64 {
        match self {
            Layout::D24Standard | Layout::F32Standard => NEAR * FAR / (FAR - w * (FAR - NEAR)),
            Layout::D24Reversed | Layout::F32Reversed => NEAR * FAR / (w * (FAR - NEAR) + NEAR),
            Layout::F32ReversedInfinite => NEAR / w,
        }
    }

    /// Distance in view space between the stored value at `z` and its neighbour further away.
    fn resolution(self, z: f64) -> f64 {
        let w = self.window(z);
        let (a, b) = match self {
            Layout::D24Standard => {
                let c = (w * D24_MAX).floor().min(D24_MAX - 1.0);
                (c / D24_MAX, (c + 1.0) / D24_MAX)
            }
            Layout::D24Reversed => {
                let c = (w * D24_MAX).ceil().max(1.0);
                (c / D24_MAX, (c - 1.0) / D24_MAX)
            }
            Layout::F32Standard => {
                let s = w as f32;
                (f64::from(s), f64::from(s.next_up()))
            }
            Layout::F32Reversed | Layout::F32ReversedInfinite => {
                let s = w as f32;
                (f64::from(s), f64::from(s.next_down()))
            }
        };
        (self.view(b) - self.view(a)).abs()
    }
}

/// The resolution plot and its CSV.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let samples = 400;
    let zs: Vec<f64> = (0..samples)
        .map(|k| {
            let t = (k as f64 + 0.5) / samples as f64;
            NEAR * (FAR / NEAR).powf(t)
        })
        .collect();
    let mut csv = String::from("format,convention,near_m,far_m,distance_m,resolution_m\n");
    let mut series = Vec::new();
    for layout in Layout::ALL {
        let (format, convention) = layout.csv();
        let far = if layout == Layout::F32ReversedInfinite {
            f64::INFINITY
        } else {
            FAR
        };
        let points: Vec<(f64, f64)> = zs.iter().map(|&z| (z, layout.resolution(z))).collect();
        for &(z, r) in &points {
            let _ = writeln!(csv, "{format},{convention},{NEAR},{far},{z},{r}");
        }
        series.push(Series {
            label: layout.label().into(),
            points,
        });
    }
    ctx.csv("depth_resolution.csv", &csv)?;
    ctx.line("## Depth resolution against distance");
    ctx.line("");
    ctx.line(format!(
        "Distance between neighbouring stored depth values, mapped back to view space, near = \
         {NEAR} m, far = {FAR} m (the infinite projection has no far plane). Exact projection \
         maths in f64; no adapter involved. Data: `depth_resolution.csv`. Away from the near \
         plane the three standard/unorm curves coincide (a unorm step and an f32 ULP near 1 are \
         both about 2^-24): only a float buffer with reversed Z gains."
    ));
    ctx.line("");
    let at = |layout: Layout, z: f64| crate::ctx::num(layout.resolution(z));
    ctx.line("| format | at 1 m | at 100 m | at 1000 m |");
    ctx.line("|---|---|---|---|");
    for layout in Layout::ALL {
        ctx.line(format!(
            "| {} | {} m | {} m | {} m |",
            layout.label(),
            at(layout, 1.0),
            at(layout, 100.0),
            at(layout, 1000.0)
        ));
    }
    ctx.line("");
    let chart = Chart::Lines(LineChart {
        title: format!("Depth resolution, near {NEAR} m, far {FAR} m"),
        x_label: "view distance (m, log scale)".into(),
        y_label: "distance to the next stored depth (m, log scale)".into(),
        series,
    });
    ctx.chart(
        &chart,
        "depth_resolution",
        "depth resolution against distance",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn window_and_view_are_inverse() {
        for layout in Layout::ALL {
            for z in [0.2, 3.0, 500.0, 9000.0] {
                let back = layout.view(layout.window(z));
                prepass::assert_within_abs!(
                    back,
                    z,
                    1e-9 * z,
                    "literal: 1e-9 relative, generous for an f64 round trip",
                    "{layout:?} at {z}"
                );
            }
        }
    }

    #[test]
    fn d24_standard_matches_the_closed_form() {
        // dz/dw = (f − n)·z²/(n·f) for standard Z; one code step is 1/(2^24 − 1) in w.
        let z = 1000.0;
        let approx = (FAR - NEAR) * z * z / (NEAR * FAR) / D24_MAX;
        let got = Layout::D24Standard.resolution(z);
        prepass::assert_within_abs!(
            got / approx,
            1.0,
            < 0.01,
            "comment above: the first-order closed form, within 1% for one code step",
            "resolution at z {z} vs the closed form {approx}"
        );
    }
}
