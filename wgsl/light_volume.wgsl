// prepass — stencil light volumes and the depth-bounds test for lights (Mark Lee, "Pre-lighting
// in Resistance 2", Insomniac Games, GDC 2009; Michal Valient, "Deferred Rendering in Killzone
// 2", Guerrilla Games, Develop Conference 2007).
// Rust twin: src/lighting/light_volume.rs. Tests: tests/light_volume.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// A point's view depth is its view distance vz = -z (positive in front; Lee's w), near and far
// positive view depths, far may be +Inf. The volume tests use only distances and absolute
// components, so either handedness gives the same answer.
//
// Depth-pass stenciling (front faces increment, back faces decrement where the depth test
// passes) breaks when the near plane clips the volume's front faces: the camera is inside the
// volume, or the volume pokes through the near-plane rectangle. Then the renderer switches to
// depth-fail. The "fudge factor" follows from the near plane: every point of the near-plane
// rectangle lies within rho = near·sqrt(1 + tan²(fov_x/2) + tan²(fov_y/2)) of the eye (its
// corners are exactly that far), so a volume whose distance from the eye is at least rho
// cannot touch the rectangle, and depth-pass is safe. The tests add the f32 rounding of the
// distance computation on top (a relative margin derived in the twin's docs).
//
// Bad input: any NaN/Inf, a negative radius or near_corner_distance, or a zero-length cone axis
// answers 1 (depth-fail is always correct, only slower). Depth bounds with bad input return
// the full range [0, 1] (codes [0, 2^24 - 1]) — the depth-bounds test then culls nothing.

const LIGHT_VOLUME_U = 5.9604645e-8; // 2^-24, the unit roundoff of f32
const LIGHT_VOLUME_DEPTH24_MAX = 16777215.0;

// True when x is neither NaN nor ±Inf (judged from the bits).
fn light_volume_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) < 0x7f800000u;
}

// True when no component of v is NaN or ±Inf (judged from the bits).
fn light_volume_finite3(v: vec3<f32>) -> bool {
    return all((bitcast<vec3<u32>>(v) & vec3<u32>(0x7fffffffu)) < vec3<u32>(0x7f800000u));
}

// The power of two that scales a normal m >= 0 into [1, 4): exact, where x / m would divide by
// a number WGSL's / need not handle (beyond 2^126).
fn light_volume_scale(m: f32) -> f32 {
    return bitcast<f32>(max(254u - ((bitcast<u32>(m) >> 23u) & 0xffu), 1u) << 23u);
}

// Whether a + b (both finite, b >= 0) reaches 3.4e38, just below the largest f32 (3.4028e38),
// decided without adding: 3.4e38 - b cannot overflow, and the 0.08 % left above 3.4e38 covers
// any rounding of it or of a later a + b, so no addition ever produces +inf (WGSL leaves a
// run-time infinity indeterminate; a sum of halves could be refactored into (a + b)·0.5).
fn light_volume_sum_overflows(a: f32, b: f32) -> bool {
    return a >= 3.4e38 - b;
}

// rho: distance from the eye to the corners of the near-plane rectangle,
// near·sqrt(1 + tan_half_fov_x² + tan_half_fov_y²), rounded up: enlarged by 2^-19 (32u), which
// covers its own rounding on any conforming adapter (within 15u, derivation in
// src/lighting/light_volume.rs), so it is never below the exact corner distance and a volume
// touching a corner always gets depth-fail, also when rho is computed here on the GPU. The
// constant multiplies near first, the order Mesa's optimiser picks for (near·r)·K anyway: written
// so, every compiler seen evaluates the same order as the twin (any order is within the bound).
// Bad input (NaN/Inf, negative, a tangent
// above 2^60, or a distance that would pass 3.4e38) gives +Inf's stand-in 3.4e38, which makes
// every volume need depth-fail; no square or product overflows.
fn light_volume_near_corner_distance(near: f32, tan_half_fov_x: f32, tan_half_fov_y: f32) -> f32 {
    if (!light_volume_finite(near) || !light_volume_finite(tan_half_fov_x)
        || !light_volume_finite(tan_half_fov_y) || near < 0.0 || tan_half_fov_x < 0.0
        || tan_half_fov_y < 0.0 || tan_half_fov_x > 1.1529215e18 || tan_half_fov_y > 1.1529215e18) {
        return 3.4e38;
    }
    let r = sqrt(1.0 + tan_half_fov_x * tan_half_fov_x + tan_half_fov_y * tan_half_fov_y);
    if (near > 3.4e38 / r) {
        return 3.4e38;
    }
    return (near * (1.0 + 32.0 * LIGHT_VOLUME_U)) * r;
}

