//! The normal-encoding sweeps on the worst conforming adapter: each codec's WGSL rewritten by
//! [`crate::conforming::emulate`] and run through the same sweeps as on the adapter itself.

use super::normal::{
    Codec, DecoderCheck, ROUND_TRIP_FN, RoundTrip, decode_codes_with, round_trip,
    round_trip_measured, round_trip_parts, round_trip_source, round_trip_with,
};
use crate::conforming::{EmulateError, EmulatedKernel, Emulation, emulate};
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{angle_degrees, widen3};
use std::borrow::Cow;

/// How far a decoded vector's length may be from 1 on any conforming adapter, for a decoder
/// that ends in WGSL's `normalize(v)` = `v / length(v)` (or `v·inverseSqrt(dot(v, v))`, which is
/// within it). With `u = 2^-24`: `dot` is three products and two sums of non-negative terms,
/// each rounded to either neighbour (`2u` relative): `6u`; `inverseSqrt` (2 ULP ≤ `4u`) of it:
/// `3u + 4u = 7u`; `length = 1/inverseSqrt` adds the division's 2.5 ULP (`5u`): `12u`; each
/// component's division by it another `5u`: `17u`, plus `u` for second-order terms: `18u`.
/// (On a correctly rounded adapter the budget is [`super::normal::UNIT_TOLERANCE`].)
pub const UNIT_TOLERANCE_CONFORMING: f64 = 18.0 / 16_777_216.0;

/// [`super::normal::decode_angle_deg`] on any conforming adapter: `normalize(D)` inherits the
/// accuracy of `D / length(D)`, whose length only scales the result, while each component's
/// quotient may err 2.5 ULP (`5u` relative, against the correctly rounded `u`), so the turn is
/// at most `√2·5u` rad; plus the same `1e-12°` for the f64 angle.
pub fn decode_angle_conforming_deg() -> f64 {
    (2f64.sqrt() * 5.0 * 2f64.powi(-24)).to_degrees() + 1e-12
}

/// How far `decode_normal_xy_fp16` may turn a code's direction on any conforming adapter, in
/// degrees, against the exact direction `(x, y, √max(0, 1 − x² − y²))` normalised. With
/// `u = 2^-24` and `S = x² + y²` (the halves and their clamp are exact): `s = dot(xy, xy)` errs at
/// most `4u·S` (two products and a sum, each to either neighbour, `2u`; a fused form errs less),
/// and `1 − s` another `2u`, so `z² = max(0, 1 − s)` is within `δ = 6u` (for `S ≤ 1`; beyond,
/// both sides clamp to 0 and the computed one is within `4u·S − (S − 1) ≤ 6u` near `S = 1`) of
/// the exact `Z²` (plus `2^-126` for a flushed product: `8u` covers both). `|√a − √b| ≤ √|a − b|`,
/// so `|z − Z| ≤ √(8u) + 9u` (`sqrt`'s own error, as `1/inverseSqrt`: under `9u` relative, and
/// `z ≤ 1`). The vector `(x, y, z)` is then within that distance of `(x, y, Z)`, whose length is
/// at least 1, so it turns by at most `asin(√(8u) + 9u)`; the final `/ sqrt(s + z²)` rounds each
/// component by 2.5 ULP, a further `√2·5u` turn (as [`decode_angle_conforming_deg`]). The
/// square root makes this about 0.04°, not the octahedral decoders' 2.4e-5°: near the horizon
/// a few rounding units in `1 − s` move `z` by their square root.
pub fn decode_angle_conforming_xy_fp16_deg() -> f64 {
    let u = 2f64.powi(-24);
    ((8.0 * u).sqrt() + 9.0 * u).asin().to_degrees() + decode_angle_conforming_deg()
}

/// The slack the precise encoder's choice may have over the best neighbour on any conforming
/// adapter: [`super::normal::optimality_tolerance_deg`] times 5. That tolerance is a sum of
/// roundings of `+ − ×` (each `u` relative where correctly rounded, `2u` on any conforming
/// adapter) and of one division (`u`, against WGSL's 2.5 ULP ≤ `5u`): every term grows at most
/// fivefold.
pub fn optimality_tolerance_conforming_deg() -> f64 {
    5.0 * super::normal::optimality_tolerance_deg()
}

