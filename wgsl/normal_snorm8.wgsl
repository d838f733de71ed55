// prepass — unit normal as x, y, z snorm8 in an RGBA8 texel: Unity URP's default normal target
// (R8G8B8A8_SNorm: Packages/com.unity.render-pipelines.universal/Runtime/Passes/
// DepthNormalOnlyPass.cs; the shader writes the normal as it is, the format's conversion
// quantises it).
// Rust twin: src/normal/snorm8.rs. Tests: tests/normal_snorm8.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Layout: byte k (k = 0, 1, 2 for x, y, z; byte 0 is the low byte of the u32) holds the two's
// complement byte b = round(127 c) of the normalised vector; byte 3 is left zero for the material.
// As the snorm8 format defines, byte b stands for max(b/127, -1): -128 and -127 both read -1.
// The decoder normalises the integer vector max(b, -127), exact in f32; the one zero vector
// (bytes 0, 0, 0), which no encoder writes, decodes as +z (a renderer normalising it gets NaN).
//
// Bad input (encoder): NaN anywhere, the zero vector and all-subnormal vectors encode as +z;
// subnormal components count as zero; infinite components win (their signs give the direction);
// any finite length is normalised. The decoder ignores byte 3 and accepts every bit pattern.

// The input made safe (see the header); w = 0 marks the degenerate cases.
fn snorm8_sanitize(n: vec3<f32>) -> vec4<f32> {
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

// The normalised n as two's complement bytes round(127 c) for x, y, z in bits 0-23; byte 3 zero.
fn encode_normal_snorm8(n: vec3<f32>) -> u32 {
    let s = snorm8_sanitize(n).xyz;
    // sqrt and / rather than normalize(): correctly rounded on IEEE hardware, where
    // inverseSqrt has a 2-ULP allowance.
    let u = s / sqrt(dot(s, s));
    let b = vec3<i32>(round(clamp(u, vec3<f32>(-1.0), vec3<f32>(1.0)) * 127.0));
    let q = bitcast<vec3<u32>>(b) & vec3<u32>(0xffu);
    return q.x | (q.y << 8u) | (q.z << 16u);
}

// The unit vector of bytes 0-2 read as snorm8: the integer vector max(b, -127), normalised
// (+z for the zero vector); byte 3 ignored.
fn decode_normal_snorm8(p: u32) -> vec3<f32> {
    let b = max(bitcast<vec3<i32>>(vec3<u32>(p << 24u, p << 16u, p << 8u)) >> vec3<u32>(24u), vec3<i32>(-127));
    let zero = all(b == vec3<i32>(0));
    return normalize(vec3<f32>(b) + select(vec3<f32>(0.0), vec3<f32>(0.0, 0.0, 1.0), zero));
}

// Render-target form: the rgba8snorm channels to write, b/127 (alpha 0: put the material there).
// Any conforming write converts b/127 back to b.
fn encode_normal_snorm8_snorm(n: vec3<f32>) -> vec4<f32> {
    let p = encode_normal_snorm8(n);
    let b = bitcast<vec3<i32>>(vec3<u32>(p << 24u, p << 16u, p << 8u)) >> vec3<u32>(24u);
    return vec4<f32>(vec3<f32>(b) / 127.0, 0.0);
}

// The unit vector from sampled rgba8snorm channels: each channel taken to [-1, 1] from its bits
// (NaN counts as 0, magnitudes from 1 up to Inf as +-1, so no float operation sees a non-finite
// channel) and rounded back to its byte, round(127 c): a sampler's few-ULP error or a
// +-0.49/127 filter cannot change the result. Alpha ignored.
fn decode_normal_snorm8_snorm(c: vec4<f32>) -> vec3<f32> {
    let bits = bitcast<vec3<u32>>(c.xyz);
    let mag = bits & vec3<u32>(0x7fffffffu);
    let one = (bits & vec3<u32>(0x80000000u)) | vec3<u32>(0x3f800000u);
    let x = select(select(bits, one, mag >= vec3<u32>(0x3f800000u)), vec3<u32>(0u), mag > vec3<u32>(0x7f800000u));
    let q = bitcast<vec3<u32>>(vec3<i32>(round(bitcast<vec3<f32>>(x) * 127.0))) & vec3<u32>(0xffu);
    return decode_normal_snorm8(q.x | (q.y << 8u) | (q.z << 16u));
}
