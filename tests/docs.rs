//! Published text that no measuring suite computes: the README's size of the example to copy.
//! Every measured figure is published by the suite that measures it for its assertions, so it
//! is measured once: linear depth by `tests/linear_depth.rs`, 24-bit depth by
//! `tests/depth24.rs`, the normal encodings by `tests/conforming.rs`, the bad-input table by
//! `tests/bad_input.rs`, the implementations table by `tests/implementations.rs`, the frame by
//! `tests/light_prepass.rs`, the peers by `tests/errplot_peers.rs`.
//!
//! `bash .ci/docs` writes every block (`PREPASS_WRITE_DOCS=1`); otherwise each test recomputes
//! its block and FAILS when the committed text differs, naming that command. Nothing in those
//! blocks is typed by hand.

mod common;

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
    common::deferred_minimal_scene()
        .wgsl()
        .unwrap()
        .lines()
        .count()
}
