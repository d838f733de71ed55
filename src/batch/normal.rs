//! Batch twins of the normal encodings ([`crate::normal`]): xyz8 (and its best-fit encoder), xyz10, snorm8, xy FP16, octahedral 16/20/24/32 (24 also in Unity's byte order), Unreal Substrate's centred 11:11 normal
//! and its whole word (normal, roughness byte, flags)
//! (precise and rounding encoders, and the generic `bits` forms), hemi-octahedral 24, O3DE's
//! signed octahedron, the `_vouched` encoders of oct16/24/32 and hemioct24, and every
//! `_unorm` render-target form. Names, the slice contract and the vectorisation: [`crate::batch`].
//!
//! Each function writes exactly what its scalar twin returns for every input (checked by
//! `tests/batch.rs` on every level this CPU has), so the error bounds, bad-input rules and
//! layouts are the scalar twins': see the linked function. **The exception: the `_vouched`
//! encoders** equal their scalar twins on every input inside the twin's contract
//! ([`oct::is_vouched`], [`hemioct::is_vouched`]); outside it, where the scalar twin's code is
//! itself unspecified, they return some valid code (each axis in `[0, M]`, the bits above the
//! code zero) and never panic.
//!
//! **The precise octahedral encoders** evaluate the scalar twin's four candidate scores
//! `|s × D|²/|D|²` in the same order with the same operations and keep the first strictly
//! smallest, all in lanes: the same output by construction, at about four times the rounding
//! encoder's arithmetic.

use super::{batch_fn, round_even_small};
use crate::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use glam::{Vec2, Vec3};

// ---------------------------------------------------------------------------------------------
// Lane bodies: branch-free mirrors of the scalar twins, operation for operation.

/// `x` with its bits replaced when `c` (a select, not a branch).
#[inline(always)]
fn sel(c: bool, a: u32, b: u32) -> u32 {
    if c { a } else { b }
}

/// The sanitized components (bits) of `n` as [`crate::normal::sanitize`] computes them before
/// its final scaling, and whether any component is NaN.
#[inline(always)]
fn sanitize_bits(n: Vec3) -> ([u32; 3], bool) {
    // (No `array::map` in lane bodies: it is not always inlined, and a call stops the
    // vectoriser.)
    let b = [n.x.to_bits(), n.y.to_bits(), n.z.to_bits()];
    let abs = [b[0] & 0x7fff_ffff, b[1] & 0x7fff_ffff, b[2] & 0x7fff_ffff];
    let sign = [b[0] & 0x8000_0000, b[1] & 0x8000_0000, b[2] & 0x8000_0000];
    let nan = (abs[0] > 0x7f80_0000) | (abs[1] > 0x7f80_0000) | (abs[2] > 0x7f80_0000);
    let inf = (abs[0] == 0x7f80_0000) | (abs[1] == 0x7f80_0000) | (abs[2] == 0x7f80_0000);
    let comp = |k: usize| {
        let inf_form = sel(abs[k] == 0x7f80_0000, sign[k] | 0x3f80_0000, sign[k]);
        let flushed = sel(abs[k] < 0x0080_0000, sign[k], b[k]);
        sel(inf, inf_form, flushed)
    };
    ([comp(0), comp(1), comp(2)], nan)
}

/// The exact power-of-two scaling of [`crate::normal::sanitize`]: `m` the largest component
/// magnitude, each component times `2^(127 − e(m))` (clamped as the twin does), then flushed.
#[inline(always)]
fn scale_and_flush(c: [f32; 3], m: f32) -> Vec3 {
    let e = (m.to_bits() >> 23) & 0xff;
    // e ≤ 255; wrapping (only garbage lanes, selected away, ever have e = 255 or 0).
    let scale = f32::from_bits(254u32.wrapping_sub(e).max(1) << 23);
    let f = |x: f32| {
        let y = x * scale;
        let yb = y.to_bits();
        f32::from_bits(sel(yb & 0x7f80_0000 == 0, yb & 0x8000_0000, yb))
    };
    Vec3::new(f(c[0]), f(c[1]), f(c[2]))
}

/// `crate::normal::sanitize(n).unwrap_or(Vec3::Z)`, branch-free.
#[inline(always)]
fn sanitize_or_z(n: Vec3) -> Vec3 {
    let (c, nan) = sanitize_bits(n);
    let c = [
        f32::from_bits(c[0]),
        f32::from_bits(c[1]),
        f32::from_bits(c[2]),
    ];
    let m = c[0].abs().max(c[1].abs()).max(c[2].abs());
    let s = scale_and_flush(c, m);
    let bad = nan | (m == 0.0);
    Vec3::new(
        f32::from_bits(sel(bad, 0, s.x.to_bits())),
        f32::from_bits(sel(bad, 0, s.y.to_bits())),
        f32::from_bits(sel(bad, 0x3f80_0000, s.z.to_bits())),
    )
}

/// The hemi-octahedral twin's own sanitize (`z` clamped to `[0, ∞)` before the scaling).
#[inline(always)]
fn hemioct_sanitize(n: Vec3) -> Vec3 {
    let (c, nan) = sanitize_bits(n);
    let mut c = [
        f32::from_bits(c[0]),
        f32::from_bits(c[1]),
        f32::from_bits(c[2]),
    ];
    c[2] = c[2].max(0.0);
    let m = c[0].abs().max(c[1].abs()).max(c[2]);
    let s = scale_and_flush(c, m);
    let bad = nan | (m == 0.0);
    Vec3::new(
        f32::from_bits(sel(bad, 0, s.x.to_bits())),
        f32::from_bits(sel(bad, 0, s.y.to_bits())),
        f32::from_bits(sel(bad, 0x3f80_0000, s.z.to_bits())),
    )
}

/// `v / sqrt(dot(v, v))` with the scalar twin's evaluation order.
#[inline(always)]
fn normalize(v: Vec3) -> Vec3 {
    v / ((v.x * v.x + v.y * v.y) + v.z * v.z).sqrt()
}

/// The octahedral projection of `s`, folded when `s.z < 0` (the sign of ±0 counts as +),
/// branch-free: shared by [`oct_continuous`] and [`substrate_continuous`].
#[inline(always)]
fn oct_fold(s: Vec3) -> Vec2 {
    let a = s.abs();
    oct_fold_l1(s, (a.x + a.y) + a.z)
}

/// [`oct_fold`] with the L1 norm passed in (the vouched encoders guard it, or divide by the
/// unscaled one): `oct::project`, branch-free.
#[inline(always)]
fn oct_fold_l1(s: Vec3, l1: f32) -> Vec2 {
    let p = Vec2::new(s.x / l1, s.y / l1);
    let sgn = Vec2::new(
        if p.x >= 0.0 { 1.0 } else { -1.0 },
        if p.y >= 0.0 { 1.0 } else { -1.0 },
    );
    let folded = (Vec2::ONE - Vec2::new(p.y.abs(), p.x.abs())) * sgn;
    let neg = s.z < 0.0;
    Vec2::new(
        if neg { folded.x } else { p.x },
        if neg { folded.y } else { p.y },
    )
}

/// [`oct::continuous`] with `m = max_code(bits)` as f32.
#[inline(always)]
fn oct_continuous(s: Vec3, m: f32) -> Vec2 {
    let t = (oct_fold(s) * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::splat(oct::CONTINUOUS_TOP));
    t * m
}

/// [`oct::lattice`] for `(u, v)`, `m = max_code(bits)`; |components| ≤ m < 2^16, so the
/// wrapping arithmetic never wraps.
#[inline(always)]
fn oct_lattice(u: u32, v: u32, m: i32) -> [i32; 3] {
    let a = ((u << 1) as i32).wrapping_sub(m);
    let b = ((v << 1) as i32).wrapping_sub(m);
    let z = m
        .wrapping_sub(a.wrapping_abs())
        .wrapping_sub(b.wrapping_abs());
    // (m − |b|)·signum(a) as a select: `i32::signum` does not vectorise (a, b are odd, so
    // never zero).
    let (fx, fy) = (
        m.wrapping_sub(b.wrapping_abs()),
        m.wrapping_sub(a.wrapping_abs()),
    );
    let fx = if a < 0 { fx.wrapping_neg() } else { fx };
    let fy = if b < 0 { fy.wrapping_neg() } else { fy };
    let pos = z >= 0;
    [if pos { a } else { fx }, if pos { b } else { fy }, z]
}

