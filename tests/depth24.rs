//! `wgsl/depth24.wgsl` on the adapter, exhaustively over all 2^24 codes, against exact references
//! and against its Rust twin `src/depth24.rs`.

mod common;

use common::{gpu, run_kernel};
use glam::Vec3;
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::harness::Arg;
use prepass::precision::inputs::{ChannelError, all_codes_rgb8};
use prepass::precision::metrics::Mismatches;
use prepass::sweep::depth24::{
    CODES, Hyperbolic, RECOVERY_CASES, hyperbolic_all, measure_hyperbolic, recover_all,
    searched_hyperbolic, searched_recovery,
};
use prepass::wgsl::DEPTH24;
use prepass::{assert_at_least, assert_within};
use std::sync::OnceLock;

const BASELINES: &str = include_str!("baselines/depth24.wgsl");

fn with_baselines() -> String {
    format!("{DEPTH24}\n{BASELINES}")
}

/// Each recovery sweep, run once per test binary: the assertion tests below and the published
/// table ([`figures_are_published`]) read the same measurement. Per case: the shipped function's
/// mismatches (the Rust twin checked on the same channels, inside) and the unrounded
/// baseline's.
struct RecoveryRow {
    ours: Mismatches<u32>,
    twin: Mismatches<u32>,
    baseline: u64,
}

fn recovery(case: usize) -> &'static RecoveryRow {
    static ROWS: [OnceLock<RecoveryRow>; RECOVERY_CASES.len()] =
        [const { OnceLock::new() }; RECOVERY_CASES.len()];
    ROWS[case].get_or_init(|| {
        let (error, flip) = RECOVERY_CASES[case];
        let r = recover_all(gpu(), DEPTH24, "depth24_from_rgb8", error, flip).unwrap();
        let rgb = all_codes_rgb8(error, flip);
        let twin = Mismatches::count(&r.codes, |i| depth24::depth24_from_rgb8(Vec3::from(rgb[i])));
        let src = with_baselines();
        let base = recover_all(
            gpu(),
            &src,
            "baseline_depth24_from_rgb8_unrounded",
            error,
            flip,
        )
        .unwrap();
        RecoveryRow {
            ours: r.mismatches,
            twin,
            baseline: base.mismatches.count,
        }
    })
}

/// Recovery with per-channel rounding returns every code exactly under each channel error, and
/// the Rust twin returns the same codes from the same channels.
fn recovery_case(case: usize) {
    let (error, flip) = RECOVERY_CASES[case];
    let r = recovery(case);
    // Bound: 0 mismatches. Each channel is within 0.45/255 (or 3 ULP ≈ 1e-7) of byte/255, so
    // 255·c is within 0.45 + 2^-16 of the byte and round() cannot pick a neighbour.
    assert_eq!(
        r.ours.count, 0,
        "{error} (flip {flip}): first (code, got, want) = {:?}",
        r.ours.first
    );
    assert_eq!(r.twin.count, 0, "Rust twin differs: {:?}", r.twin.first);
}

#[test]
fn rgb8_recovery_exact_channels_all_codes() {
    recovery_case(0);
}

#[test]
fn rgb8_recovery_3ulp_up_and_down_all_codes() {
    recovery_case(1);
    recovery_case(2);
}

#[test]
fn rgb8_recovery_045_over_255_up_and_down_all_codes() {
    recovery_case(3);
    recovery_case(4);
}

#[test]
fn unrounded_baseline_reproduces_the_talks_problem() {
    for (case, (error, flip)) in RECOVERY_CASES.into_iter().enumerate() {
        let m = recovery(case).baseline;
        if matches!(error, ChannelError::Offset(_)) {
            // ±0.45/255 on r alone moves the unrounded total by 0.45·65536 codes: nearly every
            // code must come back wrong. If this passes with few mismatches the sweep is broken.
            assert_at_least!(
                m,
                > CODES / 2,
                "comment above: ±0.45/255 on r moves 0.45·65536 codes, nearly all wrong",
                "{error}: mismatches"
            );
        }
        eprintln!("unrounded baseline, channels {error} (flip {flip}): {m} of {CODES} codes wrong");
    }
}

