//! Shared by the integration tests: one adapter for the whole test binary.

#[cfg(not(feature = "harness"))]
compile_error!(
    "prepass's tests execute WGSL on a wgpu adapter: run them with \
     `cargo test --release --all-features` (the README's test command)"
);

use prepass::harness::Gpu;
use std::sync::OnceLock;

/// The adapter every test runs on. With none, every test that needs it FAILS with the
/// harness's message, which names the fix (install lavapipe) — nothing is skipped.
#[allow(dead_code)]
pub fn gpu() -> &'static Gpu {
    static GPU: OnceLock<Result<Gpu, String>> = OnceLock::new();
    match GPU.get_or_init(|| {
        Gpu::new()
            .inspect(|g| eprintln!("prepass tests run on: {}", g.describe()))
            .map_err(|e| e.to_string())
    }) {
        Ok(g) => g,
        Err(e) => panic!("{e}"),
    }
}

/// Each `bad` input must encode, with `codec`'s WGSL encoder on the adapter, to the same code as
/// its documented equivalent in `good` (same index), and the Rust twin must give that code too.
/// Returns the adapter's codes for further checks.
#[allow(dead_code)]
pub fn assert_encodes_like(codec: &str, bad: &[[f32; 3]], good: &[[f32; 3]]) -> Vec<u32> {
    use prepass::harness::Arg;
    let c = prepass::sweep::normal::codec(codec);
    let k = gpu().kernel(c.source, c.encode).unwrap();
    let got = k
        .run(&[Arg::column(bad)], bad.len() as u64)
        .unwrap()
        .into_words();
    let want = k
        .run(&[Arg::column(good)], good.len() as u64)
        .unwrap()
        .into_words();
    for i in 0..bad.len() {
        assert_eq!(
            got[i], want[i],
            "{codec}: {:?} should encode like {:?}",
            bad[i], good[i]
        );
        assert_eq!(
            got[i],
            (c.twin_encode)(glam::Vec3::from(bad[i])),
            "{codec}: twin differs on {:?}",
            bad[i]
        );
    }
    got
}
