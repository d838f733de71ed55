//! Hemi-octahedral codes for view-space normals (`z ≥ 0`), 2×12 bits — the Rust twin of
//! `wgsl/normal_hemioct.wgsl`: the octahedron's upper half rotated 45° to fill the square
//! (Cigolle et al. 2014). Offered beside oct24 for comparison: the same 24 bits spent on half
//! the sphere. Measured over the `z ≥ 0` half of 2^24 Fibonacci directions: mean 0.0148°, max
//! 0.0342° (oct24: 0.0195°, 0.0395°) — cells of half the area, so about `1/√2` of the error.
//!
//! Code `k` on an axis stands for `(2k − M)/M`, `M = 4095`; the decoded direction is that of the
//! exact integer vector `D = ((a + b)/2, (a − b)/2, M − max(|a|, |b|))`, `a = 2u − M`, `b = 2v − M`.
//! Layout: `u` in bits 0–11, `v` in bits 12–23, bits 24–31 zero when encoded, ignored when decoded.
//!
//! **Bad input:** as [`crate::normal`]; in addition a negative `z` is clamped to 0 (the nearest
//! point of the hemisphere, on the equator), so `(0, 0, −1)` becomes the zero vector and encodes `+z`.

use super::normalize;
use glam::{IVec2, IVec3, UVec2, Vec2, Vec3};

/// Largest code per axis, `2^12 − 1`.
pub const M: u32 = 4095;

/// The input made safe, step for step as the WGSL's `hemioct_sanitize`: NaN → `+z`; subnormal
/// components → signed zero; infinities → their signs; `z` clamped to `[0, ∞)`; zero → `+z`;
/// then an exact power-of-two scale putting the largest component in `[1, 4)`.
pub fn sanitize(n: Vec3) -> Vec3 {
    let c = n.to_array();
    if c.iter().any(|x| x.is_nan()) {
        return Vec3::Z;
    }
    let mut c = super::signs_or_flushed(c);
    c[2] = c[2].max(0.0);
    super::scale_to_unit_range(c).unwrap_or(Vec3::Z)
}

/// Continuous code coordinates in `[0, M)²` (as the WGSL computes them); the clamp stops at
/// [`oct::CONTINUOUS_TOP`](super::oct::CONTINUOUS_TOP), so `floor` stays below `M` (see
/// [`oct::continuous`](super::oct::continuous)).
pub fn continuous(s: Vec3) -> Vec2 {
    let l1 = (s.x.abs() + s.y.abs()) + s.z;
    let p = Vec2::new(s.x / l1, s.y / l1);
    let q = Vec2::new(p.x + p.y, p.x - p.y);
    (q * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::splat(super::oct::CONTINUOUS_TOP)) * M as f32
}

/// The exact integer vector code `(u, v)` stands for, by the WGSL's formula (there in f32,
/// exact): `((a + b)/2, (a − b)/2) = (u + v − M, u − v)`, and
/// `M − max(|a|, |b|) = M − |D.x| − |D.y|`.
pub fn lattice(uv: UVec2) -> IVec3 {
    let (u, v, m) = (uv.x as i32, uv.y as i32, M as i32);
    let h = IVec2::new(u + v - m, u - v);
    h.extend(m - h.abs().element_sum())
}

fn sin2(s: Vec3, uv: UVec2) -> f32 {
    super::sin2_to(s, lattice(uv))
}

/// Precise hemi-octahedral encoder (the best of the four neighbour codes, as
/// [`crate::normal::oct::encode_precise`], with the same error bound and tie rule).
/// Bit-identical to `encode_normal_hemioct24` on a correctly rounded adapter.
pub fn encode_normal_hemioct24(n: Vec3) -> u32 {
    let s = sanitize(n);
    let c = continuous(s);
    // c < M (see `continuous`), so base + 1 ≤ M.
    let base = UVec2::new(c.x.floor() as u32, c.y.floor() as u32);
    let mut best = base;
    let mut best_s2 = sin2(s, base);
    for k in 1..4u32 {
        let cand = base + UVec2::new(k & 1, k >> 1);
        let s2 = sin2(s, cand);
        if s2 < best_s2 {
            best = cand;
            best_s2 = s2;
        }
    }
    best.x | (best.y << 12)
}

/// Rounding hemi-octahedral encoder (nearest code per axis, half to even).
pub fn encode_normal_hemioct24_fast(n: Vec3) -> u32 {
    let c = continuous(sanitize(n));
    (c.x.round_ties_even() as u32) | ((c.y.round_ties_even() as u32) << 12)
}

/// Decode: `normalize(D)` of the code's exact integer vector (bits 24–31 ignored). Every bit
/// pattern gives a finite unit vector with `z ≥ 0`; direction within `√2·2^-24` rad of `D`'s.
pub fn decode_normal_hemioct24(p: u32) -> Vec3 {
    normalize(lattice(UVec2::new(p & 0xfff, (p >> 12) & 0xfff)).as_vec3())
}

/// Render-target form of [`encode_normal_hemioct24`]: rgba8unorm channels (`byte/255`).
pub fn encode_normal_hemioct24_unorm(n: Vec3) -> [f32; 4] {
    crate::depth24::unpack4x8unorm(encode_normal_hemioct24(n))
}

/// Decode sampled rgba8unorm channels (bytes rounded back; NaN → 0; clamped).
pub fn decode_normal_hemioct24_unorm(c: [f32; 4]) -> Vec3 {
    decode_normal_hemioct24(super::xyz8::unorm_bytes(c))
}

/// Exact references in f64.
pub mod exact {
    /// The direction code `p` stands for.
    pub fn decode(p: u32) -> [f64; 3] {
        let d = super::lattice(glam::UVec2::new(p & 0xfff, (p >> 12) & 0xfff));
        crate::normal::exact::unit([d.x, d.y, d.z].map(f64::from)).expect("|D|_1 = M")
    }

    /// Continuous code coordinates of a direction (z clamped to ≥ 0) in f64.
    pub fn continuous(n: [f64; 3]) -> [f64; 2] {
        let z = n[2].max(0.0);
        let l1 = n[0].abs() + n[1].abs() + z;
        let p = [n[0] / l1, n[1] / l1];
        let m = f64::from(super::M);
        [p[0] + p[1], p[0] - p[1]].map(|x| ((x * 0.5 + 0.5) * m).clamp(0.0, m))
    }

    /// The four neighbour codes of the f64 continuous coordinates.
    pub fn neighbours(n: [f64; 3]) -> [u32; 4] {
        let c = continuous(n);
        let base = c.map(|x| (x.floor() as u32).min(super::M - 1));
        [0u32, 1, 2, 3].map(|k| (base[0] + (k & 1)) | ((base[1] + (k >> 1)) << 12))
    }

    /// The precise encoder in f64.
    pub fn encode_precise(n: [f64; 3]) -> u32 {
        crate::normal::exact::closest(n, neighbours(n), decode)
    }

    /// The rounding encoder in f64.
    pub fn encode_round(n: [f64; 3]) -> u32 {
        let c = continuous(n);
        (c[0].round_ties_even() as u32) | ((c[1].round_ties_even() as u32) << 12)
    }
}
