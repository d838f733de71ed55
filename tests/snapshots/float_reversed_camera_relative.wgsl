// Composed by prepass::scene from the shipped WGSL files.

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
