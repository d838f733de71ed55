// prepass — view- and world-space position rebuild from view distance and frustum rays.
// Rust twin: src/position.rs. Tests: tests/position.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// A full-screen pass interpolates, per pixel, the ray through that pixel scaled so its view
// axis component is 1; position = ray * view distance (from wgsl/linear_depth.wgsl). Rays are
// linear in NDC, so the rasteriser's interpolation of corner rays is exact up to rounding.
// Left-handed view space looks down +z (ray z = +1); right-handed (wgpu, Bevy) down -z
// (ray z = -1, view-space z = -distance).

// View ray through ndc_xy in a frustum with tan(fov/2) = tan_half_fov (x, y), with z = +1.
fn frustum_ray(ndc_xy: vec2<f32>, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(ndc_xy * tan_half_fov, 1.0);
}

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

// The frustum ray at a full-screen triangle's vertex, for the vertex stage to pass on.
fn fullscreen_triangle_ray(vertex_index: u32, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return frustum_ray(fullscreen_triangle_ndc(vertex_index), tan_half_fov);
}

// The frustum ray at a full-screen triangle's vertex, right-handed (-z forward).
fn fullscreen_triangle_ray_rh(vertex_index: u32, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return frustum_ray_rh(fullscreen_triangle_ndc(vertex_index), tan_half_fov);
}

// wgpu NDC from a texture coordinate (uv y down, NDC y up).
fn ndc_from_uv(uv: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
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

// World-space position: camera position + ray * distance. The f32 addition rounds to the ULP
// of the camera's coordinates (about 0.5 mm at 8 km): prefer camera_relative_position far from
// the origin.
fn world_position(world_ray_dir: vec3<f32>, view_z: f32, camera_position: vec3<f32>) -> vec3<f32> {
    return camera_position + world_ray_dir * view_z;
}