/// [`hemioct::lattice`] for `(u, v)`.
#[inline(always)]
fn hemioct_lattice(u: u32, v: u32) -> [i32; 3] {
    let m = hemioct::M as i32;
    let a = ((u << 1) as i32).wrapping_sub(m);
    let b = ((v << 1) as i32).wrapping_sub(m);
    [
        a.wrapping_add(b) / 2,
        a.wrapping_sub(b) / 2,
        m.wrapping_sub(a.wrapping_abs().max(b.wrapping_abs())),
    ]
}

/// The precise encoders' score `|s × D|² / |D|²` as the scalar twins compute it. `|D|² ≤ M²`
/// fits a `u32` (its L1 norm is M < 2^16).
#[inline(always)]
fn sin2(s: Vec3, d: [i32; 3]) -> f32 {
    let ad = [
        d[0].unsigned_abs(),
        d[1].unsigned_abs(),
        d[2].unsigned_abs(),
    ];
    let len2 = ad[0]
        .wrapping_mul(ad[0])
        .wrapping_add(ad[1].wrapping_mul(ad[1]))
        .wrapping_add(ad[2].wrapping_mul(ad[2])) as f32;
    let d = Vec3::new(d[0] as f32, d[1] as f32, d[2] as f32);
    let x = Vec3::new(
        s.y * d.z - s.z * d.y,
        s.z * d.x - s.x * d.z,
        s.x * d.y - s.y * d.x,
    );
    ((x.x * x.x + x.y * x.y) + x.z * x.z) / len2
}

/// The four-candidate selection of the precise encoders: of `base + {0,1}²` in the order
/// `(0,0), (1,0), (0,1), (1,1)`, the first with the strictly smallest score. `base = floor(c)`
/// is below M (the continuous coordinates stop below M), so every candidate is a code.
#[inline(always)]
fn best_of_four(s: Vec3, c: Vec2, lattice: impl Fn(u32, u32) -> [i32; 3]) -> (u32, u32) {
    let bx = floor_small(c.x);
    let by = floor_small(c.y);
    let (mut best_x, mut best_y) = (bx, by);
    let mut best_s2 = sin2(s, lattice(bx, by));
    for k in 1..4u32 {
        let (cx, cy) = (bx.wrapping_add(k & 1), by.wrapping_add(k >> 1));
        let s2 = sin2(s, lattice(cx, cy));
        let better = s2 < best_s2;
        best_x = sel(better, cx, best_x);
        best_y = sel(better, cy, best_y);
        best_s2 = if better { s2 } else { best_s2 };
    }
    (best_x, best_y)
}

/// `floor(c) as u32` for `0 ≤ c < 2^23`, exactly: the nearest integer `r`, less one where
/// `r > c` (`r` as f32 is exact). No float-to-int conversion, whose saturating form does not
/// vectorise.
#[inline(always)]
pub(crate) fn floor_small(c: f32) -> u32 {
    let r = round_even_small(c);
    r.wrapping_sub(u32::from(r as i32 as f32 > c))
}

#[inline(always)]
fn oct_precise_lane(n: Vec3, bits: u32, m: u32) -> u32 {
    let s = sanitize_or_z(n);
    let c = oct_continuous(s, m as f32);
    let (u, v) = best_of_four(s, c, |u, v| oct_lattice(u, v, m as i32));
    u | (v << bits)
}

#[inline(always)]
fn oct_round_lane(n: Vec3, bits: u32, m: u32) -> u32 {
    let c = oct_continuous(sanitize_or_z(n), m as f32);
    round_even_small(c.x) | (round_even_small(c.y) << bits)
}

/// The decoder's [`oct_lattice`] in f32: every value is an integer below 2^17, so each
/// operation is exact and the result is `oct_lattice(…) as f32`, zeros included: `a`, `b` are
/// odd, `z = (M − |a|) − |b|` is `+0` when zero, and the folded components get `+ 0.0`, which
/// turns the `−0` of a corner (`M − |b| = 0` with `a < 0`) into the integer's `+0` and leaves
/// every other value alone. Fewer vector operations than the integer form: `|x|` and the
/// fold's sign are bit masks.
#[inline(always)]
fn oct_lattice_f32(u: u32, v: u32, m: u32) -> Vec3 {
    let mf = m as i32 as f32;
    let a = ((u << 1) as i32).wrapping_sub(m as i32) as f32;
    let b = ((v << 1) as i32).wrapping_sub(m as i32) as f32;
    let (abs_a, abs_b) = (a.abs(), b.abs());
    let z = (mf - abs_a) - abs_b;
    // (M − |b|)·signum(a): M − |b| ≥ +0 gets a's sign bit, then −0 becomes +0.
    let fx = f32::from_bits((mf - abs_b).to_bits() | (a.to_bits() & 0x8000_0000)) + 0.0;
    let fy = f32::from_bits((mf - abs_a).to_bits() | (b.to_bits() & 0x8000_0000)) + 0.0;
    let neg = z < 0.0;
    Vec3::new(if neg { fx } else { a }, if neg { fy } else { b }, z)
}

#[inline(always)]
fn oct_decode_lane(p: u32, bits: u32, m: u32) -> Vec3 {
    normalize(oct_lattice_f32(p & m, (p >> bits) & m, m))
}

#[inline(always)]
fn hemioct_continuous(s: Vec3) -> Vec2 {
    hemioct_codes(s, (s.x.abs() + s.y.abs()) + s.z)
}

/// [`hemioct_continuous`] with the L1 norm passed in (`hemioct::codes`; the vouched encoder
/// keeps it at least `2^-126`).
#[inline(always)]
fn hemioct_codes(s: Vec3, l1: f32) -> Vec2 {
    let p = Vec2::new(s.x / l1, s.y / l1);
    let q = Vec2::new(p.x + p.y, p.x - p.y);
    (q * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::splat(oct::CONTINUOUS_TOP)) * hemioct::M as f32
}

#[inline(always)]
fn hemioct_precise_lane(n: Vec3) -> u32 {
    let s = hemioct_sanitize(n);
    let c = hemioct_continuous(s);
    let (u, v) = best_of_four(s, c, hemioct_lattice);
    u | (v << 12)
}

#[inline(always)]
fn hemioct_round_lane(n: Vec3) -> u32 {
    let c = hemioct_continuous(hemioct_sanitize(n));
    round_even_small(c.x) | (round_even_small(c.y) << 12)
}

#[inline(always)]
fn hemioct_decode_lane(p: u32) -> Vec3 {
    let d = hemioct_lattice(p & 0xfff, (p >> 12) & 0xfff);
    normalize(Vec3::new(d[0] as f32, d[1] as f32, d[2] as f32))
}

/// [`signed_oct::lattice`] for `(u, v)` (the upper hemisphere: `z ≥ 0`); every value is below
/// 2^11.
#[inline(always)]
fn signed_oct_lattice(u: u32, v: u32) -> [i32; 3] {
    let m = signed_oct::M as i32;
    let x = (u as i32).wrapping_sub(v as i32);
    let y = (u as i32).wrapping_add(v as i32).wrapping_sub(m);
    [
        x,
        y,
        m.wrapping_sub(x.wrapping_abs())
            .wrapping_sub(y.wrapping_abs()),
    ]
}

/// [`signed_oct::continuous`]: O3DE's order of operations.
#[inline(always)]
fn signed_oct_continuous(s: Vec3) -> Vec2 {
    let a = s.abs();
    let l1 = (a.x + a.y) + a.z;
    let p = Vec2::new(s.x / l1, s.y / l1);
    let y0 = p.y * 0.5 + 0.5;
    let rg = Vec2::new(p.x * 0.5 + y0, p.x * -0.5 + y0);
    rg.clamp(Vec2::ZERO, Vec2::splat(signed_oct::CONTINUOUS_TOP)) * signed_oct::M as f32
}

