//! The bad-input contract as data: every public function, and what it returns for NaN, ±Inf,
//! subnormals, zero vectors and out-of-range codes or parameters. `tests/bad_input.rs` runs every
//! row through the WGSL on the adapter and through the Rust twin, and checks that the README's
//! table is exactly these rows.
//!
//! One file per module stem, named like the WGSL file (`lpp.rs` for `wgsl/lpp.wgsl`,
//! `normal_oct.rs` for `wgsl/normal_oct.wgsl`; `projection.rs`, `precision.rs` and `normal.rs`
//! hold Rust-only functions). Each file has its `FUNCS` (WGSL source and name, and the Rust twin
//! as a closure over [`V`] arguments), its `WGSL_HELPERS` (private WGSL functions exempt from
//! rows, each with a reason) and its `ROWS`; [`TABLES`] lists the files in the README's order.
//!
//! Adding a module: add its file, declare it below and list it in [`TABLES`]; then paste the
//! table the failing README test prints.

use glam::Vec3;
use prepass::precision::inputs::ChannelError;

/// A [`Func`] whose twin is the plain call `prepass::<module>::<name>(args…)` and whose WGSL
/// function (if any) has the same name: `func!(SOURCE; module::path; name(arg kinds…) -> V kind)`,
/// or `func!(None; …)` for a Rust-only function. Each argument kind names the [`V`] accessor that
/// reads it (`f32`, `vec3`, …), in order. Functions that need a wrapper or a conversion write the
/// [`Func`] out by hand.
macro_rules! func {
    (None; $($m:ident)::+; $name:ident($($arg:ident),*) -> $kind:ident) => {
        func!(@make None; $($m)::+; $name($($arg),*) -> $kind)
    };
    ($src:expr; $($m:ident)::+; $name:ident($($arg:ident),*) -> $kind:ident) => {
        func!(@make Some(($src, stringify!($name))); $($m)::+; $name($($arg),*) -> $kind)
    };
    (@make $wgsl:expr; $($m:ident)::+; $name:ident($($arg:ident),*) -> $kind:ident) => {
        $crate::rows::Func {
            rust: concat!($(stringify!($m), "::",)+ stringify!($name)),
            wgsl: $wgsl,
            twin: |a| {
                let mut args = a.iter().copied();
                let mut next = || args.next().expect("a row gives every argument");
                $crate::rows::V::$kind($crate::rows::Plain::plain(prepass::$($m)::+::$name(
                    $(next().$arg()),*
                )))
            },
        }
    };
}

/// A twin's result as the payload of its [`V`] variant (glam vectors as arrays).
pub trait Plain {
    type Out;
    fn plain(self) -> Self::Out;
}

macro_rules! plain_as_is {
    ($($t:ty),*) => { $(impl Plain for $t { type Out = $t; fn plain(self) -> $t { self } })* };
}
plain_as_is!(
    f32,
    u32,
    f64,
    [f32; 2],
    [f32; 3],
    [f32; 4],
    [f64; 3],
    Option<u32>,
    Option<i64>,
    Option<u64>
);

impl Plain for glam::Vec2 {
    type Out = [f32; 2];
    fn plain(self) -> [f32; 2] {
        self.to_array()
    }
}
impl Plain for Vec3 {
    type Out = [f32; 3];
    fn plain(self) -> [f32; 3] {
        self.to_array()
    }
}
impl Plain for glam::Vec4 {
    type Out = [f32; 4];
    fn plain(self) -> [f32; 4] {
        self.to_array()
    }
}
impl Plain for glam::UVec2 {
    type Out = [u32; 2];
    fn plain(self) -> [u32; 2] {
        self.to_array()
    }
}

