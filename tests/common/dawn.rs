//! WGSL through Dawn, whose WGSL compiler is Tint (Chrome's, Edge's): compile a module and build
//! its pipelines (which runs Tint's backend, not only its front end), or run a harness [`Dispatch`] and read its results back as the harness's [`Output`]. Node runs
//! `tests/dawn/run.mjs` (npm `webgpu`, pinned in `tests/dawn/package-lock.json`) with the
//! variables `bash .ci/setup-dawn` wrote to `target/dawn-env` (the Vulkan driver Dawn accepts).
//! Without that setup every caller FAILS, naming the command. `PREPASS_DAWN_KEEP=1` keeps each
//! runner's folder under `target/dawn-jobs/` (its `jobs.tsv` and files), to replay a run with
//! `node tests/dawn/run.mjs DIR` (after `source target/dawn-env`; delete `results.txt` first).

use prepass::harness::{Dispatch, Output};
use std::collections::VecDeque;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

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
    /// For a job with no dispatch: the pipelines to create of the module, each a WebGPU
    /// pipeline descriptor in JSON without `module` and `layout` (the runner sets them: the
    /// job's module, `"auto"`), e.g. [`compute`]. Creating one runs Tint's backend, which
    /// compiling the module alone does not: with none, only Tint's front end judges the module.
    pub pipelines: Vec<String>,
}

/// A compute pipeline of `entry`, for [`Job::pipelines`].
pub fn compute(entry: &str) -> String {
    format!(r#"{{"compute":{{"entryPoint":"{entry}"}}}}"#)
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

/// Jobs per node process, also the unit split across cores: dawn.node 0.6.2 crashed (SIGSEGV)
/// after a few thousand shader modules in one process, before run.mjs held Dawn's instance
/// (see `run_to_the_end`; likely the same cause, not measured again).
const JOBS_PER_PROCESS: usize = 256;

/// The adapter Dawn ran on and one [`Outcome`] per job, in order. Panics (the test fails) when
/// Dawn cannot be started, with the setup command.
pub fn run(jobs: Vec<Job>) -> (String, Vec<Outcome>) {
    let (adapter, outcomes, _) = run_with_faults(jobs, "");
    (adapter, outcomes)
}

/// [`run`], with faults injected into the runner to prove that the supervision survives them
/// (`tests/implementations.rs`): `faults` is run.mjs's `PREPASS_DAWN_FAULTS`, e.g.
/// `"crash:2,hang:4"` (abort at job 2 and block at job 4, each only in a process that started
/// before that job, as a real crash strikes once). Also returns how many runner processes were
/// replaced after a crash or a hang.
pub fn run_with_faults(mut jobs: Vec<Job>, faults: &str) -> (String, Vec<Outcome>, usize) {
    let mut chunks = Vec::new();
    while !jobs.is_empty() {
        let rest = jobs.split_off(jobs.len().min(JOBS_PER_PROCESS));
        chunks.push(jobs);
        jobs = rest;
    }
    // One node process per core at a time.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut results: Vec<Option<(String, Vec<Outcome>, usize)>> =
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
                .map(|(i, c)| scope.spawn(move || (i, run_one_process(c, faults))))
                .collect();
            for h in handles {
                let (i, r) = h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
                results[i] = Some(r);
            }
        });
    }
    let (mut adapter, mut outcomes, mut restarts) = (String::new(), Vec::new(), 0);
    for (a, o, r) in results.into_iter().flatten() {
        adapter = a;
        outcomes.extend(o);
        restarts += r;
    }
    (adapter, outcomes, restarts)
}

