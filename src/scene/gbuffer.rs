//! The render targets a scene's choices imply ([`Scene::gbuffer`]), their bytes per pixel,
//! and their memory at a resolution and MSAA count. Plain data: no wgpu needed (feature
//! `harness` adds `TargetFormat::to_wgpu`).

use super::{
    DepthStorage, LightBuffers, Lights, NormalEncoding, RoughnessChoice, Scene, SceneError,
};
use crate::projection::DepthConvention;

/// A render-target or depth format, with the WebGPU format it corresponds to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TargetFormat {
    /// `rgba8unorm`: 4 × 8-bit unorm.
    Rgba8Unorm,
    /// `rgba8uint`: 4 bytes read back as integers (no conversion error).
    Rgba8Uint,
    /// `rg8unorm`: 2 × 8-bit unorm.
    Rg8Unorm,
    /// `rgb10a2unorm`: 3 × 10-bit unorm and a 2-bit alpha.
    Rgb10a2Unorm,
    /// `rgba8snorm`: 4 × 8-bit snorm. Not a render attachment in core WebGPU (the WebGPU
    /// spec's texture format capabilities: it needs the `texture-formats-tier1` feature, which
    /// Dawn and browsers offer per adapter); wgpu's native backends render to it.
    Rgba8Snorm,
    /// `r8unorm`: one byte.
    R8Unorm,
    /// `r32uint`: one 32-bit word.
    R32Uint,
    /// `rgba16float`: 4 × f16.
    Rgba16Float,
    /// `depth32float`.
    Depth32Float,
    /// `depth24plus-stencil8` (D24S8 on the consoles of the Resistance 2 and Killzone 2 slides).
    Depth24PlusStencil8,
}

impl TargetFormat {
    /// Bytes per sample.
    pub fn bytes(self) -> u64 {
        match self {
            Self::R8Unorm => 1,
            Self::Rg8Unorm => 2,
            Self::Rgba8Unorm
            | Self::Rgba8Uint
            | Self::Rgb10a2Unorm
            | Self::Rgba8Snorm
            | Self::R32Uint
            | Self::Depth32Float
            | Self::Depth24PlusStencil8 => 4,
            Self::Rgba16Float => 8,
        }
    }

    /// The WebGPU/wgpu format.
    #[cfg(feature = "harness")]
    #[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
    pub fn to_wgpu(self) -> wgpu::TextureFormat {
        use wgpu::TextureFormat as T;
        match self {
            Self::Rgba8Unorm => T::Rgba8Unorm,
            Self::Rgba8Uint => T::Rgba8Uint,
            Self::Rg8Unorm => T::Rg8Unorm,
            Self::Rgb10a2Unorm => T::Rgb10a2Unorm,
            Self::Rgba8Snorm => T::Rgba8Snorm,
            Self::R8Unorm => T::R8Unorm,
            Self::R32Uint => T::R32Uint,
            Self::Rgba16Float => T::Rgba16Float,
            Self::Depth32Float => T::Depth32Float,
            Self::Depth24PlusStencil8 => T::Depth24PlusStencil8,
        }
    }
}

/// One render target and what its channels hold.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Target {
    /// Its role, e.g. `"normal"`, `"depth"`.
    pub name: &'static str,
    /// Its format.
    pub format: TargetFormat,
    /// Channel by channel (or byte by byte) contents, e.g. `"rgb: normal xyz8, a: log roughness"`.
    pub channels: String,
}

/// A G-buffer: its targets in order.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct GBufferLayout {
    /// The targets.
    pub targets: Vec<Target>,
}

impl GBufferLayout {
    /// Bytes per pixel per sample, all targets together.
    pub fn bytes_per_pixel(&self) -> u64 {
        self.targets.iter().map(|t| t.format.bytes()).sum()
    }

    /// Memory at `width × height` with `samples` MSAA samples (every target multisampled).
    pub fn memory_bytes(&self, width: u64, height: u64, samples: u64) -> u64 {
        self.bytes_per_pixel() * width * height * samples
    }
}

