//! Property-based precision checks of *your* WGSL on a real adapter (features `harness` and
//! `proptest`).
//!
//! [`PrecisionCheck`] takes WGSL source and a function name, a proptest strategy for the
//! arguments, a Rust reference closure, an error metric and a bound. It
//!
//! 1. draws `cases` inputs and evaluates them **in one dispatch** (a batch: the per-dispatch cost
//!    of a GPU round trip is paid once, not per case);
//! 2. measures every result against the reference with the metric, and if any error exceeds the
//!    bound (or is NaN), picks the **worst** failing input;
//! 3. **shrinks** that input with proptest's value tree — every candidate is re-run on the
//!    adapter, never on a CPU copy — and reports the worst input, the shrunk input and their
//!    errors.
//!
//! Shrinking is a chain of decisions (candidate still fails → simplify further, passes → step
//! back), so a naive loop needs one GPU round trip per candidate. Here each round trip evaluates
//! the whole decision tree of the next `speculation_depth` steps at once (`2^depth − 1`
//! candidates, a trivial batch for the adapter), then follows the real outcomes through it: the
//! number of dispatches drops by about `speculation_depth`. proptest value trees cannot be
//! cloned, so each speculative candidate is rebuilt by replaying its decision path on a tree
//! regenerated from the case's seed (value trees are deterministic given their random source);
//! that costs CPU time proportional to the path length, far less than a GPU round trip.
//!
//! On the emulated worst conforming adapter ([`crate::conforming`]): [`PrecisionCheck::emulated`]
//! runs the same check under one policy, and [`PrecisionCheck::searched`] with
//! [`PrecisionCheck::run_searched`] searches each case's worst combination of ends, which on
//! `x / (y·z)` finds far more than the fixed policies do (`tests/precision_api.rs` asserts it
//! and prints both).
//!
//! ```no_run
//! use prepass::harness::Gpu;
//! use prepass::precision::check::PrecisionCheck;
//! use prepass::precision::metrics::ulp_error;
//! use prepass::precision::strategies::depth24_code;
//!
//! let gpu = Gpu::new()?;
//! let wgsl = "fn to_unit(d: u32) -> f32 { return f32(d) / 16777215.0; }";
//! let passed = PrecisionCheck::new(&gpu, wgsl, "to_unit")?
//!     .run(
//!         &depth24_code(),
//!         |d: &u32| f64::from(*d) / 16777215.0,          // exact reference
//!         |got: &f32, want: &f64| ulp_error(*got, *want), // metric: ULPs of the exact value
//!         2.5 + 0.5, // bound: WGSL's `/` allowance, plus rounding of f32(d) (exact here: d < 2^24)
//!     )
//!     .map_err(|e| e.to_string())?;
//! println!("max {} ULP over {} cases", passed.stats.max, passed.cases);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::metrics::ErrorStats;
pub use super::value::{WgslArgs, WgslValue};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output, ValueType};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::fmt::{self, Debug};

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

/// A WGSL function prepared for property-based precision checks on an adapter.
pub struct PrecisionCheck<'g> {
    /// Under emulation its one tail word is 1 where the spec leaves the result undefined.
    kernel: Kernel<'g>,
    function: String,
    config: CheckConfig,
    /// Under [`PrecisionCheck::searched`]: the kernel the search climbs with, and the direction
    /// table every plain evaluation (shrinking) gives its elements.
    search: Option<Searching<'g>>,
}

struct Searching<'g> {
    kernel: crate::conforming::EmulatedKernel<'g>,
    table: std::sync::Mutex<crate::conforming::search::DirectionTable>,
}

/// What [`PrecisionCheck::run_searched`] did, in [`Passed::search`].
#[derive(Clone, Debug, PartialEq)]
pub struct SearchSummary {
    /// Inputs climbed: the first batch's worst at the start tables.
    pub inputs: usize,
    /// Of them, searched exhaustively (every assignment of the table slots they read).
    pub exhaustive: usize,
    /// Direction tables evaluated over the whole batch.
    pub evaluated: usize,
    /// The largest error at the fixed policies' tables (all upper, all lower).
    pub greedy_max: f64,
    /// The largest error found.
    pub found_max: f64,
    /// The table that gave it.
    pub table: crate::conforming::search::DirectionTable,
}

