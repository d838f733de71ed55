//! `wgsl/roughness.wgsl` on the adapter: log-range specular exponent, measured against f64 over
//! every `f32` power in `[1, 8192]`, every code, and the bad inputs; twins `src/roughness.rs`.

mod common;

use common::{gpu, run_kernel};
use prepass::harness::Arg;
use prepass::roughness::{self, quantisation_limit};
use prepass::sweep::roughness::{
    ONE_BITS, decode_all_codes, log_roughness_all_powers, powers_in, profile_bin_start,
    roundtrip_all_powers,
};
use prepass::wgsl::ROUGHNESS;
use prepass::{assert_at_least, assert_within, assert_within_abs};

const BASELINES: &str = include_str!("baselines/roughness.wgsl");
const U: f64 = 1.0 / 16_777_216.0; // 2^-24, unit roundoff of f32

#[test]
fn every_power_up_to_8192_round_trips_at_the_quantisation_limit() {
    let max = 8192.0f32;
    let r = log_roughness_all_powers(gpu(), max).unwrap();
    assert_eq!(r.count, powers_in(max));
    assert_eq!(r.count, 13 * (1 << 23) + 1);
    let limit = quantisation_limit(8192.0);
    // Derivation. Encoding is exact (integer comparisons with rounded-up boundaries), decoding is
    // correctly rounded (relative error ≤ 2^-24). So |decode(encode(p)) − p|/p ≤ limit + 2^-24·
    // (1 + limit): the worst power sits just above a boundary T (rounded up to the step
    // T·2^(L/510)). The nearest f32 above each boundary is within one ULP (≤ 2^-23 relative),
    // so the sweep attains at least limit − 2^-23·(1 + limit) − 2^-24·(1 + limit). Both sides
    // are within 2e-7 of the limit, well inside the 1e-6.
    let excess = r.relative.max - limit;
    let at = f32::from_bits(ONE_BITS + r.relative.argmax as u32);
    assert_within_abs!(
        r.relative.max,
        limit,
        3.0 * U * (1.0 + limit),
        "derivation above: 2^-23 + 2^-24 of (1 + limit) below, 2^-24·(1 + limit) above",
        "max relative error vs quantisation_limit (at power {at})"
    );
    assert_within_abs!(
        r.relative.max,
        limit,
        1e-6,
        "the issue's 1e-6 (derivation above: both sides within 2e-7)",
        "max relative error vs quantisation_limit (at power {at})"
    );
    assert_eq!(r.relative.nan_count, 0);
    // Constant relative precision: no bin exceeds the limit, and every bin that holds a code
    // boundary (a half-integer of t = 255·log2(p)/13) reaches it, as low powers do.
    assert_eq!(r.profile.len(), 13 * 16);
    let mut with_boundary = 0;
    for (b, &(max, _)) in r.profile.iter().enumerate() {
        let (lo, hi) = (profile_bin_start(b), profile_bin_start(b + 1));
        let t = |p: f64| 255.0 * p.log2() / 13.0 - 0.5;
        assert_within!(
            max,
            limit + 3.0 * U,
            "no bin exceeds the limit (+ 3u, derivation above)",
            "bin {b} (from p = {lo})"
        );
        if t(hi).floor() > t(lo).floor() && t(hi).fract() > 1e-3 {
            assert_at_least!(
                max,
                limit - 2e-7 - 3.0 * U,
                "a bin with a code boundary reaches the limit (within 2e-7 + 3u, derivation above)",
                "bin {b} (from p = {lo})"
            );
            with_boundary += 1;
        }
    }
    assert!(with_boundary > 150, "{with_boundary}");
    // Exact encoder and exact table decoder: the twins must agree bit for bit, and the codes
    // must be the exact nearest codes in log range.
    assert_eq!(r.twin_code_mismatches, Some(0));
    assert_eq!(r.twin_decode_mismatches, Some(0));
    assert_eq!(r.exact_code_mismatches, Some(0));
    eprintln!(
        "log range, max 8192, {} powers: max rel {:.9} (limit {:.9}, excess {:.2e}) at p={}, \
         mean {:.6}, rms {:.6}, at p=1 {:.3e}, max over p<=2 {:.6}",
        r.count,
        r.relative.max,
        limit,
        excess,
        f32::from_bits(ONE_BITS + r.relative.argmax as u32),
        r.relative.mean(),
        r.relative.rms(),
        r.at_one,
        r.max_below_two
    );
}

