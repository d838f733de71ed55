//! The frame's WGSL: `Scene::wgsl()` (exactly the crate functions the layout's choices reach)
//! followed by this example's entry points, generated for the layout (which G-buffer targets
//! exist, how they decode) and the MSAA count (per-sample reads when multisampled).

use super::{Config, Storage};
use prepass::projection::DepthConvention;
use prepass::scene::{DepthStorage, LightBuffers, NormalEncoding, RoughnessChoice};

/// Whether the encoding leaves alpha free for the roughness code (as `Scene::gbuffer` lays it out).
pub fn alpha_free(e: NormalEncoding) -> bool {
    matches!(
        e,
        NormalEncoding::Xyz8
            | NormalEncoding::Xyz8Best
            | NormalEncoding::Oct24
            | NormalEncoding::Hemioct24
            | NormalEncoding::Oct24Unity
    )
}

/// Whether the layout stores the roughness code in a target of its own (`r8unorm`): where the
/// normal's target has no free alpha, and the Substrate word does not carry the byte itself.
pub fn roughness_target(e: NormalEncoding) -> bool {
    !alpha_free(e) && e != NormalEncoding::Substrate
}

/// The stem of the encoding's WGSL functions (`encode_normal_{stem}_unorm`; `_snorm` for snorm8).
pub fn stem(e: NormalEncoding) -> &'static str {
    match e {
        NormalEncoding::Xyz8 => "xyz8",
        NormalEncoding::Xyz8Best => "xyz8_best",
        NormalEncoding::Xyz10 => "xyz10",
        NormalEncoding::Oct20 => "oct20",
        NormalEncoding::Snorm8 => "snorm8",
        NormalEncoding::Oct24Unity => "oct24_unity",
        NormalEncoding::XyFp16 => "xy_fp16",
        NormalEncoding::Oct16 => "oct16",
        NormalEncoding::Oct24 => "oct24",
        NormalEncoding::Oct32 => "oct32",
        NormalEncoding::Hemioct24 => "hemioct24",
        NormalEncoding::Substrate => "substrate",
        NormalEncoding::SignedOct => "signed_oct",
    }
}

/// [`stem`] with its render-target suffix: the name tail of the `_unorm` (or `_snorm`) forms.
fn rt_stem(e: NormalEncoding) -> String {
    let format = if e == NormalEncoding::Snorm8 {
        "snorm"
    } else {
        "unorm"
    };
    format!("{}_{format}", stem(e))
}

/// [`rt_stem`] of the decoder: the best fit is read by xyz8's decoder.
fn rt_dec_stem(e: NormalEncoding) -> String {
    if e == NormalEncoding::Xyz8Best {
        rt_stem(NormalEncoding::Xyz8)
    } else {
        rt_stem(e)
    }
}

const COMMON: &str = r#"
// ---- light_prepass example: shared declarations ----
struct Frame {
    view: mat4x4<f32>,
    proj: mat4x4<f32>,
    tan_half_fov: vec2<f32>,
    size: vec2<f32>,
    depth_k: vec4<f32>,
    near: f32,
    far: f32,
    reversed: u32,
    max_power: f32,
    bounds_on: u32,
    count: u32,
    pad1: u32,
    pad2: u32,
};
struct Material {
    albedo_power: vec4<f32>,
    gloss_m: vec4<f32>,
    bump: vec4<f32>,
};
// View space: pos_radius = (position, radius or range), colour_kind = (rgb, 0 point / 1 spot),
// axis_cos_outer = (unit axis, cos outer), extra = (cos inner, sphere mesh scale, cone mesh tan, 0).
struct LightGpu {
    pos_radius: vec4<f32>,
    colour_kind: vec4<f32>,
    axis_cos_outer: vec4<f32>,
    extra: vec4<f32>,
};
struct Counters {
    shaded: atomic<u32>,
    rejected: atomic<u32>,
    sky: atomic<u32>,
    pad: atomic<u32>,
};
@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var<storage, read> materials: array<Material>;
@group(0) @binding(2) var<storage, read> lights: array<LightGpu>;
@group(0) @binding(3) var<storage, read_write> counters: Counters;

