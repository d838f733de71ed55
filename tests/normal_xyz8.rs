//! `wgsl/normal_xyz8.wgsl` on the adapter: round trip over the tier's spherical-Fibonacci
//! directions (2^20; 2^24 in the full tier)
//! and the adversarial set, all 2^24 codes decoded, bad input and the render-target form —
//! against the Rust twin `src/normal/xyz8.rs` and f64 references.

mod common;

use common::gpu;
use glam::Vec3;
use prepass::assert_within;
use prepass::normal::xyz8;
use prepass::sweep::normal::{bad_inputs, codec, decode_codes, decode_range};

#[test]
fn round_trip_meets_target_and_twin_is_bit_identical() {
    let rt = common::assert_linear_round_trip(
        "xyz8",
        0xff_ffff,
        xyz8::max_angle_deg(),
        "normal::xyz8::max_angle_deg(), asin(√3/255)",
    );
    // The rule: no worse than its float64 reproduction by more than 2%.
    let (mean_t, max_t) = codec("xyz8").target.unwrap();
    let rule = "Codec::target: within 2% of the f64 reproduction (comment above)";
    assert_within!(
        rt.error.mean(),
        mean_t * 1.02,
        rule,
        "{}: mean degrees",
        common::tier::fibonacci_set_label()
    );
    assert_within!(
        rt.error.max,
        max_t * 1.02,
        rule,
        "{}: max degrees",
        common::tier::fibonacci_set_label()
    );
}

#[test]
fn every_code_decodes_to_a_unit_vector_and_byte_3_is_ignored() {
    let c = codec("xyz8");
    let d = decode_range(gpu(), c, 0, 1 << 24).unwrap();
    let junk: Vec<u32> = (0u32..1 << 16)
        .map(|p| (p * 251) & 0xff_ffff | (p << 24))
        .collect();
    let dj = decode_codes(gpu(), c, &junk).unwrap();
    for (name, d) in [("all 2^24", &d), ("byte 3 junk", &dj)] {
        common::assert_decoder(&format!("xyz8 {name}"), d);
    }
    common::assert_high_bits_ignored(c.source, c.decode, &junk, 0xff_ffff);
}

#[test]
fn bad_input_gets_the_documented_code_on_both_sides() {
    let cases = bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("xyz8", &bad, &good);
    // +z: bytes round(127.5) = 128 (half to even), 128, 255.
    assert_eq!(xyz8::encode_normal_xyz8(Vec3::ZERO), 0x00ff_8080);
}

#[test]
fn render_target_form_matches_the_code_path() {
    let inputs = common::render_target_inputs();
    common::assert_unorm_forms(
        "xyz8",
        "encode_normal_xyz8_unorm",
        "decode_normal_xyz8_unorm",
        4,
        &inputs,
    );
    common::assert_twin_unorm_form(
        &inputs,
        xyz8::encode_normal_xyz8_unorm,
        xyz8::decode_normal_xyz8_unorm,
        xyz8::encode_normal_xyz8,
        xyz8::decode_normal_xyz8,
    );
    assert_eq!(
        xyz8::decode_normal_xyz8_unorm([f32::NAN, 2.0, -1.0, 0.5]),
        xyz8::decode_normal_xyz8(0x0000_ff00)
    );
}

// ---------------------------------------------------------------------------------------------
// The best-fit encoder (Godot 4's format): exactness against an exhaustive search, the WGSL
// against its twin, the round trip, bad input and the render-target form.