/// `codec` with its WGSL replaced by the emulating module. The module's text is leaked (a
/// [`Codec`] holds `&'static str`): a handful per test run.
pub fn emulated_codec(codec: &Codec, emulation: &Emulation) -> Result<Codec, EmulateError> {
    let e = emulate(codec.source, emulation)?;
    let name = |f: &str| {
        e.function_name(f)
            .map(|n| &*Box::leak(n.to_string().into_boxed_str()))
            .ok_or_else(|| EmulateError(format!("no function `{f}`")))
    };
    let (encode, decode) = (name(codec.encode)?, name(codec.decode)?);
    Ok(Codec {
        source: Box::leak(e.source.into_boxed_str()),
        encode,
        decode,
        ..*codec
    })
}

/// Largest `|len − 1|` of decoded vectors (f64 length of the f32 result), and how many are not
/// finite or beyond `tolerance`.
pub fn length_check(decoded: &[[f32; 3]], tolerance: f64) -> (f64, u64) {
    let mut worst = 0.0f64;
    let mut bad = 0;
    for v in decoded {
        let l = v.iter().map(|&x| f64::from(x).powi(2)).sum::<f64>().sqrt();
        if l.is_finite() {
            worst = worst.max((l - 1.0).abs());
        }
        bad += u64::from(!l.is_finite() || (l - 1.0).abs() > tolerance);
    }
    (worst, bad)
}

/// One codec's round trip under one emulation, and its decoder over `codes`.
pub struct EmulatedCodec {
    /// Encoded and decoded by the emulating module (the twins are the unemulated Rust ones, so
    /// `twin_encode` counts the codes that the emulated adapter chooses differently).
    pub round_trip: RoundTrip,
    /// The decoder over the given codes (its `not_unit` counts against the correctly rounded
    /// tolerance; see [`EmulatedCodec::decode_length`] for the conforming one).
    pub decoder: DecoderCheck,
    /// (largest `|len − 1|`, count beyond [`UNIT_TOLERANCE_CONFORMING`] or not finite) over the
    /// round trip's decoded vectors.
    pub round_trip_length: (f64, u64),
    /// Over the codes that differ from the Rust twin's: the largest difference in any lane of
    /// the code (an octahedral coordinate, a byte of xyz8, an f16 of xy FP16 counted in f16
    /// steps), i.e. how many code steps away the emulated adapter lands; two codes of one exact
    /// direction count as 0.
    pub max_code_step: u32,
}

/// The largest per-lane difference between two codes of `codec`, over its [`Codec::lanes`].
fn code_step(codec: &Codec, a: u32, b: u32) -> u32 {
    use super::normal::LaneKind;
    codec
        .lanes
        .iter()
        .map(|lane| {
            let m = (1u32 << lane.width) - 1;
            let (x, y) = ((a >> lane.shift) & m, (b >> lane.shift) & m);
            let value = |h: u32| -> i64 {
                match lane.kind {
                    LaneKind::Unsigned => i64::from(h),
                    // Sign-extend the field.
                    LaneKind::Signed => {
                        i64::from(((h << (32 - lane.width)) as i32) >> (32 - lane.width))
                    }
                    // f16 lanes are compared in their order (±0 one value).
                    LaneKind::F16 if h & 0x8000 != 0 => -i64::from(h & 0x7fff),
                    LaneKind::F16 => i64::from(h),
                }
            };
            let (x, y) = (value(x), value(y));
            // An adapter may flush an f16-subnormal lane to ±0 (WGSL: pack intermediates may be
            // flushed): a lane at most one step above the subnormals (|code| ≤ 0x400, 2^-14)
            // stored as zero is that freedom, counted as one step.
            if lane.kind == LaneKind::F16 && (x == 0 || y == 0) && x.abs().max(y.abs()) <= 0x400 {
                return u32::from(x != y);
            }
            x.abs_diff(y) as u32
        })
        .max()
        .unwrap_or(0)
}

/// How many code steps `codes` (an adapter's, `codes[i]` encoded from `inputs[i]`) lie from the
/// Rust twin's codes of the same inputs at most, counted per lane as
/// [`EmulatedCodec::max_code_step`] says (two codes of one exact direction, such as the four
/// corners of the octahedral square, are no step apart). The twins promise at most 1 on every
/// conforming adapter.
pub fn max_code_step(codec: &Codec, inputs: &[[f32; 3]], codes: &[u32]) -> u32 {
    codes
        .iter()
        .zip(inputs)
        .map(|(&got, &n)| {
            let twin = (codec.twin_encode)(glam::Vec3::from(n));
            if got == twin || (codec.reference_decode)(got) == (codec.reference_decode)(twin) {
                0
            } else {
                code_step(codec, got, twin)
            }
        })
        .max()
        .unwrap_or(0)
}

