//! The light pre-pass factorisation `result = C(mp, Σ P(l_i, gp))` and Engel's specular
//! reconstruction — Rust twins of `wgsl/lpp.wgsl`. Sources: Mark Lee, "Pre-lighting in
//! Resistance 2" (Insomniac Games, GDC 2009); Wolfgang Engel, "Light Pre-Pass: More Blood"
//! (blog post, 28 September 2008), written up as "Designing a Renderer for Multiple Lights: The
//! Light Pre-Pass Renderer" (ShaderX7, 2009).
//!
//! P runs once per light and is summed by additive blending into a light buffer:
//! - one RGBA buffer (Engel): `rgb = N·L·att·colour`, `a = N·L·att·lum(colour)·(N·H)^n`;
//! - two buffers (Resistance 2): diffuse `N·L·att·colour`, specular `N·L·att·colour·(N·H)^n`.
//!
//! C runs with the material: `albedo·diffuse + gloss·specular`; the one-buffer layout first
//! recovers the specular as `(a / lum(rgb))^m · lum(rgb)` — `N·H^n` divided back out by the
//! luminance of the diffuse sum, the material exponent `m` on top of the light's `n`. For one
//! white light this equals Blinn-Phong with exponent `n·m` (up to rounding, bounded in
//! `tests/lpp.rs`); for several it is an approximation whose error the tests and
//! `errplot` measure.
//!
//! **Twins:** these use the same formulas in `f32`; they are not bit-identical to an adapter
//! (WGSL allows `inverseSqrt` 2 ULP, `/` 2.5 ULP, `log2`/`exp2` several, and fusing), so the
//! tests measure the difference.
//!
//! **Bad input (both sides):** any NaN/±Inf input, or a normal, `to_light` or `to_eye` whose
//! largest component is zero or subnormal, gives zero light. Colours clamp to `[0, 65504]`,
//! attenuation to `[0, 1]`, powers to `[0, 65504]`; `x^0 = 1` for `x > 0`, `0^y = 0`.

use glam::{Vec3, Vec4};

/// Rec. 709 luminance weights used to turn the light buffer's diffuse rgb into `N·L·att`.
pub const LPP_LUMINANCE: Vec3 = Vec3::new(0.2126, 0.7152, 0.0722);
/// Largest colour, attenuation-free power and exponent accepted (fp16 max).
pub const LPP_COLOUR_MAX: f32 = 65504.0;

fn lpp_finite(x: f32) -> bool {
    (x.to_bits() & 0x7fff_ffff) < 0x7f80_0000
}

fn lpp_finite3(v: Vec3) -> bool {
    lpp_finite(v.x) && lpp_finite(v.y) && lpp_finite(v.z)
}

/// `v/|v|`, or zero when `v` is non-finite or its largest component is zero or subnormal.
/// Scales by the largest component first so `|v|²` cannot overflow. Error ≈ 3 ULP per
/// component on a conforming adapter (division 2.5 ULP, `inverseSqrt` 2 ULP, products).
pub fn lpp_direction(v: Vec3) -> Vec3 {
    let m = v.abs().max_element();
    if !lpp_finite3(v) || m.to_bits() < 0x0080_0000 {
        return Vec3::ZERO;
    }
    let s = v * pow2_scale(m);
    s * (1.0 / s.dot(s).sqrt())
}

/// The power of two that scales a normal `m ≥ 0` into `[1, 4)` (WGSL `lpp_scale`): exact, where
/// `v / m` would divide by a number WGSL's `/` need not handle (beyond `2^126`).
pub(crate) fn pow2_scale(m: f32) -> f32 {
    f32::from_bits((254 - ((m.to_bits() >> 23) & 0xff)).max(1) << 23)
}

