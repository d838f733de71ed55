// prepass — the light pre-pass factorisation result = C(mp, Σ_i P(l_i, gp)) (Mark Lee,
// "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009) and Engel's specular
// reconstruction (Wolfgang Engel, "Light Pre-Pass: More Blood", blog post, 28 September 2008;
// written up as "Designing a Renderer for Multiple Lights: The Light Pre-Pass Renderer",
// ShaderX7, 2009).
// Rust twin: src/lighting/lpp.rs. Tests: tests/lpp.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// P runs once per light in the light pass and its results are summed by additive blending:
//   one RGBA buffer (Engel): rgb = N·L·att·colour, a = N·L·att·lum(colour)·(N·H)^n
//   two buffers (Resistance 2): diffuse = N·L·att·colour, specular = N·L·att·colour·spec
// C runs in the second geometry pass with the material: albedo·diffuse + gloss·specular, where
// the one-buffer layout first recovers spec = (a / lum(rgb))^m · lum(rgb): N·H^n divided back
// out by the luminance of the diffuse sum, the material exponent m applied on top of the
// light's n. Exact for one white light; an approximation for several (measured in the tests).
//
// Conventions: every direction points away from the surface (to_light = light − surface,
// to_eye = eye − surface) and need not be unit length.
// Bad input (same on both sides): any NaN or ±Inf input, a zero or subnormal-length normal or
// direction gives zero light. Colours are clamped to [0, 65504] (lights never subtract; the fp16
// range of a light buffer), attenuations to [0, 1], powers to [0, 65504]. x^0 is 1 for x > 0,
// and 0^y is 0: a zero N·H gives no highlight.

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
// The power of two that scales a normal m >= 0 into [1, 4): exact, where v / m would divide by a
// number WGSL's / need not handle (beyond 2^126).
fn lpp_scale(m: f32) -> f32 {
    return bitcast<f32>(max(254u - ((bitcast<u32>(m) >> 23u) & 0xffu), 1u) << 23u);
}

fn lpp_direction(v: vec3<f32>) -> vec3<f32> {
    // The bits are judged before abs and max see a NaN or an infinity.
    if (!lpp_finite3(v)) {
        return vec3<f32>(0.0);
    }
    let a = abs(v);
    let m = max(a.x, max(a.y, a.z));
    if (bitcast<u32>(m) < 0x00800000u) {
        return vec3<f32>(0.0);
    }
    let s = v * lpp_scale(m);
    return s * inverseSqrt(dot(s, s));
}

// Luminance (Rec. 709 weights) of a light-buffer colour. Negative channels count (callers clamp
// colours first). Bad input: the result is finite — each channel is read from its bits first,
// NaN -> 0, +-inf -> +-2^126, finite channels clamped to [-2^126, 2^126], so the sum cannot
// overflow (the weights sum to 1).
fn lpp_luminance(rgb: vec3<f32>) -> f32 {
    let bits = bitcast<vec3<u32>>(rgb);
    let mag = bits & vec3<u32>(0x7fffffffu);
    let big = select(vec3<f32>(8.507059e37), vec3<f32>(-8.507059e37),
        (bits & vec3<u32>(0x80000000u)) != vec3<u32>(0u));
    let finite = clamp(select(rgb, vec3<f32>(0.0), mag >= vec3<u32>(0x7f800000u)),
        vec3<f32>(-8.507059e37), vec3<f32>(8.507059e37));
    return dot(select(finite, big, mag == vec3<u32>(0x7f800000u)), LPP_LUMINANCE);
}

// x^y for a cosine x and an exponent y >= 0: clamped to [0, 1], 0 for x <= 0 and when the
// computed y·log2(x) is below -126 (exp2's argument is never below -126, so no subnormal or
// -Inf arrives; a result just under 2^-126 may round up to 2^-126).
// Bad input: x or y NaN (from their bits) → 0, no highlight; y <= 0 acts as 0 (x^0 = 1 for
// x > 0); y = +Inf gives 0 for x < 1.
fn lpp_pow_cosine(x: f32, y: f32) -> f32 {
    // Every test before the exponent reads bits, so no comparison sees a NaN or an infinity:
    // a set sign bit or +0 is x <= 0; a positive x's bits from 1.0 up (+Inf included) are x >= 1.
    let xb = bitcast<u32>(x);
    let yb = bitcast<u32>(y);
    if ((xb & 0x7fffffffu) > 0x7f800000u || (yb & 0x7fffffffu) > 0x7f800000u
        || xb >= 0x80000000u || xb == 0u) {
        return 0.0;
    }
    if (xb >= 0x3f800000u || yb >= 0x80000000u || yb == 0u) {
        return 1.0;
    }
    // No log2 of a subnormal and no product with an infinity: x below 2^-126 or y = +inf give
    // x^y = 0 (x < 1 here); y is capped at 2^100, where t is far below -126 already.
    if (xb < 0x00800000u || yb == 0x7f800000u) {
        return 0.0;
    }
    let t = min(y, 1.2676506e30) * log2(x);
    if (t < -126.0) {
        return 0.0;
    }
    return exp2(t);
}