impl EmulatedCodec {
    /// Decoder lengths against the conforming budget: the largest `|len − 1|`, and whether it is
    /// within [`UNIT_TOLERANCE_CONFORMING`] (non-finite results count as beyond).
    pub fn decode_length(&self) -> (f64, bool) {
        (
            self.decoder.max_len_error,
            self.decoder.max_len_error <= UNIT_TOLERANCE_CONFORMING
                && self.decoder.max_angle_deg.is_finite(),
        )
    }
}

/// Run `codec` under `emulation`: encode and decode `inputs`, and decode `codes`. The encoder
/// and the decoder run as two kernels (two emulated pipelines to compile).
pub fn emulated_codec_sweep(
    gpu: &Gpu,
    codec: &Codec,
    emulation: &Emulation,
    inputs: &[[f32; 3]],
    codes: &[u32],
) -> Result<EmulatedCodec, HarnessError> {
    codec_sweep(gpu, codec, emulation, inputs, codes, false)
}

/// [`emulated_codec_sweep`]; with `composed`, the round trip runs as the encoder and decoder in
/// one function ([`round_trip_source`]), the function and pipeline the round-trip search of the
/// same codec runs, so a caller that searches next compiles the encoder once, not twice (on
/// lavapipe most of an emulated sweep is compiling). Either way every operation gets the
/// direction it has in the encoder's or decoder's own module: a fixed table's and the seeded
/// draw's depend on the operation's site and operands, not on its caller.
fn codec_sweep(
    gpu: &Gpu,
    codec: &Codec,
    emulation: &Emulation,
    inputs: &[[f32; 3]],
    codes: &[u32],
    composed: bool,
) -> Result<EmulatedCodec, HarnessError> {
    let decode = EmulatedKernel::new(gpu, codec.source, codec.decode, emulation)?;
    let decode = |a: &[Arg<'_>], n: u64| Ok(decode.run(a, n)?.0);
    let rt = if composed {
        let k = EmulatedKernel::new(gpu, &round_trip_source(codec), ROUND_TRIP_FN, emulation)?;
        let (out, _) = k.run(&[Arg::column(inputs)], inputs.len() as u64)?;
        let (codes_rt, decoded) = out.as_vec4().iter().map(|&v| round_trip_parts(v)).unzip();
        round_trip_measured(codec, inputs, codes_rt, decoded)
    } else {
        let encode = EmulatedKernel::new(gpu, codec.source, codec.encode, emulation)?;
        round_trip_with(codec, inputs, &|a, n| Ok(encode.run(a, n)?.0), &decode)?
    };
    let round_trip_length = length_check(&rt.decoded, UNIT_TOLERANCE_CONFORMING);
    let decoder = decode_codes_with(codec, codes, &decode)?;
    let max_code_step = max_code_step(codec, inputs, &rt.codes);
    Ok(EmulatedCodec {
        round_trip: rt,
        decoder,
        round_trip_length,
        max_code_step,
    })
}

/// One encoding's published figures: its round trip on the adapter and on the emulated worst
/// adapter, over the same inputs.
#[derive(Clone, Debug)]
pub struct NormalFigures {
    /// The codec's table name.
    pub name: &'static str,
    /// Bits of the code.
    pub bits: u32,
    /// The render-target format the scene stores it in (`Scene::gbuffer`).
    pub target: String,
    /// Round-trip angle (degrees) on the adapter (z ≥ 0 only for the hemisphere codes and xy
    /// FP16).
    pub adapter: crate::precision::metrics::ErrorStats,
    /// Largest round-trip angle under each policy, in the order given.
    pub emulated_max: Vec<f64>,
    /// Largest mean round-trip angle over the policies (a sampling codec's over the evenly
    /// spread part of its sample, [`emulation_sample`]).
    pub emulated_mean: f64,
    /// The inputs the emulated sweeps ran at ([`emulation_sample`]: all of them but for a codec
    /// that samples).
    pub emulated_inputs: usize,
    /// Most codes differing from the Rust twin's under any policy.
    pub twin_changed: u64,
    /// Largest `|len − 1|` of any emulated decode (round trip and decoder sample).
    pub max_len_error: f64,
    /// The worst round-trip angle the search found ([`super::normal::searched_round_trip`],
    /// at the inputs the policies erred most on); 0 where nothing was searched.
    pub searched: f64,
    /// Where, with the search's record (how it was found, slots read, tables evaluated).
    pub searched_at: String,
    /// Over the searched inputs: the fewest and most table slots a round trip read, and whether
    /// every input was searched exhaustively.
    pub searched_slots: (u32, u32, bool),
    /// Searched inputs.
    pub searched_inputs: usize,
    /// At the worst tables found: the largest step of the chosen code from the Rust twin's
    /// (the one-code promise, as [`EmulatedCodec::max_code_step`] counts it).
    pub searched_code_step: u32,
    /// At the worst tables found: the largest `|len − 1|` of the decoded vectors (non-finite
    /// lengths count as infinite).
    pub searched_len_error: f64,
    /// SPIR-V instructions of the encoder and of the decoder, callees included.
    pub spirv: (usize, usize),
}

/// 65,536 codes spread over a `bits`-bit code space (every code of a 16-bit one): 65,521 is
/// odd, so `i·65,521 mod 2^16` is every 16-bit code once.
pub fn spread_codes(bits: u32) -> Vec<u32> {
    (0..1u64 << 16)
        .map(|i| ((i * 65_521) % (1u64 << bits)) as u32)
        .collect()
}

/// [`spread_codes`] of a codec's code space as the words its decoder reads: for the signed
/// octahedron, whose 21-bit code indices stand for texels with B = 1023 or 0, those texels
/// ([`crate::normal::signed_oct::texel_of_index`]).
pub fn spread_words(c: &Codec) -> Vec<u32> {
    let codes = spread_codes(c.bits);
    if c.source == crate::wgsl::NORMAL_SIGNED_OCT {
        return codes
            .into_iter()
            .map(crate::normal::signed_oct::texel_of_index)
            .collect();
    }
    codes
}

/// The inputs a codec's emulated sweeps run at, and how many of them (the first ones) spread
/// evenly over `inputs`: all of `inputs` where [`Codec::emulation_sample`] is 1; for `k > 1`,
/// one input in `k` (picked by a hash of its index), then the `len/k` inputs at which the adapter's round trip (`decoded`,
/// one per input) erred most that are not among them. The emulation moves a code only near a
/// tie (within one step, or for the best fit within its conforming slack), so the emulated
/// worst lies where the adapter's round trip is already near its worst: the second part keeps
/// those; the first keeps the sweep spread over the sphere, and the mean is taken over it alone
/// (the second part is the worst, not a sample).
pub fn emulation_sample<'a>(
    c: &Codec,
    inputs: &'a [[f32; 3]],
    decoded: &[[f32; 3]],
) -> (Cow<'a, [[f32; 3]]>, usize) {
    let k = c.emulation_sample.max(1);
    if k == 1 {
        return (Cow::Borrowed(inputs), inputs.len());
    }
    // One input in k, by a multiplicative hash of its index rather than a stride: the
    // adversarial set comes in regular groups, which a stride would sample unevenly.
    let picked =
        |i: usize| ((i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 32).is_multiple_of(k as u64);
    let mut sample: Vec<[f32; 3]> = (0..inputs.len())
        .filter(|&i| picked(i))
        .map(|i| inputs[i])
        .collect();
    let spread = sample.len();
    // Over the inputs the codec's figures count: a hemisphere code's lower half would fill
    // this part.
    let mut by_error: Vec<(f64, usize)> = round_trip_angles(c, inputs, decoded)
        .map(|(i, a)| (a, i))
        .collect();
    // NaN (none on a conforming adapter) sorts first: such an input is kept.
    by_error.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    sample.extend(
        by_error
            .iter()
            .take(inputs.len() / k)
            .filter(|&&(_, i)| !picked(i))
            .map(|&(_, i)| inputs[i]),
    );
    (Cow::Owned(sample), spread)
}

/// `(i, angle)`: the round trip's angle in degrees (f64), `inputs[i]` against `decoded[i]`, at
/// each input `c`'s figures count: every one, or for a hemisphere code those with z ≥ 0 (its
/// lower half decodes to the upper one, far off).
fn round_trip_angles<'a>(
    c: &'a Codec,
    inputs: &'a [[f32; 3]],
    decoded: &'a [[f32; 3]],
) -> impl Iterator<Item = (usize, f64)> + 'a {
    inputs
        .iter()
        .zip(decoded)
        .enumerate()
        .filter(|(_, (n, _))| !c.hemisphere || n[2] >= 0.0)
        .map(|(i, (&n, &d))| (i, angle_degrees(widen3(n), widen3(d))))
}