#[inline(always)]
fn signed_oct_precise_lane(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let a = Vec3::new(s.x, s.y, s.z.abs());
    let (u, v) = best_of_four(a, signed_oct_continuous(s), signed_oct_lattice);
    u | (v << 10) | sel(s.z > 0.0, signed_oct::B_MASK, 0)
}

#[inline(always)]
fn signed_oct_round_lane(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let c = signed_oct_continuous(s);
    round_even_small(c.x) | (round_even_small(c.y) << 10) | sel(s.z > 0.0, signed_oct::B_MASK, 0)
}

/// The twin's decode: `D` with z times the sign of B's factor for B = 0 or 1023, else
/// `(1023·D.x, 1023·D.y, (2b − 1023)·D.z)` (exact integers; `−0` on the equator for
/// `b < 512`), normalised.
#[inline(always)]
fn signed_oct_decode_lane(p: u32) -> Vec3 {
    let d = signed_oct_lattice(p & 0x3ff, (p >> 10) & 0x3ff);
    let m = signed_oct::M as f32;
    let f = signed_oct::z_factor(signed_oct::b_code(p)) as f32;
    let whole = f.abs() == m;
    let (s, zf) = (
        if whole { 1.0 } else { m },
        if whole { f.signum() } else { f },
    );
    normalize(Vec3::new(
        d[0] as f32 * s,
        d[1] as f32 * s,
        d[2] as f32 * zf,
    ))
}

#[inline(always)]
fn signed_oct_encode_unorm(n: Vec3) -> [f32; 4] {
    let p = signed_oct_precise_lane(n);
    let b = f32::from_bits(sel(p & signed_oct::SIGN_BIT != 0, 0x3f80_0000, 0));
    [unorm10_lane(p), unorm10_lane(p >> 10), b, 0.0]
}

#[inline(always)]
fn signed_oct_decode_unorm(c: [f32; 4]) -> Vec3 {
    let b = unorm10_code_lane(c[2]) << 20;
    signed_oct_decode_lane(unorm10_code_lane(c[0]) | (unorm10_code_lane(c[1]) << 10) | b)
}

/// The per-channel unorm encoders (xyz8: `M = 255`, `W = 8`; xyz10: `1023`, `10`):
/// `round(M·(u/2 + 1/2))` per coordinate of the unit vector, field k at bit `k·W`.
#[inline(always)]
fn unorm_xyz_encode_lane<const M: u32, const W: u32>(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let u = s / ((s.x * s.x + s.y * s.y) + s.z * s.z).sqrt();
    let c = (u * 0.5 + 0.5).clamp(Vec3::ZERO, Vec3::ONE) * M as f32;
    round_even_small(c.x) | (round_even_small(c.y) << W) | (round_even_small(c.z) << (2 * W))
}

/// The per-channel unorm decoders: `normalize(2k − M)` of the three `W`-bit fields.
#[inline(always)]
fn unorm_xyz_decode_lane<const M: u32, const W: u32>(p: u32) -> Vec3 {
    let c = |k: u32| (((k & ((1 << W) - 1)) << 1) as i32).wrapping_sub(M as i32) as f32;
    normalize(Vec3::new(c(p), c(p >> W), c(p >> (2 * W))))
}

/// `round_ties_even(127·x)` as a two's complement byte, for `|x| ≤ 1` (rounding is symmetric,
/// so the magnitude is rounded and the sign put back).
#[inline(always)]
fn snorm_byte_lane(x: f32) -> u32 {
    let r = round_even_small((x * 127.0).abs());
    sel(x < 0.0, r.wrapping_neg(), r) & 0xff
}

#[inline(always)]
fn snorm8_encode_lane(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let u = (s / ((s.x * s.x + s.y * s.y) + s.z * s.z).sqrt()).clamp(Vec3::NEG_ONE, Vec3::ONE);
    snorm_byte_lane(u.x) | (snorm_byte_lane(u.y) << 8) | (snorm_byte_lane(u.z) << 16)
}

/// The integer a snorm8 byte stands for, `max(b, −127)`.
#[inline(always)]
fn snorm_value_lane(b: u32) -> i32 {
    (((b & 0xff) << 24) as i32 >> 24).max(-127)
}

#[inline(always)]
fn snorm8_decode_lane(p: u32) -> Vec3 {
    let (x, y, z) = (
        snorm_value_lane(p),
        snorm_value_lane(p >> 8),
        snorm_value_lane(p >> 16),
    );
    let zero = (x | y | z) == 0;
    normalize(Vec3::new(x as f32, y as f32, (z + i32::from(zero)) as f32))
}

/// f32 → f16 bits, round to nearest even, for `|x| ≤ 1` (all the encoder passes it; any f32
/// there, subnormals and ±0 included): the normal-half range by integer rounding of the
/// dropped 13 mantissa bits (a carry moves into the exponent field correctly), the
/// subnormal-half range `|x| < 2^-14` as the integer nearest `|x|·2^24` (exact product).
#[inline(always)]
fn f16_bits_unit(x: f32) -> u32 {
    let b = x.to_bits();
    let sign = (b >> 16) & 0x8000;
    let a = b & 0x7fff_ffff;
    let normal = (a.wrapping_add(0x0fff).wrapping_add((a >> 13) & 1) >> 13).wrapping_sub(112 << 10);
    let sub = round_even_small(f32::from_bits(a) * 16_777_216.0);
    sign | sel(a >= 0x3880_0000, normal, sub)
}

/// f16 bits (low 16 bits of `h`) → f32, exactly; NaN halves give some NaN (the decoder only
/// asks whether it is one).
#[inline(always)]
fn f16_to_f32(h: u32) -> f32 {
    let sign = (h & 0x8000) << 16;
    let e = (h >> 10) & 0x1f;
    let m = h & 0x3ff;
    let normal = (e.wrapping_add(112) << 23) | (m << 13);
    let special = 0x7f80_0000 | (m << 13);
    let sub = (m as i32 as f32 * (1.0 / 16_777_216.0)).to_bits();
    f32::from_bits(sign | sel(e == 0, sub, sel(e == 31, special, normal)))
}

#[inline(always)]
fn xy_fp16_encode_lane(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let u = s / ((s.x * s.x + s.y * s.y) + s.z * s.z).sqrt();
    let xy = Vec2::new(u.x, u.y).clamp(Vec2::splat(-1.0), Vec2::splat(1.0));
    f16_bits_unit(xy.x) | (f16_bits_unit(xy.y) << 16)
}

#[inline(always)]
fn xy_fp16_decode_lane(p: u32) -> Vec3 {
    xy_fp16::decode_halves(Vec2::new(f16_to_f32(p & 0xffff), f16_to_f32(p >> 16)))
}

/// [`crate::depth24::unpack4x8unorm`]: `byte/255` per byte, byte 0 first.
#[inline(always)]
pub(crate) fn unpack4x8unorm_lane(p: u32) -> [f32; 4] {
    let c = |b: u32| (b & 0xff) as i32 as f32 / 255.0;
    [c(p), c(p >> 8), c(p >> 16), c(p >> 24)]
}

/// `round(255·clamp(c, 0, 1))` with NaN → 0 for one channel (the twins' `unorm_bytes` rule).
#[inline(always)]
pub(crate) fn unorm_byte_lane(c: f32) -> u32 {
    let c = if c.is_nan() { 0.0 } else { c };
    round_even_small(c.clamp(0.0, 1.0) * 255.0)
}

#[inline(always)]
fn unorm_bytes_lane(c: [f32; 4]) -> u32 {
    unorm_byte_lane(c[0])
        | (unorm_byte_lane(c[1]) << 8)
        | (unorm_byte_lane(c[2]) << 16)
        | (unorm_byte_lane(c[3]) << 24)
}

// Named lanes for the composite forms: a closure whose body is large after inlining may not be
// inlined into the loop itself (a call there stops the vectoriser); an `inline(always)` fn is.

