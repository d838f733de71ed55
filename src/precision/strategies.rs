//! proptest strategies for the inputs shader maths meets in practice, with the adversarial cases
//! weighted in (feature `proptest`).
//!
//! A uniform random draw almost never lands on a pole, an octahedron fold, depth code 0 or a
//! far/near ratio of 10^9 — yet those are where encodings break. Every strategy here mixes a
//! broad random draw with explicit sets of such cases (each a `prop_oneof!` arm with its weight),
//! so a few thousand cases cover both. Values shrink towards the simple end of each arm.
//!
//! Adding a module's inputs: add a function returning `impl Strategy<Value = …>` here, built the
//! same way (broad arm + adversarial arms), and list it in the table below.
//!
//! | strategy | values | adversarial cases weighted in |
//! |---|---|---|
//! | `unit_vector()` | unit `Vec3`, a third uniform on the sphere | poles and axes with signed zeros, equator and the octahedron fold `abs(x) + abs(y) ≈ 1` (`abs(z)` down to 2^-149), lower-hemisphere seams `x = ±0`/`y = ±0`, near-pole `abs(z) = 1 − ε`, diagonals |
//! | `direction()` | any-length `Vec3` | lengths 10^-42 (subnormal lanes) … 3·10^38 |
//! | `bad_f32()`, `any_f32_bits()` | `f32` | NaN (quiet, signalling, negative), ±Inf, ±0, subnormals, ±MIN_POSITIVE, ±MAX |
//! | `depth24_code()`, `depth24_code_any()` | `u32` codes | 0, 1, 2, 2^24 − 3 … 2^24 − 1, byte roll-overs, powers of two ± 1; `_any` adds 2^24, u32::MAX, … |
//! | `near_far()`, `stiff_near_far()`, `near_plane()`, `far_near_ratio()` | `(near, far)` | near 10^-4 … 10, far/near 10 … 10^9 and +Inf; stiff: far/near ≥ 10^6 |
//! | `spec_power()`, `spec_power_in(lo, hi)` | `f32` exponents, log-uniform | both ends and their f32 neighbours |
//! | `light()`, `light_set(max)` | `Light { position, color }` around a shaded point at the origin | a light at the vertex (distance 0), 10^-6 … 10^4 distances, black lights, mirrored pairs that cancel |

use crate::depth24::DEPTH24_MAX;
use glam::Vec3;
use proptest::prelude::*;
use proptest::sample::select;

/// Normalise in `f64` and round each lane to `f32`: the unit vector nearest the direction, with
/// length within a few `f32` ULPs of 1 (each lane is correctly rounded). Zero stays zero.
fn unit_f64(v: [f64; 3]) -> Vec3 {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if len == 0.0 {
        return Vec3::ZERO;
    }
    Vec3::new(
        (v[0] / len) as f32,
        (v[1] / len) as f32,
        (v[2] / len) as f32,
    )
}

/// A direction from a cosine `z ∈ [−1, 1]` and an azimuth (uniform on the sphere when both are
/// uniform), in `f64`.
fn from_z_phi(z: f64, phi: f64) -> [f64; 3] {
    let r = (1.0 - z * z).max(0.0).sqrt();
    [r * phi.cos(), r * phi.sin(), z]
}

/// Signs to apply to a vector's lanes, as three booleans (true = negate). Negating `0.0` gives
/// `−0.0`, so axis cases cover signed zeros.
fn signs() -> impl Strategy<Value = [bool; 3]> {
    any::<[bool; 3]>()
}

fn apply_signs(v: Vec3, s: [bool; 3]) -> Vec3 {
    let f = |x: f32, neg: bool| if neg { -x } else { x };
    Vec3::new(f(v.x, s[0]), f(v.y, s[1]), f(v.z, s[2]))
}

