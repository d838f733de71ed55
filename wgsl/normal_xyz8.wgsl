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

// Best-fit code (Kaplanyan, "CryENGINE 3: Reaching the speed of light", SIGGRAPH 2010; Godot 4's
// G-buffer normal): of all 2^24 codes, the one whose decoded direction (the odd-integer vector
// D = 2b - 255 that decode_normal_xyz8 normalises) is nearest in angle to n, found without a
// lookup texture. Same layout, decoder and bad-input rules as encode_normal_xyz8.
// For each odd value m of D's component on n's dominant axis (a plane, 255 down to 1) the best
// code of the plane is one of the 3 x 3 odd points around where the ray meets it (proof:
// src/normal/xyz8.rs, best_fit_code), scored by |s x D|^2/|D|^2 through the offsets e = D - h
// from the hit h, so the cross product has no cancellation; the first strictly smallest score
// wins (ties: larger m, then smaller other components). A plane is skipped when a lower bound
// on its best sine, less twice the scoring slack 2^-19, already loses. Zero components take
// D's positive sign. Cost: a loop of 128 planes of ~15 operations (no division or square
// root), and 9 candidates of ~17 more (a division each) in each plane the bound keeps (5.7 on
// average over the sphere, all 128 at worst): on the order of 100 times encode_normal_xyz8.
fn encode_normal_xyz8_best(n: vec3<f32>) -> u32 {
    let s = xyz8_sanitize(n).xyz;
    let a = abs(s);
    var axis = 2u;
    if (a.x >= a.y && a.x >= a.z) {
        axis = 0u;
    } else if (a.y >= a.z) {
        axis = 1u;
    }
    var r = a.zxy;
    if (axis == 0u) {
        r = a;
    } else if (axis == 1u) {
        r = a.yzx;
    }
    let t1 = r.y / r.x;
    let t2 = r.z / r.x;
    let l = (1.0 + t1 * t1) + t2 * t2;
    // 2 * 2^-19: the scoring slack (src/normal/xyz8.rs, BEST_FIT_SINE_SLACK), twice.
    let margin = 3.814697265625e-6;
    var best = 4.0;
    var bd = vec3<f32>(255.0, 1.0, 1.0);
    // A plane is skipped when the distance rho from its hit to the nearest odd point exceeds
    // cut * m: its lower bound rho / (l (m + rho)) on the sine then beats sqrt(best / l) + margin.
    var cut = 1.0e6;
    for (var i = 0; i < 128; i = i + 1) {
        let m = f32(255 - 2 * i);
        let h1 = m * t1;
        let h2 = m * t2;
        let q1 = floor(h1 * 0.5) * 2.0 + 1.0;
        let q2 = floor(h2 * 0.5) * 2.0 + 1.0;
        let r1 = h1 - q1;
        let r2 = h2 - q2;
        let cm = cut * m;
        if (r1 * r1 + r2 * r2 > cm * cm) {
            continue;
        }
        for (var j = -2; j <= 2; j = j + 2) {
            let d1 = clamp(q1 + f32(j), 1.0, 255.0);
            let e1 = d1 - h1;
            for (var k = -2; k <= 2; k = k + 2) {
                let d2 = clamp(q2 + f32(k), 1.0, 255.0);
                let e2 = d2 - h2;
                let c = vec3<f32>(t1 * e2 - t2 * e1, e2, e1);
                let len2 = (m * m + d1 * d1) + d2 * d2;
                let score = dot(c, c) / len2;
                if (score < best) {
                    best = score;
                    bd = vec3<f32>(m, d1, d2);
                }
            }
        }
        let tl = (sqrt(best / l) + margin) * l;
        cut = select(1.0e6, tl / (1.0 - tl), tl < 0.5);
    }
    var d = bd.yzx;
    if (axis == 0u) {
        d = bd;
    } else if (axis == 1u) {
        d = bd.zxy;
    }
    let sd = select(-d, d, s >= vec3<f32>(0.0));
    let b = vec3<u32>((sd + 255.0) * 0.5);
    return b.x | (b.y << 8u) | (b.z << 16u);
}

// Render-target form of encode_normal_xyz8_best: the rgba8unorm channels (alpha 0).
fn encode_normal_xyz8_best_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_xyz8_best(n));
}

// The unit vector of bytes 0-2: the odd-integer vector (2b - 255), normalised; byte 3 ignored.
fn decode_normal_xyz8(p: u32) -> vec3<f32> {
    let b = vec3<i32>(vec3<u32>(p, p >> 8u, p >> 16u) & vec3<u32>(0xffu));
    return normalize(vec3<f32>(2 * b - vec3<i32>(255)));
}

// Render-target form: the rgba8unorm channels to write (alpha 0: put the material there), and
// the decode of sampled channels, bytes rounded back so unpack4x8unorm's 3-ULP error or a
// +-0.49/255 filter cannot change the result. Channels are taken to [0, 1] from
// their bits (NaN -> 0, +Inf -> 1), so no float operation sees a non-finite one.
fn encode_normal_xyz8_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_xyz8(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back; alpha ignored).
fn decode_normal_xyz8_unorm(c: vec4<f32>) -> vec3<f32> {
    let bits = bitcast<vec4<u32>>(c);
    let x = select(select(bits, vec4<u32>(0x3f800000u), bits >= vec4<u32>(0x3f800000u)), vec4<u32>(0u), bits > vec4<u32>(0x7f800000u));
    let b = vec4<u32>(round(bitcast<vec4<f32>>(x) * 255.0));
    return decode_normal_xyz8(b.x | (b.y << 8u) | (b.z << 16u));
}
