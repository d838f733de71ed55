//! `wgsl/lpp.wgsl` and `lighting::lpp`: the light pre-pass P and C and Engel's specular
//! reconstruction, with the exact references.

use super::{Func, INF, NAN, NEG_NAN, Row, SUB_MAX, SUB_MIN, V, ZN};
use prepass::lighting::lpp;

/// `lpp_cosines` takes a `bool`, which the harness cannot feed: a wrapper takes it as a `u32`.
const LPP_COSINES_WGSL: &str = concat!(
    include_str!("../../wgsl/lpp.wgsl"),
    "\nfn bad_input_lpp_cosines(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>, phong: u32) -> vec2<f32> {\n",
    "    return lpp_cosines(normal, to_eye, to_light, phong != 0u);\n}\n"
);

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_direction(vec3) -> Vec3),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_luminance(vec3) -> F32),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_pow_cosine(f32, f32) -> F32),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_point_attenuation(f32, f32) -> F32),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_spot_attenuation(f32, f32, f32) -> F32),
    Func {
        rust: "lighting::lpp::lpp_cosines",
        wgsl: Some((LPP_COSINES_WGSL, "bad_input_lpp_cosines")),
        twin: |a| {
            let (d, s) = lpp::lpp_cosines(a[0].vec3(), a[1].vec3(), a[2].vec3(), a[3].u32() != 0);
            V::Vec2([d, s])
        },
    },
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_blinn_phong_light(vec3, vec3, vec3, vec3, f32, f32) -> Vec4),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_phong_light(vec3, vec3, vec3, vec3, f32, f32) -> Vec4),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_point_light(vec3, vec3, vec3, vec4, f32) -> Vec4),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_spot_light(vec3, vec3, vec3, vec4, vec4, f32, f32) -> Vec4),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_blinn_phong_specular_rgb(vec3, vec3, vec3, vec3, f32, f32) -> Vec3),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_reconstruct_specular(vec4, f32) -> F32),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_combine(vec3, vec3, vec4, f32) -> Vec3),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_combine_two_buffers(vec3, vec3, vec3, vec3) -> Vec3),
    func!(prepass::wgsl::LPP; lighting::lpp; lpp_clamp_colour(vec3) -> Vec3),
    Func {
        rust: "lighting::lpp::exact::unit",
        wgsl: None,
        twin: |a| V::F64x3(lpp::exact::unit(a[0].f64x3())),
    },
    Func {
        rust: "lighting::lpp::exact::lpp_cosines",
        wgsl: None,
        twin: |a| {
            let (d, s) = lpp::exact::lpp_cosines(a[0].f64x3(), a[1].f64x3(), a[2].f64x3());
            V::F64x2([d, s])
        },
    },
    Func {
        rust: "lighting::lpp::exact::multi_light_specular",
        wgsl: None,
        twin: |a| {
            // Arguments: normal, to_eye, material power, then (to_light, lum, att, n) per light.
            let lights: Vec<lpp::exact::Light> = a[3..]
                .chunks(4)
                .map(|l| (l[0].f64x3(), l[1].f64(), l[2].f64(), l[3].f64()))
                .collect();
            V::F64(lpp::exact::multi_light_specular(
                a[0].f64x3(),
                a[1].f64x3(),
                &lights,
                a[2].f64(),
            ))
        },
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "lpp_scale",
        "private to lpp.wgsl: an exact power-of-two scale instead of a division, exercised by the huge-direction rows",
    ),
    (
        "lpp_finite",
        "private to lpp.wgsl: finiteness test on bits, exercised by every NaN/Inf row",
    ),
    (
        "lpp_finite3",
        "private to lpp.wgsl: finiteness test on bits, exercised by every NaN/Inf row",
    ),
    (
        "lpp_point_falloff",
        "private to lpp.wgsl: the scaled distance falloff of lpp_point_light and lpp_spot_light, exercised by their rows",
    ),
    (
        "lpp_light",
        "private to lpp.wgsl: the body of lpp_blinn_phong_light and lpp_phong_light",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Light pre-pass (unit vectors along z unless stated: every expected value below is exact).
    Row { func: "lpp_direction", case: "NaN", args: &[V::Vec3([NAN, 0.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "+Inf", args: &[V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "zero vector", args: &[V::Vec3([0.0; 3])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0; 3])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "subnormal", args: &[V::Vec3([SUB_MAX, -SUB_MIN, 0.0])], expect: V::Vec3([0.0; 3]), why: "largest component subnormal → zero" },
    Row { func: "lpp_direction", case: "huge (|v|² would overflow)", args: &[V::Vec3([-f32::MAX, 0.0, 0.0])], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "scaled by the largest component first" },
    Row { func: "lpp_luminance", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::F32(0.0), why: "NaN channel → 0" },
    Row { func: "lpp_luminance", case: "+Inf", args: &[V::Vec3([INF, 0.0, 0.0])], expect: V::F32(0.2126 * 8.507_059e37), why: "+Inf → 2^126: finite" },
    Row { func: "lpp_luminance", case: "+Inf − Inf", args: &[V::Vec3([INF, -INF, 0.0])], expect: V::F32(0.2126 * 8.507_059e37 - 0.7152 * 8.507_059e37), why: "±2^126 weighted: finite" },
    Row { func: "lpp_luminance", case: "negative channel", args: &[V::Vec3([-1.0, 0.0, 0.0])], expect: V::F32(-0.2126), why: "not clamped (callers clamp colours first)" },
    Row { func: "lpp_pow_cosine", case: "NaN cosine", args: &[V::F32(NAN), V::F32(8.0)], expect: V::F32(0.0), why: "x ≤ 0 or NaN → 0" },
    Row { func: "lpp_pow_cosine", case: "N·H > 1", args: &[V::F32(1.5), V::F32(8.0)], expect: V::F32(1.0), why: "x ≥ 1 → 1" },
    Row { func: "lpp_pow_cosine", case: "+Inf cosine", args: &[V::F32(INF), V::F32(8.0)], expect: V::F32(1.0), why: "x ≥ 1 → 1" },
    Row { func: "lpp_pow_cosine", case: "−Inf cosine", args: &[V::F32(-INF), V::F32(8.0)], expect: V::F32(0.0), why: "x ≤ 0 → 0" },
    Row { func: "lpp_pow_cosine", case: "zero cosine, zero power", args: &[V::F32(0.0), V::F32(0.0)], expect: V::F32(0.0), why: "0^y = 0, even for y = 0" },
    Row { func: "lpp_pow_cosine", case: "zero power", args: &[V::F32(0.5), V::F32(0.0)], expect: V::F32(1.0), why: "x^0 = 1 for x > 0" },
    Row { func: "lpp_pow_cosine", case: "subnormal cosine", args: &[V::F32(SUB_MIN), V::F32(1.0)], expect: V::F32(0.0), why: "below 2^-126 → 0, flushed or not" },
    Row { func: "lpp_pow_cosine", case: "NaN power", args: &[V::F32(0.5), V::F32(NAN)], expect: V::F32(0.0), why: "no highlight" },
    Row { func: "lpp_pow_cosine", case: "+Inf power", args: &[V::F32(0.5), V::F32(INF)], expect: V::F32(0.0), why: "x^∞ = 0 for x < 1" },
    Row { func: "lpp_pow_cosine", case: "negative power", args: &[V::F32(0.5), V::F32(-3.0)], expect: V::F32(1.0), why: "acts as power 0" },
    Row { func: "lpp_point_attenuation", case: "NaN distance", args: &[V::F32(NAN), V::F32(2.0)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "+Inf distance", args: &[V::F32(INF), V::F32(2.0)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "+Inf radius", args: &[V::F32(1.0), V::F32(INF)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "zero radius", args: &[V::F32(0.0), V::F32(0.0)], expect: V::F32(0.0), why: "r ≤ 0 → 0" },
    Row { func: "lpp_point_attenuation", case: "negative radius", args: &[V::F32(0.0), V::F32(-2.0)], expect: V::F32(0.0), why: "r ≤ 0 → 0" },
    Row { func: "lpp_point_attenuation", case: "subnormal radius", args: &[V::F32(1.0), V::F32(SUB_MAX)], expect: V::F32(0.0), why: "beyond the radius, flushed or not" },
    Row { func: "lpp_point_attenuation", case: "negative distance", args: &[V::F32(-1.0), V::F32(2.0)], expect: V::F32(1.0), why: "counts as 0: full light" },
    Row { func: "lpp_point_attenuation", case: "out of range: beyond the radius", args: &[V::F32(3.0), V::F32(2.0)], expect: V::F32(0.0), why: "windowed to 0" },
    Row { func: "lpp_point_attenuation", case: "huge distance, small radius", args: &[V::F32(f32::MAX), V::F32(0.3)], expect: V::F32(0.0), why: "windowed to 0: d/r is never formed beyond r, so no overflow" },
    Row { func: "lpp_spot_attenuation", case: "out of range: cosines beyond ±1 (huge)", args: &[V::F32(3.4027746e38), V::F32(-2.2331028e38), V::F32(3.4027746e38)], expect: V::F32(1.0), why: "clamped to [−1, 1] first: no overflow" },
    Row { func: "lpp_spot_attenuation", case: "NaN", args: &[V::F32(NAN), V::F32(0.5), V::F32(0.9)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_spot_attenuation", case: "+Inf cos_inner", args: &[V::F32(1.0), V::F32(0.5), V::F32(INF)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_spot_attenuation", case: "cos_inner = cos_outer, inside", args: &[V::F32(0.5), V::F32(0.5), V::F32(0.5)], expect: V::F32(1.0), why: "hard edge at cos_outer" },
    Row { func: "lpp_spot_attenuation", case: "cos_inner < cos_outer, outside", args: &[V::F32(0.4), V::F32(0.5), V::F32(0.2)], expect: V::F32(0.0), why: "hard edge at cos_outer" },
    Row { func: "lpp_spot_attenuation", case: "out of range: cosine 2", args: &[V::F32(2.0), V::F32(0.5), V::F32(0.9)], expect: V::F32(1.0), why: "clamped to [0, 1]" },
    Row { func: "lpp_spot_attenuation", case: "out of range: cosine −2", args: &[V::F32(-2.0), V::F32(0.5), V::F32(0.9)], expect: V::F32(0.0), why: "clamped to [0, 1]" },
    Row { func: "lpp_cosines", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "subnormal normal", args: &[V::Vec3([0.0, 0.0, SUB_MAX]), V::Vec3(ZN), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "zero to_eye", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "NaN to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([NAN, 0.0, 1.0]), V::U32(1)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no highlight without N·L" },
    Row { func: "lpp_cosines", case: "N·L < 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, -1.0]), V::U32(1)], expect: V::Vec2([0.0, 0.0]), why: "clamped at 0" },
    Row { func: "lpp_cosines", case: "N·H at its maximum 1", args: &[V::Vec3([0.0, 0.0, 4.0]), V::Vec3(ZN), V::Vec3([0.0, 0.0, 2.0]), V::U32(0)], expect: V::Vec2([1.0, 1.0]), why: "any length; clamped to [0, 1]" },
    Row { func: "lpp_blinn_phong_light", case: "NaN colour", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([NAN, 1.0, 1.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "+Inf colour", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([INF, 1.0, 1.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "NaN power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(NAN)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "+Inf power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(INF)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "−Inf attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(-INF), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "subnormal to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, SUB_MIN]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "attenuation 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(0.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "negative attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(-2.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "clamped to 0" },
    Row { func: "lpp_blinn_phong_light", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-1.0, 2.0, -3.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 2.0, 0.0, 1.4304]), why: "channels clamped to [0, 65504]" },
    Row { func: "lpp_blinn_phong_light", case: "negative power", args: &[V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(-4.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to 0: (N·H)^0 = 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: power 1e30", args: &[V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(1e30)], expect: V::Vec4([0.0, 1.0, 0.0, 0.0]), why: "clamped to 65504: 0.707^65504 → 0" },
    Row { func: "lpp_blinn_phong_light", case: "subnormal power, N·H = 1", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(SUB_MAX)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "1^y = 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: attenuation 2", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(2.0), V::F32(8.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: colour 1e9", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1e9, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 65504.0, 0.0, 46848.46]), why: "clamped to 65504 (fp16 max)" },
    Row { func: "lpp_phong_light", case: "NaN normal", args: &[V::Vec3([NAN, 0.0, 1.0]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "zero to_eye", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "NaN attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(NAN), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "R·V at its maximum 1, negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-1.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to [0, 1]; colour clamped at 0" },
    Row { func: "lpp_point_light", case: "zero radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "negative radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, -2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "NaN radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, NAN]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "zero to_light (light at the surface)", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "no direction → zero light" },
    Row { func: "lpp_point_light", case: "+Inf to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, INF]), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_point_light", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, 1e-30]), V::Vec4([-1.0, -1.0, -1.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "colour clamped to 0" },
    Row { func: "lpp_spot_light", case: "zero-length axis", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, 0.0, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "cosine 0: outside the cone" },
    Row { func: "lpp_spot_light", case: "NaN cos_inner", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, -1.0, 0.5]), V::F32(NAN), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "cone factor 0" },
    Row { func: "lpp_spot_light", case: "+Inf axis", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, -INF, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "no axis: cosine 0, outside the cone" },
    Row { func: "lpp_spot_light", case: "zero radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 0.0]), V::Vec4([0.0, 0.0, -1.0, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "NaN power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(NAN)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "zero-length normal", args: &[V::Vec3([-0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "attenuation 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(0.0), V::F32(8.0)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "N·H at its maximum 1, negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-5.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "(N·H)^n = 1; colour clamped at 0" },
    Row { func: "lpp_reconstruct_specular", case: "NaN light", args: &[V::Vec4([NAN, 1.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "+Inf a", args: &[V::Vec4([0.0, 1.0, 0.0, INF]), V::F32(8.0)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "NaN material power", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(NAN)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "zero diffuse (lum 0)", args: &[V::Vec4([0.0, 0.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "nothing to divide by" },
    Row { func: "lpp_reconstruct_specular", case: "negative diffuse", args: &[V::Vec4([-1.0, -1.0, -1.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "clamped at 0: lum 0" },
    Row { func: "lpp_reconstruct_specular", case: "subnormal luminance", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "lum below 2^-126 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "zero a", args: &[V::Vec4([0.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::F32(0.0), why: "a ≤ 0 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "negative a", args: &[V::Vec4([0.0, 1.0, 0.0, -1.0]), V::F32(8.0)], expect: V::F32(0.0), why: "a ≤ 0 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "out of range: a > lum (ratio > 1)", args: &[V::Vec4([0.0, 1.0, 0.0, 5.0]), V::F32(8.0)], expect: V::F32(0.7152), why: "ratio clamped to 1: never above lum" },
    Row { func: "lpp_reconstruct_specular", case: "negative material power", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(-2.0)], expect: V::F32(0.7152), why: "clamped to 0: ratio^0 = 1" },
    Row { func: "lpp_reconstruct_specular", case: "out of range: material power 1e30", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(1e30)], expect: V::F32(0.0), why: "clamped to 65504: 0.7^65504 → 0" },
    Row { func: "lpp_combine", case: "NaN albedo", args: &[V::Vec3([NAN, 1.0, 0.0]), V::Vec3([0.0; 3]), V::Vec4([1.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN channel → 0" },
    Row { func: "lpp_combine", case: "NaN light", args: &[V::Vec3([1.0; 3]), V::Vec3([1.0; 3]), V::Vec4([NAN, 1.0, 0.0, 0.5]), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN channel → 0; no specular" },
    Row { func: "lpp_combine", case: "+Inf gloss", args: &[V::Vec3([0.0; 3]), V::Vec3([INF, 0.0, 0.0]), V::Vec4([0.0, 1.0, 0.0, 5.0]), V::F32(8.0)], expect: V::Vec3([46848.46, 0.0, 0.0]), why: "gloss clamped to 65504" },
    Row { func: "lpp_combine", case: "negative light", args: &[V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec4([-1.0, 2.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec3([0.0, 2.0, 0.0]), why: "lights never subtract" },
    Row { func: "lpp_combine_two_buffers", case: "NaN, −1 albedo", args: &[V::Vec3([NAN, 1.0, -1.0]), V::Vec3([0.0; 3]), V::Vec3([1.0; 3]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN → 0, clamped at 0" },
    Row { func: "lpp_combine_two_buffers", case: "+Inf diffuse", args: &[V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec3([INF, 2.0, 0.0]), V::Vec3([0.0; 3])], expect: V::Vec3([65504.0, 2.0, 0.0]), why: "clamped to 65504" },
    Row { func: "lpp_combine_two_buffers", case: "−Inf specular", args: &[V::Vec3([0.0; 3]), V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec3([-INF, 3.0, NAN])], expect: V::Vec3([0.0, 3.0, 0.0]), why: "clamped at 0; NaN → 0" },
    Row { func: "lpp_clamp_colour", case: "NaN, ±Inf", args: &[V::Vec3([NAN, -INF, INF])], expect: V::Vec3([0.0, 0.0, 65504.0]), why: "NaN → 0, clamped to [0, 65504]" },
    Row { func: "lpp_clamp_colour", case: "−NaN, out of range", args: &[V::Vec3([NEG_NAN, -3.0, 1e9])], expect: V::Vec3([0.0, 0.0, 65504.0]), why: "clamped to [0, 65504]" },
    Row { func: "lighting::lpp::exact::unit", case: "zero vector", args: &[V::F64x3([0.0; 3])], expect: V::F64x3([0.0; 3]), why: "zero, like the twins" },
    Row { func: "lighting::lpp::exact::unit", case: "NaN", args: &[V::F64x3([f64::NAN, 0.0, 1.0])], expect: V::F64x3([f64::NAN; 3]), why: "propagates (reference only)" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "zero-length normal", args: &[V::F64x3([0.0; 3]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64x2([0.0, 0.0]), why: "no light, like the twins" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "NaN normal", args: &[V::F64x3([f64::NAN, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64x2([0.0, 0.0]), why: "max(NaN, 0) = 0: no light" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "N·L = 0", args: &[V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64x2([0.0, 0.0]), why: "no highlight without N·L" },
    Row { func: "lighting::lpp::exact::multi_light_specular", case: "zero-length normal", args: &[V::F64x3([0.0; 3]), V::F64x3([0.0, 0.0, 1.0]), V::F64(8.0), V::F64x3([0.0, 0.0, 1.0]), V::F64(1.0), V::F64(1.0), V::F64(16.0)], expect: V::F64(0.0), why: "no light" },
];
