//! The naga IR pass after the rewrite: branches that the policy's constants decide are taken
//! or dropped before the host compiler sees the module.
//!
//! Why: a module built for one policy (the identity above all) calls helpers whose freedom
//! switches are constants (`core.wgsl`'s `PREPASS_CF_POLICY`), but a host compiler inlines every
//! helper body at every call before it folds them: lavapipe spent about 1.5 s compiling each
//! identity module of a normal encoder, nearly all of it on branches the identity never takes.
//!
//! What, and nothing else (so the module computes exactly what it did):
//! - an `if` whose condition is a constant (literals, module constants, `!`, `&&`, `||` and
//!   integer or boolean comparisons of constants) becomes the branch it takes, spliced into
//!   the enclosing block; a block that ends in `return`, `discard`, `break` or `continue` ends
//!   the enclosing one, whose remaining statements are unreachable and dropped;
//! - a call of a function whose folded body is a bare `return` of a constant (the identity's
//!   `prepass_cf_on` and `prepass_cf_dir`) becomes that constant. Such a body has no side
//!   effects, and the arguments are expressions, which have none either.
//!
//! Callees precede their callers in naga's arena, so one pass in arena order folds a call with
//! its callee already folded. The expressions only the dropped statements evaluated then go
//! (their `let` names, then `naga::compact`, keeping every function): the validator requires
//! every expression of a function to be evaluated somewhere.

use naga::{
    BinaryOperator, Block, Expression, Function, Handle, Literal, Module, Statement, UnaryOperator,
};
use std::collections::{HashMap, HashSet};

/// Fold every function and entry point of `module`; returns how many branches and calls went.
pub fn fold(module: &mut Module) -> usize {
    let mut constant_results: HashMap<Handle<Function>, Literal> = HashMap::new();
    let mut folded = 0;
    let handles: Vec<Handle<Function>> = module.functions.iter().map(|(h, _)| h).collect();
    for h in handles {
        let mut f = std::mem::take(&mut module.functions[h]);
        folded += fold_function(module, &mut f, &constant_results);
        if let Some(value) = constant_return(module, &f) {
            constant_results.insert(h, value);
        }
        module.functions[h] = f;
    }
    for i in 0..module.entry_points.len() {
        let mut f = std::mem::take(&mut module.entry_points[i].function);
        folded += fold_function(module, &mut f, &constant_results);
        module.entry_points[i].function = f;
    }
    if folded > 0 {
        naga::compact::compact(module, naga::compact::KeepUnused::Yes);
    }
    folded
}

fn fold_function(
    module: &Module,
    f: &mut Function,
    constant_results: &HashMap<Handle<Function>, Literal>,
) -> usize {
    let mut folded = 0;
    let body = std::mem::take(&mut f.body);
    f.body = fold_block(module, f, body, constant_results, &mut folded);
    if folded > 0 {
        // A name keeps its expression alive in compaction: drop the names of those no
        // statement evaluates any more.
        let mut evaluated = HashSet::new();
        evaluated_in(&f.body, &mut evaluated);
        let kept = |h: &Handle<Expression>| {
            evaluated.contains(h)
                || match f.expressions[*h] {
                    Expression::CallResult(_) => false,
                    ref e => e.needs_pre_emit() || !is_emitted_kind(e),
                }
        };
        f.named_expressions.retain(|h, _| kept(h));
    }
    folded
}

/// Whether `e` is evaluated by an `Emit` (rather than by a statement of its own, as the results
/// of atomics, barriers' loads, ray queries and subgroup operations are; those are kept).
fn is_emitted_kind(e: &Expression) -> bool {
    !matches!(
        e,
        Expression::AtomicResult { .. }
            | Expression::WorkGroupUniformLoadResult { .. }
            | Expression::RayQueryProceedResult
            | Expression::SubgroupBallotResult
            | Expression::SubgroupOperationResult { .. }
    )
}

/// Every expression `block` (and what it nests) emits or computes by a call.
fn evaluated_in(block: &Block, out: &mut HashSet<Handle<Expression>>) {
    super::rewrite::visit(block, &mut |s| match s {
        Statement::Emit(range) => out.extend(range.clone()),
        Statement::Call {
            result: Some(r), ..
        } => {
            out.insert(*r);
        }
        _ => {}
    });
}

/// `block` folded: taken branches spliced in, constant calls replaced, unreachable statements dropped.
fn fold_block(
    module: &Module,
    f: &mut Function,
    block: Block,
    constant_results: &HashMap<Handle<Function>, Literal>,
    folded: &mut usize,
) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        match stmt {
            Statement::Call {
                function,
                result: Some(result),
                ..
            } if constant_results.contains_key(&function) => {
                f.expressions[result] = Expression::Literal(constant_results[&function]);
                *folded += 1;
            }
            Statement::If {
                condition,
                accept,
                reject,
            } if constant(module, f, condition).is_some() => {
                let taken = match constant(module, f, condition) {
                    Some(Literal::Bool(true)) => accept,
                    _ => reject,
                };
                *folded += 1;
                let taken = fold_block(module, f, taken, constant_results, folded);
                let leaves = taken.last().is_some_and(leaves_block);
                for (s, sp) in taken.span_into_iter() {
                    out.push(s, sp);
                }
                if leaves {
                    return out;
                }
            }
            other => {
                let s = super::rewrite::map_nested(other, &mut |b| {
                    fold_block(module, f, b, constant_results, folded)
                });
                let leaves = leaves_block(&s);
                out.push(s, span);
                if leaves {
                    return out;
                }
            }
        }
    }
    out
}

