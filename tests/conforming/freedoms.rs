//! Every freedom the emulation claims, checked at its ends. A check runs its builtin under the
//! policy that should reach the upper end and under the one that should reach the lower end,
//! and returns what was not reached. `every_freedom_reaches_its_ends` runs each as
//! (`Upper`, `Lower`); `every_freedom_check_fails_under_identity` runs each with
//! `Policy::Identity` in both places and expects it to fail: a check that passes there would
//! pass on an emulation that does not use the freedom at all. (The interval checks — every
//! result inside the spec's interval — are the other tests of this binary.)

use super::{f32_around, pairs, run, special_f32s, ulp32};
use prepass::conforming::{EmulatedKernel, Emulation, Freedoms, Policy};
use prepass::harness::Arg;

const SRC: &str = "
fn t_pack2x16float(v: vec2<f32>) -> u32 { return pack2x16float(v); }
fn t_unpack2x16float(p: u32) -> vec2<f32> { return unpack2x16float(p); }
fn t_f32_u32(x: u32) -> f32 { return f32(x); }
fn t_f32_i32(x: i32) -> f32 { return f32(x); }
fn t_matvec(c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    return mat3x3<f32>(c0, c1, c2) * v;
}
fn t_vecmat(c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    return v * mat3x3<f32>(c0, c1, c2);
}
fn t_floor(x: f32) -> f32 { return floor(x); }
fn t_ceil(x: f32) -> f32 { return ceil(x); }
fn t_min(a: f32, b: f32) -> f32 { return min(a, b); }
fn t_max(a: f32, b: f32) -> f32 { return max(a, b); }
fn t_clamp(x: f32, lo: f32, hi: f32) -> f32 { return clamp(x, lo, hi); }
fn t_lt(a: f32, b: f32) -> u32 { return select(0u, 1u, a < b); }
";

