//! The WGSL functions a scene's passes call: the roots the composer starts from.

use super::{
    DepthStorage, LightBuffers, Lights, NormalEncoding, NormalInput, PositionChoice,
    RoughnessChoice, Scene, SceneError, Specular,
};
use crate::projection::DepthConvention;

/// The normal functions a G-buffer pass (encode, through the render-target form) and a
/// lighting pass (decode) call.
fn normal_roots(e: NormalEncoding, fast: bool, vouched: bool) -> [&'static str; 4] {
    // Names are spelled out so a search for a WGSL function finds its scene choice.
    let (enc, enc_fast, dec, enc_unorm, dec_unorm) = match e {
        NormalEncoding::Xyz8 => (
            "encode_normal_xyz8",
            "encode_normal_xyz8",
            "decode_normal_xyz8",
            "encode_normal_xyz8_unorm",
            "decode_normal_xyz8_unorm",
        ),
        NormalEncoding::Xyz8Best => (
            "encode_normal_xyz8_best",
            "encode_normal_xyz8_best",
            "decode_normal_xyz8",
            "encode_normal_xyz8_best_unorm",
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
        NormalEncoding::Oct20 => (
            "encode_normal_oct20",
            "encode_normal_oct20_fast",
            "decode_normal_oct20",
            "encode_normal_oct20_unorm",
            "decode_normal_oct20_unorm",
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
        NormalEncoding::SignedOct => (
            "encode_normal_signed_oct",
            "encode_normal_signed_oct_fast",
            "decode_normal_signed_oct",
            "encode_normal_signed_oct_unorm",
            "decode_normal_signed_oct_unorm",
        ),
        NormalEncoding::Xyz10 => (
            "encode_normal_xyz10",
            "encode_normal_xyz10",
            "decode_normal_xyz10",
            "encode_normal_xyz10_unorm",
            "decode_normal_xyz10_unorm",
        ),
        NormalEncoding::Oct24Unity => (
            "encode_normal_oct24_unity",
            "encode_normal_oct24_unity_fast",
            "decode_normal_oct24_unity",
            "encode_normal_oct24_unity_unorm",
            "decode_normal_oct24_unity_unorm",
        ),
        // The word is the target's texel: the encoder and decoders are the render-target forms.
        NormalEncoding::Substrate => (
            "encode_substrate_word",
            "encode_substrate_word_fast",
            "decode_substrate_normal",
            "encode_substrate_word",
            "decode_substrate_normal",
        ),
        NormalEncoding::Snorm8 => (
            "encode_normal_snorm8",
            "encode_normal_snorm8",
            "decode_normal_snorm8",
            "encode_normal_snorm8_snorm",
            "decode_normal_snorm8_snorm",
        ),
    };
    let enc = match (e, fast, vouched) {
        (_, true, false) => enc_fast,
        (_, false, false) => enc,
        (NormalEncoding::Oct16, false, true) => "encode_normal_oct16_vouched",
        (NormalEncoding::Oct16, true, true) => "encode_normal_oct16_fast_vouched",
        (NormalEncoding::Oct24, false, true) => "encode_normal_oct24_vouched",
        (NormalEncoding::Oct24, true, true) => "encode_normal_oct24_fast_vouched",
        (NormalEncoding::Oct32, false, true) => "encode_normal_oct32_vouched",
        (NormalEncoding::Oct32, true, true) => "encode_normal_oct32_fast_vouched",
        (NormalEncoding::Hemioct24, false, true) => "encode_normal_hemioct24_vouched",
        (NormalEncoding::Hemioct24, true, true) => "encode_normal_hemioct24_fast_vouched",
        // `Scene::validate` refuses vouched input for the other encodings.
        (_, _, true) => unreachable!("validated: {e:?} has no vouched encoder"),
    };
    [enc, dec, enc_unorm, dec_unorm]
}

impl Scene {
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
        // The convention-aware uniform form (`Projection::depth_uniform`), beside the
        // per-convention constants form.
        r.push(match d.storage {
            DepthStorage::Float32 => "view_z_from_depth_uniform",
            DepthStorage::Code24 | DepthStorage::Code24Rgba8 => "view_z_from_depth24_uniform",
        });
        r.push("VIEW_Z_SKY");
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
            // Every full-screen pass also needs its vertices' clip position.
            PositionChoice::View => r.extend([
                "fullscreen_triangle_ndc",
                "fullscreen_triangle_ray_rh",
                "view_position",
            ]),
            PositionChoice::World => r.extend([
                "fullscreen_triangle_ndc",
                "fullscreen_triangle_ray_rh",
                "world_ray",
                "world_position",
            ]),
            PositionChoice::CameraRelative => r.extend([
                "fullscreen_triangle_ndc",
                "fullscreen_triangle_ray_rh",
                "world_ray",
                "camera_relative_position",
            ]),
        }
        if let Some(e) = self.normal.encoding {
            r.extend(normal_roots(
                e,
                self.normal.fast_encoder,
                self.normal_input == NormalInput::Vouched,
            ));
        }
        match self.roughness {
            RoughnessChoice::Ggx8 => {
                if self.normal.encoding == Some(NormalEncoding::Substrate) {
                    r.extend(["decode_substrate_roughness", "decode_roughness_ggx8_alpha"]);
                } else {
                    r.extend(["encode_roughness_ggx8_unorm", "decode_roughness_ggx8_unorm"]);
                    r.push("decode_roughness_ggx8_alpha");
                }
            }
            RoughnessChoice::Ggx8Log => r.extend([
                "encode_roughness_ggx8_log_unorm",
                "decode_roughness_ggx8_log_unorm",
                "decode_roughness_ggx8_log_alpha",
            ]),
            RoughnessChoice::Godot8 => r.extend([
                "encode_roughness_godot8_unorm",
                "decode_roughness_godot8_unorm",
            ]),
            RoughnessChoice::None | RoughnessChoice::Log8 => {}
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
}
