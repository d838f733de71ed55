//! What a WGSL function costs on real GPU instruction sets: AMD's ACO and Intel's brw compile it
//! without the hardware, and their own statistics are read back.
//!
//! Mesa's RADV (ACO) and ANV (brw) Vulkan drivers run on a machine with no GPU behind Mesa's
//! noop kernel-driver shims: they create pipelines, and report per pipeline what shader-db and
//! Fossilize read through `VK_KHR_pipeline_executable_properties` — instruction counts,
//! registers, occupancy, ACO's latency and inverse-throughput model, brw's cycle estimate. They
//! cannot run anything (submissions do nothing), so every compile happens in a **child
//! process** with its own driver environment, never in the caller's process: the child is the
//! caller's own executable, entered before `main` (see `child.rs`), so a test binary, errplot
//! and a user's program all work without a helper to install. Mesa's shader cache is off in the
//! child, so every figure is a fresh compile.
//!
//! **A figure is a static compiler estimate**, for the Mesa version it names: what the
//! compiler emitted and its own scheduling model, not a timing. Compare within one target:
//! AMD's figures are per wave64, Intel's per SIMD thread.
//!
//! # How a function is wrapped
//! As the harness wraps it ([`Signature::read`], the same [`Feed`]s): a compute kernel loads
//! every argument (columns from storage buffers, splats from a uniform, as a renderer's uniform),
//! calls the function and stores its result's bits. The kernel evaluates
//! [`Costing::independent`] (`k`, default 8) independent inputs per invocation, so a small
//! function does not hide under the memory floor of ACO's throughput model. The same wrap
//! without the call — the same loads, and the XOR of the arguments' first lanes stored in every
//! result lane — is the **baseline**; every per-evaluation figure is net of it:
//!
//! - instructions, ALU instructions, ACO inverse throughput, brw cycles: `(f_k − b_k) / k`, the
//!   k-way kernel minus the k-way baseline, per evaluation;
//! - ACO latency: `f_1 − b_1`, one evaluation's critical path (its own kernel, `k = 1`);
//! - registers, spills and occupancy: the `k = 1` kernel as it is (not net: what a renderer's
//!   shader pays holding one evaluation), beside the baseline's.
//!
//! # Setup
//! `bash .ci/setup-gpu-compilers` unpacks Mesa 25's drivers and shims from Debian
//! bookworm-backports and builds Intel's shim from Mesa's source package (a minute or two,
//! once); [`Costing::new`] finds them through [`ROOT_VAR`]. A target whose pieces are missing
//! is reported as not measured, with the reason, never as a number.
//!
//! ```no_run
//! use prepass::isa::{Costing, Function, Target};
//! let report = Costing::new()
//!     .targets(&[Target::Rdna2, Target::XeHpg])
//!     .cost(&[Function::new(prepass::wgsl::NORMAL_OCT, "encode_normal_oct24")])?;
//! for t in &report.targets {
//!     match &t.outcome {
//!         Ok(costs) => {
//!             let c = costs.functions[0].clone()?;
//!             println!("{}: {:.1} instructions ({})", t.target, c.net.instructions, costs.driver_info);
//!         }
//!         Err(why) => println!("{}: not measured: {why}", t.target),
//!     }
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod child;
pub mod freedoms;
mod kernel;
mod stats;
mod target;

pub use child::CHILD_VAR;
pub use kernel::ENTRY;
pub use stats::{Cost, Net, Stats};
pub use target::{ROOT_VAR, Target, Vendor, default_root};

use crate::harness::{Feed, Signature};
use std::collections::HashMap;
use std::path::PathBuf;
use std::process::Command;

/// A WGSL function to cost: a source valid on its own, the function's name, and how each
/// argument is fed (by default every argument a column, one value per evaluation).
#[derive(Clone, Debug)]
pub struct Function {
    /// The WGSL source holding the function and whatever it calls.
    pub source: String,
    /// The function's name.
    pub function: String,
    /// One feed per parameter, or empty for "every argument a column".
    pub feeds: Vec<Feed>,
}

