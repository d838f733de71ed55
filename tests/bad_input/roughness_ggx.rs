//! `wgsl/roughness_ggx.wgsl` and `roughness_ggx`: GGX perceptual roughness in 8 bits (linear r,
//! Godot's 7 bits + flag, the log curve), with its exact references.

use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};
use prepass::roughness_ggx as ggx;

/// The channel value of byte 127 and 128 (`b/255`, correctly rounded).
const B127: f32 = 127.0 / 255.0;
const B128: f32 = 128.0 / 255.0;
/// The log curve's smallest roughness, `2^-6`.
const LOG_MIN: f32 = 0.015625;

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_ggx8(f32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8_alpha(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_ggx8_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_urp8(f32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_urp8(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_urp8_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_urp8_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_substrate8(f32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_substrate8(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_godot8(f32, u32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_godot8(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; roughness_godot8_is_dynamic(u32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_godot8_unorm(f32, u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_godot8_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_ggx8_log(f32) -> U32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8_log(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8_log_alpha(u32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; encode_roughness_ggx8_log_unorm(f32) -> F32),
    func!(prepass::wgsl::ROUGHNESS_GGX; roughness_ggx; decode_roughness_ggx8_log_unorm(f32) -> F32),
    Func {
        rust: "roughness_ggx::exact::linear_code",
        wgsl: None,
        twin: |a| V::U32(ggx::exact::linear_code(a[0].f64(), a[1].u32())),
    },
    Func {
        rust: "roughness_ggx::exact::log_code",
        wgsl: None,
        twin: |a| V::U32(ggx::exact::log_code(a[0].f64())),
    },
    Func {
        rust: "roughness_ggx::exact::ggx_d",
        wgsl: None,
        twin: |a| V::F64(ggx::exact::ggx_d(a[0].f64(), a[1].f64())),
    },
    Func {
        rust: "roughness_ggx::bounds::lobe_relative",
        wgsl: None,
        twin: |a| V::F64(ggx::bounds::lobe_relative(a[0].f64(), a[1].f64())),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "ggx_linear_code",
        "private to roughness_ggx.wgsl: the exact linear quantiser, exercised by the encode rows",
    ),
    (
        "ggx_unorm_byte",
        "private to roughness_ggx.wgsl: a channel's byte, exercised by the _unorm decode rows",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Linear r (the engines' byte).
    Row { func: "encode_roughness_ggx8", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(255), why: "roughest code (r = 1), read from the bits" },
    Row { func: "encode_roughness_ggx8", case: "−NaN, signalling", args: &[V::F32(NEG_NAN)], expect: V::U32(255), why: "every NaN → roughest" },
    Row { func: "encode_roughness_ggx8", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(255), why: "clamped to 1" },
    Row { func: "encode_roughness_ggx8", case: "−Inf", args: &[V::F32(-INF)], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "encode_roughness_ggx8", case: "negative", args: &[V::F32(-0.3)], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "encode_roughness_ggx8", case: "−0.0", args: &[V::F32(-0.0)], expect: V::U32(0), why: "r = 0" },
    Row { func: "encode_roughness_ggx8", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(0), why: "nearest code 0 (flushed or not)" },
    Row { func: "encode_roughness_ggx8", case: "out of range: above 1", args: &[V::F32(1.5)], expect: V::U32(255), why: "clamped to 1" },
    Row { func: "encode_roughness_ggx8", case: "the one tie, r = 1/2", args: &[V::F32(0.5)], expect: V::U32(128), why: "127.5 → upwards" },
    Row { func: "decode_roughness_ggx8", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(1.0), why: "decodes as 255" },
    Row { func: "decode_roughness_ggx8", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "decodes as 255" },
    Row { func: "decode_roughness_ggx8_alpha", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(1.0), why: "decodes as 255: α = 1" },
    Row { func: "encode_roughness_urp8", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(0), why: "smoothness 0: the roughest (r = 1), read from the bits" },
    Row { func: "encode_roughness_urp8", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(0), why: "r clamped to 1: smoothness 0" },
    Row { func: "encode_roughness_urp8", case: "negative", args: &[V::F32(-0.3)], expect: V::U32(255), why: "r clamped to 0: smoothness 1" },
    Row { func: "encode_roughness_urp8", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(255), why: "r's nearest code 0 (flushed or not): smoothness 255" },
    Row { func: "encode_roughness_urp8", case: "the one tie, r = 1/2", args: &[V::F32(0.5)], expect: V::U32(127), why: "255 − 128: the tie towards the rougher code" },
    Row { func: "decode_roughness_urp8", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(0.0), why: "decodes as 255: smoothness 1, r = 0" },
    Row { func: "decode_roughness_urp8", case: "byte 0", args: &[V::U32(0)], expect: V::F32(1.0), why: "smoothness 0: r = 1" },
    Row { func: "encode_roughness_urp8_unorm", case: "NaN", args: &[V::F32(SNAN)], expect: V::F32(0.0), why: "byte 0" },
    Row { func: "encode_roughness_urp8_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(1.0), why: "byte 255" },
    Row { func: "decode_roughness_urp8_unorm", case: "NaN", args: &[V::F32(NAN)], expect: V::F32(1.0), why: "NaN channel counts as 0: smoothness 0, r = 1" },
    Row { func: "decode_roughness_urp8_unorm", case: "+Inf", args: &[V::F32(INF)], expect: V::F32(0.0), why: "clamped to 1: r = 0" },
    Row { func: "encode_roughness_substrate8", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(255), why: "roughest code, read from the bits (Unreal's saturate(NaN) is the GPU's)" },
    Row { func: "encode_roughness_substrate8", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(255), why: "clamped to 1" },
    Row { func: "encode_roughness_substrate8", case: "−Inf", args: &[V::F32(-INF)], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "encode_roughness_substrate8", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(0), why: "truncated to 0 (flushed or not)" },
    Row { func: "encode_roughness_substrate8", case: "just below 1", args: &[V::F32(0.999_999_94)], expect: V::U32(254), why: "PackR8 truncates: 254.99998 → 254" },
    Row { func: "decode_roughness_substrate8", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(1.0), why: "decodes as 255: 255·fl(1/255) rounds to 1" },
    Row { func: "encode_roughness_ggx8_unorm", case: "NaN", args: &[V::F32(SNAN)], expect: V::F32(1.0), why: "byte 255" },
    Row { func: "encode_roughness_ggx8_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(0.0), why: "byte 0" },
    Row { func: "encode_roughness_ggx8_unorm", case: "subnormal", args: &[V::F32(SUB_MIN)], expect: V::F32(0.0), why: "byte 0" },
    Row { func: "decode_roughness_ggx8_unorm", case: "NaN", args: &[V::F32(NAN)], expect: V::F32(0.0), why: "NaN channel counts as 0" },
    Row { func: "decode_roughness_ggx8_unorm", case: "+Inf", args: &[V::F32(INF)], expect: V::F32(1.0), why: "clamped to byte 255" },
    Row { func: "decode_roughness_ggx8_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(0.0), why: "clamped to byte 0" },
    Row { func: "decode_roughness_ggx8_unorm", case: "out of range: 2", args: &[V::F32(2.0)], expect: V::F32(1.0), why: "clamped to byte 255" },
    Row { func: "decode_roughness_ggx8_unorm", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::F32(0.0), why: "byte 0" },
    // Godot's 7 bits + dynamic-object flag.
    Row { func: "encode_roughness_godot8", case: "NaN, static", args: &[V::F32(NAN), V::U32(0)], expect: V::U32(127), why: "roughest k = 127" },
    Row { func: "encode_roughness_godot8", case: "NaN, dynamic", args: &[V::F32(NAN), V::U32(1)], expect: V::U32(128), why: "k = 127 → 255 − 127" },
    Row { func: "encode_roughness_godot8", case: "+Inf, dynamic", args: &[V::F32(INF), V::U32(1)], expect: V::U32(128), why: "clamped to 1: k = 127" },
    Row { func: "encode_roughness_godot8", case: "−Inf, static", args: &[V::F32(-INF), V::U32(0)], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "encode_roughness_godot8", case: "out-of-range flag u32::MAX", args: &[V::F32(-INF), V::U32(u32::MAX)], expect: V::U32(255), why: "any non-zero flag is dynamic: 255 − 0" },
    Row { func: "encode_roughness_godot8", case: "subnormal", args: &[V::F32(SUB_MAX), V::U32(0)], expect: V::U32(0), why: "k = 0" },
    Row { func: "encode_roughness_godot8", case: "the one tie, r = 1/2", args: &[V::F32(0.5), V::U32(0)], expect: V::U32(64), why: "63.5 → upwards" },
    Row { func: "decode_roughness_godot8", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(0.0), why: "decodes as 255: dynamic, k = 0" },
    Row { func: "decode_roughness_godot8", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(0.0), why: "decodes as 255" },
    Row { func: "roughness_godot8_is_dynamic", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::U32(1), why: "reads as 255: dynamic" },
    Row { func: "roughness_godot8_is_dynamic", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::U32(1), why: "reads as 255: dynamic" },
    Row { func: "encode_roughness_godot8_unorm", case: "NaN, static", args: &[V::F32(NAN), V::U32(0)], expect: V::F32(B127), why: "byte 127" },
    Row { func: "encode_roughness_godot8_unorm", case: "NaN, dynamic", args: &[V::F32(NAN), V::U32(1)], expect: V::F32(B128), why: "byte 128" },
    Row { func: "decode_roughness_godot8_unorm", case: "NaN", args: &[V::F32(NAN)], expect: V::F32(0.0), why: "byte 0: static, k = 0" },
    Row { func: "decode_roughness_godot8_unorm", case: "+Inf", args: &[V::F32(INF)], expect: V::F32(0.0), why: "byte 255: dynamic, k = 0" },
    Row { func: "decode_roughness_godot8_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(0.0), why: "byte 0" },
    // The log curve.
    Row { func: "encode_roughness_ggx8_log", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(255), why: "roughest code (r = 1)" },
    Row { func: "encode_roughness_ggx8_log", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(255), why: "clamped to 1" },
    Row { func: "encode_roughness_ggx8_log", case: "−Inf", args: &[V::F32(-INF)], expect: V::U32(0), why: "smoothest code (r = 2^-6)" },
    Row { func: "encode_roughness_ggx8_log", case: "negative", args: &[V::F32(-0.5)], expect: V::U32(0), why: "smoothest code" },
    Row { func: "encode_roughness_ggx8_log", case: "zero (−0.0)", args: &[V::F32(-0.0)], expect: V::U32(0), why: "smoothest code" },
    Row { func: "encode_roughness_ggx8_log", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(0), why: "≤ 2^-6 → 0" },
    Row { func: "encode_roughness_ggx8_log", case: "out of range: below 2^-6", args: &[V::F32(0.01)], expect: V::U32(0), why: "≤ 2^-6 → 0" },
    Row { func: "encode_roughness_ggx8_log", case: "out of range: above 1", args: &[V::F32(3.0)], expect: V::U32(255), why: "clamped to 1" },
    Row { func: "decode_roughness_ggx8_log", case: "out-of-range code 256", args: &[V::U32(256)], expect: V::F32(1.0), why: "decodes as 255" },
    Row { func: "decode_roughness_ggx8_log", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "decodes as 255" },
    Row { func: "decode_roughness_ggx8_log_alpha", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "decodes as 255: α = 1" },
    Row { func: "encode_roughness_ggx8_log_unorm", case: "NaN", args: &[V::F32(NAN)], expect: V::F32(1.0), why: "byte 255" },
    Row { func: "encode_roughness_ggx8_log_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(0.0), why: "byte 0" },
    Row { func: "decode_roughness_ggx8_log_unorm", case: "NaN", args: &[V::F32(NAN)], expect: V::F32(LOG_MIN), why: "byte 0: r = 2^-6" },
    Row { func: "decode_roughness_ggx8_log_unorm", case: "+Inf", args: &[V::F32(INF)], expect: V::F32(1.0), why: "byte 255" },
    Row { func: "decode_roughness_ggx8_log_unorm", case: "−Inf", args: &[V::F32(-INF)], expect: V::F32(LOG_MIN), why: "byte 0" },
    // Exact references and bounds (Rust only).
    Row { func: "roughness_ggx::exact::linear_code", case: "NaN", args: &[V::F64(f64::NAN), V::U32(255)], expect: V::U32(255), why: "roughest, like the twins" },
    Row { func: "roughness_ggx::exact::linear_code", case: "out of range: −Inf", args: &[V::F64(f64::NEG_INFINITY), V::U32(127)], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "roughness_ggx::exact::log_code", case: "NaN", args: &[V::F64(f64::NAN)], expect: V::U32(255), why: "roughest, like the twins" },
    Row { func: "roughness_ggx::exact::log_code", case: "out of range: 0", args: &[V::F64(0.0)], expect: V::U32(0), why: "≤ 2^-6 → 0" },
    Row { func: "roughness_ggx::exact::ggx_d", case: "NaN", args: &[V::F64(f64::NAN), V::F64(0.5)], expect: V::F64(f64::NAN), why: "propagates (reference only)" },
    Row { func: "roughness_ggx::exact::ggx_d", case: "α = 0 at the peak", args: &[V::F64(1.0), V::F64(0.0)], expect: V::F64(f64::NAN), why: "0/0: a delta (reference only)" },
    Row { func: "roughness_ggx::bounds::lobe_relative", case: "α̂ = 0", args: &[V::F64(0.5), V::F64(0.0)], expect: V::F64(f64::INFINITY), why: "unbounded peak error" },
];
