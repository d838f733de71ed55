//! The report's charts, each written twice: SVG (for the README and browsers) and PNG.
//!
//! Text is drawn with DejaVu Sans embedded in the binary (`font/`, Bitstream Vera licence), so
//! PNGs render the same on a fresh machine with no fonts installed.

pub use crate::fronts::Scatter;
use plotters::coord::Shift;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

const FONT: &[u8] = include_bytes!("font/DejaVuSans.ttf");
pub const FAMILY: &str = "sans-serif";
const SIZE: (u32, u32) = (960, 600);

/// Register the embedded font with plotters; call once before drawing.
pub fn init() -> Result<(), String> {
    plotters::style::register_font(FAMILY, FontStyle::Normal, FONT)
        .map_err(|_| "the embedded font could not be read".to_string())
}

/// Distinct colours for series: the colour-blind-friendly Okabe–Ito eight, then four of Paul
/// Tol's muted scheme.
pub fn colour(k: usize) -> RGBColor {
    const C: [RGBColor; 12] = [
        RGBColor(0, 114, 178),
        RGBColor(213, 94, 0),
        RGBColor(0, 158, 115),
        RGBColor(204, 121, 167),
        RGBColor(230, 159, 0),
        RGBColor(86, 180, 233),
        RGBColor(0, 0, 0),
        RGBColor(120, 120, 120),
        RGBColor(136, 34, 85),
        RGBColor(153, 153, 51),
        RGBColor(51, 34, 136),
        RGBColor(68, 170, 153),
    ];
    C[k % C.len()]
}

/// One named line of points `(x, y)`.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// Points in x order.
    pub points: Vec<(f64, f64)>,
}

/// A log–log line chart.
#[derive(Clone, Debug)]
pub struct LineChart {
    /// Title above the chart.
    pub title: String,
    /// x-axis label, with units.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
}

/// A `width × height` image of values (e.g. error over the octahedral square), drawn with a
/// colour scale and a colour bar.
#[derive(Clone, Debug)]
pub struct ErrorImage {
    /// Title above the image.
    pub title: String,
    /// x-axis label, with units.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// Colour-bar label, with units.
    pub value_label: String,
    /// Columns.
    pub width: usize,
    /// Rows (row 0 at the bottom).
    pub height: usize,
    /// `width × height` values, row-major; NaN marks cells with no value.
    pub values: Vec<f64>,
    /// The x and y ranges the image covers.
    pub extent: [(f64, f64); 2],
}

/// One histogram bin: `(lower edge, upper edge, count)`.
pub type Bin = (f64, f64, u64);

/// One panel of a histogram: its bins and its largest value, marked.
#[derive(Clone, Debug)]
pub struct HistSeries {
    /// Panel heading.
    pub label: String,
    /// Bins on a log x axis (positive edges).
    pub bins: Vec<Bin>,
    /// The largest value counted (marked with a line and its value).
    pub max: f64,
}

/// Histograms as small multiples (one panel per series, three across) on a shared log x axis,
/// each panel's y the share of the values in each bin.
#[derive(Clone, Debug)]
pub struct Histogram {
    /// Title above the panels.
    pub title: String,
    /// x-axis label, with units (once, under the panels).
    pub x_label: String,
    /// The panels.
    pub series: Vec<HistSeries>,
}

/// Anything the report draws.
#[derive(Clone, Debug)]
pub enum Chart {
    /// See [`LineChart`].
    Lines(LineChart),
    /// See [`Scatter`].
    Scatter(Scatter),
    /// See [`ErrorImage`].
    Image(ErrorImage),
    /// See [`Histogram`].
    Histogram(Histogram),
}