/// Luminance `0.2126 r + 0.7152 g + 0.0722 b` (a dot product: error within 3 ULP of the
/// exact sum for non-negative channels, products and sums each correctly rounded or fused).
///
/// **Bad input:** the result is finite (WGSL may assume no NaN or ±∞ at run time): each
/// channel is read from its bits first, NaN → 0, ±∞ → ±2^126, finite channels clamped to
/// `[−2^126, 2^126]`, so the weighted sum cannot overflow. Negative channels count (callers
/// clamp colours with [`lpp_clamp_colour`] first).
pub fn lpp_luminance(rgb: Vec3) -> f32 {
    const BIG: f32 = 8.507_059e37; // 2^126
    crate::position::read_finite3(rgb, BIG).dot(LPP_LUMINANCE)
}

/// `x^y` for a cosine `x` and exponent `y ≥ 0`, computed as `exp2(y·log2 x)`: 0 for `x ≤ 0`
/// or when `y·log2 x < −126`; 1 for `x ≥ 1` or `y = 0`. Error: WGSL's
/// `log2`/`exp2` allowances, `≤ (3 + 2|t|)·2^-23 + ln2·Δt` relative with `t = y·log2 x`.
///
/// **Bad input:** `x` or `y` NaN → 0 (no highlight); `y ≤ 0` acts as 0 (1 for `x > 0`);
/// `y = +∞` gives 0 for `x < 1`; `x = +∞` gives 1.
pub fn lpp_pow_cosine(x: f32, y: f32) -> f32 {
    if x.is_nan() || y.is_nan() || x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 || y <= 0.0 {
        return 1.0;
    }
    // As the WGSL: no log2 of a subnormal, no product with an infinity.
    if x < f32::MIN_POSITIVE || y == f32::INFINITY {
        return 0.0;
    }
    let t = y.min(1.267_650_6e30) * x.log2();
    if t < -126.0 { 0.0 } else { t.exp2() }
}

/// Windowed point-light falloff `(1 − (d/r)²)²`, 0 for `d ≥ r`. Bad input: NaN/Inf or `r`
/// below `2^-126` → 0; `d < 0` counts as 0.
pub fn lpp_point_attenuation(distance: f32, radius: f32) -> f32 {
    if !lpp_finite(distance) || !lpp_finite(radius) || radius.is_nan() || radius < f32::MIN_POSITIVE
    {
        return 0.0;
    }
    // As the WGSL: a divisor beyond 2^126 is scaled by 2^-64 first.
    let (d, r) = if radius > 8.507_059e37 {
        (distance * 5.421_011e-20, radius * 5.421_011e-20)
    } else {
        (distance, radius)
    };
    // As the WGSL: d/r only below r (no overflow), exactly 1 from r on.
    let x = if d >= r {
        1.0
    } else {
        (d.max(0.0).min(r) / r).clamp(0.0, 1.0)
    };
    let w = 1.0 - x * x;
    w * w
}

/// Spot cone factor: 0 below `cos_outer`, 1 above `cos_inner`, linear in the cosine between;
/// `cos_inner ≤ cos_outer` gives a hard edge. NaN/Inf → 0; cosines outside `[−1, 1]` are
/// clamped to it first, so no difference overflows (finite cosines of ±3e38 gave NaN: found by
/// the fuzz target `lighting`).
pub fn lpp_spot_attenuation(cos_angle: f32, cos_outer: f32, cos_inner: f32) -> f32 {
    if !lpp_finite(cos_angle) || !lpp_finite(cos_outer) || !lpp_finite(cos_inner) {
        return 0.0;
    }
    let c = cos_angle.clamp(-1.0, 1.0);
    let outer = cos_outer.clamp(-1.0, 1.0);
    let inner = cos_inner.clamp(-1.0, 1.0);
    // A width below 2^-126 (none included) is a hard edge: no division by a subnormal.
    if inner - outer < f32::MIN_POSITIVE {
        return if c >= outer { 1.0 } else { 0.0 };
    }
    ((c - outer) / (inner - outer)).clamp(0.0, 1.0)
}

