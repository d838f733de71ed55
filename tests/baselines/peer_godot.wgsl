// Peer baseline (not public API): Godot 4's best-fit normal in its RGBA8 normal_roughness
// target (Forward+), re-implemented from its published formula to be measured beside
// encode_normal_xyz8_best (wgsl/normal_xyz8.wgsl). Godot's encoder
// (servers/rendering/renderer_rd/shaders/forward_clustered/scene_forward_clustered.glsl,
// encode24, written as encode24(normal) * 0.5 + 0.5) divides n by its largest magnitude and
// scales it by a factor read from a 1024 x 1024 R8 lookup texture with a nearest, clamp-to-edge
// sampler, at coordinates (u, v): u = the larger of the two minor magnitudes over the largest,
// v = the smaller over the larger. The texture is made by
// servers/rendering/renderer_rd/shaders/forward_clustered/best_fit_normal.glsl: texel (i, j)
// holds, for the direction (x, x*y, 1) with x = (i + 0.5)/1024 and y = (j + 0.5)/1024, the scale
// t = s/127.5 (s = 1.5, 2.5, ..., 126.5) whose quantised t*dir has the smallest max-norm error
// per unit t (first smallest kept); R8 stores t exactly (255 t = 2s is an integer).
// A harness kernel cannot bind a texture, so peer_godot_best_fit_scale computes, inline, the
// texel the nearest sampler would read: i = clamp(floor(1024 u), 0, 1023), j likewise from v.
// The inline loop is not Godot's cost (a texture fetch is): cost figures for this peer overstate
// it. Where both minor magnitudes are 0, Godot divides 0 by 0 (an undefined texel); this peer
// reads v = 0 there. The target's conversion round(255 c) is written as round(), half to even
// (Vulkan leaves the tie to the implementation). The decoder is Godot's normalize(c * 2 - 1) of
// c = byte/255. Measured by tests/errplot_peers.rs and errplot (src/bin/errplot/peers.rs).

// The R8 texel Godot's lookup reads at (u, v) in [0, 1]^2 (nearest, clamp to edge).
fn peer_godot_best_fit_scale(uv: vec2<f32>) -> f32 {
    let ij = clamp(floor(uv * 1024.0), vec2<f32>(0.0), vec2<f32>(1023.0));
    var c = ij * (1.0 / 1024.0) + vec2<f32>(0.5 / 1024.0);
    c.y = c.y * c.x;
    let dir = vec3<f32>(c.x, c.y, 1.0);
    var min_error = 100000.0;
    var t_best = 0.0;
    for (var s = 1.5; s < 127.5; s = s + 1.0) {
        let t = s / 127.5;
        let vp = dir * t;
        let q = round(clamp(vp * 0.5 + 0.5, vec3<f32>(0.0), vec3<f32>(1.0)) * 255.0) * (1.0 / 255.0) * 2.0 - 1.0;
        let diff = (q - vp) / t;
        let e = max(abs(diff.x), max(abs(diff.y), abs(diff.z)));
        if (e < min_error) {
            min_error = e;
            t_best = t;
        }
    }
    // The R8 texel: round(255 t) / 255.
    return round(t_best * 255.0) / 255.0;
}

// Godot's encode24(n) * 0.5 + 0.5, stored by an rgba8unorm target: bytes 0-2 (alpha, Godot's
// roughness, left zero).
fn peer_godot_normal_encode(n: vec3<f32>) -> u32 {
    let a = abs(n);
    let m = max(a.z, max(a.x, a.y));
    var uv = select(select(a.xz, a.yz, a.y < m), a.xy, !(a.z < m));
    uv = uv / m;
    uv = select(uv, uv.yx, uv.x < uv.y);
    uv.y = select(0.0, uv.y / uv.x, uv.x > 0.0);
    let r = n / m * peer_godot_best_fit_scale(uv);
    let b = vec3<u32>(round(clamp(r * 0.5 + 0.5, vec3<f32>(0.0), vec3<f32>(1.0)) * 255.0));
    return b.x | (b.y << 8u) | (b.z << 16u);
}

// Godot's reader: normalize(c * 2 - 1) of the sampled channels c = byte/255.
fn peer_godot_normal_decode(p: u32) -> vec3<f32> {
    let c = vec3<f32>(vec3<u32>(p, p >> 8u, p >> 16u) & vec3<u32>(0xffu)) / 255.0;
    return normalize(c * 2.0 - 1.0);
}
