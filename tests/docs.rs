//! The published figures: the README's generated tables and `docs/figures.md`, computed here on
//! the adapter and, under the conforming-adapter emulation, on the worst conforming adapter.
//!
//! `bash .ci/docs` writes them (`PREPASS_WRITE_DOCS=1`); otherwise every test here recomputes its
//! block and FAILS when the committed text differs, naming that command. Nothing in those blocks
//! is typed by hand. The figures are lavapipe's (CI's adapter): on another adapter the
//! last digits may differ, and the failure says so.

mod common;

use common::gpu;
use prepass::conforming::{EmulatedKernel, Emulation, Policy};
use prepass::harness::Arg;
use prepass::scene::{NormalChoice, Scene};
use prepass::sweep::conforming::emulated_codec_sweep;
use prepass::sweep::normal::{CODECS, adversarial_directions, fibonacci_directions, round_trip};
use std::fmt::Write as _;
use std::sync::Mutex;

static FILES: Mutex<()> = Mutex::new(());

/// Replace (with `PREPASS_WRITE_DOCS=1`) or check the text between
/// `<!-- generated:NAME:begin -->` and `<!-- generated:NAME:end -->` in `path`.
fn publish(path: &str, name: &str, body: &str) {
    let _g = FILES.lock().unwrap_or_else(|e| e.into_inner());
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&full).unwrap_or_default();
    let (b, e) = (
        format!("<!-- generated:{name}:begin -->"),
        format!("<!-- generated:{name}:end -->"),
    );
    let block = format!("{b}\n{body}{e}");
    let found = text.find(&b).zip(text.find(&e));
    if std::env::var_os("PREPASS_WRITE_DOCS").is_some() {
        let new = match found {
            Some((i, j)) => format!("{}{block}{}", &text[..i], &text[j + e.len()..]),
            None => format!("{text}\n{block}\n"),
        };
        std::fs::write(&full, new).unwrap();
        return;
    }
    let current = found.map(|(i, j)| &text[i..j + e.len()]);
    assert_eq!(
        current,
        Some(block.as_str()),
        "{path}, block `{name}`, differs from what this test measures on {}: run `bash .ci/docs` \
         to regenerate (on an adapter other than lavapipe the last digits may differ)",
        gpu().describe()
    );
}

fn adapter_line() -> String {
    let i = gpu().adapter_info();
    format!("Measured on {} ({}).\n", i.name, i.driver_info)
}

#[test]
fn normal_encodings() {
    // One sample for the adapter and the emulation, so the columns compare.
    let mut inputs = fibonacci_directions(1 << 18);
    inputs.extend(adversarial_directions());
    let mut readme = String::from(
        "| encoding | bits | target format | max° | mean° | max° on the worst conforming adapter | SPIR-V encode / decode |\n|---|---|---|---|---|---|---|\n",
    );
    let mut full = adapter_line();
    full.push_str(&
        format!("\n| encoding | bits | max° | mean° | emulated max° (upper / lower / seeded) | emulated mean° | codes ≠ Rust twin (emulated, of {}) | max \\|len − 1\\| of emulated decodes |\n|---|---|---|---|---|---|---|---|\n", inputs.len()),
    );
    for c in &CODECS {
        let hemisphere = c.name.starts_with("hemioct") || c.name.starts_with("xy");
        let pick = |rt: &prepass::sweep::normal::RoundTrip| {
            if hemisphere {
                rt.error_upper.clone()
            } else {
                rt.error.clone()
            }
        };
        let plain = pick(&round_trip(gpu(), c, &inputs).unwrap());
        // 65,536 codes spread over the code space (every code of a 16-bit one: 65,521 is odd).
        let codes: Vec<u32> = (0..1u64 << 16)
            .map(|i| ((i * 65_521) % (1u64 << c.bits)) as u32)
            .collect();
        let (mut maxes, mut mean, mut changed, mut len) = (Vec::new(), 0.0f64, 0u64, 0.0f64);
        for policy in [Policy::Upper, Policy::Lower, Policy::Seeded(1)] {
            let e =
                emulated_codec_sweep(gpu(), c, &Emulation::new(policy), &inputs, &codes).unwrap();
            let s = pick(&e.round_trip);
            maxes.push(s.max);
            mean = mean.max(s.mean());
            changed = changed.max(e.round_trip.twin_encode.count);
            len = len.max(e.round_trip_length.0).max(e.decoder.max_len_error);
        }
        let worst = maxes.iter().copied().fold(0.0, f64::max);
        let enc = prepass::wgsl::spirv_instruction_count(c.source, c.encode)
            .unwrap()
            .total;
        let dec = prepass::wgsl::spirv_instruction_count(c.source, c.decode)
            .unwrap()
            .total;
        let encoding = prepass::scene::NormalEncoding::ALL
            .into_iter()
            .find(|e| {
                format!("{e:?}").to_lowercase() == c.name.trim_end_matches(" fast").replace(' ', "")
            })
            .unwrap_or_else(|| panic!("no NormalEncoding for {}", c.name));
        let scene = Scene {
            normal: NormalChoice {
                encoding: Some(encoding),
                fast_encoder: c.name.ends_with("fast"),
            },
            ..Scene::default()
        };
        let format = scene
            .gbuffer()
            .unwrap()
            .targets
            .iter()
            .find(|t| t.name == "normal")
            .map(|t| format!("{:?}", t.format.to_wgpu()))
            .unwrap_or_default();
        let _ = writeln!(
            readme,
            "| {} | {} | {format} | {:.4} | {:.4} | {worst:.4} | {enc} / {dec} |",
            c.name,
            c.bits,
            plain.max,
            plain.mean()
        );
        let _ = writeln!(
            full,
            "| {} | {} | {:.6} | {:.6} | {:.6} / {:.6} / {:.6} | {mean:.6} | {changed} | {len:.3e} |",
            c.name,
            c.bits,
            plain.max,
            plain.mean(),
            maxes[0],
            maxes[1],
            maxes[2]
        );
    }
    publish("README.md", "normal-encodings", &readme);
    publish("docs/figures.md", "normal-encodings", &full);
}

