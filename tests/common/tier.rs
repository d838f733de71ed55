//! The tiers of proof (README "Commands", CONTRIBUTING.md, DESIGN.md "Tiers of proof").
//!
//! - **default** (`bash .ci/test`): every published claim checked and every bound asserted.
//!   Sweeps over a whole code space that cost seconds stay exhaustive; emulated sweeps, large
//!   direction sets and searches may sample, each stating its rule where it is taken. A block
//!   such a sample feeds is held against the published one by its worst columns: what the
//!   sample measures may not exceed what was published ([`publish_sampled`]).
//! - **full** (`PREPASS_FULL=1 bash .ci/test`): every sweep exhaustive, every emulated input.
//!   The published figures come from it, and it compares every block bit for bit.

// Each test binary uses a part of this.
#![allow(dead_code)]

/// The tier this run checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tier {
    /// `bash .ci/test`.
    Default,
    /// `PREPASS_FULL=1 bash .ci/test`.
    Full,
}

/// The tier asked for: [`Tier::Full`] when `PREPASS_FULL` is set to anything but `0`.
pub fn tier() -> Tier {
    if std::env::var_os("PREPASS_FULL").is_some_and(|v| v != "0") {
        Tier::Full
    } else {
        Tier::Default
    }
}

/// `default` in the default tier, `full` in the full one: the size or stride of a sampled
/// sweep, stated once where it is taken.
pub fn by_tier<T>(default: T, full: T) -> T {
    match tier() {
        Tier::Default => default,
        Tier::Full => full,
    }
}

/// The command that regenerates a block of figures: the full tier, writing.
pub fn regenerate_command(test: &str) -> String {
    format!(
        "`PREPASS_FULL=1 PREPASS_WRITE_DOCS=1 cargo test --release --all-features --test {test}` \
         (or `PREPASS_FULL=1 bash .ci/docs` for every block)"
    )
}

/// The numbers in a table cell, in order (`"0.0390 / 0.0390 · 0.0594"` gives three; `"97 %"` one).
pub fn numbers(cell: &str) -> Vec<f64> {
    cell.split(|c: char| !(c.is_ascii_digit() || "+-.eE".contains(c)))
        .filter_map(|t| t.trim_end_matches('.').parse().ok())
        .collect()
}

/// A Markdown table's header cells and rows (cells trimmed), from the first `|` line on.
fn table(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text
        .lines()
        .filter(|l| l.trim_start().starts_with('|'))
        .map(|l| {
            // An escaped `\|` is text inside a cell, not a border.
            l.trim()
                .replace("\\|", "\u{1}")
                .trim_matches('|')
                .split('|')
                .map(|c| c.trim().replace('\u{1}', "\\|"))
                .collect::<Vec<_>>()
        });
    let header = lines.next().unwrap_or_default();
    let rows = lines
        .filter(|r| !r.iter().all(|c| c.chars().all(|ch| ch == '-' || ch == ':')))
        .collect();
    (header, rows)
}

/// Where a sampled measurement exceeds a published worst: each entry names the row, the column,
/// the measured and the published number. Rows are matched by their first cell, columns by
/// their header; a row or a worst column the published table lacks is an entry too (the block
/// is stale).
pub fn worsts_exceeded(published: &str, measured: &str, worst_columns: &[&str]) -> Vec<String> {
    let (ph, prows) = table(published);
    let (mh, mrows) = table(measured);
    let mut out = Vec::new();
    for col in worst_columns {
        let (Some(pc), Some(mc)) = (
            ph.iter().position(|h| h == col),
            mh.iter().position(|h| h == col),
        ) else {
            out.push(format!(
                "column `{col}` is missing from the published or the measured table"
            ));
            continue;
        };
        for m in &mrows {
            let Some(p) = prows.iter().find(|p| p.first() == m.first()) else {
                out.push(format!("row `{}` is not published", m[0]));
                continue;
            };
            let (pv, mv) = (numbers(&p[pc]), numbers(&m[mc]));
            if pv.len() != mv.len() {
                out.push(format!(
                    "row `{}`, column `{col}`: measured `{}` has another shape than published `{}`",
                    m[0], m[mc], p[pc]
                ));
                continue;
            }
            for (a, b) in mv.iter().zip(&pv) {
                if a > b {
                    out.push(format!(
                        "row `{}`, column `{col}`: measured {a} > published {b} (`{}` against `{}`)",
                        m[0], m[mc], p[pc]
                    ));
                }
            }
        }
    }
    out
}

/// Publish a block of figures that the default tier measures on a sample.
///
/// In the full tier it is [`super::publish_measured`]: compared bit for bit on the publishing
/// adapter, written under `PREPASS_WRITE_DOCS=1`. In the default tier nothing is written, and
/// on the publishing adapter the block's `worst_columns` must not exceed the published ones,
/// row by row (the sample's inputs are a subset of the full tier's, so its worst can only be
/// lower or equal; a higher one is a regression or a stale block). The other columns (means,
/// counts) are the sample's and are not compared. `test` names the test binary, for the
/// regenerating command the failure prints.
pub fn publish_sampled(path: &str, name: &str, body: &str, worst_columns: &[&str], test: &str) {
    if tier() == Tier::Full {
        super::publish_measured(path, name, body);
        return;
    }
    let committed = super::committed_block(path, name).unwrap_or_else(|| {
        panic!(
            "{path} has no block `{name}`: run {}",
            regenerate_command(test)
        )
    });
    if std::env::var_os("PREPASS_WRITE_DOCS").is_some() {
        eprintln!(
            "{path}, block `{name}`: not written by the default tier (the published figures come \
             from the full tier): {}",
            regenerate_command(test)
        );
    }
    if !super::is_publishing_adapter() {
        eprintln!(
            "{path}, block `{name}`: published from another adapter; compared with its bounds \
             only. This adapter's, on the default tier's sample:\n{body}"
        );
        return;
    }
    let exceeded = worsts_exceeded(&committed, body, worst_columns);
    assert!(
        exceeded.is_empty(),
        "{path}, block `{name}`: the default tier's sample measured more than the published \
         worst (published from the full tier, whose inputs include the sample's):\n  {}\n\
         Either the code regressed or the block is stale; regenerate it with {}.\n\
         Measured on the sample:\n{body}",
        exceeded.join("\n  "),
        regenerate_command(test)
    );
}

/// Log2 of the spherical-Fibonacci direction set the normal suites sweep on the adapter: 2^20
/// in the default tier, 2^24 in the full tier.
///
/// The rule: the suites' claims are per input (a derived bound on the round trip, the WGSL
/// equal to its twin bit for bit, the precise encoder's choice optimal among its neighbours),
/// so a sparser quasi-uniform set checks each claim at fewer inputs of the same kind; the
/// adversarial set (folds, poles, the equator, lattice corners and near-ties: where codes and
/// twins part) is kept whole in both tiers. The published worsts come from
/// `tests/conforming.rs`'s own set, not from these sweeps.
pub fn fibonacci_log2() -> u32 {
    by_tier(20, 24)
}

/// The Fibonacci set of [`fibonacci_log2`] and its label (`"fibonacci 2^20"`).
pub fn fibonacci_set() -> (String, Vec<[f32; 3]>) {
    let k = fibonacci_log2();
    (
        format!("fibonacci 2^{k}"),
        prepass::sweep::normal::fibonacci_directions(1 << k),
    )
}

/// The label of [`fibonacci_set`], without building the set.
pub fn fibonacci_set_label() -> String {
    format!("fibonacci 2^{}", fibonacci_log2())
}