fn run_src(
    function: &str,
    policy: Policy,
    freedoms: Freedoms,
    args: &[Arg<'_>],
    n: usize,
) -> Vec<u32> {
    let emu = Emulation::new(policy).with_freedoms(freedoms);
    let k = EmulatedKernel::new(crate::common::gpu(), SRC, function, &emu)
        .unwrap_or_else(|e| panic!("{function}: {e}"));
    k.run(args, n as u64).unwrap().0.into_words()
}

/// What a check did not reach, or a one-line summary of what it did.
type Checked = Result<String, String>;

/// How many of `got` differ from `want`, as an error naming the first.
fn expect_all<T: PartialEq + std::fmt::Debug>(
    what: &str,
    inputs: &[impl std::fmt::Debug],
    got: &[T],
    want: &[T],
) -> Result<usize, String> {
    let bad: Vec<usize> = (0..got.len()).filter(|&i| got[i] != want[i]).collect();
    match bad.first() {
        None => Ok(got.len()),
        Some(&i) => Err(format!(
            "{what}: {} of {} differ, first at input {:?}: {:?}, want {:?}",
            bad.len(),
            got.len(),
            inputs[i],
            got[i],
            want[i]
        )),
    }
}

fn f16_value(code: u32) -> f32 {
    half::f16::from_bits(code as u16).to_f32()
}

/// pack2x16float rounds each in-range lane to either neighbouring f16: the upper policy to the
/// larger, the lower to the smaller (lanes between every pair of adjacent f16s sampled, at a
/// quarter, the tie and three quarters, both signs, subnormal f16s included).
fn pack2x16float_either_neighbour(up: Policy, lo: Policy) -> Checked {
    let mut lanes = Vec::new();
    let mut want_up = Vec::new();
    let mut want_lo = Vec::new();
    for code in (0u32..0x7bff)
        .step_by(37)
        .chain([0, 1, 0x3ff, 0x400, 0x3c00, 0x7bfe])
    {
        let (a, b) = (f16_value(code), f16_value(code + 1));
        for t in [0.25f32, 0.5, 0.75] {
            let x = a + (b - a) * t; // exact: f32 has 13 more significand bits
            lanes.push([x, -x]);
            want_up.push([b, -a]);
            want_lo.push([a, -b]);
        }
    }
    let n = lanes.len();
    let decode = |w: Vec<u32>| -> Vec<[f32; 2]> {
        w.iter()
            .map(|&c| [f16_value(c & 0xffff), f16_value(c >> 16)])
            .collect()
    };
    let args = [Arg::column(&lanes)];
    let got_up = decode(run_src("t_pack2x16float", up, Freedoms::PACK, &args, n));
    let got_lo = decode(run_src("t_pack2x16float", lo, Freedoms::PACK, &args, n));
    expect_all(
        "upper: the larger neighbouring f16",
        &lanes,
        &got_up,
        &want_up,
    )?;
    expect_all(
        "lower: the smaller neighbouring f16",
        &lanes,
        &got_lo,
        &want_lo,
    )?;
    Ok(format!(
        "{n} lane pairs between adjacent f16s at both neighbours"
    ))
}

/// pack2x16float may flush an f16-subnormal lane (keeping its sign); unpack2x16float may flush a
/// subnormal f16 it reads. Upper keeps the larger value (positive kept, negative flushed to −0),
/// lower the smaller.
fn f16_subnormals_flushed(up: Policy, lo: Policy) -> Checked {
    let codes: Vec<u32> = (1u32..0x400).step_by(7).collect();
    let lanes: Vec<[f32; 2]> = codes
        .iter()
        .map(|&c| [f16_value(c), -f16_value(c)])
        .collect();
    let n = lanes.len();
    let args = [Arg::column(&lanes)];
    let decode = |w: Vec<u32>| -> Vec<[f32; 2]> {
        w.iter()
            .map(|&c| [f16_value(c & 0xffff), f16_value(c >> 16)])
            .collect()
    };
    let keep_pos: Vec<[f32; 2]> = lanes.iter().map(|l| [l[0], 0.0]).collect();
    let keep_neg: Vec<[f32; 2]> = lanes.iter().map(|l| [0.0, l[1]]).collect();
    let got = decode(run_src("t_pack2x16float", up, Freedoms::FLUSH, &args, n));
    expect_all(
        "pack, upper: positive kept, negative flushed",
        &lanes,
        &got,
        &keep_pos,
    )?;
    let got = decode(run_src("t_pack2x16float", lo, Freedoms::FLUSH, &args, n));
    expect_all(
        "pack, lower: positive flushed, negative kept",
        &lanes,
        &got,
        &keep_neg,
    )?;
    let packed: Vec<u32> = codes.iter().map(|&c| c | ((c | 0x8000) << 16)).collect();
    let args = [Arg::column(&packed)];
    let floats = |w: Vec<u32>| -> Vec<[f32; 2]> {
        w.chunks(2)
            .map(|p| [f32::from_bits(p[0]), f32::from_bits(p[1])])
            .collect()
    };
    let got = floats(run_src("t_unpack2x16float", up, Freedoms::FLUSH, &args, n));
    expect_all(
        "unpack, upper: positive kept, negative flushed",
        &packed,
        &got,
        &keep_pos,
    )?;
    let got = floats(run_src("t_unpack2x16float", lo, Freedoms::FLUSH, &args, n));
    expect_all(
        "unpack, lower: positive flushed, negative kept",
        &packed,
        &got,
        &keep_neg,
    )?;
    Ok(format!(
        "{n} subnormal f16 lanes of each sign, packed and unpacked"
    ))
}

/// f32 of an integer that no f32 holds is either neighbour: the upper policy takes the larger,
/// the lower the smaller (u32 and i32, up to 2^32 − 1 whose upper neighbour is 2^32).
fn integer_conversion_either_neighbour(up: Policy, lo: Policy) -> Checked {
    let mut us: Vec<u32> = vec![(1 << 24) + 1, (1 << 25) + 3, 0x89ab_cdef, u32::MAX, 1 << 31];
    let mut s = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..2000 {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        us.push(((s >> 32) as u32) | 0x0100_0000);
    }
    let is: Vec<i32> = us.iter().map(|&u| u as i32).collect();
    let n = us.len();
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let around_u: Vec<(f32, f32)> = us.iter().map(|&u| f32_around(f64::from(u))).collect();
    let around_i: Vec<(f32, f32)> = is.iter().map(|&i| f32_around(f64::from(i))).collect();
    let (hi_u, lo_u): (Vec<f32>, Vec<f32>) = around_u.iter().map(|&(l, h)| (h, l)).unzip();
    let (hi_i, lo_i): (Vec<f32>, Vec<f32>) = around_i.iter().map(|&(l, h)| (h, l)).unzip();
    let c = Freedoms::CONVERSION;
    let ua = [Arg::column(&us)];
    let ia = [Arg::column(&is)];
    expect_all(
        "u32, upper",
        &us,
        &run_src("t_f32_u32", up, c, &ua, n),
        &bits(&hi_u),
    )?;
    expect_all(
        "u32, lower",
        &us,
        &run_src("t_f32_u32", lo, c, &ua, n),
        &bits(&lo_u),
    )?;
    expect_all(
        "i32, upper",
        &is,
        &run_src("t_f32_i32", up, c, &ia, n),
        &bits(&hi_i),
    )?;
    expect_all(
        "i32, lower",
        &is,
        &run_src("t_f32_i32", lo, c, &ia, n),
        &bits(&lo_i),
    )?;
    let inexact = around_u.iter().filter(|(l, h)| l != h).count();
    Ok(format!(
        "{n} integers ({inexact} inexact) converted to each neighbour"
    ))
}

/// `m * v` and `v * m` are dot products per lane, so every product and sum may round either
/// way: with positive entries the upper policy (each rounding up, the larger order and form)
/// never lands below the exact lane and the lower never above; each lands strictly off the
/// correctly rounded lane somewhere.
fn matrix_vector_as_dot_products(up: Policy, lo: Policy) -> Checked {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        0.1 + (s >> 11) as f32 / (1u64 << 53) as f32 * 1.9
    };
    let n = 4096;
    let cols: Vec<[[f32; 3]; 3]> = (0..n)
        .map(|_| {
            [
                [next(), next(), next()],
                [next(), next(), next()],
                [next(), next(), next()],
            ]
        })
        .collect();
    let vs: Vec<[f32; 3]> = (0..n).map(|_| [next(), next(), next()]).collect();
    let c: [Vec<[f32; 3]>; 3] = std::array::from_fn(|j| cols.iter().map(|m| m[j]).collect());
    let args = [
        Arg::column(&c[0]),
        Arg::column(&c[1]),
        Arg::column(&c[2]),
        Arg::column(&vs),
    ];
    let mut summary = Vec::new();
    for (f, vec_left) in [("t_matvec", false), ("t_vecmat", true)] {
        let exact = |k: usize, lane: usize| -> f64 {
            (0..3)
                .map(|j| {
                    let m = if vec_left {
                        cols[k][lane][j]
                    } else {
                        cols[k][j][lane]
                    };
                    f64::from(m) * f64::from(vs[k][j])
                })
                .sum()
        };
        let (mut above, mut below) = (0usize, 0usize);
        for (policy, upper) in [(up, true), (lo, false)] {
            let got = run_src(f, policy, Freedoms::ALL, &args, n);
            for k in 0..n {
                for lane in 0..3 {
                    let e = exact(k, lane);
                    let g = f32::from_bits(got[3 * k + lane]);
                    let nearest = e as f32;
                    let wrong_side = if upper {
                        f64::from(g) < e
                    } else {
                        f64::from(g) > e
                    };
                    if wrong_side {
                        return Err(format!(
                            "{f} {policy}: lane {lane} of input {k} = {g} is on the wrong side of the exact {e}"
                        ));
                    }
                    if g != nearest {
                        if upper { above += 1 } else { below += 1 }
                    }
                }
            }
        }
        if above == 0 || below == 0 {
            return Err(format!(
                "{f}: lanes off the correctly rounded value: {above} (upper), {below} (lower)"
            ));
        }
        summary.push(format!(
            "{f}: {above} lanes above, {below} below the correctly rounded"
        ));
    }
    Ok(summary.join("; "))
}

