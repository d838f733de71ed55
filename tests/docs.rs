//! The published figures: the README's generated tables and `docs/figures.md` (the linear-depth
//! table is published by `tests/linear_depth.rs`, which measures it), computed here on
//! the adapter and, under the conforming-adapter emulation, on the worst conforming adapter.
//!
//! `bash .ci/docs` writes them (`PREPASS_WRITE_DOCS=1`); otherwise every test here recomputes its
//! block and FAILS when the committed text differs, naming that command. Nothing in those blocks
//! is typed by hand. The figures are lavapipe's (CI's adapter): on another adapter the
//! last digits may differ, and the failure says so.

mod common;

use common::{adapter_line, gpu, publish_measured};
use prepass::conforming::{Emulation, Policy};
use std::fmt::Write as _;

#[test]
fn normal_encodings() {
    use prepass::sweep::conforming::normal_figures;
    use prepass::sweep::normal::{adversarial_directions, fibonacci_directions};
    // One sample for the adapter and the emulation, so the columns compare.
    let mut inputs = fibonacci_directions(1 << 18);
    inputs.extend(adversarial_directions());
    let rows = normal_figures(
        gpu(),
        &inputs,
        &[Policy::Upper, Policy::Lower, Policy::Seeded(1)],
    )
    .unwrap();
    let mut readme = String::from(
        "| encoding | bits | target format | max° | mean° | max° on the worst conforming adapter | SPIR-V encode / decode |\n|---|---|---|---|---|---|---|\n",
    );
    let mut full = adapter_line();
    let _ = writeln!(
        full,
        "\n| encoding | bits | max° | mean° | emulated max° (upper / lower / seeded) | emulated mean° | codes ≠ Rust twin (emulated, of {}) | max \\|len − 1\\| of emulated decodes |\n|---|---|---|---|---|---|---|---|",
        inputs.len()
    );
    for r in &rows {
        let worst = r.emulated_max.iter().copied().fold(0.0, f64::max);
        let _ = writeln!(
            readme,
            "| {} | {} | {} | {:.4} | {:.4} | {worst:.4} | {} / {} |",
            r.name,
            r.bits,
            r.target,
            r.adapter.max,
            r.adapter.mean(),
            r.spirv.0,
            r.spirv.1
        );
        let _ = writeln!(
            full,
            "| {} | {} | {:.6} | {:.6} | {:.6} / {:.6} / {:.6} | {:.6} | {} | {:.3e} |",
            r.name,
            r.bits,
            r.adapter.max,
            r.adapter.mean(),
            r.emulated_max[0],
            r.emulated_max[1],
            r.emulated_max[2],
            r.emulated_mean,
            r.twin_changed,
            r.max_len_error
        );
    }
    // Measured blocks: compared as text on the adapter they were published from; elsewhere the
    // differences are printed and the encodings' bounds are what must hold — asserted on every
    // adapter by tests/normal_*.rs (the adapter) and tests/conforming.rs (the emulation).
    for r in &rows {
        assert_eq!(r.adapter.nan_count, 0, "{}: NaN round trips", r.name);
    }
    publish_measured("README.md", "normal-encodings", &readme);
    publish_measured("docs/figures.md", "normal-encodings", &full);
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
        // The promise (README): every code recovered, on the adapter, whatever its driver.
        assert_eq!(
            ours.mismatches.count, 0,
            "depth24_from_rgb8 with channels off by {error} (flip {flip}): codes not recovered"
        );
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
        if f == "hyperbolic_depth_from_depth24" {
            // The promise: correctly rounded on every conforming adapter (≤ 0.5 ULP, every
            // code returned by the exact inverse).
            assert!(
                h.ulps.max <= 0.5 && max <= 0.5 && h.exact_roundtrip_failures == 0 && fails == 0,
                "{name}: {} / {max} ULP, {} / {fails} codes not returned (correctly rounded: ≤ 0.5 ULP, 0)",
                h.ulps.max,
                h.exact_roundtrip_failures
            );
        }
    }
    publish_measured("docs/figures.md", "depth24", &s);
}

/// The README's size of the example to copy (`examples/deferred_minimal`): lines of Rust and of
/// WGSL, counted from the files (`bash .ci/test` runs the example itself and checks its image).
#[test]
fn deferred_minimal_example_size() {
    let lines = |p: &str| {
        std::fs::read_to_string(format!("{}/{p}", env!("CARGO_MANIFEST_DIR")))
            .unwrap_or_else(|e| panic!("{p}: {e}"))
            .lines()
            .count()
    };
    let (rust, wgsl) = (
        lines("examples/deferred_minimal/main.rs"),
        lines("examples/deferred_minimal/deferred.wgsl"),
    );
    common::publish(
        "README.md",
        "deferred-minimal",
        &format!(
            "`examples/deferred_minimal`: {rust} lines of Rust (`main.rs`) and {wgsl} of WGSL \
             (`deferred.wgsl`), beside the {} lines prepass composes for its scene.\n",
            deferred_minimal_scene_lines()
        ),
    );
}

/// Lines of `Scene::wgsl` for the example's scene (reversed-Z infinite D32F, oct24, view
/// positions), as the example builds it.
fn deferred_minimal_scene_lines() -> usize {
    use prepass::projection::DepthConvention;
    use prepass::scene::*;
    let scene = Scene {
        depth: DepthChoice {
            storage: DepthStorage::Float32,
            convention: DepthConvention::Reversed,
            infinite_far: true,
        },
        normal: NormalChoice {
            encoding: Some(NormalEncoding::Oct24),
            fast_encoder: false,
        },
        position: PositionChoice::View,
        ..Scene::default()
    };
    scene.wgsl().unwrap().lines().count()
}
