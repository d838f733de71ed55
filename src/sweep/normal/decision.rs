//! The precise (hemi-)octahedral encoders' choice among their four candidate codes on the
//! emulated worst adapter, searched on the decision margin rather than on the round-trip angle.
//!
//! Searched on the angle ([`super::searched_round_trip`]), the climb is flat wherever a slot's
//! flip leaves the chosen code as it is, which is almost everywhere: a flip of the choice needs
//! many roundings moved together. Here the function searched returns the four candidates'
//! scores themselves (each computed by the file's own `oct_try`, `oct_try_wide` at 16 bits or
//! `hemioct_try`, from the same sanitised input and the same `c00` as the encoder), so the
//! climb sees the margin between the best candidate and the runner-up move with every slot and
//! pushes it across zero. The inputs are built near the runner-up's tie, at graded distances, so
//! the search also finds how large an exact lead a conforming evaluation can overturn.
//!
//! Every table is a conforming evaluation of the scores the shipped encoder compares (its
//! `oct_try` calls differ only in the `best` operand of the final `select`, which no rounding
//! touches), so a choice found here is one some conforming adapter's encoder makes.

use super::codecs::Codec;
use crate::conforming::search::{self, DirectionTable, Found, SearchConfig};
use crate::conforming::{EmulatedKernel, Emulation, Policy};
use crate::harness::{Arg, Gpu, HarnessError, Output};
use crate::normal::{hemioct, oct};
use crate::precision::metrics::{angle_degrees, widen3};
use crate::wgsl::{NORMAL_HEMIOCT, NORMAL_OCT};

/// The function a decision search runs, appended to the codec's file by [`scores_source`]:
/// `fn(n: vec3<f32>, bits: u32) -> vec4<f32>`, the four candidates' scores in the encoder's
/// order (0,0), (1,0), (0,1), (1,1) with `bits` per axis (the hemi-octahedral file's is 12
/// and the signed octahedron's 10 whatever `bits` says), so oct16 and oct24 share one module;
/// each calls the `try` function its encoder calls (`oct_try`, `oct_try_wide` for oct32,
/// `hemioct_try`, `signed_oct_try`), and only that one,
/// so the emulated module is no larger than the encoder's.
pub const SCORES_FN: &str = "prepass_candidate_scores";

/// `codec`'s file with [`SCORES_FN`] appended, or `None` where `codec` is not a precise
/// (hemi-)octahedral encoder.
pub fn scores_source(codec: &Codec) -> Option<String> {
    if codec.name.ends_with("fast") {
        return None;
    }
    let scores = |call: &str| {
        let each: Vec<String> = ["0.0, 0.0", "1.0, 0.0", "0.0, 1.0", "1.0, 1.0"]
            .iter()
            .map(|off| call.replace("OFF", off))
            .collect();
        format!("vec4<f32>({})", each.join(", "))
    };
    let body = match codec.source {
        s if s == NORMAL_OCT => format!(
            "    let m = f32((1u << bits) - 1u);\n    let s = oct_sanitize(n).xyz;\n    \
             let c00 = floor(oct_continuous(s, m));\n    return {};\n",
            scores(if codec.bits == 32 {
                "oct_try_wide(s, c00, vec2<f32>(OFF), none).z"
            } else {
                "oct_try(s, m, c00, vec2<f32>(OFF), none).z"
            }),
        ),
        s if s == NORMAL_HEMIOCT => format!(
            "    let s = hemioct_sanitize(n);\n    \
             let c00 = floor(hemioct_continuous(s, 4095u));\n    return {};\n",
            scores("hemioct_try(s, c00, vec2<f32>(OFF), none).z"),
        ),
        s if s == crate::wgsl::NORMAL_SIGNED_OCT => format!(
            "    let s0 = signed_oct_sanitize(n);\n    let s = vec3<f32>(s0.xy, abs(s0.z));\n    \
             let c00 = floor(signed_oct_continuous(s0));\n    return {};\n",
            scores("signed_oct_try(s, c00, vec2<f32>(OFF), none).z"),
        ),
        _ => return None,
    };
    Some(format!(
        "{}\nfn {SCORES_FN}(n: vec3<f32>, bits: u32) -> vec4<f32> {{\n    \
         let none = vec3<f32>(0.0, 0.0, 3.0e38);\n{body}}}\n",
        codec.source
    ))
}

/// The four candidate codes of `n` (exact continuous coordinates), in the encoder's order.
pub(super) fn neighbours(codec: &Codec, n: [f64; 3]) -> [u32; 4] {
    if codec.source == crate::wgsl::NORMAL_SUBSTRATE {
        crate::normal::substrate::exact::neighbours(n)
    } else if codec.source == crate::wgsl::NORMAL_SIGNED_OCT {
        crate::normal::signed_oct::exact::neighbours(n)
    } else if codec.source == NORMAL_HEMIOCT {
        hemioct::exact::neighbours(n)
    } else {
        oct::exact::neighbours(n, codec.bits / 2)
    }
}

