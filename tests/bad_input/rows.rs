//! The bad-input contract as data: every public function, and what it returns for NaN, ±Inf,
//! subnormals, zero vectors and out-of-range codes or parameters. `tests/bad_input.rs` runs every
//! row through the WGSL on the adapter and through the Rust twin, and checks that the README's
//! table is exactly these rows.
//!
//! Adding a module: add its functions to [`FUNCS`] (WGSL source + name, and the Rust twin as a
//! closure over [`V`] arguments) and its rows to [`ROWS`]; then paste the table the failing
//! README test prints.

use glam::Vec3;
use prepass::depth24;
use prepass::lighting::aggregate_light as agg;
use prepass::lighting::light_volume as vol;
use prepass::lighting::lpp;
use prepass::linear_depth as ld;
use prepass::normal::{hemioct, oct, xy_fp16, xyz8};
use prepass::position as pos;
use prepass::precision::inputs::{self, ChannelError};
use prepass::precision::metrics;
use prepass::projection::{
    Depth24Consts, DepthConsts, DepthConvention, Projection, ReversedDepthConsts,
};
use prepass::roughness as rough;

/// A value in the table: an argument or a result.
#[derive(Clone, Copy, Debug)]
pub enum V {
    F32(f32),
    U32(u32),
    Vec2([f32; 2]),
    Vec3([f32; 3]),
    Vec4([f32; 4]),
    /// A `vec2<u32>`.
    UVec2([u32; 2]),
    /// Two `f32` 3-vectors (a Rust-only pair result).
    Vec3x2([[f32; 3]; 2]),
    /// Two `f64` (a Rust-only pair result).
    F64x2([f64; 2]),
    F64(f64),
    OptU32(Option<u32>),
    OptVec3(Option<[f32; 3]>),
    // Rust-only argument and result types (the precision metrics and inputs).
    I64(i64),
    Bool(bool),
    F64x3([f64; 3]),
    OptI64(Option<i64>),
    OptU64(Option<u64>),
    Channel(ChannelError),
    /// A Rust-only result described in words (e.g. which field a builder rejects).
    Text(&'static str),
}

impl V {
    pub fn f32(self) -> f32 {
        match self {
            V::F32(x) => x,
            v => panic!("{v:?} is not an f32"),
        }
    }
    pub fn u32(self) -> u32 {
        match self {
            V::U32(x) => x,
            v => panic!("{v:?} is not a u32"),
        }
    }
    pub fn f64(self) -> f64 {
        match self {
            V::F64(x) => x,
            v => panic!("{v:?} is not an f64"),
        }
    }
    pub fn f64x3(self) -> [f64; 3] {
        match self {
            V::F64x3(x) => x,
            v => panic!("{v:?} is not an [f64; 3]"),
        }
    }
    pub fn i64(self) -> i64 {
        match self {
            V::I64(x) => x,
            v => panic!("{v:?} is not an i64"),
        }
    }
    pub fn bool(self) -> bool {
        match self {
            V::Bool(x) => x,
            v => panic!("{v:?} is not a bool"),
        }
    }
    pub fn channel(self) -> ChannelError {
        match self {
            V::Channel(x) => x,
            v => panic!("{v:?} is not a ChannelError"),
        }
    }
    pub fn vec2(self) -> glam::Vec2 {
        match self {
            V::Vec2(x) => glam::Vec2::from(x),
            v => panic!("{v:?} is not a vec2"),
        }
    }
    pub fn vec4(self) -> glam::Vec4 {
        match self {
            V::Vec4(x) => glam::Vec4::from(x),
            v => panic!("{v:?} is not a vec4"),
        }
    }
    pub fn vec3(self) -> Vec3 {
        match self {
            V::Vec3(x) => Vec3::from(x),
            v => panic!("{v:?} is not a vec3"),
        }
    }
}

/// A public function: its Rust twin, and its WGSL (source, name) where it has one.
pub struct Func {
    /// The Rust path below `prepass::` (the table's "Rust twin" column; the key of a Rust-only
    /// function).
    pub rust: &'static str,
    /// WGSL source and function name, or `None` for Rust-only functions.
    pub wgsl: Option<(&'static str, &'static str)>,
    /// The Rust twin.
    pub twin: fn(&[V]) -> V,
}

/// Prefix of the wrappers a row appends to a file's text for arguments the harness cannot feed.
pub const WRAPPER_PREFIX: &str = "bad_input_";

impl Func {
    /// The name rows and the table key this function by: its WGSL name (a `bad_input_` wrapper
    /// stands for the function or builtin it wraps), or for a Rust-only function its Rust path.
    pub fn key(&self) -> &'static str {
        match self.wgsl {
            Some((_, name)) => name.strip_prefix(WRAPPER_PREFIX).unwrap_or(name),
            None => self.rust,
        }
    }
}

/// `world_ray` takes a `mat3x3`, which the harness cannot feed: a wrapper builds it from columns.
const WORLD_RAY_WGSL: &str = concat!(
    include_str!("../../wgsl/position.wgsl"),
    "\nfn bad_input_world_ray(ray: vec3<f32>, c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>) -> vec3<f32> {\n",
    "    return world_ray(ray, mat3x3<f32>(c0, c1, c2));\n}\n"
);

/// `Projection::new` as a table value: `Ok` or the rejected field.
fn projection_new(a: &[V]) -> V {
    let conv = if a[2].bool() {
        DepthConvention::Reversed
    } else {
        DepthConvention::Standard
    };
    match Projection::new(a[0].f32(), a[1].f32(), conv) {
        Ok(_) => V::Text("Ok"),
        Err(e) if e.field == "near" => V::Text("Err(near)"),
        Err(_) => V::Text("Err(far)"),
    }
}

/// WGSL's builtin `unpack4x8unorm` (twin: `depth24::unpack4x8unorm`) behind a callable name.
const UNPACK_WGSL: &str =
    "fn bad_input_unpack4x8unorm(p: u32) -> vec4<f32> { return unpack4x8unorm(p); }";

/// `roughness::range` as the WGSL's `log_roughness_range_log2` answers it: 0 degenerate, `L`
/// for `2^L`, `0xffffffff` for a general range.
fn range_code(r: rough::Range) -> u32 {
    match r {
        rough::Range::Degenerate => 0,
        rough::Range::PowerOfTwo(l) => l,
        rough::Range::General(_) => u32::MAX,
    }
}

/// The light-volume WGSL's convention argument: 0 standard, anything else reversed.
fn convention(code: u32) -> DepthConvention {
    if code == 0 {
        DepthConvention::Standard
    } else {
        DepthConvention::Reversed
    }
}

/// `lpp_cosines` takes a `bool`, which the harness cannot feed: a wrapper takes it as a `u32`.
const LPP_COSINES_WGSL: &str = concat!(
    include_str!("../../wgsl/lpp.wgsl"),
    "\nfn bad_input_lpp_cosines(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>, phong: u32) -> vec2<f32> {\n",
    "    return lpp_cosines(normal, to_eye, to_light, phong != 0u);\n}\n"
);

