// prepass — view-space normal x and y as two FP16 halves in one u32 (an RGBA8 texel), z rebuilt
// as +sqrt(1 - x^2 - y^2) (Killzone 2 G-buffer: "2xFP16 compressed to RGBA8 on write"; Michal
// Valient, "Deferred Rendering in Killzone 2", Guerrilla Games, Develop Conference 2007).
// Rust twin: src/normal/xy_fp16.rs. Tests: tests/normal_xy_fp16.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Only normals with z >= 0 survive: the sign of z is not stored, and under perspective a visible
// surface's view-space normal can have z < 0 (the "viewspace normal myth" of Mark Lee,
// "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009), which decodes mirrored through
// the xy plane. README measures how often and how badly.
//
// Bad input (encoder): NaN anywhere, the zero vector and all-subnormal vectors encode as +z;
// subnormal components count as zero; infinite components win; any finite length is normalised.
// x and y are clamped to [-1, 1] before pack2x16float (out-of-range input is indeterminate).
// Decoder: every bit pattern gives a finite unit vector; NaN halves count as 0, infinite or
// out-of-range halves are clamped to [-1, 1], and x^2 + y^2 > 1 gives z = 0 (then normalised).

// The input made safe (see the header); w = 0 marks the degenerate cases, which encode +z.
fn xyfp16_sanitize(n: vec3<f32>) -> vec4<f32> {
    let bits = bitcast<vec3<u32>>(n);
    let mag = bits & vec3<u32>(0x7fffffffu);
    if (any(mag > vec3<u32>(0x7f800000u))) {
        return vec4<f32>(0.0, 0.0, 1.0, 0.0);
    }
    let sign_one = bitcast<vec3<f32>>((bits & vec3<u32>(0x80000000u)) | vec3<u32>(0x3f800000u));
    let signed_zero = bitcast<vec3<f32>>(bits & vec3<u32>(0x80000000u));
    let is_inf = mag == vec3<u32>(0x7f800000u);
    let is_sub = (bits & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    var c = select(n, signed_zero, is_sub);
    if (any(is_inf)) {
        c = select(signed_zero, sign_one, is_inf);
    }
    let m = max(max(abs(c.x), abs(c.y)), abs(c.z));
    if (m == 0.0) {
        return vec4<f32>(0.0, 0.0, 1.0, 0.0);
    }
    let e = (bitcast<u32>(m) >> 23u) & 0xffu;
    let s = c * bitcast<f32>(max(254u - e, 1u) << 23u);
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return vec4<f32>(select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub), 1.0);
}

// x and y of the normalised n as two halves: x in bits 0-15, y in bits 16-31.
fn encode_normal_xy_fp16(n: vec3<f32>) -> u32 {
    let s = xyfp16_sanitize(n).xyz;
    let u = s / sqrt(dot(s, s));
    return pack2x16float(clamp(u.xy, vec2<f32>(-1.0), vec2<f32>(1.0)));
}

// The unit vector (x, y, +sqrt(1 - x^2 - y^2)) of two halves x (bits 0-15) and y (16-31).
fn decode_normal_xy_fp16(p: u32) -> vec3<f32> {
    // Halves read from their bits first (unpack2x16float of an infinite or NaN half is outside
    // WGSL's finite-math domain): NaN -> +0, +-Inf -> +-1 (what the clamp gives it).
    let m = vec2<u32>(p, p >> 16u) & vec2<u32>(0xffffu);
    let mag = m & vec2<u32>(0x7fffu);
    let inf = (m & vec2<u32>(0x8000u)) | vec2<u32>(0x3c00u);
    let safe = select(m, select(vec2<u32>(0u), inf, mag == vec2<u32>(0x7c00u)), mag >= vec2<u32>(0x7c00u));
    let xy = clamp(unpack2x16float(safe.x | (safe.y << 16u)), vec2<f32>(-1.0), vec2<f32>(1.0));
    // Normalised by hand with |v|^2 = s + z^2 written as s + max(0, 1 - s): normalize() would
    // square the sqrt, which an optimiser may or may not fold back (Mesa does), so its result
    // would depend on the compiler.
    let s = dot(xy, xy);
    let z2 = max(0.0, 1.0 - s);
    return vec3<f32>(xy, sqrt(z2)) / sqrt(s + z2);
}

// Render-target form, as Killzone 2 wrote it: the rgba8unorm channels holding the four bytes of
// the two halves, and the decode of sampled channels (bytes rounded back, so unpack4x8unorm's
// 3-ULP error cannot flip a bit of a half). Channels are taken to [0, 1] from
// their bits (NaN -> 0, +Inf -> 1), so no float operation sees a non-finite one.
fn encode_normal_xy_fp16_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_xy_fp16(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back, then decoded).
fn decode_normal_xy_fp16_unorm(c: vec4<f32>) -> vec3<f32> {
    let bits = bitcast<vec4<u32>>(c);
    let x = select(select(bits, vec4<u32>(0x3f800000u), bits >= vec4<u32>(0x3f800000u)), vec4<u32>(0u), bits > vec4<u32>(0x7f800000u));
    let b = vec4<u32>(round(bitcast<vec4<f32>>(x) * 255.0));
    return decode_normal_xy_fp16(b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u));
}
