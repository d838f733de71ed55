//! View-space normal x and y as two FP16 halves in one `u32`, z rebuilt — the Rust twin of
//! `wgsl/normal_xy_fp16.wgsl`.
//!
//! Killzone 2 stored "view space normals XY (RG FP16)", packed as 2×FP16 into RGBA8 on write,
//! and rebuilt `z = sqrt(1 − x² − y²)` (Michal Valient, "Deferred Rendering in Killzone 2",
//! Guerrilla Games, Develop Conference 2007). The sign of z is lost: a normal with `z < 0`
//! decodes mirrored through the xy plane. Under perspective a visible surface's normal does
//! reach `z < 0` (down to −sin of the view ray's angle off the axis) — the "viewspace normal
//! myth" of Mark Lee, "Pre-lighting in Resistance 2" (Insomniac Games, GDC 2009).
//! `prepass::sweep::normal::killzone_myth` (feature `harness`) measures it.

use super::{dot, sanitize};
use glam::{Vec2, Vec3};
use half::f16;

/// WGSL's `pack2x16float(v)`: `v.x` to the low half, `v.y` to the high half, each rounded to the
/// nearest f16 (ties to even, what lavapipe does; WGSL leaves inexact conversions to the
/// implementation, and out-of-range values indeterminate: callers clamp first).
///
/// **Bad input (this twin; the WGSL builtin leaves these indeterminate):** NaN gives an f16 NaN
/// of the same sign, quiet bit set, top payload bits kept (`0x7e00` for the default NaN and for
/// the signalling `0x7f800001`); ±Inf and values rounding past 65504 (from 65520 up) give ±Inf; f32 subnormals
/// round to a signed zero half.
pub fn pack2x16float(v: Vec2) -> u32 {
    u32::from(f16::from_f32(v.x).to_bits()) | (u32::from(f16::from_f32(v.y).to_bits()) << 16)
}

/// WGSL's `unpack2x16float(p)`: exact (every f16 is an f32). Every bit pattern is accepted: NaN
/// halves give NaN, ±Inf halves ±Inf, subnormal halves their exact (normal f32) value.
pub fn unpack2x16float(p: u32) -> Vec2 {
    Vec2::new(
        f16::from_bits(p as u16).to_f32(),
        f16::from_bits((p >> 16) as u16).to_f32(),
    )
}

/// Encode `pack2x16float(clamp(u.xy, −1, 1))` of `u = n/|n|`; the sign of `u.z` is dropped.
///
/// **Error bound:** each half is the f16 nearest `u.x`, `u.y` (relative error ≤ 2^-11, absolute
/// ≤ 2^-12 for |u| in [0.5, 1]); the round trip for `z ≥ 0` is measured over 2^24 directions in
/// the README (worst near the equator, where `z = sqrt(1 − x² − y²)` magnifies the xy error).
/// For `z < 0` the decoded normal is the mirror image: angular error `2·asin(|z|)`.
/// Bit-identical to `encode_normal_xy_fp16` on a correctly rounded, round-to-nearest-even adapter.
///
/// **Bad input:** see [`crate::normal`]: NaN, zero and all-subnormal vectors encode `+z` (0),
/// infinities win, any finite length is normalised.
pub fn encode_normal_xy_fp16(n: Vec3) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let u = s / dot(s, s).sqrt();
    pack2x16float(Vec2::new(u.x, u.y).clamp(Vec2::splat(-1.0), Vec2::splat(1.0)))
}

/// Decode to `(x, y, √z2) / √(s + z2)` with `(x, y) = unpack2x16float(p)`, `s = x² + y²`,
/// `z2 = max(0, 1 − s)`: Killzone 2's `z = +sqrt(max(0, 1 − x² − y²))`, normalised.
///
/// **Error bound:** for codes written by the encoder, `x² + y² ≤ 1` up to the halves' rounding
/// and the final normalise only corrects that rounding; see the README for measured errors.
///
/// **Bad input:** every bit pattern gives a finite unit vector: NaN halves count as 0, infinite
/// and out-of-range halves are clamped to `[−1, 1]`, and `x² + y² > 1` gives `z = 0` before
/// normalising.
pub fn decode_normal_xy_fp16(p: u32) -> Vec3 {
    decode_halves(unpack2x16float(p))
}

