//! `Projection` properties (proptest): validation never panics and names the field; view
//! distance is monotonic in the code; forward (distance → code) then back lands within one
//! code's width; and on the adapter, random projections agree with the twins within 1 ULP.

mod common;

use common::run_kernel;
use prepass::depth24::{DEPTH24_MAX, hyperbolic_depth_from_depth24};
use prepass::harness::Arg;
use prepass::linear_depth::{self as ld, exact};
use prepass::precision::metrics::ulp_distance;
use prepass::projection::{DepthConvention, Projection};
use prepass::{assert_within, assert_within_abs};
use proptest::prelude::*;

/// Stiff projections: near log-uniform in [1e-4, 10], far/near log-uniform in [10, 1e9] or ∞.
fn stiff() -> impl Strategy<Value = (f32, f32)> {
    (-4.0f64..1.0, 1.0f64..9.0, any::<bool>()).prop_map(|(ln, lr, inf)| {
        let near = 10f64.powf(ln) as f32;
        let far = if inf {
            f32::INFINITY
        } else {
            (f64::from(near) * 10f64.powf(lr)) as f32
        };
        (near, far)
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn validation_never_panics_and_names_the_field(n in any::<u32>(), f in any::<u32>()) {
        let (near, far) = (f32::from_bits(n), f32::from_bits(f));
        // The documented rules, restated: near a positive normal float with near·(2^24 − 1)
        // finite in f32; far > near, and a finite far keeps near/far ≥ the smallest normal.
        let (n64, f64_) = (f64::from(near), f64::from(far));
        let near_ok = near >= f32::MIN_POSITIVE
            && near.is_finite()
            && n64 * 16_777_215.0 <= f64::from(f32::MAX);
        let far_ok = far > near && (far.is_infinite() || n64 / f64_ >= f64::from(f32::MIN_POSITIVE));
        match Projection::new(near, far, DepthConvention::Standard) {
            Ok(p) => {
                prop_assert!(near_ok && far_ok);
                prop_assert_eq!((p.near(), p.far()), (near, far));
            }
            Err(e) => {
                prop_assert!(!(near_ok && far_ok));
                prop_assert_eq!(e.field, if near_ok { "far" } else { "near" });
                prop_assert!(e.to_string().contains(e.field));
            }
        }
    }

    #[test]
    fn view_z_is_monotonic_in_the_code((near, far) in stiff(), d in 0u32..DEPTH24_MAX) {
        prop_assert!(ld::view_z_from_depth24(d, near, far) <= ld::view_z_from_depth24(d + 1, near, far));
    }

    #[test]
    fn forward_then_back_is_within_one_code((near, far) in stiff(), t in 0.0f64..1.0, reversed in any::<bool>()) {
        let conv = if reversed { DepthConvention::Reversed } else { DepthConvention::Standard };
        let p = Projection::new(near, far, conv).unwrap();
        // A distance log-uniform between near and min(far, 1e30).
        let top = f64::from(far).min(1e30);
        let vz = f64::from(near) * (top / f64::from(near)).powf(t);
        let code = p.depth24_from_view_z(vz);
        let back = |c: u32| -> f64 {
            match conv {
                DepthConvention::Standard => f64::from(ld::view_z_from_depth24(c, near, far)),
                DepthConvention::Reversed => f64::from(ld::view_z_from_reversed_depth(
                    hyperbolic_depth_from_depth24(c), near, far)),
            }
        };
        let exact_of = |c: u32| -> f64 {
            match conv {
                DepthConvention::Standard => exact::view_z_from_depth24(c, near, far),
                DepthConvention::Reversed => exact::view_z_from_reversed_depth(
                    hyperbolic_depth_from_depth24(c), near, far),
            }
        };
        let got = back(code);
        if got.is_infinite() {
            // The far code of an infinite projection reads back as +inf by design: then vz must
            // lie beyond the last finite code's distance.
            let (far_code, last) = match conv {
                DepthConvention::Standard => (DEPTH24_MAX, DEPTH24_MAX - 1),
                DepthConvention::Reversed => (0, 1),
            };
            prop_assert!(far.is_infinite() && code == far_code);
            prop_assert!(vz >= exact_of(last), "vz {} read back as inf", vz);
            return Ok(());
        }
        // One code's width: the larger gap to a neighbouring code's exact distance. vz lies within
        // half a code of `code`, and the twin's result within its correctly rounded bound
        // (`linear_depth::bounds::DEPTH24_CORRECTLY_ROUNDED` ULP, each ≤ 2^-23 relative) of
        // `code`'s exact distance.
        let lo = if code > 0 { exact_of(code - 1) } else { exact_of(code) };
        let hi = if code < DEPTH24_MAX { exact_of(code + 1) } else { exact_of(code) };
        let here = exact_of(code);
        let width = (here - lo).abs().max((hi - here).abs());
        let slack = ld::bounds::DEPTH24_CORRECTLY_ROUNDED * 2f64.powi(-23) * got.abs();
        assert_within_abs!(got, vz, width + slack,
            "comment above: one code's width + the twin's bound in relative terms",
            "vz {} → code {} → {} (width {})", vz, code, got, width);
    }

    #[test]
    fn random_projections_agree_with_twins_on_the_adapter(
        cases in proptest::collection::vec((stiff(), 0u32..=DEPTH24_MAX), 4096)
    ) {
        let near: Vec<f32> = cases.iter().map(|c| c.0.0).collect();
        let far: Vec<f32> = cases.iter().map(|c| c.0.1).collect();
        let code: Vec<u32> = cases.iter().map(|c| c.1).collect();
        let out = run_kernel(prepass::wgsl::LINEAR_DEPTH, "view_z_from_depth24", &[Arg::column(&code), Arg::column(&near), Arg::column(&far)], code.len() as u64);
        for (k, &got) in out.as_f32().iter().enumerate() {
            let twin = ld::view_z_from_depth24(code[k], near[k], far[k]);
            // Where the adapter evaluates like the twins (common::evaluates_like_the_twins):
            // within 1 ULP of the twin (the bound; only fusion could separate them)…
            if common::evaluates_like_the_twins() {
                assert_within!(ulp_distance(got, twin).unwrap(), 1, "twins within 1 ULP: only fusion separates them", "{} vs twin {}", got, twin);
            }
            // …and within its bound of the exact distance: correctly rounded there, the
            // conforming one on any other adapter (checked under emulation in
            // tests/linear_depth.rs). (The sky, 2^127 and beyond, is the sentinel `ld::SKY`:
            // `distance_error` counts it.)
            let e = exact::view_z_from_depth24(code[k], near[k], far[k]);
            let err = prepass::sweep::linear_depth::distance_error(got, e);
            let (bound, which) = common::bound_here(ld::bounds::DEPTH24_CORRECTLY_ROUNDED, ld::bounds::DEPTH24_CONFORMING);
            assert_within!(err, bound, format_args!("linear_depth::bounds::DEPTH24_*, {which}"), "code {} near {} far {}", code[k], near[k], far[k]);
        }
    }
}
