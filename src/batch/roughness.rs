//! Batch twins of [`crate::roughness`]'s encoder and decoder, for one `max_power` per batch.
//! Names, the slice contract and the vectorisation: [`crate::batch`]. Each writes exactly what
//! its scalar twin returns for every input (`tests/batch.rs`).
//!
//! The range ([`crate::roughness::range`]) is classified once per batch. For power-of-two
//! ranges both directions are vectorised:
//! - decode: the scalar twin's table lookup and exponent add;
//! - encode: a different evaluation of the same exact function. The scalar twin's code is
//!   exact (see [`crate::roughness`], "Exact for power-of-two ranges"): the number of code
//!   boundaries `T_j` (`j = 0..=254`) at or below the power, each test decided on bit
//!   patterns. Here a candidate `c` comes from a degree-4 polynomial for `log2` of the
//!   significand (Chebyshev interpolation of `log2(1 + x)` on `[0, 1]`, error ≤ 1.2e-4, so
//!   `t = 255·log2(p)/L` is off by ≤ `255·1.2e-4 + ε` < 0.04 codes at `L = 1` and less for
//!   larger `L`), so `c` is within one of the code; one comparison with each neighbouring
//!   boundary (a table of the `T_j` bit patterns built once per batch) then gives the code
//!   exactly. No `f32::log2` call and no branch; LLVM still keeps this loop scalar (it judges
//!   gathers for the two table reads not worth it), so the gain over the scalar twin is the
//!   library call saved (`benches/batch.rs`, group `batch_others`). `tests/batch.rs` checks it
//!   against the scalar twin over every `f32` in `[1, 2]` at `L = 1`, every 3rd `f32` in
//!   `[1, 8192]` at `L = 13`, every 61st in `[1, 2^127]` at `L = 127`, and a stratified sample
//!   of all bit patterns at every tested range.
//!
//! General (not power-of-two) ranges keep the scalar twins' `log2`/`exp2` per element (library
//! calls, not vectorised), with the classification and `log2(max_power)` hoisted.

use super::{Level, check_lengths, check_level};
use crate::roughness::{self as r, CODE_MAX, EXP2_STEPS, Range};

mod kernels {
    use super::super::{batch_fn, normal::floor_small};
    use super::{CODE_MAX, EXP2_STEPS, r};

    /// `log2(1 + x)` for `x ∈ [0, 1)`, within 1.2e-4: the degree-4 polynomial interpolating it
    /// at the Chebyshev nodes (Horner, plain multiplies and adds).
    #[inline(always)]
    fn log2_1p(x: f32) -> f32 {
        let c = [
            0.000_114_579_96,
            1.436_874_9,
            -0.670_882_7,
            0.312_269_48,
            -0.078_440_68,
        ];
        (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0]
    }

    /// `T[0] = 0`, `T[j + 1]` = bits of boundary `j` (`j = 0..=254`), `T[256] = u32::MAX`: so
    /// for a code `c`, `T[c]` is the boundary below it and `T[c + 1]` the one above.
    pub(super) fn boundaries(l: u32) -> [u32; 257] {
        let mut t = [u32::MAX; 257];
        t[0] = 0;
        for (j, b) in t[1..256].iter_mut().enumerate() {
            *b = r::boundary_bits(j as u32, l);
        }
        t
    }

    /// The exact code for `max_power = 2^l` (module docs): candidate, then one boundary test
    /// each way; bad powers (NaN, negative, `≤ 1`, subnormal) give 0 as in the scalar twin.
    #[inline(always)]
    fn encode_pow2_lane(p: f32, scale: f32, t: &[u32; 257]) -> u32 {
        let b = p.to_bits();
        let bad = ((b & 0x7fff_ffff) > 0x7f80_0000) | ((b >> 31) != 0) | (b <= 0x3f80_0000);
        // log2(p) ≈ e + log2(1 + f); valid lanes have e ∈ [0, 128] (128: +Inf).
        let e = ((b >> 23) as i32).wrapping_sub(127) as f32;
        let f = f32::from_bits((b & 0x007f_ffff) | 0x3f80_0000) - 1.0;
        let tc = (e + log2_1p(f)) * scale;
        let c = floor_small((tc + 0.5).clamp(0.0, 255.0)) & 0xff;
        let (lo, hi) = (t[c as usize], t[c as usize + 1]);
        let k = if b < lo {
            c.wrapping_sub(1)
        } else if b >= hi {
            c.wrapping_add(1)
        } else {
            c
        };
        if bad { 0 } else { k }
    }

