//! A headless light pre-pass renderer on top of prepass: real render targets, the crate's
//! composed WGSL (`Scene::wgsl()`) plus this example's entry points, three passes
//! (G-buffer, light volumes, composite), timestamp queries, PNG output. Shared by the example
//! (`examples/light_prepass/main.rs`) and its test (`tests/light_prepass.rs`).
//!
//! **MSAA.** Encoded normals, roughness codes and depth codes are never averaged: nothing in
//! the G-buffer is resolved. The light pass and the composite pass run per sample
//! (`@builtin(sample_index)` forces sample-rate shading): each sample's own code is decoded
//! and lit, the light buffers stay multisampled, and only the final colour is resolved — an
//! average of colours, which is what a resolve is for. Why: it is the one strategy that is exact
//! at every edge; sample 0 plus an edge mask saves the second sample's lighting off edges, but
//! needs an edge-detection pass and still lights edges per sample. Cost: the light and
//! composite passes shade every covered sample (twice the fragments at 2×), measured by
//! `--compare` (the MSAA section of `compare.md`). lavapipe offers 1× and 4× only: `--msaa 2`
//! there is refused with the counts it has, and `--compare` measures 4× in its place.
//!
//! **Roughness.** The materials hold a Blinn-Phong specular power `p`. `Config::roughness`
//! picks how pass (a) stores it: `Log8`, the power's log-range code (`encode_log_roughness`);
//! or GGX perceptual roughness as engines store it, `r = √α` with `α = √(2/(p + 2))` (the exact
//! inverse of the exponent `2/α² − 2`), by the library's byte encoders (`Ggx8` linear, `Ggx8Log`
//! on the log curve, `Godot8` with the dynamic-object flag 0: the scene is static). The light
//! pass decodes `α` and lights with the power `2/α² − 2` (capped at [`MAX_POWER`]). The Substrate
//! normal's word carries the linear byte itself: it takes `Ggx8` only ([`resolve_roughness`]).
//!
//! **Depth bounds.** WebGPU has no depth-bounds test. Each light's range comes from the crate's
//! `light_volume_sphere_depth_bounds` (`…bounds24` for the 24-bit code; a spot light uses the
//! sphere of its range around the apex), computed per instance in the vertex stage; the fragment
//! shader compares the stored depth against it and discards before decoding the normal. It
//! never changes the image (the range is conservative); `--compare` counts the fragments it
//! rejects and times the light pass with and without it.
//!
//! **Bad input** (every frame carries the first three lights; the test checks each):
//! - *a light at the camera*: its sphere contains the eye, so the camera-inside test
//!   (`light_volume_sphere_needs_depth_fail`) sends it to the back-face pipeline (depth test
//!   "volume behind the scene"); it lights what lies within its radius. A surface point exactly
//!   at a light has a zero light vector, for which the crate's lighting returns no light;
//! - *a volume crossing the near plane*: the same test (the eye within radius + the near-plane
//!   corner distance) draws its back faces, so the clipped front faces lose nothing;
//! - *a zero-radius light* (or a negative or non-finite one) is left out on the CPU and counted;
//!   drawn anyway, its mesh would be degenerate and its attenuation 0;
//! - *a pixel with no geometry* (the sky of the infinite projection): its depth is the clear
//!   value (reversed 0 / standard 1, code 0 / 2^24 − 1, fat view depth 0), which the light pass
//!   discards before anything else — an infinite view depth never becomes a position; the
//!   composite draws geometry only, so the sky keeps the clear colour;
//! - *a resolution of 0 or beyond `max_texture_dimension_2d`*, or an MSAA count the adapter
//!   lacks: a clear error before any texture is created.
//!
//! With a finite far plane, volumes reaching past it are clipped there (the default projection
//! is infinite, so none is).

pub mod bound;
pub mod compare;
pub mod png_out;
pub mod render;
pub mod report;
pub mod scene;
pub mod shaders;
pub mod volumes;

use prepass::projection::DepthConvention;
use prepass::scene::{
    DepthChoice, DepthStorage, LightBuffers, LightingChoice, Lights, NormalChoice, NormalEncoding,
    NormalInput, PositionChoice, RoughnessChoice, Scene, Specular,
};

/// The ambient term every layout adds (`ambient·albedo`), so unlit geometry is not black.
pub const AMBIENT: f32 = 0.04;
/// The largest specular power the log-range roughness code spans (2^13, the exact table path).
pub const MAX_POWER: f32 = 8192.0;

