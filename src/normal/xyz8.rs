//! x, y, z as unorm8 in bytes 0–2 of an RGBA8 texel — the Rust twin of `wgsl/normal_xyz8.wgsl`.
//!
//! Resistance 2 stored "viewspace normals as 3 8-bit components for simplicity" with the spec power
//! in alpha (Mark Lee, "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009). Byte `b` stands
//! for the coordinate `(2b − 255)/255`; the decoder normalises. Measured over 2^24
//! spherical-Fibonacci directions on the adapter (see the README): mean 0.170°, max 0.39° angular
//! error — the 24-bit octahedral code is about 9 times better in the same bits.
//!
//! [`encode_normal_xyz8_best`] writes the same format as Godot 4 does (Kaplanyan's best-fit
//! normals): the code, of all 2^24, nearest in angle to the input, found by a search over the
//! dominant component's 128 odd values (no lookup texture). Over 2^24 Fibonacci directions on
//! lavapipe: mean 0.0280°, max 0.3150° (the rounding encoder: mean 0.170°, max 0.386°).

use glam::Vec3;

/// Encode a normal as `x | y << 8 | z << 16`, each byte `round(255·(u/2 + 1/2))` (round half to
/// even) of `u = n/|n|`; byte 3 is zero (for the material: spec power or roughness).
///
/// **Error bound:** each coordinate of the decoded direction is within half a byte step
/// (1/255) of `u`; angular error ≤ [`max_angle_deg`] (`asin(√3/255)`, derived there).
/// Bit-identical to `encode_normal_xyz8` on a correctly rounded adapter.
///
/// **Bad input:** see [`crate::normal`]: NaN, zero and all-subnormal vectors encode `+z`
/// (`0x00ff8080`), infinities win, any finite length is normalised.
pub fn encode_normal_xyz8(n: Vec3) -> u32 {
    super::encode_unorm_xyz(n, 255.0, 8)
}

/// Decode bytes 0–2 (byte 3 ignored) to the unit vector `normalize(2b − 255)`.
///
/// **Error bound:** the exact direction of the odd-integer vector `2b − 255`, off by the
/// normalisation's rounding only (≤ 2^-24·√2 rad on a correctly rounded adapter; WGSL's
/// `inverseSqrt` allowance only scales the length, by ≤ 2 ULP). Every bit pattern gives a finite
/// unit vector (the integer vector is never zero).
pub fn decode_normal_xyz8(p: u32) -> Vec3 {
    super::decode_unorm_xyz(p, 255, 8)
}

/// Render-target form of [`encode_normal_xyz8`]: the rgba8unorm channels (`byte/255`, alpha 0).
pub fn encode_normal_xyz8_unorm(n: Vec3) -> [f32; 4] {
    crate::depth24::unpack4x8unorm(encode_normal_xyz8(n))
}

/// Decode sampled rgba8unorm channels: each channel clamped to `[0, 1]` (NaN counts as 0),
/// rounded back to its byte (`round(255·c)`), then [`decode_normal_xyz8`]. Exact whenever each
/// channel is within ±0.49/255 of `byte/255` (so under `unpack4x8unorm`'s 3-ULP allowance).
pub fn decode_normal_xyz8_unorm(c: [f32; 4]) -> Vec3 {
    decode_normal_xyz8(unorm_bytes(c))
}

