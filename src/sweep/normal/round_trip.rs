//! Round trips through an encoding on the adapter, measured against the inputs and the Rust
//! twins, and the f64 reproduction of the same algorithm.

use super::codecs::Codec;
use super::pool::par_fold;
use crate::harness::{Arg, Gpu, HarnessError, Output};
use crate::precision::metrics::{ErrorStats, Mismatches, angle_degrees, widen3};
use glam::Vec3;

/// What one encoding did to a set of directions, encoded and decoded on the adapter.
#[derive(Clone, Debug)]
pub struct RoundTrip {
    /// Angle in degrees between each input (widened to f64) and its decoded vector.
    pub error: ErrorStats,
    /// The same restricted to inputs with `z ≥ 0` (the hemisphere xy FP16 can represent).
    pub error_upper: ErrorStats,
    /// Codes where the Rust encoder differs from the adapter's.
    pub twin_encode: Mismatches<u32>,
    /// Decoded vectors (bits) where the Rust decoder differs from the adapter's.
    pub twin_decode: Mismatches<u32>,
    /// Decoded vectors whose length is off 1 by more than [`UNIT_TOLERANCE`] or not finite.
    pub not_unit: u64,
    /// The adapter's codes, in input order.
    pub codes: Vec<u32>,
    /// The adapter's decoded vectors, in input order.
    pub decoded: Vec<[f32; 3]>,
}

pub use crate::normal::UNIT_TOLERANCE;

pub(super) fn is_unit(v: [f32; 3]) -> bool {
    let l = widen3(v).iter().map(|x| x * x).sum::<f64>().sqrt();
    l.is_finite() && (l - 1.0).abs() <= UNIT_TOLERANCE
}

/// Encode every input with `codec`'s WGSL encoder, decode with its WGSL decoder, and measure
/// against the input and against the Rust twins.
pub fn round_trip(
    gpu: &Gpu,
    codec: &Codec,
    inputs: &[[f32; 3]],
) -> Result<RoundTrip, HarnessError> {
    let (encode, decode) = (
        gpu.kernel(codec.source, codec.encode)?,
        gpu.kernel(codec.source, codec.decode)?,
    );
    round_trip_with(codec, inputs, &|a, n| encode.run(a, n), &|a, n| {
        decode.run(a, n)
    })
}

/// A batch runner: the arguments and the element count in, the results out.
pub type Runner<'a> = dyn Fn(&[Arg<'_>], u64) -> Result<Output, HarnessError> + 'a;

/// [`round_trip`] with the encoder and decoder given as runners (an emulated module's kernels,
/// say), measured the same way against `codec`'s twins.
pub fn round_trip_with(
    codec: &Codec,
    inputs: &[[f32; 3]],
    encode: &Runner<'_>,
    decode: &Runner<'_>,
) -> Result<RoundTrip, HarnessError> {
    let n = inputs.len() as u64;
    let codes = encode(&[Arg::column(inputs)], n)?.into_words();
    let decoded = decode(&[Arg::column(&codes)], n)?.as_vec3().to_vec();
    Ok(round_trip_measured(codec, inputs, codes, decoded))
}

/// A round trip already run (the codes an encoder chose for `inputs`, in order, and the
/// vectors its decoder gave for them), measured as [`round_trip`] measures: against the inputs
/// and against `codec`'s twins. For runs where encoder and decoder are one function (the
/// emulated round trip, [`super::round_trip_source`]).
pub fn round_trip_measured(
    codec: &Codec,
    inputs: &[[f32; 3]],
    codes: Vec<u32>,
    decoded: Vec<[f32; 3]>,
) -> RoundTrip {
    assert_eq!(
        (codes.len(), decoded.len()),
        (inputs.len(), inputs.len()),
        "one code and one decoded vector per input"
    );
    let parts = par_fold(inputs.len(), |r| {
        let base = r.start as u64;
        let mut e = ErrorStats::default();
        let mut up = ErrorStats::default();
        let mut not_unit = 0;
        for i in r.clone() {
            let a = angle_degrees(widen3(inputs[i]), widen3(decoded[i]));
            e.add(i as u64, a);
            if inputs[i][2] >= 0.0 {
                up.add(i as u64, a);
            }
            not_unit += u64::from(!is_unit(decoded[i]));
        }
        let enc = Mismatches::count(&codes[r.clone()], |k| {
            (codec.twin_encode)(Vec3::from(inputs[r.start + k]))
        });
        let dec_bits: Vec<u32> = decoded[r.clone()]
            .iter()
            .flatten()
            .map(|x| x.to_bits())
            .collect();
        // Lanes come in order: each code is decoded once, for its three lanes.
        let mut twin = (usize::MAX, [0u32; 3]);
        let dec = Mismatches::count(&dec_bits, |k| {
            if twin.0 != k / 3 {
                let v = (codec.twin_decode)(codes[r.start + k / 3]);
                twin = (k / 3, v.to_array().map(f32::to_bits));
            }
            twin.1[k % 3]
        });
        (base, e, up, not_unit, enc, dec)
    });
    let mut rt = RoundTrip {
        error: ErrorStats::default(),
        error_upper: ErrorStats::default(),
        twin_encode: Mismatches::default(),
        twin_decode: Mismatches::default(),
        not_unit: 0,
        codes,
        decoded,
    };
    for (base, e, up, nu, enc, dec) in parts {
        rt.error.merge(&e);
        rt.error_upper.merge(&up);
        rt.not_unit += nu;
        rt.twin_encode.merge(enc, base);
        rt.twin_decode.merge(dec, base * 3);
    }
    rt
}

/// The f64 reproduction of `codec`'s algorithm on the same inputs: reference encoder, exact
/// decode, angle to the input: the row the published targets are compared with.
pub fn reference_error(codec: &Codec, inputs: &[[f32; 3]]) -> ErrorStats {
    let parts = par_fold(inputs.len(), |r| {
        let mut e = ErrorStats::default();
        for i in r {
            let n = widen3(inputs[i]);
            e.add(
                i as u64,
                angle_degrees(n, (codec.reference_decode)((codec.reference_encode)(n))),
            );
        }
        e
    });
    parts.iter().fold(ErrorStats::default(), |mut a, p| {
        a.merge(p);
        a
    })
}
