//! The naga IR pass: find every f32 operation whose result WGSL leaves free, and turn it into a
//! call of the helper in `core.wgsl` (or a generated vector wrapper of it).
//!
//! An expression `e` that is rewritten keeps its handle, so everything that uses it still does:
//! `e` becomes `CallResult(helper)`, its `Emit` range is split around it, and a `Call` statement
//! computing it from the original operands is put in its place. Operands have smaller handles
//! than `e` (naga's arena order), so they are already evaluated where the call stands.

use naga::{
    BinaryOperator, Block, Expression, Function, Handle, Literal, MathFunction, Module, Range,
    ScalarKind, Span, Statement, TypeInner, VectorSize,
};
use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::fmt::Write as _;

/// Prefix of everything the emulation adds to a module.
pub const PREFIX: &str = "prepass_cf_";

/// Lanes of an f32 value: 1 for a scalar, 2–4 for a vector.
type Lanes = u8;

/// One operand: an existing expression, with its lane count.
#[derive(Clone, Copy, Debug)]
struct Operand {
    expr: Handle<Expression>,
    lanes: Lanes,
}

/// What an expression becomes.
#[derive(Clone, Debug)]
struct Site {
    expr: Handle<Expression>,
    /// Helper function name.
    helper: String,
    operands: Vec<Handle<Expression>>,
}

/// Whether a helper takes no freedom (it only checks its operands' domain), so its site needs no
/// number of its own: the checked float-to-integer conversions. Numbering them would renumber
/// every later site, and so move every seeded policy's choices.
fn unnumbered(helper: &str) -> bool {
    helper.contains("_from_f32")
}

/// A helper the module needs: its name and, for generated ones, its WGSL.
#[derive(Default)]
pub struct Plan {
    sites: HashMap<String, Vec<Site>>,
    /// Generated wrappers by name.
    pub wrappers: BTreeMap<String, String>,
    /// Inexact operations left at the host's accuracy (not emulated), by name.
    pub uncovered: BTreeSet<String>,
}

fn f32_lanes(inner: &TypeInner) -> Option<Lanes> {
    match *inner {
        TypeInner::Scalar(s) if s.kind == ScalarKind::Float && s.width == 4 => Some(1),
        TypeInner::Vector { size, scalar }
            if scalar.kind == ScalarKind::Float && scalar.width == 4 =>
        {
            Some(size as u8)
        }
        _ => None,
    }
}

fn ty_name(lanes: Lanes) -> String {
    ty_of(lanes, "f32")
}

/// WGSL type of `lanes` lanes of `scalar` (`f32`, `u32`, `i32`, `bool`).
fn ty_of(lanes: Lanes, scalar: &str) -> String {
    if lanes == 1 {
        scalar.into()
    } else {
        format!("vec{lanes}<{scalar}>")
    }
}

fn lane(arg: &str, lanes: Lanes, k: u8) -> String {
    if lanes == 1 {
        arg.to_string()
    } else {
        format!("{arg}[{k}]")
    }
}

/// A component-wise wrapper of the scalar f32 core helper `core` for these operand shapes.
fn componentwise(plan: &mut Plan, core: &str, shapes: &[Lanes]) -> String {
    let typed: Vec<(Lanes, &str)> = shapes.iter().map(|&l| (l, "f32")).collect();
    componentwise_typed(plan, core, &typed, "f32")
}

/// A component-wise wrapper of the scalar core helper `core`, whose operands are these
/// (lanes, scalar type) and whose lanes are of type `ret`.
fn componentwise_typed(plan: &mut Plan, core: &str, shapes: &[(Lanes, &str)], ret: &str) -> String {
    let n = shapes.iter().map(|s| s.0).max().unwrap_or(1);
    let core_name = format!("{PREFIX}{core}");
    if n == 1 {
        return core_name;
    }
    let sig: String = shapes.iter().map(|s| s.0.to_string()).collect();
    let name = format!("{PREFIX}{core}_v{sig}");
    plan.wrappers.entry(name.clone()).or_insert_with(|| {
        let params: Vec<String> = shapes
            .iter()
            .enumerate()
            .map(|(i, &(l, t))| format!("a{i}: {}", ty_of(l, t)))
            .collect();
        let lanes: Vec<String> = (0..n)
            .map(|k| {
                let args: Vec<String> = shapes
                    .iter()
                    .enumerate()
                    .map(|(i, &(l, _))| lane(&format!("a{i}"), l, k))
                    .collect();
                format!(
                    "{core_name}(site + {}u, {})",
                    1024 * u32::from(k),
                    args.join(", ")
                )
            })
            .collect();
        format!(
            "fn {name}(site: u32, {}) -> {} {{\n    return {}({});\n}}\n",
            params.join(", "),
            ty_of(n, ret),
            ty_of(n, ret),
            lanes.join(", ")
        )
    });
    name
}

