// Test baselines for linear depth (not public API): the textbook forms measured beside
// wgsl/linear_depth.wgsl. Constants are computed on the CPU in f64 and rounded once, the most
// favourable setting for them.

// The textbook inverse (Mark Lee, "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009):
// vz = 1 / (zw·a + b), a = (f - n)/(-f n), b = 1/n, zw = d/(2^24 - 1).
fn baseline_view_z_textbook24(d: u32, ab: vec2<f32>) -> f32 {
    let zw = f32(d) * (1.0 / 16777215.0);
    return 1.0 / (zw * ab.x + ab.y);
}

// The same on a float depth.
fn baseline_view_z_textbook(z: f32, ab: vec2<f32>) -> f32 {
    return 1.0 / (z * ab.x + ab.y);
}

// vz = B / (z - A), A = f/(f - n), B = -f n/(f - n).
fn baseline_view_z_b_over_d_minus_a(z: f32, ab: vec2<f32>) -> f32 {
    return ab.y / (z - ab.x);
}

// The same on a 24-bit code.
fn baseline_view_z_b_over_d_minus_a24(d: u32, ab: vec2<f32>) -> f32 {
    let zw = f32(d) * (1.0 / 16777215.0);
    return ab.y / (zw - ab.x);
}
