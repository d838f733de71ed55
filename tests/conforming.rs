//! Self-tests of the conforming-adapter emulation (`prepass::conforming`): per builtin, on powers
//! of two, subnormals, signed zeros, values near overflow and random values, every emulated
//! result lies inside the WGSL spec's interval (computed here in f64), the policies reach both
//! ends of it, the host adapter is as accurate as `HostAccuracy` assumes, and the identity
//! policy reproduces every shipped module bit for bit.

mod common;

use common::{gpu, run_kernel};
use prepass::conforming::{EmulatedKernel, Emulation, Freedoms, HostAccuracy, Policy, allowance};
use prepass::harness::{Arg, Signature};
use prepass::{assert_at_least, assert_within, assert_within_abs};

/// Where the reach floor of the pushed policies comes from: the host within 0.5 ULP, the push
/// 2 ULP of the spacing below it (at least half the exact result's ULP), so each end is reached
/// to within the host's error.
const PUSH: &str = "allowance::DIVISION_ULP 2.5, each quotient placed at the last float inside it from the exact quotient (within one float spacing of 2.5 ULP; the freedom checks test that each is the end): the maximum over these inputs reaches 2 (PUSH)";

const ALL_POLICIES: [Policy; 6] = [
    Policy::Identity,
    Policy::Upper,
    Policy::Lower,
    Policy::Seeded(1),
    Policy::Seeded(2),
    Policy::Seeded(3),
];

const TESTS: &str = "
fn t_div(a: f32, b: f32) -> f32 { return a / b; }
fn t_add(a: f32, b: f32) -> f32 { return a + b; }
fn t_sub(a: f32, b: f32) -> f32 { return a - b; }
fn t_mul(a: f32, b: f32) -> f32 { return a * b; }
fn t_mad(a: f32, b: f32, c: f32) -> f32 { return a * b + c; }
fn t_add3(a: f32, b: f32, c: f32) -> f32 { return (a + b) + c; }
fn t_prod(a: f32, b: f32) -> f32 { return a * b; }
fn t_prod_of(a: f32, b: f32) -> f32 { return t_prod(a, b); }
fn t_mad_helper(a: f32, b: f32, c: f32) -> f32 { return t_prod(a, b) + c; }
fn t_mad_helper_right(a: f32, b: f32, c: f32) -> f32 { return c + t_prod(a, b); }
fn t_msub_helper(a: f32, b: f32, c: f32) -> f32 { return t_prod(a, b) - c; }
fn t_nmad_helper(a: f32, b: f32, c: f32) -> f32 { return c - t_prod(a, b); }
fn t_mad_helper_nested(a: f32, b: f32, c: f32) -> f32 { return t_prod_of(a, b) + c; }
fn t_sub_add(a: f32, b: f32, c: f32) -> f32 { return (a - b) + c; }
fn t_add_sub(a: f32, b: f32, c: f32) -> f32 { return (a + b) - c; }
fn t_mul_div(a: f32, b: f32, c: f32) -> f32 { return (a * b) / c; }
fn t_matmat(a: f32, b: f32, c: f32) -> vec4<f32> {
    let m = mat2x2<f32>(a, b, c, a) * mat2x2<f32>(b, c, a, b);
    return vec4<f32>(m[0], m[1]);
}
fn t_dot3(a: f32, b: f32, c: f32) -> f32 { return dot(vec3<f32>(a, b, c), vec3<f32>(1.0)); }
fn t_dot4(a: f32, b: f32, c: f32) -> f32 { return dot(vec4<f32>(a, b, c, -0.5 * b), vec4<f32>(1.0)); }
fn t_inverse_sqrt(x: f32) -> f32 { return inverseSqrt(x); }
fn t_sqrt(x: f32) -> f32 { return sqrt(x); }
fn t_exp2(x: f32) -> f32 { return exp2(x); }
fn t_log2(x: f32) -> f32 { return log2(x); }
fn t_sin(x: f32) -> f32 { return sin(x); }
fn t_cos(x: f32) -> f32 { return cos(x); }
fn t_u32_of(x: f32) -> u32 { return u32(x); }
fn t_i32_of(x: vec2<f32>) -> vec2<i32> { return vec2<i32>(x); }
fn t_unpack4x8unorm(p: u32) -> vec4<f32> { return unpack4x8unorm(p); }
fn t_unpack4x8snorm(p: u32) -> vec4<f32> { return unpack4x8snorm(p); }
fn t_pack4x8unorm(v: vec4<f32>) -> u32 { return pack4x8unorm(v); }
fn t_length(v: vec3<f32>) -> f32 { return length(v); }
fn t_min(a: f32, b: f32) -> f32 { return min(a, b); }
fn t_max(a: f32, b: f32) -> f32 { return max(a, b); }
fn t_clamp(a: f32, b: f32) -> f32 { return clamp(a, -b, 2.0); }
fn t_abs(a: f32) -> f32 { return abs(a); }
fn t_floor(a: f32) -> f32 { return floor(a); }
fn t_lt(a: f32, b: f32) -> f32 { return select(0.0, 1.0, a < b); }
";

/// The spec's ULP of a real x: the least distance between two adjacent finite f32 values
/// a ≤ x ≤ b. Inside a binade that is the binade's spacing; at a power of two 2^k itself the
/// pair below (2^k − 2^(k−24), 2^k) is the closer one, so the ULP is the spacing below, half
/// the binade's (2^-149 throughout the subnormals and at 2^-126).
fn ulp32(x: f64) -> f64 {
    let a = x.abs();
    if a <= f64::powi(2.0, -126) {
        return f64::powi(2.0, -149);
    }
    let e = a.log2().floor() as i32;
    let e = if f64::powi(2.0, e) > a { e - 1 } else { e }; // log2's rounding near 2^k
    if a == f64::powi(2.0, e) {
        f64::powi(2.0, e - 24)
    } else {
        f64::powi(2.0, e - 23)
    }
}

/// The f32 values next to the real x: (largest ≤ x, smallest ≥ x).
fn f32_around(x: f64) -> (f32, f32) {
    let r = x as f32;
    let r64 = f64::from(r);
    if r64 == x {
        (r, r)
    } else if r64 < x {
        (r, r.next_up())
    } else {
        (r.next_down(), r)
    }
}

/// Powers of two, subnormals, signed zeros, values near overflow and random finite values.
fn special_f32s() -> Vec<f32> {
    let mut v = vec![
        0.0,
        -0.0,
        1.0,
        -1.0,
        f32::MAX,
        -f32::MAX,
        f32::MAX / 2.0,
        1.5 * 2f32.powi(126),
    ];
    for e in -149..=127 {
        v.push(2f32.powi(e));
        v.push(-(2f32.powi(e)));
    }
    for bits in [1u32, 2, 3, 0x0040_0000, 0x007f_ffff] {
        v.push(f32::from_bits(bits));
        v.push(-f32::from_bits(bits));
    }
    let mut s = 0x1234_5678_9abc_def0u64;
    for _ in 0..3000 {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        let bits = (s >> 32) as u32;
        let x = f32::from_bits(bits);
        if x.is_finite() {
            v.push(x);
        }
        // Moderate magnitudes too: random mantissa, exponent in 2^-20..2^20.
        let m = f32::from_bits(0x3f80_0000 | (bits & 0x007f_ffff));
        v.push(m * 2f32.powi((s & 31) as i32 - 16) * if s & 64 == 0 { 1.0 } else { -1.0 });
    }
    v
}

fn pairs(xs: &[f32]) -> (Vec<f32>, Vec<f32>) {
    let mut a = Vec::new();
    let mut b = Vec::new();
    let n = xs.len();
    for i in 0..n {
        for j in [0, 1, 7, 31, 97] {
            a.push(xs[i]);
            b.push(xs[(i * 13 + j * 101 + 5) % n]);
        }
    }
    (a, b)
}

fn run(
    function: &str,
    policy: Policy,
    freedoms: Freedoms,
    args: &[Arg<'_>],
    n: usize,
) -> (Vec<u32>, Vec<bool>) {
    let emu = Emulation::new(policy).with_freedoms(freedoms);
    let k = EmulatedKernel::new(gpu(), TESTS, function, &emu).unwrap_or_else(|e| panic!("{e}"));
    let (out, flags) = k.run(args, n as u64).unwrap();
    (out.into_words(), flags)
}

/// Marsaglia's xorshift64 from `seed` (non-zero): the tests' reproducible random draws.
fn xorshift64(mut s: u64) -> impl FnMut() -> u64 {
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s
    }
}

/// The inputs a flushing adapter may see for x: x itself, and ±0 for a subnormal.
fn flushed(x: f32) -> Vec<f32> {
    if x != 0.0 && x.abs() < f32::MIN_POSITIVE {
        vec![x, 0.0f32.copysign(x)]
    } else {
        vec![x]
    }
}

/// Whether `got` lies within `k` ULPs of the exact result for some allowed flushing of the
/// inputs, or is a flushed (zero) output where the interval reaches the subnormals (as the CTS
/// adds 0 to such an interval).
fn inside_k_ulp(got: f32, exacts: &[f64], k: f64) -> bool {
    exacts.iter().any(|&e| {
        let g = f64::from(got);
        let near_subnormal = e.abs() - k * ulp32(e) < f64::powi(2.0, -126);
        (g - e).abs() <= k * ulp32(e) * (1.0 + 1e-9) || (near_subnormal && got == 0.0)
    })
}

/// Per builtin: (worst distance below, worst distance above) the exact result, in its ULPs, over
/// the normal-range inputs, for the upper and lower policies: they must reach near the ends.
struct Reach {
    max_above: f64,
    max_below: f64,
}

fn reach(got: &[f32], exact: &[f64], keep: &[bool]) -> Reach {
    let mut r = Reach {
        max_above: f64::NEG_INFINITY,
        max_below: f64::NEG_INFINITY,
    };
    for ((&g, &e), &k) in got.iter().zip(exact).zip(keep) {
        if !k {
            continue;
        }
        let d = (f64::from(g) - e) / ulp32(e);
        r.max_above = r.max_above.max(d);
        r.max_below = r.max_below.max(-d);
    }
    r
}

#[test]
fn division_stays_within_2_5_ulp_and_reaches_both_ends() {
    let (a, b) = pairs(&special_f32s());
    let n = a.len();
    let args = [Arg::column(&a), Arg::column(&b)];
    let normal = |x: f32| x != 0.0 && x.abs() >= f32::MIN_POSITIVE && x.abs() <= 2f32.powi(126);
    let exact: Vec<f64> = a
        .iter()
        .zip(&b)
        .map(|(&x, &y)| f64::from(x) / f64::from(y))
        .collect();
    // Normal operands and a normal, finite quotient: where no flush and no domain edge decides.
    let plain: Vec<bool> = a
        .iter()
        .zip(&b)
        .zip(&exact)
        .map(|((&x, &y), &e)| normal(x) && normal(y) && e.abs() >= 1e-37 && e.abs() <= 1e38)
        .collect();
    for policy in ALL_POLICIES {
        let (got, flags) = run("t_div", policy, Freedoms::ALL, &args, n);
        let got: Vec<f32> = got.iter().map(|&w| f32::from_bits(w)).collect();
        let mut checked = 0;
        for i in 0..n {
            let in_domain =
                normal(b[i]) || (b[i].abs() >= f32::MIN_POSITIVE && b[i].abs() <= 2f32.powi(126));
            if !in_domain {
                assert!(
                    flags[i],
                    "{policy}: {} / {} has a divisor outside ±[2^-126, 2^126] but was not flagged",
                    a[i], b[i]
                );
                continue;
            }
            if flags[i] {
                // Only an overflowing quotient may be flagged in the domain.
                assert_at_least!(
                    exact[i].abs(),
                    > f64::from(f32::MAX) * 0.99,
                    "comment above: only an overflowing quotient may be flagged",
                    "{policy}: {} / {} flagged",
                    a[i],
                    b[i]
                );
                continue;
            }
            let exacts: Vec<f64> = flushed(a[i])
                .into_iter()
                .map(|x| f64::from(x) / f64::from(b[i]))
                .collect();
            assert!(
                inside_k_ulp(got[i], &exacts, allowance::DIVISION_ULP),
                "{policy}: {} / {} = {} is outside the spec's {} ULP of {:?} (bound: WGSL `/` accuracy)",
                a[i],
                b[i],
                got[i],
                allowance::DIVISION_ULP,
                exacts
            );
            checked += 1;
        }
        assert!(
            checked > n / 2,
            "{policy}: only {checked} of {n} quotients were in the domain"
        );
        let r = reach(&got, &exact, &plain);
        eprintln!(
            "t_div {policy}: max {:.3} ULP above, {:.3} below the exact quotient",
            r.max_above, r.max_below
        );
        // Identity: the host's own quotient (correctly rounded on lavapipe); the other policies
        // place each quotient at an end of the interval from its exact residual.
        match policy {
            Policy::Identity => {
                let why = "HostAccuracy::division_ulp: the host's `/` correctly rounded";
                let wrong = "0.5 is wrong for this adapter";
                assert_within!(r.max_above, 0.5, why, "above the exact quotient; {wrong}");
                assert_within!(r.max_below, 0.5, why, "below the exact quotient; {wrong}");
            }
            Policy::Upper => {
                assert_at_least!(r.max_above, 2.0, PUSH, "upper: ULP above");
                assert_within!(
                    r.max_below,
                    0.0,
                    "upper never rounds down",
                    "upper: ULP below"
                );
            }
            Policy::Lower => {
                assert_at_least!(r.max_below, 2.0, PUSH, "lower: ULP below");
                assert_within!(
                    r.max_above,
                    0.0,
                    "lower never rounds up",
                    "lower: ULP above"
                );
            }
            Policy::Seeded(_) | Policy::Searched => {
                assert_at_least!(r.max_above, 2.0, PUSH, "seeded: ULP above");
                assert_at_least!(r.max_below, 2.0, PUSH, "seeded: ULP below");
            }
        }
    }
}

