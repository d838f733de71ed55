//! The `batch` target's table: every batch twin of `prepass::batch` against its scalar twin.
//!
//! Each entry reads a length `1..=64` (so the vector loops' tails and short batches run), that
//! many inputs (any bit patterns: NaN, Inf, subnormals, codes with high bits set), and for the
//! generic octahedral codes a `bits` in `1..=16` or for roughness a `max_power`; it runs the
//! batch twin at every level this CPU has and in its plain (detected-level) form, and asserts
//! every output has the scalar twin's bits.

use crate::normal::oct_bits;
use crate::{Entry, Input};
use glam::Vec3;
use prepass::batch::{Level, depth24 as bd, normal as bn, roughness as br, roughness_ggx as bg};
use prepass::depth24 as d24;
use prepass::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use prepass::roughness as r;
use prepass::roughness_ggx as g;

/// A value compared by its bits.
trait Bits: Copy + Default + std::fmt::Debug {
    fn bits(self) -> [u32; 4];
}
impl Bits for u32 {
    fn bits(self) -> [u32; 4] {
        [self, 0, 0, 0]
    }
}
impl Bits for f32 {
    fn bits(self) -> [u32; 4] {
        [self.to_bits(), 0, 0, 0]
    }
}
impl Bits for Vec3 {
    fn bits(self) -> [u32; 4] {
        [self.x.to_bits(), self.y.to_bits(), self.z.to_bits(), 0]
    }
}
impl Bits for [f32; 4] {
    fn bits(self) -> [u32; 4] {
        self.map(f32::to_bits)
    }
}
/// Substrate's word encoders' input `(n, roughness, flags)` (the flags show in the `Debug` form).
impl Bits for (Vec3, f32, u32) {
    fn bits(self) -> [u32; 4] {
        let (n, r, _) = self;
        [n.x.to_bits(), n.y.to_bits(), n.z.to_bits(), r.to_bits()]
    }
}

/// Inputs read from the fuzz bytes: a length byte, then that many values.
trait Read: Bits {
    fn read(i: &mut Input) -> Self;
}
impl Read for u32 {
    fn read(i: &mut Input) -> Self {
        i.u32()
    }
}
impl Read for f32 {
    fn read(i: &mut Input) -> Self {
        i.f32()
    }
}
impl Read for Vec3 {
    fn read(i: &mut Input) -> Self {
        i.vec3()
    }
}
impl Read for [f32; 4] {
    fn read(i: &mut Input) -> Self {
        [i.f32(), i.f32(), i.f32(), i.f32()]
    }
}
impl Read for (Vec3, f32, u32) {
    fn read(i: &mut Input) -> Self {
        (i.vec3(), i.f32(), i.u32())
    }
}

fn inputs<I: Read>(i: &mut Input) -> Vec<I> {
    let n = usize::from(i.u8() % 64) + 1;
    (0..n).map(|_| I::read(i)).collect()
}

/// Every level and the plain form against the scalar twin, bit for bit.
#[track_caller]
fn same<I: Bits, O: Bits>(
    name: &str,
    src: &[I],
    scalar: impl Fn(I) -> O,
    with: impl Fn(Level, &[I], &mut [O]),
    plain: impl Fn(&[I], &mut [O]),
) {
    let want: Vec<O> = src.iter().map(|&x| scalar(x)).collect();
    let mut got = vec![O::default(); src.len()];
    let compare = |form: &str, got: &[O]| {
        for (k, (g, w)) in got.iter().zip(&want).enumerate() {
            assert!(
                g.bits() == w.bits(),
                "{name} [{form}]: input #{k} {:?} (bits {:08x?}): batch {g:?} but scalar twin {w:?}",
                src[k],
                src[k].bits()
            );
        }
    };
    for level in Level::all_available() {
        with(level, src, &mut got);
        compare(&level.to_string(), &got);
    }
    plain(src, &mut got);
    compare("plain", &got);
}