/// The functions of [`hyperbolic`]: the shipped one and the two baselines.
const HYPERBOLIC: [&str; 3] = [
    "hyperbolic_depth_from_depth24",
    "baseline_hyperbolic_divide",
    "baseline_hyperbolic_reciprocal",
];

/// Each hyperbolic-depth sweep over all 2^24 codes, run once per test binary (shipped function
/// and baselines, on the adapter).
fn hyperbolic(function: &str) -> &'static Hyperbolic {
    static ROWS: [OnceLock<Hyperbolic>; HYPERBOLIC.len()] =
        [const { OnceLock::new() }; HYPERBOLIC.len()];
    let k = HYPERBOLIC
        .iter()
        .position(|f| *f == function)
        .expect("a measured function");
    ROWS[k].get_or_init(|| hyperbolic_all(gpu(), &with_baselines(), function).unwrap())
}

#[test]
fn packed_paths_are_exact_and_match_the_twin_for_every_code() {
    let packed =
        run_kernel(DEPTH24, "pack_depth24", &[Arg::Index { start: 0 }], CODES).into_words();
    let twin = Mismatches::count(&packed, |d| depth24::pack_depth24(d as u32));
    assert_eq!(twin.count, 0, "pack_depth24 twin differs: {:?}", twin.first);
    assert!(
        packed.iter().all(|p| p >> 24 == 0),
        "alpha byte must stay 0"
    );

    // Alpha is not part of the code: fill it with junk before unpacking.
    let with_alpha: Vec<u32> = packed
        .iter()
        .enumerate()
        .map(|(d, p)| p | ((d as u32).wrapping_mul(0x9e37_79b9) & 0xff00_0000))
        .collect();
    let codes = run_kernel(
        DEPTH24,
        "depth24_from_packed",
        &[Arg::column(&with_alpha)],
        CODES,
    )
    .into_words();
    let m = Mismatches::count(&codes, |d| d as u32);
    assert_eq!(m.count, 0, "depth24_from_packed: {:?}", m.first);
    let twin = Mismatches::count(&codes, |i| depth24::depth24_from_packed(with_alpha[i]));
    assert_eq!(twin.count, 0);

    // The identity, through the adapter's own unpack4x8unorm.
    let src = format!(
        "{DEPTH24}\nfn roundtrip(d: u32) -> u32 {{ return depth24_from_rgb8(unpack4x8unorm(pack_depth24(d)).xyz); }}"
    );
    let back = run_kernel(&src, "roundtrip", &[Arg::Index { start: 0 }], CODES).into_words();
    let m = Mismatches::count(&back, |d| d as u32);
    assert_eq!(m.count, 0, "unpack4x8unorm round trip: {:?}", m.first);
}

#[test]
fn hyperbolic_depth_is_correctly_rounded_for_every_code() {
    let h = hyperbolic("hyperbolic_depth_from_depth24");
    // Bound: correctly rounded (≤ 0.5 ULP). The integer construction has no rounding step, so
    // anything above 0.5 is a bug, not an accuracy allowance.
    assert_eq!(h.ulps.nan_count, 0);
    assert_within!(
        h.ulps.max,
        0.5,
        "correctly rounded: the integer construction has no rounding step (comment above)",
        "at code {}",
        h.ulps.argmax
    );
    assert_eq!(h.exact_roundtrip_failures, 0);
    assert_eq!(h.collisions, 0, "two codes share a float");
    let twin: Vec<f32> = (0..=DEPTH24_MAX)
        .map(depth24::hyperbolic_depth_from_depth24)
        .collect();
    let m = prepass::precision::metrics::bit_mismatches(&h.values, &twin);
    assert_eq!(m.count, 0, "Rust twin differs: {:?}", m.first);
    eprintln!(
        "hyperbolic_depth_from_depth24: max {:.3} ULP, mean {:.3}; f32 round trip failures {}",
        h.ulps.max,
        h.ulps.mean(),
        h.f32_roundtrip_failures
    );
    // Independent of the adapter: the twin measured the same way.
    let t = measure_hyperbolic(twin);
    assert_eq!(t.ulps.max, h.ulps.max);
}

