//! [`LIGHTING`]: the light pre-pass (`prepass::lighting::lpp`: the light-buffer writes P, the
//! reconstruction and the combine C), the aggregate vertex lights and the light volumes, each
//! against its documented range and bad-input answer (module docs of `prepass::lighting::*`).

use crate::normal::assert_unit;
use crate::{Entry, Input};
use glam::{Vec2, Vec3, Vec4};
use prepass::assert_within_abs;
use prepass::lighting::aggregate_light as agg;
use prepass::lighting::light_volume as lv;
use prepass::lighting::lpp::{self, LPP_COLOUR_MAX};

/// [`lpp::bounds::n_dot_l_max`] in the `f32` the functions return.
fn n_dot_l_max() -> f32 {
    lpp::bounds::n_dot_l_max() as f32
}

/// Largest light-buffer channel: the clamped colour times [`n_dot_l_max`].
fn light_max() -> f32 {
    LPP_COLOUR_MAX * n_dot_l_max()
}

/// An aggregate-light lane as the functions read it: NaN → 0, clamped to ±2^100.
fn read_finite3(v: Vec3) -> Vec3 {
    let l = agg::AGGREGATE_LIGHT_LIMIT;
    let lane = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(-l, l) };
    Vec3::new(lane(v.x), lane(v.y), lane(v.z))
}

fn finite3(v: Vec3) -> bool {
    v.is_finite()
}

/// A normal, `to_eye` or `to_light` the light pre-pass treats as missing: non-finite, or with a
/// largest component that is zero or subnormal.
fn bad_direction(v: Vec3) -> bool {
    !v.is_finite() || !v.abs().max_element().is_normal()
}

/// A light-buffer texel or colour: finite, no negative channel, no channel above `max`.
#[track_caller]
fn assert_light(v: &[f32], max: f32, context: std::fmt::Arguments<'_>) {
    for &c in v {
        assert!(
            c.is_finite() && (0.0..=max).contains(&c),
            "{context}: {v:?}"
        );
    }
}

/// The one-buffer light P shared by the Blinn-Phong and Phong entries.
#[track_caller]
fn one_buffer(i: &mut Input, phong: bool) {
    let (n, e, l, c) = (i.vec3(), i.vec3(), i.vec3(), i.vec3());
    let (att, power) = (i.f32(), i.f32());
    let p = if phong {
        lpp::lpp_phong_light(n, e, l, c, att, power)
    } else {
        lpp::lpp_blinn_phong_light(n, e, l, c, att, power)
    };
    let ctx = format_args!("{n:?} {e:?} {l:?} {c:?} {att:?} {power:?} → {p:?}");
    assert_light(&p.to_array(), light_max(), ctx);
    let bad = [n, e, l].into_iter().any(bad_direction)
        || !finite3(c)
        || !att.is_finite()
        || !power.is_finite();
    if bad {
        assert_eq!(p, Vec4::ZERO, "{ctx}: bad input gives zero light");
    }
}

