//! errplot — the crate's report: every paired function's precision sweep on the available
//! adapter, the Rust twins on the CPU, each encoding variant's cost measured three ways, and
//! the plots, tables and CSV files that show them.
//!
//! ```text
//! cargo run --release --all-features --bin errplot -- [--out DIR] [--quick | --full] [--exhaustive32]
//! cargo run --release --all-features --bin errplot -- --check DIR   # measure written SVGs
//! ```
//! Three tiers ([`ctx::Tier`]): `--quick` (CI's smoke run), the default (every section sized for
//! a few minutes on two cores: long sweeps sampled, no timing on a software adapter) and
//! `--full` (every sweep at full size, every variant timed: the published figures).
//! Output goes to `errplot-out/` by default: `report.md` (tables, plots embedded), one CSV per
//! sweep (columns documented in `report.md`'s "Files" section), each plot as SVG and PNG.
//!
//! One file per section. A new module joins the report with:
//! 1. a file here with `pub fn section(ctx: &mut Ctx) -> Result<(), String>` that runs its sweeps
//!    (from `src/sweep/<topic>`), writes Markdown (`ctx.line`), CSV (`ctx.csv`) and charts
//!    (`ctx.chart` with a `plot::Chart`; it fails the run on a figure that fails [`layout`]'s
//!    checks), marking adapter-only cells `NEEDS_ADAPTER` when
//!    `ctx.gpu()` is `None`;
//! 2. one line in [`MEASURING`] (the sections that run side by side before the cost table);
//! 3. one `ctx.variants.push(variant::Variant { .. })` per encoding variant (its error, the WGSL and
//!    timing arguments, the twin's timer): the cost table and the Pareto plots pick them up;
//! 4. one line per CSV file in `files.rs` documenting its columns.

mod conforming;
mod cost;
mod ctx;
mod depth24;
mod depth_resolution;
mod files;
mod fronts;
mod layout;
mod linear_depth;
mod lpp;
mod normal;
mod peers;
mod pick;
mod plot;
mod roughness;
mod roughness_ggx;
mod variant;

use ctx::{Ctx, Options, Tier};
use prepass::harness::Gpu;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::Instant;

/// A section of the report: writes into the context, or fails with a message.
type Section = fn(&mut Ctx) -> Result<(), String>;

/// The measuring sections, in the report's order; each writes its Markdown, CSV and plots and
/// registers its encoding variants. They run side by side, one per core (on a CPU adapter most
/// of their time is the driver compiling their kernels, which takes one thread per kernel),
/// started from the last: the conforming section, the longest, first.
const MEASURING: &[(&str, Section)] = &[
    ("depth resolution", depth_resolution::section),
    ("linear depth", linear_depth::section),
    ("24-bit depth", depth24::section),
    ("normal encodings", normal::section),
    ("roughness", roughness::section),
    ("GGX roughness", roughness_ggx::section),
    ("light pre-pass (lpp)", lpp::section),
    ("conforming adapters", conforming::section),
];

/// Then, alone, so that nothing else competes for the cores while it times: the cost table,
/// which times the registered variants, and the list of files.
const AFTER: &[(&str, Section)] = &[
    ("error against run time", cost::section),
    ("files", files::section),
];

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        out: PathBuf::from("errplot-out"),
        tier: Tier::Default,
        exhaustive32: false,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => o.out = args.next().ok_or("--out needs a directory")?.into(),
            "--quick" | "--full" if o.tier != Tier::Default => {
                return Err("--quick and --full pick one tier each: give one of them".into());
            }
            "--quick" => o.tier = Tier::Quick,
            "--full" => o.tier = Tier::Full,
            "--exhaustive32" => o.exhaustive32 = true,
            "--check" => {
                let dir = PathBuf::from(args.next().ok_or("--check needs a directory")?);
                std::process::exit(check(&dir));
            }
            "-h" | "--help" => {
                println!(
                    "usage: errplot [--out DIR] [--quick | --full] [--exhaustive32] | --check DIR\n\n\
                     Writes report.md, CSV files and SVG/PNG plots into DIR (default errplot-out).\n\
                     Three tiers:\n\
                     \x20 --quick: CI's smoke run (notebooks too): fewer cases, the rounding \
                     encoders under emulation, the three plotted cost targets, no timing on a software adapter.\n\
                     \x20 (no flag), the default: every section, codec and cost target, the long sweeps \
                     sampled (the report says how much), no timing on a software adapter; minutes on two cores.\n\
                     \x20 --full: every sweep at full size, every codec under every policy, every \
                     variant timed (lavapipe too): the report's published figures.\n\
                     --exhaustive32: also decode all 2^32 codes of oct32 and xy fp16 (~15 min on lavapipe).\n\
                     --check DIR: measure every SVG in DIR (text and boxes inside the image; \
                     errplot checks each figure as it writes it) and exit 1 on a problem.\n\
                     PREPASS_ADAPTER=NAME picks an adapter by name; WGPU_BACKEND restricts backends."
                );
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument {other:?} (try --help)")),
        }
    }
    Ok(o)
}

/// `errplot --check DIR`: every SVG in DIR measured for text and boxes outside the image
/// (the check each figure passes as errplot writes it, for figures written before).
fn check(dir: &std::path::Path) -> i32 {
    if let Err(e) = plot::init() {
        eprintln!("errplot: {e}");
        return 1;
    }
    match layout::check_dir(dir) {
        Ok((files, problems)) => {
            for p in &problems {
                println!("{p}");
            }
            println!(
                "errplot --check: {files} SVG files, {} problems",
                problems.len()
            );
            i32::from(!problems.is_empty() || files == 0)
        }
        Err(e) => {
            eprintln!("errplot: {e}");
            1
        }
    }
}

