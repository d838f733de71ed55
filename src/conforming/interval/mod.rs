//! Machine-derived error bounds: a WGSL function evaluated over intervals under the spec's
//! accuracy rules (WGSL "Floating Point Accuracy"), in the style of dEQP's precision tests.
//!
//! For one concrete input, [`Enclosure::of`] walks the function's naga IR and carries, for
//! every f32 value, an interval that holds every result a conforming implementation may
//! produce there; integers and booleans are carried as intervals and "true, false or either".
//! The interval of the returned value therefore holds every result any conforming adapter can
//! return for that input, and its distance from the exact value, in ULPs of the exact value,
//! is a bound that no adapter can exceed on that input. The per-family tests take the largest
//! over their inputs and check that the hand-derived bound (`linear_depth::bounds`) contains it.
//!
//! The rules, per operation (f32; `ULP(y)` as the spec defines it: the spacing of the binade
//! below a power of two):
//!
//! | operation | results allowed |
//! |---|---|
//! | `+ − ×` | either f32 neighbour of the exact result (the spec's "correctly rounded") |
//! | `/` | within 2.5 ULP of the exact quotient, for divisors of magnitude in `[2^-126, 2^126]`; any other divisor is [`IntervalError::Indeterminate`] |
//! | `f32(u32)`, `f32(i32)` | either neighbour where the integer is not an f32 |
//! | matrix × vector, `dot` | each row's (the lanes') products summed in every order (the spec's inherited accuracy) |
//! | `log2` | 3 ULP, absolute `2^-21` on `[0.5, 2]`; `exp2(x)`: `3 + 2|x|` ULP |
//! | `fract(x)` | as `x − floor(x)` (inherited) |
//! | `min max clamp abs floor ceil round trunc select`, comparisons, bit casts, integers | exact |
//! | flushing (optional, [`Enclosure::of`]'s `flush`) | any subnormal operand or result may be ±0 |
//!
//! **Fusion** is covered without being tried: the hull of `a·b + c` evaluated with two
//! roundings contains the fused result (rounding is monotone and the exact `a·b` lies between
//! the neighbours of the product). **Reassociation** of sums is refused rather than modelled:
//! an f32 `+` or `−` whose operand is itself the result of one (through locals, calls and
//! vector construction too, as a compiler sees it after inlining) is
//! [`IntervalError::NotCovered`], because another order can cancel where this one does not.
//! Products and quotients are reassociated: where an operand of `·` or `/` is itself a product
//! or quotient (through locals and calls too), every one-level reordering the spec's
//! `(a·b)/c ↔ (a/c)·b` stands for is evaluated and hulled in; a chain of three or more is
//! [`IntervalError::NotCovered`]. A product by an exact power of two (a scaling) counts no depth
//! among products, where every order is exact; with a quotient it reorders like any product,
//! `(4·x)/c ↔ (4/c)·x` rounding a quotient of the power of two (found when the emulation placed
//! `decode_log_roughness`'s quotients at their ends): enumerated where the scaling is an operand
//! of the division, refused elsewhere.
//! Builtins other than those in the table are refused ([`IntervalError::NotCovered`]).
//!
//! Intervals are evaluated per input, so the dependency problem of interval arithmetic (the
//! same value drawn twice from its interval) can only widen them: each enclosure is sound,
//! never tight by construction. Infinities and NaN are never produced: an operation whose
//! result could overflow is [`IntervalError::Indeterminate`].
//!
//! Files: `arith.rs` (f32 intervals and their arithmetic), `value.rs` (values lane by lane,
//! three-valued conditions), `ops.rs` (operators, builtins, conversions on values),
//! `enclosure.rs` (the walk over the IR); this file holds the error type.

mod arith;
mod enclosure;
mod ops;
mod value;

pub use arith::{Iv, ulp_spec};
pub use enclosure::Enclosure;
pub use value::{Tri, Value};

// One namespace for the parts (each does `use super::*`), as when they were one file.
use arith::*;
use ops::*;
use value::*;

use naga::{
    Arena, BinaryOperator, Block, Expression, Function, Handle, Literal, MathFunction, Module,
    RelationalFunction, ScalarKind, Statement, TypeInner, UnaryOperator,
};
use std::fmt;

/// Why a function has no enclosure on an input.
#[derive(Clone, Debug, PartialEq)]
pub enum IntervalError {
    /// The WGSL does not parse or the function does not exist.
    Source(String),
    /// An operation the evaluator does not model (named), so no bound can be derived.
    NotCovered(String),
    /// An operation whose result the spec leaves undefined on the enclosure reached (named).
    Indeterminate(String),
}

impl fmt::Display for IntervalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IntervalError::Source(m) => write!(f, "source: {m}"),
            IntervalError::NotCovered(m) => write!(f, "not covered by the interval rules: {m}"),
            IntervalError::Indeterminate(m) => write!(f, "indeterminate under WGSL: {m}"),
        }
    }
}

impl std::error::Error for IntervalError {}

type R<T> = Result<T, IntervalError>;

fn not_covered(what: &str) -> IntervalError {
    IntervalError::NotCovered(what.to_string())
}

#[cfg(test)]
mod tests;
