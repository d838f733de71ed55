//! The error-against-cost charts: one panel per competing bit budget, each point labelled beside
//! it, prepass's functions filled and the peers (and textbook baselines) hollow, the Pareto front of each panel drawn.

use crate::plot::{DrawResult, FAMILY, colour, fitted, log_ticks, padded, tick, titled};
use plotters::coord::Shift;
use plotters::prelude::*;

/// What a point is: a shipped function (filled), the rounding form of one (filled, another
/// shape, joined to its precise form), or a peer's (hollow).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A shipped function (its precise form, where it has two).
    Shipped,
    /// A shipped function's rounding (`_fast`) form.
    Rounding,
    /// A baseline: another project's function, or a textbook form.
    Peer,
}

/// One point of an error-against-cost panel.
#[derive(Clone, Debug)]
pub struct Labelled {
    /// Short text drawn beside the point.
    pub label: String,
    /// The encoding it belongs to: points of one group share a colour and are joined.
    pub group: String,
    /// Shipped, rounding form or peer.
    pub kind: Kind,
    /// Cost.
    pub x: f64,
    /// Max error.
    pub y: f64,
}

/// One panel: the points that compete (one bit budget), under its own heading.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Heading, naming the budget.
    pub title: String,
    /// The points.
    pub points: Vec<Labelled>,
}

/// Error against cost on log–log axes, in panels stacked top to bottom; x and y ranges shared.
#[derive(Clone, Debug)]
pub struct Scatter {
    /// Title above the panels.
    pub title: String,
    /// x-axis label, with units (drawn under every panel).
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// The panels.
    pub panels: Vec<Panel>,
    /// x ticks, where the default (1, 2, 5 per decade) would not suit (e.g. bits).
    pub x_ticks: Option<Vec<f64>>,
}

/// Marker shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    /// ●
    Circle,
    /// ▲
    Triangle,
    /// ■
    Square,
    /// ◆
    Diamond,
}

/// How one point is drawn: colour (palette index), shape, filled or hollow.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Style {
    /// Palette index ([`colour`]).
    pub colour: usize,
    /// Marker shape.
    pub shape: Shape,
    /// Filled (shipped) or hollow (peer).
    pub filled: bool,
}

/// Colours in the palette before a group's shape changes.
const PALETTE: usize = 12;

/// Each point's style, in panel then point order. Groups take colours in first-seen order,
/// shipped and peer groups counted apart (they differ in fill); a group's precise form is a
/// circle, its rounding form a triangle, a peer a hollow square; past [`PALETTE`] groups the
/// shapes change (diamond, or a filled square for rounding forms), so no two groups of a
/// figure share colour, shape and fill (for up to 24 shipped and 24 peer groups).
pub fn styles(c: &Scatter) -> Vec<Style> {
    let (mut shipped, mut peers): (Vec<&str>, Vec<&str>) = (Vec::new(), Vec::new());
    let mut out = Vec::new();
    for p in c.panels.iter().flat_map(|p| &p.points) {
        let groups = if p.kind == Kind::Peer {
            &mut peers
        } else {
            &mut shipped
        };
        let k = groups
            .iter()
            .position(|g| *g == p.group)
            .unwrap_or_else(|| {
                groups.push(&p.group);
                groups.len() - 1
            });
        let second = k >= PALETTE;
        let shape = match (p.kind, second) {
            (Kind::Shipped, false) => Shape::Circle,
            (Kind::Rounding, false) => Shape::Triangle,
            (Kind::Peer, false) => Shape::Square,
            (Kind::Shipped, true) | (Kind::Peer, true) => Shape::Diamond,
            (Kind::Rounding, true) => Shape::Square,
        };
        out.push(Style {
            colour: k % PALETTE,
            shape,
            filled: p.kind != Kind::Peer,
        });
    }
    out
}

