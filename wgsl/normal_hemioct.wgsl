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

// Continuous code coordinates in [0, M)^2: p = s.xy / (|x| + |y| + z), rotated (p.x + p.y,
// p.x - p.y); x * 0.5 is exact, so fusing the add cannot change the sum. The clamp stops at
// 1 - 2^-23, as oct_continuous's does: floor() stays below M whichever way the scaling rounds.
fn hemioct_continuous(s: vec3<f32>, m: u32) -> vec2<f32> {
    let l1 = (abs(s.x) + abs(s.y)) + s.z;
    let p = s.xy / l1;
    let q = vec2<f32>(p.x + p.y, p.x - p.y);
    return clamp(q * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(0.99999988079071044921875)) * f32(m);
}
// The integer direction D that code c (whole numbers, in f32) stands for (see the header):
// ((a + b)/2, (a - b)/2) = (u + v - M, u - v), and M - max(|a|, |b|) = M - |D.x| - |D.y|.
// Every value is an integer below 2^14, so every operation is exact on any conforming adapter.
fn hemioct_lattice(c: vec2<f32>) -> vec3<f32> {
    let h = mat2x2<f32>(1.0, 1.0, 1.0, -1.0) * c - vec2<f32>(4095.0, 0.0);
    return vec3<f32>(h, 4095.0 - dot(abs(h), vec2<f32>(1.0)));
}
// One step of the precise encoder's choice, as normal_oct.wgsl's oct_try: the code c00 + off
// replaces the best so far (code in xy, score in z) only if its score, sin^2 of the angle to s
// times |s|^2, is strictly smaller. |D|^2 <= M^2 < 2^24, so its float dot is exact.
fn hemioct_try(s: vec3<f32>, c00: vec2<f32>, off: vec2<f32>, best: vec3<f32>) -> vec3<f32> {
    let c = c00 + off;
    let d = hemioct_lattice(c);
    let x = cross(s, d);
    let score = dot(x, x) / dot(d, d);
    return select(best, vec3<f32>(c, score), score < best.z);
}
// Precise: the best of the four codes around the continuous coordinates, by hemioct_try's
// score (the same expression per candidate); of equal scores the first in the order (0,0),
// (1,0), (0,1), (1,1), as hemioct_try's chain of strict comparisons chooses. Straight-line;
// written out rather than as four hemioct_try calls so that the candidates share their parts:
// hemioct_lattice's (x, y) = (u + v - M, u - v) are (h, k) for c00, then (h + 1, k + 1),
// (h + 1, k - 1), (h + 2, k), and z = (M - |x|) - |y|: every value an integer below 2^14, so
// every operation is exact on any conforming adapter and each D is hemioct_lattice's. The
// choice is a tree (as normal_oct.wgsl's oct_encode_precise: the first of the smallest; every
// score is finite, below 48), the code taken from the bits of c00 + 2^23 (0x4b000000 + c00,
// exact; the high half's bias shifts out of the u32, the low half's is taken off).
fn encode_normal_hemioct24(n: vec3<f32>) -> u32 {
    let s = hemioct_sanitize(n);
    let c00 = floor(hemioct_continuous(s, 4095u));
    let h = (c00.x + c00.y) - 4095.0;
    let k = c00.x - c00.y;
    let h1 = h + 1.0;
    let x = vec4<f32>(h, h1, h1, h + 2.0);
    let y = vec4<f32>(k, k + 1.0, k - 1.0, k);
    let z = (vec4<f32>(4095.0) - abs(x)) - abs(y);
    let d0 = vec3<f32>(x.x, y.x, z.x);
    let d1 = vec3<f32>(x.y, y.y, z.y);
    let d2 = vec3<f32>(x.z, y.z, z.z);
    let d3 = vec3<f32>(x.w, y.w, z.w);
    let x0 = cross(s, d0);
    let x1 = cross(s, d1);
    let x2 = cross(s, d2);
    let x3 = cross(s, d3);
    let q = vec4<f32>(dot(x0, x0) / dot(d0, d0), dot(x1, x1) / dot(d1, d1), dot(x2, x2) / dot(d2, d2), dot(x3, x3) / dot(d3, d3));
    let j = min(q.z, q.w) < min(q.x, q.y);
    let i = select(q.y < q.x, q.w < q.z, j);
    let w = bitcast<vec2<u32>>(c00 + vec2<f32>(8388608.0)) + vec2<u32>(select(0u, 1u, i), select(0u, 1u, j));
    return (w.x + (w.y << 12u)) - 0x4b000000u;
}
// Rounding encoder: nearest code per axis (round half to even).
fn encode_normal_hemioct24_fast(n: vec3<f32>) -> u32 {
    let uv = vec2<u32>(round(hemioct_continuous(hemioct_sanitize(n), 4095u)));
    return uv.x | (uv.y << 12u);
}

// The unit vector (z >= 0) of a 2x12-bit hemi-oct code; bits 24-31 are ignored.
fn decode_normal_hemioct24(p: u32) -> vec3<f32> {
    let uv = vec2<u32>(p & 0xfffu, (p >> 12u) & 0xfffu);
    return normalize(hemioct_lattice(vec2<f32>(uv)));
}

// Render-target form: rgba8unorm channels (alpha 0, free for the material); the decode rounds
// bytes back (each channel taken to [0, 1] from its bits: NaN -> 0, +Inf -> 1), so unpack4x8unorm's 3-ULP error cannot change the code.
fn encode_normal_hemioct24_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_hemioct24(n));
}

// The unit vector from sampled rgba8unorm channels (bytes rounded back, then decoded).
fn decode_normal_hemioct24_unorm(c: vec4<f32>) -> vec3<f32> {
    let bits = bitcast<vec4<u32>>(c);
    let x = select(select(bits, vec4<u32>(0x3f800000u), bits >= vec4<u32>(0x3f800000u)), vec4<u32>(0u), bits > vec4<u32>(0x7f800000u));
    let b = vec4<u32>(round(bitcast<vec4<f32>>(x) * 255.0));
    return decode_normal_hemioct24(b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u));
}
