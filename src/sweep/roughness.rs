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
    let table = table.into_f32();
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
    let values = out.into_f32();
    let mut ulps = ErrorStats::default();
    for (k, &v) in values.iter().enumerate() {
        ulps.add(
            k as u64,
            ulp_error(v, exact::decode(k as u32, f64::from(max_power))),
        );
    }
    Ok(Decoded { ulps, values })
}

/// The ranges measured on the worst conforming adapter: two power-of-two ranges (exact by
/// construction) and three general ones (`log2`/`exp2`, spanning `L` from 6.65 to 21.5).
pub const EMULATED_RANGES: [f32; 5] = [8192.0, 256.0, 1000.0, 100.5, 3.0e6];

/// Powers spread over `[1, max_power]`: every 61st `f32` pattern, and `max_power` itself
/// (about 1.4 million for 1000). The stride is odd, so the sample walks across every code
/// and every significand pattern rather than a lattice of them.
pub fn sampled_powers(max_power: f32) -> Vec<f32> {
    (ONE_BITS..=max_power.to_bits())
        .step_by(61)
        .map(f32::from_bits)
        .chain([max_power])
        .collect()
}

/// The round trip as one WGSL function, `(code, bits of the decoded power)`, so the emulation
/// and the interval evaluator see the encoder's and the decoder's operations together.
pub const ROUND_TRIP_FUNCTION: &str = "log_roughness_round_trip";

/// `wgsl/roughness.wgsl` with [`ROUND_TRIP_FUNCTION`] appended.
pub fn round_trip_source() -> String {
    format!(
        "{}\nfn {ROUND_TRIP_FUNCTION}(p: f32, m: f32) -> vec2<u32> {{\n    let c = encode_log_roughness(p, m);\n    return vec2<u32>(c, bitcast<u32>(decode_log_roughness(c, m)));\n}}\n",
        crate::wgsl::ROUGHNESS
    )
}

/// The encoder's decision points: for every 8th code boundary `j` (32 of them), the `f32`
/// nearest the exact boundary `max_power^((2j+1)/510)` and its neighbours 1, 2, 4, … 128
/// patterns away on either side. These are the powers a conforming adapter's `log2` and
/// division can send to the neighbouring code, and how far from the boundary that reaches.
pub fn boundary_powers(max_power: f32) -> Vec<f32> {
    let l = f64::from(max_power).log2();
    let mut out = Vec::new();
    for j in (0..255u32).step_by(8) {
        let t = (f64::from(2 * j + 1) * l / 510.0).exp2() as f32;
        let offsets = (0..8).map(|s| 1i64 << s);
        for d in std::iter::once(0)
            .chain(offsets.clone())
            .chain(offsets.map(|d| -d))
        {
            let p = f32::from_bits((i64::from(t.to_bits()) + d) as u32);
            if p > 1.0 && p < max_power {
                out.push(p);
            }
        }
    }
    out
}

/// Distance of `p` from the nearest code boundary, in codes: `|t − (j + ½)|` for
/// `t = 255·log2(p)/log2(max_power)` in f64 (error ~1e-13 codes).
pub fn boundary_distance(p: f32, max_power: f32) -> f64 {
    let t = 255.0 * f64::from(p).log2() / f64::from(max_power).log2();
    (t - t.floor() - 0.5).abs()
}