/// WGSL statements that mark the evaluation outside the spec's domain where `var` (`lanes` f32
/// lanes; a matrix of that many rows where `columns` > 0) holds a ±Inf or NaN: the identity's
/// builtin paths below compute on their operands without the core helpers, which check them.
fn check_stmts(var: &str, lanes: Lanes, columns: u8) -> String {
    let checked = if lanes == 1 {
        format!("{PREFIX}checked")
    } else {
        format!("{PREFIX}checked{lanes}")
    };
    if columns == 0 {
        return format!("        _ = {checked}({var});\n");
    }
    (0..columns)
        .map(|c| format!("        _ = {checked}({var}[{c}]);\n"))
        .collect()
}

/// `m * v` (`vec_left` false) or `v * m` of an f32 matrix of `columns` × `rows`, as the spec
/// defines them: each result lane a `dot` of a row (or a column) with the vector, so each inherits
/// the freedoms of `dot`.
fn matrix_vector(plan: &mut Plan, columns: Lanes, rows: Lanes, vec_left: bool) -> String {
    let name = format!(
        "{PREFIX}{}{columns}x{rows}",
        if vec_left { "vecmat" } else { "matvec" }
    );
    if plan.wrappers.contains_key(&name) {
        return name;
    }
    let m = format!("mat{columns}x{rows}<f32>");
    let (inner, outer) = if vec_left {
        (rows, columns)
    } else {
        (columns, rows)
    };
    let dot = inherited(plan, "dot", inner);
    let p = PREFIX;
    let lanes: Vec<String> = (0..outer)
        .map(|i| {
            let other = if vec_left {
                format!("m[{i}]")
            } else {
                let row: Vec<String> = (0..columns).map(|c| format!("m[{c}][{i}]")).collect();
                format!("vec{columns}<f32>({})", row.join(", "))
            };
            let (a, b) = if vec_left {
                ("v".to_string(), other)
            } else {
                (other, "v".to_string())
            };
            format!("{dot}(site + {}u, {a}, {b})", 8192 * u32::from(i))
        })
        .collect();
    let (params, builtin, v_lanes) = if vec_left {
        (format!("v: vec{rows}<f32>, m: {m}"), "v * m", rows)
    } else {
        (format!("m: {m}, v: vec{columns}<f32>"), "m * v", columns)
    };
    let checks = check_stmts("m", rows, columns) + &check_stmts("v", v_lanes, 0);
    let r = check_stmts("r", outer, 0);
    let s = format!(
        "fn {name}(site: u32, {params}) -> vec{outer}<f32> {{\n    if (!{p}on(PREPASS_CF_INHERITED)) {{\n{checks}        let r = {builtin};\n{r}        return r;\n    }}\n    return vec{outer}<f32>({});\n}}\n",
        lanes.join(", ")
    );
    plan.wrappers.insert(name.clone(), s);
    name
}

