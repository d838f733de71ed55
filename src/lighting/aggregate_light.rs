//! God of War III's aggregate vertex lights — Rust twins of `wgsl/aggregate_light.wgsl`.
//! Source: Vassily Filippov, "Dynamic lighting in GOW3" (Sony Santa Monica; Advances in
//! Real-Time Rendering in 3D Graphics and Games, SIGGRAPH 2011).
//!
//! Per vertex `V`, lights `i` (position `P_i`, weight `W_i` = its intensity at `V`) fold into
//! one aggregate light:
//! `acc.xyz = Σ W_i·L_i` with `L_i = (P_i − V)/|P_i − V|`, `acc.w = Σ W_i/|P_i − V|`;
//! position `P_agg = V + acc.xyz/acc.w`, direction `L_agg = acc.xyz/|acc.xyz|`, colour
//! `C_agg = Σ C_i (L_i·L_agg)`. Per pixel the interpolated `P_agg` gives
//! `C_agg·max(N·normalize(P_agg − p), 0)`.
//!
//! **Why it is exact for luminance** (Filippov's argument): with scalar luminances `l_i`,
//! `X = Σ l_i L_i`, `L_agg = X/|X|` and `l_agg = Σ l_i (L_i·L_agg) = X·L_agg = |X|`, so
//! `(N·L_agg)·l_agg = N·X = Σ l_i (N·L_i)` — the per-light sum whenever every `N·L_i ≥ 0`.
//! `tests/aggregate_light.rs` checks it on the adapter within a derived rounding budget.
//!
//! **Twins** use the same `f32` formulas; not bit-identical to an adapter (`inverseSqrt`, `/`).
//!
//! **Bad input (both sides):** a light with NaN/Inf input, or within `2^-64` of the vertex in
//! every coordinate, is skipped; weights and colours clamp to `[0, 2^40]`. When the
//! weighted directions cancel (largest component of `acc.xyz` zero or subnormal) the direction
//! is zero, every colour term zero and the position `V`. Per pixel: a zero-length `P_agg − p`,
//! a bad normal or non-finite input gives 0, and channels are clamped at 0. Every result is
//! finite (WGSL leaves a run-time ±∞ indeterminate): accumulator, colour and position lanes are
//! read finite first (NaN → 0, ±∞ and beyond ±2^100 → ±2^100, [`AGGREGATE_LIGHT_LIMIT`]; a
//! skipped light returns the accumulator so read), the aggregate direction's within `±2^40`,
//! so no difference, sum or product overflows; a position whose offset `acc.xyz/acc.w` would
//! reach `2^101` is the vertex.

use glam::{Vec3, Vec4};

/// Largest weight or colour channel accepted, `2^40` (intensities 1e-6 … 1e6 and far beyond).
pub const AGGREGATE_LIGHT_WEIGHT_MAX: f32 = 1_099_511_627_776.0;
/// Lights closer than this to the vertex in every coordinate are skipped (`2^-64`).
pub const AT_VERTEX: f32 = 5.421_011e-20;

/// The largest magnitude of a position or accumulator lane computed with, `2^100`.
pub const AGGREGATE_LIGHT_LIMIT: f32 = 1.267_650_6e30;

/// `v` with every lane finite and within `±limit` (WGSL `aggregate_light_sane3`): NaN → 0,
/// ±∞ → ±limit.
fn sane3(v: Vec3, limit: f32) -> Vec3 {
    crate::position::read_finite3(v, limit)
}

fn sane4(v: Vec4, limit: f32) -> Vec4 {
    sane3(v.truncate(), limit).extend(sane3(Vec3::new(v.w, 0.0, 0.0), limit).x)
}

fn aggregate_light_finite3(v: Vec3) -> bool {
    v.to_array()
        .iter()
        .all(|x| (x.to_bits() & 0x7fff_ffff) < 0x7f80_0000)
}

fn aggregate_light_unit(v: Vec3, smallest: u32) -> Vec3 {
    let m = v.abs().max_element();
    if !aggregate_light_finite3(v) || m.to_bits() < smallest {
        return Vec3::ZERO;
    }
    let s = v * crate::lighting::lpp::pow2_scale(m);
    s * (1.0 / s.dot(s).sqrt())
}

