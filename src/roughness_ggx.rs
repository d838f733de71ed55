//! GGX perceptual roughness in 8 bits, as the engines store it — the Rust twins of
//! `wgsl/roughness_ggx.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! GGX (Bruce Walter, Stephen Marschner, Hongsong Li, Kenneth Torrance, "Microfacet Models for
//! Refraction through Rough Surfaces", EGSR 2007) with Burley's remapping `α = r²` of perceptual
//! roughness `r` (Brent Burley, "Physically Based Shading at Disney", SIGGRAPH 2012 course):
//! `D(n·h) = α² / (π ((n·h)²(α² − 1) + 1)²)`, whose peak is `D(1) = 1/(π α²)`.
//!
//! Five 8-bit forms:
//! - **linear r** ([`encode_roughness_ggx8`], [`decode_roughness_ggx8`]): byte `b` stands for
//!   `r = b/255`, what Bevy, Unreal's GBuffer and Unity HDRP store in a unorm8 channel (HDRP's
//!   normal buffer alpha, `NormalBuffer.hlsl`: perceptual roughness);
//! - **URP's smoothness** ([`encode_roughness_urp8`], [`decode_roughness_urp8`]): URP stores
//!   smoothness `1 − r`, not roughness (`UnityGBuffer.hlsl`: `GBuffer2 = half4(packedNormalWS,
//!   smoothness)`), so byte `b` stands for `r = 1 − b/255`; a URP byte read with
//!   [`decode_roughness_ggx8`] gives `1 − r`;
//! - **Unreal Substrate's truncated byte** ([`encode_roughness_substrate8`],
//!   [`decode_roughness_substrate8`]): Substrate's `PackR8(v) = uint(saturate(v)·255)` truncates
//!   and its `UnpackR8(b) = b·(1/255)` multiplies by the rounded reciprocal (Unreal's shader
//!   library, as `Engine/Shaders/Private/Substrate/Substrate.ush` calls them); Unreal's bytes,
//!   where a renderer needs them, rather than the nearest code;
//! - **Godot 4's 7 bits + flag** ([`encode_roughness_godot8`], [`decode_roughness_godot8`]):
//!   Godot's Forward+ writes `w = r·127/255` to the normal-roughness buffer's alpha, and `1 − w`
//!   for a dynamic object (`servers/rendering/renderer_rd/shaders/forward_clustered/
//!   scene_forward_clustered.glsl`, `MODE_RENDER_NORMAL_ROUGHNESS`), and reads it back with
//!   `normal_roughness_compatibility` (`forward_clustered/scene_forward_clustered_inc.glsl`): a
//!   channel `c > 0.5` is dynamic and becomes `1 − c`, then `r = c/(127/255)`. As bytes: `k =
//!   round(127·r)` for static objects, `255 − k` for dynamic ones — bit 7 is the flag;
//! - **log r** ([`encode_roughness_ggx8_log`], [`decode_roughness_ggx8_log`]): code `k` stands
//!   for `r = 2^(6k/255 − 6)`, `r ∈ [1/64, 1]` (so `α = 2^(12k/255 − 12)`): equal relative
//!   steps, the curve `tests/roughness_ggx.rs`'s search finds best for the GGX lobe over the
//!   clamped range engines shade (Unreal clamps `r ≥ 0.02`, Bevy `r ≥ 0.089`). It is
//!   [`crate::roughness`]'s log-range codec applied to `64·r` with `max_power = 2^6`, and exact
//!   the same way (integer operations on the same two tables).
//!
//! ## Exact encoders
//! The linear encoders return the code nearest `n·r` (`n = 255` or `127`) **exactly**, ties
//! upwards (the only tie is `r = 1/2`): the candidate `⌊n·r + 1/2⌋` from `f32` arithmetic is
//! within one code, and the boundary `r = (j + ½)/n` between codes `j` and `j + 1`, `n = 2^m − 1`,
//! is tested as `2^m·r − (j + ½) ≥ r`. `2^m·r` is exact; wherever the test is close
//! (`n·r ≈ j + ½`) the subtraction is exact by Sterbenz's lemma (`2^m r / (j + ½) ≈ 2^m/n ∈
//! [1, 2]`), and elsewhere `|n·r − (j + ½)|` exceeds `r` by far more than any rounding. So the
//! code is exact on every conforming adapter (no `+ − ×` rounding direction, fusion or
//! reassociation of the candidate can move it), and equals the twin's. Engines let the render
//! target round `fl(255·r)` instead (`⌊255·c + ½⌋` of a rounded product, the `pack4x8unorm`
//! rule); that differs from the nearest code only for `r` within an ULP or so of a boundary
//! (counted in `tests/roughness_ggx.rs`).
//!
//! ## Decoders and their error
//! - linear: `b/255`, one division — correctly rounded where `/` is (lavapipe, the twin), within
//!   2.5 ULP on any conforming adapter; this is the value a unorm8 texture read returns.
//! - Godot: Godot's own arithmetic on the channel `fl(b/255)`, operation for operation, so a byte
//!   Godot wrote decodes to the value Godot's `normal_roughness_compatibility` computes. It
//!   differs from `k/127` by at most [`bounds::GODOT_DECODE`] (the `1 − c` of a dynamic byte
//!   keeps `c`'s absolute rounding, `2^-25`).
//! - log: `2^(6k/255 − 6)` correctly rounded (table), exact on every adapter;
//!   [`decode_roughness_ggx8_log_alpha`] gives `α` correctly rounded from the same table.
//!
//! ## Bad input (identical in WGSL and Rust)
//! - NaN encodes as the roughest code (linear and log: 255, `r = 1`; Godot: `k = 127`): the lobe
//!   with the lowest peak, read from the bits.
//! - negative values, `−0`, subnormals and `−Inf` encode as code 0 (the log curve: its smoothest
//!   code, `r = 2^-6`); `+Inf` and anything `≥ 1` as the roughest code.
//! - codes above 255 decode as 255.
//! - `_unorm` decoders: a NaN channel counts as 0; channels are clamped to `[0, 1]` and rounded
//!   back to their byte (so `unpack4x8unorm`'s 3-ULP allowance or a ±0.49/255 filter cannot
//!   change the result).

