//! Scene-driven composition: minimal modules, every combination validated and translated,
//! stable output (snapshots), module sizes, G-buffer memory (naga_oil and WESL consumers:
//! `tests/imports.rs`).

mod common;

#[path = "common/dawn.rs"]
mod dawn;

use prepass::projection::DepthConvention;
use prepass::scene::gbuffer::{GBufferLayout, Target, TargetFormat, megabytes};
use prepass::scene::{
    DepthChoice, DepthStorage, Library, LightBuffers, LightingChoice, Lights, NormalChoice,
    NormalEncoding, NormalInput, PositionChoice, RoughnessChoice, Scene, Specular,
};
use std::collections::{BTreeSet, HashMap};
use std::path::Path;

/// The functions of `wgsl` as naga reads it; panics, naming `what`, unless it validates.
fn function_names(wgsl: &str, what: &dyn std::fmt::Debug) -> BTreeSet<String> {
    let c = prepass::wgsl::parse_and_validate(wgsl)
        .unwrap_or_else(|e| panic!("{what:?}: the composed module does not validate: {e}"));
    c.module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.clone())
        .collect()
}

fn scene(storage: DepthStorage, convention: DepthConvention, position: PositionChoice) -> Scene {
    Scene {
        depth: DepthChoice {
            storage,
            convention,
            infinite_far: false,
        },
        position,
        ..Scene::default()
    }
}

#[test]
fn a_depth_only_scene_contains_only_its_depth_function_and_helpers() {
    let s = scene(
        DepthStorage::Float32,
        DepthConvention::Reversed,
        PositionChoice::None,
    );
    let names = function_names(&s.wgsl().unwrap(), &s);
    // Checked through naga's function list: the roots and the helpers they call, nothing else.
    // The uniform form decides the convention at run time, so it brings the standard path too.
    let want: BTreeSet<String> = [
        "view_z_from_reversed_depth_consts",
        "view_z_from_depth_uniform",
        "ld_is_nan",
        "ld_divide_or_sky",
        "ld_consts_ok",
        "ld_clamp_unit",
        "ld_view_z_reversed",
        "ld_view_z_standard",
        "ld_one_minus",
        "ld_uniform_near_times_max",
        "ld_uniform_ok",
        "ld_uniform_reversed",
    ]
    .map(String::from)
    .into();
    assert_eq!(names, want);
    for absent in [
        "frustum_ray",
        "view_position",
        "depth24_from_rgb8",
        "view_z_from_depth24",
    ] {
        assert!(
            !names.contains(absent),
            "{absent} leaked into a depth-only module"
        );
    }
}

/// Every scene declaration, valid or not: 1,244,160 of them (the exhaustive tests' input).
fn all_scenes() -> Vec<Scene> {
    let mut depths = Vec::new();
    for storage in [
        DepthStorage::Float32,
        DepthStorage::Code24,
        DepthStorage::Code24Rgba8,
    ] {
        for convention in [DepthConvention::Standard, DepthConvention::Reversed] {
            for infinite_far in [false, true] {
                depths.push(DepthChoice {
                    storage,
                    convention,
                    infinite_far,
                });
            }
        }
    }
    let positions = [
        PositionChoice::None,
        PositionChoice::View,
        PositionChoice::World,
        PositionChoice::CameraRelative,
    ];
    let mut normals = vec![NormalChoice::default()];
    for e in NormalEncoding::ALL {
        for fast_encoder in [false, true] {
            normals.push(NormalChoice {
                encoding: Some(e),
                fast_encoder,
            });
        }
    }
    let mut lightings = Vec::new();
    for lights in [
        Lights::None,
        Lights::Point,
        Lights::Spot,
        Lights::PointAndSpot,
    ] {
        for specular in [Specular::None, Specular::BlinnPhong, Specular::Phong] {
            for buffers in [LightBuffers::One, LightBuffers::Two] {
                for aggregate_vertex_lights in [false, true] {
                    for light_volumes in [false, true] {
                        lightings.push(LightingChoice {
                            lights,
                            specular,
                            buffers,
                            aggregate_vertex_lights,
                            light_volumes,
                        });
                    }
                }
            }
        }
    }
    let mut v = Vec::new();
    for &depth in &depths {
        for &position in &positions {
            for &normal in &normals {
                for normal_input in [NormalInput::Robust, NormalInput::Vouched] {
                    for roughness in [
                        RoughnessChoice::None,
                        RoughnessChoice::Log8,
                        RoughnessChoice::Ggx8,
                        RoughnessChoice::Ggx8Log,
                        RoughnessChoice::Godot8,
                    ] {
                        for &lighting in &lightings {
                            v.push(Scene {
                                depth,
                                position,
                                normal,
                                normal_input,
                                roughness,
                                lighting,
                            });
                        }
                    }
                }
            }
        }
    }
    v
}