/// Whether a point can sit on log–log axes.
fn drawable(p: &Labelled) -> bool {
    p.x > 0.0 && p.y > 0.0 && p.x.is_finite() && p.y.is_finite()
}

/// The points of `points` on their Pareto front (no other point has cost and error both no
/// larger, one smaller), sorted by cost.
pub fn front(points: &[Labelled]) -> Vec<(f64, f64)> {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| drawable(p))
        .map(|p| (p.x, p.y))
        .collect();
    let mut f: Vec<(f64, f64)> = pts
        .iter()
        .copied()
        .filter(|&(x, y)| {
            !pts.iter()
                .any(|&(a, b)| a <= x && b <= y && (a < x || b < y))
        })
        .collect();
    f.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
    f.dedup();
    f
}

/// Height of one panel, in pixels.
pub const PANEL_HEIGHT: u32 = 430;
/// Height of the figure's heading (title and key).
const HEAD: u32 = 66;

/// The figure's size for `panels` panels.
pub fn size(panels: usize) -> (u32, u32) {
    (960, HEAD + PANEL_HEIGHT * panels.max(1) as u32)
}

/// A pixel rectangle `[x0, y0, x1, y1]`.
type Rect = [i32; 4];

fn overlap(a: &Rect, b: &Rect) -> i64 {
    let w = (a[2].min(b[2]) - a[0].max(b[0])).max(0);
    let h = (a[3].min(b[3]) - a[1].max(b[1])).max(0);
    i64::from(w) * i64::from(h)
}

/// Draw the figure.
pub fn draw<DB: DrawingBackend>(c: &Scatter, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let (w, _) = root.dim_in_pixel();
    let (head, body) = root.split_vertically(HEAD);
    let title_size = fitted(&head, &c.title, 22.0, w as i32 - 30);
    head.draw(&Text::new(
        c.title.clone(),
        (14, 8),
        (FAMILY, title_size).into_font(),
    ))?;
    // The key names only the kinds the figure has.
    let has = |k: Kind| c.panels.iter().flat_map(|p| &p.points).any(|p| p.kind == k);
    let mut parts = vec!["filled ● prepass"];
    if has(Kind::Rounding) {
        parts.push("▲ its rounding form (same colour, joined)");
    }
    if has(Kind::Peer) {
        parts.push("hollow ■ ◆ peers, textbook baselines");
    }
    parts.push("grey steps: the Pareto front");
    let key = parts.join("  ·  ");
    let key_size = fitted(&head, &key, 14.0, w as i32 - 30);
    head.draw(&Text::new(
        key.clone(),
        (14, 40),
        (FAMILY, key_size).into_font().color(&RGBColor(80, 80, 80)),
    ))?;
    let all = || {
        c.panels
            .iter()
            .flat_map(|p| &p.points)
            .filter(|p| drawable(p))
    };
    let xs = padded(all().map(|p| p.x), 1.6);
    let style_of = styles(c);
    let mut next_style = style_of.iter();
    let panels = body.split_evenly((c.panels.len().max(1), 1));
    for (panel, area) in c.panels.iter().zip(&panels) {
        let styles: Vec<Style> = next_style
            .by_ref()
            .take(panel.points.len())
            .copied()
            .collect();
        // Each panel its own error range: budgets differ by decades.
        let ys = padded(
            panel.points.iter().filter(|p| drawable(p)).map(|p| p.y),
            2.5,
        );
        draw_panel(c, panel, &styles, area, root, xs, ys)?;
    }
    Ok(())
}

