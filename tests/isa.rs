//! Every shipped function compiled by AMD's ACO and Intel's brw (Mesa 25, without a GPU:
//! `prepass::isa`) for every target: a compile failure fails here, and the figures are
//! published in docs/figures.md (blocks `isa-costs` and `isa-precise-ratio`).

mod common;

use prepass::harness::Signature;
use prepass::isa::{Costing, Function, Target, TargetCosts};
use std::fmt::Write as _;

/// Every function of every shipped file that the harness can wrap (scalars and vectors in and
/// out), with the file it comes from.
fn shipped_functions() -> Vec<(&'static str, Function)> {
    let mut out = Vec::new();
    for file in prepass::wgsl::FILES {
        let checked = prepass::wgsl::parse_and_validate(file.source).unwrap();
        for (_, f) in checked.module.functions.iter() {
            let name = f.name.as_deref().unwrap();
            if Signature::read(file.source, name).is_ok() {
                out.push((file.name, Function::new(file.source, name)));
            }
        }
    }
    out
}

/// The targets' outcomes, every one measured: a target that was not is a setup failure, and
/// the message says how to set up.
fn measured(report: &prepass::isa::Report) -> Vec<(Target, &TargetCosts)> {
    report
        .targets
        .iter()
        .map(|t| match &t.outcome {
            Ok(c) => (t.target, c),
            Err(why) => panic!(
                "{} was not measured: {why}\nThe real-ISA checks need Mesa 25's RADV and ANV and \
                 the noop drm shims: run `bash .ci/setup-gpu-compilers` (bash .ci/test does), or \
                 point {} at the folder it fills.",
                t.target,
                prepass::isa::ROOT_VAR
            ),
        })
        .collect()
}

fn driver_line(targets: &[(Target, &TargetCosts)]) -> String {
    let mut versions: Vec<&str> = targets
        .iter()
        .map(|(_, c)| c.driver_info.as_str())
        .collect();
    versions.dedup();
    format!(
        "<!-- measured on: {} (ACO and brw, static compiler estimates) -->\n",
        versions.join(", ")
    )
}

fn cell(x: Option<f64>) -> String {
    x.map_or("—".into(), |v| format!("{v:.1}"))
}

/// Every shipped function compiles on every target, each figure is finite, and the full table
/// is published.
#[test]
fn every_shipped_function_compiles_and_is_costed_on_every_target() {
    let functions = shipped_functions();
    let list: Vec<Function> = functions.iter().map(|(_, f)| f.clone()).collect();
    let report = Costing::new().cost(&list).unwrap();
    let targets = measured(&report);
    let mut table = String::from(
        "Net per evaluation (8 independent evaluations per invocation, minus a kernel with the \
         same loads and stores; latency: one evaluation's). AMD: instructions / ALU / ACO \
         latency / ACO inverse throughput (cycles per wave64), VGPRs and waves per SIMD of the \
         one-evaluation kernel. Intel: instructions / ALU / brw cycles (per SIMD thread), \
         max live registers and SIMD width. Compare within a target, never across vendors.\n\n\
         | file | function |",
    );
    for (t, _) in &targets {
        let _ = write!(table, " {} |", t.label());
    }
    table.push_str("\n|---|---|");
    table.push_str(&"---|".repeat(targets.len()));
    table.push('\n');
    for (k, (file, f)) in functions.iter().enumerate() {
        let _ = write!(table, "| {file} | `{}` |", f.function);
        for (t, c) in &targets {
            let cost = c.functions[k].as_ref().unwrap_or_else(|e| {
                panic!("{}: `{}` does not compile: {e}", t.label(), f.function)
            });
            let n = cost.net;
            for (what, v) in [
                ("instructions", Some(n.instructions)),
                ("ALU", Some(n.alu)),
                ("latency", n.latency),
                ("inverse throughput", n.inverse_throughput),
                ("cycles", n.cycles),
            ] {
                assert!(
                    v.is_none_or(f64::is_finite),
                    "{}: `{}`: {what} is {v:?}",
                    t.label(),
                    f.function
                );
            }
            let k1 = &cost.kernel;
            match t.vendor() {
                prepass::isa::Vendor::Amd => {
                    let _ = write!(
                        table,
                        " {:.1} / {:.1} / {} / {}; {} VGPRs, {} waves |",
                        n.instructions,
                        n.alu,
                        cell(n.latency),
                        cell(n.inverse_throughput),
                        k1.registers,
                        k1.occupancy.unwrap_or(f64::NAN)
                    );
                }
                prepass::isa::Vendor::Intel => {
                    let _ = write!(
                        table,
                        " {:.1} / {:.1} / {}; {} regs, SIMD{} |",
                        n.instructions,
                        n.alu,
                        cell(n.cycles),
                        k1.registers,
                        k1.subgroup_size
                    );
                }
            }
            if k1.spills > 0.0 {
                let _ = write!(table, " ({} spills)", k1.spills);
            }
        }
        table.push('\n');
    }
    common::publish_on(
        "docs/figures.md",
        "isa-costs",
        &table,
        driver_line(&targets)
            .trim_start_matches("<!-- measured on: ")
            .trim_end_matches(" -->\n"),
    );
}