/// 64-bit mixer (splitmix64's finaliser): independent-looking seeds from consecutive indices.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A runner whose random source is fixed by `(seed, case)`, so the case's value tree can be
/// regenerated identically at any time.
fn runner(seed: u64, case: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    let mut s = mix(seed ^ mix(case));
    for chunk in bytes.chunks_mut(8) {
        s = mix(s);
        chunk.copy_from_slice(&s.to_le_bytes());
    }
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &bytes),
    )
}

/// Run `kernel` once over `inputs`, each parameter's bits in a column of its own.
/// The inputs' argument columns (`params` of them), as words.
fn columns_of<I: WgslArgs>(inputs: &[I], params: usize) -> Vec<Vec<u32>> {
    let mut columns = vec![Vec::with_capacity(inputs.len() * 4); params];
    for x in inputs {
        x.push_columns(&mut columns);
    }
    columns
}

/// Run `inputs` (then the `extra` arguments) through `kernel`: results and tail words.
fn run_batch_with_tail<I: WgslArgs>(
    kernel: &Kernel<'_>,
    inputs: &[I],
    extra: &[Arg<'_>],
) -> Result<(Output, Vec<u32>), HarnessError> {
    let params = kernel.signature().params.len() - extra.len();
    let columns = columns_of(inputs, params);
    let mut args: Vec<Arg<'_>> = columns
        .iter()
        .map(|c| Arg::Column(bytemuck::cast_slice(c)))
        .collect();
    args.extend_from_slice(extra);
    kernel.run_with_tail(&args, inputs.len() as u64)
}

/// An error fails unless it is within the bound; NaN (unmeasurable) fails.
fn fails(error: f64, bound: f64) -> bool {
    error.is_nan() || error > bound
}

impl<'g> PrecisionCheck<'g> {
    /// Prepare `function` from `source` (valid WGSL on its own) on `gpu`, with the default
    /// [`CheckConfig`].
    pub fn new(gpu: &'g Gpu, source: &str, function: &str) -> Result<Self, HarnessError> {
        Ok(Self {
            kernel: gpu.kernel(source, function)?,
            function: function.to_string(),
            config: CheckConfig::default(),
            search: None,
        })
    }

    /// Like [`PrecisionCheck::new`], but on the worst conforming adapter emulated on `gpu`
    /// ([`crate::conforming`]): every operation the WGSL spec leaves free is evaluated as
    /// `emulation` says. Inputs for which an operation leaves the spec's domain are reported in
    /// [`Passed::undefined`] and never fail the check.
    ///
    /// ```no_run
    /// use prepass::conforming::{Emulation, Policy};
    /// use prepass::harness::Gpu;
    /// use prepass::precision::check::PrecisionCheck;
    /// use prepass::precision::metrics::ulp_error;
    /// use prepass::precision::strategies::depth24_code;
    ///
    /// let gpu = Gpu::new()?;
    /// let wgsl = "fn to_unit(d: u32) -> f32 { return f32(d) / 16777215.0; }";
    /// for policy in Policy::WORST {
    ///     let passed = PrecisionCheck::emulated(&gpu, wgsl, "to_unit", &Emulation::new(policy))?
    ///         .run(
    ///             &depth24_code(),
    ///             |d: &u32| f64::from(*d) / 16777215.0,
    ///             |got: &f32, want: &f64| ulp_error(*got, *want),
    ///             2.5, // WGSL's `/` allowance; f32(d) is exact for d < 2^24
    ///         )
    ///         .map_err(|e| e.to_string())?;
    ///     println!("{policy}: max {} ULP", passed.stats.max);
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn emulated(
        gpu: &'g Gpu,
        source: &str,
        function: &str,
        emulation: &crate::conforming::Emulation,
    ) -> Result<Self, HarnessError> {
        let e = crate::conforming::emulate(source, emulation)
            .map_err(|e| HarnessError::Shader(e.to_string()))?;
        let name = e.function_name(function).ok_or_else(|| {
            HarnessError::Shader(format!("the module has no function `{function}`"))
        })?;
        // The flag comes from the same pipeline as the values (one compilation, not two).
        let flag = [crate::conforming::UNDEFINED_FLAG.to_string()];
        Ok(Self {
            kernel: gpu.kernel_with_tail(&e.source, name, &flag)?,
            function: function.to_string(),
            config: CheckConfig::default(),
            search: None,
        })
    }

    /// Prepare `function` for [`PrecisionCheck::run_searched`]: emulated as `emulation` says
    /// (its freedoms and host accuracy; the policy is [`Policy::Searched`]), each case's worst
    /// combination of ends searched ([`crate::conforming::search::climb`]) rather than the
    /// greedy policies' (the search behind the README's "searched" linear-depth column).
    ///
    /// ```no_run
    /// use prepass::conforming::{Emulation, Policy};
    /// use prepass::conforming::search::SearchConfig;
    /// use prepass::harness::Gpu;
    /// use prepass::precision::check::PrecisionCheck;
    /// use prepass::precision::metrics::ulp_error;
    /// use prepass::precision::proptest::prelude::*;
    ///
    /// let gpu = Gpu::new()?;
    /// let wgsl = "fn ratio(x: f32, y: f32, z: f32) -> f32 { return x / (y * z); }";
    /// let unit = || 1.0f32..2.0;
    /// let passed = PrecisionCheck::searched(&gpu, wgsl, "ratio", &Emulation::new(Policy::Searched))?
    ///     .run_searched(
    ///         &(unit(), unit(), unit()),
    ///         |&(x, y, z): &(f32, f32, f32)| f64::from(x) / (f64::from(y) * f64::from(z)),
    ///         |got: &f32, want: &f64| ulp_error(*got, *want),
    ///         4.51, // `/` 2.5 ULP of a quotient whose divisor is off 1 ULP (≤ 2 ULP of it)
    ///         &SearchConfig::default(),
    ///         32,
    ///     )
    ///     .map_err(|e| e.to_string())?;
    /// let s = passed.search.expect("a searched run reports its search");
    /// println!("greedy {} ULP, searched {} ULP", s.greedy_max, s.found_max);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// [`Policy::Searched`]: crate::conforming::Policy::Searched
    pub fn searched(
        gpu: &'g Gpu,
        source: &str,
        function: &str,
        emulation: &crate::conforming::Emulation,
    ) -> Result<Self, HarnessError> {
        use crate::conforming::{EmulatedKernel, Emulation, Policy, UNDEFINED_FLAG};
        let emulation = Emulation {
            policy: Policy::Searched,
            ..*emulation
        };
        let kernel = EmulatedKernel::new(gpu, source, function, &emulation)?;
        let (wrapper, _) = kernel
            .emulated
            .table_functions(function)
            .ok_or_else(|| HarnessError::Shader(format!("`{function}` has no table wrapper")))?;
        // The pipeline EmulatedKernel runs a single table with (the device caches it).
        let plain = gpu.kernel_with_tail(
            &kernel.emulated.source,
            wrapper,
            &[UNDEFINED_FLAG.to_string()],
        )?;
        Ok(Self {
            kernel: plain,
            function: function.to_string(),
            config: CheckConfig::default(),
            search: Some(Searching {
                kernel,
                table: std::sync::Mutex::new(crate::conforming::search::DirectionTable::UPPER),
            }),
        })
    }

    /// The arguments after the function's own: the current direction table under a search.
    fn table_args(&self) -> Vec<Arg<'static>> {
        match &self.search {
            Some(s) => s
                .table
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .args()
                .to_vec(),
            None => Vec::new(),
        }
    }

    /// Use `config` instead of the defaults.
    pub fn with_config(mut self, config: CheckConfig) -> Self {
        self.config = config;
        self
    }

    /// Set how many cases the first batch draws.
    pub fn cases(mut self, cases: u32) -> Self {
        self.config.cases = cases;
        self
    }

    /// Set the seed of the draw.
    pub fn seed(mut self, seed: u64) -> Self {
        self.config.seed = seed;
        self
    }

    /// The configuration in use.
    pub fn config(&self) -> &CheckConfig {
        &self.config
    }

    /// Run the function on the adapter for every input, in one batch.
    ///
    /// Returns the results in input order; fails with [`CheckError::Setup`] when `I` or `O` do
    /// not match the function's signature.
    pub fn evaluate<I: WgslArgs, O: WgslValue, R>(
        &self,
        inputs: &[I],
    ) -> Result<Vec<O>, CheckError<I, O, R>> {
        let sig = self.kernel.signature();
        let mut want: Vec<ValueType> = sig.params.iter().map(|p| p.ty).collect();
        if self.search.is_some() {
            want.truncate(want.len() - 3); // the direction table's halves and the mode
        }
        if I::param_types() != want || O::TYPE != sig.result {
            let show = |ts: &[ValueType]| {
                ts.iter()
                    .map(|t| t.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            return Err(CheckError::Setup(format!(
                "`{}` is fn({}) -> {}, but the strategy gives ({}) and the metric reads {}",
                sig.function,
                show(&want),
                sig.result,
                show(&I::param_types()),
                O::TYPE
            )));
        }
        let (out, _) = run_batch_with_tail(&self.kernel, inputs, &self.table_args())?;
        Ok(out
            .words()
            .chunks(O::TYPE.words())
            .map(O::from_words)
            .collect())
    }

    /// Under emulation, whether each input's result is left undefined by the spec (all `false`
    /// otherwise).
    fn undefined_flags<I: WgslArgs, O: WgslValue, R>(
        &self,
        inputs: &[I],
    ) -> Result<Vec<bool>, CheckError<I, O, R>> {
        if self.kernel.tail_words() == 0 {
            return Ok(Vec::new());
        }
        let (_, flags) = run_batch_with_tail(&self.kernel, inputs, &self.table_args())?;
        Ok(flags.iter().map(|&f| f != 0).collect())
    }

    /// Draw `cases` inputs; case k's tree comes from `runner(seed, k')`, k' counting rejections
    /// too, so it can be regenerated later for shrinking. The inputs and their draw numbers.
    #[allow(clippy::type_complexity)]
    fn draw<S, O, R>(
        &self,
        strategy: &S,
    ) -> Result<(Vec<S::Value>, Vec<u64>), CheckError<S::Value, O, R>>
    where
        S: Strategy,
    {
        let cfg = self.config;
        let mut seeds = Vec::with_capacity(cfg.cases as usize);
        let mut inputs = Vec::with_capacity(cfg.cases as usize);
        let mut draw = 0u64;
        let mut rejects = 0u32;
        while inputs.len() < cfg.cases as usize {
            match strategy.new_tree(&mut runner(cfg.seed, draw)) {
                Ok(tree) => {
                    seeds.push(draw);
                    inputs.push(tree.current());
                }
                Err(why) => {
                    rejects += 1;
                    if rejects > cfg.max_rejects {
                        return Err(CheckError::Setup(format!(
                            "the strategy rejected {rejects} draws (last: {why})"
                        )));
                    }
                }
            }
            draw += 1;
        }
        Ok((inputs, seeds))
    }

    /// Check that `error(wgsl_result, reference(input)) ≤ bound` for `cases` inputs drawn from
    /// `strategy`, evaluated on the adapter in one batch; on failure, shrink the worst input on
    /// the adapter and report both (see the module docs).
    ///
    /// `O`, the WGSL result type, is read from the metric's first parameter; a NaN error is a
    /// failure.
    pub fn run<S, O, R>(
        &self,
        strategy: &S,
        reference: impl Fn(&S::Value) -> R,
        error: impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> Result<Passed<S::Value>, CheckError<S::Value, O, R>>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let (inputs, seeds) = self.draw::<S, O, R>(strategy)?;
        let outputs = self.evaluate::<S::Value, O, R>(&inputs)?;
        let undefined = self.undefined_flags::<S::Value, O, R>(&inputs)?;
        let (mut undefined_count, mut undefined_example) = (0u64, None);
        let mut stats = ErrorStats::default();
        let mut failing = 0u64;
        let mut worst: Option<(usize, f64)> = None;
        let rank = |e: f64| if e.is_nan() { f64::INFINITY } else { e };
        let mut worst_any: Option<(usize, f64)> = None;
        let mut refs = Vec::with_capacity(inputs.len());
        for (i, (x, got)) in inputs.iter().zip(&outputs).enumerate() {
            if undefined.get(i).copied().unwrap_or(false) {
                undefined_count += 1;
                undefined_example.get_or_insert_with(|| x.clone());
                refs.push(reference(x));
                continue;
            }
            let r = reference(x);
            let e = error(got, &r);
            refs.push(r);
            stats.add(i as u64, e);
            if worst_any.is_none_or(|(_, w)| rank(e) > rank(w)) {
                worst_any = Some((i, e));
            }
            if fails(e, bound) {
                failing += 1;
                if worst.is_none_or(|(_, w)| rank(e) > rank(w)) {
                    worst = Some((i, e));
                }
            }
        }
        let Some((w, w_err)) = worst else {
            return Ok(Passed {
                cases: inputs.len() as u64,
                stats,
                worst: worst_any.map(|(i, _)| inputs[i].clone()),
                undefined: undefined_count,
                undefined_example,
                search: None,
            });
        };
        let worst = Evaluated {
            input: inputs[w].clone(),
            got: outputs[w].clone(),
            reference: refs.swap_remove(w),
            error: w_err,
        };
        let shape = (inputs.len() as u64, failing, stats);
        Err(self.failure(strategy, seeds[w], worst, shape, &reference, &error, bound))
    }

    /// The failure at `worst` (drawn as `case`), shrunk; `shape` is the batch's case count,
    /// failing count and statistics.
    #[allow(clippy::too_many_arguments)]
    fn failure<S, O, R>(
        &self,
        strategy: &S,
        case: u64,
        worst: Evaluated<S::Value, O, R>,
        shape: (u64, u64, ErrorStats),
        reference: &impl Fn(&S::Value) -> R,
        error: &impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> CheckError<S::Value, O, R>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let shrink = match self.shrink(strategy, case, reference, error, bound) {
            Ok(s) => s,
            Err(e) => return e,
        };
        let shrank = shrink.best.is_some();
        // Nothing simpler failed: the worst input is its own shrink.
        let shrunk = shrink.best.unwrap_or_else(|| Evaluated {
            input: worst.input.clone(),
            got: worst.got.clone(),
            reference: reference(&worst.input),
            error: worst.error,
        });
        let (cases, failing, stats) = shape;
        CheckError::Failed(Box::new(Failure {
            function: self.function.clone(),
            bound,
            cases,
            failing,
            stats,
            worst,
            shrunk,
            shrank,
            shrink_steps: shrink.steps,
            shrink_truncated: shrink.truncated,
            shrink_dispatches: shrink.dispatches,
            shrink_evaluations: shrink.evaluations,
            seed: self.config.seed,
        }))
    }

    /// [`PrecisionCheck::run`] on the emulated worst adapter, searched (a check built by
    /// [`PrecisionCheck::searched`]): every case is evaluated at the tables of the fixed
    /// policies (all upper, all lower: what [`PrecisionCheck::emulated`] gives under
    /// `Policy::Upper` and `Policy::Lower`) and at the other starts of `search` (seeded
    /// tables); the `searched_inputs` cases that erred most are climbed from every start
    /// ([`crate::conforming::search::climb`]: every assignment of the table slots a case reads
    /// where they are at most `search.exhaustive_slots`, steepest ascent elsewhere). Each case counts at the worst table found for it. A failure is shrunk
    /// at the table of the worst case (the table, not the input, is what the search chose).
    /// A NaN error ranks as +∞; a case undefined at every start table counts as undefined.
    pub fn run_searched<S, O, R>(
        &self,
        strategy: &S,
        reference: impl Fn(&S::Value) -> R,
        error: impl Fn(&O, &R) -> f64,
        bound: f64,
        search: &crate::conforming::search::SearchConfig,
        searched_inputs: usize,
    ) -> Result<Passed<S::Value>, CheckError<S::Value, O, R>>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        use crate::conforming::search::{DirectionTable, SearchConfig, climb};
        let Some(s) = &self.search else {
            return Err(CheckError::Setup(
                "run_searched needs a check built by PrecisionCheck::searched".into(),
            ));
        };
        let (inputs, seeds) = self.draw::<S, O, R>(strategy)?;
        // The types, checked as every run checks them (and one evaluation at the upper table).
        self.evaluate::<S::Value, O, R>(&inputs[..inputs.len().min(1)])?;
        let n = inputs.len();
        let refs: Vec<R> = inputs.iter().map(&reference).collect();
        let params = S::Value::param_types().len();
        let w = O::TYPE.words();
        let measure = |i: usize, out: &Output, e: usize| {
            let v = error(&O::from_words(&out.words()[e * w..(e + 1) * w]), &refs[i]);
            if v.is_nan() { f64::INFINITY } else { v }
        };
        let cols = columns_of(&inputs, params);
        let args: Vec<Arg<'_>> = cols
            .iter()
            .map(|c| Arg::Column(bytemuck::cast_slice(c)))
            .collect();
        // Every case at the fixed policies' tables (what Upper and Lower give), then at every
        // start of the search (the seeded tables explore mixtures): one dispatch each.
        let at = |starts: Vec<(&'static str, DirectionTable)>| {
            let config = SearchConfig {
                exhaustive_slots: 0,
                rounds: 0,
                starts,
            };
            climb(&s.kernel, &args, n, &measure, &config)
        };
        let fixed = vec![
            ("upper", DirectionTable::UPPER),
            ("lower", DirectionTable::LOWER),
        ];
        let greedy_max = at(fixed)?
            .iter()
            .map(|f| f.error)
            .fold(f64::NEG_INFINITY, f64::max);
        let mut found = at(search.starts.clone())?;
        // The worst cases at the starts, climbed.
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| found[b].error.total_cmp(&found[a].error));
        order.truncate(searched_inputs);
        let picked: Vec<S::Value> = order.iter().map(|&i| inputs[i].clone()).collect();
        let sub = columns_of(&picked, params);
        let sub_args: Vec<Arg<'_>> = sub
            .iter()
            .map(|c| Arg::Column(bytemuck::cast_slice(c)))
            .collect();
        let sub_measure = |k: usize, out: &Output, e: usize| measure(order[k], out, e);
        let climbed = climb(&s.kernel, &sub_args, order.len(), &sub_measure, search)?;
        let exhaustive = climbed
            .iter()
            .filter(|f| f.slots <= search.exhaustive_slots)
            .count();
        let mut evaluated: usize = found.iter().map(|f| f.evaluated).sum();
        for (&i, f) in order.iter().zip(climbed) {
            evaluated += f.evaluated;
            if f.error > found[i].error {
                found[i] = f;
            }
        }
        let (mut stats, mut failing, mut worst) = (ErrorStats::default(), 0u64, None);
        let (mut undefined, mut undefined_example) = (0u64, None);
        for (i, f) in found.iter().enumerate() {
            if f.error == f64::NEG_INFINITY {
                undefined += 1;
                undefined_example.get_or_insert_with(|| inputs[i].clone());
                continue;
            }
            stats.add(i as u64, f.error);
            failing += u64::from(fails(f.error, bound));
            if worst.is_none_or(|(_, e)| f.error > e) {
                worst = Some((i, f.error));
            }
        }
        let summary = SearchSummary {
            inputs: order.len(),
            exhaustive,
            evaluated,
            greedy_max,
            found_max: worst.map_or(f64::NEG_INFINITY, |(_, e)| e),
            table: worst.map_or(
                crate::conforming::search::DirectionTable::UPPER,
                |(i, _)| found[i].table,
            ),
        };
        match worst {
            Some((i, e)) if fails(e, bound) => {
                // Shrink (and report) at the worst case's table.
                *s.table.lock().unwrap_or_else(|p| p.into_inner()) = summary.table;
                let got = self.evaluate::<S::Value, O, R>(std::slice::from_ref(&inputs[i]))?;
                let got = got.into_iter().next().expect("one input, one result");
                let r = reference(&inputs[i]);
                let worst = Evaluated {
                    error: error(&got, &r),
                    input: inputs[i].clone(),
                    got,
                    reference: r,
                };
                let shape = (n as u64, failing, stats);
                let failure =
                    self.failure(strategy, seeds[i], worst, shape, &reference, &error, bound);
                *s.table.lock().unwrap_or_else(|p| p.into_inner()) =
                    crate::conforming::search::DirectionTable::UPPER;
                Err(failure)
            }
            _ => Ok(Passed {
                cases: n as u64,
                stats,
                worst: worst.map(|(i, _)| inputs[i].clone()),
                undefined,
                undefined_example,
                search: Some(summary),
            }),
        }
    }

    /// proptest's shrinking walk from the failing input drawn as `case` (fail → simplify, pass → complicate, stop when the tree has no
    /// move left), `speculation_depth` decisions per dispatch.
    fn shrink<S, O, R>(
        &self,
        strategy: &S,
        case: u64,
        reference: &impl Fn(&S::Value) -> R,
        error: &impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> ShrinkResult<S::Value, O, R>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let cfg = self.config;
        let depth = cfg.speculation_depth.clamp(1, 10) as usize;
        // The tree after the first simplify and then `path` (true = simplify, false =
        // complicate); None when a move along the way was refused (that branch has ended).
        let tree_at = |path: &[bool]| -> Option<S::Tree> {
            let mut tree = strategy.new_tree(&mut runner(cfg.seed, case)).ok()?;
            let moved = std::iter::once(&true).chain(path).all(|&s| {
                if s {
                    tree.simplify()
                } else {
                    tree.complicate()
                }
            });
            moved.then_some(tree)
        };
        let mut out = Shrunk {
            best: None,
            steps: 0,
            truncated: false,
            dispatches: 0,
            evaluations: 0,
        };
        let mut frontier: Vec<bool> = Vec::new();
        loop {
            // Every node of the next `depth` decision levels below the frontier, breadth first:
            // node j's children are 2j+1 (after simplify: it failed) and 2j+2 (after complicate).
            let mut nodes: Vec<Option<S::Value>> = vec![None; (1 << depth) - 1];
            for j in 0..nodes.len() {
                // A move below a refused move does not exist either.
                if j == 0 || nodes[(j - 1) / 2].is_some() {
                    let mut path = frontier.clone();
                    path.extend_from_slice(&suffix_of(j));
                    nodes[j] = tree_at(&path).map(|t| t.current());
                }
            }
            if nodes[0].is_none() {
                return Ok(out);
            }
            let live: Vec<usize> = (0..nodes.len()).filter(|&j| nodes[j].is_some()).collect();
            let batch: Vec<S::Value> = live.iter().map(|&j| nodes[j].clone().unwrap()).collect();
            let got = self.evaluate::<S::Value, O, R>(&batch)?;
            out.dispatches += 1;
            out.evaluations += batch.len() as u64;
            let mut results: Vec<Option<O>> = vec![None; nodes.len()];
            for (&j, g) in live.iter().zip(got) {
                results[j] = Some(g);
            }
            // Follow the real outcomes down the evaluated levels.
            let mut j = 0usize;
            let mut walked = Vec::new();
            loop {
                let Some(g) = results[j].take() else {
                    return Ok(out); // the tree refused this move: shrinking is over
                };
                if out.steps >= cfg.max_shrink_steps {
                    out.truncated = true;
                    return Ok(out);
                }
                out.steps += 1;
                let input = nodes[j].take().expect("evaluated nodes exist");
                let r = reference(&input);
                let e = error(&g, &r);
                let failed = fails(e, bound);
                if failed {
                    out.best = Some(Evaluated {
                        input,
                        got: g,
                        reference: r,
                        error: e,
                    });
                }
                walked.push(failed);
                j = 2 * j + if failed { 1 } else { 2 };
                if j >= nodes.len() {
                    break;
                }
            }
            frontier.extend_from_slice(&walked);
        }
    }
}

