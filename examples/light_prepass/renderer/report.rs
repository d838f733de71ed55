//! `--compare`: the same frame with the fat reference G-buffer and with every diet layout, one
//! row per layout (memory from `Scene::gbuffer()`, GPU time per pass, error against the fat
//! frame), the depth-bounds and MSAA measurements, and `compare.md`.

use super::compare::{ErrorStats, error_stats, false_colour, non_finite, to_rgb8};
use super::render::{Device, Output, render};
use super::scene::SceneData;
use super::{Config, LightFormat, Storage, diet_layouts, png_out};
use prepass::scene::LightBuffers;
use prepass::scene::gbuffer::megabytes;
use std::fmt::Write as _;
use std::path::Path;

/// One rendered layout of the comparison.
pub struct Row {
    /// Its configuration.
    pub cfg: Config,
    /// Bytes per pixel per sample of every target (G-buffer, light buffers).
    pub bytes_per_pixel: u64,
    /// Where the byte count comes from.
    pub layout_source: &'static str,
    /// The frame.
    pub output: Output,
    /// Its 8-bit levels.
    pub rgb: Vec<[u8; 3]>,
    /// Error against the fat frame of the same light layout (`None` for the fat rows).
    pub error: Option<ErrorStats>,
}

/// Bytes per pixel of `cfg`'s targets: `Scene::gbuffer()` for a diet layout (its light buffers
/// are rgba16float; an rgba8unorm light buffer counts 4 bytes less each), counted here for the
/// fat reference, which is no `Scene` layout.
pub fn bytes_per_pixel(cfg: &Config) -> Result<(u64, &'static str), String> {
    let lights = match cfg.lights_layout {
        LightBuffers::One => 1,
        LightBuffers::Two => 2,
    };
    let light_bytes = match cfg.light_format {
        LightFormat::Rgba16Float => 8,
        LightFormat::Rgba8Unorm => 4,
    };
    match cfg.storage {
        // depth32float + rgba32float normal/roughness + r32float view depth + light buffers.
        Storage::Fat => Ok((
            4 + 16 + 4 + lights * light_bytes,
            "counted (not a Scene layout)",
        )),
        Storage::Diet { .. } => {
            let g = cfg.scene().gbuffer().map_err(|e| e.to_string())?;
            let fp16 = g.bytes_per_pixel();
            Ok((fp16 - lights * (8 - light_bytes), "Scene::gbuffer()"))
        }
    }
}

/// Render the fat frame and every diet layout for both light layouts.
pub fn run(dev: &Device, base: &Config, scene: &SceneData) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for lights in [LightBuffers::One, LightBuffers::Two] {
        rows.extend(run_layouts(
            dev,
            base,
            lights,
            &diet_layouts(lights),
            scene,
        )?);
    }
    Ok(rows)
}

/// Render the fat frame of light layout `lights` (`base`'s other choices, its roughness form
/// included), then each diet layout of `layouts`: the fat row first.
pub fn run_layouts(
    dev: &Device,
    base: &Config,
    lights: LightBuffers,
    layouts: &[(Storage, LightBuffers)],
    scene: &SceneData,
) -> Result<Vec<Row>, String> {
    let fat_cfg = Config {
        storage: Storage::Fat,
        lights_layout: lights,
        ..*base
    };
    let fat = render(dev, &fat_cfg, scene)?;
    let fat_rgb = to_rgb8(&fat.colour);
    let (b, src) = bytes_per_pixel(&fat_cfg)?;
    let mut diet_rows = Vec::new();
    for &(storage, l) in layouts {
        let cfg = Config {
            storage,
            lights_layout: l,
            ..*base
        };
        eprintln!("  rendering {}", cfg.layout_name());
        let output = render(dev, &cfg, scene)?;
        let rgb = to_rgb8(&output.colour);
        let (bytes, source) = bytes_per_pixel(&cfg)?;
        diet_rows.push(Row {
            cfg,
            bytes_per_pixel: bytes,
            layout_source: source,
            error: Some(error_stats(&fat_rgb, &rgb)),
            output,
            rgb,
        });
    }
    let mut rows = vec![Row {
        cfg: fat_cfg,
        bytes_per_pixel: b,
        layout_source: src,
        output: fat,
        rgb: fat_rgb,
        error: None,
    }];
    rows.extend(diet_rows);
    Ok(rows)
}

fn ms(v: Option<[f64; 3]>, k: usize) -> String {
    v.map_or("n/a".into(), |t| format!("{:.2}", t[k]))
}

/// The fat frame of `row`'s light layout and roughness form.
pub fn fat_of<'a>(rows: &'a [Row], row: &Row) -> &'a Row {
    rows.iter()
        .find(|r| {
            r.cfg.storage == Storage::Fat
                && r.cfg.lights_layout == row.cfg.lights_layout
                && r.cfg.roughness == row.cfg.roughness
        })
        .expect("a fat row for each light layout and roughness")
}

