// prepass — unit normal as x, y, z unorm10 in an RGB10A2 texel: Unreal 5's GBufferA
// (Engine/Shaders/Private/DeferredShadingCommon.ush, EncodeNormal: n * 0.5 + 0.5) and Bevy's
// normal prepass (crates/bevy_pbr/src/prepass/prepass.wgsl, an Rgb10a2Unorm target).
// Rust twin: src/normal/xyz10.rs. Tests: tests/normal_xyz10.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Layout: as an rgb10a2unorm texel packs it: x in bits 0-9, y in 10-19, z in 20-29; bits 30-31
// (the 2-bit alpha) are left zero for the renderer. Code k stands for the coordinate
// (2k - 1023)/1023, never 0 (1023 is odd), so the decoder normalises the exact odd-integer vector
// (2k - 1023) and cannot meet a zero vector. The engines decode normalize(c * 2 - 1) with
// c = k/1023: the same direction up to f32 rounding.
//
// Bad input (encoder): NaN anywhere, the zero vector and all-subnormal vectors encode as +z;
// subnormal components count as zero; infinite components win (their signs give the direction);
// any finite length is normalised. The decoder ignores bits 30-31 and accepts every bit pattern.

// The input made safe (see the header); w = 0 marks the degenerate cases.
fn xyz10_sanitize(n: vec3<f32>) -> vec4<f32> {
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

// The normalised n as codes round(1023 (c/2 + 1/2)) for x, y, z in bits 0-29; bits 30-31 zero.
fn encode_normal_xyz10(n: vec3<f32>) -> u32 {
    let s = xyz10_sanitize(n).xyz;
    // sqrt and / rather than normalize(): correctly rounded on IEEE hardware, where
    // inverseSqrt has a 2-ULP allowance.
    let u = s / sqrt(dot(s, s));
    // u * 0.5 is exact, so fusing the add cannot change the sum.
    let c = clamp(u * 0.5 + 0.5, vec3<f32>(0.0), vec3<f32>(1.0));
    let k = vec3<u32>(round(c * 1023.0));
    return k.x | (k.y << 10u) | (k.z << 20u);
}

// The unit vector of bits 0-29: the odd-integer vector (2k - 1023), normalised; bits 30-31
// ignored.
fn decode_normal_xyz10(p: u32) -> vec3<f32> {
    let k = vec3<i32>(vec3<u32>(p, p >> 10u, p >> 20u) & vec3<u32>(0x3ffu));
    return normalize(vec3<f32>(2 * k - vec3<i32>(1023)));
}

// Render-target form: the rgb10a2unorm channels to write, k/1023 (alpha 0: the renderer's two
// bits go there). Any conforming write converts k/1023 back to k.
fn encode_normal_xyz10_unorm(n: vec3<f32>) -> vec4<f32> {
    let p = encode_normal_xyz10(n);
    let k = vec3<u32>(p, p >> 10u, p >> 20u) & vec3<u32>(0x3ffu);
    return vec4<f32>(vec3<f32>(k) / 1023.0, 0.0);
}

// The unit vector from sampled rgb10a2unorm channels: each channel taken to [0, 1] from its bits
// (NaN, negative values and -0 count as 0, values from 1 up to +Inf as 1, so no float operation
// sees a non-finite channel) and rounded back to its code, round(1023 c): a sampler's few-ULP
// error or a +-0.49/1023 filter cannot change the result. Alpha ignored.
fn decode_normal_xyz10_unorm(c: vec4<f32>) -> vec3<f32> {
    let b = bitcast<vec3<u32>>(c.xyz);
    let x = select(select(b, vec3<u32>(0x3f800000u), b >= vec3<u32>(0x3f800000u)), vec3<u32>(0u), b > vec3<u32>(0x7f800000u));
    let k = vec3<u32>(round(bitcast<vec3<f32>>(x) * 1023.0));
    return decode_normal_xyz10(k.x | (k.y << 10u) | (k.z << 20u));
}