mod aggregate_light;
mod depth24;
mod light_volume;
mod linear_depth;
mod lpp;
mod normal;
mod normal_hemioct;
mod normal_oct;
mod normal_signed_oct;
mod normal_snorm8;
mod normal_substrate;
mod normal_xy_fp16;
mod normal_xyz10;
mod normal_xyz8;
mod position;
mod precision;
mod projection;
mod roughness;
mod roughness_ggx;

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
    /// An expected result that the Rust twin defines and WGSL does not: a run-time ±∞ or NaN,
    /// which WGSL's finite-math rule makes an indeterminate value. The twin must return the
    /// inner value; the WGSL row still runs, and its value is not checked ([`wgsl_expect`]).
    WgslIndeterminate(&'static V),
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
    /// A `vec4` argument as an array (the rgba8unorm decoders' channels).
    pub fn rgba(self) -> [f32; 4] {
        self.vec4().to_array()
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

/// One documented answer.
pub struct Row {
    /// [`Func::key`]: the WGSL name, or the Rust path of a Rust-only function.
    pub func: &'static str,
    /// The kind of bad input.
    pub case: &'static str,
    /// The arguments.
    pub args: &'static [V],
    /// What both sides must return (bit for bit; any NaN matches NaN), or
    /// [`V::WgslIndeterminate`] where only the Rust twin's answer is defined.
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
const MAX24: u32 = prepass::depth24::DEPTH24_MAX;
/// The unit z axis: a valid normal, eye and light direction whose cosines are exactly 1.
const ZN: [f32; 3] = [0.0, 0.0, 1.0];

/// One module's part of the contract: its functions, its exempt WGSL helpers, its rows.
pub struct Table {
    pub funcs: &'static [Func],
    pub wgsl_helpers: &'static [(&'static str, &'static str)],
    pub rows: &'static [Row],
}

macro_rules! table {
    ($m:ident) => {
        Table {
            funcs: $m::FUNCS,
            wgsl_helpers: $m::WGSL_HELPERS,
            rows: $m::ROWS,
        }
    };
}

/// Every module's table, in the README's order.
pub const TABLES: &[Table] = &[
    table!(depth24),
    table!(linear_depth),
    table!(projection),
    table!(position),
    table!(precision),
    table!(roughness),
    table!(roughness_ggx),
    table!(lpp),
    table!(aggregate_light),
    table!(light_volume),
    table!(normal_xyz8),
    table!(normal_xyz10),
    table!(normal_snorm8),
    table!(normal_xy_fp16),
    table!(normal_oct),
    table!(normal_hemioct),
    table!(normal_substrate),
    table!(normal_signed_oct),
    table!(normal),
];

/// Every function, module by module.
pub fn funcs() -> impl Iterator<Item = &'static Func> {
    TABLES.iter().flat_map(|t| t.funcs)
}

/// Every private WGSL helper exempt from rows, with its reason.
pub fn wgsl_helpers() -> impl Iterator<Item = &'static (&'static str, &'static str)> {
    TABLES.iter().flat_map(|t| t.wgsl_helpers)
}

/// Every row, module by module (the README table's order).
pub fn rows() -> impl Iterator<Item = &'static Row> {
    TABLES.iter().flat_map(|t| t.rows)
}

/// What a WGSL row must return, or `None` where WGSL leaves it indeterminate.
pub fn wgsl_expect(expect: V) -> Option<V> {
    match expect {
        V::WgslIndeterminate(_) => None,
        v => Some(v),
    }
}

/// Bit-for-bit equality; any NaN matches any NaN (payloads are not part of the contract). An
/// expected [`V::WgslIndeterminate`] compares its inner value (the Rust twin's answer).
pub fn same(a: V, b: V) -> bool {
    if let V::WgslIndeterminate(&b) = b {
        return same(a, b);
    }
    let f = |x: f32, y: f32| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
    match (a, b) {
        (V::F32(x), V::F32(y)) => f(x, y),
        (V::U32(x), V::U32(y)) => x == y,
        (V::UVec2(x), V::UVec2(y)) => x == y,
        (V::Vec3x2(x), V::Vec3x2(y)) => x
            .iter()
            .flatten()
            .zip(y.iter().flatten())
            .all(|(&p, &q)| f(p, q)),
        (V::F64x2(x), V::F64x2(y)) => x
            .iter()
            .zip(&y)
            .all(|(p, q)| p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan())),
        (V::Vec2(x), V::Vec2(y)) => x.iter().zip(&y).all(|(&p, &q)| f(p, q)),
        (V::Vec3(x), V::Vec3(y)) => x.iter().zip(&y).all(|(&p, &q)| f(p, q)),
        (V::Text(x), V::Text(y)) => x == y,
        (V::Vec4(x), V::Vec4(y)) => x.iter().zip(&y).all(|(&p, &q)| f(p, q)),
        (V::F64(x), V::F64(y)) => x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()),
        (V::OptU32(x), V::OptU32(y)) => x == y,
        (V::OptVec3(None), V::OptVec3(None)) => true,
        (V::OptVec3(Some(x)), V::OptVec3(Some(y))) => x.iter().zip(&y).all(|(&p, &q)| f(p, q)),
        (V::F64x3(x), V::F64x3(y)) => x
            .iter()
            .zip(&y)
            .all(|(p, q)| p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan())),
        (V::OptI64(x), V::OptI64(y)) => x == y,
        (V::OptU64(x), V::OptU64(y)) => x == y,
        (V::I64(x), V::I64(y)) => x == y,
        (V::Bool(x), V::Bool(y)) => x == y,
        _ => false,
    }
}

pub fn words(v: V, out: &mut Vec<u32>) {
    match v {
        V::F32(x) => out.push(x.to_bits()),
        V::U32(x) => out.push(x),
        V::Vec2(x) => out.extend(x.map(f32::to_bits)),
        V::Vec3(x) => out.extend(x.map(f32::to_bits)),
        V::Vec4(x) => out.extend(x.map(f32::to_bits)),
        V::UVec2(x) => out.extend(x),
        _ => panic!("{v:?} has no WGSL type"),
    }
}

/// Read a WGSL result shaped like `like` from its words.
pub fn from_words(like: V, w: &[u32]) -> V {
    let f = |i: usize| f32::from_bits(w[i]);
    match like {
        V::F32(_) => V::F32(f(0)),
        V::U32(_) => V::U32(w[0]),
        V::Vec2(_) => V::Vec2([f(0), f(1)]),
        V::Vec3(_) => V::Vec3([f(0), f(1), f(2)]),
        V::Vec4(_) => V::Vec4([f(0), f(1), f(2), f(3)]),
        V::UVec2(_) => V::UVec2([w[0], w[1]]),
        V::WgslIndeterminate(&v) => from_words(v, w),
        _ => panic!("{like:?} has no WGSL type"),
    }
}
