// prepass — hemi-octahedral codes for view-space normals (z >= 0 only), 2x12 bits: the upper half
// of the octahedron, rotated 45 degrees so it fills the whole square (Cigolle et al. 2014, the
// survey's "hemi-oct"). Offered beside oct24 for comparison: same bits, half the sphere.
// Rust twin: src/normal/hemioct.rs. Tests: tests/normal_hemioct.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Code k on an axis stands for (2k - M)/M, M = 4095; the decoded vector before normalising is
// the exact integer vector D = ((a + b)/2, (a - b)/2, M - max(|a|, |b|)) with a = 2u - M,
// b = 2v - M (both odd, so the halves are exact). Layout: u in bits 0-11, v in bits 12-23;
// bits 24-31 are left zero (for the material) and ignored by the decoder.
//
// Bad input: as wgsl/normal_oct.wgsl (NaN, zero, all-subnormal -> +z; infinities win; any
// finite length). A negative z is first clamped to 0 (the nearest point of the hemisphere, on
// the equator); (0, 0, -1) thereby becomes the zero vector and encodes +z.

// The input made safe as oct_sanitize does (see the header), after clamping z to >= 0.
fn hemioct_sanitize(n: vec3<f32>) -> vec3<f32> {
    let bits = bitcast<vec3<u32>>(n);
    let mag = bits & vec3<u32>(0x7fffffffu);
    if (any(mag > vec3<u32>(0x7f800000u))) {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let sign_one = bitcast<vec3<f32>>((bits & vec3<u32>(0x80000000u)) | vec3<u32>(0x3f800000u));
    let signed_zero = bitcast<vec3<f32>>(bits & vec3<u32>(0x80000000u));
    let is_inf = mag == vec3<u32>(0x7f800000u);
    let is_sub = (bits & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    var c = select(n, signed_zero, is_sub);
    if (any(is_inf)) {
        c = select(signed_zero, sign_one, is_inf);
    }
    c.z = max(c.z, 0.0);
    let m = max(max(abs(c.x), abs(c.y)), c.z);
    if (m == 0.0) {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let e = (bitcast<u32>(m) >> 23u) & 0xffu;
    let s = c * bitcast<f32>(max(254u - e, 1u) << 23u);
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub);
}

// Continuous code coordinates in [0, M]^2: p = s.xy / (|x| + |y| + z), rotated (p.x + p.y,
// p.x - p.y); x * 0.5 is exact, so fusing the add cannot change the sum.
fn hemioct_continuous(s: vec3<f32>, m: u32) -> vec2<f32> {
    let l1 = (abs(s.x) + abs(s.y)) + s.z;
    let p = s.xy / l1;
    let q = vec2<f32>(p.x + p.y, p.x - p.y);
    return clamp(q * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(1.0)) * f32(m);
}

// The exact integer direction D that code (u, v) stands for (see the header). a and b are odd,
// so a + b and a - b are even and the arithmetic shift halves them exactly.
fn hemioct_lattice(uv: vec2<u32>, m: u32) -> vec3<i32> {
    let mi = i32(m);
    let ab = bitcast<vec2<i32>>(uv + uv) - vec2<i32>(mi);
    let h = (ab * vec2<i32>(1, -1) + ab.yx) >> vec2<u32>(1u);
    let aab = abs(ab);
    return vec3<i32>(h, mi - max(aab.x, aab.y));
}

// One step of the precise encoder's choice, as normal_oct.wgsl's oct_try: the code c00 + off
// replaces the best so far (code in xy, score bits in z) only if its score, sin^2 of the angle
// to s times |s|^2, is strictly smaller (compared as floats, as there).
fn hemioct_try(s: vec3<f32>, m: u32, c00: vec2<u32>, off: vec2<u32>, best: vec3<u32>) -> vec3<u32> {
    let c = c00 + off;
    let d = hemioct_lattice(c, m);
    // |D|^2 <= M^2: exact in u32 (squares of the two's-complement bits, mod 2^32), one rounding.
    let du = bitcast<vec3<u32>>(d);
    let sq = du * du;
    let x = cross(s, vec3<f32>(d));
    let score = dot(x, x) / f32(sq.x + sq.y + sq.z);
    return select(best, vec3<u32>(c, bitcast<u32>(score)), score < bitcast<f32>(best.z));
}

// Precise: the best of the four codes around the continuous coordinates, tried in the order
// (0,0), (1,0), (0,1), (1,1), a later one winning only if strictly closer ((0,0) always
// replaces the +inf start). Straight-line (no loop, no variables).
fn encode_normal_hemioct24(n: vec3<f32>) -> u32 {
    let m = 4095u;
    let s = hemioct_sanitize(n);
    let c00 = min(vec2<u32>(floor(hemioct_continuous(s, m))), vec2<u32>(m - 1u));
    let b0 = hemioct_try(s, m, c00, vec2<u32>(0u, 0u), vec3<u32>(0u, 0u, 0x7f800000u));
    let b1 = hemioct_try(s, m, c00, vec2<u32>(1u, 0u), b0);
    let b2 = hemioct_try(s, m, c00, vec2<u32>(0u, 1u), b1);
    let best = hemioct_try(s, m, c00, vec2<u32>(1u, 1u), b2);
    return best.x | (best.y << 12u);
}

// Rounding encoder: nearest code per axis (round half to even).
fn encode_normal_hemioct24_fast(n: vec3<f32>) -> u32 {
    let uv = vec2<u32>(round(hemioct_continuous(hemioct_sanitize(n), 4095u)));
    return uv.x | (uv.y << 12u);
}

// The unit vector (z >= 0) of a 2x12-bit hemi-oct code; bits 24-31 are ignored.
fn decode_normal_hemioct24(p: u32) -> vec3<f32> {
    let uv = vec2<u32>(p & 0xfffu, (p >> 12u) & 0xfffu);
    return normalize(vec3<f32>(hemioct_lattice(uv, 4095u)));
}

// Render-target form: rgba8unorm channels (alpha 0, free for the material); the decode rounds
// bytes back (NaN -> 0, clamped), so unpack4x8unorm's 3-ULP error cannot change the code.
fn encode_normal_hemioct24_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_hemioct24(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back, then decoded).
fn decode_normal_hemioct24_unorm(c: vec4<f32>) -> vec3<f32> {
    let is_nan = (bitcast<vec4<u32>>(c) & vec4<u32>(0x7fffffffu)) > vec4<u32>(0x7f800000u);
    let b = vec4<u32>(round(clamp(select(c, vec4<f32>(0.0), is_nan), vec4<f32>(0.0), vec4<f32>(1.0)) * 255.0));
    return decode_normal_hemioct24(b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u));
}
