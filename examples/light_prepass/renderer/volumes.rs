//! Light volumes: the sphere and cone meshes (built to enclose the light's region, not to be
//! inscribed in it), the lights in view space as the shaders read them, and the camera-inside
//! test (`light_volume_*_needs_depth_fail`, the crate's Rust twins) that sorts them into the
//! front-face and back-face pipelines.

use super::scene::Light;
use glam::{Mat4, Vec2, Vec3};
use prepass::lighting::light_volume::{
    light_volume_cone_needs_depth_fail, light_volume_near_corner_distance,
    light_volume_sphere_needs_depth_fail,
};

/// A light as the shaders read it (64 bytes, WGSL `LightGpu`), view space.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LightGpu {
    /// View position, radius (point) or range (spot).
    pub pos_radius: [f32; 4],
    /// rgb colour, w: 0 point, 1 spot.
    pub colour_kind: [f32; 4],
    /// Unit view-space axis, cos of the outer half-angle.
    pub axis_cos_outer: [f32; 4],
    /// cos inner, sphere mesh scale, cone mesh tan, 0.
    pub extra: [f32; 4],
}

/// A unit icosphere (subdivided twice): triangle list, outward-facing, counter-clockwise, and
/// the factor that makes it enclose the unit sphere (1 / the distance of its nearest face).
pub fn icosphere() -> (Vec<[f32; 3]>, f32) {
    let t = (1.0 + 5f32.sqrt()) / 2.0;
    let mut v: Vec<Vec3> = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
    .iter()
    .map(|p| Vec3::from(*p).normalize())
    .collect();
    let mut f: Vec<[usize; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..2 {
        let mut next = Vec::new();
        for [a, b, c] in f {
            let mut mid = |i: usize, j: usize| {
                v.push(((v[i] + v[j]) * 0.5).normalize());
                v.len() - 1
            };
            let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        f = next;
    }
    let mut inradius = f32::INFINITY;
    let mut tris = Vec::new();
    for [a, b, c] in f {
        let n = (v[b] - v[a]).cross(v[c] - v[a]).normalize();
        inradius = inradius.min(n.dot(v[a]));
        tris.extend([v[a], v[b], v[c]].map(|p| p.to_array()));
    }
    // The nearest face plane is at `inradius`; scaling by its inverse (plus one part in 10^5
    // for the rounding of the scaled vertices) puts every face outside the unit sphere.
    (tris, 1.0 / inradius * (1.0 + 1e-5))
}

/// Segments of the cone's base polygon.
pub const CONE_SEGMENTS: u32 = 24;

/// A unit cone: apex at the origin, axis +z, flat cap at z = 1; the cap polygon circumscribes
/// the unit circle (vertices at 1/cos(π/N)), so the mesh encloses the cone of radius 1.
/// Triangle list, outward-facing, counter-clockwise. Returns the mesh and its radius factor.
pub fn cone() -> (Vec<[f32; 3]>, f32) {
    let k = 1.0 / (std::f32::consts::PI / CONE_SEGMENTS as f32).cos() * (1.0 + 1e-5);
    let at = |i: u32| {
        let a = std::f32::consts::TAU * i as f32 / CONE_SEGMENTS as f32;
        [a.cos() * k, a.sin() * k, 1.0]
    };
    let mut tris = Vec::new();
    for i in 0..CONE_SEGMENTS {
        // Side: apex, then the rim clockwise seen from +z looking back at the apex.
        tris.extend([[0.0, 0.0, 0.0], at(i + 1), at(i)]);
        // Cap, facing +z.
        tris.extend([[0.0, 0.0, 1.0], at(i), at(i + 1)]);
    }
    (tris, k)
}

/// Lights sorted for drawing, with counts of each class.
pub struct Sorted {
    /// Spheres (front faces), spheres (camera inside: back faces), cones likewise.
    pub lights: Vec<LightGpu>,
    /// Instance ranges in `lights`: sphere outside, sphere inside, cone outside, cone inside.
    pub ranges: [std::ops::Range<u32>; 4],
    /// Lights left out: radius zero, negative or not finite (no volume, no light).
    pub skipped: u32,
}

/// Move the lights into view space, drop the ones with no volume, and sort them by shape and by
/// the camera-inside test (the Rust twins, as a renderer runs them on the CPU).
pub fn sort(
    lights: &[Light],
    view: Mat4,
    near: f32,
    tan_half_fov: Vec2,
    sphere_scale: f32,
    cone_scale: f32,
) -> Sorted {
    let rho = light_volume_near_corner_distance(near, tan_half_fov.x, tan_half_fov.y);
    let mut classes: [Vec<LightGpu>; 4] = Default::default();
    let mut skipped = 0;
    for l in lights {
        let finite = l.position.is_finite() && l.colour.is_finite() && l.radius.is_finite();
        if !finite || l.radius <= 0.0 {
            skipped += 1;
            continue;
        }
        let p = view.transform_point3(l.position);
        let (class, gpu) = match l.spot {
            None => {
                let inside = light_volume_sphere_needs_depth_fail(p, l.radius * sphere_scale, rho);
                (
                    inside as usize,
                    LightGpu {
                        pos_radius: [p.x, p.y, p.z, l.radius],
                        colour_kind: [l.colour.x, l.colour.y, l.colour.z, 0.0],
                        axis_cos_outer: [0.0, 0.0, -1.0, -1.0],
                        extra: [-1.0, l.radius * sphere_scale, 0.0, 0.0],
                    },
                )
            }
            Some((axis, cos_outer, cos_inner)) => {
                let a = view.transform_vector3(axis).normalize();
                let tan = (1.0 - cos_outer * cos_outer).max(0.0).sqrt() / cos_outer;
                let tan_mesh = tan * cone_scale;
                let inside =
                    light_volume_cone_needs_depth_fail(p, a, Vec2::new(l.radius, tan_mesh), rho);
                (
                    2 + inside as usize,
                    LightGpu {
                        pos_radius: [p.x, p.y, p.z, l.radius],
                        colour_kind: [l.colour.x, l.colour.y, l.colour.z, 1.0],
                        axis_cos_outer: [a.x, a.y, a.z, cos_outer],
                        extra: [cos_inner, sphere_scale, tan, 0.0],
                    },
                )
            }
        };
        classes[class].push(gpu);
    }
    let mut out = Vec::new();
    let mut ranges: [std::ops::Range<u32>; 4] = Default::default();
    for (k, c) in classes.into_iter().enumerate() {
        let start = out.len() as u32;
        out.extend(c);
        ranges[k] = start..out.len() as u32;
    }
    Sorted {
        lights: out,
        ranges,
        skipped,
    }
}
