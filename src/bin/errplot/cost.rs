//! The error-against-run-time table and Pareto plots.
//!
//! A section registers each variant it measured ([`Ctx::variants`], see [`crate::variant`]): its
//! error, the WGSL to time on the adapter and the Rust twin to time on the CPU. This module then
//! measures every variant's cost three ways in one run:
//! - GPU ns per evaluation: [`prepass::harness::Kernel::time`] over one dispatch of 2^24
//!   invocations, minus its empty-kernel baseline;
//! - Rust twin ns per call: a batch loop over `black_box`ed inputs, fastest of several batches,
//!   minus the same loop around an identity function;
//! - SPIR-V instructions: [`prepass::wgsl::spirv_instruction_count`] (callees included);
//! - real instruction sets: [`prepass::isa`], AMD's ACO and Intel's brw compiling the WGSL
//!   for eight targets without a GPU (static compiler estimates, net of a same-loads baseline).

use crate::ctx::{Ctx, NEEDS_ADAPTER, num};
use crate::fronts::{Kind, Labelled, Panel, Scatter};
use crate::peers::{self, Point};
use crate::plot::Chart;
use crate::variant::{TimedArg, TwinTimer, Variant, twin_timer};
use prepass::harness::{Arg, Feed, MIN_TIMED_INVOCATIONS, TimingMethod};
use prepass::isa::{Costing, Function, Net, Target};
use std::fmt::Write as _;

struct Costs {
    gpu_ns: Option<f64>,
    gpu_gross_ns: Option<f64>,
    cpu_ns: Option<f64>,
    spirv: Option<usize>,
    /// Net per-evaluation figures per target, in [`Target::ALL`] order.
    isa: Vec<Option<Net>>,
}

/// The targets drawn on Pareto plots and checked for dominance: one AMD generation before and
/// one after RDNA3's dual issue, and Intel's discrete Xe-HPG.
pub const PLOTTED: [Target; 3] = [Target::Rdna2, Target::Rdna3, Target::XeHpg];

/// What the compilers said: per target, the driver version or why it was not measured.
struct IsaRun {
    versions: Vec<Result<String, String>>,
}

/// Cost every WGSL variant on `targets` (one child process per target, side by side); the
/// other targets of [`Target::ALL`] are reported as not measured, saying why.
fn isa_costs(variants: &[Variant], targets: &[Target]) -> (IsaRun, Vec<Vec<Option<Net>>>) {
    let functions: Vec<Function> = variants
        .iter()
        .filter_map(|v| v.wgsl.as_ref())
        .map(|w| {
            let feeds: Vec<Feed> = w
                .args
                .iter()
                .map(|a| match a {
                    TimedArg::Splat(_) => Feed::Splat,
                    _ => Feed::Column,
                })
                .collect();
            Function::new(&w.source, &w.function).with_feeds(&feeds)
        })
        .collect();
    let none = || vec![vec![None; Target::ALL.len()]; variants.len()];
    let report = match Costing::new().targets(targets).cost(&functions) {
        Ok(r) => r,
        Err(e) => {
            let why = format!("naga refused a kernel: {e}");
            return (
                IsaRun {
                    versions: vec![Err(why); Target::ALL.len()],
                },
                none(),
            );
        }
    };
    let mut per_variant = none();
    let mut versions: Vec<Result<String, String>> = vec![
        Err(
            "not costed in a quick run (RDNA2, RDNA3 and Xe-HPG only, the plotted targets; \
             the full run costs all eight)"
                .into()
        );
        Target::ALL.len()
    ];
    for t in &report.targets {
        let ti = target_index(t.target);
        match &t.outcome {
            Ok(c) => {
                versions[ti] = Ok(c.driver_info.clone());
                let mut k = 0;
                for (vi, v) in variants.iter().enumerate() {
                    if v.wgsl.is_some() {
                        per_variant[vi][ti] = c.functions[k].as_ref().ok().map(|c| c.net);
                        k += 1;
                    }
                }
            }
            Err(why) => versions[ti] = Err(why.clone()),
        }
    }
    (IsaRun { versions }, per_variant)
}

