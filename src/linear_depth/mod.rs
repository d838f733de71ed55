//! View distance from stored depth — the Rust twins of `wgsl/linear_depth.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! **Sign:** every `view_z_*` function returns the positive view distance `vz`. Right-handed
//! view space (wgpu, Bevy) has `z = −vz`: Bevy's `depth_ndc_to_view_z(d)` is
//! `-view_z_from_depth_uniform(d, k)`.
//!
//! **Which to call:** upload [`Projection::depth_uniform`](crate::projection::Projection::depth_uniform)
//! and call [`view_z_from_depth_uniform`] (float depth) or [`view_z_from_depth24_uniform`]
//! (24-bit codes): the convention travels with the constants. The `_consts` forms take one
//! convention's constants (fewer instructions: no run-time branch on the convention); the
//! near/far forms compute the constants per pixel.
//!
//! The textbook inverse `vz = 1/(z·a + b)` (`a = (f−n)/(−f·n)`, `b = 1/n`, as the
//! light-pre-pass talks recover linear depth) cancels near the far plane and loses precision like
//! `(f/n)·2^-24` — about 8 % at `f/n = 10^6`. Rearranged so that every term is non-negative:
//!
//! - standard float: `vz = n / ((1 − z) + z·(n/f))` for `z ≥ 0.5` (`1 − z` exact there) and
//!   `n / (1 − z·(1 − n/f))` below (`z·(1 − n/f) < 0.5`: no cancellation; monotonic in `z`),
//! - reversed float: `vz = n / (z·(1 − n/f) + n/f)`,
//! - 24-bit code `d`: `vz = n·(2^24−1) / ((2^24−1−d) + d·(n/f))` (integer complement, exact),
//!
//! with `n/f = 0` for an infinite far plane. Nothing cancels, so the error is a handful of
//! roundings whatever `f/n` is.
//!
//! **Error bound (derived):** with `u = 2^-24` and `w = d·(n/f)/s ∈ [0, 1)` the weight of the
//! product term in the denominator `s`, the relative error is at most
//! `u·(1 + 1 + 2w) + ε_div` for the float paths (below `z = 0.5` read `w` as the share of
//! `z·(1 − n/f)`, at most 1/2 of `s`) and one more `u` for the code path (the rounded `n·(2^24−1)`), where `ε_div`
//! is the division's error: `u` where `/` is correctly rounded (lavapipe, and the Rust twin),
//! up to 2.5 ULP where an adapter uses WGSL's full allowance. A relative error `k·u` is at most
//! `k` ULP. The measured maxima over all codes and the stiff grid are in the README
//! (`tests/linear_depth.rs` asserts the bounds of [`bounds`]).
//!
//! **Twins:** the same operations in the same order in f32. They are bit-identical where the
//! adapter neither fuses `a·b + c` into an fma nor divides less accurately than correctly
//! rounded; WGSL permits both, so the tests require agreement within 1 ULP and report how many
//! results differ.
//!
//! **Bad input (every result finite):** depth is clamped to `[0, 1]` and codes to `2^24 − 1`.
//! WGSL lets an implementation assume that no float operation sees or produces NaN or ±∞, so
//! none of these functions returns one. They return [`SKY`], the largest finite `f32`, for:
//! - a distance of `2^127` or more: the far plane of an infinite projection, the sky, and the
//!   depths next to it. It is decided on the computed denominator, so an exact distance within
//!   the error bound below `2^127` may read as the sky too (only projections whose `far` is near
//!   `2^127` have such distances);
//! - a subnormal denominator (a subnormal reversed depth of an infinite projection);
//! - NaN depth;
//! - planes or constants no [`Projection`](crate::projection::Projection) has: NaN or ±∞, `near`
//!   outside `[2^-126, 2^104]`, `far ≤ near`, ratios outside `[0, 1]`.
//!
//! Special inputs are recognised from their bits, as the WGSL does. A lighting pass tests
//! `vz >= SKY` for the sky (`vz >= VIEW_Z_SKY` in WGSL, the shipped constant
//! `3.4028234e38`, which rounds to it: Tint rejects the usual `3.4028235e38`, which lies above
//! `f32::MAX`).
//!
//! **Dependencies:** this module and the constants it reads (`src/linear_depth/constants.rs`:
//! [`DepthConvention`], [`DepthUniform`], [`DepthConsts`], [`ReversedDepthConsts`],
//! [`Depth24Consts`]) use nothing of [`crate::projection`], which depends on them: it builds the
//! constants from near/far, re-exports them at `prepass::projection::*`, and reads depth through
//! [`view_z_from_depth_uniform`]. `tests::no_use_of_projection` keeps it one way.

