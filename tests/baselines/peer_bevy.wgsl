// Peer baseline (not public API): Bevy's deferred G-buffer normal and its reversed-infinite view
// depth, written fresh to be measured beside wgsl/normal_oct.wgsl and wgsl/linear_depth.wgsl. The
// normal as bevy_pbr writes and reads it (checked against its source for issue 60):
// render/utils.wgsl, octahedral_encode (the fold's sign select(-1, 1, n.xy > 0): a zero
// component folds negative) and octahedral_decode; deferred/pbr_deferred_functions.wgsl,
// pack_24bit_normal_and_flags (u32(saturate(x) * 4095 + 0.5), u in bits 0-11, v in 12-23) and
// unpack_24bit_normal. Measured by errplot (src/bin/errplot/peers.rs), tests/errplot_peers.rs
// and tests/normal_oct.rs (bevy_deferred_word_both_ways, the interop test).

// Octahedral projection to [0, 1]^2: L1-normalise, fold the lower half (a zero component folds
// with sign -1), then map [-1, 1] to [0, 1].
fn peer_bevy_oct_encode(v: vec3<f32>) -> vec2<f32> {
    let n = v / (abs(v.x) + abs(v.y) + abs(v.z));
    let wrap = (vec2<f32>(1.0) - abs(n.yx)) * select(vec2<f32>(-1.0), vec2<f32>(1.0), n.xy > vec2<f32>(0.0));
    let o = select(n.xy, wrap, n.z < 0.0);
    return o * 0.5 + 0.5;
}

// Octahedral decode of signed coordinates in [-1, 1]^2: unfold by t = saturate(-z), normalise.
fn peer_bevy_oct_decode(f: vec2<f32>) -> vec3<f32> {
    let z = 1.0 - abs(f.x) - abs(f.y);
    let t = saturate(-z);
    let xy = f + select(vec2<f32>(t), vec2<f32>(-t), f >= vec2<f32>(0.0));
    return normalize(vec3<f32>(xy, z));
}

// G-buffer normal, 12 + 12 bits: each [0, 1] coordinate as u32(saturate(o)·4095 + 0.5).
fn peer_bevy_gbuffer_normal_encode(n: vec3<f32>) -> u32 {
    let u = vec2<u32>(saturate(peer_bevy_oct_encode(n)) * 4095.0 + 0.5);
    return u.x | (u.y << 12u);
}

// G-buffer normal decode: f32(u)/4095 per axis, back to [-1, 1], octahedral decode.
fn peer_bevy_gbuffer_normal_decode(p: u32) -> vec3<f32> {
    let u = vec2<u32>(p & 0xfffu, (p >> 12u) & 0xfffu);
    return peer_bevy_oct_decode(vec2<f32>(u) / 4095.0 * 2.0 - 1.0);
}

// View-space z (negative in front) of a reversed, infinite-far perspective depth d: -near/d.
fn peer_bevy_view_z_reversed_infinite(d: f32, near: f32) -> f32 {
    return -near / d;
}