/// How many distinct root sets (so distinct composed modules) the valid declarations give,
/// stated once: CONTRIBUTING.md quotes it, and `the_stated_counts_are_the_counted_ones` checks
/// both.
const DISTINCT_ROOT_SETS: usize = 131_976;

/// How many of them [`root_sets_for_backends`] picks outside `PREPASS_FULL=1`.
const SAMPLED_ROOT_SETS: usize = 2_175;

/// Every distinct root set a valid declaration gives (each sorted).
fn distinct_root_sets() -> BTreeSet<Vec<&'static str>> {
    all_scenes()
        .iter()
        .filter_map(|s| s.roots().ok())
        .map(|mut roots| {
            roots.sort_unstable();
            roots
        })
        .collect()
}

/// The distinct root sets whose modules naga validates and the backends (naga's four, Tint)
/// translate: all of them under `PREPASS_FULL=1`; otherwise every root alone, the largest set,
/// and every 64th set in order (the test prints how many). Why the sample proves the same: a
/// composed module is the union of its roots' closures, in library order, under names that
/// are unique across the library, so each function reaches the validator and a backend with
/// the same declarations it has alone; both work declaration by declaration. A module
/// validates and translates when each of its functions does, and every function is in some
/// root's closure. The sets sampled besides check the union empirically.
fn root_sets_for_backends<'a>(by_roots: &BTreeSet<Vec<&'a str>>) -> Vec<Vec<&'a str>> {
    if common::full_strength() {
        return by_roots.iter().cloned().collect();
    }
    sampled_root_sets(by_roots)
}

/// Every root alone and the largest set: what each sample below starts from.
fn roots_alone_and_largest<'a>(by_roots: &BTreeSet<Vec<&'a str>>) -> BTreeSet<Vec<&'a str>> {
    let mut picked: BTreeSet<Vec<&str>> = by_roots.iter().flatten().map(|r| vec![*r]).collect();
    picked.extend(by_roots.iter().max_by_key(|r| r.len()).cloned());
    picked
}

/// [`root_sets_for_backends`]' sample: every root alone, the largest set, every 64th set.
fn sampled_root_sets<'a>(by_roots: &BTreeSet<Vec<&'a str>>) -> Vec<Vec<&'a str>> {
    let mut picked = roots_alone_and_largest(by_roots);
    picked.extend(by_roots.iter().step_by(64).cloned());
    picked.into_iter().collect()
}

/// The root sets whose modules the GPU compilers (ACO and brw; Tint's backend) compile whole:
/// every root alone and the largest set, all of [`root_sets_for_backends`] under
/// `PREPASS_FULL=1`. The argument is that of [`root_sets_for_backends`]: a module is the union
/// of its roots' closures, and a compiler works on what each function computes.
fn root_sets_for_compilers<'a>(by_roots: &BTreeSet<Vec<&'a str>>) -> Vec<Vec<&'a str>> {
    if common::full_strength() {
        return root_sets_for_backends(by_roots);
    }
    roots_alone_and_largest(by_roots).into_iter().collect()
}

/// Composed modules compile with AMD's ACO and Intel's brw on every target (`prepass::isa`,
/// Mesa 25 without a GPU): every root alone and the largest set (all of
/// [`root_sets_for_backends`] under `PREPASS_FULL=1`). Each module is compiled whole, every
/// function it holds called on loaded arguments. The sample's argument is the one above for
/// naga's backends: a module is the union of its roots' closures, and the compilers work on what
/// each function computes. Adding every 64th set (286 modules) took 389 s on the 2-core CI
/// machine: beyond the test budget.
#[test]
fn composed_modules_compile_with_aco_and_brw() {
    let lib = Library::shipped().unwrap();
    let by_roots = distinct_root_sets();
    let sets = root_sets_for_compilers(&by_roots);
    let modules: Vec<String> = sets
        .iter()
        .map(|roots| lib.compose_text(roots.iter().copied()).unwrap())
        .collect();
    let sources: Vec<&str> = modules.iter().map(String::as_str).collect();
    let (reports, _) = prepass::isa::Costing::new()
        .compile_libraries(&sources)
        .unwrap();
    for r in &reports {
        let (_, compiled) = r.outcome.as_ref().unwrap_or_else(|why| {
            panic!(
                "{} was not measured: {why} (run `bash .ci/setup-gpu-compilers`)",
                r.target
            )
        });
        for (roots, m) in sets.iter().zip(compiled) {
            if let Err(e) = m {
                panic!(
                    "{}: composed [{}] does not compile: {e}",
                    r.target,
                    roots.join(", ")
                );
            }
        }
    }
    eprintln!(
        "{} composed modules of {} compiled by ACO and brw on {} targets",
        sets.len(),
        by_roots.len(),
        reports.len()
    );
}

