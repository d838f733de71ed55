//! The light pre-pass example's frame (`examples/light_prepass`), rendered on the adapter at a
//! small size with the fat reference G-buffer and every diet layout `--compare` renders (every
//! `--normal` choice but snorm8, whose target core WebGPU cannot render: the issue's xyz8,
//! oct24, oct32, xy FP16, then oct16, hemioct24, xyz10, oct20, the signed octahedron, oct24 in
//! Unity's order; D24 in RGBA8 and D32F depth; one and two light buffers). It checks
//! that no pixel is NaN or infinite, that each diet G-buffer read back from its render targets
//! decodes within the encodings' derived errors of the fat one, that every diet frame stays
//! within the bound derived in
//! `examples/light_prepass/renderer/bound.rs` of the fat frame at every pixel, that xy FP16's
//! mirrored and hemioct24's clamped `z < 0` normals show beyond that bound, that the images are
//! written, and the bad input of the issue (a light at the camera, a volume through the near plane, a zero-radius
//! light, the sky, resolutions of 0 and beyond the adapter's limit). The same checks hold with the
//! G-buffer's roughness stored the GGX ways (`--roughness ggx8 | ggx8-log | godot8`) and with the
//! Substrate word (`--normal substrate`, ggx8 in its own byte).
//!
//! It publishes docs/light_prepass.md's `light-prepass` table (bytes per pixel, memory, error: the
//! deterministic columns; times vary per run and stay in the example's `compare.md`) and, with
//! `PREPASS_WRITE_DOCS=1` (`bash .ci/docs`), rewrites that page's PNGs in `docs/light_prepass/`;
//! otherwise it checks that the committed PNGs are the frames it renders.

mod common;

#[path = "common/dawn.rs"]
mod dawn;

#[path = "../examples/light_prepass/renderer/mod.rs"]
#[allow(dead_code)]
mod renderer;

use prepass::{assert_at_least, assert_within};
use renderer::compare::{false_colour, non_finite, to_rgb8};
use renderer::render::{Device, PipelineShape, lights_in_view, pipeline_shapes, render};
use renderer::report::{Row, fat_of, run, table};
use renderer::{Config, Storage, bound, scene};
use std::sync::OnceLock;

/// The frame the test renders: the default frame (its scene, camera and 256 lights) at 320×180.
fn small() -> Config {
    Config {
        width: 320,
        height: 180,
        repeats: 0,
        ..Config::default_frame()
    }
}

/// The adapter; with none this FAILS, naming the fix (install lavapipe).
fn device() -> &'static Device {
    static DEV: OnceLock<Result<Device, String>> = OnceLock::new();
    match DEV.get_or_init(|| {
        Device::new().inspect(|d| eprintln!("light_prepass test renders on: {}", d.describe()))
    }) {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    }
}

/// Every pixel of `row` against its fat frame and the derived bound. Returns, for the pixels
/// outside the encoding's domain (view-space z < 0), how many there are, how many break the
/// bound they would have inside it, and the largest such excess in levels.
fn check_bound(rows: &[Row], row: &Row, scene: &scene::SceneData) -> (usize, usize, f64) {
    let fat = fat_of(rows, row);
    let fat_g = fat.output.fat.as_ref().expect("the fat frame's G-buffer");
    let (tan, sorted) = lights_in_view(&row.cfg, scene);
    let inputs = bound::Inputs {
        cfg: &row.cfg,
        fat: fat_g,
        fat_colour: &fat.output.colour,
        lights: &sorted.lights,
        materials: &scene.materials,
        tan_half_fov: tan,
        near: scene.camera.near,
    };
    let name = row.cfg.layout_name();
    let (mut worst, mut at) = (f64::NEG_INFINITY, None);
    let (mut excluded, mut broken, mut excess_max) = (0usize, 0usize, 0f64);
    for y in 0..row.cfg.height {
        for x in 0..row.cfg.width {
            let i = (y * row.cfg.width + x) as usize;
            let (a, b) = (fat.rgb[i], row.rgb[i]);
            match bound::pixel(&inputs, x, y) {
                None => {
                    excluded += 1;
                    let pb = bound::in_domain(&inputs, x, y);
                    let over = (0..3)
                        .map(|k| f64::from(a[k].abs_diff(b[k])) - pb.levels[k])
                        .fold(f64::NEG_INFINITY, f64::max);
                    if over > 0.0 {
                        broken += 1;
                        excess_max = excess_max.max(over);
                    }
                }
                Some(pb) => {
                    for k in 0..3 {
                        let excess = f64::from(a[k].abs_diff(b[k])) - pb.levels[k];
                        if excess > worst {
                            worst = excess;
                            at = Some((x, y, k, a[k].abs_diff(b[k]), pb));
                        }
                    }
                }
            }
        }
    }
    let (x, y, k, e, pb) = at.expect("pixels");
    eprintln!(
        "{name}: worst pixel ({x}, {y}) channel {k}: error {e} levels, bound {:.3} levels; \
         {excluded} pixels outside the encoding's domain, {broken} of them beyond the \
         in-domain bound (by up to {excess_max:.1} levels)",
        pb.levels[k]
    );
    assert_within!(
        worst,
        0.0,
        "examples/light_prepass/renderer/bound.rs (the derivation in its module docs): \
         error − bound at the worst pixel",
        "{name}: pixel ({x}, {y}) channel {k}: error {e} levels, bound {:.4} levels from a linear \
         bound {:.3e}; θ = {:.3e} rad, ε_p = {:.3e}, {} lights reach it",
        pb.levels[k],
        pb.linear[k],
        pb.theta,
        pb.eps_p,
        pb.lights
    );
    (excluded, broken, excess_max)
}