fn leaves_block(s: &Statement) -> bool {
    matches!(
        s,
        Statement::Return { .. } | Statement::Kill | Statement::Break | Statement::Continue
    )
}

/// The constant `f`'s folded body returns, when it is nothing but `return` of a constant.
fn constant_return(module: &Module, f: &Function) -> Option<Literal> {
    let mut rest = f.body.iter().filter(|s| !matches!(s, Statement::Emit(_)));
    match (rest.next(), rest.next()) {
        (Some(Statement::Return { value: Some(v) }), None) => constant(module, f, *v),
        _ => None,
    }
}

/// The value of `e` when it is a constant of the kinds the module docs list.
fn constant(module: &Module, f: &Function, e: Handle<Expression>) -> Option<Literal> {
    value(module, &f.expressions, e)
}

fn value(
    module: &Module,
    arena: &naga::Arena<Expression>,
    e: Handle<Expression>,
) -> Option<Literal> {
    let recurse = |h| value(module, arena, h);
    match arena[e] {
        Expression::Literal(l) => Some(l),
        Expression::Constant(c) => {
            value(module, &module.global_expressions, module.constants[c].init)
        }
        Expression::Unary {
            op: UnaryOperator::LogicalNot,
            expr,
        } => match recurse(expr)? {
            Literal::Bool(b) => Some(Literal::Bool(!b)),
            _ => None,
        },
        Expression::Binary { op, left, right } => {
            use BinaryOperator as B;
            let l = recurse(left)?;
            // && and || decide on their left operand alone where they can.
            match (op, l) {
                (B::LogicalAnd, Literal::Bool(false)) => return Some(l),
                (B::LogicalOr, Literal::Bool(true)) => return Some(l),
                _ => {}
            }
            let r = recurse(right)?;
            let ordered = match (l, r) {
                (Literal::U32(a), Literal::U32(b)) => Some(a.cmp(&b)),
                (Literal::I32(a), Literal::I32(b)) => Some(a.cmp(&b)),
                (Literal::Bool(a), Literal::Bool(b)) => Some(a.cmp(&b)),
                _ => None,
            }?;
            use std::cmp::Ordering as O;
            let b = match op {
                B::Equal => ordered == O::Equal,
                B::NotEqual => ordered != O::Equal,
                B::Less => ordered == O::Less,
                B::LessEqual => ordered != O::Greater,
                B::Greater => ordered == O::Greater,
                B::GreaterEqual => ordered != O::Less,
                B::LogicalAnd | B::LogicalOr => return Some(r),
                _ => return None,
            };
            Some(Literal::Bool(b))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use crate::conforming::{Emulation, Policy, emulate};
    use std::collections::BTreeSet;

    /// Names of the functions `root` calls, directly or through others, in `source`.
    fn reachable(source: &str, root: &str) -> BTreeSet<String> {
        let module = naga::front::wgsl::parse_str(source).unwrap();
        let mut todo: Vec<_> = module
            .functions
            .iter()
            .filter(|(_, f)| f.name.as_deref() == Some(root))
            .map(|(h, _)| h)
            .collect();
        let mut seen = BTreeSet::new();
        while let Some(h) = todo.pop() {
            if seen.insert(module.functions[h].name.clone().unwrap_or_default()) {
                crate::conforming::rewrite::visit(&module.functions[h].body, &mut |s| {
                    if let naga::Statement::Call { function, .. } = s {
                        todo.push(*function);
                    }
                });
            }
        }
        seen
    }

    #[test]
    fn the_identity_module_keeps_no_branch_its_constants_rule_out() {
        let src = "fn f(a: f32, b: f32) -> f32 { return exp2(a / b) * inverseSqrt(a + b); }";
        let reach = |policy| {
            let e = emulate(src, &Emulation::new(policy)).unwrap();
            reachable(&e.source, e.function_name("f").unwrap())
        };
        let (identity, searched) = (reach(Policy::Identity), reach(Policy::Searched));
        // The switches themselves, the rounding push and the placement at an interval's end.
        for name in [
            "prepass_cf_on",
            "prepass_cf_dir",
            "prepass_cf_round",
            "prepass_cf_place_ulp",
        ] {
            assert!(
                !identity.contains(name),
                "the identity module still reaches {name}"
            );
            assert!(
                searched.contains(name),
                "the searched module no longer reaches {name}"
            );
        }
    }
}
