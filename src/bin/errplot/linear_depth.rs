//! View distance from stored depth (`wgsl/linear_depth.wgsl`) against the textbook baselines
//! (`tests/baselines/linear_depth.wgsl`): error against distance, the stiff-grid table, and the
//! cost-table variants.

use crate::ctx::{Ctx, NEEDS_ADAPTER, Tier, num};
use crate::peers;
use crate::plot::{Chart, LineChart, Series};
use crate::variant::{TimedArg, Variant, Wgsl, twin_timer};
use prepass::depth24::DEPTH24_MAX;
use prepass::harness::Arg;
use prepass::linear_depth as ld;
use prepass::precision::metrics::{ErrorStats, relative_error};
use prepass::projection::DepthConvention;
use prepass::sweep::linear_depth::{
    GridRow, NEARS, StiffCase, codes_sweep, grid_table, stiff_grid, textbook_consts,
};
use std::fmt::Write as _;

/// The textbook forms the stable ones are compared with (test baselines, not public API).
const BASELINES: &str = include_str!("../../../tests/baselines/linear_depth.wgsl");

/// Near plane of the error-against-distance chart, metres.
pub const NEAR: f32 = 0.1;

/// far/near ratios plotted.
pub const RATIOS: [f64; 3] = [1e3, 1e5, 1e7];

/// The far/near ratio whose forms enter the cost table.
pub const VARIANT_RATIO: f64 = 1e5;

/// Bins per curve (log-spaced in distance).
pub const BINS: usize = 120;

/// Float depths per grid case in the default tier: a sample of the full run's 2^22 (the stiff
/// grid's float sweeps are cheap beside its D24 ones; the sample keeps the run short).
const DEFAULT_FLOATS: usize = 1 << 18;

/// Values per timing tile.
const TILE: u32 = 1 << 16;

fn source() -> String {
    format!("{}\n{BASELINES}", prepass::wgsl::LINEAR_DEPTH)
}