/// Encode a normal as the best-fit code (Kaplanyan, "CryENGINE 3: Reaching the speed of light",
/// SIGGRAPH 2010; Godot 4's G-buffer normal): of all 2^24 codes, the one whose decoded
/// direction — the odd-integer vector `D = 2b − 255` that [`decode_normal_xyz8`] normalises — is
/// nearest in angle to `n`. Same layout, decoder and bad-input rules as [`encode_normal_xyz8`].
///
/// **The search** (derivation at `best_fit_code` in the source): with `a = |s|` of the
/// sanitised input and its dominant axis first, every odd value `m` of `D`'s dominant component
/// is a plane; the best
/// code in that plane is one of the 3 × 3 odd points around where the ray meets it, scored by
/// `|s × D|²/|D|²` (sin² of the angle, times `|s|²`), the first strictly smallest kept. Planes
/// are visited from `m = 255` down, each skipped when a lower bound on its score already loses
/// (over 2^20 Fibonacci directions 5.7 of the 128 planes are scored on average, 20 at the
/// 99th percentile, all 128 at worst).
///
/// **Tie rule:** the smallest f32 score; on equal scores the first met: larger `m` (the longer
/// vector), then smaller second and third components (in the cyclic order after the dominant
/// axis, which is the first of equal largest magnitudes in x, y, z order). A zero component of
/// `n` (both signs) takes `D`'s positive sign there, as the rounding encoder does.
///
/// **Exact up to f32 scoring:** each candidate's computed sine is within
/// [`BEST_FIT_SINE_SLACK`] of its exact value, so the chosen code is at most
/// `2·BEST_FIT_SINE_SLACK` (in sine) worse than the exact best; checked against an exhaustive
/// search of every code by `tests/normal_xyz8.rs`, which reports how often the choice differs.
/// **Error bound:** at most [`max_angle_deg`] (the rounding encoder's code is one candidate).
/// Bit-identical to `encode_normal_xyz8_best` on an adapter that evaluates like the twins
/// (lavapipe); on any other conforming adapter the code may differ from the twin's only between
/// candidates within `2·`[`BEST_FIT_SINE_SLACK_CONFORMING`] of the best (such codes can be
/// many code steps apart: the one-code-step promise of the other encoders does not apply).
///
/// **Cost:** a loop of 128 planes of about 15 operations each (no division or square root),
/// and 9 candidates of about 17 operations for each plane the bound does not skip (a division
/// each): on the order of a hundred times the rounding encoder's work; meant for G-buffer
/// passes that can afford it, or for baking on the CPU.
pub fn encode_normal_xyz8_best(n: Vec3) -> u32 {
    best_fit_code(super::sanitize(n).unwrap_or(Vec3::Z), true)
}

/// Render-target form of [`encode_normal_xyz8_best`]: the rgba8unorm channels (`byte/255`,
/// alpha 0).
pub fn encode_normal_xyz8_best_unorm(n: Vec3) -> [f32; 4] {
    crate::depth24::unpack4x8unorm(encode_normal_xyz8_best(n))
}

/// [`encode_normal_xyz8_best`] visiting every plane (no skipping): the same code, by the
/// bound's construction; for the tests that check so.
#[doc(hidden)]
pub fn encode_normal_xyz8_best_full_search(n: Vec3) -> u32 {
    best_fit_code(super::sanitize(n).unwrap_or(Vec3::Z), false)
}

/// How far, in sine, a best-fit candidate's computed score `√(S/L)` can be from the exact sine
/// of its angle (`L = 1 + t1² + t2²`, `t = a/a_dominant`): `t` is one correctly rounded quotient
/// (relative `2^-24`), the hit `h = m·t` one product, so `h` is within `m·2^-23` of `m·t_exact`
/// (`m ≤ 255`); `e = d − h` adds a relative `2^-24` of `|e| ≤ 3`; the cross product
/// `(t1·e2 − t2·e1, −e2, e1)` is then off by at most `3·m·2^-23 + 2^-21` per component, √3 of
/// that in length, and divided by `|s'|·|D| ≥ m` that is under `√3·(3 + 4)·2^-23 < 2^-19` in
/// sine; the squares, sums and the quotient add a few relative ULPs, far below. So
/// `2^-19` (1.9e-6).
pub const BEST_FIT_SINE_SLACK: f32 = 1.0 / 524_288.0;