/// [`NormalFigures`] of each of `codecs` (e.g. [`super::normal::CODECS`]) over `inputs`, under
/// each of `policies`, then searched at the `searched_inputs` inputs those policies erred most
/// on (0: no search); each decoder also over [`spread_codes`].
pub fn normal_figures(
    gpu: &Gpu,
    codecs: &[Codec],
    inputs: &[[f32; 3]],
    policies: &[crate::conforming::Policy],
    searched_inputs: usize,
) -> Result<Vec<NormalFigures>, HarnessError> {
    normal_figures_with(
        gpu,
        codecs,
        inputs,
        policies,
        searched_inputs,
        &|c| spread_words(c),
        &mut |_, _, _, _| {},
    )
}

/// Inputs per codec the round-trip search runs at in the full tier (`PREPASS_FULL=1`, where
/// the published figures come from): the worst of every policy's sweep, pooled.
pub const SEARCHED_NORMAL_INPUTS: usize = 16;

/// Inputs per codec the round-trip search runs at in the default tier: the first
/// [`SEARCHED_NORMAL_INPUTS_DEFAULT_TIER`] of the same pool, the inputs the policies erred most
/// on, each searched from every start as in the full tier.
///
/// Why that holds the worst: the search climbs each input on its own (`search::climb`: one
/// lane per input and start, none reads another's), so the default tier's search is the full
/// tier's restricted to the pool's head, and the worst round trip a search finds sits where the
/// greedy policies already erred most: the search only recombines the ends those policies
/// take. Measured at every codec of the normal-encodings block (2026-12-07, the search's 16
/// inputs, each lane's error after every round logged): the worst of the first 4 inputs equals
/// the worst of all 16 on all 19 codecs, the first input alone on 18 (not oct32 fast), and no
/// lane improved after its sixth round of 24; searching from the upper and lower starts only
/// loses oct16 fast's worst (by under 10^-6°), so every start is kept.
/// `default_tier_sample_finds_the_full_tiers_worst` (tests/conforming.rs) checks the default
/// tier's whole rule, emulation sample and search together, against the full tier's.
pub const SEARCHED_NORMAL_INPUTS_DEFAULT_TIER: usize = 4;