#[test]
fn rounding_of_add_sub_mul_is_either_neighbour_and_directed_at_the_ends() {
    let (a, b) = pairs(&special_f32s());
    let n = a.len();
    let args = [Arg::column(&a), Arg::column(&b)];
    for (f, op) in [("t_add", 0), ("t_sub", 1), ("t_mul", 2)] {
        let exact = |x: f32, y: f32| -> Option<f64> {
            let (x, y) = (f64::from(x), f64::from(y));
            let e = match op {
                0 => x + y,
                1 => x - y,
                _ => x * y,
            };
            // f64 holds the exact product always, the exact sum when exponents are close.
            let exact_in_f64 =
                op == 2 || (x == 0.0 || y == 0.0 || (x.abs().log2() - y.abs().log2()).abs() < 25.0);
            (exact_in_f64 && e.abs() <= f64::from(f32::MAX) && (e == 0.0 || e.abs() >= 1e-30))
                .then_some(e)
        };
        for policy in ALL_POLICIES {
            let (got, _) = run(f, policy, Freedoms::ALL, &args, n);
            let (mut up, mut down) = (0, 0);
            for i in 0..n {
                let Some(e) = exact(a[i], b[i]) else { continue };
                if a[i].abs() < f32::MIN_POSITIVE || b[i].abs() < f32::MIN_POSITIVE {
                    continue; // flushing decides there; see the flush test
                }
                let g = f32::from_bits(got[i]);
                let (lo, hi) = f32_around(e);
                assert!(
                    g == lo || g == hi,
                    "{policy}: {f}({}, {}) = {g} is neither neighbour {lo} / {hi} of the exact {e}",
                    a[i],
                    b[i]
                );
                let dekker_ok = op != 2
                    || (a[i].abs() < 2f32.powi(60)
                        && b[i].abs() < 2f32.powi(60)
                        && (e.abs() > 2f64.powi(-100)));
                if lo != hi && dekker_ok {
                    match policy {
                        Policy::Upper => {
                            assert_eq!(g, hi, "upper: {f}({}, {}) must round up", a[i], b[i])
                        }
                        Policy::Lower => {
                            assert_eq!(g, lo, "lower: {f}({}, {}) must round down", a[i], b[i])
                        }
                        _ => {}
                    }
                    if g == hi { up += 1 } else { down += 1 }
                }
            }
            eprintln!("{f} {policy}: rounded up {up}, down {down} of the inexact results");
            if let Policy::Seeded(_) = policy {
                assert!(
                    up > 0 && down > 0,
                    "{f} {policy}: the seeded policy rounds one way only"
                );
            }
        }
    }
}

#[test]
fn flush_to_zero_of_subnormal_inputs_and_outputs() {
    let sub = f32::from_bits(0x0000_0100);
    let a = [sub, -sub, sub, 2f32.powi(-100)];
    let b = [0.0f32, 0.0, 1.0, 2f32.powi(-30)];
    let args = [Arg::column(&a), Arg::column(&b)];
    let (upper, _) = run("t_add", Policy::Upper, Freedoms::FLUSH, &args, 4);
    let (lower, _) = run("t_add", Policy::Lower, Freedoms::FLUSH, &args, 4);
    let (ident, _) = run("t_add", Policy::Identity, Freedoms::ALL, &args, 4);
    let f = |w: &[u32]| w.iter().map(|&x| f32::from_bits(x)).collect::<Vec<_>>();
    let (upper, lower, ident) = (f(&upper), f(&lower), f(&ident));
    eprintln!("flush: identity {ident:?}, upper {upper:?}, lower {lower:?}");
    // sub + 0: kept (sub) or flushed (0); the upper policy keeps the larger, the lower the smaller.
    assert_eq!(ident[0], sub);
    assert_eq!(upper[0], sub);
    assert_eq!(lower[0], 0.0);
    assert_eq!(upper[1], 0.0);
    assert_eq!(lower[1], -sub);
    // 2^-100 · 2^-30 is subnormal: its product would be flushed by t_mul; here the sum is normal.
    assert_eq!(upper[3], ident[3]);
    let (m_up, _) = run("t_mul", Policy::Upper, Freedoms::FLUSH, &args, 4);
    let (m_lo, _) = run("t_mul", Policy::Lower, Freedoms::FLUSH, &args, 4);
    assert_eq!(
        f32::from_bits(m_up[3]),
        2f32.powi(-130),
        "upper keeps the subnormal product"
    );
    assert_eq!(
        f32::from_bits(m_lo[3]),
        0.0,
        "lower flushes the subnormal product"
    );
}

#[test]
fn fusion_and_reassociation_reach_their_alternatives() {
    // a·b + c with a·b = 1 + 2^-11 + 2^-24 (a tie, rounded to even: 1 + 2^-11) and c = -1:
    // unfused gives 2^-11, fused keeps the 2^-24 term (2^-11 + 2^-24 is a float).
    let a = [1.0 + 2f32.powi(-12)];
    let b = [1.0 + 2f32.powi(-12)];
    let c = [-1.0f32];
    let args = [Arg::column(&a), Arg::column(&b), Arg::column(&c)];
    let exact = (1.0 + 2f64.powi(-12)).powi(2) - 1.0;
    let (fused_up, _) = run("t_mad", Policy::Upper, Freedoms::FUSION, &args, 1);
    let (fused_lo, _) = run("t_mad", Policy::Lower, Freedoms::FUSION, &args, 1);
    let (ident, _) = run("t_mad", Policy::Identity, Freedoms::ALL, &args, 1);
    let (up, lo, id) = (
        f32::from_bits(fused_up[0]),
        f32::from_bits(fused_lo[0]),
        f32::from_bits(ident[0]),
    );
    eprintln!("a·b + c: exact {exact:e}, identity {id:e}, upper {up:e}, lower {lo:e}");
    assert_within_abs!(
        f64::from(up),
        exact,
        ulp32(exact),
        "fused a·b + c: one rounding of the exact value",
        "upper policy, fusion only"
    );
    assert_eq!(lo, id, "the lower policy keeps the smaller, unfused result");
    assert!(
        up > id,
        "the upper policy takes the fused result, larger here"
    );
    // (a + b) + c with a = 1, b = c = 2^-24: left to right rounds to 1 twice; a + (b + c) = 1 + 2^-23.
    let a = [1.0f32];
    let b = [2f32.powi(-24)];
    let args = [Arg::column(&a), Arg::column(&b), Arg::column(&b)];
    let (r_up, _) = run("t_add3", Policy::Upper, Freedoms::REASSOCIATION, &args, 1);
    let (r_lo, _) = run("t_add3", Policy::Lower, Freedoms::REASSOCIATION, &args, 1);
    assert_eq!(
        f32::from_bits(r_up[0]),
        1.0 + 2f32.powi(-23),
        "upper takes a + (b + c)"
    );
    assert_eq!(f32::from_bits(r_lo[0]), 1.0, "lower takes (a + b) + c");
}

/// A product a helper returns, fused into its caller's sum or difference, as a compiler may
/// after inlining: with fusion the only freedom, the two policies' results must be exactly the
/// fused and the unfused value (in either order), for each form (the helper's result on the
/// left or right of `+`, either side of `−`, and through a second helper). The identity
/// gives the unfused value only, and so did the emulation before it inlined sums.
#[test]
fn fusion_reaches_products_returned_by_helpers() {
    // a·b = 1 + 2^-11 + 2^-24, a tie that rounds to even (1 + 2^-11); with c = ∓1 the fused
    // result keeps the 2^-24 term, the unfused one does not.
    let a = [1.0 + 2f32.powi(-12)];
    let (p, q) = (2f32.powi(-11), 2f32.powi(-11) + 2f32.powi(-24));
    let cases = [
        ("t_mad_helper", -1.0f32, (p, q)),
        ("t_mad_helper_right", -1.0, (p, q)),
        ("t_msub_helper", 1.0, (p, q)),
        ("t_nmad_helper", 1.0, (-p, -q)),
        ("t_mad_helper_nested", -1.0, (p, q)),
    ];
    for (f, c, (unfused, fused)) in cases {
        let c = [c];
        let args = [Arg::column(&a), Arg::column(&a), Arg::column(&c)];
        let (up, _) = run(f, Policy::Upper, Freedoms::FUSION, &args, 1);
        let (lo, _) = run(f, Policy::Lower, Freedoms::FUSION, &args, 1);
        let (id, _) = run(f, Policy::Identity, Freedoms::ALL, &args, 1);
        let (up, lo, id) = (
            f32::from_bits(up[0]),
            f32::from_bits(lo[0]),
            f32::from_bits(id[0]),
        );
        let want = (unfused.max(fused), unfused.min(fused));
        assert_eq!(
            (up, lo),
            want,
            "{f}: upper/lower gave ({up:e}, {lo:e}); fused {fused:e} and unfused {unfused:e} \
             must be the two ends (a product returned by a helper may fuse into the caller's sum)"
        );
        assert_eq!(id, unfused, "{f}: the identity computes the unfused value");
    }
}

/// Every grouping the spec's reassociation allows for three terms (and for `dot`'s lanes),
/// reached: with reassociation the only freedom, every other operation rounds to nearest as the
/// host (and this f32 arithmetic) does, so the upper policy must return the largest of the
/// groupings' results and the lower the smallest, at every input. Each grouping must be the
/// only one to reach that end at some input, so an emulation missing one fails, and so does
/// the identity (only the written grouping).
#[test]
fn reassociation_reaches_every_grouping() {
    type Groupings = fn(f32, f32, f32) -> Vec<f32>;
    let cases: [(&str, Freedoms, Groupings); 6] = [
        ("t_add3", Freedoms::REASSOCIATION, |a, b, c| {
            vec![(a + b) + c, a + (b + c), (a + c) + b]
        }),
        ("t_sub_add", Freedoms::REASSOCIATION, |a, b, c| {
            vec![(a - b) + c, (a + c) - b, a - (b - c)]
        }),
        ("t_add_sub", Freedoms::REASSOCIATION, |a, b, c| {
            vec![(a + b) - c, a + (b - c), (a - c) + b]
        }),
        ("t_mul_div", Freedoms::REASSOCIATION, |a, b, c| {
            vec![(a * b) / c, (a / c) * b, a * (b / c)]
        }),
        // dot as its defining sum (inherited). Its products are exact here (each term times
        // 1): what is tested is the order of the sum. With rounded products lavapipe returned,
        // at some inputs, another grouping's sum than the one the wrapper wrote (its compiler
        // may regroup float adds, as WGSL allows), so the test would measure the host's order.
        (
            "t_dot3",
            Freedoms::REASSOCIATION.union(Freedoms::INHERITED),
            |a, b, c| vec![(a + b) + c, a + (b + c), (a + c) + b],
        ),
        (
            "t_dot4",
            Freedoms::REASSOCIATION.union(Freedoms::INHERITED),
            |a, b, c| {
                let d = -0.5 * b;
                vec![((a + b) + c) + d, a + (b + (c + d)), (a + b) + (c + d)]
            },
        ),
    ];
    // Magnitudes spread over 2^±12 of either sign, so sums cancel and groupings differ.
    let mut next = xorshift64(0x9e37_79b9_7f4a_7c15);
    let mut draw = || {
        let s = next();
        let m = 1.0 + (s >> 40) as f32 / (1u64 << 24) as f32;
        let e = ((s >> 8) % 25) as i32 - 12;
        let sign = if s & 1 == 1 { -1.0 } else { 1.0 };
        sign * m * 2f32.powi(e)
    };
    let n = 4096;
    let v: Vec<[f32; 3]> = (0..n).map(|_| [draw(), draw(), draw()]).collect();
    let col = |k: usize| v.iter().map(|x| x[k]).collect::<Vec<f32>>();
    let (xs, ys, zs) = (col(0), col(1), col(2));
    let args = [Arg::column(&xs), Arg::column(&ys), Arg::column(&zs)];
    for (f, freedoms, groupings) in cases {
        let (up, _) = run(f, Policy::Upper, freedoms, &args, n);
        let (lo, _) = run(f, Policy::Lower, freedoms, &args, n);
        let mut only = [[0usize; 3]; 2];
        for i in 0..n {
            let g = groupings(xs[i], ys[i], zs[i]);
            let (max, min) = (
                g.iter().copied().fold(f32::MIN, f32::max),
                g.iter().copied().fold(f32::MAX, f32::min),
            );
            let (u, l) = (f32::from_bits(up[i]), f32::from_bits(lo[i]));
            assert_eq!(
                u.to_bits(),
                max.to_bits(),
                "{f}({}, {}, {}): upper gave {u:e}, the largest grouping is {max:e} (groupings {g:?})",
                xs[i],
                ys[i],
                zs[i]
            );
            assert_eq!(
                l.to_bits(),
                min.to_bits(),
                "{f}({}, {}, {}): lower gave {l:e}, the smallest grouping is {min:e} (groupings {g:?})",
                xs[i],
                ys[i],
                zs[i]
            );
            for (end, v) in [(0, max), (1, min)] {
                let reach: Vec<usize> = (0..3).filter(|&k| g[k] == v).collect();
                if let [k] = reach[..] {
                    only[end][k] += 1;
                }
            }
        }
        eprintln!(
            "{f}: inputs where grouping k alone is the max {:?}, the min {:?}",
            only[0], only[1]
        );
        for (k, (at_max, at_min)) in only[0].iter().zip(only[1]).enumerate() {
            assert!(
                at_max + at_min > 0,
                "{f}: grouping {k} is never the only one at an end over {n} inputs: the test \
                 would not see it missing"
            );
        }
    }
}

