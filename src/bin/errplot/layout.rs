//! The figures checked, not only written: every text box inside the image, every series of a
//! figure told apart by its style and its name, every figure with data.
//!
//! Text boxes are measured on the SVG as written, with plotters' own extents for the embedded
//! font ([`crate::plot::FAMILY`]) at the size plotters drew (the SVG's `font-size` × 1.24).
//! plotters scales the font to its full height (ascent − descent, 1.16 em for DejaVu Sans) where
//! a browser scales it to the em, so these widths are the PNG's and about 6 % wider than a
//! browser draws the SVG: a box that fits here fits both.

use crate::fronts;
use crate::plot::{self, Chart, FAMILY};
use plotters::style::{FontDesc, FontFamily, FontStyle};

/// The value of attribute `name` in the tag text `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    let len = tag[start..].find('"')?;
    Some(&tag[start..start + len])
}

fn number(tag: &str, name: &str) -> Option<f64> {
    attr(tag, name)?.trim().parse().ok()
}

fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// The corners of `text`'s box as drawn by the `<text>` tag `tag` (anchor, baseline shift and
/// rotation applied), or why it cannot be measured.
fn text_box(tag: &str, text: &str) -> Result<[(f64, f64); 4], String> {
    let (x, y) = (
        number(tag, "x").ok_or("no x")?,
        number(tag, "y").ok_or("no y")?,
    );
    let f = number(tag, "font-size").ok_or("no font-size")?;
    let (w, _) = FontDesc::new(FontFamily::Name(FAMILY), f * 1.24, FontStyle::Normal)
        .box_size(text)
        .map_err(|e| format!("the font: {e:?}"))?;
    let w = f64::from(w);
    let (left, right) = match attr(tag, "text-anchor") {
        Some("middle") => (-w / 2.0, w / 2.0),
        Some("end") => (-w, 0.0),
        _ => (0.0, w),
    };
    // plotters' baseline shifts: top (0.76em), bottom (−0.5ex), centre (0.5ex), or none.
    let (top, bottom) = match attr(tag, "dy") {
        Some("0.76em") => (0.0, f),
        Some("-0.5ex") => (-f, 0.0),
        Some("0.5ex") => (-f / 2.0, f / 2.0),
        _ => (-0.76 * f, 0.24 * f),
    };
    let turn = attr(tag, "transform")
        .and_then(|t| t.strip_prefix("rotate("))
        .and_then(|t| t.split([',', ' ', ')']).next())
        .and_then(|a| a.parse::<f64>().ok())
        .unwrap_or(0.0)
        .to_radians();
    let (s, c) = turn.sin_cos();
    Ok([(left, top), (right, top), (right, bottom), (left, bottom)]
        .map(|(dx, dy)| (x + dx * c - dy * s, y + dx * s + dy * c)))
}

