//! Octahedral unit-vector codes, 2×8, 2×12 and 2×16 bits — the Rust twin of
//! `wgsl/normal_oct.wgsl` (Cigolle, Donow, Evangelakos, Mara, McGuire, Sharpe, "A Survey of
//! Efficient Representations for Independent Unit Vectors", JCGT 3(2), 2014).
//!
//! A direction is projected onto the octahedron `|x| + |y| + |z| = 1`, the lower half folded over
//! the diagonals onto the square, and each square coordinate quantised to `N` bits. Code `k`
//! stands for the coordinate `(2k − M)/M`, `M = 2^N − 1`, so the decoded direction is that of the
//! exact integer vector `D = (2u − M, 2v − M, M − |2u − M| − |2v − M|)` (folded when that z is
//! negative). Layout: `u` in the low `N` bits, `v` in the next `N`; higher bits are zero when
//! encoded and ignored when decoded.
//!
//! The *precise* encoder (the survey's) tries the four codes around the continuous coordinates
//! and keeps the one whose direction is closest to the input; the `_fast` encoder rounds each
//! coordinate. Measured over 2^24 spherical-Fibonacci directions (README): the precise encoder
//! cuts the maximum error by about a third at every size.

use super::{normalize, sanitize};
use glam::{IVec2, IVec3, UVec2, Vec2, Vec3};

/// `M = 2^bits − 1`, the largest code per axis.
///
/// **Bad input:** panics unless `1 ≤ bits ≤ 16` (the two codes must fit a `u32`, and the precise
/// encoder's exact `|D|² ≤ M²` a `u32`). Every generic function below starts from `max_code`, so
/// [`encode_precise`], [`encode_round`], [`decode`], [`continuous`] and [`lattice`] panic alike
/// instead of wrapping silently in release builds.
pub const fn max_code(bits: u32) -> u32 {
    assert!(
        bits >= 1 && bits <= 16,
        "octahedral codes have 1 to 16 bits per axis"
    );
    (1 << bits) - 1
}

/// The continuous code coordinates in `[0, M]²` of a sanitized vector: its octahedral projection
/// `s.xy / (|x| + |y| + |z|)`, folded when `s.z < 0` (the sign of ±0 counts as +), mapped by
/// `(p/2 + 1/2)·M`. As the WGSL computes it, operation for operation.
pub fn continuous(s: Vec3, bits: u32) -> Vec2 {
    let a = s.abs();
    let l1 = (a.x + a.y) + a.z;
    let mut p = Vec2::new(s.x / l1, s.y / l1);
    if s.z < 0.0 {
        let sgn = Vec2::new(
            if p.x >= 0.0 { 1.0 } else { -1.0 },
            if p.y >= 0.0 { 1.0 } else { -1.0 },
        );
        p = (Vec2::ONE - Vec2::new(p.y.abs(), p.x.abs())) * sgn;
    }
    let t = (p * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::ONE);
    t * max_code(bits) as f32
}

/// The exact integer vector code `(u, v)` stands for (L1 norm `M`; see the module docs).
/// Branch-free like the WGSL: the fold is a select between exact integer vectors.
pub fn lattice(uv: UVec2, bits: u32) -> IVec3 {
    let m = max_code(bits) as i32;
    let ab = IVec2::new(2 * uv.x as i32 - m, 2 * uv.y as i32 - m);
    let aab = ab.abs();
    let z = m - aab.x - aab.y;
    // Folded when z < 0: then a and b are odd (M is odd), never zero, so signum is ±1.
    let folded = (IVec2::splat(m) - IVec2::new(aab.y, aab.x)) * ab.signum();
    let xy = if z < 0 { folded } else { ab };
    xy.extend(z)
}

/// `|s × D|² / |D|²` as the WGSL's `oct_sin2` computes it: the precise encoder's score
/// (sin² of the angle to the code's direction, times `|s|²`).
fn sin2(s: Vec3, uv: UVec2, bits: u32) -> f32 {
    super::sin2_to(s, lattice(uv, bits))
}