/// The directions the exhaustive check runs over (a few thousand; each costs 2^21 codes): the
/// axes and diagonals with signed zeros, 1024 Fibonacci directions, every 64th adversarial
/// direction, directions of random codes (exact lattice directions rounded to f32, and a ULP
/// either side: every multiple of such a direction ties in exact arithmetic), and near ties:
/// the angle bisector of a random code's direction and a neighbour's, nudged a ULP.
fn best_fit_check_directions() -> Vec<[f32; 3]> {
    use prepass::normal::exact::unit;
    use prepass::sweep::normal::{adversarial_directions, fibonacci_directions};
    let mut v: Vec<[f32; 3]> = Vec::new();
    for x in [-1.0f32, -0.0, 0.0, 1.0] {
        for y in [-1.0f32, -0.0, 0.0, 1.0] {
            for z in [-1.0f32, -0.0, 0.0, 1.0] {
                if x != 0.0 || y != 0.0 || z != 0.0 {
                    v.push([x, y, z]);
                }
            }
        }
    }
    v.extend(fibonacci_directions(1024));
    v.extend(adversarial_directions().into_iter().step_by(64));
    let mut rng = prepass::sweep::SplitMix(0x0be5_7f17);
    let ulp = |x: f32, d: i32| {
        if x == 0.0 {
            x
        } else {
            f32::from_bits(x.to_bits().wrapping_add_signed(d))
        }
    };
    for _ in 0..512 {
        let p = (rng.next_u64() & 0xff_ffff) as u32;
        let d = xyz8::exact::decode(p);
        let f = d.map(|x| x as f32);
        v.push(f);
        v.push([ulp(f[0], 1), ulp(f[1], -1), f[2]]);
    }
    for _ in 0..512 {
        let p = (rng.next_u64() & 0xff_ffff) as u32;
        let lane = (rng.next_u64() % 3) as u32;
        let step = if rng.next_u64() & 1 == 0 { 1u32 } else { 0xff };
        let field = ((p >> (8 * lane)) + step) & 0xff;
        let q = (p & !(0xff << (8 * lane))) | (field << (8 * lane));
        let (a, b) = (xyz8::exact::decode(p), xyz8::exact::decode(q));
        if let Some(m) = unit(std::array::from_fn(|i| a[i] + b[i])) {
            let f = m.map(|x| x as f32);
            v.push(f);
            v.push([ulp(f[0], -1), f[1], ulp(f[2], 1)]);
        }
    }
    v
}

