//! Unreal 5 Substrate's 32-bit top-layer word — the Rust twin of `wgsl/normal_substrate.wgsl`.
//!
//! The word is `normal22 << 10 | roughness8 << 2 | flags2`. The normal is an octahedral code on an
//! 11:11 *centred* grid: per axis, code `k` stands for the octahedral coordinate
//! `x = (k − 1024)/1023`, so code 1024 is `x = 0` exactly, codes 1..=2047 span `[−1, 1]`, and
//! code 0 stands for `x = −1024/1023`, just outside the square (Unreal's writer,
//! `trunc(clamp(x·1023 + 1024, 0, 2047))`, never writes it for `x ≥ −1`; Unreal's fold still
//! reads it as the direction just across the square's edge, and so does [`decode_substrate_normal`]).
//! The decoded vector before normalising is `1/1023` times the integer vector
//! `D = (a, b, 1023 − |a| − |b|)`, `a = k_u − 1024`, `b = k_v − 1024`, folded when that `z < 0`
//! (see [`lattice`]).
//!
//! **Source.** Unreal Engine 5, `Engine/Shaders/Private/Substrate/Substrate.ush`, as summarised
//! in prepass's survey of engine G-buffers: Unreal's source is not public and the search tools
//! found no copy of that file, so the formulas are the survey's, not re-read from the source.
//! Assumed and not verified: `u` (from `x`) in word bits 10–20 and `v` (from `y`) in bits 21–31,
//! the roughness byte read as `b/255`, the fold of Unreal's `UnitVectorToOctahedron` /
//! `OctahedronToUnitVector` (the survey's octahedron, the sign of 0 counting as +). If the
//! engine's order of `u` and `v` is the other one, only [`U_SHIFT`] and [`V_SHIFT`] (and the
//! WGSL's shifts) change.
//!
//! **Encoders.** [`encode_substrate_word`] writes the closest of the four codes around the
//! continuous coordinates (the octahedral precise encoder's choice, [`super::oct::encode_precise`],
//! on the centred grid) and the roughness byte nearest `255·r` (as
//! [`crate::roughness_ggx::encode_roughness_ggx8`]); [`encode_substrate_word_fast`] rounds each
//! coordinate instead. Unreal's own writer truncates, which doubles the worst error
//! (`tests/normal_substrate.rs` measures both).
//!
//! **Bad input** (the same in the WGSL): the normal as the octahedral encoders ([`crate::normal`]:
//! NaN anywhere, zero and all-subnormal vectors encode `+z`; infinities win); roughness as
//! [`crate::roughness_ggx::encode_roughness_ggx8`] (clamped to `[0, 1]`, NaN → 255, the
//! roughest); flags: only the low 2 bits are stored. Decoders accept every bit pattern: a finite
//! unit vector, a roughness in `[0, 1]`, flags in `0..=3`.

use super::{normalize, sanitize, sin2_to};
use glam::{IVec2, IVec3, UVec2, Vec2, Vec3};

/// The lowest bit of `u` (the code from `x`) in the word (assumed; see the module docs).
pub const U_SHIFT: u32 = 10;
/// The lowest bit of `v` (the code from `y`) in the word (assumed; see the module docs).
pub const V_SHIFT: u32 = 21;
/// The centre code, `x = 0`.
pub const CENTRE: i32 = 1024;
/// The grid's scale: code `k` stands for `(k − 1024)/1023`.
pub const SCALE: i32 = 1023;

/// The top of the clamped octahedral projection, `1 − 2^-23`: `1023·p` then stays below 1023
/// whichever neighbour a conforming multiply rounds to (the exact product `1023 − 1023·2^-23`
/// lies between `1023 − 2·ulp(1023)` and `1023 − ulp(1023)`), so `floor` is at most 1022 and the
/// precise encoder's candidates `floor + 1` stay codes; rounding still gives 1023.
pub const CONTINUOUS_TOP: f32 = 1.0 - f32::EPSILON;

/// The codes `(u, v)` of a word.
pub fn codes(word: u32) -> UVec2 {
    UVec2::new((word >> U_SHIFT) & 0x7ff, word >> V_SHIFT)
}

/// The word bits of codes `(u, v)` (each at most 2047; roughness and flags zero).
pub fn word_of(k: UVec2) -> u32 {
    (k.x << U_SHIFT) | (k.y << V_SHIFT)
}