/// What [`normal_figures_with`] hands each emulated sweep to: the codec, the policy, the inputs
/// the sweep ran at ([`emulation_sample`]) and its measurement.
pub type InspectSweep<'a> =
    dyn FnMut(&Codec, crate::conforming::Policy, &[[f32; 3]], &EmulatedCodec) + 'a;

/// [`normal_figures`] with the decoder's codes chosen per codec, and every emulated sweep handed
/// to `inspect` as it is measured, with the inputs it ran at ([`emulation_sample`]), so that a
/// suite asserts on the same measurement it publishes.
pub fn normal_figures_with(
    gpu: &Gpu,
    codecs: &[Codec],
    inputs: &[[f32; 3]],
    policies: &[crate::conforming::Policy],
    searched_inputs: usize,
    codes_for: &dyn Fn(&Codec) -> Vec<u32>,
    inspect: &mut InspectSweep<'_>,
) -> Result<Vec<NormalFigures>, HarnessError> {
    use crate::scene::{NormalChoice, NormalEncoding, Scene};
    let mut rows = Vec::new();
    for c in codecs {
        let hemisphere = c.hemisphere;
        let pick = |rt: &RoundTrip| {
            if hemisphere { rt.error_upper } else { rt.error }
        };
        let on_adapter = round_trip(gpu, c, inputs)?;
        let adapter = pick(&on_adapter);
        let (sample, spread) = emulation_sample(c, inputs, &on_adapter.decoded);
        let inputs = &sample[..];
        let codes = codes_for(c);
        let mut row = NormalFigures {
            name: c.name,
            bits: c.bits,
            target: String::new(),
            adapter,
            emulated_max: Vec::new(),
            emulated_mean: 0.0,
            emulated_inputs: inputs.len(),
            twin_changed: 0,
            max_len_error: 0.0,
            searched: 0.0,
            searched_at: String::new(),
            searched_slots: (0, 0, true),
            searched_inputs: 0,
            searched_code_step: 0,
            searched_len_error: 0.0,
            spirv: (0, 0),
        };
        // (angle, input index, policy) of each policy's worst round trips.
        let mut pool: Vec<(f64, usize, crate::conforming::Policy)> = Vec::new();
        for &policy in policies {
            let emulation = Emulation::new(policy);
            let e = codec_sweep(gpu, c, &emulation, inputs, &codes, searched_inputs > 0)?;
            inspect(c, policy, inputs, &e);
            let mut worst: Vec<(f64, usize, crate::conforming::Policy)> =
                round_trip_angles(c, inputs, &e.round_trip.decoded)
                    .map(|(i, a)| (a, i, policy))
                    .collect();
            worst.sort_by(|a, b| b.0.total_cmp(&a.0));
            worst.truncate(searched_inputs);
            pool.extend(worst);
            let s = pick(&e.round_trip);
            row.emulated_max.push(s.max);
            let mean = if spread == inputs.len() {
                s.mean()
            } else {
                // A sampled codec: over the evenly spread part only (emulation_sample).
                let angles: Vec<f64> =
                    round_trip_angles(c, &inputs[..spread], &e.round_trip.decoded)
                        .map(|(_, a)| a)
                        .collect();
                angles.iter().sum::<f64>() / angles.len().max(1) as f64
            };
            row.emulated_mean = row.emulated_mean.max(mean);
            row.twin_changed = row.twin_changed.max(e.round_trip.twin_encode.count);
            row.max_len_error = row
                .max_len_error
                .max(e.round_trip_length.0)
                .max(e.decoder.max_len_error);
        }
        if searched_inputs > 0 {
            search_round_trips(gpu, c, inputs, pool, searched_inputs, &mut row)?;
        }
        let cost = |f: &str| {
            crate::wgsl::spirv_instruction_count(c.source, f)
                .map(|s| s.total)
                .map_err(|e| HarnessError::Shader(e.to_string()))
        };
        row.spirv = (cost(c.encode)?, cost(c.decode)?);
        // "xyz8 best-fit" is the scene's Xyz8Best.
        let base = c
            .name
            .trim_end_matches(" fast")
            .replace(" best-fit", "best")
            .replace(' ', "");
        if let Some(encoding) = NormalEncoding::ALL
            .into_iter()
            .find(|e| format!("{e:?}").to_lowercase() == base)
        {
            let scene = Scene {
                normal: NormalChoice {
                    encoding: Some(encoding),
                    fast_encoder: c.name.ends_with("fast"),
                },
                ..Scene::default()
            };
            if let Ok(g) = scene.gbuffer() {
                row.target = g
                    .targets
                    .iter()
                    .find(|t| t.name == "normal")
                    .map(|t| format!("{:?}", t.format.to_wgpu()))
                    .unwrap_or_default();
            }
        }
        rows.push(row);
    }
    Ok(rows)
}