/// The survey's precise encoder with `bits` bits per axis (1..=16; panics otherwise, see
/// [`max_code`]).
///
/// Of the four codes `floor(c) + {0, 1}²` around the continuous coordinates `c`, returns the one
/// with the smallest computed `sin²` of the angle between the input and the code's direction,
/// trying `(0,0), (1,0), (0,1), (1,1)` in that order and switching only when strictly smaller
/// (so ties resolve identically in Rust and WGSL).
///
/// **Error bound:** optimal among its four neighbours up to the f32 evaluation of the scores:
/// the chosen direction is at most `2·(2√3 + 3)·2^-24` rad (4.4e-5°) farther from the input
/// than the best neighbour. Each cross-product component is off by ≤ `2^-24·(2|s||D| + |x_k|)`,
/// so the computed sine by ≤ `(2√3 + 1)·2^-24`, and the dot product, conversion and quotient add
/// ≤ 1.5·2^-24 relative; two scores off in opposite directions give the factor 2. A cosine
/// score (largest dot product) cannot rank oct32's candidates in f32 at all (their cosines all
/// round to 1). Scores use the exact integer direction `D`, which the decoder turns into
/// `normalize(D)` to within `√2·2^-24` rad. Measured over 2^24 directions: worst excess 5.4e-6°.
/// Bit-identical to the WGSL on a correctly rounded adapter.
pub fn encode_precise(n: Vec3, bits: u32) -> u32 {
    let m = max_code(bits);
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let c = continuous(s, bits);
    let c00 = UVec2::new(
        (c.x.floor() as u32).min(m - 1),
        (c.y.floor() as u32).min(m - 1),
    );
    // As the WGSL's select chain: each later candidate replaces the best only if strictly
    // smaller, in the order (0,0), (1,0), (0,1), (1,1).
    let mut best = (c00, sin2(s, c00, bits));
    for cand in [c00 + UVec2::X, c00 + UVec2::Y, c00 + UVec2::ONE] {
        let s2 = sin2(s, cand, bits);
        if s2 < best.1 {
            best = (cand, s2);
        }
    }
    best.0.x | (best.0.y << bits)
}

/// The rounding encoder: each continuous coordinate rounded to the nearest code (half to even).
/// Bit-identical to the WGSL `_fast` encoders on a correctly rounded adapter.
pub fn encode_round(n: Vec3, bits: u32) -> u32 {
    let c = continuous(sanitize(n).unwrap_or(Vec3::Z), bits);
    (c.x.round_ties_even() as u32) | ((c.y.round_ties_even() as u32) << bits)
}

/// Decode `bits` bits per axis: `normalize(D)` of the code's exact integer vector.
/// Every bit pattern gives a finite unit vector (D is never zero: its L1 norm is M).
pub fn decode(p: u32, bits: u32) -> Vec3 {
    let m = max_code(bits);
    normalize(lattice(UVec2::new(p & m, (p >> bits) & m), bits).as_vec3())
}

macro_rules! oct_size {
    ($bits:literal, $enc:ident, $fast:ident, $dec:ident, $enc_unorm:ident, $dec_unorm:ident,
     $what:literal) => {
        #[doc = concat!("Precise octahedral encoder, ", $what, " (twin of the WGSL function of the same name; see [`encode_precise`]). Bad input: see [`crate::normal`].")]
        pub fn $enc(n: Vec3) -> u32 {
            encode_precise(n, $bits)
        }
        #[doc = concat!("Rounding octahedral encoder, ", $what, " (see [`encode_round`]). Bad input: see [`crate::normal`].")]
        pub fn $fast(n: Vec3) -> u32 {
            encode_round(n, $bits)
        }
        #[doc = concat!("Octahedral decoder, ", $what, " (see [`decode`]); bits above the code are ignored.")]
        pub fn $dec(p: u32) -> Vec3 {
            decode(p, $bits)
        }
        #[doc = concat!("Render-target form of the precise encoder, ", $what, ": the unorm8 channels `byte/255` of the code's bytes.")]
        pub fn $enc_unorm(n: Vec3) -> [f32; 4] {
            crate::depth24::unpack4x8unorm($enc(n))
        }
        #[doc = concat!("Decode sampled unorm8 channels, ", $what, ": bytes rounded back (`round(255·clamp(c, 0, 1))`, NaN → 0), so exact within ±0.49/255 per channel.")]
        pub fn $dec_unorm(c: [f32; 4]) -> Vec3 {
            $dec(super::xyz8::unorm_bytes(c))
        }
    };
}