/// Unit vectors (length 1 to within `f32` rounding of each lane), uniform on the sphere in about
/// a third of the cases and otherwise from adversarial sets:
/// - axis-aligned (poles `±z`, and `±x`, `±y`) with every combination of signed zeros;
/// - the equator `z = ±0`, and just off it (`|z|` from `2^-149` to `10^-3`): the octahedron fold
///   `|x| + |y| ≈ 1` of an octahedral map, where the upper and lower halves meet;
/// - the lower hemisphere's seams `x = ±0` or `y = ±0` with `z < 0` (the edges of the folded
///   octahedron square) and the neighbourhood of the south pole (its corners);
/// - near the poles, `|z| = 1 − ε` (view-space normals facing the camera, where `z = √(1−x²−y²)`
///   loses its digits);
/// - the diagonals `(±1, ±1, ±1)/√3` and `(±1, ±1, 0)/√2` (equal lanes: ties in packing).
pub fn unit_vector() -> impl Strategy<Value = Vec3> {
    use std::f64::consts::TAU;
    let uniform = (-1.0f64..=1.0, 0.0f64..TAU).prop_map(|(z, phi)| unit_f64(from_z_phi(z, phi)));
    let axes =
        (select(vec![Vec3::X, Vec3::Y, Vec3::Z]), signs()).prop_map(|(v, s)| apply_signs(v, s));
    let tiny_z = prop_oneof![
        Just(0.0f64),
        Just(f64::from(f32::from_bits(1))),
        Just(f64::from(f32::MIN_POSITIVE)),
        (-30.0f64..-3.0).prop_map(|e| 10f64.powf(e)),
    ];
    let fold = (tiny_z, 0.0f64..TAU, any::<bool>())
        .prop_map(|(z, phi, neg)| unit_f64(from_z_phi(if neg { -z } else { z }, phi)));
    let seams = (-1.0f64..0.0, any::<bool>(), any::<bool>()).prop_map(|(z, on_x, neg)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        let r = if neg { -r } else { r };
        // On the seam the other lane is a signed zero: `x = ±0` or `y = ±0`.
        let zero = if neg { -0.0 } else { 0.0 };
        // Division keeps the zero's sign, so the seam lane stays ±0 exactly.
        unit_f64(if on_x { [zero, r, z] } else { [r, zero, z] })
    });
    let near_pole = ((-12.0f64..-1.0), 0.0f64..TAU, any::<bool>()).prop_map(|(e, phi, south)| {
        let z = 1.0 - 10f64.powf(e);
        unit_f64(from_z_phi(if south { -z } else { z }, phi))
    });
    let s3 = 1.0 / 3f64.sqrt();
    let s2 = 1.0 / 2f64.sqrt();
    let diagonals = (
        select(vec![
            [s3, s3, s3],
            [s2, s2, 0.0],
            [s2, 0.0, s2],
            [0.0, s2, s2],
        ]),
        signs(),
    )
        .prop_map(|(v, s)| apply_signs(Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32), s));
    prop_oneof![
        4 => uniform,
        2 => axes,
        2 => fold,
        1 => seams,
        1 => near_pole,
        1 => diagonals,
    ]
}

/// Directions of any finite length: a [`unit_vector`] scaled by a length from `10^-42` (lanes
/// subnormal or zero) to `10^38` (lanes near `f32::MAX`), with the near-zero and huge ends
/// weighted in. For functions that normalise their input themselves. The zero vector is not
/// included (see [`bad_f32`] and the README's bad-input table for it).
pub fn direction() -> impl Strategy<Value = Vec3> {
    let length = prop_oneof![
        2 => (-38.0f64..38.0).prop_map(|e| 10f64.powf(e)),
        1 => select(vec![1e-42, 1e-38, 1e-30, 1e-19, 1.0, 1e19, 1e30, 1e38, 3.0e38]),
    ];
    (unit_vector(), length).prop_filter_map("scaled to zero", |(u, len)| {
        let v = Vec3::new(
            (f64::from(u.x) * len) as f32,
            (f64::from(u.y) * len) as f32,
            (f64::from(u.z) * len) as f32,
        );
        (v != Vec3::ZERO && v.is_finite()).then_some(v)
    })
}

