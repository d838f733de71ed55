//! O3DE's signed octahedron in RGB10A2 — the Rust twin of `wgsl/normal_signed_oct.wgsl`: the
//! hemi-octahedral map of `(x, y, |z|)` at 10 bits per axis in R and G, z's sign in B; the whole
//! sphere in 21 bits, A's 2 bits left to the renderer.
//!
//! **Source.** O3DE, `Gems/Atom/RPI/Assets/ShaderLib/Atom/RPI/Math.azsli`,
//! `EncodeNormalSignedOctahedron` / `DecodeNormalSignedOctahedron` ("Store in a 10/10/10/2
//! texture", after John White's 2017 "signed octahedron normal encoding"). O3DE writes, with
//! `p = n.xy/(|x| + |y| + |z|)`, `R = p.x/2 + (p.y/2 + 1/2)`, `G = −p.x/2 + (p.y/2 + 1/2)`,
//! `B = saturate(n.z·FLT_MAX)` (1 for `z > 0`, 0 for `z ≤ 0`), and reads `x = R − G`,
//! `y = (R + G) − 1`, `z = (2B − 1)(1 − |x| − |y|)`, normalised; the RGB10A2 write rounds R and G
//! to `k/1023`.
//!
//! **Grid.** Codes `(u, v)` (R's and G's) stand for the exact integer vector
//! `D = (u − v, u + v − M, ±(M − |u − v| − |u + v − M|))`, `M = 1023`, the sign from B (`+` for
//! B = 1023, `−` for 0) — O3DE's decode times `M`, exactly ([`exact::o3de_decode`] checks it). That is
//! [`super::hemioct`]'s lattice at 10 bits with O3DE's axes: `u` is hemioct's first axis,
//! `v` its second mirrored (`v ↦ M − v`). `|D|₁ = M`: never zero.
//!
//! **Layout** of the `u32` form: the RGB10A2 texel's bits — `u` (R) in bits 0–9, `v` (G) in
//! bits 10–19, B in bits 20–29: 1023 for `z > 0` (O3DE's `B = 1`), 0 otherwise; bits 30–31 (A)
//! zero when encoded. The decoders read B as O3DE does: z's factor is `2B/1023 − 1`, so
//! `z > 0` exactly when `B ≥ 512`, for every B; A is ignored. On the equator (`u` or `v` at 0 or
//! `M`) a B below 512 gives `z = −0`, as O3DE's decoder does.
//!
//! **Breaking fix (issue 60).** Before, the encoders put z's sign in bit 20 alone and the decoder
//! read bit 20: a word that, stored as the texel, O3DE reads as `B = 1/1023` (z negative, +z
//! 179.94° off), and a texel with `B = 1022` or 512 that O3DE reads with z > 0 came back with
//! z < 0. The README's convention is that every encoder returns the `u32` the target stores, and
//! a renderer storing this word in O3DE's RGB10A2 target (or reading O3DE's texel with
//! [`decode_normal_signed_oct`]) expects O3DE's bits, so the word is now the texel. A word
//! written by the old encoder with z > 0 (bit 20 alone) now reads with z < 0: re-encode.
//!
//! **Error.** Rounding each of R, G to the nearest code moves the L1-normalised vector
//! `(x, y, 1 − |x| − |y|)` by `|Δv|² ≤ Δx² + Δy² + (|Δx| + |Δy|)² ≤ 8h²` (`Δx = ΔR − ΔG`,
//! `Δy = ΔR + ΔG`, `|ΔR|, |ΔG| ≤ h`), and `sin∠ ≤ √3·|Δv|` (both vectors have length ≥ 1/√3):
//! `sin∠ ≤ 2√6·h`, `h = 1/2046 + 4·2^-24` (half a code and the f32 coordinates' error):
//! **≤ 0.1373°** for the rounding encoder and O3DE's own (the same codes), and for the precise
//! encoder that plus `prepass::sweep::normal::optimality_tolerance_deg` (derived and measured in
//! `tests/normal_signed_oct.rs`). Measured over 2^20 spherical-Fibonacci directions on lavapipe:
//! precise mean 0.0593°, max 0.1360°; rounding (and O3DE's encoder, the same codes) mean
//! 0.0596°, max 0.1360° — the cells' worst points are their centres, where every candidate is
//! as far; oct20 (the full octahedron in the same R and G) errs up to 0.1575°.
//!
//! **Bad input:** as [`crate::normal`] (NaN, zero, all-subnormal → `+z`; infinities win; any
//! finite length). `z = ±0` after that writes bit 20 clear, as O3DE's `saturate(0·FLT_MAX) = 0`.

