//! Lighting maths of the light pre-pass renderers, one concern per file:
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! | module | WGSL | what |
//! |---|---|---|
//! | [`lpp`] | `wgsl/lpp.wgsl` | P per light (point, spot; Blinn-Phong, Phong), light-buffer layouts, C, Engel's specular reconstruction |
//! | [`aggregate_light`] | `wgsl/aggregate_light.wgsl` | God of War III aggregate vertex lights |
//! | [`light_volume`] | `wgsl/light_volume.wgsl` | depth-pass/depth-fail choice for sphere and cone volumes, depth bounds |
//!
//! Each module shares its stem with its WGSL file, its tests (`tests/<stem>.rs`) and its bad-input
//! rows (`tests/bad_input/<stem>.rs`), and each Rust twin has the name of the WGSL function it
//! twins (`lpp::lpp_luminance` is WGSL `lpp_luminance`), so one name finds all of them.

pub mod aggregate_light;
pub mod light_volume;
pub mod lpp;