/// How the G-buffer stores normals and depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// The reference: f32 view-space normals and f32 view depth (`rgba32float`, `r32float`).
    Fat,
    /// A diet layout, as `Scene::gbuffer()` lays it out.
    Diet {
        /// Normal encoding.
        normal: NormalEncoding,
        /// `Float32` (the depth buffer, sampled) or `Code24Rgba8` (a 24-bit code in RGBA8).
        depth: DepthStorage,
    },
}

/// Light-buffer texel format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightFormat {
    /// 8-bit unorm: sums clamp at 1.
    Rgba8Unorm,
    /// Half float.
    Rgba16Float,
}

/// Everything one frame depends on.
#[derive(Clone, Copy, Debug)]
pub struct Config {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Number of random lights (the three bad-input lights come on top).
    pub lights: usize,
    /// MSAA samples, 1 or 2.
    pub msaa: u32,
    /// G-buffer storage.
    pub storage: Storage,
    /// Depth convention.
    pub convention: DepthConvention,
    /// Far plane (`f32::INFINITY` for the default infinite projection).
    pub far: f32,
    /// Light-buffer layout.
    pub lights_layout: LightBuffers,
    /// Light-buffer format.
    pub light_format: LightFormat,
    /// Reject pixels outside each light's depth range in the fragment shader.
    pub depth_bounds: bool,
    /// Timed repetitions (the minimum per pass is reported); the first is untimed.
    pub repeats: u32,
    /// How the G-buffer stores the material's specular power: `Log8` (the power's log-range
    /// code) or a GGX perceptual roughness form (`Ggx8`, `Ggx8Log`, `Godot8`: the power's
    /// roughness, lit with the power `2/α² − 2` of the decoded α).
    pub roughness: RoughnessChoice,
}

impl Config {
    /// The default frame: 1280×720, 256 lights, oct24 normals, reversed float depth with an
    /// infinite far plane, the one-buffer light layout in rgba16float, no MSAA, log roughness.
    pub fn default_frame() -> Self {
        Config {
            width: 1280,
            height: 720,
            lights: 256,
            msaa: 1,
            storage: Storage::Diet {
                normal: NormalEncoding::Oct24,
                depth: DepthStorage::Float32,
            },
            convention: DepthConvention::Reversed,
            far: f32::INFINITY,
            lights_layout: LightBuffers::One,
            light_format: LightFormat::Rgba16Float,
            depth_bounds: true,
            repeats: 2,
            roughness: RoughnessChoice::Log8,
        }
    }

    /// The `prepass` scene declaration these choices make (the fat layout declares the
    /// float-depth scene: its lighting functions are the same, its normals are not encoded).
    pub fn scene(&self) -> Scene {
        let (normal, storage) = match self.storage {
            Storage::Fat => (NormalEncoding::Oct32, DepthStorage::Float32),
            Storage::Diet { normal, depth } => (normal, depth),
        };
        Scene {
            depth: DepthChoice {
                storage,
                convention: self.convention,
                infinite_far: self.far == f32::INFINITY,
            },
            position: PositionChoice::View,
            normal: NormalChoice {
                encoding: Some(normal),
                fast_encoder: false,
            },
            normal_input: NormalInput::Robust,
            roughness: self.roughness,
            lighting: LightingChoice {
                lights: Lights::PointAndSpot,
                specular: Specular::BlinnPhong,
                buffers: self.lights_layout,
                aggregate_vertex_lights: false,
                light_volumes: true,
            },
        }
    }

    /// A short name of the layout, e.g. `oct24 + D32F, one buffer` (`…, one buffer, ggx8` for a
    /// roughness other than the default log8).
    pub fn layout_name(&self) -> String {
        let s = match self.storage {
            Storage::Fat => "fat (f32 normal + f32 view depth)".to_string(),
            Storage::Diet { normal, depth } => format!(
                "{} + {}",
                encoding_name(normal),
                match depth {
                    DepthStorage::Float32 => "D32F",
                    DepthStorage::Code24Rgba8 => "D24 in RGBA8",
                    DepthStorage::Code24 => "D24 in R32Uint",
                }
            ),
        };
        let l = match self.lights_layout {
            LightBuffers::One => "one buffer",
            LightBuffers::Two => "two buffers",
        };
        match self.roughness {
            RoughnessChoice::Log8 => format!("{s}, {l}"),
            r => format!("{s}, {l}, {}", roughness_name(r)),
        }
    }

