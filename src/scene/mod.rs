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

/// A normal encoding of the G-buffer (see [`crate::normal`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NormalEncoding {
    /// x, y, z as unorm8 (Resistance 2), alpha free for the roughness.
    Xyz8,
    /// View-space x, y as two FP16 in RGBA8, z rebuilt (Killzone 2).
    XyFp16,
    /// Octahedral, 2×8 bits.
    Oct16,
    /// Octahedral, 2×12 bits, alpha free.
    Oct24,
    /// Octahedral, 2×16 bits.
    Oct32,
    /// Hemi-octahedral (view-space, z ≥ 0), 2×12 bits, alpha free.
    Hemioct24,
}

impl NormalEncoding {
    /// Every encoding.
    pub const ALL: [NormalEncoding; 6] = [
        Self::Xyz8,
        Self::XyFp16,
        Self::Oct16,
        Self::Oct24,
        Self::Oct32,
        Self::Hemioct24,
    ];

    /// Whether a cheaper rounding encoder (`_fast`) exists beside the precise one.
    pub fn has_fast_encoder(self) -> bool {
        !matches!(self, Self::Xyz8 | Self::XyFp16)
    }
}

/// The G-buffer's normal: an encoding (or none) and whether to use its `_fast` encoder.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct NormalChoice {
    /// The encoding, or `None` for a depth-only pass.
    pub encoding: Option<NormalEncoding>,
    /// Use the plain rounding encoder instead of the precise (best-of-4-neighbours) one.
    pub fast_encoder: bool,
}

/// The specular exponent (roughness) in the G-buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum RoughnessChoice {
    /// None stored.
    #[default]
    None,
    /// 8-bit log-range code (Killzone 2), in the normal target's alpha when it has one free.
    Log8,
}

/// Which dynamic lights the light pre-pass accumulates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Lights {
    /// No dynamic lights.
    #[default]
    None,
    /// Point lights.
    Point,
    /// Spot lights.
    Spot,
    /// Both.
    PointAndSpot,
}

/// The specular term of each light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Specular {
    /// Diffuse only.
    #[default]
    None,
    /// Blinn-Phong (N·H)^n.
    BlinnPhong,
    /// Phong (R·V)^n.
    Phong,
}

/// Light-buffer layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum LightBuffers {
    /// One buffer: diffuse rgb + specular luminance in alpha; specular colour reconstructed
    /// (Engel's light pre-pass).
    #[default]
    One,
    /// Two buffers: diffuse rgb and specular rgb.
    Two,
}

/// The lighting pieces a scene uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct LightingChoice {
    /// Dynamic lights.
    pub lights: Lights,
    /// Their specular term.
    pub specular: Specular,
    /// Light-buffer layout.
    pub buffers: LightBuffers,
    /// God of War III aggregate vertex lights (forward, per vertex).
    pub aggregate_vertex_lights: bool,
    /// Stencil light volumes and depth bounds for the dynamic lights.
    pub light_volumes: bool,
}

/// Everything a scene uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Scene {
    /// Depth source.
    pub depth: DepthChoice,
    /// Position rebuild.
    pub position: PositionChoice,
    /// Normal encoding.
    pub normal: NormalChoice,
    /// Roughness storage.
    pub roughness: RoughnessChoice,
    /// Lighting pieces.
    pub lighting: LightingChoice,
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

/// The normal functions a G-buffer pass (encode, through the render-target form) and a
/// lighting pass (decode) call.
fn normal_roots(e: NormalEncoding, fast: bool) -> [&'static str; 4] {
    // Names are spelled out so a search for a WGSL function finds its scene choice.
    let (enc, enc_fast, dec, enc_unorm, dec_unorm) = match e {
        NormalEncoding::Xyz8 => (
            "encode_normal_xyz8",
            "encode_normal_xyz8",
            "decode_normal_xyz8",
            "encode_normal_xyz8_unorm",
            "decode_normal_xyz8_unorm",
        ),
        NormalEncoding::XyFp16 => (
            "encode_normal_xy_fp16",
            "encode_normal_xy_fp16",
            "decode_normal_xy_fp16",
            "encode_normal_xy_fp16_unorm",
            "decode_normal_xy_fp16_unorm",
        ),
        NormalEncoding::Oct16 => (
            "encode_normal_oct16",
            "encode_normal_oct16_fast",
            "decode_normal_oct16",
            "encode_normal_oct16_unorm",
            "decode_normal_oct16_unorm",
        ),
        NormalEncoding::Oct24 => (
            "encode_normal_oct24",
            "encode_normal_oct24_fast",
            "decode_normal_oct24",
            "encode_normal_oct24_unorm",
            "decode_normal_oct24_unorm",
        ),
        NormalEncoding::Oct32 => (
            "encode_normal_oct32",
            "encode_normal_oct32_fast",
            "decode_normal_oct32",
            "encode_normal_oct32_unorm",
            "decode_normal_oct32_unorm",
        ),
        NormalEncoding::Hemioct24 => (
            "encode_normal_hemioct24",
            "encode_normal_hemioct24_fast",
            "decode_normal_hemioct24",
            "encode_normal_hemioct24_unorm",
            "decode_normal_hemioct24_unorm",
        ),
    };
    [if fast { enc_fast } else { enc }, dec, enc_unorm, dec_unorm]
}

