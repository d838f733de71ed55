// Composed by prepass::scene from the shipped WGSL files.

// ---- from wgsl/light_volume.wgsl ----

const LIGHT_VOLUME_U = 5.9604645e-8;

// True when x is neither NaN nor ±Inf (judged from the bits).
fn light_volume_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) < 0x7f800000u;
}

// True when no component of v is NaN or ±Inf (judged from the bits).
fn light_volume_finite3(v: vec3<f32>) -> bool {
    return all((bitcast<vec3<u32>>(v) & vec3<u32>(0x7fffffffu)) < vec3<u32>(0x7f800000u));
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
    // A reach beyond f32 (r + rho overflows) touches every finite centre.
    let sum = radius + near_corner_distance;
    if (!light_volume_finite(sum)) {
        return 1u;
    }
    // Scale by the largest magnitude so the squares cannot overflow.
    let a = abs(center);
    let s = max(max(a.x, max(a.y, a.z)), sum);
    if (s == 0.0 || bitcast<u32>(s) < 0x00800000u) {
        return 1u;
    }
    let c = center / s;
    let reach = sum / s;
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
    let aa = abs(axis);
    let am = max(aa.x, max(aa.y, aa.z));
    if (!light_volume_finite3(apex) || !light_volume_finite3(axis) || !light_volume_finite(h)
        || !light_volume_finite(k) || !light_volume_finite(near_corner_distance) || h < 0.0
        || k < 0.0 || near_corner_distance < 0.0 || bitcast<u32>(am) < 0x00800000u) {
        return 1u;
    }
    // One power of two scales every length so the largest lies in [1, 4): squares then neither
    // underflow nor overflow, and wherever they did not the decision is unchanged (each step is
    // homogeneous in the lengths, and power-of-two scaling is exact).
    let ap = abs(apex);
    let big = max(max(max(ap.x, ap.y), max(ap.z, h)), max(h * k, near_corner_distance));
    if (big == 0.0 || !light_volume_finite(big)) {
        return 1u; // the apex at the eye, or h·tan beyond f32
    }
    let sc = bitcast<f32>(max(254u - ((bitcast<u32>(big) >> 23u) & 0xffu), 1u) << 23u);
    return light_volume_cone_scaled(apex * sc, axis, h * sc, k, near_corner_distance * sc);
}

