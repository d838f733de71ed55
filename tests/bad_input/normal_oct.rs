//! `wgsl/normal_oct.wgsl` and `normal::oct`: octahedral normals in 16, 24 and 32 bits (24 also in
//! Unity's byte order), and the generic Rust-only octahedral functions.

use super::normal::{B127, B247};

/// The unorm8 channel of byte 0x77, `119/255` (byte 2 of +z in Unity's order).
const B119: f32 = 119.0 / 255.0;
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};
use prepass::normal::oct;

/// What the generic octahedral functions do with `bits` outside 1..=16.
const BITS_PANIC: &str = "panics";

/// `f()`, or [`BITS_PANIC`] if it panics (the panic message still prints).
fn normal_or_panic(f: impl FnOnce() -> V) -> V {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or(V::Text(BITS_PANIC))
}

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct16(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct16_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct16(u32) -> Vec3),
    // The WGSL render-target form of oct16 is rg8unorm (vec2); the twin takes [c0, c1, 0, 0].
    Func {
        rust: "normal::oct::encode_normal_oct16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct16_unorm")),
        twin: |a| {
            let c = oct::encode_normal_oct16_unorm(a[0].vec3());
            V::Vec2([c[0], c[1]])
        },
    },
    Func {
        rust: "normal::oct::decode_normal_oct16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct16_unorm")),
        twin: |a| {
            let c = a[0].vec2();
            V::Vec3(oct::decode_normal_oct16_unorm([c.x, c.y, 0.0, 0.0]).to_array())
        },
    },
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct24(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct24_unorm(rgba) -> Vec3),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24_unity(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24_unity_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct24_unity(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct24_unity_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct24_unity_unorm(rgba) -> Vec3),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct32(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct32_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct32(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; encode_normal_oct32_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_OCT; normal::oct; decode_normal_oct32_unorm(rgba) -> Vec3),
    Func {
        rust: "normal::oct::max_code",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::max_code(a[0].u32()))),
    },
    Func {
        rust: "normal::oct::encode_precise",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::encode_precise(a[0].vec3(), a[1].u32()))),
    },
    Func {
        rust: "normal::oct::encode_round",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::encode_round(a[0].vec3(), a[1].u32()))),
    },
    Func {
        rust: "normal::oct::decode",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::Vec3(oct::decode(a[0].u32(), a[1].u32()).to_array())),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "oct_unity_bytes",
        "private to normal_oct.wgsl: oct24's word in Unity's byte order, behind every Unity encoder row",
    ),
    (
        "oct_unity_word",
        "private to normal_oct.wgsl: Unity's bytes as oct24's word, behind every Unity decoder row",
    ),
    (
        "oct_sanitize",
        "private to normal_oct.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
    ),
    (
        "oct_continuous",
        "private to normal_oct.wgsl: continuous code coordinates, behind every oct encoder row",
    ),
    (
        "oct_lattice",
        "private to normal_oct.wgsl: a code's integer vector, behind every oct decoder row",
    ),
    (
        "oct_try",
        "private to normal_oct.wgsl: the precise encoders' score and choice step, behind their rows",
    ),
    (
        "oct_try_wide",
        "private to normal_oct.wgsl: oct_try with a 32-bit |D|^2, behind encode_normal_oct32's rows",
    ),
    (
        "oct_encode_precise",
        "private to normal_oct.wgsl: body of encode_normal_oct16/24, each with rows",
    ),
    (
        "oct_encode_precise_wide",
        "private to normal_oct.wgsl: body of encode_normal_oct32, with rows",
    ),
    (
        "oct_encode_round",
        "private to normal_oct.wgsl: body of the _fast encoders, each with rows",
    ),
    (
        "oct_decode",
        "private to normal_oct.wgsl: body of the oct decoders, each with rows",
    ),
    (
        "oct_unorm_bytes",
        "private to normal_oct.wgsl: channels to bytes, exercised by the _unorm decoder rows",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`).
    Row { func: "encode_normal_oct16", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x7f7f), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct16", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x7f7f), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct16", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x7fff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct16", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x40bf), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct16", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct16", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x7f7f), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct16", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xff7f), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct16", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x7f7f), why: "code of +z" },
    Row { func: "encode_normal_oct16", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x7f7f), why: "code of +z" },
    Row { func: "encode_normal_oct16", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct16", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7f), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct16", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct16_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8080), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x8080), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x80ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct16_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x40bf), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct16_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct16_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8080), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xff80), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct16_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8080), why: "code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x8080), why: "code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x80), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x80ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct24", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct24", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x007f_f7ff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct24", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x007f_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct24", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0040_0bff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct24", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct24", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x007f_f7ff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct24", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x00ff_f7ff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct24", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_oct24", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_oct24", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00aa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct24", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7ff), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct24", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x007f_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct24_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0080_0800), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x0080_0800), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x0080_0fff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct24_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0040_0bff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct24_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct24_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x0080_0800), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x00ff_f800), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct24_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00aa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x800), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_0fff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct32", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x7fff_7fff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct32", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x7fff_7fff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct32", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x7fff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct32", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4000_bfff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct32", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct32", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x7fff_7fff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct32", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xffff_7fff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct32", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x7fff_7fff), why: "code of +z" },
    Row { func: "encode_normal_oct32", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x7fff_7fff), why: "code of +z" },
    Row { func: "encode_normal_oct32", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct32", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct32", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct32_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8000_8000), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x8000_8000), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x8000_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct32_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4000_bfff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct32_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct32_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8000_8000), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xffff_8000), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct32_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8000_8000), why: "code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x8000_8000), why: "code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x8000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x8000_ffff), why: "the tiny one vanishes: code of +x" },
    // Decoders.
    Row { func: "decode_normal_oct16", case: "all ones (unused bits 16–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (M, M) = −z" },
    Row { func: "decode_normal_oct16", case: "unused bits 16–31 only", args: &[V::U32(0xabcd_0000)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (0, 0) = −z" },
    Row { func: "decode_normal_oct24", case: "all ones (unused bits 24–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (M, M) = −z" },
    Row { func: "decode_normal_oct24", case: "unused bits 24–31 only", args: &[V::U32(0xff00_0000)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (0, 0) = −z" },
    Row { func: "decode_normal_oct32", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "corner (M, M) = −z" },
    Row { func: "decode_normal_oct32", case: "corner (M, 0)", args: &[V::U32(0x0000_ffff)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "every corner is −z" },
    // Render-target forms.
    Row { func: "encode_normal_oct16_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec2([B127, B127]), why: "+z: code (127, 127)" },
    Row { func: "encode_normal_oct16_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec2([1.0, B127]), why: "+x: code (255, 127)" },
    Row { func: "encode_normal_oct16_unorm", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::Vec2([B127, B127]), why: "+z" },
    Row { func: "decode_normal_oct16_unorm", case: "NaN", args: &[V::Vec2([NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct16_unorm", case: "out of range, +Inf", args: &[V::Vec2([INF, -1.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes (255, 0): corner = −z" },
    Row { func: "decode_normal_oct16_unorm", case: "out of range", args: &[V::Vec2([2.0, 7.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "clamped to 1: corner (255, 255) = −z" },
    Row { func: "encode_normal_oct24_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z: code 0x7ff7ff, alpha 0" },
    Row { func: "encode_normal_oct24_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, B127, 0.0]), why: "+x: code 0x7fffff" },
    Row { func: "encode_normal_oct24_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z" },
    Row { func: "decode_normal_oct24_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct24_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "alpha ignored; corner (M, M) = −z" },
    // Unity's byte order of the same codes (+z 0x7ff7ff → 0x77ffff, the rounding +z 0x800800 →
    // 0x880000; +x and −z read the same in both orders).
    Row { func: "encode_normal_oct24_unity", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0077_ffff), why: "NaN anywhere → code of +z, Unity's bytes" },
    Row { func: "encode_normal_oct24_unity", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x007f_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct24_unity", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x0077_ffff), why: "code of +z" },
    Row { func: "encode_normal_oct24_unity_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0088_0000), why: "NaN anywhere → code of +z, Unity's bytes" },
    Row { func: "encode_normal_oct24_unity_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of −z" },
    Row { func: "decode_normal_oct24_unity", case: "all ones (byte 3 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "byte 3 ignored; corner (M, M) = −z" },
    Row { func: "decode_normal_oct24_unity", case: "byte 3 only", args: &[V::U32(0xab00_0000)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "byte 3 ignored; corner (0, 0) = −z" },
    Row { func: "encode_normal_oct24_unity_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, 1.0, B119, 0.0]), why: "+z: bytes (0xff, 0xff, 0x77), alpha 0" },
    Row { func: "encode_normal_oct24_unity_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, B127, 0.0]), why: "+x: bytes (0xff, 0xff, 0x7f)" },
    Row { func: "decode_normal_oct24_unity_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct24_unity_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "alpha ignored; corner (M, M) = −z" },
    Row { func: "encode_normal_oct32_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B127, 1.0, B127]), why: "+z: code 0x7fff7fff" },
    Row { func: "encode_normal_oct32_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, 1.0, B127]), why: "+x: code 0x7fffffff" },
    Row { func: "encode_normal_oct32_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B127, 1.0, B127]), why: "+z" },
    Row { func: "decode_normal_oct32_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct32_unorm", case: "out of range, ±Inf", args: &[V::Vec4([2.0, INF, -INF, -1.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "code (0xffff, 0): corner = −z" },
    // The generic octahedral functions: any bits outside 1..=16 panic (see `oct::max_code`).
    Row { func: "normal::oct::max_code", case: "out-of-range bits 0", args: &[V::U32(0)], expect: V::Text(BITS_PANIC), why: "no code fits 0 bits" },
    Row { func: "normal::oct::max_code", case: "out-of-range bits 17", args: &[V::U32(17)], expect: V::Text(BITS_PANIC), why: "M² would overflow the u32 scores" },
    Row { func: "normal::oct::max_code", case: "out-of-range bits u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::encode_precise", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0]), V::U32(12)], expect: V::U32(0x007f_f7ff), why: "code of +z, as encode_normal_oct24" },
    Row { func: "normal::oct::encode_precise", case: "out-of-range bits 0", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(0)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::encode_precise", case: "out-of-range bits 17", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(17)], expect: V::Text(BITS_PANIC), why: "two codes need 34 bits" },
    Row { func: "normal::oct::encode_round", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::U32(16)], expect: V::U32(0x8000_8000), why: "code of +z, as encode_normal_oct32_fast" },
    Row { func: "normal::oct::encode_round", case: "out-of-range bits 32", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(32)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::decode", case: "all ones", args: &[V::U32(u32::MAX), V::U32(8)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner = −z" },
    Row { func: "normal::oct::decode", case: "out-of-range bits 0", args: &[V::U32(0), V::U32(0)], expect: V::Text(BITS_PANIC), why: "never wraps" },
];
