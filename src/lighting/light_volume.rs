//! Stencil light volumes and depth bounds — Rust twins of `wgsl/light_volume.wgsl`. Sources:
//! Mark Lee, "Pre-lighting in Resistance 2" (Insomniac Games, GDC 2009) for the stencil volumes
//! and the switch to depth-fail; Michal Valient, "Deferred Rendering in Killzone 2" (Guerrilla
//! Games, Develop Conference 2007) for the depth-bounds test.
//!
//! Conventions: README, "Conventions". A point's view depth is its view distance `vz = −z`
//! (positive in front); `near`, `far` are positive view depths, `far` may be `+∞`. The volume
//! tests use only distances and absolute components, so either handedness gives the same answer.
//!
//! **Depth-pass or depth-fail.** Depth-pass stenciling breaks when the near plane clips the
//! volume's front faces. Every point of the near-plane rectangle lies within
//! `ρ = near·√(1 + tan²(fov_x/2) + tan²(fov_y/2))` of the eye (the corners are exactly that
//! far), so a volume farther than `ρ` from the eye cannot reach it (triangle inequality) and
//! depth-pass is safe; otherwise use depth-fail. That is Lee's "fudge factor", derived:
//! [`light_volume_near_corner_distance`]. The comparisons are widened by their own rounding: for the sphere,
//! `|c|²` and `(r + ρ)²` (after scaling by the largest magnitude) are each within `≈ 6u`
//! relative (`u = 2^-24`: three products, two sums, one scaling division of 2.5 ULP), so the
//! right side is enlarged by `16u` relative, which can only add depth-fail cases.
//!
//! **Depth bounds.** A sphere of view depth `c` and radius `r` covers view depths
//! `[c − r, c + r] ∩ [near, far]`; window depth is monotonic in `vz`, so its range is the
//! window depth of the ends: standard `z = f(vz − n)/((f − n)vz)` (evaluated as
//! `(f/(f − n))(1 − n/vz)`), reversed `1 − z = (n/(f − n))(f/vz − 1)`, infinite far
//! `1 − n/vz` and `n/vz`. Evaluation error (WGSL: `/` 2.5 ULP ≤ 5u relative, others 0.5 ULP):
//! with `k = f/(f − n)`, standard `|Δz| ≤ k·(5u + u + u) + z·(6u + u) ≤ 8u·(1 + k)` and
//! reversed likewise with `m = k − 1`, so both are widened by `ε = 16u·(1 + k)` (`32u` for
//! infinite far). 24-bit codes take the floor of the minimum and the ceiling of the maximum
//! times `2^24 − 1`; each product rounds by at most half a code (values `≤ 2^24`), so the code
//! nearest any depth inside the float range lies inside the code range.
//!
//! **Bad input (both sides):** NaN/Inf, negative radius, `near ≤ 0`, `far ≤ near` → depth-fail
//! (1) and the full depth range `[0, 1]` / codes `[0, 2^24 − 1]`; a sphere wholly outside
//! `[near, far]` gives the empty range `(1, 0)` / codes `(2^24 − 1, 0)`.
//!
//! **Twins** are the same `f32` formulas, not bit-identical (division, `sqrt`); the tests check
//! the conservative property on both sides.

use crate::projection::DepthConvention;
use glam::{Vec2, Vec3};

/// Unit roundoff of `f32`, `2^-24`.
pub const LIGHT_VOLUME_U: f32 = 5.960_464_5e-8;
const LIGHT_VOLUME_DEPTH24_MAX: f32 = 16_777_215.0;

fn light_volume_finite(x: f32) -> bool {
    (x.to_bits() & 0x7fff_ffff) < 0x7f80_0000
}

fn light_volume_finite3(v: Vec3) -> bool {
    light_volume_finite(v.x) && light_volume_finite(v.y) && light_volume_finite(v.z)
}

/// `a / b` for `b > 0` within WGSL's specified divisors (WGSL `light_volume_div`): `b` beyond
/// `2^126` is scaled, with `a`, by `2^-64` first.
fn div(a: f32, b: f32) -> f32 {
    if b > 8.507_059e37 {
        (a * 5.421_011e-20) / (b * 5.421_011e-20)
    } else {
        a / b
    }
}

/// Whether `a + b` (finite, `b ≥ 0`) reaches `3.4e38`, just below `f32::MAX`, decided without
/// adding, so no addition produces `+∞` (WGSL `light_volume_sum_overflows`).
fn light_volume_sum_overflows(a: f32, b: f32) -> bool {
    a >= 3.4e38 - b
}

