//! The registry's entries: one encoding variant a section measured, with the WGSL and the Rust
//! twin that [`crate::cost`] times.

use prepass::precision::metrics::ErrorStats;
use std::hint::black_box;
use std::time::Instant;

/// How one argument of a timed WGSL function is fed (owned form of
/// [`Arg`](prepass::harness::Arg)).
#[derive(Clone, Debug)]
pub enum TimedArg {
    /// `start + i` as the parameter's bits.
    Index(u32),
    /// The same value everywhere.
    Splat([u32; 4]),
    /// A tile of values (power-of-two count), as raw words.
    Column(Vec<u32>),
}

/// The WGSL side of a variant.
pub struct Wgsl {
    /// Source, valid on its own.
    pub source: String,
    /// Function name in it.
    pub function: String,
    /// Arguments for the timed dispatch.
    pub args: Vec<TimedArg>,
}

/// Times `calls` calls of a Rust twin and returns the elapsed nanoseconds (`Send`: the section
/// that registers it may run on another thread than the cost table that calls it).
pub type TwinTimer = Box<dyn Fn(usize) -> f64 + Send>;

/// A timer for `f` over `inputs` (a power-of-two count, cycled): the loop is monomorphised for
/// `f`, so the call inlines as it would in a user's loop; `black_box` on each input and result
/// keeps the compiler from hoisting or dropping the work.
pub fn twin_timer<I: Copy + Send + 'static, O>(
    inputs: Vec<I>,
    f: impl Fn(I) -> O + Send + 'static,
) -> TwinTimer {
    assert!(inputs.len().is_power_of_two());
    let mask = inputs.len() - 1;
    Box::new(move |calls| {
        let t = Instant::now();
        for k in 0..calls {
            black_box(f(black_box(inputs[k & mask])));
        }
        t.elapsed().as_secs_f64() * 1e9
    })
}

/// One encoding variant: a row of the cost table, a point of its family's Pareto plot.
pub struct Variant {
    /// Variants compared with each other (one Pareto plot per family); names the quantity.
    pub family: &'static str,
    /// Unit of the error columns.
    pub unit: &'static str,
    /// Function name; a peer's (a baseline from another project, `tests/baselines/peer_*.wgsl`)
    /// starts with [`crate::peers::PREFIX`].
    pub name: String,
    /// Bits stored per value (the encoding's size), or 0 when it stores nothing.
    pub bits: u32,
    /// Error statistics, or `None` where they need an adapter and there is none.
    pub error: Option<ErrorStats>,
    /// Where and over what the error was measured.
    pub error_from: String,
    /// The error counts directions with z ≥ 0 only (hemisphere-only normal encodings).
    pub upper_only: bool,
    /// Peers of normal codecs: their error over z ≥ 0, for the dominance check against an
    /// `upper_only` variant (see [`crate::peers::dominates`]).
    pub error_upper: Option<ErrorStats>,
    /// The WGSL to time and count (None for CPU-only variants).
    pub wgsl: Option<Wgsl>,
    /// The Rust twin's timer, if the variant has a twin.
    pub twin: Option<TwinTimer>,
}
