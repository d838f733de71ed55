//! `wgsl/normal_xyz8.wgsl` and `normal::xyz8`: x, y, z in three unorm8 channels.

use super::normal::{B128, R3};
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; encode_normal_xyz8(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; decode_normal_xyz8(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; encode_normal_xyz8_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; decode_normal_xyz8_unorm(rgba) -> Vec3),
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; encode_normal_xyz8_best(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_XYZ8; normal::xyz8; encode_normal_xyz8_best_unorm(vec3) -> Vec4),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[(
    "xyz8_sanitize",
    "private to normal_xyz8.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
)];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`).
    Row { func: "encode_normal_xyz8", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x00ff_8080), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xyz8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x00ff_8080), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xyz8", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x0080_80ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xyz8", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0080_25da), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_xyz8", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x8080), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xyz8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x00ff_8080), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xyz8", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x0080_ff80), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xyz8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x00ff_8080), why: "code of +z" },
    Row { func: "encode_normal_xyz8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x00ff_8080), why: "code of +z" },
    Row { func: "encode_normal_xyz8", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00c9_c9c9), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_xyz8", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_0080), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xyz8", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_80ff), why: "the tiny one vanishes: code of +x" },
    // The best-fit encoder: the same rules; where a direction has several exact codes (the
    // multiples of one odd vector) the longest wins, and a zero component takes D's + sign.
    Row { func: "encode_normal_xyz8_best", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x00ff_8080), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xyz8_best", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x00ff_8080), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xyz8_best", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x0080_80ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xyz8_best", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0080_00ff), why: "their signs: (1, −1, 0)/√2, best as (255, −255, 1)" },
    Row { func: "encode_normal_xyz8_best", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x8080), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xyz8_best", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x00ff_8080), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xyz8_best", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x0080_ff80), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xyz8_best", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x00ff_8080), why: "code of +z" },
    Row { func: "encode_normal_xyz8_best", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x00ff_8080), why: "code of +z (−0 takes the + sign)" },
    Row { func: "encode_normal_xyz8_best", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00ff_ffff), why: "no overflow: (1, 1, 1) exactly, as its longest multiple (255, 255, 255)" },
    Row { func: "encode_normal_xyz8_best", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_0080), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xyz8_best", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_80ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_xyz8_best_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z: bytes (128, 128, 255, 0)" },
    Row { func: "encode_normal_xyz8_best_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, B128, B128, 0.0]), why: "+x: bytes (255, 128, 128, 0)" },
    Row { func: "encode_normal_xyz8_best_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xyz8_best_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z" },
    // Decoders. No xyz8 code decodes to an exact f32 vector (three odd integers: |D|² ≡ 3 mod 8
    // is never a square), so its rows give v/√(v·v) with each step correctly rounded, as
    // documented.
    Row { func: "decode_normal_xyz8", case: "all ones (byte 3 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([R3, R3, R3]), why: "byte 3 ignored: (1, 1, 1)/√3, rounded" },
    Row { func: "decode_normal_xyz8", case: "byte 3 only", args: &[V::U32(0xab00_0000)], expect: V::Vec3([-R3, -R3, -R3]), why: "byte 3 ignored: (−1, −1, −1)/√3, rounded" },
    // Render-target forms.
    Row { func: "encode_normal_xyz8_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z: bytes (128, 128, 255, 0)" },
    Row { func: "encode_normal_xyz8_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, B128, B128, 0.0]), why: "+x: bytes (255, 128, 128, 0)" },
    Row { func: "encode_normal_xyz8_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xyz8_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_xyz8_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([-R3, -R3, -R3]), why: "bytes 0: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz8_unorm", case: "out of range, ±Inf, NaN", args: &[V::Vec4([2.0, -1.0, NAN, INF])], expect: V::Vec3([R3, -R3, -R3]), why: "bytes (255, 0, 0): (1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz8_unorm", case: "+Inf", args: &[V::Vec4([INF, INF, INF, -INF])], expect: V::Vec3([R3, R3, R3]), why: "clamped to 1: (1, 1, 1)/√3, rounded" },
];
