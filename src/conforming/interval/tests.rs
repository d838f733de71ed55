use super::*;

const SRC: &str = "
        fn add(a: f32, b: f32) -> f32 { return a + b; }
        fn quo(a: f32, b: f32) -> f32 { return a / b; }
        fn fma_like(a: f32, b: f32, c: f32) -> f32 { return a * b + c; }
        fn three(a: f32, b: f32, c: f32) -> f32 { return (a + b) + c; }
        fn inner(a: f32, b: f32) -> f32 { return a - b; }
        fn through_call(a: f32, b: f32, c: f32) -> f32 { return inner(a, b) + c; }
        fn lanes(a: f32, b: f32) -> f32 { let v = vec2<f32>(a + b, a); return v.y + b; }
        fn branchy(a: f32, b: f32) -> f32 {
            let s = a + b;
            if (s < 1.0) { return s * 4.0; }
            return s;
        }
        fn conv(x: u32) -> f32 { return f32(x); }
        fn scaled(a: f32, b: f32, c: f32) -> f32 { let p = a * b; return p / c; }
        fn long_chain(a: f32, b: f32, c: f32) -> f32 { return ((a * b) / c) * a; }
        fn sane(x: f32) -> f32 {
            let bits = bitcast<u32>(x);
            return select(x, 1e30, (bits & 0x7fffffffu) >= 0x7f800000u);
        }
        fn spread(a: f32, b: f32) -> f32 { return sane((a / b) * b - a); }
        fn dotted(a: f32, b: f32, c: f32) -> f32 { return dot(vec3<f32>(a, b, c), vec3<f32>(1.0)); }
        fn scaled_chain(a: f32, b: f32, c: f32) -> f32 { return ((a * 4.0) * b) * c; }
        fn row(a: f32, b: f32, c: f32) -> f32 {
            return (mat3x3<f32>(vec3<f32>(1.0), vec3<f32>(1.0), vec3<f32>(1.0)) * vec3<f32>(a, b, c)).x;
        }
    ";

fn f(name: &str, args: &[f32], flush: bool) -> R<Iv> {
    let e = Enclosure::new(SRC, flush)?;
    let v: Vec<Value> = args.iter().map(|&x| Value::f32s(&[x])).collect();
    Ok(e.of(name, &v)?.f32_lanes().unwrap()[0])
}

#[test]
fn an_inexact_sum_may_be_either_neighbour_and_an_exact_one_only_itself() {
    let (a, b) = (1.0f32, 2f32.powi(-30));
    let iv = f("add", &[a, b], false).unwrap();
    assert_eq!((iv.lo, iv.hi), (1.0, 1.0f32.next_up()));
    let iv = f("add", &[1.5, 0.25], false).unwrap();
    assert_eq!((iv.lo, iv.hi), (1.75, 1.75));
}

#[test]
fn a_quotient_spans_every_f32_within_two_and_a_half_ulp() {
    let iv = f("quo", &[1.0, 3.0], false).unwrap();
    let q = 1.0f64 / 3.0;
    let u = ulp_spec(q);
    // Inside, and no f32 just outside the allowance is admitted.
    assert!(f64::from(iv.lo) >= q - 2.5 * u && f64::from(iv.hi) <= q + 2.5 * u);
    assert!(f64::from(iv.lo.next_down()) < q - 2.5 * u);
    assert!(f64::from(iv.hi.next_up()) > q + 2.5 * u);
    assert_eq!(
        iv.hi.to_bits() - iv.lo.to_bits(),
        4,
        "five f32 values, {iv:?}"
    );
}

#[test]
fn the_spec_ulp_at_a_power_of_two_is_the_spacing_below() {
    assert_eq!(ulp_spec(1.0), 2f64.powi(-24));
    assert_eq!(ulp_spec(1.5), 2f64.powi(-23));
    assert_eq!(ulp_spec(0.75), 2f64.powi(-24));
}

#[test]
fn a_product_then_a_sum_holds_the_fused_result_too() {
    let (a, b, c) = (1.0f32 + 2f32.powi(-12), 1.0f32 - 2f32.powi(-13), -1.0f32);
    let iv = f("fma_like", &[a, b, c], false).unwrap();
    let fused = a.mul_add(b, c);
    let unfused = a * b + c;
    for r in [fused, unfused] {
        assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
    }
    assert_ne!(fused, unfused, "the case must tell fusion apart");
}

#[test]
fn a_sum_a_compiler_could_reassociate_is_refused() {
    for name in ["three", "through_call"] {
        assert!(
            matches!(
                f(name, &[1.0, 2.0, 3.0], false),
                Err(IntervalError::NotCovered(_))
            ),
            "{name}"
        );
    }
    // A lane that is not a sum, taken from a vector that holds one, is fine.
    assert!(f("lanes", &[1.0, 2.0], false).is_ok());
}