/// `f32` values that are not ordinary: NaN (quiet, signalling, negative), `±Inf`, `±0.0`, the
/// smallest and largest subnormals of both signs, `±f32::MIN_POSITIVE` and `±f32::MAX`. Every
/// public function has a documented answer for these (docs/bad_input.md).
pub fn bad_f32() -> impl Strategy<Value = f32> {
    select(vec![
        f32::NAN,
        -f32::NAN,
        f32::from_bits(0x7f80_0001), // signalling NaN
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.0,
        -0.0,
        f32::from_bits(1),
        -f32::from_bits(1),
        f32::from_bits(0x007f_ffff),
        -f32::from_bits(0x007f_ffff),
        f32::MIN_POSITIVE,
        -f32::MIN_POSITIVE,
        f32::MAX,
        f32::MIN,
    ])
}

/// Any `f32` bit pattern, with [`bad_f32`]'s values weighted in (a uniform draw of 32 bits hits
/// NaN one time in 256 and zero almost never).
pub fn any_f32_bits() -> impl Strategy<Value = f32> {
    prop_oneof![3 => any::<u32>().prop_map(f32::from_bits), 1 => bad_f32()]
}

/// The edge codes of the 24-bit depth range: 0, 1, 2 and `2^24 − 3 … 2^24 − 1`.
pub const DEPTH24_EDGES: [u32; 6] = [0, 1, 2, DEPTH24_MAX - 2, DEPTH24_MAX - 1, DEPTH24_MAX];

/// 24-bit depth codes `0 ..= 2^24 − 1`: uniform in half the cases, otherwise the edges
/// ([`DEPTH24_EDGES`]), byte boundaries (`k·256 − 1`, `k·256`, `k·65536 ± 1`, where one channel
/// rolls over into the next) and powers of two with their neighbours.
pub fn depth24_code() -> impl Strategy<Value = u32> {
    let byte_edge = (
        0u32..=0xff,
        0u32..=0xff,
        select(vec![-1i64, 0, 1]),
        any::<bool>(),
    )
        .prop_map(|(hi, mid, off, wide)| {
            let base = if wide {
                i64::from(hi) << 16
            } else {
                i64::from(hi << 16 | mid << 8)
            };
            (base + off).clamp(0, i64::from(DEPTH24_MAX)) as u32
        });
    let power = (0u32..24, select(vec![-1i64, 0, 1]))
        .prop_map(|(k, off)| ((1i64 << k) + off).clamp(0, i64::from(DEPTH24_MAX)) as u32);
    prop_oneof![
        4 => 0..=DEPTH24_MAX,
        2 => select(DEPTH24_EDGES.to_vec()),
        1 => byte_edge,
        1 => power,
    ]
}

/// Any `u32` as a depth code: [`depth24_code`] in most cases, otherwise out-of-range values
/// (`2^24`, `2^24 + 1`, `2^31`, `u32::MAX − 1`, `u32::MAX`, or uniform above `2^24 − 1`), which
/// the depth functions saturate.
pub fn depth24_code_any() -> impl Strategy<Value = u32> {
    prop_oneof![
        4 => depth24_code(),
        1 => select(vec![DEPTH24_MAX + 1, DEPTH24_MAX + 2, 1 << 31, u32::MAX - 1, u32::MAX]),
        1 => (DEPTH24_MAX + 1)..=u32::MAX,
    ]
}

/// Near-plane distances `10^-4 … 10`, log-uniform, with both ends weighted in.
pub fn near_plane() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => (-4.0f64..=1.0).prop_map(|e| 10f64.powf(e) as f32),
        1 => select(vec![1e-4f32, 1e-3, 0.01, 0.1, 1.0, 10.0]),
    ]
}

/// Far/near ratios `10 … 10^9`, log-uniform, with both ends and the ratio where standard-Z's
/// relative error passes 1 % (`≈ 1.7·10^5`: `(f/n)·2^-24 = 0.01`) weighted in.
pub fn far_near_ratio() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => (1.0f64..=9.0).prop_map(|e| 10f64.powf(e)),
        1 => select(vec![10.0, 100.0, 1.7e5, 1e6, 1e9]),
    ]
}

