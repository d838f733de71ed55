//! `wgsl/light_volume.wgsl` on the adapter: depth bounds of sphere lights contain every point of
//! the sphere (proptest, points on the surface) and are tight; the depth-pass/depth-fail choice
//! is conservative for spheres and cones; bad input. Twins: `src/lighting/light_volume.rs`.

mod common;

use common::{gpu, run_kernel};
use glam::{Vec2, Vec3};
use prepass::assert_within;
use prepass::harness::Arg;
use prepass::lighting::light_volume::{self, exact};
use prepass::projection::DepthConvention;
use prepass::wgsl::LIGHT_VOLUME;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

const U: f64 = 1.0 / 16_777_216.0;
const D24: f64 = 16_777_215.0;

fn draw<S: Strategy>(s: &S, n: usize) -> Vec<S::Value> {
    let mut runner = TestRunner::deterministic();
    (0..n)
        .map(|_| s.new_tree(&mut runner).unwrap().current())
        .collect()
}

/// (center_z, radius, near, far (+Inf one time in four), reversed): near 1e-4…10, far/near
/// 10…1e9, spheres anywhere from in front of near to beyond far.
fn bounds_case() -> impl Strategy<Value = (f32, f32, f32, f32, u32)> {
    (
        -4.0f64..1.0,
        1.0f64..9.0,
        0.0f64..1.0,
        -3.0f64..0.5,
        0u32..2,
        0u32..4,
    )
        .prop_map(|(log_near, log_ratio, pos, log_r, reversed, inf)| {
            let near = 10f64.powf(log_near);
            let far = near * 10f64.powf(log_ratio);
            // centre spread log-uniformly between near/2 and 2·far
            let cz = (near * 0.5) * ((far * 4.0) / near).powf(pos);
            let radius = cz * 10f64.powf(log_r);
            let far = if inf == 0 { f64::INFINITY } else { far };
            (cz as f32, radius as f32, near as f32, far as f32, reversed)
        })
}

fn convention(r: u32) -> DepthConvention {
    if r == 0 {
        DepthConvention::Standard
    } else {
        DepthConvention::Reversed
    }
}

