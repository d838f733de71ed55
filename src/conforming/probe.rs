//! The host check: whether the adapter's `+ − ×` carry the emulation's error-free
//! transformations (feature `harness`).
//!
//! [`check_host`] passes on an adapter whose compiled helpers compute TwoSum's error term,
//! Dekker's product error, the fused `a·b + c` built from them, and subnormal differences and
//! products as a host rounding `+ − ×` to nearest, without contraction, reassociation or
//! flushing, computes them, at the inputs it tries; it fails with [`HarnessError::UnfitHost`],
//! naming the helper, the input, the value it came back with and the suspected freedom, where
//! one comes back different. Passing is evidence, not proof: a host that rewrites only some
//! expressions, or errs only at other inputs, can pass. Lavapipe (Mesa 22.3) passes
//! (`tests/conforming_probe.rs`). [`super::EmulatedKernel::new`] runs it, once per adapter and
//! process, before it builds any emulated module but the identity's.
//!
//! Fast2Sum, in the pack lanes' tie direction (`prepass_cf_pack_lane`), is probed but does not
//! refuse a host: where a compiler folds it, the lane keeps the host's integer, one the spec
//! allows, and the emulation only reaches less of the tie freedom. [`check_host_with`] returns
//! it as a note. Lavapipe folds it: `(−c) − (t − hi)` with `t = hi − c` comes back 0 (measured,
//! Mesa 22.3.6), so the emulated `pack4x8snorm` and 16-bit pack ties keep lavapipe's integer
//! (`core.wgsl` allows for this at the helper).
//!
//! Why: the emulation finds the either-neighbour rounding of `+ − ×` with error-free
//! transformations (Knuth's TwoSum, Dekker's split product) and builds the fused `a·b + c` from
//! them (`core.wgsl`); each is exact only where its operations are rounded to nearest as
//! written. A contracting host turns the fused construction's `p + c` of `p = a·b` into
//! `fma(a, b, c)`, after which TwoSum's error term no longer fits its sum (measured on the CPU
//! with a twin of the helper: 45 % of random inputs in [1, 2) came back one float off); a
//! reassociating one folds `(a − (s − bb)) + (b − bb)` or Dekker's split `ca − (ca − a)` to
//! what real arithmetic gives (0, or `a`); a flushing one loses the subnormal results the flush
//! emulation reads. The emulation's results would then leave the spec's intervals with no
//! error raised.
//!
//! Lavapipe is no such host in general: its compiler applies inexact algebraic rules where it
//! recognises the pattern (the Fast2Sum above) and fuses a product used once into the sum it
//! feeds (measured: the cross terms `x.x * y.y + x.y * y.x` of `prepass_cf_df_mul` come back
//! rounded once). The helpers are written so that neither touches what must be exact (their
//! products that feed a sum are exact or used twice, their sums read through a run-time
//! scaling), and contracting an inexact product elsewhere, as in those cross terms, only makes
//! a double-f32 reference more accurate. That is why the probe runs the helpers as shipped
//! rather than bare `a·b + c`, which lavapipe would fail.
//!
//! How: `probe.wgsl` is appended to the searched policy's prelude and `core.wgsl`, and runs the
//! shipped helpers with its inputs as columns and the table wrappers' run-time mode
//! (`prepass_cf_opaque` reads it), as an emulated kernel feeds them: the host's compiler can
//! constant-fold nothing. One pipeline, one dispatch of seven elements. Each case's result is
//! computed here exactly, as sums and products of f32 values in f64 where the inputs make them
//! exact (asserted), rounded to f32 once. `tests/conforming_probe.rs` checks that models of a
//! contracting, a reassociating and a flushing host are refused with the right helper named.

use super::{CORE_WGSL, Emulation, Policy};
use crate::harness::{Arg, Gpu, HarnessError};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// The probe's WGSL (`probe.wgsl`); not valid on its own, see [`probe_source`].
pub const PROBE_WGSL: &str = include_str!("probe.wgsl");

/// The probe's function in [`probe_source`]: `(kind: u32, x: vec4<f32>, dirs: u32,
/// mode: vec4<u32>) -> vec2<f32>`.
pub const PROBE_FUNCTION: &str = "prepass_cf_probe";

