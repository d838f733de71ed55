//! Tolerance asserts that say why: [`assert_within!`](crate::assert_within),
//! [`assert_within_abs!`](crate::assert_within_abs) and
//! [`assert_at_least!`](crate::assert_at_least).
//!
//! In the spirit of glam's `assert_approx_eq!`, which prints expected, actual and tolerance, a
//! failing check prints one message naming the measured value, the bound, the margin (how far
//! the measured value is on the wrong side, as a negative number) and where the bound comes from
//! — the named constant or the derivation it was worked out in — plus optional context:
//!
//! ```text
//! assert_within! failed: `err` ≤ `DIVISION_ULP`
//!   measured: 2.75
//!   bound:    2.5
//!   margin:   -0.25 (bound − measured)
//!   from:     prepass::conforming::allowance::DIVISION_ULP (WGSL's 2.5 ULP for x / y)
//!   context:  code 0x12345
//! ```
//!
//! The values are compared as `f64` ([`ToF64`]: every primitive number converts, `f32` and
//! integers below 2^53 exactly). A NaN measured value or a NaN bound always fails.
//!
//! A float literal bound is an `f64`: write `1e-6f32` where the check is meant against the
//! `f32` value of the literal.
//!
//! Each macro takes `<` (or `>` for [`assert_at_least!`](crate::assert_at_least)) before the
//! bound for a strict comparison. They need only `core` and `std`, so they are available with no
//! features, in downstream suites as in this crate's own.

use core::fmt;

/// A number the tolerance asserts accept: converted to `f64` for the comparison and the
/// message. Exact for `f32`, `f64` and integers of magnitude below 2^53 (the `u64`, `i64`,
/// `usize` and `isize` conversions round above that).
pub trait ToF64: Copy {
    /// The value as an `f64`.
    fn to_f64(self) -> f64;

    /// The value for the comparison and the message (an `f32` is printed as one).
    #[doc(hidden)]
    #[inline]
    fn value(self) -> Value {
        Value {
            value: self.to_f64(),
            f32: false,
        }
    }
}

/// A compared value: as an `f64`, and whether it was an `f32` (printed in `f32`'s shortest
/// form, so `0.1_f32` reads `0.1`, not `0.10000000149011612`).
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub struct Value {
    /// The value.
    pub value: f64,
    /// Whether it came from an `f32`.
    pub f32: bool,
}

macro_rules! to_f64_lossless {
    ($($t:ty)*) => {$(
        impl ToF64 for $t {
            #[inline]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
        }
    )*};
}
to_f64_lossless!(f64 i8 i16 i32 u8 u16 u32);

impl ToF64 for f32 {
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }

    #[inline]
    fn value(self) -> Value {
        Value {
            value: f64::from(self),
            f32: true,
        }
    }
}

macro_rules! to_f64_rounding {
    ($($t:ty)*) => {$(
        impl ToF64 for $t {
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
        }
    )*};
}
to_f64_rounding!(i64 u64 isize usize);

impl<T: ToF64> ToF64 for &T {
    #[inline]
    fn to_f64(self) -> f64 {
        (*self).to_f64()
    }

    #[inline]
    fn value(self) -> Value {
        (*self).value()
    }
}

/// A float whose absolute difference [`assert_within_abs!`](crate::assert_within_abs) takes:
/// `|a − b|` is computed in the type itself (as `(a - b).abs()` would be), then converted to
/// `f64`.
pub trait AbsDiff: ToF64 {
    /// `|self − other|`, computed in `Self`, as an `f64`.
    fn abs_diff_f64(self, other: Self) -> f64;

    /// `|self − other|` for the comparison and the message.
    #[doc(hidden)]
    fn abs_diff_value(self, other: Self) -> Value;
}

impl AbsDiff for f32 {
    #[inline]
    fn abs_diff_f64(self, other: Self) -> f64 {
        f64::from((self - other).abs())
    }

