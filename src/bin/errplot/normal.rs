//! Normal encodings (`wgsl/normal_*.wgsl`): angular round-trip error of every encoding over
//! spherical-Fibonacci directions, as an octahedral error image per encoding and one histogram,
//! and each encoder and decoder as a cost-table variant.

use crate::ctx::{Ctx, num};
use crate::peers;
use crate::plot::{Bin, Chart, ErrorImage, HistSeries, Histogram};
use crate::variant::{TimedArg, Variant, Wgsl, twin_timer};
use glam::Vec3;
use prepass::precision::metrics::{ErrorStats, angle_degrees, widen3};
use prepass::sweep::normal::{CODECS, Codec, fibonacci_directions, round_trip};
use std::fmt::Write as _;

/// Image side (cells) of the octahedral error images.
const SIDE: usize = 96;

/// Octahedral coordinates in [−1, 1]² of a direction (f64): the map every image is drawn in.
fn octahedral(d: [f32; 3]) -> (f64, f64) {
    let [x, y, z] = d.map(f64::from);
    let l1 = x.abs() + y.abs() + z.abs();
    let (u, v) = (x / l1, y / l1);
    if z >= 0.0 {
        (u, v)
    } else {
        ((1.0 - v.abs()) * u.signum(), (1.0 - u.abs()) * v.signum())
    }
}

/// Per-direction angular errors of `codec` over `dirs`: on the adapter when there is one,
/// otherwise through the Rust twins (bit-identical to the WGSL on lavapipe).
fn errors(ctx: &Ctx, codec: &Codec, dirs: &[[f32; 3]]) -> Result<(Vec<f64>, &'static str), String> {
    let decoded: Vec<[f32; 3]> = match ctx.gpu() {
        Some(g) => {
            round_trip(g, codec, dirs)
                .map_err(|e| e.to_string())?
                .decoded
        }
        None => dirs
            .iter()
            .map(|&d| (codec.twin_decode)((codec.twin_encode)(Vec3::from(d))).to_array())
            .collect(),
    };
    let place = if ctx.gpu().is_some() {
        "adapter"
    } else {
        "Rust twins"
    };
    Ok((
        dirs.iter()
            .zip(&decoded)
            .map(|(&d, &r)| angle_degrees(widen3(d), widen3(r)))
            .collect(),
        place,
    ))
}

