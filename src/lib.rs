//! # prepass
//!
//! GPU shader maths for deferred and light-pre-pass renderers, written twice — as WGSL that a
//! renderer ships (`wgsl/*.wgsl`, embedded in [`wgsl`]) and as Rust twins for the CPU side —
//! and proven by exhaustive and property-based tests that execute the WGSL on a real adapter and
//! measure it against exact references.
//!
//! | module | WGSL | what |
//! |---|---|---|
//! | [`depth`] | `wgsl/depth.wgsl` | 24-bit depth codes in RGBA8 texels, hyperbolic depth |
//! | [`normal`] | `wgsl/normal_*.wgsl` | normal encodings: xyz8, xy FP16, octahedral 16/24/32, hemi-octahedral 24 |
//! | [`precision`] | — | error metrics (ULP, relative, angular, mismatches) and test inputs |
//! | [`wgsl`] | all | embedded sources; naga validation/translation (feature `validate`) |
//! | `harness` | any | run any WGSL function on a wgpu adapter (feature `harness`) |
//!
//! Features: none by default (glam + half only); `validate` adds naga, `harness` adds wgpu,
//! `proptest` adds strategies for downstream precision suites.

#![warn(missing_docs)]

pub mod depth;
#[cfg(feature = "harness")]
pub mod harness;
pub mod normal;
pub mod precision;
#[cfg(feature = "harness")]
pub mod sweep;
pub mod wgsl;

/// The README's code examples, compiled and run as doctests so they cannot rot.
#[cfg(all(doctest, feature = "harness"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