fn target_index(t: Target) -> usize {
    Target::ALL
        .iter()
        .position(|&x| x == t)
        .expect("a listed target")
}

/// A CSV field, quoted (RFC 4180) when it holds a comma, a quote or a line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// What the GPU-ns cells say where this run does not time on its adapter (see
/// [`times_on_adapter`]).
pub const NOT_TIMED: &str = "not timed (software adapter; `--full` times it)";

/// Whether this run times the WGSL on its adapter: only `--full` does on a software adapter.
/// There a timing is seconds of this CPU running the shader (2^24 invocations, the harness's
/// minimum, twice: 0.2 to 0.3 s a variant on lavapipe, the best-fit encoder's search 17 s, 39 s
/// of the quick run's 77 s, 2-core Xeon, 2026-12-07; most of the full run's 417 s cost section)
/// and ranks nothing on a GPU; the real-instruction-set columns are then the cost. On a real
/// GPU every tier times.
fn times_on_adapter(ctx: &Ctx) -> bool {
    ctx.gpu()
        .is_some_and(|g| ctx.opts.full() || !g.is_software())
}

/// An adapter this run does not time on (its GPU-ns cells say [`NOT_TIMED`], not "needs
/// adapter").
fn adapter_not_timed(ctx: &Ctx) -> bool {
    ctx.gpu().is_some() && !times_on_adapter(ctx)
}