fn draw_panel<DB: DrawingBackend>(
    c: &Scatter,
    panel: &Panel,
    styles: &[Style],
    area: &DrawingArea<DB, Shift>,
    root: &DrawingArea<DB, Shift>,
    xs: (f64, f64),
    ys: (f64, f64),
) -> DrawResult<DB> {
    let (w, h) = area.dim_in_pixel();
    let (y_area, x_area) = (78u32, 56u32);
    let desc_size = fitted(area, &c.x_label, 15.0, (w - y_area) as i32 - 30).min(fitted(
        area,
        &c.y_label,
        15.0,
        (h - x_area) as i32 - 60,
    ));
    let x_keys = c.x_ticks.clone().unwrap_or_else(|| log_ticks(xs.0, xs.1));
    let mut chart = titled(area, &panel.title, 18.0, [10, 24, x_area, y_area]).build_cartesian_2d(
        (xs.0..xs.1).log_scale().with_key_points(x_keys),
        (ys.0..ys.1)
            .log_scale()
            .with_key_points(log_ticks(ys.0, ys.1)),
    )?;
    chart
        .configure_mesh()
        .x_desc(&c.x_label)
        .y_desc(&c.y_label)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, desc_size))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .light_line_style(WHITE)
        .draw()?;
    // The front first, under the points.
    let f = front(&panel.points);
    let mut steps = Vec::new();
    for (i, &(x, y)) in f.iter().enumerate() {
        if i > 0 {
            steps.push((x, f[i - 1].1));
        }
        steps.push((x, y));
    }
    if let Some(&(_, y)) = f.last() {
        steps.push((xs.1, y));
    }
    if let Some(&(x, _)) = f.first() {
        steps.insert(0, (x, ys.1));
    }
    // Lines a label should not cover, as pixel segments.
    let mut segments: Vec<((i32, i32), (i32, i32))> = steps
        .windows(2)
        .map(|w| (chart.backend_coord(&w[0]), chart.backend_coord(&w[1])))
        .collect();
    chart.draw_series(LineSeries::new(
        steps,
        RGBColor(170, 170, 170).stroke_width(5),
    ))?;
    // A group's points joined (precise to rounding form).
    let pts: Vec<(&Labelled, Style)> = panel
        .points
        .iter()
        .zip(styles.iter().copied())
        .filter(|(p, _)| drawable(p))
        .collect();
    for (i, (p, s)) in pts.iter().enumerate() {
        for (q, _) in &pts[i + 1..] {
            if q.group == p.group {
                segments.push((
                    chart.backend_coord(&(p.x, p.y)),
                    chart.backend_coord(&(q.x, q.y)),
                ));
                chart.draw_series(LineSeries::new(
                    [(p.x, p.y), (q.x, q.y)],
                    colour(s.colour).stroke_width(2),
                ))?;
            }
        }
    }
    // Each segment as small boxes every 4 pixels along it.
    let lines: Vec<Rect> = segments
        .iter()
        .flat_map(|&((x0, y0), (x1, y1))| {
            let n = ((x1 - x0).abs().max((y1 - y0).abs()) / 4).max(1);
            (0..=n).map(move |k| {
                let (x, y) = (x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n);
                [x - 3, y - 3, x + 3, y + 3]
            })
        })
        .collect();
    let mut taken: Vec<Rect> = Vec::new();
    let centres: Vec<(i32, i32)> = pts
        .iter()
        .map(|(p, _)| chart.backend_coord(&(p.x, p.y)))
        .collect();
    // Peers (hollow, larger) first, so a shipped point at the same place shows inside.
    for peers_pass in [true, false] {
        for (&(x, y), (_, s)) in centres.iter().zip(&pts) {
            if s.filled != peers_pass {
                let r = radius(*s);
                root.draw(&marker(*s, r).at((x, y)))?;
                taken.push([x - r, y - r, x + r, y + r]);
            }
        }
    }
    // Labels: beside each point, the first free place of eight around it, else the least
    // covered; never outside the plotting area.
    let (px, py) = chart.plotting_area().get_pixel_range();
    let font = (FAMILY, 14).into_text_style(root);
    for (&(x, y), (p, s)) in centres.iter().zip(&pts) {
        let (tw, th) = root.estimate_text_size(&p.label, &font)?;
        let (tw, th) = (tw as i32, th as i32);
        let g = radius(*s) + 6;
        let candidates = [
            (x + g, y - th / 2),
            (x - g - tw, y - th / 2),
            (x - tw / 2, y - g - th),
            (x - tw / 2, y + g),
            (x + g, y - g - th),
            (x + g, y + g),
            (x - g - tw, y - g - th),
            (x - g - tw, y + g),
            (x + 2 * g, y - th / 2 - th),
            (x + 2 * g, y + th / 2),
            (x - 2 * g - tw, y - th / 2 - th),
            (x - 2 * g - tw, y + th / 2),
        ];
        let place = candidates
            .iter()
            .map(|&(lx, ly)| {
                let lx = lx.clamp(px.start + 2, (px.end - 2 - tw).max(px.start + 2));
                let ly = ly.clamp(py.start + 2, (py.end - 2 - th).max(py.start + 2));
                let r = [lx, ly, lx + tw, ly + th];
                // Covering a marker or a label costs more than crossing a line.
                let cover: i64 = 8 * taken.iter().map(|t| overlap(t, &r)).sum::<i64>()
                    + lines.iter().map(|t| overlap(t, &r)).sum::<i64>();
                (cover, r)
            })
            .min_by_key(|(cover, _)| *cover)
            .map(|(_, r)| r)
            .unwrap_or([x, y, x + tw, y + th]);
        taken.push(place);
        let col = colour(s.colour);
        let dark = RGBColor(col.0 / 2 + 10, col.1 / 2 + 10, col.2 / 2 + 10);
        root.draw(&Text::new(
            p.label.clone(),
            (place[0], place[1]),
            font.color(&dark),
        ))?;
    }
    Ok(())
}

