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
//! For vectors a scene vouches for (finite, no subnormals; see
//! [`encode_normal_hemioct24_vouched`]): `encode_normal_hemioct24_vouched` and
//! `encode_normal_hemioct24_fast_vouched`, the robust encoders' codes bit for bit inside that
//! contract, without their bad-input handling.

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
    codes(s, (s.x.abs() + s.y.abs()) + s.z)
}

/// [`continuous`] with the L1 norm `l1` passed in: shared with
/// [`encode_normal_hemioct24_vouched`], which keeps `l1` at least `2^-126` (the WGSL's
/// `hemioct_continuous_vouched`, a copy of `hemioct_continuous` with that `max`).
fn codes(s: Vec3, l1: f32) -> Vec2 {
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
    choose(s, continuous(s))
}

/// The precise encoder's choice (the WGSL's `hemioct_choose`) for a scaled input `s` and its
/// continuous coordinates `c`: shared by [`encode_normal_hemioct24`] and
/// [`encode_normal_hemioct24_vouched`].
fn choose(s: Vec3, c: Vec2) -> u32 {
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

/// Whether `n` is inside the vouched encoders' contract ([`encode_normal_hemioct24_vouched`]):
/// `z` finite, and the hemisphere's clamp `c = (x, y, max(z, 0))` inside the octahedral one
/// ([`oct::is_vouched`](super::oct::is_vouched)): every component finite, every non-zero one at
/// least `2^-126·max(1, ‖c‖∞)` in magnitude, and `0 < ‖c‖∞ ≤ 2^124`.
pub fn is_vouched(n: Vec3) -> bool {
    n.z.is_finite() && super::oct::is_vouched(Vec3::new(n.x, n.y, n.z.max(0.0)))
}

/// `c = (x, y, max(z, 0))` times `2^(127 − e)`, `e` the biased exponent of `‖c‖∞` (the WGSL's
/// `hemioct_scale_vouched`): the power of two [`sanitize`] picks after its own clamp of `z`, so
/// in the contract (no component made subnormal) exactly `sanitize(n)`; a zero `c` stays zero.
/// The `u32` arithmetic wraps as WGSL's does: an out-of-contract input gives some float, no panic.
fn scale_vouched(n: Vec3) -> Vec3 {
    let c = Vec3::new(n.x, n.y, n.z.max(0.0));
    let e = c.abs().max_element().to_bits() >> 23;
    c * f32::from_bits(254u32.wrapping_sub(e) << 23)
}

/// The precise hemi-octahedral encoder for a vector the scene vouches for (twin of the WGSL
/// function of the same name): [`encode_normal_hemioct24`] without the bad-input handling.
///
/// **Contract** ([`is_vouched`]), on the hemisphere's clamp `c = (x, y, max(z, 0))` — kept in
/// the vouched form, as an interpolated view-space normal at a silhouette may point slightly
/// away from the camera: `n` finite; every non-zero component of `c` at least
/// `2^-126·max(1, ‖c‖∞)` in magnitude (no subnormals); `0 < ‖c‖∞ ≤ 2^124`. A negative `z` may
/// be any finite value. Outside it, yet defined as the robust form: a zero `c` (the zero vector,
/// `(0, 0, z ≤ 0)`) encodes `+z` (the L1 norm kept at least `2^-126`).
///
/// **Maths:** `s = c·2^(127−e)` (`scale_vouched`, `e` the biased exponent of `‖c‖∞`) is exact in
/// the contract and equals [`sanitize`]`(n)` (which clamps `z` the same way, would only flush
/// subnormals, none here, and scales by the same power of two); the choice is then
/// [`encode_normal_hemioct24`]'s on the same `s`. So the code is [`encode_normal_hemioct24`]'s
/// bit for bit, and so is its **error bound**. The WGSL is bit-identical to this twin on a
/// correctly rounded adapter.
///
/// **Outside the contract** (NaN, ±Inf, subnormal components, `‖c‖∞ > 2^124`): the WGSL's
/// result is indeterminate — some `u32`, which the decoder accepts (bits 24–31 may be set; it
/// ignores them). This twin's is deterministic (NaN coordinates convert to 0) and it never panics.
pub fn encode_normal_hemioct24_vouched(n: Vec3) -> u32 {
    let s = scale_vouched(n);
    let a = s.abs();
    choose(s, codes(s, ((a.x + a.y) + s.z).max(f32::MIN_POSITIVE)))
}

/// The rounding hemi-octahedral encoder for a vector the scene vouches for (twin of the WGSL
/// function of the same name): each coordinate of `t = q/2 + 1/2`, `q = (p.x + p.y, p.x − p.y)`,
/// `p = n.xy / ((|x| + |y|) + max(z, 0))` (no sanitising, no scaling, no guard), rounded to the
/// nearest code `round(t·M)` (half to even). The WGSL assembles the code as `u32(v·2^12 + u)`
/// (whole numbers below 2^24, exact); in the contract that is `u | v << 12`.
///
/// **Contract:** [`encode_normal_hemioct24_vouched`]'s ([`is_vouched`]; a zero clamp `c` is
/// outside it). **Maths:** in the contract `sanitize(n) = c·2^k` exactly, and the L1 norm's sums
/// (of non-negative normal floats, at most `3·2^124`) commute with that power of two, as does a
/// correctly rounded quotient; so `p` is [`continuous`]'s. [`continuous`] then clamps `t` to
/// `[0, 1 − 2^-23]`, which changes no rounded code: `|p.x| + |p.y| ≤ 1` up to a few ULP, and
/// `round(t·M)` of a `t` above the top is `M`, as the top's is (below 0 it is `−0`). So the code
/// is [`encode_normal_hemioct24_fast`]'s bit for bit on a correctly rounded adapter, with its
/// **error bound**. **Zero clamp and outside the contract:** `0/0` and the like — the WGSL's
/// result is indeterminate, some `u32` the decoder accepts; this twin's (NaN converts to 0,
/// conversions saturate) is deterministic and it never panics.
pub fn encode_normal_hemioct24_fast_vouched(n: Vec3) -> u32 {
    let l1 = (n.x.abs() + n.y.abs()) + n.z.max(0.0);
    let p = Vec2::new(n.x / l1, n.y / l1);
    let t = Vec2::new(p.x + p.y, p.x - p.y) * 0.5 + 0.5;
    let m = M as f32;
    let (u, v) = ((t.x * m).round_ties_even(), (t.y * m).round_ties_even());
    (u as u32) | ((v as u32) << 12)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The vouched twins never panic, and inside their contract give the robust twins' codes:
    /// random vectors whose components take every exponent (so many fall outside the contract,
    /// some on its edges; half the draws have `z < 0`, which the clamp drops), scaled copies of
    /// them, and the special patterns (zeros, the `−z` half-axis, the contract's edges).
    #[test]
    fn vouched_twins_equal_the_robust_ones_inside_the_contract() {
        type Pair = (fn(Vec3) -> u32, fn(Vec3) -> u32);
        let pairs: [Pair; 2] = [
            (encode_normal_hemioct24_vouched, encode_normal_hemioct24),
            (
                encode_normal_hemioct24_fast_vouched,
                encode_normal_hemioct24_fast,
            ),
        ];
        let (tiny, big) = (f32::MIN_POSITIVE, super::super::oct::VOUCHED_MAX);
        let mut special = Vec::new();
        for sx in [1.0f32, -1.0] {
            for sz in [1.0f32, -1.0] {
                special.extend([
                    Vec3::new(0.0 * sx, -0.0, 0.0 * sz),
                    Vec3::new(0.0, 0.0, -sz.abs()),
                    Vec3::new(tiny * sx, 1.0, 0.5 * sz),
                    Vec3::new(tiny * sx, -tiny, sz),
                    Vec3::new(big * sx, big, big * sz),
                    Vec3::new(tiny * sx, 0.0, -big * sz.abs()),
                    Vec3::new(tiny * sx, 0.0, tiny * sz),
                    Vec3::new(0.5 * sx, 0.25, tiny * sz),
                    Vec3::new(sx, 0.0, f32::MAX * sz),
                ]);
            }
        }
        for n in special {
            for (vouched, robust) in pairs {
                let code = vouched(n);
                if is_vouched(n) {
                    assert_eq!(code, robust(n), "{n:?}");
                }
            }
        }
        super::super::vouched_draws_agree(&pairs, is_vouched);
    }

    /// The precise vouched form gives a zero clamp `c` (outside the contract) the robust code of
    /// `+z`, as its docs say; the robust encoder gives every such vector that code.
    #[test]
    fn vouched_precise_encodes_a_zero_clamp_as_plus_z() {
        let z = encode_normal_hemioct24(Vec3::Z);
        for n in [
            Vec3::ZERO,
            Vec3::new(-0.0, 0.0, -0.0),
            Vec3::NEG_Z,
            Vec3::new(0.0, -0.0, -3e38),
        ] {
            assert!(!is_vouched(n));
            assert_eq!(encode_normal_hemioct24(n), z, "{n:?}");
            assert_eq!(encode_normal_hemioct24_vouched(n), z, "{n:?}");
        }
    }
}
