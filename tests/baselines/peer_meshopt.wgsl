// Peer baseline (not public API): meshoptimizer's octahedral vertex filter (encode and its
// scalar decode) at K = 8, 12 and 16 bits per component, written fresh from the description in
// the project's research notes (peers.md) to be measured beside wgsl/normal_oct.wgsl.
// Layout here: the two K-bit two's-complement codes in the low and high 16 bits of a u32 (the
// filter stores them as int8 or int16 lanes). The decode returns the snorm8 (K = 8) or snorm16
// (K > 8) integers it stores, read back as snorm (int / 127 or int / 32767).
// Measured by errplot (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

// int(x ± 0.5) with the sign of x: rounding half away from zero by truncation.
fn peer_meshopt_round(x: f32) -> i32 {
    return i32(x + select(-0.5, 0.5, x >= 0.0));
}

// Encode with K bits per component: s = 1/|v|_1 (0 for the zero vector), fold when z < 0 with
// the sign of x >= 0, quantise clamp(c, -1, 1)·(2^(K-1) - 1) rounding half away from zero.
fn peer_meshopt_oct_encode(v: vec3<f32>, k: u32) -> u32 {
    let l1 = abs(v.x) + abs(v.y) + abs(v.z);
    let s = select(1.0 / l1, 0.0, l1 == 0.0);
    let p = v.xy * s;
    let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
    let uv = select((vec2<f32>(1.0) - abs(p.yx)) * sgn, p, v.z >= 0.0);
    let q = f32((1 << (k - 1u)) - 1);
    let c = clamp(uv, vec2<f32>(-1.0), vec2<f32>(1.0)) * q;
    let a = bitcast<u32>(peer_meshopt_round(c.x)) & 0xffffu;
    let b = bitcast<u32>(peer_meshopt_round(c.y)) & 0xffffu;
    return a | (b << 16u);
}

// Scalar decode: x, y from the codes, z = one - |x| - |y| (one = 2^(K-1) - 1), t = min(z, 0),
// x += x >= 0 ? t : -t (y likewise), scale by max/|v| and round to the container's snorm.
fn peer_meshopt_oct_decode(p: u32, k: u32) -> vec3<f32> {
    let one = f32((1 << (k - 1u)) - 1);
    let x = f32((bitcast<i32>(p) << 16u) >> 16u);
    let y = f32(bitcast<i32>(p) >> 16u);
    let z = one - abs(x) - abs(y);
    let t = min(z, 0.0);
    let xy = vec2<f32>(x, y) + select(vec2<f32>(-t), vec2<f32>(t), vec2<f32>(x, y) >= vec2<f32>(0.0));
    let smax = select(32767.0, 127.0, k <= 8u);
    let s = smax / sqrt(xy.x * xy.x + xy.y * xy.y + z * z);
    let q = vec3<f32>(f32(peer_meshopt_round(xy.x * s)), f32(peer_meshopt_round(xy.y * s)), f32(peer_meshopt_round(z * s)));
    return q / smax;
}

// K = 8 (16 information bits; snorm8 output).
fn peer_meshopt_oct8_encode(v: vec3<f32>) -> u32 {
    return peer_meshopt_oct_encode(v, 8u);
}
// K = 8 decode.
fn peer_meshopt_oct8_decode(p: u32) -> vec3<f32> {
    return peer_meshopt_oct_decode(p, 8u);
}
// K = 12 (24 information bits; snorm16 output).
fn peer_meshopt_oct12_encode(v: vec3<f32>) -> u32 {
    return peer_meshopt_oct_encode(v, 12u);
}
// K = 12 decode.
fn peer_meshopt_oct12_decode(p: u32) -> vec3<f32> {
    return peer_meshopt_oct_decode(p, 12u);
}
// K = 16 (32 information bits; snorm16 output).
fn peer_meshopt_oct16_encode(v: vec3<f32>) -> u32 {
    return peer_meshopt_oct_encode(v, 16u);
}
// K = 16 decode.
fn peer_meshopt_oct16_decode(p: u32) -> vec3<f32> {
    return peer_meshopt_oct_decode(p, 16u);
}