/// Bytes as decimal megabytes (10^6), the unit the Resistance 2 and Killzone 2 slides' figures
/// turn out to use.
pub fn megabytes(bytes: u64) -> f64 {
    bytes as f64 / 1e6
}

/// Bytes as binary mebibytes (2^20).
pub fn mebibytes(bytes: u64) -> f64 {
    bytes as f64 / 1_048_576.0
}

impl Scene {
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
            DepthStorage::Code24 | DepthStorage::Code24Rgba8 => {
                targets.push(Target {
                    name: "depth",
                    format: TargetFormat::Depth24PlusStencil8,
                    channels: format!("hardware depth test + stencil ({convention}{far})"),
                });
                let (format, channels) = if self.depth.storage == DepthStorage::Code24 {
                    (TargetFormat::R32Uint, "r: 24-bit depth code")
                } else {
                    (
                        TargetFormat::Rgba8Unorm,
                        "r: code bits 23–16, g: 15–8, b: 7–0, a: free",
                    )
                };
                targets.push(Target {
                    name: "depth code",
                    format,
                    channels: channels.into(),
                });
            }
        }
        let rough = self.roughness != RoughnessChoice::None;
        let rough_name = match self.roughness {
            RoughnessChoice::Ggx8 => "GGX perceptual roughness",
            RoughnessChoice::Ggx8Log => "GGX perceptual roughness (log curve)",
            RoughnessChoice::Godot8 => "GGX perceptual roughness (7 bits) and dynamic flag",
            _ => "log roughness",
        };
        let substrate = self.normal.encoding == Some(NormalEncoding::Substrate);
        let alpha_free = matches!(
            self.normal.encoding,
            Some(
                NormalEncoding::Xyz8
                    | NormalEncoding::Xyz8Best
                    | NormalEncoding::Oct24
                    | NormalEncoding::Hemioct24
                    | NormalEncoding::Oct24Unity
            )
        );
        if let Some(e) = self.normal.encoding {
            let a = if rough && alpha_free {
                format!("a: {rough_name}")
            } else if alpha_free {
                "a: free (material)".into()
            } else {
                String::new()
            };
            let (format, channels) = match e {
                NormalEncoding::Xyz8 => {
                    (TargetFormat::Rgba8Unorm, format!("rgb: normal xyz8, {a}"))
                }
                NormalEncoding::Xyz8Best => (
                    TargetFormat::Rgba8Unorm,
                    format!("rgb: normal xyz8 (best fit), {a}"),
                ),
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
                NormalEncoding::Oct20 => (
                    TargetFormat::Rgb10a2Unorm,
                    "rg: octahedral u, v (10 bits each), b: 10 bits free, a: 2 bits free".into(),
                ),
                NormalEncoding::SignedOct => (
                    TargetFormat::Rgb10a2Unorm,
                    "rg: signed-octahedral u, v (10 bits each), b: z's sign (0 or 1), a: 2 bits free"
                        .into(),
                ),
                NormalEncoding::Xyz10 => (
                    TargetFormat::Rgb10a2Unorm,
                    "rgb: normal xyz10 (10 bits each), a: 2 bits free".into(),
                ),
                NormalEncoding::Oct24Unity => (
                    TargetFormat::Rgba8Unorm,
                    format!(
                        "rg: low 8 bits of octahedral u, v; b: their high 4 bits (Unity's order), {a}"
                    ),
                ),
                NormalEncoding::Substrate => (
                    TargetFormat::R32Uint,
                    format!(
                        "r: Substrate word — bits 10–31 octahedral 11:11, 2–9 {}, 0–1 flags (0)",
                        if rough {
                            "GGX perceptual roughness"
                        } else {
                            "roughness (0)"
                        }
                    ),
                ),
                NormalEncoding::Snorm8 => (
                    TargetFormat::Rgba8Snorm,
                    "rgb: normal snorm8, a: free (snorm material)".into(),
                ),
            };
            targets.push(Target {
                name: "normal",
                format,
                channels,
            });
        }
        if rough && !alpha_free && !substrate {
            targets.push(Target {
                name: "roughness",
                format: TargetFormat::R8Unorm,
                channels: format!("r: {rough_name} code"),
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
}
