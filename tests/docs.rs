//! The published figures: the README's generated tables and `docs/figures.md` (the linear-depth
//! table is published by `tests/linear_depth.rs` and the 24-bit one by `tests/depth24.rs`,
//! which measure them for their assertions), computed here on
//! the adapter and, under the conforming-adapter emulation, on the worst conforming adapter.
//!
//! `bash .ci/docs` writes them (`PREPASS_WRITE_DOCS=1`); otherwise every test here recomputes its
//! block and FAILS when the committed text differs, naming that command. Nothing in those blocks
//! is typed by hand. The figures are lavapipe's (CI's adapter): on another adapter the
//! last digits may differ, and the failure says so.

mod common;

use common::{adapter_line, gpu, publish_measured};
use prepass::conforming::Policy;
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
