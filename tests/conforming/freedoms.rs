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

/// Per input, how far the f32 result in `got` (lane 0 of every `stride` words) lies from
/// `exact` toward an end, in the spec's ULPs: `sign` +1 toward the upper end, −1 the lower.
fn toward_end(got: &[u32], stride: usize, exact: &[f64], sign: f64) -> Vec<f64> {
    exact
        .iter()
        .enumerate()
        .map(|(i, &e)| sign * (f64::from(f32::from_bits(got[stride * i])) - e) / ulp32(e))
        .collect()
}

fn most(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
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

/// `/` reaches 2 ULP (the allowance less the host's 0.5) above the exact quotient under the
/// upper policy and below it under the lower, over normal operands and quotients.
fn division_reaches_both_ends(up: Policy, lo: Policy) -> Checked {
    let xs: Vec<f32> = special_f32s()
        .into_iter()
        .filter(|x| x.abs() >= 1e-10 && x.abs() <= 1e10)
        .collect();
    let (a, b) = pairs(&xs);
    let n = a.len();
    let args = [Arg::column(&a), Arg::column(&b)];
    let exact: Vec<f64> = a
        .iter()
        .zip(&b)
        .map(|(&x, &y)| f64::from(x) / f64::from(y))
        .collect();
    let reach = |policy: Policy, sign: f64| -> f64 {
        let got = run("t_div", policy, Freedoms::ALL, &args, n).0;
        most(&toward_end(&got, 1, &exact, sign))
    };
    let (above, below) = (reach(up, 1.0), reach(lo, -1.0));
    if above < 2.0 || below < 2.0 {
        return Err(format!(
            "reached {above:.3} ULP above (upper) and {below:.3} below (lower), want ≥ 2 each"
        ));
    }
    Ok(format!("{above:.3} ULP above, {below:.3} below"))
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
/// band a correctly rounded evaluation stays in. Per operation correctly rounded, the three
/// squares and two sums are within 5 roundings of 2^-24 relative of the dot product, `sqrt`
/// halves that (2.5·2^-24) and rounds once more (0.5 ULP): at most 3 ULP of the length, since
/// its ULP is at least 2^-24 of it. So a result beyond 3 ULP is one only the emulation makes.
fn length_leaves_the_correctly_rounded_band(up: Policy, lo: Policy) -> Checked {
    let vs: Vec<[f32; 3]> = (0..4000)
        .map(|i| {
            let t = i as f32 * 0.37;
            [t.sin() * 3.0, (t * 1.3).cos(), 0.5 + (t * 0.7).sin()]
        })
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
    const BAND: f64 = 3.0;
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

/// `inverseSqrt`: the upper policy never lands below the exact value and reaches at least 1 ULP
/// above it (the 2 ULP allowance less the refined value's 0.5 and the push's rounding back
/// toward it); the lower mirrors it.
fn inverse_sqrt_reaches_both_sides(up: Policy, lo: Policy) -> Checked {
    let xs: Vec<f32> = special_f32s()
        .into_iter()
        .filter(|x| (f32::MIN_POSITIVE..=1e37).contains(x))
        .collect();
    let n = xs.len();
    let exact: Vec<f64> = xs.iter().map(|&x| 1.0 / f64::from(x).sqrt()).collect();
    let mut out = Vec::new();
    for (policy, sign) in [(up, 1.0), (lo, -1.0)] {
        let got = run(
            "t_inverse_sqrt",
            policy,
            Freedoms::ALL,
            &[Arg::column(&xs)],
            n,
        )
        .0;
        let d = toward_end(&got, 1, &exact, sign);
        let (least, most) = (d.iter().copied().fold(f64::INFINITY, f64::min), most(&d));
        if least < 0.0 || most < 1.0 {
            return Err(format!(
                "{policy}: between {least:.3} and {most:.3} ULP toward its end; want ≥ 0 everywhere and ≥ 1 somewhere"
            ));
        }
        out.push(format!("{policy}: {least:.3}–{most:.3} ULP toward its end"));
    }
    Ok(out.join("; "))
}

/// `exp2` (3 + 2|x| ULP) and `log2` (3 ULP outside [0.5, 2]) push every result by the allowance
/// less the host's assumed error (`HostAccuracy::exp_ulp`, `log_ulp`), from the host's own
/// result, whose error is not known per input: no single result is promised to reach an end.
/// What is promised is the shift: each result moves by its push, while a conforming host's
/// errors average out, so the mean of offset / push over many inputs is at least ½ toward the
/// policy's end (a host biased by more than half a push in one direction fails here, as its
/// results would not reach that end). Inputs: exp2 on [1, 4) (push ≥ 2.5 ULP), log2 on
/// [2^10, 2^18) (push 1 ULP), 2048 each.
fn exp2_and_log2_shift_toward_both_ends(up: Policy, lo: Policy) -> Checked {
    use prepass::conforming::{HostAccuracy, allowance};
    let host = HostAccuracy::default();
    let mut s = prepass::sweep::SplitMix(0x5eed);
    let ex: Vec<f32> = (0..2048).map(|_| s.range(1.0, 4.0)).collect();
    let lx: Vec<f32> = (0..2048)
        .map(|_| s.range(1.0, 2.0) * 2f32.powi(10 + (s.next_u64() % 8) as i32))
        .collect();
    // (function, inputs, per input the exact result and the push in ULPs)
    type Case<'a> = (&'static str, &'a [f32], Vec<(f64, f64)>);
    let cases: [Case<'_>; 2] = [
        (
            "t_exp2",
            &ex,
            ex.iter()
                .map(|&x| {
                    let x = f64::from(x);
                    (x.exp2(), allowance::exp_ulp(x) - host.exp_ulp)
                })
                .collect(),
        ),
        (
            "t_log2",
            &lx,
            lx.iter()
                .map(|&x| (f64::from(x).log2(), allowance::LOG_ULP - host.log_ulp))
                .collect(),
        ),
    ];
    let mut out = Vec::new();
    for (function, xs, exact) in &cases {
        let e: Vec<f64> = exact.iter().map(|&(e, _)| e).collect();
        for (policy, sign) in [(up, 1.0), (lo, -1.0)] {
            let got = run(
                function,
                policy,
                Freedoms::EXP_LOG,
                &[Arg::column(xs)],
                xs.len(),
            )
            .0;
            let d = toward_end(&got, 1, &e, sign);
            let mean = d
                .iter()
                .zip(exact)
                .map(|(d, &(_, push))| d / push)
                .sum::<f64>()
                / d.len() as f64;
            if mean < 0.5 {
                return Err(format!(
                    "{function} {policy}: mean offset over the push {mean:.3} toward its end, want ≥ 0.5"
                ));
            }
            out.push(format!("{function} {policy}: mean {mean:.3} of the push"));
        }
    }
    Ok(out.join("; "))
}

/// `unpack4x8unorm` reaches 2 ULP above v/255 (3 less the 0.5 of its correctly rounded start,
/// rounded down to whole half ULPs) under the upper policy and 2 below under the lower.
fn unpack_reaches_both_ends(up: Policy, lo: Policy) -> Checked {
    let codes: Vec<u32> = (1..256u32).map(|v| v * 0x0101_0101).collect();
    let exact: Vec<f64> = (1..256).map(|v| f64::from(v) / 255.0).collect();
    let n = codes.len();
    let mut out = Vec::new();
    for (policy, sign) in [(up, 1.0), (lo, -1.0)] {
        let got = run(
            "t_unpack4x8unorm",
            policy,
            Freedoms::ALL,
            &[Arg::column(&codes)],
            n,
        )
        .0;
        let reached = most(&toward_end(&got, 4, &exact, sign));
        if reached < 2.0 {
            return Err(format!(
                "{policy}: reached {reached:.3} ULP toward its end, want ≥ 2"
            ));
        }
        out.push(format!("{policy}: {reached:.3} ULP"));
    }
    Ok(out.join("; "))
}

/// `a·b + c` fused, `(a + b) + c` reassociated, subnormal sums flushed: each alternative is
/// taken by the policy whose end it is (inputs where the alternatives differ).
fn forms_and_flushes_reach_their_alternatives(up: Policy, lo: Policy) -> Checked {
    let one = |f: &str, p: Policy, fr: Freedoms, cols: &[&[f32]]| -> f32 {
        let args: Vec<Arg<'_>> = cols.iter().map(|c| Arg::column(c)).collect();
        f32::from_bits(run(f, p, fr, &args, 1).0[0])
    };
    let mut wrong = Vec::new();
    // a·b = 1 + 2^-11 + 2^-24, c = −1: unfused 2^-11, fused 2^-11 + 2^-24 (larger).
    let a = [1.0 + 2f32.powi(-12)];
    let c = [-1.0f32];
    let fused = 2f32.powi(-11) + 2f32.powi(-24);
    if one("t_mad", up, Freedoms::FUSION, &[&a, &a, &c]) != fused {
        wrong.push("upper does not take the fused a·b + c");
    }
    if one("t_mad", lo, Freedoms::FUSION, &[&a, &a, &c]) != 2f32.powi(-11) {
        wrong.push("lower does not take the unfused a·b + c");
    }
    // 1 + 2^-24 + 2^-24: left to right 1, right to left 1 + 2^-23.
    let (x, y) = ([1.0f32], [2f32.powi(-24)]);
    if one("t_add3", up, Freedoms::REASSOCIATION, &[&x, &y, &y]) != 1.0 + 2f32.powi(-23) {
        wrong.push("upper does not take a + (b + c)");
    }
    if one("t_add3", lo, Freedoms::REASSOCIATION, &[&x, &y, &y]) != 1.0 {
        wrong.push("lower does not take (a + b) + c");
    }
    let sub = [f32::from_bits(0x100)];
    let zero = [0.0f32];
    if one("t_add", up, Freedoms::FLUSH, &[&sub, &zero]) != sub[0] {
        wrong.push("upper flushes a positive subnormal sum");
    }
    if one("t_add", lo, Freedoms::FLUSH, &[&sub, &zero]) != 0.0 {
        wrong.push("lower keeps a positive subnormal sum");
    }
    if wrong.is_empty() {
        Ok("fused, reassociated and flushed forms each taken at their end".into())
    } else {
        Err(wrong.join("; "))
    }
}

type Check = fn(Policy, Policy) -> Checked;

const CHECKS: [(&str, Check); 12] = [
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
    ("inverseSqrt: 2 ULP", inverse_sqrt_reaches_both_sides),
    ("unpack4x8unorm: 3 ULP", unpack_reaches_both_ends),
    (
        "exp2, log2: 3 + 2|x|, 3 ULP",
        exp2_and_log2_shift_toward_both_ends,
    ),
    (
        "fusion, reassociation, flush",
        forms_and_flushes_reach_their_alternatives,
    ),
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