impl Scene {
    /// Check the combination of choices; the error names the conflicting fields.
    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |fields: &[&'static str], reason: &str| {
            Err(SceneError {
                fields: fields.to_vec(),
                reason: reason.to_string(),
            })
        };
        let l = self.lighting;
        let lit = l.lights != Lights::None;
        if self.normal.fast_encoder && !self.normal.encoding.is_some_and(|e| e.has_fast_encoder()) {
            return bad(
                &["normal.fast_encoder", "normal.encoding"],
                "only the octahedral encodings have a `_fast` encoder",
            );
        }
        if lit && self.normal.encoding.is_none() {
            return bad(
                &["lighting.lights", "normal"],
                "lights need a normal per pixel",
            );
        }
        if lit && self.position == PositionChoice::None {
            return bad(
                &["lighting.lights", "position"],
                "lights need each pixel's position (the light vector)",
            );
        }
        if l.specular != Specular::None && !lit {
            return bad(
                &["lighting.specular", "lighting.lights"],
                "specular without lights",
            );
        }
        if l.specular != Specular::None && self.roughness == RoughnessChoice::None {
            return bad(
                &["lighting.specular", "roughness"],
                "the specular exponent is read from the G-buffer: store a roughness",
            );
        }
        if l.buffers == LightBuffers::Two && l.specular == Specular::None {
            return bad(
                &["lighting.buffers", "lighting.specular"],
                "a second (specular) light buffer with no specular term",
            );
        }
        if l.light_volumes && !lit {
            return bad(
                &["lighting.light_volumes", "lighting.lights"],
                "light volumes without lights",
            );
        }
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
        if let Some(e) = self.normal.encoding {
            r.extend(normal_roots(e, self.normal.fast_encoder));
        }
        if self.roughness == RoughnessChoice::Log8 {
            r.extend(["encode_log_roughness", "decode_log_roughness"]);
            if self.normal.encoding == Some(NormalEncoding::Xyz8) {
                r.extend([
                    "pack_normal_xyz8_log_roughness",
                    "normal_xyz8_from_log_roughness_texel",
                    "log_roughness_code_from_texel",
                ]);
            }
        }
        let l = self.lighting;
        let (point, spot) = match l.lights {
            Lights::None => (false, false),
            Lights::Point => (true, false),
            Lights::Spot => (false, true),
            Lights::PointAndSpot => (true, true),
        };
        if point {
            r.extend(["lpp_point_light", "lpp_point_attenuation"]);
        }
        if spot {
            r.extend(["lpp_spot_light", "lpp_spot_attenuation"]);
        }
        match l.specular {
            Specular::None => {}
            Specular::BlinnPhong => r.push("lpp_blinn_phong_light"),
            Specular::Phong => r.push("lpp_phong_light"),
        }
        if point || spot {
            match (l.buffers, l.specular) {
                (LightBuffers::One, Specular::None) => r.push("lpp_combine"),
                (LightBuffers::One, _) => r.extend(["lpp_combine", "lpp_reconstruct_specular"]),
                (LightBuffers::Two, _) => {
                    r.extend(["lpp_combine_two_buffers", "lpp_blinn_phong_specular_rgb"])
                }
            }
        }
        if l.aggregate_vertex_lights {
            r.extend([
                "aggregate_light_accumulate",
                "aggregate_light_accumulate_colour",
                "aggregate_light_position",
                "aggregate_light_diffuse",
            ]);
        }
        if l.light_volumes {
            if point {
                r.push("light_volume_sphere_needs_depth_fail");
            }
            if spot {
                r.push("light_volume_cone_needs_depth_fail");
            }
            r.push(match self.depth.storage {
                DepthStorage::Float32 => "light_volume_sphere_depth_bounds",
                _ => "light_volume_sphere_depth_bounds24",
            });
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
        let rough = self.roughness == RoughnessChoice::Log8;
        let alpha_free = matches!(
            self.normal.encoding,
            Some(NormalEncoding::Xyz8 | NormalEncoding::Oct24 | NormalEncoding::Hemioct24)
        );
        if let Some(e) = self.normal.encoding {
            let a = if rough && alpha_free {
                "a: log roughness"
            } else if alpha_free {
                "a: free (material)"
            } else {
                ""
            };
            let (format, channels) = match e {
                NormalEncoding::Xyz8 => {
                    (TargetFormat::Rgba8Unorm, format!("rgb: normal xyz8, {a}"))
                }
                NormalEncoding::XyFp16 => (
                    TargetFormat::Rgba8Unorm,
                    "rg: view-space x as f16, ba: y as f16".to_string(),
                ),
                NormalEncoding::Oct16 => (
                    TargetFormat::Rg8Unorm,
                    "rg: octahedral u, v (8 bits each)".into(),
                ),
                NormalEncoding::Oct24 => (
                    TargetFormat::Rgba8Unorm,
                    format!("rgb: octahedral u, v (12 bits each), {a}"),
                ),
                NormalEncoding::Oct32 => (
                    TargetFormat::Rgba8Unorm,
                    "rg: octahedral u, ba: v (16 bits each)".into(),
                ),
                NormalEncoding::Hemioct24 => (
                    TargetFormat::Rgba8Unorm,
                    format!("rgb: hemi-octahedral u, v (12 bits each), {a}"),
                ),
            };
            targets.push(Target {
                name: "normal",
                format,
                channels,
            });
        }
        if rough && !alpha_free {
            targets.push(Target {
                name: "roughness",
                format: TargetFormat::R8Unorm,
                channels: "r: log roughness code".into(),
            });
        }
        if self.lighting.lights != Lights::None {
            match self.lighting.buffers {
                LightBuffers::One => targets.push(Target {
                    name: "light buffer",
                    format: TargetFormat::Rgba16Float,
                    channels: "rgb: Σ diffuse, a: Σ specular luminance".into(),
                }),
                LightBuffers::Two => {
                    targets.push(Target {
                        name: "diffuse light",
                        format: TargetFormat::Rgba16Float,
                        channels: "rgb: Σ diffuse".into(),
                    });
                    targets.push(Target {
                        name: "specular light",
                        format: TargetFormat::Rgba16Float,
                        channels: "rgb: Σ specular".into(),
                    });
                }
            }
        }
        Ok(GBufferLayout { targets })
    }