/// Inputs and outputs of the exactly rounded operations may be flushed: floor, ceil, min, max,
/// clamp and comparisons of subnormals give different results flushed and kept.
fn exact_operations_flush_their_operands(up: Policy, lo: Policy) -> Checked {
    let sub = f32::from_bits(0x0000_0100);
    let fl = Freedoms::FLUSH;
    let one = |f: &str, policy: Policy, args: &[Arg<'_>]| run_src(f, policy, fl, args, 1)[0];
    let mut wrong = Vec::new();
    let mut expect = |what: &str, got: u32, want: f32| {
        if f32::from_bits(got) != want {
            wrong.push(format!("{what}: {} (want {want})", f32::from_bits(got)));
        }
    };
    let neg = [-sub];
    let pos = [sub];
    let zero = [0.0f32];
    let unit = [1.0f32];
    expect(
        "floor(−sub), upper: flushed to −0",
        one("t_floor", up, &[Arg::column(&neg)]),
        0.0,
    );
    expect(
        "floor(−sub), lower: kept",
        one("t_floor", lo, &[Arg::column(&neg)]),
        -1.0,
    );
    expect(
        "ceil(sub), upper: kept",
        one("t_ceil", up, &[Arg::column(&pos)]),
        1.0,
    );
    expect(
        "ceil(sub), lower: flushed",
        one("t_ceil", lo, &[Arg::column(&pos)]),
        0.0,
    );
    let (p, z) = (Arg::column(&pos), Arg::column(&zero));
    expect("max(sub, 0), upper: kept", one("t_max", up, &[p, z]), sub);
    let (p, z) = (Arg::column(&pos), Arg::column(&zero));
    expect(
        "max(sub, 0), lower: flushed",
        one("t_max", lo, &[p, z]),
        0.0,
    );
    let (m, z) = (Arg::column(&neg), Arg::column(&zero));
    expect(
        "min(−sub, 0), upper: flushed",
        one("t_min", up, &[m, z]),
        0.0,
    );
    let (m, z) = (Arg::column(&neg), Arg::column(&zero));
    expect("min(−sub, 0), lower: kept", one("t_min", lo, &[m, z]), -sub);
    let clamp = |p: Policy| {
        let args = [Arg::column(&pos), Arg::column(&zero), Arg::column(&unit)];
        one("t_clamp", p, &args)
    };
    expect("clamp(sub, 0, 1), upper: kept", clamp(up), sub);
    expect("clamp(sub, 0, 1), lower: flushed", clamp(lo), 0.0);
    let lt = |p: Policy| {
        // The boolean as 0.0 / 1.0, in the bits `expect` reads.
        (one("t_lt", p, &[Arg::column(&zero), Arg::column(&pos)]) as f32).to_bits()
    };
    expect("0 < sub, upper: sub kept, true", lt(up), 1.0);
    expect("0 < sub, lower: sub flushed, false", lt(lo), 0.0);
    if wrong.is_empty() {
        Ok("floor, ceil, min, max, clamp and < each reach both".into())
    } else {
        Err(wrong.join("; "))
    }
}

/// The float after `x` toward +∞ (`up`) or −∞.
fn next_f32(x: f32, up: bool) -> f32 {
    if x == 0.0 {
        let tiny = f32::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let b = x.to_bits();
    f32::from_bits(if (x > 0.0) == up { b + 1 } else { b - 1 })
}

/// The emulation gives up 2^-12 of each allowance to cover its references' own error
/// (`prepass_cf_ulp_budget` in src/conforming/core.wgsl).
const REFERENCE_MARGIN: f64 = 1.0 / 4096.0;

/// Every result placed at its end: per input, `got` (lane 0 of every `stride` words) lies within
/// `budget` (absolute) of `exact` on side `sign`, and the next float beyond it is farther than
/// the budget less the emulation's margin. That is what "at the end of its interval" means, per
/// input: a result pushed from the host's own (unknown) error misses it on about half the
/// inputs, and the identity on all. Both policies, over all inputs; the count of misses and the
/// first one is the error.
fn every_result_at_its_end(
    function: &str,
    args: &[Arg<'_>],
    stride: usize,
    ends: &[(f64, f64)],
    (up, lo): (Policy, Policy),
) -> Checked {
    let mut out = Vec::new();
    for (policy, sign) in [(up, 1.0), (lo, -1.0)] {
        let got = run(function, policy, Freedoms::ALL, args, ends.len()).0;
        let miss: Vec<usize> = (0..ends.len())
            .filter(|&i| {
                let (e, budget) = ends[i];
                let g = f32::from_bits(got[stride * i]);
                let beyond = f64::from(next_f32(g, sign > 0.0));
                let inside = sign * (f64::from(g) - e) <= budget * (1.0 + 1e-12);
                !(inside && sign * (beyond - e) > budget * (1.0 - REFERENCE_MARGIN))
            })
            .collect();
        if let Some(&i) = miss.first() {
            let (e, budget) = ends[i];
            let g = f64::from(f32::from_bits(got[stride * i]));
            return Err(format!(
                "{function} {policy}: {} of {} results not the last float inside exact ± allowance; first: {g:e} at {:.4} of the allowance from the exact {e:e}",
                miss.len(),
                ends.len(),
                sign * (g - e) / budget
            ));
        }
        out.push(format!(
            "{policy}: {} of {} at the end",
            ends.len(),
            ends.len()
        ));
    }
    Ok(format!("{function}: {}", out.join(", ")))
}

/// `/` at 2.5 ULP of the exact quotient, every quotient, over normal operands and quotients.
fn division_reaches_both_ends(up: Policy, lo: Policy) -> Checked {
    use prepass::conforming::allowance::DIVISION_ULP;
    let xs: Vec<f32> = special_f32s()
        .into_iter()
        .filter(|x| x.abs() >= 1e-10 && x.abs() <= 1e10)
        .collect();
    let (a, b) = pairs(&xs);
    let ends: Vec<(f64, f64)> = a
        .iter()
        .zip(&b)
        .map(|(&x, &y)| {
            let e = f64::from(x) / f64::from(y);
            (e, DIVISION_ULP * ulp32(e))
        })
        .collect();
    every_result_at_its_end(
        "t_div",
        &[Arg::column(&a), Arg::column(&b)],
        1,
        &ends,
        (up, lo),
    )
}

/// `+ − ×` round every inexact result up under the upper policy and down under the lower.
fn rounding_reaches_both_neighbours(up: Policy, lo: Policy) -> Checked {
    let xs: Vec<f32> = special_f32s()
        .into_iter()
        .filter(|x| x.abs() >= 1e-10 && x.abs() <= 1e10)
        .collect();
    let (a, b) = pairs(&xs);
    let n = a.len();
    let args = [Arg::column(&a), Arg::column(&b)];
    let mut inexact = 0;
    for (f, op) in [("t_add", 0), ("t_mul", 2)] {
        let exact: Vec<f64> = (0..n)
            .map(|i| {
                let (x, y) = (f64::from(a[i]), f64::from(b[i]));
                if op == 0 { x + y } else { x * y }
            })
            .collect();
        // f64 holds these exactly: |x|, |y| within 2^±34 of each other for sums, always for
        // products of 24-bit significands.
        let keep: Vec<usize> = (0..n)
            .filter(|&i| op == 2 || (a[i].abs().log2() - b[i].abs().log2()).abs() < 25.0)
            .collect();
        for (policy, upper) in [(up, true), (lo, false)] {
            let got = run(f, policy, Freedoms::ROUNDING, &args, n).0;
            for &i in &keep {
                let (l, h) = f32_around(exact[i]);
                if l == h {
                    continue;
                }
                inexact += 1;
                let want = if upper { h } else { l };
                if f32::from_bits(got[i]) != want {
                    return Err(format!(
                        "{f}({}, {}) {policy}: {} is not the {} neighbour {want}",
                        a[i],
                        b[i],
                        f32::from_bits(got[i]),
                        if upper { "upper" } else { "lower" }
                    ));
                }
            }
        }
    }
    Ok(format!(
        "{inexact} inexact sums and products at the chosen neighbour"
    ))
}

/// `length` as `sqrt(dot(v, v))`, `sqrt` as `1 / inverseSqrt`: the emulated results leave the
/// band a correctly rounded evaluation stays in. The components are multiples of 1/64 below 4
/// (at most 8 significant bits), so every square and sum of the dot product is exact, and a
/// correctly rounded `sqrt` of it is within 0.5 ULP of the length. A result beyond 0.5 ULP is
/// one only the inherited interval allows (`inverseSqrt`'s 2 ULP and the quotient's 2.5, which
/// a greedy policy only partly cancels).
fn length_leaves_the_correctly_rounded_band(up: Policy, lo: Policy) -> Checked {
    let k = |i: i32| ((i % 511) - 255) as f32 / 64.0;
    let vs: Vec<[f32; 3]> = (1..4001)
        .map(|i| [k(i * 37), k(i * 101 + 7), k(i * 13 + 100)])
        .filter(|v| v.iter().any(|&c| c != 0.0))
        .collect();
    let n = vs.len();
    let mut worst = [0.0f64; 2];
    for (slot, policy) in [up, lo].into_iter().enumerate() {
        let got = run("t_length", policy, Freedoms::ALL, &[Arg::column(&vs)], n).0;
        for i in 0..n {
            let v = vs[i].map(f64::from);
            let e = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let d = (f64::from(f32::from_bits(got[i])) - e).abs() / ulp32(e);
            worst[slot] = worst[slot].max(d);
        }
    }
    const BAND: f64 = 0.5;
    if worst[0].max(worst[1]) <= BAND {
        return Err(format!(
            "worst {:.3} ULP (upper), {:.3} ULP (lower): inside the correctly rounded band of {BAND} ULP",
            worst[0], worst[1]
        ));
    }
    Ok(format!(
        "worst {:.3} ULP (upper), {:.3} (lower)",
        worst[0], worst[1]
    ))
}

/// `inverseSqrt` at 2 ULP of the exact `1/sqrt(x)`, every input (normal, up to 1e37).
fn inverse_sqrt_reaches_both_ends(up: Policy, lo: Policy) -> Checked {
    use prepass::conforming::allowance::INVERSE_SQRT_ULP;
    let xs: Vec<f32> = special_f32s()
        .into_iter()
        .filter(|x| (f32::MIN_POSITIVE..=1e37).contains(x))
        .collect();
    let ends: Vec<(f64, f64)> = xs
        .iter()
        .map(|&x| {
            let e = 1.0 / f64::from(x).sqrt();
            (e, INVERSE_SQRT_ULP * ulp32(e))
        })
        .collect();
    every_result_at_its_end("t_inverse_sqrt", &[Arg::column(&xs)], 1, &ends, (up, lo))
}

/// `exp2` at `3 + 2|x|` ULP of the exact value (x on [−30, 30], and 512 on [−¼, ¼], where the
/// allowance is smallest) and `log2` at 3 ULP outside [0.5, 2] and 2^-21 absolute inside (x
/// log-uniform on [2^-20, 2^20]), every input: f64's `exp2` and `log2` are within an f64 ULP,
/// far inside the emulation's margin.
fn exp2_and_log2_reach_both_ends(up: Policy, lo: Policy) -> Checked {
    use prepass::conforming::allowance;
    let mut s = prepass::sweep::SplitMix(0x5eed);
    let mut ex: Vec<f32> = (0..2048).map(|_| s.range(-30.0, 30.0)).collect();
    ex.extend((0..512).map(|_| s.range(-0.25, 0.25)));
    let lx: Vec<f32> = (0..2048)
        .map(|_| s.range(1.0, 2.0) * 2f32.powi((s.next_u64() % 41) as i32 - 20))
        .collect();
    let exp_ends: Vec<(f64, f64)> = ex
        .iter()
        .map(|&x| {
            let e = f64::from(x).exp2();
            (e, allowance::exp_ulp(f64::from(x)) * ulp32(e))
        })
        .collect();
    let log_ends: Vec<(f64, f64)> = lx
        .iter()
        .map(|&x| {
            let e = f64::from(x).log2();
            let budget = if (0.5..=2.0).contains(&x) {
                allowance::LOG_ABS
            } else {
                allowance::LOG_ULP * ulp32(e)
            };
            (e, budget)
        })
        .collect();
    let e = every_result_at_its_end("t_exp2", &[Arg::column(&ex)], 1, &exp_ends, (up, lo))?;
    let l = every_result_at_its_end("t_log2", &[Arg::column(&lx)], 1, &log_ends, (up, lo))?;
    Ok(format!("{e}; {l}"))
}

/// `unpack4x8unorm` at 3 ULP of v/255, every nonzero byte.
fn unpack_reaches_both_ends(up: Policy, lo: Policy) -> Checked {
    use prepass::conforming::allowance::UNPACK_ULP;
    let codes: Vec<u32> = (1..256u32).map(|v| v * 0x0101_0101).collect();
    let ends: Vec<(f64, f64)> = (1..256)
        .map(|v| {
            let e = f64::from(v) / 255.0;
            (e, UNPACK_ULP * ulp32(e))
        })
        .collect();
    every_result_at_its_end(
        "t_unpack4x8unorm",
        &[Arg::column(&codes)],
        4,
        &ends,
        (up, lo),
    )
}

/// One lane of `f` under policy `p` with only the freedoms `fr`.
fn one(f: &str, p: Policy, fr: Freedoms, cols: &[&[f32]]) -> f32 {
    let args: Vec<Arg<'_>> = cols.iter().map(|c| Arg::column(c)).collect();
    f32::from_bits(run(f, p, fr, &args, 1).0[0])
}

/// Each end's alternative, or what it took instead.
fn alternatives(taken: [(bool, &str); 2], said: &str) -> Checked {
    let wrong: Vec<&str> = taken.iter().filter(|t| !t.0).map(|t| t.1).collect();
    if wrong.is_empty() {
        Ok(said.into())
    } else {
        Err(wrong.join("; "))
    }
}

/// `a·b + c` fused at the upper end, unfused at the lower, where the two differ. A check of its
/// own (as are reassociation and flushing below): bundled, the identity failed the bundle on
/// fusion alone, and the other two could have gone vacuous unseen.
fn fusion_reaches_its_alternative(up: Policy, lo: Policy) -> Checked {
    // a·b = 1 + 2^-11 + 2^-24, c = −1: unfused 2^-11, fused 2^-11 + 2^-24 (larger).
    let a = [1.0 + 2f32.powi(-12)];
    let c = [-1.0f32];
    let fused = 2f32.powi(-11) + 2f32.powi(-24);
    alternatives(
        [
            (
                one("t_mad", up, Freedoms::FUSION, &[&a, &a, &c]) == fused,
                "upper does not take the fused a·b + c",
            ),
            (
                one("t_mad", lo, Freedoms::FUSION, &[&a, &a, &c]) == 2f32.powi(-11),
                "lower does not take the unfused a·b + c",
            ),
        ],
        "fused a·b + c at the upper end, unfused at the lower",
    )
}

/// `(a + b) + c` regrouped as `a + (b + c)` at the upper end, as written at the lower.
fn reassociation_reaches_its_alternative(up: Policy, lo: Policy) -> Checked {
    // 1 + 2^-24 + 2^-24: left to right 1, right to left 1 + 2^-23.
    let (x, y) = ([1.0f32], [2f32.powi(-24)]);
    alternatives(
        [
            (
                one("t_add3", up, Freedoms::REASSOCIATION, &[&x, &y, &y]) == 1.0 + 2f32.powi(-23),
                "upper does not take a + (b + c)",
            ),
            (
                one("t_add3", lo, Freedoms::REASSOCIATION, &[&x, &y, &y]) == 1.0,
                "lower does not take (a + b) + c",
            ),
        ],
        "a + (b + c) at the upper end, (a + b) + c at the lower",
    )
}

/// A positive subnormal sum kept at the upper end, flushed to 0 at the lower.
fn flush_reaches_its_alternative(up: Policy, lo: Policy) -> Checked {
    let sub = [f32::from_bits(0x100)];
    let zero = [0.0f32];
    alternatives(
        [
            (
                one("t_add", up, Freedoms::FLUSH, &[&sub, &zero]) == sub[0],
                "upper flushes a positive subnormal sum",
            ),
            (
                one("t_add", lo, Freedoms::FLUSH, &[&sub, &zero]) == 0.0,
                "lower keeps a positive subnormal sum",
            ),
        ],
        "a positive subnormal sum kept at the upper end, flushed at the lower",
    )
}

type Check = fn(Policy, Policy) -> Checked;

const CHECKS: [(&str, Check); 14] = [
    (
        "pack2x16float: either neighbouring f16",
        pack2x16float_either_neighbour,
    ),
    (
        "pack/unpack2x16float: f16 subnormals flushed",
        f16_subnormals_flushed,
    ),
    (
        "f32(u32), f32(i32): either neighbour",
        integer_conversion_either_neighbour,
    ),
    (
        "matrix × vector: dot products",
        matrix_vector_as_dot_products,
    ),
    (
        "floor/ceil/min/max/clamp/<: flushed operands",
        exact_operations_flush_their_operands,
    ),
    ("/: 2.5 ULP", division_reaches_both_ends),
    ("+ − ×: either neighbour", rounding_reaches_both_neighbours),
    (
        "length: inherited",
        length_leaves_the_correctly_rounded_band,
    ),
    ("inverseSqrt: 2 ULP", inverse_sqrt_reaches_both_ends),
    ("unpack4x8unorm: 3 ULP", unpack_reaches_both_ends),
    (
        "exp2, log2: 3 + 2|x| ULP, 3 ULP / 2^-21",
        exp2_and_log2_reach_both_ends,
    ),
    ("fusion: a·b + c", fusion_reaches_its_alternative),
    (
        "reassociation: (a + b) + c",
        reassociation_reaches_its_alternative,
    ),
    ("flush: subnormal sums", flush_reaches_its_alternative),
];

#[test]
fn every_freedom_reaches_its_ends() {
    let mut failed = Vec::new();
    for (name, check) in CHECKS {
        match check(Policy::Upper, Policy::Lower) {
            Ok(s) => eprintln!("{name}: {s}"),
            Err(e) => failed.push(format!("{name}: {e}")),
        }
    }
    assert!(
        failed.is_empty(),
        "freedoms not reached:\n{}",
        failed.join("\n")
    );
}

#[test]
fn every_freedom_check_fails_under_identity() {
    let mut passed = Vec::new();
    for (name, check) in CHECKS {
        match check(Policy::Identity, Policy::Identity) {
            Ok(s) => passed.push(format!("{name}: {s}")),
            Err(e) => eprintln!("{name} under identity fails as it must: {e}"),
        }
    }
    assert!(
        passed.is_empty(),
        "these freedom checks pass under Policy::Identity, so they cannot tell an emulation \
         that does not use the freedom:\n{}",
        passed.join("\n")
    );
}