mod constants;

pub use constants::{
    Depth24Consts, DepthConsts, DepthConvention, DepthUniform, ReversedDepthConsts,
};

use crate::depth24::DEPTH24_MAX;

/// The view distance every function here returns for the sky (and for NaN depth and invalid
/// planes): `f32::MAX`, the largest finite `f32` (WGSL `const VIEW_Z_SKY`, written
/// `3.4028234e38`, which rounds to it).
/// Finite, because WGSL leaves a run-time ±∞ indeterminate and rejects a constant one.
pub const SKY: f32 = f32::MAX;

/// `2^127`: quotients at or above it return [`SKY`] (so no division can overflow).
const SKY_THRESHOLD: f32 = 1.701_411_8e38;

/// `n/f` with an infinite far plane giving exactly 0 (as WGSL `ld_near_over_far`).
fn near_over_far(near: f32, far: f32) -> f32 {
    if far.is_infinite() {
        0.0
    } else if far > 8.507_059e37 {
        // As the WGSL: a divisor beyond 2^126 is scaled, with the dividend, by 2^-64 first.
        (near * 5.421_011e-20) / (far * 5.421_011e-20)
    } else {
        near / far
    }
}

/// `numerator / s`, or [`SKY`] where the quotient would be `2^127` or more or `s` is subnormal
/// (which an adapter may flush to 0 in the division but not in a comparison), as WGSL
/// `ld_divide_or_sky`; the test `s·2^127 ≤ numerator` is exact for `s < 2`.
fn divide_or_sky(numerator: f32, s: f32) -> f32 {
    if s < f32::MIN_POSITIVE || (s < 2.0 && s * SKY_THRESHOLD <= numerator) {
        SKY
    } else {
        numerator / s
    }
}

/// Planes a projection can have (as WGSL `ld_planes_ok`, from bits, and as
/// [`Projection::new`](crate::projection::Projection::new) checks): `near` normal in
/// `[2^-126, 2^104]` (so `near·(2^24 − 1)` stays finite), `far > near` finite or `+∞`.
fn planes_ok(near: f32, far: f32) -> bool {
    near.to_bits().wrapping_sub(0x0080_0000) <= 0x7300_0000
        && (far == f32::INFINITY || (far.is_finite() && far > near))
}

/// Constants a projection can give (as WGSL `ld_consts_ok`, from bits): `k0` positive and
/// finite, the ratios in `[+0, 1]`.
fn consts_ok(k0: f32, k1: f32, k2: f32) -> bool {
    k0.to_bits().wrapping_sub(1) <= 0x7f7f_fffe
        && k1.to_bits() <= 0x3f80_0000
        && k2.to_bits() <= 0x3f80_0000
}

/// `z` (not NaN) clamped to `[0, 1]` as WGSL `ld_clamp_unit` does it from the bits: anything
/// with the sign bit (−0 and −∞ included) to `+0`, 1 and above (`+∞` included) to 1.
fn clamp_unit(z: f32) -> f32 {
    if z.is_sign_negative() {
        0.0
    } else if z >= 1.0 {
        1.0
    } else {
        z
    }
}

/// The 24-bit path on checked constants (WGSL `ld_view_z_depth24`).
fn depth24_checked(d: u32, k: Depth24Consts) -> f32 {
    let code = d.min(DEPTH24_MAX);
    let s = (DEPTH24_MAX - code) as f32 + code as f32 * k.near_over_far;
    divide_or_sky(k.near_times_max, s)
}

/// The standard float path on checked constants (WGSL `ld_view_z_standard`).
fn standard_checked(z: f32, k: DepthConsts) -> f32 {
    if z.is_nan() {
        return SKY;
    }
    let zc = clamp_unit(z);
    let s = if zc < 0.5 {
        1.0 - zc * k.one_minus_near_over_far
    } else {
        // Exact in f32 (Sterbenz): the same value the WGSL builds from z's bits
        // (`ld_one_minus`), which keeps it exact under any reassociation on the GPU.
        (1.0 - zc) + zc * k.near_over_far
    };
    divide_or_sky(k.near, s)
}

/// The reversed float path on checked constants (WGSL `ld_view_z_reversed`).
fn reversed_checked(z: f32, k: ReversedDepthConsts) -> f32 {
    if z.is_nan() {
        return SKY;
    }
    let zc = clamp_unit(z);
    let s = zc * k.one_minus_near_over_far + k.near_over_far;
    divide_or_sky(k.near, s)
}

