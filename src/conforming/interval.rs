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

/// A closed interval of f32 values; `lo` may be `-0.0` where a negative zero is possible.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iv {
    /// Smallest value.
    pub lo: f32,
    /// Largest value.
    pub hi: f32,
    /// The product or quotient this value is the rounding of, for the reassociations.
    chain: Chain,
}

/// A value's last multiplicative operation: `kind` 0 none, 1 `a·b`, 2 `a/b`, with the operand
/// enclosures and how many such operations are chained at and below it; whether the chain holds
/// a scaling by a power of two (depth 0 when it is the scaling itself) and a quotient.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Chain {
    kind: u8,
    a: (f32, f32),
    b: (f32, f32),
    depth: u8,
    scaled: bool,
    quotient: bool,
}

const NO_CHAIN: Chain = Chain {
    kind: 0,
    a: (0.0, 0.0),
    b: (0.0, 0.0),
    depth: 0,
    scaled: false,
    quotient: false,
};

impl Iv {
    fn new(lo: f32, hi: f32) -> Iv {
        Iv {
            lo,
            hi,
            chain: NO_CHAIN,
        }
    }
    /// The single value `x`.
    pub fn point(x: f32) -> Iv {
        Iv::new(x, x)
    }
    fn hull(self, o: Iv) -> Iv {
        Iv::new(lo_min(self.lo, o.lo), hi_max(self.hi, o.hi))
    }
    fn may_be_negative(self) -> bool {
        self.lo < 0.0 || self.lo.to_bits() == 0x8000_0000
    }
}

// Minimum and maximum that order -0 below +0.
fn lo_min(a: f32, b: f32) -> f32 {
    if a.total_cmp(&b).is_le() { a } else { b }
}
fn hi_max(a: f32, b: f32) -> f32 {
    if a.total_cmp(&b).is_ge() { a } else { b }
}

/// `ULP(y)` as WGSL defines it for f32: the distance between the two closest distinct finite
/// f32 values around `y`, which below and at a power of two is the spacing of the lower binade.
pub fn ulp_spec(y: f64) -> f64 {
    let above = crate::precision::metrics::f32_ulp_at(y);
    // A power of two: the mantissa field is zero (f32_ulp_at reads the binade above it).
    if y.abs() >= f64::from(f32::MIN_POSITIVE) && y.abs().to_bits() & ((1u64 << 52) - 1) == 0 {
        above / 2.0
    } else {
        above
    }
}

/// The f32 neighbours (below, above) of the exact value `hi + lo` (a double-double, `|lo|`
/// at most half an f64 ULP of `hi`); equal when it is an f32.
fn bracket(hi: f64, lo: f64, what: &str) -> R<(f32, f32)> {
    let c = hi as f32;
    if !c.is_finite() {
        return Err(IntervalError::Indeterminate(format!(
            "{what} overflows f32"
        )));
    }
    // hi − c is exact (c is hi rounded to fewer bits); the sum's sign is the exact one's.
    let d = (hi - f64::from(c)) + lo;
    Ok(if d == 0.0 {
        (c, c)
    } else if d > 0.0 {
        (c, c.next_up())
    } else {
        (c.next_down(), c)
    })
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn checked(iv: Iv, what: &str) -> R<Iv> {
    if iv.lo.is_finite() && iv.hi.is_finite() {
        Ok(iv)
    } else {
        Err(IntervalError::Indeterminate(format!(
            "{what} overflows f32"
        )))
    }
}

// An exact-zero result is +0 unless an operand could be negative (then -0 is kept possible).
fn zero_sign(iv: Iv, negative_operand: bool) -> Iv {
    if negative_operand && iv.lo == 0.0 {
        Iv::new(-0.0, iv.hi)
    } else {
        iv
    }
}

fn add(a: Iv, b: Iv) -> R<Iv> {
    let (sl, el) = two_sum(f64::from(a.lo), f64::from(b.lo));
    let (sh, eh) = two_sum(f64::from(a.hi), f64::from(b.hi));
    let lo = bracket(sl, el, "+")?.0;
    let hi = bracket(sh, eh, "+")?.1;
    Ok(zero_sign(
        Iv::new(lo, hi),
        a.may_be_negative() || b.may_be_negative(),
    ))
}

fn neg(a: Iv) -> Iv {
    // −(x·y) = (−x)·y and −(x/y) = (−x)/y: the chain stays, its first operand negated.
    let mut chain = a.chain;
    chain.a = (-chain.a.1, -chain.a.0);
    Iv {
        lo: -a.hi,
        hi: -a.lo,
        chain,
    }
}

fn mul(a: Iv, b: Iv) -> R<Iv> {
    // f32 × f32 is exact in f64.
    let p = [
        f64::from(a.lo) * f64::from(b.lo),
        f64::from(a.lo) * f64::from(b.hi),
        f64::from(a.hi) * f64::from(b.lo),
        f64::from(a.hi) * f64::from(b.hi),
    ];
    let (mn, mx) = p
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
            (l.min(x), h.max(x))
        });
    let lo = bracket(mn, 0.0, "×")?.0;
    let hi = bracket(mx, 0.0, "×")?.1;
    Ok(zero_sign(
        Iv::new(lo, hi),
        a.may_be_negative() != b.may_be_negative() || a.may_be_negative(),
    ))
}

/// 2^-126 and 2^126, the divisor magnitudes `/` is specified for.
const DIV_MIN: f32 = f32::MIN_POSITIVE;
const DIV_MAX: f32 = 8.507_059e37;

fn div(a: Iv, b: Iv) -> R<Iv> {
    let ok = |x: f32| x.abs() >= DIV_MIN && x.abs() <= DIV_MAX;
    if !(ok(b.lo) && ok(b.hi) && (b.lo > 0.0) == (b.hi > 0.0)) {
        return Err(IntervalError::Indeterminate(format!(
            "`/` by a divisor in [{:e}, {:e}] (specified for magnitudes 2^-126 to 2^126)",
            b.lo, b.hi
        )));
    }
    let q = [
        f64::from(a.lo) / f64::from(b.lo),
        f64::from(a.lo) / f64::from(b.hi),
        f64::from(a.hi) / f64::from(b.lo),
        f64::from(a.hi) / f64::from(b.hi),
    ];
    let (mn, mx) = q
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
            (l.min(x), h.max(x))
        });
    // 2.5 ULP of the largest |q| bounds the allowance everywhere (ULP grows with |q|); inward's
    // 2^-50 relative slack covers the f64 rounding of the quotients and of these sums.
    let allow = 2.5 * ulp_spec(mn.abs().max(mx.abs()));
    Ok(zero_sign(
        inward(mn - allow, mx + allow, "/")?,
        a.may_be_negative() != b.may_be_negative() || a.may_be_negative(),
    ))
}

/// The hull of a sum of `terms` over every order of evaluation (every binary tree of them).
fn every_order(terms: &[Iv], flush: bool) -> R<Iv> {
    if terms.len() == 1 {
        return Ok(terms[0]);
    }
    let n = terms.len();
    let mut hull: Option<Iv> = None;
    // Every split into two non-empty sets, each once: the first term always on the left.
    for mask in 1..(1u32 << (n - 1)) {
        let left: Vec<Iv> = (0..n)
            .filter(|&k| k == 0 || mask >> (k - 1) & 1 == 0)
            .map(|k| terms[k])
            .collect();
        let right: Vec<Iv> = (1..n)
            .filter(|&k| mask >> (k - 1) & 1 == 1)
            .map(|k| terms[k])
            .collect();
        let s = flushed(
            add(
                flushed(every_order(&left, flush)?, flush),
                flushed(every_order(&right, flush)?, flush),
            )?,
            flush,
        );
        hull = Some(hull.map_or(s, |h| h.hull(s)));
    }
    Ok(hull.expect("two or more terms have a split"))
}

