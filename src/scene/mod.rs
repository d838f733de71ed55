//! Leave out what a scene does not need: a renderer declares its choices, and gets one WGSL
//! module holding only the functions, constants and types those choices reach (composed by
//! following naga's call graph, feature `validate`), and the G-buffer layout they imply.
//!
//! ```
//! use prepass::scene::{DepthChoice, DepthStorage, PositionChoice, Scene};
//! use prepass::projection::DepthConvention;
//! let scene = Scene {
//!     depth: DepthChoice { storage: DepthStorage::Float32, convention: DepthConvention::Reversed, infinite_far: true },
//!     position: PositionChoice::CameraRelative,
//!     ..Scene::default()
//! };
//! let roots = scene.roots().unwrap();
//! assert!(roots.contains(&"view_z_from_reversed_depth_consts"));
//! let layout = scene.gbuffer().unwrap();
//! assert_eq!(layout.bytes_per_pixel(), 4); // depth32float only
//! ```

#[cfg(feature = "validate")]
mod compose;
pub mod gbuffer;

#[cfg(feature = "validate")]
pub use compose::{ComposeError, Item, Library, naga_oil_module, wesl_module};

use crate::projection::DepthConvention;
use gbuffer::{GBufferLayout, Target, TargetFormat};

/// How depth is stored for the lighting passes to read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthStorage {
    /// A float depth buffer (`depth32float`) read as `texture_depth_2d`.
    Float32,
    /// A 24-bit code the renderer wrote itself as one `u32` (an `r32uint` target or storage).
    Code24,
    /// A 24-bit code packed into an RGBA8 colour target (`pack_depth24`), read back through a
    /// sampler (`depth24_from_rgb8`) — WebGPU cannot alias the depth buffer itself.
    Code24Rgba8,
}

/// The depth source: storage, convention and whether the far plane is at infinity.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DepthChoice {
    /// Storage.
    pub storage: DepthStorage,
    /// Standard (near → 0) or reversed (near → 1).
    pub convention: DepthConvention,
    /// Infinite far plane.
    pub infinite_far: bool,
}

impl Default for DepthChoice {
    fn default() -> Self {
        DepthChoice {
            storage: DepthStorage::Float32,
            convention: DepthConvention::Standard,
            infinite_far: false,
        }
    }
}

/// Which position rebuild the lighting passes need.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum PositionChoice {
    /// None: only view distance.
    #[default]
    None,
    /// View-space position from frustum rays.
    View,
    /// World-space position (rotated rays plus the camera position).
    World,
    /// Camera-relative position in world orientation (precise far from the origin).
    CameraRelative,
}

/// Everything a scene uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Scene {
    /// Depth source.
    pub depth: DepthChoice,
    /// Position rebuild.
    pub position: PositionChoice,
}

/// A scene declaration that cannot be built, with the choices at fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneError {
    /// The conflicting choices, e.g. `["lighting.point", "position"]`.
    pub fields: Vec<&'static str>,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "invalid scene ({}): {}",
            self.fields.join(" + "),
            self.reason
        )
    }
}

impl std::error::Error for SceneError {}

impl Scene {
    /// Check the combination of choices.
    pub fn validate(&self) -> Result<(), SceneError> {
        Ok(())
    }

    /// The public WGSL functions the scene's passes call (the composer adds what they reach).
    pub fn roots(&self) -> Result<Vec<&'static str>, SceneError> {
        self.validate()?;
        let mut r = Vec::new();
        let d = self.depth;
        match d.storage {
            DepthStorage::Float32 => {}
            DepthStorage::Code24 => {}
            DepthStorage::Code24Rgba8 => r.extend(["pack_depth24", "depth24_from_rgb8"]),
        }
        match (d.storage, d.convention) {
            (DepthStorage::Float32, DepthConvention::Standard) => {
                r.push("view_z_from_depth_consts")
            }
            (DepthStorage::Float32, DepthConvention::Reversed) => {
                r.push("view_z_from_reversed_depth_consts")
            }
            (_, DepthConvention::Standard) => r.push("view_z_from_depth24_consts"),
            // A reversed 24-bit code: its correctly rounded depth, then the reversed float path.
            (_, DepthConvention::Reversed) => r.extend([
                "hyperbolic_depth_from_depth24",
                "view_z_from_reversed_depth_consts",
            ]),
        }
        match self.position {
            PositionChoice::None => {}
            PositionChoice::View => r.extend(["fullscreen_triangle_ray_rh", "view_position"]),
            PositionChoice::World => {
                r.extend(["fullscreen_triangle_ray_rh", "world_ray", "world_position"])
            }
            PositionChoice::CameraRelative => r.extend([
                "fullscreen_triangle_ray_rh",
                "world_ray",
                "camera_relative_position",
            ]),
        }
        Ok(r)
    }

    /// The G-buffer the choices imply.
    pub fn gbuffer(&self) -> Result<GBufferLayout, SceneError> {
        self.validate()?;
        let mut targets = Vec::new();
        let convention = match self.depth.convention {
            DepthConvention::Standard => "standard",
            DepthConvention::Reversed => "reversed",
        };
        let far = if self.depth.infinite_far {
            ", infinite far"
        } else {
            ""
        };
        match self.depth.storage {
            DepthStorage::Float32 => targets.push(Target {
                name: "depth",
                format: TargetFormat::Depth32Float,
                channels: format!("float depth ({convention}{far})"),
            }),
            DepthStorage::Code24 => {
                targets.push(Target {
                    name: "depth",
                    format: TargetFormat::Depth24PlusStencil8,
                    channels: format!("hardware depth test + stencil ({convention}{far})"),
                });
                targets.push(Target {
                    name: "depth code",
                    format: TargetFormat::R32Uint,
                    channels: "r: 24-bit depth code".into(),
                });
            }
            DepthStorage::Code24Rgba8 => {
                targets.push(Target {
                    name: "depth",
                    format: TargetFormat::Depth24PlusStencil8,
                    channels: format!("hardware depth test + stencil ({convention}{far})"),
                });
                targets.push(Target {
                    name: "depth code",
                    format: TargetFormat::Rgba8Unorm,
                    channels: "r: code bits 23–16, g: 15–8, b: 7–0, a: free".into(),
                });
            }
        }
        Ok(GBufferLayout { targets })
    }

    /// Every scene declaration, valid or not (for exhaustive tests).
    pub fn all() -> Vec<Scene> {
        let mut v = Vec::new();
        for storage in [
            DepthStorage::Float32,
            DepthStorage::Code24,
            DepthStorage::Code24Rgba8,
        ] {
            for convention in [DepthConvention::Standard, DepthConvention::Reversed] {
                for infinite_far in [false, true] {
                    for position in [
                        PositionChoice::None,
                        PositionChoice::View,
                        PositionChoice::World,
                        PositionChoice::CameraRelative,
                    ] {
                        v.push(Scene {
                            depth: DepthChoice {
                                storage,
                                convention,
                                infinite_far,
                            },
                            position,
                        });
                    }
                }
            }
        }
        v
    }

    /// The composed WGSL module for this scene: only what its roots reach, validated by naga.
    #[cfg(feature = "validate")]
    pub fn wgsl(&self) -> Result<String, Box<dyn std::error::Error + Send + Sync>> {
        let roots = self.roots()?;
        Ok(Library::shipped()?.compose(roots)?)
    }
}