#[test]
fn every_code_decodes_correctly_rounded_for_power_of_two_ranges() {
    for max in [8192.0f32, 2.0, 256.0, 2f32.powi(127)] {
        let d = decode_all_codes(gpu(), max).unwrap();
        // Bound: ≤ 0.5 ULP. The table entry is correctly rounded and the exponent add is exact;
        // the f64 reference is within ~1e-15 relative (≤ 1e-7 ULP), hence the 1e-6 slack.
        assert_within!(
            d.ulps.max,
            0.5 + 1e-6,
            "comment above: correctly rounded table entry, exact exponent add; 1e-6 f64 slack",
            "max {max}: ULP at code {}",
            d.ulps.argmax
        );
        assert_eq!(d.ulps.nan_count, 0);
        for (k, v) in d.values.iter().enumerate() {
            let twin = roughness::decode_log_roughness(k as u32, max);
            assert_eq!(v.to_bits(), twin.to_bits(), "max {max}, code {k}");
        }
        assert_eq!(d.values[0], 1.0);
        assert_eq!(d.values[255], max);
        eprintln!(
            "decode, max {max}: max {:.4} ULP, mean {:.4} ULP over 256 codes",
            d.ulps.max,
            d.ulps.mean()
        );
    }
}

#[test]
fn linear_8bit_baselines_are_measured_beside_it() {
    let src = format!("{ROUGHNESS}\n{BASELINES}");
    for (enc, dec) in [
        ("baseline_linear8_encode", "baseline_linear8_decode"),
        ("baseline_affine8_encode", "baseline_affine8_decode"),
    ] {
        let r = roundtrip_all_powers(gpu(), &src, enc, dec, 8192.0, None, false).unwrap();
        eprintln!(
            "{enc}: max rel {:.6} at p={}, mean {:.6}, rms {:.6}, at p=1 {:.6}, max over p<=2 {:.6}",
            r.relative.max,
            f32::from_bits(ONE_BITS + r.relative.argmax as u32),
            r.relative.mean(),
            r.relative.rms(),
            r.at_one,
            r.max_below_two
        );
        if enc == "baseline_linear8_encode" {
            // p = 1: 255/8192 = 0.031 rounds to code 0, which decodes to 0 — all of it lost.
            assert_eq!(r.at_one, 1.0);
        } else {
            // Half a step is (8192 − 1)/510 ≈ 16.06: a power just below 17.06 returns 1, a
            // relative error of ≈ 16.06/17.06 = 0.9414.
            let half = 8191.0 / 510.0;
            let want = half / (1.0 + half);
            assert_within_abs!(
                r.relative.max,
                want,
                < 1e-3,
                "comment above: half a step (8191/510) lost just below 17.06",
                "{enc}: max relative error"
            );
        }
    }
}

/// Powers spread over `[1, max]` for the non-power-of-two ranges: every 61st f32 pattern.
fn sampled_powers(max: f32) -> Vec<f32> {
    (ONE_BITS..=max.to_bits())
        .step_by(61)
        .map(f32::from_bits)
        .chain([max])
        .collect()
}