/// `p·q` (`kind` 1) or `p/q` (2), with every reassociation of it hulled in: where an operand
/// is itself a product or quotient, every other order of the same three operands
/// (`(a·b)/q ↔ (a/q)·b ↔ a·(b/q)` and the rest), each evaluated from the operands' own
/// enclosures. A chain of three or more is refused (its reorderings are not enumerated).
fn mul_div(kind: u8, p: Iv, q: Iv, flush: bool) -> R<Iv> {
    let fl = |v: Iv| flushed(v, flush);
    let op = |k: u8, a: Iv, b: Iv| -> R<Iv> {
        let r = if k == 1 {
            mul(fl(a), fl(b))
        } else {
            div(fl(a), fl(b))
        }?;
        Ok(fl(r))
    };
    // A product by an exact power of two (a scaling) is exact in every order among products,
    // so it counts no depth: (s·x)·y may be any order of the three at no extra rounding. With
    // a quotient it does reorder: (s·x)/c ↔ (s/c)·x rounds a quotient of s. That one-level
    // reordering is enumerated below where the scaling is an operand of the division and the
    // other operand is no chain; any other meeting of a scaling and a quotient in one chain is
    // refused (its reorderings are not enumerated).
    let pow2 = |v: Iv| {
        v.lo == v.hi && v.lo != 0.0 && v.lo.is_normal() && v.lo.to_bits() & 0x007f_ffff == 0
    };
    let normal_or_zero = |v: Iv| {
        [v.lo, v.hi]
            .iter()
            .all(|x| *x == 0.0 || x.abs() >= f32::MIN_POSITIVE)
            && !(v.lo < 0.0 && v.hi > 0.0 && flush)
    };
    if kind == 1 {
        for (s, x) in [(q, p), (p, q)] {
            if pow2(s) && x.chain.kind == 0 {
                let mut r = op(1, x, s)?;
                if normal_or_zero(r) && normal_or_zero(x) {
                    r.chain = Chain {
                        kind: 1,
                        a: (x.lo, x.hi),
                        b: (s.lo, s.hi),
                        depth: 0,
                        scaled: true,
                        quotient: false,
                    };
                    return Ok(r);
                }
            }
        }
    }
    let scaling_operand = |v: Iv, other: Iv| {
        kind == 2 && v.chain.scaled && v.chain.depth == 0 && other.chain.kind == 0
    };
    let scaled = p.chain.scaled || q.chain.scaled;
    let quotient = kind == 2 || p.chain.quotient || q.chain.quotient;
    if scaled && quotient && !scaling_operand(p, q) && !scaling_operand(q, p) {
        return Err(not_covered(
            "a power-of-two scaling and a quotient in one chain (a compiler may divide the power of two)",
        ));
    }
    if p.chain.depth >= 2 || q.chain.depth >= 2 {
        return Err(not_covered(
            "a chain of three or more products and quotients (a compiler may reorder it)",
        ));
    }
    let mut r = op(kind, p, q)?;
    let iv = |x: (f32, f32)| Iv::new(x.0, x.1);
    let (pa, pb, qa, qb) = (iv(p.chain.a), iv(p.chain.b), iv(q.chain.a), iv(q.chain.b));
    let mut alts: Vec<Iv> = Vec::new();
    // Each chain of two is one of three families over its three operands, every member of
    // which is mathematically equal: x·y·z, x·y/z and x/(y·z).
    match (kind, p.chain.kind) {
        // (a·b)·q: a·(b·q), b·(a·q)
        (1, 1) => alts.extend([op(1, pa, op(1, pb, q)?)?, op(1, pb, op(1, pa, q)?)?]),
        // (a/b)·q: (a·q)/b, a·(q/b)
        (1, 2) => alts.extend([op(2, op(1, pa, q)?, pb)?, op(1, pa, op(2, q, pb)?)?]),
        // (a·b)/q: (a/q)·b, a·(b/q)
        (2, 1) => alts.extend([op(1, op(2, pa, q)?, pb)?, op(1, pa, op(2, pb, q)?)?]),
        // (a/b)/q: a/(b·q), (a/q)/b
        (2, 2) => alts.extend([op(2, pa, op(1, pb, q)?)?, op(2, op(2, pa, q)?, pb)?]),
        _ => {}
    }
    match (kind, q.chain.kind) {
        // p·(a·b): (p·a)·b, (p·b)·a
        (1, 1) => alts.extend([op(1, op(1, p, qa)?, qb)?, op(1, op(1, p, qb)?, qa)?]),
        // p·(a/b): (p·a)/b, (p/b)·a
        (1, 2) => alts.extend([op(2, op(1, p, qa)?, qb)?, op(1, op(2, p, qb)?, qa)?]),
        // p/(a·b): (p/a)/b, (p/b)/a
        (2, 1) => alts.extend([op(2, op(2, p, qa)?, qb)?, op(2, op(2, p, qb)?, qa)?]),
        // p/(a/b): (p·b)/a, (p/a)·b, p·(b/a)
        (2, 2) => alts.extend([
            op(2, op(1, p, qb)?, qa)?,
            op(1, op(2, p, qa)?, qb)?,
            op(1, p, op(2, qb, qa)?)?,
        ]),
        _ => {}
    }
    for a in alts {
        r = r.hull(a);
    }
    r.chain = Chain {
        kind,
        a: (p.lo, p.hi),
        b: (q.lo, q.hi),
        depth: 1 + p.chain.depth.max(q.chain.depth),
        scaled,
        quotient,
    };
    Ok(r)
}

fn flushed(iv: Iv, flush: bool) -> Iv {
    let sub = |x: f32| x != 0.0 && x.abs() < f32::MIN_POSITIVE;
    // Some subnormal value lies in the interval when an end is subnormal or it spans zero.
    if flush && (sub(iv.lo) || sub(iv.hi) || (iv.lo < 0.0 && iv.hi > 0.0)) {
        Iv {
            lo: lo_min(iv.lo, -0.0),
            hi: hi_max(iv.hi, 0.0),
            chain: iv.chain,
        }
    } else {
        iv
    }
}

/// Three-valued truth: what a condition may be over the enclosures it reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tri {
    /// True on every value of the enclosures.
    True,
    /// False on every value.
    False,
    /// Either, depending on the value.
    Either,
}

impl Tri {
    fn of(b: bool) -> Tri {
        if b { Tri::True } else { Tri::False }
    }
    fn join(self, o: Tri) -> Tri {
        if self == o { self } else { Tri::Either }
    }
    fn not(self) -> Tri {
        match self {
            Tri::True => Tri::False,
            Tri::False => Tri::True,
            Tri::Either => Tri::Either,
        }
    }
    fn and(self, o: Tri) -> Tri {
        match (self, o) {
            (Tri::False, _) | (_, Tri::False) => Tri::False,
            (Tri::True, Tri::True) => Tri::True,
            _ => Tri::Either,
        }
    }
    fn or(self, o: Tri) -> Tri {
        self.not().and(o.not()).not()
    }
}

/// An enclosure of a WGSL value, lane by lane (scalars have one lane).
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// f32 lanes; bit `k` of `sum` marks lane `k` as the result of an f32 `+`/`−` (for the
    /// reassociation refusal).
    F32 {
        /// The lanes.
        lanes: Vec<Iv>,
        /// Which lanes are sums a compiler could reassociate with another term.
        sum: u8,
    },
    /// u32 lanes, `[lo, hi]`.
    U32(Vec<(u32, u32)>),
    /// i32 lanes, `[lo, hi]`.
    I32(Vec<(i32, i32)>),
    /// bool lanes.
    Bool(Vec<Tri>),
    /// Array or struct members.
    Composite(Vec<Value>),
    /// A pointer: a local (`true`) or global variable's index, then member indices.
    Ptr(bool, usize, Vec<usize>),
}

impl Value {
    /// f32 scalar or vector lanes from exact values.
    pub fn f32s(x: &[f32]) -> Value {
        Value::F32 {
            lanes: x.iter().map(|&v| Iv::point(v)).collect(),
            sum: 0,
        }
    }
    /// u32 scalar or vector lanes from exact values.
    pub fn u32s(x: &[u32]) -> Value {
        Value::U32(x.iter().map(|&v| (v, v)).collect())
    }
    /// The f32 lanes, if this is an f32 value.
    pub fn f32_lanes(&self) -> Option<&[Iv]> {
        match self {
            Value::F32 { lanes, .. } => Some(lanes),
            _ => None,
        }
    }
    fn join(&self, o: &Value) -> R<Value> {
        Ok(match (self, o) {
            (Value::F32 { lanes: a, sum: s }, Value::F32 { lanes: b, sum: t }) => Value::F32 {
                lanes: a.iter().zip(b).map(|(x, y)| x.hull(*y)).collect(),
                sum: *s | *t,
            },
            (Value::U32(a), Value::U32(b)) => Value::U32(
                a.iter()
                    .zip(b)
                    .map(|(x, y)| (x.0.min(y.0), x.1.max(y.1)))
                    .collect(),
            ),
            (Value::I32(a), Value::I32(b)) => Value::I32(
                a.iter()
                    .zip(b)
                    .map(|(x, y)| (x.0.min(y.0), x.1.max(y.1)))
                    .collect(),
            ),
            (Value::Bool(a), Value::Bool(b)) => {
                Value::Bool(a.iter().zip(b).map(|(x, y)| x.join(*y)).collect())
            }
            (Value::Composite(a), Value::Composite(b)) => {
                Value::Composite(a.iter().zip(b).map(|(x, y)| x.join(y)).collect::<R<_>>()?)
            }
            (a, b) if a == b => a.clone(),
            _ => return Err(not_covered("joining values of different kinds")),
        })
    }
    fn lanes(&self) -> usize {
        match self {
            Value::F32 { lanes, .. } => lanes.len(),
            Value::U32(l) => l.len(),
            Value::I32(l) => l.len(),
            Value::Bool(l) => l.len(),
            Value::Composite(m) => m.len(),
            Value::Ptr(..) => 1,
        }
    }
    fn lane(&self, k: usize) -> Value {
        match self {
            Value::F32 { lanes, sum } => Value::F32 {
                lanes: vec![lanes[k]],
                sum: (*sum >> k) & 1,
            },
            Value::U32(l) => Value::U32(vec![l[k]]),
            Value::I32(l) => Value::I32(vec![l[k]]),
            Value::Bool(l) => Value::Bool(vec![l[k]]),
            Value::Composite(m) => m[k].clone(),
            Value::Ptr(..) => self.clone(),
        }
    }
    fn concat(parts: &[Value]) -> R<Value> {
        let mut out = parts
            .first()
            .cloned()
            .ok_or_else(|| not_covered("empty construction"))?;
        for p in &parts[1..] {
            match (&mut out, p) {
                (Value::F32 { lanes: a, sum: s }, Value::F32 { lanes: b, sum: t }) => {
                    *s |= *t << a.len();
                    a.extend_from_slice(b);
                }
                (Value::U32(a), Value::U32(b)) => a.extend_from_slice(b),
                (Value::I32(a), Value::I32(b)) => a.extend_from_slice(b),
                (Value::Bool(a), Value::Bool(b)) => a.extend_from_slice(b),
                _ => return Err(not_covered("mixed-kind vector construction")),
            }
        }
        Ok(out)
    }
    fn tri(&self) -> R<Vec<Tri>> {
        match self {
            Value::Bool(l) => Ok(l.clone()),
            _ => Err(not_covered("a condition that is not bool")),
        }
    }
}

