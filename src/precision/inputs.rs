//! Adversarial inputs for the crate's sweeps, reusable by downstream suites.

use super::metrics::step_ulps;
use crate::depth24::DEPTH24_MAX;

/// How far a sampled unorm8 channel sits from the exact `byte/255`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ChannelError {
    /// The correctly rounded `byte/255`, as a conforming conversion returns it.
    Exact,
    /// `byte/255` moved by this many `f32` ULPs (WGSL allows `unpack4x8unorm` 3).
    Ulps(u32),
    /// `(byte ± offset)/255` rounded to `f32`: an imprecise texture unit's conversion
    /// (Resistance 2's problem); `offset` is in units of one byte step.
    Offset(f64),
}

impl std::fmt::Display for ChannelError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Exact => f.write_str("exact"),
            Self::Ulps(u) => write!(f, "±{u} ULP"),
            Self::Offset(o) => write!(f, "±{o}/255"),
        }
    }
}

/// The sign pattern (bit k set = channel k pushed down) used for `code`: a mixing hash, so all
/// eight combinations occur across codes and neighbouring codes differ; `flip` complements it so
/// two sweeps push every channel of every code both ways.
pub fn sign_pattern(code: u32, flip: bool) -> u32 {
    let mut h = code.wrapping_mul(0x9e37_79b9);
    h ^= h >> 16;
    h = h.wrapping_mul(0x85eb_ca6b);
    h ^= h >> 13;
    (h ^ if flip { 7 } else { 0 }) & 7
}

/// One unorm8 channel holding `byte`, as a sampler might return it under `error`, pushed down
/// when `down`.
///
/// **Bad input:** bytes above 255 are used as given (`256/255 > 1`: out-of-range test inputs);
/// a push below `byte = 0` gives negative values (`Ulps(3)` down from `+0.0` is `−3·2^-149`);
/// a NaN offset gives NaN.
pub fn unorm8_channel(byte: u32, error: ChannelError, down: bool) -> f32 {
    let exact = byte as f32 / 255.0; // correctly rounded quotient
    match error {
        ChannelError::Exact => exact,
        ChannelError::Ulps(u) => step_ulps(exact, if down { -i64::from(u) } else { i64::from(u) }),
        ChannelError::Offset(o) => {
            let o = if down { -o } else { o };
            ((f64::from(byte) + o) / 255.0) as f32
        }
    }
}

/// The r, g, b channels of an RGBA8 texel holding the 24-bit `code` (r most significant), each
/// perturbed by `error` in the direction given by [`sign_pattern`]. Codes above `2^24 − 1`
/// saturate to `2^24 − 1` (the sign pattern still comes from the code as given).
pub fn rgb8_channels(code: u32, error: ChannelError, flip: bool) -> [f32; 3] {
    let signs = sign_pattern(code, flip);
    let code = code.min(DEPTH24_MAX);
    [16, 8, 0]
        .iter()
        .enumerate()
        .map(|(k, shift)| unorm8_channel((code >> shift) & 0xff, error, signs >> k & 1 == 1))
        .collect::<Vec<_>>()
        .try_into()
        .expect("three channels")
}

/// [`rgb8_channels`] for every 24-bit code, in code order (2^24 texels, 192 MiB).
pub fn all_codes_rgb8(error: ChannelError, flip: bool) -> Vec<[f32; 3]> {
    (0..=DEPTH24_MAX)
        .map(|d| rgb8_channels(d, error, flip))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_sign_combination_occurs_and_flip_complements() {
        let mut seen = [false; 8];
        for d in 0..64 {
            seen[sign_pattern(d, false) as usize] = true;
            assert_eq!(sign_pattern(d, false) ^ sign_pattern(d, true), 7);
        }
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn perturbations_have_the_stated_size() {
        let c = unorm8_channel(128, ChannelError::Ulps(3), false);
        assert_eq!(
            super::super::metrics::ulp_distance(c, 128.0 / 255.0),
            Some(3)
        );
        let o = unorm8_channel(128, ChannelError::Offset(0.45), true);
        crate::assert_within_abs!(
            f64::from(o) * 255.0,
            127.55,
            < 1e-4,
            "literal: the f32 channel's rounding is 2^-24·0.5·255 ≈ 8e-6 codes",
            "128 − 0.45 in codes"
        );
    }
}