/// Matrix × matrix is emulated as the dot products that define each element: with rounding the
/// only freedom (and inheritance, so the dots are expanded), the upper policy's every element is
/// at or above the exact value and the lower's at or below, and both leave the host's
/// round-to-nearest result at some inputs (so the identity, or a product left at the host's
/// accuracy, fails).
#[test]
fn matrix_products_round_each_way() {
    let n = 2048;
    let mut next = xorshift64(0x2545_f491_4f6c_dd1d);
    let mut draw = || {
        let s = next();
        (1.0 + (s >> 41) as f32 / (1u64 << 23) as f32) * if s & 1 == 1 { -1.0 } else { 1.0 }
    };
    let v: Vec<[f32; 3]> = (0..n).map(|_| [draw(), draw(), draw()]).collect();
    let col = |k: usize| v.iter().map(|x| x[k]).collect::<Vec<f32>>();
    let (xs, ys, zs) = (col(0), col(1), col(2));
    let args = [Arg::column(&xs), Arg::column(&ys), Arg::column(&zs)];
    let fr = Freedoms::ROUNDING.union(Freedoms::INHERITED);
    let (up, _) = run("t_matmat", Policy::Upper, fr, &args, n);
    let (lo, _) = run("t_matmat", Policy::Lower, fr, &args, n);
    let (id, _) = run("t_matmat", Policy::Identity, fr, &args, n);
    let (mut up_moved, mut lo_moved) = (0, 0);
    for i in 0..n {
        let [a, b, c] = v[i].map(f64::from);
        // Columns: A = [(a, b), (c, a)], B = [(b, c), (a, b)]; (A·B)[j] = B[j].x·A[0] + B[j].y·A[1].
        let exact = [b * a + c * c, b * b + c * a, a * a + b * c, a * b + b * a];
        for k in 0..4 {
            let (u, l, h) = (
                f64::from(f32::from_bits(up[4 * i + k])),
                f64::from(f32::from_bits(lo[4 * i + k])),
                f32::from_bits(id[4 * i + k]),
            );
            // The exact value in f64 is a sum of two exact products: within 2^-52 of it.
            let slack = exact[k].abs() * 2f64.powi(-52);
            assert!(
                u >= exact[k] - slack && l <= exact[k] + slack,
                "element {k} at ({a}, {b}, {c}): upper {u:e} and lower {l:e} do not bracket the exact {:e}",
                exact[k]
            );
            up_moved += usize::from(u != f64::from(h));
            lo_moved += usize::from(l != f64::from(h));
        }
    }
    eprintln!(
        "matrix × matrix: upper left the host's result in {up_moved}, lower in {lo_moved} of {} elements",
        4 * n
    );
    assert!(
        up_moved > 0 && lo_moved > 0,
        "the policies never moved a matrix product's element: not emulated"
    );
}

#[test]
fn inverse_sqrt_sqrt_and_length_stay_inside_their_intervals() {
    let xs: Vec<f32> = special_f32s().into_iter().filter(|x| *x > 0.0).collect();
    let n = xs.len();
    let args = [Arg::column(&xs)];
    for policy in ALL_POLICIES {
        let (got, flags) = run("t_inverse_sqrt", policy, Freedoms::ALL, &args, n);
        let got: Vec<f32> = got.iter().map(|&w| f32::from_bits(w)).collect();
        let exact: Vec<f64> = xs.iter().map(|&x| 1.0 / f64::from(x).sqrt()).collect();
        let normal: Vec<bool> = xs.iter().map(|&x| x >= f32::MIN_POSITIVE).collect();
        for i in 0..n {
            if !normal[i] {
                assert!(flags[i], "inverseSqrt of subnormal {} not flagged", xs[i]);
                continue;
            }
            assert!(
                inside_k_ulp(got[i], &[exact[i]], allowance::INVERSE_SQRT_ULP),
                "{policy}: inverseSqrt({}) = {} outside {} ULP of {}",
                xs[i],
                got[i],
                allowance::INVERSE_SQRT_ULP,
                exact[i]
            );
        }
        let r = reach(&got, &exact, &normal);
        eprintln!(
            "t_inverse_sqrt {policy}: max {:.3} ULP above, {:.3} below",
            r.max_above, r.max_below
        );
        if policy == Policy::Upper {
            assert_at_least!(
                r.max_above,
                0.5,
                "the upper policy pushes inverseSqrt above the exact value",
                "upper never reached above the exact value"
            );
        }
        // sqrt = 1 / inverseSqrt: the spec's interval is the quotient's 2.5 ULP around the
        // inverseSqrt interval, i.e. within (2.5 + 2·(1 + …)) ULP of sqrt(x); bound it by
        // composing the two relative errors: (1 + 2u)/(1 − 2u)·(1 + 2.5u) − 1 ≤ 6.5 u (u = 2^-24
        // relative, ULP ≥ u·|x|·… ): at most 2·(2 + 2.5) = 9 ULP with the binade factor.
        let (got_s, _) = run("t_sqrt", policy, Freedoms::ALL, &args, n);
        for i in 0..n {
            if !normal[i] {
                continue;
            }
            let g = f32::from_bits(got_s[i]);
            let e = f64::from(xs[i]).sqrt();
            assert!(
                inside_k_ulp(
                    g,
                    &[e],
                    2.0 * (allowance::INVERSE_SQRT_ULP + allowance::DIVISION_ULP)
                ),
                "{policy}: sqrt({}) = {g} outside the inherited interval around {e}",
                xs[i]
            );
        }
    }
}

/// `sin` and `cos`: every emulated result lies within the spec's absolute 2^-11 of the exact
/// value on `[−π, π]`; the upper and lower policies reach that end less the host's error and
/// the push's rounding (so the check fails if the push is dropped: under the identity a result
/// is the host's, within `HOST_TRIG_ABS`); the host's own error is what `HOST_TRIG_ABS`
/// assumes; and an argument beyond `[−π, π]`, where the spec states no accuracy, raises the
/// indeterminate flag.
#[test]
fn sin_and_cos_reach_their_absolute_allowance_and_flag_beyond_pi() {
    use prepass::conforming::HOST_TRIG_ABS;
    let d = allowance::TRIG_DOMAIN;
    let xs: Vec<f32> = (0..=4000)
        .map(|i| -d + i as f32 * (2.0 * d / 4000.0))
        .chain([0.0, d, -d, 1e-3, -1e-30])
        .collect();
    let beyond = [
        std::f32::consts::PI,
        -std::f32::consts::PI,
        4.0,
        -100.0,
        1e6,
    ];
    let n = xs.len();
    // The push is the allowance less HOST_TRIG_ABS and 2^-24; the result then errs by the host's
    // own error (≤ HOST_TRIG_ABS) and the push's rounding (≤ 2^-25) at most.
    let reach = allowance::TRIG_ABS - 2.0 * HOST_TRIG_ABS - 2f64.powi(-23);
    for (f, exact) in [("t_sin", f64::sin as fn(f64) -> f64), ("t_cos", f64::cos)] {
        for policy in ALL_POLICIES {
            let (got, flags) = run(f, policy, Freedoms::ALL, &[Arg::column(&xs)], n);
            let mut host_max = 0.0f64;
            for i in 0..n {
                assert!(!flags[i], "{policy}: {f}({}) flagged inside [−π, π]", xs[i]);
                let err = f64::from(f32::from_bits(got[i])) - exact(f64::from(xs[i]));
                assert_within_abs!(
                    err,
                    0.0,
                    allowance::TRIG_ABS,
                    "conforming::allowance::TRIG_ABS: WGSL's 2^-11 for sin and cos on [−π, π]",
                    "{policy}: {f}({})",
                    xs[i]
                );
                match policy {
                    Policy::Upper => assert_at_least!(
                        err,
                        reach,
                        "the push, TRIG_ABS − HOST_TRIG_ABS − 2^-24, less the host's error and the push's rounding",
                        "upper: {f}({}) − exact",
                        xs[i]
                    ),
                    Policy::Lower => assert_at_least!(
                        -err,
                        reach,
                        "the push, TRIG_ABS − HOST_TRIG_ABS − 2^-24, less the host's error and the push's rounding",
                        "lower: exact − {f}({})",
                        xs[i]
                    ),
                    _ => {}
                }
                host_max = host_max.max(err.abs());
            }
            if policy == Policy::Identity {
                eprintln!("host {f}: max {host_max:.3e} absolute on [−π, π]");
                assert_within!(
                    host_max,
                    HOST_TRIG_ABS,
                    "conforming::HOST_TRIG_ABS (lavapipe's sin and cos)",
                    "the host's {f}, absolute"
                );
            }
            let (_, flags) = run(
                f,
                policy,
                Freedoms::ALL,
                &[Arg::column(&beyond)],
                beyond.len(),
            );
            for (x, flagged) in beyond.iter().zip(flags) {
                assert!(flagged, "{policy}: {f}({x}) beyond [−π, π] is not flagged");
            }
        }
    }
}

/// `u32(x)` and `i32(x)` of an f32 are exact (truncated toward zero, then clamped to the values
/// both types represent: `[0, 2^32 − 256]`, `[−2^31, 2^31 − 128]`, WGSL "Conversion of a
/// floating point value to an integer"), so
/// the emulation takes no freedom there; a ±∞ or NaN operand is outside the spec's domain and
/// raises the flag under every policy (the bad-input suite relies on it), a finite one never.
#[test]
fn float_to_integer_conversions_flag_only_non_finite_operands() {
    let finite = [
        0.0f32,
        -0.0,
        1.5,
        -1.5,
        2.5,
        255.49,
        4294967040.0,
        5e9,
        -5e9,
        2147483520.0,
        1e-40,
        -1e-40,
        3e38,
        -3e38,
    ];
    let bad = [f32::INFINITY, f32::NEG_INFINITY, f32::NAN, -f32::NAN];
    for policy in ALL_POLICIES {
        let (got, flags) = run(
            "t_u32_of",
            policy,
            Freedoms::ALL,
            &[Arg::column(&finite)],
            finite.len(),
        );
        for ((x, w), flagged) in finite.iter().zip(&got).zip(&flags) {
            assert!(!flagged, "{policy}: u32({x:e}) flagged");
            assert_eq!(*w, x.min(4294967040.0) as u32, "{policy}: u32({x:e})");
        }
        let pairs: Vec<f32> = finite.iter().flat_map(|&x| [x, -x]).collect();
        let (got, flags) = run(
            "t_i32_of",
            policy,
            Freedoms::ALL,
            &[Arg::column(&pairs)],
            finite.len(),
        );
        for (i, flagged) in flags.iter().enumerate() {
            let (x, y) = (pairs[2 * i], pairs[2 * i + 1]);
            assert!(!flagged, "{policy}: vec2<i32>({x:e}, {y:e}) flagged");
            assert_eq!(
                [got[2 * i] as i32, got[2 * i + 1] as i32],
                [x, y].map(|v| v.clamp(-2147483648.0, 2147483520.0) as i32),
                "{policy}: vec2<i32>({x:e}, {y:e})"
            );
        }
        let (_, flags) = run(
            "t_u32_of",
            policy,
            Freedoms::ALL,
            &[Arg::column(&bad)],
            bad.len(),
        );
        for (x, flagged) in bad.iter().zip(flags) {
            assert!(flagged, "{policy}: u32({x}) is not flagged");
        }
        // One bad lane of two is enough.
        let mixed: Vec<f32> = bad.iter().flat_map(|&x| [1.0, x]).collect();
        let (_, flags) = run(
            "t_i32_of",
            policy,
            Freedoms::ALL,
            &[Arg::column(&mixed)],
            bad.len(),
        );
        for (x, flagged) in bad.iter().zip(flags) {
            assert!(flagged, "{policy}: vec2<i32>(1, {x}) is not flagged");
        }
    }
}