/// `(near, far)` clip-plane pairs with `0 < near < far ≤ +Inf`: near from [`near_plane`], far =
/// near × [`far_near_ratio`] rounded to `f32` (so `far/near` spans `10 … 10^9`), plus infinite
/// far planes, plus "stiff" pairs with `far/near ≥ 10^6`, where the textbook linearisation loses
/// whole percents. A plain pair until the `Projection` type lands; then this strategy grows a
/// `Projection` twin.
pub fn near_far() -> impl Strategy<Value = (f32, f32)> {
    let finite = (near_plane(), far_near_ratio()).prop_map(|(n, r)| (n, (f64::from(n) * r) as f32));
    let infinite = near_plane().prop_map(|n| (n, f32::INFINITY));
    prop_oneof![6 => finite, 1 => infinite, 2 => stiff_near_far()]
}

/// Only the stiff `(near, far)` pairs: `far/near` from `10^6` to `10^9`, near from
/// [`near_plane`].
pub fn stiff_near_far() -> impl Strategy<Value = (f32, f32)> {
    (near_plane(), 6.0f64..=9.0).prop_map(|(n, e)| (n, (f64::from(n) * 10f64.powf(e)) as f32))
}

/// The range [`spec_power`] draws from: Blinn–Phong exponents `1 … 8192`.
pub const SPEC_POWER_RANGE: (f32, f32) = (1.0, 8192.0);

/// Specular exponents in `[lo, hi]` (`0 < lo < hi`, both finite), log-uniform (an encoding stores
/// them in log range, so errors are comparable across it), with both ends and their `f32`
/// neighbours inside the range weighted in.
///
/// # Panics
/// Unless `0 < lo < hi < +Inf` (a programming error in the test, not data).
pub fn spec_power_in(lo: f32, hi: f32) -> impl Strategy<Value = f32> {
    assert!(
        lo > 0.0 && lo < hi && hi.is_finite(),
        "spec_power_in needs 0 < lo < hi < Inf, got {lo} … {hi}"
    );
    let (l, h) = (f64::from(lo).log2(), f64::from(hi).log2());
    let ends = vec![
        lo,
        hi,
        f32::from_bits(lo.to_bits() + 1),
        f32::from_bits(hi.to_bits() - 1),
    ];
    prop_oneof![
        3 => (l..=h).prop_map(move |e| (e.exp2() as f32).clamp(lo, hi)),
        1 => select(ends),
    ]
}

/// [`spec_power_in`] over [`SPEC_POWER_RANGE`].
pub fn spec_power() -> impl Strategy<Value = f32> {
    spec_power_in(SPEC_POWER_RANGE.0, SPEC_POWER_RANGE.1)
}

/// One point light as a shading test sees it: position relative to the shaded point (which sits
/// at the origin) and linear RGB intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Light position minus shaded position.
    pub position: Vec3,
    /// Linear RGB intensity (non-negative).
    pub color: Vec3,
}

/// One light: a direction from [`unit_vector`] at a distance from `10^-6` to `10^4` (log-uniform),
/// or exactly at the shaded point (distance 0 — "a light at the vertex"), with an intensity from
/// 0 to `10^4` per channel, black and white weighted in.
pub fn light() -> impl Strategy<Value = Light> {
    let distance = prop_oneof![
        4 => (-6.0f64..=4.0).prop_map(|e| 10f64.powf(e)),
        1 => Just(0.0),
    ];
    let channel = prop_oneof![3 => 0.0f32..=1e4, 1 => select(vec![0.0f32, 1.0])];
    let color =
        (channel.clone(), channel.clone(), channel).prop_map(|(r, g, b)| Vec3::new(r, g, b));
    (unit_vector(), distance, color).prop_map(|(dir, d, color)| Light {
        position: Vec3::new(
            (f64::from(dir.x) * d) as f32,
            (f64::from(dir.y) * d) as f32,
            (f64::from(dir.z) * d) as f32,
        ),
        color,
    })
}