/// The probe module [`check_host`] runs: the searched policy's constants, the helper library
/// [`CORE_WGSL`] as shipped, and [`PROBE_WGSL`]. [`check_host_with`] takes it, or a variant of
/// it (a test's model of a contracting host), as its source.
pub fn probe_source() -> String {
    let mut s = Emulation::new(Policy::Searched).prelude();
    s.push_str(CORE_WGSL);
    s.push('\n');
    s.push_str(PROBE_WGSL);
    s
}

/// What a host that gets a case wrong is suspected of.
#[derive(Clone, Copy)]
enum Suspect {
    Contracts,
    Reassociates,
    Flushes,
}

impl Suspect {
    fn says(self) -> &'static str {
        match self {
            Suspect::Contracts => "contracts a·b + c into a fused multiply-add",
            Suspect::Reassociates => "reassociates or algebraically simplifies + and −",
            Suspect::Flushes => "flushes subnormal results to zero",
        }
    }
}

/// One probe element: `probe.wgsl`'s `kind`, `x` and `dirs`, and the two lanes a host rounding
/// to nearest returns.
struct Case {
    kind: u32,
    x: [f32; 4],
    dirs: u32,
    expected: [f32; 2],
    /// The helper the case runs.
    helper: &'static str,
    /// What each result lane is.
    lanes: [&'static str; 2],
    /// The inputs as the message names them: (name, lane of `x`).
    inputs: &'static [(&'static str, usize)],
    suspect: Suspect,
    /// Whether a wrong result refuses the host; otherwise it is a note (the emulation falls
    /// back to an allowed result there, and only reaches less of the spec's freedom).
    refuses: bool,
}

/// `x + y` in f64, asserted exact (Knuth's TwoSum error is 0): the probe's inputs are chosen so.
fn exact_sum(x: f64, y: f64) -> f64 {
    let s = x + y;
    let bb = s - x;
    let err = (x - (s - bb)) + (y - bb);
    assert!(
        err == 0.0,
        "probe case: {x:e} + {y:e} is not exact in f64; choose other inputs"
    );
    s
}

/// `x` as f32, asserted exact.
fn exact_f32(x: f64) -> f32 {
    let r = x as f32;
    assert!(r as f64 == x, "probe case: {x:e} is not an f32");
    r
}

/// The f32 neighbours `(below, above)` of `x`, which no f32 equals.
fn f32_around(x: f64) -> (f32, f32) {
    let r = x as f32;
    assert!(
        r as f64 != x,
        "probe case: {x:e} is an f32: no two neighbours to choose between"
    );
    let step = |v: f32, up: bool| {
        let b = v.to_bits();
        f32::from_bits(if (v > 0.0) == up { b + 1 } else { b - 1 })
    };
    if (r as f64) < x {
        (r, step(r, true))
    } else {
        (step(r, false), r)
    }
}

/// TwoSum of `a + b`: the rounded sum and its exact error.
fn two_sum(a: f32, b: f32) -> [f32; 2] {
    let exact = exact_sum(a as f64, b as f64);
    let s = exact as f32;
    [s, exact_f32(exact_sum(exact, -(s as f64)))]
}