/// View distance of a 24-bit standard-convention depth code (twin of WGSL
/// `view_z_from_depth24`). See the module docs for the formula, error bound and bad input.
pub fn view_z_from_depth24(d: u32, near: f32, far: f32) -> f32 {
    if !planes_ok(near, far) {
        return SKY;
    }
    let k = Depth24Consts {
        near_times_max: near * DEPTH24_MAX as f32,
        near_over_far: near_over_far(near, far),
    };
    depth24_checked(d, k)
}

/// [`view_z_from_depth24`] with `k = (n·(2^24 − 1), n/f)` from
/// [`crate::projection::Projection::depth24_consts`] (twin of `view_z_from_depth24_consts`).
pub fn view_z_from_depth24_consts(d: u32, k: Depth24Consts) -> f32 {
    if !consts_ok(k.near_times_max, k.near_over_far, 0.0) {
        return SKY;
    }
    depth24_checked(d, k)
}

/// View distance of a float standard-convention depth (twin of WGSL `view_z_from_depth`).
pub fn view_z_from_depth(z: f32, near: f32, far: f32) -> f32 {
    if !planes_ok(near, far) {
        return SKY;
    }
    let r = near_over_far(near, far);
    let k = DepthConsts {
        near,
        near_over_far: r,
        one_minus_near_over_far: 1.0 - r,
    };
    standard_checked(z, k)
}

/// [`view_z_from_depth`] with `k = (n, n/f, (f − n)/f)` from
/// [`crate::projection::Projection::depth_consts`]. Below `z = 0.5` the denominator is
/// `1 − z·(1 − n/f)` (where `1 − z` would round and let the result step backwards), so the
/// result is monotonic in `z`.
pub fn view_z_from_depth_consts(z: f32, k: DepthConsts) -> f32 {
    if !consts_ok(k.near, k.near_over_far, k.one_minus_near_over_far) {
        return SKY;
    }
    standard_checked(z, k)
}

/// View distance of a float reversed-convention depth (twin of WGSL
/// `view_z_from_reversed_depth`). Depth 0 of an infinite projection (the sky) gives [`SKY`].
pub fn view_z_from_reversed_depth(z: f32, near: f32, far: f32) -> f32 {
    if !planes_ok(near, far) {
        return SKY;
    }
    let r = near_over_far(near, far);
    let k = ReversedDepthConsts {
        near,
        one_minus_near_over_far: 1.0 - r,
        near_over_far: r,
    };
    reversed_checked(z, k)
}

/// [`view_z_from_reversed_depth`] with `k = (n, (f − n)/f, n/f)` from
/// [`crate::projection::Projection::reversed_depth_consts`].
pub fn view_z_from_reversed_depth_consts(z: f32, k: ReversedDepthConsts) -> f32 {
    if !consts_ok(k.near, k.one_minus_near_over_far, k.near_over_far) {
        return SKY;
    }
    reversed_checked(z, k)
}

/// `|k.w|` of a depth uniform, from its bits (WGSL `ld_uniform_near_times_max`).
fn uniform_near_times_max(k: DepthUniform) -> f32 {
    f32::from_bits(k.signed_near_times_max.to_bits() & 0x7fff_ffff)
}

/// Whether `k` is a uniform some projection gives (WGSL `ld_uniform_ok`).
fn uniform_ok(k: DepthUniform) -> bool {
    consts_ok(k.near, k.near_over_far, k.one_minus_near_over_far)
        && consts_ok(uniform_near_times_max(k), 0.0, 0.0)
}

