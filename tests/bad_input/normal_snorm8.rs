//! `wgsl/normal_snorm8.wgsl` and `normal::snorm8`: x, y, z as two's complement bytes, read as
//! the snorm8 format reads them.

use super::normal::R3;
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_SNORM8; normal::snorm8; encode_normal_snorm8(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_SNORM8; normal::snorm8; decode_normal_snorm8(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_SNORM8; normal::snorm8; encode_normal_snorm8_snorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_SNORM8; normal::snorm8; decode_normal_snorm8_snorm(rgba) -> Vec3),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[(
    "snorm8_sanitize",
    "private to normal_snorm8.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
)];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`). +z is bytes (0, 0, 127).
    Row { func: "encode_normal_snorm8", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x007f_0000), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_snorm8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x007f_0000), why: "every NaN → code of +z" },
    Row { func: "encode_normal_snorm8", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x7f), why: "infinities win: code of +x" },
    Row { func: "encode_normal_snorm8", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0xa65a), why: "their signs: code of (1, −1, 0)/√2, bytes (90, −90, 0)" },
    Row { func: "encode_normal_snorm8", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0081_0000), why: "infinities win: code of −z, byte −127 (never −128)" },
    Row { func: "encode_normal_snorm8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x007f_0000), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_snorm8", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x7f00), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_snorm8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x007f_0000), why: "code of +z" },
    Row { func: "encode_normal_snorm8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x007f_0000), why: "code of +z" },
    Row { func: "encode_normal_snorm8", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x0049_4949), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_snorm8", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x8100), why: "no underflow: code of −y" },
    Row { func: "encode_normal_snorm8", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7f), why: "the tiny one vanishes: code of +x" },
    // Decoders: −128 reads as −127 (the format's max(b/127, −1)); the zero vector reads +z.
    Row { func: "decode_normal_snorm8", case: "all ones (byte 3 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([-R3, -R3, -R3]), why: "bytes −1: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_snorm8", case: "byte 3 only", args: &[V::U32(0xab00_0000)], expect: V::Vec3([0.0, 0.0, 1.0]), why: "byte 3 ignored; the zero vector, which no encoder writes, reads +z" },
    Row { func: "decode_normal_snorm8", case: "−128", args: &[V::U32(0x0080_8080)], expect: V::Vec3([-R3, -R3, -R3]), why: "−128 reads −127: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_snorm8", case: "−128 alone", args: &[V::U32(0x80)], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "−x, exactly" },
    // Render-target forms: channels b/127; decoders take each channel from its bits.
    Row { func: "encode_normal_snorm8_snorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 1.0, 0.0]), why: "+z: bytes (0, 0, 127), alpha 0" },
    Row { func: "encode_normal_snorm8_snorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 0.0, 0.0, 0.0]), why: "+x: bytes (127, 0, 0)" },
    Row { func: "encode_normal_snorm8_snorm", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::Vec4([0.0, 0.0, -1.0, 0.0]), why: "−z: bytes (0, 0, −127)" },
    Row { func: "encode_normal_snorm8_snorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 1.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_snorm8_snorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, 1.0]), why: "NaN counts as 0: the zero vector reads +z" },
    Row { func: "decode_normal_snorm8_snorm", case: "out of range, +Inf, NaN", args: &[V::Vec4([2.0, NAN, -0.0, INF])], expect: V::Vec3([1.0, 0.0, 0.0]), why: "bytes (127, 0, 0): +x" },
    Row { func: "decode_normal_snorm8_snorm", case: "−Inf, out of range", args: &[V::Vec4([NAN, -INF, -0.5e-3, 7.0])], expect: V::Vec3([0.0, -1.0, 0.0]), why: "bytes (0, −127, 0): −y" },
    Row { func: "decode_normal_snorm8_snorm", case: "±Inf", args: &[V::Vec4([INF, -INF, -INF, NAN])], expect: V::Vec3([R3, -R3, -R3]), why: "taken as ±1: (1, −1, −1)/√3, rounded" },
];