/// The cases, each with the result a host rounding to nearest gives.
fn cases() -> Vec<Case> {
    let ab = &[("a", 0), ("b", 1)];
    let mut cases = Vec::new();
    // TwoSum: the error of 1e8 + 0.3 is 0.3 (the sum rounds to 1e8); a host that simplifies
    // (a − (s − bb)) + (b − bb) to a + b − s gives 0. The second pair is below 2^-60, where
    // prepass_cf_add_err scales first.
    for (a, b) in [(1.0e8f32, 0.3f32), (1.0e-20, 3.0e-28)] {
        cases.push(Case {
            kind: 0,
            x: [a, b, 0.0, 0.0],
            dirs: 0,
            expected: two_sum(a, b),
            helper: "prepass_cf_two_sum",
            lanes: ["the sum", "TwoSum's error term"],
            inputs: ab,
            suspect: Suspect::Reassociates,
            refuses: true,
        });
    }
    // Dekker: 1e-4 · 16777215 (the product lavapipe's compiler got wrong with a literal
    // operand, core.wgsl); a host that folds the splits ca − (ca − a) to a and cb − (cb − b)
    // to b gives 0.
    let (a, b) = (1.0e-4f32, 16_777_215.0f32);
    let p = a * b;
    cases.push(Case {
        kind: 1,
        x: [a, b, 0.0, 0.0],
        dirs: 0,
        expected: [p, exact_f32(exact_sum(a as f64 * b as f64, -(p as f64)))],
        helper: "prepass_cf_mul_err",
        lanes: ["the product", "Dekker's product error"],
        inputs: ab,
        suspect: Suspect::Reassociates,
        refuses: true,
    });
    // Fast2Sum in a pack lane: 32767·c just off the tie n + 1/2, so its two f32 neighbours
    // round half up to n and n + 1; the direction table picks the upper (all ones) or the lower.
    // A host that folds (−c) − (t − hi) to 0 returns the same byte for both.
    let (s2, n) = (32768.0f32, 12345.0f64);
    let mut c = ((n + 0.5) / (s2 as f64 - 1.0)) as f32;
    if (s2 as f64 - 1.0) * c as f64 >= n + 0.5 {
        // One step of c moves 32767·c by just under one of its f32 steps: below the tie.
        c = f32::from_bits(c.to_bits() - 1);
    }
    let (below, above) = f32_around((s2 as f64 - 1.0) * c as f64);
    let byte = |t: f32| (t as f64 + 0.5).floor() as f32;
    assert!(
        byte(below) != byte(above),
        "probe case: 32767·{c:e} is no tie"
    );
    for (dirs, t, lane) in [
        (u32::MAX, above, "the pack lane's upper integer"),
        (0, below, "the pack lane's lower integer"),
    ] {
        cases.push(Case {
            kind: 3,
            x: [c, s2, 0.0, 0.0],
            dirs,
            expected: [byte(t), 0.0],
            helper: "prepass_cf_pack_lane, Fast2Sum",
            lanes: [lane, "the unused lane"],
            inputs: &[("c", 0), ("s2", 1)],
            suspect: Suspect::Reassociates,
            refuses: false,
        });
    }
    // Subnormal results: 1.75·2^-126 − 1.5·2^-126 (a difference, through TwoSum) and
    // 1.5·2^-70 · 1.25·2^-60 (a product), both exact subnormals.
    let (a, b) = (f32::from_bits(0x00e0_0000), -f32::from_bits(0x00c0_0001));
    cases.push(Case {
        kind: 0,
        x: [a, b, 0.0, 0.0],
        dirs: 0,
        expected: [exact_f32(exact_sum(a as f64, b as f64)), 0.0],
        helper: "prepass_cf_two_sum",
        lanes: ["the subnormal difference", "TwoSum's error term"],
        inputs: ab,
        suspect: Suspect::Flushes,
        refuses: true,
    });
    let (a, b) = (1.5 * 2f32.powi(-70), 1.25 * 2f32.powi(-60));
    cases.push(Case {
        kind: 1,
        x: [a, b, 0.0, 0.0],
        dirs: 0,
        expected: [exact_f32(a as f64 * b as f64), 0.0],
        helper: "prepass_cf_mul's a·b",
        lanes: ["the subnormal product", "Dekker's product error"],
        inputs: ab,
        suspect: Suspect::Flushes,
        refuses: true,
    });
    // The composite of the transformations above, last: where one of those fails, the first
    // failure a refusal names is the transformation itself. The fused a·b + c, rounded once; a host that contracts its p + c returns the float below.
    let (a, b, c) = (1.577_255_7f32, 1.438_026_8f32, -1.822_803_6f32);
    cases.push(Case {
        kind: 2,
        x: [a, b, c, 0.0],
        dirs: 0,
        expected: [exact_sum(a as f64 * b as f64, c as f64) as f32, 0.0],
        helper: "prepass_cf_fused",
        lanes: ["the fused a·b + c", "the unused lane"],
        inputs: &[("a", 0), ("b", 1), ("c", 2)],
        suspect: Suspect::Contracts,
        refuses: true,
    });
    cases
}

/// `x` as `1e8 (0x4cbebc20)`.
fn show(x: f32) -> String {
    format!("{x:e} ({:#010x})", x.to_bits())
}