impl Function {
    /// `function` from `source`, every argument a column.
    pub fn new(source: &str, function: &str) -> Self {
        Function {
            source: source.to_string(),
            function: function.to_string(),
            feeds: Vec::new(),
        }
    }

    /// The same, with the feeds given (a [`Feed::Splat`] is read from a uniform, as a
    /// renderer's per-frame constants are; [`Feed::Index`] is costed as a column).
    pub fn with_feeds(mut self, feeds: &[Feed]) -> Self {
        self.feeds = feeds.to_vec();
        self
    }
}

/// Why nothing could be costed at all (per-target and per-function failures are reported in
/// the [`Report`] instead).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IsaError(pub String);

impl std::fmt::Display for IsaError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for IsaError {}

/// Every function's cost on one target, with the driver that compiled them.
#[derive(Clone, Debug)]
pub struct TargetCosts {
    /// The device and driver as the driver names them, e.g. `AMD Radeon RX 6800 (RADV NAVI21)
    /// (radv)`.
    pub driver: String,
    /// The driver's version string, e.g. `Mesa 25.0.7-2~bpo12+1`.
    pub driver_info: String,
    /// One entry per function, in order; `Err` holds the compiler's or naga's message.
    pub functions: Vec<Result<Cost, String>>,
}

/// One target's outcome.
#[derive(Clone, Debug)]
pub struct TargetReport {
    /// The target.
    pub target: Target,
    /// Its costs, or why it was not measured (a missing piece, a driver that did not start).
    pub outcome: Result<TargetCosts, String>,
}

/// What [`Costing::cost`] found, one entry per target asked for.
#[derive(Clone, Debug)]
pub struct Report {
    /// In the order the targets were given.
    pub targets: Vec<TargetReport>,
}

impl Report {
    /// The cost of function `index` on `target`, if it was measured.
    pub fn get(&self, target: Target, index: usize) -> Option<&Cost> {
        let t = self.targets.iter().find(|t| t.target == target)?;
        t.outcome.as_ref().ok()?.functions.get(index)?.as_ref().ok()
    }

    /// The driver version that compiled for `target`, if it was measured.
    pub fn driver_info(&self, target: Target) -> Option<&str> {
        let t = self.targets.iter().find(|t| t.target == target)?;
        Some(t.outcome.as_ref().ok()?.driver_info.as_str())
    }
}

/// A costing run: which targets, how many independent evaluations per invocation, where the
/// compilers are.
#[derive(Clone, Debug)]
pub struct Costing {
    root: Option<PathBuf>,
    targets: Vec<Target>,
    independent: u32,
    disassembly: bool,
}

impl Default for Costing {
    fn default() -> Self {
        Self::new()
    }
}

impl Costing {
    /// Every target of [`Target::ALL`], 8 evaluations per invocation, the compilers from
    /// [`default_root`].
    pub fn new() -> Self {
        Costing {
            root: default_root(),
            targets: Target::ALL.to_vec(),
            independent: 8,
            disassembly: false,
        }
    }

    /// Cost on these targets only.
    pub fn targets(mut self, targets: &[Target]) -> Self {
        self.targets = targets.to_vec();
        self
    }

    /// Independent evaluations per invocation (at least 1).
    pub fn independent(mut self, k: u32) -> Self {
        self.independent = k.max(1);
        self
    }

    /// Where `.ci/setup-gpu-compilers` put the compilers.
    pub fn root(mut self, root: impl Into<PathBuf>) -> Self {
        self.root = Some(root.into());
        self
    }

    /// Also keep each function's disassembly (the `k = 1` kernel) in [`Cost::disassembly`].
    pub fn disassembly(mut self, keep: bool) -> Self {
        self.disassembly = keep;
        self
    }