fn run_one_process(jobs: Vec<Job>, faults: &str) -> (String, Vec<Outcome>, usize) {
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
            None if job.pipelines.is_empty() => {
                let _ = writeln!(tsv, "{name}\t{src}\t-");
            }
            None => {
                let f = format!("pipes{i}.json");
                std::fs::write(dir.join(&f), format!("[{}]", job.pipelines.join(","))).unwrap();
                let _ = writeln!(tsv, "{name}\t{src}\t-\t{f}");
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
    // Nothing runs, so lavapipe's LLVM need not optimise what it compiles (as `.ci/test` does
    // for the compile-bound binaries): Tint's backend has run by then, and so has the driver's.
    let compile_only = jobs.iter().all(|j| j.dispatch.is_none());
    let (adapter, done, restarts) = run_to_the_end(&root, &dir, jobs.len(), faults, compile_only);
    let mut out: Vec<Outcome> = jobs
        .iter()
        .map(|j| Outcome {
            name: j.name.clone(),
            messages: Vec::new(),
            error: None,
            output: None,
        })
        .collect();
    for line in &done {
        let line = line.as_str();
        let (kind, rest) = line.split_once(' ').unwrap_or((line, ""));
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
    if std::env::var_os("PREPASS_DAWN_KEEP").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    }
    (adapter, out, restarts)
}

/// What the runner's `results.txt` holds so far: the adapter it named, the lines of every
/// finished job (a job's lines end with its `job` line, appended together), and the byte length
/// of that finished part (anything after it is a job cut off by a crash).
struct Finished {
    adapter: String,
    jobs: usize,
    lines: Vec<String>,
    bytes: u64,
}

fn read_finished(results: &Path) -> Finished {
    let text = std::fs::read_to_string(results).unwrap_or_default();
    let mut done = Finished {
        adapter: String::new(),
        jobs: 0,
        lines: Vec::new(),
        bytes: 0,
    };
    let mut pending = Vec::new();
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        at += line.len();
        let Some(line) = line.strip_suffix('\n') else {
            break; // cut off mid-line
        };
        if let Some(a) = line.strip_prefix("adapter ") {
            done.adapter = a.to_string();
            pending.clear();
        } else if line.starts_with("job ") {
            done.jobs += 1;
            done.lines.append(&mut pending);
            done.bytes = at as u64;
        } else {
            pending.push(line.to_string());
        }
    }
    done
}

/// CPU time (user + system, in the kernel's clock ticks, 100 a second for user space) that a
/// process has used, all its threads together; `None` where /proc cannot tell (not Linux).
fn cpu_ticks(pid: u32) -> Option<u64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // Fields after the parenthesised command name: state is field 3, utime 14, stime 15.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    Some(fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?)
}

/// A runner that finishes no job and uses less than `IDLE_CPU_TICKS` of CPU (2 % of a core)
/// over the last `HANG_WINDOW` is hung: seen here as a deadlock in Dawn's event processing
/// (`dawn::native::InstanceBase::ProcessEvents` waiting on a mutex no thread holds, the freed
/// instance's: see `run_to_the_end`; 2 s of CPU in 16 min, 0.2 %). A job that is compiling keeps a
/// core busy, and so does a dispatch on lavapipe (on a GPU these dispatches take milliseconds),
/// so a slow job is not mistaken for a hang. Where CPU time cannot be read (not Linux), only
/// `NO_JOB_LIMIT` without a finished job counts as hung.
const HANG_WINDOW: Duration = Duration::from_secs(5);
const IDLE_CPU_TICKS: u64 = 10;
const NO_JOB_LIMIT: Duration = Duration::from_secs(900);

/// Starts in a row that finish no job before the runner is given up on.
const FRUITLESS_STARTS: usize = 5;

