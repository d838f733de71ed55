//! WGSL through Dawn, whose WGSL compiler is Tint (Chrome's, Edge's): compile a module, or run a
//! harness [`Dispatch`] and read its results back as the harness's [`Output`]. Node runs
//! `tests/dawn/run.mjs` (npm `webgpu`, pinned in `tests/dawn/package-lock.json`) with the
//! variables `bash .ci/setup-dawn` wrote to `target/dawn-env` (the Vulkan driver Dawn accepts).
//! Without that setup every caller FAILS, naming the command.

use prepass::harness::{Dispatch, Output};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::Command;

/// The fix named in every failure to start Dawn.
pub const SETUP: &str = "run `bash .ci/setup-dawn` (installs the pinned npm package `webgpu` in \
     tests/dawn and, where Dawn refuses the machine's Vulkan driver, Mesa 25 lavapipe beside it)";

/// One module for Dawn: compiled only, or compiled and dispatched.
pub struct Job {
    /// A name for messages.
    pub name: String,
    /// The WGSL (for a dispatch, the dispatch's own source is used).
    pub source: String,
    /// What to run, if anything.
    pub dispatch: Option<Dispatch>,
}

/// What Dawn said of a job.
#[derive(Debug)]
pub struct Outcome {
    /// The job's name.
    pub name: String,
    /// Tint's compilation messages: `(type, "line:col message")`.
    pub messages: Vec<(String, String)>,
    /// A shader-module or pipeline validation error.
    pub error: Option<String>,
    /// The dispatch's results.
    pub output: Option<Output>,
}

/// Jobs per node process: dawn.node 0.6.2 crashed (SIGSEGV) after a few thousand shader
/// modules in one process.
const JOBS_PER_PROCESS: usize = 256;

/// The adapter Dawn ran on and one [`Outcome`] per job, in order. Panics (the test fails) when
/// Dawn cannot be started, with the setup command.
pub fn run(mut jobs: Vec<Job>) -> (String, Vec<Outcome>) {
    let mut chunks = Vec::new();
    while !jobs.is_empty() {
        let rest = jobs.split_off(jobs.len().min(JOBS_PER_PROCESS));
        chunks.push(jobs);
        jobs = rest;
    }
    // One node process per core at a time.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut results: Vec<Option<(String, Vec<Outcome>)>> =
        (0..chunks.len()).map(|_| None).collect();
    let total: usize = chunks.iter().map(Vec::len).sum();
    let mut done = 0;
    let mut pending: Vec<(usize, Vec<Job>)> = chunks.into_iter().enumerate().rev().collect();
    while !pending.is_empty() {
        // Progress on long runs (thousands of modules), straight to stderr: the test harness
        // captures only the print macros.
        if total > 4 * JOBS_PER_PROCESS
            && done % (8 * JOBS_PER_PROCESS) < threads * JOBS_PER_PROCESS
        {
            use std::io::Write as _;
            let line = format!("  … Dawn (Tint): {done}/{total} jobs\n");
            let _ = std::io::stderr().write_all(line.as_bytes());
        }
        done += pending
            .iter()
            .rev()
            .take(threads)
            .map(|(_, c)| c.len())
            .sum::<usize>();
        let batch: Vec<(usize, Vec<Job>)> = (0..threads).filter_map(|_| pending.pop()).collect();
        std::thread::scope(|scope| {
            let handles: Vec<_> = batch
                .into_iter()
                .map(|(i, c)| scope.spawn(move || (i, run_one_process(c))))
                .collect();
            for h in handles {
                let (i, r) = h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
                results[i] = Some(r);
            }
        });
    }
    let mut adapter = String::new();
    let mut outcomes = Vec::new();
    for (a, o) in results.into_iter().flatten() {
        adapter = a;
        outcomes.extend(o);
    }
    (adapter, outcomes)
}