pub const FUNCS: &[Func] = &[
    Func {
        rust: "depth24::depth24_from_rgb8",
        wgsl: Some((prepass::wgsl::DEPTH24, "depth24_from_rgb8")),
        twin: |a| V::U32(depth24::depth24_from_rgb8(a[0].vec3())),
    },
    Func {
        rust: "depth24::depth24_from_packed",
        wgsl: Some((prepass::wgsl::DEPTH24, "depth24_from_packed")),
        twin: |a| V::U32(depth24::depth24_from_packed(a[0].u32())),
    },
    Func {
        rust: "depth24::pack_depth24",
        wgsl: Some((prepass::wgsl::DEPTH24, "pack_depth24")),
        twin: |a| V::U32(depth24::pack_depth24(a[0].u32())),
    },
    Func {
        rust: "depth24::hyperbolic_depth_from_depth24",
        wgsl: Some((prepass::wgsl::DEPTH24, "hyperbolic_depth_from_depth24")),
        twin: |a| V::F32(depth24::hyperbolic_depth_from_depth24(a[0].u32())),
    },
    Func {
        rust: "depth24::unpack4x8unorm",
        wgsl: Some((UNPACK_WGSL, "bad_input_unpack4x8unorm")),
        twin: |a| V::Vec4(depth24::unpack4x8unorm(a[0].u32())),
    },
    Func {
        rust: "depth24::exact::hyperbolic_depth",
        wgsl: None,
        twin: |a| V::F64(depth24::exact::hyperbolic_depth(a[0].u32())),
    },
    Func {
        rust: "depth24::exact::nearest_code",
        wgsl: None,
        twin: |a| V::OptU32(depth24::exact::nearest_code(a[0].f32())),
    },
    Func {
        rust: "precision::metrics::ordinal",
        wgsl: None,
        twin: |a| V::OptI64(metrics::ordinal(a[0].f32())),
    },
    Func {
        rust: "precision::metrics::ulp_distance",
        wgsl: None,
        twin: |a| V::OptU64(metrics::ulp_distance(a[0].f32(), a[1].f32())),
    },
    Func {
        rust: "precision::metrics::step_ulps",
        wgsl: None,
        twin: |a| V::F32(metrics::step_ulps(a[0].f32(), a[1].i64())),
    },
    Func {
        rust: "precision::metrics::f32_ulp_at",
        wgsl: None,
        twin: |a| V::F64(metrics::f32_ulp_at(a[0].f64())),
    },
    Func {
        rust: "precision::metrics::ulp_error",
        wgsl: None,
        twin: |a| V::F64(metrics::ulp_error(a[0].f32(), a[1].f64())),
    },
    Func {
        rust: "precision::metrics::relative_error",
        wgsl: None,
        twin: |a| V::F64(metrics::relative_error(a[0].f64(), a[1].f64())),
    },
    Func {
        rust: "precision::metrics::angle_degrees",
        wgsl: None,
        twin: |a| V::F64(metrics::angle_degrees(a[0].f64x3(), a[1].f64x3())),
    },
    Func {
        rust: "precision::metrics::widen3",
        wgsl: None,
        twin: |a| V::F64x3(metrics::widen3(a[0].vec3().to_array())),
    },
    Func {
        rust: "precision::inputs::unorm8_channel",
        wgsl: None,
        twin: |a| {
            V::F32(inputs::unorm8_channel(
                a[0].u32(),
                a[1].channel(),
                a[2].bool(),
            ))
        },
    },
    Func {
        rust: "precision::inputs::rgb8_channels",
        wgsl: None,
        twin: |a| {
            V::Vec3(inputs::rgb8_channels(
                a[0].u32(),
                a[1].channel(),
                a[2].bool(),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_depth24",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24")),
        twin: |a| V::F32(ld::view_z_from_depth24(a[0].u32(), a[1].f32(), a[2].f32())),
    },
    Func {
        rust: "linear_depth::view_z_from_depth24_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth24_consts(
                a[0].u32(),
                Depth24Consts::from_wgsl(a[1].vec2().to_array()),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_depth",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth")),
        twin: |a| V::F32(ld::view_z_from_depth(a[0].f32(), a[1].f32(), a[2].f32())),
    },
    Func {
        rust: "linear_depth::view_z_from_depth_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth_consts(
                a[0].f32(),
                DepthConsts::from_wgsl(a[1].vec3().to_array()),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_reversed_depth",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_reversed_depth")),
        twin: |a| {
            V::F32(ld::view_z_from_reversed_depth(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
            ))
        },
    },
    Func {
        rust: "linear_depth::view_z_from_reversed_depth_consts",
        wgsl: Some((
            prepass::wgsl::LINEAR_DEPTH,
            "view_z_from_reversed_depth_consts",
        )),
        twin: |a| {
            V::F32(ld::view_z_from_reversed_depth_consts(
                a[0].f32(),
                ReversedDepthConsts::from_wgsl(a[1].vec3().to_array()),
            ))
        },
    },
    Func {
        rust: "projection::Projection::new",
        wgsl: None,
        twin: projection_new,
    },
    Func {
        rust: "position::frustum_ray",
        wgsl: Some((prepass::wgsl::POSITION, "frustum_ray")),
        twin: |a| V::Vec3(pos::frustum_ray(a[0].vec2(), a[1].vec2()).to_array()),
    },
    Func {
        rust: "position::frustum_ray_rh",
        wgsl: Some((prepass::wgsl::POSITION, "frustum_ray_rh")),
        twin: |a| V::Vec3(pos::frustum_ray_rh(a[0].vec2(), a[1].vec2()).to_array()),
    },
    Func {
        rust: "position::view_position",
        wgsl: Some((prepass::wgsl::POSITION, "view_position")),
        twin: |a| V::Vec3(pos::view_position(a[0].vec3(), a[1].f32()).to_array()),
    },
    Func {
        rust: "position::fullscreen_triangle_ndc",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ndc")),
        twin: |a| V::Vec2(pos::fullscreen_triangle_ndc(a[0].u32()).to_array()),
    },
    Func {
        rust: "position::fullscreen_triangle_ray",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ray")),
        twin: |a| V::Vec3(pos::fullscreen_triangle_ray(a[0].u32(), a[1].vec2()).to_array()),
    },
    Func {
        rust: "position::fullscreen_triangle_ray_rh",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ray_rh")),
        twin: |a| V::Vec3(pos::fullscreen_triangle_ray_rh(a[0].u32(), a[1].vec2()).to_array()),
    },
    Func {
        rust: "position::ndc_from_uv",
        wgsl: Some((prepass::wgsl::POSITION, "ndc_from_uv")),
        twin: |a| V::Vec2(pos::ndc_from_uv(a[0].vec2()).to_array()),
    },
    Func {
        rust: "position::world_ray",
        wgsl: Some((WORLD_RAY_WGSL, "bad_input_world_ray")),
        twin: |a| {
            let m = glam::Mat3::from_cols(a[1].vec3(), a[2].vec3(), a[3].vec3());
            V::Vec3(pos::world_ray(a[0].vec3(), m).to_array())
        },
    },
    Func {
        rust: "position::camera_relative_position",
        wgsl: Some((prepass::wgsl::POSITION, "camera_relative_position")),
        twin: |a| V::Vec3(pos::camera_relative_position(a[0].vec3(), a[1].f32()).to_array()),
    },
    Func {
        rust: "position::world_position",
        wgsl: Some((prepass::wgsl::POSITION, "world_position")),
        twin: |a| V::Vec3(pos::world_position(a[0].vec3(), a[1].f32(), a[2].vec3()).to_array()),
    },
    Func {
        rust: "roughness::range",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "log_roughness_range_log2")),
        twin: |a| V::U32(range_code(rough::range(a[0].f32()))),
    },
    Func {
        rust: "roughness::encode_log_roughness",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "encode_log_roughness")),
        twin: |a| V::U32(rough::encode_log_roughness(a[0].f32(), a[1].f32())),
    },
    Func {
        rust: "roughness::decode_log_roughness",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "decode_log_roughness")),
        twin: |a| V::F32(rough::decode_log_roughness(a[0].u32(), a[1].f32())),
    },
    Func {
        rust: "roughness::pack_normal_xyz8_log_roughness",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "pack_normal_xyz8_log_roughness")),
        twin: |a| {
            V::U32(rough::pack_normal_xyz8_log_roughness(
                a[0].u32(),
                a[1].u32(),
            ))
        },
    },
    Func {
        rust: "roughness::normal_xyz8_from_log_roughness_texel",
        wgsl: Some((
            prepass::wgsl::ROUGHNESS,
            "normal_xyz8_from_log_roughness_texel",
        )),
        twin: |a| V::U32(rough::normal_xyz8_from_log_roughness_texel(a[0].u32())),
    },
    Func {
        rust: "roughness::log_roughness_code_from_texel",
        wgsl: Some((prepass::wgsl::ROUGHNESS, "log_roughness_code_from_texel")),
        twin: |a| V::U32(rough::log_roughness_code_from_texel(a[0].u32())),
    },
    Func {
        rust: "roughness::quantisation_limit",
        wgsl: None,
        twin: |a| V::F64(rough::quantisation_limit(a[0].f64())),
    },
    Func {
        rust: "roughness::exact::decode",
        wgsl: None,
        twin: |a| V::F64(rough::exact::decode(a[0].u32(), a[1].f64())),
    },
    Func {
        rust: "roughness::exact::encode",
        wgsl: None,
        twin: |a| V::U32(rough::exact::encode(a[0].f64(), a[1].f64())),
    },
    Func {
        rust: "lighting::lpp::lpp_direction",
        wgsl: Some((prepass::wgsl::LPP, "lpp_direction")),
        twin: |a| V::Vec3(lpp::lpp_direction(a[0].vec3()).to_array()),
    },
    Func {
        rust: "lighting::lpp::lpp_luminance",
        wgsl: Some((prepass::wgsl::LPP, "lpp_luminance")),
        twin: |a| V::F32(lpp::lpp_luminance(a[0].vec3())),
    },
    Func {
        rust: "lighting::lpp::lpp_pow_cosine",
        wgsl: Some((prepass::wgsl::LPP, "lpp_pow_cosine")),
        twin: |a| V::F32(lpp::lpp_pow_cosine(a[0].f32(), a[1].f32())),
    },
    Func {
        rust: "lighting::lpp::lpp_point_attenuation",
        wgsl: Some((prepass::wgsl::LPP, "lpp_point_attenuation")),
        twin: |a| V::F32(lpp::lpp_point_attenuation(a[0].f32(), a[1].f32())),
    },
    Func {
        rust: "lighting::lpp::lpp_spot_attenuation",
        wgsl: Some((prepass::wgsl::LPP, "lpp_spot_attenuation")),
        twin: |a| {
            V::F32(lpp::lpp_spot_attenuation(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
            ))
        },
    },
    Func {
        rust: "lighting::lpp::lpp_cosines",
        wgsl: Some((LPP_COSINES_WGSL, "bad_input_lpp_cosines")),
        twin: |a| {
            let (d, s) = lpp::lpp_cosines(a[0].vec3(), a[1].vec3(), a[2].vec3(), a[3].u32() != 0);
            V::Vec2([d, s])
        },
    },
    Func {
        rust: "lighting::lpp::lpp_blinn_phong_light",
        wgsl: Some((prepass::wgsl::LPP, "lpp_blinn_phong_light")),
        twin: |a| {
            V::Vec4(
                lpp::lpp_blinn_phong_light(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec3(),
                    a[4].f32(),
                    a[5].f32(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_phong_light",
        wgsl: Some((prepass::wgsl::LPP, "lpp_phong_light")),
        twin: |a| {
            V::Vec4(
                lpp::lpp_phong_light(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec3(),
                    a[4].f32(),
                    a[5].f32(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_point_light",
        wgsl: Some((prepass::wgsl::LPP, "lpp_point_light")),
        twin: |a| {
            V::Vec4(
                lpp::lpp_point_light(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec4(),
                    a[4].f32(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_spot_light",
        wgsl: Some((prepass::wgsl::LPP, "lpp_spot_light")),
        twin: |a| {
            V::Vec4(
                lpp::lpp_spot_light(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec4(),
                    a[4].vec4(),
                    a[5].f32(),
                    a[6].f32(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_blinn_phong_specular_rgb",
        wgsl: Some((prepass::wgsl::LPP, "lpp_blinn_phong_specular_rgb")),
        twin: |a| {
            V::Vec3(
                lpp::lpp_blinn_phong_specular_rgb(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec3(),
                    a[4].f32(),
                    a[5].f32(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_reconstruct_specular",
        wgsl: Some((prepass::wgsl::LPP, "lpp_reconstruct_specular")),
        twin: |a| V::F32(lpp::lpp_reconstruct_specular(a[0].vec4(), a[1].f32())),
    },
    Func {
        rust: "lighting::lpp::lpp_combine",
        wgsl: Some((prepass::wgsl::LPP, "lpp_combine")),
        twin: |a| {
            V::Vec3(lpp::lpp_combine(a[0].vec3(), a[1].vec3(), a[2].vec4(), a[3].f32()).to_array())
        },
    },
    Func {
        rust: "lighting::lpp::lpp_combine_two_buffers",
        wgsl: Some((prepass::wgsl::LPP, "lpp_combine_two_buffers")),
        twin: |a| {
            V::Vec3(
                lpp::lpp_combine_two_buffers(a[0].vec3(), a[1].vec3(), a[2].vec3(), a[3].vec3())
                    .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::lpp_clamp_colour",
        wgsl: Some((prepass::wgsl::LPP, "lpp_clamp_colour")),
        twin: |a| V::Vec3(lpp::lpp_clamp_colour(a[0].vec3()).to_array()),
    },
    Func {
        rust: "lighting::lpp::exact::unit",
        wgsl: None,
        twin: |a| V::F64x3(lpp::exact::unit(a[0].f64x3())),
    },
    Func {
        rust: "lighting::aggregate_light::aggregate_light_accumulate",
        wgsl: Some((prepass::wgsl::AGGREGATE_LIGHT, "aggregate_light_accumulate")),
        twin: |a| {
            V::Vec4(
                agg::aggregate_light_accumulate(a[0].vec4(), a[1].vec3(), a[2].vec3(), a[3].f32())
                    .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::aggregate_light::aggregate_light_direction",
        wgsl: Some((prepass::wgsl::AGGREGATE_LIGHT, "aggregate_light_direction")),
        twin: |a| V::Vec3(agg::aggregate_light_direction(a[0].vec4()).to_array()),
    },
    Func {
        rust: "lighting::aggregate_light::aggregate_light_position",
        wgsl: Some((prepass::wgsl::AGGREGATE_LIGHT, "aggregate_light_position")),
        twin: |a| V::Vec3(agg::aggregate_light_position(a[0].vec4(), a[1].vec3()).to_array()),
    },
    Func {
        rust: "lighting::aggregate_light::aggregate_light_accumulate_colour",
        wgsl: Some((
            prepass::wgsl::AGGREGATE_LIGHT,
            "aggregate_light_accumulate_colour",
        )),
        twin: |a| {
            V::Vec3(
                agg::aggregate_light_accumulate_colour(
                    a[0].vec3(),
                    a[1].vec3(),
                    a[2].vec3(),
                    a[3].vec3(),
                    a[4].vec3(),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::aggregate_light::aggregate_light_diffuse",
        wgsl: Some((prepass::wgsl::AGGREGATE_LIGHT, "aggregate_light_diffuse")),
        twin: |a| {
            V::Vec3(
                agg::aggregate_light_diffuse(a[0].vec3(), a[1].vec3(), a[2].vec3(), a[3].vec3())
                    .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::lpp::exact::lpp_cosines",
        wgsl: None,
        twin: |a| {
            let (d, s) = lpp::exact::lpp_cosines(a[0].f64x3(), a[1].f64x3(), a[2].f64x3());
            V::F64x2([d, s])
        },
    },
    Func {
        rust: "lighting::lpp::exact::multi_light_specular",
        wgsl: None,
        twin: |a| {
            // Arguments: normal, to_eye, material power, then (to_light, lum, att, n) per light.
            let lights: Vec<lpp::exact::Light> = a[3..]
                .chunks(4)
                .map(|l| (l[0].f64x3(), l[1].f64(), l[2].f64(), l[3].f64()))
                .collect();
            V::F64(lpp::exact::multi_light_specular(
                a[0].f64x3(),
                a[1].f64x3(),
                &lights,
                a[2].f64(),
            ))
        },
    },
    Func {
        rust: "lighting::aggregate_light::aggregate",
        wgsl: None,
        twin: |a| {
            // Arguments: the vertex, then (position, weight, colour) per light.
            let lights: Vec<(Vec3, f32, Vec3)> = a[1..]
                .chunks(3)
                .map(|l| (l[0].vec3(), l[1].f32(), l[2].vec3()))
                .collect();
            let (p, c) = agg::aggregate(a[0].vec3(), &lights);
            V::Vec3x2([p.to_array(), c.to_array()])
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_near_corner_distance",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_near_corner_distance",
        )),
        twin: |a| {
            V::F32(vol::light_volume_near_corner_distance(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_sphere_needs_depth_fail",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_sphere_needs_depth_fail",
        )),
        twin: |a| {
            V::U32(vol::light_volume_sphere_needs_depth_fail(
                a[0].vec3(),
                a[1].f32(),
                a[2].f32(),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_cone_needs_depth_fail",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_cone_needs_depth_fail",
        )),
        twin: |a| {
            V::U32(vol::light_volume_cone_needs_depth_fail(
                a[0].vec3(),
                a[1].vec3(),
                a[2].vec2(),
                a[3].f32(),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_window_depth",
        wgsl: Some((prepass::wgsl::LIGHT_VOLUME, "light_volume_window_depth")),
        twin: |a| {
            V::F32(vol::light_volume_window_depth(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
                convention(a[3].u32()),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_sphere_depth_bounds",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_sphere_depth_bounds",
        )),
        twin: |a| {
            V::Vec2(
                vol::light_volume_sphere_depth_bounds(
                    a[0].f32(),
                    a[1].f32(),
                    a[2].f32(),
                    a[3].f32(),
                    convention(a[4].u32()),
                )
                .to_array(),
            )
        },
    },
    Func {
        rust: "lighting::light_volume::light_volume_sphere_depth_bounds24",
        wgsl: Some((
            prepass::wgsl::LIGHT_VOLUME,
            "light_volume_sphere_depth_bounds24",
        )),
        twin: |a| {
            V::UVec2(vol::light_volume_sphere_depth_bounds24(
                a[0].f32(),
                a[1].f32(),
                a[2].f32(),
                a[3].f32(),
                convention(a[4].u32()),
            ))
        },
    },
    Func {
        rust: "lighting::light_volume::exact::light_volume_window_depth",
        wgsl: None,
        twin: |a| {
            V::F64(vol::exact::light_volume_window_depth(
                a[0].f64(),
                a[1].f64(),
                a[2].f64(),
                convention(a[3].u32()),
            ))
        },
    },
    // Normal encodings
    Func {
        rust: "normal::xyz8::encode_normal_xyz8",
        wgsl: Some((prepass::wgsl::NORMAL_XYZ8, "encode_normal_xyz8")),
        twin: |a| V::U32(xyz8::encode_normal_xyz8(a[0].vec3())),
    },
    Func {
        rust: "normal::xyz8::decode_normal_xyz8",
        wgsl: Some((prepass::wgsl::NORMAL_XYZ8, "decode_normal_xyz8")),
        twin: |a| V::Vec3(xyz8::decode_normal_xyz8(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::xyz8::encode_normal_xyz8_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_XYZ8, "encode_normal_xyz8_unorm")),
        twin: |a| V::Vec4(xyz8::encode_normal_xyz8_unorm(a[0].vec3())),
    },
    Func {
        rust: "normal::xyz8::decode_normal_xyz8_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_XYZ8, "decode_normal_xyz8_unorm")),
        twin: |a| V::Vec3(xyz8::decode_normal_xyz8_unorm(normal_vec4(a[0])).to_array()),
    },
    Func {
        rust: "normal::xy_fp16::encode_normal_xy_fp16",
        wgsl: Some((prepass::wgsl::NORMAL_XY_FP16, "encode_normal_xy_fp16")),
        twin: |a| V::U32(xy_fp16::encode_normal_xy_fp16(a[0].vec3())),
    },
    Func {
        rust: "normal::xy_fp16::decode_normal_xy_fp16",
        wgsl: Some((prepass::wgsl::NORMAL_XY_FP16, "decode_normal_xy_fp16")),
        twin: |a| V::Vec3(xy_fp16::decode_normal_xy_fp16(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::xy_fp16::encode_normal_xy_fp16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_XY_FP16, "encode_normal_xy_fp16_unorm")),
        twin: |a| V::Vec4(xy_fp16::encode_normal_xy_fp16_unorm(a[0].vec3())),
    },
    Func {
        rust: "normal::xy_fp16::decode_normal_xy_fp16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_XY_FP16, "decode_normal_xy_fp16_unorm")),
        twin: |a| V::Vec3(xy_fp16::decode_normal_xy_fp16_unorm(normal_vec4(a[0])).to_array()),
    },
    Func {
        rust: "normal::oct::encode_normal_oct16",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct16")),
        twin: |a| V::U32(oct::encode_normal_oct16(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::encode_normal_oct16_fast",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct16_fast")),
        twin: |a| V::U32(oct::encode_normal_oct16_fast(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::decode_normal_oct16",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct16")),
        twin: |a| V::Vec3(oct::decode_normal_oct16(a[0].u32()).to_array()),
    },
    // The WGSL render-target form of oct16 is rg8unorm (vec2); the twin takes [c0, c1, 0, 0].
    Func {
        rust: "normal::oct::encode_normal_oct16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct16_unorm")),
        twin: |a| {
            let c = oct::encode_normal_oct16_unorm(a[0].vec3());
            V::Vec2([c[0], c[1]])
        },
    },
    Func {
        rust: "normal::oct::decode_normal_oct16_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct16_unorm")),
        twin: |a| {
            let c = a[0].vec2();
            V::Vec3(oct::decode_normal_oct16_unorm([c.x, c.y, 0.0, 0.0]).to_array())
        },
    },
    Func {
        rust: "normal::oct::encode_normal_oct24",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct24")),
        twin: |a| V::U32(oct::encode_normal_oct24(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::encode_normal_oct24_fast",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct24_fast")),
        twin: |a| V::U32(oct::encode_normal_oct24_fast(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::decode_normal_oct24",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct24")),
        twin: |a| V::Vec3(oct::decode_normal_oct24(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::oct::encode_normal_oct24_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct24_unorm")),
        twin: |a| V::Vec4(oct::encode_normal_oct24_unorm(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::decode_normal_oct24_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct24_unorm")),
        twin: |a| V::Vec3(oct::decode_normal_oct24_unorm(normal_vec4(a[0])).to_array()),
    },
    Func {
        rust: "normal::oct::encode_normal_oct32",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct32")),
        twin: |a| V::U32(oct::encode_normal_oct32(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::encode_normal_oct32_fast",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct32_fast")),
        twin: |a| V::U32(oct::encode_normal_oct32_fast(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::decode_normal_oct32",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct32")),
        twin: |a| V::Vec3(oct::decode_normal_oct32(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::oct::encode_normal_oct32_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "encode_normal_oct32_unorm")),
        twin: |a| V::Vec4(oct::encode_normal_oct32_unorm(a[0].vec3())),
    },
    Func {
        rust: "normal::oct::decode_normal_oct32_unorm",
        wgsl: Some((prepass::wgsl::NORMAL_OCT, "decode_normal_oct32_unorm")),
        twin: |a| V::Vec3(oct::decode_normal_oct32_unorm(normal_vec4(a[0])).to_array()),
    },
    Func {
        rust: "normal::hemioct::encode_normal_hemioct24",
        wgsl: Some((prepass::wgsl::NORMAL_HEMIOCT, "encode_normal_hemioct24")),
        twin: |a| V::U32(hemioct::encode_normal_hemioct24(a[0].vec3())),
    },
    Func {
        rust: "normal::hemioct::encode_normal_hemioct24_fast",
        wgsl: Some((
            prepass::wgsl::NORMAL_HEMIOCT,
            "encode_normal_hemioct24_fast",
        )),
        twin: |a| V::U32(hemioct::encode_normal_hemioct24_fast(a[0].vec3())),
    },
    Func {
        rust: "normal::hemioct::decode_normal_hemioct24",
        wgsl: Some((prepass::wgsl::NORMAL_HEMIOCT, "decode_normal_hemioct24")),
        twin: |a| V::Vec3(hemioct::decode_normal_hemioct24(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::hemioct::encode_normal_hemioct24_unorm",
        wgsl: Some((
            prepass::wgsl::NORMAL_HEMIOCT,
            "encode_normal_hemioct24_unorm",
        )),
        twin: |a| V::Vec4(hemioct::encode_normal_hemioct24_unorm(a[0].vec3())),
    },
    Func {
        rust: "normal::hemioct::decode_normal_hemioct24_unorm",
        wgsl: Some((
            prepass::wgsl::NORMAL_HEMIOCT,
            "decode_normal_hemioct24_unorm",
        )),
        twin: |a| V::Vec3(hemioct::decode_normal_hemioct24_unorm(normal_vec4(a[0])).to_array()),
    },
    Func {
        rust: "normal::sanitize",
        wgsl: None,
        twin: |a| V::OptVec3(prepass::normal::sanitize(a[0].vec3()).map(|v| v.to_array())),
    },
    Func {
        rust: "normal::xy_fp16::pack2x16float",
        wgsl: None,
        twin: |a| V::U32(xy_fp16::pack2x16float(a[0].vec2())),
    },
    Func {
        rust: "normal::xy_fp16::unpack2x16float",
        wgsl: Some((UNPACK2X16_WGSL, "bad_input_unpack2x16float")),
        twin: |a| V::Vec2(xy_fp16::unpack2x16float(a[0].u32()).to_array()),
    },
    Func {
        rust: "normal::oct::max_code",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::max_code(a[0].u32()))),
    },
    Func {
        rust: "normal::oct::encode_precise",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::encode_precise(a[0].vec3(), a[1].u32()))),
    },
    Func {
        rust: "normal::oct::encode_round",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::U32(oct::encode_round(a[0].vec3(), a[1].u32()))),
    },
    Func {
        rust: "normal::oct::decode",
        wgsl: None,
        twin: |a| normal_or_panic(|| V::Vec3(oct::decode(a[0].u32(), a[1].u32()).to_array())),
    },
];

/// WGSL functions in `wgsl/` that are not public API (private helpers a file needs), exempt
/// from "every WGSL function has rows". Each needs a reason.
pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "ld_one_minus",
        "private to linear_depth.wgsl: exact 1 - z from the bits, exercised by every standard-depth row with z >= 0.5",
    ),
    (
        "ld_is_nan",
        "private to linear_depth.wgsl: NaN test on bits, exercised by every NaN row",
    ),
    (
        "ld_is_inf",
        "private to linear_depth.wgsl: infinite-far test, exercised by the far = +Inf rows",
    ),
    (
        "ld_positive_inf",
        "private to linear_depth.wgsl: builds +Inf from bits for the far-plane rows",
    ),
    (
        "ld_nan",
        "private to linear_depth.wgsl: builds NaN from bits for the NaN rows",
    ),
    (
        "ld_near_over_far",
        "private to linear_depth.wgsl: n/f, 0 when far = +Inf (infinite-far rows)",
    ),
    (
        "ld_divide_or_inf",
        "private to linear_depth.wgsl: n/s, +Inf at s = 0 (far-plane rows)",
    ),
    (
        "log_roughness_boundary_bits",
        "private to roughness.wgsl: table lookup of a code boundary, exercised by the encode rows",
    ),
    (
        "lpp_finite",
        "private to lpp.wgsl: finiteness test on bits, exercised by every NaN/Inf row",
    ),
    (
        "lpp_finite3",
        "private to lpp.wgsl: finiteness test on bits, exercised by every NaN/Inf row",
    ),
    (
        "lpp_light",
        "private to lpp.wgsl: the body of lpp_blinn_phong_light and lpp_phong_light",
    ),
    (
        "aggregate_light_finite3",
        "private to aggregate_light.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    (
        "aggregate_light_unit",
        "private to aggregate_light.wgsl: the guarded normalise behind aggregate_light_direction",
    ),
    (
        "light_volume_finite",
        "private to light_volume.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    (
        "light_volume_finite3",
        "private to light_volume.wgsl: finiteness test on bits, exercised by the NaN/Inf rows",
    ),
    // Normal encodings
    (
        "xyz8_sanitize",
        "private to normal_xyz8.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
    ),
    (
        "xyfp16_sanitize",
        "private to normal_xy_fp16.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
    ),
    (
        "oct_sanitize",
        "private to normal_oct.wgsl: NaN/Inf/subnormal handling, exercised by every encoder row",
    ),
    (
        "oct_continuous",
        "private to normal_oct.wgsl: continuous code coordinates, behind every oct encoder row",
    ),
    (
        "oct_lattice",
        "private to normal_oct.wgsl: a code's integer vector, behind every oct decoder row",
    ),
    (
        "oct_sin2",
        "private to normal_oct.wgsl: the precise encoders' score, behind their rows",
    ),
    (
        "oct_encode_precise",
        "private to normal_oct.wgsl: body of encode_normal_oct16/24/32, each with rows",
    ),
    (
        "oct_encode_round",
        "private to normal_oct.wgsl: body of the _fast encoders, each with rows",
    ),
    (
        "oct_decode",
        "private to normal_oct.wgsl: body of the oct decoders, each with rows",
    ),
    (
        "oct_unorm_bytes",
        "private to normal_oct.wgsl: channels to bytes, exercised by the _unorm decoder rows",
    ),
    (
        "hemioct_sanitize",
        "private to normal_hemioct.wgsl: NaN/Inf/subnormal/z < 0 handling, behind every encoder row",
    ),
    (
        "hemioct_continuous",
        "private to normal_hemioct.wgsl: continuous code coordinates, behind the encoder rows",
    ),
    (
        "hemioct_lattice",
        "private to normal_hemioct.wgsl: a code's integer vector, behind the decoder rows",
    ),
    (
        "hemioct_sin2",
        "private to normal_hemioct.wgsl: the precise encoder's score, behind its rows",
    ),
];

/// One documented answer.
pub struct Row {
    /// [`Func::key`]: the WGSL name, or the Rust path of a Rust-only function.
    pub func: &'static str,
    /// The kind of bad input.
    pub case: &'static str,
    /// The arguments.
    pub args: &'static [V],
    /// What both sides must return (bit for bit; any NaN matches NaN).
    pub expect: V,
    /// Why, in a few words.
    pub why: &'static str,
}

const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;
const SNAN: f32 = f32::from_bits(0x7f80_0001);
const NEG_NAN: f32 = f32::from_bits(0xffc0_0000);
const SUB_MIN: f32 = f32::from_bits(1);
const SUB_MAX: f32 = f32::from_bits(0x007f_ffff);
const MAX24: u32 = depth24::DEPTH24_MAX;
/// The unit z axis: a valid normal, eye and light direction whose cosines are exactly 1.
const ZN: [f32; 3] = [0.0, 0.0, 1.0];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // depth24_from_rgb8: channels clamp to [0, 1], NaN (from its bits) counts as 0.
    Row { func: "depth24_from_rgb8", case: "NaN", args: &[V::Vec3([NAN, NAN, NAN])], expect: V::U32(0), why: "NaN channel → byte 0" },
    Row { func: "depth24_from_rgb8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([NEG_NAN, 1.0, SNAN])], expect: V::U32(0x00ff00), why: "every NaN → byte 0" },
    Row { func: "depth24_from_rgb8", case: "+Inf", args: &[V::Vec3([INF, INF, INF])], expect: V::U32(MAX24), why: "clamped to 1 → byte 255" },
    Row { func: "depth24_from_rgb8", case: "−Inf", args: &[V::Vec3([-INF, -INF, -INF])], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "depth24_from_rgb8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0), why: "rounds to byte 0, flushed or not" },
    Row { func: "depth24_from_rgb8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth24_from_rgb8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth24_from_rgb8", case: "out of range", args: &[V::Vec3([-1.0, 2.0, 1.5])], expect: V::U32(0x00ffff), why: "clamped to [0, 1]" },
    Row { func: "depth24_from_rgb8", case: "huge", args: &[V::Vec3([f32::MAX, f32::MIN, 0.5])], expect: V::U32(0xff0080), why: "clamped; 127.5 rounds half to even" },
    // depth24_from_packed: pure bit operations, every u32 is valid.
    Row { func: "depth24_from_packed", case: "alpha byte set", args: &[V::U32(0xff12_3456)], expect: V::U32(0x56_3412), why: "byte 3 ignored" },
    Row { func: "depth24_from_packed", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(MAX24), why: "byte 3 ignored" },
    Row { func: "depth24_from_packed", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // pack_depth24: codes above 2^24 − 1 saturate.
    Row { func: "pack_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::U32(0x00ff_ffff), why: "saturates to 2^24 − 1" },
    Row { func: "pack_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::U32(0x00ff_ffff), why: "saturates; alpha stays 0" },
    Row { func: "pack_depth24", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // hyperbolic_depth_from_depth24: codes above 2^24 − 1 saturate to 1.0.
    Row { func: "hyperbolic_depth_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "hyperbolic_depth_from_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "hyperbolic_depth_from_depth24", case: "zero", args: &[V::U32(0)], expect: V::F32(0.0), why: "+0.0, never −0.0" },
    // unpack4x8unorm: every u32 is four valid bytes.
    Row { func: "unpack4x8unorm", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec4([1.0; 4]), why: "255/255 = 1 exactly" },
    Row { func: "unpack4x8unorm", case: "zero", args: &[V::U32(0)], expect: V::Vec4([0.0; 4]), why: "+0.0 lanes" },
    // Linear depth (near 1, far 2 unless stated: every expected value below is exact in f32).
    Row { func: "view_z_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24", case: "out-of-range code, far +Inf", args: &[V::U32(u32::MAX), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "far code of an infinite projection → +Inf" },
    Row { func: "view_z_from_depth24", case: "zero", args: &[V::U32(0), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "code 0 = near plane" },
    Row { func: "view_z_from_depth24_consts", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Vec2([16_777_215.0, 0.5])], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "view_z_from_depth24_consts", case: "far +Inf (n/f = 0)", args: &[V::U32(MAX24), V::Vec2([16_777_215.0, 0.0])], expect: V::F32(INF), why: "far code → +Inf" },
    Row { func: "view_z_from_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN (found from its bits)" },
    Row { func: "view_z_from_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 1 = far" },
    Row { func: "view_z_from_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_depth", case: "subnormal", args: &[V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "near, flushed or not" },
    Row { func: "view_z_from_depth", case: "out of range", args: &[V::F32(1.5), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "clamped to 1; infinite far → +Inf" },
    Row { func: "view_z_from_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_depth_consts", case: "out of range", args: &[V::F32(-3.0), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "view_z_from_reversed_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_reversed_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 1 = near" },
    Row { func: "view_z_from_reversed_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 0 = far" },
    Row { func: "view_z_from_reversed_depth", case: "subnormal", args: &[V::F32(SUB_MIN), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "far, flushed or not" },
    Row { func: "view_z_from_reversed_depth", case: "zero, far +Inf (sky)", args: &[V::F32(0.0), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "the sky of reversed-infinite → +Inf" },
    Row { func: "view_z_from_reversed_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "view_z_from_reversed_depth_consts", case: "−0.0, infinite (k = (1, 1, 0))", args: &[V::F32(-0.0), V::Vec3([1.0, 1.0, 0.0])], expect: V::F32(INF), why: "the sky → +Inf" },
    Row { func: "projection::Projection::new", case: "NaN near", args: &[V::F32(NAN), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(near)"), why: "names the field" },
    Row { func: "projection::Projection::new", case: "zero near", args: &[V::F32(0.0), V::F32(1.0), V::Bool(true)], expect: V::Text("Err(near)"), why: "near must be > 0" },
    Row { func: "projection::Projection::new", case: "subnormal near", args: &[V::F32(SUB_MAX), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(near)"), why: "near must be a normal float" },
    Row { func: "projection::Projection::new", case: "+Inf near", args: &[V::F32(INF), V::F32(INF), V::Bool(false)], expect: V::Text("Err(near)"), why: "near must be finite" },
    Row { func: "projection::Projection::new", case: "NaN far", args: &[V::F32(1.0), V::F32(NAN), V::Bool(false)], expect: V::Text("Err(far)"), why: "names the field" },
    Row { func: "projection::Projection::new", case: "far ≤ near", args: &[V::F32(1.0), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(far)"), why: "far must exceed near" },
    Row { func: "projection::Projection::new", case: "out of range: near·(2^24 − 1) overflows", args: &[V::F32(1e32), V::F32(INF), V::Bool(false)], expect: V::Text("Err(near)"), why: "the 24-bit path would overflow" },
    Row { func: "projection::Projection::new", case: "out of range: far/near > 2^126", args: &[V::F32(1e-4), V::F32(1e36), V::Bool(false)], expect: V::Text("Err(far)"), why: "n/f would be subnormal: use +Inf" },
    Row { func: "projection::Projection::new", case: "+Inf far", args: &[V::F32(0.1), V::F32(INF), V::Bool(true)], expect: V::Text("Ok"), why: "infinite projection" },
    // Position rebuild: plain products and sums; NaN and ±Inf propagate as IEEE arithmetic does.
    Row { func: "frustum_ray", case: "NaN", args: &[V::Vec2([NAN, 0.5]), V::Vec2([1.0, 2.0])], expect: V::Vec3([NAN, 1.0, 1.0]), why: "propagates per lane; z stays 1" },
    Row { func: "frustum_ray", case: "+Inf", args: &[V::Vec2([INF, -INF]), V::Vec2([1.0, 2.0])], expect: V::Vec3([INF, -INF, 1.0]), why: "propagates per lane" },
    Row { func: "frustum_ray_rh", case: "zero vector", args: &[V::Vec2([0.0, 0.0]), V::Vec2([0.0, 0.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "the view axis" },
    Row { func: "view_position", case: "+Inf view z (sky)", args: &[V::Vec3([0.5, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "view_position", case: "NaN view z", args: &[V::Vec3([0.5, 0.0, 1.0]), V::F32(NAN)], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index 3", args: &[V::U32(3)], expect: V::Vec2([3.0, 3.0]), why: "low two bits: off screen" },
    Row { func: "fullscreen_triangle_ndc", case: "out-of-range index u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Vec2([3.0, 3.0]), why: "low two bits" },
    Row { func: "fullscreen_triangle_ray", case: "out-of-range index 6", args: &[V::U32(6), V::Vec2([1.0, 0.5])], expect: V::Vec3([-1.0, 1.5, 1.0]), why: "index 6 reads as 2" },
    Row { func: "fullscreen_triangle_ray_rh", case: "NaN", args: &[V::U32(0), V::Vec2([NAN, 1.0])], expect: V::Vec3([NAN, -1.0, -1.0]), why: "propagates per lane" },
    Row { func: "ndc_from_uv", case: "out of range", args: &[V::Vec2([2.0, -1.0])], expect: V::Vec2([3.0, 3.0]), why: "not clamped" },
    Row { func: "ndc_from_uv", case: "NaN", args: &[V::Vec2([NAN, 0.25])], expect: V::Vec2([NAN, 0.5]), why: "propagates per lane" },
    Row { func: "world_ray", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "0·NaN = NaN in every lane" },
    Row { func: "world_ray", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 0.0, 0.0]), why: "zero" },
    Row { func: "camera_relative_position", case: "+Inf view z (sky)", args: &[V::Vec3([1.0, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "world_position", case: "+Inf camera", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(1.0), V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([INF, 0.0, 0.0]), why: "propagates" },
    Row { func: "world_position", case: "NaN view z", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(NAN), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
    // Exact references (Rust only).
    Row { func: "depth24::exact::hyperbolic_depth", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth24::exact::hyperbolic_depth", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth24::exact::nearest_code", case: "NaN", args: &[V::F32(NAN)], expect: V::OptU32(None), why: "no code" },
    Row { func: "depth24::exact::nearest_code", case: "+Inf", args: &[V::F32(INF)], expect: V::OptU32(None), why: "above 1" },
    Row { func: "depth24::exact::nearest_code", case: "−Inf", args: &[V::F32(-INF)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth24::exact::nearest_code", case: "−0.0", args: &[V::F32(-0.0)], expect: V::OptU32(Some(0)), why: "−0.0 is 0" },
    Row { func: "depth24::exact::nearest_code", case: "subnormal", args: &[V::F32(SUB_MIN)], expect: V::OptU32(Some(0)), why: "rounds to code 0" },
    Row { func: "depth24::exact::nearest_code", case: "negative subnormal", args: &[V::F32(-SUB_MIN)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth24::exact::nearest_code", case: "out of range", args: &[V::F32(1.000_000_1)], expect: V::OptU32(None), why: "above 1" },
    // Precision metrics (Rust only): NaN propagates as None/NaN, infinities are ordinary ends.
    Row { func: "precision::metrics::ordinal", case: "NaN", args: &[V::F32(NAN)], expect: V::OptI64(None), why: "NaN has no position" },
    Row { func: "precision::metrics::ordinal", case: "+Inf", args: &[V::F32(INF)], expect: V::OptI64(Some(0x7f80_0000)), why: "one past f32::MAX" },
    Row { func: "precision::metrics::ordinal", case: "−0.0", args: &[V::F32(-0.0)], expect: V::OptI64(Some(0)), why: "same position as +0.0" },
    Row { func: "precision::metrics::ulp_distance", case: "NaN", args: &[V::F32(NAN), V::F32(1.0)], expect: V::OptU64(None), why: "no distance" },
    Row { func: "precision::metrics::ulp_distance", case: "+Inf", args: &[V::F32(f32::MAX), V::F32(INF)], expect: V::OptU64(Some(1)), why: "Inf is one past MAX" },
    Row { func: "precision::metrics::ulp_distance", case: "signed zeros", args: &[V::F32(0.0), V::F32(-0.0)], expect: V::OptU64(Some(0)), why: "±0 coincide" },
    Row { func: "precision::metrics::step_ulps", case: "NaN", args: &[V::F32(NAN), V::I64(1)], expect: V::F32(NAN), why: "returned unchanged" },
    Row { func: "precision::metrics::step_ulps", case: "past f32::MAX", args: &[V::F32(f32::MAX), V::I64(5)], expect: V::F32(INF), why: "saturates at ±Inf" },
    Row { func: "precision::metrics::step_ulps", case: "through zero", args: &[V::F32(0.0), V::I64(-1)], expect: V::F32(-SUB_MIN), why: "−0 skipped, first negative subnormal" },
    Row { func: "precision::metrics::f32_ulp_at", case: "NaN", args: &[V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "no ULP" },
    Row { func: "precision::metrics::f32_ulp_at", case: "+Inf", args: &[V::F64(f64::INFINITY)], expect: V::F64(f64::NAN), why: "no ULP" },
    Row { func: "precision::metrics::f32_ulp_at", case: "zero", args: &[V::F64(0.0)], expect: V::F64(1.401298464324817e-45), why: "subnormal spacing 2^-149" },
    Row { func: "precision::metrics::f32_ulp_at", case: "out of f32 range", args: &[V::F64(1e300)], expect: V::F64(2.028240960365167e31), why: "capped at 2^104, the ULP of f32::MAX" },
    Row { func: "precision::metrics::ulp_error", case: "NaN", args: &[V::F32(NAN), V::F64(1.0)], expect: V::F64(f64::NAN), why: "counted apart by ErrorStats" },
    Row { func: "precision::metrics::ulp_error", case: "+Inf", args: &[V::F32(INF), V::F64(f64::INFINITY)], expect: V::F64(0.0), why: "an exact infinity matches itself" },
    Row { func: "precision::metrics::ulp_error", case: "finite vs +Inf", args: &[V::F32(f32::MAX), V::F64(f64::INFINITY)], expect: V::F64(f64::INFINITY), why: "never within a bound" },
    Row { func: "precision::metrics::relative_error", case: "zero reference", args: &[V::F64(1.0), V::F64(0.0)], expect: V::F64(f64::INFINITY), why: "only 0 matches 0" },
    Row { func: "precision::metrics::relative_error", case: "zero vs zero", args: &[V::F64(-0.0), V::F64(0.0)], expect: V::F64(0.0), why: "exact" },
    Row { func: "precision::metrics::relative_error", case: "NaN", args: &[V::F64(f64::NAN), V::F64(1.0)], expect: V::F64(f64::NAN), why: "propagates" },
    Row { func: "precision::metrics::angle_degrees", case: "zero vector", args: &[V::F64x3([0.0; 3]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "NaN", args: &[V::F64x3([f64::NAN, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "+Inf", args: &[V::F64x3([f64::INFINITY, 0.0, 0.0]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "subnormal", args: &[V::F64x3([1e-320, 0.0, 0.0]), V::F64x3([0.0, 1.0, 0.0])], expect: V::F64(90.0), why: "any non-zero length is a direction" },
    Row { func: "precision::metrics::widen3", case: "NaN, ±Inf", args: &[V::Vec3([NAN, INF, -INF])], expect: V::F64x3([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]), why: "exact widening" },
    // Test-input builders (Rust only).
    Row { func: "precision::inputs::unorm8_channel", case: "out-of-range byte", args: &[V::U32(256), V::Channel(ChannelError::Exact), V::Bool(false)], expect: V::F32(1.003_921_6), why: "not clamped: 256/255, for out-of-range inputs" },
    Row { func: "precision::inputs::unorm8_channel", case: "pushed below 0", args: &[V::U32(0), V::Channel(ChannelError::Ulps(3)), V::Bool(true)], expect: V::F32(-4e-45), why: "3 ULP below +0: negative subnormal" },
    Row { func: "precision::inputs::unorm8_channel", case: "NaN offset", args: &[V::U32(7), V::Channel(ChannelError::Offset(f64::NAN)), V::Bool(false)], expect: V::F32(NAN), why: "propagates" },
    Row { func: "precision::inputs::rgb8_channels", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Channel(ChannelError::Exact), V::Bool(false)], expect: V::Vec3([1.0, 1.0, 1.0]), why: "saturates to 2^24 − 1" },
    // Log roughness (max_power 8192 = 2^13 unless stated; power-of-two ranges are exact tables).
    Row { func: "log_roughness_range_log2", case: "NaN", args: &[V::F32(NAN)], expect: V::U32(0), why: "degenerate: only power 1" },
    Row { func: "log_roughness_range_log2", case: "≤ 1 (1.0)", args: &[V::F32(1.0)], expect: V::U32(0), why: "degenerate: only power 1" },
    Row { func: "log_roughness_range_log2", case: "negative", args: &[V::F32(-8.0)], expect: V::U32(0), why: "degenerate" },
    Row { func: "log_roughness_range_log2", case: "subnormal", args: &[V::F32(SUB_MAX)], expect: V::U32(0), why: "degenerate (≤ 1)" },
    Row { func: "log_roughness_range_log2", case: "+Inf", args: &[V::F32(INF)], expect: V::U32(127), why: "acts as 2^127" },
    Row { func: "log_roughness_range_log2", case: "out of range: above 2^127", args: &[V::F32(f32::MAX)], expect: V::U32(127), why: "acts as 2^127" },
    Row { func: "log_roughness_range_log2", case: "not a power of two", args: &[V::F32(1000.0)], expect: V::U32(u32::MAX), why: "general range (log2/exp2)" },
    Row { func: "encode_log_roughness", case: "NaN power", args: &[V::F32(NAN), V::F32(8192.0)], expect: V::U32(0), why: "code 0" },
    Row { func: "encode_log_roughness", case: "−NaN power, general range", args: &[V::F32(NEG_NAN), V::F32(1000.0)], expect: V::U32(0), why: "code 0" },
    Row { func: "encode_log_roughness", case: "+Inf power", args: &[V::F32(INF), V::F32(8192.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "+Inf power, general range", args: &[V::F32(INF), V::F32(1000.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "−Inf power", args: &[V::F32(-INF), V::F32(8192.0)], expect: V::U32(0), why: "negative → 0" },
    Row { func: "encode_log_roughness", case: "negative power", args: &[V::F32(-100.0), V::F32(8192.0)], expect: V::U32(0), why: "negative → 0" },
    Row { func: "encode_log_roughness", case: "subnormal power", args: &[V::F32(SUB_MAX), V::F32(8192.0)], expect: V::U32(0), why: "≤ 1 → 0" },
    Row { func: "encode_log_roughness", case: "zero power (−0.0)", args: &[V::F32(-0.0), V::F32(8192.0)], expect: V::U32(0), why: "≤ 1 → 0" },
    Row { func: "encode_log_roughness", case: "out of range: power above max", args: &[V::F32(1e9), V::F32(8192.0)], expect: V::U32(255), why: "≥ max_power → 255" },
    Row { func: "encode_log_roughness", case: "out of range: f32::MAX, max_power +Inf", args: &[V::F32(f32::MAX), V::F32(INF)], expect: V::U32(255), why: "max_power acts as 2^127" },
    Row { func: "encode_log_roughness", case: "NaN max_power", args: &[V::F32(100.0), V::F32(NAN)], expect: V::U32(0), why: "degenerate range → 0" },
    Row { func: "encode_log_roughness", case: "out of range: max_power ≤ 1", args: &[V::F32(100.0), V::F32(0.5)], expect: V::U32(0), why: "degenerate range → 0" },
    Row { func: "decode_log_roughness", case: "out-of-range code 256", args: &[V::U32(256), V::F32(8192.0)], expect: V::F32(8192.0), why: "decodes as 255" },
    Row { func: "decode_log_roughness", case: "out-of-range code, general range", args: &[V::U32(u32::MAX), V::F32(1000.0)], expect: V::F32(1000.0), why: "decodes as 255 = max_power" },
    Row { func: "decode_log_roughness", case: "NaN max_power", args: &[V::U32(200), V::F32(NAN)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "−Inf max_power", args: &[V::U32(200), V::F32(-INF)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "subnormal max_power", args: &[V::U32(255), V::F32(SUB_MIN)], expect: V::F32(1.0), why: "degenerate range → 1" },
    Row { func: "decode_log_roughness", case: "+Inf max_power", args: &[V::U32(255), V::F32(INF)], expect: V::F32(1.7014118e38), why: "acts as 2^127" },
    Row { func: "pack_normal_xyz8_log_roughness", case: "out-of-range code, byte 3 set", args: &[V::U32(0xff12_3456), V::U32(999)], expect: V::U32(0xff12_3456), why: "byte 3 replaced; code saturates to 255" },
    Row { func: "pack_normal_xyz8_log_roughness", case: "out-of-range code u32::MAX", args: &[V::U32(0x0000_0080), V::U32(u32::MAX)], expect: V::U32(0xff00_0080), why: "code saturates to 255" },
    Row { func: "normal_xyz8_from_log_roughness_texel", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(0x00ff_ffff), why: "byte 3 dropped" },
    Row { func: "log_roughness_code_from_texel", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(255), why: "every texel holds a valid code" },
    Row { func: "roughness::quantisation_limit", case: "NaN", args: &[V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "propagates" },
    Row { func: "roughness::quantisation_limit", case: "max_power 1", args: &[V::F64(1.0)], expect: V::F64(0.0), why: "one code: no step" },
    Row { func: "roughness::quantisation_limit", case: "+Inf", args: &[V::F64(f64::INFINITY)], expect: V::F64(f64::INFINITY), why: "unbounded step" },
    Row { func: "roughness::exact::decode", case: "out-of-range code", args: &[V::U32(300), V::F64(8192.0)], expect: V::F64(8192.0), why: "decodes as 255, like the twin" },
    Row { func: "roughness::exact::decode", case: "NaN max_power", args: &[V::U32(10), V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "propagates (reference only)" },
    Row { func: "roughness::exact::encode", case: "NaN power", args: &[V::F64(f64::NAN), V::F64(8192.0)], expect: V::U32(0), why: "NaN casts to code 0" },
    Row { func: "roughness::exact::encode", case: "+Inf power", args: &[V::F64(f64::INFINITY), V::F64(8192.0)], expect: V::U32(255), why: "clamped to 255" },
    Row { func: "roughness::exact::encode", case: "out of range: power below 1", args: &[V::F64(0.25), V::F64(8192.0)], expect: V::U32(0), why: "clamped to 0" },
    // Light pre-pass (unit vectors along z unless stated: every expected value below is exact).
    Row { func: "lpp_direction", case: "NaN", args: &[V::Vec3([NAN, 0.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "+Inf", args: &[V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "zero vector", args: &[V::Vec3([0.0; 3])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0; 3])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "lpp_direction", case: "subnormal", args: &[V::Vec3([SUB_MAX, -SUB_MIN, 0.0])], expect: V::Vec3([0.0; 3]), why: "largest component subnormal → zero" },
    Row { func: "lpp_direction", case: "huge (|v|² would overflow)", args: &[V::Vec3([-f32::MAX, 0.0, 0.0])], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "scaled by the largest component first" },
    Row { func: "lpp_luminance", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::F32(NAN), why: "plain dot: propagates" },
    Row { func: "lpp_luminance", case: "+Inf", args: &[V::Vec3([INF, 0.0, 0.0])], expect: V::F32(INF), why: "plain dot: propagates" },
    Row { func: "lpp_luminance", case: "+Inf − Inf", args: &[V::Vec3([INF, -INF, 0.0])], expect: V::F32(NAN), why: "∞ − ∞" },
    Row { func: "lpp_luminance", case: "negative channel", args: &[V::Vec3([-1.0, 0.0, 0.0])], expect: V::F32(-0.2126), why: "not clamped (callers clamp colours first)" },
    Row { func: "lpp_pow_cosine", case: "NaN cosine", args: &[V::F32(NAN), V::F32(8.0)], expect: V::F32(0.0), why: "x ≤ 0 or NaN → 0" },
    Row { func: "lpp_pow_cosine", case: "N·H > 1", args: &[V::F32(1.5), V::F32(8.0)], expect: V::F32(1.0), why: "x ≥ 1 → 1" },
    Row { func: "lpp_pow_cosine", case: "+Inf cosine", args: &[V::F32(INF), V::F32(8.0)], expect: V::F32(1.0), why: "x ≥ 1 → 1" },
    Row { func: "lpp_pow_cosine", case: "−Inf cosine", args: &[V::F32(-INF), V::F32(8.0)], expect: V::F32(0.0), why: "x ≤ 0 → 0" },
    Row { func: "lpp_pow_cosine", case: "zero cosine, zero power", args: &[V::F32(0.0), V::F32(0.0)], expect: V::F32(0.0), why: "0^y = 0, even for y = 0" },
    Row { func: "lpp_pow_cosine", case: "zero power", args: &[V::F32(0.5), V::F32(0.0)], expect: V::F32(1.0), why: "x^0 = 1 for x > 0" },
    Row { func: "lpp_pow_cosine", case: "subnormal cosine", args: &[V::F32(SUB_MIN), V::F32(1.0)], expect: V::F32(0.0), why: "below 2^-126 → 0, flushed or not" },
    Row { func: "lpp_pow_cosine", case: "NaN power", args: &[V::F32(0.5), V::F32(NAN)], expect: V::F32(0.0), why: "no highlight" },
    Row { func: "lpp_pow_cosine", case: "+Inf power", args: &[V::F32(0.5), V::F32(INF)], expect: V::F32(0.0), why: "x^∞ = 0 for x < 1" },
    Row { func: "lpp_pow_cosine", case: "negative power", args: &[V::F32(0.5), V::F32(-3.0)], expect: V::F32(1.0), why: "acts as power 0" },
    Row { func: "lpp_point_attenuation", case: "NaN distance", args: &[V::F32(NAN), V::F32(2.0)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "+Inf distance", args: &[V::F32(INF), V::F32(2.0)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "+Inf radius", args: &[V::F32(1.0), V::F32(INF)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_point_attenuation", case: "zero radius", args: &[V::F32(0.0), V::F32(0.0)], expect: V::F32(0.0), why: "r ≤ 0 → 0" },
    Row { func: "lpp_point_attenuation", case: "negative radius", args: &[V::F32(0.0), V::F32(-2.0)], expect: V::F32(0.0), why: "r ≤ 0 → 0" },
    Row { func: "lpp_point_attenuation", case: "subnormal radius", args: &[V::F32(1.0), V::F32(SUB_MAX)], expect: V::F32(0.0), why: "beyond the radius, flushed or not" },
    Row { func: "lpp_point_attenuation", case: "negative distance", args: &[V::F32(-1.0), V::F32(2.0)], expect: V::F32(1.0), why: "counts as 0: full light" },
    Row { func: "lpp_point_attenuation", case: "out of range: beyond the radius", args: &[V::F32(3.0), V::F32(2.0)], expect: V::F32(0.0), why: "windowed to 0" },
    Row { func: "lpp_spot_attenuation", case: "NaN", args: &[V::F32(NAN), V::F32(0.5), V::F32(0.9)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_spot_attenuation", case: "+Inf cos_inner", args: &[V::F32(1.0), V::F32(0.5), V::F32(INF)], expect: V::F32(0.0), why: "no light" },
    Row { func: "lpp_spot_attenuation", case: "cos_inner = cos_outer, inside", args: &[V::F32(0.5), V::F32(0.5), V::F32(0.5)], expect: V::F32(1.0), why: "hard edge at cos_outer" },
    Row { func: "lpp_spot_attenuation", case: "cos_inner < cos_outer, outside", args: &[V::F32(0.4), V::F32(0.5), V::F32(0.2)], expect: V::F32(0.0), why: "hard edge at cos_outer" },
    Row { func: "lpp_spot_attenuation", case: "out of range: cosine 2", args: &[V::F32(2.0), V::F32(0.5), V::F32(0.9)], expect: V::F32(1.0), why: "clamped to [0, 1]" },
    Row { func: "lpp_spot_attenuation", case: "out of range: cosine −2", args: &[V::F32(-2.0), V::F32(0.5), V::F32(0.9)], expect: V::F32(0.0), why: "clamped to [0, 1]" },
    Row { func: "lpp_cosines", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "subnormal normal", args: &[V::Vec3([0.0, 0.0, SUB_MAX]), V::Vec3(ZN), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "zero to_eye", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "NaN to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([NAN, 0.0, 1.0]), V::U32(1)], expect: V::Vec2([0.0, 0.0]), why: "no light" },
    Row { func: "lpp_cosines", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::U32(0)], expect: V::Vec2([0.0, 0.0]), why: "no highlight without N·L" },
    Row { func: "lpp_cosines", case: "N·L < 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, -1.0]), V::U32(1)], expect: V::Vec2([0.0, 0.0]), why: "clamped at 0" },
    Row { func: "lpp_cosines", case: "N·H at its maximum 1", args: &[V::Vec3([0.0, 0.0, 4.0]), V::Vec3(ZN), V::Vec3([0.0, 0.0, 2.0]), V::U32(0)], expect: V::Vec2([1.0, 1.0]), why: "any length; clamped to [0, 1]" },
    Row { func: "lpp_blinn_phong_light", case: "NaN colour", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([NAN, 1.0, 1.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "+Inf colour", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([INF, 1.0, 1.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "NaN power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(NAN)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "+Inf power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(INF)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "−Inf attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(-INF), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "subnormal to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, SUB_MIN]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "attenuation 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(0.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_blinn_phong_light", case: "negative attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(-2.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "clamped to 0" },
    Row { func: "lpp_blinn_phong_light", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-1.0, 2.0, -3.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 2.0, 0.0, 1.4304]), why: "channels clamped to [0, 65504]" },
    Row { func: "lpp_blinn_phong_light", case: "negative power", args: &[V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(-4.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to 0: (N·H)^0 = 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: power 1e30", args: &[V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(1e30)], expect: V::Vec4([0.0, 1.0, 0.0, 0.0]), why: "clamped to 65504: 0.707^65504 → 0" },
    Row { func: "lpp_blinn_phong_light", case: "subnormal power, N·H = 1", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(SUB_MAX)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "1^y = 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: attenuation 2", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(2.0), V::F32(8.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to 1" },
    Row { func: "lpp_blinn_phong_light", case: "out of range: colour 1e9", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1e9, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 65504.0, 0.0, 46848.46]), why: "clamped to 65504 (fp16 max)" },
    Row { func: "lpp_phong_light", case: "NaN normal", args: &[V::Vec3([NAN, 0.0, 1.0]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "zero to_eye", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "N·L = 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "NaN attenuation", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(NAN), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_phong_light", case: "R·V at its maximum 1, negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-1.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec4([0.0, 1.0, 0.0, 0.7152]), why: "clamped to [0, 1]; colour clamped at 0" },
    Row { func: "lpp_point_light", case: "zero radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "negative radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, -2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "NaN radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, NAN]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_point_light", case: "zero to_light (light at the surface)", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "no direction → zero light" },
    Row { func: "lpp_point_light", case: "+Inf to_light", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, INF]), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "zero light" },
    Row { func: "lpp_point_light", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 0.0, 1e-30]), V::Vec4([-1.0, -1.0, -1.0, 2.0]), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "colour clamped to 0" },
    Row { func: "lpp_spot_light", case: "zero-length axis", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, 0.0, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "cosine 0: outside the cone" },
    Row { func: "lpp_spot_light", case: "NaN cos_inner", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, -1.0, 0.5]), V::F32(NAN), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "cone factor 0" },
    Row { func: "lpp_spot_light", case: "+Inf axis", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 2.0]), V::Vec4([0.0, 0.0, -INF, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "no axis: cosine 0, outside the cone" },
    Row { func: "lpp_spot_light", case: "zero radius", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec4([0.0, 1.0, 0.0, 0.0]), V::Vec4([0.0, 0.0, -1.0, 0.5]), V::F32(0.9), V::F32(8.0)], expect: V::Vec4([0.0; 4]), why: "attenuation 0" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "NaN power", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(NAN)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "zero-length normal", args: &[V::Vec3([-0.0; 3]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "attenuation 0", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([0.0, 1.0, 0.0]), V::F32(0.0), V::F32(8.0)], expect: V::Vec3([0.0; 3]), why: "zero light" },
    Row { func: "lpp_blinn_phong_specular_rgb", case: "N·H at its maximum 1, negative intensity", args: &[V::Vec3(ZN), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([-5.0, 1.0, 0.0]), V::F32(1.0), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "(N·H)^n = 1; colour clamped at 0" },
    Row { func: "lpp_reconstruct_specular", case: "NaN light", args: &[V::Vec4([NAN, 1.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "+Inf a", args: &[V::Vec4([0.0, 1.0, 0.0, INF]), V::F32(8.0)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "NaN material power", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(NAN)], expect: V::F32(0.0), why: "no specular" },
    Row { func: "lpp_reconstruct_specular", case: "zero diffuse (lum 0)", args: &[V::Vec4([0.0, 0.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "nothing to divide by" },
    Row { func: "lpp_reconstruct_specular", case: "negative diffuse", args: &[V::Vec4([-1.0, -1.0, -1.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "clamped at 0: lum 0" },
    Row { func: "lpp_reconstruct_specular", case: "subnormal luminance", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 0.5]), V::F32(8.0)], expect: V::F32(0.0), why: "lum below 2^-126 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "zero a", args: &[V::Vec4([0.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::F32(0.0), why: "a ≤ 0 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "negative a", args: &[V::Vec4([0.0, 1.0, 0.0, -1.0]), V::F32(8.0)], expect: V::F32(0.0), why: "a ≤ 0 → 0" },
    Row { func: "lpp_reconstruct_specular", case: "out of range: a > lum (ratio > 1)", args: &[V::Vec4([0.0, 1.0, 0.0, 5.0]), V::F32(8.0)], expect: V::F32(0.7152), why: "ratio clamped to 1: never above lum" },
    Row { func: "lpp_reconstruct_specular", case: "negative material power", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(-2.0)], expect: V::F32(0.7152), why: "clamped to 0: ratio^0 = 1" },
    Row { func: "lpp_reconstruct_specular", case: "out of range: material power 1e30", args: &[V::Vec4([0.0, 1.0, 0.0, 0.5]), V::F32(1e30)], expect: V::F32(0.0), why: "clamped to 65504: 0.7^65504 → 0" },
    Row { func: "lpp_combine", case: "NaN albedo", args: &[V::Vec3([NAN, 1.0, 0.0]), V::Vec3([0.0; 3]), V::Vec4([1.0, 1.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN channel → 0" },
    Row { func: "lpp_combine", case: "NaN light", args: &[V::Vec3([1.0; 3]), V::Vec3([1.0; 3]), V::Vec4([NAN, 1.0, 0.0, 0.5]), V::F32(8.0)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN channel → 0; no specular" },
    Row { func: "lpp_combine", case: "+Inf gloss", args: &[V::Vec3([0.0; 3]), V::Vec3([INF, 0.0, 0.0]), V::Vec4([0.0, 1.0, 0.0, 5.0]), V::F32(8.0)], expect: V::Vec3([46848.46, 0.0, 0.0]), why: "gloss clamped to 65504" },
    Row { func: "lpp_combine", case: "negative light", args: &[V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec4([-1.0, 2.0, 0.0, 0.0]), V::F32(8.0)], expect: V::Vec3([0.0, 2.0, 0.0]), why: "lights never subtract" },
    Row { func: "lpp_combine_two_buffers", case: "NaN, −1 albedo", args: &[V::Vec3([NAN, 1.0, -1.0]), V::Vec3([0.0; 3]), V::Vec3([1.0; 3]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "NaN → 0, clamped at 0" },
    Row { func: "lpp_combine_two_buffers", case: "+Inf diffuse", args: &[V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec3([INF, 2.0, 0.0]), V::Vec3([0.0; 3])], expect: V::Vec3([65504.0, 2.0, 0.0]), why: "clamped to 65504" },
    Row { func: "lpp_combine_two_buffers", case: "−Inf specular", args: &[V::Vec3([0.0; 3]), V::Vec3([1.0; 3]), V::Vec3([0.0; 3]), V::Vec3([-INF, 3.0, NAN])], expect: V::Vec3([0.0, 3.0, 0.0]), why: "clamped at 0; NaN → 0" },
    Row { func: "lpp_clamp_colour", case: "NaN, ±Inf", args: &[V::Vec3([NAN, -INF, INF])], expect: V::Vec3([0.0, 0.0, 65504.0]), why: "NaN → 0, clamped to [0, 65504]" },
    Row { func: "lpp_clamp_colour", case: "−NaN, out of range", args: &[V::Vec3([NEG_NAN, -3.0, 1e9])], expect: V::Vec3([0.0, 0.0, 65504.0]), why: "clamped to [0, 65504]" },
    Row { func: "lighting::lpp::exact::unit", case: "zero vector", args: &[V::F64x3([0.0; 3])], expect: V::F64x3([0.0; 3]), why: "zero, like the twins" },
    Row { func: "lighting::lpp::exact::unit", case: "NaN", args: &[V::F64x3([f64::NAN, 0.0, 1.0])], expect: V::F64x3([f64::NAN; 3]), why: "propagates (reference only)" },
    // Aggregate lights (accumulator (1, 2, 3, 4) where a skipped light must leave it unchanged).
    Row { func: "aggregate_light_accumulate", case: "NaN vertex", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([NAN, 0.0, 0.0]), V::Vec3(ZN), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "+Inf light position", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([0.0, INF, 0.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "NaN weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(NAN)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "+Inf weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(INF)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate", case: "zero vector (light at the vertex)", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([5.0, 5.0, 5.0]), V::Vec3([5.0, 5.0, 5.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "no direction: skipped" },
    Row { func: "aggregate_light_accumulate", case: "within 2^-64 of the vertex", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([1e-20, -1e-20, 0.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "no direction: skipped" },
    Row { func: "aggregate_light_accumulate", case: "P − V overflows", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([-3e38, 0.0, 0.0]), V::Vec3([3e38, 0.0, 0.0]), V::F32(1.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "non-finite: skipped" },
    Row { func: "aggregate_light_accumulate", case: "negative intensity", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3([0.0, 3.0, 4.0]), V::F32(-5.0)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "clamped to 0: adds nothing" },
    Row { func: "aggregate_light_accumulate", case: "subnormal weight", args: &[V::Vec4([1.0, 2.0, 3.0, 4.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(SUB_MAX)], expect: V::Vec4([1.0, 2.0, 3.0, 4.0]), why: "adds below half an ULP of the sums" },
    Row { func: "aggregate_light_accumulate", case: "out of range: weight 1e20", args: &[V::Vec4([0.0; 4]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::F32(1e20)], expect: V::Vec4([0.0, 0.0, 1_099_511_627_776.0, 1_099_511_627_776.0]), why: "clamped to 2^40" },
    Row { func: "aggregate_light_direction", case: "NaN", args: &[V::Vec4([NAN, 0.0, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "+Inf", args: &[V::Vec4([0.0, -INF, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "zero vector (directions cancel)", args: &[V::Vec4([0.0, 0.0, 0.0, 2.0])], expect: V::Vec3([0.0; 3]), why: "zero direction" },
    Row { func: "aggregate_light_direction", case: "subnormal", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "largest component subnormal → zero" },
    Row { func: "aggregate_light_direction", case: "huge", args: &[V::Vec4([0.0, f32::MAX, 0.0, 1.0])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "scaled first: no overflow" },
    Row { func: "aggregate_light_position", case: "NaN acc", args: &[V::Vec4([NAN, 0.0, 1.0, 1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "NaN weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, NAN]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "+Inf weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, INF]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "zero acc (nothing accumulated)", args: &[V::Vec4([0.0; 4]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "subnormal acc.xyz (directions cancel)", args: &[V::Vec4([SUB_MAX, 0.0, 0.0, 1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "zero weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, 0.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_position", case: "negative weight sum", args: &[V::Vec4([0.0, 0.0, 1.0, -1.0]), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "the vertex" },
    Row { func: "aggregate_light_accumulate_colour", case: "NaN colour", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([NAN, 1.0, 1.0]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "+Inf aggregate direction", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3([0.0, 0.0, INF])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "zero vector (light at the vertex)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3(ZN), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "light skipped" },
    Row { func: "aggregate_light_accumulate_colour", case: "zero aggregate direction (cancelled)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3]), V::Vec3([0.0; 3])], expect: V::Vec3([1.0, 2.0, 3.0]), why: "colour term zero" },
    Row { func: "aggregate_light_accumulate_colour", case: "negative intensity", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([-1.0, -2.0, -3.0]), V::Vec3(ZN)], expect: V::Vec3([1.0, 2.0, 3.0]), why: "clamped to 0: adds nothing" },
    Row { func: "aggregate_light_accumulate_colour", case: "out of range: colour 1e20", args: &[V::Vec3([0.0; 3]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1e20, 0.0, 0.0]), V::Vec3(ZN)], expect: V::Vec3([1_099_511_627_776.0, 0.0, 0.0]), why: "clamped to 2^40" },
    Row { func: "aggregate_light_diffuse", case: "NaN position", args: &[V::Vec3(ZN), V::Vec3([NAN, 0.0, 0.0]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "+Inf colour", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([INF, 1.0, 1.0])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "zero-length normal", args: &[V::Vec3([0.0; 3]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "NaN normal", args: &[V::Vec3([0.0, NAN, 1.0]), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no light" },
    Row { func: "aggregate_light_diffuse", case: "zero vector (P_agg = p)", args: &[V::Vec3(ZN), V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "no direction → 0" },
    Row { func: "aggregate_light_diffuse", case: "N·L < 0", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3([0.0, 0.0, -1.0]), V::Vec3([1.0; 3])], expect: V::Vec3([0.0; 3]), why: "clamped at 0" },
    Row { func: "aggregate_light_diffuse", case: "negative intensity", args: &[V::Vec3(ZN), V::Vec3([0.0; 3]), V::Vec3(ZN), V::Vec3([-1.0, 2.0, 0.0])], expect: V::Vec3([0.0, 2.0, 0.0]), why: "channels clamped at 0" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "zero-length normal", args: &[V::F64x3([0.0; 3]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64x2([0.0, 0.0]), why: "no light, like the twins" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "NaN normal", args: &[V::F64x3([f64::NAN, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64x2([0.0, 0.0]), why: "max(NaN, 0) = 0: no light" },
    Row { func: "lighting::lpp::exact::lpp_cosines", case: "N·L = 0", args: &[V::F64x3([0.0, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64x2([0.0, 0.0]), why: "no highlight without N·L" },
    Row { func: "lighting::lpp::exact::multi_light_specular", case: "zero-length normal", args: &[V::F64x3([0.0; 3]), V::F64x3([0.0, 0.0, 1.0]), V::F64(8.0), V::F64x3([0.0, 0.0, 1.0]), V::F64(1.0), V::F64(1.0), V::F64(16.0)], expect: V::F64(0.0), why: "no light" },
    Row { func: "lighting::aggregate_light::aggregate", case: "no lights", args: &[V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "the vertex, no colour" },
    Row { func: "lighting::aggregate_light::aggregate", case: "NaN light", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([NAN, 2.0, 4.0]), V::F32(1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "skipped" },
    Row { func: "lighting::aggregate_light::aggregate", case: "negative intensity", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([1.0, 2.0, 4.0]), V::F32(-1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "weight 0: nothing accumulated" },
    Row { func: "lighting::aggregate_light::aggregate", case: "zero vector (directions cancel)", args: &[V::Vec3([1.0, 2.0, 3.0]), V::Vec3([2.0, 2.0, 3.0]), V::F32(1.0), V::Vec3([1.0; 3]), V::Vec3([0.0, 2.0, 3.0]), V::F32(1.0), V::Vec3([1.0; 3])], expect: V::Vec3x2([[1.0, 2.0, 3.0], [0.0; 3]]), why: "zero direction: the vertex, no colour" },
    // Light volumes (near 1, far 2 unless stated): bad input answers depth-fail and the full range.
    Row { func: "light_volume_near_corner_distance", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf: depth-fail everywhere" },
    Row { func: "light_volume_near_corner_distance", case: "+Inf tan", args: &[V::F32(0.1), V::F32(INF), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "negative near", args: &[V::F32(-0.1), V::F32(1.0), V::F32(1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "negative tan", args: &[V::F32(0.1), V::F32(1.0), V::F32(-1.0)], expect: V::F32(3.4e38), why: "stand-in for +Inf" },
    Row { func: "light_volume_near_corner_distance", case: "zero near", args: &[V::F32(0.0), V::F32(1.0), V::F32(1.0)], expect: V::F32(0.0), why: "near·√… = 0" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "NaN centre", args: &[V::Vec3([NAN, 0.0, 10.0]), V::F32(1.0), V::F32(0.1)], expect: V::U32(1), why: "depth-fail (always correct)" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "+Inf radius", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(INF), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "NaN near-corner distance", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(1.0), V::F32(NAN)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "negative radius", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(-1.0), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "negative near-corner distance", args: &[V::Vec3([0.0, 0.0, 10.0]), V::F32(1.0), V::F32(-0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "zero vector, zero radius", args: &[V::Vec3([0.0; 3]), V::F32(0.0), V::F32(0.0)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "subnormal", args: &[V::Vec3([SUB_MAX, 0.0, 0.0]), V::F32(0.0), V::F32(0.0)], expect: V::U32(1), why: "depth-fail, flushed or not" },
    Row { func: "light_volume_sphere_needs_depth_fail", case: "huge centre (c·c would overflow)", args: &[V::Vec3([0.0, 0.0, 3e38]), V::F32(1.0), V::F32(0.1)], expect: V::U32(0), why: "scaled first: far away, depth-pass" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "NaN apex", args: &[V::Vec3([NAN, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "zero-length axis", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0; 3]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "subnormal axis", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0, SUB_MAX, 0.0]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail, flushed or not" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "+Inf length", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([INF, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative tan", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, -0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative length", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([-10.0, 0.5]), V::F32(0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "negative near-corner distance", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(-0.1)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "+Inf near-corner distance", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3(ZN), V::Vec2([10.0, 0.5]), V::F32(INF)], expect: V::U32(1), why: "depth-fail" },
    Row { func: "light_volume_cone_needs_depth_fail", case: "huge axis (any length)", args: &[V::Vec3([0.0, 0.0, 100.0]), V::Vec3([0.0, 0.0, f32::MAX]), V::Vec2([10.0, 0.5]), V::F32(0.1)], expect: V::U32(0), why: "scaled first: far away, depth-pass" },
    Row { func: "light_volume_window_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::F32(NAN), why: "no guard: propagates" },
    Row { func: "light_volume_window_depth", case: "+Inf view depth, far +Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(0)], expect: V::F32(1.0), why: "1 − n/∞ = 1" },
    Row { func: "light_volume_window_depth", case: "+Inf view depth, far +Inf, reversed", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(1)], expect: V::F32(0.0), why: "n/∞ = 0" },
    Row { func: "light_volume_window_depth", case: "out-of-range convention code 7", args: &[V::F32(INF), V::F32(1.0), V::F32(INF), V::U32(7)], expect: V::F32(0.0), why: "anything but 0 is reversed" },
    Row { func: "light_volume_window_depth", case: "out of range: beyond far", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::F32(2.0), why: "not clipped: f/(f − n) at vz = ∞" },
    Row { func: "light_volume_sphere_depth_bounds", case: "NaN centre", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range: culls nothing" },
    Row { func: "light_volume_sphere_depth_bounds", case: "+Inf radius", args: &[V::F32(1.5), V::F32(INF), V::F32(1.0), V::F32(2.0), V::U32(1)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "negative radius", args: &[V::F32(1.5), V::F32(-1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "zero near", args: &[V::F32(1.5), V::F32(1.0), V::F32(0.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "far ≤ near", args: &[V::F32(1.5), V::F32(1.0), V::F32(2.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "NaN far", args: &[V::F32(1.5), V::F32(1.0), V::F32(1.0), V::F32(NAN), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "−Inf far", args: &[V::F32(1.5), V::F32(1.0), V::F32(1.0), V::F32(-INF), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "full range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out of range: in front of near", args: &[V::F32(0.25), V::F32(0.25), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([1.0, 0.0]), why: "empty range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out of range: behind far", args: &[V::F32(10.0), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(1)], expect: V::Vec2([1.0, 0.0]), why: "empty range" },
    Row { func: "light_volume_sphere_depth_bounds", case: "c + r overflows, far +Inf", args: &[V::F32(3e38), V::F32(3e38), V::F32(1.0), V::F32(INF), V::U32(0)], expect: V::Vec2([0.0, 1.0]), why: "reaches infinity: window depth 1" },
    Row { func: "light_volume_sphere_depth_bounds", case: "out-of-range convention code", args: &[V::F32(3e38), V::F32(3e38), V::F32(1.0), V::F32(INF), V::U32(u32::MAX)], expect: V::Vec2([0.0, 1.0]), why: "reversed: infinity at 0" },
    Row { func: "light_volume_sphere_depth_bounds", case: "subnormal radius at the near plane", args: &[V::F32(1.0), V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::Vec2([0.0, 3.0 / 1_048_576.0]), why: "the point z = 0, widened by ε = 16u·(1 + 2) = 3·2^-20" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "NaN centre", args: &[V::F32(NAN), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([0, MAX24]), why: "full range of codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "zero near", args: &[V::F32(1.5), V::F32(1.0), V::F32(0.0), V::F32(INF), V::U32(1)], expect: V::UVec2([0, MAX24]), why: "full range of codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "out of range: behind far", args: &[V::F32(10.0), V::F32(1.0), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([MAX24, 0]), why: "empty range as codes" },
    Row { func: "light_volume_sphere_depth_bounds24", case: "subnormal radius at the near plane", args: &[V::F32(1.0), V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0), V::U32(0)], expect: V::UVec2([0, 48]), why: "ceil(48u·(2^24 − 1))" },
    Row { func: "lighting::light_volume::exact::light_volume_window_depth", case: "NaN", args: &[V::F64(f64::NAN), V::F64(1.0), V::F64(2.0), V::U32(0)], expect: V::F64(f64::NAN), why: "propagates (reference only)" },
    Row { func: "lighting::light_volume::exact::light_volume_window_depth", case: "+Inf view depth, far +Inf", args: &[V::F64(f64::INFINITY), V::F64(1.0), V::F64(f64::INFINITY), V::U32(1)], expect: V::F64(0.0), why: "n/∞ = 0" },
    // Normal encodings
    // Encoders: NaN, zero and all-subnormal vectors give the code of +z; infinities give the
    // direction of their signs; subnormal components count as 0; any finite length is normalised.
    Row { func: "encode_normal_xyz8", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x00ff_8080), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xyz8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x00ff_8080), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xyz8", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x0080_80ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xyz8", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0080_25da), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_xyz8", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x8080), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xyz8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x00ff_8080), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xyz8", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x0080_ff80), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xyz8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x00ff_8080), why: "code of +z" },
    Row { func: "encode_normal_xyz8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x00ff_8080), why: "code of +z" },
    Row { func: "encode_normal_xyz8", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00c9_c9c9), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_xyz8", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_0080), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xyz8", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_80ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_xy_fp16", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0), why: "every NaN → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x3c00), why: "infinities win: code of +x" },
    Row { func: "encode_normal_xy_fp16", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0xb9a8_39a8), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_xy_fp16", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0), why: "infinities win: code of −z" },
    Row { func: "encode_normal_xy_fp16", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x3c00_0000), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_xy_fp16", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0), why: "code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0), why: "code of +z" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x389e_389e), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0xbc00_0000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_xy_fp16", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x3c00), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_xy_fp16", case: "out of range: z < 0", args: &[V::Vec3([0.0, 0.0, -1.0])], expect: V::U32(0), why: "sign of z not stored: code of +z" },
    Row { func: "encode_normal_oct16", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x7f7f), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct16", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x7f7f), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct16", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x7fff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct16", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x40bf), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct16", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct16", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x7f7f), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct16", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xff7f), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct16", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x7f7f), why: "code of +z" },
    Row { func: "encode_normal_oct16", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x7f7f), why: "code of +z" },
    Row { func: "encode_normal_oct16", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct16", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7f), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct16", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct16_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8080), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x8080), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x80ff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct16_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x40bf), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct16_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct16_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8080), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xff80), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct16_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8080), why: "code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x8080), why: "code of +z" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x80), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct16_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x80ff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct24", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct24", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x007f_f7ff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct24", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x007f_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct24", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0040_0bff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct24", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct24", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x007f_f7ff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct24", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x00ff_f7ff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct24", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_oct24", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_oct24", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00aa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct24", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7ff), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct24", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x007f_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct24_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0080_0800), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x0080_0800), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x0080_0fff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct24_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x0040_0bff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct24_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct24_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x0080_0800), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0x00ff_f800), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct24_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x00aa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x800), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct24_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x0080_0fff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct32", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x7fff_7fff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct32", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x7fff_7fff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct32", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x7fff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct32", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4000_bfff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct32", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct32", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x7fff_7fff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct32", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xffff_7fff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct32", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x7fff_7fff), why: "code of +z" },
    Row { func: "encode_normal_oct32", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x7fff_7fff), why: "code of +z" },
    Row { func: "encode_normal_oct32", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct32", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct32", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x7fff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_oct32_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x8000_8000), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x8000_8000), why: "every NaN → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x8000_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_oct32_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x4000_bfff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_oct32_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0xffff_ffff), why: "infinities win: code of −z" },
    Row { func: "encode_normal_oct32_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x8000_8000), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xffff_8000), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_oct32_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x8000_8000), why: "code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x8000_8000), why: "code of +z" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0xaaaa_aaaa), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x8000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_oct32_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x8000_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_hemioct24", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x007f_f7ff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_hemioct24", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x00ff_f7ff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_hemioct24", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x007f_f7ff), why: "−z clamped to the equator: zero → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x007f_f7ff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_hemioct24", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_hemioct24", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x007f_fd54), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_f000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_hemioct24", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0x00ff_ffff), why: "z clamped to 0: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0080_0800), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x0080_0800), why: "every NaN → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x00ff_f800), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_hemioct24_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0080_0800), why: "−z clamped to the equator: zero → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x0080_0800), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_hemioct24_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x0080_0d55), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_f000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0x00ff_ffff), why: "z clamped to 0: code of +x" },
    // Normal decoders: every bit pattern gives a finite unit vector; unused high bits are ignored.
    // No xyz8 code decodes to an exact f32 vector (three odd integers: |D|² ≡ 3 mod 8 is never a
    // square), so its rows give v/√(v·v) with each step correctly rounded, as documented.
    Row { func: "decode_normal_xyz8", case: "all ones (byte 3 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([R3, R3, R3]), why: "byte 3 ignored: (1, 1, 1)/√3, rounded" },
    Row { func: "decode_normal_xyz8", case: "byte 3 only", args: &[V::U32(0xab00_0000)], expect: V::Vec3([-R3, -R3, -R3]), why: "byte 3 ignored: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xy_fp16", case: "NaN halves", args: &[V::U32(0x7e00_7e00)], expect: V::Vec3([0.0, 0.0, 1.0]), why: "NaN halves count as 0: +z" },
    Row { func: "decode_normal_xy_fp16", case: "−NaN halves (all ones)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, 1.0]), why: "NaN halves count as 0: +z" },
    Row { func: "decode_normal_xy_fp16", case: "+Inf half", args: &[V::U32(0x0000_7c00)], expect: V::Vec3([1.0, 0.0, 0.0]), why: "clamped to 1: +x" },
    Row { func: "decode_normal_xy_fp16", case: "NaN and −Inf halves", args: &[V::U32(0xfc00_7e00)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "x = 0, y clamped to −1: −y" },
    Row { func: "decode_normal_xy_fp16", case: "±Inf halves: x² + y² > 1", args: &[V::U32(0x7c00_7c00)], expect: V::Vec3([R2, R2, 0.0]), why: "clamped to (1, 1), z = 0: (1, 1, 0)/√2, rounded" },
    Row { func: "decode_normal_xy_fp16", case: "out-of-range half −2", args: &[V::U32(0xc000_0000)], expect: V::Vec3([0.0, -1.0, 0.0]), why: "clamped to −1: −y" },
    Row { func: "decode_normal_xy_fp16", case: "subnormal half", args: &[V::U32(0x0000_0001)], expect: V::Vec3([5.960_464_5e-8, 0.0, 1.0]), why: "2^-24 is a normal f32: kept; z rounds to 1" },
    Row { func: "decode_normal_xy_fp16", case: "−0.0 halves", args: &[V::U32(0x8000_8000)], expect: V::Vec3([-0.0, -0.0, 1.0]), why: "+z; the zeros keep their signs" },
    Row { func: "decode_normal_oct16", case: "all ones (unused bits 16–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (M, M) = −z" },
    Row { func: "decode_normal_oct16", case: "unused bits 16–31 only", args: &[V::U32(0xabcd_0000)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (0, 0) = −z" },
    Row { func: "decode_normal_oct24", case: "all ones (unused bits 24–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (M, M) = −z" },
    Row { func: "decode_normal_oct24", case: "unused bits 24–31 only", args: &[V::U32(0xff00_0000)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner (0, 0) = −z" },
    Row { func: "decode_normal_oct32", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "corner (M, M) = −z" },
    Row { func: "decode_normal_oct32", case: "corner (M, 0)", args: &[V::U32(0x0000_ffff)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "every corner is −z" },
    Row { func: "decode_normal_hemioct24", case: "all ones (unused bits 24–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([1.0, 0.0, 0.0]), why: "high bits ignored; corner (M, M) = +x" },
    Row { func: "decode_normal_hemioct24", case: "unused bits 24–31 only", args: &[V::U32(0xff00_0000)], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "high bits ignored; corner (0, 0) = −x" },
    Row { func: "decode_normal_hemioct24", case: "unused bits set, corner (M, 0)", args: &[V::U32(0xab00_0fff)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "high bits ignored; +y" },
    // Render-target forms: encoders write byte/255 (alpha 0 where free); decoders clamp each
    // channel to [0, 1] (NaN counts as 0) and round it back to its byte.
    Row { func: "encode_normal_xyz8_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z: bytes (128, 128, 255, 0)" },
    Row { func: "encode_normal_xyz8_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, B128, B128, 0.0]), why: "+x: bytes (255, 128, 128, 0)" },
    Row { func: "encode_normal_xyz8_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xyz8_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([B128, B128, 1.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_xyz8_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([-R3, -R3, -R3]), why: "bytes 0: (−1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz8_unorm", case: "out of range, ±Inf, NaN", args: &[V::Vec4([2.0, -1.0, NAN, INF])], expect: V::Vec3([R3, -R3, -R3]), why: "bytes (255, 0, 0): (1, −1, −1)/√3, rounded" },
    Row { func: "decode_normal_xyz8_unorm", case: "+Inf", args: &[V::Vec4([INF, INF, INF, -INF])], expect: V::Vec3([R3, R3, R3]), why: "clamped to 1: (1, 1, 1)/√3, rounded" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "+z: both halves 0" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([0.0, B60, 0.0, 0.0]), why: "+x: x half 0x3c00" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "subnormal", args: &[V::Vec3([SUB_MAX, SUB_MIN, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "counts as zero: +z" },
    Row { func: "encode_normal_xy_fp16_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([0.0, 0.0, 0.0, 0.0]), why: "+z" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, 1.0]), why: "bytes 0: halves 0: +z" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "out of range, −Inf, NaN", args: &[V::Vec4([-1.0, B60, NAN, -INF])], expect: V::Vec3([1.0, 0.0, 0.0]), why: "bytes (0, 60, 0, 0): x half 1.0: +x" },
    Row { func: "decode_normal_xy_fp16_unorm", case: "+Inf", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 0.0, 1.0]), why: "bytes 255: NaN halves count as 0: +z" },
    Row { func: "encode_normal_oct16_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec2([B127, B127]), why: "+z: code (127, 127)" },
    Row { func: "encode_normal_oct16_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec2([1.0, B127]), why: "+x: code (255, 127)" },
    Row { func: "encode_normal_oct16_unorm", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::Vec2([B127, B127]), why: "+z" },
    Row { func: "decode_normal_oct16_unorm", case: "NaN", args: &[V::Vec2([NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct16_unorm", case: "out of range, +Inf", args: &[V::Vec2([INF, -1.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes (255, 0): corner = −z" },
    Row { func: "decode_normal_oct16_unorm", case: "out of range", args: &[V::Vec2([2.0, 7.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "clamped to 1: corner (255, 255) = −z" },
    Row { func: "encode_normal_oct24_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z: code 0x7ff7ff, alpha 0" },
    Row { func: "encode_normal_oct24_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, B127, 0.0]), why: "+x: code 0x7fffff" },
    Row { func: "encode_normal_oct24_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z" },
    Row { func: "decode_normal_oct24_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct24_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "alpha ignored; corner (M, M) = −z" },
    Row { func: "encode_normal_oct32_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B127, 1.0, B127]), why: "+z: code 0x7fff7fff" },
    Row { func: "encode_normal_oct32_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, 1.0, B127]), why: "+x: code 0x7fffffff" },
    Row { func: "encode_normal_oct32_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B127, 1.0, B127]), why: "+z" },
    Row { func: "decode_normal_oct32_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "bytes 0: corner (0, 0) = −z" },
    Row { func: "decode_normal_oct32_unorm", case: "out of range, ±Inf", args: &[V::Vec4([2.0, INF, -INF, -1.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "code (0xffff, 0): corner = −z" },
    Row { func: "encode_normal_hemioct24_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z: code 0x7ff7ff, alpha 0" },
    Row { func: "encode_normal_hemioct24_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, 1.0, 0.0]), why: "+x: code 0xffffff" },
    Row { func: "encode_normal_hemioct24_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z" },
    Row { func: "decode_normal_hemioct24_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "bytes 0: corner (0, 0) = −x" },
    Row { func: "decode_normal_hemioct24_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([1.0, 0.0, 0.0]), why: "alpha ignored; corner (M, M) = +x" },
    Row { func: "decode_normal_hemioct24_unorm", case: "out of range, −Inf, NaN", args: &[V::Vec4([INF, B15, -1.0, NAN])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "code (0xfff, 0): +y" },
    // The shared encoder front end and the f16 conversions (the WGSL builtins' twins).
    Row { func: "normal::sanitize", case: "NaN", args: &[V::Vec3([NAN, 0.0, 1.0])], expect: V::OptVec3(None), why: "degenerate: the encoders use +z" },
    Row { func: "normal::sanitize", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::OptVec3(None), why: "degenerate" },
    Row { func: "normal::sanitize", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MAX, 0.0])], expect: V::OptVec3(None), why: "all subnormal = zero: degenerate" },
    Row { func: "normal::sanitize", case: "±Inf", args: &[V::Vec3([INF, -5.0, -INF])], expect: V::OptVec3(Some([1.0, -0.0, -1.0])), why: "signs of the infinities, signed zero elsewhere" },
    Row { func: "normal::sanitize", case: "subnormal component", args: &[V::Vec3([-0.0, 1.0, SUB_MIN])], expect: V::OptVec3(Some([-0.0, 1.0, 0.0])), why: "flushed to signed zero" },
    Row { func: "normal::sanitize", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, -3.0])], expect: V::OptVec3(Some([3.999_999_8, 0.0, -3.0 * f32::MIN_POSITIVE])), why: "scaled by 2^-126 into [1, 4); 2^-252 flushed" },
    Row { func: "normal::sanitize", case: "non-unit: tiny", args: &[V::Vec3([0.0, -SUB_MAX, f32::MIN_POSITIVE])], expect: V::OptVec3(Some([0.0, -0.0, 1.0])), why: "scaled by 2^126; subnormal flushed first" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "NaN", args: &[V::Vec2([NAN, NEG_NAN])], expect: V::U32(0xfe00_7e00), why: "quiet f16 NaN, sign kept (WGSL: indeterminate)" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "NaN (signalling)", args: &[V::Vec2([SNAN, 0.0])], expect: V::U32(0x7e00), why: "stays NaN: quiet bit set" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "±Inf", args: &[V::Vec2([INF, -INF])], expect: V::U32(0xfc00_7c00), why: "±Inf halves" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "out of range", args: &[V::Vec2([65_520.0, -1e9])], expect: V::U32(0xfc00_7c00), why: "rounds to ±Inf (WGSL: indeterminate, clamp first)" },
    Row { func: "normal::xy_fp16::pack2x16float", case: "subnormal", args: &[V::Vec2([-SUB_MIN, 5.960_464_5e-8])], expect: V::U32(0x0001_8000), why: "−0 half; 2^-24 → smallest f16 subnormal" },
    Row { func: "unpack2x16float", case: "NaN and +Inf halves", args: &[V::U32(0x7e00_7c00)], expect: V::Vec2([INF, NAN]), why: "exact: +Inf, NaN" },
    Row { func: "unpack2x16float", case: "−Inf and −NaN halves", args: &[V::U32(0xfc00_fe00)], expect: V::Vec2([NAN, -INF]), why: "exact: NaN, −Inf" },
    Row { func: "unpack2x16float", case: "subnormal halves", args: &[V::U32(0x0001_8001)], expect: V::Vec2([-5.960_464_5e-8, 5.960_464_5e-8]), why: "exact: ±2^-24, normal in f32" },
    // The generic octahedral functions: any bits outside 1..=16 panic (see `oct::max_code`).
    Row { func: "normal::oct::max_code", case: "out-of-range bits 0", args: &[V::U32(0)], expect: V::Text(BITS_PANIC), why: "no code fits 0 bits" },
    Row { func: "normal::oct::max_code", case: "out-of-range bits 17", args: &[V::U32(17)], expect: V::Text(BITS_PANIC), why: "M² would overflow the u32 scores" },
    Row { func: "normal::oct::max_code", case: "out-of-range bits u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::encode_precise", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0]), V::U32(12)], expect: V::U32(0x007f_f7ff), why: "code of +z, as encode_normal_oct24" },
    Row { func: "normal::oct::encode_precise", case: "out-of-range bits 0", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(0)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::encode_precise", case: "out-of-range bits 17", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(17)], expect: V::Text(BITS_PANIC), why: "two codes need 34 bits" },
    Row { func: "normal::oct::encode_round", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::U32(16)], expect: V::U32(0x8000_8000), why: "code of +z, as encode_normal_oct32_fast" },
    Row { func: "normal::oct::encode_round", case: "out-of-range bits 32", args: &[V::Vec3([0.0, 0.0, 1.0]), V::U32(32)], expect: V::Text(BITS_PANIC), why: "never wraps" },
    Row { func: "normal::oct::decode", case: "all ones", args: &[V::U32(u32::MAX), V::U32(8)], expect: V::Vec3([0.0, 0.0, -1.0]), why: "high bits ignored; corner = −z" },
    Row { func: "normal::oct::decode", case: "out-of-range bits 0", args: &[V::U32(0), V::U32(0)], expect: V::Text(BITS_PANIC), why: "never wraps" },
];

// Normal encodings: the channel values k/255 and the rounded decodes the rows above name.
const B15: f32 = 15.0 / 255.0;
const B60: f32 = 60.0 / 255.0;
const B127: f32 = 127.0 / 255.0;
const B128: f32 = 128.0 / 255.0;
const B247: f32 = 247.0 / 255.0;
/// 1/√3 as decoders compute it, `255/√195075` with each step correctly rounded.
const R3: f32 = 0.577_350_26;
/// 1/√2 as decoders compute it, `1/√2` with each step correctly rounded.
const R2: f32 = 0.707_106_77;

/// WGSL's builtin `unpack2x16float` (twin: `normal::xy_fp16::unpack2x16float`) behind a callable
/// name.
const UNPACK2X16_WGSL: &str =
    "fn bad_input_unpack2x16float(p: u32) -> vec2<f32> { return unpack2x16float(p); }";

/// What the generic octahedral functions do with `bits` outside 1..=16.
const BITS_PANIC: &str = "panics";

/// `f()`, or [`BITS_PANIC`] if it panics (the panic message still prints).
fn normal_or_panic(f: impl FnOnce() -> V) -> V {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or(V::Text(BITS_PANIC))
}

/// A `vec4` argument (the rgba8unorm decoders' channels).
fn normal_vec4(v: V) -> [f32; 4] {
    match v {
        V::Vec4(x) => x,
        v => panic!("{v:?} is not a vec4"),
    }
}