// The cone test of light_volume_cone_needs_depth_fail on lengths already scaled to [1, 4).
fn light_volume_cone_scaled(apex: vec3<f32>, axis: vec3<f32>, h: f32, k: f32,
                            near_corner_distance: f32) -> u32 {
    let aa = abs(axis);
    let am = max(aa.x, max(aa.y, aa.z));
    let d = (axis / am) * inverseSqrt(dot(axis / am, axis / am));
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
// Bad input: no guards (sphere_depth_bounds clips vz to [near, far] first): outside it the
// formula extrapolates, NaN propagates.
fn light_volume_window_depth(vz: f32, near: f32, far: f32, reversed: u32) -> f32 {
    let infinite = bitcast<u32>(far) == 0x7f800000u;
    if (reversed == 0u) {
        if (infinite) {
            return 1.0 - near / vz;
        }
        return (far / (far - near)) * (1.0 - near / vz);
    }
    if (infinite) {
        return near / vz;
    }
    return (near / (far - near)) * (far / vz - 1.0);
}

// Depth-bounds range (min, max window depth) that contains every point of a sphere light of
// view depth center_z and radius: the view-depth interval [c − r, c + r] clipped to
// [near, far], mapped through the window depth, and widened by the evaluation's rounding bound
// eps = 16u·(1 + f/(f − n)) (32u for infinite far), clamped to [0, 1].
// A sphere wholly in front of near or behind far gives (1, 0): an empty range.
fn light_volume_sphere_depth_bounds(center_z: f32, radius: f32, near: f32, far: f32,
                                    reversed: u32) -> vec2<f32> {
    let infinite = bitcast<u32>(far) == 0x7f800000u;
    if (!light_volume_finite(center_z) || !light_volume_finite(radius) || !light_volume_finite(near)
        || !(light_volume_finite(far) || infinite) || radius < 0.0 || !(near > 0.0)
        || !(far > near)) {
        return vec2<f32>(0.0, 1.0);
    }
    let lo = max(center_z - radius, near);
    let sum = center_z + radius;
    // c + r may overflow (checked from its bits): it then lies beyond any finite far.
    let sum_finite = light_volume_finite(sum);
    var hi = sum;
    if (!infinite && (!sum_finite || sum > far)) {
        hi = far;
    }
    let hi_at_infinity = infinite && !sum_finite;
    if (!hi_at_infinity && lo > hi) {
        return vec2<f32>(1.0, 0.0);
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

// ---- from wgsl/linear_depth.wgsl ----

// Whether x is NaN, from its bits (WGSL may assume no NaN in float comparisons).
fn ld_is_nan(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u;
}

// +inf, built from bits.
fn ld_positive_inf() -> f32 {
    return bitcast<f32>(0x7f800000u);
}

// A quiet NaN, built from bits.
fn ld_nan() -> f32 {
    return bitcast<f32>(0x7fc00000u);
}

// numerator / s, with s == 0 (the far plane of an infinite projection) giving +inf.
fn ld_divide_or_inf(numerator: f32, s: f32) -> f32 {
    if (s == 0.0) {
        return ld_positive_inf();
    }
    return numerator / s;
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

// ---- from wgsl/lpp.wgsl ----

const LPP_LUMINANCE = vec3<f32>(0.2126, 0.7152, 0.0722);

const LPP_COLOUR_MAX = 65504.0;

// True when x is neither NaN nor ±Inf (judged from the bits).
fn lpp_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) < 0x7f800000u;
}

// True when no component of v is NaN or ±Inf (judged from the bits).
fn lpp_finite3(v: vec3<f32>) -> bool {
    return all((bitcast<vec3<u32>>(v) & vec3<u32>(0x7fffffffu)) < vec3<u32>(0x7f800000u));
}

// v / |v|, or zero when v is non-finite or its largest component is zero or subnormal. Scaling
// by the largest component first keeps |v|² from overflowing or underflowing.
fn lpp_direction(v: vec3<f32>) -> vec3<f32> {
    let a = abs(v);
    let m = max(a.x, max(a.y, a.z));
    if (!lpp_finite3(v) || bitcast<u32>(m) < 0x00800000u) {
        return vec3<f32>(0.0);
    }
    let s = v / m;
    return s * inverseSqrt(dot(s, s));
}

// Luminance (Rec. 709 weights) of a light-buffer colour. A plain dot product: NaN and ±Inf
// propagate and negative channels count (callers clamp colours first).
fn lpp_luminance(rgb: vec3<f32>) -> f32 {
    return dot(rgb, LPP_LUMINANCE);
}

// x^y for a cosine x and an exponent y >= 0: clamped to [0, 1], 0 for x <= 0 and when the
// computed y·log2(x) is below -126 (exp2's argument is never below -126, so no subnormal or
// -Inf arrives; a result just under 2^-126 may round up to 2^-126).
// Bad input: x or y NaN (from their bits) → 0, no highlight; y <= 0 acts as 0 (x^0 = 1 for
// x > 0); y = +Inf gives 0 for x < 1.
fn lpp_pow_cosine(x: f32, y: f32) -> f32 {
    let nan = (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u
        || (bitcast<u32>(y) & 0x7fffffffu) > 0x7f800000u;
    if (nan || x <= 0.0) {
        return 0.0;
    }
    if (x >= 1.0 || y <= 0.0) {
        return 1.0;
    }
    let t = y * log2(x);
    if (t < -126.0) {
        return 0.0;
    }
    return exp2(t);
}

// Windowed falloff of a point light of radius r: (1 − (d/r)²)², 0 beyond r.
// Bad input: NaN/Inf or r <= 0 → 0; d < 0 counts as 0.
fn lpp_point_attenuation(distance: f32, radius: f32) -> f32 {
    if (!lpp_finite(distance) || !lpp_finite(radius) || !(radius > 0.0)) {
        return 0.0;
    }
    let x = clamp(max(distance, 0.0) / radius, 0.0, 1.0);
    let w = 1.0 - x * x;
    return w * w;
}

// Spot cone factor: 0 outside cos_outer, 1 inside cos_inner, linear in the cosine between.
// cos_angle is the cosine between the spot axis and the direction from the light to the surface.
// Bad input: NaN/Inf → 0; cosines outside [-1, 1] are clamped to it first (so no difference
// overflows); cos_inner <= cos_outer gives a hard edge at cos_outer.
fn lpp_spot_attenuation(cos_angle: f32, cos_outer: f32, cos_inner: f32) -> f32 {
    if (!lpp_finite(cos_angle) || !lpp_finite(cos_outer) || !lpp_finite(cos_inner)) {
        return 0.0;
    }
    let c = clamp(cos_angle, -1.0, 1.0);
    let outer = clamp(cos_outer, -1.0, 1.0);
    let inner = clamp(cos_inner, -1.0, 1.0);
    if (inner <= outer) {
        return select(0.0, 1.0, c >= outer);
    }
    return clamp((c - outer) / (inner - outer), 0.0, 1.0);
}

// N·L·att (the diffuse weight) and the specular cosine (N·H for Blinn-Phong, R·V for Phong),
// or zeros for bad input.
fn lpp_cosines(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>, phong: bool) -> vec2<f32> {
    let n = lpp_direction(normal);
    let l = lpp_direction(to_light);
    let v = lpp_direction(to_eye);
    let n_dot_l = max(dot(n, l), 0.0);
    if (all(v == vec3<f32>(0.0))) {
        return vec2<f32>(0.0);
    }
    if (!(n_dot_l > 0.0)) {
        return vec2<f32>(n_dot_l, 0.0);
    }
    if (phong) {
        let r = 2.0 * dot(n, l) * n - l; // reflect(−l, n)
        return vec2<f32>(n_dot_l, clamp(dot(r, v), 0.0, 1.0));
    }
    let h = lpp_direction(l + v);
    return vec2<f32>(n_dot_l, clamp(dot(n, h), 0.0, 1.0));
}

// The one-buffer P of the two lights below; phong picks R·V instead of N·H as the cosine.
fn lpp_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>, colour: vec3<f32>,
             attenuation: f32, power: f32, phong: bool) -> vec4<f32> {
    if (!lpp_finite3(colour) || !lpp_finite(attenuation) || !lpp_finite(power)) {
        return vec4<f32>(0.0);
    }
    let c = clamp(colour, vec3<f32>(0.0), vec3<f32>(LPP_COLOUR_MAX));
    let cos = lpp_cosines(normal, to_eye, to_light, phong);
    let d = cos.x * clamp(attenuation, 0.0, 1.0);
    let s = lpp_pow_cosine(cos.y, clamp(power, 0.0, LPP_COLOUR_MAX));
    return vec4<f32>(d * c, d * lpp_luminance(c) * s);
}

// P for the one-buffer layout, Blinn-Phong: (N·L·att·colour, N·L·att·lum(colour)·(N·H)^power).
fn lpp_blinn_phong_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                         colour: vec3<f32>, attenuation: f32, power: f32) -> vec4<f32> {
    return lpp_light(normal, to_eye, to_light, colour, attenuation, power, false);
}

// P of a point light (colour_radius = colour, radius) with Blinn-Phong specular.
fn lpp_point_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                   colour_radius: vec4<f32>, power: f32) -> vec4<f32> {
    let att = lpp_point_attenuation(length(to_light), colour_radius.w);
    return lpp_blinn_phong_light(normal, to_eye, to_light, colour_radius.xyz, att, power);
}