// 1 when a sphere light volume (view-space centre, radius) may touch the eye's rho-ball, so the
// stencil pass must use depth-fail; 0 when depth-pass is safe. Tests |c|² < (r + rho)² with the
// right side enlarged by 2^-20 relative, which covers the f32 rounding of both sides (each
// within 6u relative, derivation in src/lighting/light_volume.rs).
fn light_volume_sphere_needs_depth_fail(center: vec3<f32>, radius: f32, near_corner_distance: f32) -> u32 {
    if (!light_volume_finite3(center) || !light_volume_finite(radius)
        || !light_volume_finite(near_corner_distance) || radius < 0.0 || near_corner_distance < 0.0) {
        return 1u;
    }
    // A reach at or beyond 3.4e38 (r + rho could overflow) touches every finite centre.
    if (light_volume_sum_overflows(radius, near_corner_distance)) {
        return 1u;
    }
    let sum = radius + near_corner_distance;
    // Scale by the largest magnitude so the squares cannot overflow.
    let a = abs(center);
    let s = max(max(a.x, max(a.y, a.z)), sum);
    if (s == 0.0 || bitcast<u32>(s) < 0x00800000u) {
        return 1u;
    }
    let sc = light_volume_scale(s);
    let c = center * sc;
    let reach = sum * sc;
    return select(0u, 1u, dot(c, c) <= reach * reach * (1.0 + 16.0 * LIGHT_VOLUME_U));
}

// 1 when a cone light volume may touch the eye's rho-ball (depth-fail), 0 when depth-pass is
// safe. The cone: apex (view space), axis (any length), length h = range_tan.x along the axis,
// base radius h·range_tan.y (range_tan.y = tan of the half-angle), flat cap. The distance from
// the eye to the solid cone is measured in the plane of the axis (t along it, s across it),
// where the cone is the triangle (0,0), (h,0), (h, h·tan); the comparison is widened by the
// derived rounding margin 16u·(|apex| + h·(1 + tan)) + 16u·rho.
fn light_volume_cone_needs_depth_fail(apex: vec3<f32>, axis: vec3<f32>, range_tan: vec2<f32>,
                                      near_corner_distance: f32) -> u32 {
    let h = range_tan.x;
    let k = range_tan.y;
    // The bits first, in a test of their own: WGSL's || need not short-circuit once compiled, and
    // no comparison, abs or max may see a NaN or an infinity.
    if (!light_volume_finite3(apex) || !light_volume_finite3(axis) || !light_volume_finite(h)
        || !light_volume_finite(k) || !light_volume_finite(near_corner_distance)) {
        return 1u;
    }
    let aa = abs(axis);
    let am = max(aa.x, max(aa.y, aa.z));
    if (h < 0.0 || k < 0.0 || near_corner_distance < 0.0 || bitcast<u32>(am) < 0x00800000u) {
        return 1u;
    }
    // One power of two scales every length so the largest lies in [1, 4): squares then neither
    // underflow nor overflow, and wherever they did not the decision is unchanged (each step is
    // homogeneous in the lengths, and power-of-two scaling is exact).
    // h·tan beyond f32 (decided on h·2^-64, exact for h >= 2^-62 and harmless below): depth-fail.
    if (k > 1.8446744e19 || (h * 5.421011e-20) * k > 1.8446743e19) {
        return 1u;
    }
    let ap = abs(apex);
    let big = max(max(max(ap.x, ap.y), max(ap.z, h)), max(h * k, near_corner_distance));
    if (big == 0.0) {
        return 1u; // the apex at the eye
    }
    let sc = bitcast<f32>(max(254u - ((bitcast<u32>(big) >> 23u) & 0xffu), 1u) << 23u);
    return light_volume_cone_scaled(apex * sc, axis, h * sc, k, near_corner_distance * sc);
}

