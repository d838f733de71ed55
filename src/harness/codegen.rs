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
    entry_point_with_tail(sig, feeds, &[])
}

/// [`entry_point`] with `tail`: `u32` expressions evaluated after the call (a `var<private>`
/// the function set, say), each stored as one more word of the element's output after the
/// result's words. One pipeline then yields what would otherwise take a second compilation of
/// the same function.
pub fn entry_point_with_tail(sig: &Signature, feeds: &[Feed], tail: &[String]) -> String {
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
    let stride = w + tail.len();
    let _ = writeln!(
        body,
        "    let r = bitcast<{}>({}({}));",
        sig.result.wgsl_bits(),
        sig.function,
        args.join(", ")
    );
    if stride == 1 {
        let _ = writeln!(body, "    prepass_h_out[i] = r;");
    } else {
        for (k, lane) in ["x", "y", "z", "w"].iter().take(w).enumerate() {
            let value = if w == 1 {
                "r".to_string()
            } else {
                format!("r.{lane}")
            };
            let _ = writeln!(body, "    prepass_h_out[i * {stride}u + {k}u] = {value};");
        }
        for (j, e) in tail.iter().enumerate() {
            let _ = writeln!(body, "    prepass_h_out[i * {stride}u + {}u] = {e};", w + j);
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

/// What a timing entry point computes per invocation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimedBody {
    /// Call the function, as the harness's ordinary entry point does.
    Function,
    /// The empty-kernel baseline: load every argument exactly as [`TimedBody::Function`] does and
    /// store one word derived from them (XOR of their first lanes) in every result lane, without
    /// calling the function — same loads, same stores, no arithmetic.
    Baseline,
}

/// WGSL of a timing entry point: like [`entry_point`], but columns and the output are tiles of
/// `pad0 + 1` values (a power of two) indexed by `i & pad0`, so a dispatch of 2^24 invocations
/// needs only a tile of memory and its loads stay in cache. Invocations that share a slot
/// race on the store; nobody reads it back (WGSL makes the stored value indeterminate, nothing
/// worse).
pub fn timing_entry_point(sig: &Signature, feeds: &[Feed], body_kind: TimedBody) -> String {
    let plain = entry_point(sig, feeds);
    // Every buffer index in the body is `[i]` or `[i * W + k]` (columns and the output): read
    // and write the tile slot `t` instead. `i` itself still feeds `Arg::Index`.
    let mut s = plain
        .replace(
            "let i = gid.y * prepass_h_params.row_stride + gid.x;",
            "let i = gid.y * prepass_h_params.row_stride + gid.x;\n    let t = i & prepass_h_params.pad0;",
        )
        .replace("[i]", "[t]")
        .replace("[i * ", "[t * ");
    if body_kind == TimedBody::Function {
        return s;
    }
    // Baseline: replace the call with a word folded from the arguments' first lanes.
    let call = format!("{}(", sig.function);
    let line_start = s
        .find(&format!(
            "let r = bitcast<{}>({call}",
            sig.result.wgsl_bits()
        ))
        .expect("entry_point always emits the call line");
    let line_end = line_start + s[line_start..].find('\n').expect("line ends");
    let mut fold = String::from("0u");
    for (k, p) in sig.params.iter().enumerate() {
        let first = if p.ty.lanes == 1 {
            format!("a{k}")
        } else {
            format!("a{k}.x")
        };
        let bits = if p.ty.scalar == Scalar::U32 {
            first
        } else {
            format!("bitcast<u32>({first})")
        };
        fold = format!("({fold} ^ {bits})");
    }
    let replacement = format!("let r = {}({fold});", sig.result.wgsl_bits());
    s.replace_range(line_start..line_end, &replacement);
    s
}