/// The tables, images, histogram, CSV and variants.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    // Directions per codec: the default tier samples 2^18 of the full run's 2^22 (the same
    // spherical-Fibonacci construction at a coarser spacing; each codec's worst cell moves
    // little), 1/16 of its adapter time; quick runs 2^16.
    let n = ctx.opts.pick(1 << 16, 1 << 18, 1 << 22);
    let dirs = fibonacci_directions(n);
    let bar = ctx.progress(CODECS.len() as u64, "normals");
    let mut measured = Vec::new();
    for codec in &CODECS {
        bar.set_message(codec.name);
        let (e, place) = errors(ctx, codec, &dirs)?;
        measured.push((codec, e, place));
        bar.inc(1);
    }
    bar.finish_and_clear();
    let place = measured[0].2;
    ctx.line("## Normal encodings");
    ctx.line("");
    ctx.line(format!(
        "Angle between each of {n} spherical-Fibonacci directions and its decoded vector, \
         encoded and decoded by the {place}. xy FP16 and hemi-octahedral store view-space \
         normals with z ≥ 0 only: their rows count the upper hemisphere alone (the tests \
         measure what happens below it). Data: `normal_error.csv`.{}",
        if ctx.opts.full() {
            String::new()
        } else {
            format!(
                " This run: 2^{} of the full run's 2^22 directions; `--full` for all.",
                n.ilog2()
            )
        }
    ));
    ctx.line("");
    ctx.line("| encoding | bits | mean error (°) | max error (°) | RMS (°) |");
    ctx.line("|---|---|---|---|---|");
    let mut csv = String::from("encoding,bits,directions,where,mean_deg,max_deg,rms_deg\n");
    let mut hist = Vec::new();
    let mut maxima = Vec::new();
    for (codec, e, place) in &measured {
        let upper_only = codec.hemisphere;
        let mut s = ErrorStats::default();
        for (i, (&err, d)) in e.iter().zip(&dirs).enumerate() {
            if !upper_only || d[2] >= 0.0 {
                s.add(i as u64, err);
            }
        }
        ctx.line(format!(
            "| {} | {} | {} | {} | {} |",
            codec.name,
            codec.bits,
            num(s.mean()),
            num(s.max),
            num(s.rms())
        ));
        let _ = writeln!(
            csv,
            "{},{},{},{place},{},{},{}",
            codec.name,
            codec.bits,
            s.count,
            s.mean(),
            s.max,
            s.rms()
        );
        // Histogram: ten log-spaced bins a decade from 1e-5° to 10° (smaller errors counted in
        // the first).
        const BINS: usize = 60;
        let mut bins: Vec<Bin> = (0..BINS)
            .map(|k| {
                let lo = 10f64.powf(-5.0 + 6.0 * k as f64 / BINS as f64);
                let hi = 10f64.powf(-5.0 + 6.0 * (k + 1) as f64 / BINS as f64);
                (lo, hi, 0)
            })
            .collect();
        for (&err, d) in e.iter().zip(&dirs) {
            if upper_only && d[2] < 0.0 {
                continue;
            }
            let k = (((err.max(1e-5)).log10() + 5.0) / 6.0 * BINS as f64).floor() as usize;
            bins[k.min(BINS - 1)].2 += 1;
        }
        maxima.push((*codec, s.max));
        hist.push(HistSeries {
            label: format!(
                "{} ({} bits{})",
                codec.name,
                codec.bits,
                if upper_only { ", z ≥ 0" } else { "" }
            ),
            bins,
            max: s.max,
        });
    }
    ctx.line("");
    ctx.csv("normal_error.csv", &csv)?;
    ctx.chart(
        &Chart::Histogram(Histogram {
            title: format!("Normal encodings: round-trip error, every encoding ({n} directions)"),
            x_label: "angular error (degrees, log scale; red: the largest)".into(),
            series: hist,
        }),
        "normal_error_histogram",
        "normal encoding error histogram",
    )?;
    crate::pick::figure(ctx, &maxima, n)?;
    ctx.line(
        "Error over the sphere, drawn in octahedral coordinates (centre = +z, corners = −z; \
         each cell shows the largest error of the directions in it):",
    );
    ctx.line("");
    for (codec, e, _) in &measured {
        let mut values = vec![f64::NAN; SIDE * SIDE];
        for (&err, &d) in e.iter().zip(&dirs) {
            let (u, v) = octahedral(d);
            let cx = (((u + 1.0) / 2.0) * SIDE as f64)
                .floor()
                .clamp(0.0, SIDE as f64 - 1.0) as usize;
            let cy = (((v + 1.0) / 2.0) * SIDE as f64)
                .floor()
                .clamp(0.0, SIDE as f64 - 1.0) as usize;
            let cell = &mut values[cy * SIDE + cx];
            *cell = if cell.is_nan() { err } else { cell.max(err) };
        }
        ctx.chart(
            &Chart::Image(ErrorImage {
                title: format!(
                    "{} ({} bits): round-trip error over the sphere",
                    codec.name, codec.bits
                ),
                x_label: "octahedral u".into(),
                y_label: "octahedral v".into(),
                value_label: "max angular error (degrees)".into(),
                width: SIDE,
                height: SIDE,
                values,
                extent: [(-1.0, 1.0), (-1.0, 1.0)],
            }),
            &format!("normal_error_image_{}", codec.name.replace(' ', "_")),
            &format!("{} error over the sphere", codec.name),
        )?;
    }

    exhaustive32(ctx)?;

    // Cost-table variants: each encoder and each decoder, timed on spread-out inputs.
    // Quick runs (CI, notebooks) time the precise encodings only, to stay under a minute.
    let tile_dirs: Vec<[f32; 3]> = fibonacci_directions(1 << 16);
    let quick = ctx.opts.quick();
    for (codec, e, place) in measured {
        if quick && (codec.name.contains("fast") || codec.name.contains("hemi")) {
            continue;
        }
        let mut s = ErrorStats::default();
        let upper_only = codec.hemisphere;
        for (i, (&err, d)) in e.iter().zip(&dirs).enumerate() {
            if !upper_only || d[2] >= 0.0 {
                s.add(i as u64, err);
            }
        }
        let enc = codec.twin_encode;
        let dec = codec.twin_decode;
        let codes: Vec<u32> = tile_dirs.iter().map(|&d| enc(Vec3::from(d))).collect();
        let dir_words: Vec<u32> = tile_dirs.iter().flatten().map(|x| x.to_bits()).collect();
        let tile_vecs: Vec<Vec3> = tile_dirs.iter().map(|&d| Vec3::from(d)).collect();
        // Encoder and decoder share the round trip's error; each is timed on its own input.
        let variant = |family, function: &str, args, twin| Variant {
            family,
            unit: "degrees",
            name: function.into(),
            bits: codec.bits,
            error: Some(s),
            error_from: format!("{place}: {n} Fibonacci directions, round trip"),
            upper_only,
            error_upper: None,
            wgsl: Some(Wgsl {
                source: codec.source.into(),
                function: function.into(),
                args: vec![TimedArg::Column(args)],
            }),
            twin: Some(twin),
        };
        let encode = variant(
            "normal encoding: encode",
            codec.encode,
            dir_words,
            twin_timer(tile_vecs, enc),
        );
        ctx.variants.push(encode);
        if codec.name.contains("fast") {
            continue; // a `_fast` encoding shares its precise sibling's decoder
        }
        let decode = variant(
            "normal encoding: decode",
            codec.decode,
            codes.clone(),
            twin_timer(codes, dec),
        );
        ctx.variants.push(decode);
    }
    peer_variants(ctx, &dirs, &tile_dirs)
}

