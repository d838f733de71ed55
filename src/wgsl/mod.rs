//! The shipped WGSL sources, embedded as text, and (with the `validate` feature) naga checks.
//!
//! Each file in `wgsl/` is plain WGSL, valid on its own: a renderer can paste it, `include_str!`
//! it, or take it from here.

#[cfg(feature = "validate")]
mod naga_check;
#[cfg(feature = "validate")]
mod spirv_cost;
#[cfg(feature = "validate")]
#[cfg_attr(docsrs, doc(cfg(feature = "validate")))]
pub use naga_check::{
    CALL_ALL_ENTRY, Checked, Translations, WgslError, parse_and_validate, translate_all,
};
#[cfg(feature = "validate")]
#[cfg_attr(docsrs, doc(cfg(feature = "validate")))]
pub use spirv_cost::{SpirvCost, spirv_instruction_count};

/// One shipped WGSL file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WgslFile {
    /// File name inside `wgsl/`.
    pub name: &'static str,
    /// The file's text.
    pub source: &'static str,
}

/// `wgsl/depth24.wgsl`: 24-bit depth codes in RGBA8 texels (twin: [`crate::depth24`]).
pub const DEPTH24: &str = include_str!("../../wgsl/depth24.wgsl");

/// `wgsl/linear_depth.wgsl`: view distance from depth (twin: [`crate::linear_depth`]).
pub const LINEAR_DEPTH: &str = include_str!("../../wgsl/linear_depth.wgsl");

/// `wgsl/position.wgsl`: frustum rays and position rebuild (twin: [`crate::position`]).
pub const POSITION: &str = include_str!("../../wgsl/position.wgsl");

/// `wgsl/roughness.wgsl`: specular exponent in log range (twin: [`crate::roughness`]).
pub const ROUGHNESS: &str = include_str!("../../wgsl/roughness.wgsl");

/// `wgsl/roughness_ggx.wgsl`: GGX perceptual roughness in 8 bits (twin: [`crate::roughness_ggx`]).
pub const ROUGHNESS_GGX: &str = include_str!("../../wgsl/roughness_ggx.wgsl");

/// `wgsl/lpp.wgsl`: light pre-pass P/C, Engel's reconstruction (twin:
/// [`crate::lighting::lpp`]).
pub const LPP: &str = include_str!("../../wgsl/lpp.wgsl");

/// `wgsl/aggregate_light.wgsl`: aggregate vertex lights (twin: [`crate::lighting::aggregate_light`]).
pub const AGGREGATE_LIGHT: &str = include_str!("../../wgsl/aggregate_light.wgsl");

/// `wgsl/light_volume.wgsl`: light volumes and depth bounds (twin:
/// [`crate::lighting::light_volume`]).
pub const LIGHT_VOLUME: &str = include_str!("../../wgsl/light_volume.wgsl");

/// `wgsl/normal_xyz8.wgsl`: normal as x, y, z unorm8 (twin: [`crate::normal::xyz8`]).
pub const NORMAL_XYZ8: &str = include_str!("../../wgsl/normal_xyz8.wgsl");

/// `wgsl/normal_xyz10.wgsl`: normal as x, y, z unorm10 in RGB10A2 (twin: [`crate::normal::xyz10`]).
pub const NORMAL_XYZ10: &str = include_str!("../../wgsl/normal_xyz10.wgsl");

/// `wgsl/normal_snorm8.wgsl`: normal as x, y, z snorm8 (twin: [`crate::normal::snorm8`]).
pub const NORMAL_SNORM8: &str = include_str!("../../wgsl/normal_snorm8.wgsl");

/// `wgsl/normal_xy_fp16.wgsl`: view-space normal xy as two FP16 (twin: [`crate::normal::xy_fp16`]).
pub const NORMAL_XY_FP16: &str = include_str!("../../wgsl/normal_xy_fp16.wgsl");

/// `wgsl/normal_oct.wgsl`: octahedral normals, 16/24/32 bits (twin: [`crate::normal::oct`]).
pub const NORMAL_OCT: &str = include_str!("../../wgsl/normal_oct.wgsl");

/// `wgsl/normal_hemioct.wgsl`: hemi-octahedral view-space normals, 24 bits (twin:
/// [`crate::normal::hemioct`]).
pub const NORMAL_HEMIOCT: &str = include_str!("../../wgsl/normal_hemioct.wgsl");

/// `wgsl/normal_substrate.wgsl`: Unreal 5 Substrate's top-layer word, an 11:11 centred octahedral
/// normal with roughness and flags (twin: [`crate::normal::substrate`]).
pub const NORMAL_SUBSTRATE: &str = include_str!("../../wgsl/normal_substrate.wgsl");

/// `wgsl/normal_signed_oct.wgsl`: O3DE's signed octahedron in RGB10A2, 10:10 hemi-octahedral
/// codes of `(x, y, |z|)` and z's sign (twin: [`crate::normal::signed_oct`]).
pub const NORMAL_SIGNED_OCT: &str = include_str!("../../wgsl/normal_signed_oct.wgsl");

/// Every shipped WGSL file. `tests/wgsl_validate.rs` checks this list against the directory.
pub const FILES: &[WgslFile] = &[
    WgslFile {
        name: "aggregate_light.wgsl",
        source: AGGREGATE_LIGHT,
    },
    WgslFile {
        name: "depth24.wgsl",
        source: DEPTH24,
    },
    WgslFile {
        name: "light_volume.wgsl",
        source: LIGHT_VOLUME,
    },
    WgslFile {
        name: "linear_depth.wgsl",
        source: LINEAR_DEPTH,
    },
    WgslFile {
        name: "lpp.wgsl",
        source: LPP,
    },
    WgslFile {
        name: "normal_hemioct.wgsl",
        source: NORMAL_HEMIOCT,
    },
    WgslFile {
        name: "normal_oct.wgsl",
        source: NORMAL_OCT,
    },
    WgslFile {
        name: "normal_signed_oct.wgsl",
        source: NORMAL_SIGNED_OCT,
    },
    WgslFile {
        name: "normal_snorm8.wgsl",
        source: NORMAL_SNORM8,
    },
    WgslFile {
        name: "normal_substrate.wgsl",
        source: NORMAL_SUBSTRATE,
    },
    WgslFile {
        name: "normal_xy_fp16.wgsl",
        source: NORMAL_XY_FP16,
    },
    WgslFile {
        name: "normal_xyz10.wgsl",
        source: NORMAL_XYZ10,
    },
    WgslFile {
        name: "normal_xyz8.wgsl",
        source: NORMAL_XYZ8,
    },
    WgslFile {
        name: "position.wgsl",
        source: POSITION,
    },
    WgslFile {
        name: "roughness.wgsl",
        source: ROUGHNESS,
    },
    WgslFile {
        name: "roughness_ggx.wgsl",
        source: ROUGHNESS_GGX,
    },
];