/// Sets of 1 to `max` lights (`max ≥ 1`): independent [`light`]s, or sets built to cancel — each
/// light paired with its mirror image through the shaded point, same intensity, so the summed
/// light direction is zero (aggregate-light schemes must not divide by that length).
///
/// # Panics
/// If `max` is 0.
pub fn light_set(max: usize) -> impl Strategy<Value = Vec<Light>> {
    assert!(max >= 1, "light_set needs max ≥ 1");
    let independent = proptest::collection::vec(light(), 1..=max);
    let pairs = (max / 2).max(1);
    let cancelling = proptest::collection::vec(light(), 1..=pairs).prop_map(move |ls| {
        let mut out = Vec::with_capacity(2 * ls.len());
        for l in ls {
            out.push(l);
            out.push(Light {
                position: -l.position,
                color: l.color,
            });
        }
        out.truncate(max);
        out
    });
    prop_oneof![3 => independent, 1 => cancelling]
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    fn sample<S: Strategy>(s: S, n: usize) -> Vec<S::Value> {
        let mut runner = TestRunner::deterministic();
        (0..n)
            .map(|_| s.new_tree(&mut runner).unwrap().current())
            .collect()
    }

    #[test]
    fn unit_vectors_are_unit_and_hit_the_adversarial_sets() {
        let vs = sample(unit_vector(), 4000);
        for v in &vs {
            // Each lane correctly rounded from the exact unit vector: |len − 1| ≤ 3·2^-24.
            let len = v.as_dvec3().length();
            crate::assert_within_abs!(
                len,
                1.0,
                3.0 * 2f64.powi(-24),
                "comment above: each lane correctly rounded, |len − 1| ≤ 3·2^-24",
                "{v}"
            );
        }
        assert!(
            vs.iter().any(|v| *v == Vec3::Z || *v == -Vec3::Z),
            "no pole"
        );
        assert!(vs.iter().any(|v| v.z == 0.0), "no equator");
        assert!(
            vs.iter().any(|v| v.z != 0.0 && v.z.abs() < 1e-20),
            "no near-fold"
        );
        assert!(vs.iter().any(|v| v.x.to_bits() == 0x8000_0000), "no −0.0");
        assert!(
            vs.iter()
                .any(|v| v.z < 0.0 && (v.x == 0.0 || v.y == 0.0) && v.z > -1.0),
            "no lower seam"
        );
    }

    #[test]
    fn directions_span_lengths() {
        let vs = sample(direction(), 2000);
        assert!(vs.iter().all(|v| v.is_finite() && *v != Vec3::ZERO));
        assert!(vs.iter().any(|v| v.as_dvec3().length() < 1e-30));
        assert!(vs.iter().any(|v| v.as_dvec3().length() > 1e30));
    }

    #[test]
    fn depth_codes_cover_edges_and_stay_in_range() {
        let cs = sample(depth24_code(), 2000);
        assert!(cs.iter().all(|&c| c <= DEPTH24_MAX));
        for e in DEPTH24_EDGES {
            assert!(cs.contains(&e), "edge {e:#x} missing");
        }
        let any = sample(depth24_code_any(), 2000);
        assert!(any.contains(&u32::MAX) && any.contains(&(DEPTH24_MAX + 1)));
    }

    #[test]
    fn near_far_pairs_are_ordered_and_reach_the_extremes() {
        let ps = sample(near_far(), 3000);
        for &(n, f) in &ps {
            assert!((1e-4..=10.0).contains(&n) && f > n, "({n}, {f})");
        }
        assert!(ps.iter().any(|p| p.1.is_infinite()));
        let ratio = |p: &(f32, f32)| f64::from(p.1) / f64::from(p.0);
        assert!(ps.iter().any(|p| p.1.is_finite() && ratio(p) > 0.99e9));
        assert!(ps.iter().any(|p| ratio(p) < 10.01));
    }

    #[test]
    fn spec_powers_stay_in_range_and_hit_both_ends() {
        let ps = sample(spec_power(), 2000);
        assert!(ps.iter().all(|p| (1.0..=8192.0).contains(p)));
        assert!(ps.contains(&1.0) && ps.contains(&8192.0));
    }

    #[test]
    fn light_sets_include_vertex_lights_and_cancelling_pairs() {
        let sets = sample(light_set(4), 2000);
        assert!(sets.iter().all(|s| (1..=4).contains(&s.len())));
        assert!(sets.iter().flatten().any(|l| l.position == Vec3::ZERO));
        assert!(sets.iter().any(|s| {
            s.len() >= 2
                && s.iter().map(|l| l.position).sum::<Vec3>() == Vec3::ZERO
                && s.iter().any(|l| l.position != Vec3::ZERO)
        }));
    }
}
