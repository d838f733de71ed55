//! The round trip on the emulated worst adapter, searched: the encoder and the decoder run as
//! one function under [`Policy::Searched`], so [`search::climb`] chooses the encoder's
//! roundings (and so its choice among candidate codes) together with the decoder's.

use super::codecs::Codec;
use crate::conforming::search::{self, DirectionTable, Found, SearchConfig};
use crate::conforming::{EmulatedKernel, Emulation, Policy};
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{angle_degrees, widen3};

/// The function a searched round trip runs, appended to the codec's file by
/// [`round_trip_source`]: `vec4(decode(c), bitcast<f32>(c))` with `c = encode(n)`, so one
/// result carries the decoded direction and the code the encoder chose.
pub const ROUND_TRIP_FN: &str = "prepass_round_trip";

/// The code and the decoded direction in one result of [`ROUND_TRIP_FN`].
pub fn round_trip_parts(v: [f32; 4]) -> (u32, [f32; 3]) {
    (v[3].to_bits(), [v[0], v[1], v[2]])
}

/// `codec`'s file with [`ROUND_TRIP_FN`] appended.
pub fn round_trip_source(codec: &Codec) -> String {
    format!(
        "{}\nfn {ROUND_TRIP_FN}(n: vec3<f32>) -> vec4<f32> {{\n    let c = {}(n);\n    return vec4<f32>({}(c), bitcast<f32>(c));\n}}\n",
        codec.source, codec.encode, codec.decode
    )
}

/// What the search found at one input, with the result at the worst table.
#[derive(Clone, Debug)]
pub struct SearchedRoundTrip {
    /// The search's record (the error is the round-trip angle in degrees).
    pub found: Found,
    /// The code the encoder chose under the worst table.
    pub code: u32,
    /// The decoded direction under the worst table.
    pub decoded: [f32; 3],
}

/// The worst combination of ends for the round trip of each of `inputs` (directions, not
/// necessarily unit), measured as the angle to the input in degrees; a non-finite angle counts
/// as the largest error, so the search seeks it and the caller sees it.
pub fn searched_round_trip(
    gpu: &Gpu,
    codec: &Codec,
    inputs: &[[f32; 3]],
    config: &SearchConfig,
) -> Result<Vec<SearchedRoundTrip>, HarnessError> {
    let kernel = EmulatedKernel::new(
        gpu,
        &round_trip_source(codec),
        ROUND_TRIP_FN,
        &Emulation::new(Policy::Searched),
    )?;
    let args = [Arg::column(inputs)];
    let angle = |i: usize, v: [f32; 4]| {
        let a = angle_degrees(widen3(inputs[i]), widen3([v[0], v[1], v[2]]));
        if a.is_nan() { f64::INFINITY } else { a }
    };
    let error = |i: usize, out: &crate::harness::Output, e: usize| angle(i, out.as_vec4()[e]);
    let found = search::climb(&kernel, &args, inputs.len(), &error, config)?;
    let plan: Vec<(usize, DirectionTable)> = found
        .iter()
        .enumerate()
        .map(|(i, f)| (i, f.table))
        .collect();
    let (out, _) = search::run_at(&kernel, &args, inputs.len(), &plan)?;
    Ok(found
        .into_iter()
        .zip(out.as_vec4())
        .map(|(found, &v)| {
            let (code, decoded) = round_trip_parts(v);
            SearchedRoundTrip {
                found,
                code,
                decoded,
            }
        })
        .collect())
}