/// Write `chart` as `dir/stem.svg` and `dir/stem.png`; returns the SVG's path.
pub fn save(chart: &Chart, dir: &Path, stem: &str) -> Result<PathBuf, String> {
    let svg = dir.join(format!("{stem}.svg"));
    let png = dir.join(format!("{stem}.png"));
    let size = size(chart);
    {
        let root = SVGBackend::new(&svg, size).into_drawing_area();
        render(chart, &root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    {
        let root = BitMapBackend::new(&png, size).into_drawing_area();
        render(chart, &root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// Columns of the histograms' small multiples.
const HIST_COLUMNS: usize = 3;
/// Height of one histogram panel, in pixels.
const HIST_PANEL: u32 = 200;

/// A chart's image size in pixels: panelled charts grow with their panels.
fn size(chart: &Chart) -> (u32, u32) {
    match chart {
        Chart::Scatter(c) => crate::fronts::size(c.panels.len()),
        Chart::Histogram(c) => (
            SIZE.0,
            50 + 50 + HIST_PANEL * c.series.len().div_ceil(HIST_COLUMNS).max(1) as u32,
        ),
        _ => SIZE,
    }
}

/// The largest font size at most `size` (down to 9) at which `text` is at most `width`
/// pixels wide on `area`'s backend: titles and axis labels shrink to fit rather than run off.
pub fn fitted<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
    width: i32,
) -> f64 {
    let mut s = size;
    while s > 9.0 {
        match area.estimate_text_size(text, &(FAMILY, s).into_text_style(area)) {
            Ok((w, _)) if w as i32 > width => s -= 0.5,
            _ => break,
        }
    }
    s
}

/// A chart builder on `area` under `title` (at most `size`, fitted to the area's width), with
/// `[margin, right margin, x label area, y label area]` in pixels.
pub fn titled<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    size: f64,
    [margin, right, x_area, y_area]: [u32; 4],
) -> ChartBuilder<'a, 'static, DB> {
    let w = area.dim_in_pixel().0 as i32;
    let mut b = ChartBuilder::on(area);
    b.caption(
        title,
        (FAMILY, fitted(area, title, size, w - 20 - right as i32)),
    )
    .margin(margin)
    .margin_right(right)
    .x_label_area_size(x_area)
    .y_label_area_size(y_area);
    b
}

fn render<DB: DrawingBackend>(chart: &Chart, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    match chart {
        Chart::Lines(c) => lines(c, root),
        Chart::Scatter(c) => crate::fronts::draw(c, root),
        Chart::Image(c) => image(c, root),
        Chart::Histogram(c) => histogram(c, root),
    }
    .map_err(|e| e.to_string())
}

/// Tick text: plain numbers between 0.001 and 10^5, scientific outside.
pub fn tick(v: &f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-3..1e5).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

/// A log range around the positive values with a margin of `pad` (a factor) on both sides.
pub fn padded(values: impl Iterator<Item = f64>, pad: f64) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.1, 10.0);
    }
    (lo / pad, hi * pad)
}

/// Ticks at 1, 2 and 5 times powers of ten inside `[lo, hi]` (powers of ten only when that
/// would give more than a dozen), so a log axis narrower than a decade still has labels.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let all: Vec<f64> = (lo.log10().floor() as i32..=hi.log10().ceil() as i32)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|v| (lo..=hi).contains(v))
        .collect();
    if all.len() > 12 {
        all.into_iter()
            .filter(|v| (v.log10() - v.log10().round()).abs() < 1e-9)
            .collect()
    } else {
        all
    }
}

pub type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// The axes, labels and grid of a chart whose both axes are logarithmic, ticks in [`tick`]'s form.
fn log_log_mesh<DB: DrawingBackend, X, Y>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    x_label: &str,
    y_label: &str,
) -> DrawResult<DB>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .draw()
}

/// Powers of ten around the positive values, so log axes start and end on decades.
fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.1, 10.0);
    }
    let lo = 10f64.powf(lo.log10().floor());
    let hi = 10f64.powf(hi.log10().ceil()).max(lo * 10.0);
    (lo, hi)
}

/// The `k`-th of `n` lines' palette index and width: earlier series are drawn wider, so a
/// later one lying exactly on top leaves them visible.
pub fn line_style(k: usize, n: usize) -> (usize, u32) {
    (k % 12, (2 + (n - 1 - k) as u32).min(7))
}

