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
    let values = out.into_f32();
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

/// What the worst-case search ([`crate::conforming::search::climb`]) finds for one function of
/// `wgsl/depth24.wgsl` on the emulated worst conforming adapter.
#[derive(Clone, Debug)]
pub struct Searched {
    /// The largest error found (as the caller of [`searched_recovery`] or
    /// [`searched_hyperbolic`] measures it).
    pub worst: f64,
    /// Inputs searched.
    pub inputs: usize,
    /// Fewest and most slots an input's evaluation reads.
    pub slots: (u32, u32),
    /// Whether every input got every assignment of the slots it reads.
    pub exhaustive: bool,
    /// Direction tables evaluated in all.
    pub evaluated: usize,
}

impl Searched {
    fn of(found: &[crate::conforming::search::Found], exhaustive_slots: u32) -> Searched {
        Searched {
            worst: found.iter().map(|f| f.error).fold(0.0, f64::max),
            inputs: found.len(),
            slots: (
                found.iter().map(|f| f.slots).min().unwrap_or(0),
                found.iter().map(|f| f.slots).max().unwrap_or(0),
            ),
            exhaustive: found.iter().all(|f| f.slots <= exhaustive_slots),
            evaluated: found.iter().map(|f| f.evaluated).sum(),
        }
    }
}

/// `function(rgb: vec3<f32>) -> u32` of `source` (`depth24_from_rgb8`, or a function that
/// works lane by lane as it does) searched for its worst conforming evaluation under channel
/// `error`: the error is the largest `|recovered byte − byte|` of a lane (0: the code comes
/// back).
///
/// Inputs: every byte `0 … 255` pushed each way by `error` (once where `error` is exact), in all
/// three lanes at once. The recovery works lane by lane (NaN test, clamp, `× 255`, `round`,
/// `u32`) and joins the bytes with exact integer shifts, so a lane's byte depends on its own
/// channel and the direction table alone: when every input is searched exhaustively (every
/// assignment of the slots it reads), these 512 inputs (256 where exact) cover every code of
/// 2^24 under every sign pattern and every conforming evaluation the emulation can express.
pub fn searched_recovery(
    gpu: &Gpu,
    source: &str,
    function: &str,
    error: ChannelError,
) -> Result<Searched, HarnessError> {
    use crate::conforming::search::{SearchConfig, climb};
    use crate::conforming::{EmulatedKernel, Emulation, Policy};
    use crate::precision::inputs::unorm8_channel;
    let pushes: &[bool] = if error == ChannelError::Exact {
        &[false]
    } else {
        &[false, true]
    };
    let lanes: Vec<(u32, [f32; 3])> = (0..=255u32)
        .flat_map(|b| {
            pushes
                .iter()
                .map(move |&down| (b, [unorm8_channel(b, error, down); 3]))
        })
        .collect();
    let rgb: Vec<[f32; 3]> = lanes.iter().map(|l| l.1).collect();
    let kernel = EmulatedKernel::new(gpu, source, function, &Emulation::new(Policy::Searched))?;
    let byte_error = |i: usize, out: &crate::harness::Output, e: usize| {
        let (b, code) = (lanes[i].0, out.words()[e]);
        [16, 8, 0]
            .iter()
            .map(|s| f64::from(((code >> s) & 0xff).abs_diff(b)))
            .fold(0.0, f64::max)
    };
    // Three lanes read up to 17 slots together (the default enumerates 16).
    let config = SearchConfig {
        exhaustive_slots: 18,
        ..SearchConfig::default()
    };
    let found = climb(
        &kernel,
        &[Arg::column(&rgb)],
        rgb.len(),
        &byte_error,
        &config,
    )?;
    Ok(Searched::of(&found, config.exhaustive_slots))
}

/// `function(d: u32) -> f32` of `source` (`hyperbolic_depth_from_depth24` or a baseline of its
/// signature) searched for its worst conforming evaluation at every `stride`-th code and the
/// last: the error is in ULPs of the exact `d / (2^24 − 1)`.
pub fn searched_hyperbolic(
    gpu: &Gpu,
    source: &str,
    function: &str,
    stride: usize,
) -> Result<Searched, HarnessError> {
    use crate::conforming::search::{SearchConfig, climb};
    use crate::conforming::{EmulatedKernel, Emulation, Policy};
    let codes: Vec<u32> = (0..=DEPTH24_MAX)
        .step_by(stride)
        .chain([DEPTH24_MAX])
        .collect();
    let kernel = EmulatedKernel::new(gpu, source, function, &Emulation::new(Policy::Searched))?;
    let ulps = |i: usize, out: &crate::harness::Output, e: usize| {
        ulp_error(out.as_f32()[e], exact::hyperbolic_depth(codes[i]))
    };
    let config = SearchConfig::default();
    let found = climb(&kernel, &[Arg::column(&codes)], codes.len(), &ulps, &config)?;
    Ok(Searched::of(&found, config.exhaustive_slots))
}