#[test]
fn hyperbolic_baselines_are_measured() {
    for f in [
        "baseline_hyperbolic_divide",
        "baseline_hyperbolic_reciprocal",
    ] {
        let h = hyperbolic(f);
        // WGSL allows `/` 2.5 ULP; the reciprocal form rounds twice (≤ 0.5 + 0.5·(1+2^-23) ULP
        // plus the constant's own 0.5 ULP relative error): both stay within 2.5 ULP, so a
        // conforming adapter cannot exceed this.
        assert_within!(
            h.ulps.max,
            2.5,
            "comment above: WGSL's 2.5 ULP `/`; the reciprocal's two roundings stay within it",
            "{f}: ULP"
        );
        eprintln!(
            "{f}: max {:.3} ULP, mean {:.4}; exact round trip failures {}, f32 round trip \
             failures {}, collisions {}",
            h.ulps.max,
            h.ulps.mean(),
            h.exact_roundtrip_failures,
            h.f32_roundtrip_failures,
            h.collisions
        );
    }
}

#[test]
fn bad_channels_give_the_documented_clamped_code_on_both_sides() {
    let specials = [
        f32::NAN,
        -f32::NAN,
        f32::from_bits(0x7f80_0001), // signalling-NaN bit pattern
        f32::INFINITY,
        f32::NEG_INFINITY,
        -1.0,
        2.0,
        -0.0,
        f32::from_bits(1), // smallest subnormal (may be flushed: still byte 0)
        1e30,
        0.5,
    ];
    // Documented per-channel byte: NaN → 0, ≤ 0 → 0, ≥ 1 → 255, else round(255c).
    let byte = |c: f32| -> u32 {
        if c.is_nan() || c <= 0.0 {
            0
        } else if c >= 1.0 {
            255
        } else {
            (c * 255.0).round_ties_even() as u32
        }
    };
    let mut rgb = Vec::new();
    for &r in &specials {
        for &g in &specials {
            for &b in &specials {
                rgb.push([r, g, b]);
            }
        }
    }
    let out = run_kernel(
        DEPTH24,
        "depth24_from_rgb8",
        &[Arg::column(&rgb)],
        rgb.len() as u64,
    );
    for (i, (&got, c)) in out.as_u32().iter().zip(&rgb).enumerate() {
        let want = (byte(c[0]) << 16) | (byte(c[1]) << 8) | byte(c[2]);
        assert_eq!(got, want, "WGSL, input {i}: {c:?}");
        assert_eq!(
            depth24::depth24_from_rgb8(Vec3::from(*c)),
            want,
            "Rust, input {c:?}"
        );
    }
}

#[test]
fn codes_above_24_bits_saturate_on_both_sides() {
    let n = 4096u64; // the top of the u32 range, and just above 2^24 − 1
    for start in [u32::MAX - 4095, DEPTH24_MAX + 1] {
        let idx = [Arg::Index { start }];
        let packed = run_kernel(DEPTH24, "pack_depth24", &idx, n);
        let hyper = run_kernel(DEPTH24, "hyperbolic_depth_from_depth24", &idx, n);
        for i in 0..n as usize {
            let d = start.wrapping_add(i as u32);
            assert_eq!(packed.as_u32()[i], 0x00ff_ffff, "pack_depth24({d})");
            assert_eq!(depth24::pack_depth24(d), 0x00ff_ffff);
            assert_eq!(hyper.as_f32()[i], 1.0, "hyperbolic_depth_from_depth24({d})");
            assert_eq!(depth24::hyperbolic_depth_from_depth24(d), 1.0);
        }
    }
}