/// The chart of error against distance for the given series.
pub fn chart(series: Vec<Series>) -> Chart {
    Chart::Lines(LineChart {
        title: format!("View distance from a D24 code: arithmetic error, near {NEAR} m"),
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

/// The textbook form (Lee, "Pre-lighting in Resistance 2") in f32 on the CPU, exactly as the
/// baseline WGSL spells it.
fn textbook_cpu(d: u32, ab: [f32; 2]) -> f32 {
    let zw = d as f32 * (1.0 / DEPTH24_MAX as f32);
    1.0 / (zw * ab[0] + ab[1])
}

/// One plotted form: label, WGSL function, its arguments after the code, its CPU evaluation.
type Form<'a> = (
    &'static str,
    &'static str,
    Vec<Arg<'a>>,
    Box<dyn Fn(u32) -> f32>,
);

/// Codes spread over the whole range, as a timing tile.
fn timing_codes() -> Vec<u32> {
    (0..TILE)
        .map(|k| k.wrapping_mul(0x9e37_79b1) & DEPTH24_MAX)
        .collect()
}

/// The chart, the grid table, their CSV files, and the variants for the cost table.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let src = source();
    let place = if ctx.gpu().is_some() {
        "adapter"
    } else {
        "cpu"
    };
    // Quick runs plot the cost-table ratio only; the default and full runs all three (each
    // curve is every D24 code, about a second on lavapipe).
    let ratios: Vec<f64> = if ctx.opts.quick() {
        vec![VARIANT_RATIO]
    } else {
        RATIOS.to_vec()
    };
    let bar = ctx.progress(ratios.len() as u64 * 2, "linear depth");
    let mut series = Vec::new();
    let mut csv = String::from("form,where,near_m,far_m,distance_m,max_relative_error\n");
    let mut variant_errors: Vec<(&str, ErrorStats)> = Vec::new();
    for ratio in ratios {
        let case = StiffCase {
            near: NEAR,
            far: (f64::from(NEAR) * ratio) as f32,
            ratio,
        };
        let (near, far) = (case.near, case.far);
        let ab = textbook_consts(case, DepthConvention::Standard);
        let k24 = case
            .projection(DepthConvention::Standard)
            .depth24_consts()
            .expect("a projection of the convention these constants read");
        let forms: [Form; 3] = [
            (
                "stable",
                "view_z_from_depth24",
                vec![Arg::splat_f32(near), Arg::splat_f32(far)],
                Box::new(move |d| ld::view_z_from_depth24(d, near, far)),
            ),
            (
                "stable_consts",
                "view_z_from_depth24_consts",
                vec![Arg::splat_vec(&k24.to_wgsl())],
                Box::new(move |d| ld::view_z_from_depth24_consts(d, k24)),
            ),
            (
                "textbook",
                "baseline_view_z_textbook24",
                vec![Arg::splat_vec(&ab)],
                Box::new(move |d| textbook_cpu(d, ab)),
            ),
        ];
        for (form, function, extra, cpu) in forms {
            // On the adapter when there is one; otherwise the same arithmetic on the CPU.
            let values: Vec<f32> = match ctx.gpu() {
                Some(g) => {
                    codes_sweep(g, &src, function, &extra, case, None)
                        .map_err(|e| e.to_string())?
                        .1
                }
                None => (0..=DEPTH24_MAX).map(&*cpu).collect(),
            };
            let samples: Vec<(f64, f64)> = values
                .iter()
                .enumerate()
                .map(|(d, &v)| {
                    let exact = ld::exact::view_z_from_depth24(d as u32, near, far);
                    (exact, relative_error(f64::from(v), exact))
                })
                .collect();
            if ratio == VARIANT_RATIO {
                let mut stats = ErrorStats::default();
                for (k, &(_, e)) in samples.iter().enumerate() {
                    stats.add(k as u64, e);
                }
                variant_errors.push((function, stats));
            }
            if form == "stable_consts" {
                continue; // plotted curve would coincide with `stable`
            }
            let points = max_per_bin(f64::from(near), f64::from(far), samples.into_iter());
            for &(z, e) in &points {
                let _ = writeln!(csv, "{form},{place},{near},{far},{z},{e}");
            }
            let label = match form {
                "stable" => "stable view_z_from_depth24",
                _ => "textbook 1/(zw·a+b)",
            };
            series.push(Series {
                label: format!("{label}, far/near = {ratio:.0e} ({place})"),
                points,
            });
            bar.inc(1);
        }
    }
    bar.finish_and_clear();
    ctx.csv("linear_depth_error.csv", &csv)?;

    ctx.line("## View distance from depth");
    ctx.line("");
    ctx.line(format!(
        "Relative error of view distance from every standard-Z D24 code, maximum per distance \
         bin, against the exact f64 distance of the code, computed on the {place}. The textbook \
         form `1/(zw·a + b)` cancels near the far plane and loses about (far/near)·2^-24; the \
         stable form (`n·D / ((D − d) + d·n/f)`) stays within a few ULP everywhere. Data: \
         `linear_depth_error.csv`."
    ));
    ctx.line("");
    ctx.chart(
        &chart(series),
        "linear_depth_error",
        "view distance error against distance",
    )?;

    grid_section(ctx)?;

    // Cost-table variants, far/near 1e5.
    let case = StiffCase {
        near: NEAR,
        far: (f64::from(NEAR) * VARIANT_RATIO) as f32,
        ratio: VARIANT_RATIO,
    };
    let (near, far) = (case.near, case.far);
    let ab = textbook_consts(case, DepthConvention::Standard);
    let k24 = case
        .projection(DepthConvention::Standard)
        .depth24_consts()
        .expect("a projection of the convention these constants read");
    let tile = timing_codes();
    for (function, stats) in variant_errors {
        let (args, twin) = match function {
            "view_z_from_depth24" => (
                vec![
                    TimedArg::Column(tile.clone()),
                    TimedArg::Splat([near.to_bits(), 0, 0, 0]),
                    TimedArg::Splat([far.to_bits(), 0, 0, 0]),
                ],
                twin_timer(tile.clone(), move |d| ld::view_z_from_depth24(d, near, far)),
            ),
            "view_z_from_depth24_consts" => (
                vec![
                    TimedArg::Column(tile.clone()),
                    TimedArg::Splat([
                        k24.near_times_max.to_bits(),
                        k24.near_over_far.to_bits(),
                        0,
                        0,
                    ]),
                ],
                twin_timer(tile.clone(), move |d| {
                    ld::view_z_from_depth24_consts(d, k24)
                }),
            ),
            _ => (
                vec![
                    TimedArg::Column(tile.clone()),
                    TimedArg::Splat([ab[0].to_bits(), ab[1].to_bits(), 0, 0]),
                ],
                twin_timer(tile.clone(), move |d| textbook_cpu(d, ab)),
            ),
        };
        ctx.variants.push(Variant {
            family: "view distance from a standard-Z D24 code, far/near 1e5",
            unit: "relative",
            name: function.into(),
            bits: 24,
            error: Some(stats),
            error_from: format!("{place}: all 2^24 codes, near {NEAR} m"),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: src.clone(),
                function: function.into(),
                args,
            }),
            twin: Some(twin),
        });
    }
    peer_variants(ctx, near, far, &tile)
}