// P of a spot light: a point light times the cone factor. axis_cos_outer = the direction the
// spot points (any length) and the cosine of its outer half-angle.
fn lpp_spot_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                  colour_radius: vec4<f32>, axis_cos_outer: vec4<f32>, cos_inner: f32,
                  power: f32) -> vec4<f32> {
    let cos_angle = dot(lpp_direction(axis_cos_outer.xyz), -lpp_direction(to_light));
    let att = lpp_point_attenuation(length(to_light), colour_radius.w)
        * lpp_spot_attenuation(cos_angle, axis_cos_outer.w, cos_inner);
    return lpp_blinn_phong_light(normal, to_eye, to_light, colour_radius.xyz, att, power);
}

// Engel's reconstruction from an accumulated one-buffer texel: (a / lum(rgb))^m · lum(rgb).
// The ratio is N·H^n for one light; for several it is a luminance-weighted mix and may exceed 1
// (the blog comments' worry): it is clamped to [0, 1] before the exponent, so the result never
// exceeds lum(rgb). Guards: a non-finite channel, lum(rgb) below 2^-126 or a <= 0 give 0; the
// division only runs when a < lum, so it cannot overflow. material_power is clamped to
// [0, 65504]; NaN/Inf give 0.
fn lpp_reconstruct_specular(light: vec4<f32>, material_power: f32) -> f32 {
    if (!lpp_finite3(light.xyz) || !lpp_finite(light.w) || !lpp_finite(material_power)) {
        return 0.0;
    }
    let rgb = max(light.xyz, vec3<f32>(0.0));
    let lum = lpp_luminance(rgb);
    if (bitcast<u32>(lum) < 0x00800000u || !(light.w > 0.0)) {
        return 0.0;
    }
    var ratio = 1.0;
    if (light.w < lum) {
        ratio = light.w / lum;
    }
    return lpp_pow_cosine(ratio, clamp(material_power, 0.0, LPP_COLOUR_MAX)) * lum;
}

// C for the one-buffer layout: albedo·rgb + gloss·reconstructed specular. Inputs are clamped to
// [0, 65504] (NaN → 0).
fn lpp_combine(albedo: vec3<f32>, gloss: vec3<f32>, light: vec4<f32>, material_power: f32) -> vec3<f32> {
    let spec = lpp_reconstruct_specular(light, material_power);
    return lpp_clamp_colour(albedo) * lpp_clamp_colour(light.xyz) + lpp_clamp_colour(gloss) * spec;
}

// Clamp to [0, 65504], NaN (from its bits) to 0.
fn lpp_clamp_colour(c: vec3<f32>) -> vec3<f32> {
    let nan = (bitcast<vec3<u32>>(c) & vec3<u32>(0x7fffffffu)) > vec3<u32>(0x7f800000u);
    return clamp(select(c, vec3<f32>(0.0), nan), vec3<f32>(0.0), vec3<f32>(LPP_COLOUR_MAX));
}

// ---- from wgsl/normal_oct.wgsl ----

// The input made safe: NaN or zero -> none (w = 0); infinities -> their signs; subnormal
// components -> signed zero; then scaled by an exact power of two so the largest component
// lies in [1, 4). w = 1 when valid.
fn oct_sanitize(n: vec3<f32>) -> vec4<f32> {
    let bits = bitcast<vec3<u32>>(n);
    let mag = bits & vec3<u32>(0x7fffffffu);
    if (any(mag > vec3<u32>(0x7f800000u))) {
        return vec4<f32>(0.0, 0.0, 1.0, 0.0);
    }
    let sign_one = bitcast<vec3<f32>>((bits & vec3<u32>(0x80000000u)) | vec3<u32>(0x3f800000u));
    let signed_zero = bitcast<vec3<f32>>(bits & vec3<u32>(0x80000000u));
    let is_inf = mag == vec3<u32>(0x7f800000u);
    let is_sub = (bits & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    var c = select(n, signed_zero, is_sub);
    if (any(is_inf)) {
        c = select(signed_zero, sign_one, is_inf);
    }
    let m = max(max(abs(c.x), abs(c.y)), abs(c.z));
    if (m == 0.0) {
        return vec4<f32>(0.0, 0.0, 1.0, 0.0);
    }
    let e = (bitcast<u32>(m) >> 23u) & 0xffu;
    let scale = bitcast<f32>(max(254u - e, 1u) << 23u);
    let s = c * scale;
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return vec4<f32>(select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub), 1.0);
}

// The continuous code coordinates in [0, M]^2 of a sanitized vector (before rounding).
fn oct_continuous(s: vec3<f32>, m: u32) -> vec2<f32> {
    let a = abs(s);
    let l1 = (a.x + a.y) + a.z;
    var p = s.xy / l1;
    if (s.z < 0.0) {
        // Lower hemisphere: fold over the diagonals. The sign of +-0 counts as +.
        let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
        p = (vec2<f32>(1.0) - abs(p.yx)) * sgn;
    }
    // p * 0.5 is exact, so fusing the add cannot change the sum.
    let t = clamp(p * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(1.0));
    return t * f32(m);
}

// The exact integer direction code (u, v) stands for (see the header); its L1 norm is M.
// Branch-free: the fold is a select between exact integer vectors.
fn oct_lattice(uv: vec2<u32>, m: u32) -> vec3<i32> {
    let mi = i32(m);
    let ab = 2 * vec2<i32>(uv) - vec2<i32>(mi);
    let aab = abs(ab);
    let z = mi - aab.x - aab.y;
    // Folded when z < 0: then a and b are odd (M is odd), never zero, so sign() is +-1.
    let folded = (vec2<i32>(mi) - aab.yx) * sign(ab);
    return vec3<i32>(select(ab, folded, z < 0), z);
}

// sin^2 of the angle between s and the direction of code uv: |s x D|^2 / |D|^2, up to the common
// factor |s|^2. Sine, not cosine: at oct32's 2e-5 rad a cosine is 1.0 in f32.
fn oct_sin2(s: vec3<f32>, uv: vec2<u32>, m: u32) -> f32 {
    let d = oct_lattice(uv, m);
    let ad = vec3<u32>(abs(d));
    // |D|^2 <= M^2 < 2^32: exact in u32, one rounding to f32.
    let sq = ad * ad;
    let len2 = f32(sq.x + sq.y + sq.z);
    let x = cross(s, vec3<f32>(d));
    return dot(x, x) / len2;
}