/// View distance of a float depth in the projection's own convention, from its
/// [`DepthUniform`] (twin of WGSL `view_z_from_depth_uniform`): for a standard uniform
/// [`view_z_from_depth_consts`], for a reversed one [`view_z_from_reversed_depth_consts`], on
/// the same constants, so the same bits and the same error bounds
/// ([`bounds::of`] those functions).
///
/// Those promises are for the vectors
/// [`Projection::depth_uniform`](crate::projection::Projection::depth_uniform) gives. Any other
/// vector returns a finite value `≥ 0`, not necessarily [`SKY`]: [`SKY`] where an entry fails
/// the checks every projection passes (`k.x` or `|k.w|` not positive and finite, `k.y` or `k.z`
/// outside `[+0, 1]`), otherwise the formula's value on the entries as given, with no bound:
/// `(0.1, 0.5, 0.9, 1.0)`, whose ratios do not sum to 1, reads 0.1 at depth 0 and 0.2 at
/// depth 1, and a subnormal `k.x` can give 0.
///
/// ```
/// use prepass::linear_depth::{SKY, view_z_from_depth_uniform};
/// use prepass::projection::DepthUniform;
/// let k = DepthUniform::from_wgsl([0.1, 0.5, 0.9, 1.0]); // no projection gives it
/// assert_eq!((view_z_from_depth_uniform(0.0, k), view_z_from_depth_uniform(1.0, k)), (0.1, 0.2));
/// assert_ne!(view_z_from_depth_uniform(0.5, k), SKY);
/// ```
pub fn view_z_from_depth_uniform(z: f32, k: DepthUniform) -> f32 {
    if !uniform_ok(k) {
        return SKY;
    }
    match k.convention() {
        DepthConvention::Standard => standard_checked(
            z,
            DepthConsts {
                near: k.near,
                near_over_far: k.near_over_far,
                one_minus_near_over_far: k.one_minus_near_over_far,
            },
        ),
        DepthConvention::Reversed => reversed_checked(
            z,
            ReversedDepthConsts {
                near: k.near,
                one_minus_near_over_far: k.one_minus_near_over_far,
                near_over_far: k.near_over_far,
            },
        ),
    }
}

/// View distance of a 24-bit depth code in the projection's own convention, from its
/// [`DepthUniform`] (twin of WGSL `view_z_from_depth24_uniform`). Reversed depth is exactly
/// `1 −` standard depth, so a reversed code `d` reads as the standard code `2^24 − 1 − d`: the
/// result is [`view_z_from_depth24_consts`] of that code, bit for bit, with its error bound.
pub fn view_z_from_depth24_uniform(d: u32, k: DepthUniform) -> f32 {
    if !uniform_ok(k) {
        return SKY;
    }
    let code = d.min(DEPTH24_MAX);
    let standard = match k.convention() {
        DepthConvention::Standard => code,
        DepthConvention::Reversed => DEPTH24_MAX - code,
    };
    depth24_checked(
        standard,
        Depth24Consts {
            near_times_max: uniform_near_times_max(k),
            near_over_far: k.near_over_far,
        },
    )
}

/// Error bounds of every function here, in f32 ULPs of the exact distance, kept once: the tests,
/// the fuzz targets and the docs read them from here.
///
/// With `u = 2^-24`, a result `y` has `ULP(y) ≥ u·|y|`, so a relative error `k·u` is at most
/// `k` ULP. Per operation (WGSL "Floating Point Accuracy"):
///
/// | adapter | `+ − ×` | `/` | rounded-once constant (`Projection::*_consts`, f64 → f32) |
/// |---|---|---|---|
/// | correctly rounded (lavapipe, the Rust twins) | `u` | `u` | `u` |
/// | any conforming one | `2u` (either neighbour) | `5u` (2.5 ULP ≤ 2.5·2u) | `u` |
///
/// and every conforming adapter may also fuse `a·b + c` (one rounding fewer: never worse) and
/// reassociate. Each denominator is a sum of two non-negative terms, `s = a + p` with
/// `p = x·k` (the 24-bit complement `a = D − d` is an exact integer; `a = 1 − z` is exact for
/// `z ≥ 0.5` and built from the bits of `z`, so no reassociation can turn it into
/// `(1 + p) − z`); with `w = p/s ∈ [0, 1]`:
/// `ε_s ≤ ε_+ + w·(ε_× + ε_k)`, and the result `n'/s` errs `ε_n + ε_s + ε_/`, first order
/// (second-order terms are below 10^-5 ULP; the constants add 0.01 ULP for them).
///
/// | function | `ε_n` | `ε_k` | correctly rounded | conforming |
/// |---|---|---|---|---|
/// | `view_z_from_depth24_consts` | u | u | 1 + 1 + 2 + 1 = 5 | 1 + 2 + (2 + 1) + 5 = 11 |
/// | `view_z_from_depth24` | u (`n·D`) | u (`n/f`) | 5 | 2 + 2 + (2 + 5) + 5 = 16 |
/// | `view_z_from_depth_consts` | 0 | u | 0 + 1 + 2 + 1 = 4 | 0 + 2 + (2 + 1) + 5 = 10 |
/// | `view_z_from_depth` | 0 | u (`n/f`, `1 − n/f`) | 4 | 0 + 2 + (2 + 5) + 5 = 14 |
/// | `view_z_from_reversed_depth_consts` | 0 | u | 4 | 0 + 2 + (2 + 1) + 5 = 10 |
/// | `view_z_from_reversed_depth` | 0 | u | 4 | 0 + 2 + (2 + 5) + 5 = 14 |
///
/// (Below `z = 0.5` the standard path's denominator is `1 − z·(1 − n/f)` with the product
/// under half of it: the same sum with `w ≤ 1`.) The correctly rounded figures are the
/// lavapipe promise; the conforming ones hold on every conforming adapter, and
/// `tests/linear_depth.rs` checks both, the second under emulation
/// (`prepass::conforming`, feature `validate`).
pub mod bounds {
    /// Second-order terms of the first-order sums below.
    const SECOND_ORDER: f64 = 0.01;