/// Run the probe module `source` ([`probe_source`] or a variant of it) on `gpu`, uncached.
///
/// `Ok` with the notes where every case the emulation's correctness rests on comes back as a
/// host rounding `+ − ×` to nearest gives it: a note names a case whose helper falls back to an
/// allowed result on this host and so reaches less of the spec's freedom (the pack lanes'
/// Fast2Sum: lavapipe's compiler folds it, and the emulated `pack4x8snorm` and 16-bit pack ties
/// then keep the host's integer). [`HarnessError::UnfitHost`] naming the first case that does
/// not (its result lane, helper, inputs, the value it came back with and the suspected
/// freedom; further failures follow), and the harness's own error where the module does not
/// compile or run.
pub fn check_host_with(gpu: &Gpu, source: &str) -> Result<Vec<String>, HarnessError> {
    let cases = cases();
    let kind: Vec<u32> = cases.iter().map(|c| c.kind).collect();
    let x: Vec<[f32; 4]> = cases.iter().map(|c| c.x).collect();
    let dirs: Vec<u32> = cases.iter().map(|c| c.dirs).collect();
    let out = gpu.kernel(source, PROBE_FUNCTION)?.run(
        &[
            Arg::column(&kind),
            Arg::column(&x),
            Arg::column(&dirs),
            Arg::Splat([0; 4]),
        ],
        cases.len() as u64,
    )?;
    let (mut failures, mut notes) = (Vec::new(), Vec::new());
    for (case, got) in cases.iter().zip(out.as_vec2()) {
        // Compared as values: a zero of either sign is the same zero.
        let Some(k) = (0..2).find(|&k| got[k] != case.expected[k]) else {
            continue;
        };
        let inputs: Vec<String> = case
            .inputs
            .iter()
            .map(|&(name, lane)| format!("{name} = {}", show(case.x[lane])))
            .collect();
        let table = match (case.kind, case.dirs) {
            (3, 0) => ", direction table all zeros",
            (3, _) => ", direction table all ones",
            _ => "",
        };
        let what = format!(
            "{} ({}) came back {} at {}{table}, where + − × rounded to nearest give {}",
            case.lanes[k],
            case.helper,
            show(got[k]),
            inputs.join(", "),
            show(case.expected[k]),
        );
        if case.refuses {
            failures.push((case.suspect, what));
        } else {
            notes.push(format!(
                "{what}: the host {}, and the helper falls back to the host's result there, \
                 one the spec allows, so the emulation reaches less of that freedom",
                case.suspect.says()
            ));
        }
    }
    let Some((suspect, first)) = failures.first() else {
        return Ok(notes);
    };
    let mut message = format!(
        "the host adapter {} {} ({first}): the conforming emulation needs + − × rounded to \
         nearest without contraction, reassociation or flushing (src/conforming/core.wgsl); \
         run it on an adapter that rounds so, such as Mesa's lavapipe \
         (PREPASS_ADAPTER=llvmpipe)",
        gpu.describe(),
        suspect.says(),
    );
    for (suspect, more) in &failures[1..] {
        message.push_str(&format!("; also, as if it {}: {more}", suspect.says()));
    }
    Err(HarnessError::UnfitHost(message))
}

/// [`check_host_with`] of [`probe_source`] (its notes dropped), run once per adapter (by
/// [`Gpu::describe`]: name, kind, backend and driver) and process; the verdict is kept, a
/// harness error is returned and tried again next time. On lavapipe the first call compiles and
/// runs one pipeline (see `tests/conforming_probe.rs` for its measured cost); later calls cost a
/// map look-up.
pub fn check_host(gpu: &Gpu) -> Result<(), HarnessError> {
    type Verdict = Arc<Mutex<Option<Result<(), String>>>>;
    static VERDICTS: OnceLock<Mutex<HashMap<String, Verdict>>> = OnceLock::new();
    let cell = VERDICTS
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .entry(gpu.describe())
        .or_default()
        .clone();
    // Held while the probe runs: a second thread waits for this verdict instead of compiling
    // the probe again.
    let mut verdict = cell.lock().unwrap_or_else(|p| p.into_inner());
    if verdict.is_none() {
        *verdict = match check_host_with(gpu, &probe_source()) {
            Ok(_notes) => Some(Ok(())),
            Err(HarnessError::UnfitHost(m)) => Some(Err(m)),
            Err(e) => return Err(e),
        };
    }
    match verdict.as_ref() {
        Some(Err(m)) => Err(HarnessError::UnfitHost(m.clone())),
        _ => Ok(()),
    }
}