/// What in the SVG `svg` falls outside its image: each text box and each rectangle (legend
/// boxes) that leaves the view box by more than half a pixel.
pub fn svg_problems(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let Some(view) = attr(svg, "viewBox") else {
        return vec!["no viewBox".into()];
    };
    let v: Vec<f64> = view.split(' ').filter_map(|s| s.parse().ok()).collect();
    let [x0, y0, w, h] = v[..] else {
        return vec![format!("viewBox {view:?}")];
    };
    let inside = |(x, y): (f64, f64)| {
        (x0 - 0.5..=x0 + w + 0.5).contains(&x) && (y0 - 0.5..=y0 + h + 0.5).contains(&y)
    };
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let after = &rest[start..];
        let Some(tag_end) = after.find('>') else {
            break;
        };
        let Some(close) = after.find("</text>") else {
            break;
        };
        let (tag, text) = (
            &after[..tag_end],
            unescape(after[tag_end + 1..close].trim()),
        );
        match text_box(tag, &text) {
            Ok(corners) if corners.iter().all(|&p| inside(p)) => {}
            Ok(corners) => {
                let xs = corners.map(|p| p.0);
                let ys = corners.map(|p| p.1);
                let min = |a: [f64; 4]| a.iter().copied().fold(f64::INFINITY, f64::min);
                let max = |a: [f64; 4]| a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                out.push(format!(
                    "text {text:?} spans x {:.0}..{:.0}, y {:.0}..{:.0}: outside the {w}×{h} image",
                    min(xs),
                    max(xs),
                    min(ys),
                    max(ys)
                ));
            }
            Err(why) => out.push(format!("text {text:?} cannot be measured: {why}")),
        }
        rest = &after[close..];
    }
    let mut rest = svg;
    while let Some(start) = rest.find("<rect") {
        let after = &rest[start..];
        let tag = &after[..after.find('>').unwrap_or(after.len())];
        if let (Some(x), Some(y), Some(rw), Some(rh)) = (
            number(tag, "x"),
            number(tag, "y"),
            number(tag, "width"),
            number(tag, "height"),
        ) && !(inside((x, y)) && inside((x + rw, y + rh)))
        {
            out.push(format!(
                "a box at ({x}, {y}) of {rw}×{rh} leaves the {w}×{h} image"
            ));
        }
        rest = &after[5..];
    }
    out
}

/// What in the chart a reader could not tell apart or would find empty: two series with one
/// name, two series drawn alike (colour and marker, or colour and line width), no data.
pub fn chart_problems(chart: &Chart) -> Vec<String> {
    let mut out = Vec::new();
    let mut once = |names: Vec<String>, what: &str| {
        for (i, n) in names.iter().enumerate() {
            if names[..i].contains(n) {
                out.push(format!("two {what} {n:?}"));
            }
        }
    };
    let points = match chart {
        Chart::Scatter(c) => {
            let all: Vec<&fronts::Labelled> = c.panels.iter().flat_map(|p| &p.points).collect();
            once(
                all.iter().map(|p| p.label.clone()).collect(),
                "points named",
            );
            once(
                fronts::styles(c).iter().map(|s| format!("{s:?}")).collect(),
                "points drawn as",
            );
            all.iter()
                .filter(|p| p.x > 0.0 && p.y > 0.0 && p.x.is_finite() && p.y.is_finite())
                .count()
        }
        Chart::Lines(c) => {
            once(
                c.series.iter().map(|s| s.label.clone()).collect(),
                "lines named",
            );
            once(
                (0..c.series.len())
                    .map(|k| format!("{:?}", plot::line_style(k, c.series.len())))
                    .collect(),
                "lines drawn as (colour, width)",
            );
            c.series.iter().map(|s| s.points.len()).sum()
        }
        Chart::Histogram(c) => {
            once(
                c.series.iter().map(|s| s.label.clone()).collect(),
                "panels named",
            );
            c.series
                .iter()
                .map(|s| s.bins.iter().map(|b| b.2 as usize).sum::<usize>())
                .sum()
        }
        Chart::Image(c) => c.values.iter().filter(|v| v.is_finite()).count(),
    };
    if points == 0 {
        out.push("no data drawn".into());
    }
    out
}