/// `ρ = near·√(1 + tan_x² + tan_y²)`: distance from the eye to the near-plane rectangle's
/// corners, rounded up — enlarged by `2^-19` (`32u`) so that it is never below the exact corner
/// distance on any conforming adapter, and a volume touching a corner always gets depth-fail.
/// Its own rounding, first order with `u = 2^-24` and one ULP `≤ 2u` relative: the squares and
/// the two sums `2u` each put the radicand within `6u`, which `√` halves to `3u`; `√` itself is
/// inherited as `1/inverseSqrt` (2 ULP, then a 2.5-ULP division: `9u`); the product `2u`: within
/// `14u`, `15u` with second-order terms. Then `(1 − 15u)(1 + 32u)(1 − 2u) > 1` (the enlarging
/// product's own rounding included), and the result is at most `≈ 49u` above the exact distance.
/// Without it, a worst conforming adapter computing `ρ` in WGSL can send a sphere that touches a
/// corner to depth-pass (`tests/light_volume.rs`, the corner-touching search). Bad input (NaN/Inf, negative, a tangent above `2^60`, a distance that would pass
/// `3.4e38`) → `3.4e38` (every volume then needs depth-fail); no square or product overflows.
pub fn light_volume_near_corner_distance(
    near: f32,
    tan_half_fov_x: f32,
    tan_half_fov_y: f32,
) -> f32 {
    if !light_volume_finite(near)
        || !light_volume_finite(tan_half_fov_x)
        || !light_volume_finite(tan_half_fov_y)
        || near < 0.0
        || tan_half_fov_x < 0.0
        || tan_half_fov_y < 0.0
        || tan_half_fov_x > 1.152_921_5e18
        || tan_half_fov_y > 1.152_921_5e18
    {
        return 3.4e38;
    }
    let r = (1.0 + tan_half_fov_x * tan_half_fov_x + tan_half_fov_y * tan_half_fov_y).sqrt();
    if near > 3.4e38 / r {
        return 3.4e38;
    }
    // The constant first, as the WGSL writes it (and as Mesa reorders `(near·r)·K`).
    (near * (1.0 + 32.0 * LIGHT_VOLUME_U)) * r
}

/// 1 when a sphere volume (view-space `center`, `radius`) may touch the eye's `ρ`-ball (use
/// depth-fail), 0 when depth-pass is safe: `|c|² ≤ (r + ρ)²·(1 + 16u)` after scaling.
/// `r + ρ` at or beyond `3.4e38` (a reach beyond f32's range, decided without adding) → 1.
pub fn light_volume_sphere_needs_depth_fail(
    center: Vec3,
    radius: f32,
    near_corner_distance: f32,
) -> u32 {
    if !light_volume_finite3(center)
        || !light_volume_finite(radius)
        || !light_volume_finite(near_corner_distance)
        || radius < 0.0
        || near_corner_distance < 0.0
    {
        return 1;
    }
    // A reach beyond f32 (r + ρ overflows) touches every finite centre (found by the fuzz
    // target `lighting`: r = 3.39e38, ρ = f32::MAX used to give 0).
    if light_volume_sum_overflows(radius, near_corner_distance) {
        return 1;
    }
    let sum = radius + near_corner_distance;
    let s = center.abs().max_element().max(sum);
    if s == 0.0 || s.to_bits() < 0x0080_0000 {
        return 1;
    }
    // Scaled by a power of two (exact), not divided by s (WGSL `light_volume_scale`).
    let sc = crate::lighting::lpp::pow2_scale(s);
    let c = center * sc;
    let reach = sum * sc;
    u32::from(c.dot(c) <= reach * reach * (1.0 + 16.0 * LIGHT_VOLUME_U))
}