/// Fold a light into a vertex's accumulator (start from `Vec4::ZERO`):
/// `acc + (W·L_i, W/|P_i − V|)`.
pub fn aggregate_light_accumulate(
    acc: Vec4,
    vertex: Vec3,
    light_position: Vec3,
    weight: f32,
) -> Vec4 {
    let a0 = sane4(acc, AGGREGATE_LIGHT_LIMIT);
    if !aggregate_light_finite3(vertex)
        || !aggregate_light_finite3(light_position)
        || (weight.to_bits() & 0x7fff_ffff) >= 0x7f80_0000
    {
        return a0;
    }
    let rel = sane3(light_position, AGGREGATE_LIGHT_LIMIT) - sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    let m = rel.abs().max_element();
    if m.to_bits() < AT_VERTEX.to_bits() {
        return a0;
    }
    let w = weight.clamp(0.0, AGGREGATE_LIGHT_WEIGHT_MAX);
    let sc = crate::lighting::lpp::pow2_scale(m);
    let s = rel * sc;
    let inv = 1.0 / s.dot(s).sqrt();
    // |rel| = 1/(inv·sc), so W/|rel| = W·inv·sc (WGSL: the same; no division by m).
    a0 + (w * (s * inv)).extend(w * inv * sc)
}

/// The aggregate direction `L_agg` (zero when the weighted directions cancel).
pub fn aggregate_light_direction(acc: Vec4) -> Vec3 {
    aggregate_light_unit(acc.truncate(), 0x0080_0000)
}

/// The aggregate position `V + acc.xyz/acc.w` (`V` when nothing accumulated or they cancel).
pub fn aggregate_light_position(acc: Vec4, vertex: Vec3) -> Vec3 {
    let v = sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    let x = acc.truncate();
    let m = x.abs().max_element();
    if !aggregate_light_finite3(x)
        || (acc.w.to_bits() & 0x7fff_ffff) >= 0x7f80_0000
        || m.to_bits() < 0x0080_0000
        || acc.w.is_nan()
        || acc.w < f32::MIN_POSITIVE
        // m/W below 2^101, from the exponents (WGSL: the same test on the bits as i32).
        || (m.to_bits() as i32).wrapping_sub(acc.w.to_bits() as i32) >= 100 << 23
    {
        return v;
    }
    // As the WGSL: a weight sum beyond 2^126 is scaled by 2^-64 before dividing.
    if acc.w > 8.507_059e37 {
        v + (x * 5.421_011e-20) / (acc.w * 5.421_011e-20)
    } else {
        v + x / acc.w
    }
}

/// Fold a light's colour into `C_agg`: `colour_acc + C_i (L_i·L_agg)` (unclamped, as in
/// Filippov's slides).
pub fn aggregate_light_accumulate_colour(
    colour_acc: Vec3,
    vertex: Vec3,
    light_position: Vec3,
    colour: Vec3,
    aggregate_direction: Vec3,
) -> Vec3 {
    let c0 = sane3(colour_acc, AGGREGATE_LIGHT_LIMIT);
    if !aggregate_light_finite3(vertex)
        || !aggregate_light_finite3(light_position)
        || !aggregate_light_finite3(colour)
        || !aggregate_light_finite3(aggregate_direction)
    {
        return c0;
    }
    let rel = sane3(light_position, AGGREGATE_LIGHT_LIMIT) - sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    if rel.abs().max_element().to_bits() < AT_VERTEX.to_bits() {
        return c0;
    }
    let l = aggregate_light_unit(rel, AT_VERTEX.to_bits());
    let c = colour.clamp(Vec3::ZERO, Vec3::splat(AGGREGATE_LIGHT_WEIGHT_MAX));
    let d = sane3(aggregate_direction, AGGREGATE_LIGHT_WEIGHT_MAX);
    c0 + c * l.dot(d)
}