/// Every shipped file compiles whole (every function called in one kernel) on every target.
#[test]
fn every_shipped_file_compiles_whole_on_every_target() {
    let sources: Vec<&str> = prepass::wgsl::FILES.iter().map(|f| f.source).collect();
    let (reports, called) = Costing::new().compile_libraries(&sources).unwrap();
    for r in &reports {
        let (_, modules) = r.outcome.as_ref().unwrap_or_else(|why| {
            panic!(
                "{} was not measured: {why} (run `bash .ci/setup-gpu-compilers`)",
                r.target
            )
        });
        for ((file, m), names) in prepass::wgsl::FILES.iter().zip(modules).zip(&called) {
            assert!(!names.is_empty(), "{}: no function called", file.name);
            if let Err(e) = m {
                panic!("{}: {} does not compile whole: {e}", r.target, file.name);
            }
        }
    }
}

/// The README's real-instruction-set costs: each encoding's encoder and decoder (block
/// `isa-cost`, under "Pick an encoding"), the depth and roughness functions (block
/// `isa-cost-depth`, under "Depth"), on RDNA2 and Xe-HPG beside SPIR-V. A function's
/// first argument is per pixel (a column); the rest are per-frame constants, fed from a
/// uniform as a renderer feeds them.
#[test]
fn readme_cost_table_on_real_instruction_sets() {
    // Every encoding of the sweeps' table, in its order, then the vouched-input octahedral and
    // hemi-octahedral encoders (the same codes inside their contract; `Scene::normal_input`).
    let oct = prepass::wgsl::NORMAL_OCT;
    let hemioct = prepass::wgsl::NORMAL_HEMIOCT;
    let normals: Vec<(&str, &str, &str, &str)> = prepass::sweep::normal::CODECS
        .iter()
        .map(|c| (c.name, c.source, c.encode, c.decode))
        .chain([
            (
                "oct24, vouched input",
                oct,
                "encode_normal_oct24_vouched",
                "decode_normal_oct24",
            ),
            (
                "oct24 fast, vouched input",
                oct,
                "encode_normal_oct24_fast_vouched",
                "decode_normal_oct24",
            ),
            (
                "hemioct24, vouched input",
                hemioct,
                "encode_normal_hemioct24_vouched",
                "decode_normal_hemioct24",
            ),
            (
                "hemioct24 fast, vouched input",
                hemioct,
                "encode_normal_hemioct24_fast_vouched",
                "decode_normal_hemioct24",
            ),
        ])
        .collect();
    let others = [
        ("linear_depth", "view_z_from_depth24"),
        ("linear_depth", "view_z_from_depth24_consts"),
        ("linear_depth", "view_z_from_depth"),
        ("linear_depth", "view_z_from_depth_consts"),
        ("linear_depth", "view_z_from_reversed_depth"),
        ("linear_depth", "view_z_from_reversed_depth_consts"),
        ("linear_depth", "view_z_from_depth_uniform"),
        ("depth24", "depth24_from_rgb8"),
        ("depth24", "hyperbolic_depth_from_depth24"),
        ("roughness", "encode_log_roughness"),
        ("roughness", "decode_log_roughness"),
        ("roughness_ggx", "encode_roughness_ggx8"),
        ("roughness_ggx", "decode_roughness_ggx8"),
        ("roughness_ggx", "encode_roughness_ggx8_log"),
        ("roughness_ggx", "decode_roughness_ggx8_log"),
    ];
    let source = |stem: &str| {
        prepass::wgsl::FILES
            .iter()
            .find(|f| f.name == format!("{stem}.wgsl"))
            .unwrap()
            .source
    };
    let function = |src: &str, name: &str| {
        let sig = Signature::read(src, name).unwrap();
        let feeds: Vec<prepass::harness::Feed> = (0..sig.params.len())
            .map(|k| {
                if k == 0 {
                    prepass::harness::Feed::Column
                } else {
                    prepass::harness::Feed::Splat
                }
            })
            .collect();
        Function::new(src, name).with_feeds(&feeds)
    };
    let mut list = Vec::new();
    for &(_, source, enc, dec) in &normals {
        list.push(function(source, enc));
        list.push(function(source, dec));
    }
    for (stem, name) in others {
        list.push(function(source(stem), name));
    }
    let shown = [Target::Rdna2, Target::XeHpg];
    let report = Costing::new().targets(&shown).cost(&list).unwrap();
    let targets = measured(&report);
    let get = |t: Target, k: usize| {
        report
            .get(t, k)
            .unwrap_or_else(|| panic!("{}: `{}` did not compile", t.label(), list[k].function))
    };
    let spirv = |k: usize| {
        prepass::wgsl::spirv_instruction_count(&list[k].source, &list[k].function)
            .unwrap()
            .total
    };
    let mut body = String::from(
        "| encoding | SPIR-V encode / decode | RDNA2 instructions encode / decode | RDNA2 inverse throughput encode / decode | Xe-HPG cycles encode / decode |\n|---|---|---|---|---|\n",
    );
    // One row per encoding, its rounding encoder's figures after a `·` (the decoder is shared).
    let names: Vec<&str> = normals.iter().map(|n| n.0).collect();
    for (i, fast) in common::precise_with_fast(&names) {
        let d = 2 * i + 1;
        let enc = |g: &dyn Fn(usize) -> String| common::with_fast(g(2 * i), fast.map(|f| g(2 * f)));
        let (rd, xd) = (get(Target::Rdna2, d).net, get(Target::XeHpg, d).net);
        let _ = writeln!(
            body,
            "| {} | {} / {} | {} / {:.1} | {} / {} | {} / {} |",
            names[i],
            enc(&|k| spirv(k).to_string()),
            spirv(d),
            enc(&|k| format!("{:.1}", get(Target::Rdna2, k).net.instructions)),
            rd.instructions,
            enc(&|k| cell(get(Target::Rdna2, k).net.inverse_throughput)),
            cell(rd.inverse_throughput),
            enc(&|k| cell(get(Target::XeHpg, k).net.cycles)),
            cell(xd.cycles)
        );
    }
    let mut depth = String::from(
        "| function | SPIR-V | RDNA2 instructions | RDNA2 inverse throughput | Xe-HPG cycles |\n|---|---|---|---|---|\n",
    );
    for (k, f) in list.iter().enumerate().skip(2 * normals.len()) {
        let (r, x) = (get(Target::Rdna2, k).net, get(Target::XeHpg, k).net);
        let _ = writeln!(
            depth,
            "| `{}` | {} | {:.1} | {} | {} |",
            f.function,
            spirv(k),
            r.instructions,
            cell(r.inverse_throughput),
            cell(x.cycles)
        );
    }
    let on = driver_line(&targets);
    let on = on
        .trim_start_matches("<!-- measured on: ")
        .trim_end_matches(" -->\n");
    common::publish_on("README.md", "isa-cost", &body, on);
    common::publish_on("README.md", "isa-cost-depth", &depth, on);
}