/// The conforming-adapter emulation catches the division baseline — `f32(d) / 16777215.0` is
/// correctly rounded on lavapipe, but WGSL allows `/` 2.5 ULP, and pushed to either end it no
/// longer maps every code back — while `hyperbolic_depth_from_depth24`, built from integers,
/// stays correctly rounded under every policy. All 2^24 codes per policy.
#[test]
fn emulation_breaks_the_division_baseline_but_not_the_integer_construction() {
    use prepass::conforming::{Emulation, Policy, emulate};
    for policy in Policy::WORST {
        let e = emulate(DEPTH24, &Emulation::new(policy)).unwrap();
        let f = e.function_name("hyperbolic_depth_from_depth24").unwrap();
        let h = hyperbolic_all(gpu(), &e.source, f).unwrap();
        eprintln!(
            "emulated {policy}: hyperbolic_depth_from_depth24 max {:.3} ULP, {} exact / {} f32 round-trip failures, {} collisions",
            h.ulps.max, h.exact_roundtrip_failures, h.f32_roundtrip_failures, h.collisions
        );
        assert_within!(
            h.ulps.max,
            0.5,
            "correctly rounded under every policy: built from integers (doc above)",
            "{policy}: ULP"
        );
        assert_eq!(
            h.exact_roundtrip_failures + h.collisions,
            0,
            "{policy}: round trip broken"
        );
        let b = emulate(BASELINES, &Emulation::new(policy)).unwrap();
        let f = b.function_name("baseline_hyperbolic_divide").unwrap();
        let h = hyperbolic_all(gpu(), &b.source, f).unwrap();
        eprintln!(
            "emulated {policy}: baseline f32(d) / 16777215.0 max {:.3} ULP, {} exact / {} f32 round-trip failures, {} collisions",
            h.ulps.max, h.exact_roundtrip_failures, h.f32_roundtrip_failures, h.collisions
        );
        assert_within!(
            h.ulps.max,
            prepass::conforming::allowance::DIVISION_ULP,
            "conforming::allowance::DIVISION_ULP: WGSL's 2.5 ULP for `/`",
            "{policy}: the emulated division, ULP"
        );
        assert!(
            h.exact_roundtrip_failures > 0,
            "{policy}: the division baseline kept its exact round trip under emulation — the emulation does not reach the division's freedom"
        );
    }
}

/// The 24-bit recovery on the emulated worst adapter: every code comes back from channels off
/// by 0, ±3 ULP (both sign patterns), and through the emulated `unpack4x8unorm` (3 ULP), under
/// the upper, lower and one seeded policy — the rounding of each channel survives any
/// conforming arithmetic (255·c within 0.45 + 2^-15 of the byte: the product's either-neighbour
/// rounding adds 2^-16 at most).
#[test]
fn recovery_survives_emulation() {
    use prepass::conforming::{Emulation, Policy, emulate};
    use prepass::precision::inputs::ChannelError;
    let round_trip = format!(
        "{DEPTH24}\nfn roundtrip(d: u32) -> u32 {{ return depth24_from_rgb8(unpack4x8unorm(pack_depth24(d)).xyz); }}"
    );
    for policy in [Policy::Upper, Policy::Lower, Policy::Seeded(1)] {
        let e = emulate(DEPTH24, &Emulation::new(policy)).unwrap();
        let f = e.function_name("depth24_from_rgb8").unwrap();
        for (error, flip) in [
            (ChannelError::Exact, false),
            (ChannelError::Ulps(3), false),
            (ChannelError::Ulps(3), true),
        ] {
            let r = recover_all(gpu(), &e.source, f, error, flip).unwrap();
            eprintln!(
                "emulated {policy}: depth24_from_rgb8, {error} (flip {flip}): {} wrong codes",
                r.mismatches.count
            );
            assert_eq!(
                r.mismatches.count, 0,
                "{policy} {error} flip {flip}: {:?}",
                r.mismatches.first
            );
        }
        let e = emulate(&round_trip, &Emulation::new(policy)).unwrap();
        let back = run_kernel(
            &e.source,
            e.function_name("roundtrip").unwrap(),
            &[Arg::Index { start: 0 }],
            CODES,
        )
        .into_words();
        let m = Mismatches::count(&back, |d| d as u32);
        eprintln!(
            "emulated {policy}: pack → unpack4x8unorm → recover: {} wrong codes",
            m.count
        );
        assert_eq!(
            m.count, 0,
            "{policy}: emulated unpack4x8unorm round trip: {:?}",
            m.first
        );
    }
}

