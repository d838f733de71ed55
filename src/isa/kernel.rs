//! The compute kernels a function is costed in: the harness's reading of its signature and
//! its feeds, with `k` independent evaluations per invocation, and a baseline kernel with the
//! same loads and stores that evaluates nothing.

use crate::harness::{Feed, Scalar, Signature, ValueType, WORKGROUP_SIZE};
use std::fmt::Write as _;

/// Name of the generated entry point.
pub const ENTRY: &str = "prepass_isa_main";

/// The generated WGSL and its bindings (one letter each, as the child expects them).
pub(crate) struct Wrapped {
    pub source: String,
    pub bindings: String,
}

fn lane_read(ty: ValueType, buffer: &str, index: &str) -> String {
    let w = ty.words();
    if w == 1 {
        return format!("{buffer}[{index}]");
    }
    let lanes: Vec<String> = (0..w)
        .map(|k| format!("{buffer}[({index}) * {w}u + {k}u]"))
        .collect();
    format!("{}({})", ty.wgsl_bits(), lanes.join(", "))
}

/// Wrap `sig`'s function: `k` evaluations per invocation, each on its own element of every
/// column (indices `gid.x · k + j`), splats read from one uniform. `evaluate = false` gives the
/// baseline: the same loads, and per evaluation the XOR of the arguments' first lanes stored in
/// every result lane, so loads and stores match and nothing else is computed.
pub(crate) fn wrap(user: &str, sig: &Signature, feeds: &[Feed], k: u32, evaluate: bool) -> Wrapped {
    let mut s = String::new();
    let mut bindings = String::new();
    let splats = feeds.iter().filter(|f| **f == Feed::Splat).count();
    if splats > 0 {
        let _ = writeln!(
            s,
            "struct PrepassIsaParams {{ slots: array<vec4<u32>, {}> }}\n\
             @group(0) @binding(0) var<uniform> prepass_isa_params: PrepassIsaParams;",
            sig.params.len()
        );
        bindings.push('u');
    }
    for (p, feed) in feeds.iter().enumerate() {
        if *feed != Feed::Splat {
            let _ = writeln!(
                s,
                "@group(0) @binding({}) var<storage, read> prepass_isa_in{p}: array<u32>;",
                bindings.len()
            );
            bindings.push('r');
        }
    }
    let _ = writeln!(
        s,
        "@group(0) @binding({}) var<storage, read_write> prepass_isa_out: array<u32>;",
        bindings.len()
    );
    bindings.push('w');
    let w = sig.result.words();
    let _ = writeln!(
        s,
        "@compute @workgroup_size({WORKGROUP_SIZE})\nfn {ENTRY}(@builtin(global_invocation_id) gid: vec3<u32>) {{"
    );
    for j in 0..k {
        let index = format!("gid.x * {k}u + {j}u");
        let mut args = Vec::new();
        let mut fold = String::from("0u");
        for (p, (param, feed)) in sig.params.iter().zip(feeds).enumerate() {
            let bits = match feed {
                Feed::Splat => {
                    let swizzle = ["x", "xy", "xyz", "xyzw"][param.ty.words() - 1];
                    format!("prepass_isa_params.slots[{p}].{swizzle}")
                }
                // An index feed is a column here: the cost of a function does not depend on
                // where its argument came from, and a computed index would add ALU work.
                _ => lane_read(param.ty, &format!("prepass_isa_in{p}"), &index),
            };
            let value = if param.ty.scalar == Scalar::U32 {
                bits
            } else {
                format!("bitcast<{}>({bits})", param.ty.wgsl())
            };
            let _ = writeln!(s, "    let a{p}_{j} = {value};");
            args.push(format!("a{p}_{j}"));
            let first = if param.ty.lanes == 1 {
                format!("a{p}_{j}")
            } else {
                format!("a{p}_{j}.x")
            };
            let first = if param.ty.scalar == Scalar::U32 {
                first
            } else {
                format!("bitcast<u32>({first})")
            };
            fold = format!("({fold} ^ {first})");
        }
        let value = if evaluate {
            format!(
                "bitcast<{}>({}({}))",
                sig.result.wgsl_bits(),
                sig.function,
                args.join(", ")
            )
        } else {
            format!("{}({fold})", sig.result.wgsl_bits())
        };
        let _ = writeln!(s, "    let r{j} = {value};");
        for lane in 0..w {
            let v = if w == 1 {
                format!("r{j}")
            } else {
                format!("r{j}.{}", ["x", "y", "z", "w"][lane])
            };
            let _ = writeln!(s, "    prepass_isa_out[({index}) * {w}u + {lane}u] = {v};");
        }
    }
    s.push_str("}\n");
    Wrapped {
        source: format!("{user}\n{s}"),
        bindings,
    }
}

/// A call's arguments, each as the values loaded for it and, for a matrix, the type its
/// columns build.
type Args = Vec<(Vec<ValueType>, Option<String>)>;

/// [`library`]'s kernel, the functions it calls, and those it leaves out with why.
type Library = (Wrapped, Vec<String>, Vec<(String, String)>);