use super::{normalize, sanitize, sin2_to};
use glam::{IVec2, IVec3, UVec2, Vec2, Vec3};

/// Largest code per axis, `2^10 − 1`.
pub const M: u32 = 1023;

/// Bit 20, B's lowest bit: set in every word the encoders write for `z > 0` (where B is 1023,
/// [`B_MASK`]); the decoders read all of B ([`b_code`]).
pub const SIGN_BIT: u32 = 1 << 20;

/// B's ten bits, 20–29: all set by the encoders for `z > 0` (O3DE's `B = 1`), clear otherwise.
pub const B_MASK: u32 = 0x3ff << 20;

/// B's code (bits 20–29) of a word.
pub fn b_code(p: u32) -> u32 {
    (p >> 20) & 0x3ff
}

/// O3DE's `2B − 1` on `B = b/1023`, times 1023: `2b − 1023`, an odd integer in `[−1023, 1023]`
/// (never 0): z's factor. Its sign is z's for every B.
pub fn z_factor(b: u32) -> i32 {
    2 * (b & 0x3ff) as i32 - M as i32
}

/// The top of the clamped continuous coordinates `(R, G)`, `1 − 2^-23`
/// ([`super::oct::CONTINUOUS_TOP`]): `floor(1023·c)` stays below `M`, `round` still gives `M`.
pub const CONTINUOUS_TOP: f32 = super::oct::CONTINUOUS_TOP;

/// The codes `(u, v)` of a word.
pub fn codes(p: u32) -> UVec2 {
    UVec2::new(p & 0x3ff, (p >> 10) & 0x3ff)
}

/// The word (texel) of codes `(u, v)` (each at most `M`) on the hemisphere `positive`
/// (`z > 0`): B = 1023 there, 0 otherwise.
pub fn word_of(k: UVec2, positive: bool) -> u32 {
    k.x | (k.y << 10) | if positive { B_MASK } else { 0 }
}

/// The exact integer vector of codes `(u, v)` on the upper hemisphere:
/// `(u − v, u + v − M, M − |u − v| − |u + v − M|)`, `z ≥ 0`, `|D|₁ = M` (the WGSL's
/// `signed_oct_lattice`, there in f32, exact).
pub fn lattice(k: UVec2) -> IVec3 {
    let (u, v, m) = (k.x as i32, k.y as i32, M as i32);
    let h = IVec2::new(u - v, u + v - m);
    h.extend(m - h.abs().element_sum())
}

/// Continuous code coordinates `1023·(R, G)` in `[0, M)` of a sanitized vector, in O3DE's order
/// of operations (`p = s.xy/|s|₁`, `y0 = p.y/2 + 1/2`, `R = p.x/2 + y0`, `G = −p.x/2 + y0`),
/// clamped to `[0, CONTINUOUS_TOP]` before the scaling (as the WGSL's `signed_oct_continuous`).
pub fn continuous(s: Vec3) -> Vec2 {
    let a = s.abs();
    let l1 = (a.x + a.y) + a.z;
    let p = Vec2::new(s.x / l1, s.y / l1);
    let y0 = p.y * 0.5 + 0.5;
    let rg = Vec2::new(p.x * 0.5 + y0, p.x * -0.5 + y0);
    rg.clamp(Vec2::ZERO, Vec2::splat(CONTINUOUS_TOP)) * M as f32
}