#[test]
fn general_ranges_stay_within_their_derived_bound() {
    for max in [1000.0f32, 100.5, 3.0e6] {
        let limit = quantisation_limit(f64::from(max));
        let dec = roughness::bounds::general_range_decode(max);
        let bound = roughness::bounds::general_range(max);
        let ps = sampled_powers(max);
        let out = run_kernel(
            &format!(
                "{ROUGHNESS}\nfn rt(p: f32, m: f32) -> vec2<u32> {{ let c = encode_log_roughness(p, m); \
                     return vec2<u32>(c, bitcast<u32>(decode_log_roughness(c, m))); }}"
            ),
            "rt",
            &[Arg::column(&ps), Arg::splat_f32(max)],
            ps.len() as u64,
        );
        let mut worst = 0.0f64;
        let (mut code_diff, mut value_diff) = (0u64, 0u64);
        for (p, w) in ps.iter().zip(out.words().chunks_exact(2)) {
            let v = f64::from(f32::from_bits(w[1]));
            worst = worst.max((v - f64::from(*p)).abs() / f64::from(*p));
            if roughness::encode_log_roughness(*p, max) != w[0] {
                code_diff += 1;
            }
            if roughness::decode_log_roughness(w[0], max).to_bits() != w[1] {
                value_diff += 1;
            }
        }
        assert_within!(
            worst,
            bound,
            "roughness::bounds::general_range (derivation in its rustdoc)",
            "max {max}: relative error"
        );
        // Every code's decoded value against the exact max^(k/255): within the decode part of
        // the bound above.
        let d = decode_all_codes(gpu(), max).unwrap();
        let dec_rel = d
            .values
            .iter()
            .enumerate()
            .map(|(k, &v)| {
                let e = roughness::exact::decode(k as u32, f64::from(max));
                (f64::from(v) - e).abs() / e
            })
            .fold(0.0, f64::max);
        assert_within!(
            dec_rel,
            dec + U,
            "roughness::bounds::general_range_decode + u (derivation in its rustdoc)",
            "max {max}: decode relative error"
        );
        eprintln!(
            "general range {max}: decode of every code max {:.2} ULP ({dec_rel:.2e} relative, \
             derived bound {:.2e})",
            d.ulps.max,
            dec + U
        );
        assert_at_least!(
            worst,
            limit * 0.99,
            "a dense enough sweep reaches the quantisation limit (within 1%)",
            "max {max}: sweep too sparse"
        );
        eprintln!(
            "general range {max}: {} sampled powers, max rel {worst:.7} (limit {limit:.7}, bound \
             {bound:.7}); Rust twin differs in {code_diff} codes and {value_diff} decoded values (of the sampled round trips)",
            ps.len()
        );
    }
}

#[test]
fn bad_input_gives_the_documented_answers_on_both_sides() {
    let powers = [
        f32::NAN,
        -f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -1.0,
        -0.0,
        0.0,
        f32::from_bits(1),
        0.5,
        1.0,
        1.5,
        8191.0,
        8192.0,
        1e30,
        f32::MAX,
    ];
    let maxes = [
        8192.0f32,
        1000.0,
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1.0,
        0.5,
        0.0,
        -8192.0,
        f32::MAX,
        2f32.powi(127),
    ];
    let (mut ps, mut ms) = (Vec::new(), Vec::new());
    for &m in &maxes {
        for &p in &powers {
            ps.push(p);
            ms.push(m);
        }
    }
    let codes = run_kernel(
        ROUGHNESS,
        "encode_log_roughness",
        &[Arg::column(&ps), Arg::column(&ms)],
        ps.len() as u64,
    );
    for (i, &c) in codes.as_u32().iter().enumerate() {
        let (p, m) = (ps[i], ms[i]);
        assert_eq!(c, roughness::encode_log_roughness(p, m), "p={p} max={m}");
        let degenerate = m.is_nan() || m <= 1.0;
        let want = if degenerate || p.is_nan() || p <= 1.0 {
            Some(0)
        } else if p >= m.min(2f32.powi(127)) {
            Some(255)
        } else {
            None
        };
        if let Some(w) = want {
            assert_eq!(c, w, "p={p} max={m}");
        }
    }
    let ks: Vec<u32> = [0u32, 1, 128, 254, 255, 256, 1000, u32::MAX].repeat(maxes.len());
    let ms2: Vec<f32> = maxes.iter().flat_map(|&m| [m; 8]).collect();
    let values = run_kernel(
        ROUGHNESS,
        "decode_log_roughness",
        &[Arg::column(&ks), Arg::column(&ms2)],
        ks.len() as u64,
    );
    for (i, &v) in values.as_f32().iter().enumerate() {
        let (k, m) = (ks[i], ms2[i]);
        assert!(v.is_finite() && v >= 1.0, "code {k} max {m}: {v}");
        let twin = roughness::decode_log_roughness(k, m);
        if matches!(roughness::range(m), roughness::Range::General(_)) {
            // Transcendentals: the twin may differ by the exp2/log2 allowance only.
            assert_within_abs!(
                f64::from(v) / f64::from(twin),
                1.0,
                < 1e-5,
                "comment above: the exp2/log2 allowance",
                "code {k} max {m}: adapter / twin"
            );
        } else {
            assert_eq!(v.to_bits(), twin.to_bits(), "code {k} max {m}");
        }
        if m.is_nan() || m <= 1.0 {
            assert_eq!(v, 1.0);
        } else if k >= 255 {
            // The top code is max_power itself, 2^127 for larger (and +Inf) ranges.
            assert_eq!(v, m.min(2f32.powi(127)));
        }
    }
}