fn not_covered(what: &str) -> IntervalError {
    IntervalError::NotCovered(what.to_string())
}

/// The enclosure of one function call, and the module it runs in.
pub struct Enclosure {
    module: Module,
    flush: bool,
    /// Every global variable's initial value, evaluated once (stores to globals are refused,
    /// so they stay these).
    globals: Vec<Option<Value>>,
}

struct Frame<'a> {
    exprs: &'a Arena<Expression>,
    args: Vec<Value>,
    cache: Vec<Option<Value>>,
    locals: Vec<Option<Value>>,
}

impl Frame<'_> {
    fn join(&mut self, other: &Frame<'_>) -> R<()> {
        for (a, b) in self.locals.iter_mut().zip(&other.locals) {
            *a = match (a.take(), b) {
                (Some(x), Some(y)) => Some(x.join(y)?),
                (x, None) => x,
                (None, y) => y.clone(),
            };
        }
        Ok(())
    }
}

/// What a block does: whether control can continue past it, and the join of what it returns.
struct Flow {
    continues: bool,
    returned: Option<Value>,
}

fn join_opt(a: Option<Value>, b: Option<Value>) -> R<Option<Value>> {
    Ok(match (a, b) {
        (Some(x), Some(y)) => Some(x.join(&y)?),
        (x, None) => x,
        (None, y) => y,
    })
}

impl Enclosure {
    /// Parse `source` (valid WGSL on its own). `flush`: whether subnormals may be flushed.
    pub fn new(source: &str, flush: bool) -> R<Enclosure> {
        let module = naga::front::wgsl::parse_str(source)
            .map_err(|e| IntervalError::Source(e.emit_to_string(source)))?;
        let mut e = Enclosure {
            module,
            flush,
            globals: Vec::new(),
        };
        let inits: Vec<_> = e
            .module
            .global_variables
            .iter()
            .map(|(_, g)| g.init)
            .collect();
        e.globals = inits
            .into_iter()
            .map(|init| init.map(|h| e.global(h)).transpose())
            .collect::<R<_>>()?;
        Ok(e)
    }

    /// How many members or lanes global variable `i` has at `path`.
    fn global_len(&self, i: usize, path: &[usize]) -> R<usize> {
        let mut v = self.globals[i]
            .as_ref()
            .ok_or_else(|| not_covered("a global variable without initialiser"))?;
        for &k in path {
            match v {
                Value::Composite(m) if k < m.len() => v = &m[k],
                _ => return Err(not_covered("an index out of range")),
            }
        }
        Ok(v.lanes())
    }

    /// Global variable `i`'s value at `path` (member and lane indices).
    fn global_at(&self, i: usize, path: &[usize]) -> R<Value> {
        let mut v = self.globals[i]
            .as_ref()
            .ok_or_else(|| not_covered("a global variable without initialiser"))?;
        for (n, &k) in path.iter().enumerate() {
            match v {
                Value::Composite(m) if k < m.len() => v = &m[k],
                _ if n + 1 == path.len() && k < v.lanes() => return Ok(v.lane(k)),
                _ => return Err(not_covered("an index out of range")),
            }
        }
        Ok(v.clone())
    }

    /// The enclosure of `function(args)`: every result a conforming adapter may return.
    pub fn of(&self, function: &str, args: &[Value]) -> R<Value> {
        let (h, _) = self
            .module
            .functions
            .iter()
            .find(|(_, f)| f.name.as_deref() == Some(function))
            .ok_or_else(|| IntervalError::Source(format!("no function `{function}`")))?;
        self.call(h, args.to_vec(), 0)
    }

    fn call(&self, h: Handle<Function>, args: Vec<Value>, depth: usize) -> R<Value> {
        if depth > 64 {
            return Err(not_covered("recursion deeper than 64 calls"));
        }
        let f = &self.module.functions[h];
        let mut frame = Frame {
            exprs: &f.expressions,
            args,
            cache: vec![None; f.expressions.len()],
            locals: vec![None; f.local_variables.len()],
        };
        for (lh, lv) in f.local_variables.iter() {
            if let Some(init) = lv.init {
                frame.locals[lh.index()] = Some(self.eval(&mut frame, init, depth)?);
            }
        }
        let flow = self.block(&mut frame, &f.body, depth)?;
        flow.returned
            .ok_or_else(|| not_covered("a function that returns no value"))
    }

    fn block(&self, fr: &mut Frame<'_>, b: &Block, depth: usize) -> R<Flow> {
        let mut returned = None;
        for st in b.iter() {
            match st {
                Statement::Emit(range) => {
                    for e in range.clone() {
                        let v = self.eval_uncached(fr, e, depth)?;
                        fr.cache[e.index()] = Some(v);
                    }
                }
                Statement::Block(inner) => {
                    let flow = self.block(fr, inner, depth)?;
                    returned = join_opt(returned, flow.returned)?;
                    if !flow.continues {
                        return Ok(Flow {
                            continues: false,
                            returned,
                        });
                    }
                }
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => {
                    let c = self.eval(fr, *condition, depth)?.tri()?[0];
                    let go = |fr: &mut Frame<'_>, blk: &Block| self.block(fr, blk, depth);
                    let (cont, ret) = match c {
                        Tri::True => {
                            let f = go(fr, accept)?;
                            (f.continues, f.returned)
                        }
                        Tri::False => {
                            let f = go(fr, reject)?;
                            (f.continues, f.returned)
                        }
                        Tri::Either => {
                            let mut other = Frame {
                                exprs: fr.exprs,
                                args: fr.args.clone(),
                                cache: fr.cache.clone(),
                                locals: fr.locals.clone(),
                            };
                            let fa = go(fr, accept)?;
                            let fb = go(&mut other, reject)?;
                            match (fa.continues, fb.continues) {
                                (true, true) => fr.join(&other)?,
                                (false, true) => {
                                    fr.locals = other.locals;
                                    fr.cache = other.cache;
                                }
                                _ => {}
                            }
                            (
                                fa.continues || fb.continues,
                                join_opt(fa.returned, fb.returned)?,
                            )
                        }
                    };
                    returned = join_opt(returned, ret)?;
                    if !cont {
                        return Ok(Flow {
                            continues: false,
                            returned,
                        });
                    }
                }
                Statement::Return { value } => {
                    let v = match value {
                        Some(e) => Some(self.eval(fr, *e, depth)?),
                        None => None,
                    };
                    return Ok(Flow {
                        continues: false,
                        returned: join_opt(returned, v)?,
                    });
                }
                Statement::Store { pointer, value } => {
                    let v = self.eval(fr, *value, depth)?;
                    match self.eval(fr, *pointer, depth)? {
                        Value::Ptr(true, i, path) => {
                            let slot =
                                fr.locals[i].get_or_insert_with(|| Value::Composite(Vec::new()));
                            store(slot, &path, v)?;
                        }
                        _ => return Err(not_covered("a store to anything but a local")),
                    }
                }
                Statement::Call {
                    function,
                    arguments,
                    result,
                } => {
                    let args = arguments
                        .iter()
                        .map(|&a| self.eval(fr, a, depth))
                        .collect::<R<Vec<_>>>()?;
                    let v = self.call(*function, args, depth + 1)?;
                    if let Some(r) = result {
                        fr.cache[r.index()] = Some(v);
                    }
                }
                other => {
                    return Err(IntervalError::NotCovered(format!(
                        "statement {:?}",
                        std::mem::discriminant(other)
                    )));
                }
            }
        }
        Ok(Flow {
            continues: true,
            returned,
        })
    }

