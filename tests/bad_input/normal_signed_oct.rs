//! `wgsl/normal_signed_oct.wgsl` and `normal::signed_oct`: O3DE's signed octahedron in RGB10A2
//! (u in bits 0–9, v in 10–19, z's sign in bit 20).

use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};

/// The unorm10 channel of code 511, `511/1023` (the precise encoder's +z: code (511, 511)).
const K511: f32 = 511.0 / 1023.0;
/// The unorm10 channel of code 852, `852/1023` (the precise encoder's (1, 1, 1)/√3).
const K852: f32 = 852.0 / 1023.0;
/// Code (511, 511)'s direction `normalize(0, −1, ±1022)`, each step correctly rounded: y, |z|.
const PZ_Y: f32 = f32::from_bits(0xba80_401c);
const PZ_Z: f32 = f32::from_bits(0x3f7f_fff8);

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_SIGNED_OCT; normal::signed_oct; encode_normal_signed_oct(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_SIGNED_OCT; normal::signed_oct; encode_normal_signed_oct_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_SIGNED_OCT; normal::signed_oct; decode_normal_signed_oct(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_SIGNED_OCT; normal::signed_oct; encode_normal_signed_oct_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_SIGNED_OCT; normal::signed_oct; decode_normal_signed_oct_unorm(rgba) -> Vec3),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "signed_oct_sanitize",
        "private to normal_signed_oct.wgsl: NaN/Inf/subnormal handling, behind every encoder row",
    ),
    (
        "signed_oct_continuous",
        "private to normal_signed_oct.wgsl: continuous code coordinates, behind the encoder rows",
    ),
    (
        "signed_oct_decode_any_b",
        "private to normal_signed_oct.wgsl: the decoder's path for B other than 0 and 1023, behind the B = 1 and B = 512 rows",
    ),
    (
        "signed_oct_lattice",
        "private to normal_signed_oct.wgsl: a code's integer vector, behind the decoder rows",
    ),
    (
        "signed_oct_try",
        "private to normal_signed_oct.wgsl: one candidate's score (the decision search's), the precise encoder writes its four out",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`). Bit 20: z > 0.
    Row { func: "encode_normal_signed_oct", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x3ff7_fdff), why: "NaN anywhere → code of +z (511, 511), B = 1023" },
    Row { func: "encode_normal_signed_oct", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x3ff7_fdff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_signed_oct", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x3ff), why: "infinities win: code of +x (1023, 0), z = 0: B = 0" },
    Row { func: "encode_normal_signed_oct", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x1ff), why: "their signs: code of (1, −1, 0)/√2 (511, 0)" },
    Row { func: "encode_normal_signed_oct", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0007_fdff), why: "infinities win: code of −z, B = 0" },
    Row { func: "encode_normal_signed_oct", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x3ff7_fdff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_signed_oct", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x000f_ffff), why: "subnormals count as 0: code of +y (1023, 1023), z = −0: B = 0" },
    Row { func: "encode_normal_signed_oct", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x3ff7_fdff), why: "code of +z" },
    Row { func: "encode_normal_signed_oct", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x3ff7_fdff), why: "code of +z" },
    Row { func: "encode_normal_signed_oct", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x3ff7_ff54), why: "no overflow: code of (1, 1, 1)/√3 (852, 511)" },
    Row { func: "encode_normal_signed_oct", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0), why: "no underflow: code of −y (0, 0)" },
    Row { func: "encode_normal_signed_oct", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x3ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_signed_oct", case: "z = −0", args: &[V::Vec3([0.6, 0.8, -0.0])], expect: V::U32(0x0009_27ff), why: "on the equator: B = 0, as O3DE's B = saturate(−0·FLT_MAX) = 0" },
    Row { func: "encode_normal_signed_oct_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x3ff8_0200), why: "NaN anywhere → code of +z (512, 512), B = 1023" },
    Row { func: "encode_normal_signed_oct_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x3ff8_0200), why: "every NaN → code of +z" },
    Row { func: "encode_normal_signed_oct_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x3ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_signed_oct_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x200), why: "their signs: code of (1, −1, 0)/√2 (512, 0)" },
    Row { func: "encode_normal_signed_oct_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0008_0200), why: "infinities win: code of −z, B = 0" },
    Row { func: "encode_normal_signed_oct_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x3ff8_0200), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_signed_oct_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x000f_ffff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_signed_oct_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x3ff8_0200), why: "code of +z" },
    Row { func: "encode_normal_signed_oct_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x3ff8_0200), why: "code of +z" },
    Row { func: "encode_normal_signed_oct_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x3ff8_0355), why: "no overflow: code of (1, 1, 1)/√3 (853, 512)" },
    Row { func: "encode_normal_signed_oct_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0), why: "no underflow: code of −y" },
    Row { func: "encode_normal_signed_oct_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x3ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_signed_oct_fast", case: "z = −0", args: &[V::Vec3([0.6, 0.8, -0.0])], expect: V::U32(0x0009_27ff), why: "on the equator: B = 0" },
    // Decoders.
    Row { func: "decode_normal_signed_oct", case: "all ones (A set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "A ignored; corner (M, M) = +y, B = 1023: z = +0" },
    Row { func: "decode_normal_signed_oct", case: "bits 21–31 only (B = 1022, A set)", args: &[V::U32(0xffe0_0000)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "A ignored; corner (0, 0) = −y on the equator, B = 1022 ≥ 512: z = +0 (O3DE's 2B − 1 > 0; before issue 60 bit 20 alone: −0)" },
    Row { func: "decode_normal_signed_oct", case: "B = 1 (the old words' bit 20 alone)", args: &[V::U32(0x0010_0000)], expect: V::Vec3([0.0, -1.0, -0.0]), why: "corner (0, 0) = −y on the equator; B = 1 < 512: z's factor 2/1023 − 1 < 0, z = −0, as O3DE reads it" },
    Row { func: "decode_normal_signed_oct", case: "B = 512", args: &[V::U32(0x2000_0000)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "corner (0, 0) = −y on the equator; B = 512: z's factor 1/1023 > 0, z = +0, as O3DE reads it" },
    Row { func: "decode_normal_signed_oct", case: "equator, B = 0", args: &[V::U32(0x3ff)], expect: V::Vec3([1.0, 0.0, -0.0]), why: "corner (M, 0) = +x with z = −0" },
    Row { func: "decode_normal_signed_oct", case: "pole, B = 0", args: &[V::U32(0x0007_fdff)], expect: V::Vec3([0.0, PZ_Y, -PZ_Z]), why: "(511, 511): normalize(0, −1, −1022), the code nearest −z" },
    // Render-target forms.
    Row { func: "encode_normal_signed_oct_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([K511, K511, 1.0, 0.0]), why: "+z: code (511, 511), B = 1, A 0 (the renderer's)" },
    Row { func: "encode_normal_signed_oct_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 0.0, 0.0, 0.0]), why: "+x: code (1023, 0), B = 0" },
    Row { func: "encode_normal_signed_oct_unorm", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::Vec4([K511, K511, 1.0, 0.0]), why: "+z" },
    Row { func: "encode_normal_signed_oct_unorm", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::Vec4([K852, K511, 1.0, 0.0]), why: "(1, 1, 1)/√3: code (852, 511), B = 1" },
    Row { func: "decode_normal_signed_oct_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, -1.0, -0.0]), why: "codes 0 (NaN read from bits), B 0: −y with z = −0" },
    Row { func: "decode_normal_signed_oct_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "taken to 1: corner (M, M) = +y, B 1: z = +0; alpha ignored" },
    Row { func: "decode_normal_signed_oct_unorm", case: "out of range, −1, NaN", args: &[V::Vec4([2.0, 7.0, -1.0, NAN])], expect: V::Vec3([0.0, 1.0, -0.0]), why: "R, G taken to 1; B negative → 0: +y with z = −0" },
    Row { func: "decode_normal_signed_oct_unorm", case: "B between codes", args: &[V::Vec4([0.0, 1.0, 0.7, -3.0])], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "code (0, 1023) = −x; B = 0.7 > 1/2: z = +0 (O3DE's sign of 2B − 1)" },
];
