//! The freedoms a compiler took, read from its disassembly: fused multiply-adds, division as
//! reciprocal × numerator, hardware `inverseSqrt`/`sqrt`/`exp2`/`log2`, conversions, DX9
//! multiplies that assume finite operands. Each is a freedom the WGSL spec grants, and each must
//! be one [`crate::conforming`] models ([`Freedoms`]) for the emulated worst conforming adapter
//! to cover what this compiler does; an instruction that is neither exact nor a known freedom is
//! reported as [`Taken::Unknown`], so a new compiler's new trick is found rather than assumed.
//!
//! Reassociation and subnormal flushing leave no instruction of their own and are not read
//! here.

use super::target::Vendor;
use crate::conforming::Freedoms;
use std::collections::BTreeMap;

/// What one instruction kind means for precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Taken {
    /// A freedom of the WGSL spec that [`crate::conforming`] emulates.
    Freedom(Freedoms),
    /// The finite-math freedom (an implementation may assume no ±∞ or NaN, e.g. `0 · x = 0`
    /// for every `x`): not emulated; prepass's functions meet it by reading special inputs from
    /// their bits, and no test asserts a non-finite intermediate.
    FiniteMath,
    /// A freedom the spec grants that the emulation does not model (`tan`, `atan2`, …).
    Unmodelled,
    /// A float instruction this table does not know: classify it before trusting a figure.
    Unknown,
}

/// One kind of instruction seen, how often, and what it means.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Observed {
    /// The opcode as the disassembly spells it (`v_fmac_f32`, `mad`, `math inv`).
    pub opcode: String,
    /// How many times it occurs.
    pub count: usize,
    /// Its class.
    pub taken: Taken,
    /// The freedom in words.
    pub what: &'static str,
}

fn amd(op: &str) -> Option<(Taken, &'static str)> {
    // Encoding suffixes (`_e32`, `_e64`, `_dpp`, `_sdwa`) say nothing about the maths.
    let op = op
        .trim_end_matches("_e32")
        .trim_end_matches("_e64")
        .trim_end_matches("_dpp")
        .trim_end_matches("_sdwa");
    let float = op.contains("_f32") || op.contains("_f16") || op.contains("_f64");
    if !float || !op.starts_with("v_") {
        return None;
    }
    let fused = [
        "v_fma_f32",
        "v_fmac_f32",
        "v_fmaak_f32",
        "v_fmamk_f32",
        "v_mad_f32",
        "v_mac_f32",
        "v_madak_f32",
        "v_madmk_f32",
        "v_pk_fma_f32",
        "v_fma_mix_f32",
    ];
    let legacy = [
        "v_mul_legacy_f32",
        "v_mad_legacy_f32",
        "v_mac_legacy_f32",
        "v_fma_legacy_f32",
        "v_fmac_legacy_f32",
    ];
    let exact_prefixes = [
        "v_add_f32",
        "v_sub_f32",
        "v_subrev_f32",
        "v_mul_f32",
        "v_min_f32",
        "v_max_f32",
        "v_min3_f32",
        "v_max3_f32",
        "v_med3_f32",
        "v_floor_f32",
        "v_ceil_f32",
        "v_trunc_f32",
        "v_rndne_f32",
        "v_fract_f32",
        "v_cmp_",
        "v_cmpx_",
        "v_frexp_",
        "v_ldexp_f32",
        "v_cvt_u32_f32",
        "v_cvt_i32_f32",
        "v_cvt_flr_i32_f32",
        "v_cvt_rpi_i32_f32",
        "v_cvt_f32_ubyte",
        "v_cvt_f32_f16",
        "v_pk_mul_f32",
        "v_pk_add_f32",
        "v_rcp_iflag_f32",
        "v_mov_b32",
    ];
    Some(if legacy.contains(&op) {
        (
            Taken::FiniteMath,
            "DX9 multiply: 0 · x = 0 even for x = ±∞ or NaN (finite math)",
        )
    } else if fused.contains(&op) {
        (Taken::Freedom(Freedoms::FUSION), "a·b + c fused")
    } else if op.starts_with("v_rcp_f32") || op.starts_with("v_div_") {
        (
            Taken::Freedom(Freedoms::DIVISION),
            "division as reciprocal × numerator (2.5 ULP)",
        )
    } else if op == "v_rsq_f32" {
        (
            Taken::Freedom(Freedoms::INVERSE_SQRT),
            "hardware inverseSqrt",
        )
    } else if op == "v_sqrt_f32" {
        (Taken::Freedom(Freedoms::INHERITED), "hardware sqrt")
    } else if op == "v_exp_f32" || op == "v_log_f32" {
        (Taken::Freedom(Freedoms::EXP_LOG), "hardware exp2 / log2")
    } else if op == "v_cvt_f32_u32" || op == "v_cvt_f32_i32" {
        (
            Taken::Freedom(Freedoms::CONVERSION),
            "f32 of an integer (either neighbour)",
        )
    } else if op.starts_with("v_cvt_pk") || op == "v_cvt_f16_f32" {
        (
            Taken::Freedom(Freedoms::PACK),
            "packing to f16 or normalised integers (either neighbour)",
        )
    } else if op == "v_sin_f32" || op == "v_cos_f32" {
        (
            Taken::Freedom(Freedoms::TRIG),
            "hardware sin / cos (2^-11 absolute on [−π, π])",
        )
    } else if exact_prefixes.iter().any(|p| op.starts_with(p)) {
        return None;
    } else {
        (Taken::Unknown, "float instruction not classified")
    })
}

