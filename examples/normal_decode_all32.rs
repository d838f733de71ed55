//! Decodes all 2^32 codes of a 32-bit normal encoding with its shipped WGSL decoder on the
//! adapter (streamed), checking each result is a finite unit vector in the code's exact
//! direction and bit-identical to the Rust twin — the full sweep the test suite samples:
//!
//! ```text
//! cargo run --release --all-features --example normal_decode_all32 -- [oct32|"xy fp16"]
//! ```

use prepass::harness::Gpu;
use prepass::sweep::normal::{UNIT_TOLERANCE, codec, decode_all_32};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let name = std::env::args().nth(1).unwrap_or_else(|| "oct32".into());
    let gpu = Gpu::new()?;
    let c = codec(&name);
    let t = Instant::now();
    let d = decode_all_32(&gpu, c)?;
    println!(
        "{name} on {}: {} codes in {:.0} s; not unit (|len-1| > {UNIT_TOLERANCE:.2e}) {}; max |len-1| {:.3e}; max angle to exact {:.3e}°; Rust twin differs {}",
        gpu.describe(),
        d.codes,
        t.elapsed().as_secs_f64(),
        d.not_unit,
        d.max_len_error,
        d.max_angle_deg,
        d.twin.count
    );
    Ok(())
}
