//! Decoders run over ranges or lists of codes (up to all 2^32), checked for unit length,
//! angle to the exact direction, and agreement with the Rust twin.

use super::codecs::Codec;
use super::pool::par_fold;
use super::round_trip::is_unit;
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{Mismatches, angle_degrees, widen3};

/// How far a decoded vector may turn from its code's exact direction on a correctly rounded
/// adapter, in degrees: every decoder here normalises an exact integer vector `D`, so only
/// the final per-component quotient's rounding (`u = 2^-24` relative each) turns it, by at most
/// `√2·u` rad; plus `1e-12°` for the f64 angle's own rounding (about `1e-15°`).
pub fn decode_angle_deg() -> f64 {
    (2f64.sqrt() * 2f64.powi(-24)).to_degrees() + 1e-12
}

/// A decoder run over a set of codes.
#[derive(Clone, Debug, Default)]
pub struct DecoderCheck {
    /// Codes decoded.
    pub codes: u64,
    /// Results not finite or with `|len − 1|` above [`UNIT_TOLERANCE`](super::UNIT_TOLERANCE).
    pub not_unit: u64,
    /// Largest `|len − 1|` seen (f64 length of the f32 result).
    pub max_len_error: f64,
    /// Largest angle (degrees) between a result and the code's exact direction.
    pub max_angle_deg: f64,
    /// Results (bits) where the Rust twin differs.
    pub twin: Mismatches<u32>,
}

impl DecoderCheck {
    /// Fold in another part's results (its twin mismatch indices already absolute).
    pub fn merge(&mut self, p: DecoderCheck) {
        self.codes += p.codes;
        self.not_unit += p.not_unit;
        self.max_len_error = self.max_len_error.max(p.max_len_error);
        self.max_angle_deg = self.max_angle_deg.max(p.max_angle_deg);
        self.twin.merge(p.twin, 0);
    }

    /// Check one chunk of results (`out[k]` decoded from `code(k)`), on every core.
    fn add(
        &mut self,
        codec: &Codec,
        code: impl Fn(u64) -> u32 + Sync,
        out: &[[f32; 3]],
        base: u64,
    ) {
        for part in par_fold(out.len(), |r| {
            let mut c = DecoderCheck {
                codes: r.len() as u64,
                ..Default::default()
            };
            for k in r {
                let (p, v) = (code(k as u64), out[k]);
                let l = widen3(v).iter().map(|x| x * x).sum::<f64>().sqrt();
                c.not_unit += u64::from(!is_unit(v));
                if l.is_finite() {
                    c.max_len_error = c.max_len_error.max((l - 1.0).abs());
                }
                let a = angle_degrees(widen3(v), (codec.reference_decode)(p));
                c.max_angle_deg = c
                    .max_angle_deg
                    .max(if a.is_nan() { f64::INFINITY } else { a });
                let t = (codec.twin_decode)(p).to_array();
                c.twin.total += 1;
                if t.map(f32::to_bits) != v.map(f32::to_bits) {
                    c.twin.count += 1;
                    if c.twin.first.len() < 8 {
                        c.twin
                            .first
                            .push((base + k as u64, v[0].to_bits(), t[0].to_bits()));
                    }
                }
            }
            c
        }) {
            self.merge(part);
        }
    }
}

/// Decode `count` consecutive codes from `start` (streamed in chunks; `count` up to 2^32).
pub fn decode_range(
    gpu: &Gpu,
    codec: &Codec,
    start: u32,
    count: u64,
) -> Result<DecoderCheck, HarnessError> {
    let k = gpu.kernel(codec.source, codec.decode)?;
    let mut check = DecoderCheck::default();
    k.run_chunks(&[Arg::Index { start }], count, |first, out| {
        let s = start.wrapping_add(first as u32);
        check.add(codec, |i| s.wrapping_add(i as u32), out.as_vec3(), first);
        Ok(())
    })?;
    Ok(check)
}

/// [`decode_codes`] with the decoder given as a runner (an emulated module's kernel, say), in
/// one batch.
pub fn decode_codes_with(
    codec: &Codec,
    codes: &[u32],
    decode: &super::round_trip::Runner<'_>,
) -> Result<DecoderCheck, HarnessError> {
    let mut check = DecoderCheck::default();
    let out = decode(&[Arg::column(codes)], codes.len() as u64)?;
    check.add(codec, |i| codes[i as usize], out.as_vec3(), 0);
    Ok(check)
}

/// Decode the given codes with `codec`'s WGSL decoder and check them (see [`DecoderCheck`]);
/// results are streamed chunk by chunk.
pub fn decode_codes(gpu: &Gpu, codec: &Codec, codes: &[u32]) -> Result<DecoderCheck, HarnessError> {
    let k = gpu.kernel(codec.source, codec.decode)?;
    let mut check = DecoderCheck::default();
    k.run_chunks(&[Arg::column(codes)], codes.len() as u64, |first, out| {
        let f = first as usize;
        check.add(codec, |i| codes[f + i as usize], out.as_vec3(), first);
        Ok(())
    })?;
    Ok(check)
}

/// All 2^32 codes of `codec` (a 32-bit one: oct32 or xy fp16) through its WGSL decoder, streamed
/// (memory bounded by one chunk). Minutes on lavapipe: for `errplot`, not for the test suite.
pub fn decode_all_32(gpu: &Gpu, codec: &Codec) -> Result<DecoderCheck, HarnessError> {
    decode_range(gpu, codec, 0, 1u64 << 32)
}