/// The deterministic columns (bytes, memory at `memory_at`, error), one row per layout, as a
/// Markdown table; `timing` adds the GPU time per pass.
pub fn table(rows: &[Row], memory_at: (u32, u32), timing: bool) -> String {
    let mut s = String::from("| layout | bytes/pixel | memory at ");
    let _ = write!(s, "{}×{}", memory_at.0, memory_at.1);
    s.push_str(" | max error (levels) | mean error | PSNR (dB) |");
    if timing {
        s.push_str(" (a) G-buffer ms | (b) lights ms | (c) composite ms |");
    }
    s.push_str("\n|---|---|---|---|---|---|");
    if timing {
        s.push_str("---|---|---|");
    }
    s.push('\n');
    for r in rows {
        let mem = r.bytes_per_pixel * u64::from(memory_at.0) * u64::from(memory_at.1);
        let (max, mean, psnr) = match r.error {
            None => ("reference".to_string(), "—".to_string(), "—".to_string()),
            Some(e) => (
                e.max.to_string(),
                format!("{:.3}", e.mean),
                if e.psnr.is_infinite() {
                    "∞".into()
                } else {
                    format!("{:.1}", e.psnr)
                },
            ),
        };
        let _ = write!(
            s,
            "| {} | {} | {:.2} MB | {max} | {mean} | {psnr} |",
            r.cfg.layout_name(),
            r.bytes_per_pixel,
            megabytes(mem)
        );
        if timing {
            let t = r.output.pass_ms;
            let _ = write!(s, " {} | {} | {} |", ms(t, 0), ms(t, 1), ms(t, 2));
        }
        s.push('\n');
    }
    s
}

/// Write every frame, its false-colour error image and `compare.md` into `dir`; `extra` is
/// appended (the depth-bounds and MSAA sections).
pub fn write(
    dir: &Path,
    dev: &Device,
    base: &Config,
    scene: &SceneData,
    rows: &[Row],
    extra: &str,
) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for r in rows {
        let stem = r.cfg.file_stem();
        png_out::write_rgb(
            &dir.join(format!("{stem}.png")),
            base.width,
            base.height,
            &r.rgb,
        )?;
        if r.error.is_some() {
            let fat = fat_of(rows, r);
            png_out::write_rgb(
                &dir.join(format!("{stem}_error.png")),
                base.width,
                base.height,
                &false_colour(&fat.rgb, &r.rgb),
            )?;
        }
    }
    let mut md = String::from("# Light pre-pass: the render-target diet, measured\n\n");
    let _ = writeln!(
        md,
        "Adapter: {}{}. Frame {}×{}, {} lights (+3 bad-input lights), MSAA {}, depth {:?} \
         with far = {}, light buffers {:?}.\n",
        dev.describe(),
        if dev.is_software() {
            " — a software rasteriser (lavapipe): the GPU times are CPU times"
        } else {
            ""
        },
        base.width,
        base.height,
        base.lights,
        base.msaa,
        base.convention,
        base.far,
        base.light_format
    );
    if !dev.timestamps {
        md.push_str("This adapter has no timestamp queries: the time columns say n/a.\n\n");
    }
    md.push_str(
        "Error: each diet frame against the fat frame (f32 normals, f32 view depth) of the \
         same light layout, in 8-bit output levels over every channel. Bytes per pixel: every \
         render target, the light buffers included (`Scene::gbuffer()` for the diet layouts). \
         Times: the minimum over the repeats, per pass, from timestamp queries.\n\n",
    );
    md.push_str(&table(rows, (base.width, base.height), true));
    let non: usize = rows.iter().map(|r| non_finite(&r.output.colour)).sum();
    let _ = writeln!(
        md,
        "\nPixels with a NaN or infinite channel, all frames: {non}.\n\n\
         Files: `<layout>.png` (the frame), `<layout>_error.png` (false colour of the largest \
         channel error: black 0, blue ≈1, magenta ≈3, orange ≈7, yellow ≈15, white ≥ {} \
         levels).\n",
        super::compare::FALSE_COLOUR_TOP
    );
    if let Some(r) = rows.first() {
        let c = r.output.classes;
        let _ = writeln!(
            md,
            "Light volumes: {} spheres drawn by their front faces, {} by their back faces \
             (camera inside, or the near plane cuts them), {} cones by front faces, {} by back \
             faces; {} lights left out (zero radius).\n",
            c[0], c[1], c[2], c[3], r.output.skipped
        );
    }
    if let Some(r) = rows.first() {
        let o = &r.output;
        let _ = writeln!(
            md,
            "## Bad input\n\nEvery frame carries a light at the camera and one whose volume \
             crosses the near plane: the camera-inside test draws both by their back faces ({} \
             sphere volumes went that way). A zero-radius light is left out on the CPU ({} left \
             out). Sky pixels (no geometry, infinite depth) are discarded by the light pass \
             before anything else ({} light-pass fragments of the fat frame) and keep the clear \
             colour. A resolution of 0 or beyond the adapter's `max_texture_dimension_2d`, or an \
             MSAA count it lacks, stops with an error before anything is created.\n",
            o.classes[1], o.skipped, o.fragments[2]
        );
    }
    md.push_str(
        "## The G-buffer, decoded\n\nEach diet G-buffer read back from its render targets, \
         decoded with the crate's Rust twins, against the fat one at every pixel with geometry \
         (xy FP16 and hemioct24: normals with z ≥ 0 only), beside the bounds derived in \
         `examples/light_prepass/renderer/bound.rs`.\n\n| layout | max normal error ° | of \
         its derived bound | max view-depth error (relative) | of its derived bound |\n\
         |---|---|---|---|---|\n",
    );
    for r in rows.iter().filter(|r| r.error.is_some()) {
        let Some(fat) = fat_of(rows, r).output.fat.as_ref() else {
            continue;
        };
        match super::bound::gbuffer_error(r, fat, scene) {
            Ok(g) => {
                let _ = writeln!(
                    md,
                    "| {} | {:.4} | {:.2} | {:.2e} | {:.2} |",
                    r.cfg.layout_name(),
                    g.angle_deg,
                    g.angle_ratio,
                    g.depth_rel,
                    g.depth_ratio
                );
            }
            Err(e) => {
                let _ = writeln!(md, "| {} | {e} | | | |", r.cfg.layout_name());
            }
        }
    }
    md.push('\n');
    md.push_str(extra);
    std::fs::write(dir.join("compare.md"), md).map_err(|e| format!("compare.md: {e}"))
}