// The survey's precise encoder: of the four codes around the continuous coordinates (floor and
// floor + 1 per axis), the one whose decoded direction is closest to s. Candidates are tried in
// the order (0,0), (1,0), (0,1), (1,1); a later one wins only if strictly closer. Straight-line
// (no loop, no variables): each later candidate replaces the best so far through a select.
fn oct_encode_precise(n: vec3<f32>, bits: u32) -> u32 {
    let m = (1u << bits) - 1u;
    let s = oct_sanitize(n).xyz;
    let c00 = min(vec2<u32>(floor(oct_continuous(s, m))), vec2<u32>(m - 1u));
    let c10 = c00 + vec2<u32>(1u, 0u);
    let c01 = c00 + vec2<u32>(0u, 1u);
    let c11 = c00 + vec2<u32>(1u);
    let s00 = oct_sin2(s, c00, m);
    let s10 = oct_sin2(s, c10, m);
    let t10 = s10 < s00;
    let b1 = select(c00, c10, t10);
    let s1 = select(s00, s10, t10);
    let s01 = oct_sin2(s, c01, m);
    let t01 = s01 < s1;
    let b2 = select(b1, c01, t01);
    let s2 = select(s1, s01, t01);
    let best = select(b2, c11, oct_sin2(s, c11, m) < s2);
    return best.x | (best.y << bits);
}

// The unit vector of code p with `bits` bits per axis: its integer direction D, normalised.
fn oct_decode(p: u32, bits: u32) -> vec3<f32> {
    let m = (1u << bits) - 1u;
    let uv = vec2<u32>(p & m, (p >> bits) & m);
    return normalize(vec3<f32>(oct_lattice(uv, m)));
}

// Byte k of the u32 from a unorm8 channel: round(255 c) after clamping; NaN counts as 0.
fn oct_unorm_bytes(c: vec4<f32>) -> u32 {
    let is_nan = (bitcast<vec4<u32>>(c) & vec4<u32>(0x7fffffffu)) > vec4<u32>(0x7f800000u);
    let b = vec4<u32>(round(clamp(select(c, vec4<f32>(0.0), is_nan), vec4<f32>(0.0), vec4<f32>(1.0)) * 255.0));
    return b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u);
}

// ---- 2 x 12 bits (three bytes of an RGBA8 texel; alpha left zero for the material) ----
// The 2x12-bit code whose direction is closest to n: u in bits 0-11, v in bits 12-23.
fn encode_normal_oct24(n: vec3<f32>) -> u32 {
    return oct_encode_precise(n, 12u);
}

// The unit vector of a 2x12-bit code; bits 24-31 are ignored.
fn decode_normal_oct24(p: u32) -> vec3<f32> {
    return oct_decode(p, 12u);
}

// The rgba8unorm channels to write for encode_normal_oct24(n) (alpha 0, for the material).
fn encode_normal_oct24_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_oct24(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back; alpha ignored).
fn decode_normal_oct24_unorm(c: vec4<f32>) -> vec3<f32> {
    return oct_decode(oct_unorm_bytes(c), 12u);
}

// ---- from wgsl/position.wgsl ----

// View ray through ndc_xy for right-handed view space (-z forward): z = -1.
fn frustum_ray_rh(ndc_xy: vec2<f32>, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(ndc_xy * tan_half_fov, -1.0);
}

// NDC of a full-screen triangle's vertex 0, 1, 2: (-1,-1), (3,-1), (-1,3); it covers the
// screen with one primitive, and vertex attributes linear in NDC interpolate exactly.
fn fullscreen_triangle_ndc(vertex_index: u32) -> vec2<f32> {
    let v = vec2<u32>(vertex_index & 1u, (vertex_index >> 1u) & 1u);
    return vec2<f32>(v) * 4.0 - 1.0;
}

// The frustum ray at a full-screen triangle's vertex, right-handed (-z forward).
fn fullscreen_triangle_ray_rh(vertex_index: u32, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return frustum_ray_rh(fullscreen_triangle_ndc(vertex_index), tan_half_fov);
}

// A view ray rotated into world orientation (view_to_world = the camera's rotation, columns =
// its right, up and back/forward axes). Rotate the corner rays in the vertex stage, not per pixel.
fn world_ray(view_ray: vec3<f32>, view_to_world: mat3x3<f32>) -> vec3<f32> {
    return view_to_world * view_ray;
}

// Position relative to the camera, in world orientation: keeps view-space relative precision
// however far the camera is from the world origin. Add the camera position in higher precision
// (or not at all: light in camera-relative space).
fn camera_relative_position(world_ray_dir: vec3<f32>, view_z: f32) -> vec3<f32> {
    return world_ray_dir * view_z;
}

// ---- from wgsl/roughness.wgsl ----