/// A floor under every form of the precise octahedral encoders (`encode_normal_oct16`, `_oct24`,
/// `_oct32`) whose codes are the loop's bit for bit (`tests/normal_oct.rs`,
/// `straight_line_precise_encoder_equals_the_loop_it_replaced`): the shipped encoder less its
/// |D|², its four divisions and its choice. The loop picks by the four candidates' scores
/// |s×D|²/|D|², so a straight-line form with its codes computes the four lattice directions D
/// and the four numerators |s×D|², rounded as the loop rounds them. Kept: the input made safe
/// and projected (the rounding encoder's work), the shipped `oct_choose` up to its four cross
/// products (its text, cut there: the floor follows the shipped construction of D), the
/// numerators, and as little as keeps them alive (three xors: a choice of one of four needs
/// three operations at least) folded into the code of the floor corner. WGSL appended to
/// `normal_oct.wgsl`; functions `precise_oct16_floor`, `_oct24_` and `_oct32_`.
fn precise_oct_floor_source() -> String {
    let oct = prepass::wgsl::NORMAL_OCT;
    let head = "fn oct_choose(s: vec3<f32>, c: vec2<f32>, bits: u32) -> u32 {\n";
    let cut = "    let x3 = cross(s, d3);\n";
    let start = oct.find(head).expect("normal_oct.wgsl defines oct_choose") + head.len();
    let end = start
        + oct[start..]
            .find(cut)
            .expect("oct_choose computes the cross products x0..x3")
        + cut.len();
    format!(
        "{oct}
fn precise_oct_floor_choose(s: vec3<f32>, c: vec2<f32>, bits: u32) -> u32 {{
{}    let q = bitcast<vec4<u32>>(vec4<f32>(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)));
    let uv = vec2<u32>(c00);
    return (uv.x | (uv.y << bits)) ^ ((q.x ^ q.y) ^ (q.z ^ q.w));
}}
fn precise_oct_floor(n: vec3<f32>, bits: u32) -> u32 {{
    let s = oct_sanitize(n).xyz;
    return precise_oct_floor_choose(s, oct_continuous(s, f32((1u << bits) - 1u)), bits);
}}
fn precise_oct16_floor(n: vec3<f32>) -> u32 {{
    return precise_oct_floor(n, 8u);
}}
fn precise_oct24_floor(n: vec3<f32>) -> u32 {{
    return precise_oct_floor(n, 12u);
}}
fn precise_oct32_floor(n: vec3<f32>) -> u32 {{
    return precise_oct_floor(n, 16u);
}}
",
        &oct[start..end]
    )
}