#[inline(always)]
fn oct_precise_fixed<const BITS: u32>(n: Vec3) -> u32 {
    oct_precise_lane(n, BITS, (1 << BITS) - 1)
}
#[inline(always)]
fn oct_round_fixed<const BITS: u32>(n: Vec3) -> u32 {
    oct_round_lane(n, BITS, (1 << BITS) - 1)
}
#[inline(always)]
fn oct_decode_fixed<const BITS: u32>(p: u32) -> Vec3 {
    oct_decode_lane(p, BITS, (1 << BITS) - 1)
}
#[inline(always)]
fn oct_precise_unorm<const BITS: u32>(n: Vec3) -> [f32; 4] {
    unpack4x8unorm_lane(oct_precise_fixed::<BITS>(n))
}
#[inline(always)]
fn oct_decode_unorm<const BITS: u32>(c: [f32; 4]) -> Vec3 {
    oct_decode_fixed::<BITS>(unorm_bytes_lane(c))
}
#[inline(always)]
fn xyz8_encode_unorm(n: Vec3) -> [f32; 4] {
    unpack4x8unorm_lane(unorm_xyz_encode_lane::<255, 8>(n))
}
#[inline(always)]
fn xyz8_decode_unorm(c: [f32; 4]) -> Vec3 {
    unorm_xyz_decode_lane::<255, 8>(unorm_bytes_lane(c))
}
// ---- Unreal Substrate's centred 11:11 octahedron ([`substrate`]) ----

/// `round_ties_even(x)` as an `i32` for `|x| < 2^22`: `x + 1.5·2^23` lies in `[2^23, 2^24)`,
/// where the float spacing is 1, so the sum is `x` rounded half to even (`1.5·2^23` is even)
/// and its bits less those of `1.5·2^23` are that integer. Vectorises without `roundps`.
#[inline(always)]
fn round_even_signed(x: f32) -> i32 {
    ((x + 12_582_912.0).to_bits() as i32).wrapping_sub(0x4b40_0000)
}

/// `floor(x)` as an `i32` for `|x| < 2^22`, exactly: the nearest integer, less one where it
/// exceeds `x` (the integer is exact in f32).
#[inline(always)]
fn floor_signed(x: f32) -> i32 {
    let r = round_even_signed(x);
    r.wrapping_sub(i32::from(r as f32 > x))
}

/// [`substrate::continuous`], branch-free: the folded projection clamped to
/// `[−1, CONTINUOUS_TOP]`, times 1023.
#[inline(always)]
fn substrate_continuous(s: Vec3) -> Vec2 {
    oct_fold(s).clamp(Vec2::splat(-1.0), Vec2::splat(substrate::CONTINUOUS_TOP)) * 1023.0
}

/// [`substrate::lattice`] of the centred coordinates `a = k_u − 1024`, `b = k_v − 1024`: when
/// `z < 0`, `(1023 − |b|, 1023 − |a|)` with `a`'s and `b`'s signs (`+` for 0), as selects.
#[inline(always)]
fn substrate_lattice(a: i32, b: i32) -> [i32; 3] {
    let z = 1023i32
        .wrapping_sub(a.wrapping_abs())
        .wrapping_sub(b.wrapping_abs());
    let fx = 1023i32.wrapping_sub(b.wrapping_abs());
    let fy = 1023i32.wrapping_sub(a.wrapping_abs());
    let fx = if a < 0 { fx.wrapping_neg() } else { fx };
    let fy = if b < 0 { fy.wrapping_neg() } else { fy };
    let pos = z >= 0;
    [if pos { a } else { fx }, if pos { b } else { fy }, z]
}

/// The word bits of centred coordinates `(a, b)` (each in `[−1024, 1023]`).
#[inline(always)]
fn substrate_word(a: i32, b: i32) -> u32 {
    ((a.wrapping_add(1024) as u32) << substrate::U_SHIFT)
        | ((b.wrapping_add(1024) as u32) << substrate::V_SHIFT)
}

#[inline(always)]
fn substrate_precise_lane(n: Vec3) -> u32 {
    let s = sanitize_or_z(n);
    let q = substrate_continuous(s);
    let (ax, ay) = (floor_signed(q.x), floor_signed(q.y));
    let (mut best_a, mut best_b) = (ax, ay);
    let mut best_s2 = sin2(s, substrate_lattice(ax, ay));
    for k in 1..4i32 {
        let (ca, cb) = (ax.wrapping_add(k & 1), ay.wrapping_add(k >> 1));
        let s2 = sin2(s, substrate_lattice(ca, cb));
        let better = s2 < best_s2;
        best_a = if better { ca } else { best_a };
        best_b = if better { cb } else { best_b };
        best_s2 = if better { s2 } else { best_s2 };
    }
    substrate_word(best_a, best_b)
}

#[inline(always)]
fn substrate_round_lane(n: Vec3) -> u32 {
    let q = substrate_continuous(sanitize_or_z(n));
    substrate_word(round_even_signed(q.x), round_even_signed(q.y))
}

#[inline(always)]
fn substrate_decode_lane(p: u32) -> Vec3 {
    let a = (((p >> substrate::U_SHIFT) & 0x7ff) as i32).wrapping_sub(1024);
    let b = ((p >> substrate::V_SHIFT) as i32).wrapping_sub(1024);
    let d = substrate_lattice(a, b);
    normalize(Vec3::new(d[0] as f32, d[1] as f32, d[2] as f32))
}

/// Substrate's whole word from `(n, roughness, flags)`: the normal bits of `normal`, the
/// roughness byte ([`crate::roughness_ggx::encode_roughness_ggx8`]'s lane) at bit 2, the low 2
/// flag bits.
#[inline(always)]
fn substrate_word_with(normal: impl Fn(Vec3) -> u32, (n, r, flags): (Vec3, f32, u32)) -> u32 {
    normal(n) | (super::roughness_ggx::linear_lane(r, 256.0) << 2) | (flags & 3)
}
#[inline(always)]
fn substrate_word_lane(w: (Vec3, f32, u32)) -> u32 {
    substrate_word_with(substrate_precise_lane, w)
}
#[inline(always)]
fn substrate_word_fast_lane(w: (Vec3, f32, u32)) -> u32 {
    substrate_word_with(substrate_round_lane, w)
}

// ---- Vouched encoders ([`oct::encode_precise_vouched`], [`oct::encode_round_vouched`],
// hemioct's): the scalar twins' operations in order; only where those leave the result to a
// saturating float-to-int conversion (outside the contract) do the lanes differ. ----

/// `oct::scale_vouched` (and hemioct's, given the clamped vector): `n·2^(127 − e)`, `e` the
/// biased exponent of `‖n‖∞` taken as glam's `max_element` takes it, the `u32` arithmetic
/// wrapping as the twin's.
#[inline(always)]
fn scale_vouched_lane(n: Vec3) -> Vec3 {
    let a = n.abs();
    let max = |a: f32, b: f32| if a > b { a } else { b };
    let e = max(max(a.x, a.y), a.z).to_bits() >> 23;
    n * f32::from_bits(254u32.wrapping_sub(e) << 23)
}

/// `round_ties_even(x)` of a rounding vouched encoder's `t·M`, clamped to `[0, M]` first (NaN →
/// 0): in the contract `t·M` lies within a few ULP of `[0, M]` and rounds into it, so the clamp
/// changes no code; outside it, it keeps each axis a code (the twin's `as u32` saturates, which
/// does not vectorise).
#[inline(always)]
fn round_code_lane(x: f32, m: f32) -> u32 {
    let x = if x > 0.0 { x } else { 0.0 };
    round_even_small(if x < m { x } else { m })
}

#[inline(always)]
fn oct_precise_vouched_lane<const BITS: u32>(n: Vec3) -> u32 {
    let m = (1u32 << BITS) - 1;
    let s = scale_vouched_lane(n);
    let a = s.abs();
    let p = oct_fold_l1(s, ((a.x + a.y) + a.z).max(f32::MIN_POSITIVE));
    let c = (p * 0.5 + 0.5).clamp(Vec2::ZERO, Vec2::splat(oct::CONTINUOUS_TOP)) * m as f32;
    let (u, v) = best_of_four(s, c, |u, v| oct_lattice(u, v, m as i32));
    u | (v << BITS)
}

#[inline(always)]
fn oct_round_vouched_lane<const BITS: u32>(n: Vec3) -> u32 {
    let m = ((1u32 << BITS) - 1) as f32;
    let a = n.abs();
    let t = oct_fold_l1(n, (a.x + a.y) + a.z) * 0.5 + 0.5;
    round_code_lane(t.x * m, m) | (round_code_lane(t.y * m, m) << BITS)
}