// 2^(r/255) for r = 0..254, correctly rounded to f32 (bit patterns).
var<private> LOG_ROUGHNESS_EXP2_STEPS: array<u32, 255> = array<u32, 255>(
    0x3f800000u, 0x3f805931u, 0x3f80b2a0u, 0x3f810c4eu, 0x3f81663au, 0x3f81c065u, 0x3f821aceu, 0x3f827577u,
    0x3f82d05fu, 0x3f832b86u, 0x3f8386edu, 0x3f83e293u, 0x3f843e79u, 0x3f849a9fu, 0x3f84f706u, 0x3f8553acu,
    0x3f85b094u, 0x3f860dbcu, 0x3f866b25u, 0x3f86c8cfu, 0x3f8726bau, 0x3f8784e7u, 0x3f87e356u, 0x3f884206u,
    0x3f88a0f8u, 0x3f89002cu, 0x3f895fa3u, 0x3f89bf5cu, 0x3f8a1f58u, 0x3f8a7f97u, 0x3f8ae019u, 0x3f8b40deu,
    0x3f8ba1e7u, 0x3f8c0333u, 0x3f8c64c3u, 0x3f8cc697u, 0x3f8d28afu, 0x3f8d8b0bu, 0x3f8dedacu, 0x3f8e5092u,
    0x3f8eb3bdu, 0x3f8f172du, 0x3f8f7ae2u, 0x3f8fdedcu, 0x3f90431cu, 0x3f90a7a2u, 0x3f910c6eu, 0x3f917181u,
    0x3f91d6d9u, 0x3f923c79u, 0x3f92a25fu, 0x3f93088cu, 0x3f936f01u, 0x3f93d5bcu, 0x3f943cc0u, 0x3f94a40bu,
    0x3f950b9eu, 0x3f957379u, 0x3f95db9du, 0x3f964409u, 0x3f96acbeu, 0x3f9715bcu, 0x3f977f03u, 0x3f97e894u,
    0x3f98526eu, 0x3f98bc92u, 0x3f9926ffu, 0x3f9991b7u, 0x3f99fcb9u, 0x3f9a6806u, 0x3f9ad39eu, 0x3f9b3f80u,
    0x3f9babaeu, 0x3f9c1827u, 0x3f9c84ecu, 0x3f9cf1fdu, 0x3f9d5f59u, 0x3f9dcd02u, 0x3f9e3af7u, 0x3f9ea939u,
    0x3f9f17c7u, 0x3f9f86a3u, 0x3f9ff5ccu, 0x3fa06542u, 0x3fa0d506u, 0x3fa14518u, 0x3fa1b578u, 0x3fa22626u,
    0x3fa29723u, 0x3fa3086eu, 0x3fa37a09u, 0x3fa3ebf2u, 0x3fa45e2bu, 0x3fa4d0b4u, 0x3fa5438cu, 0x3fa5b6b5u,
    0x3fa62a2du, 0x3fa69df6u, 0x3fa71210u, 0x3fa7867bu, 0x3fa7fb37u, 0x3fa87044u, 0x3fa8e5a3u, 0x3fa95b53u,
    0x3fa9d156u, 0x3faa47aau, 0x3faabe52u, 0x3fab354bu, 0x3fabac98u, 0x3fac2438u, 0x3fac9c2bu, 0x3fad1472u,
    0x3fad8d0du, 0x3fae05fcu, 0x3fae7f3fu, 0x3faef8d6u, 0x3faf72c2u, 0x3fafed03u, 0x3fb0679au, 0x3fb0e285u,
    0x3fb15dc7u, 0x3fb1d95eu, 0x3fb2554cu, 0x3fb2d18fu, 0x3fb34e2au, 0x3fb3cb1bu, 0x3fb44863u, 0x3fb4c603u,
    0x3fb543fau, 0x3fb5c249u, 0x3fb640efu, 0x3fb6bfefu, 0x3fb73f46u, 0x3fb7bef6u, 0x3fb83f00u, 0x3fb8bf62u,
    0x3fb9401eu, 0x3fb9c134u, 0x3fba42a4u, 0x3fbac46du, 0x3fbb4692u, 0x3fbbc911u, 0x3fbc4bebu, 0x3fbccf20u,
    0x3fbd52b0u, 0x3fbdd69cu, 0x3fbe5ae4u, 0x3fbedf89u, 0x3fbf6489u, 0x3fbfe9e7u, 0x3fc06fa1u, 0x3fc0f5b9u,
    0x3fc17c2du, 0x3fc20300u, 0x3fc28a31u, 0x3fc311bfu, 0x3fc399adu, 0x3fc421f9u, 0x3fc4aaa4u, 0x3fc533aeu,
    0x3fc5bd17u, 0x3fc646e1u, 0x3fc6d10au, 0x3fc75b94u, 0x3fc7e67eu, 0x3fc871c9u, 0x3fc8fd75u, 0x3fc98982u,
    0x3fca15f1u, 0x3fcaa2c2u, 0x3fcb2ff5u, 0x3fcbbd8bu, 0x3fcc4b83u, 0x3fccd9ddu, 0x3fcd689cu, 0x3fcdf7bdu,
    0x3fce8742u, 0x3fcf172cu, 0x3fcfa779u, 0x3fd0382cu, 0x3fd0c943u, 0x3fd15abfu, 0x3fd1eca0u, 0x3fd27ee7u,
    0x3fd31194u, 0x3fd3a4a8u, 0x3fd43821u, 0x3fd4cc02u, 0x3fd56049u, 0x3fd5f4f8u, 0x3fd68a0fu, 0x3fd71f8du,
    0x3fd7b573u, 0x3fd84bc2u, 0x3fd8e27au, 0x3fd9799bu, 0x3fda1125u, 0x3fdaa919u, 0x3fdb4176u, 0x3fdbda3eu,
    0x3fdc7370u, 0x3fdd0d0du, 0x3fdda715u, 0x3fde4188u, 0x3fdedc67u, 0x3fdf77b2u, 0x3fe01369u, 0x3fe0af8cu,
    0x3fe14c1cu, 0x3fe1e91au, 0x3fe28685u, 0x3fe3245du, 0x3fe3c2a4u, 0x3fe46158u, 0x3fe5007cu, 0x3fe5a00eu,
    0x3fe6400fu, 0x3fe6e080u, 0x3fe78161u, 0x3fe822b2u, 0x3fe8c473u, 0x3fe966a5u, 0x3fea0948u, 0x3feaac5cu,
    0x3feb4fe2u, 0x3febf3dau, 0x3fec9844u, 0x3fed3d21u, 0x3fede271u, 0x3fee8833u, 0x3fef2e6au, 0x3fefd514u,
    0x3ff07c32u, 0x3ff123c5u, 0x3ff1cbccu, 0x3ff27449u, 0x3ff31d3au, 0x3ff3c6a2u, 0x3ff47080u, 0x3ff51ad4u,
    0x3ff5c59fu, 0x3ff670e0u, 0x3ff71c99u, 0x3ff7c8cau, 0x3ff87573u, 0x3ff92294u, 0x3ff9d02eu, 0x3ffa7e40u,
    0x3ffb2cccu, 0x3ffbdbd2u, 0x3ffc8b51u, 0x3ffd3b4bu, 0x3ffdebc0u, 0x3ffe9cafu, 0x3fff4e1au,
);

