//! The report's charts, each written twice: SVG (for the README and browsers) and PNG.
//!
//! Text is drawn with DejaVu Sans embedded in the binary (`font/`, Bitstream Vera licence), so
//! PNGs render the same on a fresh machine with no fonts installed.

use plotters::coord::Shift;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

const FONT: &[u8] = include_bytes!("font/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";
const SIZE: (u32, u32) = (960, 600);
/// Width of the scatter charts' legend strip, in pixels (labels up to about 36 characters).
const LEGEND_WIDTH: i32 = 290;

/// Register the embedded font with plotters; call once before drawing.
pub fn init() -> Result<(), String> {
    plotters::style::register_font(FAMILY, FontStyle::Normal, FONT)
        .map_err(|_| "the embedded font could not be read".to_string())
}

/// Distinct colours for series (colour-blind-friendly Okabe–Ito order, then greys).
fn colour(k: usize) -> RGBColor {
    const C: [RGBColor; 8] = [
        RGBColor(0, 114, 178),
        RGBColor(213, 94, 0),
        RGBColor(0, 158, 115),
        RGBColor(204, 121, 167),
        RGBColor(230, 159, 0),
        RGBColor(86, 180, 233),
        RGBColor(0, 0, 0),
        RGBColor(120, 120, 120),
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

/// One point of a scatter chart, with a label drawn beside it.
#[derive(Clone, Debug)]
pub struct Labelled {
    /// A peer (a baseline from another project): drawn as a cross, shipped points as filled
    /// shapes.
    pub peer: bool,
    /// Text beside the point.
    pub label: String,
    /// Position.
    pub x: f64,
    /// Position.
    pub y: f64,
}

/// A labelled scatter chart on log–log axes (the Pareto plots).
#[derive(Clone, Debug)]
pub struct Scatter {
    /// Title above the chart.
    pub title: String,
    /// x-axis label, with units.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// The points.
    pub points: Vec<Labelled>,
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

/// A histogram with a logarithmic count axis.
#[derive(Clone, Debug)]
pub struct Histogram {
    /// Title above the chart.
    pub title: String,
    /// x-axis label, with units.
    pub x_label: String,
    /// Named series of bins.
    pub series: Vec<(String, Vec<Bin>)>,
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
    {
        let root = SVGBackend::new(&svg, SIZE).into_drawing_area();
        render(chart, &root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    {
        let root = BitMapBackend::new(&png, SIZE).into_drawing_area();
        render(chart, &root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

fn render<DB: DrawingBackend>(chart: &Chart, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    match chart {
        Chart::Lines(c) => lines(c, root),
        Chart::Scatter(c) => scatter(c, root),
        Chart::Image(c) => image(c, root),
        Chart::Histogram(c) => histogram(c, root),
    }
    .map_err(|e| e.to_string())
}

/// Tick text: plain numbers between 0.001 and 10^5, scientific outside.
fn tick(v: &f64) -> String {
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
fn padded(values: impl Iterator<Item = f64>, pad: f64) -> (f64, f64) {
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
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
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

type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

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

fn lines<DB: DrawingBackend>(c: &LineChart, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let xs = decades(c.series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let ys = decades(c.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let mut chart = ChartBuilder::on(root)
        .caption(&c.title, (FAMILY, 22))
        .margin(14)
        .margin_right(40)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d((xs.0..xs.1).log_scale(), (ys.0..ys.1).log_scale())?;
    log_log_mesh(&mut chart, &c.x_label, &c.y_label)?;
    let n = c.series.len();
    for (k, s) in c.series.iter().enumerate() {
        let col = colour(k);
        // Earlier series are drawn wider, so a later one lying exactly on top leaves them visible.
        let width = (2 + (n - 1 - k) as u32).min(7);
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

fn scatter<DB: DrawingBackend>(c: &Scatter, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let xs = padded(c.points.iter().map(|p| p.x), 1.5);
    let ys = decades(c.points.iter().map(|p| p.y));
    // The legend gets its own strip on the right: drawn over the plot it hid points.
    let (plot, key) = root.split_horizontally(root.dim_in_pixel().0 as i32 - LEGEND_WIDTH);
    let mut chart = ChartBuilder::on(&plot)
        .caption(&c.title, (FAMILY, 22))
        .margin(14)
        .margin_right(40)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(
            (xs.0..xs.1)
                .log_scale()
                .with_key_points(log_ticks(xs.0, xs.1)),
            (ys.0..ys.1)
                .log_scale()
                .with_key_points(log_ticks(ys.0, ys.1)),
        )?;
    log_log_mesh(&mut chart, &c.x_label, &c.y_label)?;
    // Every point has its own (colour, marker) pair: shipped points are filled shapes, the
    // colour cycling fastest and the shape changing after each round of colours; peers are
    // crosses (× then +), numbered separately. Variants with equal cost and error coincide,
    // so the sizes also differ.
    let (mut shipped, mut peers) = (0usize, 0usize);
    let mut legend = Vec::new();
    for p in &c.points {
        if !(p.x > 0.0 && p.y > 0.0 && p.x.is_finite() && p.y.is_finite()) {
            continue;
        }
        let k = if p.peer { &mut peers } else { &mut shipped };
        let (col, shape) = marker_style(*k, p.peer);
        // Sizes step down with the index, so coinciding points stay visible around each other.
        let size = 13 - 2 * (*k % 4) as i32;
        *k += 1;
        chart.draw_series(std::iter::once(
            Marker::new(shape, size, col).at((p.x, p.y)),
        ))?;
        legend.push((p.label.as_str(), shape, col));
    }
    // One line per point, in drawing order, from the top of the plotting area.
    for (i, (label, shape, col)) in legend.into_iter().enumerate() {
        let y = 60 + 20 * i as i32;
        key.draw(&Marker::new(shape, 6, col).at((10, y)))?;
        key.draw(&Text::new(label, (24, y - 8), (FAMILY, 13)))?;
    }
    Ok(())
}

/// Marker shapes of the scatter charts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Square,
    Circle,
    Triangle,
    Diamond,
    Cross,
    Plus,
}

/// The colour and shape of the `k`-th shipped point or the `k`-th peer: the colour cycles
/// through the palette's eight, the shape steps after each cycle, so no two points of one chart
/// share both (for up to 32 shipped points and 16 peers).
fn marker_style(k: usize, peer: bool) -> (RGBColor, Shape) {
    const SHIPPED: [Shape; 4] = [
        Shape::Square,
        Shape::Circle,
        Shape::Triangle,
        Shape::Diamond,
    ];
    const PEER: [Shape; 2] = [Shape::Cross, Shape::Plus];
    let shape = if peer {
        PEER[(k / 8) % PEER.len()]
    } else {
        SHIPPED[(k / 8) % SHIPPED.len()]
    };
    (colour(k), shape)
}

/// One marker of a scatter chart, centred on its coordinate.
struct Marker {
    shape: Shape,
    size: i32,
    colour: RGBColor,
}

impl Marker {
    fn new(shape: Shape, size: i32, colour: RGBColor) -> Self {
        Marker {
            shape,
            size,
            colour,
        }
    }

    /// The marker as one element type for every shape (so the chart and its legend take it
    /// alike): a filled polygon plus two strokes; crosses have a one-pixel polygon, filled shapes
    /// stroke their own outline.
    fn at<C: Clone, DB: DrawingBackend>(self, at: C) -> MarkerElement<C, DB> {
        let (s, col) = (self.size, self.colour);
        let fill: Vec<(i32, i32)> = match self.shape {
            Shape::Square => vec![(-s, -s), (s, -s), (s, s), (-s, s)],
            Shape::Circle => (0..16)
                .map(|k| {
                    let t = f64::from(k) / 16.0 * std::f64::consts::TAU;
                    (
                        (f64::from(s) * t.cos()) as i32,
                        (f64::from(s) * t.sin()) as i32,
                    )
                })
                .collect(),
            Shape::Triangle => vec![(0, -s), (s, s), (-s, s)],
            Shape::Diamond => vec![(0, -s), (s, 0), (0, s), (-s, 0)],
            Shape::Cross | Shape::Plus => vec![(0, 0)],
        };
        let (a, b) = match self.shape {
            Shape::Cross => (vec![(-s, -s), (s, s)], vec![(-s, s), (s, -s)]),
            Shape::Plus => (vec![(-s, 0), (s, 0)], vec![(0, -s), (0, s)]),
            _ => {
                let mut outline = fill.clone();
                outline.push(fill[0]);
                (outline, vec![(0, 0)])
            }
        };
        let width = if matches!(self.shape, Shape::Cross | Shape::Plus) {
            3
        } else {
            1
        };
        EmptyElement::at(at)
            + Polygon::new(fill, col.filled())
            + PathElement::new(a, col.stroke_width(width))
            + PathElement::new(b, col.stroke_width(width))
    }
}

/// What [`Marker::at`] builds.
type MarkerElement<C, DB> = plotters::element::ComposedElement<
    C,
    DB,
    Polygon<(i32, i32)>,
    plotters::element::ComposedElement<
        (i32, i32),
        DB,
        PathElement<(i32, i32)>,
        PathElement<(i32, i32)>,
    >,
>;

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
    let mut chart = ChartBuilder::on(&main)
        .caption(&c.title, (FAMILY, 22))
        .margin(14)
        .margin_right(40)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
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
    let bins = || c.series.iter().flat_map(|s| s.1.iter());
    let x0 = bins().map(|b| b.0).fold(f64::INFINITY, f64::min);
    let x1 = bins().map(|b| b.1).fold(f64::NEG_INFINITY, f64::max);
    let (x0, x1) = if x0 < x1 { (x0, x1) } else { (0.0, 1.0) };
    let top = bins().map(|b| b.2).max().unwrap_or(1).max(1) as f64;
    let top = 10f64.powf(top.log10().ceil().max(1.0));
    let mut chart = ChartBuilder::on(root)
        .caption(&c.title, (FAMILY, 22))
        .margin(14)
        .margin_right(40)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, (0.5..top).log_scale())?;
    chart
        .configure_mesh()
        .x_desc(&c.x_label)
        .y_desc("count (log scale)")
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 16))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (k, (label, series)) in c.series.iter().enumerate() {
        let col = colour(k);
        // Outlined steps so overlapping series stay readable.
        let mut pts = Vec::new();
        for &(a, b, n) in series {
            let h = (n as f64).max(0.5);
            pts.push((a, h));
            pts.push((b, h));
        }
        chart
            .draw_series(LineSeries::new(pts, col.stroke_width(2)))?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], col.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .label_font((FAMILY, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
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
            series: vec![(
                "a".into(),
                (0..20)
                    .map(|k| (k as f64 * 0.1, (k + 1) as f64 * 0.1, 1u64 << k))
                    .collect(),
            )],
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