/// `dot`, `length`, `normalize`, `distance`, `reflect`, `cross` of `n` lanes, as their
/// defining expressions (the spec's "inherited" accuracy).
fn inherited(plan: &mut Plan, what: &str, n: Lanes) -> String {
    let name = format!("{PREFIX}{what}{n}");
    if plan.wrappers.contains_key(&name) {
        return name;
    }
    let t = ty_name(n);
    let p = PREFIX;
    let mut s = String::new();
    // The builtin where the identity leaves it: its operands (`n` lanes each) and result
    // (`out` lanes) checked for the domain.
    let guard = |s: &mut String, builtin: &str, operands: &[&str], out: Lanes| {
        let checks: String = operands.iter().map(|o| check_stmts(o, n, 0)).collect();
        let _ = write!(
            s,
            "    if (!{p}on(PREPASS_CF_INHERITED)) {{\n{checks}        let r = {builtin};\n{}        return r;\n    }}\n",
            check_stmts("r", out, 0)
        );
    };
    match what {
        "dot" => {
            let _ = writeln!(s, "fn {name}(site: u32, a: {t}, b: {t}) -> f32 {{");
            guard(
                &mut s,
                if n == 1 { "a * b" } else { "dot(a, b)" },
                &["a", "b"],
                1,
            );
            for k in 0..n {
                let _ = writeln!(
                    s,
                    "    let p{k} = {p}mul(site + {}u, {}, {});",
                    64 * u32::from(k),
                    lane("a", n, k),
                    lane("b", n, k)
                );
            }
            // The written order, left to right.
            let _ = writeln!(s, "    var r = p0;");
            for k in 1..n {
                let _ = writeln!(
                    s,
                    "    r = {p}add(site + {}u, r, p{k});",
                    512 + 64 * u32::from(k)
                );
            }
            if n > 2 {
                // Reassociated: right to left.
                let _ = writeln!(s, "    var q = p{};", n - 1);
                for k in (0..n - 1).rev() {
                    let _ = writeln!(
                        s,
                        "    q = {p}add(site + {}u, p{k}, q);",
                        1024 + 64 * u32::from(k)
                    );
                }
                let _ = writeln!(
                    s,
                    "    r = {p}pick(PREPASS_CF_REASSOCIATION, site + 1600u, r, q);"
                );
                // The grouping neither order reaches: the outer terms first, (p0 + p2) + p1
                // at three lanes; pairwise, (p0 + p1) + (p2 + p3), at four.
                let third = if n == 3 {
                    format!("{p}add(site + 3072u, {p}add(site + 3136u, p0, p2), p1)")
                } else {
                    format!(
                        "{p}add(site + 3072u, {p}add(site + 3136u, p0, p1), {p}add(site + 3200u, p2, p3))"
                    )
                };
                let _ = writeln!(
                    s,
                    "    r = {p}pick(PREPASS_CF_REASSOCIATION, site + 3264u, r, {third});"
                );
            }
            if n > 1 {
                // Fused: every product after the first folded into a multiply-add.
                let _ = writeln!(s, "    var m = p0;");
                for k in 1..n {
                    let _ = writeln!(
                        s,
                        "    m = {p}mad(site + {}u, {}, {}, m);",
                        2048 + 64 * u32::from(k),
                        lane("a", n, k),
                        lane("b", n, k)
                    );
                }
                let _ = writeln!(s, "    r = {p}pick(PREPASS_CF_FUSION, site + 2600u, r, m);");
            }
            let _ = writeln!(s, "    return r;\n}}");
        }
        "length" => {
            let dot = inherited(plan, "dot", n);
            let _ = writeln!(s, "fn {name}(site: u32, v: {t}) -> f32 {{");
            guard(&mut s, "length(v)", &["v"], 1);
            let _ = writeln!(
                s,
                "    return {p}sqrt(site, {dot}(site + 8192u, v, v));\n}}"
            );
        }
        "distance" => {
            let len = inherited(plan, "length", n);
            let sub = componentwise(plan, "sub", &[n, n]);
            let _ = writeln!(s, "fn {name}(site: u32, a: {t}, b: {t}) -> f32 {{");
            guard(&mut s, "distance(a, b)", &["a", "b"], 1);
            let _ = writeln!(s, "    return {len}(site, {sub}(site + 16384u, a, b));\n}}");
        }
        "normalize" => {
            let len = inherited(plan, "length", n);
            let div = componentwise(plan, "div", &[n, 1]);
            let _ = writeln!(s, "fn {name}(site: u32, v: {t}) -> {t} {{");
            guard(&mut s, "normalize(v)", &["v"], n);
            let _ = writeln!(s, "    return {div}(site + 16384u, v, {len}(site, v));\n}}");
        }
        "reflect" => {
            let dot = inherited(plan, "dot", n);
            let nmad = componentwise(plan, "nmad", &[1, n, n]);
            let _ = writeln!(s, "fn {name}(site: u32, e1: {t}, e2: {t}) -> {t} {{");
            guard(&mut s, "reflect(e1, e2)", &["e1", "e2"], n);
            let _ = writeln!(
                s,
                "    let k = 2.0 * {dot}(site, e2, e1);\n    return {nmad}(site + 16384u, k, e2, e1);\n}}"
            );
        }
        "cross" => {
            let _ = writeln!(
                s,
                "fn {name}(site: u32, a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {{"
            );
            guard(&mut s, "cross(a, b)", &["a", "b"], 3);
            let _ = writeln!(
                s,
                "    return vec3<f32>(\n        \
                 {p}msub(site, a.y, b.z, {p}mul(site + 64u, a.z, b.y)),\n        \
                 {p}msub(site + 1024u, a.z, b.x, {p}mul(site + 1088u, a.x, b.z)),\n        \
                 {p}msub(site + 2048u, a.x, b.y, {p}mul(site + 2112u, a.y, b.x)));\n}}"
            );
        }
        _ => unreachable!("no inherited helper {what}"),
    }
    plan.wrappers.insert(name.clone(), s);
    name
}

