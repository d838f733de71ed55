//! Every WGSL file — shipped (`wgsl/`) and test baselines (`tests/baselines/`) — parses,
//! validates, and translates through naga's SPIR-V, MSL, HLSL and GLSL backends.
//! Files are found by listing the directories, so a new file cannot escape.

mod common;

#[path = "common/dawn.rs"]
mod dawn;

use std::path::{Path, PathBuf};

fn wgsl_files(dir: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "wgsl"))
        .collect();
    files.sort();
    files
}

fn check(path: &Path) {
    let source = std::fs::read_to_string(path).expect("read wgsl");
    // Plain WGSL: no preprocessor (naga_oil's `#import`/`#define`, C-style `#include`).
    for (n, line) in source.lines().enumerate() {
        assert!(
            !line.trim_start().starts_with('#'),
            "{}:{}: preprocessor directive in a plain WGSL file: {line}",
            path.display(),
            n + 1
        );
    }
    let t =
        prepass::wgsl::translate_all(&source).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let checked = prepass::wgsl::parse_and_validate(&source).expect("validated above");
    // Every function the file defines reaches every backend's output.
    for (_, f) in checked.module.functions.iter() {
        let name = f.name.as_deref().expect("named function");
        for (backend, text) in [("msl", &t.msl), ("hlsl", &t.hlsl), ("glsl", &t.glsl)] {
            assert!(
                text.contains(name),
                "{}: `{name}` missing from the {backend} output",
                path.display()
            );
        }
    }
    assert_eq!(t.spirv[0], 0x0723_0203, "SPIR-V magic");
}

#[test]
fn every_shipped_file_validates_and_translates() {
    let files = wgsl_files("wgsl");
    assert!(!files.is_empty(), "no WGSL files found in wgsl/");
    for f in &files {
        check(f);
    }
}

#[test]
fn every_baseline_file_validates_and_translates() {
    for f in wgsl_files("tests/baselines") {
        check(&f);
    }
}

/// Tint (Chrome's WGSL compiler, through Dawn) accepts every shipped and baseline file, built to
/// a compute pipeline that calls every function (`dawn::assert_compile`), so Tint's backend and
/// Dawn's pipeline checks judge them too (a module over a device limit, such as 32 KiB of
/// workgroup memory, passes the front end and fails here): naga is not the only compiler a
/// renderer meets (Tint rejects, for one, a constant that is not a finite f32, which naga
/// accepts).
#[test]
fn every_shipped_and_baseline_file_compiles_with_tint() {
    let mut modules = Vec::new();
    for dir in ["wgsl", "tests/baselines"] {
        for path in wgsl_files(dir) {
            let source = std::fs::read_to_string(&path).expect("read wgsl");
            modules.push((
                format!("{dir}/{}", path.file_name().unwrap().to_string_lossy()),
                source,
            ));
        }
    }
    assert!(modules.len() >= prepass::wgsl::FILES.len());
    dawn::assert_compile(modules);
}

#[test]
fn embedded_registry_matches_the_directory() {
    let on_disk: Vec<String> = wgsl_files("wgsl")
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    let embedded: Vec<String> = prepass::wgsl::FILES
        .iter()
        .map(|f| f.name.to_string())
        .collect();
    assert_eq!(
        embedded, on_disk,
        "src/wgsl/mod.rs FILES must list every wgsl/ file"
    );
    for f in prepass::wgsl::FILES {
        let disk = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("wgsl")
                .join(f.name),
        )
        .unwrap();
        assert_eq!(
            f.source, disk,
            "{} embedded text differs from the file",
            f.name
        );
    }
}

#[test]
fn a_broken_file_is_caught_with_its_line() {
    let e = prepass::wgsl::translate_all("fn f(x: f32) -> f32 { return x + 1u; }").unwrap_err();
    assert_eq!(e.stage, "validate");
    assert!(e.message.contains("x + 1u"), "{}", e.message);
}