    #[inline]
    fn abs_diff_value(self, other: Self) -> Value {
        (self - other).abs().value()
    }
}

impl AbsDiff for f64 {
    #[inline]
    fn abs_diff_f64(self, other: Self) -> f64 {
        (self - other).abs()
    }

    #[inline]
    fn abs_diff_value(self, other: Self) -> Value {
        (self - other).abs().value()
    }
}

/// The comparison a check made, for the message.
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub enum Cmp {
    /// `measured ≤ bound`.
    AtMost,
    /// `measured < bound`.
    Below,
    /// `measured ≥ floor`.
    AtLeast,
    /// `measured > floor`.
    Above,
}

impl Cmp {
    /// Whether `measured` passes against `bound`; NaN on either side fails.
    #[doc(hidden)]
    #[inline]
    pub fn holds(self, measured: f64, bound: f64) -> bool {
        match self {
            Cmp::AtMost => measured <= bound,
            Cmp::Below => measured < bound,
            Cmp::AtLeast => measured >= bound,
            Cmp::Above => measured > bound,
        }
    }

    fn symbol(self) -> &'static str {
        match self {
            Cmp::AtMost => "≤",
            Cmp::Below => "<",
            Cmp::AtLeast => "≥",
            Cmp::Above => ">",
        }
    }
}

/// A number for the message: the shortest form that reads back as the same value (of its own
/// type, `f32` or `f64`), in exponent notation when very small or very large.
struct Num(Value);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0.value;
        let a = v.abs();
        let plain = a == 0.0 || !a.is_finite() || (1e-4..1e7).contains(&a);
        match (self.0.f32, plain) {
            (true, true) => write!(f, "{}", v as f32),
            (true, false) => write!(f, "{:e}", v as f32),
            (false, true) => write!(f, "{v}"),
            (false, false) => write!(f, "{v:e}"),
        }
    }
}

/// The margin for the message, to 6 significant digits (a difference of two values carries
/// their roundings, which would only add noise digits).
fn margin(v: f64) -> Num {
    Num(Value {
        value: format!("{v:.5e}").parse().unwrap_or(v),
        f32: false,
    })
}

/// The context line, its value aligned after `pad` spaces.
fn context_line(context: Option<fmt::Arguments<'_>>, pad: &str) -> String {
    match context {
        Some(c) => format!("\n  context:{pad}{c}"),
        None => String::new(),
    }
}

fn nan_note(v: f64) -> &'static str {
    if v.is_nan() {
        " (NaN never passes)"
    } else {
        ""
    }
}

/// The failure of `assert_within!` or `assert_at_least!`: panics with the message.
#[doc(hidden)]
#[cold]
#[inline(never)]
#[track_caller]
pub fn fail(
    cmp: Cmp,
    exprs: (&str, &str),
    (m, b): (Value, Value),
    from: &dyn fmt::Display,
    context: Option<fmt::Arguments<'_>>,
) -> ! {
    let (measured, bound) = (m.value, b.value);
    let (name, kind, margin_value, margin_is) = match cmp {
        Cmp::AtMost | Cmp::Below => (
            "assert_within!",
            "bound",
            bound - measured,
            "bound − measured",
        ),
        Cmp::AtLeast | Cmp::Above => (
            "assert_at_least!",
            "floor",
            measured - bound,
            "measured − floor",
        ),
    };
    panic!(
        "{name} failed: `{}` {} `{}`\n  measured: {}{}\n  {kind}:    {}{}\n  margin:   {} ({margin_is})\n  from:     {from}{}",
        exprs.0,
        cmp.symbol(),
        exprs.1,
        Num(m),
        nan_note(measured),
        Num(b),
        nan_note(bound),
        margin(margin_value),
        context_line(context, "  "),
    )
}

