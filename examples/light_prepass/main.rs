//! A headless light pre-pass renderer on top of prepass: real render targets, the crate's
//! composed WGSL, light volumes, a composite pass, PNGs out; `--compare` measures the
//! render-target diet against a fat G-buffer. See docs/light_prepass.md.
//!
//! The G-buffer stores each material's specular power as the 8-bit log-range code (`log8`,
//! the default) or, with `--roughness`, as GGX perceptual roughness `r` the way engines store
//! it (`ggx8`: linear `r`; `ggx8-log`: prepass's log curve; `godot8`: Godot's 7 bits and a
//! static-object flag): the power `p` becomes `r = √α`, `α = √(2/(p + 2))`, and the light pass
//! lights with the power `2/α² − 2` of the decoded `α`. `--normal substrate` (Unreal Substrate's
//! word) carries linear `r` in its own byte, so it stores ggx8 (the default there) and refuses
//! the other forms.
//!
//! ```text
//! cargo run --release --all-features --example light_prepass -- --out DIR [options]
//! ```
//!
//! Arguments are parsed by hand (a dozen flags; a parser crate would be the example's only
//! extra dependency). `--help` lists them.

// Shared with tests/light_prepass.rs, which uses parts the CLI does not (the bound).
#[allow(dead_code)]
mod renderer;

use prepass::projection::DepthConvention;
use prepass::scene::{DepthStorage, LightBuffers, NormalEncoding};
use renderer::render::{Device, render};
use renderer::{Config, LightFormat, ROUGHNESS, Storage, compare, png_out, report, scene};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