/// [`BEST_FIT_SINE_SLACK`] on any conforming adapter: the same error terms, each at most five
/// times as large (`+ − ×` may round to either neighbour, `2u` instead of `u`; the quotient
/// `t` may err 2.5 ULP, `5u`; a fused product is no worse than the unfused one), so `5·2^-19`.
/// Where the WGSL's code differs from the twin's on such an adapter, its exact angle exceeds the
/// best code's by at most twice this (the plane bound's margin of `2·`[`BEST_FIT_SINE_SLACK`]
/// only skips planes whose candidates are farther still).
pub const BEST_FIT_SINE_SLACK_CONFORMING: f32 = 5.0 / 524_288.0;

/// The best-fit search on a sanitised `s` (largest magnitude in `[1, 4)`): the code, with
/// `prune` skipping planes that cannot win (the tests compare with `prune = false`).
///
/// **Why the 3 × 3 block suffices.** Let `ŝ` be the unit direction, `e0` the dominant axis, and
/// `D* ` the best code, in plane `m = D*·e0` (its signs are `ŝ`'s: flipping a component against
/// `ŝ` lowers `ŝ·D` at the same `|D|`). Write a plane point as `H + v`, `H = m ŝ/ŝ0` the hit and
/// `v ⊥ e0`. Then `sin²θ = Q(v)/|H + v|²` with `Q(v) = |v|² − (ŝ·v)²`, whose eigenvalues lie in
/// `[ŝ0², 1]` and `ŝ0² ≥ 1/3`. A point has angle at most θ iff
/// `Q(v) − k|v|² − 2k H·v ≤ k|H|²` (`k = sin²θ`). `θ* ≤ asin(√3/255)` (the rounding code is a
/// candidate), so `k ≤ 3/255²` and `k|H| ≤ 3·√3·255/255² < 0.021`. Outside the block some
/// coordinate of `v` is at least 3 from the hit (the block holds the three odd values nearest
/// each coordinate), so the left side is at least `9(1/3 − k) − 6k|H| > 2.87`; the block's
/// nearest corner has `|v|² ≤ 2` and left side at most `2 + 2√2·k|H| < 2.07`. So a point
/// outside the block is never the best. Values beyond 255 are clamped (a repeated candidate).
///
/// **The plane bound.** With `ρ` the distance from the hit to the nearest odd point of the
/// plane, every point of the plane has `sin θ ≥ ŝ0·ρ/(|H| + ρ) ≥ ρ/(L(m + ρ))`. Each candidate's
/// computed score `S̃` is at least `L(sin θ − Δ)²` (`Δ` = [`BEST_FIT_SINE_SLACK`]), so a plane
/// whose bound exceeds `τ = √(best/L) + 2Δ` cannot win: every candidate's `S̃` would exceed
/// the best score so far, and skipping it never changes the full search's answer (the second
/// `Δ` covers the roundings of `τ` and of the test, relative `2^-21` of a sine under 0.007).
/// With `T = τL < 1/2`, `ρ/(L(m + ρ)) > τ` is `ρ > m·T/(1 − T)`: after each plane scored, the
/// search sets `cut = T/(1 − T)` (or, while `T ≥ 1/2`, a cut no `ρ ≤ √2` can pass) and skips a
/// plane when `ρ² > (cut·m)²`: no division or square root per plane.
pub(crate) fn best_fit_code(s: Vec3, prune: bool) -> u32 {
    let a = s.abs();
    let axis = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    let r = match axis {
        0 => a,
        1 => Vec3::new(a.y, a.z, a.x),
        _ => Vec3::new(a.z, a.x, a.y),
    };
    let (t1, t2) = (r.y / r.x, r.z / r.x);
    let l = (1.0 + t1 * t1) + t2 * t2;
    let margin = 2.0 * BEST_FIT_SINE_SLACK;
    let mut best = 4.0f32;
    let mut bd = [255.0f32, 1.0, 1.0];
    // Skip a plane when ρ > cut·m (see the doc above); no skipping until a score is known.
    let mut cut = 1.0e6f32;
    for i in 0..128 {
        let m = (255 - 2 * i) as f32;
        let (h1, h2) = (m * t1, m * t2);
        let q1 = (h1 * 0.5).floor() * 2.0 + 1.0;
        let q2 = (h2 * 0.5).floor() * 2.0 + 1.0;
        let (r1, r2) = (h1 - q1, h2 - q2);
        let cm = cut * m;
        if prune && r1 * r1 + r2 * r2 > cm * cm {
            continue;
        }
        for j in [-2.0f32, 0.0, 2.0] {
            let d1 = (q1 + j).clamp(1.0, 255.0);
            let e1 = d1 - h1;
            for k in [-2.0f32, 0.0, 2.0] {
                let d2 = (q2 + k).clamp(1.0, 255.0);
                let e2 = d2 - h2;
                let c = Vec3::new(t1 * e2 - t2 * e1, e2, e1);
                let len2 = (m * m + d1 * d1) + d2 * d2;
                let score = super::dot(c, c) / len2;
                if score < best {
                    best = score;
                    bd = [m, d1, d2];
                }
            }
        }
        let tl = ((best / l).sqrt() + margin) * l;
        cut = if tl < 0.5 { tl / (1.0 - tl) } else { 1.0e6 };
    }
    let d = match axis {
        0 => bd,
        1 => [bd[2], bd[0], bd[1]],
        _ => [bd[1], bd[2], bd[0]],
    };
    let sg = s.to_array();
    (0..3).fold(0, |acc, k| {
        let dk = if sg[k] >= 0.0 { d[k] } else { -d[k] };
        acc | ((((dk + 255.0) * 0.5) as u32) << (8 * k))
    })
}