#[inline(always)]
fn hemioct_precise_vouched_lane(n: Vec3) -> u32 {
    let s = scale_vouched_lane(Vec3::new(n.x, n.y, n.z.max(0.0)));
    let a = s.abs();
    let c = hemioct_codes(s, ((a.x + a.y) + s.z).max(f32::MIN_POSITIVE));
    let (u, v) = best_of_four(s, c, hemioct_lattice);
    u | (v << 12)
}

#[inline(always)]
fn hemioct_round_vouched_lane(n: Vec3) -> u32 {
    let l1 = (n.x.abs() + n.y.abs()) + n.z.max(0.0);
    let p = Vec2::new(n.x / l1, n.y / l1);
    let t = Vec2::new(p.x + p.y, p.x - p.y) * 0.5 + 0.5;
    let m = hemioct::M as f32;
    round_code_lane(t.x * m, m) | (round_code_lane(t.y * m, m) << 12)
}

#[inline(always)]
fn unity_bytes_lane(p: u32) -> u32 {
    let (u, v) = (p & 0xfff, (p >> 12) & 0xfff);
    (u & 0xff) | ((v & 0xff) << 8) | ((u >> 8) << 16) | ((v >> 8) << 20)
}
#[inline(always)]
fn unity_word_lane(p: u32) -> u32 {
    ((p & 0xff) | (((p >> 16) & 0xf) << 8)) | ((((p >> 8) & 0xff) | (((p >> 20) & 0xf) << 8)) << 12)
}
#[inline(always)]
fn oct24_unity_precise(n: Vec3) -> u32 {
    unity_bytes_lane(oct_precise_fixed::<12>(n))
}
#[inline(always)]
fn oct24_unity_round(n: Vec3) -> u32 {
    unity_bytes_lane(oct_round_fixed::<12>(n))
}
#[inline(always)]
fn oct24_unity_decode(p: u32) -> Vec3 {
    oct_decode_fixed::<12>(unity_word_lane(p))
}
#[inline(always)]
fn oct24_unity_encode_unorm(n: Vec3) -> [f32; 4] {
    unpack4x8unorm_lane(oct24_unity_precise(n))
}
#[inline(always)]
fn oct24_unity_decode_unorm(c: [f32; 4]) -> Vec3 {
    oct24_unity_decode(unorm_bytes_lane(c))
}
/// The rgb10a2unorm channel `k/1023` of the 10-bit field at the bottom of `k`.
#[inline(always)]
fn unorm10_lane(k: u32) -> f32 {
    (k & 0x3ff) as f32 / 1023.0
}
/// The 10-bit code of a sampled rgb10a2unorm channel, from the bits as the scalar twin
/// (`normal::xyz10`): NaN, negatives and −0 → 0, 1 up to +∞ → 1, then `round(1023·c)`.
#[inline(always)]
fn unorm10_code_lane(x: f32) -> u32 {
    let b = x.to_bits();
    let b = sel(b > 0x7f80_0000, 0, sel(b >= 0x3f80_0000, 0x3f80_0000, b));
    round_even_small(f32::from_bits(b) * 1023.0)
}
#[inline(always)]
fn xyz10_encode_unorm(n: Vec3) -> [f32; 4] {
    let p = unorm_xyz_encode_lane::<1023, 10>(n);
    [
        unorm10_lane(p),
        unorm10_lane(p >> 10),
        unorm10_lane(p >> 20),
        0.0,
    ]
}
#[inline(always)]
fn xyz10_decode_unorm(c: [f32; 4]) -> Vec3 {
    let k = unorm10_code_lane;
    unorm_xyz_decode_lane::<1023, 10>(k(c[0]) | (k(c[1]) << 10) | (k(c[2]) << 20))
}
#[inline(always)]
fn oct20_encode_unorm(n: Vec3) -> [f32; 4] {
    let p = oct_precise_fixed::<10>(n);
    [unorm10_lane(p), unorm10_lane(p >> 10), 0.0, 0.0]
}
#[inline(always)]
fn oct20_decode_unorm(c: [f32; 4]) -> Vec3 {
    oct_decode_fixed::<10>(unorm10_code_lane(c[0]) | (unorm10_code_lane(c[1]) << 10))
}
#[inline(always)]
fn snorm8_encode_snorm(n: Vec3) -> [f32; 4] {
    let p = snorm8_encode_lane(n);
    let c = |b: u32| ((((b & 0xff) << 24) as i32) >> 24) as f32 / 127.0;
    [c(p), c(p >> 8), c(p >> 16), 0.0]
}
#[inline(always)]
fn snorm8_decode_snorm(c: [f32; 4]) -> Vec3 {
    // From the bits, as the scalar twin: NaN → 0, magnitudes from 1 up to ∞ → ±1.
    let b = |x: f32| {
        let bits = x.to_bits();
        let mag = bits & 0x7fff_ffff;
        let v = sel(
            mag > 0x7f80_0000,
            0,
            sel(mag >= 0x3f80_0000, (bits & 0x8000_0000) | 0x3f80_0000, bits),
        );
        snorm_byte_lane(f32::from_bits(v))
    };
    snorm8_decode_lane(b(c[0]) | (b(c[1]) << 8) | (b(c[2]) << 16))
}
#[inline(always)]
fn xy_fp16_encode_unorm(n: Vec3) -> [f32; 4] {
    unpack4x8unorm_lane(xy_fp16_encode_lane(n))
}
#[inline(always)]
fn xy_fp16_decode_unorm(c: [f32; 4]) -> Vec3 {
    xy_fp16_decode_lane(unorm_bytes_lane(c))
}
#[inline(always)]
fn hemioct_encode_unorm(n: Vec3) -> [f32; 4] {
    unpack4x8unorm_lane(hemioct_precise_lane(n))
}
#[inline(always)]
fn hemioct_decode_unorm(c: [f32; 4]) -> Vec3 {
    hemioct_decode_lane(unorm_bytes_lane(c))
}

// ---------------------------------------------------------------------------------------------
// The public batch twins.

batch_fn!(
    /// Batch [`xyz8::encode_normal_xyz8`].
    encode_normal_xyz8, encode_normal_xyz8_with, "normal::encode_normal_xyz8",
    (), Vec3 => u32,
    scalar: xyz8::encode_normal_xyz8,
    lane: unorm_xyz_encode_lane::<255, 8>,
);
batch_fn!(
    /// Batch [`xyz8::decode_normal_xyz8`].
    decode_normal_xyz8, decode_normal_xyz8_with, "normal::decode_normal_xyz8",
    (), u32 => Vec3,
    scalar: xyz8::decode_normal_xyz8,
    lane: unorm_xyz_decode_lane::<255, 8>,
);
batch_fn!(
    /// Batch [`xyz8::encode_normal_xyz8_unorm`].
    encode_normal_xyz8_unorm, encode_normal_xyz8_unorm_with, "normal::encode_normal_xyz8_unorm",
    (), Vec3 => [f32; 4],
    scalar: xyz8::encode_normal_xyz8_unorm,
    lane: xyz8_encode_unorm,
);
batch_fn!(
    /// Batch [`xyz8::encode_normal_xyz8_best`]: the scalar twin per element (its search over
    /// 128 planes, most of them skipped by a data-dependent bound, does not vectorise); split
    /// across rayon's pool for long batches, which is what makes it worth calling for baking.
    encode_normal_xyz8_best, encode_normal_xyz8_best_with, "normal::encode_normal_xyz8_best",
    (), Vec3 => u32,
    scalar: xyz8::encode_normal_xyz8_best,
    lane: xyz8::encode_normal_xyz8_best,
);
batch_fn!(
    /// Batch [`xyz8::encode_normal_xyz8_best_unorm`] (the scalar twin per element, as
    /// [`encode_normal_xyz8_best`]).
    encode_normal_xyz8_best_unorm, encode_normal_xyz8_best_unorm_with,
    "normal::encode_normal_xyz8_best_unorm",
    (), Vec3 => [f32; 4],
    scalar: xyz8::encode_normal_xyz8_best_unorm,
    lane: xyz8::encode_normal_xyz8_best_unorm,
);
batch_fn!(
    /// Batch [`xyz8::decode_normal_xyz8_unorm`].
    decode_normal_xyz8_unorm, decode_normal_xyz8_unorm_with, "normal::decode_normal_xyz8_unorm",
    (), [f32; 4] => Vec3,
    scalar: xyz8::decode_normal_xyz8_unorm,
    lane: xyz8_decode_unorm,
);

