//! `wgsl/normal_hemioct.wgsl` and `normal::hemioct`: hemi-octahedral view-space normals in 24
//! bits.

use super::normal::{B15, B127, B247};
use super::{Func, INF, NAN, NEG_NAN, Row, SNAN, SUB_MAX, SUB_MIN, V};
use prepass::normal::{hemioct, oct};

pub const FUNCS: &[Func] = &[
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; encode_normal_hemioct24(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; encode_normal_hemioct24_fast(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; decode_normal_hemioct24(u32) -> Vec3),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; encode_normal_hemioct24_unorm(vec3) -> Vec4),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; decode_normal_hemioct24_unorm(rgba) -> Vec3),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; encode_normal_hemioct24_vouched(vec3) -> U32),
    func!(prepass::wgsl::NORMAL_HEMIOCT; normal::hemioct; encode_normal_hemioct24_fast_vouched(vec3) -> U32),
    Func {
        rust: "normal::hemioct::is_vouched",
        wgsl: None,
        twin: |a| V::Bool(hemioct::is_vouched(a[0].vec3())),
    },
];

pub const WGSL_HELPERS: &[(&str, &str)] = &[
    (
        "hemioct_sanitize",
        "private to normal_hemioct.wgsl: NaN/Inf/subnormal/z < 0 handling, behind every encoder row",
    ),
    (
        "hemioct_continuous",
        "private to normal_hemioct.wgsl: continuous code coordinates, behind the encoder rows",
    ),
    (
        "hemioct_continuous_vouched",
        "private to normal_hemioct.wgsl: the precise vouched encoder's continuous code coordinates, behind its rows",
    ),
    (
        "hemioct_choose",
        "private to normal_hemioct.wgsl: the precise choice of encode_normal_hemioct24 and its vouched form, behind their rows",
    ),
    (
        "hemioct_scale_vouched",
        "private to normal_hemioct.wgsl: the precise vouched encoder's clamp and power-of-two scale, behind its rows",
    ),
    (
        "hemioct_lattice",
        "private to normal_hemioct.wgsl: a code's integer vector, behind the decoder rows",
    ),
    (
        "hemioct_try",
        "private to normal_hemioct.wgsl: the precise encoder's score and choice step, behind its rows",
    ),
];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    // Encoders (the rules they share are in `normal.rs`).
    Row { func: "encode_normal_hemioct24", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x007f_f7ff), why: "every NaN → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_hemioct24", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x00ff_f7ff), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_hemioct24", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x007f_f7ff), why: "−z clamped to the equator: zero → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x007f_f7ff), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_hemioct24", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_hemioct24", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_hemioct24", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x007f_f7ff), why: "code of +z" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x007f_fd54), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_f000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_hemioct24", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_hemioct24", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0x00ff_ffff), why: "z clamped to 0: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::U32(0x0080_0800), why: "NaN anywhere → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "NaN (−NaN, signalling)", args: &[V::Vec3([0.0, NEG_NAN, SNAN])], expect: V::U32(0x0080_0800), why: "every NaN → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::U32(0x00ff_ffff), why: "infinities win: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "±Inf", args: &[V::Vec3([INF, -INF, 5.0])], expect: V::U32(0x00ff_f800), why: "their signs: code of (1, −1, 0)/√2" },
    Row { func: "encode_normal_hemioct24_fast", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::U32(0x0080_0800), why: "−z clamped to the equator: zero → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "subnormal", args: &[V::Vec3([SUB_MIN, -SUB_MIN, SUB_MAX])], expect: V::U32(0x0080_0800), why: "all subnormal = zero → code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "subnormals count as 0: code of +y" },
    Row { func: "encode_normal_hemioct24_fast", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "zero vector (−0.0)", args: &[V::Vec3([-0.0, -0.0, -0.0])], expect: V::U32(0x0080_0800), why: "code of +z" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x0080_0d55), why: "no overflow: code of (1, 1, 1)/√3" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_f000), why: "no underflow: code of −y" },
    Row { func: "encode_normal_hemioct24_fast", case: "non-unit: components 2^254 apart", args: &[V::Vec3([f32::MAX, f32::MIN_POSITIVE, 0.0])], expect: V::U32(0x00ff_ffff), why: "the tiny one vanishes: code of +x" },
    Row { func: "encode_normal_hemioct24_fast", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0x00ff_ffff), why: "z clamped to 0: code of +x" },
    // Decoders.
    // Vouched encoders: inside the contract (`hemioct::is_vouched`: the octahedral contract of
    // (x, y, max(z, 0)), z finite) the robust encoder's code; outside it WGSL leaves the result
    // indeterminate (some u32; the decoder accepts every bit pattern).
    Row { func: "encode_normal_hemioct24_vouched", case: "unit +x", args: &[V::Vec3([1.0, 0.0, 0.0])], expect: V::U32(0xffffff), why: "in the contract: the robust code (+x)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "−0 components", args: &[V::Vec3([-0.0, -0.0, 1.0])], expect: V::U32(0x7ff7ff), why: "in the contract: the robust code (+z)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0xffffff), why: "in the contract (a negative z is clamped): the robust code (+x)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "z = −f32::MAX", args: &[V::Vec3([0.0, 1.0, -f32::MAX])], expect: V::U32(0xfff), why: "in the contract (any finite negative z; the scale is (x, y, 0)'s): the robust code (+y)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "components 2^-126 beside 1", args: &[V::Vec3([f32::MIN_POSITIVE, 1.0, -f32::MIN_POSITIVE])], expect: V::U32(0xfff), why: "in the contract (normal, not subnormal): the robust code (+y)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0xfff000), why: "in the contract: the robust code (−y)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "non-unit: largest 2^124", args: &[V::Vec3([oct::VOUCHED_MAX, oct::VOUCHED_MAX, oct::VOUCHED_MAX])], expect: V::U32(0x7ffd54), why: "in the contract: the robust code ((1, 1, 1)/√3)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract: WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_vouched", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract: WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_vouched", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::WgslIndeterminate(&V::U32(0x555fff)), why: "outside the contract (z not finite): WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_vouched", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "outside the contract, yet defined: +y, flushed or not (not promised)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::U32(0x7ff7ff), why: "outside the contract (‖c‖∞ = 0), yet +z as the robust form (the L1 norm kept ≥ 2^-126)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "straight down", args: &[V::Vec3([0.0, 0.0, -1.0])], expect: V::U32(0x7ff7ff), why: "outside the contract (‖c‖∞ = 0 after the clamp), yet +z as the robust form (the L1 norm kept ≥ 2^-126)" },
    Row { func: "encode_normal_hemioct24_vouched", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::U32(0x7ff7ff), why: "outside the contract (above 2^124), yet defined: the scale 2^(127 − 254) has bits 0, so +z (not promised)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "unit +x", args: &[V::Vec3([1.0, 0.0, 0.0])], expect: V::U32(0xffffff), why: "in the contract: the robust code (+x)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "−0 components", args: &[V::Vec3([-0.0, -0.0, 1.0])], expect: V::U32(0x800800), why: "in the contract: the robust code (+z)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "out of range: z < 0", args: &[V::Vec3([1.0, 0.0, -5.0])], expect: V::U32(0xffffff), why: "in the contract (a negative z is clamped): the robust code (+x)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "z = −f32::MAX", args: &[V::Vec3([0.0, 1.0, -f32::MAX])], expect: V::U32(0xfff), why: "in the contract (any finite negative z; the scale is (x, y, 0)'s): the robust code (+y)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "components 2^-126 beside 1", args: &[V::Vec3([f32::MIN_POSITIVE, 1.0, -f32::MIN_POSITIVE])], expect: V::U32(0xfff), why: "in the contract (normal, not subnormal): the robust code (+y)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "non-unit: tiny", args: &[V::Vec3([0.0, -f32::MIN_POSITIVE, 0.0])], expect: V::U32(0xfff000), why: "in the contract: the robust code (−y)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "non-unit: largest 2^124", args: &[V::Vec3([oct::VOUCHED_MAX, oct::VOUCHED_MAX, oct::VOUCHED_MAX])], expect: V::U32(0x800d55), why: "in the contract: the robust code ((1, 1, 1)/√3)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "NaN", args: &[V::Vec3([NAN, 1.0, 0.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract: WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract: WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "−Inf", args: &[V::Vec3([1.0, 2.0, -INF])], expect: V::WgslIndeterminate(&V::U32(0x555fff)), why: "outside the contract (z not finite): WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "subnormal components", args: &[V::Vec3([SUB_MAX, 1.0, -SUB_MIN])], expect: V::U32(0xfff), why: "outside the contract, yet defined: +y, flushed or not (not promised)" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "zero vector", args: &[V::Vec3([0.0, -0.0, 0.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract: 0/0, WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "straight down", args: &[V::Vec3([0.0, 0.0, -1.0])], expect: V::WgslIndeterminate(&V::U32(0x0)), why: "outside the contract (‖c‖∞ = 0 after the clamp): 0/0, WGSL indeterminate" },
    Row { func: "encode_normal_hemioct24_fast_vouched", case: "non-unit: huge", args: &[V::Vec3([f32::MAX, f32::MAX, f32::MAX])], expect: V::WgslIndeterminate(&V::U32(0x800800)), why: "outside the contract (above 2^124): the L1 norm overflows" },
    Row { func: "normal::hemioct::is_vouched", case: "NaN", args: &[V::Vec3([NAN, 0.0, 1.0])], expect: V::Bool(false), why: "not finite" },
    Row { func: "normal::hemioct::is_vouched", case: "−Inf z", args: &[V::Vec3([1.0, 0.0, -INF])], expect: V::Bool(false), why: "z not finite" },
    Row { func: "normal::hemioct::is_vouched", case: "z = −f32::MAX", args: &[V::Vec3([1.0, 0.0, -f32::MAX])], expect: V::Bool(true), why: "a negative z is clamped: any finite value" },
    Row { func: "normal::hemioct::is_vouched", case: "subnormal negative z", args: &[V::Vec3([1.0, 0.0, -SUB_MAX])], expect: V::Bool(true), why: "a negative z is clamped to 0" },
    Row { func: "normal::hemioct::is_vouched", case: "subnormal component", args: &[V::Vec3([SUB_MAX, 0.0, 1.0])], expect: V::Bool(false), why: "below 2^-126" },
    Row { func: "normal::hemioct::is_vouched", case: "straight down", args: &[V::Vec3([0.0, -0.0, -1.0])], expect: V::Bool(false), why: "the clamp (0, 0, 0) is zero" },
    Row { func: "normal::hemioct::is_vouched", case: "2^-126 beside −2^10 z", args: &[V::Vec3([f32::MIN_POSITIVE, 0.0, -1024.0])], expect: V::Bool(true), why: "the clamp (2^-126, 0, 0) is inside oct's contract" },
    Row { func: "normal::hemioct::is_vouched", case: "2^-126 beside 2", args: &[V::Vec3([f32::MIN_POSITIVE, 0.0, 2.0])], expect: V::Bool(false), why: "below 2^-126 · ‖c‖∞: the robust scaling would flush it" },
    Row { func: "normal::hemioct::is_vouched", case: "f32::MAX", args: &[V::Vec3([f32::MAX, 0.0, 1.0])], expect: V::Bool(false), why: "above 2^124" },
    Row { func: "decode_normal_hemioct24", case: "all ones (unused bits 24–31 set)", args: &[V::U32(u32::MAX)], expect: V::Vec3([1.0, 0.0, 0.0]), why: "high bits ignored; corner (M, M) = +x" },
    Row { func: "decode_normal_hemioct24", case: "unused bits 24–31 only", args: &[V::U32(0xff00_0000)], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "high bits ignored; corner (0, 0) = −x" },
    Row { func: "decode_normal_hemioct24", case: "unused bits set, corner (M, 0)", args: &[V::U32(0xab00_0fff)], expect: V::Vec3([0.0, 1.0, 0.0]), why: "high bits ignored; +y" },
    // Render-target forms.
    Row { func: "encode_normal_hemioct24_unorm", case: "NaN", args: &[V::Vec3([NAN, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z: code 0x7ff7ff, alpha 0" },
    Row { func: "encode_normal_hemioct24_unorm", case: "+Inf", args: &[V::Vec3([INF, 1.0, 0.0])], expect: V::Vec4([1.0, 1.0, 1.0, 0.0]), why: "+x: code 0xffffff" },
    Row { func: "encode_normal_hemioct24_unorm", case: "zero vector", args: &[V::Vec3([0.0, 0.0, 0.0])], expect: V::Vec4([1.0, B247, B127, 0.0]), why: "+z" },
    Row { func: "decode_normal_hemioct24_unorm", case: "NaN", args: &[V::Vec4([NAN, NAN, NAN, NAN])], expect: V::Vec3([-1.0, 0.0, 0.0]), why: "bytes 0: corner (0, 0) = −x" },
    Row { func: "decode_normal_hemioct24_unorm", case: "+Inf (alpha set)", args: &[V::Vec4([INF, INF, INF, INF])], expect: V::Vec3([1.0, 0.0, 0.0]), why: "alpha ignored; corner (M, M) = +x" },
    Row { func: "decode_normal_hemioct24_unorm", case: "out of range, −Inf, NaN", args: &[V::Vec4([INF, B15, -1.0, NAN])], expect: V::Vec3([0.0, 1.0, 0.0]), why: "code (0xfff, 0): +y" },
];