/// The depth peers, on the adapter: LYGIA's two forms in the D24 family above; Bevy's
/// `−near/d` beside the shipped reversed-Z forms with an infinite far plane, in a family of its
/// own (float depths from [`peers::reversed_depths`]). No Rust twins for the peers.
fn peer_variants(ctx: &mut Ctx, near: f32, far: f32, tile: &[u32]) -> Result<(), String> {
    let Some(g) = ctx.gpu() else {
        return Ok(());
    };
    let mut pushes = Vec::new();
    for p in &peers::DEPTH24_PEERS {
        let stats = peers::depth24_errors(g, p, near, far)?;
        pushes.push(Variant {
            family: "view distance from a standard-Z D24 code, far/near 1e5",
            unit: "relative",
            name: format!("{}{}", peers::PREFIX, p.name),
            bits: 24,
            error: Some(stats),
            error_from: format!("adapter: all 2^24 codes, near {NEAR} m"),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: peers::LYGIA.into(),
                function: p.function.into(),
                args: vec![
                    TimedArg::Column(tile.to_vec()),
                    TimedArg::Splat([near.to_bits(), 0, 0, 0]),
                    TimedArg::Splat([far.to_bits(), 0, 0, 0]),
                ],
            }),
            twin: None,
        });
    }
    // Reversed-Z, infinite far: the shipped forms and Bevy's on the same float depths.
    let family = "view distance from a reversed-Z f32 depth, infinite far";
    let z = peers::reversed_depths(1 << 20);
    let z_tile: Vec<u32> = z.iter().step_by(16).map(|x| x.to_bits()).collect();
    let inf = f32::INFINITY;
    let k = [near, 1.0, 0.0];
    let z_col = Arg::column(&z);
    let shipped: [(&str, Vec<Arg>, Vec<TimedArg>); 2] = [
        (
            "view_z_from_reversed_depth",
            vec![z_col, Arg::splat_f32(near), Arg::splat_f32(inf)],
            vec![
                TimedArg::Column(z_tile.clone()),
                TimedArg::Splat([near.to_bits(), 0, 0, 0]),
                TimedArg::Splat([inf.to_bits(), 0, 0, 0]),
            ],
        ),
        (
            "view_z_from_reversed_depth_consts",
            vec![z_col, Arg::splat_vec(&k)],
            vec![
                TimedArg::Column(z_tile.clone()),
                TimedArg::Splat([near.to_bits(), 1f32.to_bits(), 0, 0]),
            ],
        ),
    ];
    for (function, args, timed) in shipped {
        let out = g
            .kernel(prepass::wgsl::LINEAR_DEPTH, function)
            .and_then(|kern| kern.run(&args, z.len() as u64))
            .map_err(|e| format!("{function}: {e}"))?;
        let twin: crate::variant::TwinTimer = if function == "view_z_from_reversed_depth" {
            twin_timer(
                z_tile.iter().map(|&b| f32::from_bits(b)).collect(),
                move |x| ld::view_z_from_reversed_depth(x, near, inf),
            )
        } else {
            let kc = prepass::projection::ReversedDepthConsts {
                near,
                one_minus_near_over_far: 1.0,
                near_over_far: 0.0,
            };
            twin_timer(
                z_tile.iter().map(|&b| f32::from_bits(b)).collect(),
                move |x| ld::view_z_from_reversed_depth_consts(x, kc),
            )
        };
        pushes.push(Variant {
            family,
            unit: "relative",
            name: function.into(),
            bits: 0,
            error: Some(peers::reversed_errors(&z, out.as_f32(), near, false)),
            error_from: format!("adapter: 2^20 depths in [2^-20, 1], near {NEAR} m"),
            upper_only: false,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: prepass::wgsl::LINEAR_DEPTH.into(),
                function: function.into(),
                args: timed,
            }),
            twin: Some(twin),
        });
    }
    let out = g
        .kernel(peers::BEVY, "peer_bevy_view_z_reversed_infinite")
        .and_then(|kern| kern.run(&[z_col, Arg::splat_f32(near)], z.len() as u64))
        .map_err(|e| format!("peer_bevy_view_z_reversed_infinite: {e}"))?;
    pushes.push(Variant {
        family,
        unit: "relative",
        name: format!("{}bevy −near/d (negated)", peers::PREFIX),
        bits: 0,
        error: Some(peers::reversed_errors(&z, out.as_f32(), near, true)),
        error_from: format!("adapter: 2^20 depths in [2^-20, 1], near {NEAR} m"),
        upper_only: false,
        error_upper: None,
        wgsl: Some(Wgsl {
            source: peers::BEVY.into(),
            function: "peer_bevy_view_z_reversed_infinite".into(),
            args: vec![
                TimedArg::Column(z_tile),
                TimedArg::Splat([near.to_bits(), 0, 0, 0]),
            ],
        }),
        twin: None,
    });
    ctx.variants.extend(pushes);
    Ok(())
}