batch_fn!(
    /// Batch [`substrate::encode_substrate_normal`].
    encode_substrate_normal, encode_substrate_normal_with, "normal::encode_substrate_normal",
    (), Vec3 => u32,
    scalar: substrate::encode_substrate_normal,
    lane: substrate_precise_lane,
);
batch_fn!(
    /// Batch [`substrate::encode_substrate_normal_fast`].
    encode_substrate_normal_fast, encode_substrate_normal_fast_with,
    "normal::encode_substrate_normal_fast",
    (), Vec3 => u32,
    scalar: substrate::encode_substrate_normal_fast,
    lane: substrate_round_lane,
);
batch_fn!(
    /// Batch [`substrate::decode_substrate_normal`].
    decode_substrate_normal, decode_substrate_normal_with, "normal::decode_substrate_normal",
    (), u32 => Vec3,
    scalar: substrate::decode_substrate_normal,
    lane: substrate_decode_lane,
);
batch_fn!(
    /// Batch [`substrate::encode_substrate_word`]: each `src[i] = (n, roughness, flags)` packed
    /// into Unreal Substrate's whole 32-bit word, `normal22 << 10 | byte << 2 | (flags & 3)`:
    /// the precise centred 11:11 octahedral code of `n` (bits 10–31), the roughness byte
    /// nearest `255·clamp(roughness, 0, 1)` (exact; NaN → 255), the low two flag bits. The
    /// scalar twin's word for every input, so its error bound: the normal within
    /// [`substrate::encode_substrate_normal`]'s (≈ 0.1189° plus the f32 scoring tolerance), the
    /// roughness within half a step, `1/510`.
    encode_substrate_word, encode_substrate_word_with, "normal::encode_substrate_word",
    (), (Vec3, f32, u32) => u32,
    scalar: |(n, r, flags)| substrate::encode_substrate_word(n, r, flags),
    lane: substrate_word_lane,
);
batch_fn!(
    /// Batch [`substrate::encode_substrate_word_fast`]: [`encode_substrate_word`] with the
    /// rounding normal encoder ([`substrate::encode_substrate_normal_fast`]: each centred
    /// coordinate rounded half to even, within ≈ 0.1189° of the input); the scalar twin's word
    /// for every input.
    encode_substrate_word_fast, encode_substrate_word_fast_with,
    "normal::encode_substrate_word_fast",
    (), (Vec3, f32, u32) => u32,
    scalar: |(n, r, flags)| substrate::encode_substrate_word_fast(n, r, flags),
    lane: substrate_word_fast_lane,
);

batch_fn!(
    /// Batch [`oct::encode_normal_oct24_unity`].
    encode_normal_oct24_unity, encode_normal_oct24_unity_with, "normal::encode_normal_oct24_unity",
    (), Vec3 => u32,
    scalar: oct::encode_normal_oct24_unity,
    lane: oct24_unity_precise,
);
batch_fn!(
    /// Batch [`oct::encode_normal_oct24_hdrp`] (the scalar twin per element: HDRP's `|z|` floor
    /// needs the sanitized vector's length before the precise search).
    encode_normal_oct24_hdrp, encode_normal_oct24_hdrp_with, "normal::encode_normal_oct24_hdrp",
    (), Vec3 => u32,
    scalar: oct::encode_normal_oct24_hdrp,
    lane: oct::encode_normal_oct24_hdrp,
);
batch_fn!(
    /// Batch [`oct::encode_normal_oct24_unity_fast`].
    encode_normal_oct24_unity_fast, encode_normal_oct24_unity_fast_with,
    "normal::encode_normal_oct24_unity_fast",
    (), Vec3 => u32,
    scalar: oct::encode_normal_oct24_unity_fast,
    lane: oct24_unity_round,
);
batch_fn!(
    /// Batch [`oct::decode_normal_oct24_unity`].
    decode_normal_oct24_unity, decode_normal_oct24_unity_with, "normal::decode_normal_oct24_unity",
    (), u32 => Vec3,
    scalar: oct::decode_normal_oct24_unity,
    lane: oct24_unity_decode,
);
batch_fn!(
    /// Batch [`oct::encode_normal_oct24_unity_unorm`].
    encode_normal_oct24_unity_unorm, encode_normal_oct24_unity_unorm_with,
    "normal::encode_normal_oct24_unity_unorm",
    (), Vec3 => [f32; 4],
    scalar: oct::encode_normal_oct24_unity_unorm,
    lane: oct24_unity_encode_unorm,
);
batch_fn!(
    /// Batch [`oct::decode_normal_oct24_unity_unorm`].
    decode_normal_oct24_unity_unorm, decode_normal_oct24_unity_unorm_with,
    "normal::decode_normal_oct24_unity_unorm",
    (), [f32; 4] => Vec3,
    scalar: oct::decode_normal_oct24_unity_unorm,
    lane: oct24_unity_decode_unorm,
);

batch_fn!(
    /// Batch [`oct::encode_normal_oct20`].
    encode_normal_oct20, encode_normal_oct20_with, "normal::encode_normal_oct20",
    (), Vec3 => u32,
    scalar: oct::encode_normal_oct20,
    lane: oct_precise_fixed::<10>,
);
batch_fn!(
    /// Batch [`oct::encode_normal_oct20_fast`].
    encode_normal_oct20_fast, encode_normal_oct20_fast_with, "normal::encode_normal_oct20_fast",
    (), Vec3 => u32,
    scalar: oct::encode_normal_oct20_fast,
    lane: oct_round_fixed::<10>,
);
batch_fn!(
    /// Batch [`oct::decode_normal_oct20`].
    decode_normal_oct20, decode_normal_oct20_with, "normal::decode_normal_oct20",
    (), u32 => Vec3,
    scalar: oct::decode_normal_oct20,
    lane: oct_decode_fixed::<10>,
);
batch_fn!(
    /// Batch [`oct::encode_normal_oct20_unorm`].
    encode_normal_oct20_unorm, encode_normal_oct20_unorm_with, "normal::encode_normal_oct20_unorm",
    (), Vec3 => [f32; 4],
    scalar: oct::encode_normal_oct20_unorm,
    lane: oct20_encode_unorm,
);
batch_fn!(
    /// Batch [`oct::decode_normal_oct20_unorm`].
    decode_normal_oct20_unorm, decode_normal_oct20_unorm_with, "normal::decode_normal_oct20_unorm",
    (), [f32; 4] => Vec3,
    scalar: oct::decode_normal_oct20_unorm,
    lane: oct20_decode_unorm,
);

batch_fn!(
    /// Batch [`xyz10::encode_normal_xyz10`].
    encode_normal_xyz10, encode_normal_xyz10_with, "normal::encode_normal_xyz10",
    (), Vec3 => u32,
    scalar: xyz10::encode_normal_xyz10,
    lane: unorm_xyz_encode_lane::<1023, 10>,
);
batch_fn!(
    /// Batch [`xyz10::decode_normal_xyz10`].
    decode_normal_xyz10, decode_normal_xyz10_with, "normal::decode_normal_xyz10",
    (), u32 => Vec3,
    scalar: xyz10::decode_normal_xyz10,
    lane: unorm_xyz_decode_lane::<1023, 10>,
);
batch_fn!(
    /// Batch [`xyz10::encode_normal_xyz10_unorm`].
    encode_normal_xyz10_unorm, encode_normal_xyz10_unorm_with, "normal::encode_normal_xyz10_unorm",
    (), Vec3 => [f32; 4],
    scalar: xyz10::encode_normal_xyz10_unorm,
    lane: xyz10_encode_unorm,
);
batch_fn!(
    /// Batch [`xyz10::decode_normal_xyz10_unorm`].
    decode_normal_xyz10_unorm, decode_normal_xyz10_unorm_with, "normal::decode_normal_xyz10_unorm",
    (), [f32; 4] => Vec3,
    scalar: xyz10::decode_normal_xyz10_unorm,
    lane: xyz10_decode_unorm,
);

