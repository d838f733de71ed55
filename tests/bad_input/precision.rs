//! `precision` (Rust only): the error metrics and the test-input builders.

use super::{Func, INF, NAN, Row, SUB_MIN, V};
use prepass::precision::inputs::ChannelError;
use prepass::precision::metrics;

pub const FUNCS: &[Func] = &[
    func!(None; precision::metrics; ordinal(f32) -> OptI64),
    func!(None; precision::metrics; ulp_distance(f32, f32) -> OptU64),
    func!(None; precision::metrics; step_ulps(f32, i64) -> F32),
    func!(None; precision::metrics; f32_ulp_at(f64) -> F64),
    func!(None; precision::metrics; ulp_error(f32, f64) -> F64),
    func!(None; precision::metrics; relative_error(f64, f64) -> F64),
    func!(None; precision::metrics; angle_degrees(f64x3, f64x3) -> F64),
    Func {
        rust: "precision::metrics::widen3",
        wgsl: None,
        twin: |a| V::F64x3(metrics::widen3(a[0].vec3().to_array())),
    },
    func!(None; precision::inputs; unorm8_channel(u32, channel, bool) -> F32),
    func!(None; precision::inputs; rgb8_channels(u32, channel, bool) -> Vec3),
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Precision metrics (Rust only): NaN propagates as None/NaN, infinities are ordinary ends.
    Row { func: "precision::metrics::ordinal", case: "NaN", args: &[V::F32(NAN)], expect: V::OptI64(None), why: "NaN has no position" },
    Row { func: "precision::metrics::ordinal", case: "+Inf", args: &[V::F32(INF)], expect: V::OptI64(Some(0x7f80_0000)), why: "one past f32::MAX" },
    Row { func: "precision::metrics::ordinal", case: "−0.0", args: &[V::F32(-0.0)], expect: V::OptI64(Some(0)), why: "same position as +0.0" },
    Row { func: "precision::metrics::ulp_distance", case: "NaN", args: &[V::F32(NAN), V::F32(1.0)], expect: V::OptU64(None), why: "no distance" },
    Row { func: "precision::metrics::ulp_distance", case: "+Inf", args: &[V::F32(f32::MAX), V::F32(INF)], expect: V::OptU64(Some(1)), why: "Inf is one past MAX" },
    Row { func: "precision::metrics::ulp_distance", case: "signed zeros", args: &[V::F32(0.0), V::F32(-0.0)], expect: V::OptU64(Some(0)), why: "±0 coincide" },
    Row { func: "precision::metrics::step_ulps", case: "NaN", args: &[V::F32(NAN), V::I64(1)], expect: V::F32(NAN), why: "returned unchanged" },
    Row { func: "precision::metrics::step_ulps", case: "past f32::MAX", args: &[V::F32(f32::MAX), V::I64(5)], expect: V::F32(INF), why: "saturates at ±Inf" },
    Row { func: "precision::metrics::step_ulps", case: "through zero", args: &[V::F32(0.0), V::I64(-1)], expect: V::F32(-SUB_MIN), why: "−0 skipped, first negative subnormal" },
    Row { func: "precision::metrics::f32_ulp_at", case: "NaN", args: &[V::F64(f64::NAN)], expect: V::F64(f64::NAN), why: "no ULP" },
    Row { func: "precision::metrics::f32_ulp_at", case: "+Inf", args: &[V::F64(f64::INFINITY)], expect: V::F64(f64::NAN), why: "no ULP" },
    Row { func: "precision::metrics::f32_ulp_at", case: "zero", args: &[V::F64(0.0)], expect: V::F64(1.401298464324817e-45), why: "subnormal spacing 2^-149" },
    Row { func: "precision::metrics::f32_ulp_at", case: "out of f32 range", args: &[V::F64(1e300)], expect: V::F64(2.028240960365167e31), why: "capped at 2^104, the ULP of f32::MAX" },
    Row { func: "precision::metrics::ulp_error", case: "NaN", args: &[V::F32(NAN), V::F64(1.0)], expect: V::F64(f64::NAN), why: "counted apart by ErrorStats" },
    Row { func: "precision::metrics::ulp_error", case: "+Inf", args: &[V::F32(INF), V::F64(f64::INFINITY)], expect: V::F64(0.0), why: "an exact infinity matches itself" },
    Row { func: "precision::metrics::ulp_error", case: "finite vs +Inf", args: &[V::F32(f32::MAX), V::F64(f64::INFINITY)], expect: V::F64(f64::INFINITY), why: "never within a bound" },
    Row { func: "precision::metrics::relative_error", case: "zero reference", args: &[V::F64(1.0), V::F64(0.0)], expect: V::F64(f64::INFINITY), why: "only 0 matches 0" },
    Row { func: "precision::metrics::relative_error", case: "zero vs zero", args: &[V::F64(-0.0), V::F64(0.0)], expect: V::F64(0.0), why: "exact" },
    Row { func: "precision::metrics::relative_error", case: "NaN", args: &[V::F64(f64::NAN), V::F64(1.0)], expect: V::F64(f64::NAN), why: "propagates" },
    Row { func: "precision::metrics::angle_degrees", case: "zero vector", args: &[V::F64x3([0.0; 3]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "NaN", args: &[V::F64x3([f64::NAN, 0.0, 1.0]), V::F64x3([0.0, 0.0, 1.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "+Inf", args: &[V::F64x3([f64::INFINITY, 0.0, 0.0]), V::F64x3([1.0, 0.0, 0.0])], expect: V::F64(f64::NAN), why: "no direction" },
    Row { func: "precision::metrics::angle_degrees", case: "subnormal", args: &[V::F64x3([1e-320, 0.0, 0.0]), V::F64x3([0.0, 1.0, 0.0])], expect: V::F64(90.0), why: "any non-zero length is a direction" },
    Row { func: "precision::metrics::widen3", case: "NaN, ±Inf", args: &[V::Vec3([NAN, INF, -INF])], expect: V::F64x3([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]), why: "exact widening" },
    // Test-input builders (Rust only).
    Row { func: "precision::inputs::unorm8_channel", case: "out-of-range byte", args: &[V::U32(256), V::Channel(ChannelError::Exact), V::Bool(false)], expect: V::F32(1.003_921_6), why: "not clamped: 256/255, for out-of-range inputs" },
    Row { func: "precision::inputs::unorm8_channel", case: "pushed below 0", args: &[V::U32(0), V::Channel(ChannelError::Ulps(3)), V::Bool(true)], expect: V::F32(-4e-45), why: "3 ULP below +0: negative subnormal" },
    Row { func: "precision::inputs::unorm8_channel", case: "NaN offset", args: &[V::U32(7), V::Channel(ChannelError::Offset(f64::NAN)), V::Bool(false)], expect: V::F32(NAN), why: "propagates" },
    Row { func: "precision::inputs::rgb8_channels", case: "out-of-range code u32::MAX", args: &[V::U32(u32::MAX), V::Channel(ChannelError::Exact), V::Bool(false)], expect: V::Vec3([1.0, 1.0, 1.0]), why: "saturates to 2^24 − 1" },
];