oct_size!(
    8,
    encode_normal_oct16,
    encode_normal_oct16_fast,
    decode_normal_oct16,
    encode_normal_oct16_unorm,
    decode_normal_oct16_unorm,
    "2×8 bits (RG8; the WGSL render-target form is `vec2` — pass channels 2, 3 as 0)"
);
oct_size!(
    12,
    encode_normal_oct24,
    encode_normal_oct24_fast,
    decode_normal_oct24,
    encode_normal_oct24_unorm,
    decode_normal_oct24_unorm,
    "2×12 bits (three bytes of RGBA8, alpha free)"
);
oct_size!(
    16,
    encode_normal_oct32,
    encode_normal_oct32_fast,
    decode_normal_oct32,
    encode_normal_oct32_unorm,
    decode_normal_oct32_unorm,
    "2×16 bits (all of RGBA8, or RG16)"
);

/// Exact references: the survey's algorithms in f64.
pub mod exact {
    use super::max_code;

    /// The direction code `p` stands for, in f64.
    pub fn decode(p: u32, bits: u32) -> [f64; 3] {
        let m = max_code(bits);
        let d = super::lattice(glam::UVec2::new(p & m, (p >> bits) & m), bits);
        super::super::exact::unit([d.x, d.y, d.z].map(f64::from)).expect("|D|_1 = M > 0")
    }

    /// Continuous code coordinates of a direction in f64.
    pub fn continuous(n: [f64; 3], bits: u32) -> [f64; 2] {
        let l1 = n[0].abs() + n[1].abs() + n[2].abs();
        let mut p = [n[0] / l1, n[1] / l1];
        if n[2] < 0.0 {
            let sgn = |x: f64| if x >= 0.0 { 1.0 } else { -1.0 };
            p = [
                (1.0 - p[1].abs()) * sgn(p[0]),
                (1.0 - p[0].abs()) * sgn(p[1]),
            ];
        }
        let m = f64::from(max_code(bits));
        p.map(|x| ((x * 0.5 + 0.5) * m).clamp(0.0, m))
    }

    /// The four neighbour codes `floor(c) + {0,1}²` of the f64 continuous coordinates.
    pub fn neighbours(n: [f64; 3], bits: u32) -> [u32; 4] {
        let m = max_code(bits);
        let c = continuous(n, bits);
        let base = c.map(|x| (x.floor() as u32).min(m - 1));
        [0u32, 1, 2, 3].map(|k| (base[0] + (k & 1)) | ((base[1] + (k >> 1)) << bits))
    }

    /// The survey's precise encoder in f64: the neighbour with the smallest angle to `n`.
    pub fn encode_precise(n: [f64; 3], bits: u32) -> u32 {
        let mut best = (f64::INFINITY, 0);
        for p in neighbours(n, bits) {
            let e = crate::precision::metrics::angle_degrees(n, decode(p, bits));
            if e < best.0 {
                best = (e, p);
            }
        }
        best.1
    }

    /// The rounding encoder in f64.
    pub fn encode_round(n: [f64; 3], bits: u32) -> u32 {
        let c = continuous(n, bits);
        (c[0].round_ties_even() as u32) | ((c[1].round_ties_even() as u32) << bits)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_has_l1_norm_m_and_inverts_continuous() {
        for bits in [8, 12, 16] {
            let m = max_code(bits) as i32;
            for uv in [UVec2::new(0, 0), UVec2::new(3, 250), UVec2::new(200, 9)] {
                let d = lattice(uv, bits);
                assert_eq!(d.x.abs() + d.y.abs() + d.z.abs(), m);
            }
        }
        // Poles and axes come back through the fast encoder exactly up to the code grid.
        for v in [Vec3::X, Vec3::NEG_X, Vec3::Y, Vec3::NEG_Z] {
            let got = decode_normal_oct32(encode_normal_oct32(v));
            crate::assert_within!(
                got.angle_between(v),
                < 1e-4_f32,
                "comment above: poles and axes exact up to the code grid (literal 1e-4 rad)",
                "{v} -> {got}"
            );
        }
    }

    #[test]
    fn degenerate_inputs_encode_plus_z() {
        let z = encode_normal_oct24(Vec3::Z);
        for v in [
            Vec3::ZERO,
            Vec3::new(f32::NAN, 0.0, 1.0),
            Vec3::splat(1e-40),
        ] {
            assert_eq!(encode_normal_oct24(v), z);
        }
        assert_eq!(
            encode_normal_oct24(Vec3::new(f32::INFINITY, 1.0, 0.0)),
            encode_normal_oct24(Vec3::X)
        );
    }
}