/// The exact integer vector codes `k` stand for (1023 times the decoded vector before
/// normalising): `a = k_u − 1024`, `b = k_v − 1024`, `z = 1023 − |a| − |b|`, and when `z < 0`
/// the fold `D.xy = (a, b) + sgn(a, b)·z` with `sgn(0) = +1`, i.e. `(1023 − |b|, 1023 − |a|)`
/// with `a`'s and `b`'s signs (Unreal's `OctahedronToUnitVector` in exact arithmetic). Never
/// zero: `|D|₁ ≥ 1023` for codes 1..=2047, and code 0's `z = −1 − |b|` is negative.
pub fn lattice(k: UVec2) -> IVec3 {
    let ab = k.as_ivec2() - IVec2::splat(CENTRE);
    let z = SCALE - ab.abs().element_sum();
    let sgn = IVec2::new(
        if ab.x >= 0 { 1 } else { -1 },
        if ab.y >= 0 { 1 } else { -1 },
    );
    (ab + sgn * z.min(0)).extend(z)
}

/// The continuous centred coordinates `q = 1023·p` of a sanitized vector, `p` its octahedral
/// projection (folded when `s.z < 0`; the sign of ±0 counts as +) clamped to
/// `[−1, CONTINUOUS_TOP]`; the code is `q + 1024`. As the WGSL's `substrate_continuous`.
pub fn continuous(s: Vec3) -> Vec2 {
    let a = s.abs();
    let p = super::oct::project(s, (a.x + a.y) + a.z);
    p.clamp(Vec2::splat(-1.0), Vec2::splat(CONTINUOUS_TOP)) * 1023.0
}

/// The precise choice (the WGSL's `substrate_choose`): of the codes `floor(q) + {0, 1}² + 1024`,
/// the one with the smallest computed `|s × D|²/|D|²`, trying `(0,0), (1,0), (0,1), (1,1)` and
/// switching only when strictly smaller (the WGSL's tree picks the same). Returns the word's
/// normal bits.
fn choose(s: Vec3, q: Vec2) -> u32 {
    let k00 = (q.floor() + Vec2::splat(1024.0)).as_uvec2();
    debug_assert!(k00.min_element() >= 1 && k00.max_element() <= 2046);
    let mut best = (k00, sin2_to(s, lattice(k00)));
    for cand in [k00 + UVec2::X, k00 + UVec2::Y, k00 + UVec2::ONE] {
        let s2 = sin2_to(s, lattice(cand));
        if s2 < best.1 {
            best = (cand, s2);
        }
    }
    word_of(best.0)
}

/// The word's normal bits (roughness and flags zero) whose direction is closest to `n` among
/// the four codes around its continuous coordinates.
///
/// **Error bound:** optimal among its four neighbours up to the f32 evaluation of the scores,
/// as [`super::oct::encode_precise`] (the same score and argument:
/// `prepass::sweep::normal::optimality_tolerance_deg`). The four include the rounded code, so
/// the round trip is within the rounding encoder's bound `asin(3√2·(1/2046 + 4·2^-24))` ≈ 0.1189°
/// (derived in `tests/normal_substrate.rs`) plus that tolerance; measured over 2^20
/// spherical-Fibonacci directions on lavapipe: max 0.0787°, mean 0.0391° (rounding: 0.1176°,
/// 0.0418°; Unreal's truncating writer: 0.2355°, 0.0836°). Optimal among the four, not over
/// every code: near the square's edges a code mirrored across the edge can be closer (a
/// brute-force search found that for 5532 of 1,276,664 test directions, by at most 0.0367°).
/// Bit-identical to the WGSL on a correctly rounded adapter. Bad input: see the module docs.
pub fn encode_substrate_normal(n: Vec3) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    choose(s, continuous(s))
}

/// The word's normal bits by rounding each centred coordinate (half to even): cheaper, not
/// always the closest direction. Bit-identical to the WGSL on a correctly rounded adapter.
pub fn encode_substrate_normal_fast(n: Vec3) -> u32 {
    let q = continuous(sanitize(n).unwrap_or(Vec3::Z));
    let k = Vec2::new(q.x.round_ties_even(), q.y.round_ties_even()) + Vec2::splat(1024.0);
    word_of(k.as_uvec2())
}

/// The whole word: [`encode_substrate_normal`]`(n) | byte << 2 | (flags & 3)`, the byte
/// [`crate::roughness_ggx::encode_roughness_ggx8`]`(roughness)` (nearest `255·r`, exact).
pub fn encode_substrate_word(n: Vec3, roughness: f32, flags: u32) -> u32 {
    encode_substrate_normal(n)
        | (crate::roughness_ggx::encode_roughness_ggx8(roughness) << 2)
        | (flags & 3)
}

/// [`encode_substrate_word`] with the rounding normal encoder.
pub fn encode_substrate_word_fast(n: Vec3, roughness: f32, flags: u32) -> u32 {
    encode_substrate_normal_fast(n)
        | (crate::roughness_ggx::encode_roughness_ggx8(roughness) << 2)
        | (flags & 3)
}

