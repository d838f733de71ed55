//! Leave out what a scene does not need: a renderer declares its choices, and gets one WGSL
//! module holding only the functions, constants and types those choices reach
//! ([`Scene::wgsl`], default features), and the G-buffer layout they imply. Feature `validate`
//! adds `Library`, the same composition from naga's IR (call graph, constants, types), for
//! your own files too; the tests prove the two give the same text for every scene.
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
mod import;
mod items;
mod roots;

#[cfg(feature = "validate")]
#[cfg_attr(docsrs, doc(cfg(feature = "validate")))]
pub use compose::{ComposeError, Item, Library};
pub use import::{WESL_TOML, naga_oil_module, wesl_module, wesl_package};

use crate::projection::DepthConvention;

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
    /// Octahedral, 2×10 bits in R and G of RGB10A2; B (10 bits) and A (2 bits) free.
    Oct20,
    /// Octahedral, 2×12 bits, alpha free.
    Oct24,
    /// Octahedral, 2×16 bits.
    Oct32,
    /// Hemi-octahedral (view-space, z ≥ 0), 2×12 bits, alpha free.
    Hemioct24,
    /// x, y, z as unorm10 in RGB10A2 (Unreal 5's GBufferA, Bevy's normal prepass), 2 bits free.
    Xyz10,
    /// x, y, z as snorm8 (Unity URP's default normal target), alpha free.
    Snorm8,
    /// Octahedral 2×12 bits in Unity's byte order (HDRP's normal buffer, URP's accurate
    /// G-buffer normals): oct24's grid, alpha free.
    Oct24Unity,
    /// Unreal 5 Substrate's 32-bit word (`r32uint`): an 11:11 centred-grid octahedron, the
    /// perceptual roughness byte ([`RoughnessChoice::Ggx8`]'s, or 0 when none is stored) and two
    /// flag bits (written 0).
    Substrate,
    /// xyz8's format written by the best-fit encoder (Godot 4's normal_roughness: the nearest of
    /// the 2^24 codes), read by xyz8's decoder; alpha free.
    Xyz8Best,
    /// O3DE's signed octahedron in RGB10A2: R and G the hemi-octahedral 10:10 code of
    /// `(x, y, |z|)`, B z's sign (0 or 1), A (2 bits) free.
    SignedOct,
}

impl NormalEncoding {
    /// Every encoding.
    pub const ALL: [NormalEncoding; 13] = [
        Self::Xyz8,
        Self::XyFp16,
        Self::Oct16,
        Self::Oct20,
        Self::Oct24,
        Self::Oct32,
        Self::Hemioct24,
        Self::Xyz10,
        Self::Snorm8,
        Self::Oct24Unity,
        Self::Substrate,
        Self::Xyz8Best,
        Self::SignedOct,
    ];

    /// Whether a cheaper rounding encoder (`_fast`) exists beside the precise one.
    pub fn has_fast_encoder(self) -> bool {
        !matches!(
            self,
            Self::Xyz8 | Self::XyFp16 | Self::Xyz10 | Self::Snorm8 | Self::Xyz8Best
        )
    }