/// Every SVG in `dir` checked by [`svg_problems`]; one line per problem, file named.
pub fn check_dir(dir: &std::path::Path) -> Result<(usize, Vec<String>), String> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    files.sort();
    let mut problems = Vec::new();
    for f in &files {
        let svg = std::fs::read_to_string(f).map_err(|e| format!("{}: {e}", f.display()))?;
        let name = f.file_name().unwrap_or_default().to_string_lossy();
        problems.extend(
            svg_problems(&svg)
                .into_iter()
                .map(|p| format!("{name}: {p}")),
        );
    }
    Ok((files.len(), problems))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn svg(text_tag: &str) -> String {
        format!(
            "<svg width=\"200\" height=\"100\" viewBox=\"0 0 200 100\">\n{text_tag}\nhello world\n</text>\n</svg>"
        )
    }

    /// The busiest figures the report draws, on synthetic data: a front with every kind of
    /// point (the key at its longest) and a long title and axis label, and a histogram of 19
    /// panels, pass both checks. (A default run's encode front failed here once: its key, in
    /// full, ran 23 px past the right edge at the smallest font.)
    #[test]
    fn the_busiest_figures_pass_their_checks() {
        use crate::fronts::{Kind, Labelled, Panel, Scatter};
        use crate::plot::{HistSeries, Histogram};
        plot::init().unwrap();
        let point = |k: usize, kind: Kind| Labelled {
            label: format!("{kind:?} encoding number {k}"),
            group: format!("group {k}"),
            kind,
            x: 10.0 + 37.0 * k as f64,
            y: 0.001 * (1.0 + k as f64).powi(2),
        };
        let panel = |bits: usize| Panel {
            title: format!("{bits}-bit codes (they compete)"),
            points: (0..8)
                .flat_map(|k| {
                    let k = bits + k;
                    [
                        point(k, Kind::Shipped),
                        point(k, Kind::Rounding),
                        point(k, Kind::Peer),
                    ]
                })
                .collect(),
        };
        let front = Chart::Scatter(Scatter {
            title: "Max error against cost: view distance from a reversed-Z f32 depth, \
                    infinite far, and then some more words"
                .into(),
            x_label: "RDNA2 (navi21): ACO inverse throughput (cycles/wave64) per evaluation, \
                      net; static estimate of Mesa 25.0.7-2~bpo12+1; log"
                .into(),
            y_label: "max error (degrees, log scale)".into(),
            panels: vec![panel(16), panel(24), panel(32)],
            x_ticks: None,
        });
        let hist = Chart::Histogram(Histogram {
            title: "Normal encodings: round-trip error, every encoding (65536 directions)".into(),
            x_label: "angular error (degrees, log scale; red: the largest)".into(),
            series: (0..19)
                .map(|k| HistSeries {
                    label: format!("hemioct24 fast {k} (24 bits, z ≥ 0)"),
                    bins: (0..60)
                        .map(|b| {
                            let lo = 10f64.powf(-5.0 + b as f64 / 10.0);
                            (lo, lo * 10f64.powf(0.1), (b * (60 - b)) as u64)
                        })
                        .collect(),
                    max: 10f64.powf(-3.0 + k as f64 / 6.0),
                })
                .collect(),
        });
        let dir = std::env::temp_dir().join(format!("errplot-layout-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for (chart, stem) in [(front, "front"), (hist, "hist")] {
            assert_eq!(chart_problems(&chart), Vec::<String>::new(), "{stem}");
            let svg = plot::save(&chart, &dir, stem).unwrap();
            let text = std::fs::read_to_string(svg).unwrap();
            assert_eq!(svg_problems(&text), Vec::<String>::new(), "{stem}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A label centred near the left edge runs off it; the same label in the middle does not;
    /// a rotated axis label is measured along its own direction.
    #[test]
    fn text_boxes_are_measured_against_the_view_box() {
        plot::init().unwrap();
        let at = |x: u32, extra: &str| {
            svg(&format!(
                "<text x=\"{x}\" y=\"50\" dy=\"0.5ex\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"12\"{extra}>"
            ))
        };
        assert_eq!(svg_problems(&at(100, "")), Vec::<String>::new());
        let off = svg_problems(&at(20, ""));
        assert_eq!(off.len(), 1, "{off:?}");
        assert!(off[0].contains("hello world"), "{off:?}");
        // Rotated a quarter turn about its anchor, 'hello world' (about 80 px at 12 px) runs
        // 40 px up and down from y = 50: inside the 100 px height at x = 20.
        assert_eq!(
            svg_problems(&at(20, " transform=\"rotate(270, 20, 50)\"")),
            Vec::<String>::new()
        );
        let tall = svg(
            "<text x=\"20\" y=\"50\" dy=\"0.5ex\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"24\" transform=\"rotate(270, 20, 50)\">",
        );
        assert_eq!(svg_problems(&tall).len(), 1);
    }
}