    /// `view_z_from_depth24_consts` where `+ − × /` are correctly rounded.
    pub const DEPTH24_CONSTS_CORRECTLY_ROUNDED: f64 = 5.0 + SECOND_ORDER;
    /// `view_z_from_depth24_consts` on every conforming adapter.
    pub const DEPTH24_CONSTS_CONFORMING: f64 = 11.0 + SECOND_ORDER;
    /// `view_z_from_depth24` where `+ − × /` are correctly rounded.
    pub const DEPTH24_CORRECTLY_ROUNDED: f64 = 5.0 + SECOND_ORDER;
    /// `view_z_from_depth24` on every conforming adapter.
    pub const DEPTH24_CONFORMING: f64 = 16.0 + SECOND_ORDER;
    /// `view_z_from_depth_consts` and `view_z_from_reversed_depth_consts` where `+ − × /` are
    /// correctly rounded.
    pub const FLOAT_CONSTS_CORRECTLY_ROUNDED: f64 = 4.0 + SECOND_ORDER;
    /// `view_z_from_depth_consts` and `view_z_from_reversed_depth_consts` on every conforming
    /// adapter.
    pub const FLOAT_CONSTS_CONFORMING: f64 = 10.0 + SECOND_ORDER;
    /// `view_z_from_depth` and `view_z_from_reversed_depth` where `+ − × /` are correctly
    /// rounded.
    pub const FLOAT_CORRECTLY_ROUNDED: f64 = 4.0 + SECOND_ORDER;
    /// `view_z_from_depth` and `view_z_from_reversed_depth` on every conforming adapter.
    pub const FLOAT_CONFORMING: f64 = 14.0 + SECOND_ORDER;

    /// The bound of a function by name: (correctly rounded, conforming), with the row of the
    /// derivation table it comes from. `None` for names not in this module.
    pub fn of(function: &str) -> Option<(f64, f64, &'static str)> {
        Some(match function {
            "view_z_from_depth24_consts" | "view_z_from_depth24_uniform" => (
                DEPTH24_CONSTS_CORRECTLY_ROUNDED,
                DEPTH24_CONSTS_CONFORMING,
                "ε_n u + ε_+ + (ε_× + ε_k u) + ε_/ (linear_depth::bounds)",
            ),
            "view_z_from_depth24" => (
                DEPTH24_CORRECTLY_ROUNDED,
                DEPTH24_CONFORMING,
                "ε_n (n·D) + ε_+ + (ε_× + ε_k = n/f) + ε_/ (linear_depth::bounds)",
            ),
            "view_z_from_depth_consts"
            | "view_z_from_reversed_depth_consts"
            | "view_z_from_depth_uniform" => (
                FLOAT_CONSTS_CORRECTLY_ROUNDED,
                FLOAT_CONSTS_CONFORMING,
                "ε_+ + (ε_× + ε_k u) + ε_/, exact 1 − z (linear_depth::bounds)",
            ),
            "view_z_from_depth" | "view_z_from_reversed_depth" => (
                FLOAT_CORRECTLY_ROUNDED,
                FLOAT_CONFORMING,
                "ε_+ + (ε_× + ε_k = n/f) + ε_/, exact 1 − z (linear_depth::bounds)",
            ),
            _ => return None,
        })
    }
}

/// Exact references in f64 from the f32 parameters as given (relative error ~2^-52, i.e.
/// ~2^-28 of an f32 ULP: every term is non-negative, so f64 loses nothing to cancellation).
pub mod exact {
    use crate::depth24::DEPTH24_MAX;

