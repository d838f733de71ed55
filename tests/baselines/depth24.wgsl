// Test baselines for the 24-bit depth functions (not public API): the forms Mark Lee's
// "Pre-lighting in Resistance 2" (Insomniac Games, GDC 2009) warns
// about, measured beside wgsl/depth24.wgsl's.

// Resistance 2's first attempt: weight the unrounded channels and round only the total.
fn baseline_depth24_from_rgb8_unrounded(rgb: vec3<f32>) -> u32 {
    return u32(round(dot(rgb * 255.0, vec3<f32>(65536.0, 256.0, 1.0))));
}

// d / (2^24 - 1) with WGSL's division (2.5 ULP allowed).
fn baseline_hyperbolic_divide(d: u32) -> f32 {
    return f32(d) / 16777215.0;
}

// d times the rounded reciprocal: two roundings.
fn baseline_hyperbolic_reciprocal(d: u32) -> f32 {
    return f32(d) * (1.0 / 16777215.0);
}