    /// Compile every function for every target, one child process per target (run side by
    /// side), and return the net per-evaluation figures. A function naga rejects fails the call;
    /// a target that cannot be compiled for is reported in its [`TargetReport`].
    pub fn cost(&self, functions: &[Function]) -> Result<Report, IsaError> {
        let dir = scratch_dir()?;
        let result = self.cost_in(&dir, functions);
        let _ = std::fs::remove_dir_all(&dir);
        result
    }

    fn cost_in(&self, dir: &std::path::Path, functions: &[Function]) -> Result<Report, IsaError> {
        // Four kernels per function (k-way and one-way, function and baseline); baselines are
        // shared between functions with the same signature and feeds.
        let mut modules: Vec<(PathBuf, String)> = Vec::new();
        let mut by_source: HashMap<String, usize> = HashMap::new();
        let mut plan = Vec::new();
        let k = self.independent;
        for f in functions {
            let sig = Signature::read(&f.source, &f.function)
                .map_err(|e| IsaError(format!("{}: {e}", f.function)))?;
            let feeds = if f.feeds.is_empty() {
                vec![Feed::Column; sig.params.len()]
            } else if f.feeds.len() == sig.params.len() {
                f.feeds.clone()
            } else {
                return Err(IsaError(format!(
                    "{}: {} feeds for {} parameters",
                    f.function,
                    f.feeds.len(),
                    sig.params.len()
                )));
            };
            let mut ids = [0usize; 4];
            for (slot, (kk, evaluate)) in [(k, true), (k, false), (1, true), (1, false)]
                .into_iter()
                .enumerate()
            {
                let w = kernel::wrap(&f.source, &sig, &feeds, kk, evaluate);
                let id = match by_source.get(&w.source) {
                    Some(&id) => id,
                    None => {
                        let path = spirv_file(dir, modules.len(), &w.source)
                            .map_err(|e| IsaError(format!("{}: {e}", f.function)))?;
                        by_source.insert(w.source.clone(), modules.len());
                        modules.push((path, w.bindings));
                        modules.len() - 1
                    }
                };
                ids[slot] = id;
            }
            plan.push(ids);
        }
        let root = self.root.clone();
        let disassembly = self.disassembly;
        let targets = per_target(&self.targets, |target| TargetReport {
            target,
            outcome: compile_for(
                target,
                root.as_deref(),
                dir,
                &modules,
                &plan,
                k,
                disassembly,
            ),
        });
        Ok(Report { targets })
    }
}

/// `f` for every target, each on its own thread (each waits on its own child process), in the
/// targets' order.
fn per_target<T: Send>(targets: &[Target], f: impl Fn(Target) -> T + Sync) -> Vec<T> {
    std::thread::scope(|scope| {
        let f = &f;
        let handles: Vec<_> = targets.iter().map(|&t| scope.spawn(move || f(t))).collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a compiling thread panicked"))
            .collect()
    })
}

