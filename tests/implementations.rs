//! The shipped functions on WGSL implementations we did not write, measured the same way on each:
//! naga → SPIR-V on the machine's Vulkan driver (in this process), naga → SPIR-V on Mesa 25
//! lavapipe and naga → GLSL on Mesa's GL (llvmpipe, EGL without a display; both in a child
//! process of this binary, since the Vulkan loader and wgpu's backend are chosen at start-up), and
//! Tint → SPIR-V through Dawn. Every implementation must hold the promises made for every
//! conforming adapter; the figures go into `docs/figures.md` ("implementations"), compared as text
//! only where every implementation is the one it was published from.
//!
//! Inputs, the same everywhere: the linear-depth paths over the whole stiff grid, sampled as the
//! emulated suite samples it (`sweep::linear_depth::sampled_worst`: 66,049 codes, 2^16 float
//! depths); every normal codec on 2^14 spherical-Fibonacci directions plus the adversarial set;
//! `hyperbolic_depth_from_depth24` on every 8th code and the top 256; the roughness codec on
//! every code and 4,096 powers; every shipped function with a twin on 4,096 random argument
//! sets (results ≠ twin), on its bad-input rows (results ≠ the documented answer) and on the
//! fuzz corpora's inputs, with the non-finite results over all three (which must be none).

mod common;

#[path = "common/dawn.rs"]
mod dawn;

#[path = "bad_input/rows.rs"]
#[allow(dead_code)]
mod rows;

use prepass::harness::{Arg, Dispatch, HarnessError, Output};
use prepass::precision::metrics::{angle_degrees, ulp_distance, ulp_error, widen3};
use prepass::sweep::conforming::UNIT_TOLERANCE_CONFORMING;
use prepass::sweep::linear_depth::{PATHS, sampled_worst};
use prepass::sweep::normal::{CODECS, adversarial_directions, fibonacci_directions};
use std::cell::RefCell;
use std::fmt::Write as _;

/// The line a child process prints per figure: `XCHECK family|function|value|detail`.
const TAG: &str = "XCHECK ";

/// One figure of one implementation.
#[derive(Clone, Debug, PartialEq)]
struct Figure {
    family: &'static str,
    function: String,
    /// The worst error in the family's unit, or a count.
    value: f64,
    /// The bound on every conforming adapter, if the library states one for this figure.
    bound: Option<f64>,
    detail: String,
}

/// Runs a batch of calls on one implementation: the calls are recorded first, run together, and
/// their results handed back in order (Dawn starts one node process for all of them).
trait Executor {
    fn run_all(&self, calls: Vec<Dispatch>) -> Vec<Output>;
    /// The compiler and the adapter with its driver, in full.
    fn name(&self) -> String;
}

/// The machine's adapter through wgpu (this process).
struct Wgpu;

impl Executor for Wgpu {
    fn run_all(&self, calls: Vec<Dispatch>) -> Vec<Output> {
        calls.into_iter().map(run_dispatch_on_wgpu).collect()
    }

    fn name(&self) -> String {
        let i = common::gpu().adapter_info();
        let out = if i.backend == wgpu::Backend::Gl {
            "GLSL"
        } else {
            "SPIR-V"
        };
        format!(
            "naga → {out}, {:?}: {} ({})",
            i.backend, i.name, i.driver_info
        )
    }
}

/// A dispatch run by the harness itself: the module already holds its entry point, so the
/// harness compiles it as is (its `Kernel` appends one: here the function is the whole module).
fn run_dispatch_on_wgpu(d: Dispatch) -> Output {
    common::gpu()
        .run_dispatch(&d)
        .unwrap_or_else(|e| panic!("wgpu: {e}"))
}

/// Dawn (Tint).
struct Dawn(RefCell<String>);

/// One Dawn job per dispatch, named by its place.
fn dawn_jobs(calls: Vec<Dispatch>) -> Vec<dawn::Job> {
    calls
        .into_iter()
        .enumerate()
        .map(|(i, d)| dawn::Job {
            name: format!("call {i}"),
            source: String::new(),
            dispatch: Some(d),
            pipelines: Vec::new(),
        })
        .collect()
}

