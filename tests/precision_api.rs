//! `prepass::precision::check` as a downstream suite uses it: only the public API, against
//! deliberately wrong WGSL functions. The check must find the failure and shrink it — on the
//! adapter — to a small input, and must pass a correct function.

mod common;

use common::{gpu, run_kernel};
use prepass::depth24;
use prepass::harness::{Arg, ValueType};
use prepass::precision::check::{
    CheckConfig, CheckError, Failure, PrecisionCheck, WgslArgs, WgslValue,
};
use prepass::precision::metrics::{relative_error, ulp_error};
use prepass::precision::proptest::prelude::*;
use prepass::precision::strategies::{depth24_code, near_far};
use prepass::{assert_at_least, assert_within};

/// Divides by 2^24 where `d/(2^24 − 1)` was meant: the off-by-one every depth decoder risks.
const WRONG_DEPTH: &str = "fn depth_unit_wrong(d: u32) -> f32 { return f32(d) / 16777216.0; }";

/// Packs a 24-bit code but forgets to saturate codes above `2^24 − 1`.
const WRONG_PACK: &str = "fn pack_unsaturated(d: u32) -> u32 {
    return ((d >> 16u) & 0xffu) | (d & 0xff00u) | ((d & 0xffu) << 16u);
}";

fn exact_depth(d: &u32) -> f64 {
    depth24::exact::hyperbolic_depth(*d)
}

fn ulps(got: &f32, want: &f64) -> f64 {
    ulp_error(*got, *want)
}

/// Bound for a correctly rounded result: half an ULP of the exact value.
const CORRECTLY_ROUNDED: f64 = 0.5;

fn expect_failure<I, O, R>(r: Result<impl std::fmt::Debug, CheckError<I, O, R>>) -> Failure<I, O, R>
where
    I: std::fmt::Debug,
    O: std::fmt::Debug,
    R: std::fmt::Debug,
{
    match r {
        Err(CheckError::Failed(f)) => {
            eprintln!("{f}");
            *f
        }
        Err(e) => panic!("the check could not run: {e}"),
        Ok(p) => panic!("a wrong function passed: {p:?}"),
    }
}

#[test]
fn off_by_one_depth_is_found_and_shrunk_to_the_smallest_failing_code() {
    let check = PrecisionCheck::new(gpu(), WRONG_DEPTH, "depth_unit_wrong").unwrap();
    let fail = expect_failure(check.run(&depth24_code(), exact_depth, ulps, CORRECTLY_ROUNDED));

    // Independent answer: sweep the first 4096 codes through the same WGSL on the adapter and
    // take the first whose error exceeds the bound. (Derivation: d = 0 is exact; d = 1 gives
    // 2^-24 where 2^-24·(1 + 2^-24 + …) was meant, 0.5·(1 + 2^-24 + …) ULP > 0.5.)
    let sweep = run_kernel(
        WRONG_DEPTH,
        "depth_unit_wrong",
        &[Arg::Index { start: 0 }],
        4096,
    );
    let smallest = (0u32..4096)
        .find(|&d| ulps(&sweep.as_f32()[d as usize], &exact_depth(&d)) > CORRECTLY_ROUNDED)
        .expect("the sweep finds a failing code");

    assert!(fail.failing > 0);
    let wrong = "CORRECTLY_ROUNDED: the wrong function exceeds half an ULP (derivation above)";
    assert_at_least!(fail.worst.error, > CORRECTLY_ROUNDED, wrong, "the worst input must fail");
    assert_at_least!(fail.shrunk.error, > CORRECTLY_ROUNDED, wrong, "shrunk input must still fail");
    assert_eq!(
        fail.shrunk.input, smallest,
        "shrunk to {} (worst was {})",
        fail.shrunk.input, fail.worst.input
    );
    // The reported error is the adapter's result measured again, not a stale value.
    assert_eq!(
        fail.shrunk.error,
        ulps(&fail.shrunk.got, &exact_depth(&smallest))
    );
    assert!(fail.shrank && fail.shrink_steps > 0 && fail.shrink_dispatches > 0);
}