/// The failure of `assert_within_abs!`: panics with the message.
#[doc(hidden)]
#[cold]
#[inline(never)]
#[track_caller]
pub fn fail_abs(
    strict: bool,
    exprs: (&str, &str, &str),
    (actual, expected, diff, tolerance): (Value, Value, Value, Value),
    from: &dyn fmt::Display,
    context: Option<fmt::Arguments<'_>>,
) -> ! {
    panic!(
        "assert_within_abs! failed: |`{}` − `{}`| {} `{}`\n  actual:    {}\n  expected:  {}\n  |diff|:    {}{}\n  tolerance: {}{}\n  margin:    {} (tolerance − |diff|)\n  from:      {from}{}",
        exprs.0,
        exprs.1,
        if strict { "<" } else { "≤" },
        exprs.2,
        Num(actual),
        Num(expected),
        Num(diff),
        nan_note(diff.value),
        Num(tolerance),
        nan_note(tolerance.value),
        margin(tolerance.value - diff.value),
        context_line(context, "   "),
    )
}

/// Asserts that a measured error is within its bound, `measured ≤ bound`, and on failure panics
/// with the measured value, the bound, the margin (`bound − measured`, negative) and where the
/// bound comes from.
///
/// `assert_within!(measured, bound, from)` or
/// `assert_within!(measured, bound, from, "context {}", args...)`, where `measured` and `bound`
/// are any primitive numbers ([`ToF64`](crate::precision::assert::ToF64); compared as `f64`),
/// `from` names the bound's origin (anything `Display`: the named constant, or a pointer to its
/// derivation) and the context is a `format!` string and its arguments. Write
/// `assert_within!(measured, < bound, from)` for a strict `measured < bound`.
///
/// A NaN measured value fails, as does a NaN bound. Each argument is evaluated once; the
/// message and the context are only formatted on failure, so the check is cheap in a loop.
///
/// ```
/// use prepass::assert_within;
/// let err = 0.4_f32; // e.g. the measured ULP error of a correctly rounded result
/// assert_within!(err, 0.5, "correctly rounded: half an ULP");
/// let worst = 3u64;
/// assert_within!(worst, 4, "derived above: 4 roundings", "at code {:#x}", 0x1234);
/// assert_within!(1e-7_f64, < 1e-6, "strictly below the literal's bound");
/// ```
///
/// ```should_panic
/// // Panics: "assert_within! failed: `f32::NAN` ≤ `1.0` … measured: NaN (NaN never passes)".
/// prepass::assert_within!(f32::NAN, 1.0, "NaN fails whatever the bound");
/// ```
#[macro_export]
macro_rules! assert_within {
    ($measured:expr, < $bound:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check!(Below, $measured, $bound, $from, None)
    };
    ($measured:expr, < $bound:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check!(Below, $measured, $bound, $from, Some(format_args!($($context)+)))
    };
    ($measured:expr, $bound:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check!(AtMost, $measured, $bound, $from, None)
    };
    ($measured:expr, $bound:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check!(AtMost, $measured, $bound, $from, Some(format_args!($($context)+)))
    };
}

/// Asserts that a measured value reaches its floor, `measured ≥ floor` — a lower bound, such as
/// "the emulation reaches the end of the interval" or "the sweep is dense enough to find the
/// worst case" — and on failure panics with the measured value, the floor, the margin
/// (`measured − floor`, negative) and where the floor comes from.
///
/// The same form as [`assert_within!`](crate::assert_within):
/// `assert_at_least!(measured, floor, from [, "context {}", args...])`, and
/// `assert_at_least!(measured, > floor, from ...)` for a strict `measured > floor`. A NaN
/// measured value fails.
///
/// ```
/// use prepass::assert_at_least;
/// let reached = 2.5_f64; // e.g. how far an emulated division reaches above the exact value
/// assert_at_least!(reached, 2.0, "the upper policy reaches WGSL's 2.5 ULP allowance");
/// assert_at_least!(reached, > 0.0, "it moves at all", "policy {}", "upper");
/// ```
///
/// ```should_panic
/// prepass::assert_at_least!(0.3_f32, 0.5, "too sparse a sweep misses the worst case");
/// ```
#[macro_export]
macro_rules! assert_at_least {
    ($measured:expr, > $floor:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check!(Above, $measured, $floor, $from, None)
    };
    ($measured:expr, > $floor:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check!(Above, $measured, $floor, $from, Some(format_args!($($context)+)))
    };
    ($measured:expr, $floor:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check!(AtLeast, $measured, $floor, $from, None)
    };
    ($measured:expr, $floor:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check!(AtLeast, $measured, $floor, $from, Some(format_args!($($context)+)))
    };
}