/// The peer codecs (`crate::peers::NORMAL_PEERS`) on the same directions, on the adapter: a
/// table, and each encoder and decoder as a cost-table variant (no Rust twin: CPU ns "—").
fn peer_variants(ctx: &mut Ctx, dirs: &[[f32; 3]], tile_dirs: &[[f32; 3]]) -> Result<(), String> {
    let n = dirs.len();
    ctx.line("### Peers on the same directions");
    ctx.line("");
    let Some(g) = ctx.gpu() else {
        ctx.line(format!(
            "The peers (`tests/baselines/peer_*.wgsl`) have no Rust twin: {}.",
            crate::ctx::NEEDS_ADAPTER
        ));
        ctx.line("");
        return Ok(());
    };
    let mut rows = Vec::new();
    for p in &peers::NORMAL_PEERS {
        let rt = peers::normal_round_trip(g, p, dirs)?;
        let timing = peers::normal_round_trip(g, p, tile_dirs)?.codes;
        rows.push((p, rt, timing));
    }
    ctx.line(format!(
        "Baselines from other projects, re-implemented in WGSL from their descriptions \
         (`tests/baselines/peer_*.wgsl`), encoded and decoded on the adapter over the same {n} \
         Fibonacci directions. Their rows in the cost table start with `{}`.",
        peers::PREFIX
    ));
    ctx.line("");
    ctx.line("| peer | bits | mean error (°) | max error (°) | max error, z ≥ 0 (°) |");
    ctx.line("|---|---|---|---|---|");
    for (p, rt, _) in &rows {
        ctx.line(format!(
            "| {} | {} | {} | {} | {} |",
            p.name,
            p.bits,
            num(rt.error.mean()),
            num(rt.error.max),
            num(rt.error_upper.max)
        ));
    }
    ctx.line("");
    let dir_words: Vec<u32> = tile_dirs.iter().flatten().map(|x| x.to_bits()).collect();
    for (p, rt, timing) in rows {
        for (family, function, args) in [
            (
                "normal encoding: encode",
                p.encode,
                vec![TimedArg::Column(dir_words.clone())],
            ),
            (
                "normal encoding: decode",
                p.decode,
                vec![TimedArg::Column(timing.clone())],
            ),
        ] {
            ctx.variants.push(Variant {
                family,
                unit: "degrees",
                name: format!("{}{}", peers::PREFIX, p.name),
                bits: p.bits,
                error: Some(rt.error),
                error_from: format!("adapter: {n} Fibonacci directions, round trip"),
                upper_only: false,
                error_upper: Some(rt.error_upper),
                wgsl: Some(Wgsl {
                    source: p.source.into(),
                    function: function.into(),
                    args,
                }),
                twin: None,
            });
        }
    }
    Ok(())
}

/// With `--exhaustive32`: every one of the 2^32 codes of the 32-bit encodings through the WGSL
/// decoder (the tests run a documented stratified 2^26 of them; this is the full sweep).
fn exhaustive32(ctx: &mut Ctx) -> Result<(), String> {
    if !ctx.opts.exhaustive32 {
        return Ok(());
    }
    let Some(g) = ctx.gpu() else {
        ctx.line(format!(
            "All 2^32 decodes (--exhaustive32): {}.",
            crate::ctx::NEEDS_ADAPTER
        ));
        return Ok(());
    };
    let mut rows = Vec::new();
    for name in ["oct32", "xy fp16"] {
        let codec = prepass::sweep::normal::codec(name);
        let t = std::time::Instant::now();
        let c = prepass::sweep::normal::decode_all_32(g, codec).map_err(|e| e.to_string())?;
        rows.push((name, c, t.elapsed().as_secs_f64()));
    }
    ctx.line("### Every 32-bit code decoded (`--exhaustive32`)");
    ctx.line("");
    ctx.line("| encoding | codes | not unit | max abs(len − 1) | max angle to the exact decode (°) | Rust twin differs | seconds |");
    ctx.line("|---|---|---|---|---|---|---|");
    for (name, c, secs) in rows {
        ctx.line(format!(
            "| {name} | {} | {} | {} | {} | {} | {secs:.0} |",
            c.codes,
            c.not_unit,
            num(c.max_len_error),
            num(c.max_angle_deg),
            c.twin.count
        ));
    }
    ctx.line("");
    Ok(())
}