/// `(N·L, specular cosine)`: `N·L` clamped below at 0 only (both directions are normalised in
/// f32, so it may exceed 1 by a few ULP, at most [`bounds::n_dot_l_max`]), and `N·H`
/// (Blinn-Phong) or `R·V` (Phong) clamped to `[0, 1]`; zeros for a bad `to_eye`, specular 0
/// when `N·L = 0`.
pub fn lpp_cosines(normal: Vec3, to_eye: Vec3, to_light: Vec3, phong: bool) -> (f32, f32) {
    let n = lpp_direction(normal);
    let l = lpp_direction(to_light);
    let v = lpp_direction(to_eye);
    let n_dot_l = n.dot(l).max(0.0);
    if v == Vec3::ZERO {
        return (0.0, 0.0);
    }
    if n_dot_l.is_nan() || n_dot_l <= 0.0 {
        return (n_dot_l, 0.0);
    }
    let spec = if phong {
        let r = 2.0 * n.dot(l) * n - l;
        r.dot(v)
    } else {
        n.dot(lpp_direction(l + v))
    };
    (n_dot_l, spec.clamp(0.0, 1.0))
}

/// The one-buffer texel of [`lpp_terms`]: `(d·c, d·lum(c)·s)`, or zero.
fn lpp_light(terms: Option<(Vec3, f32, f32)>) -> Vec4 {
    match terms {
        Some((c, d, s)) => (d * c).extend(d * lpp_luminance(c) * s),
        None => Vec4::ZERO,
    }
}

/// What every P shares, operation for operation as the WGSL: `None` (P = 0) unless colour,
/// attenuation and power are finite; else the clamped colour, `N·L·att` and the cosine term
/// `cos^power` (Blinn-Phong's `N·H`, or Phong's `R·V`).
fn lpp_terms(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour: Vec3,
    attenuation: f32,
    power: f32,
    phong: bool,
) -> Option<(Vec3, f32, f32)> {
    if !lpp_finite3(colour) || !lpp_finite(attenuation) || !lpp_finite(power) {
        return None;
    }
    let c = colour.clamp(Vec3::ZERO, Vec3::splat(LPP_COLOUR_MAX));
    let (n_dot_l, s) = lpp_cosines(normal, to_eye, to_light, phong);
    let d = n_dot_l * attenuation.clamp(0.0, 1.0);
    Some((c, d, lpp_pow_cosine(s, power.clamp(0.0, LPP_COLOUR_MAX))))
}

/// P for the one-buffer layout with Blinn-Phong specular:
/// `(N·L·att·colour, N·L·att·lum(colour)·(N·H)^power)`.
pub fn lpp_blinn_phong_light(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour: Vec3,
    attenuation: f32,
    power: f32,
) -> Vec4 {
    lpp_light(lpp_terms(
        normal,
        to_eye,
        to_light,
        colour,
        attenuation,
        power,
        false,
    ))
}

/// P for the one-buffer layout with Phong specular: `(…, N·L·att·lum(colour)·(R·V)^power)`.
pub fn lpp_phong_light(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour: Vec3,
    attenuation: f32,
    power: f32,
) -> Vec4 {
    lpp_light(lpp_terms(
        normal,
        to_eye,
        to_light,
        colour,
        attenuation,
        power,
        true,
    ))
}

/// [`lpp_point_attenuation`]`(|to_light|, radius)` with both lengths first scaled by one power of
/// two (exact; WGSL `lpp_point_falloff`) that takes `max(max|to_light_i|, radius)` into `[1, 4)`:
/// `|to_light|²` neither overflows nor underflows, and `d/r` is unchanged. Non-finite input or a
/// radius below `2^-126` gives 0.
fn lpp_point_falloff(to_light: Vec3, radius: f32) -> f32 {
    if !lpp_finite3(to_light)
        || !lpp_finite(radius)
        || radius.is_nan()
        || radius < f32::MIN_POSITIVE
    {
        return 0.0;
    }
    let a = to_light.abs();
    let s = pow2_scale(a.x.max(a.y).max(a.z.max(radius)));
    lpp_point_attenuation((to_light * s).length(), radius * s)
}