#[test]
fn sphere_depth_bounds_contain_every_surface_point_and_are_tight() {
    let cases = draw(&bounds_case(), 4096);
    let col =
        |f: fn(&(f32, f32, f32, f32, u32)) -> f32| -> Vec<f32> { cases.iter().map(f).collect() };
    let (cz, r, n, f) = (col(|c| c.0), col(|c| c.1), col(|c| c.2), col(|c| c.3));
    let rev: Vec<u32> = cases.iter().map(|c| c.4).collect();
    let args = [
        Arg::column(&cz),
        Arg::column(&r),
        Arg::column(&n),
        Arg::column(&f),
        Arg::column(&rev),
    ];
    let bounds = run_kernel(
        LIGHT_VOLUME,
        "light_volume_sphere_depth_bounds",
        &args,
        cases.len() as u64,
    );
    let codes = run_kernel(
        LIGHT_VOLUME,
        "light_volume_sphere_depth_bounds24",
        &args,
        cases.len() as u64,
    );
    let (mut points, mut empty) = (0u64, 0u64);
    let (mut loose_u, mut loose_codes) = (0.0f64, 0.0f64);
    let mut rng = prepass::sweep::SplitMix(3);
    for (i, (b, c)) in bounds
        .as_vec2()
        .iter()
        .zip(codes.words().chunks_exact(2))
        .enumerate()
    {
        let (czi, ri, ni, fi) = (
            f64::from(cz[i]),
            f64::from(r[i]),
            f64::from(n[i]),
            f64::from(f[i]),
        );
        let conv = convention(rev[i]);
        assert!(b[0].is_finite() && b[1].is_finite());
        let twin = light_volume::light_volume_sphere_depth_bounds(cz[i], r[i], n[i], f[i], conv);
        let k = if fi.is_infinite() {
            1.0
        } else {
            fi / (fi - ni)
        };
        let eps = 16.0 * U * (1.0 + k);
        let lo = (czi - ri).max(ni);
        let hi = (czi + ri).min(fi);
        if lo > hi {
            // Wholly outside [near, far]: the empty range on both sides (an f32 tie at the
            // edge could go either way; none occurs in these cases).
            assert!(b[0] > b[1] && twin.x > twin.y, "case {i}: {b:?}");
            assert_eq!((c[0], c[1]), (0xff_ffff, 0));
            empty += 1;
            continue;
        }
        // Every point of the sphere's surface with a visible depth: 64 random directions plus
        // the two poles along the view axis.
        for j in 0..66 {
            let dz = match j {
                0 => 1.0,
                1 => -1.0,
                _ => f64::from(rng.range(-1.0, 1.0)),
            };
            let vz = czi + ri * dz;
            if vz < ni || vz > fi {
                continue; // clipped by the near or far plane: never in the depth buffer
            }
            let z = exact::light_volume_window_depth(vz, ni, fi, conv);
            assert!(
                f64::from(b[0]) <= z && z <= f64::from(b[1]),
                "case {i} {:?}: depth {z} of vz {vz} outside {b:?}",
                cases[i]
            );
            let code = (z * D24).round() as u32;
            assert!(
                c[0] <= code && code <= c[1],
                "case {i}: code {code} outside {c:?}"
            );
            points += 1;
        }
        // Tightness: the float range is within the widening eps plus the evaluation error
        // (≤ eps, derived in src/lighting/light_volume.rs) of the exact range: ≤ 2·eps each side.
        let (za, zb) = (
            exact::light_volume_window_depth(lo, ni, fi, conv),
            if hi.is_infinite() {
                if rev[i] == 0 { 1.0 } else { 0.0 }
            } else {
                exact::light_volume_window_depth(hi, ni, fi, conv)
            },
        );
        let (emin, emax) = (za.min(zb), za.max(zb));
        let (dl, dh) = (emin - f64::from(b[0]), f64::from(b[1]) - emax);
        let tight = "comment above: widening eps + evaluation error ≤ eps (light_volume docs), + U";
        assert_within!(
            dl,
            2.0 * eps + U,
            tight,
            "case {i}: loose below, eps {eps:e}"
        );
        assert_within!(
            dh,
            2.0 * eps + U,
            tight,
            "case {i}: loose above, eps {eps:e}"
        );
        // Codes: one more code each side at most beyond the float range.
        let (cl, ch) = (emin * D24 - f64::from(c[0]), f64::from(c[1]) - emax * D24);
        let codes = "comment above: the float range's 2·eps + U in codes, + 1 code";
        assert_within!(
            cl,
            (2.0 * eps + U) * D24 + 1.0,
            codes,
            "case {i}: codes below"
        );
        assert_within!(
            ch,
            (2.0 * eps + U) * D24 + 1.0,
            codes,
            "case {i}: codes above"
        );
        loose_u = loose_u.max(dl.max(dh) / U);
        loose_codes = loose_codes.max(cl.max(ch));
        // The twin: same formulas, within the evaluation error of each other.
        assert_within!(
            (twin - Vec2::from(*b)).abs().max_element() as f64,
            2.0 * eps + U,
            "comment above: the same formulas, each within its evaluation error",
            "case {i}: twin {twin} vs {b:?}"
        );
    }
    eprintln!(
        "depth bounds: {} spheres ({empty} outside [near, far]), {points} surface points all \
         inside; widest margin {loose_u:.1} u beyond the exact range ({loose_codes:.2} codes)",
        cases.len()
    );
}

/// (center, radius, near, tan_x, tan_y) for the stencil choice: spheres around the eye.
fn sphere_case() -> impl Strategy<Value = ([f32; 3], f32, f32, f32, f32)> {
    (
        [-3.0f32..3.0, -3.0f32..3.0, -3.0f32..3.0],
        0.01f32..2.0,
        0.01f32..1.0,
        0.1f32..2.0,
        0.1f32..2.0,
    )
}