/// Largest 8-bit code.
pub const CODE_MAX: u32 = 255;

/// Largest Godot 7-bit roughness code `k`.
pub const GODOT_CODE_MAX: u32 = 127;

/// The code nearest `n·r`, `n = scale − 1 = 2^m − 1`, exactly, ties upwards (see the module
/// docs, "Exact encoders"); NaN, `≥ 1` and `+Inf` give `n`; negative, `−0` and `−Inf` give 0.
fn linear_code(r: f32, scale: f32) -> u32 {
    let b = r.to_bits();
    let n = scale - 1.0;
    if (b & 0x7fff_ffff) > 0x7f80_0000 || (0x3f80_0000..0x8000_0000).contains(&b) {
        return n as u32;
    }
    if b >= 0x8000_0000 {
        return 0;
    }
    let mut k = ((r * n + 0.5).floor() as u32).min(n as u32);
    let h = r * scale;
    if k > 0 && h - (k as f32 - 0.5) < r {
        k -= 1;
    } else if k < n as u32 && h - (k as f32 + 0.5) >= r {
        k += 1;
    }
    k
}

/// The byte of a unorm8 channel value: `round(255·c)` (half to even, as WGSL's `round`) after
/// clamping to `[0, 1]`; NaN counts as 0.
fn unorm_byte(c: f32) -> u32 {
    let c = if c.is_nan() { 0.0 } else { c };
    (c.clamp(0.0, 1.0) * 255.0).round_ties_even() as u32
}

/// The 8-bit code of perceptual roughness `r`: the byte nearest `255·r` (`r` clamped to
/// `[0, 1]`), ties upwards, computed exactly.
///
/// **Error bound:** `|r − b/255| ≤ 1/510` for every `r ∈ [0, 1]` (the exact nearest code,
/// bit-identical to the WGSL on every conforming adapter).
///
/// **Bad input:** NaN → 255; negative, `−0`, subnormal, `−Inf` → 0; `+Inf` and `≥ 1` → 255.
pub fn encode_roughness_ggx8(r: f32) -> u32 {
    linear_code(r, 256.0)
}

