//! The host check of `prepass::conforming` (`src/conforming/probe.rs`): the shipped probe
//! passes on the test adapter, and models of hosts that contract, reassociate or flush (the
//! probe module with one helper line of `core.wgsl` rewritten as such a host would compile it)
//! are refused with a message naming the helper that came back wrong.

mod common;

use common::gpu;
use prepass::conforming::{
    EmulatedKernel, Emulation, Policy, check_host, check_host_with, probe_source,
};
use prepass::harness::HarnessError;
use std::time::Instant;

/// The probe module with `from` (which must occur exactly once: a `core.wgsl` that no longer
/// has the line fails here rather than testing nothing) replaced by `to`.
fn host_model(from: &str, to: &str) -> String {
    replace_once(probe_source(), from, to)
}

/// `source` with `from`, which must occur in it exactly once, replaced by `to`.
fn replace_once(source: String, from: &str, to: &str) -> String {
    assert_eq!(
        source.matches(from).count(),
        1,
        "`{from}` must occur once in the probe module (src/conforming/core.wgsl changed?)"
    );
    source.replace(from, to)
}

/// A fused multiply-add rounded once, for the model of a contracting host: WGSL's `fma` may
/// itself be evaluated unfused (lavapipe's is), so the model calls this copy of the shipped
/// fused construction, which rounds once at the probe's inputs (the real probe checks it).
const TRUE_FMA: &str = "
fn prepass_cf_probe_model_fma(a: f32, b: f32, c: f32) -> f32 {
    let p = a * b;
    let s = p + c;
    return s + (prepass_cf_add_err(p, c, s) + prepass_cf_mul_err(a, b, p));
}
";

/// [`host_model`] with [`TRUE_FMA`] appended.
fn contracting_model(from: &str, to: &str) -> String {
    host_model(from, to) + TRUE_FMA
}

#[test]
fn probe_passes_on_the_test_adapter_and_is_cheap() {
    let start = Instant::now();
    let notes = check_host_with(gpu(), &probe_source())
        .unwrap_or_else(|e| panic!("the test adapter {} fails the probe: {e}", gpu().describe()));
    let cold = start.elapsed();
    for n in &notes {
        eprintln!("probe note: {n}");
    }
    let start = Instant::now();
    check_host(gpu()).unwrap_or_else(|e| panic!("{e}"));
    check_host(gpu()).unwrap_or_else(|e| panic!("{e}"));
    let cached = start.elapsed();
    // Timings are reported, not asserted (CONTRIBUTING.md).
    eprintln!(
        "probe on {}: {:.3} s compiling and running, then {:.6} s for two cached checks",
        gpu().describe(),
        cold.as_secs_f64(),
        cached.as_secs_f64()
    );
    // The constructor every emulated run goes through passes too.
    EmulatedKernel::new(
        gpu(),
        "fn f(a: f32, b: f32) -> f32 { return a * b + a; }",
        "f",
        &Emulation::new(Policy::Upper),
    )
    .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn probe_refuses_contracting_reassociating_and_flushing_hosts() {
    // (the host modelled, its probe module, what its refusal must say); all run, then judged.
    let models = [
        (
            "a host contracting the fused construction's p + c",
            contracting_model(
                "let s = p + c;",
                "let s = prepass_cf_probe_model_fma(a, b, c);",
            ),
            &[
                "contracts a·b + c into a fused multiply-add (the fused a·b + c \
                 (prepass_cf_fused) came back",
                "at a = 1.5772557e0",
            ][..],
        ),
        (
            "a host simplifying TwoSum's error term to a + b − s",
            host_model(
                "select((a - (s - bb)) + (b - bb), 0.0, exact)",
                "select((a + b) - s, 0.0, exact)",
            ),
            &[
                "reassociates",
                "TwoSum's error term (prepass_cf_two_sum) came back 0e0",
            ],
        ),
        (
            "a host simplifying Dekker's splits ca − (ca − a) to a and cb − (cb − b) to b",
            replace_once(
                host_model("let ah = ca - (ca - a);", "let ah = a;"),
                "let bh = cb - (cb - b);",
                "let bh = b;",
            ),
            &[
                "reassociates",
                "Dekker's product error (prepass_cf_mul_err) came back 0e0",
            ],
        ),
        (
            "a host flushing subnormal sums",
            host_model(
                "let s = prepass_cf_opaque(a) + prepass_cf_opaque(b);",
                "let s0 = prepass_cf_opaque(a) + prepass_cf_opaque(b);\n    \
                 let s = select(s0, 0.0, prepass_cf_is_subnormal(s0));",
            ),
            &[
                "flushes subnormal results to zero",
                "the subnormal difference (prepass_cf_two_sum) came back 0e0",
            ],
        ),
    ];
    let mut wrong = Vec::new();
    for (model, source, says) in &models {
        match check_host_with(gpu(), source) {
            Err(HarnessError::UnfitHost(m)) => {
                eprintln!("{model}: {m}");
                if let Some(s) = says.iter().find(|s| !m.contains(**s)) {
                    wrong.push(format!("{model}: the refusal does not say `{s}`: {m}"));
                }
            }
            Err(e) => wrong.push(format!("{model}: the probe did not run: {e}")),
            Ok(notes) => wrong.push(format!("{model}: passed (notes: {notes:?})")),
        }
    }
    // Fast2Sum's error in a pack lane folded to 0 (as lavapipe folds it): a note, not a
    // refusal, since the lane then keeps the host's integer, an allowed one.
    match check_host_with(
        gpu(),
        &host_model("let e = (-c) - (t - hi);", "let e = 0.0;"),
    ) {
        Ok(notes)
            if notes
                .iter()
                .any(|n| n.contains("(prepass_cf_pack_lane, Fast2Sum) came back")) => {}
        other => wrong.push(format!("a host folding Fast2Sum: {other:?}")),
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