/// Each precise (hemi-)octahedral encoder's net cost over its rounding sibling's, per target,
/// and the floor under any bit-identical form of the octahedral ones ([`precise_oct_floor_source`])
/// over the same rounding encoder (docs/figures.md, block `isa-precise-ratio`). The floor must
/// cost no more than the encoder it is taken from, or it is no floor: checked per target.
#[test]
fn precise_over_rounding_encoders_on_every_target() {
    let pairs = [
        ("normal_oct", "encode_normal_oct16"),
        ("normal_oct", "encode_normal_oct24"),
        ("normal_oct", "encode_normal_oct32"),
        ("normal_hemioct", "encode_normal_hemioct24"),
        ("normal_signed_oct", "encode_normal_signed_oct"),
    ];
    let mut list = Vec::new();
    for (stem, name) in pairs {
        let src = prepass::wgsl::FILES
            .iter()
            .find(|f| f.name == format!("{stem}.wgsl"))
            .unwrap()
            .source;
        list.push(Function::new(src, name));
        list.push(Function::new(src, &format!("{name}_fast")));
    }
    let floor_src = precise_oct_floor_source();
    let floor = list.len();
    // The octahedral pairs are the first three: oct16, oct24, oct32.
    let floored: Vec<&str> = pairs[..3]
        .iter()
        .map(|(_, name)| name.trim_start_matches("encode_normal_"))
        .collect();
    for bits in &floored {
        list.push(Function::new(&floor_src, &format!("precise_{bits}_floor")));
    }
    let report = Costing::new().cost(&list).unwrap();
    let targets = measured(&report);
    let mut body = String::from(
        "Precise encoder's net cost / its rounding sibling's (`_fast`): instructions, and ACO \
         inverse throughput (AMD) or brw cycles (Intel).\n\n| encoder |",
    );
    for (t, _) in &targets {
        let _ = write!(body, " {} |", t.label());
    }
    let _ = writeln!(body, "\n|---|{}", "---|".repeat(targets.len()));
    let net = |t: Target, k: usize| report.get(t, k).expect("compiled").net;
    // One cell: function k's net cost over function f's (instructions / the target's rank).
    let ratio = |body: &mut String, t: Target, k: usize, f: usize| {
        let (p, f) = (net(t, k), net(t, f));
        let _ = write!(
            body,
            " {:.2}× / {:.2}× |",
            p.instructions / f.instructions,
            p.rank() / f.rank()
        );
    };
    for (i, (_, name)) in pairs.iter().enumerate() {
        let _ = write!(body, "| `{name}` |");
        for (t, _) in &targets {
            ratio(&mut body, *t, 2 * i, 2 * i + 1);
        }
        body.push('\n');
    }
    for (k, bits) in floored.iter().enumerate() {
        let _ = write!(
            body,
            "| floor under any bit-identical `encode_normal_{bits}` (`tests/isa.rs`: \
             `precise_oct_floor_source`) |"
        );
        for (t, _) in &targets {
            let (lo, p) = (net(*t, floor + k), net(*t, 2 * k));
            assert!(
                lo.rank() <= p.rank(),
                "{t}: the {bits} floor ({:.1}) costs more than its encoder ({:.1}): it is no floor",
                lo.rank(),
                p.rank()
            );
            ratio(&mut body, *t, floor + k, 2 * k + 1);
        }
        body.push('\n');
    }
    body.push_str(
        "\nThe floor: the rounding encoder's work (the input made safe and projected), the four \
         candidates' lattice directions D and the numerators |s×D|² of the loop's scores, three \
         xors to keep them alive; no |D|², no division, no choice. A straight-line form whose \
         codes are the loop's bit for bit evaluates the loop's four scores, so it computes at \
         least these: where a floor row exceeds 1.5×, issue 46's 1.5× goal is out of reach for that \
         encoder on that target.\n",
    );
    common::publish_on(
        "docs/figures.md",
        "isa-precise-ratio",
        &body,
        driver_line(&targets)
            .trim_start_matches("<!-- measured on: ")
            .trim_end_matches(" -->\n"),
    );
}

