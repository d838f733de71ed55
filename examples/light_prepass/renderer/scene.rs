//! The procedural scene: a normal-mapped ground plane, a few dozen spheres and boxes with varied
//! specular powers, hundreds of point and spot lights, and the camera. Deterministic: the same
//! light count gives the same frame on every run (a small xorshift generator, seeded).

use glam::{Mat4, Vec3};

/// One vertex of the scene geometry, world space (`material` indexes [`Material`]).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// World position.
    pub position: [f32; 3],
    /// World normal (unit).
    pub normal: [f32; 3],
    /// Index into the material table.
    pub material: u32,
}

/// A material as the shaders read it (48 bytes, WGSL `Material`).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Material {
    /// rgb albedo, w: specular power stored in the G-buffer (log-range code, or GGX roughness:
    /// `Config::roughness`).
    pub albedo_power: [f32; 4],
    /// rgb gloss, w: the material exponent `m` the one-buffer combine applies on top.
    pub gloss_m: [f32; 4],
    /// x: bump amplitude (0 = no normal map), y: bump frequency.
    pub bump: [f32; 4],
}

/// A light as the CPU knows it (world space).
#[derive(Clone, Copy, Debug)]
pub struct Light {
    /// Position (the apex for a spot).
    pub position: Vec3,
    /// Radius of influence (point) or range (spot); attenuation reaches 0 there.
    pub radius: f32,
    /// Linear rgb colour.
    pub colour: Vec3,
    /// `Some((axis, cos_outer, cos_inner))` for a spot light.
    pub spot: Option<(Vec3, f32, f32)>,
}

/// The camera: an infinite reversed-Z projection by default.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Eye position.
    pub eye: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Vertical field of view, radians.
    pub fov_y: f32,
    /// Near plane distance.
    pub near: f32,
}

impl Camera {
    /// World → view (right-handed, −z forward).
    pub fn view(&self) -> Mat4 {
        let f = (self.target - self.eye).normalize();
        let s = f.cross(Vec3::Y).normalize();
        let u = s.cross(f);
        // Rows s, u, −f: view x right, y up, −z forward.
        Mat4::from_cols(
            glam::Vec4::new(s.x, u.x, -f.x, 0.0),
            glam::Vec4::new(s.y, u.y, -f.y, 0.0),
            glam::Vec4::new(s.z, u.z, -f.z, 0.0),
            glam::Vec4::new(-s.dot(self.eye), -u.dot(self.eye), f.dot(self.eye), 1.0),
        )
    }
}

/// Everything the frame draws.
pub struct SceneData {
    /// Triangle list, world space.
    pub vertices: Vec<Vertex>,
    /// Material table.
    pub materials: Vec<Material>,
    /// Lights, world space.
    pub lights: Vec<Light>,
    /// The camera.
    pub camera: Camera,
}

/// A small deterministic generator (xorshift64*), so the frame needs no `rand` crate.
pub struct Rng(u64);

impl Rng {
    /// Seeded generator.
    pub fn new(seed: u64) -> Self {
        Rng(seed.max(1))
    }
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (x >> 40) as f32 / (1u64 << 24) as f32
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, a: f32, b: f32) -> f32 {
        a + (b - a) * self.next()
    }
}

/// Ground half-size (world units): the plane spans [−G, G]² at y = 0.
pub const GROUND: f32 = 40.0;

fn push_quad(v: &mut Vec<Vertex>, p: [Vec3; 4], n: Vec3, material: u32) {
    for i in [0, 1, 2, 0, 2, 3] {
        v.push(Vertex {
            position: p[i].to_array(),
            normal: n.to_array(),
            material,
        });
    }
}

/// The ground, tessellated so each triangle spans a small depth range.
fn ground(v: &mut Vec<Vertex>, material: u32) {
    let n = 48;
    let step = 2.0 * GROUND / n as f32;
    for i in 0..n {
        for j in 0..n {
            let (x0, z0) = (-GROUND + i as f32 * step, -GROUND + j as f32 * step);
            let (x1, z1) = (x0 + step, z0 + step);
            // Counter-clockwise seen from above (+y).
            push_quad(
                v,
                [
                    Vec3::new(x0, 0.0, z0),
                    Vec3::new(x0, 0.0, z1),
                    Vec3::new(x1, 0.0, z1),
                    Vec3::new(x1, 0.0, z0),
                ],
                Vec3::Y,
                material,
            );
        }
    }
}

fn sphere(v: &mut Vec<Vertex>, c: Vec3, r: f32, material: u32) {
    let (slices, stacks) = (32, 20);
    let at = |i: u32, j: u32| {
        let theta = std::f32::consts::PI * j as f32 / stacks as f32;
        let phi = std::f32::consts::TAU * i as f32 / slices as f32;
        Vec3::new(
            theta.sin() * phi.cos(),
            theta.cos(),
            theta.sin() * phi.sin(),
        )
    };
    for i in 0..slices {
        for j in 0..stacks {
            let q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            // (i, j) → (i+1, j) → (i+1, j+1) is counter-clockwise seen from outside.
            for k in [0, 1, 2, 0, 2, 3] {
                v.push(Vertex {
                    position: (c + q[k] * r).to_array(),
                    normal: q[k].to_array(),
                    material,
                });
            }
        }
    }
}