/// The counts stated in prose are the counted ones: [`DISTINCT_ROOT_SETS`] and
/// [`SAMPLED_ROOT_SETS`] against the declarations, and CONTRIBUTING.md's figure against the
/// constant (a cheap check; the long test asserts them again where it prints them).
#[test]
fn the_stated_counts_are_the_counted_ones() {
    let by_roots = distinct_root_sets();
    assert_eq!(by_roots.len(), DISTINCT_ROOT_SETS, "distinct root sets");
    assert_eq!(
        sampled_root_sets(&by_roots).len(),
        SAMPLED_ROOT_SETS,
        "root sets sampled for the backends"
    );
    let n = DISTINCT_ROOT_SETS;
    let stated = format!("all {},{:03} distinct composed modules", n / 1000, n % 1000);
    let contributing =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/CONTRIBUTING.md")).unwrap();
    assert!(
        contributing.contains(&stated),
        "CONTRIBUTING.md does not say `{stated}` (tests/scene.rs, DISTINCT_ROOT_SETS)"
    );
}

/// Composed modules compile with Tint too (through Dawn): Tint's front end judges the root
/// sets of [`root_sets_for_backends`], and those of [`root_sets_for_compilers`] are built to
/// compute pipelines as well (every function called, `dawn::assert_libraries`), which runs
/// Tint's backend; under `PREPASS_FULL=1` every distinct set, each built. Building all the
/// sampled modules would take about 335 s on a loaded 2-core Xeon (the first 355 took 126 s,
/// 2026-12-06): beyond the test budget.
#[test]
fn every_distinct_module_compiles_with_tint() {
    let lib = Library::shipped().unwrap();
    let by_roots = distinct_root_sets();
    let built: BTreeSet<Vec<&str>> = root_sets_for_compilers(&by_roots).into_iter().collect();
    let modules: Vec<(String, String, bool)> = root_sets_for_backends(&by_roots)
        .iter()
        .map(|roots| {
            (
                format!("composed [{}]", roots.join(", ")),
                // naga validates these same sets in the test below; Tint judges the text alone.
                lib.compose_text(roots.iter().copied()).unwrap(),
                built.contains(roots),
            )
        })
        .collect();
    let n = modules.iter().filter(|m| m.2).count();
    assert!(n > 1 && n == built.len(), "every sampled set is built");
    dawn::assert_libraries(modules);
}