/// One range's figures on the adapter and on the worst conforming adapter (README's and
/// `docs/figures.md`'s roughness tables; `tests/roughness.rs` asserts the promises on them).
#[derive(Clone, Debug)]
pub struct ConformingFigures {
    /// The range's top power.
    pub max_power: f32,
    /// `max_power` is `2^L` with integer `L`: the integer encoder and table decoder.
    pub power_of_two: bool,
    /// Powers in the round-trip sample ([`sampled_powers`]).
    pub powers: usize,
    /// Round trip, largest relative error `|decode(encode(p)) − p| / p`: on the adapter, and
    /// the worst of the emulation's policies.
    pub round_trip: (f64, f64),
    /// The worst policy's name.
    pub round_trip_policy: String,
    /// Codes that differ from the exact nearest ([`exact::encode`]): on the adapter, and the
    /// most under any policy.
    pub codes_off: (u64, u64),
    /// Codes that differ from the Rust twin's encoder on the adapter.
    pub codes_off_twin: u64,
    /// Decoded values (of the sampled round trips) whose bits differ from the Rust twin's
    /// decode of the same code: on the adapter, and the most under any policy.
    pub decodes_off_twin: (u64, u64),
    /// The interval enclosure of the round trip ([`crate::conforming::interval`], flushing
    /// allowed) at every [`MACHINE_STRIDE`]-th sampled power: the relative error at its
    /// farther end (general ranges; 0 for power-of-two ranges, whose decode is exact).
    pub round_trip_machine: f64,
    /// Of those powers, how many the enclosure gives more than one possible code.
    pub machine_codes_wide: u64,
    /// Powers the enclosure was evaluated at.
    pub machine_powers: usize,
    /// Where the enclosure contradicts the exact code or (power-of-two ranges) the twin's
    /// decode: each would be a flaw of the evaluator or of the shipped function. Empty when sound.
    pub machine_violations: Vec<String>,
    /// Encoder decision points searched ([`boundary_powers`]).
    pub boundary_inputs: usize,
    /// Of those, how many some direction table sends to a code other than the exact nearest.
    pub boundary_flipped: usize,
    /// The farthest such power from its boundary, in codes (0 where none flips).
    pub boundary_flip_distance: f64,
    /// The farthest power from its boundary whose enclosure holds two codes (general ranges;
    /// the enclosure does not split the power-of-two encoder's boundary test, see
    /// `tests/roughness.rs`).
    pub boundary_machine_distance: f64,
    /// Fewest and most slots the encoder reads at those points, and whether every one was
    /// searched exhaustively.
    pub encode_slots: (u32, u32, bool),
    /// Decode of every code, relative error against `max_power^(k/255)`: on the adapter, the
    /// worst policy, the worst the search found, and the enclosure's farther end.
    pub decode: (f64, f64, f64, f64),
    /// Fewest and most slots a decode reads, and whether every code was searched exhaustively.
    pub decode_slots: (u32, u32, bool),
    /// Codes where a policy or the search decoded outside the enclosure (a flaw of the
    /// emulation or of the evaluator). Empty when sound.
    pub decode_violations: Vec<String>,
}

/// Stride of the round-trip sample at which the interval evaluator (CPU) runs.
pub const MACHINE_STRIDE: usize = 64;