fn cpu_name() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string())
}

fn run(ctx: &mut Ctx) -> Result<(), String> {
    let started = Instant::now();
    ctx.line("# prepass error report");
    ctx.line("");
    let header = match ctx.gpu.as_ref() {
        Ok(g) => {
            let mut s = format!("- Adapter: {}", g.describe());
            if g.is_software() {
                s.push_str(
                    "\n  — a software adapter: its rounding is measured like any adapter's, its \
                     timings measure this CPU and say nothing about a GPU.",
                );
            }
            s
        }
        Err(e) => format!(
            "- Adapter: **none** — {e}\n\n\
             **Columns and tables marked \"{}\" were not computed**: the adapter-side error of \
             every WGSL function, the code-recovery tables, and GPU time per evaluation. \
             Everything computed on the CPU is here: the Rust twins' errors and ns/call, the \
             SPIR-V instruction counts, depth resolution and the CPU linear-depth curves. \
             To fill them in, get an adapter (the fix above; `bash .ci/setup-adapter` installs \
             lavapipe on Debian/Ubuntu) and run `bash .ci/errplot` again.",
            ctx::NEEDS_ADAPTER
        ),
    };
    ctx.line(header);
    ctx.line(format!(
        "- CPU: {} ({} threads)",
        cpu_name(),
        std::thread::available_parallelism().map_or(1, |n| n.get())
    ));
    ctx.line(format!(
        "- Mode: {}{}",
        ctx.opts.tier.label(),
        match ctx.opts.tier {
            Tier::Full => " — every sweep at full size, every variant timed on the adapter",
            Tier::Default =>
                " — the long sweeps sampled (each section says how much; `--full` runs them \
                 whole), no timing on a software adapter",
            Tier::Quick => " — CI's smoke run: fewer cases, the rounding encoders under emulation",
        }
    ));
    ctx.line(
        "- The report's published figures come from `bash .ci/errplot --full`; the default run \
         (`bash .ci/errplot`, = `cargo run --release --all-features --bin errplot`) samples the \
         long sweeps, `--quick` is CI's smoke run.",
    );
    ctx.line("");
    run_side_by_side(ctx, MEASURING)?;
    for (name, section) in AFTER {
        let t = Instant::now();
        section(ctx).map_err(|e| format!("section {name}: {e}"))?;
        ctx.say(&format!(
            "errplot: {name} ({:.1} s)",
            t.elapsed().as_secs_f64()
        ));
    }
    ctx.line(format!(
        "Generated in {:.1} s.",
        started.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// Run `sections` on one thread per core, the last first, each into its own part of the
/// report; the parts are appended in the sections' order (also the ones before a failure, so
/// the report shows it in context), and the first failure in that order is returned.
fn run_side_by_side(ctx: &mut Ctx, sections: &[(&str, Section)]) -> Result<(), String> {
    type Done = (Ctx, Result<(), String>);
    let todo: Mutex<Vec<(usize, Ctx)>> = Mutex::new(
        sections
            .iter()
            .enumerate()
            .map(|(i, _)| (i, ctx.fork()))
            .collect(),
    );
    let done: Mutex<Vec<Option<Done>>> = Mutex::new(sections.iter().map(|_| None).collect());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..threads.min(sections.len()) {
            scope.spawn(|| {
                loop {
                    // Its own statement: a `while let` would hold the lock through the section.
                    let next = todo.lock().unwrap().pop();
                    let Some((i, mut part)) = next else { break };
                    let (name, section) = sections[i];
                    let t = Instant::now();
                    let result = section(&mut part).map_err(|e| format!("section {name}: {e}"));
                    part.say(&format!(
                        "errplot: {name} ({:.1} s)",
                        t.elapsed().as_secs_f64()
                    ));
                    done.lock().unwrap()[i] = Some((part, result));
                }
            });
        }
    });
    for (part, result) in done.into_inner().unwrap().into_iter().flatten() {
        ctx.absorb(part);
        result?;
    }
    Ok(())
}

fn main() {
    let opts = match parse_args() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("errplot: {e}");
            std::process::exit(2);
        }
    };
    if let Err(e) = std::fs::create_dir_all(&opts.out)
        .map_err(|e| e.to_string())
        .and_then(|()| plot::init())
    {
        eprintln!("errplot: cannot start: {e}");
        std::process::exit(1);
    }
    let gpu = Gpu::new().map_err(|e| e.to_string());
    if let Err(e) = &gpu {
        eprintln!("errplot: no adapter — writing the CPU-side results only. {e}");
    }
    let mut ctx = Ctx::new(opts, gpu);
    let result = run(&mut ctx);
    let path = ctx.opts.out.join("report.md");
    // Write what was gathered even when a section failed, so the failure can be read in context.
    if let Err(e) = std::fs::write(&path, ctx.markdown()) {
        eprintln!("errplot: cannot write {}: {e}", path.display());
        std::process::exit(1);
    }
    if let Err(e) = result {
        eprintln!("errplot: {e}");
        std::process::exit(1);
    }
    eprintln!(
        "errplot: wrote {} and {} data/plot files in {}",
        path.display(),
        ctx.written.len(),
        ctx.opts.out.display()
    );
}
