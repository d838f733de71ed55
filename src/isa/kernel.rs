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

/// A library's witness kernel: every function whose signature the harness reads
/// ([`Signature::read`]) called once on arguments loaded from one storage buffer (each
/// argument its own words), the XOR of every result's bits stored, so that no call is dead.
/// Returns the kernel and the functions it calls.
pub(crate) fn library(user: &str) -> Result<(Wrapped, Vec<String>), String> {
    let checked = crate::wgsl::parse_and_validate(user).map_err(|e| e.to_string())?;
    let mut body = String::from("    var acc = 0u;\n");
    let mut names = Vec::new();
    let mut word = 0usize;
    for (_, f) in checked.module.functions.iter() {
        let Some(name) = &f.name else { continue };
        let Ok(sig) = Signature::read(user, name) else {
            continue;
        };
        let mut args = Vec::new();
        for p in &sig.params {
            let bits = lane_read(p.ty, "prepass_isa_lib_in", &format!("{word}u + gid.x"));
            word += p.ty.words();
            args.push(if p.ty.scalar == Scalar::U32 {
                bits
            } else {
                format!("bitcast<{}>({bits})", p.ty.wgsl())
            });
        }
        let r = format!(
            "bitcast<{}>({name}({}))",
            sig.result.wgsl_bits(),
            args.join(", ")
        );
        let _ = writeln!(body, "    {{ let r = {r};");
        for lane in 0..sig.result.words() {
            let v = if sig.result.words() == 1 {
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
    Ok((
        Wrapped {
            source,
            bindings: "rw".into(),
        },
        names,
    ))
}
