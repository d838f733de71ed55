//! Enclosures of WGSL values lane by lane ([`Value`]), three-valued conditions ([`Tri`]), and
//! the lane and component access the IR walk needs.

use super::*;

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
    pub(super) fn of(b: bool) -> Tri {
        if b { Tri::True } else { Tri::False }
    }
    pub(super) fn join(self, o: Tri) -> Tri {
        if self == o { self } else { Tri::Either }
    }
    pub(super) fn not(self) -> Tri {
        match self {
            Tri::True => Tri::False,
            Tri::False => Tri::True,
            Tri::Either => Tri::Either,
        }
    }
    pub(super) fn and(self, o: Tri) -> Tri {
        match (self, o) {
            (Tri::False, _) | (_, Tri::False) => Tri::False,
            (Tri::True, Tri::True) => Tri::True,
            _ => Tri::Either,
        }
    }
    pub(super) fn or(self, o: Tri) -> Tri {
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
    pub(super) fn join(&self, o: &Value) -> R<Value> {
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
    pub(super) fn lanes(&self) -> usize {
        match self {
            Value::F32 { lanes, .. } => lanes.len(),
            Value::U32(l) => l.len(),
            Value::I32(l) => l.len(),
            Value::Bool(l) => l.len(),
            Value::Composite(m) => m.len(),
            Value::Ptr(..) => 1,
        }
    }
    pub(super) fn lane(&self, k: usize) -> Value {
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
    pub(super) fn concat(parts: &[Value]) -> R<Value> {
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
    pub(super) fn tri(&self) -> R<Vec<Tri>> {
        match self {
            Value::Bool(l) => Ok(l.clone()),
            _ => Err(not_covered("a condition that is not bool")),
        }
    }
}

pub(super) fn zero_lanes(kind: ScalarKind, n: usize) -> R<Value> {
    Ok(match kind {
        ScalarKind::Float => Value::f32s(&vec![0.0; n]),
        ScalarKind::Uint => Value::u32s(&vec![0; n]),
        ScalarKind::Sint => Value::I32(vec![(0, 0); n]),
        ScalarKind::Bool => Value::Bool(vec![Tri::False; n]),
        _ => return Err(not_covered("a zero of an abstract type")),
    })
}

pub(super) fn access(v: Value, k: usize) -> R<Value> {
    Ok(match v {
        Value::Ptr(local, i, mut path) => {
            path.push(k);
            Value::Ptr(local, i, path)
        }
        v if k < v.lanes() => v.lane(k),
        _ => return Err(not_covered("an index out of range")),
    })
}

pub(super) fn store(slot: &mut Value, path: &[usize], v: Value) -> R<()> {
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