fn run_one_process(jobs: Vec<Job>) -> (String, Vec<Outcome>) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let env_file = root.join("target/dawn-env");
    assert!(
        env_file.exists() && root.join("tests/dawn/node_modules/webgpu").exists(),
        "Dawn is not set up here: {SETUP}"
    );
    let dir = root.join(format!(
        "target/dawn-jobs/{}-{}",
        std::process::id(),
        unique()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let mut tsv = String::new();
    for (i, job) in jobs.iter().enumerate() {
        let src = format!("src{i}.wgsl");
        let text = job.dispatch.as_ref().map_or(&job.source, |d| &d.source);
        std::fs::write(dir.join(&src), text).unwrap();
        let name = job.name.replace(['\t', '\n'], " ");
        match &job.dispatch {
            None => {
                let _ = writeln!(tsv, "{name}\t{src}\t-");
            }
            Some(d) => {
                let mut cols = Vec::new();
                for (k, c) in d.columns.iter().enumerate() {
                    let f = format!("col{i}_{k}.bin");
                    std::fs::write(dir.join(&f), c).unwrap();
                    cols.push(f);
                }
                let uniform: Vec<String> = d.uniform.iter().map(u32::to_string).collect();
                let cols = if cols.is_empty() {
                    "-".to_string()
                } else {
                    cols.join(",")
                };
                let _ = writeln!(
                    tsv,
                    "{name}\t{src}\t{}\t{}\t{cols}\t{}\t{},{}",
                    d.entry,
                    uniform.join(","),
                    d.output_words(),
                    d.groups[0],
                    d.groups[1]
                );
            }
        }
    }
    std::fs::write(dir.join("jobs.tsv"), tsv).unwrap();
    // Dawn's node binding sometimes dies by a signal, mid-run and before any result is written
    // (SIGSEGV, or SIGABRT after "std::system_error: Invalid argument": 6 of 14 runs of
    // tests/implementations.rs on a 2-core EPYC, 2026-12-04). A crashed process has produced
    // no results (results.txt is written last); it is run again, a few times, and the crash
    // printed each time. A runner that exits with a status (an error it reports) fails at once,
    // as does one that keeps crashing.
    // 3 attempts were not enough once in CI (2026-12-04: SIGABRT, SIGSEGV, then a glibc
    // assertion in __pthread_tpp_change_priority, all in Dawn's process).
    const ATTEMPTS: usize = 8;
    for attempt in 1..=ATTEMPTS {
        let status = Command::new("bash")
            .arg("-c")
            .arg("source target/dawn-env && exec node tests/dawn/run.mjs \"$0\"")
            .arg(&dir)
            .current_dir(&root)
            .status()
            .unwrap_or_else(|e| panic!("cannot start bash/node for Dawn ({e}): {SETUP}"));
        if status.success() {
            break;
        }
        let crashed = status.code().is_none();
        assert!(
            crashed && attempt < ATTEMPTS,
            "Dawn's runner failed ({status}; its message is above{}): {SETUP}",
            if crashed { ", every attempt" } else { "" }
        );
        eprintln!(
            "Dawn's runner crashed ({status}), attempt {attempt} of {ATTEMPTS}: running it again"
        );
    }
    let text = std::fs::read_to_string(dir.join("results.txt")).unwrap();
    let mut adapter = String::new();
    let mut out: Vec<Outcome> = jobs
        .iter()
        .map(|j| Outcome {
            name: j.name.clone(),
            messages: Vec::new(),
            error: None,
            output: None,
        })
        .collect();
    for line in text.lines() {
        let (kind, rest) = line.split_once(' ').unwrap_or((line, ""));
        if kind == "adapter" {
            adapter = rest.to_string();
            continue;
        }
        let (i, rest) = rest.split_once(' ').unwrap_or((rest, ""));
        let i: usize = i.parse().unwrap();
        match kind {
            "msg" => {
                let (ty, m) = rest.split_once(' ').unwrap_or((rest, ""));
                out[i].messages.push((ty.to_string(), m.to_string()));
            }
            "err" => out[i].error = Some(rest.to_string()),
            "out" => {
                let bytes = std::fs::read(dir.join(rest)).unwrap();
                let words = bytes
                    .chunks_exact(4)
                    .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                    .collect();
                let d = jobs[i].dispatch.as_ref().expect("out for a dispatch");
                out[i].output = Some(d.output(words).unwrap());
            }
            _ => {}
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    (adapter, out)
}

fn unique() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static N: AtomicU64 = AtomicU64::new(0);
    N.fetch_add(1, Ordering::Relaxed)
}

/// Compile every `(name, source)` with Tint (through Dawn) and FAIL on any error, naming the
/// module and Tint's message; warnings are printed, one line each. Returns how many compiled.
#[allow(dead_code)]
pub fn assert_compile(modules: Vec<(String, String)>) -> usize {
    let n = modules.len();
    let jobs = modules
        .into_iter()
        .map(|(name, source)| Job {
            name,
            source,
            dispatch: None,
        })
        .collect();
    let (adapter, outcomes) = run(jobs);
    let mut errors = Vec::new();
    let mut warnings = 0;
    for o in &outcomes {
        for (ty, m) in &o.messages {
            if ty == "error" {
                errors.push(format!("{}: {m}", o.name));
            } else {
                warnings += 1;
                eprintln!("Tint {ty}: {}: {m}", o.name);
            }
        }
        if let Some(e) = &o.error {
            errors.push(format!("{}: {e}", o.name));
        }
    }
    eprintln!(
        "Tint (Dawn on {adapter}): {n} modules, {} with errors, {warnings} warnings",
        errors.len()
    );
    assert!(
        errors.is_empty(),
        "Tint rejects {} of {n} modules:\n{}",
        errors.len(),
        errors.join("\n")
    );
    n
}
