//! A downstream precision suite in miniature: check your own WGSL normal packing on the adapter
//! against an exact reference with `prepass::precision::check`, over `unit_vector()` (poles,
//! octahedron folds, seams and signed zeros weighted in).
//!
//! `cargo run --release --all-features --example precision_check`

use prepass::harness::Gpu;
use prepass::precision::check::{CheckError, PrecisionCheck};
use prepass::precision::metrics::{angle_degrees, widen3};
use prepass::precision::strategies::unit_vector;

/// Pack a unit normal into 8-bit snorm lanes and back, renormalised.
const ROUNDED: &str = "fn snorm8_roundtrip(n: vec3<f32>) -> vec3<f32> {
    return normalize(unpack4x8snorm(pack4x8snorm(vec4<f32>(n, 0.0))).xyz);
}";

/// The same with a classic bug: truncating to integers instead of rounding.
const TRUNCATED: &str = "fn snorm8_roundtrip(n: vec3<f32>) -> vec3<f32> {
    return normalize(vec3<f32>(vec3<i32>(n * 127.0)) / 127.0);
}";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let gpu = Gpu::new()?;
    println!("adapter: {}", gpu.describe());
    let exact = |n: &glam::Vec3| n.as_dvec3().to_array();
    let degrees = |got: &[f32; 3], want: &[f64; 3]| angle_degrees(widen3(*got), *want);
    // Bound: pack4x8snorm rounds each lane to the nearest k/127 (exact in WGSL), so the error
    // vector e has |e| ≤ √3 · 0.5/127 = 0.006819, and the angle between n and n + e is at most
    // asin(|e|) = 0.3907° for |n| = 1; normalize adds a few f32 ULPs (≈ 1e-5°).
    let bound = (3f64.sqrt() * 0.5 / 127.0).asin().to_degrees() + 1e-3;

    for (name, src) in [("rounded", ROUNDED), ("truncated", TRUNCATED)] {
        let check = PrecisionCheck::new(&gpu, src, "snorm8_roundtrip")?;
        match check.run(&unit_vector(), exact, degrees, bound) {
            Ok(p) => println!(
                "{name}: passed {} cases, max {:.4}°, mean {:.4}° (bound {bound:.4}°), worst {:?}",
                p.cases,
                p.stats.max,
                p.stats.mean(),
                p.worst
            ),
            Err(CheckError::Failed(f)) => println!("{name}: {f}"),
            Err(e) => return Err(e.into()),
        }
    }
    Ok(())
}
