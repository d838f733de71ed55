//! The bad-input contract (`docs/bad_input.md`): every row of `bad_input/` (one file per module,
//! listed in `bad_input/rows.rs`) runs through the WGSL on the adapter and through the Rust twin,
//! and both must return the documented answer.
//! `docs/bad_input.md`'s table is generated from the same rows (`bash .ci/docs`) and must match
//! them exactly.

mod common;

#[path = "bad_input/rows.rs"]
mod rows;

#[path = "common/dawn.rs"]
mod dawn;

use common::gpu;
use prepass::harness::Arg;
use rows::{Func, Row, V, from_words, funcs, rows, same, wgsl_expect, wgsl_helpers, words};

fn f32_text(x: f32) -> String {
    if x.is_nan() {
        let sign = if x.is_sign_negative() { "−" } else { "" };
        let kind = if x.to_bits() & 0x0040_0000 == 0 {
            " (signalling)"
        } else {
            ""
        };
        format!("{sign}NaN{kind}")
    } else if x.is_infinite() {
        (if x > 0.0 { "+Inf" } else { "−Inf" }).to_string()
    } else {
        format!("{x:?}")
    }
}

fn f64_text(x: f64) -> String {
    if x.is_nan() {
        "NaN".to_string()
    } else if x.is_infinite() {
        (if x > 0.0 { "+Inf" } else { "−Inf" }).to_string()
    } else {
        format!("{x:?}")
    }
}

fn text(v: V) -> String {
    let list = |xs: &[f32]| {
        let parts: Vec<String> = xs.iter().map(|&x| f32_text(x)).collect();
        format!("({})", parts.join(", "))
    };
    match v {
        V::F32(x) => f32_text(x),
        V::U32(x) => format!("{x:#x}"),
        V::Vec2(x) => list(&x),
        V::Vec3(x) => list(&x),
        V::Vec4(x) => list(&x),
        V::UVec2(x) => format!("({:#x}, {:#x})", x[0], x[1]),
        V::Vec3x2([p, q]) => format!("{}, {}", list(&p), list(&q)),
        V::F64x2([p, q]) => format!("({}, {})", f64_text(p), f64_text(q)),
        V::F64(x) => f64_text(x),
        V::Text(t) => t.to_string(),
        V::OptU32(None) => "None".to_string(),
        V::OptU32(Some(x)) => format!("Some({x:#x})"),
        V::OptVec3(None) => "None".to_string(),
        V::OptVec3(Some(x)) => format!("Some({})", list(&x)),
        V::I64(x) => format!("{x}"),
        V::Bool(x) => format!("{x}"),
        V::F64x3(x) => {
            let parts: Vec<String> = x.iter().map(|&v| f64_text(v)).collect();
            format!("({})", parts.join(", "))
        }
        V::OptI64(None) | V::OptU64(None) => "None".to_string(),
        V::OptI64(Some(x)) => format!("Some({x:#x})"),
        V::OptU64(Some(x)) => format!("Some({x})"),
        V::Channel(c) => format!("{c:?}"),
        V::WgslIndeterminate(&v) => text(v),
    }
}

fn func(name: &str) -> &'static Func {
    funcs()
        .find(|f| f.key() == name)
        .unwrap_or_else(|| panic!("row names `{name}`, which is in no FUNCS"))
}

fn rows_of(f: &Func) -> Vec<&'static Row> {
    rows().filter(|r| r.func == f.key()).collect()
}

fn describe(r: &Row) -> String {
    let args: Vec<String> = r.args.iter().map(|&a| text(a)).collect();
    format!("{}({}) [{}]", r.func, args.join(", "), r.case)
}

