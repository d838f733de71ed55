//! The README's "which to pick" figure: every shipped normal encoding's max round-trip error
//! against the bits it stores, each point tagged with the uses the README recommends it for
//! (thin G-buffer, quality, an engine's layout), the front of bits against error drawn. The
//! rounding forms appear where a use names one.

use crate::ctx::Ctx;
use crate::fronts::{Kind, Labelled, Panel, Scatter};
use crate::plot::Chart;
use prepass::sweep::normal::Codec;

/// The README's recommendations ("Pick an encoding"): encoding name and use.
const USES: [(&str, &str); 4] = [
    ("oct16", "thin G-buffer"),
    ("oct24 fast", "thin G-buffer"),
    ("oct24", "quality"),
    ("oct32", "quality"),
];

/// The engines of a codec's "stored by" (first word, and a version number after it), or none.
fn engines(stored_by: &str) -> Vec<String> {
    stored_by
        .split(';')
        .filter_map(|part| {
            let part = part.trim();
            let mut words = part.split([' ', ',']);
            let first = words
                .next()
                .filter(|w| w.chars().next().is_some_and(char::is_uppercase))?;
            Some(match words.next() {
                Some(v) if v.chars().all(|c| c.is_ascii_digit()) && !v.is_empty() => {
                    format!("{first} {v}")
                }
                _ => first.to_string(),
            })
        })
        .collect()
}

/// Draw `which_to_pick` from each codec's max round-trip error over `n` directions.
pub fn figure(ctx: &mut Ctx, maxima: &[(&Codec, f64)], n: u32) -> Result<(), String> {
    // A rounding (`_fast`) form is drawn where a use names it: the others sit just above their
    // precise forms, at the same bits, and would crowd the labels.
    let used = |name: &str| USES.iter().any(|(n, _)| *n == name);
    let points = maxima
        .iter()
        .filter(|(codec, _)| !codec.name.ends_with(" fast") || used(codec.name))
        .map(|&(codec, max)| {
            let mut tags: Vec<String> = USES
                .iter()
                .filter(|(name, _)| *name == codec.name)
                .map(|(_, used)| used.to_string())
                .collect();
            // A `_fast` form stores what its precise form stores: the engines go on the latter.
            if !codec.name.ends_with(" fast") {
                tags.extend(engines(codec.stored_by));
            }
            let z = if codec.hemisphere { " (z ≥ 0)" } else { "" };
            Labelled {
                label: if tags.is_empty() {
                    format!("{}{z}", codec.name)
                } else {
                    format!("{}{z}: {}", codec.name, tags.join(", "))
                },
                group: codec.name.trim_end_matches(" fast").to_string(),
                kind: if codec.name.ends_with(" fast") {
                    Kind::Rounding
                } else {
                    Kind::Shipped
                },
                x: f64::from(codec.bits),
                y: max,
            }
        })
        .collect();
    ctx.chart(
        &Chart::Scatter(Scatter {
            title: "Which normal encoding to pick: max error against the bits it stores".into(),
            x_label: "bits stored per normal (log scale)".into(),
            y_label: format!("max round-trip error (degrees, {n} directions)"),
            panels: vec![Panel {
                title: "tags: the README's uses and the engines whose layout it reads; \
                        CPU baking: any (the Rust twins give the WGSL's bits)"
                    .into(),
                points,
            }],
            x_ticks: Some(vec![16.0, 20.0, 24.0, 32.0]),
        }),
        "which_to_pick",
        "which normal encoding to pick",
    )
}