/// 1 when a cone volume (apex, axis of any length, `range_tan = (length, tan half-angle)`,
/// flat cap) may touch the eye's `ρ`-ball, 0 when depth-pass is safe. Distance from the eye
/// to the solid cone in the axis plane, compared with `ρ + 16u·(|apex| + h(1 + tan) + ρ)`.
pub fn light_volume_cone_needs_depth_fail(
    apex: Vec3,
    axis: Vec3,
    range_tan: Vec2,
    near_corner_distance: f32,
) -> u32 {
    let (h, k) = (range_tan.x, range_tan.y);
    let am = axis.abs().max_element();
    if !light_volume_finite3(apex)
        || !light_volume_finite3(axis)
        || !light_volume_finite(h)
        || !light_volume_finite(k)
        || !light_volume_finite(near_corner_distance)
        || h < 0.0
        || k < 0.0
        || near_corner_distance < 0.0
        || am.to_bits() < 0x0080_0000
    {
        return 1;
    }
    // One power of two scales every length so the largest lies in [1, 4): squares then neither
    // underflow nor overflow (lengths near 1e-22 used to lose the apex: found by the fuzz target
    // `lighting`), and wherever they did not the decision is unchanged (each step is homogeneous
    // in the lengths, and power-of-two scaling is exact).
    // h·tan beyond f32 (decided on h·2^-64, exact for h ≥ 2^-62 and harmless below, so no
    // product produces +∞): depth-fail.
    const TWO_64: f32 = 1.844_674_4e19;
    if k > TWO_64 || (h * (1.0 / TWO_64)) * k > f32::MAX / TWO_64 {
        return 1;
    }
    let big = apex
        .abs()
        .max_element()
        .max(h)
        .max(h * k)
        .max(near_corner_distance);
    if big == 0.0 {
        return 1; // the apex at the eye
    }
    let sc = f32::from_bits((254 - ((big.to_bits() >> 23) & 0xff)).max(1) << 23);
    cone_scaled(apex * sc, axis, h * sc, k, near_corner_distance * sc)
}

