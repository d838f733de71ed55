//! `wgsl/normal_xy_fp16.wgsl` and `normal::xy_fp16`: view-space x, y as two FP16, and the f16
//! conversions (the twins of WGSL's `pack2x16float` and `unpack2x16float`).

use super::normal::{B60, R2};
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};
use prepass::normal::xy_fp16;

/// WGSL's builtin `unpack2x16float` (twin: `normal::xy_fp16::unpack2x16float`) behind a callable
/// name.
const UNPACK2X16_WGSL: &str =
    "fn bad_input_unpack2x16float(p: u32) -> vec2<f32> { return unpack2x16float(p); }";

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_XY_FP16; normal::xy_fp16; encode_normal_xy_fp16(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_XY_FP16; normal::xy_fp16; decode_normal_xy_fp16(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_XY_FP16; normal::xy_fp16; encode_normal_xy_fp16_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_XY_FP16; normal::xy_fp16; decode_normal_xy_fp16_unorm(rgba) -> Vec3),
    func!(None; normal::xy_fp16; pack2x16float(vec2) -> U32),
    Func {
        rust: "normal::xy_fp16::unpack2x16float",
        wgsl: Some((UNPACK2X16_WGSL, "bad_input_unpack2x16float")),
        twin: |a| V::Vec2(xy_fp16::unpack2x16float(a[0].u32()).to_array()),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[(
    "xyfp16_sanitize",
    "private to normal_xy_fp16.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
)];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`).
    Row { func: "encode_normal_xy_fp16", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x3c00), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xy_fp16", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0xb9a8_39a8), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_xy_fp16", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xy_fp16", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x3c00_0000), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xy_fp16", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0), why: "code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0), why: "code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x389e_389e), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0xbc00_0000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x3c00), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_xy_fp16", case: "out of range: z < 0", args: &[V::Vec3([0.0, 0.0, -1.0])], expect: V::U32(0), why: "sign of z not stored: code of +z" },
    // Decoders.
    Row { func: "decode_normal_xy_fp16", case: "NaN halves", args: &[V::U32(0x7e00_7e00)], expect: V::Vec3([0.0, 0.0, 1.0]), why: "NaN halves count as 0: +z" },
    Row { func: "decode_normal_xy_fp16", case: "−NaN halves (all ones)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, 1.0]), why: "NaN halves count as 0: +z" },
    Row { func: "decode_normal_xy_fp16", case: "+Inf half", args: &[V::U32(0x0000_7c00)], expect: V::Vec3([1.0, 0.0, 0.0]), why: "clamped to 1: +x" },
    Row { func: "decode_normal_xy_fp16", case: "NaN and −Inf halves", args: &[V::U32(0xfc00_7e00)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "x = 0, y clamped to −1: −y" },
    Row { func: "decode_normal_xy_fp16", case: "±Inf halves: x² + y² > 1", args: &[V::U32(0x7c00_7c00)], expect: V::Vec3([R2, R2, 0.0]), why: "clamped to (1, 1), z = 0: (1, 1, 0)/√2, rounded" },
    Row { func: "decode_normal_xy_fp16", case: "out-of-range half −2", args: &[V::U32(0xc000_0000)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "clamped to −1: −y" },
    Row { func: "decode_normal_xy_fp16", case: "subnormal half", args: &[V::U32(0x0000_0001)], expect: V::Vec3([5.960_464_5e-8, 0.0, 1.0]), why: "2^-24 is a normal f32: kept; z rounds to 1" },
    Row { func: "decode_normal_xy_fp16", case: "−0.0 halves", args: &[V::U32(0x8000_8000)], expect: V::Vec3([-0.0, -0.0, 1.0]), why: "+z; the zeros keep their signs" },
    // Render-target forms.
    Row { func: "encode_normal_xy_fp16_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "+z: both halves 0" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([0.0, B60, 0.0, 0.0]), why: "+x: x half 0x3c00" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, 1.0]), why: "bytes 0: halves 0: +z" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "out of range, −Inf, NaN", args: &[V::Vec4([-1.0, B60, NAN, -INF])], expect: V::Vec3([1.0, 0.0, 0.0]), why: "bytes (0, 60, 0, 0): x half 1.0: +x" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "+Inf", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 0.0, 1.0]), why: "bytes 255: NaN halves count as 0: +z" },
    // The f16 conversions (the WGSL builtins' twins).
    Row { func: "normal::xy_fp16::pack2x16float", case: "NaN", args: &[V::Vec2([NAN, NEG_NAN])], expect: V::U32(0xfe00_7e00), why: "quiet f16 NaN, sign kept (WGSL: indeterminate)" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "NaN (signalling)", args: &[V::Vec2([SNAN, 0.0])], expect: V::U32(0x7e00), why: "stays NaN: quiet bit set" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "±Inf", args: &[V::Vec2([INF, -INF])], expect: V::U32(0xfc00_7c00), why: "±Inf halves" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "out of range", args: &[V::Vec2([65_520.0, -1e9])], expect: V::U32(0xfc00_7c00), why: "rounds to ±Inf (WGSL: indeterminate, clamp first)" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "subnormal", args: &[V::Vec2([-SUB_MIN, 5.960_464_5e-8])], expect: V::U32(0x0001_8000), why: "−0 half; 2^-24 → smallest f16 subnormal" },
    Row { func: "unpack2x16float", case: "NaN and +Inf halves", args: &[V::U32(0x7e00_7c00)], expect: V::WgslIndeterminate(&V::Vec2([INF, NAN])), why: "exact in Rust; in WGSL a run-time ±Inf or NaN (finite-math rule)" },
    Row { func: "unpack2x16float", case: "−Inf and −NaN halves", args: &[V::U32(0xfc00_fe00)], expect: V::WgslIndeterminate(&V::Vec2([NAN, -INF])), why: "exact in Rust; in WGSL a run-time ±Inf or NaN (finite-math rule)" },
    Row { func: "unpack2x16float", case: "subnormal halves", args: &[V::U32(0x0001_8001)], expect: V::Vec2([-5.960_464_5e-8, 5.960_464_5e-8]), why: "exact: ±2^-24, normal in f32" },
];