/// The exact continuous code coordinates of `n`.
fn continuous(codec: &Codec, n: [f64; 3]) -> [f64; 2] {
    if codec.source == crate::wgsl::NORMAL_SUBSTRATE {
        crate::normal::substrate::exact::continuous(n).map(|q| q + 1024.0)
    } else if codec.source == crate::wgsl::NORMAL_SIGNED_OCT {
        crate::normal::signed_oct::exact::continuous(n)
    } else if codec.source == NORMAL_HEMIOCT {
        hemioct::exact::continuous(n)
    } else {
        oct::exact::continuous(n, codec.bits / 2)
    }
}

/// The candidate the encoder picks from four scores: the first strictly smaller than every
/// earlier one, compared as floats (as `oct_try`'s `select` does), from +∞ (the WGSL starts
/// from 3·10^38; every score is below 48, so the first always replaces either).
pub fn chain_choice(scores: [f32; 4]) -> usize {
    let mut best = (usize::MAX, f32::INFINITY);
    for (k, &s) in scores.iter().enumerate() {
        if s < best.1 {
            best = (k, s);
        }
    }
    // No score below +∞ (none finite): the encoder keeps its start, code (0, 0) of c00.
    if best.0 == usize::MAX { 0 } else { best.0 }
}

/// One input of a decision search: the direction and its four candidates, exactly.
#[derive(Clone, Debug)]
pub struct DecisionInput {
    /// The input (f32, as the encoder receives it).
    pub n: [f32; 3],
    /// Its four candidate codes, in the encoder's order.
    pub codes: [u32; 4],
    /// Each candidate's exact angle to `n`, degrees.
    pub angles: [f64; 4],
    /// The closest candidate (the exact choice).
    pub best: usize,
    /// The runner-up.
    pub runner_up: usize,
}

impl DecisionInput {
    fn of(codec: &Codec, n: [f32; 3]) -> DecisionInput {
        let w = widen3(n);
        let codes = neighbours(codec, w);
        let angles = codes.map(|c| angle_degrees(w, (codec.reference_decode)(c)));
        let mut order = [0usize, 1, 2, 3];
        order.sort_by(|&a, &b| angles[a].total_cmp(&angles[b]));
        DecisionInput {
            n,
            codes,
            angles,
            best: order[0],
            runner_up: order[1],
        }
    }

    /// The runner-up's exact lead lost: how much farther it is than the best, degrees.
    pub fn gap(&self) -> f64 {
        self.angles[self.runner_up] - self.angles[self.best]
    }
}