/// [`ConformingFigures`] of `max_power` under each of `policies`, the worst-case search
/// (`conforming::search::climb`, exhaustive where the slots read are few) over every code's
/// decode and over the encoder's decision points, and the interval enclosure.
pub fn conforming_figures(
    gpu: &Gpu,
    max_power: f32,
    policies: &[crate::conforming::Policy],
) -> Result<ConformingFigures, HarnessError> {
    use crate::conforming::interval::{Enclosure, IntervalError, Value};
    use crate::conforming::search::{SearchConfig, climb};
    use crate::conforming::{EmulatedKernel, Emulation, Policy};
    let m64 = f64::from(max_power);
    let power_of_two = max_power.log2().fract() == 0.0;
    let src = round_trip_source();
    let machine_err = |e: IntervalError| HarnessError::Shader(format!("interval evaluation: {e}"));
    let enclosure = Enclosure::new(&src, true).map_err(machine_err)?;
    // `function(first, max_power)` over intervals.
    let enclose = |function: &str, first: Value| {
        enclosure
            .of(function, &[first, Value::f32s(&[max_power])])
            .map_err(machine_err)
    };
    let rel = |v: f32, x: f64| (f64::from(v) - x).abs() / x;
    let config = SearchConfig::default();
    let slots_of = |found: &[crate::conforming::search::Found]| {
        (
            found.iter().map(|f| f.slots).min().unwrap_or(0),
            found.iter().map(|f| f.slots).max().unwrap_or(0),
            found.iter().all(|f| f.slots <= config.exhaustive_slots),
        )
    };

    // Round trip over the sample: the adapter, then each policy.
    let ps = sampled_powers(max_power);
    let args = [Arg::column(&ps), Arg::splat_f32(max_power)];
    let exact_codes: Vec<u32> = ps
        .iter()
        .map(|&p| exact::encode(f64::from(p), m64))
        .collect();
    // A decode depends on the code alone: the twin's 256 decodes, once.
    let twin_decodes: Vec<u32> = (0..=255u32)
        .map(|k| roughness::decode_log_roughness(k, max_power).to_bits())
        .collect();
    // (worst relative error, codes ≠ exact, decodes ≠ twin, codes ≠ twin when `twin` asks).
    let tally = |words: &[u32], twin: bool| {
        let (mut worst, mut codes_off, mut decodes_off, mut twin_off) = (0.0f64, 0u64, 0u64, 0u64);
        for ((&p, w), &c) in ps.iter().zip(words.chunks_exact(2)).zip(&exact_codes) {
            worst = worst.max(rel(f32::from_bits(w[1]), f64::from(p)));
            codes_off += u64::from(c != w[0]);
            decodes_off += u64::from(twin_decodes[w[0].min(255) as usize] != w[1]);
            if twin {
                twin_off += u64::from(roughness::encode_log_roughness(p, max_power) != w[0]);
            }
        }
        (worst, codes_off, decodes_off, twin_off)
    };
    let on_adapter = gpu
        .kernel(&src, ROUND_TRIP_FUNCTION)?
        .run(&args, ps.len() as u64)?;
    let (rt_adapter, codes_adapter, decodes_adapter, codes_off_twin) =
        tally(on_adapter.words(), true);
    let (mut rt_emulated, mut rt_policy, mut codes_emulated, mut decodes_emulated) =
        (0.0f64, String::new(), 0u64, 0u64);
    for &policy in policies {
        let k = EmulatedKernel::new(gpu, &src, ROUND_TRIP_FUNCTION, &Emulation::new(policy))?;
        let (out, _) = k.run(&args, ps.len() as u64)?;
        let (worst, codes, decodes, _) = tally(out.words(), false);
        if worst >= rt_emulated {
            (rt_emulated, rt_policy) = (worst, policy.to_string());
        }
        codes_emulated = codes_emulated.max(codes);
        decodes_emulated = decodes_emulated.max(decodes);
    }

    // The round trip's enclosure at every MACHINE_STRIDE-th sampled power.
    let (mut rt_machine, mut codes_wide, mut machine_violations) = (0.0f64, 0u64, Vec::new());
    let machine_ps: Vec<(f32, u32)> = ps
        .iter()
        .zip(&exact_codes)
        .step_by(MACHINE_STRIDE)
        .map(|(&p, &c)| (p, c))
        .collect();
    for &(p, exact_code) in &machine_ps {
        let v = enclose(ROUND_TRIP_FUNCTION, Value::f32s(&[p]))?;
        let Value::U32(l) = v else {
            return Err(HarnessError::Shader(
                "the round trip returns vec2<u32>".into(),
            ));
        };
        let (code, bits) = (l[0], l[1]);
        codes_wide += u64::from(code.0 != code.1);
        if !(code.0 <= exact_code && exact_code <= code.1) {
            machine_violations.push(format!(
                "power {p:e}: the exact code {exact_code} is outside the enclosure {code:?}"
            ));
        }
        if power_of_two && code.0 == code.1 {
            let twin = roughness::decode_log_roughness(exact_code, max_power).to_bits();
            if bits != (twin, twin) {
                machine_violations.push(format!(
                    "power {p:e}: the decode's enclosure {bits:?} is not the twin's {twin:#x}"
                ));
            }
        }
        if !power_of_two {
            for b in [bits.0, bits.1] {
                rt_machine = rt_machine.max(rel(f32::from_bits(b), f64::from(p)));
            }
        }
    }

    // The encoder at its decision points: every table of the slots it reads.
    let bps = boundary_powers(max_power);
    let bexact: Vec<u32> = bps
        .iter()
        .map(|&p| exact::encode(f64::from(p), m64))
        .collect();
    let enc = EmulatedKernel::new(
        gpu,
        crate::wgsl::ROUGHNESS,
        "encode_log_roughness",
        &Emulation::new(Policy::Searched),
    )?;
    let off = |i: usize, out: &crate::harness::Output, e: usize| {
        f64::from(out.as_u32()[e].abs_diff(bexact[i]))
    };
    let found = climb(
        &enc,
        &[Arg::column(&bps), Arg::splat_f32(max_power)],
        bps.len(),
        &off,
        &config,
    )?;
    let encode_slots = slots_of(&found);
    let (mut flipped, mut flip_distance) = (0usize, 0.0f64);
    for (f, &p) in found.iter().zip(&bps) {
        if f.error > 0.0 {
            flipped += 1;
            flip_distance = flip_distance.max(boundary_distance(p, max_power));
        }
    }
    let mut boundary_machine_distance = 0.0f64;
    if !power_of_two {
        for &p in &bps {
            let v = enclose("encode_log_roughness", Value::f32s(&[p]))?;
            if let Value::U32(l) = v
                && l[0].0 != l[0].1
            {
                boundary_machine_distance =
                    boundary_machine_distance.max(boundary_distance(p, max_power));
            }
        }
    }

    // Every code's decode: the adapter, each policy, the search, the enclosure.
    let codes: Vec<u32> = (0..=255).collect();
    let exact_values: Vec<f64> = codes.iter().map(|&k| exact::decode(k, m64)).collect();
    let dargs = [Arg::column(&codes), Arg::splat_f32(max_power)];
    let worst_of = |values: &[f32]| {
        values
            .iter()
            .zip(&exact_values)
            .map(|(&v, &x)| rel(v, x))
            .fold(0.0, f64::max)
    };
    let mut hull = Vec::with_capacity(256);
    let mut decode_machine = 0.0f64;
    for &k in &codes {
        let v = enclose("decode_log_roughness", Value::u32s(&[k]))?;
        let iv = v
            .f32_lanes()
            .ok_or_else(|| HarnessError::Shader("decode_log_roughness returns an f32".into()))?[0];
        decode_machine = decode_machine
            .max(rel(iv.lo, exact_values[k as usize]))
            .max(rel(iv.hi, exact_values[k as usize]));
        hull.push((iv.lo, iv.hi));
    }
    let mut decode_violations = Vec::new();
    let mut outside = |what: &str, k: usize, v: f32| {
        let (lo, hi) = hull[k];
        if !(lo <= v && v <= hi) {
            decode_violations.push(format!(
                "{what}, code {k}: {v:e} outside the enclosure [{lo:e}, {hi:e}]"
            ));
        }
    };
    let decode_adapter = worst_of(&decode_all_codes(gpu, max_power)?.values);
    let mut decode_emulated = 0.0f64;
    for &policy in policies {
        let k = EmulatedKernel::new(
            gpu,
            crate::wgsl::ROUGHNESS,
            "decode_log_roughness",
            &Emulation::new(policy),
        )?;
        let (out, _) = k.run(&dargs, 256)?;
        decode_emulated = decode_emulated.max(worst_of(out.as_f32()));
        for (k, &v) in out.as_f32().iter().enumerate() {
            outside(&format!("{policy}"), k, v);
        }
    }
    let dec = EmulatedKernel::new(
        gpu,
        crate::wgsl::ROUGHNESS,
        "decode_log_roughness",
        &Emulation::new(Policy::Searched),
    )?;
    let err =
        |i: usize, out: &crate::harness::Output, e: usize| rel(out.as_f32()[e], exact_values[i]);
    let found = climb(&dec, &dargs, 256, &err, &config)?;
    let decode_slots = slots_of(&found);
    let plan: Vec<_> = found
        .iter()
        .enumerate()
        .map(|(k, f)| (k, f.table))
        .collect();
    let (at_worst, _) = crate::conforming::search::run_at(&dec, &dargs, 256, &plan)?;
    for (k, &v) in at_worst.as_f32().iter().enumerate() {
        outside("searched", k, v);
    }
    let decode_searched = worst_of(at_worst.as_f32());

    Ok(ConformingFigures {
        max_power,
        power_of_two,
        powers: ps.len(),
        round_trip: (rt_adapter, rt_emulated),
        round_trip_policy: rt_policy,
        codes_off: (codes_adapter, codes_emulated),
        codes_off_twin,
        decodes_off_twin: (decodes_adapter, decodes_emulated),
        round_trip_machine: rt_machine,
        machine_codes_wide: codes_wide,
        machine_powers: machine_ps.len(),
        machine_violations,
        boundary_inputs: bps.len(),
        boundary_flipped: flipped,
        boundary_flip_distance: flip_distance,
        boundary_machine_distance,
        encode_slots,
        decode: (
            decode_adapter,
            decode_emulated,
            decode_searched,
            decode_machine,
        ),
        decode_slots,
        decode_violations,
    })
}
