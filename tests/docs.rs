//! Published text that no measuring suite computes: the README's size of the example to copy,
//! its length and order, and its WGSL (validated with naga on the Quick start's scene).
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

/// The README is a five-minute read for a renderer author (issue 48): at most
/// [`README_MAX_LINES`] lines, its sections in the order that reader needs, each other topic
/// linked from `docs/` rather than explained in place.
const README_MAX_LINES: usize = 300;

/// The README's top-level sections, in order.
const README_SECTIONS: [&str; 8] = [
    "Add it",
    "Quick start",
    "Pick an encoding",
    "Depth",
    "Conventions",
    "Module map",
    "Commands",
    "More",
];

#[test]
fn readme_is_short_and_in_the_readers_order() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let lines = readme.lines().count();
    assert!(
        lines <= README_MAX_LINES,
        "README.md has {lines} lines, more than {README_MAX_LINES}: move explanations and \
         secondary tables to docs/ (each generated block with the test that writes it) and link \
         them from one line"
    );
    // Headings outside code blocks (the doctests' `# ` lines are not headings).
    let mut fenced = false;
    let mut sections = Vec::new();
    for l in readme.lines() {
        if l.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && let Some(h) = l.strip_prefix("## ") {
            sections.push(h);
        }
    }
    assert_eq!(
        sections, README_SECTIONS,
        "README.md's sections are not in the reader's order (what it is, add it, Quick start, \
         pick an encoding, depth, conventions and words, module map, commands, more)"
    );
    // Every docs/ page the README links exists.
    for link in readme.split("](docs/").skip(1) {
        let page = link.split([')', '#']).next().unwrap();
        let path = format!("{}/docs/{page}", env!("CARGO_MANIFEST_DIR"));
        assert!(
            std::path::Path::new(&path).exists(),
            "README links docs/{page}, which does not exist"
        );
    }
}

/// The README's WGSL (the Quick start's entry points: the depth uniform's binding, the G-buffer
/// write and read) is text no doctest compiles, so it is checked here: appended to the module
/// the Quick start's scene composes, as the README says to use it, it must validate with naga.
#[test]
fn readme_wgsl_validates_on_the_quick_start_scene() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let blocks: Vec<&str> = readme
        .split("```wgsl\n")
        .skip(1)
        .map(|b| b.split("\n```").next().unwrap())
        .collect();
    assert_eq!(
        blocks.len(),
        1,
        "README.md should hold one ```wgsl block, the Quick start's"
    );
    // The Quick start's doctest declares the example's scene: reversed-Z infinite Float32
    // depth, oct24 normals, view positions.
    let scene = common::deferred_minimal_scene();
    let source = scene.wgsl().unwrap() + "\n" + blocks[0] + "\n";
    let checked = prepass::wgsl::parse_and_validate(&source)
        .unwrap_or_else(|e| panic!("README.md's WGSL on the Quick start's scene: {e}"));
    let entry_points: Vec<&str> = checked
        .module
        .entry_points
        .iter()
        .map(|e| &*e.name)
        .collect();
    assert_eq!(
        entry_points.len(),
        2,
        "a geometry and a lighting entry point: {entry_points:?}"
    );
    for call in [
        "view_z_from_depth_uniform(",
        "encode_normal_oct24_unorm(",
        "decode_normal_oct24_unorm(",
        "var<uniform> depth_k: vec4<f32>",
        "depth_uniform().to_le_bytes()",
    ] {
        assert!(
            blocks[0].contains(call),
            "README.md's WGSL no longer shows `{call}`"
        );
    }
}

/// The default tier's check of a sampled block ([`common::tier::publish_sampled`]) reads every
/// number of a worst column and fails where the sample measured more than was published, or
/// where a row or column is missing, and passes where only the means moved.
#[test]
fn sampled_blocks_are_held_to_their_published_worsts() {
    use common::tier::{numbers, worsts_exceeded};
    assert_eq!(
        numbers("0.0390 / 0.0390 · 0.0594"),
        vec![0.039, 0.039, 0.0594]
    );
    assert_eq!(numbers("97 %"), vec![97.0]);
    assert_eq!(numbers("1.5e-3 and -2"), vec![1.5e-3, -2.0]);
    let published = "| f | max | mean |\n|---|---|---|\n| a | 1.0 · 2.0 | 0.5 |\n";
    let lower = "| f | max | mean |\n|---|---|---|\n| a | 1.0 · 1.5 | 0.9 |\n";
    let higher = "| f | max | mean |\n|---|---|---|\n| a | 1.1 · 1.5 | 0.1 |\n";
    assert!(worsts_exceeded(published, lower, &["max"]).is_empty());
    assert_eq!(worsts_exceeded(published, higher, &["max"]).len(), 1);
    let new_row = "| f | max |\n|-|-|\n| b | 0 |";
    assert_eq!(worsts_exceeded(published, new_row, &["max"]).len(), 1);
    assert_eq!(worsts_exceeded(published, lower, &["p99"]).len(), 1);
}

/// The three tiers carry the same names and commands in the README's Commands table,
/// CONTRIBUTING.md and `errplot --help` (issue 58: "named the same everywhere").
#[test]
fn tiers_are_named_the_same_everywhere() {
    let read = |p: &str| {
        std::fs::read_to_string(format!("{}/{p}", env!("CARGO_MANIFEST_DIR")))
            .unwrap_or_else(|e| panic!("{p}: {e}"))
    };
    let help = std::process::Command::new(env!("CARGO_BIN_EXE_errplot"))
        .arg("--help")
        .output()
        .expect("errplot --help runs");
    let help = String::from_utf8_lossy(&help.stdout).to_string();
    for (what, text, needles) in [
        (
            "README.md",
            read("README.md"),
            &[
                "**default**",
                "**quick**",
                "**full**",
                "`bash .ci/test`",
                "`PREPASS_FULL=1 bash .ci/test`",
                "`bash .ci/errplot`",
                "`bash .ci/errplot --quick`",
                "`bash .ci/errplot --full`",
            ][..],
        ),
        (
            "CONTRIBUTING.md",
            read("CONTRIBUTING.md"),
            &[
                "**full tier**",
                "PREPASS_FULL=1 bash .ci/test",
                "`--quick`",
                "`--full`",
                "default",
            ][..],
        ),
        (
            "errplot --help",
            help,
            &["Three tiers", "--quick", "the default", "--full"][..],
        ),
    ] {
        for n in needles {
            assert!(text.contains(n), "{what} does not name the tier text `{n}`");
        }
    }
}
