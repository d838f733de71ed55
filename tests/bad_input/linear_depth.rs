//! `wgsl/linear_depth.wgsl` and `linear_depth`: view distance from depth, near/far and
//! per-pixel-constant forms.

use super::{Func, INF, MAX24, NAN, Row, SUB_MAX, SUB_MIN, V};
use prepass::linear_depth as ld;
use prepass::projection::{Depth24Consts, DepthConsts, DepthUniform, ReversedDepthConsts};

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::LINEAR_DEPTH; linear_depth; view_z_from_depth24(u32, f32, f32) -> F32),
    Func {
        rust: "linear_depth::view_z_from_depth24_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth24_consts(
                a[0].u32(),
                Depth24Consts::from_wgsl(a[1].vec2().to_array()),
            ))
        },
    },
    func!(prepass::wgsl::LINEAR_DEPTH; linear_depth; view_z_from_depth(f32, f32, f32) -> F32),
    Func {
        rust: "linear_depth::view_z_from_depth_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth_consts(
                a[0].f32(),
                DepthConsts::from_wgsl(a[1].vec3().to_array()),
            ))
        },
    },
    func!(prepass::wgsl::LINEAR_DEPTH; linear_depth; view_z_from_reversed_depth(f32, f32, f32) -> F32),
    Func {
        rust: "linear_depth::view_z_from_reversed_depth_consts",
        wgsl: Some((
            prepass::wgsl::LINEAR_DEPTH,
            "view_z_from_reversed_depth_consts",
        )),
        twin: |a| {
            V::F32(ld::view_z_from_reversed_depth_consts(
                a[0].f32(),
                ReversedDepthConsts::from_wgsl(a[1].vec3().to_array()),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_depth_uniform",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth_uniform")),
        twin: |a| {
            V::F32(ld::view_z_from_depth_uniform(
                a[0].f32(),
                DepthUniform::from_wgsl(a[1].vec4().to_array()),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_depth24_uniform",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24_uniform")),
        twin: |a| {
            V::F32(ld::view_z_from_depth24_uniform(
                a[0].u32(),
                DepthUniform::from_wgsl(a[1].vec4().to_array()),
            ))
        },
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "ld_one_minus",
        "private to linear_depth.wgsl: exact 1 - z from the bits, exercised by every standard-depth row with z >= 0.5",
    ),
    (
        "ld_is_nan",
        "private to linear_depth.wgsl: NaN test on bits, exercised by every NaN row",
    ),
    (
        "ld_is_inf",
        "private to linear_depth.wgsl: infinite-far test, exercised by the far = +Inf rows",
    ),
    (
        "ld_view_z_depth24",
        "private to linear_depth.wgsl: the 24-bit path on checked constants, exercised by every depth24 row",
    ),
    (
        "ld_view_z_standard",
        "private to linear_depth.wgsl: the standard path on checked constants, exercised by every standard row",
    ),
    (
        "ld_view_z_reversed",
        "private to linear_depth.wgsl: the reversed path on checked constants, exercised by every reversed row",
    ),
    (
        "ld_near_over_far",
        "private to linear_depth.wgsl: n/f, 0 when far = +Inf (infinite-far rows)",
    ),
    (
        "ld_divide_or_sky",
        "private to linear_depth.wgsl: n/s, the sky sentinel where n/s >= 2^127 (far-plane and sky rows)",
    ),
    (
        "ld_consts_ok",
        "private to linear_depth.wgsl: constants a Projection can give, exercised by the bad-constant rows",
    ),
    (
        "ld_planes_ok",
        "private to linear_depth.wgsl: planes a projection can have, exercised by the bad-plane rows",
    ),
    (
        "ld_uniform_near_times_max",
        "private to linear_depth.wgsl: |k.w| of a depth uniform from its bits, exercised by every depth24 uniform row",
    ),
    (
        "ld_uniform_ok",
        "private to linear_depth.wgsl: uniforms a Projection can give, exercised by the bad-uniform rows",
    ),
    (
        "ld_uniform_reversed",
        "private to linear_depth.wgsl: the convention from the sign bit of k.w, exercised by the reversed uniform rows",
    ),
    (
        "ld_clamp_unit",
        "private to linear_depth.wgsl: z clamped to [0, 1] from its bits, exercised by the ±Inf and out-of-range rows",
    ),
];

const SKY: f32 = prepass::linear_depth::SKY;
/// `Projection::new(1, 2, ·).depth_uniform()`, standard and reversed.
const U_STD: [f32; 4] = [1.0, 0.5, 0.5, 16_777_215.0];
const U_REV: [f32; 4] = [1.0, 0.5, 0.5, -16_777_215.0];
/// 2^104, the largest near plane `Projection::new` takes.
const NEAR_MAX: f32 = 20_282_409_603_651_670_423_947_251_286_016.0;

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Linear depth (near 1, far 2 unless stated: every expected value below is exact in f32).
    Row { func: "view_z_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24", case: "out-of-range code, far +Inf", args: &[V::U32(u32::MAX), V::F32(1.0), V::F32(INF)], expect: V::F32(SKY), why: "far code of an infinite projection → the sky, f32::MAX" },
    Row { func: "view_z_from_depth24", case: "zero", args: &[V::U32(0), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "code 0 = near plane" },
    Row { func: "view_z_from_depth24_consts", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Vec2([16_777_215.0, 0.5])], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24_consts", case: "far +Inf (n/f = 0)", args: &[V::U32(MAX24), V::Vec2([16_777_215.0, 0.0])], expect: V::F32(SKY), why: "far code → the sky, f32::MAX" },
    Row { func: "view_z_from_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(SKY), why: "NaN (found from its bits) → the sky" },
    Row { func: "view_z_from_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 1 = far" },
    Row { func: "view_z_from_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_depth", case: "subnormal", args: &[V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "near, flushed or not" },
    Row { func: "view_z_from_depth", case: "out of range", args: &[V::F32(1.5), V::F32(1.0), V::F32(INF)], expect: V::F32(SKY), why: "clamped to 1; infinite far → the sky" },
    Row { func: "view_z_from_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(SKY), why: "NaN → the sky" },
    Row { func: "view_z_from_depth_consts", case: "out of range", args: &[V::F32(-3.0), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_reversed_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(SKY), why: "NaN → the sky" },
    Row { func: "view_z_from_reversed_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 1 = near" },
    Row { func: "view_z_from_reversed_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 0 = far" },
    Row { func: "view_z_from_reversed_depth", case: "subnormal", args: &[V::F32(SUB_MIN), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "far, flushed or not" },
    Row { func: "view_z_from_reversed_depth", case: "zero, far +Inf (sky)", args: &[V::F32(0.0), V::F32(1.0), V::F32(INF)], expect: V::F32(SKY), why: "the sky of reversed-infinite → f32::MAX" },
    Row { func: "view_z_from_reversed_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(SKY), why: "NaN → the sky" },
    Row { func: "view_z_from_reversed_depth_consts", case: "−0.0, infinite (k = (1, 1, 0))", args: &[V::F32(-0.0), V::Vec3([1.0, 1.0, 0.0])], expect: V::F32(SKY), why: "the sky → f32::MAX" },
    Row { func: "view_z_from_reversed_depth", case: "subnormal, far +Inf", args: &[V::F32(SUB_MIN), V::F32(1.0), V::F32(INF)], expect: V::F32(SKY), why: "n/z ≥ 2^127 → the sky, flushed or not" },
    Row { func: "view_z_from_reversed_depth", case: "NaN near", args: &[V::F32(0.5), V::F32(NAN), V::F32(2.0)], expect: V::F32(SKY), why: "no projection has it → the sky" },
    Row { func: "view_z_from_reversed_depth", case: "far ≤ near", args: &[V::F32(0.5), V::F32(2.0), V::F32(1.0)], expect: V::F32(SKY), why: "no projection has it → the sky" },
    Row { func: "view_z_from_depth", case: "NaN far", args: &[V::F32(0.5), V::F32(1.0), V::F32(NAN)], expect: V::F32(SKY), why: "no projection has it → the sky" },
    Row { func: "view_z_from_depth24", case: "near 2^104 (the largest a Projection takes)", args: &[V::U32(0), V::F32(NEAR_MAX), V::F32(INF)], expect: V::F32(NEAR_MAX), why: "code 0 = near: n·(2^24 − 1) = f32::MAX, finite" },
    Row { func: "view_z_from_depth", case: "subnormal near", args: &[V::F32(0.5), V::F32(SUB_MAX), V::F32(2.0)], expect: V::F32(SKY), why: "near must be normal (as Projection::new)" },
    Row { func: "view_z_from_depth", case: "zero near", args: &[V::F32(0.5), V::F32(0.0), V::F32(2.0)], expect: V::F32(SKY), why: "near must be > 0" },
    Row { func: "view_z_from_depth24", case: "+Inf near", args: &[V::U32(7), V::F32(INF), V::F32(INF)], expect: V::F32(SKY), why: "no projection has it → the sky" },
    Row { func: "view_z_from_depth24", case: "huge near (near·(2^24 − 1) would overflow)", args: &[V::U32(7), V::F32(3e38), V::F32(INF)], expect: V::F32(SKY), why: "near > 2^104 (as Projection::new) → the sky" },
    Row { func: "view_z_from_depth24_consts", case: "NaN constant", args: &[V::U32(7), V::Vec2([NAN, 0.5])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_depth_consts", case: "+Inf constant", args: &[V::F32(0.75), V::Vec3([1.0, INF, 0.5])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_depth_consts", case: "out-of-range constant", args: &[V::F32(0.75), V::Vec3([1.0, 0.5, 2.0])], expect: V::F32(SKY), why: "ratios outside [0, 1] → the sky" },
    Row { func: "view_z_from_reversed_depth_consts", case: "negative near", args: &[V::F32(0.5), V::Vec3([-1.0, 0.5, 0.5])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    // The uniform of near 1, far 2: (n, n/f, (f − n)/f, ±n·(2^24 − 1)), k.w negative when reversed.
    Row { func: "view_z_from_depth_uniform", case: "NaN, standard", args: &[V::F32(NAN), V::Vec4(U_STD)], expect: V::F32(SKY), why: "NaN → the sky" },
    Row { func: "view_z_from_depth_uniform", case: "+Inf, standard", args: &[V::F32(INF), V::Vec4(U_STD)], expect: V::F32(2.0), why: "clamped to 1 = far" },
    Row { func: "view_z_from_depth_uniform", case: "+Inf, reversed", args: &[V::F32(INF), V::Vec4(U_REV)], expect: V::F32(1.0), why: "clamped to 1 = near (reversed)" },
    Row { func: "view_z_from_depth_uniform", case: "−Inf, reversed", args: &[V::F32(-INF), V::Vec4(U_REV)], expect: V::F32(2.0), why: "clamped to 0 = far (reversed)" },
    Row { func: "view_z_from_depth_uniform", case: "zero, reversed infinite (the sky)", args: &[V::F32(0.0), V::Vec4([1.0, 0.0, 1.0, -16_777_215.0])], expect: V::F32(SKY), why: "the sky → f32::MAX" },
    Row { func: "view_z_from_depth_uniform", case: "k.w = −0", args: &[V::F32(0.5), V::Vec4([1.0, 0.5, 0.5, -0.0])], expect: V::F32(SKY), why: "no Projection gives it (|k.w| = 0) → the sky" },
    Row { func: "view_z_from_depth_uniform", case: "k.w NaN", args: &[V::F32(0.5), V::Vec4([1.0, 0.5, 0.5, NAN])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_depth_uniform", case: "ratio above 1", args: &[V::F32(0.5), V::Vec4([1.0, 0.5, 1.5, 16_777_215.0])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_depth24_uniform", case: "out-of-range code, standard", args: &[V::U32(u32::MAX), V::Vec4(U_STD)], expect: V::F32(2.0), why: "saturates to the far code" },
    Row { func: "view_z_from_depth24_uniform", case: "out-of-range code, reversed", args: &[V::U32(u32::MAX), V::Vec4(U_REV)], expect: V::F32(1.0), why: "saturates to 2^24 − 1 = near (reversed)" },
    Row { func: "view_z_from_depth24_uniform", case: "code 0, reversed", args: &[V::U32(0), V::Vec4(U_REV)], expect: V::F32(2.0), why: "reversed code 0 = far" },
    Row { func: "view_z_from_depth24_uniform", case: "code 0, reversed infinite (the sky)", args: &[V::U32(0), V::Vec4([1.0, 0.0, 1.0, -16_777_215.0])], expect: V::F32(SKY), why: "the sky → f32::MAX" },
    Row { func: "view_z_from_depth24_uniform", case: "k.w +Inf", args: &[V::U32(7), V::Vec4([1.0, 0.5, 0.5, INF])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_depth24_uniform", case: "NaN near", args: &[V::U32(7), V::Vec4([NAN, 0.5, 0.5, 16_777_215.0])], expect: V::F32(SKY), why: "no Projection gives it → the sky" },
    Row { func: "view_z_from_reversed_depth_consts", case: "huge constant, tiny depth", args: &[V::F32(1e-30), V::Vec3([3e38, 1.0, 0.0])], expect: V::F32(SKY), why: "n/s ≥ 2^127: no division overflows" },

];