#[test]
fn normal_and_roughness_share_one_texel() {
    // Every 24-bit normal pattern with junk in byte 3, against a few codes (and out-of-range).
    let n = 1u64 << 24;
    for code in [0u32, 1, 128, 255, 256, u32::MAX] {
        let src = format!(
            "{ROUGHNESS}\nfn t(i: u32, code: u32) -> vec3<u32> {{ let nrm = i | ((i * 2654435769u) & 0xff000000u); \
             let t = pack_normal_xyz8_log_roughness(nrm, code); \
             return vec3<u32>(t, normal_xyz8_from_log_roughness_texel(t), log_roughness_code_from_texel(t)); }}"
        );
        let out = run_kernel(
            &src,
            "t",
            &[Arg::Index { start: 0 }, Arg::splat_u32(code)],
            n,
        );
        for (i, w) in out.words().chunks_exact(3).enumerate() {
            let i = i as u32;
            let nrm = i | (i.wrapping_mul(2_654_435_769) & 0xff00_0000);
            let t = roughness::pack_normal_xyz8_log_roughness(nrm, code);
            assert_eq!(w[0], t, "normal {i:#x} code {code}");
            assert_eq!(w[1], i);
            assert_eq!(w[2], code.min(255));
            assert_eq!(roughness::normal_xyz8_from_log_roughness_texel(t), i);
            assert_eq!(roughness::log_roughness_code_from_texel(t), code.min(255));
        }
    }
}