/// A `_vouched` encoder's batch twin: at every level and in the plain form, the scalar twin's
/// code where `inside` (the contract) holds, and elsewhere some valid code (no bit outside
/// `mask`); no panic anywhere.
#[track_caller]
fn same_inside(
    name: &str,
    src: &[Vec3],
    scalar: fn(Vec3) -> u32,
    inside: fn(Vec3) -> bool,
    mask: u32,
    with: impl Fn(Level, &[Vec3], &mut [u32]),
    plain: impl Fn(&[Vec3], &mut [u32]),
) {
    let mut got = vec![0u32; src.len()];
    let compare = |form: &str, got: &[u32]| {
        for (k, (&g, &n)) in got.iter().zip(src).enumerate() {
            if inside(n) {
                let w = scalar(n);
                assert!(
                    g == w,
                    "{name} [{form}]: input #{k} {n:?} (inside the contract): batch {g:#x} but scalar twin {w:#x}"
                );
            } else {
                assert!(
                    g & !mask == 0,
                    "{name} [{form}]: input #{k} {n:?} (outside the contract): {g:#x} is not a code"
                );
            }
        }
    };
    for level in Level::all_available() {
        with(level, src, &mut got);
        compare(&level.to_string(), &got);
    }
    plain(src, &mut got);
    compare("plain", &got);
}

/// An [`Entry`] for a `_vouched` encoder through [`same_inside`]:
/// `vouched!(scalar, inside, mask, module::f, f_with)`, named `batch::<module>::<f>`.
macro_rules! vouched {
    ($scalar:path, $inside:path, $mask:expr, $module:ident :: $f:ident, $fw:ident) => {
        Entry {
            name: concat!("batch::", stringify!($module), "::", stringify!($f)),
            check: |i| {
                let src: Vec<Vec3> = inputs(i);
                same_inside(
                    stringify!($f),
                    &src,
                    $scalar,
                    $inside,
                    $mask,
                    |l, s, d| $module::$fw(l, s, d),
                    |s, d| $module::$f(s, d),
                );
            },
        }
    };
}

/// An [`Entry`] comparing a batch twin with its scalar twin through [`same`]:
/// - `entry!(In, scalar, module::f, f_with)`: a twin without parameters, named
///   `batch::<module>::<f>`, fed a `Vec<In>` from [`inputs`];
/// - `entry!(In, scalar, module::f, f_with; name, read)`: a twin taking one parameter, named
///   `batch::<name>::<f>`. The parameter is read first by `read` (`fn(&mut Input) -> P`), then
///   the inputs; the batch twin takes it first (`f_with(level, p, src, dst)`), the scalar twin
///   last (`scalar(x, p)`).
macro_rules! entry {
    ($in:ty, $scalar:path, $module:ident :: $f:ident, $fw:ident) => {
        Entry {
            name: concat!("batch::", stringify!($module), "::", stringify!($f)),
            check: |i| {
                let src: Vec<$in> = inputs(i);
                same(
                    stringify!($f),
                    &src,
                    $scalar,
                    |l, s, d| $module::$fw(l, s, d),
                    |s, d| $module::$f(s, d),
                );
            },
        }
    };
    ($in:ty, $scalar:path, $module:ident :: $f:ident, $fw:ident; $name:ident, $read:expr) => {
        Entry {
            name: concat!("batch::", stringify!($name), "::", stringify!($f)),
            check: |i| {
                let p = $read(i);
                let src: Vec<$in> = inputs(i);
                same(
                    stringify!($f),
                    &src,
                    |x| $scalar(x, p),
                    |l, s, d| $module::$fw(l, p, s, d),
                    |s, d| $module::$f(p, s, d),
                );
            },
        }
    };
}