/// `round(255·clamp(c, 0, 1))` per channel (NaN → 0), packed byte 0 = `c[0]`.
pub(crate) fn unorm_bytes(c: [f32; 4]) -> u32 {
    c.iter().enumerate().fold(0, |acc, (k, &x)| {
        let x = if x.is_nan() { 0.0 } else { x };
        acc | (((x.clamp(0.0, 1.0) * 255.0).round_ties_even() as u32) << (8 * k))
    })
}

/// Exact references.
pub mod exact {
    /// The encoder in f64: the byte nearest `255·(u/2 + 1/2)` per coordinate of the unit
    /// vector `u` (ties cannot occur for the irrational-looking test directions; half to even).
    pub fn encode(n: [f64; 3]) -> u32 {
        super::super::exact::encode_unorm_xyz(n, 255.0, 8)
    }

    /// The best-fit encoder's reference in f64: the plane search of
    /// `best_fit_code` (every plane, the 3 × 3 block the proof there shows holds the
    /// best) scored by `(u·D)²/|D|²` of the unit `u` (largest wins), signs from `u` (`+` at 0).
    pub fn encode_best(n: [f64; 3]) -> u32 {
        let u = super::super::exact::unit(n).unwrap_or([0.0, 0.0, 1.0]);
        let a = u.map(f64::abs);
        let axis = if a[0] >= a[1] && a[0] >= a[2] {
            0
        } else if a[1] >= a[2] {
            1
        } else {
            2
        };
        let (i1, i2) = ((axis + 1) % 3, (axis + 2) % 3);
        let (t1, t2) = (a[i1] / a[axis], a[i2] / a[axis]);
        let mut best = (-1.0f64, [0i32; 3]);
        for m in (1..=255).rev().step_by(2) {
            let q = |t: f64| 2 * ((f64::from(m) * t * 0.5).floor() as i32) + 1;
            for d1 in [-2, 0, 2].map(|j| (q(t1) + j).clamp(1, 255)) {
                for d2 in [-2, 0, 2].map(|k| (q(t2) + k).clamp(1, 255)) {
                    let mut d = [0i32; 3];
                    (d[axis], d[i1], d[i2]) = (m, d1, d2);
                    let c = cos2(a, d);
                    if c > best.0 {
                        best = (c, d);
                    }
                }
            }
        }
        code_of(u, best.1)
    }

