// Peer baseline (not public API): the RGB10A2 world normal of Unreal 5's GBufferA
// (Engine/Shaders/Private/DeferredShadingCommon.ush: EncodeNormal is n * 0.5 + 0.5, DecodeNormal
// is n * 2 - 1 then normalised; the format is set in
// Engine/Source/Runtime/RenderCore/Private/GBufferInfo.cpp), which Bevy's normal prepass also
// stores (an Rgb10a2Unorm target). Written fresh from that description to be measured beside
// wgsl/normal_xyz10.wgsl; the render target's conversion round(1023 c) is written out as
// u32(c * 1023 + 0.5), so the code is the texel the engine would store. Measured by errplot
// (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

// The engine writes n * 0.5 + 0.5 of a unit normal; the format clamps and rounds.
fn peer_unreal_gbuffer_normal_encode(n: vec3<f32>) -> u32 {
    let k = vec3<u32>(saturate(n * 0.5 + 0.5) * 1023.0 + 0.5);
    return k.x | (k.y << 10u) | (k.z << 20u);
}

// The engine samples k / 1023 and decodes normalize(c * 2 - 1).
fn peer_unreal_gbuffer_normal_decode(p: u32) -> vec3<f32> {
    let c = vec3<f32>(vec3<u32>(p, p >> 10u, p >> 20u) & vec3<u32>(0x3ffu)) / 1023.0;
    return normalize(c * 2.0 - 1.0);
}

// Unreal 5 Substrate's top-layer normal (Engine/Shaders/Private/Substrate/Substrate.ush, as
// prepass's engine survey describes it; the file itself was not found to re-read): Unreal's
// UnitVectorToOctahedron (L1-normalise, fold when z <= 0 with the sign of 0 counting as +), then
// per axis trunc(clamp(x * 1023 + 1024, 0, 2047)); u in word bits 10-20 and v in 21-31
// (assumed, as wgsl/normal_substrate.wgsl). Roughness and flags bits left zero.
fn peer_unreal_substrate_normal_encode(n: vec3<f32>) -> u32 {
    var o = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z <= 0.0) {
        o = (vec2<f32>(1.0) - abs(o.yx)) * select(vec2<f32>(-1.0), vec2<f32>(1.0), o >= vec2<f32>(0.0));
    }
    let k = vec2<u32>(clamp(o * 1023.0 + 1024.0, vec2<f32>(0.0), vec2<f32>(2047.0)));
    return (k.x << 10u) | (k.y << 21u);
}

// (k - 1024) / 1023 per axis, then OctahedronToUnitVector: z = 1 - |x| - |y|, unfold by
// t = max(-z, 0), normalise.
fn peer_unreal_substrate_normal_decode(p: u32) -> vec3<f32> {
    let k = vec2<u32>((p >> 10u) & 0x7ffu, p >> 21u);
    let f = (vec2<f32>(k) - vec2<f32>(1024.0)) / 1023.0;
    let z = 1.0 - abs(f.x) - abs(f.y);
    let t = max(-z, 0.0);
    let xy = f + select(vec2<f32>(t), vec2<f32>(-t), f >= vec2<f32>(0.0));
    return normalize(vec3<f32>(xy, z));
}
