//! The operators and builtins on [`Value`]s: binary operators (f32, u32, i32, comparisons),
//! the math builtins, `min`/`max` and conversions, each under the table of the module docs.

use super::*;

pub(super) fn lanewise<T: Copy, U>(a: &[T], b: &[T], f: impl Fn(T, T) -> R<U>) -> R<Vec<U>> {
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

pub(super) fn cmp_tri<T: PartialOrd + Copy>(op: BinaryOperator, a: (T, T), b: (T, T)) -> R<Tri> {
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

pub(super) fn binary(op: BinaryOperator, a: Value, b: Value, flush: bool) -> R<Value> {
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
pub(super) fn u32_op(op: BinaryOperator, (al, ah): (u32, u32), (bl, bh): (u32, u32)) -> (u32, u32) {
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

pub(super) fn i32_op(op: BinaryOperator, (al, ah): (i32, i32), (bl, bh): (i32, i32)) -> (i32, i32) {
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

pub(super) fn math(
    fun: MathFunction,
    a: Value,
    b: Option<Value>,
    c: Option<Value>,
    flush: bool,
) -> R<Value> {
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

/// `min` or `max` of two integer intervals: monotone in both, so end by end.
pub(super) fn ends<T: Ord + Copy>(min: bool, p: (T, T), q: (T, T)) -> (T, T) {
    if min {
        (p.0.min(q.0), p.1.min(q.1))
    } else {
        (p.0.max(q.0), p.1.max(q.1))
    }
}

pub(super) fn minmax(min: bool, a: Value, b: Value, flush: bool) -> R<Value> {
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

pub(super) fn cast(v: Value, kind: ScalarKind, convert: bool, flush: bool) -> R<Value> {
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