/// `min`, `max`, `clamp`, `abs`, `floor` and `<` are exact, so no arithmetic helper sees them;
/// a ±∞ or NaN operand of theirs still leaves the spec's domain, and raises bit 2 of the flag
/// word (`EmulatedKernel::run_flags`) under every policy, in either operand; finite operands
/// (subnormals, ±0, ±f32::MAX included) never raise a flag.
#[test]
fn exact_operations_flag_non_finite_operands_with_bit_2() {
    let finite = [0.0f32, -0.0, 1.5, -2.5, 1e-40, -1e-40, f32::MAX, -f32::MAX];
    let bad = [f32::INFINITY, f32::NEG_INFINITY, f32::NAN, -f32::NAN];
    // Two operands: each bad value first, then second, beside a finite one; every finite pair.
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for &x in &bad {
        a.extend([x, 1.0]);
        b.extend([1.0, x]);
    }
    let (fa, fb): (Vec<f32>, Vec<f32>) = finite
        .iter()
        .flat_map(|&x| finite.iter().map(move |&y| (x, y)))
        .unzip();
    // (function, operands with a non-finite value, finite operands): two-operand functions take
    // the pairs above, one-operand ones the values themselves.
    let two = |f| {
        let bad_args = vec![Arg::column(&a), Arg::column(&b)];
        (f, bad_args, vec![Arg::column(&fa), Arg::column(&fb)])
    };
    let one = |f| (f, vec![Arg::column(&bad)], vec![Arg::column(&finite)]);
    let cases = [
        two("t_min"),
        two("t_max"),
        two("t_clamp"),
        two("t_lt"),
        one("t_abs"),
        one("t_floor"),
    ];
    for policy in ALL_POLICIES {
        let emu = Emulation::new(policy);
        for (f, bad_args, finite_args) in &cases {
            let k = EmulatedKernel::new(gpu(), TESTS, f, &emu).unwrap_or_else(|e| panic!("{e}"));
            let n = |args: &[Arg<'_>]| match args[0] {
                Arg::Column(bytes) => bytes.len() as u64 / 4,
                _ => unreachable!(),
            };
            let (_, words) = k.run_flags(bad_args, n(bad_args)).unwrap();
            for (i, w) in words.iter().enumerate() {
                assert!(
                    w & 2 != 0,
                    "{policy}: {f}, bad case {i} (operands from {bad:?}) raised flag word {w:#x}, not bit 2"
                );
            }
            let (_, words) = k.run_flags(finite_args, n(finite_args)).unwrap();
            for (i, w) in words.iter().enumerate() {
                assert_eq!(
                    *w, 0,
                    "{policy}: {f}, finite case {i} (operands from {finite:?}) flagged"
                );
            }
        }
    }
}

#[test]
fn exp2_and_log2_stay_inside_their_intervals_and_the_host_exp2_is_as_assumed() {
    let xs: Vec<f32> = (0..4000)
        .map(|i| -100.0 + i as f32 * 0.05)
        .chain([0.0, 1.0, -1.0, 127.0])
        .collect();
    let n = xs.len();
    let host = HostAccuracy::default();
    for policy in ALL_POLICIES {
        let (got, flags) = run("t_exp2", policy, Freedoms::ALL, &[Arg::column(&xs)], n);
        let mut host_max = 0.0f64;
        for i in 0..n {
            if flags[i] {
                continue;
            }
            let e = f64::from(xs[i]).exp2();
            let g = f32::from_bits(got[i]);
            let k = allowance::exp_ulp(f64::from(xs[i]));
            assert!(
                inside_k_ulp(g, &[e], k),
                "{policy}: exp2({}) = {g} outside {k} ULP of {e}",
                xs[i]
            );
            host_max = host_max.max((f64::from(g) - e).abs() / ulp32(e));
        }
        if policy == Policy::Identity {
            eprintln!("host exp2: max {host_max:.3} ULP");
            assert_within!(
                host_max,
                host.exp_ulp,
                "HostAccuracy::exp_ulp (lavapipe's exp2)",
                "the host's exp2, ULP"
            );
        }
    }
    let ys: Vec<f32> = (1..6000)
        .map(|i| i as f32 * 0.001)
        .chain((1..200).map(|i| 2f32.powi(i - 100)))
        .collect();
    let n = ys.len();
    for policy in ALL_POLICIES {
        let (got, _) = run("t_log2", policy, Freedoms::ALL, &[Arg::column(&ys)], n);
        for i in 0..n {
            let e = f64::from(ys[i]).log2();
            let g = f64::from(f32::from_bits(got[i]));
            if (0.5..=2.0).contains(&ys[i]) {
                assert_within_abs!(
                    g,
                    e,
                    allowance::LOG_ABS,
                    "conforming::allowance::LOG_ABS: WGSL's 2^-21 for log2 on [0.5, 2]",
                    "{policy}: log2({})",
                    ys[i]
                );
            } else {
                assert!(
                    inside_k_ulp(g as f32, &[e], allowance::LOG_ULP),
                    "{policy}: log2({}) = {g} beyond 3 ULP of {e}",
                    ys[i]
                );
            }
        }
    }
}

#[test]
fn unpack_is_within_3_ulp_and_pack_ties_take_either_byte() {
    // Every byte in every lane.
    let codes: Vec<u32> = (0..256u32).map(|v| v * 0x0101_0101).collect();
    for (f, snorm) in [("t_unpack4x8unorm", false), ("t_unpack4x8snorm", true)] {
        for policy in ALL_POLICIES {
            let (got, _) = run(
                f,
                policy,
                Freedoms::ALL,
                &[Arg::column(&codes)],
                codes.len(),
            );
            let mut above = 0.0f64;
            for (i, lanes) in got.chunks(4).enumerate() {
                let v = i as i32;
                let exact = if snorm {
                    (f64::from((v as u8) as i8) / 127.0).max(-1.0)
                } else {
                    f64::from(v) / 255.0
                };
                for &w in lanes {
                    let g = f32::from_bits(w);
                    assert!(
                        inside_k_ulp(g, &[exact], allowance::UNPACK_ULP),
                        "{policy}: {f} of byte {v} = {g} beyond 3 ULP of {exact}"
                    );
                    if exact != 0.0 {
                        above = above.max((f64::from(g) - exact) / ulp32(exact));
                    }
                }
            }
            if policy == Policy::Upper {
                assert_at_least!(
                    above,
                    2.0,
                    "the upper policy places each lane at the last float inside UNPACK_ULP (3) of v/255, within one float spacing of 3 ULP above it",
                    "{f} upper: ULP above"
                );
            }
        }
    }
    // Lanes at and next to the .5 ties of 255·c.
    let mut lanes = Vec::new();
    for k in 0..255u32 {
        let t = (f64::from(k) + 0.5) / 255.0;
        let c = t as f32;
        for x in [c.next_down(), c, c.next_up()] {
            lanes.push([x, x, x, x]);
        }
    }
    let n = lanes.len();
    let mut differ = 0;
    let (up, _) = run(
        "t_pack4x8unorm",
        Policy::Upper,
        Freedoms::ALL,
        &[Arg::column(&lanes)],
        n,
    );
    let (lo, _) = run(
        "t_pack4x8unorm",
        Policy::Lower,
        Freedoms::ALL,
        &[Arg::column(&lanes)],
        n,
    );
    for i in 0..n {
        let c = lanes[i][0];
        let (p_lo, p_hi) = f32_around(255.0 * f64::from(c));
        let allowed = [
            (f64::from(p_lo) + 0.5).floor() as u32,
            (f64::from(p_hi) + 0.5).floor() as u32,
        ];
        for (name, w) in [("upper", up[i]), ("lower", lo[i])] {
            let byte = w & 0xff;
            assert!(
                allowed.contains(&byte),
                "{name}: pack4x8unorm({c}) byte {byte} not in {allowed:?}"
            );
        }
        assert_eq!(
            up[i] & 0xff,
            allowed[0].max(allowed[1]),
            "upper takes the larger byte at {c}"
        );
        assert_eq!(
            lo[i] & 0xff,
            allowed[0].min(allowed[1]),
            "lower takes the smaller byte at {c}"
        );
        if up[i] != lo[i] {
            differ += 1;
        }
    }
    eprintln!("pack4x8unorm: {differ} of {n} lanes near ties take either byte");
    assert!(
        differ > 0,
        "no tie was found: the test's inputs miss the .5 boundaries"
    );
}

#[test]
fn length_stays_inside_its_inherited_interval() {
    let vs: Vec<[f32; 3]> = (0..2000)
        .map(|i| {
            let t = i as f32 * 0.37;
            [t.sin() * 3.0, (t * 1.3).cos(), 0.5 + (t * 0.7).sin()]
        })
        .collect();
    let n = vs.len();
    for policy in ALL_POLICIES {
        let (got, _) = run("t_length", policy, Freedoms::ALL, &[Arg::column(&vs)], n);
        for i in 0..n {
            let v = vs[i].map(f64::from);
            let e = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            // dot: 3 products and 2 sums each within one rounding (2^-23 relative), any order:
            // relative ≤ 5·2^-23 on a sum of squares; sqrt halves it (2.5·2^-23) and adds the
            // inherited 1/inverseSqrt error (≤ 9 ULP, above): within 9 + 2·2.5 = 14 ULP.
            let g = f32::from_bits(got[i]);
            assert!(
                inside_k_ulp(g, &[e], 14.0),
                "{policy}: length({:?}) = {g}, exact {e}",
                vs[i]
            );
        }
    }
}

/// A wrapper of `f` the harness can run: each f32 matrix parameter taken as its columns, a
/// boolean parameter as the low bit of a u32, a boolean result returned as 0u / 1u:
/// `fn prepass_idw_f(...)`. `None` for other types.
fn matrix_wrapper(module: &naga::Module, f: &naga::Function) -> Option<String> {
    use naga::TypeInner as T;
    let name = f.name.as_deref()?;
    let scalar = |s: naga::Scalar| match (s.kind, s.width) {
        (naga::ScalarKind::Float, 4) => Some("f32"),
        (naga::ScalarKind::Uint, 4) => Some("u32"),
        (naga::ScalarKind::Sint, 4) => Some("i32"),
        _ => None,
    };
    let (mut params, mut call) = (Vec::new(), Vec::new());
    for (k, a) in f.arguments.iter().enumerate() {
        match module.types[a.ty].inner {
            T::Scalar(s) if s.kind == naga::ScalarKind::Bool => {
                // Fed as a u32 whose low bit is the boolean.
                params.push(format!("a{k}: u32"));
                call.push(format!("(a{k} & 1u) != 0u"));
            }
            T::Scalar(s) => {
                params.push(format!("a{k}: {}", scalar(s)?));
                call.push(format!("a{k}"));
            }
            T::Vector { size, scalar: s } => {
                params.push(format!("a{k}: vec{}<{}>", size as u8, scalar(s)?));
                call.push(format!("a{k}"));
            }
            T::Matrix { columns, rows, .. } => {
                let (c, r) = (columns as u8, rows as u8);
                let cols: Vec<String> = (0..c).map(|j| format!("a{k}c{j}")).collect();
                params.extend(cols.iter().map(|n| format!("{n}: vec{r}<f32>")));
                call.push(format!("mat{c}x{r}<f32>({})", cols.join(", ")));
            }
            _ => return None,
        }
    }
    let call = format!("{name}({})", call.join(", "));
    // Booleans come back as 0u / 1u lanes.
    let (ret, body) = match module.types[f.result.as_ref()?.ty].inner {
        T::Scalar(s) if s.kind == naga::ScalarKind::Bool => {
            ("u32".to_string(), format!("select(0u, 1u, {call})"))
        }
        T::Vector { size, scalar: s } if s.kind == naga::ScalarKind::Bool => {
            let n = size as u8;
            (
                format!("vec{n}<u32>"),
                format!("select(vec{n}<u32>(0u), vec{n}<u32>(1u), {call})"),
            )
        }
        T::Scalar(s) => (scalar(s)?.to_string(), call),
        T::Vector { size, scalar: s } => (format!("vec{}<{}>", size as u8, scalar(s)?), call),
        _ => return None,
    };
    Some(format!(
        "fn prepass_idw_{name}({}) -> {ret} {{ return {body}; }}",
        params.join(", ")
    ))
}

