//! 24-bit depth codes stored in RGBA8 texels — the Rust twins of `wgsl/depth24.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! Resistance 2 aliased an ARGB8 texture onto its D24 depth buffer and rebuilt the code as
//! `r·65536 + g·256 + b` (Mark Lee, "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009:
//! the slides "Recovering hyperbolic depth"). A sampler returns each channel as a float in
//! `[0, 1]` that is only *near* `byte/255` (WGSL allows `unpack4x8unorm` 3 ULP; older texture
//! units were worse), and the weights 65536 and 256 magnify that error into wrong codes. Rounding
//! each channel back to its byte first removes it: every function here is exact over all 2^24
//! codes, which `tests/depth24.rs` checks exhaustively on the adapter.
//!
//! Byte order follows Lee's slides: `r` (byte 0, the low byte of the packed `u32` that an RGBA8
//! target stores) holds the most significant byte of the code, `b` (byte 2) the least; byte 3
//! (alpha) is not part of the code.
//!
//! Every function is exact on every conforming adapter, and so identical to its WGSL twin: the
//! WGSL uses only integer operations, `round`, `clamp` and a multiply `255·c` whose
//! either-neighbour rounding moves it by at most 2^-16, far inside the 0.5 a wrong byte needs.
//! `tests/depth24.rs` checks it under the worst-case emulation (`prepass::conforming`) too:
//! 0 wrong codes of 2^24 from exact and ±3 ULP channels, and through the emulated
//! `unpack4x8unorm`; `hyperbolic_depth_from_depth24` stays correctly rounded under every policy,
//! while the division baseline `f32(d) / 16777215.0` loses its exact round trip.

use glam::Vec3;

/// The largest 24-bit depth code, `2^24 − 1` (the far plane in the standard convention).
pub const DEPTH24_MAX: u32 = 0x00ff_ffff;

/// Recover a 24-bit depth code from the three unorm channels of an RGBA8 texel (`r` most
/// significant), as a sampler returns them.
///
/// Computes `b_i = round(255 · clamp(c_i, 0, 1))` per channel (round half to even, as WGSL's
/// `round`), then `d = b_r·2^16 + b_g·2^8 + b_b`.
///
/// **Error bound:** exact (0 code mismatches) whenever every channel lies within ±0.49/255 of
/// `byte/255` — so for exact channels, for channels off by WGSL's 3-ULP `unpack4x8unorm`
/// allowance, and for ±0.45/255 texture-unit error, all tested over every code.
///
/// **Bad input:** each channel is clamped to `[0, 1]` before rounding, so `+Inf` and values above
/// 1 give byte 255, `−Inf` and values below 0 give byte 0, and NaN gives byte 0 (detected from
/// its bits, which WGSL's finite-math rules cannot optimise away). The result is always a valid
/// code in `[0, 2^24 − 1]`.
pub fn depth24_from_rgb8(rgb: Vec3) -> u32 {
    let byte = |c: f32| -> u32 {
        let c = if c.is_nan() { 0.0 } else { c };
        (c.clamp(0.0, 1.0) * 255.0).round_ties_even() as u32
    };
    (byte(rgb.x) << 16) | (byte(rgb.y) << 8) | byte(rgb.z)
}

/// Recover a 24-bit depth code from an RGBA8 texel read as one `u32` (an `rgba8uint` view or a
/// storage buffer): byte 0 is the most significant byte of the code, byte 2 the least, byte 3 is
/// ignored. Exact for every input bit pattern (pure bit operations).
pub fn depth24_from_packed(p: u32) -> u32 {
    ((p & 0xff) << 16) | (p & 0xff00) | ((p >> 16) & 0xff)
}

/// Pack a 24-bit depth code into the `u32` whose bytes an RGBA8 target stores: byte 0 (r) the
/// most significant byte, byte 2 (b) the least, byte 3 (alpha) zero. The inverse of
/// [`depth24_from_packed`], and `depth24_from_rgb8(unpack4x8unorm(pack_depth24(d)).xyz) == d`
/// for every code.
///
/// **Bad input:** codes above `2^24 − 1` saturate to `2^24 − 1` (the far plane), as a depth
/// buffer clamps.
pub fn pack_depth24(d: u32) -> u32 {
    let d = d.min(DEPTH24_MAX);
    ((d >> 16) & 0xff) | (d & 0xff00) | ((d & 0xff) << 16)
}

/// The hyperbolic (window-space) depth of a 24-bit code, `d / (2^24 − 1)`, correctly rounded
/// to `f32`.
///
/// **Why it can be exact:** `d/(2^24−1) = Σ_k d·2^(−24k)`, so the binary expansion of the
/// quotient is the code's 24 bits repeated forever. With `lz` leading zeros in the 24-bit code,
/// the f32 significand is the code rotated left by `lz`, and the bits below it (the same
/// rotation again, read as a fraction of an ULP: `m/(2^24−1)` with `m ≥ 2^23`) always exceed one
/// half — so the correctly rounded result is that significand plus one ULP. Built from integer
/// operations, the result is the correctly rounded quotient on every adapter, where
/// `f32(d) / 16777215.0` may be 2.5 ULP off (WGSL's division allowance) and
/// `f32(d) * (1.0 / 16777215.0)` rounds twice.
///
/// **Error bound:** ≤ 0.5 ULP (correctly rounded), measured over all 2^24 codes on the adapter.
/// Every code maps to a distinct `f32` and `round(x · (2^24 − 1))` returns the code for every
/// code: no code is ambiguous, because the spacing of codes, `1/(2^24 − 1)`, exceeds the f32 ULP
/// everywhere in `(0, 1]` (at most `2^-24`, in `[0.5, 1)`), so two codes never round to the same
/// float and half an ULP never reaches half a code.
///
/// **Bad input:** codes above `2^24 − 1` saturate to 1.0.
pub fn hyperbolic_depth_from_depth24(d: u32) -> f32 {
    let code = d.min(DEPTH24_MAX);
    if code == 0 {
        return 0.0;
    }
    if code == DEPTH24_MAX {
        return 1.0;
    }
    let lz = code.leading_zeros() - 8;
    let m = ((code << lz) | (code >> (24 - lz))) & DEPTH24_MAX;
    f32::from_bits(((126 - lz) << 23) + (m + 1 - 0x0080_0000))
}