/// Every valid declaration composes, the same text on default features (`Scene::wgsl`) as
/// naga's composer, for all [`DISTINCT_ROOT_SETS`] distinct root sets; naga validates and its four backends
/// translate the root sets of [`root_sets_for_backends`] (all under `PREPASS_FULL=1`), whose
/// argument covers validation too: naga, like the WGSL spec, checks a module declaration by
/// declaration against the declarations each names, and a union of closures adds no name a
/// closure lacks. The rules that span a whole module cannot break in a union here: names are
/// unique across the library (`Library::shipped` refuses a duplicate), a call cycle in a union
/// would lie inside one closure, and no shipped file declares bindings, override ids or
/// directives (asserted below), the only other module-wide constraints.
#[test]
fn every_valid_combination_composes_validates_and_translates() {
    let lib = Library::shipped().unwrap();
    for file in prepass::wgsl::FILES {
        for line in file.source.lines() {
            let code = line.split("//").next().unwrap_or("").trim_start();
            let directive = ["enable", "requires", "diagnostic"]
                .iter()
                .any(|d| code.starts_with(&format!("{d} ")) || code.starts_with(&format!("{d}(")));
            let attribute = ["@binding", "@group", "@id"]
                .iter()
                .any(|a| code.contains(a));
            assert!(
                !(directive || attribute),
                "{}: `{line}` is a module-wide rule the sampled validation's argument excludes \
                 (doc comment above): validate every distinct module, or extend the argument",
                file.name
            );
        }
    }
    let all = all_scenes();
    assert_eq!(all.len(), 1_244_160, "scene declarations (all_scenes' doc)");
    // One representative declaration per distinct root set (the module depends on nothing else).
    let mut by_roots: HashMap<Vec<&str>, Scene> = HashMap::new();
    let mut invalid = 0;
    for s in &all {
        match s.roots() {
            Ok(roots) => {
                let mut key = roots;
                key.sort_unstable();
                by_roots.entry(key).or_insert(*s);
            }
            Err(e) => {
                // Invalid declarations are refused with the fields named, and the layout agrees.
                assert!(!e.fields.is_empty(), "{s:?}: {e}");
                assert!(s.gbuffer().is_err());
                invalid += 1;
            }
        }
    }
    for (roots, s) in &by_roots {
        // The default-feature composer (text alone) emits naga's text exactly.
        assert_eq!(
            s.wgsl().unwrap(),
            lib.compose_text(roots.iter().copied()).unwrap(),
            "{s:?}: Scene::wgsl (text) differs from Library::compose (naga)"
        );
    }
    let keys: BTreeSet<Vec<&str>> = by_roots.keys().cloned().collect();
    let checked = root_sets_for_backends(&keys);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (done, total) = (std::sync::atomic::AtomicUsize::new(0), checked.len());
    let done = &done;
    std::thread::scope(|scope| {
        for part in checked.chunks(checked.len().div_ceil(threads)) {
            let lib = &lib;
            scope.spawn(move || {
                for roots in part {
                    let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    common::progress("composed modules validated and translated", k, total);
                    // `function_names` is naga's parse and validation of the module (what
                    // `Library::compose` adds to `compose_text`), done once here.
                    let wgsl = lib.compose_text(roots.iter().copied()).unwrap();
                    // Every root is there, and nothing the roots do not reach.
                    let names = function_names(&wgsl, roots);
                    let closure = lib.closure(roots.iter().copied()).unwrap();
                    for r in roots.iter() {
                        // A root is a function or a constant (`VIEW_Z_SKY`).
                        let present = names.contains(*r) || wgsl.contains(&format!("\nconst {r}:"));
                        assert!(present, "roots {roots:?}: root {r} missing");
                    }
                    for n in &names {
                        assert!(
                            closure.contains(n),
                            "roots {roots:?}: {n} is not reachable from the roots"
                        );
                    }
                    prepass::wgsl::translate_all(&wgsl)
                        .unwrap_or_else(|e| panic!("roots {roots:?}: {e}\n{wgsl}"));
                }
            });
        }
    });
    // The counts printed below are the ones stated (`DISTINCT_ROOT_SETS`, CONTRIBUTING.md).
    assert_eq!(
        by_roots.len(),
        DISTINCT_ROOT_SETS,
        "distinct modules composed"
    );
    if !common::full_strength() {
        assert_eq!(checked.len(), SAMPLED_ROOT_SETS, "root sets sampled");
    }
    eprintln!(
        "{} declarations ({invalid} refused), {} distinct modules composed, the same text on \
         both composers; {} root sets validated and translated by SPIR-V, MSL, HLSL, GLSL",
        all.len(),
        by_roots.len(),
        checked.len()
    );
}

/// The items (blank-line separated blocks) of a composed module, in order.
fn blocks(wgsl: &str) -> Vec<String> {
    wgsl.split("\n\n")
        .map(|b| b.trim().to_string())
        .filter(|b| !b.is_empty() && !b.starts_with("// ----") && !b.starts_with("// Composed"))
        .collect()
}

/// Every scene that differs from `s` in exactly one choice (field value), valid or not.
fn neighbours(s: &Scene) -> Vec<Scene> {
    all_scenes()
        .into_iter()
        .filter(|t| {
            let diffs = [
                t.depth.storage != s.depth.storage,
                t.depth.convention != s.depth.convention,
                t.depth.infinite_far != s.depth.infinite_far,
                t.position != s.position,
                t.normal.encoding != s.normal.encoding,
                t.normal.fast_encoder != s.normal.fast_encoder,
                t.normal_input != s.normal_input,
                t.roughness != s.roughness,
                t.lighting.lights != s.lighting.lights,
                t.lighting.specular != s.lighting.specular,
                t.lighting.buffers != s.lighting.buffers,
                t.lighting.aggregate_vertex_lights != s.lighting.aggregate_vertex_lights,
                t.lighting.light_volumes != s.lighting.light_volumes,
            ];
            diffs.iter().filter(|&&d| d).count() == 1
        })
        .collect()
}

/// Adding a choice (a neighbour whose closure is a superset) keeps every item of the smaller
/// module, unchanged and in order. Checked for every valid scene of a deterministic sample of
/// 200 (every declaration × its neighbours would be millions of compositions) and all its
/// single-choice neighbours.
#[test]
fn adding_a_choice_never_changes_the_code_emitted_for_the_others() {
    let lib = Library::shipped().unwrap();
    let valid: Vec<Scene> = all_scenes()
        .into_iter()
        .filter(|s| s.roots().is_ok())
        .collect();
    let step = (valid.len() / 200).max(1);
    let mut pairs = 0;
    for a in valid.iter().step_by(step) {
        let ra = a.roots().unwrap();
        let ca = lib.closure(ra.iter().copied()).unwrap();
        let wa = blocks(&lib.compose_text(ra.iter().copied()).unwrap());
        for b in neighbours(a) {
            let Ok(rb) = b.roots() else { continue };
            let cb = lib.closure(rb.iter().copied()).unwrap();
            if !ca.is_subset(&cb) || ca == cb {
                continue;
            }
            let wb = blocks(&lib.compose_text(rb.iter().copied()).unwrap());
            let mut it = wb.iter();
            for block in &wa {
                assert!(
                    it.any(|x| x == block),
                    "adding a choice ({a:?} → {b:?}) changed or reordered:\n{block}"
                );
            }
            pairs += 1;
        }
    }
    assert!(pairs > 200, "only {pairs} superset pairs checked");
    eprintln!("{pairs} (scene, scene + one choice) pairs checked");
}

