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
