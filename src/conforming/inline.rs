//! Fusion across inlined helpers: a sum or difference one of whose terms is what a helper
//! function returns becomes a call of a companion of that helper, which adds the other term
//! before it returns.
//!
//! A compiler that inlines `fn g(x, y) -> f32 { return x * y; }` into `g(a, b) + c` sees
//! `a * b + c`, and may fuse it (ACO emits `v_fmaak_f32` for `x·x + 3` written through a helper,
//! `../shared/research/gpu_compilers.md`). The rewrite only sees operations inside one function,
//! so before it runs, `g(a, b) + c` is turned into `prepass_cf_inline_k__g(a, b, c)`: a copy of
//! `g` with a last parameter `c` whose every `return v` reads `return v + c` (or `v − c`,
//! `c + v`, `c − v`, keeping the written order). The rewrite then finds a product beside a sum
//! inside the companion, as inlining would show it. The companion computes what the caller did
//! (the identity policy stays bit for bit); the original call stays where it was (helpers are
//! pure), its result unused. Companions of companions come from later rounds, so a helper that
//! returns another helper's product is reached too ([`ROUNDS`] levels).
//!
//! Left as they were: a term that is itself a product or a sum (the rewrite already fuses or
//! regroups that one, and one fusion per add is what an adapter can do), helpers with pointer
//! parameters (a later read could see another value), and terms of another type than the
//! helper's result (a scalar added to a vector).

use super::rewrite::{PREFIX, map_nested, rebuild, visit};
use naga::{
    Arena, BinaryOperator, Block, Expression, Function, FunctionArgument, Handle, Module, Range,
    Span, Statement, TypeInner,
};
use std::collections::{BTreeMap, HashMap, HashSet};

/// Name prefix of the companions: the emulation's own, but planned and given call contexts as
/// the module's functions are (they stand for the module's code, inlined).
pub const INLINED: &str = "prepass_cf_inline_";

/// How many levels of helpers returning helpers' results are reached.
pub const ROUNDS: usize = 4;

/// Whether `name` is code of the module (its own functions and their inlined companions), not
/// the emulation's helpers.
pub fn is_own(name: &str) -> bool {
    !name.starts_with(PREFIX) || name.starts_with(INLINED)
}

/// One sum or difference to turn into a companion call.
struct Site {
    /// The caller (its handle, or entry point index).
    at: Owner,
    expr: Handle<Expression>,
    /// The companion's key: helper, operator, whether the helper's result is the left term.
    key: (Handle<Function>, BinaryOperator, bool),
    arguments: Vec<Handle<Expression>>,
    other: Handle<Expression>,
}

/// A call of a helper: the helper and its arguments.
type Call = (Handle<Function>, Vec<Handle<Expression>>);

#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Owner {
    Function(Handle<Function>),
    Entry(usize),
}

fn f32_value(inner: &TypeInner) -> bool {
    match *inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => {
            s.kind == naga::ScalarKind::Float && s.width == 4
        }
        _ => false,
    }
}