/// Measure every registered variant and write the table, `error_vs_cost.csv` and the Pareto
/// plots.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let quick = ctx.opts.quick();
    let timed = times_on_adapter(ctx);
    // Timing repeats (the fastest is kept) and the twins' loop length: the default tier keeps
    // fewer repeats than `--full`, its figures a little noisier.
    let repeats = ctx.opts.pick(1, 3, 5);
    let calls: usize = ctx.opts.pick(1 << 20, 1 << 22, 1 << 23);
    let variants = std::mem::take(&mut ctx.variants);
    let bar = ctx.progress(variants.len() as u64, "run-time costs");
    let empty = twin_timer(vec![0u32; 1 << 12], |x| x);
    let cpu_best = |t: &TwinTimer| {
        (0..repeats + 1)
            .map(|_| t(calls))
            .fold(f64::INFINITY, f64::min)
    };
    let loop_ns = cpu_best(&empty) / calls as f64;
    let mut method = None;
    let mut costs = Vec::new();
    bar.set_message("real instruction sets (ACO, brw)");
    // A quick run compiles for the plotted targets only: each target is one child process
    // compiling every variant, and the quick report is read for its plots. The default and
    // full tiers compile every variant for all eight: the real-GPU cost the report exists for.
    let targets: &[Target] = if quick { &PLOTTED } else { &Target::ALL };
    let (isa_run, mut isa) = isa_costs(&variants, targets);
    for (v, isa) in variants.iter().zip(&mut isa) {
        bar.set_message(v.name.clone());
        let mut c = Costs {
            gpu_ns: None,
            gpu_gross_ns: None,
            cpu_ns: None,
            spirv: None,
            isa: std::mem::take(isa),
        };
        if let Some(w) = &v.wgsl {
            c.spirv = Some(
                prepass::wgsl::spirv_instruction_count(&w.source, &w.function)
                    .map_err(|e| format!("{}: {e}", w.function))?
                    .total,
            );
            if let Some(gpu) = ctx.gpu().filter(|_| timed) {
                let args: Vec<Arg> = w
                    .args
                    .iter()
                    .map(|a| match a {
                        TimedArg::Index(s) => Arg::Index { start: *s },
                        TimedArg::Splat(v) => Arg::Splat(*v),
                        TimedArg::Column(words) => Arg::column(words),
                    })
                    .collect();
                let t = gpu
                    .kernel(&w.source, &w.function)
                    .and_then(|k| k.time(&args, MIN_TIMED_INVOCATIONS, repeats))
                    .map_err(|e| format!("timing {}: {e}", w.function))?;
                method = Some(t.method);
                c.gpu_ns = Some(t.ns_per_eval());
                c.gpu_gross_ns = Some(t.gross_ns_per_eval());
            }
        }
        if let Some(t) = &v.twin {
            // The empty loop is re-measured beside each twin, so both see the same machine load.
            let (mut best, mut base) = (f64::INFINITY, f64::INFINITY);
            for _ in 0..repeats + 1 {
                best = best.min(t(calls));
                base = base.min(empty(calls));
            }
            c.cpu_ns = Some((best - base) / calls as f64);
        }
        costs.push(c);
        bar.inc(1);
    }
    bar.finish_and_clear();

    ctx.line("## Error against run time");
    ctx.line("");
    let adapter = ctx.gpu().map(|g| (g.adapter_info().name, g.is_software()));
    match (adapter, method) {
        (Some((adapter_name, software)), Some(m)) => {
            ctx.line(format!(
                "GPU ns/eval: {} over one dispatch of 2^24 invocations on {}, minus an \
                 empty-kernel baseline that loads the same arguments and stores the same bytes \
                 (fastest of {repeats}). gross = the function's kernel alone, per invocation.",
                match m {
                    TimingMethod::TimestampQuery => "the adapter's timestamp queries around the pass",
                    TimingMethod::WallClock =>
                        "wall time from submission to completion (the adapter has no timestamp queries)",
                },
                adapter_name
            ));
            if software {
                ctx.line("");
                ctx.line(
                    "**This adapter is software (a CPU running the shaders): its timings rank \
                     the functions on this CPU and say nothing about their speed on a GPU.** Run \
                     errplot on a machine with a GPU for GPU timings.",
                );
            }
        }
        (Some(_), None) => ctx.line(
            "GPU ns/eval: **not timed**: only `--full` times on a software adapter (each \
             timing is seconds of this CPU and says nothing about a GPU; the real \
             instruction sets below are the cost). `bash .ci/errplot --full` times every \
             variant.",
        ),
        (None, _) => ctx.line(format!(
            "GPU ns/eval: **{NEEDS_ADAPTER}** — no adapter was found; see the note at the top."
        )),
    }
    ctx.line("");
    ctx.line(format!(
        "CPU ns/call: the Rust twin in a loop of {calls} calls over `black_box`ed inputs, \
         fastest of {} batches, minus the same loop around an identity function timed beside \
         each twin (about {} ns/call). \
         SPIR-V: instructions naga emits for the function and everything it calls (static count, \
         device-independent).",
        repeats + 1,
        num(loop_ns)
    ));
    ctx.line("");
    isa_lines(ctx, &isa_run);
    ctx.line("| family | variant | bits | max error | mean error | RMS error | unit | error measured | RDNA2 inv. throughput | RDNA3 inv. throughput | Xe-HPG cycles | GPU ns/eval | GPU gross ns | CPU ns/call | SPIR-V instr. |");
    ctx.line("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "family,variant,bits,unit,max_error,mean_error,rms_error,error_measured,gpu_ns_per_eval,gpu_gross_ns_per_eval,gpu_timing_method,cpu_ns_per_call,spirv_instructions,peer",
    );
    for t in Target::ALL {
        let c = t.chip();
        let _ = write!(
            csv,
            ",{c}_instructions,{c}_alu,{c}_latency,{c}_inverse_throughput,{c}_cycles"
        );
    }
    csv.push('\n');
    let opt = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v}"));
    for (v, c) in variants.iter().zip(&costs) {
        let e = v.error.as_ref();
        let cell = |x: Option<f64>, adapter: bool| match x {
            Some(v) => num(v),
            None if adapter && ctx.gpu().is_none() => NEEDS_ADAPTER.into(),
            None => "—".into(),
        };
        let needs_gpu = v.wgsl.is_some();
        let gpu_cell = |x: Option<f64>| match x {
            None if needs_gpu && adapter_not_timed(ctx) => NOT_TIMED.into(),
            x => cell(x, needs_gpu),
        };
        let isa_cell = |t: Target| match (&isa_run.versions[target_index(t)], v.wgsl.is_some()) {
            (_, false) => "—".to_string(),
            (Err(_), true) => "not measured".to_string(),
            (Ok(_), true) => c.isa[target_index(t)]
                .map_or("compile failed".into(), |n| format!("{:.1}", n.rank())),
        };
        ctx.line(format!(
            "| {} | `{}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            v.family,
            v.name,
            v.bits,
            cell(e.map(|e| e.max), true),
            cell(e.map(|e| e.mean()), true),
            cell(e.map(|e| e.rms()), true),
            v.unit,
            v.error_from,
            isa_cell(Target::Rdna2),
            isa_cell(Target::Rdna3),
            isa_cell(Target::XeHpg),
            gpu_cell(c.gpu_ns),
            gpu_cell(c.gpu_gross_ns),
            cell(c.cpu_ns, false),
            c.spirv.map_or("—".into(), |s| s.to_string()),
        ));
        let _ = write!(
            csv,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(v.family),
            csv_field(&v.name),
            v.bits,
            csv_field(v.unit),
            opt(e.map(|e| e.max)),
            opt(e.map(|e| e.mean())),
            opt(e.map(|e| e.rms())),
            csv_field(&v.error_from),
            opt(c.gpu_ns),
            opt(c.gpu_gross_ns),
            method.map_or(String::new(), |m| format!("{m}")),
            opt(c.cpu_ns),
            c.spirv.map_or(String::new(), |s| s.to_string()),
            v.name.starts_with(peers::PREFIX),
        );
        for n in &c.isa {
            let _ = write!(
                csv,
                ",{},{},{},{},{}",
                opt(n.map(|n| n.instructions)),
                opt(n.map(|n| n.alu)),
                opt(n.and_then(|n| n.latency)),
                opt(n.and_then(|n| n.inverse_throughput)),
                opt(n.and_then(|n| n.cycles)),
            );
        }
        csv.push('\n');
    }
    ctx.line("");
    isa_table(ctx, &variants, &costs, &isa_run);
    ctx.csv("error_vs_cost.csv", &csv)?;

    // One Pareto plot per family: max error against the best cost measure available.
    // Families in first-seen order; a section may interleave two families' variants.
    let mut families: Vec<&str> = Vec::new();
    for v in &variants {
        if !families.contains(&v.family) {
            families.push(v.family);
        }
    }
    // Per family: one plot on the adapter's (or SPIR-V's) axis, one per plotted target.
    let base: Axis = if timed {
        (
            "GPU time per evaluation, gross (ns, log scale)".into(),
            Box::new(|c: &Costs| c.gpu_gross_ns),
            String::new(),
        )
    } else {
        (
            if adapter_not_timed(ctx) {
                "SPIR-V instructions (log scale; a software adapter is timed by `--full` only)"
            } else {
                "SPIR-V instructions (log scale; no adapter for GPU time)"
            }
            .into(),
            Box::new(|c: &Costs| c.spirv.map(|s| s as f64)),
            String::new(),
        )
    };
    let mut axes = vec![base];
    for t in PLOTTED {
        let ti = target_index(t);
        let Ok(version) = &isa_run.versions[ti] else {
            continue;
        };
        let what = match t.vendor() {
            prepass::isa::Vendor::Amd => "ACO inverse throughput (cycles/wave64)",
            prepass::isa::Vendor::Intel => "brw cycles per SIMD thread",
        };
        axes.push((
            format!(
                "{}: {what} per evaluation, net; static estimate of {version}; log",
                t.label()
            ),
            Box::new(move |c: &Costs| c.isa[ti].map(|n| n.rank()).filter(|&x| x > 0.0)),
            format!("_{}", t.chip()),
        ));
    }
    for family in &families {
        let members: Vec<(&Variant, &Costs)> = variants
            .iter()
            .zip(&costs)
            .filter(|(v, _)| v.family == *family)
            .collect();
        for (x_label, pick, suffix) in &axes {
            pareto(ctx, family, &members, x_label, pick.as_ref(), suffix)?;
        }
    }
    dominance_section(ctx, &variants, &costs);
    Ok(())
}