    /// `bitcast<u32>(x) & m` for the masks that read a field of an f32 (magnitude
    /// `0x7fffffff`, exponent `0x7f800000`, sign `0x80000000`), from `x`'s enclosure: each is
    /// monotone in `|x|` (or only the sign), where the bit cast of an interval that spans zero
    /// is not.
    fn float_field(
        &self,
        fr: &mut Frame<'_>,
        op: BinaryOperator,
        left: Handle<Expression>,
        right: Handle<Expression>,
        depth: usize,
    ) -> R<Option<Value>> {
        let Expression::As {
            expr: inner,
            kind: ScalarKind::Uint,
            convert: None,
        } = fr.exprs[left]
        else {
            return Ok(None);
        };
        if op != BinaryOperator::And {
            return Ok(None);
        }
        let (Value::F32 { lanes, .. }, Value::U32(masks)) =
            (self.eval(fr, inner, depth)?, self.eval(fr, right, depth)?)
        else {
            return Ok(None);
        };
        let mut out = Vec::with_capacity(lanes.len());
        for (k, x) in lanes.iter().enumerate() {
            let (m, m_hi) = masks[if masks.len() == 1 { 0 } else { k }];
            let x = flushed(*x, self.flush);
            let (alo, ahi) = if !x.may_be_negative() {
                (x.lo, x.hi)
            } else if x.hi < 0.0 || x.hi.to_bits() == 0x8000_0000 {
                (-x.hi, -x.lo)
            } else {
                (0.0, x.hi.max(-x.lo))
            };
            let sign_may = x.may_be_negative();
            let sign_must = x.hi < 0.0 || x.hi.to_bits() == 0x8000_0000;
            out.push(match (m, m == m_hi) {
                (0x7fff_ffff, true) => (alo.to_bits(), ahi.to_bits()),
                (0x7f80_0000, true) => (alo.to_bits() & m, ahi.to_bits() & m),
                (0x8000_0000, true) => match (sign_may, sign_must) {
                    (_, true) => (m, m),
                    (false, _) => (0, 0),
                    _ => (0, m),
                },
                _ => return Ok(None),
            });
        }
        Ok(Some(Value::U32(out)))
    }

    fn eval(&self, fr: &mut Frame<'_>, e: Handle<Expression>, depth: usize) -> R<Value> {
        if let Some(v) = &fr.cache[e.index()] {
            return Ok(v.clone());
        }
        let v = self.eval_uncached(fr, e, depth)?;
        // Loads and call results are only valid where emitted; everything else is pure.
        if !matches!(fr.exprs[e], Expression::Load { .. }) {
            fr.cache[e.index()] = Some(v.clone());
        }
        Ok(v)
    }

    fn global(&self, e: Handle<Expression>) -> R<Value> {
        let mut fr = Frame {
            exprs: &self.module.global_expressions,
            args: Vec::new(),
            cache: vec![None; self.module.global_expressions.len()],
            locals: Vec::new(),
        };
        self.eval(&mut fr, e, 0)
    }

    fn zero(&self, ty: Handle<naga::Type>) -> R<Value> {
        Ok(match self.module.types[ty].inner {
            TypeInner::Scalar(s) => zero_lanes(s.kind, 1)?,
            TypeInner::Vector { size, scalar } => zero_lanes(scalar.kind, size as usize)?,
            TypeInner::Array {
                base,
                size: naga::ArraySize::Constant(n),
                ..
            } => Value::Composite(vec![self.zero(base)?; n.get() as usize]),
            _ => return Err(not_covered("a zero value of this type")),
        })
    }

    fn eval_uncached(&self, fr: &mut Frame<'_>, e: Handle<Expression>, depth: usize) -> R<Value> {
        let flush = self.flush;
        Ok(match &fr.exprs[e] {
            Expression::Literal(l) => match *l {
                Literal::F32(x) => Value::f32s(&[x]),
                Literal::U32(x) => Value::u32s(&[x]),
                Literal::I32(x) => Value::I32(vec![(x, x)]),
                Literal::Bool(b) => Value::Bool(vec![Tri::of(b)]),
                _ => {
                    return Err(not_covered(
                        "a literal of a type other than f32/u32/i32/bool",
                    ));
                }
            },
            Expression::Constant(c) => self.global(self.module.constants[*c].init)?,
            Expression::ZeroValue(ty) => self.zero(*ty)?,
            Expression::Compose { ty, components } => {
                let parts = components
                    .iter()
                    .map(|&c| self.eval(fr, c, depth))
                    .collect::<R<Vec<_>>>()?;
                match self.module.types[*ty].inner {
                    TypeInner::Vector { .. } | TypeInner::Scalar(_) => Value::concat(&parts)?,
                    // A matrix is its columns.
                    TypeInner::Array { .. }
                    | TypeInner::Struct { .. }
                    | TypeInner::Matrix { .. } => Value::Composite(parts),
                    _ => return Err(not_covered("composing a value of this type")),
                }
            }
            Expression::Splat { size, value } => {
                let v = self.eval(fr, *value, depth)?;
                Value::concat(&vec![v; *size as usize])?
            }
            Expression::Swizzle {
                size,
                vector,
                pattern,
            } => {
                let v = self.eval(fr, *vector, depth)?;
                let parts: Vec<Value> = pattern[..*size as usize]
                    .iter()
                    .map(|&c| v.lane(c as usize))
                    .collect();
                Value::concat(&parts)?
            }
            Expression::AccessIndex { base, index } => {
                let b = self.eval(fr, *base, depth)?;
                access(b, *index as usize)?
            }
            Expression::Access { base, index } => {
                let b = self.eval(fr, *base, depth)?;
                let (lo, hi) = match self.eval(fr, *index, depth)? {
                    Value::U32(l) => (l[0].0 as usize, l[0].1 as usize),
                    Value::I32(l) if l[0].0 >= 0 => (l[0].0 as usize, l[0].1 as usize),
                    _ => return Err(not_covered("an index that may be negative")),
                };
                let n = match &b {
                    Value::Ptr(false, i, path) => self.global_len(*i, path)?,
                    Value::Ptr(..) => usize::MAX,
                    v => v.lanes(),
                };
                // WGSL clamps out-of-range indices (robust access): clamp like it.
                let (lo, hi) = (lo.min(n.saturating_sub(1)), hi.min(n.saturating_sub(1)));
                if lo == hi {
                    access(b, lo)?
                } else if let Value::Ptr(false, i, path) = &b {
                    // A global read at a range of indices: the hull of those elements (the
                    // Load that follows passes it on).
                    let mut v = self.global_at(*i, &[path.as_slice(), &[lo]].concat())?;
                    for k in lo + 1..=hi {
                        v = v.join(&self.global_at(*i, &[path.as_slice(), &[k]].concat())?)?;
                    }
                    v
                } else if let Value::Ptr(..) = b {
                    return Err(not_covered("a local indexed by a range"));
                } else {
                    let mut v = b.lane(lo);
                    for k in lo + 1..=hi {
                        v = v.join(&b.lane(k))?;
                    }
                    v
                }
            }
            Expression::FunctionArgument(i) => fr.args[*i as usize].clone(),
            Expression::LocalVariable(l) => Value::Ptr(true, l.index(), Vec::new()),
            Expression::GlobalVariable(g) => Value::Ptr(false, g.index(), Vec::new()),
            Expression::Load { pointer } => match self.eval(fr, *pointer, depth)? {
                Value::Ptr(true, i, path) => {
                    let v = fr.locals[i]
                        .clone()
                        .ok_or_else(|| not_covered("a load of an unset local"))?;
                    path.iter().try_fold(v, |v, &k| access(v, k))?
                }
                Value::Ptr(false, i, path) => self.global_at(i, &path)?,
                // A global element at a range of indices, already read (below).
                v => v,
            },
            Expression::Unary { op, expr } => {
                let v = self.eval(fr, *expr, depth)?;
                match (op, v) {
                    (UnaryOperator::Negate, Value::F32 { lanes, sum }) => Value::F32 {
                        lanes: lanes.into_iter().map(neg).collect(),
                        sum,
                    },
                    (UnaryOperator::LogicalNot, Value::Bool(l)) => {
                        Value::Bool(l.into_iter().map(Tri::not).collect())
                    }
                    (UnaryOperator::BitwiseNot, Value::U32(l)) => {
                        Value::U32(l.into_iter().map(|(lo, hi)| (!hi, !lo)).collect())
                    }
                    _ => return Err(not_covered("this unary operation")),
                }
            }
            Expression::Binary { op, left, right } => {
                if let Some(v) = self.float_field(fr, *op, *left, *right, depth)? {
                    return Ok(v);
                }
                let a = self.eval(fr, *left, depth)?;
                let b = self.eval(fr, *right, depth)?;
                binary(*op, a, b, flush)?
            }
            Expression::Select {
                condition,
                accept,
                reject,
            } => {
                let c = self.eval(fr, *condition, depth)?.tri()?;
                let a = self.eval(fr, *accept, depth)?;
                let r = self.eval(fr, *reject, depth)?;
                let n = a.lanes();
                let parts = (0..n)
                    .map(|k| match c[if c.len() == 1 { 0 } else { k }] {
                        Tri::True => Ok(a.lane(k)),
                        Tri::False => Ok(r.lane(k)),
                        Tri::Either => a.lane(k).join(&r.lane(k)),
                    })
                    .collect::<R<Vec<_>>>()?;
                match Value::concat(&parts)? {
                    Value::F32 { lanes, .. } => Value::F32 { lanes, sum: 0 },
                    v => v,
                }
            }
            Expression::Relational { fun, argument } => {
                let l = self.eval(fr, *argument, depth)?.tri()?;
                let t = match fun {
                    RelationalFunction::All => l.into_iter().fold(Tri::True, Tri::and),
                    RelationalFunction::Any => l.into_iter().fold(Tri::False, Tri::or),
                    _ => return Err(not_covered("isNan/isInf")),
                };
                Value::Bool(vec![t])
            }
            Expression::Math {
                fun,
                arg,
                arg1,
                arg2,
                ..
            } => {
                let a = self.eval(fr, *arg, depth)?;
                let b = match arg1 {
                    Some(x) => Some(self.eval(fr, *x, depth)?),
                    None => None,
                };
                let c = match arg2 {
                    Some(x) => Some(self.eval(fr, *x, depth)?),
                    None => None,
                };
                math(*fun, a, b, c, flush)?
            }
            Expression::As {
                expr,
                kind,
                convert,
            } => {
                let v = self.eval(fr, *expr, depth)?;
                cast(v, *kind, convert.is_some(), flush)?
            }
            Expression::CallResult(_) => {
                return Err(not_covered("a call result read before its call"));
            }
            other => {
                return Err(IntervalError::NotCovered(format!(
                    "expression {:?}",
                    std::mem::discriminant(other)
                )));
            }
        })
    }
}