fn dist_to_near_rect(p: [f64; 3], near: f64, tx: f64, ty: f64) -> f64 {
    let q = [
        p[0].clamp(-near * tx, near * tx),
        p[1].clamp(-near * ty, near * ty),
        near,
    ];
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

#[test]
fn sphere_stencil_choice_is_conservative() {
    let cases = draw(&sphere_case(), 8192);
    let centers: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let radii: Vec<f32> = cases.iter().map(|c| c.1).collect();
    let rho: Vec<f32> = cases
        .iter()
        .map(|c| light_volume::light_volume_near_corner_distance(c.2, c.3, c.4))
        .collect();
    let out = run_kernel(
        LIGHT_VOLUME,
        "light_volume_sphere_needs_depth_fail",
        &[
            Arg::column(&centers),
            Arg::column(&radii),
            Arg::column(&rho),
        ],
        cases.len() as u64,
    );
    let (mut needed, mut extra, mut safe) = (0, 0, 0);
    for (i, &got) in out.as_u32().iter().enumerate() {
        let (c, r, n, tx, ty) = cases[i];
        let c64 = c.map(f64::from);
        let len = (c64[0].powi(2) + c64[1].powi(2) + c64[2].powi(2)).sqrt();
        let touches = dist_to_near_rect(c64, f64::from(n), f64::from(tx), f64::from(ty))
            <= f64::from(r)
            || len <= f64::from(r);
        // The twin's decision where the adapter evaluates like the twins; anywhere, the safety
        // asserted below.
        if common::evaluates_like_the_twins() {
            assert_eq!(
                got,
                light_volume::light_volume_sphere_needs_depth_fail(Vec3::from(c), r, rho[i]),
                "case {i}: twin differs"
            );
        }
        if touches {
            assert_eq!(
                got, 1,
                "case {i}: {:?} touches the near rectangle",
                cases[i]
            );
            needed += 1;
        } else if got == 1 {
            extra += 1;
        } else {
            safe += 1;
        }
    }
    eprintln!(
        "sphere volumes: {needed} need depth-fail (all flagged), {extra} flagged by the rho margin \
         without touching the near rectangle, {safe} depth-pass"
    );
}

#[test]
fn cone_stencil_choice_is_conservative() {
    let strategy = (
        [-3.0f32..3.0, -3.0f32..3.0, -3.0f32..3.0],
        [-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0],
        0.1f32..4.0,
        0.05f32..1.5,
        0.01f32..1.0,
        0.1f32..2.0,
    );
    let cases: Vec<_> = draw(&strategy, 8192)
        .into_iter()
        .filter(|c| c.1.iter().map(|x| x * x).sum::<f32>() > 0.01)
        .collect();
    let apex: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let axis: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    let rt: Vec<[f32; 2]> = cases.iter().map(|c| [c.2, c.3]).collect();
    let rho: Vec<f32> = cases
        .iter()
        .map(|c| light_volume::light_volume_near_corner_distance(c.4, c.5, c.5))
        .collect();
    let out = run_kernel(
        LIGHT_VOLUME,
        "light_volume_cone_needs_depth_fail",
        &[
            Arg::column(&apex),
            Arg::column(&axis),
            Arg::column(&rt),
            Arg::column(&rho),
        ],
        cases.len() as u64,
    );
    let (mut needed, mut flagged, mut twin_diff) = (0, 0, 0);
    for (i, &got) in out.as_u32().iter().enumerate() {
        let (a, d, h, k, n, t) = cases[i];
        let a64 = a.map(f64::from);
        let dl = d.iter().map(|x| f64::from(*x).powi(2)).sum::<f64>().sqrt();
        let d64 = d.map(|x| f64::from(x) / dl);
        let inside = |p: [f64; 3]| {
            let q = [p[0] - a64[0], p[1] - a64[1], p[2] - a64[2]];
            let tt = q[0] * d64[0] + q[1] * d64[1] + q[2] * d64[2];
            let ss = (q.iter().map(|x| x * x).sum::<f64>() - tt * tt)
                .max(0.0)
                .sqrt();
            tt >= 0.0 && tt <= f64::from(h) && ss <= f64::from(k) * tt
        };
        // The eye and a 17×17 grid over the near rectangle: any of them inside the cone means
        // the near plane clips it (a necessary condition, checked in f64).
        let (n, t) = (f64::from(n), f64::from(t));
        let mut touches = inside([0.0; 3]);
        for ix in 0..17 {
            for iy in 0..17 {
                let x = n * t * (f64::from(ix) / 8.0 - 1.0);
                let y = n * t * (f64::from(iy) / 8.0 - 1.0);
                touches |= inside([x, y, n]);
            }
        }
        if touches {
            assert_eq!(
                got, 1,
                "case {i}: {:?} reaches the near rectangle",
                cases[i]
            );
            needed += 1;
        }
        flagged += got;
        let twin = light_volume::light_volume_cone_needs_depth_fail(
            Vec3::from(a),
            Vec3::from(d),
            Vec2::new(h, k),
            rho[i],
        );
        if twin != got {
            twin_diff += 1;
        }
    }
    // The twin may differ only for cones within the rounding margin of the threshold.
    assert_within!(
        twin_diff * 1000,
        cases.len(),
        "comment above: only cones within the threshold's rounding margin, ≤ 1 in 1000",
        "{twin_diff} twin differences (× 1000) of {} cases",
        cases.len()
    );
    eprintln!(
        "cone volumes: {} cases, {needed} reach the near rectangle (all flagged), {flagged} \
         flagged in all, twin differs in {twin_diff}",
        cases.len()
    );
}

#[test]
fn bad_input_answers_depth_fail_and_the_full_range() {
    let bad = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -1.0];
    let g = gpu();
    let sphere = g
        .kernel(LIGHT_VOLUME, "light_volume_sphere_needs_depth_fail")
        .unwrap();
    let bounds = g
        .kernel(LIGHT_VOLUME, "light_volume_sphere_depth_bounds24")
        .unwrap();
    for &x in &bad {
        let out = sphere
            .run(
                &[
                    Arg::column(&[[x, 0.0, 5.0], [0.0, 0.0, 5.0], [0.0, 0.0, 5.0]]),
                    Arg::column(&[1.0f32, x, 1.0]),
                    Arg::column(&[0.1f32, 0.1, x]),
                ],
                3,
            )
            .unwrap();
        // −1 is a valid centre coordinate (|c| = 5.1 > r + rho: depth-pass); bad elsewhere.
        let first = if x == -1.0 { 0 } else { 1 };
        assert_eq!(out.as_u32(), &[first, 1, 1], "bad {x}");
        assert_eq!(
            light_volume::light_volume_sphere_needs_depth_fail(Vec3::new(x, 0.0, 5.0), 1.0, 0.1),
            first
        );
        // center, radius, near, far bad in turn (far = +Inf is valid: infinite far plane).
        let rows: [[f32; 4]; 4] = [
            [x, 1.0, 0.1, 100.0],
            [5.0, x, 0.1, 100.0],
            [5.0, 1.0, x, 100.0],
            [5.0, 1.0, 0.1, if x == f32::INFINITY { 0.05 } else { x }],
        ];
        for row in rows {
            let out = bounds
                .run(
                    &[
                        Arg::splat_f32(row[0]),
                        Arg::splat_f32(row[1]),
                        Arg::splat_f32(row[2]),
                        Arg::splat_f32(row[3]),
                        Arg::splat_u32(0),
                    ],
                    1,
                )
                .unwrap();
            // A centre at −1 is valid: the sphere [−2, 0] lies in front of near, the empty range.
            let want = if row[0] == -1.0 {
                [0xff_ffff, 0]
            } else {
                [0, 0xff_ffff]
            };
            assert_eq!(out.as_u32(), &want, "{row:?}");
            assert_eq!(
                light_volume::light_volume_sphere_depth_bounds24(
                    row[0],
                    row[1],
                    row[2],
                    row[3],
                    DepthConvention::Standard
                ),
                want
            );
        }
    }
    assert_eq!(
        light_volume::light_volume_near_corner_distance(f32::NAN, 1.0, 1.0),
        3.4e38
    );
}