// The smallest f32 >= 2^(r/510) for r = 0..509 (bit patterns): code boundaries rounded up.
var<private> LOG_ROUGHNESS_BOUNDARY_STEPS: array<u32, 510> = array<u32, 510>(
    0x3f800000u, 0x3f802c91u, 0x3f805932u, 0x3f8085e2u, 0x3f80b2a1u, 0x3f80df70u, 0x3f810c4fu, 0x3f81393du,
    0x3f81663bu, 0x3f819348u, 0x3f81c065u, 0x3f81ed92u, 0x3f821acfu, 0x3f82481bu, 0x3f827578u, 0x3f82a2e4u,
    0x3f82d05fu, 0x3f82fdebu, 0x3f832b86u, 0x3f835932u, 0x3f8386edu, 0x3f83b4b8u, 0x3f83e293u, 0x3f84107eu,
    0x3f843e79u, 0x3f846c85u, 0x3f849aa0u, 0x3f84c8cbu, 0x3f84f706u, 0x3f852551u, 0x3f8553adu, 0x3f858218u,
    0x3f85b094u, 0x3f85df20u, 0x3f860dbcu, 0x3f863c69u, 0x3f866b25u, 0x3f8699f2u, 0x3f86c8cfu, 0x3f86f7bdu,
    0x3f8726bbu, 0x3f8755c9u, 0x3f8784e8u, 0x3f87b417u, 0x3f87e356u, 0x3f8812a6u, 0x3f884206u, 0x3f887177u,
    0x3f88a0f9u, 0x3f88d08au, 0x3f89002du, 0x3f892fe0u, 0x3f895fa4u, 0x3f898f78u, 0x3f89bf5du, 0x3f89ef52u,
    0x3f8a1f59u, 0x3f8a4f70u, 0x3f8a7f98u, 0x3f8aafd0u, 0x3f8ae019u, 0x3f8b1074u, 0x3f8b40dfu, 0x3f8b715au,
    0x3f8ba1e7u, 0x3f8bd285u, 0x3f8c0333u, 0x3f8c33f3u, 0x3f8c64c3u, 0x3f8c95a5u, 0x3f8cc697u, 0x3f8cf79bu,
    0x3f8d28afu, 0x3f8d59d5u, 0x3f8d8b0cu, 0x3f8dbc54u, 0x3f8dedadu, 0x3f8e1f17u, 0x3f8e5093u, 0x3f8e821fu,
    0x3f8eb3bdu, 0x3f8ee56cu, 0x3f8f172du, 0x3f8f48ffu, 0x3f8f7ae2u, 0x3f8facd7u, 0x3f8fdeddu, 0x3f9010f4u,
    0x3f90431du, 0x3f907557u, 0x3f90a7a3u, 0x3f90da00u, 0x3f910c6fu, 0x3f913eefu, 0x3f917181u, 0x3f91a425u,
    0x3f91d6dau, 0x3f9209a1u, 0x3f923c79u, 0x3f926f64u, 0x3f92a260u, 0x3f92d56du, 0x3f93088du, 0x3f933bbeu,
    0x3f936f01u, 0x3f93a256u, 0x3f93d5bdu, 0x3f940936u, 0x3f943cc0u, 0x3f94705du, 0x3f94a40bu, 0x3f94d7ccu,
    0x3f950b9fu, 0x3f953f83u, 0x3f95737au, 0x3f95a783u, 0x3f95db9du, 0x3f960fcau, 0x3f96440au, 0x3f96785bu,
    0x3f96acbfu, 0x3f96e135u, 0x3f9715bdu, 0x3f974a57u, 0x3f977f04u, 0x3f97b3c3u, 0x3f97e894u, 0x3f981d78u,
    0x3f98526eu, 0x3f988777u, 0x3f98bc92u, 0x3f98f1c0u, 0x3f992700u, 0x3f995c52u, 0x3f9991b8u, 0x3f99c72fu,
    0x3f99fcbau, 0x3f9a3257u, 0x3f9a6807u, 0x3f9a9dc9u, 0x3f9ad39eu, 0x3f9b0986u, 0x3f9b3f81u, 0x3f9b758eu,
    0x3f9babafu, 0x3f9be1e2u, 0x3f9c1828u, 0x3f9c4e81u, 0x3f9c84edu, 0x3f9cbb6bu, 0x3f9cf1fdu, 0x3f9d28a2u,
    0x3f9d5f5au, 0x3f9d9624u, 0x3f9dcd02u, 0x3f9e03f3u, 0x3f9e3af7u, 0x3f9e720fu, 0x3f9ea939u, 0x3f9ee077u,
    0x3f9f17c8u, 0x3f9f4f2cu, 0x3f9f86a3u, 0x3f9fbe2eu, 0x3f9ff5ccu, 0x3fa02d7eu, 0x3fa06542u, 0x3fa09d1bu,
    0x3fa0d506u, 0x3fa10d06u, 0x3fa14518u, 0x3fa17d3eu, 0x3fa1b578u, 0x3fa1edc6u, 0x3fa22627u, 0x3fa25e9bu,
    0x3fa29723u, 0x3fa2cfbfu, 0x3fa3086fu, 0x3fa34132u, 0x3fa37a09u, 0x3fa3b2f4u, 0x3fa3ebf3u, 0x3fa42505u,
    0x3fa45e2cu, 0x3fa49766u, 0x3fa4d0b4u, 0x3fa50a17u, 0x3fa5438du, 0x3fa57d17u, 0x3fa5b6b5u, 0x3fa5f067u,
    0x3fa62a2eu, 0x3fa66408u, 0x3fa69df7u, 0x3fa6d7fau, 0x3fa71211u, 0x3fa74c3cu, 0x3fa7867bu, 0x3fa7c0cfu,
    0x3fa7fb37u, 0x3fa835b4u, 0x3fa87044u, 0x3fa8aaeau, 0x3fa8e5a3u, 0x3fa92071u, 0x3fa95b54u, 0x3fa9964bu,
    0x3fa9d156u, 0x3faa0c76u, 0x3faa47abu, 0x3faa82f4u, 0x3faabe52u, 0x3faaf9c5u, 0x3fab354cu, 0x3fab70e8u,
    0x3fabac99u, 0x3fabe85eu, 0x3fac2439u, 0x3fac6028u, 0x3fac9c2cu, 0x3facd845u, 0x3fad1473u, 0x3fad50b6u,
    0x3fad8d0du, 0x3fadc97au, 0x3fae05fcu, 0x3fae4293u, 0x3fae7f3fu, 0x3faebc00u, 0x3faef8d7u, 0x3faf35c2u,
    0x3faf72c3u, 0x3fafafd9u, 0x3fafed04u, 0x3fb02a44u, 0x3fb0679au, 0x3fb0a505u, 0x3fb0e286u, 0x3fb1201cu,
    0x3fb15dc7u, 0x3fb19b88u, 0x3fb1d95fu, 0x3fb2174bu, 0x3fb2554cu, 0x3fb29363u, 0x3fb2d190u, 0x3fb30fd2u,
    0x3fb34e2au, 0x3fb38c98u, 0x3fb3cb1bu, 0x3fb409b5u, 0x3fb44864u, 0x3fb48728u, 0x3fb4c603u, 0x3fb504f4u,
    0x3fb543fau, 0x3fb58317u, 0x3fb5c249u, 0x3fb60191u, 0x3fb640f0u, 0x3fb68064u, 0x3fb6bfefu, 0x3fb6ff90u,
    0x3fb73f47u, 0x3fb77f14u, 0x3fb7bef7u, 0x3fb7fef0u, 0x3fb83f00u, 0x3fb87f26u, 0x3fb8bf63u, 0x3fb8ffb6u,
    0x3fb9401fu, 0x3fb9809eu, 0x3fb9c134u, 0x3fba01e1u, 0x3fba42a4u, 0x3fba837eu, 0x3fbac46eu, 0x3fbb0575u,
    0x3fbb4692u, 0x3fbb87c6u, 0x3fbbc911u, 0x3fbc0a73u, 0x3fbc4bebu, 0x3fbc8d7au, 0x3fbccf20u, 0x3fbd10ddu,
    0x3fbd52b1u, 0x3fbd949bu, 0x3fbdd69du, 0x3fbe18b5u, 0x3fbe5ae5u, 0x3fbe9d2cu, 0x3fbedf89u, 0x3fbf21feu,
    0x3fbf648au, 0x3fbfa72du, 0x3fbfe9e7u, 0x3fc02cb9u, 0x3fc06fa2u, 0x3fc0b2a2u, 0x3fc0f5b9u, 0x3fc138e8u,
    0x3fc17c2eu, 0x3fc1bf8cu, 0x3fc20301u, 0x3fc2468du, 0x3fc28a31u, 0x3fc2cdedu, 0x3fc311c0u, 0x3fc355abu,
    0x3fc399adu, 0x3fc3ddc7u, 0x3fc421f9u, 0x3fc46643u, 0x3fc4aaa4u, 0x3fc4ef1du, 0x3fc533aeu, 0x3fc57857u,
    0x3fc5bd18u, 0x3fc601f1u, 0x3fc646e1u, 0x3fc68beau, 0x3fc6d10bu, 0x3fc71643u, 0x3fc75b94u, 0x3fc7a0fdu,
    0x3fc7e67eu, 0x3fc82c18u, 0x3fc871c9u, 0x3fc8b793u, 0x3fc8fd76u, 0x3fc94370u, 0x3fc98983u, 0x3fc9cfaeu,
    0x3fca15f2u, 0x3fca5c4eu, 0x3fcaa2c3u, 0x3fcae950u, 0x3fcb2ff6u, 0x3fcb76b4u, 0x3fcbbd8bu, 0x3fcc047bu,
    0x3fcc4b83u, 0x3fcc92a4u, 0x3fccd9deu, 0x3fcd2131u, 0x3fcd689cu, 0x3fcdb020u, 0x3fcdf7beu, 0x3fce3f74u,
    0x3fce8743u, 0x3fcecf2bu, 0x3fcf172cu, 0x3fcf5f47u, 0x3fcfa77au, 0x3fcfefc6u, 0x3fd0382cu, 0x3fd080abu,
    0x3fd0c943u, 0x3fd111f4u, 0x3fd15abfu, 0x3fd1a3a3u, 0x3fd1eca1u, 0x3fd235b7u, 0x3fd27ee8u, 0x3fd2c831u,
    0x3fd31195u, 0x3fd35b12u, 0x3fd3a4a8u, 0x3fd3ee58u, 0x3fd43822u, 0x3fd48205u, 0x3fd4cc02u, 0x3fd51619u,
    0x3fd5604au, 0x3fd5aa94u, 0x3fd5f4f9u, 0x3fd63f77u, 0x3fd68a0fu, 0x3fd6d4c1u, 0x3fd71f8du, 0x3fd76a74u,
    0x3fd7b574u, 0x3fd8008eu, 0x3fd84bc3u, 0x3fd89712u, 0x3fd8e27bu, 0x3fd92dfeu, 0x3fd9799bu, 0x3fd9c553u,
    0x3fda1125u, 0x3fda5d12u, 0x3fdaa919u, 0x3fdaf53bu, 0x3fdb4177u, 0x3fdb8dcdu, 0x3fdbda3eu, 0x3fdc26cau,
    0x3fdc7370u, 0x3fdcc031u, 0x3fdd0d0du, 0x3fdd5a04u, 0x3fdda715u, 0x3fddf441u, 0x3fde4188u, 0x3fde8eeau,
    0x3fdedc67u, 0x3fdf29ffu, 0x3fdf77b2u, 0x3fdfc580u, 0x3fe01369u, 0x3fe0616du, 0x3fe0af8du, 0x3fe0fdc7u,
    0x3fe14c1du, 0x3fe19a8eu, 0x3fe1e91au, 0x3fe237c2u, 0x3fe28685u, 0x3fe2d564u, 0x3fe3245eu, 0x3fe37373u,
    0x3fe3c2a4u, 0x3fe411f1u, 0x3fe46159u, 0x3fe4b0ddu, 0x3fe5007cu, 0x3fe55038u, 0x3fe5a00fu, 0x3fe5f001u,
    0x3fe64010u, 0x3fe6903au, 0x3fe6e081u, 0x3fe730e3u, 0x3fe78162u, 0x3fe7d1fcu, 0x3fe822b2u, 0x3fe87385u,
    0x3fe8c474u, 0x3fe9157fu, 0x3fe966a6u, 0x3fe9b7e9u, 0x3fea0949u, 0x3fea5ac5u, 0x3feaac5du, 0x3feafe12u,
    0x3feb4fe3u, 0x3feba1d0u, 0x3febf3dbu, 0x3fec4601u, 0x3fec9845u, 0x3feceaa5u, 0x3fed3d22u, 0x3fed8fbbu,
    0x3fede271u, 0x3fee3544u, 0x3fee8834u, 0x3feedb41u, 0x3fef2e6au, 0x3fef81b1u, 0x3fefd514u, 0x3ff02895u,
    0x3ff07c32u, 0x3ff0cfedu, 0x3ff123c5u, 0x3ff177bau, 0x3ff1cbcdu, 0x3ff21ffcu, 0x3ff27449u, 0x3ff2c8b3u,
    0x3ff31d3bu, 0x3ff371e0u, 0x3ff3c6a3u, 0x3ff41b83u, 0x3ff47080u, 0x3ff4c59cu, 0x3ff51ad4u, 0x3ff5702bu,
    0x3ff5c59fu, 0x3ff61b31u, 0x3ff670e1u, 0x3ff6c6aeu, 0x3ff71c9au, 0x3ff772a3u, 0x3ff7c8cbu, 0x3ff81f10u,
    0x3ff87573u, 0x3ff8cbf5u, 0x3ff92294u, 0x3ff97952u, 0x3ff9d02eu, 0x3ffa2728u, 0x3ffa7e41u, 0x3ffad578u,
    0x3ffb2ccdu, 0x3ffb8440u, 0x3ffbdbd2u, 0x3ffc3383u, 0x3ffc8b52u, 0x3ffce33fu, 0x3ffd3b4cu, 0x3ffd9377u,
    0x3ffdebc0u, 0x3ffe4428u, 0x3ffe9cb0u, 0x3ffef555u, 0x3fff4e1au, 0x3fffa6feu,
);

