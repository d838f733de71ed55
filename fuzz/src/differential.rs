//! [`DIFFERENTIAL`]: the Rust twins against their exact references, within the documented
//! bound.

use crate::{Entry, projection};
use glam::Vec3;
use prepass::assert_within;
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::linear_depth as ld;
use prepass::precision::metrics::ulp_error;
use prepass::projection::DepthConvention;

/// The documented error of a linear-depth twin against its exact f64 distance: within `bound`
/// ULP (`from` names the bound), or the sky sentinel `linear_depth::SKY` exactly where the exact
/// distance is `2^127` or more — and allowed where the exact distance is within the bound (plus
/// one ULP) below `2^127`, or `subnormal_depth` (a subnormal float depth of an infinite
/// projection, whose denominator is subnormal).
#[track_caller]
fn assert_distance(
    got: f32,
    exact: f64,
    subnormal_depth: bool,
    (bound, from): (f64, &str),
    context: std::fmt::Arguments<'_>,
) {
    if exact >= 2f64.powi(127) {
        assert_eq!(got, ld::SKY, "{context}: 2^127 or more is the sky");
        return;
    }
    if subnormal_depth && got == ld::SKY {
        return;
    }
    // Within the error bound below 2^127 the computed quotient may reach 2^127: the sky too
    // (linear_depth, "Bad input").
    if got == ld::SKY && exact >= 2f64.powi(127) * (1.0 - (bound + 1.0) * 2f64.powi(-24)) {
        return;
    }
    assert_within!(ulp_error(got, exact), bound, from, "{context}");
}

/// Rust twins against their exact references, within the documented bound.
pub const DIFFERENTIAL: &[Entry] = &[
    Entry {
        name: "depth24::hyperbolic_depth_from_depth24 vs exact::hyperbolic_depth",
        check: |i| {
            let d = i.u32();
            let got = depth24::hyperbolic_depth_from_depth24(d);
            let err = ulp_error(got, depth24::exact::hyperbolic_depth(d));
            assert_within!(
                err,
                0.5,
                "documented: correctly rounded, ≤ 0.5 ULP",
                "{d:#x} → {got:?}"
            );
        },
    },
    Entry {
        name: "depth24::depth24_from_rgb8 within ±0.49/255 vs exact code",
        check: |i| {
            let code = i.u32() & DEPTH24_MAX;
            // Each channel moved by up to ±0.49 of a byte step (a signed byte scaled to ±0.49):
            // the documented exactness region.
            let bytes = [code >> 16, (code >> 8) & 0xff, code & 0xff];
            let rgb = bytes.map(|b| {
                let off = f64::from(i.u8() as i8) / 128.0 * 0.49;
                ((f64::from(b) + off) / 255.0) as f32
            });
            let got = depth24::depth24_from_rgb8(Vec3::from(rgb));
            assert_eq!(got, code, "{rgb:?}");
        },
    },
    Entry {
        name: "linear_depth::view_z_from_depth24 vs exact (linear_depth::bounds::DEPTH24_CORRECTLY_ROUNDED: the Rust twin rounds correctly)",
        check: |i| {
            let d = i.u32();
            let Ok(p) = projection(i) else { return };
            let got = ld::view_z_from_depth24(d, p.near(), p.far());
            let e = ld::exact::view_z_from_depth24(d, p.near(), p.far());
            assert_distance(
                got,
                e,
                false,
                (
                    ld::bounds::DEPTH24_CORRECTLY_ROUNDED,
                    "linear_depth::bounds::DEPTH24_CORRECTLY_ROUNDED",
                ),
                format_args!("{d:#x} {p:?}: {got} vs {e}"),
            );
        },
    },
    Entry {
        name: "linear_depth::view_z_from_depth / _reversed_ vs exact (linear_depth::bounds::FLOAT_CORRECTLY_ROUNDED)",
        check: |i| {
            let z = i.f32();
            let Ok(p) = projection(i) else { return };
            if z.is_nan() {
                assert_eq!(
                    match p.convention() {
                        DepthConvention::Standard => ld::view_z_from_depth(z, p.near(), p.far()),
                        DepthConvention::Reversed => {
                            ld::view_z_from_reversed_depth(z, p.near(), p.far())
                        }
                    },
                    ld::SKY,
                    "NaN depth gives the sky sentinel"
                );
                return;
            }
            let (n, f) = (p.near(), p.far());
            let (got, e) = match p.convention() {
                DepthConvention::Standard => (
                    ld::view_z_from_depth(z, n, f),
                    ld::exact::view_z_from_depth(z, n, f),
                ),
                DepthConvention::Reversed => (
                    ld::view_z_from_reversed_depth(z, n, f),
                    ld::exact::view_z_from_reversed_depth(z, n, f),
                ),
            };
            assert_distance(
                got,
                e,
                f.is_infinite() && z.abs() < f32::MIN_POSITIVE,
                (
                    ld::bounds::FLOAT_CORRECTLY_ROUNDED,
                    "linear_depth::bounds::FLOAT_CORRECTLY_ROUNDED",
                ),
                format_args!("{z:?} {p:?}: {got} vs {e}"),
            );
        },
    },
    Entry {
        name: "linear_depth::view_z_from_depth_uniform / _depth24_uniform vs exact (linear_depth::bounds::FLOAT_CONSTS_CORRECTLY_ROUNDED, DEPTH24_CONSTS_CORRECTLY_ROUNDED)",
        check: |i| {
            let (z, d) = (i.f32(), i.u32());
            let Ok(p) = projection(i) else { return };
            let (n, f, k) = (p.near(), p.far(), p.depth_uniform());
            // A reversed 24-bit code stores the depth of the standard code 2^24 − 1 − d.
            let max = prepass::depth24::DEPTH24_MAX;
            let standard_code = match p.convention() {
                DepthConvention::Standard => d.min(max),
                DepthConvention::Reversed => max - d.min(max),
            };
            let got = ld::view_z_from_depth24_uniform(d, k);
            let e = ld::exact::view_z_from_depth24(standard_code, n, f);
            assert_distance(
                got,
                e,
                false,
                (
                    ld::bounds::DEPTH24_CONSTS_CORRECTLY_ROUNDED,
                    "linear_depth::bounds::DEPTH24_CONSTS_CORRECTLY_ROUNDED",
                ),
                format_args!("{d:#x} {p:?}: {got} vs {e}"),
            );
            let got = ld::view_z_from_depth_uniform(z, k);
            if z.is_nan() {
                assert_eq!(got, ld::SKY, "NaN depth gives the sky sentinel");
                return;
            }
            let e = match p.convention() {
                DepthConvention::Standard => ld::exact::view_z_from_depth(z, n, f),
                DepthConvention::Reversed => ld::exact::view_z_from_reversed_depth(z, n, f),
            };
            assert_distance(
                got,
                e,
                f.is_infinite() && z.abs() < f32::MIN_POSITIVE,
                (
                    ld::bounds::FLOAT_CONSTS_CORRECTLY_ROUNDED,
                    "linear_depth::bounds::FLOAT_CONSTS_CORRECTLY_ROUNDED",
                ),
                format_args!("{z:?} {p:?}: {got} vs {e}"),
            );
        },
    },
];
