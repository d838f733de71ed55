// Peer baseline (not public API): O3DE's signed octahedron normal in an RGB10A2 texel
// (Gems/Atom/RPI/Assets/ShaderLib/Atom/RPI/Math.azsli: EncodeNormalSignedOctahedron and
// DecodeNormalSignedOctahedron, "Store in a 10/10/10/2 texture", after John White's 2017 "signed
// octahedron normal encoding"). Written fresh from that description to be measured beside
// wgsl/normal_signed_oct.wgsl. The render target's conversion is written out as
// round(1023 saturate(c)) (round to nearest, ties to even: what Vulkan recommends, and what
// lavapipe's write gives), so the u32 is the texel the engine would store: R in bits 0-9, G in
// 10-19, B in 20-29 (1023 for z > 0, 0 for z <= 0), A (bits 30-31) zero. Measured by errplot
// (src/bin/errplot/peers.rs), tests/errplot_peers.rs and tests/normal_signed_oct.rs.

// O3DE's encoder, channel values before the write: n / |n|_1, then
// G0 = y/2 + 1/2, R = x/2 + G0, G = -x/2 + G0, B = saturate(z * FLT_MAX).
fn peer_o3de_signed_oct_channels(n: vec3<f32>) -> vec3<f32> {
    let m = n / (abs(n.x) + abs(n.y) + abs(n.z));
    let g0 = m.y * 0.5 + 0.5;
    return vec3<f32>(m.x * 0.5 + g0, m.x * -0.5 + g0, saturate(m.z * 3.402823466e+38));
}

// The encoder's channels through the rgb10a2unorm write: the texel word.
fn peer_o3de_signed_oct_encode(n: vec3<f32>) -> u32 {
    let k = vec3<u32>(round(saturate(peer_o3de_signed_oct_channels(n)) * 1023.0));
    return k.x | (k.y << 10u) | (k.z << 20u);
}

// O3DE's decoder on sampled channels c: x = R - G, y = (R + G) - 1,
// z = (2B - 1)(1 - |x| - |y|), normalised.
fn peer_o3de_signed_oct_decode_channels(c: vec3<f32>) -> vec3<f32> {
    let x = c.x - c.y;
    let y = (c.x + c.y) - 1.0;
    let z = (c.z * 2.0 - 1.0) * (1.0 - abs(x) - abs(y));
    return normalize(vec3<f32>(x, y, z));
}

// The texel sampled (each 10-bit field k as k / 1023), then O3DE's decoder.
fn peer_o3de_signed_oct_decode(p: u32) -> vec3<f32> {
    let c = vec3<f32>(vec3<u32>(p, p >> 10u, p >> 20u) & vec3<u32>(0x3ffu)) / 1023.0;
    return peer_o3de_signed_oct_decode_channels(c);
}
