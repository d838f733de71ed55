//! View- and world-space position rebuild — the Rust twins of `wgsl/position.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! A full-screen lighting pass rebuilds each pixel's position as `ray · vz`, where `ray` is the
//! view ray through the pixel scaled to a unit view-axis component and `vz` the view distance
//! from [`crate::linear_depth`]. Rays are linear in NDC, so interpolating the corner rays of a
//! full-screen triangle gives every pixel's ray.
//!
//! **Error bound (derived):** `frustum_ray` rounds `ndc·tan` once and `view_position` rounds the
//! product with `vz` once, so each component's relative error is the error of `vz` plus at most
//! 2 roundings (`2·2^-24`, ≤ 2 ULP); the z component carries `vz`'s error alone. `world_position`
//! adds the camera position in f32: its absolute error is about half an ULP of the camera's
//! coordinates (≈ 0.5 mm at 8 km, 0.5 m at 1e7 m) whatever the pixel's distance; the
//! camera-relative path keeps the view-space relative error.
//!
//! **Bad input (every result finite):** WGSL lets an implementation assume that no NaN or ±∞
//! occurs at run time, so each float input lane is read from its bits first: NaN → 0,
//! ±∞ → ±2^40, finite values clamped to `[−2^40, 2^40]` ([`LIMIT`]; 2^40 ≈ 1.1e12, beyond any
//! distance a prepass projection resolves), so no product or sum can overflow. The sky sentinel
//! [`crate::linear_depth::SKY`] rebuilds the point `2^40` along the ray. Vertex indices above 2
//! wrap through their low two bits (index 3 gives `(3, 3)`, outside the screen).

use glam::{Mat3, Vec2, Vec3};

/// The largest magnitude any float input lane keeps: `2^40`. Larger lanes (and ±∞) are clamped
/// to `±LIMIT`, NaN lanes read as 0 (WGSL `pos_sane`).
pub const LIMIT: f32 = 1_099_511_627_776.0;

/// A lane as the WGSL reads it from its bits before computing with it: NaN → 0, clamped to
/// `[−limit, limit]` (±∞ included). Shared by the position, lighting and aggregate-light twins
/// (WGSL `pos_sane`, `lpp_luminance`, `aggregate_light_sane3`).
pub(crate) fn read_finite(x: f32, limit: f32) -> f32 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(-limit, limit)
    }
}

/// [`read_finite`] per lane of a `Vec3`.
pub(crate) fn read_finite3(v: Vec3, limit: f32) -> Vec3 {
    Vec3::new(
        read_finite(v.x, limit),
        read_finite(v.y, limit),
        read_finite(v.z, limit),
    )
}

/// One lane made finite and clamped to `[−LIMIT, LIMIT]` (WGSL `pos_sane`).
fn sane(x: f32) -> f32 {
    read_finite(x, LIMIT)
}

fn sane2(v: Vec2) -> Vec2 {
    Vec2::new(sane(v.x), sane(v.y))
}

fn sane3(v: Vec3) -> Vec3 {
    read_finite3(v, LIMIT)
}

/// `tan_half_fov` for WGSL `frustum_ray_rh` / `fullscreen_triangle_ray_rh` from a perspective
/// matrix of your own (glam's, Bevy's, or [`crate::projection::Projection::perspective_rh`]):
/// `(1/m[0][0], 1/m[1][1])`, computed in f64 and rounded once. Any convention and far plane:
/// the x and y scales do not depend on them.
pub fn tan_half_fov_of(perspective: glam::Mat4) -> [f32; 2] {
    let inv = |x: f32| (1.0 / f64::from(x)) as f32;
    [inv(perspective.x_axis.x), inv(perspective.y_axis.y)]
}

/// View ray through `ndc_xy` with z = +1 (left-handed view space, +z forward). Twin of WGSL
/// `frustum_ray`.
///
/// `tan_half_fov = (tan(fov_x/2), tan(fov_y/2)) = (aspect·tan(fov_y/2), tan(fov_y/2))`, from
/// [`crate::projection::Projection::tan_half_fov`] or [`tan_half_fov_of`] a matrix.
pub fn frustum_ray(ndc_xy: Vec2, tan_half_fov: Vec2) -> Vec3 {
    (sane2(ndc_xy) * sane2(tan_half_fov)).extend(1.0)
}

/// View ray with z = −1 (right-handed view space, −z forward, as wgpu and Bevy). Twin of WGSL
/// `frustum_ray_rh`.
pub fn frustum_ray_rh(ndc_xy: Vec2, tan_half_fov: Vec2) -> Vec3 {
    (sane2(ndc_xy) * sane2(tan_half_fov)).extend(-1.0)
}

/// `ray · view_z`. Twin of WGSL `view_position`.
pub fn view_position(ray: Vec3, view_z: f32) -> Vec3 {
    sane3(ray) * sane(view_z)
}

/// NDC of a full-screen triangle's vertex: 0 → (−1, −1), 1 → (3, −1), 2 → (−1, 3).
pub fn fullscreen_triangle_ndc(vertex_index: u32) -> Vec2 {
    Vec2::new((vertex_index & 1) as f32, ((vertex_index >> 1) & 1) as f32) * 4.0 - 1.0
}

/// [`frustum_ray`] at a full-screen triangle's vertex.
pub fn fullscreen_triangle_ray(vertex_index: u32, tan_half_fov: Vec2) -> Vec3 {
    frustum_ray(fullscreen_triangle_ndc(vertex_index), tan_half_fov)
}