/// Runs `dir`'s jobs to the end through as many node processes as it takes.
///
/// Why the runner crashed: the npm `webgpu` binding (dawn.node 0.6.2, the newest) does not keep
/// Dawn's instance alive from the device: only the JS objects `create()` and `requestAdapter()`
/// return do. run.mjs used them only at its start, so V8 was free to collect them mid-run; their
/// finaliser freed the instance that the binding's event loop still polls
/// (`InstanceBase::ProcessEvents` → `CallbackTaskManager::Flush` on freed memory), and the
/// process died by SIGSEGV, by SIGABRT ("std::system_error: Invalid argument", glibc's
/// `__pthread_mutex_lock` assertions) or deadlocked at 0 % CPU, at the first full GC after a
/// couple of hundred jobs. Reproduced by `node --expose-gc` with `gc()` after every job: every
/// run crashed at job 200 of 246 (6 of 6), and none of 10 with either object held.
/// run.mjs now holds them for the life of the process: replaying 246 small dispatches of
/// tests/implementations.rs, 0 of 30 runs crashed or hung, against 8 of 20 (6 crashes, 2 hangs)
/// before, on a 2-core Xeon (2026-12-06).
///
/// The restart stays as a guard, since Dawn is a large native library that we cannot fix here
/// and a crash costs a whole test binary otherwise: every finished job is on disk (run.mjs
/// appends it whole), so a crashed or hung process is replaced by one that starts at the first
/// unfinished job, and the crash is printed — a crash now is a new bug, to be reduced like this
/// one. A runner that exits with a status (an error it reports) fails at once, as does one that
/// crashes or hangs `FRUITLESS_STARTS` times in a row without finishing a job.
fn run_to_the_end(
    root: &Path,
    dir: &Path,
    total: usize,
    faults: &str,
    compile_only: bool,
) -> (String, Vec<String>, usize) {
    let results = dir.join("results.txt");
    let (mut fruitless, mut restarts) = (0, 0);
    loop {
        let before = read_finished(&results);
        if before.jobs == total {
            return (before.adapter, before.lines, restarts);
        }
        // Drop a job cut off mid-write before appending again.
        if let Ok(f) = std::fs::OpenOptions::new().write(true).open(&results) {
            f.set_len(before.bytes).unwrap();
        }
        let mut child = Command::new("bash")
            .arg("-c")
            .arg("source target/dawn-env && exec node tests/dawn/run.mjs \"$0\" \"$1\"")
            .arg(dir)
            .arg(before.jobs.to_string())
            .current_dir(root)
            .env("PREPASS_DAWN_FAULTS", faults)
            .envs(
                (compile_only && std::env::var_os("GALLIVM_PERF").is_none())
                    .then_some(("GALLIVM_PERF", "nopt")),
            )
            .spawn()
            .unwrap_or_else(|e| panic!("cannot start bash/node for Dawn ({e}): {SETUP}"));
        let (mut seen_jobs, mut since_job) = (before.jobs, Instant::now());
        // CPU time samples of the last HANG_WINDOW, oldest first.
        let mut samples: VecDeque<(Instant, Option<u64>)> = VecDeque::new();
        let ended = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break Some(status);
            }
            std::thread::sleep(Duration::from_millis(100));
            let now = read_finished(&results).jobs;
            if now > seen_jobs {
                (seen_jobs, since_job) = (now, Instant::now());
            }
            samples.push_back((Instant::now(), cpu_ticks(child.id())));
            while samples.len() > 2 && samples[1].0.elapsed() >= HANG_WINDOW {
                samples.pop_front();
            }
            let idle = match (samples.front(), samples.back()) {
                (Some(&(then, Some(a))), Some(&(_, Some(b)))) => {
                    then.elapsed() >= HANG_WINDOW
                        && since_job.elapsed() >= HANG_WINDOW
                        && b.saturating_sub(a) < IDLE_CPU_TICKS
                }
                _ => false,
            };
            if idle || since_job.elapsed() >= NO_JOB_LIMIT {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
        };
        let after = read_finished(&results);
        let what = match ended {
            Some(status) if status.success() => {
                assert_eq!(
                    after.jobs, total,
                    "Dawn's runner exited 0 with {} of {total} jobs finished: {SETUP}",
                    after.jobs
                );
                continue;
            }
            Some(status) => {
                assert!(
                    status.code().is_none(),
                    "Dawn's runner failed ({status}; its message is above): {SETUP}"
                );
                format!("crashed ({status})")
            }
            None => format!(
                "hung (no job finished in {} s, under {} s of CPU in the last {} s)",
                since_job.elapsed().as_secs(),
                IDLE_CPU_TICKS as f64 / 100.0,
                HANG_WINDOW.as_secs()
            ),
        };
        fruitless = if after.jobs > before.jobs {
            0
        } else {
            fruitless + 1
        };
        restarts += 1;
        assert!(
            fruitless < FRUITLESS_STARTS,
            "Dawn's runner {what}, {FRUITLESS_STARTS} starts in a row without finishing a \
             job (at job {} of {total}): {SETUP}",
            after.jobs
        );
        eprintln!(
            "Dawn's runner {what} after job {} of {total} (this start began at {}): starting \
             again from job {}",
            after.jobs, before.jobs, after.jobs
        );
    }
}

