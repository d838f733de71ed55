//! [`Enclosure`]: the walk over a function's naga IR (statements, expressions, calls, globals)
//! that carries a [`Value`] for every expression.

use super::*;

/// The enclosure of one function call, and the module it runs in.
pub struct Enclosure {
    module: Module,
    flush: bool,
    /// Every global variable's initial value, evaluated once (stores to globals are refused,
    /// so they stay these).
    globals: Vec<Option<Value>>,
}

pub(super) struct Frame<'a> {
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
pub(super) struct Flow {
    continues: bool,
    returned: Option<Value>,
}

pub(super) fn join_opt(a: Option<Value>, b: Option<Value>) -> R<Option<Value>> {
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