fn zero_lanes(kind: ScalarKind, n: usize) -> R<Value> {
    Ok(match kind {
        ScalarKind::Float => Value::f32s(&vec![0.0; n]),
        ScalarKind::Uint => Value::u32s(&vec![0; n]),
        ScalarKind::Sint => Value::I32(vec![(0, 0); n]),
        ScalarKind::Bool => Value::Bool(vec![Tri::False; n]),
        _ => return Err(not_covered("a zero of an abstract type")),
    })
}

fn access(v: Value, k: usize) -> R<Value> {
    Ok(match v {
        Value::Ptr(local, i, mut path) => {
            path.push(k);
            Value::Ptr(local, i, path)
        }
        v if k < v.lanes() => v.lane(k),
        _ => return Err(not_covered("an index out of range")),
    })
}

fn store(slot: &mut Value, path: &[usize], v: Value) -> R<()> {
    match path.split_first() {
        None => {
            *slot = v;
            Ok(())
        }
        Some((&k, rest)) => match slot {
            Value::Composite(m) if k < m.len() => store(&mut m[k], rest, v),
            Value::F32 { lanes, .. } if rest.is_empty() => {
                lanes[k] = v.f32_lanes().ok_or_else(|| not_covered("a mixed store"))?[0];
                Ok(())
            }
            _ => Err(not_covered("a store into a vector lane of this kind")),
        },
    }
}

fn lanewise<T: Copy, U>(a: &[T], b: &[T], f: impl Fn(T, T) -> R<U>) -> R<Vec<U>> {
    let n = a.len().max(b.len());
    (0..n)
        .map(|k| {
            f(
                a[if a.len() == 1 { 0 } else { k }],
                b[if b.len() == 1 { 0 } else { k }],
            )
        })
        .collect()
}

fn cmp_tri<T: PartialOrd + Copy>(op: BinaryOperator, a: (T, T), b: (T, T)) -> R<Tri> {
    // (holds for every pair of values, holds for none)
    let (all, none) = match op {
        BinaryOperator::Less => (a.1 < b.0, a.0 >= b.1),
        BinaryOperator::LessEqual => (a.1 <= b.0, a.0 > b.1),
        BinaryOperator::Greater => (a.0 > b.1, a.1 <= b.0),
        BinaryOperator::GreaterEqual => (a.0 >= b.1, a.1 < b.0),
        BinaryOperator::Equal => (
            a.0 == a.1 && b.0 == b.1 && a.0 == b.0,
            a.1 < b.0 || b.1 < a.0,
        ),
        BinaryOperator::NotEqual => (
            a.1 < b.0 || b.1 < a.0,
            a.0 == a.1 && b.0 == b.1 && a.0 == b.0,
        ),
        _ => return Err(not_covered("this comparison")),
    };
    Ok(if all {
        Tri::True
    } else if none {
        Tri::False
    } else {
        Tri::Either
    })
}

fn binary(op: BinaryOperator, a: Value, b: Value, flush: bool) -> R<Value> {
    use BinaryOperator as B;
    Ok(match (a, b) {
        (Value::F32 { lanes: x, sum: sx }, Value::F32 { lanes: y, sum: sy }) => {
            let fl = |v: Iv| flushed(v, flush);
            match op {
                B::Add | B::Subtract => {
                    let bit = |m: u8, len: usize, k: usize| (m >> if len == 1 { 0 } else { k }) & 1;
                    let n = x.len().max(y.len());
                    if (0..n).any(|k| bit(sx, x.len(), k) | bit(sy, y.len(), k) != 0) {
                        return Err(not_covered(
                            "an f32 sum of three or more terms (a compiler may reassociate it)",
                        ));
                    }
                    let lanes = lanewise(&x, &y, |p, q| {
                        let q = if op == B::Subtract { neg(q) } else { q };
                        add(fl(p), fl(q)).map(fl)
                    })?;
                    Value::F32 {
                        lanes,
                        sum: ((1u16 << n) - 1) as u8,
                    }
                }
                B::Multiply => Value::F32 {
                    lanes: lanewise(&x, &y, |p, q| mul_div(1, p, q, flush))?,
                    sum: 0,
                },
                B::Divide => Value::F32 {
                    lanes: lanewise(&x, &y, |p, q| mul_div(2, p, q, flush))?,
                    sum: 0,
                },
                _ => Value::Bool(lanewise(&x, &y, |p, q| {
                    let (p, q) = (fl(p), fl(q));
                    // -0 == +0 in comparisons: compare as f64 values.
                    cmp_tri(
                        op,
                        (f64::from(p.lo), f64::from(p.hi)),
                        (f64::from(q.lo), f64::from(q.hi)),
                    )
                })?),
            }
        }
        // Matrix × vector: each row a sum of products, in every order (the spec's inherited
        // accuracy lets an implementation sum them any way, fused or not).
        (Value::Composite(cols), Value::F32 { lanes: v, .. }) if op == B::Multiply => {
            if cols.len() != v.len() {
                return Err(not_covered("a matrix × vector of mismatched sizes"));
            }
            let rows = cols[0].lanes();
            let lanes = (0..rows)
                .map(|r| {
                    let terms = cols
                        .iter()
                        .zip(&v)
                        .map(|(c, &x)| {
                            let m = c
                                .f32_lanes()
                                .ok_or_else(|| not_covered("a non-f32 matrix"))?[r];
                            mul_div(1, m, x, flush)
                        })
                        .collect::<R<Vec<_>>>()?;
                    every_order(&terms, flush)
                })
                .collect::<R<Vec<_>>>()?;
            Value::F32 {
                lanes,
                sum: ((1u16 << rows) - 1) as u8,
            }
        }
        (Value::U32(x), Value::U32(y)) => match op {
            B::Add
            | B::Subtract
            | B::Multiply
            | B::And
            | B::InclusiveOr
            | B::ShiftLeft
            | B::ShiftRight
            | B::Divide
            | B::Modulo
            | B::ExclusiveOr => Value::U32(lanewise(&x, &y, |p, q| Ok(u32_op(op, p, q)))?),
            _ => Value::Bool(lanewise(&x, &y, |p, q| cmp_tri(op, p, q))?),
        },
        (Value::I32(x), Value::U32(y)) if matches!(op, B::ShiftLeft | B::ShiftRight) => {
            Value::I32(lanewise(
                &x,
                &y.iter()
                    .map(|&(l, h)| (l as i32, h as i32))
                    .collect::<Vec<_>>(),
                |p, q| Ok(i32_op(op, p, q)),
            )?)
        }
        (Value::I32(x), Value::I32(y)) => match op {
            B::Add | B::Subtract | B::Multiply | B::And | B::InclusiveOr | B::Divide => {
                Value::I32(lanewise(&x, &y, |p, q| Ok(i32_op(op, p, q)))?)
            }
            _ => Value::Bool(lanewise(&x, &y, |p, q| cmp_tri(op, p, q))?),
        },
        (Value::Bool(x), Value::Bool(y)) => Value::Bool(lanewise(&x, &y, |p, q| {
            Ok(match op {
                B::LogicalAnd | B::And => p.and(q),
                B::LogicalOr | B::InclusiveOr => p.or(q),
                B::Equal => match (p, q) {
                    (Tri::Either, _) | (_, Tri::Either) => Tri::Either,
                    _ => Tri::of(p == q),
                },
                B::NotEqual => match (p, q) {
                    (Tri::Either, _) | (_, Tri::Either) => Tri::Either,
                    _ => Tri::of(p != q),
                },
                _ => return Err(not_covered("this bool operation")),
            })
        })?),
        _ => return Err(not_covered("a binary operation on these kinds")),
    })
}