/// P of a point light (`colour_radius` = colour, radius) with Blinn-Phong specular.
pub fn lpp_point_light(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour_radius: Vec4,
    power: f32,
) -> Vec4 {
    let att = lpp_point_falloff(to_light, colour_radius.w);
    lpp_blinn_phong_light(
        normal,
        to_eye,
        to_light,
        colour_radius.truncate(),
        att,
        power,
    )
}

/// P of a spot light: point falloff times [`lpp_spot_attenuation`] of the angle between the spot
/// axis (`axis_cos_outer.xyz`, any length) and the light-to-surface direction.
pub fn lpp_spot_light(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour_radius: Vec4,
    axis_cos_outer: Vec4,
    cos_inner: f32,
    power: f32,
) -> Vec4 {
    let cos_angle = lpp_direction(axis_cos_outer.truncate()).dot(-lpp_direction(to_light));
    let att = lpp_point_falloff(to_light, colour_radius.w)
        * lpp_spot_attenuation(cos_angle, axis_cos_outer.w, cos_inner);
    lpp_blinn_phong_light(
        normal,
        to_eye,
        to_light,
        colour_radius.truncate(),
        att,
        power,
    )
}

/// P for the two-buffer layout's specular target: `N·L·att·colour·(N·H)^power`.
pub fn lpp_blinn_phong_specular_rgb(
    normal: Vec3,
    to_eye: Vec3,
    to_light: Vec3,
    colour: Vec3,
    attenuation: f32,
    power: f32,
) -> Vec3 {
    match lpp_terms(normal, to_eye, to_light, colour, attenuation, power, false) {
        Some((c, d, s)) => d * s * c,
        None => Vec3::ZERO,
    }
}

/// Engel's reconstruction from an accumulated one-buffer texel: `(a / lum(rgb))^m · lum(rgb)`.
///
/// The ratio is `N·H^n` for one light; for several lights it is a luminance-weighted mix that
/// can exceed 1 (the blog comments' worry): it is clamped to `[0, 1]` before the exponent, so the
/// result never exceeds `lum(rgb)` and never overflows. Guards: a non-finite channel,
/// `lum(rgb) < 2^-126` or `a ≤ 0` → 0; the division runs only when `a < lum`. `material_power`
/// clamps to `[0, 65504]`; NaN/Inf → 0.
///
/// **Error bound** (one white light, against Blinn-Phong with exponent `n·m` on the same
/// adapter): `m·(ε_pow(n) + 13u) + ε_pow(m) + ε_pow(nm) + 8u` relative, derived in
/// `tests/lpp.rs`.
pub fn lpp_reconstruct_specular(light: Vec4, material_power: f32) -> f32 {
    if !lpp_finite3(light.truncate()) || !lpp_finite(light.w) || !lpp_finite(material_power) {
        return 0.0;
    }
    let rgb = light.truncate().max(Vec3::ZERO);
    let lum = lpp_luminance(rgb);
    if lum.to_bits() < 0x0080_0000 || light.w.is_nan() || light.w <= 0.0 {
        return 0.0;
    }
    let ratio = if light.w < lum { light.w / lum } else { 1.0 };
    lpp_pow_cosine(ratio, material_power.clamp(0.0, LPP_COLOUR_MAX)) * lum
}

/// Clamp to `[0, 65504]`, NaN to 0.
pub fn lpp_clamp_colour(c: Vec3) -> Vec3 {
    let f = |x: f32| {
        if x.is_nan() {
            0.0
        } else {
            x.clamp(0.0, LPP_COLOUR_MAX)
        }
    };
    Vec3::new(f(c.x), f(c.y), f(c.z))
}

/// C for the one-buffer layout: `albedo·rgb + gloss·lpp_reconstruct_specular(light, m)`.
///
/// The result is not clamped: with texels an f16 light buffer can hold (≤ 65504) and albedo and
/// gloss in `[0, 1]` it stays within about `2·65504` (texels of 65504 give 131008). Channels
/// beyond that range are not clamped before the specular reconstruction (`lum(rgb)` of the raw
/// texel), so larger texels give larger results, and with gloss above 1 they can overflow to `+∞`.
pub fn lpp_combine(albedo: Vec3, gloss: Vec3, light: Vec4, material_power: f32) -> Vec3 {
    let spec = lpp_reconstruct_specular(light, material_power);
    lpp_clamp_colour(albedo) * lpp_clamp_colour(light.truncate()) + lpp_clamp_colour(gloss) * spec
}