/// A scene using a piece of every module: the README's "full scene" row.
fn full_scene() -> Scene {
    Scene {
        depth: DepthChoice {
            storage: DepthStorage::Float32,
            convention: DepthConvention::Reversed,
            infinite_far: true,
        },
        position: PositionChoice::CameraRelative,
        normal: NormalChoice {
            encoding: Some(NormalEncoding::Oct24),
            fast_encoder: false,
        },
        normal_input: NormalInput::Robust,
        roughness: RoughnessChoice::Log8,
        lighting: LightingChoice {
            lights: Lights::PointAndSpot,
            specular: Specular::BlinnPhong,
            buffers: LightBuffers::One,
            aggregate_vertex_lights: false,
            light_volumes: true,
        },
    }
}

/// The shipped files the roots come from, and their bytes together: what a user who picks whole
/// files by hand would ship.
fn hand_picked(lib: &Library, roots: &[&str]) -> (BTreeSet<&'static str>, usize) {
    let files: BTreeSet<&str> = roots.iter().map(|r| lib.item(r).unwrap().file).collect();
    let hand: usize = prepass::wgsl::FILES
        .iter()
        .filter(|f| files.contains(f.name))
        .map(|f| f.source.len())
        .sum();
    (files, hand)
}

#[test]
fn the_full_scene_is_smaller_than_its_files() {
    let s = full_scene();
    let lib = Library::shipped().unwrap();
    let roots = s.roots().unwrap();
    let wgsl = lib.compose(roots.iter().copied()).unwrap();
    let (files, hand) = hand_picked(&lib, &roots);
    eprintln!(
        "full scene: {} bytes composed, {hand} bytes in {files:?}; G-buffer {} B/pixel",
        wgsl.len(),
        s.gbuffer().unwrap().bytes_per_pixel()
    );
    assert!(wgsl.len() <= hand);
}

/// What a scene's module holds, one `file kind name` line per item in composed order. The
/// snapshot is this manifest, not the module's text: every item is copied verbatim from its file
/// (`compose`), so the text would only repeat the shipped files, while a change in what a scene
/// pulls in — the thing a reviewer must see — shows as a changed line here.
fn manifest(s: &Scene) -> String {
    let lib = Library::shipped().unwrap();
    let roots = s.roots().unwrap();
    let keep = lib.closure(roots.iter().copied()).unwrap();
    let mut out = String::from("# file kind name, in composed order (tests/scene.rs)\n");
    let mut composed = String::from("// Composed by prepass::scene from the shipped WGSL files.\n");
    let mut file = "";
    for item in lib.items().iter().filter(|i| keep.contains(&i.name)) {
        out.push_str(&format!("{} {} {}\n", item.file, item.kind, item.name));
        if item.file != file {
            file = item.file;
            composed.push_str(&format!("\n// ---- from wgsl/{file} ----\n"));
        }
        composed.push_str(&format!("\n{}\n", item.text));
    }
    // The manifest stands for the text only if the text is exactly these items, verbatim.
    assert_eq!(
        s.wgsl().unwrap(),
        composed,
        "the composed module is not its manifest's items copied verbatim"
    );
    out
}

#[test]
fn composed_modules_match_their_snapshots() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots");
    let named = [
        (
            "float_reversed_camera_relative",
            scene(
                DepthStorage::Float32,
                DepthConvention::Reversed,
                PositionChoice::CameraRelative,
            ),
        ),
        (
            "code24_rgba8_standard_view",
            scene(
                DepthStorage::Code24Rgba8,
                DepthConvention::Standard,
                PositionChoice::View,
            ),
        ),
        ("full_light_prepass", full_scene()),
    ];
    let update = std::env::var_os("UPDATE_SNAPSHOTS").is_some();
    for (name, s) in named {
        let got = manifest(&s);
        let path = dir.join(format!("{name}.txt"));
        if update {
            std::fs::write(&path, &got).unwrap();
            continue;
        }
        let want = std::fs::read_to_string(&path).unwrap_or_else(|e| {
            panic!(
                "{}: {e} (run with UPDATE_SNAPSHOTS=1 to create)",
                path.display()
            )
        });
        assert_eq!(
            got, want,
            "{name}: the items the scene composes changed (UPDATE_SNAPSHOTS=1 if intended)"
        );
    }
}

