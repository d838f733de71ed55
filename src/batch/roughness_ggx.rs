//! Batch twins of [`crate::roughness_ggx`]: GGX perceptual roughness in 8 bits (linear `r`,
//! Godot's 7 bits + flag, the log curve). Names, the slice contract and the vectorisation:
//! [`crate::batch`]. Each writes exactly what its scalar twin returns for every input
//! (`tests/batch.rs`).
//!
//! The linear encoders and every decoder but nothing else are written branch-free, the same
//! IEEE operations in the same order as the scalar twins (the exact quantiser of
//! [`crate::roughness_ggx`], "Exact encoders": candidate `⌊n·r + ½⌋`, one boundary test each
//! way); the log encoder calls its scalar twin per element (its `log2` candidate is a library
//! call).

use crate::roughness::EXP2_STEPS;
use crate::roughness_ggx as g;

/// The scalar twin's exact linear code, branch-free (`scale = n + 1`, a power of two).
#[inline(always)]
pub(crate) fn linear_lane(r: f32, scale: f32) -> u32 {
    let b = r.to_bits();
    let n = scale - 1.0;
    let top = n as u32;
    let high = ((b & 0x7fff_ffff) > 0x7f80_0000) | (0x3f80_0000..0x8000_0000).contains(&b);
    let low = b >= 0x8000_0000;
    let x = if high | low { 0.0 } else { r };
    let k0 = super::normal::floor_small(x * n + 0.5).min(top);
    let h = x * scale;
    let down = (k0 > 0) & (h - (k0 as f32 - 0.5) < x);
    let up = (k0 < top) & (h - (k0 as f32 + 0.5) >= x);
    let k = if down {
        k0.wrapping_sub(1)
    } else if up {
        k0.wrapping_add(1)
    } else {
        k0
    };
    if high {
        top
    } else if low {
        0
    } else {
        k
    }
}

super::batch_fn!(
    /// Batch [`g::encode_roughness_ggx8`]: `dst[i] = encode_roughness_ggx8(src[i])`.
    encode_roughness_ggx8, encode_roughness_ggx8_with, "roughness_ggx::encode_roughness_ggx8",
    (), f32 => u32,
    scalar: g::encode_roughness_ggx8,
    lane: |r| linear_lane(r, 256.0),
);

super::batch_fn!(
    /// Batch [`g::decode_roughness_ggx8`]: `dst[i] = decode_roughness_ggx8(src[i])`.
    decode_roughness_ggx8, decode_roughness_ggx8_with, "roughness_ggx::decode_roughness_ggx8",
    (), u32 => f32,
    scalar: g::decode_roughness_ggx8,
    lane: |p: u32| p.min(g::CODE_MAX) as f32 / 255.0,
);

super::batch_fn!(
    /// Batch [`g::encode_roughness_urp8`]: `dst[i] = encode_roughness_urp8(src[i])` (URP's
    /// smoothness byte, `255 −` the linear code).
    encode_roughness_urp8, encode_roughness_urp8_with, "roughness_ggx::encode_roughness_urp8",
    (), f32 => u32,
    scalar: g::encode_roughness_urp8,
    lane: |r| g::CODE_MAX - linear_lane(r, 256.0),
);

super::batch_fn!(
    /// Batch [`g::decode_roughness_urp8`]: `dst[i] = decode_roughness_urp8(src[i])`.
    decode_roughness_urp8, decode_roughness_urp8_with, "roughness_ggx::decode_roughness_urp8",
    (), u32 => f32,
    scalar: g::decode_roughness_urp8,
    lane: |p: u32| (g::CODE_MAX - p.min(g::CODE_MAX)) as f32 / 255.0,
);

super::batch_fn!(
    /// Batch [`g::encode_roughness_substrate8`]: `dst[i] = encode_roughness_substrate8(src[i])`
    /// (Unreal's truncating `PackR8` on `+0 ≤ r < 1`, the linear code elsewhere).
    encode_roughness_substrate8, encode_roughness_substrate8_with,
    "roughness_ggx::encode_roughness_substrate8",
    (), f32 => u32,
    scalar: g::encode_roughness_substrate8,
    lane: |r: f32| {
        let truncated = (r * 255.0) as u32;
        let linear = linear_lane(r, 256.0);
        if r.to_bits() < 0x3f80_0000 { truncated } else { linear }
    },
);

super::batch_fn!(
    /// Batch [`g::decode_roughness_substrate8`]: `dst[i] = decode_roughness_substrate8(src[i])`.
    decode_roughness_substrate8, decode_roughness_substrate8_with,
    "roughness_ggx::decode_roughness_substrate8",
    (), u32 => f32,
    scalar: g::decode_roughness_substrate8,
    lane: |p: u32| p.min(g::CODE_MAX) as f32 * (1.0 / 255.0),
);

super::batch_fn!(
    /// Batch [`g::encode_roughness_godot8`]: `dst[i] = encode_roughness_godot8(src[i],
    /// dynamic_object)`, one flag per batch.
    encode_roughness_godot8, encode_roughness_godot8_with, "roughness_ggx::encode_roughness_godot8",
    (dynamic_object: u32), f32 => u32,
    scalar: |r| g::encode_roughness_godot8(r, dynamic_object),
    lane: move |r| {
        let k = linear_lane(r, 128.0);
        if dynamic_object != 0 { 255u32.wrapping_sub(k) } else { k }
    },
);

super::batch_fn!(
    /// Batch [`g::decode_roughness_godot8`]: `dst[i] = decode_roughness_godot8(src[i])`.
    decode_roughness_godot8, decode_roughness_godot8_with, "roughness_ggx::decode_roughness_godot8",
    (), u32 => f32,
    scalar: g::decode_roughness_godot8,
    lane: |p: u32| {
        let c = p.min(g::CODE_MAX) as f32 / 255.0;
        let s = if c > 0.5 { 1.0 - c } else { c };
        s / (127.0f32 / 255.0)
    },
);

super::batch_fn!(
    /// Batch [`g::encode_roughness_ggx8_log`]: `dst[i] = encode_roughness_ggx8_log(src[i])`
    /// (the scalar twin per element).
    encode_roughness_ggx8_log, encode_roughness_ggx8_log_with, "roughness_ggx::encode_roughness_ggx8_log",
    (), f32 => u32,
    scalar: g::encode_roughness_ggx8_log,
    lane: g::encode_roughness_ggx8_log,
);

super::batch_fn!(
    /// Batch [`g::decode_roughness_ggx8_log`]: `dst[i] = decode_roughness_ggx8_log(src[i])`.
    decode_roughness_ggx8_log, decode_roughness_ggx8_log_with, "roughness_ggx::decode_roughness_ggx8_log",
    (), u32 => f32,
    scalar: g::decode_roughness_ggx8_log,
    lane: |p: u32| {
        let n = p.min(g::CODE_MAX).wrapping_mul(6);
        f32::from_bits(
            EXP2_STEPS[(n % 255) as usize]
                .wrapping_add((n / 255) << 23)
                .wrapping_sub(6 << 23),
        )
    },
);