/// The decisions leading from the root of a breadth-first binary tree to node `j`
/// (children of `j` are `2j + 1` = simplify and `2j + 2` = complicate).
fn suffix_of(mut j: usize) -> Vec<bool> {
    let mut path = Vec::new();
    while j > 0 {
        path.push(j % 2 == 1);
        j = (j - 1) / 2;
    }
    path.reverse();
    path
}

type ShrinkResult<I, O, R> = Result<Shrunk<I, O, R>, CheckError<I, O, R>>;

struct Shrunk<I, O, R> {
    /// The last failing candidate (the simplest found), if any candidate failed.
    best: Option<Evaluated<I, O, R>>,
    steps: u32,
    truncated: bool,
    dispatches: u32,
    evaluations: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suffixes_follow_breadth_first_numbering() {
        assert_eq!(suffix_of(0), Vec::<bool>::new());
        assert_eq!(suffix_of(1), vec![true]);
        assert_eq!(suffix_of(2), vec![false]);
        assert_eq!(suffix_of(3), vec![true, true]);
        assert_eq!(suffix_of(6), vec![false, false]);
        assert_eq!(suffix_of(5), vec![false, true]);
    }

    #[test]
    fn regenerated_trees_replay_identically() {
        use proptest::prelude::*;
        let s = (any::<u32>(), -1e6f32..1e6);
        let path = [true, false, true, true, false];
        let walk = || {
            let mut t = s.new_tree(&mut runner(7, 3)).unwrap();
            for &p in &path {
                if p {
                    t.simplify();
                } else {
                    t.complicate();
                }
            }
            t.current()
        };
        assert_eq!(walk(), walk());
    }
}