/// The safety properties on the emulated worst conforming adapter (every policy): the sphere's
/// depth bounds (float and 24-bit) contain the window depth of every visible point of its
/// surface, and a sphere that touches the near-plane rectangle (or holds the eye) is always
/// sent to depth-fail. A looser range or an extra depth-fail only costs time; these two would
/// drop light.
#[test]
fn bounds_and_stencil_choice_stay_safe_on_every_conforming_adapter() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    let cases = draw(&bounds_case(), 1024);
    let col =
        |f: fn(&(f32, f32, f32, f32, u32)) -> f32| -> Vec<f32> { cases.iter().map(f).collect() };
    let (cz, r, n, f) = (col(|c| c.0), col(|c| c.1), col(|c| c.2), col(|c| c.3));
    let rev: Vec<u32> = cases.iter().map(|c| c.4).collect();
    let args = [
        Arg::column(&cz),
        Arg::column(&r),
        Arg::column(&n),
        Arg::column(&f),
        Arg::column(&rev),
    ];
    let spheres = draw(&sphere_case(), 4096);
    let centers: Vec<[f32; 3]> = spheres.iter().map(|c| c.0).collect();
    let radii: Vec<f32> = spheres.iter().map(|c| c.1).collect();
    let rho: Vec<f32> = spheres
        .iter()
        .map(|c| light_volume::light_volume_near_corner_distance(c.2, c.3, c.4))
        .collect();
    let mut rng = prepass::sweep::SplitMix(11);
    for policy in Policy::WORST {
        let emu = Emulation::new(policy);
        let kernel = |name: &str| EmulatedKernel::new(gpu(), LIGHT_VOLUME, name, &emu).unwrap();
        let (bounds, _) = kernel("light_volume_sphere_depth_bounds")
            .run(&args, cases.len() as u64)
            .unwrap();
        let (codes, _) = kernel("light_volume_sphere_depth_bounds24")
            .run(&args, cases.len() as u64)
            .unwrap();
        let mut points = 0u64;
        for (i, (b, c)) in bounds
            .as_vec2()
            .iter()
            .zip(codes.words().chunks_exact(2))
            .enumerate()
        {
            let (czi, ri, ni, fi) = (
                f64::from(cz[i]),
                f64::from(r[i]),
                f64::from(n[i]),
                f64::from(f[i]),
            );
            // The two poles along the view axis (the range's ends), then random points.
            for j in 0..34 {
                let dz = match j {
                    0 => 1.0,
                    1 => -1.0,
                    _ => f64::from(rng.range(-1.0, 1.0)),
                };
                let vz = czi + ri * dz;
                if vz < ni || vz > fi {
                    continue;
                }
                let z = exact::light_volume_window_depth(vz, ni, fi, convention(rev[i]));
                assert!(
                    f64::from(b[0]) <= z && z <= f64::from(b[1]),
                    "{policy}, case {i} {:?}: depth {z} of vz {vz} outside {b:?}",
                    cases[i]
                );
                let code = (z * D24).round() as u32;
                assert!(
                    c[0] <= code && code <= c[1],
                    "{policy}, case {i}: code {code} outside {c:?}"
                );
                points += 1;
            }
        }
        let (fail, _) = kernel("light_volume_sphere_needs_depth_fail")
            .run(
                &[
                    Arg::column(&centers),
                    Arg::column(&radii),
                    Arg::column(&rho),
                ],
                spheres.len() as u64,
            )
            .unwrap();
        let mut touching = 0;
        for (i, &got) in fail.as_u32().iter().enumerate() {
            let (c, r, n, tx, ty) = spheres[i];
            let c64 = c.map(f64::from);
            let len = (c64[0].powi(2) + c64[1].powi(2) + c64[2].powi(2)).sqrt();
            if dist_to_near_rect(c64, f64::from(n), f64::from(tx), f64::from(ty)) <= f64::from(r)
                || len <= f64::from(r)
            {
                assert_eq!(
                    got, 1,
                    "{policy}, case {i}: {:?} touches the near rectangle but is sent to depth-pass",
                    spheres[i]
                );
                touching += 1;
            }
        }
        eprintln!(
            "emulated {policy}: {points} surface points inside their bounds; {touching} touching spheres all sent to depth-fail"
        );
    }
}

