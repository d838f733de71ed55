//! # prepass
//!
//! GPU shader maths for deferred and light-pre-pass renderers, written twice — as WGSL that a
//! renderer ships (`wgsl/*.wgsl`, embedded in [`wgsl`]) and as Rust twins for the CPU side —
//! and proven by exhaustive and property-based tests that execute the WGSL on a real adapter and
//! measure it against exact references.
//!
//! | module | WGSL | what |
//! |---|---|---|
//! | [`depth24`] | `wgsl/depth24.wgsl` | 24-bit depth codes in RGBA8 texels, hyperbolic depth |
//! | [`linear_depth`] | `wgsl/linear_depth.wgsl` | view distance from depth, stable for any far/near |
//! | [`projection`] | — | `Projection`: near/far/convention, per-pixel constants, exact forward maps |
//! | [`position`] | `wgsl/position.wgsl` | frustum rays, view/world/camera-relative position rebuild |
//! | [`scene`] | composed | scene declaration → minimal WGSL module + G-buffer layout |
//! | [`roughness`] | `wgsl/roughness.wgsl` | specular exponent in log range, 8 bits; normal + roughness RGBA8 texel |
//! | [`roughness_ggx`] | `wgsl/roughness_ggx.wgsl` | GGX perceptual roughness in 8 bits: linear as the engines store it, Godot's 7 bits + flag, a log curve |
//! | [`lighting`] (`lpp`, `aggregate_light`, `light_volume`) | `wgsl/lpp.wgsl`, `wgsl/aggregate_light.wgsl`, `wgsl/light_volume.wgsl` | light pre-pass P/C and specular reconstruction, aggregate vertex lights, light volumes and depth bounds; each twin has its WGSL function's name |
//! | [`normal`] | `wgsl/normal_*.wgsl` | normal encodings: xyz8, xy FP16, octahedral 16/24/32, hemi-octahedral 24 |
//! | [`batch`] | — | every normal, depth24 and roughness encoder and decoder over slices, SIMD (SSE2, AVX2 at run time, NEON), bit-identical to the scalar twins; feature `rayon` splits long batches |
//! | [`precision`] | — | error metrics (ULP, relative, angular, mismatches) and test inputs |
//! | `precision::strategies`, `precision::check` | any | proptest strategies with adversarial cases; batched checks of any WGSL against a Rust reference, shrinking on the adapter (features `proptest`; `check` also `harness`) |
//! | [`wgsl`] | all | embedded sources; naga validation/translation (feature `validate`) |
//! | `harness` | any | run any WGSL function on a wgpu adapter (feature `harness`) |
//! | `conforming` | any | the worst conforming adapter emulated on yours: any module rewritten so every operation the WGSL spec leaves free lands at a chosen end of its interval (feature `validate`; run with `harness`) |
//!
//! Features: none by default (glam + half only: the WGSL, the scene composer, the uniforms and
//! the twins); `bytemuck` adds `Pod` for the uniform structs, `validate` adds naga, `harness`
//! adds wgpu, `proptest` adds strategies for downstream precision suites, `rayon` splits long
//! batches of [`batch`] across threads. Each gated item is labelled with its feature on
//! docs.rs.

#![warn(missing_docs)]
// docs.rs builds with `--cfg docsrs` on nightly: label every feature-gated item with its feature.
#![cfg_attr(docsrs, feature(doc_cfg))]

/// The glam version the twins take and return (`Vec3`, `Mat3`, …), so a renderer needs no
/// direct dependency to call them.
pub use glam;

pub mod batch;
#[cfg(feature = "validate")]
#[cfg_attr(docsrs, doc(cfg(feature = "validate")))]
pub mod conforming;
pub mod depth24;
#[cfg(feature = "harness")]
#[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
pub mod harness;
#[cfg(feature = "isa")]
#[cfg_attr(docsrs, doc(cfg(feature = "isa")))]
pub mod isa;
pub mod lighting;
pub mod linear_depth;
pub mod normal;
pub mod position;
pub mod precision;
pub mod projection;
pub mod roughness;
pub mod roughness_ggx;
pub mod scene;
#[cfg(feature = "harness")]
#[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
pub mod sweep;
pub mod wgsl;

/// The README's code examples, compiled and run as doctests so they cannot rot: the first on
/// every feature set (the lean build included), the feature-gated ones where their features are
/// on (each carries its own `cfg`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// docs/precision.md's examples (validate, run, measure and cost your own WGSL), compiled and
/// run as doctests like the README's, each on the features it names.
#[cfg(doctest)]
#[doc = include_str!("../docs/precision.md")]
pub struct PrecisionDocDoctests;