const HELP: &str = "\
light_prepass: render a light pre-pass frame headless and write PNGs.

  --out DIR              output folder (default light_prepass-out)
  --size WxH             resolution (default 1280x720)
  --lights N             random point and spot lights (default 256; 3 bad-input lights are added)
  --normal NAME          xyz8 | oct16 | oct24 | oct32 | xy-fp16 | hemioct24 | xyz10 | oct20 | signed-oct | snorm8 | oct24-unity | substrate | fat (default oct24)
  --roughness NAME       how the G-buffer stores the material's specular power p: log8 (its
                         log-range code) | ggx8 (GGX perceptual roughness r = sqrt(a),
                         a = sqrt(2/(p + 2)), linear in 8 bits) | ggx8-log (r on prepass's log
                         curve) | godot8 (Godot's 7 bits, static flag); the GGX forms light with
                         the power 2/a^2 - 2 of the decoded a (default log8; with --normal
                         substrate ggx8, the only form its word holds: others are refused)
  --depth NAME           d32f | d24-rgba8 (default d32f; fat stores f32 view depth)
  --convention NAME      reversed | standard (default reversed)
  --far F                far plane, or inf (default inf: infinite projection)
  --light-buffers N      one (Engel: diffuse rgb + specular luminance) | two (diffuse, specular)
  --light-format NAME    rgba16float | rgba8unorm (default rgba16float)
  --msaa N               1, 2 or 4 where the adapter has it (default 1)
  --no-depth-bounds      light every pixel a volume covers, whatever its depth
  --repeats N            timed repetitions, the minimum is reported (default 2)
  --compare              fat reference against every diet layout: images, error images, compare.md
";

struct Args {
    out: PathBuf,
    cfg: Config,
    compare: bool,
}

fn parse() -> Result<Args, String> {
    let mut cfg = Config::default_frame();
    let mut out = PathBuf::from("light_prepass-out");
    let mut compare = false;
    let (mut normal, mut depth) = (Some(NormalEncoding::Oct24), DepthStorage::Float32);
    let mut roughness = None;
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{a} needs a value"));
        match a.as_str() {
            "--help" | "-h" => {
                print!("{HELP}");
                std::process::exit(0);
            }
            "--out" => out = PathBuf::from(value()?),
            "--size" => {
                let v = value()?;
                let (w, h) = v
                    .split_once(['x', '×'])
                    .ok_or_else(|| format!("--size {v}: expected WxH, e.g. 1280x720"))?;
                cfg.width = w
                    .parse()
                    .map_err(|_| format!("--size {v}: width is not a number"))?;
                cfg.height = h
                    .parse()
                    .map_err(|_| format!("--size {v}: height is not a number"))?;
            }
            "--lights" => {
                let v = value()?;
                cfg.lights = v
                    .parse()
                    .map_err(|_| format!("--lights {v}: not a count"))?;
            }
            "--normal" => {
                let v = value()?;
                normal = match v.as_str() {
                    "xyz8" => Some(NormalEncoding::Xyz8),
                    "xyz8-best" => Some(NormalEncoding::Xyz8Best),
                    "oct16" => Some(NormalEncoding::Oct16),
                    "oct24" => Some(NormalEncoding::Oct24),
                    "oct32" => Some(NormalEncoding::Oct32),
                    "xy-fp16" => Some(NormalEncoding::XyFp16),
                    "hemioct24" => Some(NormalEncoding::Hemioct24),
                    "xyz10" => Some(NormalEncoding::Xyz10),
                    "oct20" => Some(NormalEncoding::Oct20),
                    "signed-oct" => Some(NormalEncoding::SignedOct),
                    "snorm8" => Some(NormalEncoding::Snorm8),
                    "oct24-unity" => Some(NormalEncoding::Oct24Unity),
                    "substrate" => Some(NormalEncoding::Substrate),
                    "fat" => None,
                    _ => return Err(format!("--normal {v}: unknown encoding")),
                }
            }
            "--roughness" => {
                let v = value()?;
                roughness = Some(
                    ROUGHNESS
                        .iter()
                        .find(|(name, _)| *name == v)
                        .map(|(_, r)| *r)
                        .ok_or_else(|| {
                            format!("--roughness {v}: log8, ggx8, ggx8-log or godot8")
                        })?,
                );
            }
            "--depth" => {
                let v = value()?;
                depth = match v.as_str() {
                    "d32f" => DepthStorage::Float32,
                    "d24-rgba8" => DepthStorage::Code24Rgba8,
                    _ => return Err(format!("--depth {v}: d32f or d24-rgba8")),
                }
            }
            "--convention" => {
                let v = value()?;
                cfg.convention = match v.as_str() {
                    "reversed" => DepthConvention::Reversed,
                    "standard" => DepthConvention::Standard,
                    _ => return Err(format!("--convention {v}: reversed or standard")),
                }
            }
            "--far" => {
                let v = value()?;
                cfg.far = if v == "inf" {
                    f32::INFINITY
                } else {
                    v.parse()
                        .map_err(|_| format!("--far {v}: a number or inf"))?
                };
            }
            "--light-buffers" => {
                let v = value()?;
                cfg.lights_layout = match v.as_str() {
                    "one" | "1" => LightBuffers::One,
                    "two" | "2" => LightBuffers::Two,
                    _ => return Err(format!("--light-buffers {v}: one or two")),
                }
            }
            "--light-format" => {
                let v = value()?;
                cfg.light_format = match v.as_str() {
                    "rgba16float" => LightFormat::Rgba16Float,
                    "rgba8unorm" => LightFormat::Rgba8Unorm,
                    _ => return Err(format!("--light-format {v}: rgba16float or rgba8unorm")),
                }
            }
            "--msaa" => {
                let v = value()?;
                cfg.msaa = v
                    .parse()
                    .map_err(|_| format!("--msaa {v}: a sample count"))?;
            }
            "--repeats" => {
                let v = value()?;
                cfg.repeats = v.parse().map_err(|_| format!("--repeats {v}: a count"))?;
            }
            "--no-depth-bounds" => cfg.depth_bounds = false,
            "--compare" => compare = true,
            _ => return Err(format!("unknown argument {a} (see --help)")),
        }
    }
    cfg.roughness = renderer::resolve_roughness(normal, roughness)?;
    cfg.storage = match normal {
        None => Storage::Fat,
        Some(normal) => Storage::Diet { normal, depth },
    };
    Ok(Args { out, cfg, compare })
}

fn main() {
    if let Err(e) = run() {
        eprintln!("light_prepass: {e}");
        std::process::exit(1);
    }
}

fn summary(label: &str, cfg: &Config, o: &renderer::render::Output) -> String {
    let untimed = if cfg.repeats == 0 {
        "not timed (--repeats 0)"
    } else {
        "timestamps unsupported by this adapter"
    };
    let t = o.pass_ms.map_or(untimed.to_string(), |t| {
        format!(
            "GPU (a) {:.2} ms, (b) {:.2} ms, (c) {:.2} ms",
            t[0], t[1], t[2]
        )
    });
    format!(
        "{label}: {} at {}×{}, MSAA {}: {t}; light-pass fragments {} shaded, {} rejected by \
         depth bounds, {} sky",
        cfg.layout_name(),
        cfg.width,
        cfg.height,
        cfg.msaa,
        o.fragments[0],
        o.fragments[1],
        o.fragments[2]
    )
}