/// Lighting: any bit patterns in, the documented range or bad-input answer out.
pub const LIGHTING: &[Entry] = &[
    Entry {
        name: "lighting::lpp::lpp_direction",
        check: |i| {
            let v = i.vec3();
            let d = lpp::lpp_direction(v);
            if bad_direction(v) {
                assert_eq!(d, Vec3::ZERO, "{v:?}: zero direction");
            } else {
                assert_unit(d, format_args!("lpp_direction {v:?}"));
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_pow_cosine",
        check: |i| {
            let (x, y) = (i.f32(), i.f32());
            let p = lpp::lpp_pow_cosine(x, y);
            assert!((0.0..=1.0).contains(&p), "{x:?}^{y:?} → {p:?}");
            if x.is_nan() || y.is_nan() || x <= 0.0 {
                assert_eq!(p, 0.0, "{x:?}^{y:?}");
            } else if x >= 1.0 {
                assert_eq!(p, 1.0, "{x:?}^{y:?}");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_point_attenuation",
        check: |i| {
            let (d, r) = (i.f32(), i.f32());
            let a = lpp::lpp_point_attenuation(d, r);
            assert!((0.0..=1.0).contains(&a), "{d:?}, {r:?} → {a:?}");
            if !d.is_finite() || !r.is_finite() || r <= 0.0 || d >= r {
                assert_eq!(a, 0.0, "{d:?}, {r:?}: no light");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_spot_attenuation",
        check: |i| {
            let (c, outer, inner) = (i.f32(), i.f32(), i.f32());
            let a = lpp::lpp_spot_attenuation(c, outer, inner);
            assert!(
                (0.0..=1.0).contains(&a),
                "{c:?} {outer:?} {inner:?} → {a:?}"
            );
            if c.is_nan() || outer.is_nan() || inner.is_nan() {
                assert_eq!(a, 0.0, "{c:?} {outer:?} {inner:?}: NaN → no light");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_cosines",
        check: |i| {
            let (n, e, l, phong) = (i.vec3(), i.vec3(), i.vec3(), i.u8() & 1 == 1);
            let (nl, s) = lpp::lpp_cosines(n, e, l, phong);
            assert!(
                (0.0..=n_dot_l_max()).contains(&nl) && (0.0..=1.0).contains(&s),
                "{n:?} {e:?} {l:?} {phong} → ({nl:?}, {s:?})"
            );
            if [n, e, l].into_iter().any(bad_direction) {
                assert_eq!((nl, s), (0.0, 0.0), "{n:?} {e:?} {l:?}: no light");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_blinn_phong_light",
        check: |i| one_buffer(i, false),
    },
    Entry {
        name: "lighting::lpp::lpp_phong_light",
        check: |i| one_buffer(i, true),
    },
    Entry {
        name: "lighting::lpp::lpp_point_light",
        check: |i| {
            let (n, e, l, cr, power) = (i.vec3(), i.vec3(), i.vec3(), i.vec4(), i.f32());
            let p = lpp::lpp_point_light(n, e, l, cr, power);
            assert_light(
                &p.to_array(),
                light_max(),
                format_args!("{n:?} {e:?} {l:?} {cr:?} {power:?}"),
            );
        },
    },
    Entry {
        name: "lighting::lpp::lpp_spot_light",
        check: |i| {
            let (n, e, l, cr, ax) = (i.vec3(), i.vec3(), i.vec3(), i.vec4(), i.vec4());
            let (inner, power) = (i.f32(), i.f32());
            let p = lpp::lpp_spot_light(n, e, l, cr, ax, inner, power);
            assert_light(
                &p.to_array(),
                light_max(),
                format_args!("{n:?} {e:?} {l:?} {cr:?} {ax:?} {inner:?} {power:?}"),
            );
        },
    },
    Entry {
        name: "lighting::lpp::lpp_blinn_phong_specular_rgb",
        check: |i| {
            let (n, e, l, c) = (i.vec3(), i.vec3(), i.vec3(), i.vec3());
            let (att, power) = (i.f32(), i.f32());
            let s = lpp::lpp_blinn_phong_specular_rgb(n, e, l, c, att, power);
            let ctx = format_args!("{n:?} {e:?} {l:?} {c:?} {att:?} {power:?} → {s:?}");
            assert_light(&s.to_array(), light_max(), ctx);
            if !finite3(c) || !att.is_finite() || !power.is_finite() {
                assert_eq!(s, Vec3::ZERO, "{ctx}");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_reconstruct_specular (the light-buffer decode)",
        check: |i| {
            let (light, m) = (i.vec4(), i.f32());
            let s = lpp::lpp_reconstruct_specular(light, m);
            // Documented: never above lum(max(rgb, 0)); 0 for non-finite input.
            let lum = lpp::lpp_luminance(light.truncate().max(Vec3::ZERO));
            assert!(s.is_finite() && s >= 0.0, "{light:?} {m:?} → {s:?}");
            if light.is_finite() && m.is_finite() {
                assert!(s <= lum, "{light:?} {m:?} → {s:?} above lum {lum:?}");
            } else {
                assert_eq!(s, 0.0, "{light:?} {m:?}: non-finite → 0");
            }
        },
    },
    Entry {
        name: "lighting::lpp::lpp_clamp_colour",
        check: |i| {
            let c = i.vec3();
            let k = lpp::lpp_clamp_colour(c);
            assert_light(&k.to_array(), LPP_COLOUR_MAX, format_args!("{c:?}"));
            for (x, y) in c.to_array().into_iter().zip(k.to_array()) {
                if (0.0..=LPP_COLOUR_MAX).contains(&x) {
                    assert_eq!(x, y, "{c:?}: in range → unchanged");
                }
            }
        },
    },
    Entry {
        name: "lighting::lpp::{lpp_combine, lpp_combine_two_buffers, lpp_luminance}",
        check: |i| {
            let (albedo, gloss, light, m) = (i.vec3(), i.vec3(), i.vec4(), i.f32());
            let (d, s) = (i.vec3(), i.vec3());
            let c1 = lpp::lpp_combine(albedo, gloss, light, m);
            let c2 = lpp::lpp_combine_two_buffers(albedo, gloss, d, s);
            // Clamped factors: never NaN or negative. The reconstructed specular is bounded by
            // lum(rgb) of the unclamped texel, so the sum is finite (≤ 2·65504²) when the texel's
            // channels are within an rgba16float light buffer's 65504; beyond that (a texel no
            // f16 target holds) `gloss·spec` may overflow to +∞ (found by this target).
            let max = 2.0 * LPP_COLOUR_MAX * LPP_COLOUR_MAX;
            let in_f16 = light.to_array().iter().all(|c| c.abs() <= LPP_COLOUR_MAX);
            for ch in c1.to_array() {
                assert!(ch >= 0.0, "{albedo:?} {gloss:?} {light:?} {m:?} → {c1:?}");
            }
            if in_f16 {
                assert_light(
                    &c1.to_array(),
                    max,
                    format_args!("{albedo:?} {gloss:?} {light:?} {m:?}"),
                );
            }
            assert_light(
                &c2.to_array(),
                max,
                format_args!("{albedo:?} {gloss:?} {d:?} {s:?}"),
            );
            // Luminance of clamped colours: finite, within [0, 65504] (weights sum to 1).
            let lum = lpp::lpp_luminance(lpp::lpp_clamp_colour(d));
            assert!(
                lum.is_finite() && (0.0..=LPP_COLOUR_MAX * (1.0 + 2f32.powi(-22))).contains(&lum),
                "{d:?} → {lum:?}"
            );
        },
    },
    Entry {
        name: "lighting::aggregate_light::{aggregate_light_accumulate, _accumulate_colour}",
        check: |i| {
            let (acc, v, p, w) = (i.vec4(), i.vec3(), i.vec3(), i.f32());
            let (cacc, c, dir) = (i.vec3(), i.vec3(), i.vec3());
            // Documented: positions read within ±2^100 (no P − V overflows), a skipped light
            // returns the accumulator read finite (NaN → 0, beyond ±2^100 → ±2^100).
            let rel = read_finite3(p) - read_finite3(v);
            let skipped =
                !v.is_finite() || !p.is_finite() || rel.abs().max_element() < agg::AT_VERTEX;
            let a = agg::aggregate_light_accumulate(acc, v, p, w);
            assert!(
                a.is_finite(),
                "{acc:?} {v:?} {p:?} {w:?} → {a:?}: not finite"
            );
            if skipped || !w.is_finite() {
                let want = read_finite3(acc.truncate()).extend(read_finite3(Vec3::splat(acc.w)).x);
                assert_eq!(
                    a.to_array().map(f32::to_bits),
                    want.to_array().map(f32::to_bits),
                    "{v:?} {p:?} {w:?}: skipped"
                );
            }
            let k = agg::aggregate_light_accumulate_colour(cacc, v, p, c, dir);
            assert!(
                k.is_finite(),
                "{cacc:?} {v:?} {p:?} {c:?} {dir:?} → {k:?}: not finite"
            );
            if skipped || !c.is_finite() || !dir.is_finite() {
                assert_eq!(
                    k.to_array().map(f32::to_bits),
                    read_finite3(cacc).to_array().map(f32::to_bits),
                    "{v:?} {p:?} {c:?} {dir:?}: skipped"
                );
            }
        },
    },
    Entry {
        name: "lighting::aggregate_light::{aggregate_light_direction, _position, _diffuse}",
        check: |i| {
            let (acc, v) = (i.vec4(), i.vec3());
            let d = agg::aggregate_light_direction(acc);
            if d != Vec3::ZERO {
                assert_unit(d, format_args!("aggregate_light_direction {acc:?}"));
            }
            let x = acc.truncate();
            let p = agg::aggregate_light_position(acc, v);
            assert!(p.is_finite(), "{acc:?} {v:?} → {p:?}: not finite");
            if !x.is_finite() || !acc.w.is_finite() || acc.w.is_nan() || acc.w < f32::MIN_POSITIVE {
                assert_eq!(
                    p.to_array().map(f32::to_bits),
                    read_finite3(v).to_array().map(f32::to_bits),
                    "{acc:?}: nothing accumulated → V (read finite)"
                );
            }
            let (n, pos, c) = (i.vec3(), i.vec3(), i.vec3());
            let diffuse = agg::aggregate_light_diffuse(n, pos, p, c);
            for ch in diffuse.to_array() {
                assert!(
                    !ch.is_nan() && ch >= 0.0,
                    "{n:?} {pos:?} {p:?} {c:?} → {diffuse:?}"
                );
            }
            if !pos.is_finite() || !p.is_finite() || !c.is_finite() {
                assert_eq!(diffuse, Vec3::ZERO, "non-finite input → 0");
            }
        },
    },
    Entry {
        name: "lighting::light_volume::light_volume_near_corner_distance",
        check: |i| {
            let (n, tx, ty) = (i.f32(), i.f32(), i.f32());
            let rho = lv::light_volume_near_corner_distance(n, tx, ty);
            let bad = [n, tx, ty].iter().any(|x| !x.is_finite() || *x < 0.0);
            if bad {
                assert_eq!(rho, 3.4e38, "{n:?} {tx:?} {ty:?}: bad input");
            } else if [n, tx, ty].iter().all(|x| *x <= 1e18) {
                // No overflow: ρ = near·√(1 + tx² + ty²) ≥ near.
                assert!(rho.is_finite() && rho >= n, "{n:?} {tx:?} {ty:?} → {rho:?}");
            }
        },
    },
    Entry {
        name: "lighting::light_volume::{light_volume_sphere_needs_depth_fail, light_volume_cone_needs_depth_fail}",
        check: |i| {
            let (c, r, rho) = (i.vec3(), i.f32(), i.f32());
            let f = lv::light_volume_sphere_needs_depth_fail(c, r, rho);
            assert!(f <= 1, "{f}");
            if !c.is_finite() || !r.is_finite() || !rho.is_finite() || r < 0.0 || rho < 0.0 {
                assert_eq!(f, 1, "{c:?} {r:?} {rho:?}: bad input → depth-fail");
            } else if c.as_dvec3().length() <= f64::from(r) + f64::from(rho) {
                // The safety property: the eye's ρ-ball touches the sphere → depth-fail.
                assert_eq!(
                    f, 1,
                    "{c:?} {r:?} {rho:?}: the near plane may cut the sphere"
                );
            }
            let (apex, axis, rt) = (i.vec3(), i.vec3(), Vec2::new(i.f32(), i.f32()));
            let g = lv::light_volume_cone_needs_depth_fail(apex, axis, rt, rho);
            assert!(g <= 1, "{g}");
            if !apex.is_finite() || !axis.is_finite() || !rt.is_finite() || !rho.is_finite() {
                assert_eq!(
                    g, 1,
                    "{apex:?} {axis:?} {rt:?} {rho:?}: bad input → depth-fail"
                );
            } else if rho >= 0.0 && apex.as_dvec3().length() <= f64::from(rho) {
                assert_eq!(g, 1, "{apex:?} {rho:?}: the apex is within ρ of the eye");
            }
        },
    },
    Entry {
        name: "lighting::light_volume::{light_volume_window_depth, light_volume_sphere_depth_bounds, _bounds24}",
        check: |i| {
            let (cz, r) = (i.f32(), i.f32());
            let Ok(p) = crate::projection(i) else { return };
            let (n, f, conv) = (p.near(), p.far(), p.convention());
            // Window depth inside [near, far]: within the documented 8u·(1 + f/(f − n)) of exact.
            let t = f64::from(i.u32()) / f64::from(u32::MAX);
            let vz = if f.is_finite() {
                (f64::from(n) + t * (f64::from(f) - f64::from(n))) as f32
            } else {
                (f64::from(n) / (1.0 - t).max(1e-30)) as f32
            };
            if vz.is_finite() {
                let z = lv::light_volume_window_depth(vz, n, f, conv);
                let e = lv::exact::light_volume_window_depth(
                    f64::from(vz),
                    f64::from(n),
                    f64::from(f),
                    conv,
                );
                let k = if f.is_finite() {
                    f64::from(f) / (f64::from(f) - f64::from(n))
                } else {
                    1.0
                };
                assert_within_abs!(
                    f64::from(z),
                    e,
                    8.0 * f64::from(lv::LIGHT_VOLUME_U) * (1.0 + k),
                    "light_volume_window_depth's doc: 8u·(1 + f/(f − n))",
                    "vz {vz:?} {p:?}"
                );
            }
            let b = lv::light_volume_sphere_depth_bounds(cz, r, n, f, conv);
            assert!(
                (0.0..=1.0).contains(&b.x) && (0.0..=1.0).contains(&b.y),
                "{cz:?} {r:?} {p:?} → {b:?}"
            );
            assert!(
                b.x <= b.y || b == Vec2::new(1.0, 0.0),
                "{cz:?} {r:?} {p:?} → {b:?}"
            );
            if !cz.is_finite() || !r.is_finite() || r < 0.0 {
                assert_eq!(
                    b,
                    Vec2::new(0.0, 1.0),
                    "{cz:?} {r:?}: bad input → full range"
                );
            }
            let c = lv::light_volume_sphere_depth_bounds24(cz, r, n, f, conv);
            let max = prepass::depth24::DEPTH24_MAX;
            if b.x > b.y {
                assert_eq!(c, [max, 0], "empty range");
            } else {
                assert!(c[0] <= c[1] && c[1] <= max, "{b:?} → {c:?}");
                // As documented, in f32: (floor(min·(2^24 − 1)), ceil(max·(2^24 − 1))).
                let m = max as f32;
                assert_eq!(
                    c,
                    [(b.x * m).floor() as u32, (b.y * m).ceil() as u32],
                    "{b:?} → {c:?}"
                );
            }
        },
    },
];