fn intel(line: &str) -> Option<(String, Taken, &'static str)> {
    let mut words = line.split_whitespace().peekable();
    // A predicate comes first when there is one: `(+f0.0) sel(16) …`.
    if words.peek()?.starts_with('(') {
        words.next();
    }
    let first = words.next()?;
    // `mad(16)`, `math inv(16)`, `cmp.l.f0.0(16)`: the opcode is before the execution size.
    let op = first.split(['(', '.']).next()?;
    let (op, rest) = if op == "math" {
        let f = words.next()?;
        (
            format!("math {}", f.split('(').next()?),
            words.collect::<Vec<_>>(),
        )
    } else {
        (op.to_string(), words.collect::<Vec<_>>())
    };
    let dest_type = rest
        .first()
        .map_or("", |d| d.rsplit('>').next().unwrap_or(""));
    let src_types: Vec<&str> = rest
        .iter()
        .skip(1)
        .take_while(|w| !w.starts_with('{'))
        .map(|w| w.rsplit('>').next().unwrap_or(""))
        .collect();
    let is_float = |t: &str| t == "F" || t == "HF" || t == "DF";
    let float = is_float(dest_type) || src_types.iter().any(|t| is_float(t));
    if !float {
        return None;
    }
    let taken = match op.as_str() {
        "mad" | "lrp" => (Taken::Freedom(Freedoms::FUSION), "a·b + c fused"),
        "math inv" | "math fdiv" => (
            Taken::Freedom(Freedoms::DIVISION),
            "division as reciprocal × numerator (2.5 ULP)",
        ),
        "math rsq" => (
            Taken::Freedom(Freedoms::INVERSE_SQRT),
            "hardware inverseSqrt",
        ),
        "math sqrt" => (Taken::Freedom(Freedoms::INHERITED), "hardware sqrt"),
        "math exp" | "math log" | "math pow" => {
            (Taken::Freedom(Freedoms::EXP_LOG), "hardware exp2 / log2")
        }
        "math sin" | "math cos" => (
            Taken::Freedom(Freedoms::TRIG),
            "hardware sin / cos (2^-11 absolute on [−π, π])",
        ),
        "mov" if is_float(dest_type) && !src_types.iter().any(|t| is_float(t)) => (
            Taken::Freedom(Freedoms::CONVERSION),
            "f32 of an integer (either neighbour)",
        ),
        "mov" if dest_type == "HF" => (
            Taken::Freedom(Freedoms::PACK),
            "packing to f16 (either neighbour)",
        ),
        "f32to16" => (
            Taken::Freedom(Freedoms::PACK),
            "packing to f16 (either neighbour)",
        ),
        "add" | "mul" | "sel" | "csel" | "cmp" | "rndd" | "rnde" | "rndz" | "rndu" | "frc"
        | "mov" | "f16to32" | "and" | "or" | "xor" | "not" => return None,
        _ => (Taken::Unknown, "float instruction not classified"),
    };
    Some((op, taken.0, taken.1))
}

/// The non-exact instructions of a disassembly as [`super::Costing::disassembly`] returns it
/// (the final assembly only: ACO's `Assembly`, brw's `… Assembly` section), by opcode.
pub fn observed(vendor: Vendor, disassembly: &str) -> Vec<Observed> {
    let mut in_asm = false;
    let mut seen: BTreeMap<String, (usize, Taken, &'static str)> = BTreeMap::new();
    for line in disassembly.lines() {
        if let Some(name) = line.strip_prefix("== ") {
            in_asm = name.ends_with("Assembly");
            continue;
        }
        if !in_asm {
            continue;
        }
        let code = line.split(';').next().unwrap_or("").trim();
        let found = match vendor {
            Vendor::Amd => code
                .split_whitespace()
                .next()
                .and_then(|op| amd(op).map(|(t, w)| (op.to_string(), t, w))),
            Vendor::Intel => intel(code),
        };
        if let Some((op, taken, what)) = found {
            let op = op
                .trim_end_matches("_e32")
                .trim_end_matches("_e64")
                .to_string();
            seen.entry(op).or_insert((0, taken, what)).0 += 1;
        }
    }
    seen.into_iter()
        .map(|(opcode, (count, taken, what))| Observed {
            opcode,
            count,
            taken,
            what,
        })
        .collect()
}