/// Asserts that two floats agree within a tolerance, `|actual − expected| ≤ tolerance`, and on
/// failure panics with both values, their difference, the tolerance, the margin
/// (`tolerance − |diff|`, negative) and where the tolerance comes from.
///
/// `assert_within_abs!(actual, expected, tolerance, from [, "context {}", args...])`, and
/// `assert_within_abs!(actual, expected, < tolerance, from ...)` for a strict comparison.
/// `actual` and `expected` are both `f32` or both `f64`
/// ([`AbsDiff`](crate::precision::assert::AbsDiff)): the difference is computed in that type,
/// as `(actual - expected).abs()` would be, then compared with the tolerance as `f64`. NaN on
/// either side fails, and so do two equal infinities (their difference is NaN).
///
/// ```
/// use prepass::assert_within_abs;
/// let len = 1.0000001_f32;
/// assert_within_abs!(len, 1.0, 3.0 * 2f64.powi(-24), "a unit vector: 3 roundings");
/// assert_within_abs!(0.1_f64 + 0.2, 0.3, < 1e-15, "one rounding", "at {}", "0.1 + 0.2");
/// ```
///
/// ```should_panic
/// prepass::assert_within_abs!(1.5_f64, 1.0, 0.25, "a quarter either side");
/// ```
#[macro_export]
macro_rules! assert_within_abs {
    ($actual:expr, $expected:expr, < $tolerance:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check_abs!(true, $actual, $expected, $tolerance, $from, None)
    };
    ($actual:expr, $expected:expr, < $tolerance:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check_abs!(true, $actual, $expected, $tolerance, $from, Some(format_args!($($context)+)))
    };
    ($actual:expr, $expected:expr, $tolerance:expr, $from:expr $(,)?) => {
        $crate::__tolerance_check_abs!(false, $actual, $expected, $tolerance, $from, None)
    };
    ($actual:expr, $expected:expr, $tolerance:expr, $from:expr, $($context:tt)+) => {
        $crate::__tolerance_check_abs!(false, $actual, $expected, $tolerance, $from, Some(format_args!($($context)+)))
    };
}

/// The shared expansion of [`assert_within!`](crate::assert_within) and
/// [`assert_at_least!`](crate::assert_at_least).
#[doc(hidden)]
#[macro_export]
macro_rules! __tolerance_check {
    ($cmp:ident, $measured:expr, $bound:expr, $from:expr, $context:expr) => {{
        let measured = $crate::precision::assert::ToF64::value($measured);
        let bound = $crate::precision::assert::ToF64::value($bound);
        let cmp = $crate::precision::assert::Cmp::$cmp;
        if !cmp.holds(measured.value, bound.value) {
            $crate::precision::assert::fail(
                cmp,
                (stringify!($measured), stringify!($bound)),
                (measured, bound),
                &$from,
                $context,
            );
        }
    }};
}