/// The round-trip search at the `searched_inputs` worst of `pool` (each input once), recorded
/// in `row`.
fn search_round_trips(
    gpu: &Gpu,
    c: &Codec,
    inputs: &[[f32; 3]],
    mut pool: Vec<(f64, usize, crate::conforming::Policy)>,
    searched_inputs: usize,
    row: &mut NormalFigures,
) -> Result<(), HarnessError> {
    use crate::conforming::search::SearchConfig;
    pool.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut seen = std::collections::HashSet::new();
    pool.retain(|p| seen.insert(p.1));
    pool.truncate(searched_inputs);
    let at: Vec<[f32; 3]> = pool.iter().map(|p| inputs[p.1]).collect();
    let config = SearchConfig::default();
    let found = super::normal::searched_round_trip(gpu, c, &at, &config)?;
    let slots = found.iter().map(|s| s.found.slots);
    row.searched_slots = (
        slots.clone().min().unwrap_or(0),
        slots.max().unwrap_or(0),
        found
            .iter()
            .all(|s| s.found.slots <= config.exhaustive_slots),
    );
    row.searched_inputs = found.len();
    for (s, &(policy_error, i, policy)) in found.iter().zip(&pool) {
        let n = inputs[i];
        if s.found.error >= row.searched {
            row.searched = s.found.error;
            row.searched_at = format!(
                "input {:?} (where {policy} gave {policy_error:.6}°): {}, {} slots read, {} tables",
                n, s.found.how, s.found.slots, s.found.evaluated
            );
        }
        let twin = (c.twin_encode)(glam::Vec3::from(n));
        if (c.reference_decode)(s.code) != (c.reference_decode)(twin) {
            row.searched_code_step = row.searched_code_step.max(code_step(c, s.code, twin));
        }
        let (len, _) = length_check(&[s.decoded], 0.0);
        let finite = s.decoded.iter().all(|x| x.is_finite());
        row.searched_len_error =
            row.searched_len_error
                .max(if finite { len } else { f64::INFINITY });
    }
    Ok(())
}

