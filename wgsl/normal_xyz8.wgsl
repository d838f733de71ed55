// prepass — unit normal as x, y, z unorm8 in an RGBA8 texel (Resistance 2: "normals are stored in
// viewspace as 3 8-bit components", spec power in alpha; Mark Lee, "Pre-lighting in
// Resistance 2", Insomniac Games, GDC 2009).
// Rust twin: src/normal/xyz8.rs. Tests: tests/normal_xyz8.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Byte k (k = 0, 1, 2 for x, y, z; byte 0 is the low byte of the u32) holds
// round(255 (c/2 + 1/2)) of the normalised vector; byte 3 is left zero for the material.
// Byte b stands for the coordinate (2b - 255)/255, never 0 (255 is odd), so the decoder
// normalises the exact odd-integer vector (2b - 255) and cannot meet a zero vector.
//
// Bad input (encoder): NaN anywhere, the zero vector and all-subnormal vectors encode as +z;
// subnormal components count as zero; infinite components win (their signs give the direction);
// any finite length is normalised. The decoder ignores byte 3 and accepts every bit pattern.

// The input made safe (see the header); w = 0 marks the degenerate cases.
fn xyz8_sanitize(n: vec3<f32>) -> vec4<f32> {
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
    // An exact power-of-two scale puts the largest component in [1, 4): dot() cannot overflow.
    let e = (bitcast<u32>(m) >> 23u) & 0xffu;
    let s = c * bitcast<f32>(max(254u - e, 1u) << 23u);
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return vec4<f32>(select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub), 1.0);
}

// The normalised n as bytes round(255 (c/2 + 1/2)) for x, y, z in bits 0-23; byte 3 zero.
fn encode_normal_xyz8(n: vec3<f32>) -> u32 {
    let s = xyz8_sanitize(n).xyz;
    // sqrt and / rather than normalize(): correctly rounded on IEEE hardware, where
    // inverseSqrt has a 2-ULP allowance.
    let u = s / sqrt(dot(s, s));
    // u * 0.5 is exact, so fusing the add cannot change the sum.
    let c = clamp(u * 0.5 + 0.5, vec3<f32>(0.0), vec3<f32>(1.0));
    let b = vec3<u32>(round(c * 255.0));
    return b.x | (b.y << 8u) | (b.z << 16u);
}

// The unit vector of bytes 0-2: the odd-integer vector (2b - 255), normalised; byte 3 ignored.
fn decode_normal_xyz8(p: u32) -> vec3<f32> {
    let b = vec3<i32>(vec3<u32>(p, p >> 8u, p >> 16u) & vec3<u32>(0xffu));
    return normalize(vec3<f32>(2 * b - vec3<i32>(255)));
}

// Render-target form: the rgba8unorm channels to write (alpha 0: put the material there), and
// the decode of sampled channels, bytes rounded back so unpack4x8unorm's 3-ULP error or a
// +-0.49/255 filter cannot change the result. NaN channels count as 0; channels are clamped.
fn encode_normal_xyz8_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_xyz8(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back; alpha ignored).
fn decode_normal_xyz8_unorm(c: vec4<f32>) -> vec3<f32> {
    let is_nan = (bitcast<vec4<u32>>(c) & vec4<u32>(0x7fffffffu)) > vec4<u32>(0x7f800000u);
    let b = vec4<u32>(round(clamp(select(c, vec4<f32>(0.0), is_nan), vec4<f32>(0.0), vec4<f32>(1.0)) * 255.0));
    return decode_normal_xyz8(b.x | (b.y << 8u) | (b.z << 16u));
}