/// `a * b` of an f32 `mat{c1}x{r1}` by a `mat{c2}x{c1}`, as the spec defines it: entry (i, j) the
/// `dot` of row i of `a` with column j of `b`, each with the freedoms of `dot`.
fn matrix_matrix(plan: &mut Plan, c1: Lanes, r1: Lanes, c2: Lanes) -> String {
    let name = format!("{PREFIX}matmat{c1}x{r1}_{c2}");
    if plan.wrappers.contains_key(&name) {
        return name;
    }
    let dot = inherited(plan, "dot", c1);
    let p = PREFIX;
    let columns: Vec<String> = (0..c2)
        .map(|j| {
            let lanes: Vec<String> = (0..r1)
                .map(|i| {
                    let row: Vec<String> = (0..c1).map(|k| format!("a[{k}][{i}]")).collect();
                    format!(
                        "{dot}(site + {}u, vec{c1}<f32>({}), b[{j}])",
                        16384 * u32::from(j) + 4096 * u32::from(i),
                        row.join(", ")
                    )
                })
                .collect();
            format!("vec{r1}<f32>({})", lanes.join(", "))
        })
        .collect();
    let checks = check_stmts("a", r1, c1) + &check_stmts("b", c1, c2);
    let r = check_stmts("r", r1, c2);
    let s = format!(
        "fn {name}(site: u32, a: mat{c1}x{r1}<f32>, b: mat{c2}x{c1}<f32>) -> mat{c2}x{r1}<f32> {{\n    if (!{p}on(PREPASS_CF_INHERITED)) {{\n{checks}        let r = a * b;\n{r}        return r;\n    }}\n    return mat{c2}x{r1}<f32>({});\n}}\n",
        columns.join(", ")
    );
    plan.wrappers.insert(name.clone(), s);
    name
}

fn binary_operands(
    f: &Function,
    e: Handle<Expression>,
    want: BinaryOperator,
) -> Option<(Handle<Expression>, Handle<Expression>)> {
    match f.expressions[e] {
        Expression::Binary { op, left, right } if op == want => Some((left, right)),
        _ => None,
    }
}

