//! Sweeps for `wgsl/roughness.wgsl`: every `f32` power in `[1, max_power]` through an 8-bit
//! encode/decode pair on the adapter, measured in f64, and every code's decoded value.

use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{ErrorStats, relative_error, ulp_error};
use crate::roughness::{self, exact};

/// Bit pattern of 1.0f32, the first power of every sweep.
pub const ONE_BITS: u32 = 0x3f80_0000;

/// Number of `f32` values in `[1, max_power]` (both ends included): about 1.09e8 for 8192.
pub fn powers_in(max_power: f32) -> u64 {
    u64::from(max_power.to_bits() - ONE_BITS) + 1
}

/// What a round trip `decode(encode(p))` did over every `f32` power in `[1, max_power]`.
#[derive(Clone, Debug, Default)]
pub struct RoundTrip {
    /// Relative error `|decode(encode(p)) − p| / p` (f64), index = power's offset from 1.0.
    pub relative: ErrorStats,
    /// Relative error at `p = 1`.
    pub at_one: f64,
    /// Largest relative error among powers `≤ 2` (where linear storage fails).
    pub max_below_two: f64,
    /// Codes that differ from the Rust twin's encoder (`None` when no twin was given).
    pub twin_code_mismatches: Option<u64>,
    /// Codes (of 256) whose adapter-decoded value differs in bits from the Rust twin's.
    pub twin_decode_mismatches: Option<u64>,
    /// Codes that differ from the exact (f64) nearest code in log range.
    pub exact_code_mismatches: Option<u64>,
    /// Number of powers swept.
    pub count: u64,
    /// Error against power for plots: bin `b = 16e + s` covers the powers
    /// `[2^e(1 + s/16), 2^e(1 + (s+1)/16))` (the top four significand bits: sixteen equal
    /// steps per octave) and holds `(max, mean)` relative error of its powers; the last bin
    /// also holds `p = max_power`.
    pub profile: Vec<(f64, f64)>,
}

/// Bins per octave of [`RoundTrip::profile`].
pub const PROFILE_BINS_PER_OCTAVE: u32 = 16;

/// The lower edge (a power) of profile bin `b`.
pub fn profile_bin_start(b: usize) -> f64 {
    let per = PROFILE_BINS_PER_OCTAVE as usize;
    ((b / per) as f64).exp2() * (1.0 + (b % per) as f64 / per as f64)
}

/// A pair of Rust twins to compare the adapter's codes and values with.
pub type Twins = (fn(f32, f32) -> u32, fn(u32, f32) -> f32);

/// Run `encode(p, max_power)` from `source` on the adapter for every `f32` power
/// `p ∈ [1, max_power]` (fed as bit patterns with `Arg::Index`, streamed in chunks), decode all
/// 256 codes with `decode` on the adapter once, and measure `decode(encode(p))` — the adapter's
/// decoded value for the adapter's code, since a decode depends on the code alone — against `p`
/// in f64. With `twins`, also count the codes/values that differ from the Rust twins; with
/// `check_exact`, count the codes that differ from the exact log-range code.
pub fn roundtrip_all_powers(
    gpu: &Gpu,
    source: &str,
    encode: &str,
    decode: &str,
    max_power: f32,
    twins: Option<Twins>,
    check_exact: bool,
) -> Result<RoundTrip, HarnessError> {
    let table = gpu
        .kernel(source, decode)?
        .run(&[Arg::Index { start: 0 }, Arg::splat_f32(max_power)], 256)?;
    let table: Vec<f32> = table.as_f32().to_vec();
    let kernel = gpu.kernel(source, encode)?;
    let n = powers_in(max_power);
    let mut r = RoundTrip {
        count: n,
        twin_code_mismatches: twins.map(|_| 0),
        twin_decode_mismatches: twins.map(|(_, dec)| {
            (0..256u32)
                .filter(|&k| dec(k, max_power).to_bits() != table[k as usize].to_bits())
                .count() as u64
        }),
        exact_code_mismatches: check_exact.then_some(0),
        ..Default::default()
    };
    let m64 = f64::from(max_power);
    let bins = ((max_power.to_bits() - ONE_BITS) >> (23 - PROFILE_BINS_PER_OCTAVE.trailing_zeros()))
        .max(1) as usize;
    let mut sums = vec![(0.0f64, 0.0f64, 0u64); bins];
    kernel.run_chunks(
        &[Arg::Index { start: ONE_BITS }, Arg::splat_f32(max_power)],
        n,
        |first, out| {
            let mut stats = ErrorStats::default();
            for (k, &code) in out.as_u32().iter().enumerate() {
                let i = first + k as u64;
                let p = f32::from_bits(ONE_BITS + i as u32);
                let value = table[code.min(255) as usize];
                let rel = relative_error(f64::from(value), f64::from(p));
                stats.add(i, rel);
                // Exponent and top four significand bits: the bin, exactly.
                let b = ((i as u32) >> (23 - PROFILE_BINS_PER_OCTAVE.trailing_zeros())) as usize;
                let bin = &mut sums[b.min(bins - 1)];
                bin.0 = bin.0.max(rel);
                bin.1 += rel;
                bin.2 += 1;
                if i == 0 {
                    r.at_one = rel;
                }
                if p <= 2.0 && rel > r.max_below_two {
                    r.max_below_two = rel;
                }
                if let Some((enc, _)) = twins
                    && enc(p, max_power) != code
                {
                    *r.twin_code_mismatches.as_mut().expect("set with twins") += 1;
                }
                if check_exact && exact::encode(f64::from(p), m64) != code {
                    *r.exact_code_mismatches.as_mut().expect("set") += 1;
                }
            }
            r.relative.merge(&stats);
            Ok(())
        },
    )?;
    r.profile = sums
        .iter()
        .map(|&(max, sum, n)| (max, if n > 0 { sum / n as f64 } else { 0.0 }))
        .collect();
    Ok(r)
}

/// The shipped log-range pair over every power in `[1, max_power]`, checked against the twins
/// and the exact code.
pub fn log_roughness_all_powers(gpu: &Gpu, max_power: f32) -> Result<RoundTrip, HarnessError> {
    roundtrip_all_powers(
        gpu,
        crate::wgsl::ROUGHNESS,
        "encode_log_roughness",
        "decode_log_roughness",
        max_power,
        Some((
            roughness::encode_log_roughness,
            roughness::decode_log_roughness,
        )),
        true,
    )
}

/// Every code's decoded value on the adapter against the exact `max_power^(k/255)`.
#[derive(Clone, Debug)]
pub struct Decoded {
    /// Error in `f32` ULPs of the exact value, index = code.
    pub ulps: ErrorStats,
    /// The 256 decoded values, code order.
    pub values: Vec<f32>,
}

/// Decode every code `0..=255` on the adapter and measure against the exact value (f64).
pub fn decode_all_codes(gpu: &Gpu, max_power: f32) -> Result<Decoded, HarnessError> {
    let out = gpu
        .kernel(crate::wgsl::ROUGHNESS, "decode_log_roughness")?
        .run(&[Arg::Index { start: 0 }, Arg::splat_f32(max_power)], 256)?;
    let values = out.as_f32().to_vec();
    let mut ulps = ErrorStats::default();
    for (k, &v) in values.iter().enumerate() {
        ulps.add(
            k as u64,
            ulp_error(v, exact::decode(k as u32, f64::from(max_power))),
        );
    }
    Ok(Decoded { ulps, values })
}