/// The 24-bit figures of `docs/figures.md` (block `depth24`), from the measurements the tests
/// above assert (run once: [`recovery`], [`hyperbolic`]), plus hyperbolic depth on the worst
/// conforming adapter (emulated, every policy of `Policy::WORST`), whose promise — correctly
/// rounded everywhere — is asserted here.
#[test]
fn figures_are_published() {
    use prepass::conforming::{Emulation, Policy, emulate};
    use std::fmt::Write as _;
    let mut s = common::adapter_line();
    s.push_str("\n| channels | `depth24_from_rgb8`: wrong codes of 2^24 | the unrounded baseline: wrong codes |\n|---|---|---|\n");
    for (case, (error, flip)) in RECOVERY_CASES.into_iter().enumerate() {
        let r = recovery(case);
        // The promise (README): every code recovered, on the adapter, whatever its driver.
        assert_eq!(
            r.ours.count, 0,
            "depth24_from_rgb8 with channels off by {error} (flip {flip}): codes not recovered"
        );
        let _ = writeln!(
            s,
            "| {error}{} | {} | {} |",
            if flip { " (signs flipped)" } else { "" },
            r.ours.count,
            r.baseline
        );
    }
    // The search: every byte pushed each way, in every lane at once, under every assignment of
    // the slots its evaluation reads (`sweep::depth24::searched_recovery` says why that is every
    // code under every sign pattern).
    s.push_str("\n| channels | `depth24_from_rgb8`: max byte error at the searched worst | inputs | slots read per input | tables evaluated |\n|---|---|---|---|---|\n");
    for error in [
        ChannelError::Exact,
        ChannelError::Ulps(3),
        ChannelError::Offset(0.45),
    ] {
        let ours = searched_recovery(gpu(), DEPTH24, "depth24_from_rgb8", error).unwrap();
        // The promise at the worst combination: every byte, so every code, comes back; the
        // search must have been exhaustive for that to cover every code (see the sweep's docs).
        assert!(
            ours.exhaustive,
            "{error}: recovery read {:?} slots, more than the search enumerates",
            ours.slots
        );
        assert_eq!(
            ours.worst, 0.0,
            "depth24_from_rgb8 with channels off by {error}: a conforming evaluation the search found returns a wrong byte"
        );
        let _ = writeln!(
            s,
            "| {error} | {} | {} | {}–{}{} | {} |",
            ours.worst,
            ours.inputs,
            ours.slots.0,
            ours.slots.1,
            if ours.exhaustive { ", exhaustive" } else { "" },
            ours.evaluated
        );
    }
    s.push_str("\n| hyperbolic depth `d / (2^24 − 1)` | adapter | max ULP | codes not returned by the exact inverse |\n|---|---|---|---|\n");
    for (name, src, f) in [
        (
            "`hyperbolic_depth_from_depth24`",
            DEPTH24,
            "hyperbolic_depth_from_depth24",
        ),
        (
            "baseline `f32(d) / 16777215.0`",
            BASELINES,
            "baseline_hyperbolic_divide",
        ),
    ] {
        let h = hyperbolic(f);
        let _ = writeln!(
            s,
            "| {name} | this adapter | {:.3} | {} |",
            h.ulps.max, h.exact_roundtrip_failures
        );
        let (mut max, mut fails) = (0.0f64, 0u64);
        for policy in Policy::WORST {
            let e = emulate(src, &Emulation::new(policy)).unwrap();
            let h = hyperbolic_all(gpu(), &e.source, e.function_name(f).unwrap()).unwrap();
            max = max.max(h.ulps.max);
            fails = fails.max(h.exact_roundtrip_failures);
        }
        let _ = writeln!(s, "| {name} | worst emulated | {max:.3} | {fails} |");
        // Every 4099th code (a prime stride: every byte position moves) and the last, searched.
        let found = searched_hyperbolic(gpu(), src, f, 4099).unwrap();
        let _ = writeln!(
            s,
            "| {name} | worst found by the search ({} codes, {}–{} slots read{}) | {:.3} | — |",
            found.inputs,
            found.slots.0,
            found.slots.1,
            if found.exhaustive { ", exhaustive" } else { "" },
            found.worst
        );
        if f == "hyperbolic_depth_from_depth24" {
            // The promise: correctly rounded on every conforming adapter (≤ 0.5 ULP, every code
            // returned by the exact inverse), at the search's worst too.
            assert!(
                max <= 0.5 && fails == 0 && found.worst <= 0.5,
                "{name}: {max} ULP under the policies, {} at the search's worst, {fails} codes not returned under emulation (correctly rounded: ≤ 0.5 ULP, 0)",
                found.worst
            );
        }
    }
    common::publish_measured("docs/figures.md", "depth24", &s);
}