    /// A file-name stem for the layout, e.g. `oct24_d32f_one` (`oct24_d32f_one_ggx8` for a
    /// roughness other than log8).
    pub fn file_stem(&self) -> String {
        let s = match self.storage {
            Storage::Fat => "fat".to_string(),
            Storage::Diet { normal, depth } => format!(
                "{}_{}",
                shaders::stem(normal),
                match depth {
                    DepthStorage::Float32 => "d32f",
                    _ => "d24",
                }
            ),
        };
        let l = match self.lights_layout {
            LightBuffers::One => "one",
            LightBuffers::Two => "two",
        };
        match self.roughness {
            RoughnessChoice::Log8 => format!("{s}_{l}"),
            r => format!("{s}_{l}_{}", roughness_name(r).replace('-', "_")),
        }
    }
}

/// The encoding's table name (as the README's encoding table spells it).
pub fn encoding_name(e: NormalEncoding) -> &'static str {
    match e {
        NormalEncoding::Xyz8 => "xyz8",
        NormalEncoding::Xyz8Best => "xyz8 best-fit",
        NormalEncoding::XyFp16 => "xy fp16",
        NormalEncoding::Oct16 => "oct16",
        NormalEncoding::Oct24 => "oct24",
        NormalEncoding::Oct32 => "oct32",
        NormalEncoding::Hemioct24 => "hemioct24",
        NormalEncoding::Xyz10 => "xyz10",
        NormalEncoding::Oct20 => "oct20",
        NormalEncoding::Snorm8 => "snorm8",
        NormalEncoding::Oct24Unity => "oct24 unity",
        NormalEncoding::Substrate => "substrate",
        NormalEncoding::SignedOct => "signed oct",
    }
}

/// The roughness forms the example renders, by their `--roughness` names.
pub const ROUGHNESS: [(&str, RoughnessChoice); 4] = [
    ("log8", RoughnessChoice::Log8),
    ("ggx8", RoughnessChoice::Ggx8),
    ("ggx8-log", RoughnessChoice::Ggx8Log),
    ("godot8", RoughnessChoice::Godot8),
];

/// The `--roughness` name of a form ([`ROUGHNESS`]; `none` for none stored).
pub fn roughness_name(r: RoughnessChoice) -> &'static str {
    ROUGHNESS
        .iter()
        .find(|(_, c)| *c == r)
        .map_or("none", |(name, _)| name)
}

/// The roughness a frame with `normal` (`None`: the fat layout) stores, given `--roughness`
/// (`asked`, `None` when not given): log8 by default; the Substrate word holds a linear GGX
/// byte, so Substrate takes ggx8 by default and refuses the other forms.
pub fn resolve_roughness(
    normal: Option<NormalEncoding>,
    asked: Option<RoughnessChoice>,
) -> Result<RoughnessChoice, String> {
    match (normal, asked) {
        (Some(NormalEncoding::Substrate), None | Some(RoughnessChoice::Ggx8)) => {
            Ok(RoughnessChoice::Ggx8)
        }
        (Some(NormalEncoding::Substrate), Some(r)) => Err(format!(
            "--roughness {}: the Substrate word's roughness byte holds linear GGX perceptual \
             roughness: --normal substrate renders --roughness ggx8 only",
            roughness_name(r)
        )),
        (_, r) => Ok(r.unwrap_or(RoughnessChoice::Log8)),
    }
}

/// The layouts `--compare` renders against the fat reference: every normal `--normal` offers
/// but snorm8 — the diet normals (xyz8, oct24, oct32, xy fp16) first, then oct16,
/// hemioct24, xyz10, oct20, O3DE's signed octahedron and oct24 in Unity's byte order — with
/// each depth storage (D24 in RGBA8, D32F), for the light layout given. snorm8 is left out:
/// its `rgba8snorm` target is not colour-renderable in core WebGPU (Dawn refuses the G-buffer
/// pipeline without the `texture-formats-tier1` feature), and every layout compared here is
/// built through Dawn by `tests/light_prepass.rs`; `--normal snorm8` still renders one frame on
/// wgpu's native backends.
pub fn diet_layouts(lights: LightBuffers) -> Vec<(Storage, LightBuffers)> {
    let mut v = Vec::new();
    for normal in [
        NormalEncoding::Xyz8,
        NormalEncoding::Oct24,
        NormalEncoding::Oct32,
        NormalEncoding::XyFp16,
        NormalEncoding::Oct16,
        NormalEncoding::Hemioct24,
        NormalEncoding::Xyz10,
        NormalEncoding::Oct20,
        NormalEncoding::SignedOct,
        NormalEncoding::Oct24Unity,
    ] {
        for depth in [DepthStorage::Code24Rgba8, DepthStorage::Float32] {
            v.push((Storage::Diet { normal, depth }, lights));
        }
    }
    v
}
