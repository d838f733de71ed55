//! `wgsl/aggregate_light.wgsl` on the adapter: God of War III's aggregate vertex lights (Vassily
//! Filippov, "Dynamic lighting in GOW3", SIGGRAPH 2011). Filippov's identity
//! `(N·L_agg)·l_agg = Σ l_i (N·L_i)` over proptest-generated light sets, light at the vertex,
//! cancelling lights, 1e-6…1e6 intensities, bad input. Twins: `src/lighting/aggregate_light.rs`.

mod common;

use common::{gpu, run_kernel};
use glam::{Vec3, Vec4};
use prepass::harness::{Arg, Kernel};
use prepass::lighting::aggregate_light;
use prepass::wgsl::AGGREGATE_LIGHT;
use prepass::{assert_within, assert_within_abs};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

const U: f64 = 1.0 / 16_777_216.0; // 2^-24
const SLOTS: usize = 16;

/// One vertex: position, normal, and up to 16 lights (position, luminance); unused slots have
/// weight 0, which adds exactly nothing.
#[derive(Clone, Debug)]
struct Set {
    vertex: [f32; 3],
    normal: [f32; 3],
    lights: Vec<([f32; 3], f32)>,
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|x| x / l)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Light sets with every N·L_i ≥ 0 (lights behind the surface are mirrored in front of it),
/// distances 0.01…100 and luminances 1e-6…1e6, both log-uniform.
fn set_strategy() -> impl Strategy<Value = Set> {
    let v3 = |r: f32| [-r..r, -r..r, -r..r];
    (
        v3(10.0),
        v3(1.0),
        prop::collection::vec((v3(1.0), -2.0f32..2.0, -6.0f32..6.0), 1..=SLOTS),
    )
        .prop_filter("normal not tiny", |(_, n, _)| {
            n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0.01
        })
        .prop_map(|(vertex, normal, ls)| {
            let nn = unit(normal.map(f64::from));
            let lights = ls
                .into_iter()
                .filter_map(|(d, log_dist, log_lum)| {
                    let d = d.map(f64::from);
                    if dot(d, d) < 1e-4 {
                        return None;
                    }
                    let mut u = unit(d);
                    let s = dot(u, nn);
                    if s < 0.0 {
                        u = [0, 1, 2].map(|k| u[k] - 2.0 * s * nn[k]);
                    }
                    let dist = 10f64.powf(f64::from(log_dist));
                    let p = [0, 1, 2].map(|k| (f64::from(vertex[k]) + u[k] * dist) as f32);
                    Some((p, 10f32.powf(log_lum)))
                })
                .collect();
            Set {
                vertex,
                normal,
                lights,
            }
        })
}

struct Run<'g> {
    acc: Kernel<'g>,
    dir: Kernel<'g>,
    colour: Kernel<'g>,
    pos: Kernel<'g>,
    diffuse: Kernel<'g>,
}

