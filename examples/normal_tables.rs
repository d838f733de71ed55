//! Prints the README's normal-encoding tables (Markdown), measured on the adapter:
//!
//! ```text
//! cargo run --release --all-features --example normal_tables
//! ```
//! Every row encodes and decodes 2^24 spherical-Fibonacci directions (and the adversarial set)
//! with the shipped WGSL, beside the f64 reproduction of the same algorithm on the same set.

use prepass::harness::Gpu;
use prepass::sweep::normal::{
    CODECS, adversarial_directions, fibonacci_directions, killzone_myth, precise_optimality,
    reference_error, round_trip,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let gpu = Gpu::new()?;
    println!("Adapter: {}\n", gpu.describe());
    let fib = fibonacci_directions(1 << 24);
    let adv = adversarial_directions();
    println!(
        "| encoding | bits | mean° (2^24 Fibonacci) | max° | f64 reproduction mean° / max° | issue target mean° / max° | adversarial max° ({} dirs) | Rust twin ≠ WGSL (codes) |",
        adv.len()
    );
    println!("|---|---|---|---|---|---|---|---|");
    let mut opt_rows = Vec::new();
    let upper_only =
        |v: &[[f32; 3]]| -> Vec<[f32; 3]> { v.iter().copied().filter(|v| v[2] >= 0.0).collect() };
    let (fib_up, adv_up) = (upper_only(&fib), upper_only(&adv));
    for c in &CODECS {
        // Hemisphere codes are measured on the z >= 0 inputs only; xy fp16 on all, reported
        // for z >= 0 here (its z < 0 error is the mirror image, tabulated below).
        let hemi = c.name.starts_with("hemioct");
        let upper = hemi || c.name == "xy fp16";
        let (fset, aset) = if hemi {
            (&fib_up, &adv_up)
        } else {
            (&fib, &adv)
        };
        let rt = round_trip(&gpu, c, fset)?;
        let ra = round_trip(&gpu, c, aset)?;
        let stats = if upper { rt.error_upper } else { rt.error };
        let rstats = reference_error(c, if upper { &fib_up } else { &fib });
        let target = c
            .target
            .map_or("—".to_string(), |(m, x)| format!("{m} / {x}"));
        let amax = if upper {
            ra.error_upper.max
        } else {
            ra.error.max
        };
        println!(
            "| {}{} | {} | {:.6} | {:.6} | {:.6} / {:.6} | {target} | {:.6} | {} |",
            c.name,
            if upper { " (z ≥ 0 only)" } else { "" },
            c.bits,
            stats.mean(),
            stats.max,
            rstats.mean(),
            rstats.max,
            amax,
            rt.twin_encode.count + ra.twin_encode.count
        );
        if c.name.contains("oct") && !c.name.ends_with("fast") {
            let o = precise_optimality(c, fset, &rt);
            let oa = precise_optimality(c, aset, &ra);
            opt_rows.push((c.name, o, oa));
        }
    }
    println!(
        "\n| precise encoder | not the f64-best neighbour (Fibonacci / adversarial) | worst excess over the best neighbour° |"
    );
    println!("|---|---|---|");
    for (name, o, oa) in opt_rows {
        println!(
            "| {name} | {} / {} | {:.2e} |",
            o.not_best,
            oa.not_best,
            o.worst_excess_deg.max(oa.worst_excess_deg)
        );
    }
    println!(
        "\n| fov | pixels with a visible z < 0 normal | visible normals with z < 0 (measured / analytic) | mean error of those° | worst error° (measured / analytic 2θ_corner) |"
    );
    println!("|---|---|---|---|---|");
    for fov in [60.0, 90.0] {
        let m = killzone_myth(&gpu, fov, 64, 4096)?;
        println!(
            "| {fov}° | {} of {} | {:.2}% / {:.2}% | {:.1} | {:.1} / {:.1} |",
            m.pixels_with_negative_z,
            m.pixels,
            100.0 * m.visible_fraction_negative_z,
            100.0 * m.visible_fraction_analytic,
            m.mean_error_negative_deg,
            m.worst_error_deg,
            m.worst_error_analytic_deg
        );
    }
    Ok(())
}
