//! `wgsl/roughness.wgsl` and `roughness`: the log-range specular exponent, with its exact
//! references.

use super::{Func, INF, NAN, NEG_NAN, Row, SUB_MAX, SUB_MIN, V};
use prepass::roughness as rough;

/// `roughness::range` as the WGSL's `log_roughness_range_log2` answers it: 0 degenerate, `L`
/// for `2^L`, `0xffffffff` for a general range.
fn range_code(r: rough::Range) -> u32 {
    match r {
        rough::Range::Degenerate => 0,
        rough::Range::PowerOfTwo(l) => l,
        rough::Range::General(_) => u32::MAX,
    }
}

pub const FUNCS: &[Func] = &[
    Func {
        rust: "roughness::range",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "log_roughness_range_log2")),
        twin: |a| V::U32(range_code(rough::range(a[0].f32()))),
    },
    func!(prepass::wgsl::ROUGHNESS; roughness; encode_log_roughness(f32, f32) -> U32),
    func!(prepass::wgsl::ROUGHNESS; roughness; decode_log_roughness(u32, f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS; roughness; pack_normal_xyz8_log_roughness(u32, u32) -> U32),
    func!(prepass::wgsl::ROUGHNESS; roughness; normal_xyz8_from_log_roughness_texel(u32) -> U32),
    func!(prepass::wgsl::ROUGHNESS; roughness; log_roughness_code_from_texel(u32) -> U32),
    func!(None; roughness; quantisation_limit(f64) -> F64),
    Func {
        rust: "roughness::exact::decode",
        wgsl: None,
        twin: |a| V::F64(rough::exact::decode(a[0].u32(), a[1].f64())),
    },
    Func {
        rust: "roughness::exact::encode",
        wgsl: None,
        twin: |a| V::U32(rough::exact::encode(a[0].f64(), a[1].f64())),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[(
    "log_roughness_boundary_bits",
    "private to roughness.wgsl: table lookup of a code boundary, exercised by the encode rows",
)];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Log roughness (max_power 8192 = 2^13 unless stated; power-of-two ranges are exact tables).
    Row { func: "log_roughness_range_log2", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(0), why: "degenerate: only power 1" },
    Row { func: "log_roughness_range_log2", case: "≤ 1 (1.0)", args: &[V::F32(1.0)], expect: V::U32(0), why: "degenerate: only power 1" },
    Row { func: "log_roughness_range_log2", case: "negative", args: &[V::F32(-8.0)], expect: V::U32(0), why: "degenerate" },
    Row { func: "log_roughness_range_log2", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(0), why: "degenerate (≤ 1)" },
    Row { func: "log_roughness_range_log2", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(127), why: "acts as 2^127" },
    Row { func: "log_roughness_range_log2", case: "out of range: above 2^127", args: &[V::F32(f32::MAX)], expect: V::U32(127), why: "acts as 2^127" },
    Row { func: "log_roughness_range_log2", case: "not a power of two", args: &[V::F32(1000.0)], expect: V::U32(u32::MAX), why: "general range (log2/exp2)" },
    Row { func: "encode_log_roughness", case: "NaN power", args: &[V::F32(NAN), V::F32(8192.0)], expect: V::U32(0), why: "code 0" },
    Row { func: "encode_log_roughness", case: "−NaN power, general range", args: &[V::F32(NEG_NAN), V::F32(1000.0)], expect: V::U32(0), why: "code 0" },
    Row { func: "encode_log_roughness", case: "+Inf power", args: &[V::F32(INF), V::F32(8192.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "+Inf power, general range", args: &[V::F32(INF), V::F32(1000.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "−Inf power", args: &[V::F32(-INF), V::F32(8192.0)], expect: V::U32(0), why: "negative → 0" },
    Row { func: "encode_log_roughness", case: "negative power", args: &[V::F32(-100.0), V::F32(8192.0)], expect: V::U32(0), why: "negative → 0" },
    Row { func: "encode_log_roughness", case: "subnormal power", args: &[V::F32(SUB_MAX), V::F32(8192.0)], expect: V::U32(0), why: "≤ 1 → 0" },
    Row { func: "encode_log_roughness", case: "zero power (−0.0)", args: &[V::F32(-0.0), V::F32(8192.0)], expect: V::U32(0), why: "≤ 1 → 0" },
    Row { func: "encode_log_roughness", case: "out of range: power above max", args: &[V::F32(1e9), V::F32(8192.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "out of range: f32::MAX, max_power +Inf", args: &[V::F32(f32::MAX), V::F32(INF)], expect: V::U32(255), why: "max_power acts as 2^127" },
    Row { func: "encode_log_roughness", case: "NaN max_power", args: &[V::F32(100.0), V::F32(NAN)], expect: V::U32(0), why: "degenerate range → 0" },
    Row { func: "encode_log_roughness", case: "out of range: max_power ≤ 1", args: &[V::F32(100.0), V::F32(0.5)], expect: V::U32(0), why: "degenerate range → 0" },
    Row { func: "decode_log_roughness", case: "out-of-range code 256", args: &[V::U32(256), V::F32(8192.0)], expect: V::F32(8192.0), why: "decodes as 255" },
    Row { func: "decode_log_roughness", case: "out-of-range code, general range", args: &[V::U32(u32::MAX), V::F32(1000.0)], expect: V::F32(1000.0), why: "decodes as 255 = max_power" },
    Row { func: "decode_log_roughness", case: "NaN max_power", args: &[V::U32(200), V::F32(NAN)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "−Inf max_power", args: &[V::U32(200), V::F32(-INF)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "subnormal max_power", args: &[V::U32(255), V::F32(SUB_MIN)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "+Inf max_power", args: &[V::U32(255), V::F32(INF)], expect: V::F32(1.7014118e38), why: "acts as 2^127" },
    Row { func: "pack_normal_xyz8_log_roughness", case: "out-of-range code, byte 3 set", args: &[V::U32(0xff12_3456), V::U32(999)], expect: V::U32(0xff12_3456), why: "byte 3 replaced; code saturates to 255" },
    Row { func: "pack_normal_xyz8_log_roughness", case: "out-of-range code u32::MAX", args: &[V::U32(0x0000_0080), V::U32(u32::MAX)], expect: V::U32(0xff00_0080), why: "code saturates to 255" },
    Row { func: "normal_xyz8_from_log_roughness_texel", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(0x00ff_ffff), why: "byte 3 dropped" },
    Row { func: "log_roughness_code_from_texel", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(255), why: "every texel holds a valid code" },
    Row { func: "roughness::quantisation_limit", case: "NaN", args: &[V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "propagates" },
    Row { func: "roughness::quantisation_limit", case: "max_power 1", args: &[V::F64(1.0)], expect: V::F64(0.0), why: "one code: no step" },
    Row { func: "roughness::quantisation_limit", case: "+Inf", args: &[V::F64(f64::INFINITY)], expect: V::F64(f64::INFINITY), why: "unbounded step" },
    Row { func: "roughness::exact::decode", case: "out-of-range code", args: &[V::U32(300), V::F64(8192.0)], expect: V::F64(8192.0), why: "decodes as 255, like the twin" },
    Row { func: "roughness::exact::decode", case: "NaN max_power", args: &[V::U32(10), V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "propagates (reference only)" },
    Row { func: "roughness::exact::encode", case: "NaN power", args: &[V::F64(f64::NAN), V::F64(8192.0)], expect: V::U32(0), why: "NaN casts to code 0" },
    Row { func: "roughness::exact::encode", case: "+Inf power", args: &[V::F64(f64::INFINITY), V::F64(8192.0)], expect: V::U32(255), why: "clamped to 255" },
    Row { func: "roughness::exact::encode", case: "out of range: power below 1", args: &[V::F64(0.25), V::F64(8192.0)], expect: V::U32(0), why: "clamped to 0" },
];