/// The helper (and its operands) for expression `e`, if it is an operation the spec leaves free.
fn site_for(
    plan: &mut Plan,
    module: &Module,
    f: &Function,
    lanes_of: &dyn Fn(Handle<Expression>) -> Option<Lanes>,
    inner_of: &dyn Fn(Handle<Expression>) -> TypeInner,
    e: Handle<Expression>,
) -> Option<(String, Vec<Handle<Expression>>)> {
    let result = lanes_of(e);
    let f32_matrix = |h| match inner_of(h) {
        TypeInner::Matrix {
            columns,
            rows,
            scalar,
        } if scalar.kind == ScalarKind::Float && scalar.width == 4 => {
            Some((columns as u8, rows as u8))
        }
        _ => None,
    };
    let ops = |hs: &[Handle<Expression>]| -> Option<Vec<Operand>> {
        hs.iter()
            .map(|&h| lanes_of(h).map(|lanes| Operand { expr: h, lanes }))
            .collect()
    };
    let call = |plan: &mut Plan, core: &str, hs: &[Handle<Expression>]| {
        let o = ops(hs)?;
        let shapes: Vec<Lanes> = o.iter().map(|x| x.lanes).collect();
        Some((
            componentwise(plan, core, &shapes),
            o.iter().map(|x| x.expr).collect(),
        ))
    };
    match f.expressions[e] {
        Expression::Binary { op, left, right } => {
            use BinaryOperator as B;
            // Matrix × vector and vector × matrix: dot products per lane. Other matrix
            // arithmetic is not emulated, and is listed.
            match (f32_matrix(left), f32_matrix(right), op) {
                (Some((c, r)), None, B::Multiply) if lanes_of(right) == Some(c) && c > 1 => {
                    return Some((matrix_vector(plan, c, r, false), vec![left, right]));
                }
                (None, Some((c, r)), B::Multiply) if lanes_of(left) == Some(r) && r > 1 => {
                    return Some((matrix_vector(plan, c, r, true), vec![left, right]));
                }
                (Some((c1, r1)), Some((c2, r2)), B::Multiply) if r2 == c1 => {
                    return Some((matrix_matrix(plan, c1, r1, c2), vec![left, right]));
                }
                (None, None, _) => {}
                _ => {
                    plan.uncovered.insert(format!(
                        "matrix arithmetic other than matrix products ({op:?})"
                    ));
                    return None;
                }
            }
            let (a, b) = (lanes_of(left)?, lanes_of(right)?);
            // Comparisons are exact; only their operands' flushing is free.
            let cmp = match op {
                B::Less => Some("lt"),
                B::LessEqual => Some("le"),
                B::Greater => Some("gt"),
                B::GreaterEqual => Some("ge"),
                B::Equal => Some("eq"),
                B::NotEqual => Some("ne"),
                _ => None,
            };
            if let Some(c) = cmp {
                let name = componentwise_typed(plan, c, &[(a, "f32"), (b, "f32")], "bool");
                return Some((name, vec![left, right]));
            }
            result?;
            let mul = |h| {
                binary_operands(f, h, B::Multiply)
                    .filter(|&(a, b)| lanes_of(a).is_some() && lanes_of(b).is_some())
            };
            let add = |h| {
                binary_operands(f, h, B::Add)
                    .filter(|&(a, b)| lanes_of(a).is_some() && lanes_of(b).is_some())
            };
            let sub = |h| {
                binary_operands(f, h, B::Subtract)
                    .filter(|&(a, b)| lanes_of(a).is_some() && lanes_of(b).is_some())
            };
            match op {
                B::Add => {
                    // A product beside a sum or difference: fusion and reassociation both apply.
                    let product = mul(left)
                        .map(|p| (p, right))
                        .or_else(|| mul(right).map(|p| (p, left)));
                    if let Some(((x, y), other)) = product {
                        if let Some((a, b)) = sub(other) {
                            call(plan, "sub_add_mad", &[a, b, x, y])
                        } else if let Some((a, b)) = add(other) {
                            call(plan, "add3_mad", &[a, b, x, y])
                        } else {
                            call(plan, "mad", &[x, y, other])
                        }
                    } else if let Some((a, b)) = add(left) {
                        call(plan, "add3", &[a, b, right])
                    } else if let Some((a, b)) = add(right) {
                        call(plan, "add3", &[a, b, left])
                    } else if let Some((a, b)) = sub(left) {
                        call(plan, "sub_add", &[a, b, right])
                    } else if let Some((a, b)) = sub(right) {
                        call(plan, "sub_add", &[a, b, left])
                    } else {
                        call(plan, "add", &[left, right])
                    }
                }
                B::Subtract => {
                    if let Some((a, b)) = mul(left) {
                        call(plan, "msub", &[a, b, right])
                    } else if let Some((a, b)) = mul(right) {
                        call(plan, "nmad", &[a, b, left])
                    } else if let Some((a, b)) = add(left) {
                        call(plan, "add_sub", &[a, b, right])
                    } else {
                        call(plan, "sub", &[left, right])
                    }
                }
                B::Multiply => call(plan, "mul", &[left, right]),
                B::Divide => {
                    if let Some((a, b)) = mul(left) {
                        call(plan, "mul_div", &[a, b, right])
                    } else {
                        call(plan, "div", &[left, right])
                    }
                }
                B::Modulo => {
                    plan.uncovered.insert("f32 %".into());
                    None
                }
                _ => None,
            }
        }
        Expression::Math {
            fun,
            arg,
            arg1,
            arg2,
            ..
        } => {
            use MathFunction as M;
            let n = lanes_of(arg);
            let both = |plan: &mut Plan, what: &str| -> Option<(String, Vec<Handle<Expression>>)> {
                let n = n?;
                Some((inherited(plan, what, n), vec![arg, arg1?]))
            };
            match fun {
                M::InverseSqrt => call(plan, "inverse_sqrt", &[arg]),
                M::Sqrt => call(plan, "sqrt", &[arg]),
                M::Exp => call(plan, "exp", &[arg]),
                M::Exp2 => call(plan, "exp2", &[arg]),
                M::Sin => call(plan, "sin", &[arg]),
                M::Cos => call(plan, "cos", &[arg]),
                M::Log => call(plan, "log", &[arg]),
                M::Log2 => call(plan, "log2", &[arg]),
                M::Fract => call(plan, "fract", &[arg]),
                // Exactly rounded, but inputs and outputs may be flushed.
                M::Floor => call(plan, "floor", &[arg]),
                M::Ceil => call(plan, "ceil", &[arg]),
                M::Trunc => call(plan, "trunc", &[arg]),
                M::Round => call(plan, "round_even", &[arg]),
                M::Abs => call(plan, "abs", &[arg]),
                M::Sign => call(plan, "sign", &[arg]),
                M::Saturate => call(plan, "saturate", &[arg]),
                M::Min => call(plan, "min", &[arg, arg1?]),
                M::Max => call(plan, "max", &[arg, arg1?]),
                M::Step => call(plan, "step", &[arg, arg1?]),
                M::Clamp => call(plan, "clamp", &[arg, arg1?, arg2?]),
                M::Unpack2x16float => Some((format!("{PREFIX}unpack2x16float"), vec![arg])),
                M::Pow => call(plan, "pow", &[arg, arg1?]),
                M::Fma => call(plan, "fma", &[arg, arg1?, arg2?]),
                M::Mix => call(plan, "mix", &[arg, arg1?, arg2?]),
                M::Dot => both(plan, "dot"),
                M::Distance => both(plan, "distance"),
                M::Reflect => both(plan, "reflect"),
                M::Cross => both(plan, "cross"),
                M::Length => Some((inherited(plan, "length", n?), vec![arg])),
                M::Normalize if n? > 1 => Some((inherited(plan, "normalize", n?), vec![arg])),
                M::Unpack4x8unorm | M::Unpack4x8snorm | M::Unpack2x16unorm | M::Unpack2x16snorm => {
                    let name = match fun {
                        M::Unpack4x8unorm => "unpack4x8unorm",
                        M::Unpack4x8snorm => "unpack4x8snorm",
                        M::Unpack2x16unorm => "unpack2x16unorm",
                        _ => "unpack2x16snorm",
                    };
                    Some((format!("{PREFIX}{name}"), vec![arg]))
                }
                M::Pack4x8unorm
                | M::Pack4x8snorm
                | M::Pack2x16unorm
                | M::Pack2x16snorm
                | M::Pack2x16float => {
                    let name = match fun {
                        M::Pack4x8unorm => "pack4x8unorm",
                        M::Pack4x8snorm => "pack4x8snorm",
                        M::Pack2x16unorm => "pack2x16unorm",
                        M::Pack2x16snorm => "pack2x16snorm",
                        _ => "pack2x16float",
                    };
                    Some((format!("{PREFIX}{name}"), vec![arg]))
                }
                // Exact (or not an f32 operation).
                M::Transpose => None,
                other => {
                    // Everything else on f32 is left at the host's accuracy, and listed.
                    let f32_involved = n.is_some()
                        || result.is_some()
                        || f32_matrix(arg).is_some()
                        || f32_matrix(e).is_some();
                    if f32_involved {
                        plan.uncovered.insert(format!("{other:?}"));
                    }
                    let _ = module;
                    None
                }
            }
        }
        Expression::As {
            expr,
            kind: ScalarKind::Float,
            convert: Some(4),
        } => {
            // f32 of an integer: either neighbour where inexact.
            let (lanes, scalar) = match inner_of(expr) {
                TypeInner::Scalar(s) => (1, s),
                TypeInner::Vector { size, scalar } => (size as u8, scalar),
                _ => return None,
            };
            let (core, ty) = match (scalar.kind, scalar.width) {
                (ScalarKind::Uint, 4) => ("f32_from_u32", "u32"),
                (ScalarKind::Sint, 4) => ("f32_from_i32", "i32"),
                _ => return None, // f32 of f32 or of bool: exact
            };
            Some((
                componentwise_typed(plan, core, &[(lanes, ty)], "f32"),
                vec![expr],
            ))
        }
        Expression::As {
            expr,
            kind: kind @ (ScalarKind::Uint | ScalarKind::Sint),
            convert: Some(4),
        } => {
            // u32 or i32 of an f32: exact (WGSL truncates and saturates), but outside the
            // domain for a ±Inf or NaN operand, which no arithmetic helper sees here.
            let lanes = lanes_of(expr)?;
            let (core, ret) = if kind == ScalarKind::Uint {
                ("u32_from_f32", "u32")
            } else {
                ("i32_from_f32", "i32")
            };
            Some((
                componentwise_typed(plan, core, &[(lanes, "f32")], ret),
                vec![expr],
            ))
        }
        Expression::As {
            kind: ScalarKind::Float,
            convert: Some(2),
            ..
        } => {
            plan.uncovered.insert("conversion to f16".into());
            None
        }
        _ => None,
    }
}

