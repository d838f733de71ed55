//! A device-independent cost of a WGSL function: how many instructions naga's SPIR-V backend
//! (the translation wgpu hands to Vulkan drivers) emits for it.
//!
//! The count is static, not dynamic: every instruction of the function's body is counted once,
//! whether it sits in a branch taken or not, plus the bodies of every function it calls,
//! directly or indirectly (each callee once, however often it is called). Not counted: the
//! bookkeeping that executes nothing — `OpFunction`, `OpFunctionParameter`, `OpFunctionEnd`,
//! `OpLabel`, `OpVariable` (function-local storage declarations) and debug line markers.
//! Constants live at module level in SPIR-V and are free here. naga emits the same safety
//! checks wgpu asks for by default (index clamping, integer-division guards), so those count.
//!
//! It ranks functions by how much code a driver receives; a driver's compiler then folds,
//! fuses and schedules, so it is a proxy for run time, not a measure of it.

use super::naga_check::{WgslError, parse_and_validate};
use naga::back::spv;
use std::collections::{BTreeSet, HashMap};

/// The SPIR-V size of one function.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpirvCost {
    /// The function measured.
    pub function: String,
    /// Instructions of its own body.
    pub own: usize,
    /// Instructions of its body and of every function it reaches by calls.
    pub total: usize,
    /// Names of the functions it reaches by calls, sorted.
    pub callees: Vec<String>,
}

const OP_NAME: u32 = 5;
const OP_LINE: u32 = 8;
const OP_FUNCTION: u32 = 54;
const OP_FUNCTION_PARAMETER: u32 = 55;
const OP_FUNCTION_END: u32 = 56;
const OP_FUNCTION_CALL: u32 = 57;
const OP_VARIABLE: u32 = 59;
const OP_LABEL: u32 = 248;
const OP_NO_LINE: u32 = 317;

/// A SPIR-V literal string: UTF-8, NUL-terminated, packed little-endian into words.
fn literal_string(words: &[u32]) -> String {
    let bytes: Vec<u8> = words
        .iter()
        .flat_map(|w| w.to_le_bytes())
        .take_while(|&b| b != 0)
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

struct Body {
    counted: usize,
    calls: Vec<u32>,
}

/// The SPIR-V instruction count of `function` in `source` (valid WGSL on its own), counted as
/// the module docs say: its own body plus the bodies of all the functions it calls.
///
/// ```
/// let cost = prepass::wgsl::spirv_instruction_count(prepass::wgsl::DEPTH24, "pack_depth24")?;
/// assert!(cost.total > 0 && cost.callees.is_empty());
/// # Ok::<(), prepass::wgsl::WgslError>(())
/// ```
pub fn spirv_instruction_count(source: &str, function: &str) -> Result<SpirvCost, WgslError> {
    let checked = parse_and_validate(source)?;
    let mut options = spv::Options::default();
    // OpName is how the function is found again in the binary.
    options.flags |= spv::WriterFlags::DEBUG;
    let words =
        spv::write_vec(&checked.module, &checked.info, &options, None).map_err(|e| WgslError {
            stage: "spirv",
            message: e.to_string(),
        })?;

    let mut names: HashMap<u32, String> = HashMap::new();
    let mut bodies: HashMap<u32, Body> = HashMap::new();
    let mut current: Option<u32> = None;
    let mut at = 5; // after the header
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        let op = words[at] & 0xffff;
        if count == 0 || at + count > words.len() {
            return Err(WgslError {
                stage: "spirv",
                message: format!("malformed instruction at word {at}"),
            });
        }
        let operands = &words[at + 1..at + count];
        match op {
            OP_NAME => {
                names.insert(operands[0], literal_string(&operands[1..]));
            }
            OP_FUNCTION => {
                let id = operands[1];
                bodies.insert(
                    id,
                    Body {
                        counted: 0,
                        calls: Vec::new(),
                    },
                );
                current = Some(id);
            }
            OP_FUNCTION_END => current = None,
            OP_FUNCTION_PARAMETER | OP_LABEL | OP_VARIABLE | OP_LINE | OP_NO_LINE => {}
            _ => {
                if let Some(body) = current.and_then(|id| bodies.get_mut(&id)) {
                    body.counted += 1;
                    if op == OP_FUNCTION_CALL {
                        body.calls.push(operands[2]);
                    }
                }
            }
        }
        at += count;
    }

    let root = bodies
        .keys()
        .copied()
        .find(|id| names.get(id).is_some_and(|n| n == function))
        .ok_or_else(|| WgslError {
            stage: "spirv",
            message: format!("no function `{function}` in the SPIR-V naga emitted"),
        })?;
    let mut seen = BTreeSet::from([root]);
    let mut stack = vec![root];
    let mut total = 0;
    while let Some(id) = stack.pop() {
        let body = &bodies[&id];
        total += body.counted;
        for &callee in &body.calls {
            if seen.insert(callee) {
                stack.push(callee);
            }
        }
    }
    let mut callees: Vec<String> = seen
        .iter()
        .filter(|&&id| id != root)
        .map(|id| names.get(id).cloned().unwrap_or_else(|| format!("%{id}")))
        .collect();
    callees.sort();
    Ok(SpirvCost {
        function: function.to_string(),
        own: bodies[&root].counted,
        total,
        callees,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn callees_are_counted_once_each() {
        let src = "fn leaf(x: f32) -> f32 { return x * x + 1.0; }\n\
                   fn mid(x: f32) -> f32 { return leaf(x) + leaf(x * 2.0); }\n\
                   fn top(x: f32) -> f32 { return mid(x) - leaf(x); }\n";
        let leaf = spirv_instruction_count(src, "leaf").unwrap();
        let mid = spirv_instruction_count(src, "mid").unwrap();
        let top = spirv_instruction_count(src, "top").unwrap();
        assert!(leaf.callees.is_empty());
        assert_eq!(mid.callees, ["leaf"]);
        assert_eq!(mid.total, mid.own + leaf.own);
        assert_eq!(top.callees, ["leaf", "mid"]);
        assert_eq!(top.total, top.own + mid.own + leaf.own);
        // leaf: two arithmetic instructions and a return at least.
        assert!(leaf.own >= 3, "{leaf:?}");
    }

    #[test]
    fn unknown_function_is_an_error() {
        let e = spirv_instruction_count("fn f() -> u32 { return 1u; }", "g").unwrap_err();
        assert!(e.message.contains("`g`"), "{e}");
    }
}