/// Precise signed-octahedral encoder: bit 20 from the sign of z (set for `z > 0`), and of the
/// four codes `floor(c) + {0,1}²` around the continuous coordinates the one with the smallest
/// computed `|a × D|²/|D|²`, `a = (s.x, s.y, |s.z|)` (mirroring both in z keeps the score), the
/// first of equal scores in the order `(0,0), (1,0), (0,1), (1,1)` — hemioct's precise encoder
/// ([`super::hemioct::encode_normal_hemioct24`]) on this grid. A code on the other hemisphere is
/// never closer (its mirror image on this one is at most as far).
///
/// **Error bound:** optimal among its four candidates up to the f32 evaluation of the scores
/// (`prepass::sweep::normal::optimality_tolerance_deg`); they include the rounded code, so the
/// round trip is within the rounding bound (module docs, 0.1373°) plus that tolerance.
/// Bit-identical to `encode_normal_signed_oct` on a correctly rounded adapter. Bad input: see
/// the module docs.
pub fn encode_normal_signed_oct(n: Vec3) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let a = Vec3::new(s.x, s.y, s.z.abs());
    let c = continuous(s);
    // c < M (see `continuous`), so base + 1 ≤ M.
    let base = UVec2::new(c.x.floor() as u32, c.y.floor() as u32);
    let mut best = (base, sin2_to(a, lattice(base)));
    for cand in [base + UVec2::X, base + UVec2::Y, base + UVec2::ONE] {
        let s2 = sin2_to(a, lattice(cand));
        if s2 < best.1 {
            best = (cand, s2);
        }
    }
    word_of(best.0, s.z > 0.0)
}

/// Rounding signed-octahedral encoder: the nearest code per axis (half to even), bit 20 from
/// the sign of z. For finite vectors of normal (not subnormal) components these are the codes
/// O3DE's encoder and a round-to-nearest RGB10A2 write give: the same arithmetic, and the
/// sanitizer's power-of-two scaling leaves `p` as it is (`tests/normal_signed_oct.rs` checks
/// it against the peer). Error bound: module docs (0.1373°). Bit-identical to
/// `encode_normal_signed_oct_fast` on a correctly rounded adapter.
pub fn encode_normal_signed_oct_fast(n: Vec3) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let c = continuous(s);
    word_of(
        UVec2::new(c.x.round_ties_even() as u32, c.y.round_ties_even() as u32),
        s.z > 0.0,
    )
}

/// Decode a texel as O3DE's `DecodeNormalSignedOctahedron` reads it: the direction of
/// `(R − G, R + G − 1, (2B − 1)(1 − |x| − |y|))` on `R = u/1023`, `G = v/1023`, `B = b/1023`
/// (bits 20–29), i.e. of the exact integers `(1023·D.x, 1023·D.y, (2b − 1023)·D.z)` (below 2^20
/// in magnitude, exact in f32), normalised; for the B the encoders write (1023, 0) that
/// direction is `D`'s with z's sign, and `normalize` takes `D` itself (as before issue 60, so
/// those decodes keep their bits). For every B, z's sign is O3DE's (`+` for `b ≥ 512`), and on
/// the equator `−0` for `b < 512`. Bits 30–31 (A) ignored. Every bit pattern gives a finite
/// unit vector; its direction is within `√2·2^-24` rad of the exact one. (Breaking fix: see the
/// module docs.)
pub fn decode_normal_signed_oct(p: u32) -> Vec3 {
    let mut d = lattice(codes(p)).as_vec3();
    let b = b_code(p);
    if b != 0 && b != M {
        let m = M as f32;
        return normalize(Vec3::new(d.x * m, d.y * m, d.z * z_factor(b) as f32));
    }
    if b == 0 {
        d.z = -d.z;
    }
    normalize(d)
}

/// The texel of a code index `k < 2^21` (R and G its low 20 bits, z > 0 where bit 20 is set):
/// B = 1023 there, else 0 — the 2^21 texels O3DE writes, indexed as the old words were.
pub fn texel_of_index(k: u32) -> u32 {
    word_of(codes(k), k & SIGN_BIT != 0)
}

/// Render-target form of [`encode_normal_signed_oct`]: the rgb10a2unorm channels
/// `R = u/1023`, `G = v/1023`, `B` = 1 for `z > 0` and 0 otherwise (B's code 1023 or 0, all its
/// bits equal to bit 20), `A = 0` (the renderer's).
pub fn encode_normal_signed_oct_unorm(n: Vec3) -> [f32; 4] {
    let p = encode_normal_signed_oct(n);
    let k = |x: u32| super::xyz10::unorm10(x & 0x3ff);
    [k(p), k(p >> 10), ((p >> 20) & 1) as f32, 0.0]
}