/// The perceptual roughness `b/255` of byte `b`, as a unorm8 channel reads.
///
/// **Error bound:** correctly rounded (≤ 0.5 ULP; bit-identical to the WGSL on a correctly
/// rounded adapter such as lavapipe; 2.5 ULP on any conforming adapter, WGSL's `/`).
///
/// **Bad input:** codes above 255 decode as 255 (`r = 1`).
pub fn decode_roughness_ggx8(p: u32) -> f32 {
    p.min(CODE_MAX) as f32 / 255.0
}

/// GGX `α = r²` of byte `b`: [`decode_roughness_ggx8`] squared in `f32`.
///
/// **Error bound:** within `1.5·2^-23` relative of `(b/255)²` (two roundings of `2^-24` each,
/// the first doubled by the square) where `/` and `×` are correctly rounded.
///
/// **Bad input:** codes above 255 decode as 255 (`α = 1`).
pub fn decode_roughness_ggx8_alpha(p: u32) -> f32 {
    let r = decode_roughness_ggx8(p);
    r * r
}

/// Render-target form: the r8unorm channel value `b/255` to write for
/// [`encode_roughness_ggx8`]`(r)` (as `unpack4x8unorm` computes it: the twin takes the correctly
/// rounded quotient, [`crate::depth24::unpack4x8unorm`]).
///
/// **Error bound:** the target stores exactly the byte (the channel is within 3 ULP of `b/255`).
///
/// **Bad input:** as [`encode_roughness_ggx8`].
pub fn encode_roughness_ggx8_unorm(r: f32) -> f32 {
    crate::depth24::unpack4x8unorm(encode_roughness_ggx8(r))[0]
}

/// The roughness from a sampled r8unorm channel: the byte `round(255·c)` (clamped; half to
/// even), then [`decode_roughness_ggx8`].
///
/// **Error bound:** as [`decode_roughness_ggx8`] for any channel within ±0.49/255 of `b/255`.
///
/// **Bad input:** NaN channel → byte 0; channels clamped to `[0, 1]`.
pub fn decode_roughness_ggx8_unorm(c: f32) -> f32 {
    decode_roughness_ggx8(unorm_byte(c))
}

/// URP's smoothness byte for perceptual roughness `r`: the byte nearest `255·(1 − r)` (`r`
/// clamped to `[0, 1]`), computed exactly as `255 − `[`encode_roughness_ggx8`]`(r)`: nearest
/// codes mirror, and the one tie (`r = 1/2`) goes to byte 127 (towards the rougher code).
///
/// **Error bound:** `|r − (1 − b/255)| ≤ 1/510`, exact on every conforming adapter (as
/// [`encode_roughness_ggx8`]). URP's own write (`smoothness` to a unorm8 target) rounds
/// `fl(255·s)`, which differs only within an ULP or so of a boundary.
///
/// **Bad input:** NaN → 0 (smoothness 0: the roughest, as [`encode_roughness_ggx8`]'s 255);
/// negative, `−0`, subnormal, `−Inf` → 255; `+Inf` and `≥ 1` → 0.
pub fn encode_roughness_urp8(r: f32) -> u32 {
    CODE_MAX - encode_roughness_ggx8(r)
}

/// The perceptual roughness `1 − b/255` of URP's smoothness byte `b`, computed as
/// `(255 − b)/255`: one division of exact integers, so correctly rounded where `/` is (URP's
/// own `1 − smoothness` on the unorm read rounds twice; they differ by at most `2^-24`).
///
/// **Error bound:** as [`decode_roughness_ggx8`] (it is that of `255 − b`).
///
/// **Bad input:** codes above 255 decode as 255 (`r = 0`).
pub fn decode_roughness_urp8(p: u32) -> f32 {
    decode_roughness_ggx8(CODE_MAX - p.min(CODE_MAX))
}

/// Render-target form: the r8unorm channel (URP's GBuffer2 alpha) to write for
/// [`encode_roughness_urp8`]`(r)`, `b/255` as `unpack4x8unorm` computes it.
///
/// **Bad input:** as [`encode_roughness_urp8`].
pub fn encode_roughness_urp8_unorm(r: f32) -> f32 {
    crate::depth24::unpack4x8unorm(encode_roughness_urp8(r))[0]
}

