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