/// Add the companions `module` needs and call them; `skipped` names functions the emulation
/// leaves as they are (their sums are not rewritten). Returns how many companions were made.
pub fn inline_sums(module: &mut Module, skipped: &dyn Fn(&str) -> bool) -> Result<usize, String> {
    let mut made: HashMap<(String, BinaryOperator, bool), String> = HashMap::new();
    for _ in 0..ROUNDS {
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32,
        )
        .validate(module)
        .map_err(|e| format!("before inlining sums: {e:?}"))?;
        let mut sites = Vec::new();
        let owners: Vec<(Owner, &Function, &naga::valid::FunctionInfo)> = module
            .functions
            .iter()
            .map(|(h, f)| (Owner::Function(h), f, &info[h]))
            .chain(
                module
                    .entry_points
                    .iter()
                    .enumerate()
                    .map(|(i, ep)| (Owner::Entry(i), &ep.function, info.get_entry_point(i))),
            )
            .collect();
        for (at, f, fi) in owners {
            if f.name.as_deref().is_some_and(|n| !is_own(n) || skipped(n)) {
                continue;
            }
            find_sites(module, at, f, fi, skipped, &mut sites);
        }
        if sites.is_empty() {
            break;
        }
        // The companions, appended for now (placed after their helpers below).
        let mut companion: HashMap<(Handle<Function>, BinaryOperator, bool), Handle<Function>> =
            HashMap::new();
        let mut source_of: BTreeMap<Handle<Function>, Handle<Function>> = BTreeMap::new();
        for s in &sites {
            if companion.contains_key(&s.key) {
                continue;
            }
            let (g, op, left) = s.key;
            let g_name = module.functions[g].name.clone().unwrap_or_default();
            let known = made
                .get(&(g_name.clone(), op, left))
                .and_then(|n| module.functions.fetch_if(|f| f.name.as_deref() == Some(n)));
            let h = match known {
                Some(h) => h,
                None => {
                    let name = format!("{INLINED}{}__{g_name}", made.len());
                    let c = make_companion(&module.functions[g], &name, op, left);
                    made.insert((g_name, op, left), name);
                    let h = module.functions.append(c, Span::UNDEFINED);
                    source_of.insert(h, g);
                    h
                }
            };
            companion.insert(s.key, h);
        }
        let mut calls: HashMap<Owner, HashMap<Handle<Expression>, Statement>> = HashMap::new();
        for s in sites {
            let function = companion[&s.key];
            let mut arguments = s.arguments;
            arguments.push(s.other);
            let f = owner_mut(module, s.at);
            f.expressions[s.expr] = Expression::CallResult(function);
            calls.entry(s.at).or_default().insert(
                s.expr,
                Statement::Call {
                    function,
                    arguments,
                    result: Some(s.expr),
                },
            );
        }
        for (at, mut c) in calls {
            let f = owner_mut(module, at);
            f.body = rebuild(std::mem::take(&mut f.body), &mut c);
            if !c.is_empty() {
                return Err("an inlined sum was not found in its function's body".into());
            }
        }
        place_after_sources(module, &source_of);
    }
    Ok(made.len())
}

fn owner_mut(module: &mut Module, at: Owner) -> &mut Function {
    match at {
        Owner::Function(h) => &mut module.functions[h],
        Owner::Entry(i) => &mut module.entry_points[i].function,
    }
}

fn find_sites(
    module: &Module,
    at: Owner,
    f: &Function,
    fi: &naga::valid::FunctionInfo,
    skipped: &dyn Fn(&str) -> bool,
    out: &mut Vec<Site>,
) {
    let inner = |h: Handle<Expression>| fi[h].ty.inner_with(&module.types);
    // Where each helper's result comes from: the call and its arguments.
    let mut call_of: HashMap<Handle<Expression>, Call> = HashMap::new();
    let mut live = HashSet::new();
    visit(&f.body, &mut |s| match s {
        Statement::Call {
            function,
            arguments,
            result: Some(r),
        } => {
            call_of.insert(*r, (*function, arguments.clone()));
        }
        Statement::Emit(range) => live.extend(range.clone()),
        _ => {}
    });
    let plain = |h: Handle<Expression>| {
        !matches!(
            f.expressions[h],
            Expression::Binary {
                op: BinaryOperator::Multiply | BinaryOperator::Add | BinaryOperator::Subtract,
                ..
            }
        )
    };
    for (e, expr) in f.expressions.iter() {
        let Expression::Binary { op, left, right } = *expr else {
            continue;
        };
        if !matches!(op, BinaryOperator::Add | BinaryOperator::Subtract)
            || !live.contains(&e)
            || !f32_value(inner(e))
        {
            continue;
        }
        let pick = |term: Handle<Expression>, other: Handle<Expression>| {
            let Expression::CallResult(g) = f.expressions[term] else {
                return None;
            };
            let callee = &module.functions[g];
            let own = callee
                .name
                .as_deref()
                .is_some_and(|n| is_own(n) && !skipped(n));
            let by_value = callee
                .arguments
                .iter()
                .all(|a| !matches!(module.types[a.ty].inner, TypeInner::Pointer { .. }));
            let same = callee
                .result
                .as_ref()
                .is_some_and(|r| module.types[r.ty].inner == *inner(other));
            (own && by_value && same && plain(other) && inner(term) == inner(e))
                .then(|| call_of.get(&term).map(|(g, args)| (*g, args.clone())))
                .flatten()
        };
        let found = pick(left, right)
            .map(|c| (c, right, true))
            .or_else(|| pick(right, left).map(|c| (c, left, false)));
        if let Some(((g, arguments), other, left_term)) = found {
            out.push(Site {
                at,
                expr: e,
                key: (g, op, left_term),
                arguments,
                other,
            });
        }
    }
}

