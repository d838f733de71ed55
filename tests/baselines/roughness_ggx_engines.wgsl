// Engine baselines (not public API): how engines write and read GGX perceptual roughness in 8
// bits, re-implemented from the descriptions in the project's research notes (engines.md) to be
// run beside wgsl/roughness_ggx.wgsl by tests/roughness_ggx.rs (interoperability and accuracy).

// Bevy 0.19 deferred G-buffer (crates/bevy_pbr/src/deferred/pbr_deferred_types.wgsl and
// pbr_deferred_functions.wgsl): perceptual roughness is byte 3 of a unorm4x8 word packed as
// u32(saturate(v) * 255 + 0.5), read back as f32(byte) / 255.
fn engine_bevy_roughness_write(r: f32) -> u32 {
    return u32(saturate(r) * 255.0 + 0.5);
}

// Bevy's read of that byte.
fn engine_bevy_roughness_read(b: u32) -> f32 {
    return f32(b & 0xffu) / 255.0;
}

// Unreal (GBuffer roughness), Unity HDRP and URP: a float written to a unorm8 render target,
// which the hardware rounds as pack4x8unorm does, floor(0.5 + 255 c) of the clamped channel.
fn engine_unorm8_target_write(r: f32) -> u32 {
    return pack4x8unorm(vec4<f32>(r, 0.0, 0.0, 0.0)) & 0xffu;
}

// A unorm8 texture read of byte b, as unpack4x8unorm gives it.
fn engine_unorm8_target_read(b: u32) -> f32 {
    return unpack4x8unorm(b & 0xffu).x;
}

// Godot 4 Forward+ (servers/rendering/renderer_rd/shaders/forward_clustered/
// scene_forward_clustered.glsl, MODE_RENDER_NORMAL_ROUGHNESS): w = roughness * (127/255), and
// 1 - w for a dynamic object, written to the normal-roughness buffer's unorm8 alpha.
fn engine_godot_roughness_write(r: f32, dynamic_object: u32) -> u32 {
    var w = r * (127.0 / 255.0);
    if (dynamic_object != 0u) {
        w = 1.0 - w;
    }
    return pack4x8unorm(vec4<f32>(w, 0.0, 0.0, 0.0)) & 0xffu;
}

// Godot's normal_roughness_compatibility (forward_clustered/scene_forward_clustered_inc.glsl)
// on the sampled channel c: above 0.5 is dynamic and becomes 1 - c, then c / (127/255).
fn engine_godot_roughness_read(c: f32) -> f32 {
    var roughness = c;
    if (roughness > 0.5) {
        roughness = 1.0 - roughness;
    }
    return roughness / (127.0 / 255.0);
}

// Unity URP's deferred G-buffer (com.unity.render-pipelines.universal/ShaderLibrary/
// UnityGBuffer.hlsl: GBuffer2 = half4(packedNormalWS, smoothness)): the unorm8 alpha holds the
// material's smoothness, 1 - perceptual roughness (core ShaderLibrary/CommonMaterial.hlsl,
// PerceptualRoughnessToPerceptualSmoothness), rounded by the render target.
fn engine_urp_smoothness_write(r: f32) -> u32 {
    return pack4x8unorm(vec4<f32>(1.0 - r, 0.0, 0.0, 0.0)) & 0xffu;
}

// URP's read: the sampled smoothness s = b/255, then PerceptualSmoothnessToPerceptualRoughness,
// 1 - s.
fn engine_urp_smoothness_read(b: u32) -> f32 {
    return 1.0 - f32(b & 0xffu) / 255.0;
}

// Unreal Substrate's roughness byte: PackR8 (Unreal's shader library, as Substrate.ush calls it),
// uint(saturate(Value) * 255.0f): truncated.
fn engine_substrate_roughness_write(r: f32) -> u32 {
    return u32(saturate(r) * 255.0);
}

// Unreal's UnpackR8: float(In & 0xFF) * (1.0f / 255.0f).
fn engine_substrate_roughness_read(b: u32) -> f32 {
    return f32(b & 0xffu) * (1.0 / 255.0);
}
