// prepass — view- and world-space position rebuild from view distance and frustum rays.
// Rust twin: src/position.rs. Tests: tests/position.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// A full-screen pass interpolates, per pixel, the ray through that pixel scaled so its view
// axis component is 1; position = ray * view distance (from wgsl/linear_depth.wgsl). Rays are
// linear in NDC, so the rasteriser's interpolation of corner rays is exact up to rounding.
// Left-handed view space looks down +z (ray z = +1); right-handed (wgpu, Bevy) down -z
// (ray z = -1, view-space z = -distance).

// Bad input: every result is finite (WGSL lets an implementation assume no NaN or infinity at
// run time). Each float input lane is read from its bits first: NaN -> 0, +-inf -> +-2^40, and
// finite values are clamped to [-2^40, 2^40] (2^40 ≈ 1.1e12, beyond any view distance a
// projection of prepass resolves), so no product or sum below can overflow. The sky sentinel
// of wgsl/linear_depth.wgsl (f32::MAX) therefore rebuilds the point 2^40 along the ray.

// One lane made finite and clamped to [-2^40, 2^40], from its bits.
fn pos_sane(x: f32) -> f32 {
    let bits = bitcast<u32>(x);
    let mag = bits & 0x7fffffffu;
    let big = select(1099511627776.0, -1099511627776.0, (bits & 0x80000000u) != 0u);
    let finite = clamp(select(x, 0.0, mag >= 0x7f800000u), -1099511627776.0, 1099511627776.0);
    return select(finite, big, mag == 0x7f800000u);
}

// pos_sane per lane of a vec2.
fn pos_sane2(v: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(pos_sane(v.x), pos_sane(v.y));
}

// pos_sane per lane of a vec3.
fn pos_sane3(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(pos_sane(v.x), pos_sane(v.y), pos_sane(v.z));
}

// View ray through ndc_xy in a frustum with tan(fov/2) = tan_half_fov (x, y), with z = +1.
// tan_half_fov = (aspect·tan(fov_y/2), tan(fov_y/2)), or (1/m[0][0], 1/m[1][1]) of a perspective
// matrix m: Rust Projection::tan_half_fov(fov_y, aspect) or position::tan_half_fov_of(m).
fn frustum_ray(ndc_xy: vec2<f32>, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(pos_sane2(ndc_xy) * pos_sane2(tan_half_fov), 1.0);
}

// View ray through ndc_xy for right-handed view space (-z forward): z = -1.
fn frustum_ray_rh(ndc_xy: vec2<f32>, tan_half_fov: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(pos_sane2(ndc_xy) * pos_sane2(tan_half_fov), -1.0);
}

// View-space position: the ray times the view distance (2 roundings per component at most).
fn view_position(ray: vec3<f32>, view_z: f32) -> vec3<f32> {
    return pos_sane3(ray) * pos_sane(view_z);
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
    let u = pos_sane2(uv);
    return vec2<f32>(u.x * 2.0 - 1.0, 1.0 - u.y * 2.0);
}

// A view ray rotated into world orientation (view_to_world = the camera's rotation, columns =
// its right, up and back/forward axes). Rotate the corner rays in the vertex stage, not per pixel.
fn world_ray(view_ray: vec3<f32>, view_to_world: mat3x3<f32>) -> vec3<f32> {
    let m = mat3x3<f32>(pos_sane3(view_to_world[0]), pos_sane3(view_to_world[1]),
        pos_sane3(view_to_world[2]));
    return m * pos_sane3(view_ray);
}

// Position relative to the camera, in world orientation: keeps view-space relative precision
// however far the camera is from the world origin. Add the camera position in higher precision
// (or not at all: light in camera-relative space).
fn camera_relative_position(world_ray_dir: vec3<f32>, view_z: f32) -> vec3<f32> {
    return pos_sane3(world_ray_dir) * pos_sane(view_z);
}

// World-space position: camera position + ray * distance. The f32 addition rounds to the ULP
// of the camera's coordinates (about 0.5 mm at 8 km): prefer camera_relative_position far from
// the origin.
fn world_position(world_ray_dir: vec3<f32>, view_z: f32, camera_position: vec3<f32>) -> vec3<f32> {
    return pos_sane3(camera_position) + pos_sane3(world_ray_dir) * pos_sane(view_z);
}
