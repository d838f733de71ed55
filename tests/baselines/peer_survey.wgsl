// Peer baseline (not public API): the precise octahedral encoder as the JCGT 2014 survey
// (Cigolle et al.) publishes it — snorm grid M = 2^(N-1) - 1 per axis, floor, three neighbours,
// largest f32 dot product wins (strict >) — with its snorm decode, written fresh from the
// description in the project's research notes (peers.md) to be measured beside
// wgsl/normal_oct.wgsl. Layout: two N-bit two's-complement codes in the low and high 16 bits.
// Measured by errplot (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

// +1 for x >= 0, else -1 (the survey's signNotZero).
fn peer_survey_sign(v: vec2<f32>) -> vec2<f32> {
    return select(vec2<f32>(-1.0), vec2<f32>(1.0), v >= vec2<f32>(0.0));
}

// Octahedral projection to [-1, 1]^2, lower half folded.
fn peer_survey_oct(v: vec3<f32>) -> vec2<f32> {
    let p = v.xy / (abs(v.x) + abs(v.y) + abs(v.z));
    return select(p, (vec2<f32>(1.0) - abs(p.yx)) * peer_survey_sign(p), v.z <= 0.0);
}

// Octahedral decode of [-1, 1]^2 coordinates, normalised.
fn peer_survey_oct_decode(e: vec2<f32>) -> vec3<f32> {
    let z = 1.0 - abs(e.x) - abs(e.y);
    let xy = select(e, (vec2<f32>(1.0) - abs(e.yx)) * peer_survey_sign(e), z < 0.0);
    return normalize(vec3<f32>(xy, z));
}

// The survey's precise encoder, N bits per axis: floor onto the snorm grid, then of s and its
// neighbours s + (0,1)/M, (1,0)/M, (1,1)/M the largest dot(decode(c), v) (strict >).
fn peer_survey_precise_encode(v: vec3<f32>, n: u32) -> u32 {
    let m = f32((1 << (n - 1u)) - 1);
    let s = floor(clamp(peer_survey_oct(v), vec2<f32>(-1.0), vec2<f32>(1.0)) * m) / m;
    var best = s;
    var best_dot = dot(peer_survey_oct_decode(s), v);
    for (var k = 1u; k < 4u; k++) {
        let c = s + vec2<f32>(f32(k >> 1u), f32(k & 1u)) / m;
        let d = dot(peer_survey_oct_decode(c), v);
        if (d > best_dot) {
            best = c;
            best_dot = d;
        }
    }
    let q = vec2<i32>(round(clamp(best, vec2<f32>(-1.0), vec2<f32>(1.0)) * m));
    return (bitcast<u32>(q.x) & 0xffffu) | (bitcast<u32>(q.y) << 16u);
}

// snorm decode: max(code/M, -1) per axis, then the octahedral decode.
fn peer_survey_decode(p: u32, n: u32) -> vec3<f32> {
    let m = f32((1 << (n - 1u)) - 1);
    let q = vec2<f32>(f32((bitcast<i32>(p) << 16u) >> 16u), f32(bitcast<i32>(p) >> 16u));
    return peer_survey_oct_decode(max(q / m, vec2<f32>(-1.0)));
}

// 2 x 8 bits.
fn peer_survey_precise16_encode(v: vec3<f32>) -> u32 {
    return peer_survey_precise_encode(v, 8u);
}
// 2 x 8 bits decode.
fn peer_survey_precise16_decode(p: u32) -> vec3<f32> {
    return peer_survey_decode(p, 8u);
}
// 2 x 12 bits.
fn peer_survey_precise24_encode(v: vec3<f32>) -> u32 {
    return peer_survey_precise_encode(v, 12u);
}
// 2 x 12 bits decode.
fn peer_survey_precise24_decode(p: u32) -> vec3<f32> {
    return peer_survey_decode(p, 12u);
}
// 2 x 16 bits.
fn peer_survey_precise32_encode(v: vec3<f32>) -> u32 {
    return peer_survey_precise_encode(v, 16u);
}
// 2 x 16 bits decode.
fn peer_survey_precise32_decode(p: u32) -> vec3<f32> {
    return peer_survey_decode(p, 16u);
}