impl Executor for Dawn {
    fn run_all(&self, calls: Vec<Dispatch>) -> Vec<Output> {
        let (adapter, outcomes) = dawn::run(dawn_jobs(calls));
        *self.0.borrow_mut() = adapter;
        outcomes
            .into_iter()
            .map(|o| {
                assert!(o.error.is_none(), "Dawn, {}: {:?}", o.name, o.error);
                o.output.expect("a dispatch's output")
            })
            .collect()
    }

    fn name(&self) -> String {
        format!("Tint → SPIR-V, Dawn 0.6.2: {}", self.0.borrow())
    }
}

/// A dispatch of `function` in `source` over `args` (`n` elements).
fn call(source: &str, function: &str, args: &[Arg<'_>], n: u64) -> Dispatch {
    common::gpu()
        .kernel(source, function)
        .and_then(|k| k.dispatch(args, n))
        .unwrap_or_else(|e| panic!("{function}: {e}"))
}

/// Every figure on `exec`.
fn figures(exec: &dyn Executor) -> Vec<Figure> {
    let mut out = Vec::new();
    linear_depth(exec, &mut out);
    normals(exec, &mut out);
    depth24_and_roughness(exec, &mut out);
    every_function(exec, &mut out);
    out
}

/// Random arguments per lane, the same on every implementation: floats of either sign with
/// magnitudes log-uniform in [2^-8, 2^14] (cosines, distances, powers, depths), u32 lanes a
/// random word or a small value (conventions, vertex indices) by turns.
fn random_arg(ty: prepass::harness::ValueType, seed: &mut u64) -> rows::V {
    use prepass::harness::Scalar;
    use rows::V;
    let mut next = || {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        *seed
    };
    let mut lane = || -> u32 {
        let r = next();
        match ty.scalar {
            Scalar::U32 | Scalar::I32 => {
                if r & 1 == 0 {
                    (r >> 32) as u32
                } else {
                    ((r >> 32) % 4) as u32
                }
            }
            Scalar::F32 => {
                let u = ((r >> 11) as f64 / (1u64 << 53) as f64) * 22.0 - 8.0;
                let x = 2f64.powf(u) as f32;
                (if r & 1 == 0 { x } else { -x }).to_bits()
            }
        }
    };
    let w: Vec<u32> = (0..ty.lanes).map(|_| lane()).collect();
    let f = |i: usize| f32::from_bits(w[i]);
    match (ty.scalar, ty.lanes) {
        (prepass::harness::Scalar::F32, 1) => V::F32(f(0)),
        (prepass::harness::Scalar::F32, 2) => V::Vec2([f(0), f(1)]),
        (prepass::harness::Scalar::F32, 3) => V::Vec3([f(0), f(1), f(2)]),
        (prepass::harness::Scalar::F32, 4) => V::Vec4([f(0), f(1), f(2), f(3)]),
        (_, 1) => V::U32(w[0]),
        (_, 2) => V::UVec2([w[0], w[1]]),
        _ => panic!("no random {ty}"),
    }
}

/// Whether a result's words hold a non-finite `f32` lane.
fn non_finite(ty: prepass::harness::ValueType, w: &[u32]) -> bool {
    ty.scalar == prepass::harness::Scalar::F32 && w.iter().any(|&b| b & 0x7f80_0000 == 0x7f80_0000)
}

/// Per file of `wgsl/`: functions, random results ≠ twin, rows run and ≠ documented, results
/// and non-finite results, and each function differing from its twin with its largest distance
/// (ULP for float lanes, code steps for u32 lanes).
#[derive(Default)]
struct FileStats {
    functions: usize,
    differ: usize,
    rows: usize,
    rows_wrong: usize,
    inputs: usize,
    non_finite: usize,
    which: Vec<(&'static str, u64)>,
}

/// Every shipped WGSL function with a Rust twin (the bad-input table's) on three input sets:
/// 4,096 random argument sets (results ≠ twin, bit for bit, any NaN matching NaN), its
/// bad-input rows (results ≠ the documented answer) and the fuzz corpora's inputs; per file,
/// with the non-finite results over all three (none allowed: WGSL leaves a run-time ±∞ or NaN
/// indeterminate; builtins' wrappers, such as `unpack2x16float`'s, are not shipped functions and
/// not run here).
fn every_function(exec: &dyn Executor, out: &mut Vec<Figure>) {
    const N: usize = 4096;
    let mut calls = Vec::new();
    let mut cases = Vec::new();
    let columns_of = |sets: &mut dyn Iterator<Item = &[rows::V]>, arity: usize| {
        let mut columns = vec![Vec::new(); arity];
        for set in sets {
            for (col, &v) in columns.iter_mut().zip(set) {
                rows::words(v, col);
            }
        }
        columns
    };
    for f in rows::funcs() {
        let Some((source, name)) = f.wgsl else {
            continue;
        };
        let Some(file) = prepass::wgsl::FILES
            .iter()
            .find(|w| source.starts_with(w.source))
        else {
            continue; // a builtin's wrapper
        };
        let kernel = common::gpu().kernel(source, name).unwrap();
        let params: Vec<_> = kernel.signature().params.iter().map(|p| p.ty).collect();
        let mut seed = 0x9e37_79b9_7f4a_7c15u64 ^ (name.len() as u64);
        let args: Vec<Vec<rows::V>> = (0..N)
            .map(|_| params.iter().map(|&t| random_arg(t, &mut seed)).collect())
            .collect();
        let documented: Vec<&rows::Row> = rows::rows().filter(|r| r.func == f.key()).collect();
        let words: Vec<usize> = params.iter().map(|t| t.words()).collect();
        let sets = [
            columns_of(&mut args.iter().map(Vec::as_slice), params.len()),
            columns_of(&mut documented.iter().map(|r| r.args), params.len()),
            common::corpus_args(&words),
        ];
        for columns in &sets {
            let cols: Vec<Arg> = columns.iter().map(|c| Arg::column(c)).collect();
            let n = (columns[0].len() / words[0]) as u64;
            calls.push(kernel.dispatch(&cols, n).unwrap());
        }
        cases.push((file.name, f, args, documented));
    }
    let results = exec.run_all(calls);
    let mut per_file: Vec<(&str, FileStats)> = Vec::new();
    for ((file, f, args, documented), r) in cases.iter().zip(results.chunks(3)) {
        let (random, at_rows) = (&r[0], &r[1]);
        let width = random.ty.words();
        let i = match per_file.iter().position(|p| p.0 == *file) {
            Some(i) => i,
            None => {
                per_file.push((file, FileStats::default()));
                per_file.len() - 1
            }
        };
        let st = &mut per_file[i].1;
        st.functions += 1;
        let mut dist = None;
        for (a, w) in args.iter().zip(random.words().chunks(width)) {
            let twin = (f.twin)(a);
            if rows::same(rows::from_words(twin, w), twin) {
                continue;
            }
            st.differ += 1;
            let mut tw = Vec::new();
            rows::words(twin, &mut tw);
            for (&x, &y) in w.iter().zip(&tw) {
                let d = if random.ty.scalar == prepass::harness::Scalar::F32 {
                    ulp_distance(f32::from_bits(x), f32::from_bits(y)).unwrap_or(u64::MAX)
                } else {
                    u64::from(x.abs_diff(y))
                };
                dist = Some(dist.unwrap_or(0).max(d));
            }
        }
        if let Some(d) = dist {
            st.which.push((f.key(), d));
        }
        for (row, w) in documented.iter().zip(at_rows.words().chunks(width)) {
            st.rows += 1;
            // A row whose WGSL answer is indeterminate runs, unchecked.
            let Some(expect) = rows::wgsl_expect(row.expect) else {
                continue;
            };
            if !rows::same(rows::from_words(expect, w), expect) {
                st.rows_wrong += 1;
            }
        }
        for (set, out) in ["random", "bad-input", "corpus"].iter().zip(r) {
            st.inputs += out.len();
            let bad: Vec<usize> = out
                .words()
                .chunks(width)
                .enumerate()
                .filter(|(_, w)| non_finite(out.ty, w))
                .map(|(i, _)| i)
                .collect();
            if let Some(&i) = bad.first() {
                let example = if *set == "random" {
                    format!(", e.g. {:?}", args[i])
                } else {
                    String::new()
                };
                eprintln!(
                    "{}: {} non-finite results on the {set} inputs (first at #{i}{example})",
                    f.key(),
                    bad.len()
                );
            }
            st.non_finite += bad.len();
        }
    }
    for (file, st) in per_file {
        let which: Vec<String> = st
            .which
            .iter()
            .map(|(n, d)| format!("`{n}` ≤ {d}"))
            .collect();
        out.push(Figure {
            family: "every function, random inputs: results ≠ twin",
            function: file.to_string(),
            value: st.differ as f64,
            bound: None,
            detail: if which.is_empty() {
                format!("{} functions × {N}", st.functions)
            } else {
                format!(
                    "{} functions × {N}; differ: {}",
                    st.functions,
                    which.join(", ")
                )
            },
        });
        out.push(Figure {
            family: "bad-input rows: results ≠ the documented answer",
            function: file.to_string(),
            value: st.rows_wrong as f64,
            // The contract is the same answer, bit for bit, on every adapter.
            bound: Some(0.0),
            detail: format!("of {} rows", st.rows),
        });
        out.push(Figure {
            family: "random, bad-input and fuzz-corpus inputs: non-finite results",
            function: file.to_string(),
            value: st.non_finite as f64,
            bound: Some(0.0),
            detail: format!("of {} results", st.inputs),
        });
    }
}

/// `sampled_worst` for every path, its calls recorded, run together, then replayed.
fn linear_depth(exec: &dyn Executor, out: &mut Vec<Figure>) {
    for path in &PATHS {
        let recorded = RefCell::new(Vec::new());
        let record = |args: &[Arg<'_>], n: u64| -> Result<Vec<f32>, HarnessError> {
            recorded
                .borrow_mut()
                .push(call(prepass::wgsl::LINEAR_DEPTH, path.function, args, n));
            Ok(vec![0.0; n as usize])
        };
        sampled_worst(path, &record).unwrap();
        let results = RefCell::new(exec.run_all(recorded.into_inner()).into_iter());
        let replay = |_: &[Arg<'_>], _: u64| -> Result<Vec<f32>, HarnessError> {
            Ok(results
                .borrow_mut()
                .next()
                .expect("one result per call")
                .as_f32()
                .to_vec())
        };
        let (worst, at) = sampled_worst(path, &replay).unwrap();
        let (_, conforming, _) = prepass::linear_depth::bounds::of(path.function).unwrap();
        out.push(Figure {
            family: "linear depth, max ULP",
            function: path.function.to_string(),
            value: worst,
            bound: Some(conforming),
            detail: at,
        });
    }
}

fn normals(exec: &dyn Executor, out: &mut Vec<Figure>) {
    let mut inputs = fibonacci_directions(1 << 14);
    inputs.extend(adversarial_directions());
    let n = inputs.len() as u64;
    let mut calls = Vec::new();
    let mut twin_codes = Vec::new();
    for c in &CODECS {
        calls.push(call(c.source, c.encode, &[Arg::column(&inputs)], n));
        // The decoder on the twin's codes, so the two halves are measured independently.
        let codes: Vec<u32> = inputs
            .iter()
            .map(|&v| (c.twin_encode)(glam::Vec3::from(v)))
            .collect();
        calls.push(call(c.source, c.decode, &[Arg::column(&codes)], n));
        twin_codes.push(codes);
    }
    let results = exec.run_all(calls);
    for (k, c) in CODECS.iter().enumerate() {
        let (enc, dec) = (&results[2 * k], &results[2 * k + 1]);
        let codes_differ = enc
            .as_u32()
            .iter()
            .zip(&twin_codes[k])
            .filter(|(a, b)| a != b)
            .count();
        // The codecs that store z ≥ 0 only ("xyz8" stores the whole sphere).
        let hemisphere = c.hemisphere;
        let (mut worst, mut differ, mut not_unit, mut ulps) = (0.0f64, 0usize, 0usize, 0u64);
        // The twin's codes decoded exactly (f64): the decoder's own turn adds to this.
        let mut exact_worst = 0.0f64;
        for ((input, &code), got) in inputs.iter().zip(&twin_codes[k]).zip(dec.as_vec3()) {
            let twin = (c.twin_decode)(code).to_array();
            if twin.map(f32::to_bits) != got.map(f32::to_bits) {
                differ += 1;
                for (a, b) in twin.iter().zip(got) {
                    ulps = ulps.max(ulp_distance(*a, *b).unwrap_or(u64::MAX));
                }
            }
            let g = widen3(*got);
            let len = g.iter().map(|x| x * x).sum::<f64>().sqrt();
            if !(len.is_finite() && (len - 1.0).abs() <= UNIT_TOLERANCE_CONFORMING) {
                not_unit += 1;
            }
            if !hemisphere || input[2] >= 0.0 {
                worst = worst.max(angle_degrees(widen3(*input), g));
                exact_worst =
                    exact_worst.max(angle_degrees(widen3(*input), (c.reference_decode)(code)));
            }
        }
        out.push(Figure {
            family: "normals, round-trip max° (twin's codes)",
            function: c.name.to_string(),
            value: worst,
            bound: round_trip_bound(c, exact_worst),
            detail: format!(
                "{codes_differ} codes ≠ twin, {differ} decodes ≠ twin (max {ulps} ULP), of {n}"
            ),
        });
        out.push(Figure {
            family: "normals, decodes off unit length (conforming budget)",
            function: c.name.to_string(),
            value: not_unit as f64,
            bound: Some(0.0),
            detail: format!("|len − 1| ≤ {UNIT_TOLERANCE_CONFORMING:e}"),
        });
    }
}

/// The round trip's bound on every conforming adapter, for a decoder that normalises an exact
/// integer vector (every codec but xy fp16): by the triangle inequality, the exact (f64) angle
/// from each input to its twin code's direction, at most `exact_worst`, plus the decoder's turn
/// from that direction, at most `sweep::conforming::decode_angle_conforming_deg`; rounded up to
/// the table's 4 decimals (a looser bound). xy fp16 rebuilds z with a square root, whose turn
/// is bounded apart: `sweep::conforming::decode_angle_conforming_xy_fp16_deg`.
fn round_trip_bound(c: &prepass::sweep::normal::Codec, exact_worst: f64) -> Option<f64> {
    use prepass::sweep::conforming::{
        decode_angle_conforming_deg, decode_angle_conforming_xy_fp16_deg,
    };
    let turn = if c.name == "xy fp16" {
        decode_angle_conforming_xy_fp16_deg()
    } else {
        decode_angle_conforming_deg()
    };
    Some(((exact_worst + turn) * 1e4).ceil() / 1e4)
}

fn depth24_and_roughness(exec: &dyn Executor, out: &mut Vec<Figure>) {
    use prepass::depth24::DEPTH24_MAX;
    let mut codes: Vec<u32> = (0..DEPTH24_MAX - 255).step_by(8).collect();
    codes.extend(DEPTH24_MAX - 255..=DEPTH24_MAX);
    let max_power = 8192.0f32;
    let powers: Vec<f32> = (0..4096)
        .map(|i| (f64::from(max_power).ln() * f64::from(i) / 4095.0).exp() as f32)
        .collect();
    let rcodes: Vec<u32> = (0..256).collect();
    let calls = vec![
        call(
            prepass::wgsl::DEPTH24,
            "hyperbolic_depth_from_depth24",
            &[Arg::column(&codes)],
            codes.len() as u64,
        ),
        call(
            prepass::wgsl::ROUGHNESS,
            "encode_log_roughness",
            &[Arg::column(&powers), Arg::splat_f32(max_power)],
            powers.len() as u64,
        ),
        call(
            prepass::wgsl::ROUGHNESS,
            "decode_log_roughness",
            &[Arg::column(&rcodes), Arg::splat_f32(max_power)],
            256,
        ),
    ];
    let r = exec.run_all(calls);
    let worst = codes
        .iter()
        .zip(r[0].as_f32())
        .map(|(&d, &g)| ulp_error(g, prepass::depth24::exact::hyperbolic_depth(d)))
        .fold(0.0, f64::max);
    out.push(Figure {
        family: "24-bit depth, max ULP",
        function: "hyperbolic_depth_from_depth24".into(),
        value: worst,
        bound: Some(0.5),
        detail: format!("{} codes", codes.len()),
    });
    let enc_differ = powers
        .iter()
        .zip(r[1].as_u32())
        .filter(|&(&p, &c)| prepass::roughness::encode_log_roughness(p, max_power) != c)
        .count();
    let dec_differ = rcodes
        .iter()
        .zip(r[2].as_f32())
        .filter(|&(&c, &g)| {
            prepass::roughness::decode_log_roughness(c, max_power).to_bits() != g.to_bits()
        })
        .count();
    out.push(Figure {
        family: "roughness, results ≠ twin",
        function: "encode_log_roughness / decode_log_roughness".into(),
        value: (enc_differ + dec_differ) as f64,
        bound: None,
        detail: format!("{enc_differ} of 4096 codes, {dec_differ} of 256 powers"),
    });
}

fn print_figures(figs: &[Figure]) {
    for f in figs {
        println!(
            "{TAG}{}|{}|{:e}|{}|{}",
            f.family,
            f.function,
            f.value,
            f.bound.map_or("-".to_string(), |b| format!("{b:e}")),
            f.detail
        );
    }
}

fn parse_figures(stdout: &str) -> Vec<Figure> {
    stdout
        .lines()
        .filter_map(|l| l.find(TAG).map(|i| &l[i + TAG.len()..]))
        .filter(|l| !l.starts_with("adapter "))
        .map(|l| {
            let p: Vec<&str> = l.splitn(5, '|').collect();
            let family = FAMILIES
                .iter()
                .find(|f| **f == p[0])
                .unwrap_or_else(|| panic!("unknown family {}", p[0]));
            Figure {
                family,
                function: p[1].to_string(),
                value: p[2].parse().unwrap(),
                bound: (p[3] != "-").then(|| p[3].parse().unwrap()),
                detail: p[4].to_string(),
            }
        })
        .collect()
}

const FAMILIES: [&str; 8] = [
    "every function, random inputs: results ≠ twin",
    "bad-input rows: results ≠ the documented answer",
    "random, bad-input and fuzz-corpus inputs: non-finite results",
    "linear depth, max ULP",
    "normals, round-trip max° (twin's codes)",
    "normals, decodes off unit length (conforming budget)",
    "24-bit depth, max ULP",
    "roughness, results ≠ twin",
];

/// Run by [`every_implementation_holds_the_conforming_promises`] in a child process whose
/// environment chooses the implementation: prints the adapter and its figures.
#[test]
#[ignore = "a child of every_implementation_holds_the_conforming_promises (it runs this with each driver)"]
fn implementation_child() {
    println!("{TAG}adapter {}", Wgpu.name());
    print_figures(&figures(&Wgpu));
}

/// This binary's child test under `env`: the adapter's name and its figures. FAILS, with the
/// child's output, when the child does.
fn child(env: &[(&str, String)]) -> (String, Vec<Figure>) {
    let exe = std::env::current_exe().unwrap();
    let mut cmd = std::process::Command::new(exe);
    cmd.args([
        "--exact",
        "implementation_child",
        "--include-ignored",
        "--nocapture",
        "--test-threads",
        "1",
    ]);
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "the child with {env:?} failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The test harness's "test … " may stand before a line on the same line.
    let tag = format!("{TAG}adapter ");
    let adapter = stdout
        .lines()
        .find_map(|l| l.find(&tag).map(|i| l[i + tag.len()..].to_string()))
        .expect("the child names its adapter");
    (adapter, parse_figures(&stdout))
}

/// Mesa 25 lavapipe's variables, from `.ci/setup-mesa25 --env` (which `.ci/setup-dawn` ran).
fn mesa25_env() -> Vec<(&'static str, String)> {
    let root = env!("CARGO_MANIFEST_DIR");
    let manifest = format!("{root}/target/mesa25/lvp_icd.json");
    assert!(
        std::path::Path::new(&manifest).exists(),
        "Mesa 25 lavapipe is not unpacked here: run `bash .ci/setup-mesa25` (`.ci/test` does)"
    );
    let lib = format!("{root}/target/mesa25/usr/lib/x86_64-linux-gnu");
    let ld = match std::env::var("LD_LIBRARY_PATH") {
        Ok(old) if !old.is_empty() => format!("{lib}:{old}"),
        _ => lib,
    };
    vec![
        ("VK_DRIVER_FILES", manifest),
        ("LD_LIBRARY_PATH", ld),
        ("WGPU_BACKEND", "vulkan".into()),
    ]
}

#[test]
fn every_implementation_holds_the_conforming_promises() {
    let here = (Wgpu.name(), figures(&Wgpu));
    let dawn = Dawn(RefCell::new(String::new()));
    let dawn_figs = figures(&dawn);
    let mut columns = vec![here, (dawn.name(), dawn_figs)];
    let (a, f) = child(&mesa25_env());
    columns.push((a, f));
    let (a, f) = child(&[("WGPU_BACKEND", "gl".into())]);
    columns.push((a, f));
    // Every figure with a bound holds it, on every implementation.
    let mut broken = Vec::new();
    for (name, figs) in &columns {
        for f in figs {
            if let Some(b) = f.bound
                && (f.value.is_nan() || f.value > b)
            {
                broken.push(format!(
                    "{name}: {} `{}` = {} beyond {b} ({})",
                    f.family, f.function, f.value, f.detail
                ));
            }
        }
    }
    // The table: one row per figure, one column per implementation (named in full above it).
    let mut body = String::new();
    for (k, (name, _)) in columns.iter().enumerate() {
        let _ = writeln!(body, "{}. {name}", k + 1);
    }
    body.push_str("\n| family | function |");
    for (k, (name, _)) in columns.iter().enumerate() {
        let _ = write!(
            body,
            " ({}) {} |",
            k + 1,
            name.split(':').next().unwrap_or(name)
        );
    }
    body.push_str(" bound, every conforming adapter |\n|---|---|");
    body.push_str(&"---|".repeat(columns.len() + 1));
    body.push('\n');
    for (i, f) in columns[0].1.iter().enumerate() {
        let _ = write!(body, "| {} | `{}` |", f.family, f.function);
        for (name, figs) in &columns {
            let g = figs
                .get(i)
                .filter(|g| g.family == f.family && g.function == f.function)
                .unwrap_or_else(|| panic!("{name} lacks {} {}", f.family, f.function));
            let _ = write!(body, " {} |", cell(g));
        }
        let _ = writeln!(
            body,
            " {} |",
            f.bound.map_or("—".to_string(), |b| format!("{b}"))
        );
    }
    let drivers: Vec<&str> = columns.iter().map(|(n, _)| n.as_str()).collect();
    assert!(broken.is_empty(), "promises broken:\n{}", broken.join("\n"));
    common::publish_on(
        "docs/figures.md",
        "implementations",
        &body,
        &drivers.join("; "),
    );
}

/// A figure as a table cell: the value (4 significant digits, or a count), with the detail.
fn cell(f: &Figure) -> String {
    let v = if f.value.fract() == 0.0 && f.value.abs() < 1e15 {
        format!("{}", f.value as u64)
    } else {
        format!("{:.4}", f.value)
    };
    if f.family.starts_with("normals, round")
        || f.family.starts_with("roughness")
        || f.family.ends_with("≠ twin")
        || f.family.contains("non-finite")
        || f.family.starts_with("bad-input")
    {
        format!("{v} ({})", f.detail)
    } else {
        v
    }
}

/// Dawn's node binding crashes or hangs now and then (tests/common/dawn.rs, `run_to_the_end`):
/// with a crash and a hang injected into the runner, every job still comes back once, in order,
/// with the results wgpu gives, and two runner processes were replaced. Fails if a crashed or
/// hung runner lost a job, repeated one, or was not detected (the hang would never end).
#[test]
fn dawn_runner_survives_a_crash_and_a_hang() {
    let codes: Vec<u32> = (0..64).map(|k| k * 262_143).collect();
    let dispatches: Vec<Dispatch> = (0..6)
        .map(|k| {
            let part = &codes[k * 10..k * 10 + 10];
            call(
                prepass::wgsl::DEPTH24,
                "hyperbolic_depth_from_depth24",
                &[Arg::column(part)],
                part.len() as u64,
            )
        })
        .collect();
    let want: Vec<Vec<u32>> = dispatches
        .iter()
        .map(|d| run_dispatch_on_wgpu(d.clone()).into_words())
        .collect();
    let (_, outcomes, restarts) = dawn::run_with_faults(dawn_jobs(dispatches), "crash:2,hang:4");
    assert_eq!(restarts, 2, "a crash and a hang, each replaced once");
    let got: Vec<Vec<u32>> = outcomes
        .into_iter()
        .map(|o| o.output.expect("every job's output").into_words())
        .collect();
    assert_eq!(
        got, want,
        "Dawn's results after the restarts, against wgpu's"
    );
}
