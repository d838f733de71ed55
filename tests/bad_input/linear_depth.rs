//! `wgsl/linear_depth.wgsl` and `linear_depth`: view distance from depth, near/far and
//! per-pixel-constant forms.

use super::{Func, INF, MAX24, NAN, Row, SUB_MAX, SUB_MIN, V};
use prepass::linear_depth as ld;
use prepass::projection::{Depth24Consts, DepthConsts, ReversedDepthConsts};

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
        "ld_positive_inf",
        "private to linear_depth.wgsl: builds +Inf from bits for the far-plane rows",
    ),
    (
        "ld_nan",
        "private to linear_depth.wgsl: builds NaN from bits for the NaN rows",
    ),
    (
        "ld_near_over_far",
        "private to linear_depth.wgsl: n/f, 0 when far = +Inf (infinite-far rows)",
    ),
    (
        "ld_divide_or_inf",
        "private to linear_depth.wgsl: n/s, +Inf at s = 0 (far-plane rows)",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Linear depth (near 1, far 2 unless stated: every expected value below is exact in f32).
    Row { func: "view_z_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24", case: "out-of-range code, far +Inf", args: &[V::U32(u32::MAX), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "far code of an infinite projection → +Inf" },
    Row { func: "view_z_from_depth24", case: "zero", args: &[V::U32(0), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "code 0 = near plane" },
    Row { func: "view_z_from_depth24_consts", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Vec2([16_777_215.0, 0.5])], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24_consts", case: "far +Inf (n/f = 0)", args: &[V::U32(MAX24), V::Vec2([16_777_215.0, 0.0])], expect: V::F32(INF), why: "far code → +Inf" },
    Row { func: "view_z_from_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN (found from its bits)" },
    Row { func: "view_z_from_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 1 = far" },
    Row { func: "view_z_from_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_depth", case: "subnormal", args: &[V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "near, flushed or not" },
    Row { func: "view_z_from_depth", case: "out of range", args: &[V::F32(1.5), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "clamped to 1; infinite far → +Inf" },
    Row { func: "view_z_from_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_depth_consts", case: "out of range", args: &[V::F32(-3.0), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_reversed_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_reversed_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 1 = near" },
    Row { func: "view_z_from_reversed_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 0 = far" },
    Row { func: "view_z_from_reversed_depth", case: "subnormal", args: &[V::F32(SUB_MIN), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "far, flushed or not" },
    Row { func: "view_z_from_reversed_depth", case: "zero, far +Inf (sky)", args: &[V::F32(0.0), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "the sky of reversed-infinite → +Inf" },
    Row { func: "view_z_from_reversed_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_reversed_depth_consts", case: "−0.0, infinite (k = (1, 1, 0))", args: &[V::F32(-0.0), V::Vec3([1.0, 1.0, 0.0])], expect: V::F32(INF), why: "the sky → +Inf" },
];