/// [`decode_normal_xy_fp16`] from the two unpacked halves (shared with `prepass::batch`, which
/// unpacks them its own way).
#[inline(always)]
pub(crate) fn decode_halves(h: Vec2) -> Vec3 {
    let h = Vec2::new(
        if h.x.is_nan() { 0.0 } else { h.x },
        if h.y.is_nan() { 0.0 } else { h.y },
    );
    let xy = h.clamp(Vec2::splat(-1.0), Vec2::splat(1.0));
    // |v|² as the WGSL writes it, s + max(0, 1 − s), not (√z2)²: see the WGSL's comment.
    let s = xy.x * xy.x + xy.y * xy.y;
    let z2 = (1.0 - s).max(0.0);
    Vec3::new(xy.x, xy.y, z2.sqrt()) / (s + z2).sqrt()
}

/// Render-target form of [`encode_normal_xy_fp16`]: the four rgba8unorm channels holding the
/// two halves' bytes (`byte/255`).
pub fn encode_normal_xy_fp16_unorm(n: Vec3) -> [f32; 4] {
    crate::depth24::unpack4x8unorm(encode_normal_xy_fp16(n))
}

/// Decode sampled rgba8unorm channels: bytes rounded back (`round(255·clamp(c, 0, 1))`, NaN →
/// 0), then [`decode_normal_xy_fp16`]. Exact whenever each channel is within ±0.49/255 of
/// `byte/255`: a 3-ULP channel error cannot flip a bit of a half.
pub fn decode_normal_xy_fp16_unorm(c: [f32; 4]) -> Vec3 {
    decode_normal_xy_fp16(super::xyz8::unorm_bytes(c))
}

/// The worst angular error of an xy FP16 round trip for `z ≥ 0`, in degrees, derived: the halves
/// are within `δ = 2^-12` of x, y (half an f16 ULP on [0.5, 1), less below), so `x'² + y'²` is
/// within `ε = 2δ(|x| + |y|) + 2δ² ≤ 2^-11·√2 + 2δ²` of `x² + y²` and the rebuilt `z` within `√ε`
/// of `z` (`|√a − √b| ≤ √|a − b|`). The decoded point is then within `d = √(2δ² + ε)` of the
/// unit input: angle ≤ `asin(d)` (1.506°). For `z < 0` the decode is the mirror image, error
/// `2·asin(|z|)`, moved by at most this bound. Measured round trips are checked against this plus
/// [`super::F32_SLACK_DEG`].
pub fn max_angle_upper_deg() -> f64 {
    let delta = 2f64.powi(-12);
    let eps = 2f64.powi(-11) * 2f64.sqrt() + 2.0 * delta * delta;
    (2.0 * delta * delta + eps).sqrt().asin().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figure the docs quote is the formula's.
    #[test]
    fn max_angle_upper_deg_is_the_documented_figure() {
        assert_eq!(format!("{:.3}", max_angle_upper_deg()), "1.506");
    }

    #[test]
    fn halves_round_trip_and_bad_halves_decode_to_unit_vectors() {
        assert_eq!(pack2x16float(Vec2::new(1.0, -0.5)), 0xb800_3c00);
        assert_eq!(unpack2x16float(0xb800_3c00), Vec2::new(1.0, -0.5));
        assert_eq!(encode_normal_xy_fp16(Vec3::new(f32::NAN, 0.0, 0.0)), 0);
        for p in [0x7c00_7c00u32, 0xfe00_0001, 0x3c00_3c00, 0xffff_ffff] {
            let v = decode_normal_xy_fp16(p);
            assert!(v.is_finite(), "{p:#x}: {v}");
            crate::assert_within_abs!(
                v.length(),
                1.0,
                < 1e-6_f32,
                "literal: 1e-6 ≈ 17u, a few f32 roundings of the normalise",
                "{p:#x}: {v}"
            );
        }
    }
}