#[test]
fn composed_module_is_no_larger_than_the_hand_picked_files() {
    let lib = Library::shipped().unwrap();
    eprintln!("| scene | composed bytes | hand-picked files | their bytes |");
    let mut seen = std::collections::HashSet::new();
    for s in all_scenes().into_iter().filter(|s| s.roots().is_ok()) {
        let roots = s.roots().unwrap();
        let mut key = roots.clone();
        key.sort_unstable();
        if !seen.insert(key) {
            continue;
        }
        // The text composer: `every_valid_combination_composes_validates_and_translates` checks
        // that it emits exactly what naga's `Library::compose` does for every root set, so the
        // size needs no second naga parse and validation of every distinct module.
        let wgsl = s.wgsl().unwrap();
        let (files, hand) = hand_picked(&lib, &roots);
        assert!(wgsl.len() <= hand, "{s:?}: {} > {hand}", wgsl.len());
        // Print the depth/position scenes (the README's table); check all.
        if s.normal.encoding.is_some() || s.roughness != RoughnessChoice::None {
            continue;
        }
        if s.lighting != LightingChoice::default() {
            continue;
        }
        eprintln!("| {s:?} | {} | {files:?} | {hand} |", wgsl.len());
    }
}

fn target(name: &'static str, format: TargetFormat) -> Target {
    Target {
        name,
        format,
        channels: String::new(),
    }
}

#[test]
fn gbuffer_memory_reproduces_the_talks_figures() {
    let (w, h) = (1280, 720);
    // Mark Lee, "Pre-lighting in Resistance 2" (Insomniac Games, GDC 2009): "1280*720 MSAA
    // buffer is 7.3mb, multiplied by 5 is 38mb" (2× MSAA, 32-bit).
    let one = GBufferLayout {
        targets: vec![target("rgba8", TargetFormat::Rgba8Unorm)],
    };
    let per_target = one.memory_bytes(w, h, 2);
    assert_eq!(per_target, 7_372_800);
    assert_eq!(format!("{:.1}", megabytes(per_target)), "7.4"); // Lee's slides truncate to 7.3
    let five = GBufferLayout {
        targets: vec![target("rgba8", TargetFormat::Rgba8Unorm); 5],
    };
    // 5 × 7.3728 MB = 36.9 MB (35.2 MiB): Lee's "38mb" is not 5 × his own 7.3 (36.5);
    // the computed figure is recorded in the README beside Lee's.
    assert_eq!(five.memory_bytes(w, h, 2), 36_864_000);
    // Michal Valient, "Deferred Rendering in Killzone 2" (Guerrilla Games, Develop Conference
    // 2007): four RGBA8 targets + D24S8 = 18.4 MB, 36.8 MB with 2× MSAA: decimal MB.
    let mut kz = GBufferLayout {
        targets: vec![target("rgba8", TargetFormat::Rgba8Unorm); 4],
    };
    kz.targets
        .push(target("depth", TargetFormat::Depth24PlusStencil8));
    assert_eq!(kz.memory_bytes(w, h, 1), 18_432_000);
    assert_eq!(
        format!("{:.1}", megabytes(kz.memory_bytes(w, h, 1))),
        "18.4"
    );
    assert_eq!(kz.memory_bytes(w, h, 2), 36_864_000);
    assert_eq!(
        (megabytes(kz.memory_bytes(w, h, 2)) * 10.0).floor() / 10.0,
        36.8
    );
}

#[test]
fn scene_layouts_follow_the_choices() {
    let s = scene(
        DepthStorage::Code24Rgba8,
        DepthConvention::Standard,
        PositionChoice::View,
    );
    let g = s.gbuffer().unwrap();
    assert_eq!(g.targets.len(), 2);
    assert_eq!(g.bytes_per_pixel(), 8);
    assert_eq!(g.memory_bytes(1920, 1080, 4), 8 * 1920 * 1080 * 4);
    let f = scene(
        DepthStorage::Float32,
        DepthConvention::Reversed,
        PositionChoice::None,
    );
    assert_eq!(
        f.gbuffer().unwrap().targets[0].format,
        TargetFormat::Depth32Float
    );
}