/// Every statement of `block` and of the blocks nested in it, in order.
pub(super) fn visit(block: &Block, f: &mut dyn FnMut(&Statement)) {
    for stmt in block.iter() {
        f(stmt);
        match stmt {
            Statement::Block(b) => visit(b, f),
            Statement::If { accept, reject, .. } => {
                visit(accept, f);
                visit(reject, f);
            }
            Statement::Switch { cases, .. } => cases.iter().for_each(|c| visit(&c.body, f)),
            Statement::Loop {
                body, continuing, ..
            } => {
                visit(body, f);
                visit(continuing, f);
            }
            _ => {}
        }
    }
}

fn emitted(block: &Block, out: &mut HashSet<Handle<Expression>>) {
    visit(block, &mut |s| {
        if let Statement::Emit(range) = s {
            out.extend(range.clone());
        }
    });
}

fn function_key(module: &Module, f: &Function, entry: Option<usize>) -> String {
    match entry {
        Some(i) => format!("entry:{}", module.entry_points[i].name),
        None => format!("fn:{}", f.name.as_deref().unwrap_or("")),
    }
}

/// Whether the emulation leaves the module's function `name` as it is: one of
/// [`super::EXACT_FUNCTIONS`], unless `emulate_exact`.
pub(super) fn skipped_exact(name: &str, emulate_exact: bool) -> bool {
    !emulate_exact && super::EXACT_FUNCTIONS.iter().any(|&(f, _)| f == name)
}