/// The expansion of [`assert_within_abs!`](crate::assert_within_abs).
#[doc(hidden)]
#[macro_export]
macro_rules! __tolerance_check_abs {
    ($strict:expr, $actual:expr, $expected:expr, $tolerance:expr, $from:expr, $context:expr) => {{
        let (actual, expected) = ($actual, $expected);
        let diff = $crate::precision::assert::AbsDiff::abs_diff_value(actual, expected);
        let tolerance = $crate::precision::assert::ToF64::value($tolerance);
        let cmp = if $strict {
            $crate::precision::assert::Cmp::Below
        } else {
            $crate::precision::assert::Cmp::AtMost
        };
        if !cmp.holds(diff.value, tolerance.value) {
            $crate::precision::assert::fail_abs(
                $strict,
                (
                    stringify!($actual),
                    stringify!($expected),
                    stringify!($tolerance),
                ),
                (
                    $crate::precision::assert::ToF64::value(actual),
                    $crate::precision::assert::ToF64::value(expected),
                    diff,
                    tolerance,
                ),
                &$from,
                $context,
            );
        }
    }};
}

#[cfg(test)]
mod tests {
    use std::panic::{AssertUnwindSafe, catch_unwind};

    /// The panic message of `f`, or `None` if it did not panic.
    fn message(f: impl FnOnce()) -> Option<String> {
        let payload = catch_unwind(AssertUnwindSafe(f)).err()?;
        Some(
            payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .expect("a string payload"),
        )
    }

    #[test]
    fn passes_within_and_at_the_bound() {
        crate::assert_within!(0.4_f32, 0.5, "half an ULP");
        crate::assert_within!(0.5_f32, 0.5, "equal passes");
        crate::assert_within!(3u64, 4, "integers", "with context {}", 1);
        crate::assert_within!(1usize, 2usize, "usize", "trailing comma {}", 1,);
        crate::assert_within!(-1i64, 0.0, "mixed types");
        let v = 2.0_f64;
        crate::assert_within!(&v, 2.0, "by reference");
        crate::assert_within!(1.0_f64, < 1.5, "strict");
        crate::assert_at_least!(2.5_f64, 2.0, "floor");
        crate::assert_at_least!(2.0_f64, 2.0, "equal passes");
        crate::assert_at_least!(2.0_f64, > 1.0, "strict floor");
        crate::assert_within_abs!(1.0000001_f32, 1.0, 2f64.powi(-23), "one ULP");
        crate::assert_within_abs!(0.5_f64, 1.0, 0.5, "at the tolerance");
        crate::assert_within_abs!(0.5_f64, 1.0, < 0.6, "strict", "ctx {}", 3);
    }

    #[test]
    fn a_failure_names_value_bound_margin_origin_and_context() {
        let err = 2.75_f64;
        let m = message(|| {
            crate::assert_within!(
                err,
                2.5,
                "conforming::allowance::DIVISION_ULP",
                "code {:#x}",
                0x12
            )
        })
        .expect("2.75 > 2.5 fails");
        assert_eq!(
            m,
            "assert_within! failed: `err` ≤ `2.5`\n  measured: 2.75\n  bound:    2.5\n  \
             margin:   -0.25 (bound − measured)\n  from:     conforming::allowance::DIVISION_ULP\n  \
             context:  code 0x12"
        );
        let m = message(|| crate::assert_within!(1e-9_f64, 1e-10, "tiny")).unwrap();
        assert!(
            m.contains("measured: 1e-9") && m.contains("bound:    1e-10"),
            "{m}"
        );
        assert!(
            m.contains("margin:   -9e-10") && !m.contains("context"),
            "{m}"
        );
    }

    #[test]
    fn f32_values_print_as_f32() {
        let (err, step) = (0.1_f32, 0.05_f32);
        let m = message(|| crate::assert_within!(err, step, "f32")).unwrap();
        assert!(m.contains("measured: 0.1\n  bound:    0.05\n"), "{m}");
        let m = message(|| crate::assert_within!(1.1920929e-7_f32, 0.0, "tiny f32")).unwrap();
        assert!(m.contains("measured: 1.1920929e-7\n"), "{m}");
        let m = message(|| crate::assert_within_abs!(1.1_f32, 1.0, 0.01, "abs f32")).unwrap();
        assert!(
            m.contains("actual:    1.1\n  expected:  1\n  |diff|:    0.100000024\n"),
            "{m}"
        );
        assert!(m.contains("tolerance: 0.01\n"), "{m}");
    }