#[test]
fn rust_twins_give_the_documented_answers() {
    let mut wrong = Vec::new();
    for r in rows() {
        let got = (func(r.func).twin)(r.args);
        if !same(got, r.expect) {
            wrong.push(format!(
                "{}: Rust gives {}, documented {}",
                describe(r),
                text(got),
                text(r.expect)
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Every WGSL row of every function, one dispatch per function (one column per parameter),
/// through `execute` (the wgpu adapter, or Dawn), checked against the documented answer bit for
/// bit and for finiteness: WGSL leaves a run-time ±∞ or NaN indeterminate, so no row may return
/// one. A row whose answer WGSL leaves indeterminate ([`V::WgslIndeterminate`]) runs unchecked.
/// Returns the failures and the number of rows run.
fn check_wgsl_rows(
    execute: impl FnOnce(Vec<Job>) -> Vec<prepass::harness::Output>,
) -> (Vec<String>, usize) {
    let mut wrong = Vec::new();
    let mut ran = 0;
    let mut jobs = Vec::new();
    let mut job_rows = Vec::new();
    for f in funcs() {
        let Some((source, name)) = f.wgsl else {
            continue;
        };
        let rows = rows_of(f);
        let kernel = gpu()
            .kernel(source, name)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let arity = kernel.signature().params.len();
        let mut columns = vec![Vec::new(); arity];
        for r in &rows {
            assert_eq!(r.args.len(), arity, "{}: wrong argument count", describe(r));
            for (col, &a) in columns.iter_mut().zip(r.args) {
                words(a, col);
            }
        }
        jobs.push(Job {
            source,
            name,
            columns,
            n: rows.len() as u64,
        });
        job_rows.push(rows);
    }
    let names: Vec<&str> = jobs.iter().map(|j| j.name).collect();
    let outputs = execute(jobs);
    for ((name, rows), out) in names.iter().zip(job_rows).zip(outputs) {
        let width = out.ty.words();
        for (r, w) in rows.iter().zip(out.words().chunks(width)) {
            ran += 1;
            let Some(expect) = wgsl_expect(r.expect) else {
                continue;
            };
            let got = from_words(expect, w);
            if !same(got, expect) {
                wrong.push(format!(
                    "{}: WGSL `{name}` gives {}, documented {}",
                    describe(r),
                    text(got),
                    text(expect)
                ));
            }
            let finite = w.iter().all(|&b| b & 0x7f80_0000 != 0x7f80_0000)
                || matches!(got, V::U32(_) | V::UVec2(_));
            if !finite {
                wrong.push(format!(
                    "{}: WGSL `{name}` returns {}, not finite (WGSL leaves it indeterminate)",
                    describe(r),
                    text(got)
                ));
            }
        }
    }
    (wrong, ran)
}

/// One function's rows, one column of words per parameter.
struct Job {
    source: &'static str,
    name: &'static str,
    columns: Vec<Vec<u32>>,
    n: u64,
}

impl Job {
    fn kernel(&self) -> prepass::harness::Kernel<'static> {
        gpu()
            .kernel(self.source, self.name)
            .unwrap_or_else(|e| panic!("{}: {e}", self.name))
    }

    fn args(&self) -> Vec<Arg<'_>> {
        self.columns.iter().map(|c| Arg::column(c)).collect()
    }
}

#[test]
fn wgsl_gives_the_documented_answers_on_the_adapter() {
    let (wrong, ran) = check_wgsl_rows(|jobs| {
        jobs.iter()
            .map(|j| {
                j.kernel()
                    .run(&j.args(), j.n)
                    .unwrap_or_else(|e| panic!("{}: {e}", j.name))
            })
            .collect()
    });
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(ran > 0, "no WGSL row ran");
}

/// The same rows compiled by Tint and run through Dawn (Chrome's WebGPU): the bad-input
/// contract must not depend on the WGSL compiler.
#[test]
fn wgsl_gives_the_documented_answers_on_dawn() {
    let mut adapter = String::new();
    let (wrong, ran) = check_wgsl_rows(|jobs| {
        let dawn_jobs = jobs
            .iter()
            .map(|j| dawn::Job {
                name: j.name.to_string(),
                source: String::new(),
                dispatch: Some(
                    j.kernel()
                        .dispatch(&j.args(), j.n)
                        .unwrap_or_else(|e| panic!("{}: {e}", j.name)),
                ),
                pipelines: Vec::new(),
            })
            .collect();
        let (a, outcomes) = dawn::run(dawn_jobs);
        adapter = a;
        outcomes
            .into_iter()
            .map(|o| {
                assert!(o.error.is_none(), "{}: Dawn: {:?}", o.name, o.error);
                o.output.unwrap()
            })
            .collect()
    });
    eprintln!("Dawn ran {ran} rows on {adapter}");
    assert!(
        wrong.is_empty(),
        "on Dawn ({adapter}):\n{}",
        wrong.join("\n")
    );
    assert!(ran > 0, "no WGSL row ran");
}

/// Every WGSL row, and the fuzz corpora's inputs, under the conforming emulation's domain checks
/// (`prepass::conforming`, policy `Identity`: values as on the adapter, plus the flag word an
/// evaluation raises when an operation leaves the spec's domain). Reading an input's bits is in
/// the domain; computing with a NaN or ±∞ is not, and neither is returning one. Fails on:
/// - an arithmetic helper's flag (bit 1: a run-time ±∞ or NaN produced, or a divisor or
///   argument outside its range);
/// - a returned ±∞ or NaN, read from the result's bits, by whatever path it leaves (a `select`,
///   `min`, a returned input);
/// - an operation the arithmetic helpers do not see applied to a ±∞ or NaN (bit 2: `min`, `max`,
///   `clamp`, `abs`, `floor`, comparisons, the identity's builtins, an infinite or NaN
///   `unpack2x16float` half, `u32` or `i32` of one): every function reads such inputs from their
///   bits first;
/// - a row WGSL leaves indeterminate ([`V::WgslIndeterminate`]) whose evaluation stays in the
///   domain (then it is no indeterminate row).
#[test]
fn wgsl_rows_stay_in_the_spec_domain_under_emulation() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    // The f32 lanes of a result that are ±∞ or NaN, by their bits.
    let non_finite = |out: &prepass::harness::Output, w: &[u32]| {
        out.ty.scalar == prepass::harness::Scalar::F32
            && w.iter().any(|&b| b & 0x7f80_0000 == 0x7f80_0000)
    };
    let mut flagged = Vec::new();
    let (mut ran, mut corpus_inputs) = (0, 0);
    let total = funcs().count();
    for (k, f) in funcs().enumerate() {
        common::progress(
            "wgsl_rows_stay_in_the_spec_domain_under_emulation: functions",
            k,
            total,
        );
        let Some((source, name)) = f.wgsl else {
            continue;
        };
        let rows = rows_of(f);
        let kernel = EmulatedKernel::new(gpu(), source, name, &Emulation::new(Policy::Identity))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let arity = kernel.signature().params.len();
        let mut columns = vec![Vec::new(); arity];
        for r in &rows {
            for (col, &a) in columns.iter_mut().zip(r.args) {
                words(a, col);
            }
        }
        let args: Vec<Arg> = columns.iter().map(|c| Arg::column(c)).collect();
        let (out, flags) = kernel.run_flags(&args, rows.len() as u64).unwrap();
        let width = out.ty.words();
        for ((r, flag), w) in rows.iter().zip(flags).zip(out.words().chunks(width)) {
            ran += 1;
            if wgsl_expect(r.expect).is_none() {
                if flag == 0 {
                    flagged.push(format!(
                        "{}: documented indeterminate, yet its evaluation stays in the domain",
                        describe(r)
                    ));
                }
                continue;
            }
            if flag & 1 != 0 {
                flagged.push(format!("{}: an operation leaves the domain", describe(r)));
            }
            if flag & 2 != 0 {
                flagged.push(format!(
                    "{}: an operation on a ±Inf or NaN by a path the arithmetic helpers do not \
                     check (bit 2: min, max, clamp, abs, floor, a comparison or a builtin; read \
                     the input's bits first)",
                    describe(r)
                ));
            }
            if non_finite(&out, w) {
                flagged.push(format!("{}: returns non-finite bits {w:08x?}", describe(r)));
            }
        }
        // A builtin's wrapper is no shipped function: the corpora are the shipped functions'.
        if !prepass::wgsl::FILES
            .iter()
            .any(|file| source.starts_with(file.source))
        {
            continue;
        }
        // The fuzz corpora's inputs as argument bits (`common::corpus_args`).
        let words: Vec<usize> = kernel
            .signature()
            .params
            .iter()
            .map(|p| p.ty.words())
            .collect();
        let mut corpus = common::corpus_args(&words);
        // A vouched encoder's contract (`oct::is_vouched`, `hemioct::is_vouched`) excludes most
        // of the corpora's inputs; what it leaves WGSL indeterminate is no finding: only inputs
        // inside it run.
        if name.ends_with("_vouched") {
            let inside = if name.starts_with("encode_normal_hemioct") {
                prepass::normal::hemioct::is_vouched
            } else {
                prepass::normal::oct::is_vouched
            };
            corpus = vouched_lanes(&corpus, inside);
        }
        let n = corpus[0].len() / words[0];
        let args: Vec<Arg> = corpus.iter().map(|c| Arg::column(c)).collect();
        let (out, flags) = kernel.run_flags(&args, n as u64).unwrap();
        let width = out.ty.words();
        let bad: Vec<bool> = flags
            .iter()
            .zip(out.words().chunks(width))
            .map(|(&f, w)| f & 3 != 0 || non_finite(&out, w))
            .collect();
        let count = bad.iter().filter(|&&b| b).count();
        corpus_inputs += n;
        if let Some(first) = bad.iter().position(|&b| b) {
            let lanes: Vec<String> = corpus
                .iter()
                .zip(&words)
                .map(|(c, &w)| format!("{:08x?}", &c[first * w..(first + 1) * w]))
                .collect();
            flagged.push(format!(
                "{name}: {count} of {n} fuzz-corpus inputs leave the domain, operate on a ±Inf or \
                 NaN or return a non-finite value (first: bits {})",
                lanes.join(", ")
            ));
        }
    }
    eprintln!(
        "{} failures over {ran} rows and {corpus_inputs} corpus inputs",
        flagged.len()
    );
    assert!(
        flagged.is_empty(),
        "rows whose evaluation leaves the spec's domain:\n{}",
        flagged.join("\n")
    );
}

/// The lanes of a one-`vec3` argument column inside a vouched encoder's contract `inside`
/// (`prepass::normal::oct::is_vouched`, `prepass::normal::hemioct::is_vouched`).
fn vouched_lanes(corpus: &[Vec<u32>], inside: fn(glam::Vec3) -> bool) -> Vec<Vec<u32>> {
    assert_eq!(corpus.len(), 1, "the vouched encoders take one vec3");
    let kept: Vec<u32> = corpus[0]
        .chunks(3)
        .filter(|w| {
            inside(glam::Vec3::from_array(
                [w[0], w[1], w[2]].map(f32::from_bits),
            ))
        })
        .flatten()
        .copied()
        .collect();
    assert!(
        !kept.is_empty(),
        "no fuzz-corpus input inside the vouched contract"
    );
    vec![kept]
}

/// No WGSL row documents a value the spec leaves indeterminate: a run-time ±∞ or NaN (WGSL's
/// finite-math rule; a conforming adapter may return anything there). Such a row says so with
/// [`V::WgslIndeterminate`], and only its Rust side is checked.
#[test]
fn wgsl_rows_document_only_defined_values() {
    let mut wrong = Vec::new();
    for r in rows() {
        if func(r.func).wgsl.is_none() {
            continue;
        }
        let Some(expect) = wgsl_expect(r.expect) else {
            continue;
        };
        let mut w = Vec::new();
        words(expect, &mut w);
        let float = !matches!(expect, V::U32(_) | V::UVec2(_));
        if float && w.iter().any(|&b| b & 0x7f80_0000 == 0x7f80_0000) {
            wrong.push(format!(
                "{}: documents {} for WGSL, which the spec leaves indeterminate",
                describe(r),
                text(expect)
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_function_has_rows_and_every_row_a_function() {
    for f in funcs() {
        assert!(
            !rows_of(f).is_empty(),
            "`{}` has no bad-input rows",
            f.key()
        );
    }
    for r in rows() {
        func(r.func);
    }
}

/// A new WGSL function cannot escape the contract: every function in every shipped file must
/// be the WGSL side of a row's function (or a listed private helper).
#[test]
fn every_shipped_wgsl_function_is_in_the_table() {
    let mut missing = Vec::new();
    for file in prepass::wgsl::FILES {
        let checked = prepass::wgsl::parse_and_validate(file.source)
            .unwrap_or_else(|e| panic!("{}: {e}", file.name));
        for (_, f) in checked.module.functions.iter() {
            let name = f.name.as_deref().unwrap_or("<unnamed>");
            // A row may call the function directly, or through a `bad_input_<name>` wrapper
            // appended to the file's text (for arguments the harness cannot feed, e.g. matrices).
            let wrapper = format!("bad_input_{name}");
            let covered = funcs().any(|g| {
                g.wgsl.is_some_and(|(src, n)| {
                    (src == file.source && n == name)
                        || (src.starts_with(file.source) && n == wrapper)
                })
            });
            if !covered && !wgsl_helpers().any(|(h, _)| *h == name) {
                missing.push(format!("{}: `{name}`", file.name));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "WGSL functions without bad-input rows (add them to their module's file in tests/bad_input/):\n{}",
        missing.join("\n")
    );
}

fn table_line(r: &Row) -> String {
    let f = func(r.func);
    let args: Vec<String> = r.args.iter().map(|&a| text(a)).collect();
    let checked = match (f.wgsl, r.expect) {
        (Some(_), V::WgslIndeterminate(_)) => "Rust (WGSL: indeterminate)",
        (Some(_), _) => "WGSL + Rust",
        (None, _) => "Rust (no WGSL)",
    };
    // The key is the WGSL name; a Rust-only function's key is its Rust path already.
    let twin = if f.wgsl.is_some() {
        format!("`{}`", f.rust)
    } else {
        "—".to_string()
    };
    let returns = match r.expect {
        V::WgslIndeterminate(&v) => format!("Rust: `{}`; WGSL: indeterminate", text(v)),
        v => format!("`{}`", text(v)),
    };
    format!(
        "| `{}` | {} | {} | `{}` | {returns} | {checked} | {} |",
        r.func,
        twin,
        r.case,
        args.join(", "),
        r.why
    )
}

#[test]
fn docs_table_is_exactly_the_rows() {
    let want: Vec<String> = rows().map(table_line).collect();
    let header = "| function | Rust twin | bad input | arguments | WGSL and Rust return | checked | why |\n\
                  |---|---|---|---|---|---|---|";
    common::publish(
        "docs/bad_input.md",
        "bad-input",
        &format!("{header}\n{}\n", want.join("\n")),
    );
}