#[test]
fn a_quotient_of_a_product_holds_its_reassociations() {
    let (a, b, c) = (3.0f32, 1.0f32 / 3.0, 7.0f32);
    let iv = f("scaled", &[a, b, c], false).unwrap();
    // (a/c)·b and a·(b/c) on a correctly rounded adapter: inside as well as (a·b)/c.
    for r in [(a * b) / c, (a / c) * b, a * (b / c)] {
        assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
    }
    assert!(matches!(
        f("long_chain", &[a, b, c], false),
        Err(IntervalError::NotCovered(_))
    ));
}

#[test]
fn a_matrix_row_is_summed_in_every_order() {
    // 1 + 2^-24 − 1: (a + b) + c gives 0, a + (b + c) and (a + c) + b give 2^-24.
    let (a, b, c) = (1.0f32, 2f32.powi(-24), -1.0f32);
    let iv = f("row", &[a, b, c], false).unwrap();
    for r in [(a + b) + c, a + (b + c), (a + c) + b] {
        assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
    }
    assert!(iv.lo <= 0.0 && iv.hi >= 2f32.powi(-24));
}

#[test]
fn a_dot_product_is_summed_in_every_order() {
    // As the matrix row above: dot's inherited accuracy lets any order stand.
    let (a, b, c) = (1.0f32, 2f32.powi(-24), -1.0f32);
    let iv = f("dotted", &[a, b, c], false).unwrap();
    for r in [(a + b) + c, a + (b + c), (a + c) + b] {
        assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
    }
}

#[test]
fn a_power_of_two_scaling_starts_no_chain() {
    // a·4 is exact, so ((a·4)·b)·c has the roundings of (a·b)·c, whose reorderings are
    // hulled in; without the exemption the chain of three would be refused.
    let (a, b, c) = (1.0f32 / 3.0, 3.0f32.sqrt(), 7.0f32.sqrt());
    let iv = f("scaled_chain", &[a, b, c], false).unwrap();
    for r in [
        ((a * 4.0) * b) * c,
        (a * 4.0) * (b * c),
        ((a * 4.0) * c) * b,
    ] {
        assert!(iv.lo <= r && r <= iv.hi, "{r:e} outside {iv:?}");
    }
}

#[test]
fn a_magnitude_read_from_the_bits_of_an_enclosure_that_spans_zero_stays_finite() {
    // (1/3)·3 − 1 lies on both sides of 0, so its bits span the sign; its magnitude cannot
    // reach infinity, so the select must keep the value and never the 1e30.
    let iv = f("spread", &[1.0, 3.0], false).unwrap();
    assert!(iv.lo < 0.0 && iv.hi > 0.0 && iv.hi < 1e-6, "{iv:?}");
}

#[test]
fn division_outside_the_specified_divisors_is_indeterminate() {
    assert!(matches!(
        f("quo", &[1.0, 1e-39], false),
        Err(IntervalError::Indeterminate(_))
    ));
}

#[test]
fn a_condition_undecided_on_the_enclosure_joins_both_branches() {
    // 1 − 2^-30 + 2^-31... a + b lies on both sides of 1: either branch may run.
    let (a, b) = (1.0f32.next_down(), 2f32.powi(-25));
    let iv = f("branchy", &[a, b], false).unwrap();
    assert!(iv.lo < 1.0 && iv.hi > 3.9, "{iv:?}");
    // Decided: only one branch.
    let iv = f("branchy", &[0.25, 0.25], false).unwrap();
    assert_eq!((iv.lo, iv.hi), (2.0, 2.0));
}

#[test]
fn flushing_admits_zero_for_a_subnormal_result() {
    let tiny = f32::MIN_POSITIVE / 4.0;
    assert_eq!(f("add", &[tiny, tiny], false).unwrap().lo, 2.0 * tiny);
    assert_eq!(f("add", &[tiny, tiny], true).unwrap().lo, 0.0);
}

#[test]
fn an_integer_above_two_to_the_24_converts_to_either_neighbour() {
    let e = Enclosure::new(SRC, false).unwrap();
    let v = e.of("conv", &[Value::u32s(&[(1 << 24) + 1])]).unwrap();
    let iv = v.f32_lanes().unwrap()[0];
    assert_eq!((iv.lo, iv.hi), (16_777_216.0, 16_777_218.0));
    let v = e.of("conv", &[Value::u32s(&[12345])]).unwrap();
    assert_eq!(v.f32_lanes().unwrap()[0], Iv::point(12345.0));
}