/// A Pareto plot's x axis: its label, the cost it reads, the file-name suffix.
type Axis = (String, Box<dyn Fn(&Costs) -> Option<f64>>, String);

/// The bit budgets that compete: codes of up to 8, 16, 24 and 32 bits, and longer ones.
fn budget(bits: u32) -> u32 {
    bits.div_ceil(8).min(5)
}

/// A variant's name as drawn beside its point: the family's common prefixes and a peer's
/// parenthetical left out (the hollow marker says "peer"; the table has the full name).
fn short_name(name: &str) -> String {
    let name = name.strip_prefix(peers::PREFIX).unwrap_or(name);
    let name = name.split(" (").next().unwrap_or(name);
    let mut s = name.to_string();
    for p in ["encode_normal_", "decode_normal_", "encode_", "decode_"] {
        if let Some(rest) = s.strip_prefix(p) {
            s = rest.to_string();
            break;
        }
    }
    s.replace("_normal", "").replace('_', " ")
}

/// One family's error-against-cost figure: max error against the cost `pick` reads, one panel
/// per bit budget.
fn pareto(
    ctx: &mut Ctx,
    family: &str,
    members: &[(&Variant, &Costs)],
    x_label: &str,
    pick: &dyn Fn(&Costs) -> Option<f64>,
    suffix: &str,
) -> Result<(), String> {
    let unit = members[0].0.unit;
    // A zero maximum (an exact variant) cannot sit on a log axis: it is drawn at a floor
    // one decade below the smallest non-zero maximum, and its label says so.
    let nonzero = members
        .iter()
        .filter_map(|(v, _)| v.error.map(|e| e.max))
        .filter(|&m| m > 0.0)
        .fold(f64::INFINITY, f64::min);
    let floor = if nonzero.is_finite() {
        nonzero / 10.0
    } else {
        1.0
    };
    let mut budgets: Vec<(u32, u32, u32, Vec<Labelled>)> = Vec::new();
    let mut seen: Vec<&str> = Vec::new();
    for (v, c) in members {
        // One decoder may serve two encodings (xyz8 and its best-fit encoder): one point.
        if seen.contains(&v.name.as_str()) {
            continue;
        }
        seen.push(&v.name);
        let (Some(e), Some(x)) = (v.error, pick(c)) else {
            continue;
        };
        // Peers and the textbook baselines are drawn alike: hollow, not shipped.
        let peer = !peers::is_shipped(&v.name);
        let rounding = !peer && v.name.ends_with("_fast");
        let name = short_name(&v.name);
        let group = name.trim_end_matches(" fast").to_string();
        let point = Labelled {
            label: if e.max == 0.0 {
                format!("{name} (max 0)")
            } else {
                name
            },
            group,
            kind: if peer {
                Kind::Peer
            } else if rounding {
                Kind::Rounding
            } else {
                Kind::Shipped
            },
            x,
            y: if e.max == 0.0 { floor } else { e.max },
        };
        let b = budget(v.bits);
        match budgets.iter_mut().find(|p| p.0 == b) {
            Some(p) => {
                p.1 = p.1.min(v.bits);
                p.2 = p.2.max(v.bits);
                p.3.push(point);
            }
            None => budgets.push((b, v.bits, v.bits, vec![point])),
        }
    }
    if budgets.is_empty() {
        ctx.line(format!(
            "*Pareto plot for {family} ({x_label}): no points ({NEEDS_ADAPTER} for the error).*"
        ));
        ctx.line("");
        return Ok(());
    }
    budgets.sort_by_key(|p| p.0);
    let several = budgets.len() > 1;
    let panels = budgets
        .into_iter()
        .map(|(_, lo, hi, points)| Panel {
            title: match (lo == hi, several) {
                (_, false) if hi == 0 => "every variant (f32 input, no stored code)".into(),
                (true, true) => format!("{lo}-bit codes"),
                (false, true) => format!("{lo}–{hi}-bit codes (they compete)"),
                (true, false) => format!("every variant: {lo}-bit codes"),
                (false, false) => format!("every variant: {lo}–{hi}-bit codes"),
            },
            points,
        })
        .collect();
    let chart = Chart::Scatter(Scatter {
        title: format!("Max error against cost: {family}"),
        x_label: x_label.into(),
        y_label: format!("max error ({unit}, log scale)"),
        panels,
        x_ticks: None,
    });
    // Named after the family, so a family's file keeps its name as others are added.
    let slug: String = family
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    ctx.chart(
        &chart,
        &format!("pareto_{slug}{suffix}"),
        &format!("Pareto: {family}{}", suffix.replace('_', " on ")),
    )
}