/// One linear-depth path's published figures.
#[derive(Clone, Debug)]
pub struct LinearFigures {
    /// The function.
    pub function: &'static str,
    /// Worst ULP error on the adapter ([`super::linear_depth::sampled_worst`]).
    pub adapter: f64,
    /// Worst ULP error under any of the policies.
    pub emulated: f64,
    /// Where that worst error is: the policy and the input.
    pub emulated_at: String,
    /// The worst error the search found ([`super::linear_depth::searched_worst`], at the
    /// inputs the policies erred most on).
    pub searched: f64,
    /// Where, with the search's record (how it was found, slots read, tables evaluated).
    pub searched_at: String,
    /// Over the searched inputs: the fewest and most table slots an evaluation read, and
    /// whether every input was searched exhaustively (every assignment of those slots).
    pub searched_slots: (u32, u32, bool),
    /// The machine-derived bound: the largest error any conforming adapter can make, from the
    /// interval enclosure of every allowed result ([`super::linear_depth::machine_worst`]:
    /// the policies' sample at a stride, and every searched input).
    pub machine: f64,
    /// Where the machine-derived bound is largest.
    pub machine_at: String,
    /// Inputs where the emulation (a policy or the search) erred more than the enclosure
    /// allows: each would be a flaw of the evaluator or of the emulation. Empty when sound.
    pub machine_violations: Vec<String>,
    /// The bound where `+ − × /` are correctly rounded (`linear_depth::bounds`).
    pub bound_correctly_rounded: f64,
    /// The bound on every conforming adapter.
    pub bound_conforming: f64,
}

/// Inputs per path the search runs at in CI: the worst of every policy's sample.
pub const SEARCHED_INPUTS: usize = 32;

/// [`LinearFigures`] of every shipped path under each of `policies`, then searched at the
/// `searched_inputs` inputs those policies erred most on (each policy's `searched_inputs / 2`
/// worst, pooled), with the machine-derived bound.
pub fn linear_depth_figures(
    gpu: &Gpu,
    policies: &[crate::conforming::Policy],
    searched_inputs: usize,
) -> Result<Vec<LinearFigures>, HarnessError> {
    linear_depth_figures_with(gpu, policies, searched_inputs, MachineBound::Derive)
}

/// Whether [`linear_depth_figures_with`] derives the machine bound (the interval enclosure
/// over the policies' sample and the searched inputs: about two CPU-seconds per path).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MachineBound {
    /// Derive it: [`LinearFigures::machine`], `machine_at` and `machine_violations` filled.
    Derive,
    /// Leave it out (a report that does not show it): `machine` is NaN, `machine_at` says it
    /// was not derived, `machine_violations` is empty.
    Skip,
}