/// The unit normal of a word: `normalize(D)` of its codes' exact integer vector ([`lattice`]).
/// Every bit pattern gives a finite unit vector (within `super::UNIT_TOLERANCE`).
pub fn decode_substrate_normal(word: u32) -> Vec3 {
    normalize(lattice(codes(word)).as_vec3())
}

/// The perceptual roughness `b/255` of the word's byte `b` (bits 2–9), correctly rounded (as
/// [`crate::roughness_ggx::decode_roughness_ggx8`]).
pub fn decode_substrate_roughness(word: u32) -> f32 {
    crate::roughness_ggx::decode_roughness_ggx8((word >> 2) & 0xff)
}

/// The word's 2 flag bits (bits 0–1).
pub fn substrate_flags(word: u32) -> u32 {
    word & 3
}

/// Exact references in f64, and Unreal's own formulas.
pub mod exact {
    use super::{codes, lattice, word_of};
    use glam::UVec2;

    /// The direction a word's normal bits stand for, in f64.
    pub fn decode(word: u32) -> [f64; 3] {
        let d = lattice(codes(word));
        crate::normal::exact::unit([d.x, d.y, d.z].map(f64::from)).expect("D is never zero")
    }

    /// Unreal's reader in f64: `x = (k − 1024)/1023` per axis, then `OctahedronToUnitVector`
    /// (`N = (x, y, 1 − |x| − |y|)`, `t = max(−N.z, 0)`, `N.xy += N.xy ≥ 0 ? −t : t`),
    /// normalised. The interop reference for [`super::decode_substrate_normal`].
    pub fn unreal_decode(word: u32) -> [f64; 3] {
        let k = codes(word);
        let f = |k: u32| (f64::from(k) - 1024.0) / 1023.0;
        let (x, y) = (f(k.x), f(k.y));
        let z = 1.0 - x.abs() - y.abs();
        let t = (-z).max(0.0);
        let unfold = |a: f64| if a >= 0.0 { a - t } else { a + t };
        crate::normal::exact::unit([unfold(x), unfold(y), z]).expect("never the zero vector")
    }

    /// Continuous centred coordinates `1023·p` of a direction in f64 (`p` its folded projection,
    /// the sign of 0 counting as +).
    pub fn continuous(n: [f64; 3]) -> [f64; 2] {
        crate::normal::oct::exact::project(n).map(|x| x.clamp(-1.0, 1.0) * 1023.0)
    }

    /// The four neighbour codes `floor(q) + {0,1}² + 1024` of the f64 coordinates, as words.
    pub fn neighbours(n: [f64; 3]) -> [u32; 4] {
        let q = continuous(n);
        let base = q.map(|x| ((x.floor() as i32).min(1022) + 1024) as u32);
        [0u32, 1, 2, 3].map(|k| word_of(UVec2::new(base[0] + (k & 1), base[1] + (k >> 1))))
    }

    /// The precise encoder in f64: the neighbour with the smallest angle to `n`.
    pub fn encode_precise(n: [f64; 3]) -> u32 {
        crate::normal::exact::closest(n, neighbours(n), decode)
    }

    /// The rounding encoder in f64.
    pub fn encode_round(n: [f64; 3]) -> u32 {
        let q = continuous(n);
        let k = q.map(|x| (x.round_ties_even() + 1024.0) as u32);
        word_of(UVec2::new(k[0], k[1]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_matches_unreals_fold_and_is_never_zero() {
        for u in (0..2048)
            .step_by(7)
            .chain([0, 1, 1023, 1024, 1025, 2046, 2047])
        {
            for v in (0..2048).step_by(5).chain([0, 1, 1024, 2047]) {
                let w = word_of(UVec2::new(u, v));
                let d = lattice(UVec2::new(u, v));
                assert_ne!(d, IVec3::ZERO);
                if u >= 1 && v >= 1 {
                    assert_eq!(d.x.abs() + d.y.abs() + d.z.abs(), 1023);
                }
                let a = exact::decode(w);
                let b = exact::unreal_decode(w);
                let e = crate::precision::metrics::angle_degrees(a, b);
                assert!(e < 1e-12, "{u} {v}: {e}");
            }
        }
    }

    #[test]
    fn word_fields_round_trip() {
        let w = encode_substrate_word(Vec3::new(0.3, -0.2, 0.9), 0.5, 7);
        assert_eq!(substrate_flags(w), 3);
        assert_eq!(decode_substrate_roughness(w), 128.0 / 255.0);
        assert_eq!(
            w & !0x3ff,
            encode_substrate_normal(Vec3::new(0.3, -0.2, 0.9))
        );
        for v in [
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::Z,
            Vec3::NEG_Z,
        ] {
            for enc in [encode_substrate_normal, encode_substrate_normal_fast] {
                assert_eq!(decode_substrate_normal(enc(v)), v, "{v}");
            }
        }
    }
}