fn max_ulp(s: &prepass::sweep::linear_depth::LinearStats) -> String {
    num(s.ulps.max)
}

fn max_rel(s: &prepass::sweep::linear_depth::LinearStats) -> String {
    num(s.relative.max)
}

/// The stiff grid: every depth path × near × far/near, stable forms beside both baselines.
fn grid_section(ctx: &mut Ctx) -> Result<(), String> {
    // Quick runs: near 0.1 with far/near 1e6 and ∞, 2^16 float depths. Default runs: near 0.1
    // with all five far/near ratios, DEFAULT_FLOATS float depths (each case sweeps every D24
    // code four times, so the full grid's 25 cases (100 such sweeps) are most of the full
    // section). Full runs: all 25 cases, 2^22 floats (the tests run 2^24 per case and assert
    // the bound).
    let tier = ctx.opts.tier;
    let cases: Vec<StiffCase> = stiff_grid()
        .into_iter()
        .filter(|c| match tier {
            Tier::Quick => c.near == NEARS[2] && c.ratio >= 1e6 && c.ratio != 1e9,
            Tier::Default => c.near == NEARS[2],
            Tier::Full => true,
        })
        .collect();
    let float_count = ctx.opts.pick(1 << 16, DEFAULT_FLOATS, 1 << 22);
    ctx.line("### Stiff projections: max error per depth path and case");
    ctx.line("");
    let Some(g) = ctx.gpu() else {
        ctx.line(format!("The grid runs the WGSL: {NEEDS_ADAPTER}."));
        ctx.line("");
        return Ok(());
    };
    let bar = ctx.progress(cases.len() as u64 * 3, "linear depth grid");
    let rows: Vec<GridRow> =
        grid_table(g, BASELINES, &cases, float_count, |_| bar.inc(1)).map_err(|e| e.to_string())?;
    bar.finish_and_clear();
    ctx.line(format!(
        "On the adapter. D24: all 2^24 codes; float: {float_count} depths spread in ULP space \
         over (0, 1] plus the 64 next to 0 and to 1. Stable forms in f32 ULPs of the exact \
         distance; baselines as relative error (∞: a result of the wrong sign or infinite where \
         the distance is finite). Data: `linear_depth_grid.csv`.{}",
        match tier {
            Tier::Full => String::new(),
            _ => format!(
                " This run: {} of the full grid's 25 cases (near {} m) and {float_count} of \
                 its 2^22 float depths; `--full` for all.",
                cases.len(),
                NEARS[2]
            ),
        }
    ));
    ctx.line("");
    ctx.line("| depth | near (m) | far/near | stable (ULP) | `_consts` (ULP) | textbook 1/(z·a+b) (relative) | B/(z−A) (relative) |");
    ctx.line("|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "path,near_m,far_over_near,stable_max_ulp,consts_max_ulp,stable_max_relative,\
         textbook_max_relative,b_over_z_minus_a_max_relative\n",
    );
    for r in &rows {
        ctx.line(format!(
            "| {} | {} | {:e} | {} | {} | {} | {} |",
            r.path.label(),
            r.case.near,
            r.case.ratio,
            max_ulp(&r.stable),
            max_ulp(&r.stable_consts),
            max_rel(&r.textbook),
            max_rel(&r.b_over_z_minus_a)
        ));
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{}",
            r.path.label(),
            r.case.near,
            r.case.ratio,
            r.stable.ulps.max,
            r.stable_consts.ulps.max,
            r.stable.relative.max,
            r.textbook.relative.max,
            r.b_over_z_minus_a.relative.max
        );
    }
    ctx.line("");
    ctx.csv("linear_depth_grid.csv", &csv)
}