// u32 operation on intervals: exact on points (wrapping as WGSL does), monotone ends where no
// wrap can happen, the whole range otherwise.
fn u32_op(op: BinaryOperator, (al, ah): (u32, u32), (bl, bh): (u32, u32)) -> (u32, u32) {
    use BinaryOperator as B;
    let full = (0, u32::MAX);
    if al == ah && bl == bh {
        let r = match op {
            B::Add => al.wrapping_add(bl),
            B::Subtract => al.wrapping_sub(bl),
            B::Multiply => al.wrapping_mul(bl),
            B::And => al & bl,
            B::InclusiveOr => al | bl,
            B::ExclusiveOr => al ^ bl,
            B::ShiftLeft => al.wrapping_shl(bl),
            B::ShiftRight => al.wrapping_shr(bl),
            // WGSL: x / 0 = x and x % 0 = 0.
            B::Divide => al.checked_div(bl).unwrap_or(al),
            B::Modulo => al.checked_rem(bl).unwrap_or(0),
            _ => return full,
        };
        return (r, r);
    }
    let wide = |l: u64, h: u64| {
        if h > u64::from(u32::MAX) {
            full
        } else {
            (l as u32, h as u32)
        }
    };
    match op {
        B::Add => wide(u64::from(al) + u64::from(bl), u64::from(ah) + u64::from(bh)),
        B::Subtract if al >= bh => (al - bh, ah - bl),
        B::Multiply => wide(u64::from(al) * u64::from(bl), u64::from(ah) * u64::from(bh)),
        B::And => (0, ah.min(bh)),
        B::Divide if bl == bh && bl > 0 => (al / bl, ah / bl),
        B::Modulo if bl == bh && bl > 0 && al / bl == ah / bl => (al % bl, ah % bl),
        B::Modulo if bl == bh && bl > 0 => (0, bl - 1),
        B::ShiftRight if bl == bh && bl < 32 => (al >> bl, ah >> bl),
        B::ShiftLeft if bl == bh && bl < 32 => wide(u64::from(al) << bl, u64::from(ah) << bl),
        B::InclusiveOr | B::ExclusiveOr => {
            let m = ah.max(bh);
            (
                0,
                if m == 0 {
                    0
                } else {
                    u32::MAX >> m.leading_zeros()
                },
            )
        }
        _ => full,
    }
}

fn i32_op(op: BinaryOperator, (al, ah): (i32, i32), (bl, bh): (i32, i32)) -> (i32, i32) {
    use BinaryOperator as B;
    let full = (i32::MIN, i32::MAX);
    if al == ah && bl == bh {
        let r = match op {
            B::Add => al.wrapping_add(bl),
            B::Subtract => al.wrapping_sub(bl),
            B::Multiply => al.wrapping_mul(bl),
            B::And => al & bl,
            B::InclusiveOr => al | bl,
            B::ShiftLeft => al.wrapping_shl(bl as u32),
            B::ShiftRight => al.wrapping_shr(bl as u32),
            B::Divide => al.checked_div(bl).unwrap_or(al),
            _ => return full,
        };
        return (r, r);
    }
    let fit = |l: i64, h: i64| {
        if l < i64::from(i32::MIN) || h > i64::from(i32::MAX) {
            full
        } else {
            (l as i32, h as i32)
        }
    };
    match op {
        B::Add => fit(i64::from(al) + i64::from(bl), i64::from(ah) + i64::from(bh)),
        B::Subtract => fit(i64::from(al) - i64::from(bh), i64::from(ah) - i64::from(bl)),
        B::ShiftRight if bl == bh && (0..32).contains(&bl) => (al >> bl, ah >> bl),
        _ => full,
    }
}

fn math(fun: MathFunction, a: Value, b: Option<Value>, c: Option<Value>, flush: bool) -> R<Value> {
    use MathFunction as M;
    let fl = |v: Iv| flushed(v, flush);
    let f1 = |g: fn(f32) -> f32| -> R<Value> {
        let lanes = a
            .f32_lanes()
            .ok_or_else(|| not_covered("an integer rounding function"))?
            .iter()
            .map(|&v| {
                let v = fl(v);
                fl(Iv::new(g(v.lo), g(v.hi)))
            })
            .collect();
        Ok(Value::F32 { lanes, sum: 0 })
    };
    Ok(match fun {
        M::Floor => f1(f32::floor)?,
        M::Ceil => f1(f32::ceil)?,
        M::Trunc => f1(f32::trunc)?,
        M::Round => f1(f32::round_ties_even)?,
        M::Abs => match a {
            Value::F32 { lanes, .. } => Value::F32 {
                lanes: lanes
                    .into_iter()
                    .map(|v| {
                        let v = fl(v);
                        if !v.may_be_negative() {
                            v
                        } else if v.hi <= 0.0 {
                            neg(v)
                        } else {
                            Iv::new(0.0, v.hi.max(-v.lo))
                        }
                    })
                    .collect(),
                sum: 0,
            },
            Value::U32(l) => Value::U32(l),
            _ => return Err(not_covered("abs of i32")),
        },
        M::Min | M::Max => {
            let b = b.ok_or_else(|| not_covered("min/max arity"))?;
            minmax(fun == M::Min, a, b, flush)?
        }
        M::Clamp => {
            let (b, c) = (
                b.ok_or_else(|| not_covered("clamp arity"))?,
                c.ok_or_else(|| not_covered("clamp arity"))?,
            );
            minmax(true, minmax(false, a, b, flush)?, c, flush)?
        }
        M::Saturate => {
            let n = a.lanes();
            let z = Value::f32s(&vec![0.0; n]);
            let o = Value::f32s(&vec![1.0; n]);
            minmax(true, minmax(false, a, z, flush)?, o, flush)?
        }
        M::Fract => {
            // Inherited from x − floor(x).
            let lanes = a
                .f32_lanes()
                .ok_or_else(|| not_covered("fract of an integer"))?
                .iter()
                .map(|&v| {
                    let v = fl(v);
                    let (fa, fb) = (v.lo.floor(), v.hi.floor());
                    if fa == fb {
                        add(v, Iv::point(-fa)).map(fl)
                    } else {
                        Ok(Iv::new(0.0, 1.0))
                    }
                })
                .collect::<R<_>>()?;
            Value::F32 { lanes, sum: 0 }
        }
        M::Log2 | M::Exp2 => {
            let lanes = a
                .f32_lanes()
                .ok_or_else(|| not_covered("log2/exp2 of an integer"))?
                .iter()
                .map(|&v| {
                    if fun == M::Log2 {
                        log2(fl(v))
                    } else {
                        exp2(fl(v))
                    }
                    .map(fl)
                })
                .collect::<R<_>>()?;
            Value::F32 { lanes, sum: 0 }
        }
        M::Dot => {
            // Inherited: the lanes' products summed in any order (fused or not, as for matrix ×
            // vector), so the hull over every order.
            let b = b.ok_or_else(|| not_covered("dot arity"))?;
            let (x, y) = (
                a.f32_lanes()
                    .ok_or_else(|| not_covered("dot of integers"))?,
                b.f32_lanes()
                    .ok_or_else(|| not_covered("dot of integers"))?,
            );
            let terms = x
                .iter()
                .zip(y)
                .map(|(&p, &q)| mul_div(1, p, q, flush))
                .collect::<R<Vec<_>>>()?;
            Value::F32 {
                lanes: vec![every_order(&terms, flush)?],
                sum: 1,
            }
        }
        other => return Err(IntervalError::NotCovered(format!("builtin {other:?}"))),
    })
}