/// The diet G-buffer against the fat one (`bound::gbuffer_error`): the decoded normal within
/// the encoding's derived angle, the rebuilt view depth within its derived relative error.
/// Every frame's image is free of NaN and infinite pixels.
fn assert_finite(rows: &[Row]) {
    for r in rows {
        assert_eq!(
            non_finite(&r.output.colour),
            0,
            "{}: NaN or infinite pixels",
            r.cfg.layout_name()
        );
    }
}

fn check_gbuffer(rows: &[Row], row: &Row, scene: &scene::SceneData) {
    let fat = fat_of(rows, row)
        .output
        .fat
        .as_ref()
        .expect("the fat G-buffer");
    let g = bound::gbuffer_error(row, fat, scene).unwrap_or_else(|e| panic!("{e}"));
    let name = row.cfg.layout_name();
    let w = row.cfg.width as usize;
    eprintln!(
        "{name}: normals off by up to {:.4}° ({:.2} of the derived bound), view depth by up to \
         {:.2e} relative ({:.2} of its bound)",
        g.angle_deg, g.angle_ratio, g.depth_rel, g.depth_ratio
    );
    assert_within!(
        g.angle_ratio,
        1.0,
        "bound::normal_angle_at (derived in its docs): angle / bound at the worst texel",
        "{name}: texel ({}, {}) decodes {:.4}° from the fat normal",
        g.angle_at % w,
        g.angle_at / w,
        g.angle_deg
    );
    assert_within!(
        g.depth_ratio,
        1.0,
        "bound::depth_relative (derived in its docs): error / bound at the worst texel",
        "{name}: texel ({}, {}) rebuilds view depth {:.3e} relative from the fat one",
        g.depth_at % w,
        g.depth_at / w,
        g.depth_rel
    );
}