batch_fn!(
    /// Batch [`snorm8::encode_normal_snorm8`].
    encode_normal_snorm8, encode_normal_snorm8_with, "normal::encode_normal_snorm8",
    (), Vec3 => u32,
    scalar: snorm8::encode_normal_snorm8,
    lane: snorm8_encode_lane,
);
batch_fn!(
    /// Batch [`snorm8::decode_normal_snorm8`].
    decode_normal_snorm8, decode_normal_snorm8_with, "normal::decode_normal_snorm8",
    (), u32 => Vec3,
    scalar: snorm8::decode_normal_snorm8,
    lane: snorm8_decode_lane,
);
batch_fn!(
    /// Batch [`snorm8::encode_normal_snorm8_snorm`].
    encode_normal_snorm8_snorm, encode_normal_snorm8_snorm_with, "normal::encode_normal_snorm8_snorm",
    (), Vec3 => [f32; 4],
    scalar: snorm8::encode_normal_snorm8_snorm,
    lane: snorm8_encode_snorm,
);
batch_fn!(
    /// Batch [`snorm8::decode_normal_snorm8_snorm`].
    decode_normal_snorm8_snorm, decode_normal_snorm8_snorm_with, "normal::decode_normal_snorm8_snorm",
    (), [f32; 4] => Vec3,
    scalar: snorm8::decode_normal_snorm8_snorm,
    lane: snorm8_decode_snorm,
);

batch_fn!(
    /// Batch [`xy_fp16::encode_normal_xy_fp16`].
    encode_normal_xy_fp16, encode_normal_xy_fp16_with, "normal::encode_normal_xy_fp16",
    (), Vec3 => u32,
    scalar: xy_fp16::encode_normal_xy_fp16,
    lane: xy_fp16_encode_lane,
);
batch_fn!(
    /// Batch [`xy_fp16::decode_normal_xy_fp16`].
    decode_normal_xy_fp16, decode_normal_xy_fp16_with, "normal::decode_normal_xy_fp16",
    (), u32 => Vec3,
    scalar: xy_fp16::decode_normal_xy_fp16,
    lane: xy_fp16_decode_lane,
);
batch_fn!(
    /// Batch [`xy_fp16::encode_normal_xy_fp16_unorm`].
    encode_normal_xy_fp16_unorm, encode_normal_xy_fp16_unorm_with,
    "normal::encode_normal_xy_fp16_unorm",
    (), Vec3 => [f32; 4],
    scalar: xy_fp16::encode_normal_xy_fp16_unorm,
    lane: xy_fp16_encode_unorm,
);
batch_fn!(
    /// Batch [`xy_fp16::decode_normal_xy_fp16_unorm`].
    decode_normal_xy_fp16_unorm, decode_normal_xy_fp16_unorm_with,
    "normal::decode_normal_xy_fp16_unorm",
    (), [f32; 4] => Vec3,
    scalar: xy_fp16::decode_normal_xy_fp16_unorm,
    lane: xy_fp16_decode_unorm,
);

batch_fn!(
    /// Batch [`oct::encode_precise`] with `bits` bits per axis (**panics** unless
    /// `1 ≤ bits ≤ 16`, as [`oct::max_code`]).
    encode_oct_precise, encode_oct_precise_with, "normal::encode_oct_precise",
    (bits: u32), Vec3 => u32,
    scalar: |n| oct::encode_precise(n, bits),
    lane: {
        let m = oct::max_code(bits);
        move |n| oct_precise_lane(n, bits, m)
    },
);
batch_fn!(
    /// Batch [`oct::encode_round`] with `bits` bits per axis (**panics** unless
    /// `1 ≤ bits ≤ 16`).
    encode_oct_round, encode_oct_round_with, "normal::encode_oct_round",
    (bits: u32), Vec3 => u32,
    scalar: |n| oct::encode_round(n, bits),
    lane: {
        let m = oct::max_code(bits);
        move |n| oct_round_lane(n, bits, m)
    },
);
batch_fn!(
    /// Batch [`oct::decode`] with `bits` bits per axis (**panics** unless `1 ≤ bits ≤ 16`).
    decode_oct, decode_oct_with, "normal::decode_oct",
    (bits: u32), u32 => Vec3,
    scalar: |p| oct::decode(p, bits),
    lane: {
        let m = oct::max_code(bits);
        move |p| oct_decode_lane(p, bits, m)
    },
);

macro_rules! oct_size {
    ($bits:literal, $enc:ident, $enc_w:ident, $fast:ident, $fast_w:ident, $dec:ident, $dec_w:ident,
     $eu:ident, $eu_w:ident, $du:ident, $du_w:ident) => {
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($enc), "`].")]
            $enc, $enc_w, concat!("normal::", stringify!($enc)),
            (), Vec3 => u32,
            scalar: oct::$enc,
            lane: oct_precise_fixed::<$bits>,
        );
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($fast), "`].")]
            $fast, $fast_w, concat!("normal::", stringify!($fast)),
            (), Vec3 => u32,
            scalar: oct::$fast,
            lane: oct_round_fixed::<$bits>,
        );
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($dec), "`].")]
            $dec, $dec_w, concat!("normal::", stringify!($dec)),
            (), u32 => Vec3,
            scalar: oct::$dec,
            lane: oct_decode_fixed::<$bits>,
        );
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($eu), "`].")]
            $eu, $eu_w, concat!("normal::", stringify!($eu)),
            (), Vec3 => [f32; 4],
            scalar: oct::$eu,
            lane: oct_precise_unorm::<$bits>,
        );
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($du), "`].")]
            $du, $du_w, concat!("normal::", stringify!($du)),
            (), [f32; 4] => Vec3,
            scalar: oct::$du,
            lane: oct_decode_unorm::<$bits>,
        );
    };
}

oct_size!(
    8,
    encode_normal_oct16,
    encode_normal_oct16_with,
    encode_normal_oct16_fast,
    encode_normal_oct16_fast_with,
    decode_normal_oct16,
    decode_normal_oct16_with,
    encode_normal_oct16_unorm,
    encode_normal_oct16_unorm_with,
    decode_normal_oct16_unorm,
    decode_normal_oct16_unorm_with
);
oct_size!(
    12,
    encode_normal_oct24,
    encode_normal_oct24_with,
    encode_normal_oct24_fast,
    encode_normal_oct24_fast_with,
    decode_normal_oct24,
    decode_normal_oct24_with,
    encode_normal_oct24_unorm,
    encode_normal_oct24_unorm_with,
    decode_normal_oct24_unorm,
    decode_normal_oct24_unorm_with
);
oct_size!(
    16,
    encode_normal_oct32,
    encode_normal_oct32_with,
    encode_normal_oct32_fast,
    encode_normal_oct32_fast_with,
    decode_normal_oct32,
    decode_normal_oct32_with,
    encode_normal_oct32_unorm,
    encode_normal_oct32_unorm_with,
    decode_normal_oct32_unorm,
    decode_normal_oct32_unorm_with
);

batch_fn!(
    /// Batch [`hemioct::encode_normal_hemioct24`].
    encode_normal_hemioct24, encode_normal_hemioct24_with, "normal::encode_normal_hemioct24",
    (), Vec3 => u32,
    scalar: hemioct::encode_normal_hemioct24,
    lane: hemioct_precise_lane,
);
batch_fn!(
    /// Batch [`hemioct::encode_normal_hemioct24_fast`].
    encode_normal_hemioct24_fast, encode_normal_hemioct24_fast_with,
    "normal::encode_normal_hemioct24_fast",
    (), Vec3 => u32,
    scalar: hemioct::encode_normal_hemioct24_fast,
    lane: hemioct_round_lane,
);
batch_fn!(
    /// Batch [`hemioct::decode_normal_hemioct24`].
    decode_normal_hemioct24, decode_normal_hemioct24_with, "normal::decode_normal_hemioct24",
    (), u32 => Vec3,
    scalar: hemioct::decode_normal_hemioct24,
    lane: hemioct_decode_lane,
);
batch_fn!(
    /// Batch [`hemioct::encode_normal_hemioct24_unorm`].
    encode_normal_hemioct24_unorm, encode_normal_hemioct24_unorm_with,
    "normal::encode_normal_hemioct24_unorm",
    (), Vec3 => [f32; 4],
    scalar: hemioct::encode_normal_hemioct24_unorm,
    lane: hemioct_encode_unorm,
);
batch_fn!(
    /// Batch [`hemioct::decode_normal_hemioct24_unorm`].
    decode_normal_hemioct24_unorm, decode_normal_hemioct24_unorm_with,
    "normal::decode_normal_hemioct24_unorm",
    (), [f32; 4] => Vec3,
    scalar: hemioct::decode_normal_hemioct24_unorm,
    lane: hemioct_decode_unorm,
);

