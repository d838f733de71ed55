// prepass — view distance from stored depth, stable on stiff projections.
// Rust twin: src/linear_depth.rs (constants from src/projection.rs). Tests: tests/linear_depth.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// View distance vz is the positive distance along the view axis (right-handed view space has
// z = -vz: Bevy's depth_ndc_to_view_z(d) is -view_z_from_depth_uniform(d, k)). Window depth: standard z = f(vz - n) / ((f - n) vz), reversed z = n(f - vz) / ((f - n) vz);
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
// Every result is finite: WGSL lets an implementation assume that no float operation sees or
// produces NaN or infinity, and a constant expression that evaluates to one is a
// shader-creation error. Special inputs are detected from their bits; a distance of 2^127 or
// more (the far plane of an infinite projection, the sky, the depths next to it) and NaN depth
// return the sky sentinel, the largest finite f32 (Rust `linear_depth::SKY`), written
// 3.4028234e38, which rounds to it: a pass tests `vz >= 3.4028234e38` for the sky. (Tint
// rejects the usual 3.4028235e38, which lies above it, rather than round it down; wesl 0.4
// cannot parse hex floats, so none is used.)

// Whether x is NaN, from its bits (WGSL may assume no NaN in float comparisons).
fn ld_is_nan(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u;
}

// Whether x is +-inf, from its bits.
fn ld_is_inf(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) == 0x7f800000u;
}

