//! Batch twins of [`crate::roughness`]'s encoder and decoder, for one `max_power` per batch.
//! Names, the slice contract and the vectorisation: [`crate::batch`]. Each writes exactly what
//! its scalar twin returns for every input (`tests/batch.rs`).
//!
//! The range ([`crate::roughness::range`]) is classified once per batch. The power-of-two
//! decoder (a table lookup and an exponent add) is vectorised. The encoder keeps the scalar
//! twin's `f32::log2` candidate per element (a library call, the same bits as the scalar twin;
//! an inlined polynomial would need its own exactness proof), so it gains only the hoisted
//! classification; the general-range decoder likewise keeps `exp2` per element.

use super::{Level, check_lengths, check_level};
use crate::roughness::{self as r, CODE_MAX, EXP2_STEPS, Range};

mod kernels {
    use super::super::batch_fn;
    use super::{CODE_MAX, EXP2_STEPS, r};

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
    if r::range(max_power) == Range::Degenerate {
        dst.fill(0);
    } else {
        kernels::encode_any(max_power, src, dst);
    }
}

/// [`encode_log_roughness`] at exactly `level`, on the calling thread. **Panics** if
/// `src.len() != dst.len()` or this CPU lacks `level`.
#[track_caller]
pub fn encode_log_roughness_with(level: Level, max_power: f32, src: &[f32], dst: &mut [u32]) {
    check_lengths("roughness::encode_log_roughness", src.len(), dst.len());
    check_level("roughness::encode_log_roughness", level);
    if r::range(max_power) == Range::Degenerate {
        dst.fill(0);
    } else {
        kernels::encode_any_with(level, max_power, src, dst);
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