/// [`linear_depth_figures`], deriving the machine bound or not.
pub fn linear_depth_figures_with(
    gpu: &Gpu,
    policies: &[crate::conforming::Policy],
    searched_inputs: usize,
    machine_bound: MachineBound,
) -> Result<Vec<LinearFigures>, HarnessError> {
    use super::linear_depth::{PATHS, sampled_worst, searched_worst, worst_inputs};
    use crate::conforming::EmulatedKernel;
    use crate::conforming::search::SearchConfig;
    let mut rows = Vec::new();
    for path in &PATHS {
        let (cr, conf, _) =
            crate::linear_depth::bounds::of(path.function).expect("every shipped path has a bound");
        let k = gpu.kernel(crate::wgsl::LINEAR_DEPTH, path.function)?;
        let adapter = sampled_worst(path, &|a, n| Ok(k.run(a, n)?.into_f32()))?.0;
        let (mut emulated, mut emulated_at) = (0.0f64, String::new());
        let mut pool = Vec::new();
        for &policy in policies {
            let k = EmulatedKernel::new(
                gpu,
                crate::wgsl::LINEAR_DEPTH,
                path.function,
                &Emulation::new(policy),
            )?;
            let run = |a: &[crate::harness::Arg<'_>], n: u64| Ok(k.run(a, n)?.0.into_f32());
            let worst = worst_inputs(path, &run, searched_inputs.div_ceil(2))?;
            if let Some(w) = worst.first()
                && w.error > emulated
            {
                (emulated, emulated_at) = (w.error, format!("{policy}, {}", w.at));
            }
            pool.extend(worst);
        }
        // The pooled inputs, worst first, each once.
        pool.sort_by(|a, b| b.error.total_cmp(&a.error));
        let mut seen = std::collections::HashSet::new();
        pool.retain(|s| seen.insert((s.case.near.to_bits(), s.case.far.to_bits(), s.input_bits)));
        pool.truncate(searched_inputs);
        let found = searched_worst(gpu, path, &pool, &SearchConfig::default())?;
        let config = SearchConfig::default();
        let searched_slots = (
            found.iter().map(|f| f.slots).min().unwrap_or(0),
            found.iter().map(|f| f.slots).max().unwrap_or(0),
            found.iter().all(|f| f.slots <= config.exhaustive_slots),
        );
        let (mut searched, mut searched_at) = (0.0f64, String::new());
        for (f, s) in found.iter().zip(&pool) {
            if f.error >= searched {
                searched = f.error;
                searched_at = format!(
                    "at the input where a policy gave {} ({:.2} ULP): {}, {} slots read, {} tables",
                    s.at, s.error, f.how, f.slots, f.evaluated
                );
            }
        }
        let (machine, machine_at, machine_violations) = match machine_bound {
            MachineBound::Derive => machine_bound_of(path, &found, &pool)?,
            MachineBound::Skip => (
                f64::NAN,
                "not derived (MachineBound::Skip)".into(),
                Vec::new(),
            ),
        };
        rows.push(LinearFigures {
            function: path.function,
            adapter,
            emulated,
            emulated_at,
            searched,
            searched_at,
            searched_slots,
            machine,
            machine_at,
            machine_violations,
            bound_correctly_rounded: cr,
            bound_conforming: conf,
        });
    }
    Ok(rows)
}

/// The machine-derived bound of `path` ([`LinearFigures::machine`]): the interval enclosure's
/// worst over the policies' sample ([`super::linear_depth::machine_worst`]) and at every
/// searched input, where the emulation's error (a policy's or the search's, `found`) must lie
/// inside it; the inputs where it does not are returned as violations.
fn machine_bound_of(
    path: &super::linear_depth::Path,
    found: &[crate::conforming::search::Found],
    pool: &[super::linear_depth::SampledInput],
) -> Result<(f64, String, Vec<String>), HarnessError> {
    // The enclosure at every searched input must hold what the emulation gave there.
    let machine_err = |e: crate::conforming::interval::IntervalError| {
        HarnessError::Shader(format!("{}: interval evaluation: {e}", path.function))
    };
    let enclosure = crate::conforming::interval::Enclosure::new(crate::wgsl::LINEAR_DEPTH, true)
        .map_err(machine_err)?;
    let (mut machine, mut machine_at) =
        super::linear_depth::machine_worst(path, &enclosure).map_err(machine_err)?;
    let mut machine_violations = Vec::new();
    for (f, s) in found.iter().zip(pool) {
        let m =
            super::linear_depth::machine_error(path, &enclosure, s.input_bits, &s.case, &s.consts)
                .map_err(machine_err)?;
        if m > machine {
            (machine, machine_at) = (m, format!("searched input {}", s.at));
        }
        if f.error.max(s.error) > m {
            machine_violations.push(format!(
                "{}: policy {:.3} ULP, search {:.3} ULP, enclosure {m:.3} ULP",
                s.at, s.error, f.error
            ));
        }
    }
    Ok((machine, machine_at, machine_violations))
}