struct GeoOut {
    @builtin(position) @invariant clip: vec4<f32>,
    @location(0) world_normal: vec3<f32>,
    @location(1) world_pos: vec3<f32>,
    @location(2) @interpolate(flat) material: u32,
};

// Geometry for the G-buffer pass and the composite pass: the same function in both, and the
// position invariant, so the composite's depth test `equal` finds the G-buffer's depth.
@vertex fn geo_vs(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
                  @location(2) material: u32) -> GeoOut {
    var o: GeoOut;
    o.clip = frame.proj * (frame.view * vec4<f32>(position, 1.0));
    o.world_normal = normal;
    o.world_pos = position;
    o.material = material;
    return o;
}

// WGSL specifies sin and cos (2^-11 absolute) on [-pi, pi] only: beyond it any result
// conforms. Reduce by 2pi first; the clamp keeps a rounding at the edge inside.
fn wrap_pi(x: f32) -> f32 {
    let tau = 6.2831855;
    return clamp(x - tau * round(x / tau), -3.1415925, 3.1415925);
}

// View-space shading normal; the ground is normal-mapped with the height field
// a·sin(f x)·sin(f z), whose slopes tilt normals past the view direction (z < 0 in view space).
fn shading_normal(in: GeoOut) -> vec3<f32> {
    let m = materials[in.material];
    var n = normalize(in.world_normal);
    if (m.bump.x > 0.0) {
        let a = m.bump.x;
        let f = m.bump.y;
        let p = in.world_pos;
        let u = wrap_pi(f * p.x);
        let v = wrap_pi(f * p.z);
        let dx = a * f * cos(u) * sin(v);
        let dz = a * f * sin(u) * cos(v);
        n = normalize(vec3<f32>(-dx, 1.0, -dz));
    }
    return normalize((frame.view * vec4<f32>(n, 0.0)).xyz);
}

struct LightOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) light: u32,
    @location(1) @interpolate(flat) bounds: BOUNDS_T,
};

// A sphere light's volume: the unit icosphere scaled by extra.y (radius / inradius).
@vertex fn sphere_vs(@location(0) p: vec3<f32>, @builtin(instance_index) i: u32) -> LightOut {
    let l = lights[i];
    let v = l.pos_radius.xyz + p * l.extra.y;
    return LightOut(frame.proj * vec4<f32>(v, 1.0), i, light_bounds(l));
}

// A spot light's volume: the unit cone (apex at 0, cap at z = 1, radius 1) along the axis,
// length = range, cap radius = range·extra.z.
@vertex fn cone_vs(@location(0) p: vec3<f32>, @builtin(instance_index) i: u32) -> LightOut {
    let l = lights[i];
    let d = l.axis_cos_outer.xyz;
    let up = select(vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(1.0, 0.0, 0.0), abs(d.y) > 0.9);
    let t = normalize(cross(up, d));
    let b = cross(d, t);
    let h = l.pos_radius.w;
    let v = l.pos_radius.xyz + d * (p.z * h) + (t * p.x + b * p.y) * (h * l.extra.z);
    return LightOut(frame.proj * vec4<f32>(v, 1.0), i, light_bounds(l));
}
"#;

// The GGX forms store the material's power as perceptual roughness r (α = r²) by the exact
// inverse of the Blinn-Phong exponent the lighting takes back, 2/α² − 2 (Walter et al. 2007).
const GGX: &str = r#"
// ---- light_prepass example: specular power <-> GGX perceptual roughness ----
// r of power p: α = sqrt(2/(p + 2)), r = sqrt(α).
fn ggx_r_from_power(p: f32) -> f32 {
    return sqrt(sqrt(2.0 / (p + 2.0)));
}

