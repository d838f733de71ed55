//! Precision testing tools: error metrics and adversarial test inputs, public so that
//! downstream suites measure their own shaders the way this crate measures its own.
//!
//! - [`metrics`], [`inputs`]: always available.
//! - [`assert`](mod@assert): tolerance asserts that print the measured value, the bound, the margin and
//!   where the bound comes from — [`assert_within!`](crate::assert_within),
//!   [`assert_within_abs!`](crate::assert_within_abs), [`assert_at_least!`](crate::assert_at_least)
//!   (always available; exported at the crate root).
//! - `strategies` (feature `proptest`): proptest strategies with adversarial cases weighted in.
//! - `check` (features `proptest` + `harness`): property-based checks of any WGSL function on an
//!   adapter against a Rust reference, batched, with shrinking that re-runs the WGSL.

pub mod assert;
#[cfg(all(feature = "proptest", feature = "harness"))]
#[cfg_attr(docsrs, doc(cfg(all(feature = "proptest", feature = "harness"))))]
pub mod check;
pub mod inputs;
pub mod metrics;
#[cfg(feature = "proptest")]
#[cfg_attr(docsrs, doc(cfg(feature = "proptest")))]
pub mod strategies;
#[cfg(all(feature = "proptest", feature = "harness"))]
mod value;

/// The proptest crate these strategies are built with, so downstream code combines them with
/// the same version.
#[cfg(feature = "proptest")]
pub use proptest;