/// The Rust twin of WGSL's `unpack4x8unorm` as a conforming adapter computes it exactly: byte 0
/// to `x`, each `byte / 255` correctly rounded. (WGSL itself only promises 3 ULP; see
/// [`depth24_from_rgb8`].)
pub fn unpack4x8unorm(p: u32) -> [f32; 4] {
    [0, 8, 16, 24].map(|shift| ((p >> shift) & 0xff) as f32 / 255.0)
}

/// Exact references for this module's functions: what each one *means*, computed with integers
/// or in `f64`, with no f32 shortcut.
pub mod exact {
    use super::DEPTH24_MAX;

    /// `d / (2^24 − 1)` in f64 (relative error ≤ 2^-53, i.e. ≤ 2^-29 of an f32 ULP).
    pub fn hyperbolic_depth(d: u32) -> f64 {
        f64::from(d.min(DEPTH24_MAX)) / f64::from(DEPTH24_MAX)
    }

    /// The code an `f32` depth `x ∈ [0, 1]` stands for: the integer nearest `x · (2^24 − 1)`,
    /// computed exactly in integers (`x` is `m·2^e` exactly). `None` for negative, NaN or > 1.
    pub fn nearest_code(x: f32) -> Option<u32> {
        if !(0.0..=1.0).contains(&x) {
            return None;
        }
        if x == 0.0 {
            return Some(0);
        }
        let bits = x.to_bits();
        let exp = ((bits >> 23) & 0xff) as i32;
        let (m, e) = if exp == 0 {
            (u128::from(bits & 0x7f_ffff), -149)
        } else {
            (u128::from((bits & 0x7f_ffff) | 0x80_0000), exp - 150)
        };
        // x·D = m·D·2^e with e < 0 here (x ≤ 1 < 2^24): round half up on the exact product.
        let shift = (-e) as u32;
        // x < 2^-40 (every subnormal among them) gives x·D < 2^-16: code 0. Returning early also
        // keeps the shift below 128 (a subnormal's shift of 149 overflowed u128).
        if shift >= 64 {
            return Some(0);
        }
        let prod = m * u128::from(DEPTH24_MAX);
        Some(((prod + (1u128 << (shift - 1))) >> shift) as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packing_inverts_for_sampled_codes() {
        for d in [0, 1, 0xff, 0x100, 0xabcdef, DEPTH24_MAX] {
            assert_eq!(depth24_from_packed(pack_depth24(d)), d);
            let [r, g, b, a] = unpack4x8unorm(pack_depth24(d));
            assert_eq!(a, 0.0);
            assert_eq!(depth24_from_rgb8(Vec3::new(r, g, b)), d);
        }
        assert_eq!(pack_depth24(0x0123_4567), pack_depth24(DEPTH24_MAX));
    }

    #[test]
    fn hyperbolic_depth_matches_known_values() {
        assert_eq!(hyperbolic_depth_from_depth24(0), 0.0);
        assert_eq!(hyperbolic_depth_from_depth24(DEPTH24_MAX), 1.0);
        assert_eq!(hyperbolic_depth_from_depth24(u32::MAX), 1.0);
        // 1/(2^24−1) = 2^-24 + 2^-48 + …: rounds up to 2^-24 + 2^-47.
        assert_eq!(
            hyperbolic_depth_from_depth24(1),
            2f32.powi(-24) + 2f32.powi(-47)
        );
        // Half way: (2^23)/(2^24−1) is just above 0.5, so 0.5 + one ULP (2^-24).
        assert_eq!(hyperbolic_depth_from_depth24(1 << 23), 0.5 + 2f32.powi(-24));
    }

    #[test]
    fn nearest_code_is_exact() {
        assert_eq!(exact::nearest_code(1.0), Some(DEPTH24_MAX));
        assert_eq!(exact::nearest_code(0.5), Some(1 << 23)); // 8388607.5 rounds half up
        assert_eq!(exact::nearest_code(-0.1), None);
        assert_eq!(exact::nearest_code(f32::NAN), None);
    }

    #[test]
    fn bad_channels_clamp() {
        let nan = f32::NAN;
        assert_eq!(depth24_from_rgb8(Vec3::new(nan, nan, nan)), 0);
        assert_eq!(depth24_from_rgb8(Vec3::splat(f32::INFINITY)), DEPTH24_MAX);
        assert_eq!(
            depth24_from_rgb8(Vec3::new(-1.0, 2.0, f32::NEG_INFINITY)),
            0x00ff00
        );
    }
}