// The cone test of light_volume_cone_needs_depth_fail on lengths already scaled to [1, 4).
fn light_volume_cone_scaled(apex: vec3<f32>, axis: vec3<f32>, h: f32, k: f32,
                            near_corner_distance: f32) -> u32 {
    let aa = abs(axis);
    let am = max(aa.x, max(aa.y, aa.z));
    let a = axis * light_volume_scale(am);
    let d = a * inverseSqrt(dot(a, a));
    let p = -apex; // the eye relative to the apex
    let t = dot(p, d);
    let s = length(p - t * d);
    let base = h * k;
    var dist = 0.0;
    if (!(t >= 0.0 && t <= h && s <= k * t)) {
        // Distances to the slant edge (0,0)-(h,base), the cap (h,0)-(h,base), the axis (0,0)-(h,0).
        let e = vec2<f32>(h, base);
        let q = vec2<f32>(t, s);
        let ee = dot(e, e);
        var u = 0.0;
        if (ee > 0.0) {
            u = clamp(dot(q, e) / ee, 0.0, 1.0);
        }
        let d_slant = length(q - u * e);
        let d_cap = length(q - vec2<f32>(h, clamp(s, 0.0, base)));
        let d_axis = length(q - vec2<f32>(clamp(t, 0.0, h), 0.0));
        dist = min(d_slant, min(d_cap, d_axis));
    }
    let margin = 16.0 * LIGHT_VOLUME_U * (length(apex) + h * (1.0 + k) + near_corner_distance);
    return select(0u, 1u, dist <= near_corner_distance + margin);
}

// Window depth of a view depth vz (near <= vz <= far): standard z = f(vz − n)/((f − n)·vz),
// written (f/(f − n))·(1 − n/vz); reversed 1 − z = (n/(f − n))·(f/vz − 1); infinite far
// (far = +Inf): 1 − n/vz and n/vz. reversed: 0 standard, anything else reversed.
// Bad input (every result finite, in [0, 1] up to rounding): vz is clamped to [near, far];
// NaN or +Inf vz (from its bits) and planes no projection has (near not a normal positive
// float, far neither above near nor +Inf, far/near above 2^126) give the far end
// (1 standard, 0 reversed).
// a / b for b > 0 within WGSL's specified range of divisors: b beyond 2^126 is scaled, with a,
// by 2^-64 first (b is never below 2^-126 here).
fn light_volume_div(a: f32, b: f32) -> f32 {
    if (b > 8.507059e37) {
        return (a * 5.421011e-20) / (b * 5.421011e-20);
    }
    return a / b;
}

fn light_volume_window_depth(vz: f32, near: f32, far: f32, reversed: u32) -> f32 {
    let infinite = bitcast<u32>(far) == 0x7f800000u;
    let far_end = select(1.0, 0.0, reversed != 0u);
    let vz_bits = bitcast<u32>(vz);
    // far/near at most 2^126 (as Projection::new; exact from the bits), so f/vz stays finite; near
    // normal, so no divisor below is subnormal once tiny planes are scaled (next).
    // Bits first; a comparison runs only on values they found finite (an infinite far is
    // recognised from its bits and never compared).
    if (!light_volume_finite(near) || (vz_bits & 0x7fffffffu) > 0x7f800000u
        || vz_bits == 0x7f800000u || !(infinite || light_volume_finite(far))) {
        return far_end;
    }
    if (!(near >= 1.1754944e-38)) {
        return far_end;
    }
    if (!infinite) {
        if (!(far > near && bitcast<u32>(far) - bitcast<u32>(near) <= 0x3f000000u)) {
            return far_end;
        }
    }
    var v = near; // -Inf: the near plane
    if (vz_bits != 0xff800000u) {
        v = max(vz, near);
        if (!infinite) {
            v = min(v, far);
        }
    }
    // The window depth is homogeneous of degree 0 in (vz, near, far): planes below 2^-60 are
    // scaled by 2^64 first (exact), so f − n is never subnormal.
    var n = near;
    var f = far;
    if (!infinite) {
        if (far < 8.6736174e-19) {
            n = near * 1.8446744e19;
            f = far * 1.8446744e19;
            v = v * 1.8446744e19;
        }
    }
    if (reversed == 0u) {
        if (infinite) {
            return 1.0 - light_volume_div(n, v);
        }
        return light_volume_div(f, f - n) * (1.0 - light_volume_div(n, v));
    }
    if (infinite) {
        return light_volume_div(n, v);
    }
    return light_volume_div(n, f - n) * (light_volume_div(f, v) - 1.0);
}