/// A library's witness kernel: every function whose signature the harness reads
/// ([`Signature::read`]) called once on arguments loaded from one storage buffer (each
/// argument its own words), the XOR of every result's bits stored, so that no call is dead.
/// Returns the kernel, the functions it calls, and the functions it cannot call that none of
/// those calls either (each with why it cannot call it): the ones the kernel leaves out.
pub(crate) fn library(user: &str) -> Result<Library, String> {
    let checked = crate::wgsl::parse_and_validate(user).map_err(|e| e.to_string())?;
    let mut body = String::from("    var acc = 0u;\n");
    let mut names = Vec::new();
    let mut uncallable = Vec::new();
    let mut word = 0usize;
    for (_, f) in checked.module.functions.iter() {
        let Some(name) = &f.name else { continue };
        // Each argument as the values it is built from (a matrix: its columns).
        let (parts, result): (Args, ValueType) = match Signature::read_parsed(&checked.module, name)
        {
            Ok(sig) => (
                sig.params.iter().map(|p| (vec![p.ty], None)).collect(),
                sig.result,
            ),
            Err(why) => match with_matrices(&checked.module, f) {
                Some(read) => read,
                None => {
                    uncallable.push((name.clone(), why.to_string()));
                    continue;
                }
            },
        };
        let mut args = Vec::new();
        for (values, matrix) in parts {
            let mut loaded = Vec::new();
            for ty in values {
                let bits = lane_read(ty, "prepass_isa_lib_in", &format!("{word}u + gid.x"));
                word += ty.words();
                loaded.push(if ty.scalar == Scalar::U32 {
                    bits
                } else {
                    format!("bitcast<{}>({bits})", ty.wgsl())
                });
            }
            args.push(match matrix {
                Some(m) => format!("{m}({})", loaded.join(", ")),
                None => loaded.remove(0),
            });
        }
        let r = format!(
            "bitcast<{}>({name}({}))",
            result.wgsl_bits(),
            args.join(", ")
        );
        let _ = writeln!(body, "    {{ let r = {r};");
        for lane in 0..result.words() {
            let v = if result.words() == 1 {
                "r".to_string()
            } else {
                format!("r.{}", ["x", "y", "z", "w"][lane])
            };
            let _ = writeln!(body, "    acc ^= {v};");
        }
        body.push_str("    }\n");
        names.push(name.clone());
    }
    let source = format!(
        "{user}\n@group(0) @binding(0) var<storage, read> prepass_isa_lib_in: array<u32>;\n\
         @group(0) @binding(1) var<storage, read_write> prepass_isa_out: array<u32>;\n\
         @compute @workgroup_size({WORKGROUP_SIZE})\n\
         fn {ENTRY}(@builtin(global_invocation_id) gid: vec3<u32>) {{\n{body}    prepass_isa_out[gid.x] = acc;\n}}\n"
    );
    let reached = reachable(&checked.module, &names);
    uncallable.retain(|(name, _)| !reached.contains(name));
    Ok((
        Wrapped {
            source,
            bindings: "rw".into(),
        },
        names,
        uncallable,
    ))
}

/// `f`'s parameters and result where [`Signature::read`] refuses only its `f32` matrix
/// parameters (`world_ray` takes a camera rotation): each parameter as the values it is built
/// from, with the matrix type that builds it from its columns.
fn with_matrices(module: &naga::Module, f: &naga::Function) -> Option<(Args, ValueType)> {
    use naga::{ScalarKind, TypeInner};
    let value = |inner: &TypeInner| {
        let (s, lanes) = match inner {
            TypeInner::Scalar(s) => (*s, 1u8),
            TypeInner::Vector { size, scalar } => (*scalar, *size as u8),
            _ => return None,
        };
        let scalar = match (s.kind, s.width) {
            (ScalarKind::Float, 4) => Scalar::F32,
            (ScalarKind::Uint, 4) => Scalar::U32,
            (ScalarKind::Sint, 4) => Scalar::I32,
            _ => return None,
        };
        Some(ValueType { scalar, lanes })
    };
    let mut params = Vec::new();
    for a in &f.arguments {
        let inner = &module.types[a.ty].inner;
        params.push(match inner {
            TypeInner::Matrix {
                columns,
                rows,
                scalar,
            } if *scalar == naga::Scalar::F32 => {
                let (c, r) = (*columns as u8, *rows as u8);
                let column = ValueType {
                    scalar: Scalar::F32,
                    lanes: r,
                };
                (
                    vec![column; usize::from(c)],
                    Some(format!("mat{c}x{r}<f32>")),
                )
            }
            _ => (vec![value(inner)?], None),
        });
    }
    let result = value(&module.types[f.result.as_ref()?.ty].inner)?;
    Some((params, result))
}

/// The functions `roots` call, directly or not, roots included.
fn reachable(module: &naga::Module, roots: &[String]) -> std::collections::BTreeSet<String> {
    fn calls(block: &naga::Block, out: &mut Vec<naga::Handle<naga::Function>>) {
        use naga::Statement as S;
        for st in block.iter() {
            match st {
                S::Call { function, .. } => out.push(*function),
                S::Block(b) => calls(b, out),
                S::If { accept, reject, .. } => {
                    calls(accept, out);
                    calls(reject, out);
                }
                S::Switch { cases, .. } => cases.iter().for_each(|c| calls(&c.body, out)),
                S::Loop {
                    body, continuing, ..
                } => {
                    calls(body, out);
                    calls(continuing, out);
                }
                _ => {}
            }
        }
    }
    let mut seen = std::collections::BTreeSet::new();
    let mut todo: Vec<_> = module
        .functions
        .iter()
        .filter(|(_, f)| f.name.as_ref().is_some_and(|n| roots.contains(n)))
        .map(|(h, _)| h)
        .collect();
    while let Some(h) = todo.pop() {
        let f = &module.functions[h];
        if seen.insert(f.name.clone().unwrap_or_default()) {
            calls(&f.body, &mut todo);
        }
    }
    seen
}