/// Decode sampled rgb10a2unorm channels R, G, B, each rounded back to its code as
/// [`crate::normal::xyz10::decode_normal_xyz10_unorm`] reads a channel (NaN and negatives 0,
/// from 1 up to `+∞` 1, `round(1023·c)`), then [`decode_normal_signed_oct`] of that texel (B's
/// code read as O3DE reads B: `z > 0` for B's code at least 512); A ignored. Exact whenever each
/// channel is within ±0.49/1023 of `k/1023`.
pub fn decode_normal_signed_oct_unorm(c: [f32; 4]) -> Vec3 {
    let k = super::xyz10::unorm10_code;
    decode_normal_signed_oct(k(c[0]) | (k(c[1]) << 10) | (k(c[2]) << 20))
}

/// Exact references in f64, and O3DE's own formulas.
pub mod exact {
    use super::{M, b_code, codes, lattice, word_of, z_factor};
    use glam::UVec2;

    /// The direction a word (texel) stands for, in f64: `(D.x, D.y, D.z·(2b − 1023)/1023)`,
    /// `b` its B code.
    pub fn decode(p: u32) -> [f64; 3] {
        let d = lattice(codes(p));
        let z = f64::from(d.z) * f64::from(z_factor(b_code(p))) / f64::from(M);
        crate::normal::exact::unit([f64::from(d.x), f64::from(d.y), z]).expect("|D.xy| + |D.z| > 0")
    }

    /// O3DE's `DecodeNormalSignedOctahedron` in f64 on the channels `R = u/1023`, `G = v/1023`
    /// and `b` (B's value): `x = R − G`, `y = (R + G) − 1`, `z = (2b − 1)(1 − |x| − |y|)`,
    /// normalised. With `b = k/1023` the direction of [`decode`] of the texel with B code `k`.
    pub fn o3de_decode(u: u32, v: u32, b: f64) -> [f64; 3] {
        let (r, g) = (f64::from(u) / 1023.0, f64::from(v) / 1023.0);
        let (x, y) = (r - g, (r + g) - 1.0);
        let z = (b * 2.0 - 1.0) * (1.0 - x.abs() - y.abs());
        crate::normal::exact::unit([x, y, z])
            .expect("2b − 1 ≠ 0 for b = k/1023, so |(x, y)| + |z| > 0")
    }

    /// Continuous code coordinates `1023·(R, G)` of a direction in f64, clamped to `[0, M]`.
    pub fn continuous(n: [f64; 3]) -> [f64; 2] {
        let l1 = n[0].abs() + n[1].abs() + n[2].abs();
        let p = [n[0] / l1, n[1] / l1];
        let m = f64::from(M);
        [p[0] + p[1], p[1] - p[0]].map(|x| ((x * 0.5 + 0.5) * m).clamp(0.0, m))
    }

    /// The four neighbour codes of the f64 continuous coordinates, on `n`'s hemisphere.
    pub fn neighbours(n: [f64; 3]) -> [u32; 4] {
        let c = continuous(n);
        let base = c.map(|x| (x.floor() as u32).min(M - 1));
        [0u32, 1, 2, 3].map(|k| {
            word_of(
                UVec2::new(base[0] + (k & 1), base[1] + (k >> 1)),
                n[2] > 0.0,
            )
        })
    }

    /// The precise encoder in f64: the neighbour with the smallest angle to `n`.
    pub fn encode_precise(n: [f64; 3]) -> u32 {
        crate::normal::exact::closest(n, neighbours(n), decode)
    }

