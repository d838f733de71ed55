//! Sweeps for the normal encodings (`wgsl/normal_*.wgsl`): round-trip angular error over a
//! direction set, exhaustive and stratified decoder checks, the precise encoder's optimality,
//! a streaming sweep of all 2^32 oct32 codes, and the Killzone xy-FP16 "myth" numbers.
//! The tests assert on these; `errplot` and `examples/normal_tables.rs` tabulate them.
//!
//! One concern a file: [`CODECS`] (the encodings), the input generators, the worker pool, and
//! one file per sweep; everything public is re-exported here.

mod codecs;
mod decision;
mod decoder;
mod inputs;
pub mod interop;
mod myth;
mod optimality;
mod pool;
mod round_trip;
mod searched;
mod unorm;

pub use codecs::{
    BEST_FIT_SAMPLE, CODECS, Codec, Lane, LaneKind, PRECISE_SAMPLE, ROUNDING_DEFAULT_TIER_SAMPLE,
    codec, default_tier_sample,
};
pub use decision::{
    DecisionInput, SCORES_FN, SearchedDecision, chain_choice, decision_inputs, scores_source,
    searched_decisions,
};
pub use decoder::{
    DecoderCheck, decode_all_32, decode_angle_deg, decode_codes, decode_codes_with, decode_range,
};
pub use inputs::{
    adversarial_directions, bad_inputs, fibonacci_directions, near_tie_directions,
    stratified_codes32,
};
pub use myth::{Myth, killzone_myth};
pub use optimality::{Optimality, optimality_tolerance_deg, precise_optimality};
pub use round_trip::{
    RoundTrip, Runner, UNIT_TOLERANCE, reference_error, round_trip, round_trip_measured,
    round_trip_with,
};
pub use searched::{
    ROUND_TRIP_FN, SearchedRoundTrip, round_trip_parts, round_trip_source, searched_round_trip,
};
pub use unorm::{RenderTarget, UnormForms, render_target_forms, unorm_forms};
