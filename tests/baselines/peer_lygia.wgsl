// Peer baseline (not public API): LYGIA's linearizeDepth and depth2viewZ (OpenGL conventions:
// standard depth, finite far plane), written fresh from the description in the project's
// research notes (peers.md) to be measured beside wgsl/linear_depth.wgsl. The 24-bit forms read
// the code as depth = d/(2^24 - 1), as tests/baselines/linear_depth.wgsl does. An OpenGL
// window depth in [0, 1] equals WebGPU's standard depth of the same view distance.
// Measured by errplot (src/bin/errplot/peers.rs) and tests/errplot_peers.rs.

// linearizeDepth: d = 2·depth - 1; 2nf / (f + n - d(f - n)) (view distance).
fn peer_lygia_linearize_depth(depth: f32, near: f32, far: f32) -> f32 {
    let d = 2.0 * depth - 1.0;
    return 2.0 * near * far / (far + near - d * (far - near));
}

// depth2viewZ (three.js perspectiveDepthToViewZ): nf / ((f - n)·depth - f), negative in front.
fn peer_lygia_depth2viewz(depth: f32, near: f32, far: f32) -> f32 {
    return near * far / ((far - near) * depth - far);
}

// linearizeDepth of a 24-bit code.
fn peer_lygia_linearize_depth24(d: u32, near: f32, far: f32) -> f32 {
    return peer_lygia_linearize_depth(f32(d) * (1.0 / 16777215.0), near, far);
}

// depth2viewZ of a 24-bit code (negative in front).
fn peer_lygia_depth2viewz24(d: u32, near: f32, far: f32) -> f32 {
    return peer_lygia_depth2viewz(f32(d) * (1.0 / 16777215.0), near, far);
}
