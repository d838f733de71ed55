//! f32 intervals under the spec's rounding rules: [`Iv`], the arithmetic on them (`+ − × /`,
//! the reassociated products and quotients, flushing) and the `log2`/`exp2` allowances.

use super::*;

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
pub(super) struct Chain {
    kind: u8,
    a: (f32, f32),
    b: (f32, f32),
    depth: u8,
    scaled: bool,
    quotient: bool,
}

pub(super) const NO_CHAIN: Chain = Chain {
    kind: 0,
    a: (0.0, 0.0),
    b: (0.0, 0.0),
    depth: 0,
    scaled: false,
    quotient: false,
};

impl Iv {
    pub(super) fn new(lo: f32, hi: f32) -> Iv {
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
    pub(super) fn hull(self, o: Iv) -> Iv {
        Iv::new(lo_min(self.lo, o.lo), hi_max(self.hi, o.hi))
    }
    pub(super) fn may_be_negative(self) -> bool {
        self.lo < 0.0 || self.lo.to_bits() == 0x8000_0000
    }
}

// Minimum and maximum that order -0 below +0.
pub(super) fn lo_min(a: f32, b: f32) -> f32 {
    if a.total_cmp(&b).is_le() { a } else { b }
}
pub(super) fn hi_max(a: f32, b: f32) -> f32 {
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
pub(super) fn bracket(hi: f64, lo: f64, what: &str) -> R<(f32, f32)> {
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

pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

pub(super) fn checked(iv: Iv, what: &str) -> R<Iv> {
    if iv.lo.is_finite() && iv.hi.is_finite() {
        Ok(iv)
    } else {
        Err(IntervalError::Indeterminate(format!(
            "{what} overflows f32"
        )))
    }
}

// An exact-zero result is +0 unless an operand could be negative (then -0 is kept possible).
pub(super) fn zero_sign(iv: Iv, negative_operand: bool) -> Iv {
    if negative_operand && iv.lo == 0.0 {
        Iv::new(-0.0, iv.hi)
    } else {
        iv
    }
}

pub(super) fn add(a: Iv, b: Iv) -> R<Iv> {
    let (sl, el) = two_sum(f64::from(a.lo), f64::from(b.lo));
    let (sh, eh) = two_sum(f64::from(a.hi), f64::from(b.hi));
    let lo = bracket(sl, el, "+")?.0;
    let hi = bracket(sh, eh, "+")?.1;
    Ok(zero_sign(
        Iv::new(lo, hi),
        a.may_be_negative() || b.may_be_negative(),
    ))
}

pub(super) fn neg(a: Iv) -> Iv {
    // −(x·y) = (−x)·y and −(x/y) = (−x)/y: the chain stays, its first operand negated.
    let mut chain = a.chain;
    chain.a = (-chain.a.1, -chain.a.0);
    Iv {
        lo: -a.hi,
        hi: -a.lo,
        chain,
    }
}

pub(super) fn mul(a: Iv, b: Iv) -> R<Iv> {
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
pub(super) const DIV_MIN: f32 = f32::MIN_POSITIVE;
pub(super) const DIV_MAX: f32 = 8.507_059e37;

pub(super) fn div(a: Iv, b: Iv) -> R<Iv> {
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
pub(super) fn every_order(terms: &[Iv], flush: bool) -> R<Iv> {
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
pub(super) fn mul_div(kind: u8, p: Iv, q: Iv, flush: bool) -> R<Iv> {
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

pub(super) fn flushed(iv: Iv, flush: bool) -> Iv {
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

/// The f32 values in `[lo_real, hi_real]`, widened by `2^-50` relative for the f64 evaluation
/// of the ends (f64 `/`, `log2`, `exp2` and the allowance sums are within an f64 ULP or two).
pub(super) fn inward(lo_real: f64, hi_real: f64, what: &str) -> R<Iv> {
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
pub(super) fn log2(v: Iv) -> R<Iv> {
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
pub(super) fn exp2(v: Iv) -> R<Iv> {
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