fn cuboid(v: &mut Vec<Vertex>, c: Vec3, half: Vec3, yaw: f32, material: u32) {
    let rot = glam::Mat3::from_rotation_y(yaw);
    for axis in 0..3 {
        for s in [-1.0f32, 1.0] {
            let mut n = Vec3::ZERO;
            n[axis] = s;
            let (mut a, mut b) = (Vec3::ZERO, Vec3::ZERO);
            a[(axis + 1) % 3] = 1.0;
            b[(axis + 2) % 3] = 1.0;
            if s < 0.0 {
                std::mem::swap(&mut a, &mut b);
            }
            let f = |u: f32, w: f32| c + rot * ((n + a * u + b * w) * half);
            push_quad(
                v,
                [f(-1.0, -1.0), f(1.0, -1.0), f(1.0, 1.0), f(-1.0, 1.0)],
                rot * n,
                material,
            );
        }
    }
}

/// The default scene with `lights` dynamic lights (plus the bad-input lights of the issue: one
/// at the camera, one whose volume crosses the near plane, one of radius 0).
pub fn build(lights: usize) -> SceneData {
    let mut rng = Rng::new(0x5eed_1e55);
    let mut materials = vec![Material {
        albedo_power: [0.55, 0.52, 0.48, 24.0],
        gloss_m: [0.35, 0.35, 0.35, 1.0],
        bump: [0.12, 2.0, 0.0, 0.0],
    }];
    let mut vertices = Vec::new();
    ground(&mut vertices, 0);
    let powers = [4.0, 16.0, 48.0, 128.0, 384.0];
    for k in 0..36u32 {
        let albedo = [
            rng.range(0.25, 0.95),
            rng.range(0.25, 0.95),
            rng.range(0.25, 0.95),
        ];
        let g = rng.range(0.2, 0.8);
        materials.push(Material {
            albedo_power: [albedo[0], albedo[1], albedo[2], powers[k as usize % 5]],
            gloss_m: [g, g, g, if k % 3 == 0 { 2.0 } else { 1.0 }],
            bump: [0.0; 4],
        });
        let m = k + 1;
        // Rows spread over the ground ahead of the camera, wider than the field of view so
        // shapes at the edges show view-space normals facing away (z < 0).
        let x = rng.range(-14.0, 14.0);
        let z = rng.range(-28.0, 3.0);
        if k % 3 == 2 {
            let half = Vec3::new(
                rng.range(0.4, 1.2),
                rng.range(0.4, 1.6),
                rng.range(0.4, 1.2),
            );
            cuboid(
                &mut vertices,
                Vec3::new(x, half.y, z),
                half,
                rng.range(0.0, 3.0),
                m,
            );
        } else {
            let r = rng.range(0.5, 1.6);
            sphere(&mut vertices, Vec3::new(x, r, z), r, m);
        }
    }
    let camera = Camera {
        eye: Vec3::new(0.0, 2.6, 9.0),
        target: Vec3::new(0.0, 0.9, -6.0),
        fov_y: 60f32.to_radians(),
        near: 0.05,
    };
    let mut ls = Vec::new();
    for k in 0..lights {
        let hue = rng.next() * 6.0;
        let c = Vec3::new(
            (hue - 3.0).abs() - 1.0,
            2.0 - (hue - 2.0).abs(),
            2.0 - (hue - 4.0).abs(),
        )
        .clamp(Vec3::ZERO, Vec3::ONE);
        let colour = (c * 0.85 + Vec3::splat(0.15)) * rng.range(0.5, 1.1);
        let position = Vec3::new(
            rng.range(-16.0, 16.0),
            rng.range(0.3, 3.5),
            rng.range(-30.0, 6.0),
        );
        let spot = (k % 4 == 3).then(|| {
            let axis = Vec3::new(rng.range(-0.5, 0.5), -1.0, rng.range(-0.5, 0.5)).normalize();
            let outer = rng.range(20.0f32, 40.0).to_radians();
            (axis, outer.cos(), (outer * 0.7).cos())
        });
        let radius = if spot.is_some() {
            rng.range(3.5, 7.0)
        } else {
            rng.range(1.0, 2.6)
        };
        ls.push(Light {
            position,
            radius,
            colour,
            spot,
        });
    }
    // Bad input, kept in every frame: a light at the camera (the camera is inside its volume),
    // one whose volume crosses the near plane (its centre just ahead of the eye, off-axis), and
    // a zero-radius light (no volume, no light).
    let forward = (camera.target - camera.eye).normalize();
    ls.push(Light {
        position: camera.eye,
        radius: 3.0,
        colour: Vec3::splat(0.25),
        spot: None,
    });
    ls.push(Light {
        position: camera.eye + forward * 1.5 + Vec3::new(0.8, -0.6, 0.0),
        radius: 2.0,
        colour: Vec3::new(0.4, 0.3, 0.2),
        spot: None,
    });
    ls.push(Light {
        position: Vec3::new(0.0, 1.0, 0.0),
        radius: 0.0,
        colour: Vec3::splat(100.0),
        spot: None,
    });
    SceneData {
        vertices,
        materials,
        lights: ls,
        camera,
    }
}