/// Random inputs for a harness parameter type.
fn column_for(ty: prepass::harness::ValueType, n: usize, seed: u64) -> Vec<u32> {
    let mut next = xorshift64(seed | 1);
    let specials = [0.0f32, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-3, 1e3];
    (0..n * ty.words())
        .map(|_| {
            let r = next();
            match ty.scalar {
                prepass::harness::Scalar::F32 => {
                    let x = if r.is_multiple_of(8) {
                        specials[(r >> 8) as usize % specials.len()]
                    } else {
                        ((r >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0) as f32
                    };
                    x.to_bits()
                }
                _ => {
                    if r.is_multiple_of(4) {
                        (r >> 40) as u32 & 0xff
                    } else {
                        (r >> 32) as u32
                    }
                }
            }
        })
        .collect()
}

/// One [`column_for`] per parameter of `sig`, parameter k drawn from `seed ^ (k + 1)·0x1000_0001`.
/// Input `i` of `columns_for`'s columns as interval-evaluator arguments.
fn interval_args(
    sig: &Signature,
    cols: &[Vec<u32>],
    i: usize,
) -> Vec<prepass::conforming::interval::Value> {
    use prepass::conforming::interval::Value;
    use prepass::harness::Scalar;
    sig.params
        .iter()
        .zip(cols)
        .map(|(p, c)| {
            let l = usize::from(p.ty.lanes);
            let w = &c[i * l..(i + 1) * l];
            match p.ty.scalar {
                Scalar::F32 => {
                    Value::f32s(&w.iter().map(|&b| f32::from_bits(b)).collect::<Vec<_>>())
                }
                Scalar::U32 => Value::u32s(w),
                Scalar::I32 => Value::I32(w.iter().map(|&b| (b as i32, b as i32)).collect()),
            }
        })
        .collect()
}

/// Whether result words lie in an enclosure, lane by lane.
fn inside(e: &prepass::conforming::interval::Value, words: &[u32]) -> bool {
    use prepass::conforming::interval::Value;
    match e {
        Value::F32 { lanes, .. } => lanes.iter().zip(words).all(|(iv, &b)| {
            let x = f32::from_bits(b);
            iv.lo <= x && x <= iv.hi
        }),
        Value::U32(l) => l
            .iter()
            .zip(words)
            .all(|(&(lo, hi), &b)| lo <= b && b <= hi),
        Value::I32(l) => l
            .iter()
            .zip(words)
            .all(|(&(lo, hi), &b)| lo <= b as i32 && b as i32 <= hi),
        _ => false,
    }
}

fn columns_for(sig: &Signature, n: usize, seed: u64) -> Vec<Vec<u32>> {
    sig.params
        .iter()
        .enumerate()
        .map(|(k, p)| column_for(p.ty, n, seed ^ ((k as u64 + 1) * 0x1000_0001)))
        .collect()
}

#[test]
fn identity_reproduces_every_shipped_module_bit_for_bit() {
    let n = 4096;
    let mut functions = 0;
    for (k, file) in prepass::wgsl::FILES.iter().enumerate() {
        common::progress(
            "identity_reproduces_every_shipped_module_bit_for_bit: shipped files",
            k,
            prepass::wgsl::FILES.len(),
        );
        let checked = prepass::wgsl::parse_and_validate(file.source).unwrap();
        for (_, f) in checked.module.functions.iter() {
            let Some(name) = f.name.as_deref() else {
                continue;
            };
            // A function with matrix or boolean parameters or a boolean result runs through a wrapper.
            let (source, name) = match Signature::read(file.source, name) {
                Ok(_) => (file.source.to_string(), name.to_string()),
                Err(_) => match matrix_wrapper(&checked.module, f) {
                    Some(w) => (
                        format!("{}\n{w}", file.source),
                        format!("prepass_idw_{name}"),
                    ),
                    None => panic!("{}: cannot run `{name}` (parameter types)", file.name),
                },
            };
            let (source, name) = (source.as_str(), name.as_str());
            let sig = Signature::read(source, name).unwrap();
            let cols = columns_for(&sig, n, 0x9e37_79b9);
            let args: Vec<Arg<'_>> = cols.iter().map(|c| Arg::column(c)).collect();
            let original = run_kernel(source, name, &args, n as u64);
            let k = EmulatedKernel::new(gpu(), source, name, &Emulation::new(Policy::Identity))
                .unwrap_or_else(|e| panic!("{}: {name}: {e}", file.name));
            let (identity, outside) = k.run(&args, n as u64).unwrap();
            // Where an evaluation left the spec's domain (a ±Inf or NaN produced or operated
            // on), WGSL defines no result, and the two modules, compiled apart, may differ
            // there: those elements are not compared (a vouched encoder outside its contract
            // met this). The rest must be identical, and most elements must be compared.
            let per = original.words().len() / n;
            let (a, b) = (original.words(), identity.words());
            let differ = (0..n)
                .filter(|&e| !outside[e] && a[e * per..(e + 1) * per] != b[e * per..(e + 1) * per])
                .count();
            let skipped = outside.iter().filter(|&&o| o).count();
            assert_eq!(
                differ, 0,
                "{}: `{name}` under the identity policy differs from the original at {differ} \
                 elements inside the spec's domain",
                file.name
            );
            assert!(
                skipped < n / 2,
                "{}: `{name}`: {skipped} of {n} random inputs leave the spec's domain, too many \
                 for the comparison to mean anything",
                file.name
            );
            functions += 1;
        }
    }
    eprintln!("identity policy: {functions} shipped functions bit-identical on {n} inputs each");
    assert!(
        functions >= 60,
        "only {functions} shipped functions were checked"
    );
}

/// Every [`prepass::conforming::EXACT_FUNCTIONS`] entry is exact on its domain: emulated like
/// any other function (`Emulation::with_exact_functions_emulated`) under the upper, lower and
/// seeded policies, it returns the host's result, compared as values (WGSL lets an
/// implementation ignore the sign of a zero). Domain: the lattices' whole-number codes — every
/// 8-bit code; at 12 and 16 bits every code with a coordinate at an end of the range or beside
/// the middle (where the fold and the zero components are) and the other over every value, and
/// 2^16 seeded codes. The argument for exactness (every value an integer below 2^24) does not
/// depend on the code, so these codes check it where the values are largest and zero.
#[test]
fn exact_functions_are_exact_on_their_domain() {
    use prepass::conforming::EXACT_FUNCTIONS;
    use prepass::wgsl::{NORMAL_HEMIOCT, NORMAL_OCT, NORMAL_SIGNED_OCT};
    let codes = |bits: u32| -> Vec<[f32; 2]> {
        let m = (1u32 << bits) - 1;
        let mut v: Vec<[u32; 2]> = Vec::new();
        if bits == 8 {
            v.extend((0..=m).flat_map(|u| (0..=m).map(move |w| [u, w])));
        } else {
            for e in [0, 1, m / 2 - 1, m / 2, m / 2 + 1, m / 2 + 2, m - 1, m] {
                v.extend((0..=m).flat_map(|o| [[e, o], [o, e]]));
            }
            let mut x = 0x21u32 + bits;
            for _ in 0..1 << 16 {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                v.push([(x & 0xffff) % (m + 1), (x >> 16) % (m + 1)]);
            }
        }
        v.into_iter().map(|c| c.map(|k| k as f32)).collect()
    };
    let mut checked = Vec::new();
    for (source, function, bits) in [
        (NORMAL_OCT, "oct_lattice", 8u32),
        (NORMAL_OCT, "oct_lattice", 12),
        (NORMAL_OCT, "oct_lattice", 16),
        (NORMAL_HEMIOCT, "hemioct_lattice", 12),
        (NORMAL_SIGNED_OCT, "signed_oct_lattice", 10),
    ] {
        let c = codes(bits);
        let mf = ((1u32 << bits) - 1) as f32;
        let (m, mm) = (vec![mf; c.len()], vec![[mf; 2]; c.len()]);
        let args = if function == "oct_lattice" {
            vec![Arg::column(&c), Arg::column(&m), Arg::column(&mm)]
        } else {
            vec![Arg::column(&c)]
        };
        let host = run_kernel(source, function, &args, c.len() as u64);
        for policy in [Policy::Upper, Policy::Lower, Policy::Seeded(1)] {
            let emulation = Emulation::new(policy).with_exact_functions_emulated();
            let k = EmulatedKernel::new(gpu(), source, function, &emulation).unwrap();
            let (out, _) = k.run(&args, c.len() as u64).unwrap();
            let differ: Vec<usize> = (0..c.len())
                .filter(|&i| out.as_vec3()[i] != host.as_vec3()[i])
                .collect();
            assert!(
                differ.is_empty(),
                "{function} at {bits} bits, {policy}: {} of {} codes differ from the host under \
                 emulation, first {:?}: {:?} against {:?}; it is listed in EXACT_FUNCTIONS as \
                 exact on its domain",
                differ.len(),
                c.len(),
                differ.first().map(|&i| c[i]),
                differ.first().map(|&i| out.as_vec3()[i]),
                differ.first().map(|&i| host.as_vec3()[i]),
            );
        }
        eprintln!(
            "{function} at {bits} bits: {} codes exact under upper, lower and seeded",
            c.len()
        );
        checked.push(function);
    }
    for (f, _) in EXACT_FUNCTIONS {
        assert!(
            checked.contains(f),
            "EXACT_FUNCTIONS lists {f}, which this test does not check"
        );
    }
}

/// `encode_normal_oct32_fast` (`oct_encode_round(n, 16u)`) with every operation at the end
/// `up` says, from exact arithmetic: sums and products of f32 values are exact in f64 here
/// (inputs of one magnitude range), each then rounded to the neighbouring f32 in the policy's
/// direction; the division is the correctly rounded quotient pushed 2 ULP (`core.wgsl`'s
/// `prepass_cf_push` with `PREPASS_CF_DIV_HALVES` 4, ported); a three-term sum takes the
/// largest (smallest) of its three orders; `p·0.5 + 0.5` is exact before its rounding. `None`
/// for inputs this port does not cover (NaN, infinite or subnormal lanes, the zero vector).
fn oct32_round_at_end(n: [f32; 3], up: bool) -> Option<u32> {
    let dir = |x: f64| -> f32 {
        let f = x as f32;
        match f64::from(f).partial_cmp(&x) {
            Some(std::cmp::Ordering::Less) if up => f.next_up(),
            Some(std::cmp::Ordering::Greater) if !up => f.next_down(),
            _ => f,
        }
    };
    let m = n.iter().fold(0.0f32, |m, x| m.max(x.abs()));
    if m == 0.0 || n.iter().any(|x| !x.is_normal() && *x != 0.0) {
        return None;
    }
    let e = (m.to_bits() >> 23) & 0xff;
    let scale = f32::from_bits((254 - e).max(1) << 23);
    let s = n.map(|x| x * scale);
    let a = s.map(|x| f64::from(x.abs()));
    let sum = |x: f64, y: f64| f64::from(dir(x + y));
    let orders = [
        sum(sum(a[0], a[1]), a[2]),
        sum(a[0], sum(a[1], a[2])),
        sum(sum(a[0], a[2]), a[1]),
    ];
    let l1 = orders
        .into_iter()
        .reduce(|x, y| if up { x.max(y) } else { x.min(y) })?;
    // prepass_cf_push(q, ±4): float by float while the spent quarters of the spacing below q
    // stay within 8.
    let push = |q: f32| -> f32 {
        let below = |x: f32| (((x.to_bits() & 0x7fff_ffff).max(1) - 1) >> 23).max(1) as i32 - 150;
        let pair = |x: f32, y: f32| {
            let a = (x.to_bits() & 0x7fff_ffff).min(y.to_bits() & 0x7fff_ffff);
            ((a >> 23) as i32).max(1) - 150
        };
        let (base, mut t, mut spent) = (below(q), q, 0);
        loop {
            let next = if up { t.next_up() } else { t.next_down() };
            spent += 1 << (pair(t, next) - base + 2).clamp(0, 30);
            if spent > 8 {
                return t;
            }
            t = next;
        }
    };
    let mut p = [0, 1].map(|k| push((f64::from(s[k]) / l1) as f32));
    if s[2] < 0.0 {
        let sgn = p.map(|x| if x >= 0.0 { 1.0f32 } else { -1.0 });
        p = [
            dir(1.0 - f64::from(p[1].abs())) * sgn[0],
            dir(1.0 - f64::from(p[0].abs())) * sgn[1],
        ];
    }
    let t = p.map(|x| dir(f64::from(x) * 0.5 + 0.5).clamp(0.0, 1.0));
    let c = t.map(|x| dir(f64::from(x) * 65535.0).round_ties_even() as u32);
    Some(c[0] | (c[1] << 16))
}

/// `EmulatedKernel` serves `Policy::Upper`, `Policy::Lower` and `Policy::Seeded` from the
/// searched module with the table all ones or all zeros, or the seeded mode (one compiled
/// pipeline for every policy and the search). Against the policy's own module (the direction
/// or seed a constant), on 4096 inputs each:
/// - every value bit and every "undefined" flag equal, for functions chosen to reach every kind
///   of helper in few compilations: two linear-depth paths (division, fusion, reassociation),
///   the roughness codec (exp2/log2, integer conversion, comparisons), the 24-bit octahedral
///   encoder (the precise one: four candidates, every freedom) and decoder (inverseSqrt,
///   flush), and lighting's combine;
/// - for the 32-bit rounding encoder, where lavapipe (Mesa 22.3, 25.0) compiles the constant-direction
///   module's error terms differently and the two disagree on a few inputs: wherever they
///   differ, the table's code is the one exact arithmetic gives ([`oct32_round_at_end`]).
#[test]
fn every_policy_through_the_searched_module_matches_its_own_module() {
    use prepass::conforming::emulate;
    use prepass::wgsl::{LINEAR_DEPTH, LPP, NORMAL_OCT, ROUGHNESS};
    let n = 4096;
    let cases = [
        (LINEAR_DEPTH, "view_z_from_depth24"),
        (LINEAR_DEPTH, "view_z_from_reversed_depth_consts"),
        (ROUGHNESS, "encode_log_roughness"),
        (ROUGHNESS, "decode_log_roughness"),
        (NORMAL_OCT, "encode_normal_oct24"),
        (NORMAL_OCT, "decode_normal_oct24"),
        (NORMAL_OCT, "encode_normal_oct32_fast"),
        (LPP, "lpp_combine"),
    ];
    for (src, name) in cases {
        let sig = Signature::read(src, name).unwrap();
        let cols = columns_for(&sig, n, 0x5eed);
        let args: Vec<Arg<'_>> = cols.iter().map(|c| Arg::column(c)).collect();
        // Seeded too, except where only the directed ends have an exact reference to decide a
        // difference (the 32-bit rounding encoder: see above).
        let seeded = name != "encode_normal_oct32_fast";
        // Default tier: one directed end and one seed (the table is all ones or all zeros and
        // the seeded mode one hash either way, so the other end and seed take the same code
        // path through the module); the full tier both of each. Each is a compile of its own
        // module, which is this test's time.
        let policies: &[Policy] = common::tier::by_tier(
            &[Policy::Upper, Policy::Seeded(1)],
            &[
                Policy::Upper,
                Policy::Lower,
                Policy::Seeded(1),
                Policy::Seeded(7),
            ],
        );
        for &policy in policies
            .iter()
            .filter(|p| seeded || !matches!(p, Policy::Seeded(_)))
        {
            let emu = Emulation::new(policy);
            let own = emulate(src, &emu).unwrap();
            let f = own.function_name(name).unwrap();
            let flag = [prepass::conforming::UNDEFINED_FLAG.to_string()];
            let (want, want_flags) = gpu()
                .kernel_with_tail(&own.source, f, &flag)
                .and_then(|k| k.run_with_tail(&args, n as u64))
                .unwrap();
            let k = EmulatedKernel::new(gpu(), src, name, &emu).unwrap();
            assert_eq!(
                k.emulated.emulation.policy,
                Policy::Searched,
                "{name}: not the table"
            );
            let (got, flags) = k.run(&args, n as u64).unwrap();
            let want_flags: Vec<bool> = want_flags.iter().map(|&f| f != 0).collect();
            assert_eq!(flags, want_flags, "{name} {policy}: undefined flags differ");
            let w = sig.result.words();
            let differ: Vec<usize> = (0..n)
                .filter(|&i| want.words()[i * w..(i + 1) * w] != got.words()[i * w..(i + 1) * w])
                .collect();
            if name != "encode_normal_oct32_fast" {
                // They may differ where the policy's own module's error-free transformations
                // see literal operands, which the host compiler folds and rewrites (core.wgsl,
                // prepass_cf_opaque): its push then falls short or oversteps. There the table's
                // value must be inside the interval enclosure of every allowed result.
                let enclosure = prepass::conforming::interval::Enclosure::new(src, true).unwrap();
                let mut own_outside = 0;
                for &i in &differ {
                    let vals = interval_args(&sig, &cols, i);
                    let e = enclosure.of(name, &vals).unwrap_or_else(|e| {
                        panic!("{name} {policy}: the table differs from the policy module at {} inputs, and the interval evaluator cannot decide which is right: {e}", differ.len())
                    });
                    let (g, o) = (
                        &got.words()[i * w..(i + 1) * w],
                        &want.words()[i * w..(i + 1) * w],
                    );
                    assert!(
                        inside(&e, g),
                        "{name} {policy}, input {i}: table {g:x?} outside the enclosure of every allowed result {e:?} (own module {o:x?})"
                    );
                    own_outside += usize::from(!inside(&e, o));
                }
                if !differ.is_empty() {
                    eprintln!(
                        "{name} {policy}: the constant-direction module differs from the table at {} of {n} inputs, outside the spec at {own_outside}; the table stays inside",
                        differ.len()
                    );
                }
                continue;
            }
            for &i in &differ {
                let v: [f32; 3] = std::array::from_fn(|l| f32::from_bits(cols[0][i * 3 + l]));
                let exact = oct32_round_at_end(v, policy == Policy::Upper);
                assert_eq!(
                    Some(got.words()[i]),
                    exact,
                    "{name} {policy} at {v:?}: the table gives {:#x}, its own module {:#x}, exact arithmetic {exact:x?}",
                    got.words()[i],
                    want.words()[i]
                );
            }
            eprintln!(
                "{name} {policy}: the constant-direction module differs from the table at {} of {n} inputs; the table's code is the exact one at each",
                differ.len()
            );
        }
    }
}

/// The best-fit codec (`sweep::normal::CODECS`): its promise on a conforming adapter is an
/// angle (`normal::xyz8::BEST_FIT_SINE_SLACK_CONFORMING`), not one code step, since two nearly
/// equal candidates can lie in planes far apart.
const BEST_FIT: &str = "xyz8 best-fit";

/// Twice `BEST_FIT_SINE_SLACK_CONFORMING`, as radians: a sine slack under 1e-4 at angles under
/// 0.4° is the angle's within a relative 1e-4, which the factor 1.0001 covers.
fn best_fit_conforming_slack() -> f64 {
    2.0 * f64::from(prepass::normal::xyz8::BEST_FIT_SINE_SLACK_CONFORMING) * 1.0001
}

/// The most, over `inputs`, by which the exact angle to `codes[i]` exceeds the angle to the
/// best-fit twin's code (radians; 0 where the codes agree).
fn best_fit_excess(inputs: &[[f32; 3]], codes: &[u32]) -> f64 {
    use prepass::normal::xyz8::{encode_normal_xyz8_best, exact::angle_to};
    inputs
        .iter()
        .zip(codes)
        .map(|(v, &p)| {
            let twin = encode_normal_xyz8_best(glam::Vec3::from(*v));
            if p == twin {
                0.0
            } else {
                let n = v.map(f64::from);
                (angle_to(n, p) - angle_to(n, twin)).max(0.0)
            }
        })
        .fold(0.0, f64::max)
}

/// The twins' promises at the worst tables the round-trip search found for one codec: codes
/// within one step of the twin's (the best fit: not asserted, see [`BEST_FIT`]), decodes unit
/// within the conforming budget.
fn assert_searched_promises(r: &prepass::sweep::conforming::NormalFigures) {
    use prepass::sweep::conforming::UNIT_TOLERANCE_CONFORMING;
    // The best fit promises an angle, not a code step (checked under the policies).
    if r.name != BEST_FIT {
        assert_within!(
            r.searched_code_step,
            1,
            "the twins' promise: within one code on every conforming adapter",
            "{}: code steps from the twin's at the searched worst tables",
            r.name
        );
    }
    assert_within!(
        r.searched_len_error,
        UNIT_TOLERANCE_CONFORMING,
        "sweep::conforming::UNIT_TOLERANCE_CONFORMING",
        "{}: |len − 1| of the decodes at the searched worst tables",
        r.name
    );
}

/// The default tier's emulation sample (`sweep::normal::default_tier_sample`) finds the worst
/// that every input finds, on one encoder of each kind it samples: a rounding encoder (oct16's)
/// and a precise one (oct16), over the same 2^18 Fibonacci and adversarial directions as
/// [`every_normal_encoding_under_emulation`], under the upper and lower policies; and with it
/// the default tier's round-trip search (`SEARCHED_NORMAL_INPUTS_DEFAULT_TIER` inputs of the
/// sample's pool) finds the worst the full tier's (`SEARCHED_NORMAL_INPUTS` of every input's)
/// does. Runs in both tiers: it is the evidence for the default tier's rules.
#[test]
fn default_tier_sample_finds_the_full_tiers_worst() {
    use prepass::sweep::conforming::{
        SEARCHED_NORMAL_INPUTS, SEARCHED_NORMAL_INPUTS_DEFAULT_TIER, normal_figures,
    };
    use prepass::sweep::normal::{
        adversarial_directions, codec, default_tier_sample, fibonacci_directions,
    };
    let mut inputs = fibonacci_directions(1 << 18);
    inputs.extend(adversarial_directions());
    let policies = [Policy::Upper, Policy::Lower];
    for name in ["oct16 fast", "oct16"] {
        let c = codec(name);
        let at = |k: usize, searched: usize| {
            let c = prepass::sweep::normal::Codec {
                emulation_sample: k,
                ..*c
            };
            normal_figures(gpu(), &[c], &inputs, &policies, searched)
                .unwrap()
                .remove(0)
        };
        let (sampled, every) = (
            at(default_tier_sample(c), SEARCHED_NORMAL_INPUTS_DEFAULT_TIER),
            at(1, SEARCHED_NORMAL_INPUTS),
        );
        eprintln!(
            "{name}: emulated max (upper, lower) at 1 in {} inputs {:?}°, at every input {:?}°; searched at {} inputs {:.7}°, at {} {:.7}°",
            default_tier_sample(c),
            sampled.emulated_max,
            every.emulated_max,
            sampled.searched_inputs,
            sampled.searched,
            every.searched_inputs,
            every.searched
        );
        assert!(sampled.emulated_inputs < every.emulated_inputs);
        assert_eq!(
            sampled.emulated_max, every.emulated_max,
            "{name}: the default tier's emulation sample (sweep::normal::default_tier_sample) \
             missed the worst round trip that every input finds; its rule no longer holds"
        );
        assert_eq!(
            sampled.searched, every.searched,
            "{name}: the default tier's search ({SEARCHED_NORMAL_INPUTS_DEFAULT_TIER} inputs of the \
             sample's pool, sweep::conforming::SEARCHED_NORMAL_INPUTS_DEFAULT_TIER) missed the \
             worst the full tier's ({SEARCHED_NORMAL_INPUTS} of every input's pool) finds; its rule \
             no longer holds"
        );
    }
}

/// The inputs per codec the round-trip search runs at in this tier (the full tier's
/// `SEARCHED_NORMAL_INPUTS`, the default tier's `SEARCHED_NORMAL_INPUTS_DEFAULT_TIER`: the
/// head of the same pool; the rule in the latter's rustdoc).
fn searched_normal_inputs() -> usize {
    use prepass::sweep::conforming::{SEARCHED_NORMAL_INPUTS, SEARCHED_NORMAL_INPUTS_DEFAULT_TIER};
    common::tier::by_tier(SEARCHED_NORMAL_INPUTS_DEFAULT_TIER, SEARCHED_NORMAL_INPUTS)
}

/// Every normal encoding on the emulated worst adapter (upper, lower, one seed): round-trip
/// error beside the adapter's own (`round_trip` without emulation), every decode finite and
/// unit within the conforming budget, the codes the emulated encoder chooses differently from
/// the Rust twin, and the precise octahedral encoders' optimality. Sampled to fit CI: 2^18
/// Fibonacci directions plus the whole adversarial set, the encoders that choose among
/// candidates emulated at their `Codec::emulation_sample` of them (precise octahedral: one in 4
/// and the quarter their adapter round trip erred most on; best-fit xyz8: one in 64 and the
/// 64th); decoders over every 16-bit code, every 61st 24-bit code, every 97th code of
/// the 32-bit stratified sample.
#[test]
fn every_normal_encoding_under_emulation() {
    use prepass::sweep::conforming::{
        UNIT_TOLERANCE_CONFORMING, normal_figures_with, optimality_tolerance_conforming_deg,
    };
    use prepass::sweep::normal::{
        adversarial_directions, fibonacci_directions, optimality_tolerance_deg, precise_optimality,
        stratified_codes32,
    };
    use std::fmt::Write as _;
    // One measurement, asserted here and published (README and docs/figures.md, block
    // `normal-encodings`): 2^18 spherical-Fibonacci directions and the adversarial set, on the
    // adapter and under three policies; decoders also over every 16-bit code, every 61st 24-bit
    // code and every 97th stratified 32-bit code.
    let mut inputs = fibonacci_directions(1 << 18);
    inputs.extend(adversarial_directions());
    let codes16: Vec<u32> = (0..1 << 16).collect();
    let codes24: Vec<u32> = (0..1 << 24).step_by(61).chain([(1 << 24) - 1]).collect();
    let codes32: Vec<u32> = stratified_codes32().into_iter().step_by(97).collect();
    // What one codec costs here (its emulated modules built and run under every policy, and its
    // search), printed for `.ci/timings` (docs/timings.md), never asserted: the sweep asks for a
    // codec's codes as it starts on it, so the time from one request to the next is one codec's.
    let started = std::cell::RefCell::new(None::<(String, std::time::Instant)>);
    let codec_cost = |next: Option<&str>| {
        let now = next.map(|n| (n.to_string(), std::time::Instant::now()));
        if let Some((name, t)) = started.replace(now) {
            common::uncaptured(&format!(
                "codec cost: {name}: {:.1} s\n",
                t.elapsed().as_secs_f64()
            ));
        }
    };
    let codes_of = |c: &prepass::sweep::normal::Codec| match c.bits {
        16 => codes16.clone(),
        24 => codes24.clone(),
        // The signed octahedron: every 7th of its 2^21 codes, and the last.
        21 => (0..1 << 21)
            .step_by(7)
            .chain([(1 << 21) - 1])
            .map(prepass::normal::signed_oct::texel_of_index)
            .collect(),
        // xyz10: the stratified 32-bit sample's low 30 bits.
        30 => codes32.iter().map(|p| p & 0x3fff_ffff).collect(),
        _ => codes32.clone(),
    };
    let codes_for = |c: &prepass::sweep::normal::Codec| {
        codec_cost(Some(c.name));
        codes_of(c)
    };
    let policies = [Policy::Upper, Policy::Lower, Policy::Seeded(1)];
    let mut inspected = 0;
    let mut inspect = |c: &prepass::sweep::normal::Codec,
                       policy: Policy,
                       emulated_at: &[[f32; 3]],
                       e: &prepass::sweep::conforming::EmulatedCodec| {
        inspected += 1;
        common::progress(
            "every_normal_encoding_under_emulation: codecs × policies",
            inspected,
            prepass::sweep::normal::CODECS.len() * policies.len(),
        );
        let (len_rt, bad_rt) = e.round_trip_length;
        let (len_dec, dec_ok) = e.decode_length();
        eprintln!(
            "{:14} {policy:10}: {} codes differ from the twin; |len−1| ≤ {len_rt:.3e} (round trip), {len_dec:.3e} (decoder, {} codes), budget {UNIT_TOLERANCE_CONFORMING:.3e}",
            c.name, e.round_trip.twin_encode.count, e.decoder.codes
        );
        assert_eq!(
            bad_rt, 0,
            "{} {policy}: {bad_rt} round-trip decodes not finite or beyond the conforming unit budget {UNIT_TOLERANCE_CONFORMING:e} (derivation: sweep::conforming)",
            c.name
        );
        assert!(
            dec_ok,
            "{} {policy}: decoder |len − 1| = {len_dec:e} beyond the conforming budget {UNIT_TOLERANCE_CONFORMING:e}, or a non-finite result (max angle {}°)",
            c.name, e.decoder.max_angle_deg
        );
        if (c.name.starts_with("oct") || c.name == "substrate" || c.name == "signed oct")
            && !c.name.ends_with("fast")
        {
            let o = precise_optimality(c, emulated_at, &e.round_trip);
            let tol = optimality_tolerance_conforming_deg();
            eprintln!(
                "{:14} {policy:10}: precise choice's worst excess over the best neighbour {:.3e}° (correctly rounded tolerance {:.3e}°, conforming {tol:.3e}°)",
                c.name,
                o.worst_excess_deg,
                optimality_tolerance_deg()
            );
            assert_within!(
                o.worst_excess_deg,
                tol,
                "sweep::conforming::optimality_tolerance_conforming_deg",
                "{} {policy}: the precise encoder's choice, degrees worse than the best neighbour",
                c.name
            );
        }
        if c.name == BEST_FIT {
            let excess = best_fit_excess(emulated_at, &e.round_trip.codes);
            eprintln!(
                "{:14} {policy:10}: codes chosen differently are at most {excess:.3e} rad farther than the twin's",
                c.name
            );
            assert_within!(
                excess,
                best_fit_conforming_slack(),
                "normal::xyz8::BEST_FIT_SINE_SLACK_CONFORMING, twice (sine ≈ radians)",
                "{} {policy}: exact angle of the emulated code beyond the twin's, radians",
                c.name
            );
        } else {
            assert_within!(
                e.max_code_step,
                1,
                "the twins' promise: within one code on every conforming adapter",
                "{} {policy}: emulated code steps from the twin's",
                c.name
            );
        }
    };
    // The round-trip search at the inputs the policies erred most on (per codec: each
    // policy's worst, pooled; `searched_normal_inputs` of them): the encoder's and decoder's
    // ends chosen together, which the greedy policies never combine.
    // The full tier emulates every codec at every input; the default tier at
    // `sweep::normal::default_tier_sample` of them (its rustdoc: the rule, and why the sample
    // holds the worst; `default_tier_sample_finds_the_full_tiers_worst` checks it on one codec
    // of each kind).
    let codecs: Vec<prepass::sweep::normal::Codec> = prepass::sweep::normal::CODECS
        .iter()
        .map(|c| prepass::sweep::normal::Codec {
            emulation_sample: common::tier::by_tier(
                prepass::sweep::normal::default_tier_sample(c),
                1,
            ),
            ..*c
        })
        .collect();
    let searched = searched_normal_inputs();
    let rows = normal_figures_with(
        gpu(),
        &codecs,
        &inputs,
        &policies,
        searched,
        &codes_for,
        &mut inspect,
    )
    .unwrap();
    codec_cost(None);
    let mut readme = String::from(
        "| encoding | bits | target format | stored by | max° | mean° | max° on the worst conforming adapter, greedy / searched | SPIR-V encode / decode |\n|---|---|---|---|---|---|---|---|\n",
    );
    let mut full = common::adapter_line();
    let _ = writeln!(
        full,
        "\n| encoding | bits | max° | mean° | emulated max° (upper / lower / seeded) | max° (worst found by the search) | search: slots read per input | emulated mean° | codes ≠ Rust twin (emulated, of {}) | max \\|len − 1\\| of emulated decodes |\n|---|---|---|---|---|---|---|---|---|---|",
        inputs.len()
    );
    for r in &rows {
        assert_eq!(r.adapter.nan_count, 0, "{}: NaN round trips", r.name);
        let worst = r.emulated_max.iter().copied().fold(0.0, f64::max);
        eprintln!(
            "{:14} searched at {} inputs: worst {:.6}° (greedy {worst:.6}°) at {}",
            r.name, r.searched_inputs, r.searched, r.searched_at
        );
        assert_eq!(
            r.searched_inputs, searched,
            "{}: the search ran at fewer inputs than asked",
            r.name
        );
        assert!(
            r.searched.is_finite(),
            "{}: the searched round trip gave a non-finite angle: {}",
            r.name,
            r.searched_at
        );
        // The searched tables are conforming behaviours: the promises asserted under the
        // policies above must hold at the worst combination the search found too.
        assert_searched_promises(r);
        // docs/figures.md (Normal encodings) says the greedy and searched worst agree to the
        // fourth decimal.
        assert_within_abs!(
            r.searched - worst,
            0.0,
            1e-4,
            "docs/figures.md, Normal encodings: greedy and searched agree to the fourth decimal",
            "{}: searched worst − greedy worst, degrees",
            r.name
        );
        let (lo, hi, exhaustive) = r.searched_slots;
        let _ = writeln!(
            full,
            "| {} | {} | {:.6} | {:.6} | {:.6} / {:.6} / {:.6} | {:.6} | {lo}–{hi}{} | {:.6} | {} | {:.3e} |",
            r.name,
            r.bits,
            r.adapter.max,
            r.adapter.mean(),
            r.emulated_max[0],
            r.emulated_max[1],
            r.emulated_max[2],
            r.searched,
            if exhaustive {
                ", exhaustive"
            } else {
                ", climbed"
            },
            r.emulated_mean,
            if r.emulated_inputs == inputs.len() {
                r.twin_changed.to_string()
            } else {
                // A sampling codec (Codec::emulation_sample): its count is of its sample.
                format!("{} of {} sampled", r.twin_changed, r.emulated_inputs)
            },
            r.max_len_error
        );
    }
    // The README: one row per encoding, its rounding encoder's figures after a `·`.
    let names: Vec<&str> = rows.iter().map(|r| r.name).collect();
    let greedy = |r: &prepass::sweep::conforming::NormalFigures| {
        r.emulated_max.iter().copied().fold(0.0, f64::max)
    };
    for (i, fast) in common::precise_with_fast(&names) {
        let (r, f) = (&rows[i], fast.map(|k| &rows[k]));
        let both = |g: &dyn Fn(&prepass::sweep::conforming::NormalFigures) -> String| {
            common::with_fast(g(r), f.map(g))
        };
        let _ = writeln!(
            readme,
            "| {} | {} | {} | {} | {} | {} | {} | {} / {} |",
            r.name,
            r.bits,
            r.target,
            prepass::sweep::normal::codec(r.name).stored_by,
            both(&|x| format!("{:.4}", x.adapter.max)),
            both(&|x| format!("{:.4}", x.adapter.mean())),
            both(&|x| format!("{:.4} / {:.4}", greedy(x), x.searched)),
            both(&|x| x.spirv.0.to_string()),
            r.spirv.1
        );
    }
    // Measured blocks: compared as text on the adapter they were published from; elsewhere the
    // differences are printed and the assertions above (and tests/normal_*.rs on the adapter)
    // are what must hold.
    // Published from the full tier; the default tier's sample may not exceed its worsts.
    common::tier::publish_sampled(
        "README.md",
        "normal-encodings",
        &readme,
        &[
            "max°",
            "max° on the worst conforming adapter, greedy / searched",
        ],
        "conforming",
    );
    common::tier::publish_sampled(
        "docs/figures.md",
        "normal-encodings",
        &full,
        &[
            "max°",
            "emulated max° (upper / lower / seeded)",
            "max° (worst found by the search)",
            "max \\|len − 1\\| of emulated decodes",
        ],
        "conforming",
    );
}

/// The vouched-input encoders (`common::vouched_codec`: `encode_normal_oct*_vouched`,
/// `encode_normal_hemioct24_vouched` and their `…_fast_vouched` with the robust codecs'
/// decoders and references) on the emulated worst adapter (upper, lower, one seed, and the
/// search at the inputs they erred most on), as [`every_normal_encoding_under_emulation`] holds
/// the robust ones: every round-trip decode finite and unit within the conforming budget, the
/// emulated code within one step of the twin's, and the precise choice within the conforming
/// optimality tolerance. Their inputs (2^14 Fibonacci directions and the adversarial set: fewer
/// than the robust encoders' 2^18, to fit CI) are inside the octahedral vouched contract; for
/// hemioct24 those inside its own (`hemioct::is_vouched`: all but the `−z` half-axis, whose
/// clamp is zero). The emulated worst error is printed, not published (2026-12-06, 2^16
/// directions, octahedral: each within 3e-5° of the robust encoder's emulated worst).
#[test]
fn vouched_encoders_under_emulation() {
    use prepass::normal::{hemioct, oct};
    use prepass::sweep::conforming::{
        UNIT_TOLERANCE_CONFORMING, normal_figures_with, optimality_tolerance_conforming_deg,
    };
    use prepass::sweep::normal::{
        adversarial_directions, fibonacci_directions, precise_optimality, stratified_codes32,
    };
    let mut all = fibonacci_directions(1 << 14);
    all.extend(adversarial_directions());
    assert!(all.iter().all(|&n| oct::is_vouched(n.into())));
    // Outside hemioct's contract: only the −z half-axis.
    assert!(
        all.iter()
            .all(|&n| hemioct::is_vouched(n.into()) || (n[0] == 0.0 && n[1] == 0.0))
    );
    let hemi: Vec<[f32; 3]> = all
        .iter()
        .copied()
        .filter(|&n| hemioct::is_vouched(n.into()))
        .collect();
    // The decoders are the robust codecs' (tested by every_normal_encoding_under_emulation):
    // a few codes each.
    let codes16: Vec<u32> = (0..1 << 16).step_by(251).collect();
    let codes24: Vec<u32> = (0..1 << 24).step_by(65_521).collect();
    let codes32: Vec<u32> = stratified_codes32().into_iter().step_by(4093).collect();
    let codes_for = |c: &prepass::sweep::normal::Codec| match c.bits {
        16 => codes16.clone(),
        24 => codes24.clone(),
        _ => codes32.clone(),
    };
    let policies = [Policy::Upper, Policy::Lower, Policy::Seeded(1)];
    // Default tier: oct24 and oct32 (oct16 too in the full tier). oct16 and oct24 are one WGSL
    // construction (`oct_choose` with the width as its argument), so their emulated operation
    // sites are the same; oct32 has its own (`oct_choose_wide`). Each pair costs its modules'
    // compiles, most of this test's time.
    let octahedral: Vec<&str> = common::OCTAHEDRAL
        .into_iter()
        .filter(|n| common::full_strength() || !n.starts_with("oct16"))
        .collect();
    for (names, inputs) in [
        (&octahedral[..], &all),
        (&common::HEMIOCTAHEDRAL[..], &hemi),
    ] {
        vouched_under_emulation(names, inputs, &policies, &codes_for);
    }

    fn vouched_under_emulation(
        names: &[&str],
        inputs: &[[f32; 3]],
        policies: &[Policy],
        codes_for: &dyn Fn(&prepass::sweep::normal::Codec) -> Vec<u32>,
    ) {
        let mut inspect =
            |c: &prepass::sweep::normal::Codec,
             policy: Policy,
             emulated_at: &[[f32; 3]],
             e: &prepass::sweep::conforming::EmulatedCodec| {
                let (len_rt, bad_rt) = e.round_trip_length;
                eprintln!(
                    "{:20} {policy:10}: {} codes differ from the twin; |len−1| ≤ {len_rt:.3e}; max {:.6}°",
                    c.name, e.round_trip.twin_encode.count, e.round_trip.error.max
                );
                assert_eq!(
                    bad_rt, 0,
                    "{} {policy}: {bad_rt} round-trip decodes not finite or beyond the conforming unit budget {UNIT_TOLERANCE_CONFORMING:e} (derivation: sweep::conforming)",
                    c.name
                );
                if !c.name.ends_with("fast") {
                    let o = precise_optimality(c, emulated_at, &e.round_trip);
                    assert_within!(
                        o.worst_excess_deg,
                        optimality_tolerance_conforming_deg(),
                        "sweep::conforming::optimality_tolerance_conforming_deg",
                        "{} {policy}: the precise encoder's choice, degrees worse than the best neighbour",
                        c.name
                    );
                }
                assert_within!(
                    e.max_code_step,
                    1,
                    "the twins' promise: within one code on every conforming adapter",
                    "{} {policy}: emulated code steps from the twin's",
                    c.name
                );
            };
        let vouched: Vec<prepass::sweep::normal::Codec> =
            names.iter().map(|n| common::vouched_codec(n)).collect();
        let rows = normal_figures_with(
            gpu(),
            &vouched,
            inputs,
            policies,
            searched_normal_inputs(),
            codes_for,
            &mut inspect,
        )
        .unwrap();
        for r in &rows {
            let worst = r.emulated_max.iter().copied().fold(0.0, f64::max);
            eprintln!(
                "{:20}: adapter max {:.6}°, emulated worst {worst:.6}° (searched {:.6}°)",
                r.name, r.adapter.max, r.searched
            );
            assert_eq!(r.adapter.nan_count, 0, "{}: NaN round trips", r.name);
            assert!(r.searched.is_finite(), "{}: {}", r.name, r.searched_at);
            assert_searched_promises(r);
        }
    }
}

/// The precise (hemi-)octahedral encoders' choice among four codes, searched on the decision
/// margin (`sweep::normal::searched_decision`): inputs where the closest candidate leads the
/// runner-up by graded amounts (below), and per input the climb that pushes
/// the runner-up's score below the best's. The promise: whatever the search makes the encoder
/// choose is within `optimality_tolerance_conforming_deg` of the closest code. Published in
/// docs/figures.md (block `normal-decision`) with how much of the slack the search reached.
#[test]
fn precise_choice_searched_on_the_decision_margin() {
    use prepass::conforming::search::SearchConfig;
    use prepass::sweep::conforming::optimality_tolerance_conforming_deg;
    use prepass::sweep::normal::{
        CODECS, SCORES_FN, chain_choice, decision_inputs, optimality_tolerance_deg, scores_source,
        searched_decisions,
    };
    use std::fmt::Write as _;
    let bound = optimality_tolerance_conforming_deg();
    // Leads as fractions of the correctly rounded slack (the conforming bound is 5 of it): ten
    // from the conforming bound down to 1/64, over eight cells. The cost is the two modules'
    // compiles (the climb over 80 inputs per encoder adds about a second), so nothing is sampled.
    let cells = 8;
    let fractions = [
        5.0,
        1.0,
        0.5,
        0.25,
        0.125,
        1.0 / 12.0,
        1.0 / 16.0,
        1.0 / 24.0,
        1.0 / 32.0,
        1.0 / 64.0,
    ];
    let gaps: Vec<f64> = fractions
        .iter()
        .map(|f| f * optimality_tolerance_deg())
        .collect();
    let mut s = common::adapter_line();
    s.push_str("\n| encoding | inputs (exact lead of the closest code over the runner-up) | choices overturned: at the start tables / by the search | worst excess over the closest code found | smallest lead the search did not overturn | bound on every conforming adapter | worst found / bound | slots read per input |\n|---|---|---|---|---|---|---|---|\n");
    let precise: Vec<_> = CODECS
        .iter()
        .filter(|c| scores_source(c).is_some())
        .collect();
    assert_eq!(
        precise.len(),
        6,
        "oct16, oct20, oct24, oct32, hemioct24 and the signed octahedron precise"
    );
    // Default tier: oct24, oct32, hemioct24 and the signed octahedron, one per construction of
    // the choice (oct16 and oct20 are oct24's `oct_choose` at another width; the full tier
    // searches them too). Each costs its two modules' compiles.
    let jobs: Vec<_> = precise
        .iter()
        .filter(|c| common::full_strength() || !matches!(c.name, "oct16" | "oct20"))
        .map(|&c| (c, decision_inputs(c, cells, &gaps)))
        .collect();
    // The scores function reads the encoder's candidates in the encoder's order: where the
    // lead is at least the bound (no conforming adapter can overturn it), the adapter's scores
    // and its shipped encoder both give the exact closest code.
    for (c, inputs) in &jobs {
        let clear: Vec<_> = inputs.iter().filter(|d| d.gap() >= bound).collect();
        assert!(!clear.is_empty(), "{}: no input leads by the bound", c.name);
        let ns: Vec<[f32; 3]> = clear.iter().map(|d| d.n).collect();
        let bits: Vec<u32> = vec![c.bits / 2; ns.len()];
        let source = scores_source(c).unwrap();
        let args = [Arg::column(&ns), Arg::column(&bits)];
        let scores = run_kernel(&source, SCORES_FN, &args, ns.len() as u64);
        let codes = run_kernel(c.source, c.encode, &[Arg::column(&ns)], ns.len() as u64);
        for ((d, v), &code) in clear.iter().zip(scores.as_vec4()).zip(codes.as_u32()) {
            let best = d.codes[d.best];
            assert_eq!(
                (d.codes[chain_choice(*v)], code),
                (best, best),
                "{} at {:?}: (scores' choice, encoder's code) against the closest code",
                c.name,
                d.n
            );
        }
    }
    let results = searched_decisions(gpu(), &jobs, &SearchConfig::default()).unwrap();
    for ((c, inputs), r) in jobs.iter().zip(&results) {
        let (lo, hi) = inputs
            .iter()
            .map(|d| d.gap())
            .fold((f64::INFINITY, 0.0f64), |(a, b), g| (a.min(g), b.max(g)));
        eprintln!("{}: {r:?}", c.name);
        assert_within!(
            r.worst_excess_deg,
            bound,
            "sweep::conforming::optimality_tolerance_conforming_deg",
            "{}: the precise encoder's choice at the searched worst, degrees beyond the closest code (at {:?})",
            c.name,
            r.worst_at
        );
        let _ = writeln!(
            s,
            "| {} | {} ({lo:.2e}° to {hi:.2e}°) | {} / {} | {:.3e}° | {:.3e}° | {bound:.3e}° | {:.2} | {}–{} |",
            c.name,
            r.inputs,
            r.flipped_at_starts,
            r.flipped,
            r.worst_excess_deg,
            r.smallest_lead_kept,
            r.worst_excess_deg / bound,
            r.slots.0,
            r.slots.1
        );
    }
    common::tier::publish_sampled(
        "docs/figures.md",
        "normal-decision",
        &s,
        &[
            "worst excess over the closest code found",
            "worst found / bound",
        ],
        "conforming",
    );
}

/// Each call of a helper reads its own table slots (the call context): `h(x, y) − h(x, y)` is 0
/// wherever both calls take one end (every uniform table: the upper and lower policies), and
/// the search must find tables where the two calls err apart, by up to the division's 2.5 ULP
/// each way (5 ULP of `x/y` in all). Fails if the sites were per static expression only.
#[test]
fn each_call_of_a_helper_has_its_own_table_slots() {
    use prepass::conforming::interval::ulp_spec;
    use prepass::conforming::search::{SearchConfig, climb};
    let src = "fn h(x: f32, y: f32) -> f32 { return x / y; }\n\
               fn twice(x: f32, y: f32) -> f32 { return h(x, y) - h(x, y); }";
    let x: Vec<f32> = (0..16).map(|i| 1.0 + i as f32 * 0.37).collect();
    let y: Vec<f32> = (0..16).map(|i| 3.0 + i as f32 * 0.11).collect();
    let args = [Arg::column(&x), Arg::column(&y)];
    for policy in [Policy::Upper, Policy::Lower] {
        let k = EmulatedKernel::new(gpu(), src, "twice", &Emulation::new(policy)).unwrap();
        let out = k.run(&args, x.len() as u64).unwrap().0;
        assert!(
            out.as_f32().iter().all(|&d| d == 0.0),
            "{policy}: one end for every call, so h(x, y) − h(x, y) = 0; got {:?}",
            out.as_f32()
        );
    }
    let k = EmulatedKernel::new(gpu(), src, "twice", &Emulation::new(Policy::Searched)).unwrap();
    // The difference in ULPs of the exact quotient.
    let ulps = |i: usize, out: &prepass::harness::Output, e: usize| {
        let q = f64::from(x[i]) / f64::from(y[i]);
        f64::from(out.as_f32()[e]).abs() / ulp_spec(q)
    };
    let found = climb(&k, &args, x.len(), &ulps, &SearchConfig::default()).unwrap();
    for (i, f) in found.iter().enumerate() {
        let q = f64::from(x[i]) / f64::from(y[i]);
        if q == f64::from(q as f32) {
            continue; // exact: no freedom
        }
        // Each call reaches at least 2 ULP on either side (division_reaches_both_ends asserts
        // it), so calls with their own slots can be 4 apart; asked: 2 (with shared slots: 0).
        assert_at_least!(
            f.error,
            2.0,
            "WGSL: / within 2.5 ULP, each call at an end of its own: ≥ 4 ULP apart; asked 2",
            "input {i} ({} / {}): the searched |h − h| in ULPs ({}, {} slots read)",
            x[i],
            y[i],
            f.how,
            f.slots
        );
    }
}

#[path = "conforming/freedoms.rs"]
mod freedoms;

/// The modules a coverage check reads: every shipped file, composed scene modules (every depth
/// choice × every normal choice, with the largest position, roughness and lighting choices),
/// and the example renderer's shader as it runs (its scene module plus `deferred.wgsl`). A
/// composed module is a union of shipped functions under their own names, so the shipped files
/// already cover every scene; the composed ones check that union as built.
fn coverage_modules() -> Vec<(String, String)> {
    use prepass::projection::DepthConvention;
    use prepass::scene::{
        DepthChoice, DepthStorage, LightBuffers, LightingChoice, Lights, NormalChoice,
        NormalEncoding, NormalInput, PositionChoice, RoughnessChoice, Scene, Specular,
    };
    let mut out: Vec<(String, String)> = prepass::wgsl::FILES
        .iter()
        .map(|f| (f.name.to_string(), f.source.to_string()))
        .collect();
    let mut normals = vec![NormalChoice::default()];
    for encoding in NormalEncoding::ALL {
        for fast_encoder in [false, true] {
            normals.push(NormalChoice {
                encoding: Some(encoding),
                fast_encoder,
            });
        }
    }
    for storage in [
        DepthStorage::Float32,
        DepthStorage::Code24,
        DepthStorage::Code24Rgba8,
    ] {
        for convention in [DepthConvention::Standard, DepthConvention::Reversed] {
            for infinite_far in [false, true] {
                for (&normal, normal_input) in normals
                    .iter()
                    .flat_map(|n| [(n, NormalInput::Robust), (n, NormalInput::Vouched)])
                {
                    let scene = Scene {
                        depth: DepthChoice {
                            storage,
                            convention,
                            infinite_far,
                        },
                        position: PositionChoice::World,
                        normal,
                        normal_input,
                        roughness: RoughnessChoice::Log8,
                        lighting: LightingChoice {
                            lights: Lights::PointAndSpot,
                            specular: Specular::Phong,
                            buffers: LightBuffers::Two,
                            aggregate_vertex_lights: true,
                            light_volumes: true,
                        },
                    };
                    if let Ok(src) = scene.wgsl() {
                        out.push((format!("{scene:?}"), src));
                    }
                }
            }
        }
    }
    let example = common::deferred_minimal_scene();
    out.push((
        "examples/deferred_minimal (its scene module + deferred.wgsl)".into(),
        example.wgsl().unwrap() + include_str!("../examples/deferred_minimal/deferred.wgsl"),
    ));
    out
}

/// Coverage enforced: no shipped module, composed scene module or example shader uses an f32
/// operation that the emulation leaves at the host's accuracy (`Emulated::uncovered`), and the
/// check itself sees such operations where they are.
#[test]
fn the_emulation_covers_every_shipped_composed_and_example_module() {
    use prepass::conforming::emulate;
    let emu = Emulation::new(Policy::Upper);
    for (src, want) in [
        ("fn f(x: f32) -> f32 { return tan(x); }", "Tan"),
        (
            "fn f(a: mat2x2<f32>, b: mat2x2<f32>) -> mat2x2<f32> { return a + b; }",
            "matrix arithmetic",
        ),
    ] {
        let e = emulate(src, &emu).unwrap();
        assert!(
            e.uncovered.iter().any(|u| u.contains(want)),
            "`{src}` should list {want} as not emulated, lists {:?}",
            e.uncovered
        );
    }
    let modules = coverage_modules();
    let mut sites = 0;
    for (name, src) in &modules {
        let e = emulate(src, &emu).unwrap_or_else(|err| panic!("{name}: {err}"));
        assert!(
            e.uncovered.is_empty(),
            "{name} uses operations the emulation leaves at the host's accuracy: {:?} \
             (emulate them in src/conforming, or change the function)",
            e.uncovered
        );
        sites += e.sites;
    }
    eprintln!(
        "coverage: {} modules, {sites} emulated sites, nothing left uncovered",
        modules.len()
    );
}

/// The search beats the greedy policies where their pushes cancel: in `x / (y·z)` the upper
/// policy rounds the product up and the quotient up, which partly cancel; the worst adapter
/// rounds the product down and pushes the quotient up. Searched from the greedy tables, the
/// climb must reach at least their error at every input and more at some, and stay inside the
/// spec's bound for the expression (2.5 ULP of `/` plus one rounding of the product, 2^-23
/// relative: at most 2·2.5 + 2 ULP of the result, which the quotient's binade doubles at most).
#[test]
fn the_search_finds_what_the_greedy_policies_cancel() {
    use prepass::conforming::search::{SearchConfig, climb};
    const SRC: &str = "fn t_ratio(x: f32, y: f32, z: f32) -> f32 { return x / (y * z); }";
    let mut bits = xorshift64(0x1234_5678);
    let mut next = move || 1.0 + (bits() >> 11) as f32 / (1u64 << 53) as f32;
    let n = 64;
    let cols: [Vec<f32>; 3] = std::array::from_fn(|_| (0..n).map(|_| next()).collect());
    let exact: Vec<f64> = (0..n)
        .map(|i| f64::from(cols[0][i]) / (f64::from(cols[1][i]) * f64::from(cols[2][i])))
        .collect();
    let err = |g: f32, e: f64| (f64::from(g) - e).abs() / ulp32(e);
    let args = [
        Arg::column(&cols[0]),
        Arg::column(&cols[1]),
        Arg::column(&cols[2]),
    ];
    let mut greedy = vec![0.0f64; n];
    for policy in [Policy::Upper, Policy::Lower] {
        let k = EmulatedKernel::new(gpu(), SRC, "t_ratio", &Emulation::new(policy)).unwrap();
        let got = k.run(&args, n as u64).unwrap().0;
        for i in 0..n {
            greedy[i] = greedy[i].max(err(got.as_f32()[i], exact[i]));
        }
    }
    let k = EmulatedKernel::new(gpu(), SRC, "t_ratio", &Emulation::new(Policy::Searched)).unwrap();
    let error = |i: usize, out: &prepass::harness::Output, e: usize| err(out.as_f32()[e], exact[i]);
    let found = climb(&k, &args, n, &error, &SearchConfig::default()).unwrap();
    let mut better = 0;
    for i in 0..n {
        assert_at_least!(
            found[i].error,
            greedy[i] - 1e-12,
            "the climb starts from the upper and lower tables",
            "input {i}"
        );
        assert_within!(
            found[i].error,
            2.0 * 2.5 + 2.0,
            "the doc comment: `/`'s 2.5 ULP plus the product's rounding, binade factor 2",
            "input {i}"
        );
        if found[i].error > greedy[i] + 0.25 {
            better += 1;
        }
    }
    let worst_greedy = greedy.iter().copied().fold(0.0, f64::max);
    let worst_found = found.iter().map(|f| f.error).fold(0.0, f64::max);
    eprintln!(
        "x / (y·z): greedy worst {worst_greedy:.3} ULP, searched worst {worst_found:.3} ULP; {better} of {n} inputs improved by more than 0.25 ULP"
    );
    assert!(
        better > 0,
        "the search never beat the greedy policies by a quarter ULP"
    );
}