    /// The best-fit code by exhaustion: every code whose signs are `n`'s (`+` at 0) — 2^21 of
    /// the 2^24; the others are never nearer, as flipping a component against `n` lowers
    /// `n·D` at the same `|D|` — scored by `(u·D)²/|D|²` in f64, largest first met (dominant
    /// values from 255 down are not the order here: x, y, z each from 255 down).
    pub fn encode_best_exhaustive(n: [f64; 3]) -> u32 {
        let u = super::super::exact::unit(n).unwrap_or([0.0, 0.0, 1.0]);
        let a = u.map(f64::abs);
        let mut best = (-1.0f64, [0i32; 3]);
        for x in (1..=255).rev().step_by(2) {
            for y in (1..=255).rev().step_by(2) {
                let (px, len_xy) = (a[0] * f64::from(x) + a[1] * f64::from(y), x * x + y * y);
                for z in (1..=255).rev().step_by(2) {
                    let dot = px + a[2] * f64::from(z);
                    let c = dot * dot / f64::from(len_xy + z * z);
                    if c > best.0 {
                        best = (c, [x, y, z]);
                    }
                }
            }
        }
        code_of(u, best.1)
    }

    /// The angle in radians between `n` and the direction of code `p`, from the sine
    /// `|n × D|/(|n||D|)` (accurate for small angles).
    pub fn angle_to(n: [f64; 3], p: u32) -> f64 {
        let d = decode(p);
        let c = [
            n[1] * d[2] - n[2] * d[1],
            n[2] * d[0] - n[0] * d[2],
            n[0] * d[1] - n[1] * d[0],
        ];
        let len = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let dot = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        len(c).atan2(dot)
    }

    fn cos2(a: [f64; 3], d: [i32; 3]) -> f64 {
        let dot = a[0] * f64::from(d[0]) + a[1] * f64::from(d[1]) + a[2] * f64::from(d[2]);
        dot * dot / f64::from(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
    }

    fn code_of(u: [f64; 3], d: [i32; 3]) -> u32 {
        (0..3).fold(0, |acc, k| {
            let dk = if u[k] >= 0.0 { d[k] } else { -d[k] };
            acc | (((dk + 255) / 2) as u32) << (8 * k)
        })
    }

    /// The direction a code stands for, in f64.
    pub fn decode(p: u32) -> [f64; 3] {
        super::super::exact::decode_unorm_xyz(p, 255, 8)
    }
}

/// The worst angular error of an xyz8 round trip, in degrees, derived: each decoded coordinate
/// `(2b − 255)/255` is within half a step, 1/255, of the unit input's, so the decoded point is
/// within `√3/255` of the input and the angle is at most `asin(√3/255)` (0.3892°). Measured round
/// trips are checked against this plus [`super::F32_SLACK_DEG`].
pub fn max_angle_deg() -> f64 {
    (3f64.sqrt() / 255.0).asin().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figure the docs quote is the formula's.
    #[test]
    fn max_angle_deg_is_the_documented_figure() {
        assert_eq!(format!("{:.4}", max_angle_deg()), "0.3892");
    }

    #[test]
    fn degenerate_inputs_encode_plus_z_and_byte_3_is_free() {
        let z = encode_normal_xyz8(Vec3::Z);
        assert_eq!(z, 0x00ff_8080);
        for v in [
            Vec3::ZERO,
            Vec3::new(0.0, f32::NAN, 1.0),
            Vec3::splat(-1e-42),
        ] {
            assert_eq!(encode_normal_xyz8(v), z);
        }
        assert_eq!(
            encode_normal_xyz8(Vec3::new(1.0, f32::NEG_INFINITY, 3.0)),
            encode_normal_xyz8(Vec3::NEG_Y)
        );
        assert_eq!(decode_normal_xyz8(0xab00_0000 | z), decode_normal_xyz8(z));
        crate::assert_within_abs!(
            decode_normal_xyz8(z).length(),
            1.0,
            < 1e-6_f32,
            "literal: 1e-6 ≈ 17u, a few f32 roundings of the normalise",
            "code {z:#x}"
        );
    }
}