/// Find every site in the module's functions and entry points (the emulation's own helpers
/// excepted, and [`super::EXACT_FUNCTIONS`] unless `emulate_exact`, left as they are).
pub fn plan(module: &Module, info: &naga::valid::ModuleInfo, emulate_exact: bool) -> Plan {
    let mut plan = Plan::default();
    let skipped = |n: &str| !super::inline::is_own(n) || skipped_exact(n, emulate_exact);
    let visit = |f: &Function, fi: &naga::valid::FunctionInfo, key: String, plan: &mut Plan| {
        if f.name.as_deref().is_some_and(skipped) {
            return;
        }
        let mut live = HashSet::new();
        emitted(&f.body, &mut live);
        let lanes_of = |h: Handle<Expression>| f32_lanes(fi[h].ty.inner_with(&module.types));
        let inner_of = |h: Handle<Expression>| fi[h].ty.inner_with(&module.types).clone();
        let mut sites = Vec::new();
        for (h, _) in f.expressions.iter() {
            if !live.contains(&h) {
                continue;
            }
            if let Some((helper, operands)) = site_for(plan, module, f, &lanes_of, &inner_of, h) {
                sites.push(Site {
                    expr: h,
                    helper,
                    operands,
                });
            }
        }
        plan.sites.insert(key, sites);
    };
    for (h, f) in module.functions.iter() {
        visit(f, &info[h], function_key(module, f, None), &mut plan);
    }
    for (i, ep) in module.entry_points.iter().enumerate() {
        visit(
            &ep.function,
            info.get_entry_point(i),
            function_key(module, &ep.function, Some(i)),
            &mut plan,
        );
    }
    plan
}

/// `stmt` with each block nested in it (a block, both arms of an `if`, every case of a
/// `switch`, a loop's body and continuing) passed through `map`; other statements as they are.
pub(super) fn map_nested(stmt: Statement, map: &mut dyn FnMut(Block) -> Block) -> Statement {
    match stmt {
        Statement::Block(b) => Statement::Block(map(b)),
        Statement::If {
            condition,
            accept,
            reject,
        } => Statement::If {
            condition,
            accept: map(accept),
            reject: map(reject),
        },
        Statement::Switch {
            selector,
            mut cases,
        } => {
            for c in cases.iter_mut() {
                c.body = map(std::mem::take(&mut c.body));
            }
            Statement::Switch { selector, cases }
        }
        Statement::Loop {
            body,
            continuing,
            break_if,
        } => Statement::Loop {
            body: map(body),
            continuing: map(continuing),
            break_if,
        },
        other => other,
    }
}

pub(super) fn rebuild(block: Block, calls: &mut HashMap<Handle<Expression>, Statement>) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        match stmt {
            Statement::Emit(range) => {
                let mut run: Option<(Handle<Expression>, Handle<Expression>)> = None;
                let flush = |out: &mut Block, run: &mut Option<(Handle<Expression>, Handle<Expression>)>| {
                    if let Some((a, b)) = run.take() {
                        out.push(Statement::Emit(Range::new_from_bounds(a, b)), span);
                    }
                };
                for h in range {
                    if let Some(call) = calls.remove(&h) {
                        flush(&mut out, &mut run);
                        out.push(call, span);
                    } else {
                        run = Some(match run {
                            Some((a, _)) => (a, h),
                            None => (h, h),
                        });
                    }
                }
                flush(&mut out, &mut run);
            }
            other => out.push(map_nested(other, &mut |b| rebuild(b, calls)), span),
        }
    }
    out
}

fn apply_to(
    f: &mut Function,
    sites: &[Site],
    helpers: &HashMap<String, Handle<Function>>,
    next_site: &mut u32,
) -> Result<usize, String> {
    let mut calls = HashMap::new();
    for s in sites {
        let Some(&function) = helpers.get(&s.helper) else {
            return Err(format!("helper {} is missing from the module", s.helper));
        };
        let number = if unnumbered(&s.helper) {
            0
        } else {
            *next_site = next_site.wrapping_add(1);
            *next_site
        };
        let id = f.expressions.append(
            Expression::Literal(Literal::U32(number.wrapping_mul(1 << 16))),
            Span::UNDEFINED,
        );
        let mut arguments = vec![id];
        arguments.extend(&s.operands);
        f.expressions[s.expr] = Expression::CallResult(function);
        calls.insert(
            s.expr,
            Statement::Call {
                function,
                arguments,
                result: Some(s.expr),
            },
        );
    }
    let n = calls.len();
    f.body = rebuild(std::mem::take(&mut f.body), &mut calls);
    if !calls.is_empty() {
        return Err("an emulated expression was not found in the function body".into());
    }
    Ok(n)
}

/// Where the emulation's call contexts come from: every call of one of the module's own
/// functions is bracketed by `prepass_cf_enter(k)` (a number unique to the call statement; it
/// returns the caller's context and makes `hash(context ^ k)` the current one) and
/// `prepass_cf_leave(saved)`. The searched policy's table is read at `hash(site ^ context)`, so
/// each call of a helper has its own slots: two calls of `pow` in one expression may round in
/// opposite directions, as they may on an adapter that inlines them.
struct CallContexts {
    enter: Handle<Function>,
    leave: Handle<Function>,
    /// The module's own functions (not the emulation's helpers).
    own: HashSet<Handle<Function>>,
}

