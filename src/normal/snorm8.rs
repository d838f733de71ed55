//! x, y, z as snorm8 in an RGBA8 texel — the Rust twin of `wgsl/normal_snorm8.wgsl`.
//!
//! Unity URP's default normal target is `R8G8B8A8_SNorm`
//! (`Packages/com.unity.render-pipelines.universal/Runtime/Passes/DepthNormalOnlyPass.cs`): the
//! shader writes the normal, the format's conversion stores `round(127·c)`. Byte `b` (two's
//! complement) stands for `max(b/127, −1)`, as the format defines: −128 and −127 both read −1.
//! An xyz8 (unorm) decoder reads these bytes wrongly; this module reads and writes them.

use super::{dot, normalize, sanitize};
use glam::Vec3;

/// Encode a normal as `x | y << 8 | z << 16`, each byte the two's complement of
/// `round(127·u)` (round half to even) of `u = n/|n|`; byte 3 is zero (for the material).
///
/// **Error bound:** each coordinate of the decoded direction `b/127` is within half a step
/// (0.5/127) of `u`; angular error ≤ [`max_angle_deg`] (`asin(√3/254)`, derived there).
/// Bit-identical to `encode_normal_snorm8` on a correctly rounded adapter. The encoder never
/// writes −128.
///
/// **Bad input:** see [`crate::normal`]: NaN, zero and all-subnormal vectors encode `+z`
/// (`0x007f_0000`), infinities win, any finite length is normalised.
pub fn encode_normal_snorm8(n: Vec3) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let u = s / dot(s, s).sqrt();
    let b = (u.clamp(Vec3::NEG_ONE, Vec3::ONE) * 127.0)
        .to_array()
        .map(|x| x.round_ties_even() as i32 as u32 & 0xff);
    b[0] | (b[1] << 8) | (b[2] << 16)
}

/// The three signed bytes of `p` (byte 3 ignored), x first, as stored (−128 kept).
pub(crate) fn bytes(p: u32) -> [i32; 3] {
    [p, p >> 8, p >> 16].map(|b| i32::from((b & 0xff) as u8 as i8))
}

/// The integer vector a code stands for: `max(b, −127)` per byte, `(0, 0, 1)` for the zero vector.
fn integer_direction(p: u32) -> [i32; 3] {
    let b = bytes(p).map(|b| b.max(-127));
    if b == [0, 0, 0] { [0, 0, 1] } else { b }
}

/// Decode bytes 0–2 (byte 3 ignored) as snorm8 to the unit vector `normalize(max(b, −127))`; the
/// zero vector, which no encoder writes, decodes as `+z`.
///
/// **Error bound:** the exact direction of the integer vector, off by the normalisation's rounding
/// only (≤ 2^-24·√2 rad on a correctly rounded adapter). Every bit pattern gives a finite unit
/// vector.
pub fn decode_normal_snorm8(p: u32) -> Vec3 {
    normalize(Vec3::from_array(integer_direction(p).map(|b| b as f32)))
}

/// Render-target form of [`encode_normal_snorm8`]: the rgba8snorm channels `b/127`, alpha 0.
pub fn encode_normal_snorm8_snorm(n: Vec3) -> [f32; 4] {
    let b = bytes(encode_normal_snorm8(n));
    [
        b[0] as f32 / 127.0,
        b[1] as f32 / 127.0,
        b[2] as f32 / 127.0,
        0.0,
    ]
}

/// Decode sampled rgba8snorm channels: each of x, y, z taken to `[−1, 1]` (NaN counts as 0,
/// magnitudes from 1 up to ∞ as ±1), rounded back to its byte (`round(127·c)`), then
/// [`decode_normal_snorm8`]; alpha ignored. Exact whenever each channel is within ±0.49/127 of
/// `b/127`.
pub fn decode_normal_snorm8_snorm(c: [f32; 4]) -> Vec3 {
    let b = [c[0], c[1], c[2]].map(|x| {
        let x = if x.is_nan() {
            0.0
        } else if x.abs() >= 1.0 {
            1f32.copysign(x)
        } else {
            x
        };
        (x * 127.0).round_ties_even() as i32 as u32 & 0xff
    });
    decode_normal_snorm8(b[0] | (b[1] << 8) | (b[2] << 16))
}

/// Exact references.
pub mod exact {
    /// The encoder in f64: the byte nearest `127·u` per coordinate of the unit vector `u` (half
    /// to even).
    pub fn encode(n: [f64; 3]) -> u32 {
        let u = super::super::exact::unit(n).unwrap_or([0.0, 0.0, 1.0]);
        u.iter().enumerate().fold(0, |acc, (k, &x)| {
            acc | ((((x * 127.0).round_ties_even() as i32 as u32) & 0xff) << (8 * k))
        })
    }

    /// The direction a code stands for, in f64 (`+z` for the zero vector).
    pub fn decode(p: u32) -> [f64; 3] {
        let d = super::integer_direction(p).map(f64::from);
        super::super::exact::unit(d).expect("never the zero vector")
    }

    /// The format's own reading, `max(b/127, −1)` per channel, normalised as URP's decode does
    /// (`None` for the zero vector, where the engine's normalise gives NaN): the interop
    /// reference.
    pub fn engine_decode(p: u32) -> Option<[f64; 3]> {
        let d = super::bytes(p).map(|b| (f64::from(b) / 127.0).max(-1.0));
        super::super::exact::unit(d)
    }
}

/// The worst angular error of a snorm8 round trip, in degrees, derived: each decoded coordinate
/// `b/127` is within half a step, 0.5/127, of the unit input's, so the decoded point is within
/// `√3/254` of the input and the angle is at most `asin(√3/254)` (0.3907°).
pub fn max_angle_deg() -> f64 {
    (3f64.sqrt() / 254.0).asin().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn max_angle_deg_is_the_documented_figure() {
        assert_eq!(format!("{:.4}", max_angle_deg()), "0.3907");
    }

    #[test]
    fn the_format_reads_minus_128_as_minus_127_and_zero_as_plus_z() {
        assert_eq!(encode_normal_snorm8(Vec3::Z), 0x007f_0000);
        assert_eq!(encode_normal_snorm8(Vec3::NEG_X), 0x0000_0081);
        assert_eq!(decode_normal_snorm8(0x80), decode_normal_snorm8(0x81));
        assert_eq!(decode_normal_snorm8(0x80), Vec3::NEG_X);
        assert_eq!(decode_normal_snorm8(0xab00_0000), Vec3::Z);
        for v in [Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 1.0)] {
            assert_eq!(encode_normal_snorm8(v), 0x007f_0000);
        }
        assert_eq!(
            encode_normal_snorm8(Vec3::new(1.0, f32::NEG_INFINITY, 3.0)),
            encode_normal_snorm8(Vec3::NEG_Y)
        );
    }
}
