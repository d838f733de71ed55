// deferred_minimal: a geometry pass (oct24 normal + material id, D32F reversed-Z depth) and one
// full-screen lighting pass. main.rs appends this file to `Scene::wgsl()`, which supplies
// encode/decode_normal_oct24_unorm, view_z_from_depth_uniform, fullscreen_triangle_ray_rh and
// view_position. Conventions (right-handed view space, -z forward; view distance vz > 0):
// README.md, "Conventions".
// Lighting is done in view space: the rebuilt positions and the G-buffer normals live there,
// so the CPU moves the two lights into view space once instead of every pixel moving to world.

// One uniform for both passes; main.rs writes it field by field in this order.
struct Frame {
    view: mat4x4<f32>,       // world -> view, rigid (rotation + translation only)
    proj: mat4x4<f32>,       // Projection::perspective_rh: reversed-Z, infinite far
    depth: vec4<f32>,        // Projection::depth_uniform().to_wgsl()
    tan_half_fov: vec4<f32>, // xy: Projection::tan_half_fov
    sun_dir: vec4<f32>,      // view space, unit, towards the sun
    sun_colour: vec4<f32>,
    point: vec4<f32>,        // view-space position, w = radius
    point_colour: vec4<f32>,
    up: vec4<f32>,           // world up in view space, for the sky's ambient light
    sky: vec4<f32>,          // linear rgb
}

@group(0) @binding(0) var<uniform> frame: Frame;
// The D32F depth buffer, bound as an unfilterable float texture rather than texture_depth_2d:
// naga's GLSL backend (wgpu on GLES / WebGL2) cannot textureLoad a depth texture.
@group(0) @binding(1) var depth_tex: texture_2d<f32>;
@group(0) @binding(2) var gbuffer: texture_2d<f32>;

// Indexed by the material id stored in the G-buffer's alpha (oct24 leaves it free).
const ALBEDO = array<vec3<f32>, 3>(
    vec3(0.32, 0.32, 0.30), // 0: ground
    vec3(0.70, 0.12, 0.08), // 1: red
    vec3(0.10, 0.30, 0.75), // 2: blue
);
const SHININESS = array<f32, 3>(8.0, 64.0, 256.0);

// ---- geometry pass ----

struct GeometryOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) @interpolate(flat) material: f32,
}

@vertex
fn geometry_vs(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
               @location(2) material: f32) -> GeometryOut {
    var out: GeometryOut;
    out.clip = frame.proj * frame.view * vec4(position, 1.0);
    // A rigid view matrix carries normals as it carries directions (w = 0); no inverse-transpose.
    out.normal = (frame.view * vec4(normal, 0.0)).xyz;
    out.material = material;
    return out;
}

@fragment
fn geometry_fs(in: GeometryOut) -> @location(0) vec4<f32> {
    // The encoder is scale-free: the interpolated (shorter than unit) normal needs no normalize.
    let n = encode_normal_oct24_unorm(in.normal);
    return vec4(n.rgb, in.material / 255.0);
}

// ---- lighting pass ----

struct LightingIn {
    @builtin(position) pixel: vec4<f32>,
    // The frustum ray scaled to z = -1, so position = ray * view distance. It is linear in NDC,
    // so the rasteriser interpolates it exactly across the one full-screen triangle.
    @location(0) ray: vec3<f32>,
}

@vertex
fn lighting_vs(@builtin(vertex_index) i: u32) -> LightingIn {
    return LightingIn(vec4(fullscreen_triangle_ndc(i), 0.0, 1.0),
                      fullscreen_triangle_ray_rh(i, frame.tan_half_fov.xy));
}

@fragment
fn lighting_fs(in: LightingIn) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(in.pixel.xy);
    // Infinite far: the cleared depth 0 is "infinitely far", and the decoder says so with the
    // sky sentinel rather than an infinity (WGSL may assume none exist).
    let vz = view_z_from_depth_uniform(textureLoad(depth_tex, texel, 0).r, frame.depth);
    if (vz >= VIEW_Z_SKY) {
        return vec4(frame.sky.rgb, 1.0);
    }
    let p = view_position(in.ray, vz);
    let g = textureLoad(gbuffer, texel, 0);
    // The decoder rounds the unorm channels back to bytes, so the code survives the load exactly.
    let n = decode_normal_oct24_unorm(g);
    let m = u32(round(g.a * 255.0));
    let v = normalize(-p); // towards the camera, at the view-space origin

    let to_point = frame.point.xyz - p;
    let d = length(to_point);
    // Windowed inverse square: exactly 0 at the radius, so the light could be culled beyond it.
    let window = saturate(1.0 - (d * d) / (frame.point.w * frame.point.w));
    let falloff = window * window / (1.0 + d * d);

    let sun = blinn_phong(n, frame.sun_dir.xyz, v, m) * frame.sun_colour.rgb;
    let point = blinn_phong(n, to_point / d, v, m) * falloff * frame.point_colour.rgb;
    // Hemisphere ambient: sky colour from above, a little ground bounce from below.
    let sky_weight = 0.5 + 0.5 * dot(n, frame.up.xyz);
    let ambient = mix(vec3(0.04, 0.035, 0.03), 0.5 * frame.sky.rgb, sky_weight);
    let lit = ALBEDO[m] * ambient + sun + point;
    // Distance fog into the sky colour hides the ground's far edge at the horizon.
    return vec4(mix(frame.sky.rgb, lit, exp(-0.015 * vz)), 1.0);
}

// Lambert diffuse plus a Blinn-Phong highlight normalised by (s + 8) / 8π, so shininess narrows
// it without dimming it, at a dielectric's 4% reflectance. Both terms are scaled by π: a light's
// colour is what a white surface facing it reflects.
fn blinn_phong(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, m: u32) -> vec3<f32> {
    let n_dot_l = dot(n, l);
    if (n_dot_l <= 0.0) {
        return vec3(0.0);
    }
    let s = SHININESS[m];
    let specular = 0.04 * (s + 8.0) / 8.0 * pow(max(dot(n, normalize(l + v)), 0.0), s);
    return (ALBEDO[m] + specular) * n_dot_l;
}