    batch_fn!(
        /// `max_power = 2^l`: the exact vectorised encoder.
        encode_pow2, encode_pow2_with, "roughness::encode_log_roughness",
        (l: u32, t: &[u32; 257]), f32 => u32,
        scalar: |p| r::encode_log_roughness(p, f32::from_bits((127 + l) << 23)),
        lane: {
            let scale = 255.0 / l as f32;
            move |p| encode_pow2_lane(p, scale, t)
        },
    );

    batch_fn!(
        /// Any range, the scalar twin per element.
        encode_any, encode_any_with, "roughness::encode_log_roughness",
        (max_power: f32), f32 => u32,
        scalar: |p| r::encode_log_roughness(p, max_power),
        lane: |p| r::encode_log_roughness(p, max_power),
    );
    batch_fn!(
        /// `max_power = 2^l`: the table decode.
        decode_pow2, decode_pow2_with, "roughness::decode_log_roughness",
        (l: u32), u32 => f32,
        // 2^l, the range's own `max_power` (the twin gives it for any input that classifies
        // as `PowerOfTwo(l)`, `+Inf` and values above 2^127 included).
        scalar: |k| r::decode_log_roughness(k, f32::from_bits((127 + l) << 23)),
        lane: |code: u32| {
            // k·l ≤ 255·127: no overflow.
            let n = code.min(CODE_MAX).wrapping_mul(l);
            f32::from_bits(EXP2_STEPS[(n % 255) as usize].wrapping_add((n / 255) << 23))
        },
    );
    batch_fn!(
        /// A general range: `exp2` per element, `log2(max_power)` hoisted.
        decode_general, decode_general_with, "roughness::decode_log_roughness",
        (max_power: f32, log2_max: f32), u32 => f32,
        scalar: |k| r::decode_log_roughness(k, max_power),
        lane: |code: u32| {
            let k = code.min(CODE_MAX);
            if k == CODE_MAX { max_power } else { (k as f32 * log2_max / 255.0).exp2() }
        },
    );
}

/// Batch [`r::encode_log_roughness`]: `dst[i] = encode_log_roughness(src[i], max_power)`.
///
/// Runs at [`Level::detected`] (split across rayon's pool for long batches with the `rayon`
/// feature). **Panics** if `src.len() != dst.len()`.
#[track_caller]
pub fn encode_log_roughness(max_power: f32, src: &[f32], dst: &mut [u32]) {
    check_lengths("roughness::encode_log_roughness", src.len(), dst.len());
    match r::range(max_power) {
        Range::Degenerate => dst.fill(0),
        Range::PowerOfTwo(l) => kernels::encode_pow2(l, &kernels::boundaries(l), src, dst),
        Range::General(_) => kernels::encode_any(max_power, src, dst),
    }
}

/// [`encode_log_roughness`] at exactly `level`, on the calling thread. **Panics** if
/// `src.len() != dst.len()` or this CPU lacks `level`.
#[track_caller]
pub fn encode_log_roughness_with(level: Level, max_power: f32, src: &[f32], dst: &mut [u32]) {
    check_lengths("roughness::encode_log_roughness", src.len(), dst.len());
    check_level("roughness::encode_log_roughness", level);
    match r::range(max_power) {
        Range::Degenerate => dst.fill(0),
        Range::PowerOfTwo(l) => {
            kernels::encode_pow2_with(level, l, &kernels::boundaries(l), src, dst)
        }
        Range::General(_) => kernels::encode_any_with(level, max_power, src, dst),
    }
}

/// Batch [`r::decode_log_roughness`]: `dst[i] = decode_log_roughness(src[i], max_power)`.
///
/// Runs at [`Level::detected`] (split across rayon's pool for long batches with the `rayon`
/// feature). **Panics** if `src.len() != dst.len()`.
#[track_caller]
pub fn decode_log_roughness(max_power: f32, src: &[u32], dst: &mut [f32]) {
    check_lengths("roughness::decode_log_roughness", src.len(), dst.len());
    match r::range(max_power) {
        Range::Degenerate => dst.fill(1.0),
        Range::PowerOfTwo(l) => kernels::decode_pow2(l, src, dst),
        Range::General(m) => kernels::decode_general(m, m.log2(), src, dst),
    }
}

/// [`decode_log_roughness`] at exactly `level`, on the calling thread. **Panics** if
/// `src.len() != dst.len()` or this CPU lacks `level`.
#[track_caller]
pub fn decode_log_roughness_with(level: Level, max_power: f32, src: &[u32], dst: &mut [f32]) {
    check_lengths("roughness::decode_log_roughness", src.len(), dst.len());
    check_level("roughness::decode_log_roughness", level);
    match r::range(max_power) {
        Range::Degenerate => dst.fill(1.0),
        Range::PowerOfTwo(l) => kernels::decode_pow2_with(level, l, src, dst),
        Range::General(m) => kernels::decode_general_with(level, m, m.log2(), src, dst),
    }
}