#[test]
fn linear_depth() {
    use prepass::linear_depth::bounds;
    use prepass::sweep::linear_depth::{PATHS, sampled_worst};
    let mut table = String::from(
        "| function | max ULP (this adapter) | max ULP (worst emulated) | bound, correctly rounded | bound, every conforming adapter |\n|---|---|---|---|---|\n",
    );
    for path in &PATHS {
        let (cr, conf, _) = bounds::of(path.function).unwrap();
        let k = gpu()
            .kernel(prepass::wgsl::LINEAR_DEPTH, path.function)
            .unwrap();
        let plain = sampled_worst(path, &|a: &[Arg<'_>], n| Ok(k.run(a, n)?.as_f32().to_vec()))
            .unwrap()
            .0;
        let mut worst = 0.0f64;
        for policy in Policy::WORST {
            let k = EmulatedKernel::new(
                gpu(),
                prepass::wgsl::LINEAR_DEPTH,
                path.function,
                &Emulation::new(policy),
            )
            .unwrap();
            let run = |a: &[Arg<'_>], n: u64| Ok(k.run(a, n)?.0.as_f32().to_vec());
            worst = worst.max(sampled_worst(path, &run).unwrap().0);
        }
        let _ = writeln!(
            table,
            "| `{}` | {plain:.2} | {worst:.2} | {cr:.2} | {conf:.2} |",
            path.function
        );
    }
    publish("README.md", "linear-depth", &table);
    publish(
        "docs/figures.md",
        "linear-depth",
        &format!("{}\n{table}", adapter_line()),
    );
}

#[test]
fn depth24() {
    use prepass::conforming::emulate;
    use prepass::sweep::depth24::{RECOVERY_CASES, hyperbolic_all, recover_all};
    let mut s = adapter_line();
    s.push_str("\n| channels | `depth24_from_rgb8`: wrong codes of 2^24 | the unrounded baseline: wrong codes |\n|---|---|---|\n");
    let baselines = include_str!("baselines/depth24.wgsl");
    let both = format!("{}\n{baselines}", prepass::wgsl::DEPTH24);
    for (error, flip) in RECOVERY_CASES {
        let ours = recover_all(
            gpu(),
            prepass::wgsl::DEPTH24,
            "depth24_from_rgb8",
            error,
            flip,
        )
        .unwrap();
        let base = recover_all(
            gpu(),
            &both,
            "baseline_depth24_from_rgb8_unrounded",
            error,
            flip,
        )
        .unwrap();
        let _ = writeln!(
            s,
            "| {error}{} | {} | {} |",
            if flip { " (signs flipped)" } else { "" },
            ours.mismatches.count,
            base.mismatches.count
        );
    }
    s.push_str("\n| hyperbolic depth `d / (2^24 − 1)` | adapter | max ULP | codes not returned by the exact inverse |\n|---|---|---|---|\n");
    for (name, src, f) in [
        (
            "`hyperbolic_depth_from_depth24`",
            prepass::wgsl::DEPTH24,
            "hyperbolic_depth_from_depth24",
        ),
        (
            "baseline `f32(d) / 16777215.0`",
            baselines,
            "baseline_hyperbolic_divide",
        ),
    ] {
        let h = hyperbolic_all(gpu(), src, f).unwrap();
        let _ = writeln!(
            s,
            "| {name} | this adapter | {:.3} | {} |",
            h.ulps.max, h.exact_roundtrip_failures
        );
        let (mut max, mut fails) = (0.0f64, 0u64);
        for policy in Policy::WORST {
            let e = emulate(src, &Emulation::new(policy)).unwrap();
            let h = hyperbolic_all(gpu(), &e.source, e.function_name(f).unwrap()).unwrap();
            max = max.max(h.ulps.max);
            fails = fails.max(h.exact_roundtrip_failures);
        }
        let _ = writeln!(s, "| {name} | worst emulated | {max:.3} | {fails} |");
    }
    publish("docs/figures.md", "depth24", &s);
}