    /// `vz = n·f·D / (f·(D − d) + n·d)`, `D = 2^24 − 1`; `n·D/(D − d)` for infinite far.
    pub fn view_z_from_depth24(d: u32, near: f32, far: f32) -> f64 {
        let (n, dd, big) = (
            f64::from(near),
            f64::from(d.min(DEPTH24_MAX)),
            f64::from(DEPTH24_MAX),
        );
        if far.is_infinite() {
            return n * big / (big - dd);
        }
        let f = f64::from(far);
        n * f * big / (f * (big - dd) + n * dd)
    }

    /// `vz = n·f / (f·(1 − z) + n·z)` for standard float depth `z` (clamped to `[0, 1]`).
    pub fn view_z_from_depth(z: f32, near: f32, far: f32) -> f64 {
        let (z, n) = (f64::from(z.clamp(0.0, 1.0)), f64::from(near));
        if far.is_infinite() {
            return n / (1.0 - z);
        }
        let f = f64::from(far);
        n * f / (f * (1.0 - z) + n * z)
    }

    /// `vz = n·f / (z·(f − n) + n)` for reversed float depth `z` (clamped to `[0, 1]`).
    pub fn view_z_from_reversed_depth(z: f32, near: f32, far: f32) -> f64 {
        let (z, n) = (f64::from(z.clamp(0.0, 1.0)), f64::from(near));
        if far.is_infinite() {
            return n / z;
        }
        let f = f64::from(far);
        n * f / (z * (f - n) + n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::precision::metrics::ulp_error;

    #[test]
    fn planes_map_to_near_and_far() {
        assert_eq!(view_z_from_depth24(0, 0.1, 100.0), 0.1);
        crate::assert_within!(
            ulp_error(view_z_from_depth24(DEPTH24_MAX, 0.1, 100.0), 100.0),
            bounds::DEPTH24_CORRECTLY_ROUNDED,
            "bounds::DEPTH24_CORRECTLY_ROUNDED",
            "the far plane's code, ULP"
        );
        assert_eq!(view_z_from_depth24(DEPTH24_MAX, 0.1, f32::INFINITY), SKY);
        assert_eq!(view_z_from_depth(0.0, 0.5, 10.0), 0.5);
        assert_eq!(view_z_from_depth(1.0, 0.5, f32::INFINITY), SKY);
        assert_eq!(view_z_from_reversed_depth(1.0, 0.5, 10.0), 0.5);
        assert_eq!(view_z_from_reversed_depth(0.0, 0.5, f32::INFINITY), SKY);
        crate::assert_within!(
            ulp_error(view_z_from_reversed_depth(0.0, 0.5, 10.0), 10.0),
            bounds::FLOAT_CORRECTLY_ROUNDED,
            "bounds::FLOAT_CORRECTLY_ROUNDED",
            "the reversed far plane, ULP"
        );
    }

    /// `projection` depends on this module; a path into it from here, outside comments (doc links
    /// only point a reader there), would close the circle again.
    #[test]
    fn no_use_of_projection() {
        let m = "projection";
        let needles = [format!("{m}::"), format!("::{m}"), format!("{{{m}")];
        for (file, text) in [
            ("mod.rs", include_str!("mod.rs")),
            ("constants.rs", include_str!("constants.rs")),
        ] {
            for (i, line) in text.lines().enumerate() {
                let code = line.trim_start();
                assert!(
                    code.starts_with("//") || !needles.iter().any(|n| code.contains(n.as_str())),
                    "src/linear_depth/{file}:{}: {line}",
                    i + 1
                );
            }
        }
    }

    #[test]
    fn bad_depths_clamp_or_give_the_sky() {
        assert_eq!(view_z_from_depth(f32::NAN, 1.0, 2.0), SKY);
        assert_eq!(view_z_from_reversed_depth(f32::NAN, 1.0, 2.0), SKY);
        assert_eq!(view_z_from_reversed_depth(0.5, f32::NAN, 2.0), SKY);
        assert_eq!(view_z_from_reversed_depth(0.5, 2.0, 1.0), SKY);
        // Just below 2^127 a distance is returned; at it, the sky.
        assert_eq!(divide_or_sky(SKY_THRESHOLD, 1.0), SKY);
        assert!(divide_or_sky(SKY_THRESHOLD, 1.000_000_1) < SKY_THRESHOLD);
        assert_eq!(divide_or_sky(1.0, 1e-45), SKY);
        assert_eq!(view_z_from_depth(-5.0, 1.0, 2.0), 1.0);
        assert_eq!(
            view_z_from_depth24(u32::MAX, 1.0, 2.0),
            view_z_from_depth24(DEPTH24_MAX, 1.0, 2.0)
        );
    }
}