/// The power-of-two ranges are integer constructions, so their promise — the exact nearest
/// code, and the decode bit-identical to the twin — must hold on every conforming adapter: run
/// under every worst-case policy of the emulation on sampled powers (every 61st f32 in
/// [1, max]) and every code. General ranges keep their derived bound under emulation too.
#[test]
fn every_range_keeps_its_promise_under_emulation() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    let src = format!(
        "{ROUGHNESS}\nfn rt(p: f32, m: f32) -> vec2<u32> {{ let c = encode_log_roughness(p, m); \
         return vec2<u32>(c, bitcast<u32>(decode_log_roughness(c, m))); }}"
    );
    // The interval enclosure of every result a conforming adapter may give
    // (prepass::conforming::interval, flushing allowed), on every 64th sampled power (the
    // evaluator runs on the CPU). Power-of-two ranges: where the enclosure is one code, it must
    // be the exact code with the twin's decode, a machine-checked exactness; within 2^-8 of a
    // code boundary the log2 candidate may be either of two codes, and the evaluator, which
    // does not split cases, carries both through the boundary comparison that settles the
    // candidate (the dependency problem), so there it can only check that the exact code is
    // among them — those powers are counted, and the emulation below checks them exactly.
    // General ranges: the decode's farther end, over every code the enclosure holds, must keep
    // the derived bound.
    use prepass::conforming::interval::{Enclosure, Value};
    let enclosure = Enclosure::new(&src, true).unwrap();
    for max in [8192.0f32, 256.0, 1000.0, 100.5, 3.0e6] {
        let (mut worst, mut codes_wide) = (0.0f64, 0u64);
        let ps: Vec<f32> = sampled_powers(max).into_iter().step_by(64).collect();
        for &p in &ps {
            let v = enclosure
                .of("rt", &[Value::f32s(&[p]), Value::f32s(&[max])])
                .unwrap_or_else(|e| panic!("max {max}, power {p:e}: {e}"));
            let Value::U32(l) = v else {
                panic!("rt returns vec2<u32>")
            };
            let (code, bits) = (l[0], l[1]);
            codes_wide += u64::from(code.0 != code.1);
            let exact = roughness::exact::encode(f64::from(p), f64::from(max));
            assert!(
                code.0 <= exact && exact <= code.1,
                "max {max}, power {p:e}: the exact code {exact} is outside the enclosure {code:?}"
            );
            let pow2 = max.log2().fract() == 0.0;
            if pow2 && code.0 == code.1 {
                let twin = roughness::decode_log_roughness(exact, max).to_bits();
                assert_eq!(
                    bits,
                    (twin, twin),
                    "max {max}, power {p:e}: the decode's enclosure is not the twin's value"
                );
            }
            if !pow2 {
                for b in [bits.0, bits.1] {
                    let d = f64::from(f32::from_bits(b));
                    worst = worst.max((d - f64::from(p)).abs() / f64::from(p));
                }
            }
        }
        eprintln!(
            "machine-derived, max {max}: {} powers, max rel {worst:.7} (general ranges), {codes_wide} with more than one code possible",
            ps.len()
        );
        if max.log2().fract() != 0.0 {
            assert_within!(
                worst,
                roughness::bounds::general_range(max),
                "roughness::bounds::general_range, against the machine-derived enclosure",
                "max {max}: relative error of the enclosure's farther end"
            );
        }
    }
    for policy in Policy::WORST {
        let k = EmulatedKernel::new(gpu(), &src, "rt", &Emulation::new(policy)).unwrap();
        for max in [8192.0f32, 256.0, 1000.0, 100.5, 3.0e6] {
            let ps = sampled_powers(max);
            let (out, _) = k
                .run(&[Arg::column(&ps), Arg::splat_f32(max)], ps.len() as u64)
                .unwrap();
            let (mut code_diff, mut value_diff, mut worst) = (0u64, 0u64, 0.0f64);
            for (p, w) in ps.iter().zip(out.words().chunks_exact(2)) {
                let v = f64::from(f32::from_bits(w[1]));
                worst = worst.max((v - f64::from(*p)).abs() / f64::from(*p));
                code_diff +=
                    u64::from(roughness::exact::encode(f64::from(*p), f64::from(max)) != w[0]);
                value_diff +=
                    u64::from(roughness::decode_log_roughness(w[0], max).to_bits() != w[1]);
            }
            let limit = quantisation_limit(f64::from(max));
            eprintln!(
                "emulated {policy}, max {max}: {} powers, max rel {worst:.7} (limit {limit:.7}); {code_diff} codes off the exact nearest, {value_diff} decodes off the twin",
                ps.len()
            );
            if max.log2().fract() == 0.0 {
                assert_eq!(
                    code_diff, 0,
                    "{policy} max {max}: the integer encoder is not exact under emulation"
                );
                assert_eq!(
                    value_diff, 0,
                    "{policy} max {max}: the table decoder differs from the twin under emulation"
                );
            } else {
                let bound = roughness::bounds::general_range(max);
                assert_within!(
                    worst,
                    bound,
                    "roughness::bounds::general_range (derivation in its rustdoc)",
                    "{policy} max {max}: relative error"
                );
            }
        }
    }
}
