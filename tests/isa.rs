//! Every shipped function compiled by AMD's ACO and Intel's brw (Mesa 25, without a GPU:
//! `prepass::isa`) for every target: a compile failure fails here, and the figures are
//! published in docs/figures.md (blocks `isa-costs` and `isa-precise-ratio`).

mod common;

use prepass::harness::Signature;
use prepass::isa::{Costing, Function, Target, TargetCosts};
use std::fmt::Write as _;

/// Every function of every shipped file that the harness can wrap (scalars and vectors in and
/// out), with the file it comes from.
fn shipped_functions() -> Vec<(&'static str, Function)> {
    let mut out = Vec::new();
    for file in prepass::wgsl::FILES {
        let checked = prepass::wgsl::parse_and_validate(file.source).unwrap();
        for (_, f) in checked.module.functions.iter() {
            let name = f.name.as_deref().unwrap();
            if Signature::read(file.source, name).is_ok() {
                out.push((file.name, Function::new(file.source, name)));
            }
        }
    }
    out
}

/// The targets' outcomes, every one measured: a target that was not is a setup failure, and
/// the message says how to set up.
fn measured(report: &prepass::isa::Report) -> Vec<(Target, &TargetCosts)> {
    report
        .targets
        .iter()
        .map(|t| match &t.outcome {
            Ok(c) => (t.target, c),
            Err(why) => panic!(
                "{} was not measured: {why}\nThe real-ISA checks need Mesa 25's RADV and ANV and \
                 the noop drm shims: run `bash .ci/setup-gpu-compilers` (bash .ci/test does), or \
                 point {} at the folder it fills.",
                t.target,
                prepass::isa::ROOT_VAR
            ),
        })
        .collect()
}

fn driver_line(targets: &[(Target, &TargetCosts)]) -> String {
    let mut versions: Vec<&str> = targets.iter().map(|(_, c)| c.driver_info.as_str()).collect();
    versions.dedup();
    format!(
        "<!-- measured on: {} (ACO and brw, static compiler estimates) -->\n",
        versions.join(", ")
    )
}

fn cell(x: Option<f64>) -> String {
    x.map_or("—".into(), |v| format!("{v:.1}"))
}

/// Every shipped function compiles on every target, each figure is finite, and the full table
/// is published.
#[test]
fn every_shipped_function_compiles_and_is_costed_on_every_target() {
    let functions = shipped_functions();
    let list: Vec<Function> = functions.iter().map(|(_, f)| f.clone()).collect();
    let report = Costing::new().cost(&list).unwrap();
    let targets = measured(&report);
    let mut table = String::from(
        "Net per evaluation (8 independent evaluations per invocation, minus a kernel with the \
         same loads and stores; latency: one evaluation's). AMD: instructions / ALU / ACO \
         latency / ACO inverse throughput (cycles per wave64), VGPRs and waves per SIMD of the \
         one-evaluation kernel. Intel: instructions / ALU / brw cycles (per SIMD thread), \
         max live registers and SIMD width. Compare within a target, never across vendors.\n\n\
         | file | function |",
    );
    for (t, _) in &targets {
        let _ = write!(table, " {} |", t.label());
    }
    table.push_str("\n|---|---|");
    table.push_str(&"---|".repeat(targets.len()));
    table.push('\n');
    for (k, (file, f)) in functions.iter().enumerate() {
        let _ = write!(table, "| {file} | `{}` |", f.function);
        for (t, c) in &targets {
            let cost = c.functions[k].as_ref().unwrap_or_else(|e| {
                panic!("{}: `{}` does not compile: {e}", t.label(), f.function)
            });
            let n = cost.net;
            for (what, v) in [
                ("instructions", Some(n.instructions)),
                ("ALU", Some(n.alu)),
                ("latency", n.latency),
                ("inverse throughput", n.inverse_throughput),
                ("cycles", n.cycles),
            ] {
                assert!(
                    v.is_none_or(f64::is_finite),
                    "{}: `{}`: {what} is {v:?}",
                    t.label(),
                    f.function
                );
            }
            let k1 = &cost.kernel;
            match t.vendor() {
                prepass::isa::Vendor::Amd => {
                    let _ = write!(
                        table,
                        " {:.1} / {:.1} / {} / {}; {} VGPRs, {} waves |",
                        n.instructions,
                        n.alu,
                        cell(n.latency),
                        cell(n.inverse_throughput),
                        k1.registers,
                        k1.occupancy.unwrap_or(f64::NAN)
                    );
                }
                prepass::isa::Vendor::Intel => {
                    let _ = write!(
                        table,
                        " {:.1} / {:.1} / {}; {} regs, SIMD{} |",
                        n.instructions,
                        n.alu,
                        cell(n.cycles),
                        k1.registers,
                        k1.subgroup_size
                    );
                }
            }
            if k1.spills > 0.0 {
                let _ = write!(table, " ({} spills)", k1.spills);
            }
        }
        table.push('\n');
    }
    common::publish_on(
        "docs/figures.md",
        "isa-costs",
        &table,
        driver_line(&targets).trim_start_matches("<!-- measured on: ").trim_end_matches(" -->\n"),
    );
}

/// Every shipped file compiles whole (every function called in one kernel) on every target.
#[test]
fn every_shipped_file_compiles_whole_on_every_target() {
    let sources: Vec<&str> = prepass::wgsl::FILES.iter().map(|f| f.source).collect();
    let (reports, called) = Costing::new().compile_libraries(&sources).unwrap();
    for r in &reports {
        let (_, modules) = r.outcome.as_ref().unwrap_or_else(|why| {
            panic!(
                "{} was not measured: {why} (run `bash .ci/setup-gpu-compilers`)",
                r.target
            )
        });
        for ((file, m), names) in prepass::wgsl::FILES.iter().zip(modules).zip(&called) {
            assert!(!names.is_empty(), "{}: no function called", file.name);
            if let Err(e) = m {
                panic!("{}: {} does not compile whole: {e}", r.target, file.name);
            }
        }
    }
}
