//! `wgsl/normal_xyz10.wgsl` and `normal::xyz10`: x, y, z in the three unorm10 channels of an
//! RGB10A2 texel.

use super::normal::{K512, R3};
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_XYZ10; normal::xyz10; encode_normal_xyz10(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_XYZ10; normal::xyz10; decode_normal_xyz10(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_XYZ10; normal::xyz10; encode_normal_xyz10_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_XYZ10; normal::xyz10; decode_normal_xyz10_unorm(rgba) -> Vec3),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[(
    "xyz10_sanitize",
    "private to normal_xyz10.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
)];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`). +z is fields (512, 512, 1023).
    Row { func: "encode_normal_xyz10", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x3ff8_0200), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xyz10", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x3ff8_0200), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xyz10", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x2008_03ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xyz10", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x2002_5b69), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_xyz10", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0008_0200), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xyz10", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x3ff8_0200), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xyz10", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x200f_fe00), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xyz10", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x3ff8_0200), why: "code of +z" },
    Row { func: "encode_normal_xyz10", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x3ff8_0200), why: "code of +z" },
    Row { func: "encode_normal_xyz10", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x327c_9f27), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_xyz10", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x2000_0200), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xyz10", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x2008_03ff), why: "the tiny one vanishes: code of +x" },
    // Decoders: odd-integer vectors, like xyz8's, so no code decodes to an exact f32 vector
    // along a diagonal; the rows give v/√(v·v) with each step correctly rounded.
    Row { func: "decode_normal_xyz10", case: "all ones (alpha bits set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([R3, R3, R3]), why: "bits 30–31 ignored: (1, 1, 1)/√3, rounded" },
    Row { func: "decode_normal_xyz10", case: "alpha bits only", args: &[V::U32(0xc000_0000)], expect: V::Vec3([-R3, -R3, -R3]), why: "bits 30–31 ignored: (−1, −1, −1)/√3, rounded" },
    // Render-target forms: channels k/1023; decoders take each channel from its bits.
    Row { func: "encode_normal_xyz10_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([K512, K512, 1.0, 0.0]), why: "+z: codes (512, 512, 1023), alpha 0" },
    Row { func: "encode_normal_xyz10_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, K512, K512, 0.0]), why: "+x: codes (1023, 512, 512)" },
    Row { func: "encode_normal_xyz10_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([K512, K512, 1.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xyz10_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([K512, K512, 1.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_xyz10_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([-R3, -R3, -R3]), why: "codes 0: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz10_unorm", case: "out of range, ±Inf, NaN", args: &[V::Vec4([2.0, -1.0, NAN, INF])], expect: V::Vec3([R3, -R3, -R3]), why: "codes (1023, 0, 0): (1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz10_unorm", case: "+Inf", args: &[V::Vec4([INF, INF, INF, -INF])], expect: V::Vec3([R3, R3, R3]), why: "taken as 1: (1, 1, 1)/√3, rounded" },
    Row { func: "decode_normal_xyz10_unorm", case: "−Inf, −0", args: &[V::Vec4([-INF, -0.0, -SUB_MIN, NAN])], expect: V::Vec3([-R3, -R3, -R3]), why: "taken as 0: (−1, −1, −1)/√3, rounded" },
];