/// `Scene::normal_input`: robust by default; `NormalInput::Vouched` makes the G-buffer pass's
/// root the encoder's `_vouched` form (precise or `_fast`), whose module then holds it, and is
/// refused, naming both fields, for an encoding without one or no normal at all.
#[test]
fn vouched_normal_input_selects_the_vouched_encoder() {
    assert_eq!(Scene::default().normal_input, NormalInput::Robust);
    for (encoding, fast_encoder, robust, vouched) in [
        (
            NormalEncoding::Oct16,
            false,
            "encode_normal_oct16",
            "encode_normal_oct16_vouched",
        ),
        (
            NormalEncoding::Oct16,
            true,
            "encode_normal_oct16_fast",
            "encode_normal_oct16_fast_vouched",
        ),
        (
            NormalEncoding::Oct24,
            false,
            "encode_normal_oct24",
            "encode_normal_oct24_vouched",
        ),
        (
            NormalEncoding::Oct24,
            true,
            "encode_normal_oct24_fast",
            "encode_normal_oct24_fast_vouched",
        ),
        (
            NormalEncoding::Oct32,
            false,
            "encode_normal_oct32",
            "encode_normal_oct32_vouched",
        ),
        (
            NormalEncoding::Oct32,
            true,
            "encode_normal_oct32_fast",
            "encode_normal_oct32_fast_vouched",
        ),
        (
            NormalEncoding::Hemioct24,
            false,
            "encode_normal_hemioct24",
            "encode_normal_hemioct24_vouched",
        ),
        (
            NormalEncoding::Hemioct24,
            true,
            "encode_normal_hemioct24_fast",
            "encode_normal_hemioct24_fast_vouched",
        ),
    ] {
        let normal = NormalChoice {
            encoding: Some(encoding),
            fast_encoder,
        };
        let robust_scene = Scene {
            normal,
            ..Scene::default()
        };
        let vouched_scene = Scene {
            normal_input: NormalInput::Vouched,
            ..robust_scene
        };
        let (r, v) = (
            robust_scene.roots().unwrap(),
            vouched_scene.roots().unwrap(),
        );
        assert!(r.contains(&robust) && !r.contains(&vouched), "{r:?}");
        assert!(v.contains(&vouched) && !v.contains(&robust), "{v:?}");
        assert!(
            vouched_scene
                .wgsl()
                .unwrap()
                .contains(&format!("fn {vouched}(")),
            "{vouched}"
        );
        // The same G-buffer: only the encoder's form differs.
        assert_eq!(robust_scene.gbuffer(), vouched_scene.gbuffer());
    }
    for encoding in [
        None,
        Some(NormalEncoding::Xyz8),
        Some(NormalEncoding::XyFp16),
        Some(NormalEncoding::Xyz10),
        Some(NormalEncoding::Snorm8),
        Some(NormalEncoding::Substrate),
        Some(NormalEncoding::Xyz8Best),
        Some(NormalEncoding::Oct20),
        Some(NormalEncoding::Oct24Unity),
    ] {
        let s = Scene {
            normal: NormalChoice {
                encoding,
                fast_encoder: false,
            },
            normal_input: NormalInput::Vouched,
            ..Scene::default()
        };
        let e = s.roots().unwrap_err();
        assert_eq!(e.fields, ["normal_input", "normal.encoding"], "{e}");
        assert!(s.gbuffer().is_err());
    }
}