/// [`light_volume_cone_needs_depth_fail`] on lengths already scaled to `[1, 4)` (the WGSL's
/// `light_volume_cone_scaled`).
fn cone_scaled(apex: Vec3, axis: Vec3, h: f32, k: f32, near_corner_distance: f32) -> u32 {
    let am = axis.abs().max_element();
    let a = axis * crate::lighting::lpp::pow2_scale(am);
    let d = a * (1.0 / a.dot(a).sqrt());
    let p = -apex;
    let t = p.dot(d);
    let s = (p - t * d).length();
    let base = h * k;
    let mut dist = 0.0;
    if !(t >= 0.0 && t <= h && s <= k * t) {
        let e = Vec2::new(h, base);
        let q = Vec2::new(t, s);
        let ee = e.dot(e);
        let u = if ee > 0.0 {
            (q.dot(e) / ee).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let d_slant = (q - u * e).length();
        let d_cap = (q - Vec2::new(h, s.clamp(0.0, base))).length();
        let d_axis = (q - Vec2::new(t.clamp(0.0, h), 0.0)).length();
        dist = d_slant.min(d_cap).min(d_axis);
    }
    let margin = 16.0 * LIGHT_VOLUME_U * (apex.length() + h * (1.0 + k) + near_corner_distance);
    u32::from(dist <= near_corner_distance + margin)
}

/// Window depth of view depth `vz` (see the module docs for the forms); `far = +∞` allowed.
/// Error: within `8u·(1 + f/(f − n))` of the exact value (module docs).
///
/// **Bad input (every result finite):** `vz` is clamped to `[near, far]`; NaN or `+∞` `vz` and
/// planes no projection has (`near` not a normal positive float, `far` neither above `near` nor
/// `+∞`, `far/near > 2^126`) give the far end (1 standard, 0 reversed). The WGSL's `reversed`
/// argument is 0 for standard and anything else for reversed.
pub fn light_volume_window_depth(vz: f32, near: f32, far: f32, convention: DepthConvention) -> f32 {
    let infinite = far == f32::INFINITY;
    let far_end = match convention {
        DepthConvention::Standard => 1.0,
        DepthConvention::Reversed => 0.0,
    };
    // far/near at most 2^126 (as Projection::new; exact from the bits), so f/vz stays finite.
    if !light_volume_finite(near)
        || near < f32::MIN_POSITIVE
        || !(infinite
            || (light_volume_finite(far)
                && far > near
                && far.to_bits() - near.to_bits() <= 0x3f00_0000))
        || vz.is_nan()
        || vz == f32::INFINITY
    {
        return far_end;
    }
    let v = if infinite {
        vz.max(near)
    } else {
        vz.clamp(near, far)
    };
    // Homogeneous of degree 0 in (vz, near, far): planes below 2^-60 are scaled by 2^64 first
    // (exact, as the WGSL), so f − n is never subnormal.
    let (n, f, v) = if !infinite && far < 8.673_617_4e-19 {
        (
            near * 1.844_674_4e19,
            far * 1.844_674_4e19,
            v * 1.844_674_4e19,
        )
    } else {
        (near, far, v)
    };
    match (convention, infinite) {
        (DepthConvention::Standard, true) => 1.0 - div(n, v),
        (DepthConvention::Standard, false) => div(f, f - n) * (1.0 - div(n, v)),
        (DepthConvention::Reversed, true) => div(n, v),
        (DepthConvention::Reversed, false) => div(n, f - n) * (div(f, v) - 1.0),
    }
}

/// Depth-bounds range `(min, max)` of window depth containing every point of a sphere light
/// (view depth `center_z`, `radius`), widened by `ε = 16u(1 + f/(f − n))` and clamped to
/// `[0, 1]`; `(1, 0)` when the sphere lies wholly outside `[near, far]`.
///
/// The planes and convention can come straight from a [`Projection`](crate::projection::Projection)
/// (for the WGSL, pass `convention.to_wgsl()` as its `reversed` argument):
/// ```
/// use prepass::lighting::light_volume::light_volume_sphere_depth_bounds;
/// use prepass::projection::{DepthConvention, Projection};
/// let p = Projection::new(0.1, 100.0, DepthConvention::Reversed).unwrap();
/// let b = light_volume_sphere_depth_bounds(10.0, 1.0, p.near(), p.far(), p.convention());
/// assert!(b.x < b.y && b.y < 0.02);
/// assert_eq!(p.convention().to_wgsl(), 1);
/// ```
pub fn light_volume_sphere_depth_bounds(
    center_z: f32,
    radius: f32,
    near: f32,
    far: f32,
    convention: DepthConvention,
) -> Vec2 {
    let infinite = far == f32::INFINITY;
    if !light_volume_finite(center_z)
        || !light_volume_finite(radius)
        || !light_volume_finite(near)
        || !(light_volume_finite(far) || infinite)
        || radius < 0.0
        || near.is_nan()
        || near <= 0.0
        || far.is_nan()
        || far <= near
    {
        return Vec2::new(0.0, 1.0);
    }
    let lo = (center_z - radius).max(near);
    // c + r may overflow (decided without computing it): it then lies beyond any finite far.
    let sum_finite = !light_volume_sum_overflows(center_z, radius);
    let sum = if sum_finite { center_z + radius } else { far };
    let mut hi = sum;
    if !infinite && (!sum_finite || sum > far) {
        hi = far;
    }
    let hi_at_infinity = infinite && !sum_finite;
    if !hi_at_infinity && lo > hi {
        return Vec2::new(1.0, 0.0);
    }
    let k = if infinite { 1.0 } else { far / (far - near) };
    let eps = 16.0 * LIGHT_VOLUME_U * (1.0 + k);
    let reversed = convention == DepthConvention::Reversed;
    let mut z_lo = light_volume_window_depth(lo, near, far, convention);
    let mut z_hi = if reversed { 0.0 } else { 1.0 };
    if !hi_at_infinity {
        z_hi = light_volume_window_depth(hi, near, far, convention);
    }
    if reversed {
        std::mem::swap(&mut z_lo, &mut z_hi);
    }
    Vec2::new((z_lo - eps).clamp(0.0, 1.0), (z_hi + eps).clamp(0.0, 1.0))
}

/// [`light_volume_sphere_depth_bounds`] as 24-bit codes: `(floor(min·(2^24−1)), ceil(max·(2^24−1)))`;
/// empty range → `(2^24 − 1, 0)`.
pub fn light_volume_sphere_depth_bounds24(
    center_z: f32,
    radius: f32,
    near: f32,
    far: f32,
    convention: DepthConvention,
) -> [u32; 2] {
    let b = light_volume_sphere_depth_bounds(center_z, radius, near, far, convention);
    if b.x > b.y {
        return [0x00ff_ffff, 0];
    }
    [
        (b.x * LIGHT_VOLUME_DEPTH24_MAX).floor() as u32,
        (b.y * LIGHT_VOLUME_DEPTH24_MAX).ceil() as u32,
    ]
}

/// Exact references (f64).
pub mod exact {
    use crate::projection::DepthConvention;

    /// Window depth in f64 (no guards, like the twin: NaN propagates).
    pub fn light_volume_window_depth(
        vz: f64,
        near: f64,
        far: f64,
        convention: DepthConvention,
    ) -> f64 {
        let z = if far.is_infinite() {
            1.0 - near / vz
        } else {
            far * (vz - near) / ((far - near) * vz)
        };
        match convention {
            DepthConvention::Standard => z,
            DepthConvention::Reversed => {
                if far.is_infinite() {
                    near / vz
                } else {
                    near * (far - vz) / ((far - near) * vz)
                }
            }
        }
    }
}
