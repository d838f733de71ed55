// prepass — view distance from stored depth, stable on stiff projections.
// Rust twin: src/linear_depth.rs (constants from src/projection.rs). Tests: tests/linear_depth.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// View distance vz is the positive distance along the view axis (right-handed view space has
// z = -vz). Window depth: standard z = f(vz - n) / ((f - n) vz), reversed z = n(f - vz) / ((f - n) vz);
// far may be +inf (standard z = 1 - n/vz, reversed z = n/vz).
//
// The textbook inverse 1/(z·a + b) with a = (f - n)/(-f n), b = 1/n subtracts two nearly equal
// terms near the far plane, losing precision like (f/n)·2^-24. Solved instead as
//   vz = n / ((1 - z) + z·(n/f))          standard, z >= 0.5 (1 - z·(1 - n/f) below)
//   vz = n / (z·(1 - n/f) + n/f)          reversed
//   vz = n·(2^24 - 1) / ((2^24 - 1 - d) + d·(n/f))   24-bit code d, integer complement
// every term is non-negative, so nothing cancels: the error stays a few ULP for any f/n,
// infinite far included (n/f = 0). 1 - z (z >= 0.5) and the 24-bit complement are built from
// integers, so no reassociation a conforming adapter may apply brings the cancellation back.
// Error bounds, correctly rounded and on every conforming adapter: src/linear_depth.rs, `bounds`.
//
// Special values are built and detected through bits: WGSL lets an implementation assume that
// float operations never see or produce NaN or infinity.

// Whether x is NaN, from its bits (WGSL may assume no NaN in float comparisons).
fn ld_is_nan(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u;
}

// Whether x is +-inf, from its bits.
fn ld_is_inf(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) == 0x7f800000u;
}

// +inf, built from bits.
fn ld_positive_inf() -> f32 {
    return bitcast<f32>(0x7f800000u);
}

// A quiet NaN, built from bits.
fn ld_nan() -> f32 {
    return bitcast<f32>(0x7fc00000u);
}

// n/f, exactly 0 for an infinite far plane.
fn ld_near_over_far(near: f32, far: f32) -> f32 {
    return select(near / far, 0.0, ld_is_inf(far));
}

// 1 - z exactly, for z in [0.5, 1], built from the bits of z: z = (2^23 + m)·2^-24 with m its
// mantissa bits, so 1 - z = (2^23 - m)·2^-24 (0 at z = 1). A float subtraction 1.0 - z would be
// exact too, but WGSL lets an implementation reassociate (1 - z) + p into (1 + p) - z, which
// cancels; an integer it cannot reassociate.
fn ld_one_minus(z: f32) -> f32 {
    if (z >= 1.0) {
        return 0.0;
    }
    return f32(0x800000u - (bitcast<u32>(z) & 0x7fffffu)) * 5.9604644775390625e-8;
}

// numerator / s, with s == 0 (the far plane of an infinite projection) giving +inf.
fn ld_divide_or_inf(numerator: f32, s: f32) -> f32 {
    if (s == 0.0) {
        return ld_positive_inf();
    }
    return numerator / s;
}

// View distance of a 24-bit standard-convention depth code (0 = near, 2^24 - 1 = far).
// Codes above 2^24 - 1 saturate to 2^24 - 1; the far code of an infinite projection is +inf.
fn view_z_from_depth24(d: u32, near: f32, far: f32) -> f32 {
    return view_z_from_depth24_consts(d, vec2<f32>(near * 16777215.0, ld_near_over_far(near, far)));
}

// View distance of a 24-bit standard-convention depth code, from per-projection constants
// k = (n·(2^24 - 1), n/f) (Projection::depth24_consts): fewer operations per pixel.
fn view_z_from_depth24_consts(d: u32, k: vec2<f32>) -> f32 {
    let code = min(d, 0xffffffu);
    // Both terms are exact integers or products of them: no cancellation.
    let s = f32(0xffffffu - code) + f32(code) * k.y;
    return ld_divide_or_inf(k.x, s);
}

// View distance of a float standard-convention depth z (0 = near, 1 = far).
// z is clamped to [0, 1]; NaN gives NaN; z = 1 with an infinite far plane gives +inf.
fn view_z_from_depth(z: f32, near: f32, far: f32) -> f32 {
    let r = ld_near_over_far(near, far);
    return view_z_from_depth_consts(z, vec3<f32>(near, r, 1.0 - r));
}

// View distance of a float standard-convention depth, from per-projection constants
// k = (n, n/f, (f - n)/f) (Projection::depth_consts).
// Below z = 0.5, 1 - z would round while z·(n/f) keeps growing, so the result could step
// backwards by an ULP; there 1 - z·(1 - n/f) is used instead (no cancellation: z·(1 - n/f) < 0.5),
// and every step is a monotonic rounding, so view distance never decreases as z grows.
fn view_z_from_depth_consts(z: f32, k: vec3<f32>) -> f32 {
    if (ld_is_nan(z)) {
        return ld_nan();
    }
    let zc = clamp(z, 0.0, 1.0);
    let s = select(ld_one_minus(zc) + zc * k.y, 1.0 - zc * k.z, zc < 0.5);
    return ld_divide_or_inf(k.x, s);
}

// View distance of a float reversed-convention depth z (1 = near, 0 = far).
// z is clamped to [0, 1]; NaN gives NaN; z = 0 with an infinite far plane (the sky) gives +inf.
fn view_z_from_reversed_depth(z: f32, near: f32, far: f32) -> f32 {
    let r = ld_near_over_far(near, far);
    return view_z_from_reversed_depth_consts(z, vec3<f32>(near, 1.0 - r, r));
}

// View distance of a float reversed-convention depth, from per-projection constants
// k = (n, (f - n)/f, n/f) (Projection::reversed_depth_consts).
fn view_z_from_reversed_depth_consts(z: f32, k: vec3<f32>) -> f32 {
    if (ld_is_nan(z)) {
        return ld_nan();
    }
    let zc = clamp(z, 0.0, 1.0);
    let s = zc * k.y + k.z;
    return ld_divide_or_inf(k.x, s);
}
