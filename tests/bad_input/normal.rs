//! What the normal encodings share: `normal::sanitize` (the encoders' front end, Rust only), and
//! the channel values and decodes that the encodings' rows name.
//!
//! The rules every encoding's rows follow. Encoders: NaN, zero and all-subnormal vectors give the
//! code of +z; infinities give the direction of their signs; subnormal components count as 0; any
//! finite length is normalised. Decoders: every bit pattern gives a finite unit vector; unused
//! high bits are ignored. Render-target forms: encoders write byte/255 (k/1023 for RGB10A2, b/127
//! for snorm8; alpha 0 where free); decoders clamp each channel to [0, 1] ([−1, 1] for snorm;
//! NaN counts as 0) and round it back to its byte or code.

use super::{Func, INF, NAN, Row, SUB_MAX, SUB_MIN, V};

// The channel values k/255 and the rounded decodes that the encodings' rows name.
pub(super) const B15: f32 = 15.0 / 255.0;
pub(super) const B60: f32 = 60.0 / 255.0;
pub(super) const B127: f32 = 127.0 / 255.0;
pub(super) const B128: f32 = 128.0 / 255.0;
pub(super) const B247: f32 = 247.0 / 255.0;
/// The rgb10a2unorm channel of code 512, `512/1023`.
pub(super) const K512: f32 = 512.0 / 1023.0;
/// 1/√3 as decoders compute it, `255/√195075` with each step correctly rounded.
pub(super) const R3: f32 = 0.577_350_26;
/// 1/√2 as decoders compute it, `1/√2` with each step correctly rounded.
pub(super) const R2: f32 = 0.707_106_77;

pub const FUNCS: &[Func] = &[Func {
    rust: "normal::sanitize",
    wgsl: None,
    twin: |a| V::OptVec3(prepass::normal::sanitize(a[0].vec3()).map(|v| v.to_array())),
}];

pub const WGSL_HELPERS: &[(&str, &str)] = &[];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // The encoders' front end.
    Row { func: "normal::sanitize", case: "NaN", args: &[V::Vec3([NAN, 0.0, 1.0])], expect: V::OptVec3(None), why: "degenerate: the encoders use +z" },
    Row { func: "normal::sanitize", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::OptVec3(None), why: "degenerate" },
    Row { func: "normal::sanitize", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MAX, 0.0])], expect: V::OptVec3(None), why: "all subnormal = zero: degenerate" },
    Row { func: "normal::sanitize", case: "±Inf", args: &[V::Vec3([INF, -5.0, -INF])], expect: V::OptVec3(Some([1.0, -0.0, -1.0])), why: "signs of the infinities, signed zero elsewhere" },
    Row { func: "normal::sanitize", case: "subnormal component", args: &[V::Vec3([-0.0, 1.0, SUB_MIN])], expect: V::OptVec3(Some([-0.0, 1.0, 0.0])), why: "flushed to signed zero" },
    Row { func: "normal::sanitize", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, -3.0])], expect: V::OptVec3(Some([3.999_999_8, 0.0, -3.0 * f32::MIN_POSITIVE])), why: "scaled by 2^-126 into [1, 4); 2^-252 flushed" },
    Row { func: "normal::sanitize", case: "non-unit: tiny", args: &[V::Vec3([0.0, -SUB_MAX, f32::MIN_POSITIVE])], expect: V::OptVec3(Some([0.0, -0.0, 1.0])), why: "scaled by 2^126; subnormal flushed first" },
];
