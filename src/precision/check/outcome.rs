//! What a check is configured with and what it reports: [`CheckConfig`], [`Passed`],
//! [`Evaluated`], [`Failure`], [`CheckError`].

use super::*;

/// How a check draws, bounds its work and shrinks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheckConfig {
    /// Inputs drawn and evaluated in the first batch.
    pub cases: u32,
    /// Seed of the draw: the same seed, strategy and source give the same cases (so a failure
    /// in CI reproduces locally). Change it to explore other inputs.
    pub seed: u64,
    /// Most shrinking decisions followed before the best input so far is reported.
    pub max_shrink_steps: u32,
    /// Decision levels evaluated per dispatch while shrinking (`2^depth − 1` candidates per
    /// dispatch); 1 is the plain one-candidate-per-dispatch loop.
    pub speculation_depth: u32,
    /// Most strategy rejections (`prop_filter`) tolerated while drawing.
    pub max_rejects: u32,
}

impl Default for CheckConfig {
    fn default() -> Self {
        Self {
            cases: 4096,
            seed: 0x7072_6570_6173_7321,
            max_shrink_steps: 4096,
            speculation_depth: 5,
            max_rejects: 65_536,
        }
    }
}

/// A check that passed: every case within the bound.
#[derive(Clone, Debug)]
pub struct Passed<I> {
    /// Cases evaluated.
    pub cases: u64,
    /// Error statistics over all cases (`argmax` indexes the cases in draw order).
    pub stats: ErrorStats,
    /// The input with the largest error (`None` when no case was drawn).
    pub worst: Option<I>,
    /// Cases whose result the WGSL spec does not define (an operation left its domain: a
    /// divisor outside ±[2^-126, 2^126], `inverseSqrt` of ≤ 0, …), reported instead of
    /// measured; only an emulated check ([`PrecisionCheck::emulated`]) finds them.
    pub undefined: u64,
    /// The first such input.
    pub undefined_example: Option<I>,
    /// Under [`PrecisionCheck::run_searched`]: what the search did (`None` otherwise).
    pub search: Option<SearchSummary>,
}

/// One evaluated input: what the adapter returned, the reference, and the metric's error.
#[derive(Clone, Debug)]
pub struct Evaluated<I, O, R> {
    /// The input.
    pub input: I,
    /// The WGSL function's result on the adapter.
    pub got: O,
    /// The reference closure's value.
    pub reference: R,
    /// The metric's error (NaN when the metric could not measure, which counts as a failure).
    pub error: f64,
}

/// A check that failed, with the worst input found and the input it shrank to.
#[derive(Clone, Debug)]
pub struct Failure<I, O, R> {
    /// The function checked.
    pub function: String,
    /// The bound that was exceeded.
    pub bound: f64,
    /// Cases evaluated in the first batch, and how many of them failed.
    pub cases: u64,
    /// Failing cases in the first batch.
    pub failing: u64,
    /// Error statistics over the first batch.
    pub stats: ErrorStats,
    /// The failing input with the largest error (NaN errors rank highest).
    pub worst: Evaluated<I, O, R>,
    /// The simplest input the worst one shrank to that still fails (the worst input itself
    /// when no simpler candidate failed: see `shrank`).
    pub shrunk: Evaluated<I, O, R>,
    /// Whether shrinking found a simpler failing input than the worst one.
    pub shrank: bool,
    /// Shrinking decisions followed.
    pub shrink_steps: u32,
    /// Whether shrinking stopped at `max_shrink_steps` rather than at a local minimum.
    pub shrink_truncated: bool,
    /// GPU dispatches spent shrinking, and candidates they evaluated.
    pub shrink_dispatches: u32,
    /// Candidates evaluated while shrinking.
    pub shrink_evaluations: u64,
    /// The seed that reproduces this failure.
    pub seed: u64,
}

/// Why a check did not pass.
#[derive(Debug)]
pub enum CheckError<I, O, R> {
    /// An error exceeded the bound: the worst and the shrunk input.
    Failed(Box<Failure<I, O, R>>),
    /// The harness could not run the function (no adapter, invalid WGSL, signature).
    Harness(HarnessError),
    /// The check is set up wrong (types do not match the signature, too many rejections).
    Setup(String),
}

impl<I: Debug, O: Debug, R: Debug> fmt::Display for Failure<I, O, R> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let show = |f: &mut fmt::Formatter<'_>, what: &str, e: &Evaluated<I, O, R>| {
            writeln!(
                f,
                "  {what}: input {:?} → WGSL {:?}, reference {:?}, error {}",
                e.input, e.got, e.reference, e.error
            )
        };
        writeln!(
            f,
            "precision check of `{}` failed: {} of {} cases exceed the bound {} (max error {}, {} NaN)",
            self.function,
            self.failing,
            self.cases,
            self.bound,
            self.stats.max,
            self.stats.nan_count
        )?;
        show(f, "worst ", &self.worst)?;
        if self.shrank {
            show(f, "shrunk", &self.shrunk)?;
        } else {
            writeln!(
                f,
                "  shrunk: no simpler candidate fails; the worst input is the smallest found"
            )?;
        }
        write!(
            f,
            "  shrinking: {} steps{} in {} dispatches ({} candidates on the adapter); seed {:#x}",
            self.shrink_steps,
            if self.shrink_truncated {
                " (stopped at max_shrink_steps)"
            } else {
                ""
            },
            self.shrink_dispatches,
            self.shrink_evaluations,
            self.seed
        )
    }
}

impl<I: Debug, O: Debug, R: Debug> fmt::Display for CheckError<I, O, R> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Failed(fail) => fmt::Display::fmt(fail, f),
            Self::Harness(e) => fmt::Display::fmt(e, f),
            Self::Setup(m) => write!(f, "precision check set up wrong: {m}"),
        }
    }
}

impl<I: Debug, O: Debug, R: Debug> std::error::Error for CheckError<I, O, R> {}

impl<I, O, R> From<HarnessError> for CheckError<I, O, R> {
    fn from(e: HarnessError) -> Self {
        Self::Harness(e)
    }
}