    /// Whether encoders for vouched input (`_vouched`, `_fast_vouched`) exist beside the robust
    /// ones ([`NormalInput::Vouched`]).
    pub fn has_vouched_encoder(self) -> bool {
        matches!(
            self,
            Self::Oct16 | Self::Oct24 | Self::Oct32 | Self::Hemioct24
        )
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

/// What the scene promises about the normals its G-buffer pass encodes: which form of the
/// encoder it calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum NormalInput {
    /// Any input: the robust encoders (`encode_normal_oct24`, …), with a documented code for
    /// NaN, ±Inf, subnormals, the zero vector and any finite length.
    #[default]
    Robust,
    /// The scene vouches for its normals (its own interpolated normals): every component finite,
    /// every non-zero one at least `2^-126·max(1, ‖n‖∞)` in magnitude (no subnormals), and
    /// `0 < ‖n‖∞ ≤ 2^124` — for `Hemioct24` the same of `(x, y, max(z, 0))`, the hemisphere's
    /// clamp it keeps, so a negative `z` may be any finite value. The G-buffer pass calls the
    /// `_vouched` encoder (`encode_normal_oct24_vouched`, `encode_normal_oct24_fast_vouched`,
    /// `encode_normal_hemioct24_vouched`, …): the robust encoder's code bit for bit inside that
    /// contract without its bad-input handling, and some code (indeterminate in WGSL; every
    /// decoder accepts it) outside it. Only the octahedral encodings (`Oct16`, `Oct24`, `Oct32`)
    /// and `Hemioct24` have the vouched form ([`NormalEncoding::has_vouched_encoder`]); the
    /// contracts in full: [`crate::normal::oct::encode_precise_vouched`],
    /// [`crate::normal::hemioct::encode_normal_hemioct24_vouched`].
    Vouched,
}

/// The specular exponent (roughness) in the G-buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum RoughnessChoice {
    /// None stored.
    #[default]
    None,
    /// 8-bit log-range code (Killzone 2), in the normal target's alpha when it has one free.
    Log8,
    /// GGX perceptual roughness `r` (`α = r²`) in unorm8, linearly, as Bevy, Unreal, HDRP, URP
    /// and Substrate store it (`encode_roughness_ggx8_unorm`; the lighting reads `α`,
    /// `decode_roughness_ggx8_alpha`, and its Blinn-Phong exponent is `2/α² − 2`): in the normal
    /// target's alpha when it has one free, in the Substrate word, else in an `r8unorm` target.
    Ggx8,
    /// GGX perceptual roughness on prepass's searched log curve in unorm8 (code `k` stands for
    /// `r = 2^(6k/255 − 6)`, `r ∈ [1/64, 1]`: `encode_roughness_ggx8_log_unorm`; the lighting
    /// reads `α`, `decode_roughness_ggx8_log_alpha`), where `Ggx8` would go: finer where the GGX
    /// lobe is sharp (its error beside linear `r`: docs/figures.md, "GGX roughness"). Not in the
    /// Substrate word, whose byte is linear.
    Ggx8Log,
    /// Godot 4's byte (Forward+): GGX perceptual roughness in 7 bits and a dynamic-object flag
    /// (`encode_roughness_godot8_unorm(r, dynamic_object)`, `decode_roughness_godot8_unorm`,
    /// `α = r²`), where `Ggx8` would go. Not in the Substrate word.
    Godot8,
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
    /// Which encoder form the normal's G-buffer pass calls: robust (default) or vouched.
    pub normal_input: NormalInput,
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
        if self.normal_input == NormalInput::Vouched
            && !self
                .normal
                .encoding
                .is_some_and(|e| e.has_vouched_encoder())
        {
            return bad(
                &["normal_input", "normal.encoding"],
                "only the octahedral encodings (oct16, oct24, oct32, hemioct24) have a `_vouched` encoder",
            );
        }
        if self.normal.encoding == Some(NormalEncoding::Substrate)
            && !matches!(
                self.roughness,
                RoughnessChoice::None | RoughnessChoice::Ggx8
            )
        {
            return bad(
                &["normal.encoding", "roughness"],
                "the Substrate word's roughness byte holds GGX perceptual roughness: choose Ggx8 (or None)",
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

    /// The composed WGSL module for this scene: only the shipped functions, constants and
    /// types its roots ([`roots`](Self::roots)) reach, each with its comment, in the shipped
    /// files' order. Append your entry points and bindings and create one shader module.
    ///
    /// Cut from the files' text, on every feature set (no naga). `tests/scene.rs` proves it is
    /// the text of naga's composition (`Library::compose`, feature `validate`, which parses
    /// and validates it) for every distinct scene, and compiles each with naga and Tint; to
    /// validate your own module, `prepass::wgsl::parse_and_validate` (feature `validate`).
    pub fn wgsl(&self) -> Result<String, SceneError> {
        let roots = self.roots()?;
        // `roots` names only shipped items (the scene tests check every one).
        Ok(items::compose(roots).expect("every root is a shipped item"))
    }
}
