//! Generates the compute entry point that applies a function to a batch.
//!
//! Every buffer is a flat `array<u32>` and values cross it as bits (`bitcast`), so vectors pack
//! tightly (no 16-byte `vec3` stride) and NaN payloads, infinities and signed zeros reach the
//! function exactly as given.

use super::signature::{Scalar, Signature, ValueType};
use std::fmt::Write as _;

/// How one argument is fed, per element.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feed {
    /// From a storage buffer, one value per element.
    Column,
    /// The same value for every element, from the uniform buffer (as a renderer's uniform).
    Splat,
    /// The element's index plus a start word, reinterpreted as the scalar type.
    Index,
}

/// Invocations per workgroup. 64 fits every adapter's limits.
pub const WORKGROUP_SIZE: u32 = 64;

/// Name of the generated entry point.
pub const ENTRY: &str = "prepass_harness_main";

/// Uniform layout: `count`, `row_stride`, two pad words, then one `vec4<u32>` slot per parameter
/// (a splat's value, or an index feed's start for this chunk).
pub fn uniform_words(param_count: usize) -> usize {
    4 + 4 * param_count.max(1)
}

fn read_bits(ty: ValueType, buffer: &str, index: &str) -> String {
    let w = ty.words();
    if w == 1 {
        return format!("{buffer}[{index}]");
    }
    let lanes: Vec<String> = (0..w)
        .map(|k| format!("{buffer}[{index} * {w}u + {k}u]"))
        .collect();
    format!("{}({})", ty.wgsl_bits(), lanes.join(", "))
}

fn slot_bits(ty: ValueType, slot: usize) -> String {
    let swizzle = ["x", "xy", "xyz", "xyzw"][ty.words() - 1];
    format!("prepass_h_params.slots[{slot}].{swizzle}")
}

/// WGSL of the bindings and entry point for `sig` with the given feeds (one per parameter).
/// Bindings, group 0: 0 = uniform parameters, 1.. = one storage buffer per column feed in
/// parameter order, last = the output buffer.
pub fn entry_point(sig: &Signature, feeds: &[Feed]) -> String {
    let mut s = String::new();
    let slots = sig.params.len().max(1);
    let _ = writeln!(
        s,
        "struct PrepassHarnessParams {{ count: u32, row_stride: u32, pad0: u32, pad1: u32, \
         slots: array<vec4<u32>, {slots}> }}"
    );
    let _ = writeln!(
        s,
        "@group(0) @binding(0) var<uniform> prepass_h_params: PrepassHarnessParams;"
    );
    let mut binding = 1;
    let mut args = Vec::new();
    let mut body = String::new();
    for (k, (p, feed)) in sig.params.iter().zip(feeds).enumerate() {
        let bits = match feed {
            Feed::Column => {
                let name = format!("prepass_h_in{k}");
                let _ = writeln!(
                    s,
                    "@group(0) @binding({binding}) var<storage, read> {name}: array<u32>;"
                );
                binding += 1;
                read_bits(p.ty, &name, "i")
            }
            Feed::Splat => slot_bits(p.ty, k),
            Feed::Index => format!("(prepass_h_params.slots[{k}].x + i)"),
        };
        let value = if p.ty.scalar == Scalar::U32 {
            bits
        } else {
            format!("bitcast<{}>({bits})", p.ty.wgsl())
        };
        let _ = writeln!(body, "    let a{k} = {value};");
        args.push(format!("a{k}"));
    }
    let _ = writeln!(
        s,
        "@group(0) @binding({binding}) var<storage, read_write> prepass_h_out: array<u32>;"
    );
    let w = sig.result.words();
    let _ = writeln!(
        body,
        "    let r = bitcast<{}>({}({}));",
        sig.result.wgsl_bits(),
        sig.function,
        args.join(", ")
    );
    if w == 1 {
        let _ = writeln!(body, "    prepass_h_out[i] = r;");
    } else {
        for (k, lane) in ["x", "y", "z", "w"].iter().take(w).enumerate() {
            let _ = writeln!(body, "    prepass_h_out[i * {w}u + {k}u] = r.{lane};");
        }
    }
    let _ = write!(
        s,
        "@compute @workgroup_size({WORKGROUP_SIZE})\n\
         fn {ENTRY}(@builtin(global_invocation_id) gid: vec3<u32>) {{\n\
         \x20   let i = gid.y * prepass_h_params.row_stride + gid.x;\n\
         \x20   if (i >= prepass_h_params.count) {{\n\
         \x20       return;\n\
         \x20   }}\n\
         {body}}}\n"
    );
    s
}
