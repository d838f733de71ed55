//! `wgsl/position.wgsl` and `position`: frustum rays and position rebuild.

use super::{Func, INF, NAN, Row, V};
use prepass::position as pos;

/// `world_ray` takes a `mat3x3`, which the harness cannot feed: a wrapper builds it from columns.
const WORLD_RAY_WGSL: &str = concat!(
    include_str!("../../wgsl/position.wgsl"),
    "\nfn bad_input_world_ray(ray: vec3<f32>, c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>) -> vec3<f32> {\n",
    "    return world_ray(ray, mat3x3<f32>(c0, c1, c2));\n}\n"
);

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::POSITION; position; frustum_ray(vec2, vec2) -> Vec3),
    func!(prepass::wgsl::POSITION; position; frustum_ray_rh(vec2, vec2) -> Vec3),
    func!(prepass::wgsl::POSITION; position; view_position(vec3, f32) -> Vec3),
    func!(prepass::wgsl::POSITION; position; fullscreen_triangle_ndc(u32) -> Vec2),
    func!(prepass::wgsl::POSITION; position; fullscreen_triangle_ray(u32, vec2) -> Vec3),
    func!(prepass::wgsl::POSITION; position; fullscreen_triangle_ray_rh(u32, vec2) -> Vec3),
    func!(prepass::wgsl::POSITION; position; ndc_from_uv(vec2) -> Vec2),
    Func {
        rust: "position::world_ray",
        wgsl: Some((WORLD_RAY_WGSL, "bad_input_world_ray")),
        twin: |a| {
            let m = glam::Mat3::from_cols(a[1].vec3(), a[2].vec3(), a[3].vec3());
            V::Vec3(pos::world_ray(a[0].vec3(), m).to_array())
        },
    },
    func!(prepass::wgsl::POSITION; position; camera_relative_position(vec3, f32) -> Vec3),
    func!(prepass::wgsl::POSITION; position; world_position(vec3, f32, vec3) -> Vec3),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Position rebuild: plain products and sums; NaN and ±Inf propagate as IEEE arithmetic does.
    Row { func: "frustum_ray", case: "NaN", args: &[V::Vec2([NAN, 0.5]), V::Vec2([1.0, 2.0])], expect: V::Vec3([NAN, 1.0, 1.0]), why: "propagates per lane; z stays 1" },
    Row { func: "frustum_ray", case: "+Inf", args: &[V::Vec2([INF, -INF]), V::Vec2([1.0, 2.0])], expect: V::Vec3([INF, -INF, 1.0]), why: "propagates per lane" },
    Row { func: "frustum_ray_rh", case: "zero vector", args: &[V::Vec2([0.0, 0.0]), V::Vec2([0.0, 0.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "the view axis" },
    Row { func: "view_position", case: "+Inf view z (sky)", args: &[V::Vec3([0.5, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "view_position", case: "NaN view z", args: &[V::Vec3([0.5, 0.0, 1.0]), V::F32(NAN)], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index 3", args: &[V::U32(3)], expect: V::Vec2([3.0, 3.0]), why: "low two bits: off screen" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Vec2([3.0, 3.0]), why: "low two bits" },
    Row { func: "fullscreen_triangle_ray", case: "out-of-range index 6", args: &[V::U32(6), V::Vec2([1.0, 0.5])], expect: V::Vec3([-1.0, 1.5, 1.0]), why: "index 6 reads as 2" },
    Row { func: "fullscreen_triangle_ray_rh", case: "NaN", args: &[V::U32(0), V::Vec2([NAN, 1.0])], expect: V::Vec3([NAN, -1.0, -1.0]), why: "propagates per lane" },
    Row { func: "ndc_from_uv", case: "out of range", args: &[V::Vec2([2.0, -1.0])], expect: V::Vec2([3.0, 3.0]), why: "not clamped" },
    Row { func: "ndc_from_uv", case: "NaN", args: &[V::Vec2([NAN, 0.25])], expect: V::Vec2([NAN, 0.5]), why: "propagates per lane" },
    Row { func: "world_ray", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "0·NaN = NaN in every lane" },
    Row { func: "world_ray", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 0.0, 0.0]), why: "zero" },
    Row { func: "camera_relative_position", case: "+Inf view z (sky)", args: &[V::Vec3([1.0, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "world_position", case: "+Inf camera", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(1.0), V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([INF, 0.0, 0.0]), why: "propagates" },
    Row { func: "world_position", case: "NaN view z", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(NAN), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
];
