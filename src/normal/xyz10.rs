//! x, y, z as unorm10 in an RGB10A2 texel — the Rust twin of `wgsl/normal_xyz10.wgsl`.
//!
//! What Unreal 5's GBufferA (`Engine/Shaders/Private/DeferredShadingCommon.ush`, `EncodeNormal`,
//! `n·0.5 + 0.5`) and Bevy's normal prepass (`crates/bevy_pbr/src/prepass/prepass.wgsl`, an
//! `Rgb10a2Unorm` target) store. Code `k` stands for the coordinate `(2k − 1023)/1023`; the
//! decoder normalises. The layout is the texel's: x in bits 0–9, y in 10–19, z in 20–29, the
//! 2-bit alpha (bits 30–31) left zero for the renderer.

use glam::Vec3;

/// Encode a normal as `x | y << 10 | z << 20`, each field `round(1023·(u/2 + 1/2))` (round half
/// to even) of `u = n/|n|`; bits 30–31 are zero (the renderer's 2-bit alpha).
///
/// **Error bound:** each coordinate of the decoded direction is within half a step (1/1023) of
/// `u`; angular error ≤ [`max_angle_deg`] (`asin(√3/1023)`, derived there). Bit-identical to
/// `encode_normal_xyz10` on a correctly rounded adapter.
///
/// **Bad input:** see [`crate::normal`]: NaN, zero and all-subnormal vectors encode `+z`
/// (`0x3ff8_0200`: fields 512, 512, 1023), infinities win, any finite length is normalised.
pub fn encode_normal_xyz10(n: Vec3) -> u32 {
    super::encode_unorm_xyz(n, 1023.0, 10)
}

/// The three 10-bit fields of `p` (bits 30–31 ignored), x first.
pub(crate) fn fields(p: u32) -> [u32; 3] {
    [p, p >> 10, p >> 20].map(|k| k & 0x3ff)
}

/// Decode bits 0–29 (bits 30–31 ignored) to the unit vector `normalize(2k − 1023)`.
///
/// **Error bound:** the exact direction of the odd-integer vector `2k − 1023`, off by the
/// normalisation's rounding only (≤ 2^-24·√2 rad on a correctly rounded adapter). Every bit
/// pattern gives a finite unit vector (the integer vector is never zero). The engines' own
/// decode, `normalize(c·2 − 1)` of the sampled `c = k/1023`, is the same direction up to f32
/// rounding.
pub fn decode_normal_xyz10(p: u32) -> Vec3 {
    super::decode_unorm_xyz(p, 1023, 10)
}

/// Render-target form of [`encode_normal_xyz10`]: the rgb10a2unorm channels `k/1023`, alpha 0.
pub fn encode_normal_xyz10_unorm(n: Vec3) -> [f32; 4] {
    let k = fields(encode_normal_xyz10(n));
    [unorm10(k[0]), unorm10(k[1]), unorm10(k[2]), 0.0]
}

/// The rgb10a2unorm channel `k/1023` a render target stores as `k` (correctly rounded, as the
/// WGSL's `f32(k) / 1023.0` on lavapipe; within 2.5 ULP on any conforming adapter, far inside
/// the ±0.5/1023 a write may be off).
pub(crate) fn unorm10(k: u32) -> f32 {
    k as f32 / 1023.0
}

/// The 10-bit code of a sampled rgb10a2unorm channel: `c` taken to `[0, 1]` from its bits (NaN,
/// negative values and `−0` count as 0, values from 1 up to `+∞` as 1), then `round(1023·c)`,
/// half to even. Exact whenever `c` is within ±0.49/1023 of `k/1023`.
pub(crate) fn unorm10_code(c: f32) -> u32 {
    let b = c.to_bits();
    let x = if b > 0x7f80_0000 {
        0.0
    } else if b >= 0x3f80_0000 {
        1.0
    } else {
        c
    };
    (x * 1023.0).round_ties_even() as u32
}

/// Decode sampled rgb10a2unorm channels: each of x, y, z taken to `[0, 1]` (NaN, negative values
/// and `−0` count as 0, values from 1 up to `+∞` as 1), rounded back to its code
/// (`round(1023·c)`), then [`decode_normal_xyz10`]; alpha ignored. Exact whenever each channel is
/// within ±0.49/1023 of `k/1023`.
pub fn decode_normal_xyz10_unorm(c: [f32; 4]) -> Vec3 {
    let k = [c[0], c[1], c[2]].map(unorm10_code);
    decode_normal_xyz10(k[0] | (k[1] << 10) | (k[2] << 20))
}

/// Exact references.
pub mod exact {
    /// The encoder in f64: the code nearest `1023·(u/2 + 1/2)` per coordinate of the unit vector
    /// `u` (half to even).
    pub fn encode(n: [f64; 3]) -> u32 {
        super::super::exact::encode_unorm_xyz(n, 1023.0, 10)
    }

    /// The direction a code stands for, in f64.
    pub fn decode(p: u32) -> [f64; 3] {
        super::super::exact::decode_unorm_xyz(p, 1023, 10)
    }

    /// The engines' decoder in f64: `normalize(c·2 − 1)` with `c = k/1023` as the texture unit
    /// returns it (Unreal's `DecodeNormal`, Bevy's prepass read): the same direction as
    /// [`decode`], computed another way, for the interop checks.
    pub fn engine_decode(p: u32) -> [f64; 3] {
        let d = super::fields(p).map(|k| f64::from(k) / 1023.0 * 2.0 - 1.0);
        super::super::exact::unit(d).expect("(2k − 1023)/1023 is never 0")
    }
}

/// The worst angular error of an xyz10 round trip, in degrees, derived as for xyz8: each decoded
/// coordinate `(2k − 1023)/1023` is within half a step, 1/1023, of the unit input's, so the
/// decoded point is within `√3/1023` of the input and the angle is at most `asin(√3/1023)`
/// (0.0970°).
pub fn max_angle_deg() -> f64 {
    (3f64.sqrt() / 1023.0).asin().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn max_angle_deg_is_the_documented_figure() {
        assert_eq!(format!("{:.4}", max_angle_deg()), "0.0970");
    }

    #[test]
    fn degenerate_inputs_encode_plus_z_and_the_alpha_bits_are_free() {
        let z = encode_normal_xyz10(Vec3::Z);
        assert_eq!(fields(z), [512, 512, 1023]);
        for v in [
            Vec3::ZERO,
            Vec3::new(0.0, f32::NAN, 1.0),
            Vec3::splat(-1e-42),
        ] {
            assert_eq!(encode_normal_xyz10(v), z);
        }
        assert_eq!(
            encode_normal_xyz10(Vec3::new(1.0, f32::NEG_INFINITY, 3.0)),
            encode_normal_xyz10(Vec3::NEG_Y)
        );
        assert_eq!(decode_normal_xyz10(0xc000_0000 | z), decode_normal_xyz10(z));
    }
}
