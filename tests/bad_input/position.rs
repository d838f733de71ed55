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

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "pos_sane",
        "private to position.wgsl: a lane made finite and clamped to ±2^40, exercised by every NaN, ±Inf and huge row",
    ),
    (
        "pos_sane2",
        "private to position.wgsl: pos_sane per lane of a vec2",
    ),
    (
        "pos_sane3",
        "private to position.wgsl: pos_sane per lane of a vec3",
    ),
];

const SKY: f32 = prepass::linear_depth::SKY;
const LIM: f32 = prepass::position::LIMIT;

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Position rebuild: every input lane read from its bits first (NaN → 0, ±Inf → ±2^40) and
    // clamped to [−2^40, 2^40], so every result is finite.
    Row { func: "frustum_ray", case: "NaN", args: &[V::Vec2([NAN, 0.5]), V::Vec2([1.0, 2.0])], expect: V::Vec3([0.0, 1.0, 1.0]), why: "NaN lane → 0; z stays 1" },
    Row { func: "frustum_ray", case: "+Inf", args: &[V::Vec2([INF, -INF]), V::Vec2([1.0, 2.0])], expect: V::Vec3([LIM, -2.0 * LIM, 1.0]), why: "±Inf → ±2^40 per lane" },
    Row { func: "frustum_ray", case: "huge", args: &[V::Vec2([3e38, 1.0]), V::Vec2([3e38, 1.0])], expect: V::Vec3([LIM * LIM, 1.0, 1.0]), why: "lanes clamped to 2^40: no overflow" },
    Row { func: "frustum_ray_rh", case: "zero vector", args: &[V::Vec2([0.0, 0.0]), V::Vec2([0.0, 0.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "the view axis" },
    Row { func: "view_position", case: "sky sentinel view z", args: &[V::Vec3([0.5, 0.0, -1.0]), V::F32(SKY)], expect: V::Vec3([0.5 * LIM, 0.0, -LIM]), why: "the point 2^40 along the ray" },
    Row { func: "view_position", case: "+Inf view z", args: &[V::Vec3([0.5, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([0.5 * LIM, 0.0, -LIM]), why: "+Inf → 2^40: finite" },
    Row { func: "view_position", case: "NaN view z", args: &[V::Vec3([0.5, 0.0, 1.0]), V::F32(NAN)], expect: V::Vec3([0.0, 0.0, 0.0]), why: "NaN → 0: the eye" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index 3", args: &[V::U32(3)], expect: V::Vec2([3.0, 3.0]), why: "low two bits: off screen" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Vec2([3.0, 3.0]), why: "low two bits" },
    Row { func: "fullscreen_triangle_ray", case: "out-of-range index 6", args: &[V::U32(6), V::Vec2([1.0, 0.5])], expect: V::Vec3([-1.0, 1.5, 1.0]), why: "index 6 reads as 2" },
    Row { func: "fullscreen_triangle_ray_rh", case: "NaN", args: &[V::U32(0), V::Vec2([NAN, 1.0])], expect: V::Vec3([-0.0, -1.0, -1.0]), why: "NaN lane → 0 (−1·0 = −0)" },
    Row { func: "ndc_from_uv", case: "out of range", args: &[V::Vec2([2.0, -1.0])], expect: V::Vec2([3.0, 3.0]), why: "not clamped to the screen" },
    Row { func: "ndc_from_uv", case: "NaN", args: &[V::Vec2([NAN, 0.25])], expect: V::Vec2([-1.0, 0.5]), why: "NaN lane → 0" },
    Row { func: "ndc_from_uv", case: "−Inf", args: &[V::Vec2([-INF, 0.25])], expect: V::Vec2([-2.0 * LIM - 1.0, 0.5]), why: "−Inf → −2^40" },
    Row { func: "world_ray", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 0.0, 0.0]), why: "NaN lane → 0" },
    Row { func: "world_ray", case: "NaN matrix", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([NAN, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 2.0, 3.0]), why: "NaN matrix lane → 0" },
    Row { func: "world_ray", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 0.0, 0.0]), why: "zero" },
    Row { func: "camera_relative_position", case: "sky sentinel view z", args: &[V::Vec3([1.0, 0.0, -1.0]), V::F32(SKY)], expect: V::Vec3([LIM, 0.0, -LIM]), why: "the point 2^40 along the ray" },
    Row { func: "world_position", case: "+Inf camera", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(1.0), V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([LIM + 1.0, 0.0, 0.0]), why: "+Inf → 2^40" },
    Row { func: "world_position", case: "NaN view z", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(NAN), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "NaN → 0: the camera" },
];
