//! `wgsl/aggregate_light.wgsl` and `lighting::aggregate_light`: God of War III's aggregate
//! vertex lights.

use super::{Func, INF, NAN, Row, SUB_MAX, V, ZN};
use glam::Vec3;
use prepass::lighting::aggregate_light as agg;

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::AGGREGATE_LIGHT; lighting::aggregate_light; aggregate_light_accumulate(vec4, vec3, vec3, f32) -> Vec4),
    func!(prepass::wgsl::AGGREGATE_LIGHT; lighting::aggregate_light; aggregate_light_direction(vec4) -> Vec3),
    func!(prepass::wgsl::AGGREGATE_LIGHT; lighting::aggregate_light; aggregate_light_position(vec4, vec3) -> Vec3),
    func!(prepass::wgsl::AGGREGATE_LIGHT; lighting::aggregate_light; aggregate_light_accumulate_colour(vec3, vec3, vec3, vec3, vec3) -> Vec3),
    func!(prepass::wgsl::AGGREGATE_LIGHT; lighting::aggregate_light; aggregate_light_diffuse(vec3, vec3, vec3, vec3) -> Vec3),
    Func {
        rust: "lighting::aggregate_light::aggregate",
        wgsl: None,
        twin: |a| {
            // Arguments: the vertex, then (position, weight, colour) per light.
            let lights: Vec<(Vec3, f32, Vec3)> = a[1..]
                .chunks(3)
                .map(|l| (l[0].vec3(), l[1].f32(), l[2].vec3()))
                .collect();
            let (p, c) = agg::aggregate(a[0].vec3(), &lights);
            V::Vec3x2([p.to_array(), c.to_array()])
        },
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "aggregate_light_scale",
        "private to aggregate_light.wgsl: an exact power-of-two scale instead of a division, exercised by the huge rows",
    ),
    (
        "aggregate_light_sane3",
        "private to aggregate_light.wgsl: lanes made finite within ±limit, exercised by the NaN, ±Inf and overflow rows",
    ),
    (
        "aggregate_light_sane4",
        "private to aggregate_light.wgsl: aggregate_light_sane3 on an accumulator, exercised by the accumulator rows",
    ),
    (
        "aggregate_light_finite3",
        "private to aggregate_light.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    (
        "aggregate_light_unit",
        "private to aggregate_light.wgsl: the guarded normalise behind aggregate_light_direction",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Aggregate lights (accumulator (1, 2, 3, 4) where a skipped light must leave it unchanged).
    Row { func: "aggregate_light_accumulate", case: "NaN vertex", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([NAN, 0.0, 0.0]), V::Vec3(ZN), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "+Inf light position", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([0.0, INF, 0.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "NaN weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(NAN)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "+Inf weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(INF)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "zero vector (light at the vertex)", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([5.0, 5.0, 5.0]), V::Vec3([5.0, 5.0, 5.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "no direction: skipped" },
    Row { func: "aggregate_light_accumulate", case: "within 2^-64 of the vertex", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([1e-20, -1e-20, 0.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "no direction: skipped" },
    Row { func: "aggregate_light_accumulate", case: "P − V would overflow", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([-3e38, 0.0, 0.0]), V::Vec3([3e38, 0.0, 0.0]), V::F32(1.0)], expect: V::Vec4([2.0, 2.0, 3.0, 4.0]), why: "positions read within ±2^100: a far light along +x" },
    Row { func: "aggregate_light_accumulate", case: "NaN and +Inf accumulator", args: &[V::Vec4([NAN, INF, 3.0, 4.0]), V::Vec3([NAN, 0.0, 0.0]), V::Vec3(ZN), V::F32(1.0)], expect: V::Vec4([0.0, 1.267_650_6e30, 3.0, 4.0]), why: "lanes read finite (NaN → 0, +Inf → 2^100); light skipped" },
    Row { func: "aggregate_light_accumulate", case: "negative intensity", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([0.0, 3.0, 4.0]), V::F32(-5.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "clamped to 0: adds nothing" },
    Row { func: "aggregate_light_accumulate", case: "subnormal weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(SUB_MAX)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "adds below half an ULP of the sums" },
    Row { func: "aggregate_light_accumulate", case: "out of range: weight 1e20", args: &[V::Vec4([0.0; 4]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(1e20)], expect: V::Vec4([0.0, 0.0, 1_099_511_627_776.0, 1_099_511_627_776.0]), why: "clamped to 2^40" },
    Row { func: "aggregate_light_direction", case: "NaN", args: &[V::Vec4([NAN, 0.0, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "+Inf", args: &[V::Vec4([0.0, -INF, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "zero vector (directions cancel)", args: &[V::Vec4([0.0, 0.0, 0.0, 2.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "subnormal", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "largest component subnormal → zero" },
    Row { func: "aggregate_light_direction", case: "huge", args: &[V::Vec4([0.0, f32::MAX, 0.0, 1.0])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "scaled first: no overflow" },
    Row { func: "aggregate_light_position", case: "NaN acc", args: &[V::Vec4([NAN, 0.0, 1.0, 1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "NaN weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, NAN]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "+Inf weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, INF]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "zero acc (nothing accumulated)", args: &[V::Vec4([0.0; 4]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "subnormal acc.xyz (directions cancel)", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "zero weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, 0.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "offset beyond 2^101 (tiny weight sum)", args: &[V::Vec4([1e30, 0.0, 0.0, 1e-30]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex: no overflow" },
    Row { func: "aggregate_light_position", case: "NaN vertex", args: &[V::Vec4([0.0, 0.0, 1.0, 1.0]), V::Vec3([NAN, 2.0, 3.0])], expect: V::Vec3([0.0, 2.0, 4.0]), why: "vertex lanes read finite (NaN → 0)" },
    Row { func: "aggregate_light_position", case: "negative weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, -1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_accumulate_colour", case: "NaN accumulator", args: &[V::Vec3([NAN, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([NAN, 1.0, 1.0]), V::Vec3(ZN)], expect: V::Vec3([0.0, 2.0, 3.0]), why: "lanes read finite (NaN → 0); light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "huge aggregate direction", args: &[V::Vec3([0.0; 3]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1e20, 0.0, 0.0]), V::Vec3([0.0, 0.0, 3e38])], expect: V::Vec3([1_099_511_627_776.0 * 1_099_511_627_776.0, 0.0, 0.0]), why: "colour ≤ 2^40, direction lanes ≤ 2^40: finite" },
    Row { func: "aggregate_light_accumulate_colour", case: "NaN colour", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([NAN, 1.0, 1.0]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "+Inf aggregate direction", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3([0.0, 0.0, INF])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "zero vector (light at the vertex)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "zero aggregate direction (cancelled)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3([0.0; 3])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "colour term zero" },
    Row { func: "aggregate_light_accumulate_colour", case: "negative intensity", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([-1.0, -2.0, -3.0]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "clamped to 0: adds nothing" },
    Row { func: "aggregate_light_accumulate_colour", case: "out of range: colour 1e20", args: &[V::Vec3([0.0; 3]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1e20, 0.0, 0.0]), V::Vec3(ZN)], expect: V::Vec3([1_099_511_627_776.0, 0.0, 0.0]), why: "clamped to 2^40" },
    Row { func: "aggregate_light_diffuse", case: "P_agg − p would overflow, huge colour", args: &[V::Vec3([1.0, 0.0, 0.0]), V::Vec3([-3e38, 0.0, 0.0]), V::Vec3([3e38, 0.0, 0.0]), V::Vec3([f32::MAX, 0.0, 0.0])], expect: V::Vec3([1.267_650_6e30, 0.0, 0.0]), why: "positions and colour read within ±2^100" },
    Row { func: "aggregate_light_diffuse", case: "NaN position", args: &[V::Vec3(ZN), V::Vec3([NAN, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "+Inf colour", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([INF, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "NaN normal", args: &[V::Vec3([0.0, NAN, 1.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "zero vector (P_agg = p)", args: &[V::Vec3(ZN), V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no direction → 0" },
    Row { func: "aggregate_light_diffuse", case: "N·L < 0", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3([0.0, 0.0, -1.0]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "clamped at 0" },
    Row { func: "aggregate_light_diffuse", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([-1.0, 2.0, 0.0])], expect: V::Vec3([0.0, 2.0, 0.0]), why: "channels clamped at 0" },
    Row { func: "lighting::aggregate_light::aggregate", case: "no lights", args: &[V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "the vertex, no colour" },
    Row { func: "lighting::aggregate_light::aggregate", case: "NaN light", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([NAN, 2.0, 4.0]), V::F32(1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "skipped" },
    Row { func: "lighting::aggregate_light::aggregate", case: "negative intensity", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0, 2.0, 4.0]), V::F32(-1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "weight 0: nothing accumulated" },
    Row { func: "lighting::aggregate_light::aggregate", case: "zero vector (directions cancel)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([2.0, 2.0, 3.0]), V::F32(1.0), V::Vec3([1.0; 3]), V::Vec3([0.0, 2.0, 3.0]), V::F32(1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "zero direction: the vertex, no colour" },
];