/// The roughness from a sampled URP smoothness channel: the byte `round(255·c)` (clamped; half
/// to even), then [`decode_roughness_urp8`].
///
/// **Bad input:** NaN channel → byte 0 (`r = 1`); channels clamped to `[0, 1]`.
pub fn decode_roughness_urp8_unorm(c: f32) -> f32 {
    decode_roughness_urp8(unorm_byte(c))
}

/// Unreal Substrate's roughness byte, its `PackR8`: `uint(saturate(r)·255)`, the product rounded
/// in f32 and truncated — Unreal's bytes bit for bit where the product rounds as Unreal's GPU
/// rounds it (correctly rounded: lavapipe, this twin; a conforming adapter may round the other
/// way, as Unreal's own shader on it would).
///
/// **Error bound:** `0 ≤ 255·r − b < 1` (truncation): up to a code below the nearest, about
/// half of all `r` one code below [`encode_roughness_ggx8`]'s (counted in
/// `tests/roughness_ggx.rs`).
///
/// **Bad input:** NaN → 255 (the roughest, as every encoder here; Unreal's `saturate(NaN)` is
/// the GPU's); negative, `−0`, subnormal, `−Inf` → 0; `+Inf` and `≥ 1` → 255.
pub fn encode_roughness_substrate8(r: f32) -> u32 {
    // `+0 ≤ r < 1` exactly when its bits are below those of 1; elsewhere (NaN, ±Inf, `r ≥ 1`,
    // negative values, `−0`) the linear encoder's code, which those share.
    if r.to_bits() < 0x3f80_0000 {
        (r * 255.0) as u32
    } else {
        encode_roughness_ggx8(r)
    }
}

/// Unreal Substrate's `UnpackR8`: `b·(1/255)`, the reciprocal rounded to f32 and the product
/// rounded once — Unreal's value bit for bit where `×` is correctly rounded; it differs from
/// [`decode_roughness_ggx8`]'s `b/255` by an ULP on some bytes (counted in
/// `tests/roughness_ggx.rs`).
///
/// **Error bound:** within [`bounds::SUBSTRATE_DECODE_REL`] `= 2^-23 + 2^-48` relative of
/// `b/255` (two roundings of `2^-24` each; one is not enough: some bytes are off by more than
/// `2^-24` relative; `tests/roughness_ggx.rs` checks both on every byte).
///
/// **Bad input:** codes above 255 decode as 255 (`r` ≈ 1: `255·fl(1/255)`).
pub fn decode_roughness_substrate8(p: u32) -> f32 {
    p.min(CODE_MAX) as f32 * (1.0 / 255.0)
}

/// Godot's byte for roughness `r` and the dynamic-object flag (`dynamic_object != 0`): `k`
/// nearest `127·r` (clamped, ties upwards, exact), then `k`, or `255 − k` for a dynamic object.
///
/// **Error bound:** `|r − k/127| ≤ 1/254` for every `r ∈ [0, 1]`; Godot's decoder reads the byte
/// within that plus [`bounds::GODOT_DECODE`].
///
/// **Bad input:** NaN → `k = 127`; negative, `−0`, subnormal, `−Inf` → `k = 0`; `+Inf` and
/// `≥ 1` → `k = 127`. Any non-zero `dynamic_object` is a dynamic object.
pub fn encode_roughness_godot8(r: f32, dynamic_object: u32) -> u32 {
    let k = linear_code(r, 128.0);
    if dynamic_object != 0 { 255 - k } else { k }
}

/// The roughness of a Godot byte, computed as Godot's `normal_roughness_compatibility` computes
/// it from the channel `c = b/255`: `c > 0.5` (a dynamic object) becomes `1 − c`, then
/// `c / (127/255)` (the constant rounded to `f32`).
///
/// **Error bound:** within [`bounds::GODOT_DECODE`] of `k/127` (`k` the byte's 7-bit code);
/// bit-identical to the WGSL on a correctly rounded adapter.
///
/// **Bad input:** codes above 255 decode as 255 (a dynamic object, `k = 0`).
pub fn decode_roughness_godot8(p: u32) -> f32 {
    let c = p.min(CODE_MAX) as f32 / 255.0;
    let s = if c > 0.5 { 1.0 - c } else { c };
    s / (127.0f32 / 255.0)
}