    /// Every scene declaration, valid or not (for exhaustive tests): 119,808 of them.
    pub fn all() -> Vec<Scene> {
        let mut depths = Vec::new();
        for storage in [
            DepthStorage::Float32,
            DepthStorage::Code24,
            DepthStorage::Code24Rgba8,
        ] {
            for convention in [DepthConvention::Standard, DepthConvention::Reversed] {
                for infinite_far in [false, true] {
                    depths.push(DepthChoice {
                        storage,
                        convention,
                        infinite_far,
                    });
                }
            }
        }
        let positions = [
            PositionChoice::None,
            PositionChoice::View,
            PositionChoice::World,
            PositionChoice::CameraRelative,
        ];
        let mut normals = vec![NormalChoice::default()];
        for e in NormalEncoding::ALL {
            for fast_encoder in [false, true] {
                normals.push(NormalChoice {
                    encoding: Some(e),
                    fast_encoder,
                });
            }
        }
        let mut lightings = Vec::new();
        for lights in [
            Lights::None,
            Lights::Point,
            Lights::Spot,
            Lights::PointAndSpot,
        ] {
            for specular in [Specular::None, Specular::BlinnPhong, Specular::Phong] {
                for buffers in [LightBuffers::One, LightBuffers::Two] {
                    for aggregate_vertex_lights in [false, true] {
                        for light_volumes in [false, true] {
                            lightings.push(LightingChoice {
                                lights,
                                specular,
                                buffers,
                                aggregate_vertex_lights,
                                light_volumes,
                            });
                        }
                    }
                }
            }
        }
        let mut v = Vec::new();
        for &depth in &depths {
            for &position in &positions {
                for &normal in &normals {
                    for roughness in [RoughnessChoice::None, RoughnessChoice::Log8] {
                        for &lighting in &lightings {
                            v.push(Scene {
                                depth,
                                position,
                                normal,
                                roughness,
                                lighting,
                            });
                        }
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