#[test]
fn speculative_shrinking_takes_the_same_path_in_fewer_dispatches() {
    let run = |depth: u32| {
        let check = PrecisionCheck::new(gpu(), WRONG_DEPTH, "depth_unit_wrong")
            .unwrap()
            .with_config(CheckConfig {
                speculation_depth: depth,
                ..CheckConfig::default()
            });
        expect_failure(check.run(&depth24_code(), exact_depth, ulps, CORRECTLY_ROUNDED))
    };
    let plain = run(1);
    let speculative = run(5);
    assert_eq!(plain.shrunk.input, speculative.shrunk.input);
    assert_eq!(plain.shrink_steps, speculative.shrink_steps);
    // Depth 1 is one dispatch per step; depth 5 follows up to five steps per dispatch.
    assert_eq!(plain.shrink_dispatches, plain.shrink_steps);
    assert!(
        speculative.shrink_dispatches * 3 <= plain.shrink_dispatches,
        "{} vs {} dispatches",
        speculative.shrink_dispatches,
        plain.shrink_dispatches
    );
}

#[test]
fn unsaturated_pack_is_shrunk_to_a_minimal_out_of_range_code() {
    let check = PrecisionCheck::new(gpu(), WRONG_PACK, "pack_unsaturated").unwrap();
    // Metric: distance in codes between what the texel decodes to and what it should.
    let codes = |got: &u32, want: &u32| {
        f64::from(depth24::depth24_from_packed(*got).abs_diff(depth24::depth24_from_packed(*want)))
    };
    let fail = expect_failure(check.run(&any::<u32>(), |d| depth24::pack_depth24(*d), codes, 0.0));
    let s = fail.shrunk.input;
    // Every d ≤ 2^24 − 1 packs correctly, so a failing input is ≥ 2^24; binary-search shrinking
    // stops where s fails and s − 1 passes, which (d − 1 passes iff its low 24 bits are all
    // ones) means s = k·2^24.
    assert!(
        s >= 1 << 24 && s.is_multiple_of(1 << 24),
        "shrunk to {s:#x}"
    );
    assert!(s <= fail.worst.input);
    let got: Vec<u32> = check.evaluate::<u32, u32, ()>(&[s - 1, s]).unwrap();
    assert_eq!(got[0], depth24::pack_depth24(s - 1), "s − 1 passes");
    assert_ne!(got[1], depth24::pack_depth24(s), "s fails");
}

#[test]
fn a_correct_function_passes_with_its_documented_bound() {
    let check = PrecisionCheck::new(
        gpu(),
        prepass::wgsl::DEPTH24,
        "hyperbolic_depth_from_depth24",
    )
    .unwrap();
    let passed = check
        .run(&depth24_code(), exact_depth, ulps, CORRECTLY_ROUNDED)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(passed.cases, u64::from(CheckConfig::default().cases));
    assert_eq!(passed.stats.nan_count, 0);
    assert_within!(
        passed.stats.max,
        CORRECTLY_ROUNDED,
        "CORRECTLY_ROUNDED: hyperbolic_depth_from_depth24 is correctly rounded (depth24 docs)",
        "ULP over {} cases",
        passed.cases
    );
}

#[test]
fn mismatched_types_are_a_setup_error_not_a_panic() {
    let check = PrecisionCheck::new(gpu(), WRONG_DEPTH, "depth_unit_wrong").unwrap();
    let r = check.run(&any::<f32>(), |x| f64::from(*x), ulps, 0.5);
    match r {
        Err(CheckError::Setup(m)) => assert!(m.contains("fn(u32) -> f32"), "{m}"),
        other => panic!("expected a setup error, got {:?}", other.map(|p| p.cases)),
    }
}

/// A downstream input type: implementing `WgslArgs` for it feeds a two-parameter function.
#[derive(Clone, Debug)]
struct Planes {
    near: f32,
    far: f32,
}

impl WgslArgs for Planes {
    fn param_types() -> Vec<ValueType> {
        vec![f32::TYPE, f32::TYPE]
    }
    fn push_columns(&self, columns: &mut [Vec<u32>]) {
        self.near.push_words(&mut columns[0]);
        self.far.push_words(&mut columns[1]);
    }
}