// n/f, exactly 0 for an infinite far plane.
fn ld_near_over_far(near: f32, far: f32) -> f32 {
    // A branch, not a select: near / +inf would be an operation on an infinity.
    if (ld_is_inf(far)) {
        return 0.0;
    }
    // WGSL's / is specified for divisors up to 2^126: a larger far is scaled, with near, first.
    if (far > 8.507059e37) {
        return (near * 5.421011e-20) / (far * 5.421011e-20);
    }
    return near / far;
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

// numerator / s for a numerator in (0, f32 max] and s >= 0, or the sky sentinel where the
// quotient would be 2^127 or more (s = 0 included) or s is subnormal (an adapter may flush it
// to 0 in the division though not in a comparison: the sky either way, and only depths within
// 2^-126 of the sky's reach it). The test s·2^127 <= numerator is exact (a power-of-two scaling
// of s < 2 cannot overflow), so no division overflows to +inf.
fn ld_divide_or_sky(numerator: f32, s: f32) -> f32 {
    if (s < 1.1754944e-38 || (s < 2.0 && s * 1.7014118e38 <= numerator)) {
        return 3.4028234e38;
    }
    return numerator / s;
}

// Whether per-projection constants are usable, from their bits (so no arithmetic sees NaN or
// infinity): k0 (n or n·(2^24 - 1)) positive and finite, the ratios k1, k2 in [+0, 1], as every
// Projection gives. Anything else gives the sky.
fn ld_consts_ok(k: vec3<f32>) -> bool {
    return all(bitcast<vec3<u32>>(k) - vec3<u32>(1u, 0u, 0u)
        <= vec3<u32>(0x7f7ffffeu, 0x3f800000u, 0x3f800000u));
}

// Whether near and far are planes a projection can have (as Projection::new checks), from
// their bits: near a normal float in [2^-126, 2^104] (so near·(2^24 - 1) stays finite), far
// above near or +inf.
fn ld_planes_ok(near: f32, far: f32) -> bool {
    let bf = bitcast<u32>(far);
    return bitcast<u32>(near) - 0x00800000u <= 0x73000000u
        && (bf == 0x7f800000u || (bf < 0x7f800000u && far > near));
}

// z clamped to [0, 1] from its bits (negative, -0 and -inf to 0; 1 and above, +inf, to 1), so
// no comparison sees an infinity. z is not NaN.
fn ld_clamp_unit(z: f32) -> f32 {
    let b = bitcast<u32>(z);
    return select(select(z, 1.0, b >= 0x3f800000u), 0.0, b >= 0x80000000u);
}

// The 24-bit path on checked constants k = (n·(2^24 - 1), n/f).
fn ld_view_z_depth24(d: u32, k: vec2<f32>) -> f32 {
    let code = min(d, 0xffffffu);
    // Both terms are exact integers or products of them: no cancellation.
    let s = f32(0xffffffu - code) + f32(code) * k.y;
    return ld_divide_or_sky(k.x, s);
}

// The standard float path on checked constants k = (n, n/f, (f - n)/f).
// Below z = 0.5, 1 - z would round while z·(n/f) keeps growing, so the result could step
// backwards by an ULP; there 1 - z·(1 - n/f) is used instead (no cancellation: z·(1 - n/f) < 0.5),
// and every step is a monotonic rounding, so view distance never decreases as z grows.
fn ld_view_z_standard(z: f32, k: vec3<f32>) -> f32 {
    if (ld_is_nan(z)) {
        return 3.4028234e38;
    }
    let zc = ld_clamp_unit(z);
    let s = select(ld_one_minus(zc) + zc * k.y, 1.0 - zc * k.z, zc < 0.5);
    return ld_divide_or_sky(k.x, s);
}

// The reversed float path on checked constants k = (n, (f - n)/f, n/f).
fn ld_view_z_reversed(z: f32, k: vec3<f32>) -> f32 {
    if (ld_is_nan(z)) {
        return 3.4028234e38;
    }
    let zc = ld_clamp_unit(z);
    let s = zc * k.y + k.z;
    return ld_divide_or_sky(k.x, s);
}

// View distance of a 24-bit standard-convention depth code (0 = near, 2^24 - 1 = far).
// Codes above 2^24 - 1 saturate to 2^24 - 1; the far code of an infinite projection gives the
// sky sentinel 3.4028234e38, as do planes no projection has (ld_planes_ok).
fn view_z_from_depth24(d: u32, near: f32, far: f32) -> f32 {
    if (!ld_planes_ok(near, far)) {
        return 3.4028234e38;
    }
    return ld_view_z_depth24(d, vec2<f32>(near * 16777215.0, ld_near_over_far(near, far)));
}

// View distance of a 24-bit standard-convention depth code, from per-projection constants
// k = (n·(2^24 - 1), n/f) (Projection::depth24_consts): fewer operations per pixel.
// Constants no Projection gives (NaN, infinite, k.x <= 0, k.y outside [+0, 1]) give the sky.
fn view_z_from_depth24_consts(d: u32, k: vec2<f32>) -> f32 {
    if (!ld_consts_ok(vec3<f32>(k, 0.0))) {
        return 3.4028234e38;
    }
    return ld_view_z_depth24(d, k);
}

// View distance of a float standard-convention depth z (0 = near, 1 = far).
// z is clamped to [0, 1]; NaN z, z = 1 with an infinite far plane, and planes no projection
// has give the sky sentinel 3.4028234e38.
fn view_z_from_depth(z: f32, near: f32, far: f32) -> f32 {
    if (!ld_planes_ok(near, far)) {
        return 3.4028234e38;
    }
    let r = ld_near_over_far(near, far);
    return ld_view_z_standard(z, vec3<f32>(near, r, 1.0 - r));
}

// View distance of a float standard-convention depth, from per-projection constants
// k = (n, n/f, (f - n)/f) (Projection::depth_consts). Constants no Projection gives give the sky.
fn view_z_from_depth_consts(z: f32, k: vec3<f32>) -> f32 {
    if (!ld_consts_ok(k)) {
        return 3.4028234e38;
    }
    return ld_view_z_standard(z, k);
}

// View distance of a float reversed-convention depth z (1 = near, 0 = far).
// z is clamped to [0, 1]; NaN z, z = 0 with an infinite far plane (the sky), and planes no
// projection has give the sky sentinel 3.4028234e38.
fn view_z_from_reversed_depth(z: f32, near: f32, far: f32) -> f32 {
    if (!ld_planes_ok(near, far)) {
        return 3.4028234e38;
    }
    let r = ld_near_over_far(near, far);
    return ld_view_z_reversed(z, vec3<f32>(near, 1.0 - r, r));
}

// View distance of a float reversed-convention depth, from per-projection constants
// k = (n, (f - n)/f, n/f) (Projection::reversed_depth_consts). Constants no Projection gives
// give the sky.
fn view_z_from_reversed_depth_consts(z: f32, k: vec3<f32>) -> f32 {
    if (!ld_consts_ok(k)) {
        return 3.4028234e38;
    }
    return ld_view_z_reversed(z, k);
}

// The 24-bit numerator |k.w| of a depth uniform k = (n, n/f, (f - n)/f, +-n·(2^24 - 1)), from
// its bits; whether k.w's sign bit marks a reversed projection is ld_uniform_reversed.
fn ld_uniform_near_times_max(k: vec4<f32>) -> f32 {
    return bitcast<f32>(bitcast<u32>(k.w) & 0x7fffffffu);
}

// Whether k is a depth uniform some Projection gives: n, n/f, (f - n)/f as ld_consts_ok
// checks, and |k.w| positive and finite.
fn ld_uniform_ok(k: vec4<f32>) -> bool {
    return ld_consts_ok(k.xyz) && ld_consts_ok(vec3<f32>(ld_uniform_near_times_max(k), 0.0, 0.0));
}

// Whether the depth uniform k is of a reversed projection (the sign bit of k.w).
fn ld_uniform_reversed(k: vec4<f32>) -> bool {
    return bitcast<u32>(k.w) >= 0x80000000u;
}

// View distance of a float depth in the projection's own convention, from its depth uniform
// k = (n, n/f, (f - n)/f, +-n·(2^24 - 1)) (Projection::depth_uniform; k.w negative: reversed):
// view_z_from_depth_consts or view_z_from_reversed_depth_consts on the same constants, bit for bit.
// Any other vector gives a finite value >= 0: the sky if ld_uniform_ok fails, else the formula's.
fn view_z_from_depth_uniform(z: f32, k: vec4<f32>) -> f32 {
    if (!ld_uniform_ok(k)) {
        return 3.4028234e38;
    }
    if (ld_uniform_reversed(k)) {
        return ld_view_z_reversed(z, vec3<f32>(k.x, k.z, k.y));
    }
    return ld_view_z_standard(z, k.xyz);
}

// View distance of a 24-bit depth code in the projection's own convention, from its depth
// uniform k (Projection::depth_uniform). A reversed code d stores the same depth as the standard
// code 2^24 - 1 - d (reversed depth is exactly 1 - standard depth), so the result is
// view_z_from_depth24_consts of that code, bit for bit. Codes above 2^24 - 1 saturate first.
fn view_z_from_depth24_uniform(d: u32, k: vec4<f32>) -> f32 {
    if (!ld_uniform_ok(k)) {
        return 3.4028234e38;
    }
    let code = min(d, 0xffffffu);
    let standard = select(code, 0xffffffu - code, ld_uniform_reversed(k));
    return ld_view_z_depth24(standard, vec2<f32>(ld_uniform_near_times_max(k), k.y));
}

// The sky sentinel every function here returns for the sky (f32::MAX, Rust linear_depth::SKY):
// a lighting pass tests `vz >= VIEW_Z_SKY`. Written 3.4028234e38, which rounds to f32::MAX
// (Tint rejects 3.4028235e38, which lies above it).
const VIEW_Z_SKY: f32 = 3.4028234e38;
