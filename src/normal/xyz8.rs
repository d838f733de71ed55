//! x, y, z as unorm8 in bytes 0–2 of an RGBA8 texel — the Rust twin of `wgsl/normal_xyz8.wgsl`.
//!
//! Resistance 2 stored "viewspace normals as 3 8-bit components for simplicity" with the spec power
//! in alpha (Mark Lee, "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009). Byte `b` stands
//! for the coordinate `(2b − 255)/255`; the decoder normalises. Measured over 2^24
//! spherical-Fibonacci directions on the adapter (see the README): mean 0.170°, max 0.39° angular
//! error — the 24-bit octahedral code is about 9 times better in the same bits.

use glam::Vec3;

/// Encode a normal as `x | y << 8 | z << 16`, each byte `round(255·(u/2 + 1/2))` (round half to
/// even) of `u = n/|n|`; byte 3 is zero (for the material: spec power or roughness).
///
/// **Error bound:** each coordinate of the decoded direction is within half a byte step
/// (1/255) of `u`; angular error ≤ [`max_angle_deg`] (`asin(√3/255)`, derived there).
/// Bit-identical to `encode_normal_xyz8` on a correctly rounded adapter.
///
/// **Bad input:** see [`crate::normal`]: NaN, zero and all-subnormal vectors encode `+z`
/// (`0x00ff8080`), infinities win, any finite length is normalised.
pub fn encode_normal_xyz8(n: Vec3) -> u32 {
    super::encode_unorm_xyz(n, 255.0, 8)
}

/// Decode bytes 0–2 (byte 3 ignored) to the unit vector `normalize(2b − 255)`.
///
/// **Error bound:** the exact direction of the odd-integer vector `2b − 255`, off by the
/// normalisation's rounding only (≤ 2^-24·√2 rad on a correctly rounded adapter; WGSL's
/// `inverseSqrt` allowance only scales the length, by ≤ 2 ULP). Every bit pattern gives a finite
/// unit vector (the integer vector is never zero).
pub fn decode_normal_xyz8(p: u32) -> Vec3 {
    super::decode_unorm_xyz(p, 255, 8)
}

/// Render-target form of [`encode_normal_xyz8`]: the rgba8unorm channels (`byte/255`, alpha 0).
pub fn encode_normal_xyz8_unorm(n: Vec3) -> [f32; 4] {
    crate::depth24::unpack4x8unorm(encode_normal_xyz8(n))
}

/// Decode sampled rgba8unorm channels: each channel clamped to `[0, 1]` (NaN counts as 0),
/// rounded back to its byte (`round(255·c)`), then [`decode_normal_xyz8`]. Exact whenever each
/// channel is within ±0.49/255 of `byte/255` (so under `unpack4x8unorm`'s 3-ULP allowance).
pub fn decode_normal_xyz8_unorm(c: [f32; 4]) -> Vec3 {
    decode_normal_xyz8(unorm_bytes(c))
}

/// `round(255·clamp(c, 0, 1))` per channel (NaN → 0), packed byte 0 = `c[0]`.
pub(crate) fn unorm_bytes(c: [f32; 4]) -> u32 {
    c.iter().enumerate().fold(0, |acc, (k, &x)| {
        let x = if x.is_nan() { 0.0 } else { x };
        acc | (((x.clamp(0.0, 1.0) * 255.0).round_ties_even() as u32) << (8 * k))
    })
}

/// Exact references.
pub mod exact {
    /// The encoder in f64: the byte nearest `255·(u/2 + 1/2)` per coordinate of the unit
    /// vector `u` (ties cannot occur for the irrational-looking test directions; half to even).
    pub fn encode(n: [f64; 3]) -> u32 {
        super::super::exact::encode_unorm_xyz(n, 255.0, 8)
    }

    /// The direction a code stands for, in f64.
    pub fn decode(p: u32) -> [f64; 3] {
        super::super::exact::decode_unorm_xyz(p, 255, 8)
    }
}

/// The worst angular error of an xyz8 round trip, in degrees, derived: each decoded coordinate
/// `(2b − 255)/255` is within half a step, 1/255, of the unit input's, so the decoded point is
/// within `√3/255` of the input and the angle is at most `asin(√3/255)` (0.3892°). Measured round
/// trips are checked against this plus [`super::F32_SLACK_DEG`].
pub fn max_angle_deg() -> f64 {
    (3f64.sqrt() / 255.0).asin().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figure the docs quote is the formula's.
    #[test]
    fn max_angle_deg_is_the_documented_figure() {
        assert_eq!(format!("{:.4}", max_angle_deg()), "0.3892");
    }

    #[test]
    fn degenerate_inputs_encode_plus_z_and_byte_3_is_free() {
        let z = encode_normal_xyz8(Vec3::Z);
        assert_eq!(z, 0x00ff_8080);
        for v in [
            Vec3::ZERO,
            Vec3::new(0.0, f32::NAN, 1.0),
            Vec3::splat(-1e-42),
        ] {
            assert_eq!(encode_normal_xyz8(v), z);
        }
        assert_eq!(
            encode_normal_xyz8(Vec3::new(1.0, f32::NEG_INFINITY, 3.0)),
            encode_normal_xyz8(Vec3::NEG_Y)
        );
        assert_eq!(decode_normal_xyz8(0xab00_0000 | z), decode_normal_xyz8(z));
        crate::assert_within_abs!(
            decode_normal_xyz8(z).length(),
            1.0,
            < 1e-6_f32,
            "literal: 1e-6 ≈ 17u, a few f32 roundings of the normalise",
            "code {z:#x}"
        );
    }
}
