//! Exhaustive sweeps over all 2^24 depth codes for the functions of `wgsl/depth24.wgsl`.

use crate::depth24::{DEPTH24_MAX, exact};
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::inputs::{ChannelError, all_codes_rgb8};
use crate::precision::metrics::{ErrorStats, Mismatches, ulp_error};

/// Number of 24-bit codes.
pub const CODES: u64 = 1 << 24;

/// The channel-error cases every recovery function faces: exact channels, then each
/// perturbation with both sign patterns (so each channel of each code is pushed both ways).
pub const RECOVERY_CASES: [(ChannelError, bool); 5] = [
    (ChannelError::Exact, false),
    (ChannelError::Ulps(3), false),
    (ChannelError::Ulps(3), true),
    (ChannelError::Offset(0.45), false),
    (ChannelError::Offset(0.45), true),
];

/// Result of recovering every code from perturbed channels with one WGSL function.
#[derive(Clone, Debug)]
pub struct Recovery {
    /// Codes that did not come back exactly.
    pub mismatches: Mismatches<u32>,
    /// The codes the adapter returned, in code order.
    pub codes: Vec<u32>,
}

/// Run `function(rgb: vec3<f32>) -> u32` from `source` on the channels of every code perturbed
/// by `error` (sign pattern complemented when `flip`), and count the codes not recovered.
pub fn recover_all(
    gpu: &Gpu,
    source: &str,
    function: &str,
    error: ChannelError,
    flip: bool,
) -> Result<Recovery, HarnessError> {
    let rgb = all_codes_rgb8(error, flip);
    let out = gpu
        .kernel(source, function)?
        .run(&[Arg::column(&rgb)], CODES)?;
    let codes = out.into_words();
    let mismatches = Mismatches::count(&codes, |i| i as u32);
    Ok(Recovery { mismatches, codes })
}

/// Accuracy of an `f32` hyperbolic depth for every code.
#[derive(Clone, Debug)]
pub struct Hyperbolic {
    /// Error in f32 ULPs against the exact `d / (2^24 − 1)`.
    pub ulps: ErrorStats,
    /// Codes whose float does not map back to the code under exact arithmetic
    /// (nearest integer to `x · (2^24 − 1)`).
    pub exact_roundtrip_failures: u64,
    /// Codes whose float does not map back under the f32 shader inverse
    /// `u32(round(x * 16777215.0))`.
    pub f32_roundtrip_failures: u64,
    /// Neighbouring codes whose floats are not strictly increasing (codes that share a float).
    pub collisions: u64,
    /// The floats, in code order.
    pub values: Vec<f32>,
}

/// Measure `function(d: u32) -> f32` from `source` over every 24-bit code.
pub fn hyperbolic_all(gpu: &Gpu, source: &str, function: &str) -> Result<Hyperbolic, HarnessError> {
    let out = gpu
        .kernel(source, function)?
        .run(&[Arg::Index { start: 0 }], CODES)?;
    let values = out.as_f32().to_vec();
    Ok(measure_hyperbolic(values))
}

/// The statistics of [`Hyperbolic`] for floats computed anywhere (the Rust twin, say).
pub fn measure_hyperbolic(values: Vec<f32>) -> Hyperbolic {
    let mut ulps = ErrorStats::default();
    let (mut exact_fail, mut f32_fail, mut collisions) = (0, 0, 0);
    for (d, &x) in values.iter().enumerate() {
        let d = d as u32;
        ulps.add(u64::from(d), ulp_error(x, exact::hyperbolic_depth(d)));
        if exact::nearest_code(x) != Some(d) {
            exact_fail += 1;
        }
        let back = (x * DEPTH24_MAX as f32).round_ties_even();
        if back != d as f32 {
            f32_fail += 1;
        }
        if d > 0 && values[d as usize - 1].partial_cmp(&x) != Some(std::cmp::Ordering::Less) {
            collisions += 1;
        }
    }
    Hyperbolic {
        ulps,
        exact_roundtrip_failures: exact_fail,
        f32_roundtrip_failures: f32_fail,
        collisions,
        values,
    }
}