fn lines<DB: DrawingBackend>(c: &LineChart, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let xs = decades(c.series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let ys = decades(c.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    // 1-2-5 ticks where an axis spans few decades (one label on a decade-wide axis before).
    let mut chart = titled(root, &c.title, 22.0, [14, 40, 50, 80]).build_cartesian_2d(
        (xs.0..xs.1)
            .log_scale()
            .with_key_points(log_ticks(xs.0, xs.1)),
        (ys.0..ys.1)
            .log_scale()
            .with_key_points(log_ticks(ys.0, ys.1)),
    )?;
    log_log_mesh(&mut chart, &c.x_label, &c.y_label)?;
    let n = c.series.len();
    for (k, s) in c.series.iter().enumerate() {
        let (ci, width) = line_style(k, n);
        let col = colour(ci);
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|p| p.0 > 0.0 && p.1 > 0.0 && p.0.is_finite() && p.1.is_finite())
            .collect();
        chart
            .draw_series(LineSeries::new(pts, col.stroke_width(width)))?
            .label(&s.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], col.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FAMILY, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// Viridis-like ramp: dark blue (low) through green to yellow (high).
fn ramp(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = t.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let k = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - k as f64;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

fn image<DB: DrawingBackend>(c: &ErrorImage, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    // A near-square image panel (octahedral maps are square), the colour bar beside it.
    let (main, rest) = root.split_horizontally(SIZE.1 + 80);
    let (bar, _) = rest.split_horizontally(170);
    let finite = || c.values.iter().copied().filter(|v| v.is_finite());
    let lo = finite().fold(f64::INFINITY, f64::min);
    let hi = finite().fold(f64::NEG_INFINITY, f64::max);
    let (lo, hi) = if lo < hi {
        (lo, hi)
    } else {
        (lo - 0.5, lo + 0.5)
    };
    let [(x0, x1), (y0, y1)] = c.extent;
    let mut chart =
        titled(&main, &c.title, 22.0, [14, 40, 50, 70]).build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(&c.x_label)
        .y_desc(&c.y_label)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .draw()?;
    let (dx, dy) = ((x1 - x0) / c.width as f64, (y1 - y0) / c.height as f64);
    chart.draw_series((0..c.height).flat_map(|r| {
        (0..c.width).filter_map(move |col| {
            let v = c.values[r * c.width + col];
            v.is_finite().then(|| {
                let (x, y) = (x0 + col as f64 * dx, y0 + r as f64 * dy);
                Rectangle::new(
                    [(x, y), (x + dx, y + dy)],
                    ramp((v - lo) / (hi - lo)).filled(),
                )
            })
        })
    }))?;
    let mut scale = ChartBuilder::on(&bar)
        .margin_top(60)
        .margin_bottom(64)
        .margin_right(10)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..1.0, lo..hi)?;
    scale
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(&c.value_label)
        .label_style((FAMILY, 13))
        .axis_desc_style((FAMILY, 14))
        .draw()?;
    let steps = 100;
    scale.draw_series((0..steps).map(|k| {
        let a = lo + (hi - lo) * k as f64 / steps as f64;
        let b = lo + (hi - lo) * (k + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            ramp(k as f64 / (steps - 1) as f64).filled(),
        )
    }))?;
    Ok(())
}

fn histogram<DB: DrawingBackend>(c: &Histogram, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let (w, h) = root.dim_in_pixel();
    let (head, rest) = root.split_vertically(50);
    let (body, foot) = rest.split_vertically(h - 100);
    head.draw(&Text::new(
        c.title.clone(),
        (14, 12),
        (FAMILY, fitted(&head, &c.title, 22.0, w as i32 - 30)).into_font(),
    ))?;
    let foot_size = fitted(&foot, &c.x_label, 16.0, w as i32 - 30);
    let foot_font = (FAMILY, foot_size).into_text_style(&foot);
    let (fw, _) = foot.estimate_text_size(&c.x_label, &foot_font)?;
    foot.draw(&Text::new(
        c.x_label.clone(),
        ((w as i32 - fw as i32) / 2, 20),
        foot_font,
    ))?;
    let bins = || c.series.iter().flat_map(|s| s.bins.iter());
    let x0 = bins().map(|b| b.0).fold(f64::INFINITY, f64::min);
    let x1 = bins().map(|b| b.1).fold(f64::NEG_INFINITY, f64::max);
    let (x0, x1) = if 0.0 < x0 && x0 < x1 {
        (x0, x1)
    } else {
        (1e-5, 10.0)
    };
    let rows = c.series.len().div_ceil(HIST_COLUMNS).max(1);
    let panels = body.split_evenly((rows, HIST_COLUMNS));
    for (k, (s, area)) in c.series.iter().zip(&panels).enumerate() {
        let total: u64 = s.bins.iter().map(|b| b.2).sum::<u64>().max(1);
        let share = |n: u64| 100.0 * n as f64 / total as f64;
        let top = s
            .bins
            .iter()
            .map(|b| share(b.2))
            .fold(0.0, f64::max)
            .max(1.0)
            * 1.25;
        let y_area = if k % HIST_COLUMNS == 0 { 52 } else { 40 };
        let mut chart = titled(area, &s.label, 16.0, [6, 14, 24, y_area]).build_cartesian_2d(
            (x0..x1).log_scale().with_key_points(decade_ticks(x0, x1)),
            0.0..top,
        )?;
        let mut mesh = chart.configure_mesh();
        mesh.light_line_style(WHITE)
            .label_style((FAMILY, 12))
            .axis_desc_style((FAMILY, 13))
            .x_label_formatter(&tick)
            .y_labels(4)
            .y_label_formatter(&|v| format!("{v:.0}"));
        if k % HIST_COLUMNS == 0 {
            mesh.y_desc("% of directions");
        }
        mesh.draw()?;
        let col = colour(0);
        chart.draw_series(
            s.bins
                .iter()
                .filter(|b| b.2 > 0)
                .map(|&(a, b, n)| Rectangle::new([(a, 0.0), (b, share(n))], col.mix(0.8).filled())),
        )?;
        if s.max > 0.0 && s.max.is_finite() {
            let m = s.max.clamp(x0, x1);
            chart.draw_series(LineSeries::new(
                [(m, 0.0), (m, top)],
                RGBColor(200, 0, 0).stroke_width(2),
            ))?;
            // The value beside the line, on the side with room.
            let text = format!("max {}°", tick_sig(s.max));
            let font = (FAMILY, 13)
                .into_text_style(area)
                .color(&RGBColor(200, 0, 0));
            let (tw, _) = area.estimate_text_size(&text, &font)?;
            let (px, py) = chart.plotting_area().get_pixel_range();
            let (mx, _) = chart.backend_coord(&(m, top));
            let x = if mx + 4 + tw as i32 <= px.end {
                mx + 4
            } else {
                mx - 4 - tw as i32
            };
            root.draw(&Text::new(text, (x.max(px.start), py.start + 2), font))?;
        }
    }
    Ok(())
}

/// Powers of ten in `[lo, hi]`.
fn decade_ticks(lo: f64, hi: f64) -> Vec<f64> {
    (lo.log10().floor() as i32..=hi.log10().ceil() as i32)
        .map(|e| 10f64.powi(e))
        .filter(|v| (lo * 0.999..=hi * 1.001).contains(v))
        .collect()
}

/// A value with two significant digits (for marked maxima).
fn tick_sig(v: f64) -> String {
    if (1e-3..1e3).contains(&v) {
        let digits = (1 - v.log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    } else {
        format!("{v:.1e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chart types the next sections will use render to real SVG and PNG files.
    #[test]
    fn image_and_histogram_render() {
        init().unwrap();
        let dir = std::env::temp_dir().join(format!("errplot-plot-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (w, h) = (64, 64);
        let values: Vec<f64> = (0..w * h)
            .map(|k| {
                let (x, y) = (
                    (k % w) as f64 / w as f64 * 2.0 - 1.0,
                    (k / w) as f64 / h as f64 * 2.0 - 1.0,
                );
                if x.abs() + y.abs() > 1.9 {
                    f64::NAN
                } else {
                    (x * x + y * y).sqrt() * 0.01
                }
            })
            .collect();
        let image = Chart::Image(ErrorImage {
            title: "test image".into(),
            x_label: "u".into(),
            y_label: "v".into(),
            value_label: "error (degrees)".into(),
            width: w,
            height: h,
            values,
            extent: [(-1.0, 1.0), (-1.0, 1.0)],
        });
        let hist = Chart::Histogram(Histogram {
            title: "test histogram".into(),
            x_label: "error (degrees)".into(),
            series: vec![HistSeries {
                label: "a".into(),
                bins: (0..20)
                    .map(|k| ((k + 1) as f64 * 0.1, (k + 2) as f64 * 0.1, 1u64 << k))
                    .collect(),
                max: 2.05,
            }],
        });
        for (chart, stem) in [(image, "image"), (hist, "hist")] {
            save(&chart, &dir, stem).unwrap();
            let png = std::fs::read(dir.join(format!("{stem}.png"))).unwrap();
            assert_eq!(&png[..4], b"\x89PNG");
            let svg = std::fs::read_to_string(dir.join(format!("{stem}.svg"))).unwrap();
            assert!(svg.contains("error (degrees)"));
        }
        if std::env::var_os("ERRPLOT_KEEP_TEST_PLOTS").is_none() {
            std::fs::remove_dir_all(&dir).unwrap();
        } else {
            eprintln!("kept {}", dir.display());
        }
    }
}