fn scratch_dir() -> Result<PathBuf, IsaError> {
    use std::sync::atomic::{AtomicU32, Ordering};
    static NEXT: AtomicU32 = AtomicU32::new(0);
    let dir = std::env::temp_dir().join(format!(
        "prepass-isa-{}-{}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir).map_err(|e| IsaError(format!("{}: {e}", dir.display())))?;
    Ok(dir)
}

/// The most pipelines one child process compiles: Mesa's drm shims crash (SIGSEGV) after some
/// 500 pipelines in one process (measured on polaris10: 162 shipped functions, about 650
/// modules, crashed; 158 did not), so a long list goes through several children in turn.
const CHILD_MODULES: usize = 256;

/// [`run_child`] over `modules` in parts of at most [`CHILD_MODULES`], the answers joined. A
/// part whose child fails runs once more (the failure is printed to stderr): once in some 50
/// runs of `tests/isa.rs` a child failed on a 16-module list, the first run after a fresh
/// build, and never in the reruns (2026-12-07; its reason was not kept). Both reasons are
/// returned when the second fails too.
fn run_children(
    target: Target,
    root: Option<&std::path::Path>,
    dir: &std::path::Path,
    modules: &[(PathBuf, String)],
    wants_asm: &[bool],
) -> Result<stats::Answer, String> {
    let mut parsed: Option<stats::Answer> = None;
    for (n, (chunk, asm)) in modules
        .chunks(CHILD_MODULES)
        .zip(wants_asm.chunks(CHILD_MODULES))
        .enumerate()
    {
        let part = run_child(target, root, dir, n, chunk, asm).or_else(|first| {
            // Compiling is deterministic, so a second child answers as the first would have.
            eprintln!(
                "prepass::isa: the {} compiling child failed ({first}); running it once more",
                target.chip()
            );
            run_child(target, root, dir, n, chunk, asm)
                .map_err(|second| format!("{first}; run again: {second}"))
        })?;
        match &mut parsed {
            None => parsed = Some(part),
            Some(all) => all.modules.extend(part.modules),
        }
    }
    parsed.ok_or_else(|| "nothing to compile".to_string())
}

/// One child process for `target` (the `part`-th of its jobs): write the job, run it, read the
/// answer.
fn run_child(
    target: Target,
    root: Option<&std::path::Path>,
    dir: &std::path::Path,
    part: usize,
    modules: &[(PathBuf, String)],
    wants_asm: &[bool],
) -> Result<stats::Answer, String> {
    let root = root.ok_or_else(|| {
        format!("no compilers: set {ROOT_VAR} (bash .ci/setup-gpu-compilers fills it)")
    })?;
    let env = target::environment(root, target)?;
    let mut job = String::new();
    for ((path, bindings), asm) in modules.iter().zip(wants_asm) {
        job.push_str(&format!(
            "module\t{}\t{ENTRY}\t{bindings}\t{}\n",
            path.display(),
            u8::from(*asm)
        ));
    }
    let job_path = dir.join(format!("job-{}-{part}", target.chip()));
    std::fs::write(&job_path, job).map_err(|e| format!("{}: {e}", job_path.display()))?;
    let exe = std::env::current_exe().map_err(|e| format!("current_exe: {e}"))?;
    let out = Command::new(&exe)
        .env(CHILD_VAR, &job_path)
        .envs(env)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .output()
        .map_err(|e| format!("cannot start {}: {e}", exe.display()))?;
    let answer_path = {
        let mut p = job_path.into_os_string();
        p.push(".out");
        PathBuf::from(p)
    };
    let answer = std::fs::read_to_string(&answer_path).map_err(|_| {
        format!(
            "the compiling child exited with {} and wrote no answer; stderr: {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        )
    })?;
    let parsed = stats::parse_answer(&answer, modules.len(), target.vendor())?;
    if let Some(name) = stats::device_mismatch(target, &parsed.driver) {
        return Err(format!(
            "the driver compiled for {name}, not {}: the shim did not take",
            target.chip()
        ));
    }
    Ok(parsed)
}

/// Net the four kernels of every function compiled for `target`.
fn compile_for(
    target: Target,
    root: Option<&std::path::Path>,
    dir: &std::path::Path,
    modules: &[(PathBuf, String)],
    plan: &[[usize; 4]],
    k: u32,
    disassembly: bool,
) -> Result<TargetCosts, String> {
    // The one-way function kernels (slot 2) carry the disassembly when asked.
    let wants_asm: Vec<bool> = (0..modules.len())
        .map(|m| disassembly && plan.iter().any(|ids| ids[2] == m))
        .collect();
    let parsed = run_children(target, root, dir, modules, &wants_asm)?;
    let functions = plan
        .iter()
        .map(|ids| {
            let get = |m: usize| parsed.modules[m].clone();
            let (fk, bk, f1, b1) = (get(ids[0])?, get(ids[1])?, get(ids[2])?, get(ids[3])?);
            Ok(Cost::net(k, &fk, &bk, &f1, &b1))
        })
        .collect();
    Ok(TargetCosts {
        driver: parsed.driver,
        driver_info: parsed.driver_info,
        functions,
    })
}

/// Write `source` (a module with the [`ENTRY`] compute entry point) as SPIR-V into `dir`.
fn spirv_file(dir: &std::path::Path, n: usize, source: &str) -> Result<PathBuf, String> {
    let checked = crate::wgsl::parse_and_validate(source).map_err(|e| e.to_string())?;
    let words = naga::back::spv::write_vec(
        &checked.module,
        &checked.info,
        &naga::back::spv::Options::default(),
        Some(&naga::back::spv::PipelineOptions {
            shader_stage: naga::ShaderStage::Compute,
            entry_point: ENTRY.to_string(),
        }),
    )
    .map_err(|e| format!("SPIR-V: {e}"))?;
    let path = dir.join(format!("m{n}.spv"));
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// A library's witness kernel, as [`Costing::compile_libraries`] compiles it, for another
/// compiler to build a pipeline of (Tint, through Dawn, in the tests).
#[derive(Clone, Debug)]
pub struct LibraryKernel {
    /// The library with the [`ENTRY`] compute entry point appended. Bindings, group 0: 0 = the
    /// arguments (`array<u32>`, read), 1 = the XOR of the results (`array<u32>`, read_write).
    pub source: String,
    /// The functions the entry point calls: those whose signature the harness reads
    /// ([`Signature::read`]), and those it reads but for `f32` matrix parameters (loaded
    /// column by column).
    pub called: Vec<String>,
    /// The functions it cannot call (a pointer, struct or `bool` parameter or result, no
    /// result) that no called function reaches either, with why: no pipeline of this entry
    /// point compiles them.
    pub left_out: Vec<(String, String)>,
}

/// [`LibraryKernel`] of `source`, a WGSL library (functions, no entry point). Fails where naga
/// rejects it.
pub fn library_kernel(source: &str) -> Result<LibraryKernel, IsaError> {
    let (wrapped, called, left_out) = kernel::library(source).map_err(IsaError)?;
    Ok(LibraryKernel {
        source: wrapped.source,
        called,
        left_out,
    })
}

/// What [`Costing::compile_libraries`] found on one target: each library's kernel, compiled.
#[derive(Clone, Debug)]
pub struct LibraryReport {
    /// The target.
    pub target: Target,
    /// The driver's version and one entry per library (the compiler's message on failure), or
    /// why the target was not measured.
    pub outcome: Result<(String, Vec<Result<Stats, String>>), String>,
}

impl Costing {
    /// Compile whole WGSL libraries (modules of functions, no entry point) for every target, as
    /// a witness that the compilers accept them: each gets an entry point ([`library_kernel`])
    /// that calls every function whose signature the harness reads (`f32` matrix parameters
    /// included) on arguments loaded from a buffer, and stores
    /// the XOR of their results' bits (so no call is dead code); the names of the functions it
    /// calls come back with the report. A library naga rejects fails the call.
    pub fn compile_libraries(
        &self,
        sources: &[&str],
    ) -> Result<(Vec<LibraryReport>, Vec<Vec<String>>), IsaError> {
        let dir = scratch_dir()?;
        let result = (|| {
            let mut modules = Vec::new();
            let mut called = Vec::new();
            for (n, source) in sources.iter().enumerate() {
                let (wrapped, names, _) = kernel::library(source).map_err(IsaError)?;
                let path = spirv_file(&dir, n, &wrapped.source).map_err(IsaError)?;
                modules.push((path, wrapped.bindings));
                called.push(names);
            }
            let none = vec![false; modules.len()];
            let root = self.root.clone();
            let reports = per_target(&self.targets, |target| LibraryReport {
                target,
                outcome: run_children(target, root.as_deref(), &dir, &modules, &none).map(|a| {
                    let stats = a.modules.into_iter().map(|m| m.map(|c| c.stats)).collect();
                    (a.driver_info, stats)
                }),
            });
            Ok((reports, called))
        })();
        let _ = std::fs::remove_dir_all(&dir);
        result
    }
}