/// 1 when a Godot byte marks a dynamic object (bit 7), else 0. Exact.
///
/// **Bad input:** codes above 255 read as 255 (dynamic).
pub fn roughness_godot8_is_dynamic(p: u32) -> u32 {
    p.min(CODE_MAX) >> 7
}

/// Render-target form: the unorm8 channel value to write for
/// [`encode_roughness_godot8`]`(r, dynamic_object)`.
///
/// **Error bound:** the target stores exactly the byte.
///
/// **Bad input:** as [`encode_roughness_godot8`].
pub fn encode_roughness_godot8_unorm(r: f32, dynamic_object: u32) -> f32 {
    crate::depth24::unpack4x8unorm(encode_roughness_godot8(r, dynamic_object))[0]
}

/// The roughness from a sampled Godot channel: the byte rounded back, then
/// [`decode_roughness_godot8`].
///
/// **Error bound:** as [`decode_roughness_godot8`] for any channel within ±0.49/255 of `b/255`.
///
/// **Bad input:** NaN channel → byte 0; channels clamped to `[0, 1]`.
pub fn decode_roughness_godot8_unorm(c: f32) -> f32 {
    decode_roughness_godot8(unorm_byte(c))
}

/// `2^-6` as bits: the smallest roughness of the log curve.
const LOG_MIN_BITS: u32 = 0x3c80_0000;

/// The log-curve code of roughness `r`: nearest to `255·(log2 r + 6)/6`, ties upwards at the
/// geometric midpoints — [`crate::roughness::encode_log_roughness`]`(64·r, 64)` (`64·r` is
/// exact).
///
/// **Error bound:** exact (integer comparisons with rounded-up boundaries; bit-identical to the
/// WGSL on every conforming adapter); the decoded roughness is within a factor
/// `2^(6/510)` (0.819 %) of any `r ∈ [2^-6, 1]`.
///
/// **Bad input:** NaN, `+Inf` and `≥ 1` → 255; negative, `−0`, subnormal, `−Inf` and anything
/// `≤ 2^-6` → 0.
pub fn encode_roughness_ggx8_log(r: f32) -> u32 {
    let b = r.to_bits();
    if (b & 0x7fff_ffff) > 0x7f80_0000 || (0x3f80_0000..0x8000_0000).contains(&b) {
        return CODE_MAX;
    }
    if b >= 0x8000_0000 || b <= LOG_MIN_BITS {
        return 0;
    }
    crate::roughness::encode_log_roughness(f32::from_bits(b + (6 << 23)), 64.0)
}

/// The roughness `2^(6k/255 − 6)` of log code `k`, correctly rounded.
///
/// **Error bound:** ≤ 0.5 ULP (table), bit-identical to the WGSL on every adapter.
///
/// **Bad input:** codes above 255 decode as 255 (`r = 1`).
pub fn decode_roughness_ggx8_log(p: u32) -> f32 {
    let n = p.min(CODE_MAX) * 6;
    f32::from_bits(crate::roughness::EXP2_STEPS[(n % 255) as usize] + ((n / 255) << 23) - (6 << 23))
}

/// GGX `α = 2^(12k/255 − 12)` of log code `k`, correctly rounded (from the table, not by
/// squaring).
///
/// **Error bound:** ≤ 0.5 ULP, bit-identical to the WGSL on every adapter.
///
/// **Bad input:** codes above 255 decode as 255 (`α = 1`).
pub fn decode_roughness_ggx8_log_alpha(p: u32) -> f32 {
    let n = p.min(CODE_MAX) * 12;
    f32::from_bits(
        crate::roughness::EXP2_STEPS[(n % 255) as usize] + ((n / 255) << 23) - (12 << 23),
    )
}

/// Render-target form: the r8unorm channel value to write for
/// [`encode_roughness_ggx8_log`]`(r)`.
///
/// **Error bound:** the target stores exactly the byte.
///
/// **Bad input:** as [`encode_roughness_ggx8_log`].
pub fn encode_roughness_ggx8_log_unorm(r: f32) -> f32 {
    crate::depth24::unpack4x8unorm(encode_roughness_ggx8_log(r))[0]
}