/// Where the real-instruction-set columns come from, or why a target has none.
fn isa_lines(ctx: &mut Ctx, run: &IsaRun) {
    let mut measured = Vec::new();
    for (t, v) in Target::ALL.iter().zip(&run.versions) {
        match v {
            Ok(version) => measured.push(format!("{} ({version})", t.label())),
            Err(why) => ctx.line(format!("{}: **not measured**: {why}", t.label())),
        }
    }
    ctx.line("");
    ctx.line(format!(
        "Real instruction sets (`prepass::isa`): the WGSL compiled by Mesa's own compilers \
         without a GPU, for {}. **Static compiler estimates, not timings**, net per evaluation \
         (8 independent evaluations per invocation, minus a kernel with the same loads and \
         stores): ACO's inverse throughput on AMD (cycles per wave64 when the SIMD is kept \
         busy), brw's cycle estimate on Intel (per SIMD thread). Compare within one target, \
         never across vendors; every target's instructions, ALU instructions and ACO latency \
         are in `error_vs_cost.csv`, and the next table ranks on all eight.",
        measured.join(", ")
    ));
    ctx.line("");
}

/// Every variant's rank figure on every target.
fn isa_table(ctx: &mut Ctx, variants: &[Variant], costs: &[Costs], run: &IsaRun) {
    ctx.line("### Cost on every real instruction set");
    ctx.line("");
    ctx.line(
        "Net per evaluation: ACO inverse throughput (AMD) or brw cycles (Intel), then net \
         instructions in parentheses. Static compiler estimates.",
    );
    ctx.line("");
    let mut head = String::from("| family | variant |");
    for t in Target::ALL {
        head.push_str(&format!(" {} |", t.label()));
    }
    ctx.line(head);
    ctx.line(format!("|---|---|{}", "---|".repeat(Target::ALL.len())));
    for (v, c) in variants.iter().zip(costs) {
        if v.wgsl.is_none() {
            continue;
        }
        let mut row = format!("| {} | `{}` |", v.family, v.name);
        for (n, version) in c.isa.iter().zip(&run.versions) {
            row.push_str(&match (n, version) {
                (_, Err(_)) => " not measured |".to_string(),
                (None, Ok(_)) => " compile failed |".to_string(),
                (Some(n), Ok(_)) => format!(" {:.1} ({:.1}) |", n.rank(), n.instructions),
            });
        }
        ctx.line(row);
    }
    ctx.line("");
}