fn unique() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static N: AtomicU64 = AtomicU64::new(0);
    N.fetch_add(1, Ordering::Relaxed)
}

/// Compile every library `(name, source)` (functions, no entry point) to a compute pipeline
/// with Tint (through Dawn) and FAIL on any error, naming the module and Tint's or Dawn's
/// message; warnings are printed, one line each. Each library gets the entry point
/// `prepass::isa` compiles libraries with ([`prepass::isa::library_kernel`]: every function
/// the harness can call, called on arguments read from a storage buffer, every result stored),
/// so Tint's backend compiles every function, not only its front end. A function that entry
/// point neither calls nor reaches (a pointer, struct or `bool` parameter or result) FAILS
/// too: no pipeline would compile it. Returns how many compiled.
#[allow(dead_code)]
pub fn assert_compile(modules: Vec<(String, String)>) -> usize {
    assert_libraries(modules.into_iter().map(|(n, s)| (n, s, true)).collect())
}

/// [`assert_compile`] where only the libraries marked `true` are built to pipelines; the rest
/// meet Tint's front end alone (a sample's budget: the caller says why the sample holds).
pub fn assert_libraries(modules: Vec<(String, String, bool)>) -> usize {
    let mut left_out = Vec::new();
    let modules: Vec<_> = modules
        .into_iter()
        .map(|(name, source, build)| {
            if !build {
                return (name, source, Vec::new());
            }
            let k = prepass::isa::library_kernel(&source)
                .unwrap_or_else(|e| panic!("{name}: naga rejects it: {e}"));
            for (f, why) in k.left_out {
                left_out.push(format!("{name}: `{f}`: {why}"));
            }
            (name, k.source, vec![compute(prepass::isa::ENTRY)])
        })
        .collect();
    assert!(
        left_out.is_empty(),
        "no Tint pipeline would compile these functions (the witness entry point cannot call \
         them and no function it calls reaches them): call each from a function of scalars and \
         vectors, or extend `prepass::isa::library_kernel`:\n{}",
        left_out.join("\n")
    );
    assert_pipelines(modules)
}

/// Build every `(name, source, pipelines)` with Tint (through Dawn): compile the module and
/// create each pipeline ([`Job::pipelines`]; none: Tint's front end alone), and FAIL on any
/// error, naming the module and Tint's or Dawn's message; warnings are printed, one line each.
/// Returns how many modules compiled.
pub fn assert_pipelines(modules: Vec<(String, String, Vec<String>)>) -> usize {
    let n = modules.len();
    let built = modules.iter().filter(|m| !m.2.is_empty()).count();
    let jobs = modules
        .into_iter()
        .map(|(name, source, pipelines)| Job {
            name,
            source,
            dispatch: None,
            pipelines,
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
        "Tint (Dawn on {adapter}): {n} modules, {built} of them built to pipelines, {} with \
         errors, {warnings} warnings",
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