#[test]
fn light_prepass_frame_diet_within_derived_bound_of_fat() {
    let dev = device();
    let base = small();
    let scene = scene::build(base.lights);
    let rows = run(dev, &base, &scene).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        rows.len(),
        42,
        "two fat frames and 40 diet layouts (10 normals × 2 depths × 2 light layouts)"
    );
    assert_finite(&rows);
    for r in rows.iter().filter(|r| r.error.is_some()) {
        let Storage::Diet { normal, .. } = r.cfg.storage else {
            unreachable!()
        };
        check_gbuffer(&rows, r, &scene);
        let (excluded, broken, excess) = check_bound(&rows, r, &scene);
        if bound::hemisphere_only(normal) {
            // The scene's normal-mapped ground and off-axis spheres face away from the view
            // axis (z < 0): xy FP16 mirrors those normals, hemioct24 clamps them onto the
            // equator, and the error there must break the
            // bound the same pixels would have if their normals were in the encoding's domain
            // — the artefact is in the image, not only in the numbers.
            assert_at_least!(excluded, > 0, "the scene must have z < 0 view-space normals");
            assert_at_least!(
                excess,
                > 1.0,
                "the hemisphere-only encoding's z < 0 artefact: error beyond the in-domain bound (bound::in_domain), \
                 levels",
                "{}: {broken} of {excluded} z < 0 pixels break it",
                r.cfg.layout_name()
            );
        }
    }

    // The images and compare.md are written.
    let dir = std::env::temp_dir().join(format!("prepass-light_prepass-{}", std::process::id()));
    renderer::report::write(&dir, dev, &base, &scene, &rows, "").unwrap();
    for r in &rows {
        let stem = r.cfg.file_stem();
        let mut files = vec![format!("{stem}.png")];
        if r.error.is_some() {
            files.push(format!("{stem}_error.png"));
        }
        for f in files {
            let (w, h) = png_size(&dir.join(&f));
            assert_eq!((w, h), (base.width, base.height), "{f}");
        }
    }
    let md = std::fs::read_to_string(dir.join("compare.md")).unwrap();
    assert!(md.contains("xy fp16 + D24 in RGBA8, two buffers"), "{md}");
    assert!(md.contains("## The G-buffer, decoded"), "{md}");
    let _ = std::fs::remove_dir_all(&dir);

    // docs/light_prepass.md's table and images.
    let memory_at = (
        Config::default_frame().width,
        Config::default_frame().height,
    );
    let body = format!(
        "{} Errors at {}×{} against the fat frame of the same light layout; memory at the \
         default {}×{}, one sample.\n\n{}",
        common::adapter_line().trim_end(),
        base.width,
        base.height,
        memory_at.0,
        memory_at.1,
        table(&rows, memory_at, false)
    );
    common::publish_measured("docs/light_prepass.md", "light-prepass", &body);
    let find = |stem: &str| {
        rows.iter()
            .find(|r| r.cfg.file_stem() == stem)
            .unwrap_or_else(|| panic!("no layout {stem}"))
    };
    let frame = find("oct24_d32f_one");
    let images = [
        ("frame.png", frame.rgb.clone()),
        (
            "xy_fp16_error.png",
            false_colour(
                &fat_of(&rows, find("xy_fp16_d32f_one")).rgb,
                &find("xy_fp16_d32f_one").rgb,
            ),
        ),
        (
            "xyz8_error.png",
            false_colour(
                &fat_of(&rows, find("xyz8_d24_one")).rgb,
                &find("xyz8_d24_one").rgb,
            ),
        ),
    ];
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/light_prepass");
    for (name, rgb) in images {
        let path = docs.join(name);
        if std::env::var_os("PREPASS_WRITE_DOCS").is_some() {
            std::fs::create_dir_all(&docs).unwrap();
            renderer::png_out::write_rgb(&path, base.width, base.height, &rgb).unwrap();
        } else {
            let committed = png_pixels(&path);
            assert!(
                committed == rgb,
                "{} differs from the frame rendered now: run `bash .ci/docs` to regenerate it",
                path.display()
            );
        }
    }
}