    #[test]
    fn strict_fails_at_equality() {
        let m = message(|| crate::assert_within!(1.0_f64, < 1.0, "strict")).unwrap();
        assert!(
            m.starts_with("assert_within! failed: `1.0_f64` < `1.0`"),
            "{m}"
        );
        assert!(m.contains("margin:   0 "), "{m}");
        let m = message(|| crate::assert_at_least!(1.0_f64, > 1.0, "strict")).unwrap();
        assert!(
            m.starts_with("assert_at_least! failed: `1.0_f64` > `1.0`"),
            "{m}"
        );
        let m = message(|| crate::assert_within_abs!(2.0_f64, 1.0, < 1.0, "strict")).unwrap();
        assert!(m.contains("| < `1.0`"), "{m}");
    }

    #[test]
    fn nan_fails() {
        let m = message(|| crate::assert_within!(f32::NAN, 1.0, "nan")).unwrap();
        assert!(m.contains("measured: NaN (NaN never passes)"), "{m}");
        assert!(message(|| crate::assert_within!(f64::NAN, f64::INFINITY, "nan")).is_some());
        assert!(message(|| crate::assert_within!(0.0, f64::NAN, "nan bound")).is_some());
        assert!(message(|| crate::assert_at_least!(f64::NAN, 0.0, "nan")).is_some());
        assert!(message(|| crate::assert_within_abs!(f32::NAN, 1.0, 1.0, "nan")).is_some());
        let inf = f64::INFINITY;
        let m = message(|| crate::assert_within_abs!(inf, inf, 1.0, "inf − inf")).unwrap();
        assert!(m.contains("|diff|:    NaN (NaN never passes)"), "{m}");
    }

    #[test]
    fn lower_bound_and_two_sided_messages() {
        let m = message(|| {
            crate::assert_at_least!(0.3_f32 as f64, 0.5, "sweep dense enough", "bin {}", 7)
        })
        .unwrap();
        assert!(
            m.starts_with("assert_at_least! failed: `0.3_f32 as f64` ≥ `0.5`"),
            "{m}"
        );
        assert!(
            m.contains("floor:    0.5") && m.contains("(measured − floor)"),
            "{m}"
        );
        assert!(
            m.contains("from:     sweep dense enough\n  context:  bin 7"),
            "{m}"
        );
        let (got, want) = (1.5_f64, 1.0_f64);
        let m = message(|| crate::assert_within_abs!(got, want, 0.25, "a quarter", "at {}", 3))
            .unwrap();
        assert_eq!(
            m,
            "assert_within_abs! failed: |`got` − `want`| ≤ `0.25`\n  actual:    1.5\n  \
             expected:  1\n  |diff|:    0.5\n  tolerance: 0.25\n  margin:    -0.25 (tolerance − |diff|)\n  \
             from:      a quarter\n  context:   at 3"
        );
    }

    #[test]
    fn arguments_are_evaluated_once() {
        let mut calls = 0;
        let mut next = || {
            calls += 1;
            1.0_f64
        };
        crate::assert_within!(next(), 2.0, "once");
        crate::assert_within_abs!(next(), 1.0, 0.0, "once");
        assert_eq!(calls, 2);
    }

    #[test]
    fn f32_difference_is_computed_in_f32() {
        // In f32, 1e8 − 0.5 rounds to 1e8 (the ULP there is 8); exactly it is 99999999.5. The
        // macro takes the f32 difference, as `(a - b).abs()` on the f32s would.
        let (a, b) = (1e8_f32, 0.5_f32);
        crate::assert_within_abs!(a, b, 1e8, "the f32 difference is 1e8");
        let m = message(|| crate::assert_within_abs!(a, b, < 1e8, "strict")).unwrap();
        assert!(m.contains("|diff|:    1e8\n"), "{m}");
    }
}