impl Run<'_> {
    fn new() -> Self {
        Self::on(AGGREGATE_LIGHT, &|f| f.to_string())
    }

    /// The kernels of `source`, each function looked up through `name` (an emulated module
    /// respells some names).
    fn on(source: &str, name: &dyn Fn(&str) -> String) -> Self {
        let g = gpu();
        let k = |f: &str| g.kernel(source, &name(f)).unwrap();
        Run {
            acc: k("aggregate_light_accumulate"),
            dir: k("aggregate_light_direction"),
            colour: k("aggregate_light_accumulate_colour"),
            pos: k("aggregate_light_position"),
            diffuse: k("aggregate_light_diffuse"),
        }
    }

    /// The per-pixel result at the vertex itself, for every set, on the adapter:
    /// `diffuse(N, V, P_agg, C_agg)` with scalar luminance colours `(l, l, l)`.
    fn at_vertex(&self, sets: &[Set]) -> Vec<f32> {
        let (pos, col) = self.aggregate(sets);
        let vertex: Vec<[f32; 3]> = sets.iter().map(|s| s.vertex).collect();
        let normal: Vec<[f32; 3]> = sets.iter().map(|s| s.normal).collect();
        self.diffuse(&normal, &vertex, &pos, &col)
    }

    fn diffuse(
        &self,
        normal: &[[f32; 3]],
        at: &[[f32; 3]],
        pos: &[[f32; 3]],
        col: &[[f32; 3]],
    ) -> Vec<f32> {
        let out = self
            .diffuse
            .run(
                &[
                    Arg::column(normal),
                    Arg::column(at),
                    Arg::column(pos),
                    Arg::column(col),
                ],
                normal.len() as u64,
            )
            .unwrap();
        out.as_vec3().iter().map(|v| v[0]).collect()
    }

    /// `(P_agg, C_agg)` of every set's vertex, on the adapter.
    fn aggregate(&self, sets: &[Set]) -> (Vec<[f32; 3]>, Vec<[f32; 3]>) {
        let n = sets.len() as u64;
        let vertex: Vec<[f32; 3]> = sets.iter().map(|s| s.vertex).collect();
        let slot = |j: usize| -> (Vec<[f32; 3]>, Vec<f32>) {
            sets.iter()
                .map(|s| {
                    s.lights
                        .get(j)
                        .copied()
                        .unwrap_or(([s.vertex[0] + 1.0, s.vertex[1], s.vertex[2]], 0.0))
                })
                .unzip()
        };
        let mut acc = vec![[0.0f32; 4]; sets.len()];
        for j in 0..SLOTS {
            let (p, w) = slot(j);
            let out = self
                .acc
                .run(
                    &[
                        Arg::column(&acc),
                        Arg::column(&vertex),
                        Arg::column(&p),
                        Arg::column(&w),
                    ],
                    n,
                )
                .unwrap();
            acc = out.as_vec4().to_vec();
        }
        let dir = self.dir.run(&[Arg::column(&acc)], n).unwrap();
        let dir = dir.as_vec3().to_vec();
        let mut col = vec![[0.0f32; 3]; sets.len()];
        for j in 0..SLOTS {
            let (p, w) = slot(j);
            let c: Vec<[f32; 3]> = w.iter().map(|&l| [l; 3]).collect();
            let out = self
                .colour
                .run(
                    &[
                        Arg::column(&col),
                        Arg::column(&vertex),
                        Arg::column(&p),
                        Arg::column(&c),
                        Arg::column(&dir),
                    ],
                    n,
                )
                .unwrap();
            col = out.as_vec3().to_vec();
        }
        let pos = self
            .pos
            .run(&[Arg::column(&acc), Arg::column(&vertex)], n)
            .unwrap();
        (pos.as_vec3().to_vec(), col)
    }
}

/// `(Σ l_i (N·L_i), Σ l_i, |R|)` in f64, with `R = X / Σ l_i/d_i` the aggregate light's offset.
fn exact(set: &Set) -> (f64, f64, f64) {
    let n = unit(set.normal.map(f64::from));
    let v = set.vertex.map(f64::from);
    let (mut sum, mut s, mut x, mut w) = (0.0, 0.0, [0.0; 3], 0.0);
    for &(p, l) in &set.lights {
        let rel = [0, 1, 2].map(|k| f64::from(p[k]) - v[k]);
        let d = dot(rel, rel).sqrt();
        let li = unit(rel);
        let l = f64::from(l);
        sum += l * dot(n, li).max(0.0);
        s += l;
        for k in 0..3 {
            x[k] += l * li[k];
        }
        w += l / d;
    }
    (sum, s, dot(x, x).sqrt() / w)
}

/// `aggregate_light::bounds::identity_absolute` for this set (derivation there).
fn budget(set: &Set, s: f64, r: f64) -> f64 {
    let v = set.vertex.map(f64::from);
    let vn = dot(v, v).sqrt();
    aggregate_light::bounds::identity_absolute(SLOTS, vn, s, r)
}

#[test]
fn the_luminance_identity_holds_within_the_derived_budget() {
    let mut runner = TestRunner::deterministic();
    let strategy = set_strategy();
    let sets: Vec<Set> = (0..2048)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .filter(|s| !s.lights.is_empty())
        .collect();
    let got = Run::new().at_vertex(&sets);
    let (mut worst, mut worst_rel_s) = (0.0f64, 0.0f64);
    for (set, &g) in sets.iter().zip(&got) {
        assert!(g.is_finite());
        let (want, s, r) = exact(set);
        let b = budget(set, s, r);
        let err = (f64::from(g) - want).abs();
        assert_within!(
            err,
            b,
            "budget(): (2K + 52)u·S + 4u·(|V| + 2|R|)/|R|·S",
            "{set:?}: aggregate {g} vs Σ l_i N·L_i {want}"
        );
        // The Rust twin folds the same lights on the CPU: within the same budget.
        let lights: Vec<(Vec3, f32, Vec3)> = set
            .lights
            .iter()
            .map(|&(p, l)| (Vec3::from(p), l, Vec3::splat(l)))
            .collect();
        let (pos, col) = aggregate_light::aggregate(Vec3::from(set.vertex), &lights);
        let twin = aggregate_light::aggregate_light_diffuse(
            Vec3::from(set.normal),
            Vec3::from(set.vertex),
            pos,
            col,
        );
        assert_within_abs!(
            f64::from(twin.x),
            want,
            b,
            "budget(): the twin folds the same lights",
            "twin of {set:?}"
        );
        worst = worst.max(err / b);
        worst_rel_s = worst_rel_s.max(err / s);
    }
    eprintln!(
        "identity over {} proptest light sets (1–16 lights, luminance 1e-6…1e6): max error \
         {worst_rel_s:.3e} of Σ l_i, at most {worst:.3} of the derived budget",
        sets.len()
    );
}