batch_fn!(
    /// Batch [`signed_oct::encode_normal_signed_oct`].
    encode_normal_signed_oct, encode_normal_signed_oct_with, "normal::encode_normal_signed_oct",
    (), Vec3 => u32,
    scalar: signed_oct::encode_normal_signed_oct,
    lane: signed_oct_precise_lane,
);
batch_fn!(
    /// Batch [`signed_oct::encode_normal_signed_oct_fast`].
    encode_normal_signed_oct_fast, encode_normal_signed_oct_fast_with,
    "normal::encode_normal_signed_oct_fast",
    (), Vec3 => u32,
    scalar: signed_oct::encode_normal_signed_oct_fast,
    lane: signed_oct_round_lane,
);
batch_fn!(
    /// Batch [`signed_oct::decode_normal_signed_oct`].
    decode_normal_signed_oct, decode_normal_signed_oct_with, "normal::decode_normal_signed_oct",
    (), u32 => Vec3,
    scalar: signed_oct::decode_normal_signed_oct,
    lane: signed_oct_decode_lane,
);
batch_fn!(
    /// Batch [`signed_oct::encode_normal_signed_oct_unorm`].
    encode_normal_signed_oct_unorm, encode_normal_signed_oct_unorm_with,
    "normal::encode_normal_signed_oct_unorm",
    (), Vec3 => [f32; 4],
    scalar: signed_oct::encode_normal_signed_oct_unorm,
    lane: signed_oct_encode_unorm,
);
batch_fn!(
    /// Batch [`signed_oct::decode_normal_signed_oct_unorm`].
    decode_normal_signed_oct_unorm, decode_normal_signed_oct_unorm_with,
    "normal::decode_normal_signed_oct_unorm",
    (), [f32; 4] => Vec3,
    scalar: signed_oct::decode_normal_signed_oct_unorm,
    lane: signed_oct_decode_unorm,
);

macro_rules! oct_vouched {
    ($bits:literal, $m:literal, $enc:ident, $enc_w:ident, $robust:ident,
     $fast:ident, $fast_w:ident, $robust_fast:ident) => {
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($enc), "`]: the precise octahedral code (", stringify!($bits), " bits per axis) of a vector the caller vouches for.")]
            ///
            /// **Inside the contract** ([`oct::is_vouched`]: components finite, non-zero ones at
            /// least `2^-126·max(1, ‖n‖∞)`, `0 < ‖n‖∞ ≤ 2^124`), and for the zero vector (+z),
            /// each element is the scalar vouched twin's code bit for bit, which is
            #[doc = concat!("[`oct::", stringify!($robust), "`]'s:")]
            /// the best of the four codes around the continuous coordinates, so its maths and
            /// error bound ([`oct::encode_precise_vouched`], [`oct::encode_precise`]).
            #[doc = concat!("**Outside it:** some valid code, unspecified (each axis in `[0, ", $m, "]`, the bits above the code zero); never panics.")]
            $enc, $enc_w, concat!("normal::", stringify!($enc)),
            (), Vec3 => u32,
            scalar: oct::$enc,
            lane: oct_precise_vouched_lane::<$bits>,
        );
        batch_fn!(
            #[doc = concat!("Batch [`oct::", stringify!($fast), "`]: the rounding octahedral code (", stringify!($bits), " bits per axis) of a vector the caller vouches for, `round(t·M)` half to even per axis, `t = p/2 + 1/2`, `p` the folded projection.")]
            ///
            /// **Inside the contract** ([`oct::is_vouched`]; the zero vector is outside it) each
            /// element is the scalar vouched twin's code bit for bit, which is
            #[doc = concat!("[`oct::", stringify!($robust_fast), "`]'s,")]
            /// with its error bound ([`oct::encode_round_vouched`], [`oct::encode_round`]).
            #[doc = concat!("**Outside it:** some valid code, unspecified (each axis in `[0, ", $m, "]`, the bits above the code zero; the scalar twin's saturating conversion may differ); never panics.")]
            $fast, $fast_w, concat!("normal::", stringify!($fast)),
            (), Vec3 => u32,
            scalar: oct::$fast,
            lane: oct_round_vouched_lane::<$bits>,
        );
    };
}

oct_vouched!(
    8,
    "255",
    encode_normal_oct16_vouched,
    encode_normal_oct16_vouched_with,
    encode_normal_oct16,
    encode_normal_oct16_fast_vouched,
    encode_normal_oct16_fast_vouched_with,
    encode_normal_oct16_fast
);
oct_vouched!(
    12,
    "4095",
    encode_normal_oct24_vouched,
    encode_normal_oct24_vouched_with,
    encode_normal_oct24,
    encode_normal_oct24_fast_vouched,
    encode_normal_oct24_fast_vouched_with,
    encode_normal_oct24_fast
);
oct_vouched!(
    16,
    "65535",
    encode_normal_oct32_vouched,
    encode_normal_oct32_vouched_with,
    encode_normal_oct32,
    encode_normal_oct32_fast_vouched,
    encode_normal_oct32_fast_vouched_with,
    encode_normal_oct32_fast
);

batch_fn!(
    /// Batch [`hemioct::encode_normal_hemioct24_vouched`]: the precise hemi-octahedral code of a
    /// vector the caller vouches for.
    ///
    /// **Inside the contract** ([`hemioct::is_vouched`]: `n` finite; on the clamp
    /// `c = (x, y, max(z, 0))`, non-zero components at least `2^-126·max(1, ‖c‖∞)`,
    /// `0 < ‖c‖∞ ≤ 2^124`), and for a zero clamp (+z), each element is the scalar vouched
    /// twin's code bit for bit, which is [`hemioct::encode_normal_hemioct24`]'s: the best of the
    /// four codes around the continuous coordinates, with its error bound.
    /// **Outside it:** some valid code, unspecified (each axis in `[0, 4095]`, bits 24–31
    /// zero); never panics.
    encode_normal_hemioct24_vouched, encode_normal_hemioct24_vouched_with,
    "normal::encode_normal_hemioct24_vouched",
    (), Vec3 => u32,
    scalar: hemioct::encode_normal_hemioct24_vouched,
    lane: hemioct_precise_vouched_lane,
);
batch_fn!(
    /// Batch [`hemioct::encode_normal_hemioct24_fast_vouched`]: the rounding hemi-octahedral
    /// code of a vector the caller vouches for, `round(t·4095)` half to even per axis,
    /// `t = q/2 + 1/2`, `q = (p.x + p.y, p.x − p.y)`, `p = n.xy / ((|x| + |y|) + max(z, 0))`.
    ///
    /// **Inside the contract** ([`hemioct::is_vouched`]; a zero clamp is outside it) each
    /// element is the scalar vouched twin's code bit for bit, which is
    /// [`hemioct::encode_normal_hemioct24_fast`]'s, with its error bound.
    /// **Outside it:** some valid code, unspecified (each axis in `[0, 4095]`, bits 24–31
    /// zero; the scalar twin's saturating conversion may differ); never panics.
    encode_normal_hemioct24_fast_vouched, encode_normal_hemioct24_fast_vouched_with,
    "normal::encode_normal_hemioct24_fast_vouched",
    (), Vec3 => u32,
    scalar: hemioct::encode_normal_hemioct24_fast_vouched,
    lane: hemioct_round_vouched_lane,
);