/// C for the two-buffer layout: `albedo·diffuse + gloss·specular` (Resistance 2's `C = mp·P`).
pub fn lpp_combine_two_buffers(albedo: Vec3, gloss: Vec3, diffuse: Vec3, specular: Vec3) -> Vec3 {
    lpp_clamp_colour(albedo) * lpp_clamp_colour(diffuse)
        + lpp_clamp_colour(gloss) * lpp_clamp_colour(specular)
}

/// Error bounds of the light pre-pass maths, kept once: `tests/lpp.rs` asserts them on the
/// adapter and, multiplied by [`bounds::CONFORMING_FACTOR`] and with
/// [`bounds::independent_cosines_relative`] added, under the worst-case emulation.
pub mod bounds {
    const U: f64 = 1.0 / 16_777_216.0;

    /// Every term of the budgets below is either a rounding of `+ − ×` (`u` where correctly
    /// rounded, at most `2u` on any conforming adapter, which may round to either neighbour) or
    /// already a full WGSL allowance (`/`, `log2`, `exp2`): doubling a budget bounds the
    /// conforming error.
    pub const CONFORMING_FACTOR: f64 = 2.0;

    /// The largest `N·L` that [`super::lpp_cosines`] returns: it clamps `N·L` at 0 only, and two
    /// directions each of unit length within [`crate::normal::UNIT_TOLERANCE`] have a dot
    /// product of at most `(1 + tol)²`, plus the dot's three roundings (`3u`). A light-buffer
    /// channel may exceed its clamped colour by this factor (the fuzz target `lighting` found
    /// 65504.008 for a colour of 65504).
    pub fn n_dot_l_max() -> f64 {
        let tol = crate::normal::UNIT_TOLERANCE;
        (1.0 + tol) * (1.0 + tol) * (1.0 + 3.0 * U)
    }

    /// Relative error of WGSL's `pow(x, y) = exp2(y·log2 x)` as `lpp_pow_cosine` computes it
    /// (`x` in (0, 1), `y ≥ 0`), first order, from the spec's allowances: `log2` within 2^-21
    /// absolute on [0.5, 2] and 3 ULP (≤ `6u` relative) elsewhere; the product rounds (`u`); an
    /// absolute error `Δt` in `t = y·log2 x` becomes `ln 2·Δt` relative after `exp2`, which itself
    /// adds `(3 + 2|t|)` ULP (≤ `(3 + 2|t|)·2u` relative).
    pub fn pow_relative(x: f64, y: f64) -> f64 {
        let l = x.log2();
        let dlog = if (0.5..=2.0).contains(&x) {
            2f64.powi(-21)
        } else {
            6.0 * U * l.abs()
        };
        let t = (y * l).abs();
        std::f64::consts::LN_2 * (y * dlog + t * U) + (3.0 + 2.0 * t) * 2.0 * U
    }

    /// Relative error of Engel's reconstruction for one white light against the direct
    /// Blinn-Phong value, where `+ − ×` round correctly (`u = 2^-24`; `N·H` and `N·L·att` are the
    /// same f32 in both paths): P is `a = d·lum(1,1,1)·(N·H)^n`, the light's `pow` within
    /// `pow_relative(h, n)`, two products `u` each; C: `lum(rgb)` of `(d, d, d)` within `4u` of
    /// `d·Σw` (three products, two sums), `lum(c)` in P within `2u` of `Σw`, the division 2.5 ULP
    /// (`5u`): the ratio is `(N·H)^n·(1 + δ)`, `|δ| ≤ 13u + pow_relative(h, n)`. The material
    /// exponent `m` multiplies `δ` by `m` and adds its own `pow_relative((N·H)^n, m)`; the final
    /// product and `lum` add `5u`. The direct value carries `pow_relative(h, n·m)` and `3u`.
    pub fn single_light_relative(n_dot_h: f64, light_power: f64, material_power: f64) -> f64 {
        let r = n_dot_h.powf(light_power);
        material_power * (pow_relative(n_dot_h, light_power) + 13.0 * U)
            + pow_relative(r, material_power)
            + pow_relative(n_dot_h, light_power * material_power)
            + 8.0 * U
    }

