//! `wgsl/light_volume.wgsl` and `lighting::light_volume`: stencil light volumes and depth bounds.

use super::{Func, INF, MAX24, NAN, Row, SUB_MAX, V, ZN};
use prepass::lighting::light_volume as vol;
use prepass::projection::DepthConvention;

/// The light-volume WGSL's convention argument: 0 standard, anything else reversed.
fn convention(code: u32) -> DepthConvention {
    if code == 0 {
        DepthConvention::Standard
    } else {
        DepthConvention::Reversed
    }
}

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::LIGHT_VOLUME; lighting::light_volume; light_volume_near_corner_distance(f32, f32, f32) -> F32),
    func!(prepass::wgsl::LIGHT_VOLUME; lighting::light_volume; light_volume_sphere_needs_depth_fail(vec3, f32, f32) -> U32),
    func!(prepass::wgsl::LIGHT_VOLUME; lighting::light_volume; light_volume_cone_needs_depth_fail(vec3, vec3, vec2, f32) -> U32),
    Func {
        rust: "lighting::light_volume::light_volume_window_depth",
        wgsl: Some((prepass::wgsl::LIGHT_VOLUME, "light_volume_window_depth")),
        twin: |a| {
            V::F32(vol::light_volume_window_depth(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
                convention(a[3].u32()),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_sphere_depth_bounds",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_sphere_depth_bounds",
        )),
        twin: |a| {
            V::Vec2(
                vol::light_volume_sphere_depth_bounds(
                    a[0].f32(),
                    a[1].f32(),
                    a[2].f32(),
                    a[3].f32(),
                    convention(a[4].u32()),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_sphere_depth_bounds24",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_sphere_depth_bounds24",
        )),
        twin: |a| {
            V::UVec2(vol::light_volume_sphere_depth_bounds24(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
                a[3].f32(),
                convention(a[4].u32()),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::exact::light_volume_window_depth",
        wgsl: None,
        twin: |a| {
            V::F64(vol::exact::light_volume_window_depth(
                a[0].f64(),
                a[1].f64(),
                a[2].f64(),
                convention(a[3].u32()),
            ))
        },
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "light_volume_div",
        "private to light_volume.wgsl: a division within WGSL's specified divisors, exercised by every window-depth row",
    ),
    (
        "light_volume_scale",
        "private to light_volume.wgsl: an exact power-of-two scale instead of a division, exercised by the huge-vector rows",
    ),
    (
        "light_volume_sum_overflows",
        "private to light_volume.wgsl: a + b past f32::MAX decided on the halves, exercised by the overflow rows",
    ),
    (
        "light_volume_finite",
        "private to light_volume.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    (
        "light_volume_finite3",
        "private to light_volume.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    (
        "light_volume_cone_scaled",
        "private to light_volume.wgsl: body of light_volume_cone_needs_depth_fail, with its rows",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Light volumes (near 1, far 2 unless stated): bad input answers depth-fail and the full range.
    Row { func: "light_volume_near_corner_distance", case: "huge tangent", args: &[V::F32(1.0), V::F32(1e30), V::F32(1.0)], expect: V::F32(3.4e38), why: "tan > 2^60: stand-in for +Inf, no square overflows" },
    Row { func: "light_volume_near_corner_distance", case: "near·ρ would overflow", args: &[V::F32(3e38), V::F32(1.0), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf: depth-fail everywhere" },
    Row { func: "light_volume_near_corner_distance", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf: depth-fail everywhere" },
    Row { func: "light_volume_near_corner_distance", case: "+Inf tan", args: &[V::F32(0.1), V::F32(INF), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "negative near", args: &[V::F32(-0.1), V::F32(1.0), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "negative tan", args: &[V::F32(0.1), V::F32(1.0), V::F32(-1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "zero near", args: &[V::F32(0.0), V::F32(1.0), V::F32(1.0)], expect: V::F32(0.0), why: "near·√… = 0" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "NaN centre", args: &[V::Vec3([NAN, 0.0, 10.0]), V::F32(1.0), V::F32(0.1)], expect: V::U32(1), why: "depth-fail (always correct)" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "+Inf radius", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(INF), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "NaN near-corner distance", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(1.0), V::F32(NAN)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "negative radius", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(-1.0), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "negative near-corner distance", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(1.0), V::F32(-0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "zero vector, zero radius", args: &[V::Vec3([0.0; 3]), V::F32(0.0), V::F32(0.0)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "out of range: r + ρ overflows", args: &[V::Vec3([0.0, 0.0, 0.5]), V::F32(3.3895363e38), V::F32(f32::MAX)], expect: V::U32(1), why: "depth-fail: the reach covers every finite centre" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "subnormal", args: &[V::Vec3([SUB_MAX, 0.0, 0.0]), V::F32(0.0), V::F32(0.0)], expect: V::U32(1), why: "depth-fail, flushed or not" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "huge centre (c·c would overflow)", args: &[V::Vec3([0.0, 0.0, 3e38]), V::F32(1.0), V::F32(0.1)], expect: V::U32(0), why: "scaled first: far away, depth-pass" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "NaN apex", args: &[V::Vec3([NAN, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "tiny lengths (squares would underflow), apex at ρ", args: &[V::Vec3([1.2830058e-22, 0.0, 0.0]), V::Vec3(ZN), V::Vec2([0.0, 0.0]), V::F32(1.2830058e-22)], expect: V::U32(1), why: "scaled first: the apex is within ρ, depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "zero-length axis", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0; 3]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "subnormal axis", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0, SUB_MAX, 0.0]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail, flushed or not" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "+Inf length", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([INF, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative tan", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, -0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative length", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([-10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative near-corner distance", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(-0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "+Inf near-corner distance", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(INF)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "huge axis (any length)", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0, 0.0, f32::MAX]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(0), why: "scaled first: far away, depth-pass" },
    Row { func: "light_volume_window_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::F32(1.0), why: "NaN → the far end" },
    Row { func: "light_volume_window_depth", case: "+Inf view depth, far +Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(0)], expect: V::F32(1.0), why: "1 − n/∞ = 1" },
    Row { func: "light_volume_window_depth", case: "+Inf view depth, far +Inf, reversed", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(1)], expect: V::F32(0.0), why: "n/∞ = 0" },
    Row { func: "light_volume_window_depth", case: "out-of-range convention code 7", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(7)], expect: V::F32(0.0), why: "anything but 0 is reversed" },
    Row { func: "light_volume_window_depth", case: "out of range: beyond far", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::F32(1.0), why: "+Inf → the far end" },
    Row { func: "light_volume_window_depth", case: "out of range: beyond far", args: &[V::F32(5.0), V::F32(1.0), V::F32(2.0), V::U32(1)], expect: V::F32(0.0), why: "clamped to far (reversed 0)" },
    Row { func: "light_volume_window_depth", case: "−Inf view depth", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::F32(0.0), why: "−Inf → the near plane" },
    Row { func: "light_volume_window_depth", case: "NaN near", args: &[V::F32(1.5), V::F32(NAN), V::F32(2.0), V::U32(1)], expect: V::F32(0.0), why: "no projection has it → the far end" },
    Row { func: "light_volume_window_depth", case: "far ≤ near", args: &[V::F32(1.5), V::F32(2.0), V::F32(1.0), V::U32(0)], expect: V::F32(1.0), why: "no projection has it → the far end" },
    Row { func: "light_volume_window_depth", case: "far/near > 2^126", args: &[V::F32(1.0), V::F32(1e-30), V::F32(1e30), V::U32(1)], expect: V::F32(0.0), why: "no projection has it → the far end" },
    Row { func: "light_volume_sphere_depth_bounds", case: "NaN centre", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range: culls nothing" },
    Row { func: "light_volume_sphere_depth_bounds", case: "+Inf radius", args: &[V::F32(1.5), V::F32(INF), V::F32(1.0), V::F32(2.0), V::U32(1)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "negative radius", args: &[V::F32(1.5), V::F32(-1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "zero near", args: &[V::F32(1.5), V::F32(1.0), V::F32(0.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "far ≤ near", args: &[V::F32(1.5), V::F32(1.0), V::F32(2.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "NaN far", args: &[V::F32(1.5), V::F32(1.0), V::F32(1.0), V::F32(NAN), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "−Inf far", args: &[V::F32(1.5), V::F32(1.0), V::F32(1.0), V::F32(-INF), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out of range: in front of near", args: &[V::F32(0.25), V::F32(0.25), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([1.0, 0.0]), why: "empty range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out of range: behind far", args: &[V::F32(10.0), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(1)], expect: V::Vec2([1.0, 0.0]), why: "empty range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "c + r overflows, far +Inf", args: &[V::F32(3e38), V::F32(3e38), V::F32(1.0), V::F32(INF), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "reaches infinity: window depth 1" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out-of-range convention code", args: &[V::F32(3e38), V::F32(3e38), V::F32(1.0), V::F32(INF), V::U32(u32::MAX)], expect: V::Vec2([0.0, 1.0]), why: "reversed: infinity at 0" },
    Row { func: "light_volume_sphere_depth_bounds", case: "subnormal radius at the near plane", args: &[V::F32(1.0), V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 3.0 / 1_048_576.0]), why: "the point z = 0, widened by ε = 16u·(1 + 2) = 3·2^-20" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "NaN centre", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([0, MAX24]), why: "full range of codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "zero near", args: &[V::F32(1.5), V::F32(1.0), V::F32(0.0), V::F32(INF), V::U32(1)], expect: V::UVec2([0, MAX24]), why: "full range of codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "out of range: behind far", args: &[V::F32(10.0), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([MAX24, 0]), why: "empty range as codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "subnormal radius at the near plane", args: &[V::F32(1.0), V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([0, 48]), why: "ceil(48u·(2^24 − 1))" },
    Row { func: "lighting::light_volume::exact::light_volume_window_depth", case: "NaN", args: &[V::F64(f64::NAN), V::F64(1.0), V::F64(2.0), V::U32(0)], expect: V::F64(f64::NAN), why: "propagates (reference only)" },
    Row { func: "lighting::light_volume::exact::light_volume_window_depth", case: "+Inf view depth, far +Inf", args: &[V::F64(f64::INFINITY), V::F64(1.0), V::F64(f64::INFINITY), V::U32(1)], expect: V::F64(0.0), why: "n/∞ = 0" },
];