/// Spheres that touch the near rectangle exactly at a corner, centred on the eye's diagonal
/// through it: the tightest case of the depth-pass test, where `|c| = r + ρ`. Each centre is an
/// f32 triple moved toward the eye one pattern at a time until the sphere touches in exact
/// arithmetic (f64), so every case must be sent to depth-fail.
fn corner_touching_spheres(count: usize) -> Vec<([f32; 3], f32, f32, f32, f32)> {
    let mut rng = prepass::sweep::SplitMix(0xc0de);
    let mut out = Vec::new();
    while out.len() < count {
        let (n, tx, ty) = (
            rng.range(0.01, 1.0),
            rng.range(0.1, 2.0),
            rng.range(0.1, 2.0),
        );
        let r = rng.range(0.01, 4.0);
        let (sx, sy) = (
            if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 },
            if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 },
        );
        let q = [
            sx * f64::from(n) * f64::from(tx),
            sy * f64::from(n) * f64::from(ty),
            f64::from(n),
        ];
        let rho = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
        let k = (f64::from(r) + rho) / rho;
        let mut c = q.map(|x| (x * k) as f32);
        let touches = |c: [f32; 3]| {
            dist_to_near_rect(c.map(f64::from), f64::from(n), f64::from(tx), f64::from(ty))
                <= f64::from(r)
        };
        let mut steps = 0;
        while !touches(c) && steps < 16 {
            c = c.map(|x| if x > 0.0 { x.next_down() } else { x.next_up() });
            steps += 1;
        }
        if touches(c) {
            out.push((c, r, n, tx, ty));
        }
    }
    out
}

