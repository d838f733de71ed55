// Peer baseline (not public API): Unity HDRP's normal buffer (and URP's accurate G-buffer
// normals): octahedral 12:12 in three bytes, from Unity-Technologies/Graphics:
// com.unity.render-pipelines.core/ShaderLibrary/Packing.hlsl (PackNormalOctQuadEncode,
// PackFloat2To888, Unpack888ToFloat2, UnpackNormalOctQuadEncode) and the writer's seam clamp of
// com.unity.render-pipelines.high-definition/Runtime/Material/NormalBuffer.hlsl
// (EncodeIntoNormalBuffer: |z| raised to at least 1/1024, its sign kept by Common.hlsl's CopySign,
// which reads -0 as +), written fresh to be measured beside encode_normal_oct24_unity
// (wgsl/normal_oct.wgsl). rcp() is written as a division.
// Measured by errplot (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

// The seam clamp (z = ±max(|z|, 1/1024), + for z >= 0), L1-normalise (guarded by 1e-6), fold the
// lower half by t = saturate(-z), map to [0, 1], and quantise each axis as u32(f * 4095.5);
// bytes: low 8 bits of u, of v, then both high nibbles.
fn peer_unity_normal_encode(n_in: vec3<f32>) -> u32 {
    let za = max(abs(n_in.z), 1.0 / 1024.0);
    let n = vec3<f32>(n_in.xy, select(-za, za, n_in.z >= 0.0));
    let m = n / max(abs(n.x) + abs(n.y) + abs(n.z), 1e-6);
    let t = saturate(-m.z);
    let o = m.xy + select(vec2<f32>(-t), vec2<f32>(t), m.xy >= vec2<f32>(0.0));
    let i = vec2<u32>(saturate(o * 0.5 + 0.5) * 4095.5);
    return (i.x & 0xffu) | ((i.y & 0xffu) << 8u) | ((i.x >> 8u) << 16u) | ((i.y >> 8u) << 20u);
}

// k / 4095 per axis, back to [-1, 1], unfold by t = max(-z, 0), normalise.
fn peer_unity_normal_decode(p: u32) -> vec3<f32> {
    let k = vec2<u32>((p & 0xffu) | (((p >> 16u) & 0xfu) << 8u), ((p >> 8u) & 0xffu) | (((p >> 20u) & 0xfu) << 8u));
    let f = vec2<f32>(k) / 4095.0 * 2.0 - 1.0;
    let z = 1.0 - abs(f.x) - abs(f.y);
    let t = max(-z, 0.0);
    let xy = f + select(vec2<f32>(t), vec2<f32>(-t), f >= vec2<f32>(0.0));
    return normalize(vec3<f32>(xy, z));
}