    /// Relative difference between two evaluations of the same light's cosines on a conforming
    /// adapter — the direct Blinn-Phong value's and the light pass's — which
    /// [`single_light_relative`] takes to be the same f32 (they are, where `+ − ×` round
    /// correctly: the same operations on the same inputs). The spec makes no two evaluations
    /// bit-identical, and the worst-case search found a pixel at 1.33 of the doubled budget
    /// without this term. First order, `u = 2^-24`, every `+ − ×` within `2u` relative, the
    /// directions from `lpp_direction` (`s·inverseSqrt(s·s)`, a power-of-two scaling first):
    /// `s·s` within `6u` (a product and two sums of positive terms), `inverseSqrt` half of that
    /// plus its 2 ULP (`4u`), the product `2u`: each unit direction within `9u`. `h` is the
    /// direction of `l + v`: the sum's error is at most `9u·2 + 2u·|l + v|`, which turns the
    /// direction by at most that over `|l + v|`, plus `9u` of its own. A dot of two unit
    /// vectors adds `6u` absolute (three products, two sums, each bounded by `Σ|aᵢbᵢ| ≤ 1`).
    /// So `N·H` is within `ε_h = (18u/|l + v| + 26u)/N·H` relative and `N·L·att` within
    /// `ε_d = 24u/N·L + 2u`; the direct value carries `(N·H)^{n·m}` and `N·L·att` of one
    /// evaluation, the reconstruction those of another: `2·n·m·ε_h + 2·ε_d`.
    pub fn independent_cosines_relative(
        n_dot_h: f64,
        n_dot_l: f64,
        l_plus_v: f64,
        light_power: f64,
        material_power: f64,
    ) -> f64 {
        let eps_h = (18.0 * U / l_plus_v + 26.0 * U) / n_dot_h;
        let eps_d = 24.0 * U / n_dot_l + 2.0 * U;
        2.0 * light_power * material_power * eps_h + 2.0 * eps_d
    }
}

/// Exact references in f64.
pub mod exact {
    /// Unit vector in f64 (zero for a zero vector; NaN propagates to every component).
    pub fn unit(v: [f64; 3]) -> [f64; 3] {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if l == 0.0 { [0.0; 3] } else { v.map(|x| x / l) }
    }

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// `(N·L, N·H)` in f64, both clamped at 0 (N·H 0 when N·L = 0).
    pub fn lpp_cosines(normal: [f64; 3], to_eye: [f64; 3], to_light: [f64; 3]) -> (f64, f64) {
        let (n, l, v) = (unit(normal), unit(to_light), unit(to_eye));
        let nl = dot(n, l).max(0.0);
        if nl <= 0.0 {
            return (0.0, 0.0);
        }
        let h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
        (nl, dot(n, h).clamp(0.0, 1.0))
    }

    /// One light for [`multi_light_specular`]: `(to_light, lum(colour), attenuation, n)`.
    pub type Light = ([f64; 3], f64, f64, f64);

    /// Blinn-Phong specular of several lights, evaluated per light as a forward renderer would:
    /// `Σ_i N·L_i·att_i·lum(c_i)·(N·H_i)^(n_i·m)`.
    pub fn multi_light_specular(
        normal: [f64; 3],
        to_eye: [f64; 3],
        lights: &[Light],
        material_power: f64,
    ) -> f64 {
        lights
            .iter()
            .map(|&(to_light, lum, att, n)| {
                let (nl, nh) = lpp_cosines(normal, to_eye, to_light);
                nl * att * lum * nh.powf(n * material_power)
            })
            .sum()
    }
}
