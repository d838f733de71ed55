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
//!
//! Files: `outcome.rs` (configuration and reports), `run.rs` (drawing, batch evaluation,
//! [`PrecisionCheck::run`]), `search.rs` ([`PrecisionCheck::run_searched`]), `shrink.rs`
//! (replayable trees, speculative shrinking); this file builds the check.

use super::metrics::ErrorStats;
pub use super::value::{WgslArgs, WgslValue};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output, ValueType};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::fmt::{self, Debug};

mod outcome;
mod run;
mod search;
mod shrink;

pub use outcome::{CheckConfig, CheckError, Evaluated, Failure, Passed};
pub use search::SearchSummary;

// One namespace for the parts (each does `use super::*`), as when they were one file.
use run::*;
use search::*;
use shrink::*;

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
}