// log2(max_power) when max_power, after the bad-input rules, is a power of two 2^L with
// L in [1, 127]; 0 when the range is degenerate (max_power NaN or <= 1); 0xffffffff otherwise
// (a general max_power, handled with log2/exp2).
fn log_roughness_range_log2(max_power: f32) -> u32 {
    let b = bitcast<u32>(max_power);
    if ((b & 0x7fffffffu) > 0x7f800000u || (b >> 31u) != 0u || b <= 0x3f800000u) {
        return 0u;
    }
    if (b >= 0x7f000000u) {
        return 127u; // 2^127 and above, +Inf included
    }
    if ((b & 0x7fffffu) == 0u) {
        return (b >> 23u) - 127u;
    }
    return 0xffffffffu;
}

// Bits of the boundary between codes j and j+1 for max_power = 2^l.
fn log_roughness_boundary_bits(j: u32, l: u32) -> u32 {
    let n = (2u * j + 1u) * l;
    return LOG_ROUGHNESS_BOUNDARY_STEPS[n % 510u] + ((n / 510u) << 23u);
}

// The code of power: nearest to 255·log2(power)/log2(max_power), ties upwards.
fn encode_log_roughness(power: f32, max_power: f32) -> u32 {
    let l = log_roughness_range_log2(max_power);
    let b = bitcast<u32>(power);
    // NaN, negative (sign bit), and everything up to 1.0 encode to 0.
    if (l == 0u || (b & 0x7fffffffu) > 0x7f800000u || (b >> 31u) != 0u || b <= 0x3f800000u) {
        return 0u;
    }
    if (l != 0xffffffffu) {
        // Candidate from log2: its error (3 ULP, or 2^-21 absolute near 1) is far below half a
        // code, so the exact code is the candidate or a neighbour. Positive floats order like
        // their bit patterns: compare with the rounded-up boundaries either side.
        let t = 255.0 * log2(power) / f32(l);
        var k = u32(clamp(floor(t + 0.5), 0.0, 255.0));
        // Far from a boundary (more than 2^-8 codes, 30x the estimate's error) the candidate is
        // the code; only the ~0.8% of powers nearer one look the boundaries up.
        if (abs(fract(t) - 0.5) < 0.00390625) {
            if (k > 0u && b < log_roughness_boundary_bits(k - 1u, l)) {
                k = k - 1u;
            } else if (k < 255u && b >= log_roughness_boundary_bits(k, l)) {
                k = k + 1u;
            }
        }
        return k;
    }
    if (b >= bitcast<u32>(max_power)) {
        return 255u;
    }
    let t = 255.0 * log2(power) / log2(max_power);
    return u32(clamp(floor(t + 0.5), 0.0, 255.0));
}

// The power max_power^(k/255) that code k stands for; codes above 255 decode as 255.
fn decode_log_roughness(code: u32, max_power: f32) -> f32 {
    let k = min(code, 255u);
    let l = log_roughness_range_log2(max_power);
    if (l == 0u) {
        return 1.0;
    }
    if (l != 0xffffffffu) {
        let n = k * l;
        return bitcast<f32>(LOG_ROUGHNESS_EXP2_STEPS[n % 255u] + ((n / 255u) << 23u));
    }
    if (k == 255u) {
        return max_power;
    }
    return exp2(f32(k) * log2(max_power) / 255.0);
}
