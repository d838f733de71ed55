//! What every section of the report shares: options, the adapter (if any), the Markdown being
//! written, the CSV files, the charts and the registry of encoding variants.

use crate::plot::{self, Chart};
use crate::variant::Variant;
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};
use prepass::harness::Gpu;
use std::path::PathBuf;
use std::sync::Arc;

/// How much a run measures: the same three names in `--help`, the report's "- Mode:" line and
/// every section's choice of sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tier {
    /// `--quick`: CI's smoke run and the notebooks' input: fewer cases and repeats, one codec
    /// per kind of encoder under emulation; exhaustive sweeps over a code space stay exhaustive.
    Quick,
    /// No flag: every section, every codec and every cost target, with the long sweeps sampled
    /// (each section says what it keeps) and no timing on a software adapter, for a run of a
    /// few minutes on two cores.
    Default,
    /// `--full`: every sweep at full size, every codec emulated under every policy, every
    /// variant timed on the adapter (a software one too): the report's published figures.
    Full,
}

impl Tier {
    /// The tier's name as the report and `--help` write it.
    pub fn label(self) -> &'static str {
        match self {
            Tier::Quick => "quick (`--quick`)",
            Tier::Default => "default (no flag)",
            Tier::Full => "full (`--full`)",
        }
    }
}

/// Command-line options.
#[derive(Clone)]
pub struct Options {
    /// Output folder.
    pub out: PathBuf,
    /// How much the run measures.
    pub tier: Tier,
    /// Also decode all 2^32 codes of the 32-bit normal encodings (about 15 minutes on lavapipe).
    pub exhaustive32: bool,
}

/// The report being built, or one section's part of it ([`Ctx::fork`]).
pub struct Ctx {
    /// Options.
    pub opts: Options,
    /// The adapter, or `None` with the reason; shared by the sections that run side by side.
    pub gpu: Arc<Result<Gpu, String>>,
    /// The progress bars of every section running at the time, drawn together.
    bars: MultiProgress,
    md: String,
    /// Every encoding variant registered by the sections, for the cost table and Pareto plots.
    pub variants: Vec<Variant>,
    /// Files written, for the summary at the end.
    pub written: Vec<PathBuf>,
}

impl Options {
    /// `--quick`.
    pub fn quick(&self) -> bool {
        self.tier == Tier::Quick
    }

    /// `--full`.
    pub fn full(&self) -> bool {
        self.tier == Tier::Full
    }

    /// `quick`, `default` or `full` by the tier.
    pub fn pick<T>(&self, quick: T, default: T, full: T) -> T {
        match self.tier {
            Tier::Quick => quick,
            Tier::Default => default,
            Tier::Full => full,
        }
    }
}

/// The text put in a table cell that needs an adapter when there is none.
pub const NEEDS_ADAPTER: &str = "needs adapter";

impl Ctx {
    /// A context writing into `opts.out`.
    pub fn new(opts: Options, gpu: Result<Gpu, String>) -> Self {
        Ctx {
            opts,
            gpu: Arc::new(gpu),
            bars: MultiProgress::new(),
            md: String::new(),
            variants: Vec::new(),
            written: Vec::new(),
        }
    }

    /// An empty part for one section to write into, on any thread: the same options, adapter
    /// and progress display, its own Markdown, variants and files ([`Ctx::absorb`] appends them).
    pub fn fork(&self) -> Self {
        Ctx {
            opts: self.opts.clone(),
            gpu: Arc::clone(&self.gpu),
            bars: self.bars.clone(),
            md: String::new(),
            variants: Vec::new(),
            written: Vec::new(),
        }
    }

    /// Append a part made by [`Ctx::fork`]: its Markdown after this one's, its variants and files
    /// after these.
    pub fn absorb(&mut self, part: Ctx) {
        self.md.push_str(&part.md);
        self.variants.extend(part.variants);
        self.written.extend(part.written);
    }

    /// Print a line on stderr without tearing the progress bars being drawn.
    pub fn say(&self, line: &str) {
        self.bars.suspend(|| eprintln!("{line}"));
    }

    /// The adapter, if there is one.
    pub fn gpu(&self) -> Option<&Gpu> {
        self.gpu.as_ref().as_ref().ok()
    }

    /// Append one line of Markdown.
    pub fn line(&mut self, s: impl AsRef<str>) {
        self.md.push_str(s.as_ref());
        self.md.push('\n');
    }

    /// The Markdown so far.
    pub fn markdown(&self) -> &str {
        &self.md
    }

    /// Write `name` (a CSV file) into the output folder.
    pub fn csv(&mut self, name: &str, text: &str) -> Result<(), String> {
        let path = self.opts.out.join(name);
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        self.written.push(path);
        Ok(())
    }

    /// Draw `chart` as `stem.svg` + `stem.png` and embed the PNG in the report under `alt`.
    pub fn chart(&mut self, chart: &Chart, stem: &str, alt: &str) -> Result<(), String> {
        let svg = plot::save(chart, &self.opts.out, stem)?;
        // A figure that clips its text, draws two series alike or shows nothing fails the run.
        let text = std::fs::read_to_string(&svg).map_err(|e| format!("{}: {e}", svg.display()))?;
        let problems: Vec<String> = crate::layout::chart_problems(chart)
            .into_iter()
            .chain(crate::layout::svg_problems(&text))
            .collect();
        if !problems.is_empty() {
            return Err(format!(
                "figure {stem} fails its layout check:\n  {}",
                problems.join("\n  ")
            ));
        }
        self.written.push(svg);
        self.written.push(self.opts.out.join(format!("{stem}.png")));
        self.line(format!("![{alt}]({stem}.png) ([SVG]({stem}.svg))"));
        self.line("");
        Ok(())
    }

    /// A progress bar for `len` steps (drawn only when stderr is a terminal), beside those of
    /// the other sections running at the time.
    pub fn progress(&self, len: u64, what: &str) -> ProgressBar {
        let bar = self.bars.add(ProgressBar::new(len));
        if let Ok(style) =
            ProgressStyle::with_template("{prefix:>22} [{bar:30}] {pos}/{len} {msg} ({elapsed})")
        {
            bar.set_style(style.progress_chars("=> "));
        }
        bar.set_prefix(what.to_string());
        bar
    }
}

/// Format a float for a table: 4 significant digits, scientific outside [1e-3, 1e5).
pub fn num(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() {
        format!("{x}")
    } else if (1e-3..1e5).contains(&x.abs()) {
        let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.3e}")
    }
}