/// The GGX roughness forms (`--roughness ggx8 | ggx8-log | godot8`) and the Substrate word
/// (`--normal substrate`, whose own byte holds ggx8), as the first test checks the log8 layouts:
/// each diet frame against the fat frame of the same form — finite pixels, the G-buffer decoded
/// within its derived errors with the roughness codes identical, every pixel within the derived
/// bound (its exponent decoded by the form: `bound::power_of_code`). The fat codes are the Rust
/// twins' codes of the materials' powers (`r = √α`, `α = √(2/(p + 2))`; the scene's `r` lie at
/// least 9e-6 relative from a code boundary, far beyond f32's few ULP). And the command line's
/// choice: log8 by default, ggx8 for Substrate, which refuses the other forms.
#[test]
fn light_prepass_ggx_roughness_and_substrate_within_derived_bound_of_fat() {
    use prepass::roughness_ggx as ggx;
    use prepass::scene::RoughnessChoice as R;
    use prepass::scene::{DepthStorage as D, LightBuffers as L, NormalEncoding as N};
    use renderer::resolve_roughness;
    assert_eq!(resolve_roughness(Some(N::Oct24), None), Ok(R::Log8));
    assert_eq!(resolve_roughness(None, Some(R::Godot8)), Ok(R::Godot8));
    assert_eq!(resolve_roughness(Some(N::Substrate), None), Ok(R::Ggx8));
    assert_eq!(
        resolve_roughness(Some(N::Substrate), Some(R::Ggx8)),
        Ok(R::Ggx8)
    );
    for r in [R::Log8, R::Ggx8Log, R::Godot8] {
        let e = resolve_roughness(Some(N::Substrate), Some(r)).expect_err("Substrate refuses it");
        assert!(e.contains("ggx8 only"), "{e}");
    }

    let dev = device();
    let scene = scene::build(small().lights);
    let diet = |normal, depth, lights| (Storage::Diet { normal, depth }, lights);
    let runs = [
        (
            R::Ggx8,
            L::One,
            vec![
                diet(N::Oct24, D::Float32, L::One),
                diet(N::Oct32, D::Code24Rgba8, L::One),
                diet(N::Substrate, D::Float32, L::One),
            ],
        ),
        (
            R::Ggx8,
            L::Two,
            vec![diet(N::Substrate, D::Code24Rgba8, L::Two)],
        ),
        (R::Ggx8Log, L::One, vec![diet(N::Oct24, D::Float32, L::One)]),
        (R::Godot8, L::One, vec![diet(N::Oct32, D::Float32, L::One)]),
    ];
    for (roughness, lights, layouts) in runs {
        let base = Config {
            roughness,
            ..small()
        };
        let rows = renderer::report::run_layouts(dev, &base, lights, &layouts, &scene)
            .unwrap_or_else(|e| panic!("{e}"));
        let fat = rows[0].output.fat.as_ref().expect("the fat G-buffer");
        let codes: Vec<u32> = scene
            .materials
            .iter()
            .map(|m| {
                let r = (2.0 / (m.albedo_power[3] + 2.0)).sqrt().sqrt();
                match roughness {
                    R::Ggx8 => ggx::encode_roughness_ggx8(r),
                    R::Ggx8Log => ggx::encode_roughness_ggx8_log(r),
                    _ => ggx::encode_roughness_godot8(r, 0),
                }
            })
            .collect();
        let lit = fat.view_z.iter().filter(|&&z| z > 0.0).count();
        assert!(lit > 0, "the frame has geometry");
        for (t, z) in fat.normal.iter().zip(&fat.view_z) {
            if *z > 0.0 {
                assert!(
                    codes.contains(&(t[3] as u32)),
                    "{roughness:?}: fat code {} is no material's code {codes:?}",
                    t[3]
                );
            }
        }
        assert_finite(&rows);
        for r in rows.iter().filter(|r| r.error.is_some()) {
            check_gbuffer(&rows, r, &scene);
            check_bound(&rows, r, &scene);
        }
    }
}

fn png_size(path: &std::path::Path) -> (u32, u32) {
    let f = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let r = png::Decoder::new(std::io::BufReader::new(f))
        .read_info()
        .unwrap();
    (r.info().width, r.info().height)
}

fn png_pixels(path: &std::path::Path) -> Vec<[u8; 3]> {
    let f = std::fs::File::open(path).unwrap_or_else(|e| {
        panic!(
            "{}: {e}; run `bash .ci/docs` to write docs/light_prepass.md's images",
            path.display()
        )
    });
    let mut r = png::Decoder::new(std::io::BufReader::new(f))
        .read_info()
        .unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    buf[..info.buffer_size()]
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect()
}

/// Bad input: a resolution of 0 and one beyond the adapter's limit are clear errors; the
/// frame's own bad-input lights (at the camera, through the near plane, radius 0) and its sky
/// render finite pixels; MSAA, where the adapter has it, renders finite pixels per sample.
/// The renderer's shaders (every layout the report renders, single-sampled and 4× MSAA) build
/// with Tint too, through Dawn: every render pipeline the frame creates
/// (`render::pipeline_shapes`: formats, blending, depth and samples as `render` sets them), so
/// Tint's backend compiles each entry point for the pipeline it serves.
#[test]
fn light_prepass_shaders_compile_with_tint() {
    let modules = every_layout(&[1, 4])
        .into_iter()
        .map(|cfg| {
            let crate_wgsl = cfg.scene().wgsl().unwrap();
            (
                format!("{} msaa {}", cfg.layout_name(), cfg.msaa),
                renderer::shaders::module(&cfg, &crate_wgsl),
                pipeline_shapes(&cfg).iter().map(webgpu_pipeline).collect(),
            )
        })
        .collect();
    dawn::assert_pipelines(modules);
}