/// [`frustum_ray_rh`] at a full-screen triangle's vertex.
pub fn fullscreen_triangle_ray_rh(vertex_index: u32, tan_half_fov: Vec2) -> Vec3 {
    frustum_ray_rh(fullscreen_triangle_ndc(vertex_index), tan_half_fov)
}

/// wgpu NDC from a texture coordinate: `(2u − 1, 1 − 2v)`.
pub fn ndc_from_uv(uv: Vec2) -> Vec2 {
    let u = sane2(uv);
    Vec2::new(u.x * 2.0 - 1.0, 1.0 - u.y * 2.0)
}

/// A view ray rotated into world orientation. Twin of WGSL `world_ray` (a matrix-vector
/// product: the adapter may sum its three products in another order or fuse them, so agreement
/// is not bitwise; each lane is within a few ULP of the largest product's magnitude, which where
/// the products cancel is many ULP of the lane itself — `tests/implementations.rs` measures it).
pub fn world_ray(view_ray: Vec3, view_to_world: Mat3) -> Vec3 {
    let m = Mat3::from_cols(
        sane3(view_to_world.x_axis),
        sane3(view_to_world.y_axis),
        sane3(view_to_world.z_axis),
    );
    m * sane3(view_ray)
}

/// Position relative to the camera in world orientation: `ray · vz`.
pub fn camera_relative_position(world_ray_dir: Vec3, view_z: f32) -> Vec3 {
    sane3(world_ray_dir) * sane(view_z)
}

/// World position `camera + ray · vz`.
pub fn world_position(world_ray_dir: Vec3, view_z: f32, camera_position: Vec3) -> Vec3 {
    sane3(camera_position) + sane3(world_ray_dir) * sane(view_z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fullscreen_triangle_covers_the_screen() {
        assert_eq!(fullscreen_triangle_ndc(0), Vec2::new(-1.0, -1.0));
        assert_eq!(fullscreen_triangle_ndc(1), Vec2::new(3.0, -1.0));
        assert_eq!(fullscreen_triangle_ndc(2), Vec2::new(-1.0, 3.0));
        // The ray at NDC (x, y) is the barycentric mix of the corner rays.
        let t = Vec2::new(0.7, 0.4);
        let r: Vec<Vec3> = (0..3).map(|i| fullscreen_triangle_ray(i, t)).collect();
        let p = Vec2::new(0.25, -0.5);
        let (b1, b2) = ((p.x + 1.0) / 4.0, (p.y + 1.0) / 4.0);
        let mixed = r[0] * (1.0 - b1 - b2) + r[1] * b1 + r[2] * b2;
        crate::assert_within!(
            (mixed - frustum_ray(p, t)).abs().max_element(),
            < 1e-6_f32,
            "literal: 1e-6 ≈ 17u, a few f32 roundings of the mix",
            "NDC {p}: barycentric mix {mixed}"
        );
    }

    #[test]
    fn uv_to_ndc_flips_y() {
        assert_eq!(ndc_from_uv(Vec2::new(0.0, 0.0)), Vec2::new(-1.0, 1.0));
        assert_eq!(ndc_from_uv(Vec2::new(1.0, 1.0)), Vec2::new(1.0, -1.0));
    }
}

/// Error bounds of `view_position(frustum_ray(ndc, tan), vz)`, relative, beyond view z's own
/// error, kept once: `tests/position.rs` asserts them on the adapter and under emulation.
/// x and y are two products (`ndc·tan`, then `·vz`); z is `1·vz`, exact.
pub mod bounds {
    const U: f64 = 1.0 / 16_777_216.0;

    /// Where `×` rounds correctly (lavapipe, the Rust twin): two roundings, `2u`, plus `2^-44`
    /// for the second-order term.
    pub const XY_CORRECTLY_ROUNDED: f64 = 2.0 * U + 1.0 / 17_592_186_044_416.0;

    /// On every conforming adapter, each product rounded to either neighbour (`2u`): `4u`, plus
    /// `2^-42` for the second-order term.
    pub const XY_CONFORMING: f64 = 4.0 * U + 1.0 / 4_398_046_511_104.0;

    /// The relative error of one rounding: `u = 2^-24` where every operation rounds to nearest,
    /// `2^-23` on every conforming adapter (WGSL lets `+ − ×` round to either neighbour).
    pub const fn unit(conforming: bool) -> f64 {
        if conforming { 2.0 * U } else { U }
    }

    /// `γn = n·u / (1 − n·u)`: the relative error of a chain of `n` roundings (Higham, *Accuracy
    /// and Stability of Numerical Algorithms*, §3.1).
    pub fn gamma(n: f64, u: f64) -> f64 {
        n * u / (1.0 - n * u)
    }

    /// `camera_relative_position(world_ray(r, m), vz)`, each component `c`, absolute error: the
    /// matrix × vector lane is a 3-term dot product (3 products, 2 sums, in any order, fused or
    /// not: at most 3 roundings on any path), within `γ3·Σj |m_cj·r_j|`, and `· vz` rounds once
    /// more: `γ4·scale` with `scale = vz·Σj |m_cj·r_j|`.
    pub fn camera_relative_abs(scale: f64, conforming: bool) -> f64 {
        gamma(4.0, unit(conforming)) * scale
    }

    /// `world_position(world_ray(r, m), vz, cam)`, each component, absolute error: the offset's
    /// error (`γ5·scale` covers it with the addition fused into the last product), plus the
    /// addition's own rounding of the result, at most `u·(|w| + γ5·scale)` for the exact
    /// component `w`.
    pub fn world_abs(scale: f64, exact_abs: f64, conforming: bool) -> f64 {
        let u = unit(conforming);
        let offset = gamma(5.0, u) * scale;
        offset + u * (exact_abs + offset)
    }
}