#[test]
fn a_light_at_the_vertex_is_skipped_and_cancelling_lights_stay_finite() {
    let v = [1.0f32, 2.0, 3.0];
    let n = [0.0f32, 0.0, 1.0];
    let far = ([1.0f32, 2.0, 5.0], 1.0f32);
    let sets = vec![
        // Light exactly at the vertex next to an ordinary one: the same as the ordinary one.
        Set {
            vertex: v,
            normal: n,
            lights: vec![(v, 1e6), far],
        },
        Set {
            vertex: v,
            normal: n,
            lights: vec![far],
        },
        // Two equal lights on opposite sides, tangent to the surface: X = 0 exactly.
        Set {
            vertex: v,
            normal: n,
            lights: vec![([0.0, 2.0, 3.0], 5.0), ([2.0, 2.0, 3.0], 5.0)],
        },
        // Nearly cancelling, with 1e6 and 1e-6 intensities mixed in.
        Set {
            vertex: v,
            normal: n,
            lights: vec![
                ([0.0, 2.0, 3.0], 1e6),
                ([2.0, 2.0, 3.0001], 1e6),
                ([1.0, 2.0, 4.0], 1e-6),
            ],
        },
    ];
    let got = Run::new().at_vertex(&sets);
    assert!(got.iter().all(|g| g.is_finite()));
    assert_eq!(
        got[0].to_bits(),
        got[1].to_bits(),
        "light at the vertex must add nothing"
    );
    assert_eq!(
        got[2], 0.0,
        "exactly cancelling lights give zero direction and colour"
    );
    for (set, &g) in sets.iter().zip(&got).skip(3) {
        let (want, s, _) = exact(set);
        // The nearly cancelling set: |X| is tiny, so R = X/W is tiny and the position term of
        // the budget is large; the first-order terms alone bound the error by (2K + 52)u·S plus
        // the direction-to-P_agg term, which is at most l_agg·2 ≤ 2|X| (a unit vector's dot).
        let x_len = 1e6 * 2.0 * (1e-4f64).atan();
        assert_within_abs!(
            f64::from(g),
            want,
            (2.0 * SLOTS as f64 + 52.0) * U * s + 2.0 * x_len,
            "comment above: first-order (2K + 52)u·S + direction term ≤ 2|X|",
            "{set:?}"
        );
    }
    eprintln!(
        "light at vertex: {} (= {}), cancelling: {}, nearly cancelling: {}",
        got[0], got[1], got[2], got[3]
    );
}

#[test]
fn bad_input_is_skipped_identically_on_both_sides() {
    let specials = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -1.0,
        0.0,
        1e30,
        3e38,
    ];
    let mut acc = Vec::new();
    let mut vertex = Vec::new();
    let mut pos = Vec::new();
    let mut w = Vec::new();
    for &a in &specials {
        for k in 0..4 {
            let mut p = [1.0f32, 2.0, 3.0];
            let mut v = [0.0f32; 3];
            let mut weight = 2.0f32;
            match k {
                0 => p[0] = a,
                1 => v[1] = a,
                2 => weight = a,
                _ => p = v,
            }
            acc.push([0.5f32, 0.0, 0.0, 0.25]);
            vertex.push(v);
            pos.push(p);
            w.push(weight);
        }
    }
    let out = run_kernel(
        AGGREGATE_LIGHT,
        "aggregate_light_accumulate",
        &[
            Arg::column(&acc),
            Arg::column(&vertex),
            Arg::column(&pos),
            Arg::column(&w),
        ],
        acc.len() as u64,
    );
    for (i, got) in out.as_vec4().iter().enumerate() {
        assert!(got.iter().all(|x| x.is_finite()), "row {i}: {got:?}");
        let twin = aggregate_light::aggregate_light_accumulate(
            Vec4::from(acc[i]),
            Vec3::from(vertex[i]),
            Vec3::from(pos[i]),
            w[i],
        );
        let skipped = Vec4::from(acc[i]);
        // Skipped on one side ⇔ skipped on the other (same bit tests); otherwise equal to ~8u.
        assert_eq!(Vec4::from(*got) == skipped, twin == skipped, "row {i}");
        assert_within!(
            (Vec4::from(*got) - twin).abs().max_element(),
            1e-6 * twin.abs().max_element().max(1.0),
            "comment above: equal to ~8u; 1e-6 of max(|twin|, 1)",
            "row {i}: {got:?} vs twin {twin}"
        );
        if w[i] < 0.0 {
            assert_eq!(Vec4::from(*got), skipped, "negative weight adds nothing");
        }
    }
    // Empty accumulator: direction zero, position the vertex, diffuse zero.
    let d = run_kernel(
        AGGREGATE_LIGHT,
        "aggregate_light_direction",
        &[Arg::column(&[[0.0f32; 4], [f32::NAN, 0.0, 0.0, 1.0]])],
        2,
    );
    assert_eq!(d.as_vec3(), &[[0.0; 3], [0.0; 3]]);
    assert_eq!(
        aggregate_light::aggregate_light_direction(Vec4::ZERO),
        Vec3::ZERO
    );
    assert_eq!(
        aggregate_light::aggregate_light_position(Vec4::ZERO, Vec3::ONE),
        Vec3::ONE
    );
}