/// The roughness from a sampled r8unorm channel holding a log code: the byte rounded back, then
/// [`decode_roughness_ggx8_log`].
///
/// **Error bound:** as [`decode_roughness_ggx8_log`] for any channel within ±0.49/255 of `b/255`.
///
/// **Bad input:** NaN channel → byte 0; channels clamped to `[0, 1]`.
pub fn decode_roughness_ggx8_log_unorm(c: f32) -> f32 {
    decode_roughness_ggx8_log(unorm_byte(c))
}

/// Error bounds, kept once; `tests/roughness_ggx.rs` asserts them.
pub mod bounds {
    /// `2^-24`, the unit roundoff of `f32`.
    const U: f64 = 1.0 / 16_777_216.0;

    /// Largest `|decode_roughness_godot8(b) − k/127|`, absolute, on a correctly rounded adapter.
    /// Derivation: `c = fl(b/255)` is within `u·c ≤ u` of `b/255` (`u = 2^-24`); for a dynamic
    /// byte `1 − c` is exact (Sterbenz, `c ∈ (½, 1]`) and keeps that absolute error, `≤ u`; the
    /// constant `fl(127/255)` is within `u` relative; the quotient adds `u` relative of a
    /// result `≤ 1`. Dividing an absolute `u` by `127/255` gives `u·255/127`, so in all
    /// `u·255/127 + 2u + O(u²) ≤ 4.01u` (f32 rounding of values ≤ 1).
    pub const GODOT_DECODE: f64 = 4.01 * U;

    /// Largest `|decode_roughness_substrate8(b) − b/255| / (b/255)`, relative, on a correctly
    /// rounded adapter. Derivation: `fl(1/255)` is within `u` relative of `1/255` and the
    /// product `b·fl(1/255)` adds `u` relative more: `(1 + u)² − 1 = 2u + u²`.
    pub const SUBSTRATE_DECODE_REL: f64 = 2.0 * U + U * U;

    /// The round-trip bound of an `n`-step linear code, `|r − k/n| ≤ 1/(2n)` (absolute in `r`).
    pub fn linear_half_step(n: u32) -> f64 {
        0.5 / f64::from(n)
    }

    /// The log curve's round trip: the decoded roughness is within a factor `2^(6/510)` of `r`
    /// (half a step of `2^(6/255)`), so relative error `2^(6/510) − 1` (0.8188 %), plus the
    /// decode's half ULP.
    pub fn log_relative() -> f64 {
        (6.0f64 / 510.0).exp2() - 1.0
    }

    /// Worst relative error of the GGX lobe `D(n·h, α)` over every `n·h ∈ [0, 1]` when `α` is
    /// replaced by `α̂`: `D̂/D = (α̂/α)²·((α² + t)/(α̂² + t))²` with `t = tan²θ ∈ [0, ∞)` is
    /// monotone in `t`, so the extremes are `n·h = 1` (`(α/α̂)²`, the peak) and `n·h → 0`
    /// (`(α̂/α)²`): the worst is `max(|(α/α̂)² − 1|, |(α̂/α)² − 1|)`.
    pub fn lobe_relative(alpha: f64, alpha_hat: f64) -> f64 {
        let q = (alpha / alpha_hat).powi(2);
        (q - 1.0).abs().max((1.0 / q - 1.0).abs())
    }
}

/// Exact references: what each function means, in `f64` or integers.
pub mod exact {
    /// The code nearest `n·r` (`r` clamped to `[0, 1]`), ties upwards; NaN gives `n`. Exact for
    /// every `f32` `r`: `n·r` (24 + 8 bits) is exact in `f64`, and so is the comparison with
    /// `k + ½`.
    pub fn linear_code(r: f64, n: u32) -> u32 {
        if r.is_nan() {
            return n;
        }
        let t = r.clamp(0.0, 1.0) * f64::from(n);
        let k = t.floor();
        (if t - k >= 0.5 { k + 1.0 } else { k }) as u32
    }