/// Inputs near a tie of the precise encoder's best candidate with its runner-up, `cells` cells
/// of the code space (around spherical-Fibonacci directions, `z ≥ 0` for the hemisphere code)
/// times one input per lead in `gaps` (degrees). Per cell: the best candidate `a` of the cell's
/// direction, the great-circle path from `a`'s direction to the opposite corner's (where `a`
/// has lost the lead), and by bisection the points where `a` leads the nearest other candidate
/// by each gap, rounded to f32 (the published gap is the rounded input's, measured again).
///
/// Only inputs whose exact continuous coordinates lie at least 1/8 of a code from an integer
/// are kept: the encoder's `c00 = floor(continuous)` is then the exact one on every conforming
/// adapter (`oct_continuous` is two sums, a quotient, a fold, one fusable `·0.5 + 0.5` and a
/// scaling by M: within 16 ULP of the coordinate on any conforming adapter, at most
/// 16·2⁻²⁴·65,535 ≈ 0.06 code at oct32), so the scores the kernel returns are those of the
/// four candidates the host computed.
pub fn decision_inputs(codec: &Codec, cells: u32, gaps: &[f64]) -> Vec<DecisionInput> {
    let hemi = codec.source == NORMAL_HEMIOCT;
    let mut out = Vec::new();
    for r in super::fibonacci_directions(cells * if hemi { 2 } else { 1 }) {
        if hemi && r[2] < 0.0 {
            continue;
        }
        let start = DecisionInput::of(codec, r);
        let (a, corner) = (start.codes[start.best], start.codes[start.best ^ 3]);
        let (da, dc) = (
            (codec.reference_decode)(a),
            (codec.reference_decode)(corner),
        );
        let at = |t: f64| -> [f64; 3] {
            let v: [f64; 3] = std::array::from_fn(|i| (1.0 - t) * da[i] + t * dc[i]);
            let l = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            v.map(|x| x / l)
        };
        // a's lead over the nearest other candidate of a's cell at path position t.
        let lead = |t: f64| {
            let v = at(t);
            let codes = neighbours(codec, v);
            if !codes.contains(&a) {
                return f64::NEG_INFINITY;
            }
            let ang = |c: u32| angle_degrees(v, (codec.reference_decode)(c));
            let other = codes
                .iter()
                .filter(|&&c| c != a)
                .map(|&c| ang(c))
                .fold(f64::INFINITY, f64::min);
            other - ang(a)
        };
        for &gap in gaps {
            // lead(0) is the whole cell's margin, lead(1/2) ≤ 0 (the corner ties there).
            let (mut lo, mut hi) = (0.0, 0.5);
            if lead(lo) <= gap {
                continue;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if lead(mid) > gap {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let n = at(lo).map(|x| x as f32);
            let c = continuous(codec, widen3(n));
            if c.iter().all(|x| (x - x.round()).abs() >= 0.125) {
                out.push(DecisionInput::of(codec, n));
            }
        }
    }
    out
}

/// What the decision search found for one codec.
#[derive(Clone, Debug)]
pub struct SearchedDecision {
    /// Inputs searched.
    pub inputs: usize,
    /// Inputs where the search found a conforming evaluation choosing another candidate than
    /// the closest.
    pub flipped: usize,
    /// Inputs where one of the climb's start tables (the upper and lower policies and two
    /// seeded tables) already let the runner-up's score beat the best's.
    pub flipped_at_starts: usize,
    /// The largest exact excess of a chosen candidate over the closest, degrees (0 if none).
    pub worst_excess_deg: f64,
    /// The input of that excess.
    pub worst_at: Option<DecisionInput>,
    /// The smallest exact lead (degrees) the search could not overturn, among the inputs.
    pub smallest_lead_kept: f64,
    /// Fewest and most slots an evaluation read; tables evaluated in all.
    pub slots: (u32, u32),
    /// Tables evaluated.
    pub evaluated: usize,
}

/// The decision search for each `(codec, inputs)` job (precise encoders, see
/// [`scores_source`]): per input, the climb maximises the runner-up's score lead over the best
/// candidate's, relative to the best's (positive: the runner-up wins), then the choice at the
/// table found is read back and its exact excess measured. Jobs with one scores module share it
/// and one climb (oct16 and oct24 differ only in `bits`, an argument).
pub fn searched_decisions(
    gpu: &Gpu,
    jobs: &[(&Codec, Vec<DecisionInput>)],
    config: &SearchConfig,
) -> Result<Vec<SearchedDecision>, HarnessError> {
    let mut results = vec![None; jobs.len()];
    let sources: Vec<Option<String>> = jobs.iter().map(|(c, _)| scores_source(c)).collect();
    for (j, (first, _)) in jobs.iter().enumerate() {
        if results[j].is_some() {
            continue;
        }
        let group: Vec<usize> = (j..jobs.len())
            .filter(|&k| sources[k] == sources[j])
            .collect();
        let source = sources[j].as_deref().ok_or_else(|| {
            HarnessError::Shader(format!(
                "{}: not a precise (hemi-)octahedral encoder",
                first.name
            ))
        })?;
        let kernel =
            EmulatedKernel::new(gpu, source, SCORES_FN, &Emulation::new(Policy::Searched))?;
        let inputs: Vec<&DecisionInput> = group.iter().flat_map(|&k| &jobs[k].1).collect();
        let ns: Vec<[f32; 3]> = inputs.iter().map(|d| d.n).collect();
        let bits: Vec<u32> = group
            .iter()
            .flat_map(|&k| std::iter::repeat_n(jobs[k].0.bits / 2, jobs[k].1.len()))
            .collect();
        let args = [Arg::column(&ns), Arg::column(&bits)];
        let margin = |i: usize, out: &Output, e: usize| {
            let s = out.as_vec4()[e].map(f64::from);
            let d = inputs[i];
            let m = (s[d.best] - s[d.runner_up]) / s[d.best];
            if m.is_nan() { f64::INFINITY } else { m }
        };
        let found = search::climb(&kernel, &args, ns.len(), &margin, config)?;
        let plan: Vec<(usize, DirectionTable)> = found
            .iter()
            .enumerate()
            .map(|(i, f)| (i, f.table))
            .collect();
        let (out, _) = search::run_at(&kernel, &args, ns.len(), &plan)?;
        let mut at = 0;
        for &k in &group {
            let n = jobs[k].1.len();
            results[k] = Some(summarise(
                &jobs[k].1,
                &found[at..at + n],
                &out.as_vec4()[at..at + n],
            ));
            at += n;
        }
    }
    Ok(results
        .into_iter()
        .map(|r| r.expect("every job searched"))
        .collect())
}

/// One job's record from the climb's results and the scores at the tables found.
fn summarise(inputs: &[DecisionInput], found: &[Found], scores: &[[f32; 4]]) -> SearchedDecision {
    let mut r = SearchedDecision {
        inputs: inputs.len(),
        flipped: 0,
        flipped_at_starts: found.iter().filter(|f| f.start_error > 0.0).count(),
        worst_excess_deg: 0.0,
        worst_at: None,
        smallest_lead_kept: f64::INFINITY,
        slots: (
            found.iter().map(|f| f.slots).min().unwrap_or(0),
            found.iter().map(|f| f.slots).max().unwrap_or(0),
        ),
        evaluated: found.iter().map(|f| f.evaluated).sum(),
    };
    for (d, v) in inputs.iter().zip(scores) {
        let chosen = chain_choice(*v);
        let excess = d.angles[chosen] - d.angles[d.best];
        if chosen == d.best {
            r.smallest_lead_kept = r.smallest_lead_kept.min(d.gap());
        } else {
            r.flipped += 1;
        }
        if excess > r.worst_excess_deg {
            r.worst_excess_deg = excess;
            r.worst_at = Some(d.clone());
        }
    }
    r
}