// The power 2/α² − 2 of α for the Blinn-Phong lighting, at most frame.max_power: α² is raised
// to the cap's 2/(max_power + 2) before the division, so a roughness byte 0 (α = 0) divides by
// no zero (an infinity is outside WGSL's finite-math rule); the scene's powers 4–384 stay far
// below the cap.
fn power_from_ggx_alpha(a: f32) -> f32 {
    return 2.0 / max(a * a, 2.0 / (frame.max_power + 2.0)) - 2.0;
}
"#;

/// The roughness form's name in pass (a)'s comment, pass (a)'s lines from the material's power
/// to `code` (the byte both the fat and the diet G-buffer store; for Substrate `r` alone, the
/// word's encoder takes it), and the light pass's lines from `code` to `power`.
fn roughness_code(cfg: &Config) -> (&'static str, String, String) {
    let m = "materials[in.material].albedo_power.w";
    let substrate = matches!(
        cfg.storage,
        Storage::Diet {
            normal: NormalEncoding::Substrate,
            ..
        }
    );
    let ggx = |encoder: &str, decode: &str| {
        let mut e = format!("    let r = ggx_r_from_power({m});\n");
        if !substrate {
            e.push_str(&format!("    let code = {encoder};\n"));
        }
        ("GGX", e, decode.to_string())
    };
    match cfg.roughness {
        RoughnessChoice::None | RoughnessChoice::Log8 => (
            "log",
            format!("    let code = encode_log_roughness({m}, frame.max_power);\n"),
            "    let power = decode_log_roughness(code, frame.max_power);\n".into(),
        ),
        RoughnessChoice::Ggx8 => ggx(
            "encode_roughness_ggx8(r)",
            "    let power = power_from_ggx_alpha(decode_roughness_ggx8_alpha(code));\n",
        ),
        RoughnessChoice::Ggx8Log => ggx(
            "encode_roughness_ggx8_log(r)",
            "    let power = power_from_ggx_alpha(decode_roughness_ggx8_log_alpha(code));\n",
        ),
        // Godot's dynamic-object flag: 0, the scene is static. Its decoder gives r: α = r².
        RoughnessChoice::Godot8 => ggx(
            "encode_roughness_godot8(r, 0u)",
            "    let rg = decode_roughness_godot8(code);\n    \
             let power = power_from_ggx_alpha(rg * rg);\n",
        ),
    }
}