/// The f32 values in `[lo_real, hi_real]`, widened by `2^-50` relative for the f64 evaluation
/// of the ends (f64 `/`, `log2`, `exp2` and the allowance sums are within an f64 ULP or two).
fn inward(lo_real: f64, hi_real: f64, what: &str) -> R<Iv> {
    let lo_real = lo_real - lo_real.abs() * 2f64.powi(-50);
    let hi_real = hi_real + hi_real.abs() * 2f64.powi(-50);
    let mut lo = lo_real as f32;
    if f64::from(lo) < lo_real {
        lo = lo.next_up();
    }
    let mut hi = hi_real as f32;
    if f64::from(hi) > hi_real {
        hi = hi.next_down();
    }
    checked(Iv::new(lo, hi), what)
}

/// `log2`: 3 ULP outside `[0.5, 2]`, absolute `2^-21` inside (WGSL); positive arguments only.
fn log2(v: Iv) -> R<Iv> {
    if v.lo <= 0.0 {
        return Err(IntervalError::Indeterminate(format!(
            "log2 of [{:e}, {:e}] (positive arguments only)",
            v.lo, v.hi
        )));
    }
    let (a, b) = (f64::from(v.lo).log2(), f64::from(v.hi).log2());
    // The allowance at its largest over the interval: 3 ULP of the largest |result| outside
    // [0.5, 2], 2^-21 where the interval meets [0.5, 2].
    let mut allow = 3.0 * ulp_spec(a.abs().max(b.abs()));
    if v.lo <= 2.0 && v.hi >= 0.5 {
        allow = allow.max(2f64.powi(-21));
    }
    inward(a - allow, b + allow, "log2")
}

/// `exp2(x)`: within `3 + 2|x|` ULP (WGSL). The ULP is the exact value's: for a nonzero `x`
/// below 2^-53, f64's `exp2` rounds to 1 while the value lies above 1 (ULP 2^-23, not the
/// 2^-24 below it) for `x > 0` — the one place an f32 argument's `exp2` rounds onto a power of
/// two in f64 (elsewhere it differs from one by at least 2^-24 relative).
fn exp2(v: Iv) -> R<Iv> {
    let ulp = |x: f32, e: f64| {
        if e == 1.0 && x > 0.0 {
            f64::powi(2.0, -23)
        } else {
            ulp_spec(e)
        }
    };
    let (a, b) = (f64::from(v.lo).exp2(), f64::from(v.hi).exp2());
    let ulps = 3.0 + 2.0 * f64::from(v.lo.abs().max(v.hi.abs()));
    // The lower end with the largest ULP over the interval (the one at its top): an x just
    // above an integer inside it has a value just above a power of two, whose ULP is twice
    // the one below, so the allowed results there reach lower than at x = v.lo.
    let widest = ulp(v.lo, a).max(ulp(v.hi, b));
    inward(a - ulps * widest, b + ulps * ulp(v.hi, b), "exp2")
}

/// `min` or `max` of two integer intervals: monotone in both, so end by end.
fn ends<T: Ord + Copy>(min: bool, p: (T, T), q: (T, T)) -> (T, T) {
    if min {
        (p.0.min(q.0), p.1.min(q.1))
    } else {
        (p.0.max(q.0), p.1.max(q.1))
    }
}

fn minmax(min: bool, a: Value, b: Value, flush: bool) -> R<Value> {
    Ok(match (a, b) {
        (Value::F32 { lanes: x, .. }, Value::F32 { lanes: y, .. }) => Value::F32 {
            lanes: lanewise(&x, &y, |p, q| {
                let (p, q) = (flushed(p, flush), flushed(q, flush));
                let pick = |u: f32, v: f32| if min { u.min(v) } else { u.max(v) };
                // An equal pair of zeros may come back with either sign.
                Ok(Iv::new(
                    lo_min(
                        pick(p.lo, q.lo),
                        if p.lo == q.lo {
                            lo_min(p.lo, q.lo)
                        } else {
                            pick(p.lo, q.lo)
                        },
                    ),
                    hi_max(
                        pick(p.hi, q.hi),
                        if p.hi == q.hi {
                            hi_max(p.hi, q.hi)
                        } else {
                            pick(p.hi, q.hi)
                        },
                    ),
                ))
            })?,
            sum: 0,
        },
        (Value::U32(x), Value::U32(y)) => Value::U32(lanewise(&x, &y, |p, q| Ok(ends(min, p, q)))?),
        (Value::I32(x), Value::I32(y)) => Value::I32(lanewise(&x, &y, |p, q| Ok(ends(min, p, q)))?),
        _ => return Err(not_covered("min/max of these kinds")),
    })
}