// Windowed falloff of a point light of radius r: (1 − (d/r)²)², 0 beyond r.
// Bad input: NaN/Inf or r below 2^-126 → 0; d < 0 counts as 0.
fn lpp_point_attenuation(distance: f32, radius: f32) -> f32 {
    // A subnormal radius is below any distance; a divisor beyond 2^126 is scaled by 2^-64 first
    // (WGSL's / is only specified for divisors in [2^-126, 2^126]).
    if (!lpp_finite(distance) || !lpp_finite(radius) || !(radius >= 1.1754944e-38)) {
        return 0.0;
    }
    let big = radius > 8.507059e37;
    let d = select(distance, distance * 5.421011e-20, big);
    let r = select(radius, radius * 5.421011e-20, big);
    // d/r only for d below r (a huge d over a small r would overflow); 1 exactly from r on, so
    // the window closes whatever the division's rounding.
    let x = select(clamp(min(max(d, 0.0), r) / r, 0.0, 1.0), 1.0, d >= r);
    let w = 1.0 - x * x;
    return w * w;
}

// lpp_point_attenuation(|to_light|, radius) with both lengths scaled first by one power of two
// (exact), which takes the larger of max|to_light_i| and radius into [1, 4): |to_light|² then
// neither overflows (an unscaled length() of a vector beyond 2^64 would) nor underflows, and the
// ratio d/r is unchanged. Non-finite input, or a radius below 2^-126, gives 0 (read from bits
// before any float operation; a non-finite to_light gives zero light anyway).
fn lpp_point_falloff(to_light: vec3<f32>, radius: f32) -> f32 {
    if (!lpp_finite3(to_light) || !lpp_finite(radius)) {
        return 0.0;
    }
    if (!(radius >= 1.1754944e-38)) {
        return 0.0;
    }
    let a = abs(to_light);
    let s = lpp_scale(max(max(a.x, a.y), max(a.z, radius)));
    return lpp_point_attenuation(length(to_light * s), radius * s);
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
    // A width below 2^-126 (none included) is a hard edge: no division by a subnormal.
    if (inner - outer < 1.1754944e-38) {
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

// P for the one-buffer layout, Phong: (N·L·att·colour, N·L·att·lum(colour)·(R·V)^power).
fn lpp_phong_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                   colour: vec3<f32>, attenuation: f32, power: f32) -> vec4<f32> {
    return lpp_light(normal, to_eye, to_light, colour, attenuation, power, true);
}

// P of a point light (colour_radius = colour, radius) with Blinn-Phong specular.
fn lpp_point_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                   colour_radius: vec4<f32>, power: f32) -> vec4<f32> {
    let att = lpp_point_falloff(to_light, colour_radius.w);
    return lpp_blinn_phong_light(normal, to_eye, to_light, colour_radius.xyz, att, power);
}

// P of a spot light: a point light times the cone factor. axis_cos_outer = the direction the
// spot points (any length) and the cosine of its outer half-angle.
fn lpp_spot_light(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                  colour_radius: vec4<f32>, axis_cos_outer: vec4<f32>, cos_inner: f32,
                  power: f32) -> vec4<f32> {
    let cos_angle = dot(lpp_direction(axis_cos_outer.xyz), -lpp_direction(to_light));
    let att = lpp_point_falloff(to_light, colour_radius.w) * lpp_spot_attenuation(cos_angle, axis_cos_outer.w, cos_inner);
    return lpp_blinn_phong_light(normal, to_eye, to_light, colour_radius.xyz, att, power);
}

// P for the two-buffer layout's specular target: N·L·att·colour·(N·H)^power (Blinn-Phong); the
// diffuse target is the rgb of lpp_blinn_phong_light.
fn lpp_blinn_phong_specular_rgb(normal: vec3<f32>, to_eye: vec3<f32>, to_light: vec3<f32>,
                                colour: vec3<f32>, attenuation: f32, power: f32) -> vec3<f32> {
    if (!lpp_finite3(colour) || !lpp_finite(attenuation) || !lpp_finite(power)) {
        return vec3<f32>(0.0);
    }
    let c = clamp(colour, vec3<f32>(0.0), vec3<f32>(LPP_COLOUR_MAX));
    let cos = lpp_cosines(normal, to_eye, to_light, false);
    let d = cos.x * clamp(attenuation, 0.0, 1.0);
    return d * lpp_pow_cosine(cos.y, clamp(power, 0.0, LPP_COLOUR_MAX)) * c;
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

// C for the two-buffer layout: albedo·diffuse + gloss·specular (Resistance 2's C = mp·P).
fn lpp_combine_two_buffers(albedo: vec3<f32>, gloss: vec3<f32>, diffuse: vec3<f32>,
                           specular: vec3<f32>) -> vec3<f32> {
    return lpp_clamp_colour(albedo) * lpp_clamp_colour(diffuse)
        + lpp_clamp_colour(gloss) * lpp_clamp_colour(specular);
}

// Clamp to [0, 65504]; NaN and -Inf give 0, +Inf 65504, judged from the bits before the clamp.
fn lpp_clamp_colour(c: vec3<f32>) -> vec3<f32> {
    let bits = bitcast<vec3<u32>>(c);
    let edge = select(vec3<f32>(0.0), vec3<f32>(LPP_COLOUR_MAX), bits == vec3<u32>(0x7f800000u));
    let safe = select(c, edge, (bits & vec3<u32>(0x7fffffffu)) >= vec3<u32>(0x7f800000u));
    return clamp(safe, vec3<f32>(0.0), vec3<f32>(LPP_COLOUR_MAX));
}