/// Per pixel: `max(C_agg·max(N·normalize(P_agg − p), 0), 0)`.
pub fn aggregate_light_diffuse(
    normal: Vec3,
    position: Vec3,
    aggregate_position: Vec3,
    colour: Vec3,
) -> Vec3 {
    if !aggregate_light_finite3(position)
        || !aggregate_light_finite3(aggregate_position)
        || !aggregate_light_finite3(colour)
    {
        return Vec3::ZERO;
    }
    let n = aggregate_light_unit(normal, 0x0080_0000);
    let l = aggregate_light_unit(
        sane3(aggregate_position, AGGREGATE_LIGHT_LIMIT) - sane3(position, AGGREGATE_LIGHT_LIMIT),
        0x0080_0000,
    );
    (sane3(colour, AGGREGATE_LIGHT_LIMIT) * n.dot(l).max(0.0)).max(Vec3::ZERO)
}

/// Whole-vertex convenience (CPU side): fold `(position, weight, colour)` lights at `vertex`
/// into `(P_agg, C_agg)`.
pub fn aggregate(vertex: Vec3, lights: &[(Vec3, f32, Vec3)]) -> (Vec3, Vec3) {
    let acc = lights.iter().fold(Vec4::ZERO, |a, &(p, w, _)| {
        aggregate_light_accumulate(a, vertex, p, w)
    });
    let dir = aggregate_light_direction(acc);
    let colour = lights.iter().fold(Vec3::ZERO, |c, &(p, _, col)| {
        aggregate_light_accumulate_colour(c, vertex, p, col, dir)
    });
    (aggregate_light_position(acc, vertex), colour)
}

/// Error bound of the God of War III luminance identity, kept once: `tests/aggregate_light.rs`
/// asserts it on the adapter and, multiplied by [`bounds::CONFORMING_FACTOR`], under the
/// worst-case emulation.
pub mod bounds {
    const U: f64 = 1.0 / 16_777_216.0;

    /// Every term of [`identity_absolute`] is a rounding of `+ − ×` (`u` where correctly rounded,
    /// at most `2u` on any conforming adapter) or a full WGSL allowance (`/` 2.5 ULP,
    /// `inverseSqrt` 2 ULP): doubling it bounds the conforming error.
    pub const CONFORMING_FACTOR: f64 = 2.0;

    /// Absolute bound of `|aggregate diffuse − Σ l_i N·L_i|` at the vertex, where `+ − ×` round
    /// correctly (`u = 2^-24`, `S = Σ l_i`, `K` slots, `|V|` the vertex's distance from the
    /// origin, `|R|` the aggregate light's distance from the vertex): each `L_i` from the rounded
    /// difference `P_i − V` (`u` per component) and the scaled normalisation (division 2.5 ULP,
    /// `inverseSqrt` 2 ULP, products): `|ΔL_i| ≤ 14u`; times `l_i` (`u`) and summed over `K`
    /// terms: `|ΔX| ≤ (15 + K)u·S`. The direction of `X` is then off by `≤ |ΔX|/|X| + 14u`, which
    /// moves `(N·L_agg)·|X|` by `≤ |ΔX| + 14u·|X| ≤ (29 + K)u·S`; the colour sum
    /// `l_agg = Σ l_i (L_i·L_agg)` adds `(K + 20)u·S` (dots `3u`, `L_i` and `L_agg` errors, `K`
    /// sums), and the final products `3u·S`. Per pixel the aggregate position is `V + R` rounded
    /// (`u·(|V| + |R|)` per component) and `P_agg − V` rounds again (`u·|R|`): the direction to it
    /// is off by `≤ 2√3·u·(|V| + 2|R|)/|R|`, times `l_agg ≤ S`. Total:
    /// `(2K + 52)u·S + 4u·(|V| + 2|R|)/|R|·S`.
    pub fn identity_absolute(slots: usize, vertex_norm: f64, sum: f64, r: f64) -> f64 {
        (2.0 * slots as f64 + 52.0) * U * sum + 4.0 * U * (vertex_norm + 2.0 * r) / r * sum
    }
}