fn run() -> Result<(), String> {
    let args = parse()?;
    let started = Instant::now();
    let dev = Device::new()?;
    eprintln!("adapter: {}", dev.describe());
    let cfg = args.cfg;
    renderer::render::check(&dev, &cfg)?;
    let scene = scene::build(cfg.lights);
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    if !args.compare {
        let o = render(&dev, &cfg, &scene)?;
        let bad = compare::non_finite(&o.colour);
        let path = args.out.join("frame.png");
        png_out::write_rgb(&path, o.width, o.height, &compare::to_rgb8(&o.colour))?;
        println!("{}", summary("frame", &cfg, &o));
        println!(
            "light volumes: {:?} (sphere front, sphere back, cone front, cone back), {} left out; \
             {bad} non-finite pixels",
            o.classes, o.skipped
        );
        println!(
            "wrote {} in {:.1} s (adapter start, shader compile and {} renders included)",
            path.display(),
            started.elapsed().as_secs_f64(),
            cfg.repeats + 1
        );
        return Ok(());
    }
    if cfg.storage == Storage::Fat {
        return Err("--compare renders the fat layout itself: pick a diet --normal".into());
    }
    eprintln!(
        "compare: fat and diet layouts at {}×{}",
        cfg.width, cfg.height
    );
    let rows = report::run(&dev, &cfg, &scene)?;
    let mut extra = String::new();
    // Depth bounds: the default layout with and without the fragment-shader rejection.
    let _ = writeln!(
        extra,
        "## Depth bounds\n\n`{}`: the light pass with the fragment shader's depth-bounds \
         rejection and without it. Rejected fragments leave before decoding the normal and \
         lighting.\n\n| depth bounds | fragments shaded | rejected | sky | (b) lights ms |\n|---|---|---|---|---|",
        cfg.layout_name()
    );
    for on in [true, false] {
        let c = Config {
            depth_bounds: on,
            ..cfg
        };
        let o = render(&dev, &c, &scene)?;
        let _ = writeln!(
            extra,
            "| {} | {} | {} | {} | {} |",
            if on { "on" } else { "off" },
            o.fragments[0],
            o.fragments[1],
            o.fragments[2],
            o.pass_ms.map_or("n/a".into(), |t| format!("{:.2}", t[1]))
        );
    }
    // MSAA: per-sample lighting, measured against one sample.
    let counts = dev.sample_counts(&cfg);
    let _ = writeln!(
        extra,
        "\n## MSAA\n\nEncoded data is never averaged: the G-buffer is not resolved; the light \
         and composite passes run per sample (`@builtin(sample_index)`), each decoding its own \
         sample's codes, and only the final colour is resolved. Sample counts this adapter has \
         for every target: {counts:?}.\n"
    );
    let multi = counts.iter().copied().find(|&n| n > 1);
    match multi {
        None => extra.push_str("No multisampled count is available: nothing measured.\n"),
        Some(n) => {
            if n != 2 {
                let _ = writeln!(
                    extra,
                    "This adapter has no 2× MSAA for these formats; {n}× stands in for it.\n"
                );
            }
            let _ = writeln!(
                extra,
                "| MSAA | memory | fragments shaded (b) | (a) ms | (b) ms | (c) ms |\n|---|---|---|---|---|---|"
            );
            for s in [1, n] {
                let c = Config { msaa: s, ..cfg };
                let o = render(&dev, &c, &scene)?;
                let (b, _) = report::bytes_per_pixel(&c)?;
                let mem = b * u64::from(c.width) * u64::from(c.height) * u64::from(s);
                let t = |k: usize| o.pass_ms.map_or("n/a".into(), |t| format!("{:.2}", t[k]));
                let _ = writeln!(
                    extra,
                    "| {s}× | {:.2} MB | {} | {} | {} | {} |",
                    prepass::scene::gbuffer::megabytes(mem),
                    o.fragments[0],
                    t(0),
                    t(1),
                    t(2)
                );
                if s > 1 {
                    png_out::write_rgb(
                        &args.out.join(format!("frame_msaa{s}.png")),
                        o.width,
                        o.height,
                        &compare::to_rgb8(&o.colour),
                    )?;
                }
            }
        }
    }
    report::write(&args.out, &dev, &cfg, &scene, &rows, &extra)?;
    println!(
        "wrote {} frames, error images and compare.md to {} in {:.1} s",
        rows.len(),
        args.out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