/// The dominance check: for each shipped variant of a family with peers, the peers with no more
/// bits, max error ≤ and cost ≤ (one strictly less), on SPIR-V count and on GPU ns.
fn dominance_section(ctx: &mut Ctx, variants: &[Variant], costs: &[Costs]) {
    let with_peers: Vec<&str> = variants
        .iter()
        .filter(|v| v.name.starts_with(peers::PREFIX))
        .map(|v| v.family)
        .collect();
    if with_peers.is_empty() {
        return;
    }
    let points = |cost: &dyn Fn(&Costs) -> Option<f64>| -> Vec<Point> {
        variants
            .iter()
            .zip(costs)
            .filter(|(v, _)| with_peers.contains(&v.family))
            .filter_map(|(v, c)| {
                Some(Point {
                    family: v.family.to_string(),
                    name: v.name.clone(),
                    bits: v.bits,
                    max_error: v.error?.max,
                    max_error_upper: v.error_upper.map(|e| e.max),
                    upper_only: v.upper_only,
                    cost: cost(c)?,
                })
            })
            .collect()
    };
    let spirv = peers::dominance(&points(&|c| c.spirv.map(|s| s as f64)));
    let gpu = peers::dominance(&points(&|c| c.gpu_ns));
    let on_targets: Vec<_> = PLOTTED
        .iter()
        .map(|&t| {
            let ti = target_index(t);
            peers::dominance(&points(&|c| c.isa[ti].map(|n| n.rank())))
        })
        .collect();
    ctx.line("### Does a peer dominate a shipped function?");
    ctx.line("");
    ctx.line(
        "A peer dominates a shipped function of its family when it stores no more bits, its max \
         error is no larger and its cost no larger, one of the two strictly smaller; a \
         hemisphere-only encoding is compared with the peer's error over z ≥ 0. Cost: SPIR-V \
         instructions (static, device-independent), GPU ns/eval (net), and the net cost on \
         RDNA2, RDNA3 (ACO inverse throughput) and Xe-HPG (brw cycles), static compiler \
         estimates.",
    );
    if times_on_adapter(ctx) && ctx.gpu().is_some_and(|g| g.is_software()) {
        ctx.line("");
        ctx.line(
            "**GPU ns here come from a software adapter: they are CPU timings of the shaders and \
             say nothing about a GPU**; the GPU-ns column ranks the functions on this CPU only, \
             and the timings vary between runs by more than the closest gaps.",
        );
    }
    if ctx.opts.quick() {
        ctx.line("");
        ctx.line(
            "Quick runs leave the `_fast` and hemi-octahedral variants out of the cost table, so \
             out of this table too; `tests/errplot_peers.rs` checks the SPIR-V-count dominance \
             of every shipped function and the README lists each dominated one with its reason.",
        );
    }
    ctx.line("");
    let mut head = String::from(
        "| family | shipped function | dominated on SPIR-V count by | dominated on GPU ns by |",
    );
    for t in PLOTTED {
        head.push_str(&format!(" dominated on {} by |", t.arch()));
    }
    ctx.line(head);
    ctx.line(format!("|---|---|---|---|{}", "---|".repeat(PLOTTED.len())));
    for v in variants
        .iter()
        .filter(|v| with_peers.contains(&v.family) && peers::is_shipped(&v.name))
    {
        let find = |list: &[(String, Vec<String>)]| match list.iter().find(|(n, _)| *n == v.name) {
            None => NEEDS_ADAPTER.to_string(),
            Some((_, d)) if d.is_empty() => "none".to_string(),
            Some((_, d)) => d.join(", "),
        };
        let mut row = format!(
            "| {} | `{}` | {} | {} |",
            v.family,
            v.name,
            find(&spirv),
            if adapter_not_timed(ctx) {
                NOT_TIMED.to_string()
            } else {
                find(&gpu)
            }
        );
        for d in &on_targets {
            row.push_str(&format!(
                " {} |",
                find(d).replace(NEEDS_ADAPTER, "not measured")
            ));
        }
        ctx.line(row);
    }
    ctx.line("");
}
