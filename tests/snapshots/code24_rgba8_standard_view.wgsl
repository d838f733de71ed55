// Composed by prepass::scene from the shipped WGSL files.

// ---- from wgsl/depth24.wgsl ----

// Recover a 24-bit code from the unorm channels a sampler returns. Each channel is rounded back
// to its byte before the bytes are weighted: unrounded, the 65536 weight on r magnifies the
// channel's conversion error (3 ULP in WGSL's unpack4x8unorm, more on some texture units) into
// wrong codes. Exact while every channel is within ±0.49/255 of byte/255.
// Bad input: channels are clamped to [0, 1]; NaN (found from its bits, which finite-math
// optimisation cannot remove) counts as 0.
fn depth24_from_rgb8(rgb: vec3<f32>) -> u32 {
    let is_nan = (bitcast<vec3<u32>>(rgb) & vec3<u32>(0x7fffffffu)) > vec3<u32>(0x7f800000u);
    let c = clamp(select(rgb, vec3<f32>(0.0), is_nan), vec3<f32>(0.0), vec3<f32>(1.0));
    let b = vec3<u32>(round(c * 255.0));
    return (b.x << 16u) | (b.y << 8u) | b.z;
}

// A 24-bit code to the u32 whose bytes an RGBA8 target stores (r = most significant byte,
// alpha = 0). Codes above 2^24 - 1 saturate to 2^24 - 1.
fn pack_depth24(d: u32) -> u32 {
    let c = min(d, 0xffffffu);
    return ((c >> 16u) & 0xffu) | (c & 0xff00u) | ((c & 0xffu) << 16u);
}

// ---- from wgsl/linear_depth.wgsl ----

// +inf, built from bits.
fn ld_positive_inf() -> f32 {
    return bitcast<f32>(0x7f800000u);
}

// numerator / s, with s == 0 (the far plane of an infinite projection) giving +inf.
fn ld_divide_or_inf(numerator: f32, s: f32) -> f32 {
    if (s == 0.0) {
        return ld_positive_inf();
    }
    return numerator / s;
}

// View distance of a 24-bit standard-convention depth code, from per-projection constants
// k = (n·(2^24 - 1), n/f) (Projection::depth24_consts): fewer operations per pixel.
fn view_z_from_depth24_consts(d: u32, k: vec2<f32>) -> f32 {
    let code = min(d, 0xffffffu);
    // Both terms are exact integers or products of them: no cancellation.
    let s = f32(0xffffffu - code) + f32(code) * k.y;
    return ld_divide_or_inf(k.x, s);
}

// ---- from wgsl/position.wgsl ----

// View ray through ndc_xy for right-handed view space (-z forward): z = -1.
fn frustum_ray_rh(ndc_xy: vec2<f32>, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(ndc_xy * tan_half_fov, -1.0);
}

// View-space position: the ray times the view distance (2 roundings per component at most).
fn view_position(ray: vec3<f32>, view_z: f32) -> vec3<f32> {
    return ray * view_z;
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