#[test]
fn interpolated_aggregate_light_is_measured_between_vertices() {
    // Two vertices 0.5 apart sharing a light set; the pixel half-way gets the interpolated
    // P_agg and C_agg (as a rasteriser would) and is compared with the exact per-light sum at
    // the pixel. Filippov's slides call this "better", not exact: measured, finite, non-negative.
    let mut runner = TestRunner::deterministic();
    let strategy = set_strategy();
    let a: Vec<Set> = (0..1024)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .filter(|s| !s.lights.is_empty())
        .collect();
    let b: Vec<Set> = a
        .iter()
        .map(|s| Set {
            vertex: [s.vertex[0] + 0.5, s.vertex[1], s.vertex[2]],
            ..s.clone()
        })
        .collect();
    let run = Run::new();
    let (pa, ca) = run.aggregate(&a);
    let (pb, cb) = run.aggregate(&b);
    let mid = |x: &[[f32; 3]], y: &[[f32; 3]]| -> Vec<[f32; 3]> {
        x.iter()
            .zip(y)
            .map(|(p, q)| [0, 1, 2].map(|k| 0.5 * (p[k] + q[k])))
            .collect()
    };
    let pixel: Vec<[f32; 3]> = a
        .iter()
        .map(|s| [s.vertex[0] + 0.25, s.vertex[1], s.vertex[2]])
        .collect();
    let normal: Vec<[f32; 3]> = a.iter().map(|s| s.normal).collect();
    let got = run.diffuse(&normal, &pixel, &mid(&pa, &pb), &mid(&ca, &cb));
    let mut rel = prepass::precision::metrics::ErrorStats::default();
    for (i, (set, &g)) in a.iter().zip(&got).enumerate() {
        assert!(g.is_finite() && g >= 0.0);
        let at_pixel = Set {
            vertex: pixel[i],
            ..set.clone()
        };
        let (want, s, _) = exact(&at_pixel);
        rel.add(i as u64, (f64::from(g) - want).abs() / s);
    }
    eprintln!(
        "interpolated aggregate light at the mid-pixel of 0.5-long edges, {} sets: error / Σ l_i \
         max {:.3e}, mean {:.3e}, rms {:.3e}",
        a.len(),
        rel.max,
        rel.mean(),
        rel.rms()
    );
}

/// The God of War III identity on the emulated worst conforming adapter (every policy): the
/// same light sets, within twice the derived budget. Every term of `budget` is either a rounding
/// of `+ − ×` (`u` where correctly rounded, at most `2u` on any conforming adapter) or already a
/// full WGSL allowance (`/` 2.5 ULP, `inverseSqrt` 2 ULP), so doubling it bounds the conforming
/// error.
#[test]
fn the_luminance_identity_holds_on_every_conforming_adapter() {
    use prepass::conforming::{Emulation, Policy, emulate};
    let mut runner = TestRunner::deterministic();
    let strategy = set_strategy();
    let sets: Vec<Set> = (0..512)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .filter(|s| !s.lights.is_empty())
        .collect();
    for policy in Policy::WORST {
        let e = emulate(AGGREGATE_LIGHT, &Emulation::new(policy)).unwrap();
        let run = Run::on(&e.source, &|f| e.function_name(f).unwrap().to_string());
        let got = run.at_vertex(&sets);
        let mut worst = 0.0f64;
        for (set, &g) in sets.iter().zip(&got) {
            let (want, s, r) = exact(set);
            let b = aggregate_light::bounds::CONFORMING_FACTOR * budget(set, s, r);
            let err = (f64::from(g) - want).abs();
            assert_within!(
                err,
                b,
                "aggregate_light::bounds::identity_absolute × CONFORMING_FACTOR",
                "{policy}, {set:?}: {g} vs {want}"
            );
            worst = worst.max(err / b);
        }
        eprintln!(
            "emulated {policy}: identity within {worst:.3} of the conforming budget over {} sets",
            sets.len()
        );
    }
}