/// One entry per public batch twin (the `_with` form of each is exercised at every level).
pub const BATCH: &[Entry] = &[
    entry!(
        Vec3,
        xyz8::encode_normal_xyz8,
        bn::encode_normal_xyz8,
        encode_normal_xyz8_with
    ),
    entry!(
        u32,
        xyz8::decode_normal_xyz8,
        bn::decode_normal_xyz8,
        decode_normal_xyz8_with
    ),
    entry!(
        Vec3,
        xyz8::encode_normal_xyz8_unorm,
        bn::encode_normal_xyz8_unorm,
        encode_normal_xyz8_unorm_with
    ),
    entry!(
        [f32; 4],
        xyz8::decode_normal_xyz8_unorm,
        bn::decode_normal_xyz8_unorm,
        decode_normal_xyz8_unorm_with
    ),
    entry!(
        Vec3,
        xy_fp16::encode_normal_xy_fp16,
        bn::encode_normal_xy_fp16,
        encode_normal_xy_fp16_with
    ),
    entry!(
        u32,
        xy_fp16::decode_normal_xy_fp16,
        bn::decode_normal_xy_fp16,
        decode_normal_xy_fp16_with
    ),
    entry!(
        Vec3,
        xy_fp16::encode_normal_xy_fp16_unorm,
        bn::encode_normal_xy_fp16_unorm,
        encode_normal_xy_fp16_unorm_with
    ),
    entry!(
        [f32; 4],
        xy_fp16::decode_normal_xy_fp16_unorm,
        bn::decode_normal_xy_fp16_unorm,
        decode_normal_xy_fp16_unorm_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct16,
        bn::encode_normal_oct16,
        encode_normal_oct16_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct16_fast,
        bn::encode_normal_oct16_fast,
        encode_normal_oct16_fast_with
    ),
    entry!(
        u32,
        oct::decode_normal_oct16,
        bn::decode_normal_oct16,
        decode_normal_oct16_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct16_unorm,
        bn::encode_normal_oct16_unorm,
        encode_normal_oct16_unorm_with
    ),
    entry!(
        [f32; 4],
        oct::decode_normal_oct16_unorm,
        bn::decode_normal_oct16_unorm,
        decode_normal_oct16_unorm_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24,
        bn::encode_normal_oct24,
        encode_normal_oct24_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_fast,
        bn::encode_normal_oct24_fast,
        encode_normal_oct24_fast_with
    ),
    entry!(
        u32,
        oct::decode_normal_oct24,
        bn::decode_normal_oct24,
        decode_normal_oct24_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_unorm,
        bn::encode_normal_oct24_unorm,
        encode_normal_oct24_unorm_with
    ),
    entry!(
        [f32; 4],
        oct::decode_normal_oct24_unorm,
        bn::decode_normal_oct24_unorm,
        decode_normal_oct24_unorm_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct32,
        bn::encode_normal_oct32,
        encode_normal_oct32_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct32_fast,
        bn::encode_normal_oct32_fast,
        encode_normal_oct32_fast_with
    ),
    entry!(
        u32,
        oct::decode_normal_oct32,
        bn::decode_normal_oct32,
        decode_normal_oct32_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct32_unorm,
        bn::encode_normal_oct32_unorm,
        encode_normal_oct32_unorm_with
    ),
    entry!(
        [f32; 4],
        oct::decode_normal_oct32_unorm,
        bn::decode_normal_oct32_unorm,
        decode_normal_oct32_unorm_with
    ),
    entry!(
        Vec3,
        hemioct::encode_normal_hemioct24,
        bn::encode_normal_hemioct24,
        encode_normal_hemioct24_with
    ),
    entry!(
        Vec3,
        hemioct::encode_normal_hemioct24_fast,
        bn::encode_normal_hemioct24_fast,
        encode_normal_hemioct24_fast_with
    ),
    entry!(
        u32,
        hemioct::decode_normal_hemioct24,
        bn::decode_normal_hemioct24,
        decode_normal_hemioct24_with
    ),
    entry!(
        Vec3,
        hemioct::encode_normal_hemioct24_unorm,
        bn::encode_normal_hemioct24_unorm,
        encode_normal_hemioct24_unorm_with
    ),
    entry!(
        [f32; 4],
        hemioct::decode_normal_hemioct24_unorm,
        bn::decode_normal_hemioct24_unorm,
        decode_normal_hemioct24_unorm_with
    ),
    entry!(u32, d24::pack_depth24, bd::pack_depth24, pack_depth24_with),
    entry!(
        u32,
        d24::depth24_from_packed,
        bd::depth24_from_packed,
        depth24_from_packed_with
    ),
    entry!(
        Vec3,
        d24::depth24_from_rgb8,
        bd::depth24_from_rgb8,
        depth24_from_rgb8_with
    ),
    entry!(
        u32,
        d24::hyperbolic_depth_from_depth24,
        bd::hyperbolic_depth_from_depth24,
        hyperbolic_depth_from_depth24_with
    ),
    entry!(
        u32,
        d24::unpack4x8unorm,
        bd::unpack4x8unorm,
        unpack4x8unorm_with
    ),
    entry!(Vec3, oct::encode_precise, bn::encode_oct_precise, encode_oct_precise_with;
        normal, oct_bits),
    entry!(Vec3, oct::encode_round, bn::encode_oct_round, encode_oct_round_with; normal, oct_bits),
    entry!(u32, oct::decode, bn::decode_oct, decode_oct_with; normal, oct_bits),
    entry!(f32, r::encode_log_roughness, br::encode_log_roughness, encode_log_roughness_with;
        roughness, Input::f32),
    entry!(u32, r::decode_log_roughness, br::decode_log_roughness, decode_log_roughness_with;
        roughness, Input::f32),
    entry!(
        Vec3,
        xyz10::encode_normal_xyz10,
        bn::encode_normal_xyz10,
        encode_normal_xyz10_with
    ),
    entry!(
        u32,
        xyz10::decode_normal_xyz10,
        bn::decode_normal_xyz10,
        decode_normal_xyz10_with
    ),
    entry!(
        Vec3,
        xyz10::encode_normal_xyz10_unorm,
        bn::encode_normal_xyz10_unorm,
        encode_normal_xyz10_unorm_with
    ),
    entry!(
        [f32; 4],
        xyz10::decode_normal_xyz10_unorm,
        bn::decode_normal_xyz10_unorm,
        decode_normal_xyz10_unorm_with
    ),
    entry!(
        Vec3,
        snorm8::encode_normal_snorm8,
        bn::encode_normal_snorm8,
        encode_normal_snorm8_with
    ),
    entry!(
        u32,
        snorm8::decode_normal_snorm8,
        bn::decode_normal_snorm8,
        decode_normal_snorm8_with
    ),
    entry!(
        Vec3,
        snorm8::encode_normal_snorm8_snorm,
        bn::encode_normal_snorm8_snorm,
        encode_normal_snorm8_snorm_with
    ),
    entry!(
        [f32; 4],
        snorm8::decode_normal_snorm8_snorm,
        bn::decode_normal_snorm8_snorm,
        decode_normal_snorm8_snorm_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_unity,
        bn::encode_normal_oct24_unity,
        encode_normal_oct24_unity_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_unity_fast,
        bn::encode_normal_oct24_unity_fast,
        encode_normal_oct24_unity_fast_with
    ),
    entry!(
        u32,
        oct::decode_normal_oct24_unity,
        bn::decode_normal_oct24_unity,
        decode_normal_oct24_unity_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_unity_unorm,
        bn::encode_normal_oct24_unity_unorm,
        encode_normal_oct24_unity_unorm_with
    ),
    entry!(
        [f32; 4],
        oct::decode_normal_oct24_unity_unorm,
        bn::decode_normal_oct24_unity_unorm,
        decode_normal_oct24_unity_unorm_with
    ),
    entry!(
        f32,
        g::encode_roughness_ggx8,
        bg::encode_roughness_ggx8,
        encode_roughness_ggx8_with
    ),
    entry!(
        u32,
        g::decode_roughness_ggx8,
        bg::decode_roughness_ggx8,
        decode_roughness_ggx8_with
    ),
    entry!(
        u32,
        g::decode_roughness_godot8,
        bg::decode_roughness_godot8,
        decode_roughness_godot8_with
    ),
    entry!(
        f32,
        g::encode_roughness_ggx8_log,
        bg::encode_roughness_ggx8_log,
        encode_roughness_ggx8_log_with
    ),
    entry!(
        u32,
        g::decode_roughness_ggx8_log,
        bg::decode_roughness_ggx8_log,
        decode_roughness_ggx8_log_with
    ),
    entry!(f32, flagged_godot8, bg::encode_roughness_godot8, encode_roughness_godot8_with;
        roughness_ggx, Input::u32),
    entry!(
        Vec3,
        substrate::encode_substrate_normal,
        bn::encode_substrate_normal,
        encode_substrate_normal_with
    ),
    entry!(
        Vec3,
        substrate::encode_substrate_normal_fast,
        bn::encode_substrate_normal_fast,
        encode_substrate_normal_fast_with
    ),
    entry!(
        u32,
        substrate::decode_substrate_normal,
        bn::decode_substrate_normal,
        decode_substrate_normal_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct20,
        bn::encode_normal_oct20,
        encode_normal_oct20_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct20_fast,
        bn::encode_normal_oct20_fast,
        encode_normal_oct20_fast_with
    ),
    entry!(
        u32,
        oct::decode_normal_oct20,
        bn::decode_normal_oct20,
        decode_normal_oct20_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct20_unorm,
        bn::encode_normal_oct20_unorm,
        encode_normal_oct20_unorm_with
    ),
    entry!(
        [f32; 4],
        oct::decode_normal_oct20_unorm,
        bn::decode_normal_oct20_unorm,
        decode_normal_oct20_unorm_with
    ),
    entry!(
        Vec3,
        xyz8::encode_normal_xyz8_best,
        bn::encode_normal_xyz8_best,
        encode_normal_xyz8_best_with
    ),
    entry!(
        Vec3,
        xyz8::encode_normal_xyz8_best_unorm,
        bn::encode_normal_xyz8_best_unorm,
        encode_normal_xyz8_best_unorm_with
    ),
    entry!(
        Vec3,
        signed_oct::encode_normal_signed_oct,
        bn::encode_normal_signed_oct,
        encode_normal_signed_oct_with
    ),
    entry!(
        Vec3,
        signed_oct::encode_normal_signed_oct_fast,
        bn::encode_normal_signed_oct_fast,
        encode_normal_signed_oct_fast_with
    ),
    entry!(
        u32,
        signed_oct::decode_normal_signed_oct,
        bn::decode_normal_signed_oct,
        decode_normal_signed_oct_with
    ),
    entry!(
        Vec3,
        signed_oct::encode_normal_signed_oct_unorm,
        bn::encode_normal_signed_oct_unorm,
        encode_normal_signed_oct_unorm_with
    ),
    entry!(
        [f32; 4],
        signed_oct::decode_normal_signed_oct_unorm,
        bn::decode_normal_signed_oct_unorm,
        decode_normal_signed_oct_unorm_with
    ),
    // Appended (the corpus picks entries by index): Substrate's whole word, the vouched
    // encoders.
    entry!(
        (Vec3, f32, u32),
        substrate_word,
        bn::encode_substrate_word,
        encode_substrate_word_with
    ),
    entry!(
        (Vec3, f32, u32),
        substrate_word_fast,
        bn::encode_substrate_word_fast,
        encode_substrate_word_fast_with
    ),
    vouched!(
        oct::encode_normal_oct16_vouched,
        oct::is_vouched,
        0xffff,
        bn::encode_normal_oct16_vouched,
        encode_normal_oct16_vouched_with
    ),
    vouched!(
        oct::encode_normal_oct16_fast_vouched,
        oct::is_vouched,
        0xffff,
        bn::encode_normal_oct16_fast_vouched,
        encode_normal_oct16_fast_vouched_with
    ),
    vouched!(
        oct::encode_normal_oct24_vouched,
        oct::is_vouched,
        0xff_ffff,
        bn::encode_normal_oct24_vouched,
        encode_normal_oct24_vouched_with
    ),
    vouched!(
        oct::encode_normal_oct24_fast_vouched,
        oct::is_vouched,
        0xff_ffff,
        bn::encode_normal_oct24_fast_vouched,
        encode_normal_oct24_fast_vouched_with
    ),
    vouched!(
        oct::encode_normal_oct32_vouched,
        oct::is_vouched,
        u32::MAX,
        bn::encode_normal_oct32_vouched,
        encode_normal_oct32_vouched_with
    ),
    vouched!(
        oct::encode_normal_oct32_fast_vouched,
        oct::is_vouched,
        u32::MAX,
        bn::encode_normal_oct32_fast_vouched,
        encode_normal_oct32_fast_vouched_with
    ),
    vouched!(
        hemioct::encode_normal_hemioct24_vouched,
        hemioct::is_vouched,
        0xff_ffff,
        bn::encode_normal_hemioct24_vouched,
        encode_normal_hemioct24_vouched_with
    ),
    vouched!(
        hemioct::encode_normal_hemioct24_fast_vouched,
        hemioct::is_vouched,
        0xff_ffff,
        bn::encode_normal_hemioct24_fast_vouched,
        encode_normal_hemioct24_fast_vouched_with
    ),
    entry!(
        Vec3,
        oct::encode_normal_oct24_hdrp,
        bn::encode_normal_oct24_hdrp,
        encode_normal_oct24_hdrp_with
    ),
    entry!(
        f32,
        g::encode_roughness_urp8,
        bg::encode_roughness_urp8,
        encode_roughness_urp8_with
    ),
    entry!(
        u32,
        g::decode_roughness_urp8,
        bg::decode_roughness_urp8,
        decode_roughness_urp8_with
    ),
    entry!(
        f32,
        g::encode_roughness_substrate8,
        bg::encode_roughness_substrate8,
        encode_roughness_substrate8_with
    ),
    entry!(
        u32,
        g::decode_roughness_substrate8,
        bg::decode_roughness_substrate8,
        decode_roughness_substrate8_with
    ),
];

/// [`substrate::encode_substrate_word`] on one `(n, roughness, flags)`, as the word entries
/// call it.
fn substrate_word((n, r, flags): (Vec3, f32, u32)) -> u32 {
    substrate::encode_substrate_word(n, r, flags)
}

/// [`substrate::encode_substrate_word_fast`] on one `(n, roughness, flags)`.
fn substrate_word_fast((n, r, flags): (Vec3, f32, u32)) -> u32 {
    substrate::encode_substrate_word_fast(n, r, flags)
}

/// [`g::encode_roughness_godot8`] with the flag last, as the parameterised entries call it.
fn flagged_godot8(r: f32, dynamic_object: u32) -> u32 {
    g::encode_roughness_godot8(r, dynamic_object)
}