    /// The rounding encoder in f64 (O3DE's writer in exact arithmetic).
    pub fn encode_round(n: [f64; 3]) -> u32 {
        let c = continuous(n);
        let k = c.map(|x| x.round_ties_even() as u32);
        word_of(UVec2::new(k[0], k[1]), n[2] > 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_is_hemiocts_mirrored_and_o3de_reads_it() {
        for u in (0..=M).step_by(3).chain([0, 1, 511, 512, M - 1, M]) {
            for v in (0..=M).step_by(5).chain([0, 1, 511, 512, M - 1, M]) {
                let d = lattice(UVec2::new(u, v));
                assert!(
                    d.z >= 0 && d.x.abs() + d.y.abs() + d.z == M as i32,
                    "{u} {v}"
                );
                // hemioct's lattice at M = 1023 with v mirrored: (u + v' − M, u − v') with
                // v' = M − v.
                let (a, b) = (u as i32, (M - v) as i32);
                assert_eq!((d.x, d.y), (a + b - M as i32, a - b), "{u} {v}");
                for pos in [false, true] {
                    let w = word_of(UVec2::new(u, v), pos);
                    let e = crate::precision::metrics::angle_degrees(
                        exact::decode(w),
                        exact::o3de_decode(u, v, if pos { 1.0 } else { 0.0 }),
                    );
                    assert!(e < 1e-12, "{u} {v} {pos}: {e}");
                }
            }
        }
    }

    /// ±x and ±y are codes (corners and edge midpoints of the square); ±z is not (`M` is odd,
    /// so `u − v = 0` and `u + v = M` never hold together): its nearest codes are a step off,
    /// `atan(1/1022)`.
    #[test]
    fn axes_round_trip_and_sign_follows_z() {
        for v in [
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::Z,
            Vec3::NEG_Z,
        ] {
            for enc in [encode_normal_signed_oct, encode_normal_signed_oct_fast] {
                let p = enc(v);
                assert_eq!(p >> 30, 0);
                assert_eq!(b_code(p), if v.z > 0.0 { M } else { 0 }, "{v}");
                let d = decode_normal_signed_oct(p);
                if v.z == 0.0 {
                    assert_eq!(d.abs(), v.abs(), "{v}: {d}");
                } else {
                    let w = |a: Vec3| [a.x, a.y, a.z].map(f64::from);
                    let e = crate::precision::metrics::angle_degrees(w(d), w(v));
                    let pole = (1.0f64 / 1022.0).atan().to_degrees();
                    assert!((e - pole).abs() < 1e-5, "{v}: {d}, {e}° against {pole}°");
                }
            }
        }
        // The equator with B = 0: z = −0.
        let d = decode_normal_signed_oct(encode_normal_signed_oct(Vec3::X));
        assert_eq!(d.z.to_bits(), (-0.0f32).to_bits());
        // O3DE's B for z = 0 is 0; the unorm form writes it.
        assert_eq!(encode_normal_signed_oct_unorm(Vec3::Y)[2], 0.0);
        assert_eq!(encode_normal_signed_oct_unorm(Vec3::Z)[2], 1.0);
    }

    /// Over 20,000 spherical-Fibonacci directions: the precise choice is within its f32 score
    /// error of the f64 best of its candidates, `2(2√3 + 3)·2^-24` rad, plus the two decodes'
    /// rounding `2√2·2^-24` (`sweep::normal::optimality_tolerance_deg`'s derivation), and the
    /// round trip within the module's bound 0.1373° plus that.
    #[test]
    fn precise_is_within_its_tolerance_of_the_f64_best() {
        let ulp = 2f64.powi(-24);
        let tol = (2.0 * (2.0 * 3f64.sqrt() + 3.0) * ulp + 2.0 * 2f64.sqrt() * ulp).to_degrees();
        let bound = (2.0 * 6f64.sqrt() * (1.0 / 2046.0 + 4.0 * ulp))
            .asin()
            .to_degrees();
        let (mut worst, mut max) = (0f64, 0f64);
        for i in 0..20_000u32 {
            let t = f64::from(i) * 0.618_033_988_749_895 * std::f64::consts::TAU;
            let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / 20_000.0;
            let r = (1.0 - z * z).sqrt();
            let v = Vec3::new((r * t.cos()) as f32, (r * t.sin()) as f32, z as f32);
            let n = [v.x, v.y, v.z].map(f64::from);
            let e = |p: u32| crate::precision::metrics::angle_degrees(n, exact::decode(p));
            let got = e(encode_normal_signed_oct(v));
            worst = worst.max(got - e(exact::encode_precise(n)));
            max = max.max(got);
        }
        assert!(worst <= tol, "worst excess {worst}° over tolerance {tol}°");
        assert!(
            max <= bound + tol,
            "max {max}° over bound {bound}° + {tol}°"
        );
    }
}