fn with_call_contexts(
    block: Block,
    f: &mut naga::Arena<Expression>,
    cx: &CallContexts,
    next_call: &mut u32,
) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        match stmt {
            Statement::Call {
                function,
                arguments,
                result,
            } if cx.own.contains(&function) => {
                *next_call = next_call.wrapping_add(1);
                let k = f.append(
                    Expression::Literal(Literal::U32(next_call.wrapping_mul(0x9e37_79b9))),
                    Span::UNDEFINED,
                );
                let saved = f.append(Expression::CallResult(cx.enter), Span::UNDEFINED);
                out.push(
                    Statement::Call {
                        function: cx.enter,
                        arguments: vec![k],
                        result: Some(saved),
                    },
                    span,
                );
                out.push(
                    Statement::Call {
                        function,
                        arguments,
                        result,
                    },
                    span,
                );
                out.push(
                    Statement::Call {
                        function: cx.leave,
                        arguments: vec![saved],
                        result: None,
                    },
                    span,
                );
            }
            other => out.push(
                map_nested(other, &mut |b| with_call_contexts(b, f, cx, next_call)),
                span,
            ),
        }
    }
    out
}

/// Rewrite `module` (which holds the helper library) according to `plan`, and give every call
/// of the module's own functions its call context ([`CallContexts`]); returns the number of
/// sites rewritten.
pub fn apply(module: &mut Module, plan: &Plan) -> Result<usize, String> {
    let helpers: HashMap<String, Handle<Function>> = module
        .functions
        .iter()
        .filter_map(|(h, f)| f.name.clone().map(|n| (n, h)))
        .collect();
    let mut next_site = 0u32;
    let mut total = 0;
    let keys: Vec<(Option<Handle<Function>>, Option<usize>, String)> = module
        .functions
        .iter()
        .map(|(h, f)| (Some(h), None, function_key(module, f, None)))
        .chain(
            module
                .entry_points
                .iter()
                .enumerate()
                .map(|(i, ep)| (None, Some(i), function_key(module, &ep.function, Some(i)))),
        )
        .collect();
    for (fh, ep, key) in keys {
        let Some(sites) = plan.sites.get(&key) else {
            continue;
        };
        let f = match (fh, ep) {
            (Some(h), _) => &mut module.functions[h],
            (None, Some(i)) => &mut module.entry_points[i].function,
            _ => continue,
        };
        total += apply_to(f, sites, &helpers, &mut next_site)?;
    }
    let helper = |n: &str| {
        helpers
            .get(&format!("{PREFIX}{n}"))
            .copied()
            .ok_or_else(|| format!("helper {PREFIX}{n} is missing from the module"))
    };
    let cx = CallContexts {
        enter: helper("enter")?,
        leave: helper("leave")?,
        own: module
            .functions
            .iter()
            .filter(|(_, f)| f.name.as_deref().is_some_and(super::inline::is_own))
            .map(|(h, _)| h)
            .collect(),
    };
    let mut next_call = 0u32;
    for h in cx.own.iter().copied().collect::<BTreeSet<_>>() {
        let f = &mut module.functions[h];
        f.body = with_call_contexts(
            std::mem::take(&mut f.body),
            &mut f.expressions,
            &cx,
            &mut next_call,
        );
    }
    for ep in module.entry_points.iter_mut() {
        let f = &mut ep.function;
        f.body = with_call_contexts(
            std::mem::take(&mut f.body),
            &mut f.expressions,
            &cx,
            &mut next_call,
        );
    }
    Ok(total)
}

/// WGSL spelling of a parameter type, where it has one the wrapper can write.
pub fn wgsl_type(module: &Module, ty: Handle<naga::Type>) -> Option<String> {
    let t = &module.types[ty];
    let scalar = |s: naga::Scalar| -> Option<&'static str> {
        Some(match (s.kind, s.width) {
            (ScalarKind::Float, 4) => "f32",
            (ScalarKind::Float, 2) => "f16",
            (ScalarKind::Uint, 4) => "u32",
            (ScalarKind::Sint, 4) => "i32",
            (ScalarKind::Bool, _) => "bool",
            _ => return None,
        })
    };
    match t.inner {
        TypeInner::Scalar(s) => scalar(s).map(str::to_string),
        TypeInner::Vector { size, scalar: s } => {
            let n = match size {
                VectorSize::Bi => 2,
                VectorSize::Tri => 3,
                VectorSize::Quad => 4,
            };
            Some(format!("vec{n}<{}>", scalar(s)?))
        }
        TypeInner::Struct { .. } => t.name.clone(),
        _ => None,
    }
}