// Depth-bounds range (min, max window depth) that contains every point of a sphere light of
// view depth center_z and radius: the view-depth interval [c − r, c + r] clipped to
// [near, far], mapped through the window depth, and widened by the evaluation's rounding bound
// eps = 16u·(1 + f/(f − n)) (32u for infinite far), clamped to [0, 1].
// A sphere wholly in front of near or behind far gives (1, 0): an empty range.
fn light_volume_sphere_depth_bounds(center_z: f32, radius: f32, near: f32, far: f32,
                                    reversed: u32) -> vec2<f32> {
    let infinite = bitcast<u32>(far) == 0x7f800000u;
    // Bits first; a comparison runs only on values they found finite (an infinite far is
    // recognised from its bits and never compared).
    if (!light_volume_finite(center_z) || !light_volume_finite(radius) || !light_volume_finite(near)
        || !(light_volume_finite(far) || infinite)) {
        return vec2<f32>(0.0, 1.0);
    }
    if (radius < 0.0 || !(near > 0.0)) {
        return vec2<f32>(0.0, 1.0);
    }
    if (!infinite) {
        if (!(far > near)) {
            return vec2<f32>(0.0, 1.0);
        }
    }
    let lo = max(center_z - radius, near);
    // c + r may overflow (decided without computing it): it then lies beyond any finite far, and
    // at infinity for an infinite one.
    let sum_finite = !light_volume_sum_overflows(center_z, radius);
    let hi_at_infinity = infinite && !sum_finite;
    var hi = 0.0;
    if (!hi_at_infinity) {
        if (sum_finite) {
            hi = center_z + radius;
        }
        if (!infinite) {
            if (!sum_finite || hi > far) {
                hi = far;
            }
        }
        if (lo > hi) {
            return vec2<f32>(1.0, 0.0);
        }
    }
    var k = 1.0;
    if (!infinite) {
        k = far / (far - near);
    }
    let eps = 16.0 * LIGHT_VOLUME_U * (1.0 + k);
    var z_lo = light_volume_window_depth(lo, near, far, reversed);
    var z_hi = select(1.0, 0.0, reversed != 0u); // the window depth at infinity
    if (!hi_at_infinity) {
        z_hi = light_volume_window_depth(hi, near, far, reversed);
    }
    if (reversed != 0u) {
        let tmp = z_lo;
        z_lo = z_hi;
        z_hi = tmp;
    }
    return vec2<f32>(clamp(z_lo - eps, 0.0, 1.0), clamp(z_hi + eps, 0.0, 1.0));
}

// The same range as 24-bit depth codes, conservative: floor of the minimum, ceiling of the
// maximum (each product rounds by at most 0.5 of a code, so every depth whose nearest code is
// in the float range lies in [min, max]). Empty range: (1, 0) as codes (2^24 − 1, 0).
fn light_volume_sphere_depth_bounds24(center_z: f32, radius: f32, near: f32, far: f32,
                                      reversed: u32) -> vec2<u32> {
    let b = light_volume_sphere_depth_bounds(center_z, radius, near, far, reversed);
    if (b.x > b.y) {
        return vec2<u32>(0xffffffu, 0u);
    }
    return vec2<u32>(u32(floor(b.x * LIGHT_VOLUME_DEPTH24_MAX)), u32(ceil(b.y * LIGHT_VOLUME_DEPTH24_MAX)));
}