/// GGX roughness (`RoughnessChoice::Ggx8`) and Unreal Substrate's word: the roughness goes in
/// the normal target's free alpha, in the Substrate word (no target of its own) or in an
/// `r8unorm` target, and the lighting's roots read `α`; the log-r curve and Godot's 7 bits +
/// flag (`Ggx8Log`, `Godot8`) go where linear `r` goes, with their own codecs; Substrate with
/// anything but linear `r` is refused, naming both fields.
#[test]
fn ggx_roughness_and_the_substrate_word_lay_out_as_documented() {
    let scene = |encoding, roughness| Scene {
        normal: NormalChoice {
            encoding: Some(encoding),
            fast_encoder: false,
        },
        roughness,
        ..Scene::default()
    };
    let names = |s: &Scene| -> Vec<(&'static str, String)> {
        s.gbuffer()
            .unwrap()
            .targets
            .iter()
            .map(|t| (t.name, t.channels.clone()))
            .collect()
    };
    let oct24 = scene(NormalEncoding::Oct24, RoughnessChoice::Ggx8);
    assert!(
        names(&oct24)
            .iter()
            .any(|(n, c)| *n == "normal" && c.ends_with("a: GGX perceptual roughness")),
        "{:?}",
        names(&oct24)
    );
    let roots = oct24.roots().unwrap();
    for f in [
        "encode_roughness_ggx8_unorm",
        "decode_roughness_ggx8_unorm",
        "decode_roughness_ggx8_alpha",
    ] {
        assert!(roots.contains(&f), "{f}: {roots:?}");
    }
    let oct32 = scene(NormalEncoding::Oct32, RoughnessChoice::Ggx8);
    assert!(names(&oct32).iter().any(|(n, _)| *n == "roughness"));
    let sub = scene(NormalEncoding::Substrate, RoughnessChoice::Ggx8);
    let t = names(&sub);
    assert!(!t.iter().any(|(n, _)| *n == "roughness"), "{t:?}");
    let normal = sub
        .gbuffer()
        .unwrap()
        .targets
        .into_iter()
        .find(|t| t.name == "normal")
        .unwrap();
    assert_eq!(normal.format, TargetFormat::R32Uint);
    let roots = sub.roots().unwrap();
    for f in [
        "encode_substrate_word",
        "decode_substrate_normal",
        "decode_substrate_roughness",
        "decode_roughness_ggx8_alpha",
    ] {
        assert!(roots.contains(&f), "{f}: {roots:?}");
    }
    assert!(sub.wgsl().unwrap().contains("fn encode_substrate_word("));
    for rough in [
        RoughnessChoice::Log8,
        RoughnessChoice::Ggx8Log,
        RoughnessChoice::Godot8,
    ] {
        let e = scene(NormalEncoding::Substrate, rough).roots().unwrap_err();
        assert_eq!(e.fields, ["normal.encoding", "roughness"], "{rough:?}: {e}");
    }
    // The log curve and Godot's byte go where linear r goes: the free alpha, else a target.
    for (rough, alpha, fns) in [
        (
            RoughnessChoice::Ggx8Log,
            "a: GGX perceptual roughness (log curve)",
            &[
                "encode_roughness_ggx8_log_unorm",
                "decode_roughness_ggx8_log_unorm",
                "decode_roughness_ggx8_log_alpha",
            ][..],
        ),
        (
            RoughnessChoice::Godot8,
            "a: GGX perceptual roughness (7 bits) and dynamic flag",
            &[
                "encode_roughness_godot8_unorm",
                "decode_roughness_godot8_unorm",
            ][..],
        ),
    ] {
        let s = scene(NormalEncoding::Xyz8Best, rough);
        assert!(
            names(&s)
                .iter()
                .any(|(n, c)| *n == "normal" && c.ends_with(alpha)),
            "{rough:?}: {:?}",
            names(&s)
        );
        let roots = s.roots().unwrap();
        for f in fns {
            assert!(roots.contains(f), "{rough:?}, {f}: {roots:?}");
        }
        assert!(!roots.contains(&"decode_roughness_ggx8_alpha"), "{roots:?}");
        let wgsl = s.wgsl().unwrap();
        assert!(wgsl.contains(&format!("fn {}(", fns[0])), "{rough:?}");
        let oct32 = scene(NormalEncoding::Oct32, rough);
        assert!(
            names(&oct32).iter().any(|(n, _)| *n == "roughness"),
            "{rough:?}: no alpha free in oct32, so a roughness target"
        );
    }
}

/// O3DE's signed octahedron (`NormalEncoding::SignedOct`): an `rgb10a2unorm` normal target (R,
/// G the codes, B z's sign, A's 2 bits free), so an 8-bit roughness goes to an `r8unorm` target
/// of its own; the G-buffer pass calls the precise or rounding encoder and the render-target
/// form, the lighting the render-target decoder, and the composed module holds them.
#[test]
fn the_signed_octahedron_lays_out_in_rgb10a2() {
    for (fast_encoder, encoder) in [
        (false, "encode_normal_signed_oct"),
        (true, "encode_normal_signed_oct_fast"),
    ] {
        let s = Scene {
            normal: NormalChoice {
                encoding: Some(NormalEncoding::SignedOct),
                fast_encoder,
            },
            roughness: RoughnessChoice::Log8,
            ..Scene::default()
        };
        let g = s.gbuffer().unwrap();
        let normal = g.targets.iter().find(|t| t.name == "normal").unwrap();
        assert_eq!(normal.format, TargetFormat::Rgb10a2Unorm);
        assert!(
            normal.channels.contains("b: z's sign"),
            "{}",
            normal.channels
        );
        let rough = g.targets.iter().find(|t| t.name == "roughness").unwrap();
        assert_eq!(rough.format, TargetFormat::R8Unorm);
        let roots = s.roots().unwrap();
        for f in [
            encoder,
            "decode_normal_signed_oct",
            "encode_normal_signed_oct_unorm",
            "decode_normal_signed_oct_unorm",
        ] {
            assert!(roots.contains(&f), "{f}: {roots:?}");
        }
        let wgsl = s.wgsl().unwrap();
        for f in [encoder, "decode_normal_signed_oct_unorm"] {
            assert!(wgsl.contains(&format!("fn {f}(")), "{f} not composed");
        }
    }
}