/// The compilers as witnesses: per shipped function, the freedoms ACO (RDNA2) and brw (Xe-HPG)
/// took, read from their disassembly. Each must be one `prepass::conforming` emulates (or the
/// finite-math freedom, which the bad-input contract meets by reading special inputs from
/// bits); an unclassified float instruction or an unmodelled freedom fails the test. The
/// tally is published in docs/figures.md (block `isa-freedoms`).
#[test]
fn the_freedoms_the_compilers_take_are_the_ones_the_emulation_models() {
    use prepass::isa::freedoms::{Taken, observed};
    let functions = shipped_functions();
    let list: Vec<Function> = functions.iter().map(|(_, f)| f.clone()).collect();
    let targets = [Target::Rdna2, Target::XeHpg];
    let report = Costing::new()
        .targets(&targets)
        .independent(1)
        .disassembly(true)
        .cost(&list)
        .unwrap();
    let measured_targets = measured(&report);
    let mut body = String::from(
        "Per shipped function, the instructions through which the compiler took a freedom of \
         the WGSL spec (count in the one-evaluation kernel), and the `prepass::conforming` \
         freedom that covers each (`FiniteMath`: DX9 multiplies, which assume finite operands; \
         the bad-input contract reads special inputs from bits).\n\n| function | RDNA2 (ACO) | Xe-HPG (brw) |\n|---|---|---|\n",
    );
    let mut problems = Vec::new();
    let mut kinds: std::collections::BTreeMap<String, usize> = Default::default();
    for (k, (_, f)) in functions.iter().enumerate() {
        let mut cells = Vec::new();
        for t in targets {
            let cost = report.get(t, k).expect("measured above");
            let asm = cost
                .disassembly
                .as_deref()
                .unwrap_or_else(|| panic!("{}: no disassembly for `{}`", t.label(), f.function));
            assert!(
                asm.contains("Assembly"),
                "{}: `{}`: the disassembly has no final assembly section",
                t.label(),
                f.function
            );
            let seen = observed(t.vendor(), asm);
            let mut cell = Vec::new();
            for o in &seen {
                let class = match o.taken {
                    Taken::Freedom(fr) => fr.name().unwrap_or("several").to_string(),
                    Taken::FiniteMath => "FiniteMath".to_string(),
                    Taken::Unmodelled | Taken::Unknown => {
                        problems.push(format!(
                            "{}: `{}`: {} ×{} — {} ({:?})",
                            t.label(),
                            f.function,
                            o.opcode,
                            o.count,
                            o.what,
                            o.taken
                        ));
                        format!("{:?}", o.taken)
                    }
                };
                *kinds
                    .entry(format!("{} {} → {class}", t.arch(), o.opcode))
                    .or_default() += o.count;
                cell.push(format!("{} ×{}", o.opcode, o.count));
            }
            cells.push(if cell.is_empty() {
                "none".to_string()
            } else {
                cell.join(", ")
            });
        }
        let _ = writeln!(body, "| `{}` | {} | {} |", f.function, cells[0], cells[1]);
    }
    assert!(
        problems.is_empty(),
        "instructions that are neither exact nor a freedom prepass::conforming emulates \
         (classify them in src/isa/freedoms.rs, and extend the emulation if they are a new \
         freedom):\n{}",
        problems.join("\n")
    );
    body.push_str(
        "\n| target and instruction → freedom | count over every shipped function |\n|---|---|\n",
    );
    for (kind, n) in &kinds {
        let _ = writeln!(body, "| {kind} | {n} |");
    }
    common::publish_on(
        "docs/figures.md",
        "isa-freedoms",
        &body,
        driver_line(&measured_targets)
            .trim_start_matches("<!-- measured on: ")
            .trim_end_matches(" -->\n"),
    );
}