/// The whole module for `cfg`: the composed crate WGSL, then the entry points.
pub fn module(cfg: &Config, crate_wgsl: &str) -> String {
    let ms = cfg.msaa > 1;
    let s_arg = if ms { "s" } else { "0" };
    let sample_param = if ms {
        ", @builtin(sample_index) s: u32"
    } else {
        ""
    };
    let tex = if ms {
        "texture_multisampled_2d<f32>"
    } else {
        "texture_2d<f32>"
    };
    let depth_tex = if ms {
        "texture_depth_multisampled_2d"
    } else {
        "texture_depth_2d"
    };
    let reversed = cfg.convention == DepthConvention::Reversed;
    let view_z_float = if reversed {
        "view_z_from_reversed_depth_consts"
    } else {
        "view_z_from_depth_consts"
    };
    let mut w = String::new();
    w.push_str(crate_wgsl);
    let bounds_t = match cfg.storage {
        Storage::Diet {
            depth: DepthStorage::Code24Rgba8,
            ..
        } => "vec2<u32>",
        _ => "vec2<f32>",
    };
    w.push_str(&COMMON.replace("BOUNDS_T", bounds_t));
    if cfg.roughness != RoughnessChoice::Log8 {
        w.push_str(GGX);
    }

    // ---- depth bounds of a light (its sphere: a spot's apex and range) ----
    let bounds_fn = match cfg.storage {
        Storage::Fat => "let c = -l.pos_radius.z;\n    let r = l.pos_radius.w;\n    \
             return vec2<f32>((c - r) * (1.0 - 1e-5), (c + r) * (1.0 + 1e-5));"
            .to_string(),
        Storage::Diet { depth, .. } => {
            let f = if depth == DepthStorage::Code24Rgba8 {
                "light_volume_sphere_depth_bounds24"
            } else {
                "light_volume_sphere_depth_bounds"
            };
            format!(
                "return {f}(-l.pos_radius.z, l.pos_radius.w, frame.near, frame.far, frame.reversed);"
            )
        }
    };
    w.push_str(&format!(
        "\n// The depth-bounds range of a light's sphere (view depth for the fat layout).\n\
         fn light_bounds(l: LightGpu) -> {bounds_t} {{\n    {bounds_fn}\n}}\n"
    ));

    // ---- pass (a): G-buffer ----
    let mut gout = String::from("struct GOut {\n");
    let mut gbody = String::new();
    let mut bindings = String::new(); // light pass, group 1
    let mut read = String::new(); // light pass: vz, sky, inside
    let mut read_normal = String::new(); // light pass: n, power
    match cfg.storage {
        Storage::Fat => {
            gout.push_str(
                "    @location(0) normal: vec4<f32>,\n    @location(1) view_z: vec4<f32>,\n",
            );
            gbody.push_str(&format!(
                "    o.normal = vec4<f32>(n, f32(code));\n    \
                 o.view_z = vec4<f32>({view_z_float}(in.clip.z, frame.depth_k.xyz), 0.0, 0.0, 0.0);\n"
            ));
            bindings.push_str(&format!(
                "@group(1) @binding(0) var g_normal: {tex};\n@group(1) @binding(1) var g_view_z: {tex};\n"
            ));
            read.push_str(&format!(
                "    let vz = textureLoad(g_view_z, px, {s_arg}).x;\n    \
                 let sky = !(vz > 0.0);\n    \
                 let inside = vz >= in.bounds.x && vz <= in.bounds.y;\n"
            ));
            read_normal.push_str(&format!(
                "    let t = textureLoad(g_normal, px, {s_arg});\n    \
                 let n = t.xyz;\n    let code = u32(t.w);\n"
            ));
        }
        Storage::Diet { normal, depth } => {
            let st = rt_stem(normal);
            let oct16 = normal == NormalEncoding::Oct16;
            let substrate = normal == NormalEncoding::Substrate;
            let free = alpha_free(normal);
            if substrate {
                // An r32uint target: the word, its roughness byte included (flags 0).
                gout.push_str("    @location(0) normal: u32,\n");
                gbody.push_str("    o.normal = encode_substrate_word(n, r, 0u);\n");
                bindings.push_str(&format!(
                    "@group(1) @binding(0) var g_normal: {};\n",
                    tex.replace("<f32>", "<u32>")
                ));
            } else {
                gout.push_str("    @location(0) normal: vec4<f32>,\n");
                if oct16 {
                    gbody.push_str(&format!(
                        "    o.normal = vec4<f32>(encode_normal_{st}(n), 0.0, 0.0);\n"
                    ));
                } else if free {
                    gbody.push_str(&format!(
                        "    o.normal = vec4<f32>(encode_normal_{st}(n).xyz, f32(code) / 255.0);\n"
                    ));
                } else {
                    gbody.push_str(&format!("    o.normal = encode_normal_{st}(n);\n"));
                }
                bindings.push_str(&format!("@group(1) @binding(0) var g_normal: {tex};\n"));
            }
            let mut loc = 1;
            match depth {
                DepthStorage::Code24Rgba8 => {
                    gout.push_str(&format!("    @location({loc}) depth: vec4<f32>,\n"));
                    loc += 1;
                    gbody.push_str(
                        "    let d24 = u32(round(clamp(in.clip.z, 0.0, 1.0) * 16777215.0));\n    \
                         o.depth = unpack4x8unorm(pack_depth24(d24));\n",
                    );
                    bindings.push_str(&format!("@group(1) @binding(1) var g_depth: {tex};\n"));
                    let vz = if reversed {
                        "view_z_from_reversed_depth_consts(hyperbolic_depth_from_depth24(code24), frame.depth_k.xyz)"
                    } else {
                        "view_z_from_depth24_consts(code24, frame.depth_k.xy)"
                    };
                    let sky = if reversed {
                        "code24 == 0u"
                    } else {
                        "code24 == 0xffffffu"
                    };
                    read.push_str(&format!(
                        "    let code24 = depth24_from_rgb8(textureLoad(g_depth, px, {s_arg}).rgb);\n    \
                         let sky = {sky};\n    let vz = {vz};\n    \
                         let inside = code24 >= in.bounds.x && code24 <= in.bounds.y;\n"
                    ));
                }
                _ => {
                    bindings.push_str(&format!(
                        "@group(1) @binding(1) var g_depth: {depth_tex};\n"
                    ));
                    let sky = if reversed { "z <= 0.0" } else { "z >= 1.0" };
                    read.push_str(&format!(
                        "    let z = textureLoad(g_depth, px, {s_arg});\n    \
                         let sky = {sky};\n    let vz = {view_z_float}(z, frame.depth_k.xyz);\n    \
                         let inside = z >= in.bounds.x && z <= in.bounds.y;\n"
                    ));
                }
            }
            let arg = if oct16 { "t.xy" } else { "t" };
            let dst = rt_dec_stem(normal);
            if substrate {
                // Bits 2–9 of the word: the roughness byte (decode_substrate_roughness's b).
                read_normal.push_str(&format!(
                    "    let word = textureLoad(g_normal, px, {s_arg}).r;\n    \
                     let n = decode_substrate_normal(word);\n    \
                     let code = (word >> 2u) & 0xffu;\n"
                ));
            } else {
                read_normal.push_str(&format!(
                    "    let t = textureLoad(g_normal, px, {s_arg});\n    \
                     let n = decode_normal_{dst}({arg});\n"
                ));
            }
            if free {
                read_normal.push_str("    let code = u32(round(clamp(t.a, 0.0, 1.0) * 255.0));\n");
            } else if roughness_target(normal) {
                gout.push_str(&format!("    @location({loc}) rough: vec4<f32>,\n"));
                gbody.push_str("    o.rough = vec4<f32>(f32(code) / 255.0, 0.0, 0.0, 0.0);\n");
                bindings.push_str(&format!("@group(1) @binding(2) var g_rough: {tex};\n"));
                read_normal.push_str(&format!(
                    "    let code = u32(round(clamp(textureLoad(g_rough, px, {s_arg}).r, 0.0, 1.0) * 255.0));\n"
                ));
            }
        }
    }
    gout.push_str("};\n");
    let (kind, encode, decode) = roughness_code(cfg);
    w.push_str(&format!(
        "\n// ---- pass (a): depth, normal and {kind} roughness into the G-buffer ----\n{gout}\
         @fragment fn gbuffer_fs(in: GeoOut) -> GOut {{\n    \
         let n = shading_normal(in);\n{encode}    \
         var o: GOut;\n{gbody}    return o;\n}}\n"
    ));

    // ---- pass (b): light volumes ----
    let (lout, ret) = match cfg.lights_layout {
        LightBuffers::One => (
            "struct LOut {\n    @location(0) light: vec4<f32>,\n};\n",
            "    return LOut(c);\n",
        ),
        LightBuffers::Two => (
            "struct LOut {\n    @location(0) diffuse: vec4<f32>,\n    @location(1) specular: vec4<f32>,\n};\n",
            "    let spec = lpp_blinn_phong_specular_rgb(n, to_eye, to_light, l.colour_kind.xyz, att, power);\n    \
             return LOut(vec4<f32>(c.rgb, 0.0), vec4<f32>(spec, 0.0));\n",
        ),
    };
    w.push_str(&format!(
        "\n// ---- pass (b): light volumes, additive into the light buffer(s) ----\n{bindings}{lout}\
         @fragment fn light_fs(in: LightOut{sample_param}) -> LOut {{\n    \
         if (frame.count != 0u) {{ atomicAdd(&counters.shaded, 1u); }}\n    \
         let px = vec2<i32>(floor(in.clip.xy));\n{read}    \
         // No geometry (the sky of an infinite projection): nothing to light.\n    \
         if (sky) {{\n        if (frame.count != 0u) {{ atomicAdd(&counters.sky, 1u); }}\n        discard;\n    }}\n    \
         // Depth bounds: WebGPU has no depth-bounds test, so the fragment rejects pixels\n    \
         // whose stored depth lies outside the light sphere's depth range.\n    \
         if (frame.bounds_on != 0u && !inside) {{\n        if (frame.count != 0u) {{ atomicAdd(&counters.rejected, 1u); }}\n        discard;\n    }}\n\
         {read_normal}{decode}    \
         let uv = in.clip.xy / frame.size;\n    \
         let ray = frustum_ray_rh(vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0), frame.tan_half_fov);\n    \
         let p = view_position(ray, vz);\n    \
         let l = lights[in.light];\n    \
         let to_light = l.pos_radius.xyz - p;\n    \
         let to_eye = -p;\n    \
         let colour_radius = vec4<f32>(l.colour_kind.xyz, l.pos_radius.w);\n    \
         var c: vec4<f32>;\n    var att: f32;\n    \
         if (l.colour_kind.w < 0.5) {{\n        \
         c = lpp_point_light(n, to_eye, to_light, colour_radius, power);\n        \
         att = lpp_point_attenuation(length(to_light), l.pos_radius.w);\n    \
         }} else {{\n        \
         c = lpp_spot_light(n, to_eye, to_light, colour_radius, l.axis_cos_outer, l.extra.x, power);\n        \
         let cos_angle = dot(lpp_direction(l.axis_cos_outer.xyz), -lpp_direction(to_light));\n        \
         att = lpp_point_attenuation(length(to_light), l.pos_radius.w)\n            \
         * lpp_spot_attenuation(cos_angle, l.axis_cos_outer.w, l.extra.x);\n    }}\n{ret}}}\n"
    ));

    // ---- pass (c): composite ----
    let (cbind, combine) = match cfg.lights_layout {
        LightBuffers::One => (
            format!("@group(2) @binding(0) var l_light: {tex};\n"),
            format!(
                "lpp_combine(m.albedo_power.rgb, m.gloss_m.rgb, textureLoad(l_light, px, {s_arg}), m.gloss_m.w)"
            ),
        ),
        LightBuffers::Two => (
            format!(
                "@group(2) @binding(0) var l_diffuse: {tex};\n@group(2) @binding(1) var l_specular: {tex};\n"
            ),
            format!(
                "lpp_combine_two_buffers(m.albedo_power.rgb, m.gloss_m.rgb, \
                 textureLoad(l_diffuse, px, {s_arg}).rgb, textureLoad(l_specular, px, {s_arg}).rgb)"
            ),
        ),
    };
    w.push_str(&format!(
        "\n// ---- pass (c): the second geometry pass combines light and material ----\n{cbind}\
         const AMBIENT = {ambient:?};\n\
         @fragment fn composite_fs(in: GeoOut{sample_param}) -> @location(0) vec4<f32> {{\n    \
         let px = vec2<i32>(floor(in.clip.xy));\n    \
         let m = materials[in.material];\n    \
         let c = {combine};\n    \
         return vec4<f32>(c + AMBIENT * m.albedo_power.rgb, 1.0);\n}}\n",
        ambient = super::AMBIENT
    ));
    w
}
