// Test baselines for wgsl/roughness.wgsl (not public API): the specular power stored linearly
// in 8 bits, measured beside the log-range code.

// power/max_power as unorm8 (how a spec power lands in an alpha channel without a curve).
fn baseline_linear8_encode(power: f32, max_power: f32) -> u32 {
    return u32(round(clamp(power / max_power, 0.0, 1.0) * 255.0));
}

fn baseline_linear8_decode(code: u32, max_power: f32) -> f32 {
    return f32(min(code, 255u)) / 255.0 * max_power;
}

// (power - 1)/(max_power - 1) as unorm8: both ends of [1, max_power] exact.
fn baseline_affine8_encode(power: f32, max_power: f32) -> u32 {
    return u32(round(clamp((power - 1.0) / (max_power - 1.0), 0.0, 1.0) * 255.0));
}

fn baseline_affine8_decode(code: u32, max_power: f32) -> f32 {
    return 1.0 + f32(min(code, 255u)) / 255.0 * (max_power - 1.0);
}
