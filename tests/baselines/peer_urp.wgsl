// Peer baseline (not public API): Unity URP's default normal target, R8G8B8A8_SNorm
// (Packages/com.unity.render-pipelines.universal/Runtime/Passes/DepthNormalOnlyPass.cs): the
// shader writes the unit normal as it is, the format stores round(127 c) and reads back
// max(b / 127, -1), which the shader normalises. Written fresh from that description to be
// measured beside wgsl/normal_snorm8.wgsl; the conversion is written out as
// i32(round(clamp(c, -1, 1) * 127)), so the code is the texel URP would store. Measured by
// errplot (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

fn peer_urp_normal_encode(n: vec3<f32>) -> u32 {
    let b = bitcast<vec3<u32>>(vec3<i32>(round(clamp(n, vec3<f32>(-1.0), vec3<f32>(1.0)) * 127.0))) & vec3<u32>(0xffu);
    return b.x | (b.y << 8u) | (b.z << 16u);
}

fn peer_urp_normal_decode(p: u32) -> vec3<f32> {
    let b = bitcast<vec3<i32>>(vec3<u32>(p << 24u, p << 16u, p << 8u)) >> vec3<u32>(24u);
    return normalize(max(vec3<f32>(b) / 127.0, vec3<f32>(-1.0)));
}