/// The decision's margin as one number a search can climb: the smallest radius, in ULPs of the
/// radius away from the given one (integer steps of its bit pattern: no float operation of the
/// probe's own), at which the shipped test says depth-fail, by bisection over ±1024 (the
/// decision is monotone in the radius under any one direction table). Returned + 2048. The
/// `_gpu_rho` forms take `ρ` from `light_volume_near_corner_distance` in the same shader.
const PROBES: &str = "
fn lv_flag_threshold(center: vec3<f32>, radius: f32, rho: f32) -> u32 {
    var lo = -1024;
    var hi = 1024;
    for (var i = 0; i < 11; i++) {
        let mid = (lo + hi) / 2;
        let r = bitcast<f32>(u32(i32(bitcast<u32>(radius)) + mid));
        if (light_volume_sphere_needs_depth_fail(center, r, rho) == 1u) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return u32(hi + 2048);
}
fn lv_gpu_rho(frustum: vec3<f32>) -> f32 {
    return light_volume_near_corner_distance(frustum.x, frustum.y, frustum.z);
}
fn lv_flag_threshold_gpu_rho(center: vec3<f32>, radius: f32, frustum: vec3<f32>) -> u32 {
    return lv_flag_threshold(center, radius, lv_gpu_rho(frustum));
}
";

/// The tightest case of the depth-pass test — spheres touching the near rectangle at a corner,
/// centred on the eye's diagonal through it, `|c| = r + ρ` — on every conforming adapter, with
/// `ρ` from the twin (as the example renderer computes it, on the CPU) and from the WGSL in the
/// same shader. The worst-case search (`conforming::search::climb`) maximises how far above the
/// smallest touching radius the shipped test starts saying depth-fail (above 0, a touching
/// sphere would get depth-pass); the interval enclosure of every allowed result
/// (`conforming::interval`) then proves the decision at each case where it is one value. Before
/// `ρ` was rounded up, the search sent a touching sphere to depth-pass with the GPU's `ρ`.
#[test]
fn corner_touching_spheres_go_to_depth_fail_on_every_conforming_adapter() {
    use prepass::conforming::interval::{Enclosure, Value};
    use prepass::conforming::search::{SearchConfig, climb};
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    use std::fmt::Write as _;
    let cases = corner_touching_spheres(256);
    let centers: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let radii: Vec<f32> = cases.iter().map(|c| c.1).collect();
    let frusta: Vec<[f32; 3]> = cases.iter().map(|c| [c.2, c.3, c.4]).collect();
    let rho: Vec<f32> = cases
        .iter()
        .map(|c| light_volume::light_volume_near_corner_distance(c.2, c.3, c.4))
        .collect();
    // The smallest radius offset (ULPs) at which each sphere touches, exactly (f64).
    let touch: Vec<i32> = cases
        .iter()
        .map(|&(c, r, n, tx, ty)| {
            let at = |k: i32| f32::from_bits((r.to_bits() as i32 + k) as u32);
            let d = dist_to_near_rect(c.map(f64::from), f64::from(n), f64::from(tx), f64::from(ty));
            let mut k = 0;
            while d <= f64::from(at(k - 1)) {
                k -= 1;
            }
            k
        })
        .collect();
    let src = format!("{LIGHT_VOLUME}\n{PROBES}");
    let enclosure = Enclosure::new(&src, true).unwrap();
    let over = |i: usize, out: &prepass::harness::Output, e: usize| {
        f64::from(out.as_u32()[e] as i32 - 2048 - touch[i])
    };
    let mut table = String::from(
        "| ρ computed by | spheres | worst found by the search: depth-fail from (ULPs of the radius above the smallest touching one; ≤ 0 is safe) | greedy policies | slots read | interval enclosure proves depth-fail at |\n|---|---|---|---|---|---|\n",
    );
    for gpu_rho in [false, true] {
        let (probe, decide) = if gpu_rho {
            ("lv_flag_threshold_gpu_rho", "")
        } else {
            ("lv_flag_threshold", "light_volume_sphere_needs_depth_fail")
        };
        let third = if gpu_rho {
            Arg::column(&frusta)
        } else {
            Arg::column(&rho)
        };
        let args = [Arg::column(&centers), Arg::column(&radii), third];
        let k = EmulatedKernel::new(gpu(), &src, probe, &Emulation::new(Policy::Searched)).unwrap();
        let found = climb(&k, &args, cases.len(), &over, &SearchConfig::default()).unwrap();
        let worst = found
            .iter()
            .map(|f| f.error)
            .fold(f64::NEG_INFINITY, f64::max);
        let greedy = found
            .iter()
            .map(|f| f.start_error)
            .fold(f64::NEG_INFINITY, f64::max);
        let slots = found.iter().map(|f| f.slots).max().unwrap_or(0);
        // The enclosure with the twin's ρ: with the GPU's, `1 + tan_x² + tan_y²` is a sum of
        // three terms, which conforming::interval refuses (it does not enumerate their orders).
        let mut proved = 0;
        for i in (0..cases.len()).filter(|_| !gpu_rho) {
            let args = [
                Value::f32s(&centers[i]),
                Value::f32s(&[radii[i]]),
                Value::f32s(&[rho[i]]),
            ];
            let Value::U32(l) = enclosure.of(decide, &args).unwrap() else {
                panic!("{decide} returns u32")
            };
            assert!(
                l[0].1 == 1,
                "case {i} {:?}: the enclosure {:?} excludes depth-fail for a touching sphere",
                cases[i],
                l[0]
            );
            proved += usize::from(l[0] == (1, 1));
        }
        eprintln!(
            "corner-touching spheres, ρ from the {}: the search's worst table says depth-fail from {worst} ULPs of the radius above the smallest touching one (greedy starts {greedy}; {slots} slots, climbed); {}",
            if gpu_rho { "GPU (WGSL)" } else { "twin (CPU)" },
            if gpu_rho {
                "no enclosure (a three-term sum in ρ)".to_string()
            } else {
                format!(
                    "the enclosure proves depth-fail at {proved} of {}",
                    cases.len()
                )
            }
        );
        let _ = writeln!(
            table,
            "| {} | {} | {worst} | {greedy} | {slots}, climbed | {} |",
            if gpu_rho {
                "the WGSL, in the same shader"
            } else {
                "the twin, on the CPU (as the example renderer does)"
            },
            cases.len(),
            if gpu_rho {
                "— (`1 + tan_x² + tan_y²` is a three-term sum, which the evaluator refuses)"
                    .to_string()
            } else {
                format!("{proved} of {}", cases.len())
            }
        );
        if !gpu_rho {
            assert_eq!(
                proved,
                cases.len(),
                "the enclosure leaves the decision open at a corner-touching sphere: the 16u margin \
                 (src/lighting/light_volume.rs) no longer covers every conforming rounding"
            );
        }
        assert!(
            worst <= 0.0,
            "ρ from the {}: a conforming adapter sends a sphere touching the near rectangle to \
             depth-pass ({worst} ULPs of its radius inside the touching range)",
            if gpu_rho { "GPU" } else { "twin" }
        );
    }
    let i = gpu().adapter_info();
    common::publish_measured(
        "docs/figures.md",
        "light-volumes",
        &format!("Measured on {} ({}).\n\n{table}", i.name, i.driver_info),
    );
}