    /// The perceptual roughness `k/n` of an `n`-step linear code (`k` clamped to `n`).
    pub fn linear_value(k: u32, n: u32) -> f64 {
        f64::from(k.min(n)) / f64::from(n)
    }

    /// `2^(6k/255 − 6)`, the log curve's roughness of code `k` (clamped to 255).
    pub fn log_value(k: u32) -> f64 {
        (6.0 * f64::from(k.min(255)) / 255.0 - 6.0).exp2()
    }

    /// The log curve's code of `r`: the `k` whose cell `[2^((2k−1)·6/510 − 6), 2^((2k+1)·6/510 −
    /// 6))` holds `r` (boundaries in `f64`, 1e-16 relative, far below an `f32` step); NaN →
    /// 255, `≤ 2^-6` → 0, `≥ 1` → 255.
    pub fn log_code(r: f64) -> u32 {
        if r.is_nan() || r >= 1.0 {
            return 255;
        }
        if r <= 1.0 / 64.0 {
            return 0;
        }
        (0..255u32)
            .find(|&j| r < (f64::from(2 * j + 1) * 6.0 / 510.0 - 6.0).exp2())
            .unwrap_or(255)
    }

    /// The GGX normal distribution `D(n·h, α) = α² / (π ((n·h)²(α² − 1) + 1)²)`, in `f64`.
    pub fn ggx_d(nh: f64, alpha: f64) -> f64 {
        let a2 = alpha * alpha;
        let d = nh * nh * (a2 - 1.0) + 1.0;
        a2 / (std::f64::consts::PI * d * d)
    }

    /// The Blinn-Phong power that matches GGX `α` (Walter et al. 2007: `s = 2/α² − 2`).
    pub fn power_from_alpha(alpha: f64) -> f64 {
        2.0 / (alpha * alpha) - 2.0
    }

    /// GGX `α = sqrt(2/(s + 2))` of a Blinn-Phong power `s` (Walter et al. 2007).
    pub fn alpha_from_power(s: f64) -> f64 {
        (2.0 / (s + 2.0)).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encoders_are_the_exact_nearest_code_near_every_boundary() {
        for n in [127u32, 255] {
            for j in 0..n {
                let bnd = (f64::from(j) + 0.5) / f64::from(n);
                let mid = f32::from_bits((bnd as f32).to_bits());
                for d in -300i32..=300 {
                    let r = f32::from_bits((mid.to_bits() as i32 + d) as u32);
                    let want = exact::linear_code(f64::from(r), n);
                    let got = if n == 255 {
                        encode_roughness_ggx8(r)
                    } else {
                        encode_roughness_godot8(r, 0)
                    };
                    assert_eq!(got, want, "n {n} r {r:e}");
                }
            }
        }
        // r = 1/2 is the one exact tie: upwards.
        assert_eq!(encode_roughness_ggx8(0.5), 128);
        assert_eq!(encode_roughness_godot8(0.5, 0), 64);
    }

    #[test]
    fn log_decode_is_64_times_smaller_than_the_log_range_power() {
        for k in 0..=255 {
            assert_eq!(
                decode_roughness_ggx8_log(k),
                crate::roughness::decode_log_roughness(k, 64.0) / 64.0
            );
            let want = exact::log_value(k);
            assert_eq!(decode_roughness_ggx8_log(k), want as f32, "code {k}");
            assert_eq!(
                decode_roughness_ggx8_log_alpha(k),
                (want * want) as f32,
                "code {k}"
            );
        }
    }

    #[test]
    fn godot_bytes_put_the_flag_in_bit_7() {
        for k in 0..=127u32 {
            let r = k as f32 / 127.0;
            assert_eq!(encode_roughness_godot8(r, 0), k);
            assert_eq!(encode_roughness_godot8(r, 1), 255 - k);
            assert_eq!(roughness_godot8_is_dynamic(k), 0);
            assert_eq!(roughness_godot8_is_dynamic(255 - k), 1);
            for b in [k, 255 - k] {
                let e = (f64::from(decode_roughness_godot8(b)) - f64::from(k) / 127.0).abs();
                assert!(e <= bounds::GODOT_DECODE, "byte {b}: {e:e}");
            }
        }
    }
}
