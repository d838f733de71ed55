//! Batch twins of [`crate::depth24`]: packing, the two recoveries, hyperbolic depth and
//! `unpack4x8unorm`. Names, the slice contract and the vectorisation: [`crate::batch`]. Each
//! writes exactly what its scalar twin returns for every input (`tests/batch.rs`: all 2^24
//! codes and beyond, every level this CPU has).

use super::batch_fn;
use super::normal::{unorm_byte_lane, unpack4x8unorm_lane};
use crate::depth24::{self as d24, DEPTH24_MAX};
use glam::Vec3;

#[inline(always)]
fn pack_lane(d: u32) -> u32 {
    let d = d.min(DEPTH24_MAX);
    ((d >> 16) & 0xff) | (d & 0xff00) | ((d & 0xff) << 16)
}

#[inline(always)]
fn from_packed_lane(p: u32) -> u32 {
    ((p & 0xff) << 16) | (p & 0xff00) | ((p >> 16) & 0xff)
}

#[inline(always)]
fn from_rgb8_lane(rgb: Vec3) -> u32 {
    (unorm_byte_lane(rgb.x) << 16) | (unorm_byte_lane(rgb.y) << 8) | unorm_byte_lane(rgb.z)
}

/// [`d24::hyperbolic_depth_from_depth24`] without `leading_zeros` or variable shifts: for a
/// code `0 < d < 2^24 − 1` the twin returns `2^-24·d` plus one ULP (its significand is `d`
/// shifted left by its leading zeros, the exponent `126 − lz`), and `d as f32` is exact with
/// that significand and exponent `150 − lz − 127`; so the twin's bits are `bits(d as f32) −
/// 24·2^23 + 1`. Ends as the twin: code 0 → 0, codes `≥ 2^24 − 1` → 1.
#[inline(always)]
fn hyperbolic_lane(d: u32) -> f32 {
    let code = d.min(DEPTH24_MAX);
    let mid = (code as i32 as f32)
        .to_bits()
        .wrapping_sub(24 << 23)
        .wrapping_add(1);
    let bits = if code == 0 {
        0
    } else if code == DEPTH24_MAX {
        0x3f80_0000
    } else {
        mid
    };
    f32::from_bits(bits)
}

batch_fn!(
    /// Batch [`d24::pack_depth24`].
    pack_depth24, pack_depth24_with, "depth24::pack_depth24",
    (), u32 => u32,
    scalar: d24::pack_depth24,
    lane: pack_lane,
);
batch_fn!(
    /// Batch [`d24::depth24_from_packed`].
    depth24_from_packed, depth24_from_packed_with, "depth24::depth24_from_packed",
    (), u32 => u32,
    scalar: d24::depth24_from_packed,
    lane: from_packed_lane,
);
batch_fn!(
    /// Batch [`d24::depth24_from_rgb8`].
    depth24_from_rgb8, depth24_from_rgb8_with, "depth24::depth24_from_rgb8",
    (), Vec3 => u32,
    scalar: d24::depth24_from_rgb8,
    lane: from_rgb8_lane,
);
batch_fn!(
    /// Batch [`d24::hyperbolic_depth_from_depth24`].
    hyperbolic_depth_from_depth24, hyperbolic_depth_from_depth24_with,
    "depth24::hyperbolic_depth_from_depth24",
    (), u32 => f32,
    scalar: d24::hyperbolic_depth_from_depth24,
    lane: hyperbolic_lane,
);
batch_fn!(
    /// Batch [`d24::unpack4x8unorm`].
    unpack4x8unorm, unpack4x8unorm_with, "depth24::unpack4x8unorm",
    (), u32 => [f32; 4],
    scalar: d24::unpack4x8unorm,
    lane: unpack4x8unorm_lane,
);