/// The small frame's configuration for every layout the report renders (the fat one and every
/// diet layout, with one and with two light buffers), at each of `samples`; and the GGX
/// roughness forms' modules (`--roughness`, `--normal substrate`), whose light and G-buffer
/// passes differ from log8's in the roughness lines (and Substrate's r32uint word), single-sampled
/// where the layout is Substrate's (WebGPU has no multisampled r32uint).
fn every_layout(samples: &[u32]) -> Vec<Config> {
    use prepass::scene::{DepthStorage as D, NormalEncoding as N, RoughnessChoice as R};
    let mut out = Vec::new();
    for (storage, roughness) in [
        (Storage::Fat, R::Ggx8),
        (
            Storage::Diet {
                normal: N::Oct24,
                depth: D::Float32,
            },
            R::Ggx8,
        ),
        (
            Storage::Diet {
                normal: N::Oct32,
                depth: D::Code24Rgba8,
            },
            R::Ggx8Log,
        ),
        (
            Storage::Diet {
                normal: N::Oct24,
                depth: D::Float32,
            },
            R::Godot8,
        ),
        (
            Storage::Diet {
                normal: N::Substrate,
                depth: D::Float32,
            },
            R::Ggx8,
        ),
        (
            Storage::Diet {
                normal: N::Substrate,
                depth: D::Code24Rgba8,
            },
            R::Ggx8,
        ),
    ] {
        let substrate = matches!(
            storage,
            Storage::Diet {
                normal: N::Substrate,
                ..
            }
        );
        for &msaa in samples.iter().filter(|&&n| n == 1 || !substrate) {
            out.push(Config {
                storage,
                roughness,
                msaa,
                ..small()
            });
        }
    }
    for lights in [
        prepass::scene::LightBuffers::One,
        prepass::scene::LightBuffers::Two,
    ] {
        let mut layouts = vec![(Storage::Fat, lights)];
        layouts.extend(renderer::diet_layouts(lights));
        for (storage, lights_layout) in layouts {
            for &msaa in samples {
                out.push(Config {
                    storage,
                    lights_layout,
                    msaa,
                    ..small()
                });
            }
        }
    }
    out
}

/// `p` as a WebGPU render pipeline descriptor in JSON, less the module and layout (the Dawn
/// runner sets them). wgpu's variant names are WebGPU's enum values in another case.
fn webgpu_pipeline(p: &PipelineShape) -> String {
    // Formats: `Rgba16Float` is "rgba16float" (but "depth24plus-stencil8"); other enums:
    // `GreaterEqual` is "greater-equal".
    let format = |d: &dyn std::fmt::Debug| {
        let f = format!("{d:?}").to_lowercase();
        format!("\"{}\"", f.replace("plusstencil8", "plus-stencil8"))
    };
    let value = |d: &dyn std::fmt::Debug| {
        let mut v = String::new();
        for (i, c) in format!("{d:?}").chars().enumerate() {
            if c.is_uppercase() && i > 0 {
                v.push('-');
            }
            v.push(c.to_ascii_lowercase());
        }
        format!("\"{v}\"")
    };
    let attributes: Vec<String> = p
        .attributes
        .iter()
        .map(|a| {
            format!(
                r#"{{"shaderLocation":{},"offset":{},"format":{}}}"#,
                a.shader_location,
                a.offset,
                format(&a.format)
            )
        })
        .collect();
    let component = |c: &wgpu::BlendComponent| {
        format!(
            r#"{{"srcFactor":{},"dstFactor":{},"operation":{}}}"#,
            value(&c.src_factor),
            value(&c.dst_factor),
            value(&c.operation)
        )
    };
    let targets: Vec<String> = p
        .targets
        .iter()
        .map(|t| {
            let t = t.as_ref().expect("every target present");
            let blend = t.blend.map_or(String::new(), |b| {
                format!(
                    r#","blend":{{"color":{},"alpha":{}}}"#,
                    component(&b.color),
                    component(&b.alpha)
                )
            });
            format!(
                r#"{{"format":{},"writeMask":{}{blend}}}"#,
                format(&t.format),
                t.write_mask.bits()
            )
        })
        .collect();
    let depth = &p.depth;
    format!(
        r#"{{"label":"{}","vertex":{{"entryPoint":"{}","buffers":[{{"arrayStride":{},"attributes":[{}]}}]}},"fragment":{{"entryPoint":"{}","targets":[{}]}},"primitive":{{"cullMode":{}}},"depthStencil":{{"format":{},"depthWriteEnabled":{},"depthCompare":{}}},"multisample":{{"count":{}}}}}"#,
        p.label,
        p.vs,
        p.vertex_stride,
        attributes.join(","),
        p.fs,
        targets.join(","),
        value(&p.cull),
        format(&depth.format),
        depth.depth_write_enabled.expect("depth write set"),
        value(&depth.depth_compare.expect("depth compare set")),
        p.samples
    )
}

