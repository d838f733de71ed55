//! `wgsl/normal_substrate.wgsl` and `normal::substrate`: Unreal 5 Substrate's top-layer word, an
//! 11:11 centred octahedral normal (bits 10–31), the roughness byte (bits 2–9) and 2 flag bits.

use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};

/// Code (0, 0), both coordinates −1024/1023 (outside the square): Unreal's fold reads it as the
/// direction just across the corner, `normalize(1, 1, −1023)`, each step correctly rounded.
const C0_XY: f32 = f32::from_bits(0x3a7f_c000);
const C0_Z: f32 = f32::from_bits(0xbf7f_fff0);
/// Code (0, 1024): `normalize(−1023, −1, −1)`, rounded.
const C1_X: f32 = f32::from_bits(0xbf7f_fff0);
const C1_YZ: f32 = f32::from_bits(0xba80_2000);

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; encode_substrate_normal(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; encode_substrate_normal_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; encode_substrate_word(vec3, f32, u32) -> U32),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; encode_substrate_word_fast(vec3, f32, u32) -> U32),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; decode_substrate_normal(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; decode_substrate_roughness(u32) -> F32),
    func!(prepass::wgsl::NORMAL_SUBSTRATE; normal::substrate; substrate_flags(u32) -> U32),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "substrate_sanitize",
        "private to normal_substrate.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
    ),
    (
        "substrate_continuous",
        "private: the projection, exercised by every encoder row",
    ),
    (
        "substrate_choose",
        "private: the precise choice, exercised by the precise encoders' rows",
    ),
    (
        "substrate_lattice",
        "private: the decoders' integer direction, exercised by every decoder row",
    ),
    (
        "substrate_roughness_byte",
        "private: the roughness byte, exercised by the word encoders' rows",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Normal encoders (the rules they share are in `normal.rs`). +z is codes (1024, 1024).
    Row { func: "encode_substrate_normal", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8010_0000), why: "NaN anywhere → code of +z" },
    Row { func: "encode_substrate_normal", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x8010_0000), why: "every NaN → code of +z" },
    Row { func: "encode_substrate_normal", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x801f_fc00), why: "infinities win: code of +x, (2047, 1024)" },
    Row { func: "encode_substrate_normal", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4017_fc00), why: "their signs: the closer of the two codes tied at (1, −1, 0)/√2" },
    Row { func: "encode_substrate_normal", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff_fc00), why: "infinities win: code of −z, (2047, 2047)" },
    Row { func: "encode_substrate_normal", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8010_0000), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_substrate_normal", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff0_0000), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_substrate_normal", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8010_0000), why: "code of +z" },
    Row { func: "encode_substrate_normal", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x8010_0000), why: "code of +z" },
    Row { func: "encode_substrate_normal", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaab5_5400), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_substrate_normal", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0030_0000), why: "no underflow: code of −y, (1024, 1)" },
    Row { func: "encode_substrate_normal", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x801f_fc00), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_substrate_normal_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8010_0000), why: "NaN anywhere → code of +z" },
    Row { func: "encode_substrate_normal_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4018_0000), why: "their signs: (±511.5 rounded half to even) (1536, 512)" },
    Row { func: "encode_substrate_normal_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8010_0000), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_substrate_normal_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8010_0000), why: "code of +z" },
    // The whole word: normal bits as above, roughness byte as encode_roughness_ggx8, flags & 3.
    Row { func: "encode_substrate_word", case: "roughness NaN", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(NAN), V::U32(0)], expect: V::U32(0x8010_03fc), why: "NaN → byte 255, the roughest" },
    Row { func: "encode_substrate_word", case: "roughness < 0, flags > 3", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(-0.25), V::U32(5)], expect: V::U32(0x8010_0001), why: "clamped to byte 0; flags' low 2 bits" },
    Row { func: "encode_substrate_word", case: "roughness > 1, flags all ones", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(1.5), V::U32(u32::MAX)], expect: V::U32(0x8010_03ff), why: "clamped to byte 255; flags 3" },
    Row { func: "encode_substrate_word", case: "roughness +Inf", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(INF), V::U32(1)], expect: V::U32(0x8010_03fd), why: "byte 255" },
    Row { func: "encode_substrate_word", case: "roughness −Inf", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(-INF), V::U32(2)], expect: V::U32(0x8010_0002), why: "byte 0" },
    Row { func: "encode_substrate_word", case: "roughness subnormal", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(SUB_MAX), V::U32(3)], expect: V::U32(0x8010_0003), why: "byte 0 (nearest 255 r)" },
    Row { func: "encode_substrate_word", case: "NaN normal and roughness", args: &[V::Vec3([NAN, NAN, NAN]), V::F32(NAN), V::U32(0)], expect: V::U32(0x8010_03fc), why: "+z, byte 255" },
    Row { func: "encode_substrate_word_fast", case: "roughness NaN", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(NAN), V::U32(0)], expect: V::U32(0x8010_03fc), why: "NaN → byte 255, the roughest" },
    Row { func: "encode_substrate_word_fast", case: "roughness < 0, flags > 3", args: &[V::Vec3([0.0, 0.0, 1.0]), V::F32(-0.25), V::U32(5)], expect: V::U32(0x8010_0001), why: "clamped to byte 0; flags' low 2 bits" },
    // Decoders: every bit pattern. Code 0 stands for −1024/1023, outside the square.
    Row { func: "decode_substrate_normal", case: "all zeros: code (0, 0)", args: &[V::U32(0)], expect: V::Vec3([C0_XY, C0_XY, C0_Z]), why: "Unreal's fold: (1, 1, −1023)/|·|, rounded" },
    Row { func: "decode_substrate_normal", case: "code (0, 1024)", args: &[V::U32(0x8000_0000)], expect: V::Vec3([C1_X, C1_YZ, C1_YZ]), why: "Unreal's fold: (−1023, −1, −1)/|·|, rounded" },
    Row { func: "decode_substrate_normal", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "code (2047, 2047): −z; bits 0–9 ignored" },
    Row { func: "decode_substrate_roughness", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "byte 255 → 1; other bits ignored" },
    Row { func: "decode_substrate_roughness", case: "all zeros", args: &[V::U32(0)], expect: V::F32(0.0), why: "byte 0 → 0" },
    Row { func: "substrate_flags", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(3), why: "the low 2 bits" },
];