/// The vouched-input encoders (`encode_normal_oct*_vouched`, `encode_normal_hemioct24_vouched`,
/// `…_fast_vouched`) beside their
/// robust siblings and Bevy's G-buffer oct24 encoder (the peer `tests/baselines/peer_bevy.wgsl`),
/// on every target: each compiles, and on every target the vouched form costs no more than its
/// robust sibling (the same code inside the contract, with the sanitising taken out; a
/// comparison of static compiler estimates, not a timing). The figures are printed (net
/// instructions and ACO inverse throughput or brw cycles), not published.
#[test]
fn vouched_encoders_cost_less_than_their_robust_siblings() {
    const BEVY: &str = include_str!("baselines/peer_bevy.wgsl");
    let (oct, hemioct) = (prepass::wgsl::NORMAL_OCT, prepass::wgsl::NORMAL_HEMIOCT);
    let sourced = [
        (oct, "encode_normal_oct16"),
        (oct, "encode_normal_oct16_fast"),
        (oct, "encode_normal_oct24"),
        (oct, "encode_normal_oct24_fast"),
        (oct, "encode_normal_oct32"),
        (oct, "encode_normal_oct32_fast"),
        (hemioct, "encode_normal_hemioct24"),
        (hemioct, "encode_normal_hemioct24_fast"),
    ];
    let names = sourced.map(|(_, name)| name);
    let mut list = Vec::new();
    for (source, name) in sourced {
        list.push(Function::new(source, name));
        list.push(Function::new(source, &format!("{name}_vouched")));
    }
    list.push(Function::new(BEVY, "peer_bevy_gbuffer_normal_encode"));
    let report = Costing::new().cost(&list).unwrap();
    let targets = measured(&report);
    let mut table = String::new();
    for (t, _) in &targets {
        let bevy = report.get(*t, 2 * names.len()).expect("compiled").net;
        let _ = writeln!(
            table,
            "{}: peer_bevy_gbuffer_normal_encode {:.1} instructions, {:.1} ranked",
            t.label(),
            bevy.instructions,
            bevy.rank()
        );
        for (i, name) in names.iter().enumerate() {
            let (r, v) = (
                report.get(*t, 2 * i).expect("compiled").net,
                report.get(*t, 2 * i + 1).expect("compiled").net,
            );
            let _ = writeln!(
                table,
                "{}: {name}: robust {:.1} instr / {:.1} ranked; vouched {:.1} instr / {:.1} ranked",
                t.label(),
                r.instructions,
                r.rank(),
                v.instructions,
                v.rank()
            );
            assert!(
                v.instructions <= r.instructions && v.rank() <= r.rank(),
                "{}: {name}_vouched costs more than {name}: {v:?} vs {r:?}",
                t.label()
            );
        }
    }
    eprintln!("{table}");
}