#[test]
fn light_prepass_bad_input() {
    let dev = device();
    let max = dev.device().limits().max_texture_dimension_2d;
    for (w, h, want) in [
        (0, 180, "at least 1"),
        (320, 0, "at least 1"),
        (max + 1, 8, "limit"),
    ] {
        let cfg = Config {
            width: w,
            height: h,
            ..small()
        };
        let e = renderer::render::check(dev, &cfg).expect_err("a bad resolution must fail");
        assert!(e.contains(want), "{w}×{h}: {e}");
    }
    let cfg = Config { msaa: 3, ..small() };
    let e = renderer::render::check(dev, &cfg).expect_err("3 samples must fail");
    assert!(e.contains("supports"), "{e}");

    let base = Config {
        width: 160,
        height: 90,
        ..small()
    };
    let scene = scene::build(base.lights);
    let o = render(dev, &base, &scene).unwrap();
    let o_single = &o;
    // Two volumes need their back faces (the light at the camera, the one through the near
    // plane); the zero-radius light is left out.
    assert_at_least!(
        o.classes[1],
        2,
        "the camera-inside test on the bad-input lights"
    );
    assert_eq!(o.skipped, 1, "the zero-radius light is left out");
    assert_eq!(non_finite(&o.colour), 0);
    assert!(o.fragments[2] > 0, "the sky is reached and discarded");
    let rgb = to_rgb8(&o.colour);
    assert!(rgb.iter().any(|p| p[0] > 64), "the frame is lit");
    // The other conventions and formats render finite frames too: standard depth with a finite
    // far plane in a 24-bit code, an rgba8unorm two-buffer light layout.
    for cfg in [
        Config {
            convention: prepass::projection::DepthConvention::Standard,
            far: 200.0,
            storage: Storage::Diet {
                normal: prepass::scene::NormalEncoding::Xyz8,
                depth: prepass::scene::DepthStorage::Code24Rgba8,
            },
            ..base
        },
        Config {
            light_format: renderer::LightFormat::Rgba8Unorm,
            lights_layout: prepass::scene::LightBuffers::Two,
            ..base
        },
    ] {
        let o = render(dev, &cfg, &scene).unwrap();
        assert_eq!(non_finite(&o.colour), 0, "{}", cfg.layout_name());
        assert!(
            to_rgb8(&o.colour).iter().any(|p| p[0] > 64),
            "{} is lit",
            cfg.layout_name()
        );
    }
    if let Some(n) = dev.sample_counts(&base).into_iter().find(|&n| n > 1) {
        let o = render(dev, &Config { msaa: n, ..base }, &scene).unwrap();
        assert_eq!(non_finite(&o.colour), 0, "MSAA {n}×");
        // Per-sample lighting: a pixel a volume covers wholly runs n invocations instead of
        // one, an edge pixel at least one, so at least n/2 times the single-sample count.
        let single = f64::from(o_single.fragments[0]);
        assert_at_least!(
            f64::from(o.fragments[0]),
            single * f64::from(n) / 2.0,
            "sample-rate shading in the light pass (comment above)",
            "MSAA {n}×"
        );
    }
}

/// The renderer's shaders (every layout) use no f32 operation the conforming emulation leaves
/// at the host's accuracy (`Emulated::uncovered`): the coverage check of `tests/conforming.rs`
/// (`the_emulation_covers_every_shipped_composed_and_example_module`) applied to the example's
/// own shaders, which only this binary builds. Single-sampled only: the 4× MSAA modules differ
/// in texture types and an integer sample index alone (`shaders::module`), and the emulation's
/// validator lacks the multisampled-shading capability their `sample_index` needs.
#[test]
fn light_prepass_shaders_are_covered_by_the_emulation() {
    use prepass::conforming::{Emulation, Policy, emulate};
    let emu = Emulation::new(Policy::Upper);
    let mut checked = 0;
    for cfg in every_layout(&[1]) {
        let src = renderer::shaders::module(&cfg, &cfg.scene().wgsl().unwrap());
        let name = cfg.layout_name();
        let e = emulate(&src, &emu).unwrap_or_else(|err| panic!("{name}: {err}"));
        assert!(
            e.uncovered.is_empty(),
            "{name} uses operations the emulation leaves at the host's accuracy: {:?} \
             (emulate them in src/conforming, or change the shader)",
            e.uncovered
        );
        checked += 1;
    }
    eprintln!("coverage: {checked} light pre-pass modules, nothing left uncovered");
}
