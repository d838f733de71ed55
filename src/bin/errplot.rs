//! errplot — runs the crate's precision sweeps on the available adapter (and the Rust twins on
//! the CPU) and writes CSV data and a Markdown report.
//!
//! ```text
//! cargo run --release --all-features --bin errplot -- [--out DIR] [--quick]
//! ```
//! Output goes to `errplot-out/` by default. `--quick` is accepted for CI and notebooks; the
//! 24-bit depth sweeps are exhaustive either way (they take seconds).

use prepass::depth::{self, DEPTH24_MAX};
use prepass::harness::{Gpu, HarnessError};
use prepass::sweep::depth24::{
    CODES, RECOVERY_CASES, hyperbolic_all, measure_hyperbolic, recover_all,
};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

const BASELINES: &str = include_str!("../../tests/baselines/depth24.wgsl");

struct Options {
    out: PathBuf,
    quick: bool,
}

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        out: PathBuf::from("errplot-out"),
        quick: false,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => o.out = args.next().ok_or("--out needs a directory")?.into(),
            "--quick" => o.quick = true,
            "-h" | "--help" => {
                println!("usage: errplot [--out DIR] [--quick]");
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument {other:?} (try --help)")),
        }
    }
    Ok(o)
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

struct Report {
    md: String,
}

impl Report {
    fn line(&mut self, s: impl AsRef<str>) {
        self.md.push_str(s.as_ref());
        self.md.push('\n');
    }
}

fn main() {
    let opts = match parse_args() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("errplot: {e}");
            std::process::exit(2);
        }
    };
    if let Err(e) = std::fs::create_dir_all(&opts.out) {
        eprintln!("errplot: cannot create {}: {e}", opts.out.display());
        std::process::exit(1);
    }
    let started = Instant::now();
    let mut r = Report { md: String::new() };
    r.line("# prepass error report");
    r.line("");
    let gpu = Gpu::new();
    match &gpu {
        Ok(g) => {
            r.line(format!("- Adapter: {}", g.describe()));
            if g.is_software() {
                r.line("  (a software adapter: its rounding is measured, its speed says nothing about a GPU)");
            }
        }
        Err(e) => {
            r.line(format!("- Adapter: **none** — {e}"));
            r.line(
                "- Columns marked *adapter* below are empty; only CPU-side results were computed.",
            );
        }
    }
    r.line(format!("- CPU: {}", cpu_name()));
    r.line(format!(
        "- Mode: {}",
        if opts.quick { "quick" } else { "full" }
    ));
    r.line("");

    if let Err(e) = depth24_section(gpu.as_ref().ok(), &opts, &mut r) {
        eprintln!("errplot: {e}");
        std::process::exit(1);
    }

    r.line("");
    r.line(format!(
        "Generated in {:.1} s by `bash .ci/errplot` (`cargo run --release --all-features --bin errplot`).",
        started.elapsed().as_secs_f64()
    ));
    let path = opts.out.join("report.md");
    if let Err(e) = std::fs::write(&path, &r.md) {
        eprintln!("errplot: cannot write {}: {e}", path.display());
        std::process::exit(1);
    }
    print!("{}", r.md);
    eprintln!("errplot: wrote {}", opts.out.display());
}

fn depth24_section(gpu: Option<&Gpu>, opts: &Options, r: &mut Report) -> Result<(), HarnessError> {
    let src = format!("{}\n{BASELINES}", prepass::wgsl::DEPTH);
    r.line("## 24-bit depth from an RGBA8 texel");
    r.line("");
    r.line(format!("Every one of the {CODES} codes, channels perturbed as a sampler may return them (both directions per channel)."));
    r.line("");
    r.line("| function | channels | codes wrong (adapter) |");
    r.line("|---|---|---|");
    let mut csv = String::from("function,channel_error,flip,codes,mismatches\n");
    for f in ["depth24_from_rgb8", "baseline_depth24_from_rgb8_unrounded"] {
        for (error, flip) in RECOVERY_CASES {
            let wrong = match gpu {
                Some(g) => Some(recover_all(g, &src, f, error, flip)?.mismatches.count),
                None => None,
            };
            let cell = wrong.map_or("n/a (no adapter)".into(), |w| w.to_string());
            let dir = if flip { "flipped signs" } else { "signs" };
            r.line(format!("| `{f}` | {error} ({dir}) | {cell} |"));
            let _ = writeln!(
                csv,
                "{f},{error},{flip},{CODES},{}",
                wrong.map_or(String::new(), |w| w.to_string())
            );
        }
    }
    std::fs::write(opts.out.join("depth24_recovery.csv"), csv)
        .map_err(|e| HarnessError::Readback(e.to_string()))?;

    r.line("");
    r.line("### Hyperbolic depth d/(2^24−1) as f32");
    r.line("");
    r.line("| formulation | where | max ULP | mean ULP | exact round-trip failures | f32 round-trip failures | codes sharing a float |");
    r.line("|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "function,where,max_ulp,mean_ulp,rms_ulp,exact_roundtrip_failures,f32_roundtrip_failures,collisions\n",
    );
    let mut row = |name: &str, place: &str, h: &prepass::sweep::depth24::Hyperbolic| {
        r.line(format!(
            "| `{name}` | {place} | {:.3} | {:.4} | {} | {} | {} |",
            h.ulps.max,
            h.ulps.mean(),
            h.exact_roundtrip_failures,
            h.f32_roundtrip_failures,
            h.collisions
        ));
        let _ = writeln!(
            csv,
            "{name},{place},{},{},{},{},{},{}",
            h.ulps.max,
            h.ulps.mean(),
            h.ulps.rms(),
            h.exact_roundtrip_failures,
            h.f32_roundtrip_failures,
            h.collisions
        );
    };
    let twin = measure_hyperbolic(
        (0..=DEPTH24_MAX)
            .map(depth::hyperbolic_depth_from_depth24)
            .collect(),
    );
    row("hyperbolic_depth_from_depth24", "Rust twin (CPU)", &twin);
    if let Some(g) = gpu {
        for f in [
            "hyperbolic_depth_from_depth24",
            "baseline_hyperbolic_divide",
            "baseline_hyperbolic_reciprocal",
        ] {
            let h = hyperbolic_all(g, &src, f)?;
            row(f, "adapter", &h);
        }
    }
    std::fs::write(opts.out.join("depth24_hyperbolic.csv"), csv)
        .map_err(|e| HarnessError::Readback(e.to_string()))?;
    Ok(())
}
