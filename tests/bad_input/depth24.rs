//! `wgsl/depth24.wgsl` and `depth24`: 24-bit depth codes in RGBA8 texels, with the exact
//! references of `depth24::exact`.

use super::{Func, INF, MAX24, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};
use prepass::depth24;

/// WGSL's builtin `unpack4x8unorm` (twin: `depth24::unpack4x8unorm`) behind a callable name.
const UNPACK_WGSL: &str =
    "fn bad_input_unpack4x8unorm(p: u32) -> vec4<f32> { return unpack4x8unorm(p); }";

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::DEPTH24; depth24; depth24_from_rgb8(vec3) -> U32),
    func!(prepass::wgsl::DEPTH24; depth24; depth24_from_packed(u32) -> U32),
    func!(prepass::wgsl::DEPTH24; depth24; pack_depth24(u32) -> U32),
    func!(prepass::wgsl::DEPTH24; depth24; hyperbolic_depth_from_depth24(u32) -> F32),
    Func {
        rust: "depth24::unpack4x8unorm",
        wgsl: Some((UNPACK_WGSL, "bad_input_unpack4x8unorm")),
        twin: |a| V::Vec4(depth24::unpack4x8unorm(a[0].u32())),
    },
    Func {
        rust: "depth24::exact::hyperbolic_depth",
        wgsl: None,
        twin: |a| V::F64(depth24::exact::hyperbolic_depth(a[0].u32())),
    },
    Func {
        rust: "depth24::exact::nearest_code",
        wgsl: None,
        twin: |a| V::OptU32(depth24::exact::nearest_code(a[0].f32())),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // depth24_from_rgb8: channels clamp to [0, 1], NaN (from its bits) counts as 0.
    Row { func: "depth24_from_rgb8", case: "NaN", args: &[V::Vec3([NAN, NAN, NAN])], expect: V::U32(0), why: "NaN channel → byte 0" },
    Row { func: "depth24_from_rgb8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([NEG_NAN, 1.0, SNAN])], expect: V::U32(0x00ff00), why: "every NaN → byte 0" },
    Row { func: "depth24_from_rgb8", case: "+Inf", args: &[V::Vec3([INF, INF, INF])], expect: V::U32(MAX24), why: "clamped to 1 → byte 255" },
    Row { func: "depth24_from_rgb8", case: "−Inf", args: &[V::Vec3([-INF, -INF, -INF])], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "depth24_from_rgb8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0), why: "rounds to byte 0, flushed or not" },
    Row { func: "depth24_from_rgb8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth24_from_rgb8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth24_from_rgb8", case: "out of range", args: &[V::Vec3([-1.0, 2.0, 1.5])], expect: V::U32(0x00ffff), why: "clamped to [0, 1]" },
    Row { func: "depth24_from_rgb8", case: "huge", args: &[V::Vec3([f32::MAX, f32::MIN, 0.5])], expect: V::U32(0xff0080), why: "clamped; 127.5 rounds half to even" },
    // depth24_from_packed: pure bit operations, every u32 is valid.
    Row { func: "depth24_from_packed", case: "alpha byte set", args: &[V::U32(0xff12_3456)], expect: V::U32(0x56_3412), why: "byte 3 ignored" },
    Row { func: "depth24_from_packed", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(MAX24), why: "byte 3 ignored" },
    Row { func: "depth24_from_packed", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // pack_depth24: codes above 2^24 − 1 saturate.
    Row { func: "pack_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::U32(0x00ff_ffff), why: "saturates to 2^24 − 1" },
    Row { func: "pack_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::U32(0x00ff_ffff), why: "saturates; alpha stays 0" },
    Row { func: "pack_depth24", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // hyperbolic_depth_from_depth24: codes above 2^24 − 1 saturate to 1.0.
    Row { func: "hyperbolic_depth_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "hyperbolic_depth_from_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "hyperbolic_depth_from_depth24", case: "zero", args: &[V::U32(0)], expect: V::F32(0.0), why: "+0.0, never −0.0" },
    // unpack4x8unorm: every u32 is four valid bytes.
    Row { func: "unpack4x8unorm", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec4([1.0; 4]), why: "255/255 = 1 exactly" },
    Row { func: "unpack4x8unorm", case: "zero", args: &[V::U32(0)], expect: V::Vec4([0.0; 4]), why: "+0.0 lanes" },
    // Exact references (Rust only).
    Row { func: "depth24::exact::hyperbolic_depth", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth24::exact::hyperbolic_depth", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth24::exact::nearest_code", case: "NaN", args: &[V::F32(NAN)], expect: V::OptU32(None), why: "no code" },
    Row { func: "depth24::exact::nearest_code", case: "+Inf", args: &[V::F32(INF)], expect: V::OptU32(None), why: "above 1" },
    Row { func: "depth24::exact::nearest_code", case: "−Inf", args: &[V::F32(-INF)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth24::exact::nearest_code", case: "−0.0", args: &[V::F32(-0.0)], expect: V::OptU32(Some(0)), why: "−0.0 is 0" },
    Row { func: "depth24::exact::nearest_code", case: "subnormal", args: &[V::F32(SUB_MIN)], expect: V::OptU32(Some(0)), why: "rounds to code 0" },
    Row { func: "depth24::exact::nearest_code", case: "negative subnormal", args: &[V::F32(-SUB_MIN)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth24::exact::nearest_code", case: "out of range", args: &[V::F32(1.000_000_1)], expect: V::OptU32(None), why: "above 1" },
];