#[test]
fn a_user_input_struct_runs_over_stiff_and_infinite_planes() {
    let src = "fn far_over_near(near: f32, far: f32) -> f32 { return far / near; }";
    let check = PrecisionCheck::new(gpu(), src, "far_over_near").unwrap();
    let planes = near_far().prop_map(|(near, far)| Planes { near, far });
    let exact = |p: &Planes| f64::from(p.far) / f64::from(p.near);
    let rel = |got: &f32, want: &f64| relative_error(f64::from(*got), *want);
    // Bound: WGSL's `/` is within 2.5 ULP, and one f32 ULP is at most 2^-23 of the value, so
    // the relative error is at most 2.5·2^-23 (far = +Inf gives +Inf exactly: error 0). The
    // quotient stays far inside f32's range (far/near ≤ 1e9·(1 + 2^-24)).
    let bound = 2.5 * 2f64.powi(-23);
    let passed = check
        .run(&planes, exact, rel, bound)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(passed.stats.nan_count, 0);
    assert_within!(
        passed.stats.max,
        bound,
        "derived above: WGSL's 2.5 ULP `/`, ≤ 2.5·2^-23 relative",
        "far / near, relative error over {} cases",
        passed.cases
    );
}

/// `PrecisionCheck::searched` on `x / (y·z)`, where the greedy policies cancel (`y·z` rounded up
/// makes the quotient small, `/` pushed up makes it large): the search must find more than the
/// start tables, pass the derived bound, and fail — shrinking at the found table — at a bound
/// the greedy policies' own emulated checks pass.
#[test]
fn searched_check_finds_what_the_greedy_policies_cancel() {
    use prepass::conforming::search::SearchConfig;
    use prepass::conforming::{Emulation, Policy};
    let wgsl = "fn ratio(x: f32, y: f32, z: f32) -> f32 { return x / (y * z); }";
    let strategy = (1.0f32..2.0, 1.0f32..2.0, 1.0f32..2.0);
    let reference = |&(x, y, z): &(f32, f32, f32)| f64::from(x) / (f64::from(y) * f64::from(z));
    // `y·z` to either neighbour is 2^-23 relative, at most 2 ULP of the quotient (whose ULP is
    // at least 2^-24 of it); `/` adds its 2.5 ULP; 0.01 covers the second-order term.
    let bound = 4.51;
    let search = SearchConfig::default();
    let check = PrecisionCheck::searched(gpu(), wgsl, "ratio", &Emulation::new(Policy::Searched))
        .unwrap()
        .cases(1024);
    let passed = check
        .run_searched(&strategy, reference, ulps, bound, &search, 32)
        .unwrap_or_else(|e| panic!("{e}"));
    let s = passed
        .search
        .clone()
        .expect("a searched run reports its search");
    eprintln!(
        "x/(y·z): upper/lower {:.3} ULP, searched {:.3} ULP over {} climbed inputs ({} exhaustive, {} tables), bound {bound}",
        s.greedy_max, s.found_max, s.inputs, s.exhaustive, s.evaluated
    );
    assert_eq!(passed.stats.max, s.found_max);
    assert!(
        s.found_max > s.greedy_max,
        "the search found no more than the start tables ({} ULP)",
        s.greedy_max
    );
    // At the greedy worst as the bound, Upper and Lower pass and the searched check fails.
    for policy in [Policy::Upper, Policy::Lower] {
        PrecisionCheck::emulated(gpu(), wgsl, "ratio", &Emulation::new(policy))
            .unwrap()
            .cases(1024)
            .run(&strategy, reference, ulps, s.greedy_max)
            .unwrap_or_else(|e| panic!("{policy}: {e}"));
    }
    let f =
        expect_failure(check.run_searched(&strategy, reference, ulps, s.greedy_max, &search, 32));
    assert_eq!(
        f.worst.error, s.found_max,
        "the failure is reported at the found table"
    );
    assert!(f.shrunk.error > s.greedy_max);
}