/// `g` renamed, with a last parameter `c` of its result type, returning `v op c` (or `c op v`
/// when `!left`) wherever it returned `v`.
fn make_companion(g: &Function, name: &str, op: BinaryOperator, left: bool) -> Function {
    let mut f = g.clone();
    f.name = Some(name.to_string());
    let ty = g
        .result
        .as_ref()
        .map(|r| r.ty)
        .expect("helpers with a result");
    let index = f.arguments.len() as u32;
    f.arguments.push(FunctionArgument {
        name: Some(format!("{INLINED}term")),
        ty,
        binding: None,
    });
    let c = f
        .expressions
        .append(Expression::FunctionArgument(index), Span::UNDEFINED);
    f.body = with_term(std::mem::take(&mut f.body), &mut f.expressions, c, op, left);
    f
}

fn with_term(
    block: Block,
    exprs: &mut Arena<Expression>,
    c: Handle<Expression>,
    op: BinaryOperator,
    left: bool,
) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        match stmt {
            Statement::Return { value: Some(v) } => {
                let (l, r) = if left { (v, c) } else { (c, v) };
                let sum = exprs.append(
                    Expression::Binary {
                        op,
                        left: l,
                        right: r,
                    },
                    span,
                );
                out.push(Statement::Emit(Range::new_from_bounds(sum, sum)), span);
                out.push(Statement::Return { value: Some(sum) }, span);
            }
            other => out.push(
                map_nested(other, &mut |b| with_term(b, exprs, c, op, left)),
                span,
            ),
        }
    }
    out
}

/// Move each companion to just after the function it copies (a call may only reach a function
/// earlier in naga's arena), renumbering every call.
fn place_after_sources(
    module: &mut Module,
    source_of: &BTreeMap<Handle<Function>, Handle<Function>>,
) {
    let mut after: BTreeMap<Handle<Function>, Vec<Handle<Function>>> = BTreeMap::new();
    for (&c, &g) in source_of {
        after.entry(g).or_default().push(c);
    }
    let mut old = std::mem::take(&mut module.functions);
    let mut handles = Vec::with_capacity(old.len());
    let mut slots: Vec<Option<(Function, Span)>> = Vec::with_capacity(old.len());
    for (h, f, span) in old.drain() {
        handles.push(h);
        slots.push(Some((f, span)));
    }
    let index: HashMap<Handle<Function>, usize> =
        handles.iter().enumerate().map(|(i, &h)| (h, i)).collect();
    let mut map: HashMap<Handle<Function>, Handle<Function>> = HashMap::new();
    fn place(
        h: Handle<Function>,
        slots: &mut [Option<(Function, Span)>],
        index: &HashMap<Handle<Function>, usize>,
        after: &BTreeMap<Handle<Function>, Vec<Handle<Function>>>,
        out: &mut Arena<Function>,
        map: &mut HashMap<Handle<Function>, Handle<Function>>,
    ) {
        if let Some((f, span)) = slots[index[&h]].take() {
            map.insert(h, out.append(f, span));
            for &c in after.get(&h).into_iter().flatten() {
                place(c, slots, index, after, out, map);
            }
        }
    }
    let mut out = Arena::new();
    for &h in &handles {
        if source_of.contains_key(&h) {
            continue;
        }
        place(h, &mut slots, &index, &after, &mut out, &mut map);
    }
    for (_, f) in out.iter_mut() {
        renumber(f, &map);
    }
    for ep in module.entry_points.iter_mut() {
        renumber(&mut ep.function, &map);
    }
    module.functions = out;
}

fn renumber(f: &mut Function, map: &HashMap<Handle<Function>, Handle<Function>>) {
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::CallResult(h) = e {
            *h = map[h];
        }
    }
    f.body = renumber_calls(std::mem::take(&mut f.body), map);
}

fn renumber_calls(block: Block, map: &HashMap<Handle<Function>, Handle<Function>>) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::Call {
                function,
                arguments,
                result,
            } => Statement::Call {
                function: map[&function],
                arguments,
                result,
            },
            other => map_nested(other, &mut |b| renumber_calls(b, map)),
        };
        out.push(stmt, span);
    }
    out
}
