//! The bad-input contract as data: every public function, and what it returns for NaN, ±Inf,
//! subnormals, zero vectors and out-of-range codes or parameters. `tests/bad_input.rs` runs every
//! row through the WGSL on the adapter and through the Rust twin, and checks that the README's
//! table is exactly these rows.
//!
//! Adding a module: add its functions to [`FUNCS`] (WGSL source + name, and the Rust twin as a
//! closure over [`V`] arguments) and its rows to [`ROWS`]; then paste the table the failing
//! README test prints.

use glam::Vec3;
use prepass::depth;
use prepass::linear_depth as ld;
use prepass::position as pos;
use prepass::precision::inputs::{self, ChannelError};
use prepass::precision::metrics;
use prepass::projection::{DepthConvention, Projection};

/// A value in the table: an argument or a result.
#[derive(Clone, Copy, Debug)]
pub enum V {
    F32(f32),
    U32(u32),
    Vec2([f32; 2]),
    Vec3([f32; 3]),
    Vec4([f32; 4]),
    F64(f64),
    OptU32(Option<u32>),
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
    pub fn vec3(self) -> Vec3 {
        match self {
            V::Vec3(x) => Vec3::from(x),
            v => panic!("{v:?} is not a vec3"),
        }
    }
}

/// A public function: its Rust twin, and its WGSL (source, name) where it has one.
pub struct Func {
    /// Name as the table shows it (the Rust path below `prepass::`).
    pub name: &'static str,
    /// WGSL source and function name, or `None` for Rust-only functions.
    pub wgsl: Option<(&'static str, &'static str)>,
    /// The Rust twin.
    pub twin: fn(&[V]) -> V,
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

/// WGSL's builtin `unpack4x8unorm` (twin: `depth::unpack4x8unorm`) behind a callable name.
const UNPACK_WGSL: &str =
    "fn bad_input_unpack4x8unorm(p: u32) -> vec4<f32> { return unpack4x8unorm(p); }";

pub const FUNCS: &[Func] = &[
    Func {
        name: "depth::depth24_from_rgb8",
        wgsl: Some((prepass::wgsl::DEPTH, "depth24_from_rgb8")),
        twin: |a| V::U32(depth::depth24_from_rgb8(a[0].vec3())),
    },
    Func {
        name: "depth::depth24_from_packed",
        wgsl: Some((prepass::wgsl::DEPTH, "depth24_from_packed")),
        twin: |a| V::U32(depth::depth24_from_packed(a[0].u32())),
    },
    Func {
        name: "depth::pack_depth24",
        wgsl: Some((prepass::wgsl::DEPTH, "pack_depth24")),
        twin: |a| V::U32(depth::pack_depth24(a[0].u32())),
    },
    Func {
        name: "depth::hyperbolic_depth_from_depth24",
        wgsl: Some((prepass::wgsl::DEPTH, "hyperbolic_depth_from_depth24")),
        twin: |a| V::F32(depth::hyperbolic_depth_from_depth24(a[0].u32())),
    },
    Func {
        name: "depth::unpack4x8unorm",
        wgsl: Some((UNPACK_WGSL, "bad_input_unpack4x8unorm")),
        twin: |a| V::Vec4(depth::unpack4x8unorm(a[0].u32())),
    },
    Func {
        name: "depth::exact::hyperbolic_depth",
        wgsl: None,
        twin: |a| V::F64(depth::exact::hyperbolic_depth(a[0].u32())),
    },
    Func {
        name: "depth::exact::nearest_code",
        wgsl: None,
        twin: |a| V::OptU32(depth::exact::nearest_code(a[0].f32())),
    },
    Func {
        name: "precision::metrics::ordinal",
        wgsl: None,
        twin: |a| V::OptI64(metrics::ordinal(a[0].f32())),
    },
    Func {
        name: "precision::metrics::ulp_distance",
        wgsl: None,
        twin: |a| V::OptU64(metrics::ulp_distance(a[0].f32(), a[1].f32())),
    },
    Func {
        name: "precision::metrics::step_ulps",
        wgsl: None,
        twin: |a| V::F32(metrics::step_ulps(a[0].f32(), a[1].i64())),
    },
    Func {
        name: "precision::metrics::f32_ulp_at",
        wgsl: None,
        twin: |a| V::F64(metrics::f32_ulp_at(a[0].f64())),
    },
    Func {
        name: "precision::metrics::ulp_error",
        wgsl: None,
        twin: |a| V::F64(metrics::ulp_error(a[0].f32(), a[1].f64())),
    },
    Func {
        name: "precision::metrics::relative_error",
        wgsl: None,
        twin: |a| V::F64(metrics::relative_error(a[0].f64(), a[1].f64())),
    },
    Func {
        name: "precision::metrics::angle_degrees",
        wgsl: None,
        twin: |a| V::F64(metrics::angle_degrees(a[0].f64x3(), a[1].f64x3())),
    },
    Func {
        name: "precision::metrics::widen3",
        wgsl: None,
        twin: |a| V::F64x3(metrics::widen3(a[0].vec3().to_array())),
    },
    Func {
        name: "precision::inputs::unorm8_channel",
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
        name: "precision::inputs::rgb8_channels",
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
        name: "linear_depth::view_z_from_depth24",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24")),
        twin: |a| V::F32(ld::view_z_from_depth24(a[0].u32(), a[1].f32(), a[2].f32())),
    },
    Func {
        name: "linear_depth::view_z_from_depth24_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth24_consts(
                a[0].u32(),
                a[1].vec2().to_array(),
            ))
        },
    },
    Func {
        name: "linear_depth::view_z_from_depth",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth")),
        twin: |a| V::F32(ld::view_z_from_depth(a[0].f32(), a[1].f32(), a[2].f32())),
    },
    Func {
        name: "linear_depth::view_z_from_depth_consts",
        wgsl: Some((prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth_consts")),
        twin: |a| {
            V::F32(ld::view_z_from_depth_consts(
                a[0].f32(),
                a[1].vec3().to_array(),
            ))
        },
    },
    Func {
        name: "linear_depth::view_z_from_reversed_depth",
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
        name: "linear_depth::view_z_from_reversed_depth_consts",
        wgsl: Some((
            prepass::wgsl::LINEAR_DEPTH,
            "view_z_from_reversed_depth_consts",
        )),
        twin: |a| {
            V::F32(ld::view_z_from_reversed_depth_consts(
                a[0].f32(),
                a[1].vec3().to_array(),
            ))
        },
    },
    Func {
        name: "projection::Projection::new",
        wgsl: None,
        twin: projection_new,
    },
    Func {
        name: "position::frustum_ray",
        wgsl: Some((prepass::wgsl::POSITION, "frustum_ray")),
        twin: |a| V::Vec3(pos::frustum_ray(a[0].vec2(), a[1].vec2()).to_array()),
    },
    Func {
        name: "position::frustum_ray_rh",
        wgsl: Some((prepass::wgsl::POSITION, "frustum_ray_rh")),
        twin: |a| V::Vec3(pos::frustum_ray_rh(a[0].vec2(), a[1].vec2()).to_array()),
    },
    Func {
        name: "position::view_position",
        wgsl: Some((prepass::wgsl::POSITION, "view_position")),
        twin: |a| V::Vec3(pos::view_position(a[0].vec3(), a[1].f32()).to_array()),
    },
    Func {
        name: "position::fullscreen_triangle_ndc",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ndc")),
        twin: |a| V::Vec2(pos::fullscreen_triangle_ndc(a[0].u32()).to_array()),
    },
    Func {
        name: "position::fullscreen_triangle_ray",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ray")),
        twin: |a| V::Vec3(pos::fullscreen_triangle_ray(a[0].u32(), a[1].vec2()).to_array()),
    },
    Func {
        name: "position::fullscreen_triangle_ray_rh",
        wgsl: Some((prepass::wgsl::POSITION, "fullscreen_triangle_ray_rh")),
        twin: |a| V::Vec3(pos::fullscreen_triangle_ray_rh(a[0].u32(), a[1].vec2()).to_array()),
    },
    Func {
        name: "position::ndc_from_uv",
        wgsl: Some((prepass::wgsl::POSITION, "ndc_from_uv")),
        twin: |a| V::Vec2(pos::ndc_from_uv(a[0].vec2()).to_array()),
    },
    Func {
        name: "position::world_ray",
        wgsl: Some((WORLD_RAY_WGSL, "bad_input_world_ray")),
        twin: |a| {
            let m = glam::Mat3::from_cols(a[1].vec3(), a[2].vec3(), a[3].vec3());
            V::Vec3(pos::world_ray(a[0].vec3(), m).to_array())
        },
    },
    Func {
        name: "position::camera_relative_position",
        wgsl: Some((prepass::wgsl::POSITION, "camera_relative_position")),
        twin: |a| V::Vec3(pos::camera_relative_position(a[0].vec3(), a[1].f32()).to_array()),
    },
    Func {
        name: "position::world_position",
        wgsl: Some((prepass::wgsl::POSITION, "world_position")),
        twin: |a| V::Vec3(pos::world_position(a[0].vec3(), a[1].f32(), a[2].vec3()).to_array()),
    },
];

/// WGSL functions in `wgsl/` that are not public API (private helpers a file needs), exempt
/// from "every WGSL function has rows". Each needs a reason.
pub const WGSL_HELPERS: &[(&str, &str)] = &[
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
];

/// One documented answer.
pub struct Row {
    /// [`Func::name`].
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
const MAX24: u32 = depth::DEPTH24_MAX;

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // depth24_from_rgb8: channels clamp to [0, 1], NaN (from its bits) counts as 0.
    Row { func: "depth::depth24_from_rgb8", case: "NaN", args: &[V::Vec3([NAN, NAN, NAN])], expect: V::U32(0), why: "NaN channel → byte 0" },
    Row { func: "depth::depth24_from_rgb8", case: "NaN (−NaN, signalling)", args: &[V::Vec3([NEG_NAN, 1.0, SNAN])], expect: V::U32(0x00ff00), why: "every NaN → byte 0" },
    Row { func: "depth::depth24_from_rgb8", case: "+Inf", args: &[V::Vec3([INF, INF, INF])], expect: V::U32(MAX24), why: "clamped to 1 → byte 255" },
    Row { func: "depth::depth24_from_rgb8", case: "−Inf", args: &[V::Vec3([-INF, -INF, -INF])], expect: V::U32(0), why: "clamped to 0" },
    Row { func: "depth::depth24_from_rgb8", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0), why: "rounds to byte 0, flushed or not" },
    Row { func: "depth::depth24_from_rgb8", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth::depth24_from_rgb8", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0), why: "code 0" },
    Row { func: "depth::depth24_from_rgb8", case: "out of range", args: &[V::Vec3([-1.0, 2.0, 1.5])], expect: V::U32(0x00ffff), why: "clamped to [0, 1]" },
    Row { func: "depth::depth24_from_rgb8", case: "huge", args: &[V::Vec3([f32::MAX, f32::MIN, 0.5])], expect: V::U32(0xff0080), why: "clamped; 127.5 rounds half to even" },
    // depth24_from_packed: pure bit operations, every u32 is valid.
    Row { func: "depth::depth24_from_packed", case: "alpha byte set", args: &[V::U32(0xff12_3456)], expect: V::U32(0x56_3412), why: "byte 3 ignored" },
    Row { func: "depth::depth24_from_packed", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::U32(MAX24), why: "byte 3 ignored" },
    Row { func: "depth::depth24_from_packed", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // pack_depth24: codes above 2^24 − 1 saturate.
    Row { func: "depth::pack_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::U32(0x00ff_ffff), why: "saturates to 2^24 − 1" },
    Row { func: "depth::pack_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::U32(0x00ff_ffff), why: "saturates; alpha stays 0" },
    Row { func: "depth::pack_depth24", case: "zero", args: &[V::U32(0)], expect: V::U32(0), why: "code 0" },
    // hyperbolic_depth_from_depth24: codes above 2^24 − 1 saturate to 1.0.
    Row { func: "depth::hyperbolic_depth_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "depth::hyperbolic_depth_from_depth24", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F32(1.0), why: "saturates to 1.0" },
    Row { func: "depth::hyperbolic_depth_from_depth24", case: "zero", args: &[V::U32(0)], expect: V::F32(0.0), why: "+0.0, never −0.0" },
    // unpack4x8unorm: every u32 is four valid bytes.
    Row { func: "depth::unpack4x8unorm", case: "all ones", args: &[V::U32(u32::MAX)], expect: V::Vec4([1.0; 4]), why: "255/255 = 1 exactly" },
    Row { func: "depth::unpack4x8unorm", case: "zero", args: &[V::U32(0)], expect: V::Vec4([0.0; 4]), why: "+0.0 lanes" },
    // Linear depth (near 1, far 2 unless stated: every expected value below is exact in f32).
    Row { func: "linear_depth::view_z_from_depth24", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "linear_depth::view_z_from_depth24", case: "out-of-range code, far +Inf", args: &[V::U32(u32::MAX), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "far code of an infinite projection → +Inf" },
    Row { func: "linear_depth::view_z_from_depth24", case: "zero", args: &[V::U32(0), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "code 0 = near plane" },
    Row { func: "linear_depth::view_z_from_depth24_consts", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Vec2([16_777_215.0, 0.5])], expect: V::F32(2.0), why: "saturates to the far plane" },
    Row { func: "linear_depth::view_z_from_depth24_consts", case: "far +Inf (n/f = 0)", args: &[V::U32(MAX24), V::Vec2([16_777_215.0, 0.0])], expect: V::F32(INF), why: "far code → +Inf" },
    Row { func: "linear_depth::view_z_from_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN (found from its bits)" },
    Row { func: "linear_depth::view_z_from_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 1 = far" },
    Row { func: "linear_depth::view_z_from_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "linear_depth::view_z_from_depth", case: "subnormal", args: &[V::F32(SUB_MAX), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "near, flushed or not" },
    Row { func: "linear_depth::view_z_from_depth", case: "out of range", args: &[V::F32(1.5), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "clamped to 1; infinite far → +Inf" },
    Row { func: "linear_depth::view_z_from_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "linear_depth::view_z_from_depth_consts", case: "out of range", args: &[V::F32(-3.0), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(1.0), why: "clamped to 0 = near" },
    Row { func: "linear_depth::view_z_from_reversed_depth", case: "NaN", args: &[V::F32(NAN), V::F32(1.0), V::F32(2.0)], expect: V::F32(NAN), why: "NaN" },
    Row { func: "linear_depth::view_z_from_reversed_depth", case: "+Inf", args: &[V::F32(INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(1.0), why: "clamped to 1 = near" },
    Row { func: "linear_depth::view_z_from_reversed_depth", case: "−Inf", args: &[V::F32(-INF), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "clamped to 0 = far" },
    Row { func: "linear_depth::view_z_from_reversed_depth", case: "subnormal", args: &[V::F32(SUB_MIN), V::F32(1.0), V::F32(2.0)], expect: V::F32(2.0), why: "far, flushed or not" },
    Row { func: "linear_depth::view_z_from_reversed_depth", case: "zero, far +Inf (sky)", args: &[V::F32(0.0), V::F32(1.0), V::F32(INF)], expect: V::F32(INF), why: "the sky of reversed-infinite → +Inf" },
    Row { func: "linear_depth::view_z_from_reversed_depth_consts", case: "NaN", args: &[V::F32(NAN), V::Vec3([1.0, 0.5, 0.5])], expect: V::F32(NAN), why: "NaN" },
    Row { func: "linear_depth::view_z_from_reversed_depth_consts", case: "−0.0, infinite (k = (1, 1, 0))", args: &[V::F32(-0.0), V::Vec3([1.0, 1.0, 0.0])], expect: V::F32(INF), why: "the sky → +Inf" },
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
    Row { func: "position::frustum_ray", case: "NaN", args: &[V::Vec2([NAN, 0.5]), V::Vec2([1.0, 2.0])], expect: V::Vec3([NAN, 1.0, 1.0]), why: "propagates per lane; z stays 1" },
    Row { func: "position::frustum_ray", case: "+Inf", args: &[V::Vec2([INF, -INF]), V::Vec2([1.0, 2.0])], expect: V::Vec3([INF, -INF, 1.0]), why: "propagates per lane" },
    Row { func: "position::frustum_ray_rh", case: "zero vector", args: &[V::Vec2([0.0, 0.0]), V::Vec2([0.0, 0.0])], expect: V::Vec3([0.0, 0.0, -1.0]), why: "the view axis" },
    Row { func: "position::view_position", case: "+Inf view z (sky)", args: &[V::Vec3([0.5, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "position::view_position", case: "NaN view z", args: &[V::Vec3([0.5, 0.0, 1.0]), V::F32(NAN)], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
    Row { func: "position::fullscreen_triangle_ndc", case: "out-of-range index 3", args: &[V::U32(3)], expect: V::Vec2([3.0, 3.0]), why: "low two bits: off screen" },
    Row { func: "position::fullscreen_triangle_ndc", case: "out-of-range index u32::MAX", args: &[V::U32(u32::MAX)], expect: V::Vec2([3.0, 3.0]), why: "low two bits" },
    Row { func: "position::fullscreen_triangle_ray", case: "out-of-range index 6", args: &[V::U32(6), V::Vec2([1.0, 0.5])], expect: V::Vec3([-1.0, 1.5, 1.0]), why: "index 6 reads as 2" },
    Row { func: "position::fullscreen_triangle_ray_rh", case: "NaN", args: &[V::U32(0), V::Vec2([NAN, 1.0])], expect: V::Vec3([NAN, -1.0, -1.0]), why: "propagates per lane" },
    Row { func: "position::ndc_from_uv", case: "out of range", args: &[V::Vec2([2.0, -1.0])], expect: V::Vec2([3.0, 3.0]), why: "not clamped" },
    Row { func: "position::ndc_from_uv", case: "NaN", args: &[V::Vec2([NAN, 0.25])], expect: V::Vec2([NAN, 0.5]), why: "propagates per lane" },
    Row { func: "position::world_ray", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "0·NaN = NaN in every lane" },
    Row { func: "position::world_ray", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0]), V::Vec3([1.0, 0.0, 0.0]), V::Vec3([0.0, 1.0, 0.0]), V::Vec3([0.0, 0.0, 1.0])], expect: V::Vec3([0.0, 0.0, 0.0]), why: "zero" },
    Row { func: "position::camera_relative_position", case: "+Inf view z (sky)", args: &[V::Vec3([1.0, 0.0, -1.0]), V::F32(INF)], expect: V::Vec3([INF, NAN, -INF]), why: "0·∞ = NaN: skip sky pixels" },
    Row { func: "position::world_position", case: "+Inf camera", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(1.0), V::Vec3([INF, 0.0, 0.0])], expect: V::Vec3([INF, 0.0, 0.0]), why: "propagates" },
    Row { func: "position::world_position", case: "NaN view z", args: &[V::Vec3([1.0, 0.0, 0.0]), V::F32(NAN), V::Vec3([1.0, 2.0, 3.0])], expect: V::Vec3([NAN, NAN, NAN]), why: "propagates" },
    // Exact references (Rust only).
    Row { func: "depth::exact::hyperbolic_depth", case: "out-of-range code 2^24", args: &[V::U32(MAX24 + 1)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth::exact::hyperbolic_depth", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX)], expect: V::F64(1.0), why: "saturates like the twin" },
    Row { func: "depth::exact::nearest_code", case: "NaN", args: &[V::F32(NAN)], expect: V::OptU32(None), why: "no code" },
    Row { func: "depth::exact::nearest_code", case: "+Inf", args: &[V::F32(INF)], expect: V::OptU32(None), why: "above 1" },
    Row { func: "depth::exact::nearest_code", case: "−Inf", args: &[V::F32(-INF)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth::exact::nearest_code", case: "−0.0", args: &[V::F32(-0.0)], expect: V::OptU32(Some(0)), why: "−0.0 is 0" },
    Row { func: "depth::exact::nearest_code", case: "subnormal", args: &[V::F32(SUB_MIN)], expect: V::OptU32(Some(0)), why: "rounds to code 0" },
    Row { func: "depth::exact::nearest_code", case: "negative subnormal", args: &[V::F32(-SUB_MIN)], expect: V::OptU32(None), why: "below 0" },
    Row { func: "depth::exact::nearest_code", case: "out of range", args: &[V::F32(1.000_000_1)], expect: V::OptU32(None), why: "above 1" },
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
];
