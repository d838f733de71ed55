//! Whether the precise (hemi-)octahedral encoders pick the best of the four neighbouring codes.

use super::codecs::Codec;
use super::pool::par_fold;
use super::round_trip::RoundTrip;
use crate::precision::metrics::{angle_degrees, widen3};

/// How close the precise octahedral encoder's choices are to the best of the four neighbours.
#[derive(Clone, Copy, Debug, Default)]
pub struct Optimality {
    /// Largest `angle(chosen) − min over neighbours angle(neighbour)`, degrees (≤ 0 is optimal).
    pub worst_excess_deg: f64,
    /// Inputs whose code is not (one of) the f64-best of its neighbours.
    pub not_best: u64,
    /// Index of the input with the worst excess.
    pub argworst: u64,
}

/// The slack the precise encoder's choice may have over the best neighbour, in degrees: twice
/// its f32 score error (`(2√3 + 3)·2^-24` rad, see [`crate::normal::oct::encode_precise`]) plus twice the
/// decoder's rounding of each direction (`√2·2^-24` rad: only the final per-component
/// multiply turns the direction; the length's error does not).
pub fn optimality_tolerance_deg() -> f64 {
    let ulp = 2f64.powi(-24);
    (2.0 * (2.0 * 3f64.sqrt() + 3.0) * ulp + 2.0 * 2f64.sqrt() * ulp).to_degrees()
}

/// `sin²` of the angle between `a` and `b` in f64 (`|a×b|²/(|a|²|b|²)`): ranks small angles
/// as `angle_degrees` does, at a fraction of the cost.
fn sin2_f64(a: [f64; 3], b: [f64; 3]) -> f64 {
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    dot(c, c) / (dot(a, a) * dot(b, b))
}

/// Check every chosen code of a precise (hemi-)octahedral encoder against the four neighbours of
/// the input's exact (f64) continuous coordinates, each decoded as the shipped decoder does (the Rust twin, bit-identical to the
/// adapter's decoder — checked by [`round_trip`](super::round_trip())), all angles measured in f64. Neighbours are
/// ranked by f64 `sin²` (every error here is far below 90°); the excess is then measured with
/// [`angle_degrees`].
pub fn precise_optimality(codec: &Codec, inputs: &[[f32; 3]], rt: &RoundTrip) -> Optimality {
    let parts = par_fold(inputs.len(), |r| {
        let mut o = Optimality {
            worst_excess_deg: f64::NEG_INFINITY,
            ..Default::default()
        };
        for i in r {
            let n = widen3(inputs[i]);
            let chosen = widen3(rt.decoded[i]);
            let mut best = (f64::INFINITY, chosen);
            for p in super::decision::neighbours(codec, n) {
                let d = widen3((codec.twin_decode)(p).to_array());
                let s = sin2_f64(n, d);
                if s < best.0 {
                    best = (s, d);
                }
            }
            let excess = if sin2_f64(n, chosen) > best.0 {
                o.not_best += 1;
                angle_degrees(n, chosen) - angle_degrees(n, best.1)
            } else {
                0.0
            };
            if excess > o.worst_excess_deg {
                o.worst_excess_deg = excess;
                o.argworst = i as u64;
            }
        }
        o
    });
    parts.into_iter().fold(
        Optimality {
            worst_excess_deg: f64::NEG_INFINITY,
            ..Default::default()
        },
        |a, p| Optimality {
            not_best: a.not_best + p.not_best,
            ..if p.worst_excess_deg > a.worst_excess_deg {
                p
            } else {
                a
            }
        },
    )
}