/// A marker's half-size: peers' hollow markers larger, so a shipped point at the same place
/// shows inside one.
fn radius(s: Style) -> i32 {
    if s.filled { R } else { R + 3 }
}

/// Half-size of a filled marker, in pixels.
const R: i32 = 7;

/// What [`Marker::at`] builds.
type MarkerElement<DB> = plotters::element::ComposedElement<
    (i32, i32),
    DB,
    Polygon<(i32, i32)>,
    PathElement<(i32, i32)>,
>;

/// A marker as one element type for every shape: a polygon, filled or outlined.
struct Marker {
    points: Vec<(i32, i32)>,
    style: ShapeStyle,
}

fn marker(s: Style, r: i32) -> Marker {
    let points: Vec<(i32, i32)> = match s.shape {
        Shape::Circle => (0..20)
            .map(|k| {
                let t = f64::from(k) / 20.0 * std::f64::consts::TAU;
                (
                    (f64::from(r) * t.cos()).round() as i32,
                    (f64::from(r) * t.sin()).round() as i32,
                )
            })
            .collect(),
        Shape::Triangle => vec![(0, -r - 1), (r + 1, r), (-r - 1, r)],
        Shape::Square => vec![
            (-r + 1, -r + 1),
            (r - 1, -r + 1),
            (r - 1, r - 1),
            (-r + 1, r - 1),
        ],
        Shape::Diamond => vec![(0, -r - 1), (r + 1, 0), (0, r + 1), (-r - 1, 0)],
    };
    let c = colour(s.colour);
    Marker {
        points,
        style: if s.filled {
            c.filled()
        } else {
            c.stroke_width(3)
        },
    }
}

impl Marker {
    fn at<DB: DrawingBackend>(self, at: (i32, i32)) -> MarkerElement<DB> {
        let mut outline = self.points.clone();
        outline.push(self.points[0]);
        let (fill, edge) = if self.style.filled {
            (self.style, self.style.color.stroke_width(1))
        } else {
            (TRANSPARENT.filled(), self.style)
        };
        EmptyElement::at(at) + Polygon::new(self.points, fill) + PathElement::new(outline, edge)
    }
}