/// The twin's code is the nearest of all codes: equal to an exhaustive search of the 2^21 codes
/// with `n`'s signs (`xyz8::exact::encode_best_exhaustive`; the other codes are never nearer,
/// and for 16 directions all 2^24 codes are searched too), or — where f32 scoring cannot tell
/// two candidates apart — at most `2·BEST_FIT_SINE_SLACK` (the derived scoring slack, twice:
/// the chosen and the best candidate's) worse in sine. The f64 plane search (the codec's
/// reference) equals the exhaustive search up to f64 rounding. Also: skipping planes by the
/// bound never changes the twin's code (the full search, every plane, agrees).
#[test]
fn best_fit_is_the_nearest_of_all_codes() {
    use prepass::normal::xyz8::{BEST_FIT_SINE_SLACK, exact};
    let dirs = best_fit_check_directions();
    let widen = |v: [f32; 3]| v.map(f64::from);
    // Sine slack to angle: asin'(x) ≤ 1.0001 for sines under 0.01 (every best fit: ≤ √3/255).
    let tol = 2.0 * f64::from(BEST_FIT_SINE_SLACK) * 1.0001;
    let chunks: Vec<Vec<[f32; 3]>> = dirs
        .chunks(dirs.len().div_ceil(2))
        .map(|c| c.to_vec())
        .collect();
    let results: Vec<(usize, usize, f64, f64)> = std::thread::scope(|sc| {
        let hs: Vec<_> = chunks
            .iter()
            .map(|c| {
                sc.spawn(move || {
                    let (mut differ, mut plane_differ, mut worst, mut worst_plane) =
                        (0usize, 0usize, 0.0f64, 0.0f64);
                    for &v in c {
                        let n = widen(v);
                        let twin = xyz8::encode_normal_xyz8_best(Vec3::from(v));
                        let full = xyz8::encode_normal_xyz8_best_full_search(Vec3::from(v));
                        assert_eq!(twin, full, "plane skipping changed the code at {v:?}");
                        let ex = exact::encode_best_exhaustive(n);
                        let best = exact::angle_to(n, ex);
                        if twin != ex {
                            differ += 1;
                            let excess = exact::angle_to(n, twin) - best;
                            worst = worst.max(excess);
                            assert!(
                                excess <= tol,
                                "{v:?}: twin {twin:#08x} is {excess:e} rad worse than the \
                                 exhaustive best {ex:#08x} (slack {tol:e})"
                            );
                        }
                        let plane = exact::encode_best(n);
                        if plane != ex {
                            plane_differ += 1;
                            let excess = exact::angle_to(n, plane) - best;
                            worst_plane = worst_plane.max(excess);
                            // f64: the scores' rounding, ~2^-50 relative to cos² ≈ 1.
                            assert!(
                                excess <= 1e-12,
                                "{v:?}: f64 plane search {plane:#08x} is {excess:e} rad worse \
                                 than {ex:#08x}"
                            );
                        }
                    }
                    (differ, plane_differ, worst, worst_plane)
                })
            })
            .collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let differ: usize = results.iter().map(|r| r.0).sum();
    let plane_differ: usize = results.iter().map(|r| r.1).sum();
    let worst = results.iter().map(|r| r.2).fold(0.0, f64::max);
    let worst_plane = results.iter().map(|r| r.3).fold(0.0, f64::max);
    eprintln!(
        "xyz8 best-fit: {} directions against all 2^21 sign-matched codes: the twin's code is \
         the exhaustive one at {} (other {differ}: ties within the f32 scoring slack, worst \
         {worst:.3e} rad, slack {tol:.3e}); the f64 plane search differs at {plane_differ} \
         (worst {worst_plane:.3e} rad)",
        dirs.len(),
        dirs.len() - differ
    );
    // Every one of the 2^24 codes, both signs, for a few directions: the sign restriction holds.
    for v in dirs.iter().step_by(dirs.len() / 16).take(16) {
        let n = widen(*v);
        let u = prepass::normal::exact::unit(n).unwrap();
        let mut best = (f64::MAX, 0u32);
        for p in 0..1u32 << 24 {
            let d = exact::decode(p);
            let c = [
                u[1] * d[2] - u[2] * d[1],
                u[2] * d[0] - u[0] * d[2],
                u[0] * d[1] - u[1] * d[0],
            ];
            let dot = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
            let a = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt().atan2(dot);
            if a < best.0 {
                best = (a, p);
            }
        }
        let ex = exact::encode_best_exhaustive(n);
        assert!(
            exact::angle_to(n, ex) - best.0 <= 1e-12,
            "{v:?}: the sign-matched search {ex:#08x} misses {:#08x}",
            best.1
        );
    }
}

/// The WGSL best-fit encoder on the adapter: bit for bit the twin over the tier's Fibonacci
/// directions (2^20; 2^24 in the full tier)
/// and the adversarial set (where the adapter evaluates like the twins), every round trip within
/// the rounding encoder's derived bound, and its max error no larger than the rounding
/// encoder's on the same directions; near-lattice and near-tie directions too.
#[test]
fn best_fit_round_trip_and_twin_is_bit_identical() {
    use prepass::precision::metrics::angle_degrees;
    use prepass::sweep::normal::round_trip;
    let rt = common::assert_linear_round_trip(
        "xyz8 best-fit",
        0xff_ffff,
        xyz8::max_angle_deg(),
        "normal::xyz8::max_angle_deg(), asin(√3/255): the rounding code is a candidate",
    );
    let dirs = common::tier::fibonacci_set().1;
    let rounding = dirs
        .iter()
        .map(|v| {
            let d = xyz8::exact::decode(xyz8::encode_normal_xyz8(Vec3::from(*v)));
            angle_degrees(v.map(f64::from), d)
        })
        .fold(0.0f64, f64::max);
    eprintln!(
        "xyz8 best-fit fibonacci 2^24: max {:.6}° mean {:.6}°; rounding encoder's max {rounding:.6}°",
        rt.error.max,
        rt.error.mean()
    );
    // Bound: the rounding encoder's code is one of the best fit's candidates, so the best
    // fit's exact angle is never larger; F32_SLACK_DEG covers the f32 decode and scoring.
    prepass::assert_within!(
        rt.error.max,
        rounding + prepass::normal::F32_SLACK_DEG,
        "the rounding encoder's max on the same directions + normal::F32_SLACK_DEG",
        "xyz8 best-fit fibonacci 2^24: max degrees"
    );
    let c = prepass::sweep::normal::codec("xyz8 best-fit");
    let extra = best_fit_check_directions();
    let rt = round_trip(common::gpu(), c, &extra).unwrap();
    common::assert_round_trip_matches_twins("xyz8 best-fit near lattice and ties", c, &extra, &rt);
}

#[test]
fn best_fit_bad_input_and_render_target_form() {
    let cases = prepass::sweep::normal::bad_inputs();
    let bad: Vec<[f32; 3]> = cases.iter().map(|c| c.0).collect();
    let good: Vec<[f32; 3]> = cases.iter().map(|c| c.1).collect();
    common::assert_encodes_like("xyz8 best-fit", &bad, &good);
    assert_eq!(xyz8::encode_normal_xyz8_best(Vec3::ZERO), 0x00ff_8080);
    let inputs = common::render_target_inputs();
    common::assert_unorm_forms(
        "xyz8 best-fit",
        "encode_normal_xyz8_best_unorm",
        "decode_normal_xyz8_unorm",
        4,
        &inputs,
    );
    common::assert_twin_unorm_form(
        &inputs,
        xyz8::encode_normal_xyz8_best_unorm,
        xyz8::decode_normal_xyz8_unorm,
        xyz8::encode_normal_xyz8_best,
        xyz8::decode_normal_xyz8,
    );
}

/// prepass's best fit against Godot 4's own encoder (the peer `tests/baselines/peer_godot.wgsl`:
/// its lookup-table scale, the texel computed inline) over 2^20 Fibonacci directions and the
/// adversarial set, both on the adapter: at every direction prepass's code is at least as near
/// (exact f64 angles of the two codes; `2·BEST_FIT_SINE_SLACK`, the derived scoring slack, where
/// the twin's f32 scores cannot separate two candidates), so its max and mean are no larger.
/// Both are printed.
#[test]
fn best_fit_is_at_least_as_accurate_as_godots_encoder() {
    use prepass::harness::Arg;
    use prepass::normal::xyz8::{BEST_FIT_SINE_SLACK, exact};
    use prepass::sweep::normal::{adversarial_directions, fibonacci_directions, round_trip};
    const GODOT: &str = include_str!("baselines/peer_godot.wgsl");
    let tol = 2.0 * f64::from(BEST_FIT_SINE_SLACK) * 1.0001;
    for (set, dirs) in [
        ("fibonacci 2^20", fibonacci_directions(1 << 20)),
        ("adversarial", adversarial_directions()),
    ] {
        let n = dirs.len() as u64;
        let godot = common::run_kernel(GODOT, "peer_godot_normal_encode", &[Arg::column(&dirs)], n)
            .into_words();
        let godot_dec =
            common::run_kernel(GODOT, "peer_godot_normal_decode", &[Arg::column(&godot)], n);
        let ours = round_trip(gpu(), codec("xyz8 best-fit"), &dirs).unwrap();
        let (mut g_max, mut g_sum, mut same, mut worse) = (0.0f64, 0.0f64, 0usize, 0usize);
        let mut worst = 0.0f64;
        for (i, v) in dirs.iter().enumerate() {
            let w = v.map(f64::from);
            let g = prepass::precision::metrics::angle_degrees(
                w,
                prepass::precision::metrics::widen3(godot_dec.as_vec3()[i]),
            );
            g_max = g_max.max(g);
            g_sum += g;
            let (a_ours, a_godot) = (
                exact::angle_to(w, ours.codes[i]),
                exact::angle_to(w, godot[i]),
            );
            same += usize::from(ours.codes[i] == godot[i] & 0xff_ffff);
            // Farther beyond f64 noise (two multiples of one odd vector are one direction).
            if a_ours > a_godot + 1e-12 {
                worse += 1;
                worst = worst.max(a_ours - a_godot);
                assert!(
                    a_ours - a_godot <= tol,
                    "{set} {v:?}: prepass {:#08x} is {:e} rad farther than Godot's {:#08x}",
                    ours.codes[i],
                    a_ours - a_godot,
                    godot[i]
                );
            }
        }
        eprintln!(
            "{set}: prepass best-fit max {:.6}° mean {:.6}°; Godot's encoder (lookup texel inline) \
             max {g_max:.6}° mean {:.6}°; same code at {same} of {n}; prepass farther (by more \
             than 1e-12 rad, within the f32 scoring slack) at {worse}, by at most {worst:.3e} rad",
            ours.error.max,
            ours.error.mean(),
            g_sum / n as f64
        );
        // Bound: prepass's code is no farther at each direction (up to the scoring slack, far
        // below F32_SLACK_DEG), so its max is Godot's plus the f32 decodes' slack.
        prepass::assert_within!(
            ours.error.max,
            g_max + prepass::normal::F32_SLACK_DEG,
            "Godot's max on the same directions + normal::F32_SLACK_DEG",
            "xyz8 best-fit {set}: max degrees"
        );
    }
}

/// Godot 4's reader of its Forward+ normal_roughness texel, in f64: `normalize(c·2 − 1)` on the
/// sampled channels `c = b/255` (`normal_roughness_compatibility` in godotengine/godot
/// `servers/rendering/renderer_rd/shaders/forward_clustered/scene_forward_clustered_inc.glsl`,
/// which Godot's docs tell compositor effects to copy); alpha (roughness) ignored.
fn godot_read_f64(p: u32) -> [f64; 3] {
    let c = [p & 0xff, (p >> 8) & 0xff, (p >> 16) & 0xff].map(|b| f64::from(b) / 255.0 * 2.0 - 1.0);
    let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    c.map(|a| a / l)
}

/// Godot 4's normal texel, both ways (issue 60; Godot's writer is `encode24(n)·0.5 + 0.5` of
/// `scene_forward_clustered.glsl`, transcribed with its best-fit lookup texel in
/// `tests/baselines/peer_godot.wgsl`; its reader is [`godot_read_f64`]):
/// - **reads exact:** every 2^24 texel (alpha set) decodes with `decode_normal_xyz8` on the
///   adapter in the direction Godot's reader gives it, to the decoder's rounding;
/// - **writes:** over `common::interop_directions` (2^20 Fibonacci directions and the special
///   ones), Godot's writer, `encode_normal_xyz8_best` and `encode_normal_xyz8` run on the adapter
///   and are compared texel for texel; each one's max error as Godot reads it is printed and
///   published (`interop-godot`), and the best fit's max is no more than Godot's writer's plus
///   `normal::F32_SLACK_DEG` (its code is the nearest of all, `best_fit_is_the_nearest_of_all_codes`).
#[test]
fn godot_normal_texel_both_ways() {
    use prepass::harness::Arg;
    use prepass::precision::metrics::{angle_degrees, widen3};
    use prepass::wgsl::NORMAL_XYZ8;
    const GODOT: &str = include_str!("baselines/peer_godot.wgsl");
    let texels: Vec<u32> = (0..1u32 << 24)
        .map(|p| p | ((p * 53) & 0xff) << 24)
        .collect();
    let worst_read = common::assert_reads_like_the_engine(
        NORMAL_XYZ8,
        "decode_normal_xyz8",
        &texels,
        |p| Some(godot_read_f64(p)),
        "Godot's reader (f64)",
    );
    let dirs = common::interop_directions();
    let m = dirs.len() as u64;
    let run = |src: &str, f: &str| {
        common::run_kernel(src, f, &[Arg::column(&dirs)], m)
            .into_words()
            .into_iter()
            .map(|p| p & 0xff_ffff)
            .collect::<Vec<u32>>()
    };
    let godot = run(GODOT, "peer_godot_normal_encode");
    let best = run(NORMAL_XYZ8, "encode_normal_xyz8_best");
    let rounding = run(NORMAL_XYZ8, "encode_normal_xyz8");
    let err = |w: &[u32]| {
        dirs.iter()
            .zip(w)
            .map(|(v, &p)| angle_degrees(widen3(*v), godot_read_f64(p)))
            .fold(0f64, f64::max)
    };
    let fib = 1usize << 20;
    let differ = |w: &[u32], k: usize| (0..k).filter(|&i| w[i] != godot[i]).count();
    let (eg, eb, er) = (err(&godot), err(&best), err(&rounding));
    let body = format!(
        "| form | engine | reads the engine's texels | writes |\n|---|---|---|---|\n\
         | `decode_normal_xyz8` | Godot 4 Forward+ normal_roughness (`normal_roughness_compatibility`) | exact: every 2^24 texel within {worst_read:.2e}° of Godot's reader (f64), alpha ignored | — |\n\
         | `encode_normal_xyz8_best` | Godot 4 (`encode24`, best-fit lookup texture) | — | the nearest of all codes: differs from Godot's writer on {} of 2^20 ({} of all {m} inputs); max {eb:.4}° read by Godot against Godot's writer's {eg:.4}° |\n\
         | `encode_normal_xyz8` | Godot 4 | — | per-channel rounding (not Godot's best fit): differs from Godot's writer on {} of 2^20; max {er:.4}° read by Godot |\n",
        differ(&best, fib),
        differ(&best, dirs.len()),
        differ(&rounding, fib)
    );
    eprintln!("{body}");
    common::publish_measured("docs/figures.md", "interop-godot", &body);
    assert_within!(
        eb,
        eg + prepass::normal::F32_SLACK_DEG,
        "Godot's writer's max on the same inputs + normal::F32_SLACK_DEG",
        "encode_normal_xyz8_best read by Godot's reader: max degrees"
    );
}