fn cast(v: Value, kind: ScalarKind, convert: bool, flush: bool) -> R<Value> {
    let to_f32 = |l: i64, h: i64| -> R<Iv> {
        Ok(Iv::new(
            bracket(l as f64, 0.0, "f32()")?.0,
            bracket(h as f64, 0.0, "f32()")?.1,
        ))
    };
    Ok(match (v, kind, convert) {
        (v @ Value::F32 { .. }, ScalarKind::Float, true) => v,
        (Value::U32(l), ScalarKind::Float, true) => Value::F32 {
            lanes: l
                .iter()
                .map(|&(a, b)| to_f32(i64::from(a), i64::from(b)))
                .collect::<R<_>>()?,
            sum: 0,
        },
        (Value::I32(l), ScalarKind::Float, true) => Value::F32 {
            lanes: l
                .iter()
                .map(|&(a, b)| to_f32(i64::from(a), i64::from(b)))
                .collect::<R<_>>()?,
            sum: 0,
        },
        (Value::F32 { lanes, .. }, ScalarKind::Uint, true) => Value::U32(
            lanes
                .iter()
                .map(|v| {
                    let v = flushed(*v, flush);
                    let c = |x: f32| x.trunc().clamp(0.0, 4_294_967_040.0) as u32;
                    (c(v.lo), c(v.hi))
                })
                .collect(),
        ),
        (Value::F32 { lanes, .. }, ScalarKind::Sint, true) => Value::I32(
            lanes
                .iter()
                .map(|v| {
                    let v = flushed(*v, flush);
                    let c = |x: f32| x.trunc().clamp(-2_147_483_648.0, 2_147_483_520.0) as i32;
                    (c(v.lo), c(v.hi))
                })
                .collect(),
        ),
        (Value::U32(l), ScalarKind::Sint, _) => Value::I32(
            l.iter()
                .map(|&(a, b)| {
                    if a == b || b <= i32::MAX as u32 || a > i32::MAX as u32 {
                        (a as i32, b as i32)
                    } else {
                        (i32::MIN, i32::MAX)
                    }
                })
                .collect(),
        ),
        (Value::I32(l), ScalarKind::Uint, _) => Value::U32(
            l.iter()
                .map(|&(a, b)| {
                    if a == b || a >= 0 || b < 0 {
                        (a as u32, b as u32)
                    } else {
                        (0, u32::MAX)
                    }
                })
                .collect(),
        ),
        (Value::U32(l), ScalarKind::Uint, _) => Value::U32(l),
        (Value::I32(l), ScalarKind::Sint, _) => Value::I32(l),
        // Bit casts: exact on single values; monotone over one sign's range otherwise.
        (Value::F32 { lanes, .. }, ScalarKind::Uint, false) => Value::U32(
            lanes
                .iter()
                .map(|v| {
                    if v.lo.to_bits() == v.hi.to_bits() {
                        (v.lo.to_bits(), v.lo.to_bits())
                    } else if !v.may_be_negative() {
                        (v.lo.to_bits(), v.hi.to_bits())
                    } else if v.hi < 0.0 {
                        (v.hi.to_bits(), v.lo.to_bits())
                    } else {
                        (0, v.lo.to_bits())
                    }
                })
                .collect(),
        ),
        (Value::U32(l), ScalarKind::Float, false) => Value::F32 {
            lanes: l
                .iter()
                .map(|&(a, b)| {
                    let fin = |x: u32| x & 0x7fff_ffff < 0x7f80_0000;
                    if a == b && fin(a) {
                        Ok(Iv::point(f32::from_bits(a)))
                    } else if b < 0x7f80_0000 {
                        Ok(Iv::new(f32::from_bits(a), f32::from_bits(b)))
                    } else if a >= 0x8000_0000 && b < 0xff80_0000 {
                        Ok(Iv::new(f32::from_bits(b), f32::from_bits(a)))
                    } else {
                        Err(IntervalError::Indeterminate(
                            "a bit cast that may give NaN or infinity".into(),
                        ))
                    }
                })
                .collect::<R<_>>()?,
            sum: 0,
        },
        _ => return Err(not_covered("this conversion")),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SRC: &str = "
        fn add(a: f32, b: f32) -> f32 { return a + b; }
        fn quo(a: f32, b: f32) -> f32 { return a / b; }
        fn fma_like(a: f32, b: f32, c: f32) -> f32 { return a * b + c; }
        fn three(a: f32, b: f32, c: f32) -> f32 { return (a + b) + c; }
        fn inner(a: f32, b: f32) -> f32 { return a - b; }
        fn through_call(a: f32, b: f32, c: f32) -> f32 { return inner(a, b) + c; }
        fn lanes(a: f32, b: f32) -> f32 { let v = vec2<f32>(a + b, a); return v.y + b; }
        fn branchy(a: f32, b: f32) -> f32 {
            let s = a + b;
            if (s < 1.0) { return s * 4.0; }
            return s;
        }
        fn conv(x: u32) -> f32 { return f32(x); }
        fn scaled(a: f32, b: f32, c: f32) -> f32 { let p = a * b; return p / c; }
        fn long_chain(a: f32, b: f32, c: f32) -> f32 { return ((a * b) / c) * a; }
        fn sane(x: f32) -> f32 {
            let bits = bitcast<u32>(x);
            return select(x, 1e30, (bits & 0x7fffffffu) >= 0x7f800000u);
        }
        fn spread(a: f32, b: f32) -> f32 { return sane((a / b) * b - a); }
        fn dotted(a: f32, b: f32, c: f32) -> f32 { return dot(vec3<f32>(a, b, c), vec3<f32>(1.0)); }
        fn scaled_chain(a: f32, b: f32, c: f32) -> f32 { return ((a * 4.0) * b) * c; }
        fn row(a: f32, b: f32, c: f32) -> f32 {
            return (mat3x3<f32>(vec3<f32>(1.0), vec3<f32>(1.0), vec3<f32>(1.0)) * vec3<f32>(a, b, c)).x;
        }
    ";

    fn f(name: &str, args: &[f32], flush: bool) -> R<Iv> {
        let e = Enclosure::new(SRC, flush)?;
        let v: Vec<Value> = args.iter().map(|&x| Value::f32s(&[x])).collect();
        Ok(e.of(name, &v)?.f32_lanes().unwrap()[0])
    }

    #[test]
    fn an_inexact_sum_may_be_either_neighbour_and_an_exact_one_only_itself() {
        let (a, b) = (1.0f32, 2f32.powi(-30));
        let iv = f("add", &[a, b], false).unwrap();
        assert_eq!((iv.lo, iv.hi), (1.0, 1.0f32.next_up()));
        let iv = f("add", &[1.5, 0.25], false).unwrap();
        assert_eq!((iv.lo, iv.hi), (1.75, 1.75));
    }

    #[test]
    fn a_quotient_spans_every_f32_within_two_and_a_half_ulp() {
        let iv = f("quo", &[1.0, 3.0], false).unwrap();
        let q = 1.0f64 / 3.0;
        let u = ulp_spec(q);
        // Inside, and no f32 just outside the allowance is admitted.
        assert!(f64::from(iv.lo) >= q - 2.5 * u && f64::from(iv.hi) <= q + 2.5 * u);
        assert!(f64::from(iv.lo.next_down()) < q - 2.5 * u);
        assert!(f64::from(iv.hi.next_up()) > q + 2.5 * u);
        assert_eq!(
            iv.hi.to_bits() - iv.lo.to_bits(),
            4,
            "five f32 values, {iv:?}"
        );
    }

    #[test]
    fn the_spec_ulp_at_a_power_of_two_is_the_spacing_below() {
        assert_eq!(ulp_spec(1.0), 2f64.powi(-24));
        assert_eq!(ulp_spec(1.5), 2f64.powi(-23));
        assert_eq!(ulp_spec(0.75), 2f64.powi(-24));
    }

    #[test]
    fn a_product_then_a_sum_holds_the_fused_result_too() {
        let (a, b, c) = (1.0f32 + 2f32.powi(-12), 1.0f32 - 2f32.powi(-13), -1.0f32);
        let iv = f("fma_like", &[a, b, c], false).unwrap();
        let fused = a.mul_add(b, c);
        let unfused = a * b + c;
        for r in [fused, unfused] {
            assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
        }
        assert_ne!(fused, unfused, "the case must tell fusion apart");
    }

    #[test]
    fn a_sum_a_compiler_could_reassociate_is_refused() {
        for name in ["three", "through_call"] {
            assert!(
                matches!(
                    f(name, &[1.0, 2.0, 3.0], false),
                    Err(IntervalError::NotCovered(_))
                ),
                "{name}"
            );
        }
        // A lane that is not a sum, taken from a vector that holds one, is fine.
        assert!(f("lanes", &[1.0, 2.0], false).is_ok());
    }

    #[test]
    fn a_quotient_of_a_product_holds_its_reassociations() {
        let (a, b, c) = (3.0f32, 1.0f32 / 3.0, 7.0f32);
        let iv = f("scaled", &[a, b, c], false).unwrap();
        // (a/c)·b and a·(b/c) on a correctly rounded adapter: inside as well as (a·b)/c.
        for r in [(a * b) / c, (a / c) * b, a * (b / c)] {
            assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
        }
        assert!(matches!(
            f("long_chain", &[a, b, c], false),
            Err(IntervalError::NotCovered(_))
        ));
    }

    #[test]
    fn a_matrix_row_is_summed_in_every_order() {
        // 1 + 2^-24 − 1: (a + b) + c gives 0, a + (b + c) and (a + c) + b give 2^-24.
        let (a, b, c) = (1.0f32, 2f32.powi(-24), -1.0f32);
        let iv = f("row", &[a, b, c], false).unwrap();
        for r in [(a + b) + c, a + (b + c), (a + c) + b] {
            assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
        }
        assert!(iv.lo <= 0.0 && iv.hi >= 2f32.powi(-24));
    }

    #[test]
    fn a_dot_product_is_summed_in_every_order() {
        // As the matrix row above: dot's inherited accuracy lets any order stand.
        let (a, b, c) = (1.0f32, 2f32.powi(-24), -1.0f32);
        let iv = f("dotted", &[a, b, c], false).unwrap();
        for r in [(a + b) + c, a + (b + c), (a + c) + b] {
            assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
        }
    }

    #[test]
    fn a_power_of_two_scaling_starts_no_chain() {
        // a·4 is exact, so ((a·4)·b)·c has the roundings of (a·b)·c, whose reorderings are
        // hulled in; without the exemption the chain of three would be refused.
        let (a, b, c) = (1.0f32 / 3.0, 3.0f32.sqrt(), 7.0f32.sqrt());
        let iv = f("scaled_chain", &[a, b, c], false).unwrap();
        for r in [
            ((a * 4.0) * b) * c,
            (a * 4.0) * (b * c),
            ((a * 4.0) * c) * b,
        ] {
            assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
        }
    }

    #[test]
    fn a_magnitude_read_from_the_bits_of_an_enclosure_that_spans_zero_stays_finite() {
        // (1/3)·3 − 1 lies on both sides of 0, so its bits span the sign; its magnitude cannot
        // reach infinity, so the select must keep the value and never the 1e30.
        let iv = f("spread", &[1.0, 3.0], false).unwrap();
        assert!(iv.lo < 0.0 && iv.hi > 0.0 && iv.hi < 1e-6, "{iv:?}");
    }

    #[test]
    fn division_outside_the_specified_divisors_is_indeterminate() {
        assert!(matches!(
            f("quo", &[1.0, 1e-39], false),
            Err(IntervalError::Indeterminate(_))
        ));
    }

    #[test]
    fn a_condition_undecided_on_the_enclosure_joins_both_branches() {
        // 1 − 2^-30 + 2^-31... a + b lies on both sides of 1: either branch may run.
        let (a, b) = (1.0f32.next_down(), 2f32.powi(-25));
        let iv = f("branchy", &[a, b], false).unwrap();
        assert!(iv.lo < 1.0 && iv.hi > 3.9, "{iv:?}");
        // Decided: only one branch.
        let iv = f("branchy", &[0.25, 0.25], false).unwrap();
        assert_eq!((iv.lo, iv.hi), (2.0, 2.0));
    }

    #[test]
    fn flushing_admits_zero_for_a_subnormal_result() {
        let tiny = f32::MIN_POSITIVE / 4.0;
        assert_eq!(f("add", &[tiny, tiny], false).unwrap().lo, 2.0 * tiny);
        assert_eq!(f("add", &[tiny, tiny], true).unwrap().lo, 0.0);
    }

    #[test]
    fn an_integer_above_two_to_the_24_converts_to_either_neighbour() {
        let e = Enclosure::new(SRC, false).unwrap();
        let v = e.of("conv", &[Value::u32s(&[(1 << 24) + 1])]).unwrap();
        let iv = v.f32_lanes().unwrap()[0];
        assert_eq!((iv.lo, iv.hi), (16_777_216.0, 16_777_218.0));
        let v = e.of("conv", &[Value::u32s(&[12345])]).unwrap();
        assert_eq!(v.f32_lanes().unwrap()[0], Iv::point(12345.0));
    }
}
