// prepass — O3DE's signed octahedron: a unit normal in the R, G and B channels of an RGB10A2
// texel, the hemi-octahedral map of (x, y, |z|) at 10 bits per axis with z's sign in B (the
// whole sphere in 21 bits; A's 2 bits stay the renderer's).
// Rust twin: src/normal/signed_oct.rs. Tests: tests/normal_signed_oct.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Source: O3DE, Gems/Atom/RPI/Assets/ShaderLib/Atom/RPI/Math.azsli, EncodeNormalSignedOctahedron
// and DecodeNormalSignedOctahedron ("Store in a 10/10/10/2 texture", after John White's 2017
// "signed octahedron normal encoding"). O3DE writes, with p = n.xy / (|x| + |y| + |z|),
// R = p.x/2 + (p.y/2 + 1/2), G = -p.x/2 + (p.y/2 + 1/2), B = saturate(n.z * FLT_MAX) (1 for
// z > 0, 0 for z <= 0), and reads x = R - G, y = (R + G) - 1, z = (2B - 1)(1 - |x| - |y|),
// normalised. The RGB10A2 write rounds R and G to k/1023.
//
// Layout of the u32 form: the RGB10A2 texel's bits -- u (R's code) in bits 0-9, v (G's code)
// in bits 10-19, B in bits 20-29: 1023 for z > 0 (O3DE's B = 1), 0 for z <= 0 (B = 0); bits
// 30-31 (A) left zero by the encoders and ignored by the decoder. The decoder reads any B as
// O3DE does, z's factor 2B - 1 on B = b/1023: z > 0 exactly when b >= 512. (Until issue 60 the
// word held z's sign in bit 20 alone, which O3DE reads as B = 1/1023, z < 0.)
//
// Grid: codes (u, v) stand for the exact integer vector D = (u - v, u + v - M, +-(M - |u - v| -
// |u + v - M|)), M = 1023, z's sign from B (O3DE's decode times M, exactly): the
// hemi-octahedral lattice of wgsl/normal_hemioct.wgsl at 10 bits, with the axes O3DE's way
// round (R = (x + y)/2 + 1/2 as hemioct's first axis; G = (y - x)/2 + 1/2 is hemioct's second
// mirrored). |D|_1 = M, so D is never zero; every value is an integer below 2^11, exact in f32.
// The equator: where M - |x| - |y| = 0 (u or v at 0 or M), z is +0 for b >= 512 and -0 below,
// as O3DE's decoder gives; both are the same direction.
//
// Bad input: as wgsl/normal_oct.wgsl: NaN anywhere, the zero vector and all-subnormal vectors
// encode as +z; subnormal components count as zero; infinite components win (the direction of
// the infinities); any finite length is fine (the map is scale-free). z = +-0 (after that)
// writes B = 0, as O3DE's B = saturate(z * FLT_MAX) = 0. Decoders accept every bit
// pattern (the unorm one every float) and return a finite unit vector.
//
// Written to be evaluated identically everywhere it matters: the only products feeding sums are
// by 0.5 (exact), scores go through dot()/cross() as wholes, NaN/Inf/subnormals found from bits.
// Helper names are unique (signed_oct_*) so the files compose.

// The input made safe (normal_oct.wgsl's oct_sanitize): NaN or zero -> +z; infinities -> their
// signs; subnormal components -> signed zero; then scaled by an exact power of two so the
// largest component lies in [1, 4).
fn signed_oct_sanitize(n: vec3<f32>) -> vec3<f32> {
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
    let m = max(max(abs(c.x), abs(c.y)), abs(c.z));
    if (m == 0.0) {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let e = (bitcast<u32>(m) >> 23u) & 0xffu;
    let s = c * bitcast<f32>(max(254u - e, 1u) << 23u);
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub);
}

// Continuous code coordinates 1023 (R, G) in [0, M), in O3DE's order of operations: p = s.xy /
// |s|_1, y0 = p.y/2 + 1/2, R = p.x/2 + y0, G = -p.x/2 + y0. Every product is by +-0.5 (exact
// but for subnormal p, which no sum can notice), so fusing an add cannot change a sum. The clamp
// stops at 1 - 2^-23, as oct_continuous's does: floor() stays below M whichever way the scaling
// rounds, while round() still gives M there.
fn signed_oct_continuous(s: vec3<f32>) -> vec2<f32> {
    let a = abs(s);
    let l1 = (a.x + a.y) + a.z;
    let p = s.xy / l1;
    let y0 = p.y * 0.5 + 0.5;
    let rg = vec2<f32>(p.x * 0.5 + y0, p.x * -0.5 + y0);
    return clamp(rg, vec2<f32>(0.0), vec2<f32>(0.99999988079071044921875)) * 1023.0;
}

// The integer direction of codes c = (u, v) (whole numbers, in f32) on the upper hemisphere
// (see the header): (u - v, (u + v) - M) as a matrix product with entries +-1, and
// z = M - (|x| + |y|); every value an integer below 2^11, so every operation is exact on any
// conforming adapter, fused or not.
fn signed_oct_lattice(c: vec2<f32>) -> vec3<f32> {
    let h = mat2x2<f32>(1.0, 1.0, -1.0, 1.0) * c - vec2<f32>(0.0, 1023.0);
    return vec3<f32>(h, 1023.0 - dot(abs(h), vec2<f32>(1.0)));
}

// One step of the precise encoder's choice, as normal_hemioct.wgsl's hemioct_try: the code
// c00 + off replaces the best so far (code in xy, score in z) only if its score, sin^2 of the
// angle between a = (s.x, s.y, |s.z|) and D times |a|^2, is strictly smaller. |D|^2 <= M^2 <
// 2^24, so its float dot is exact. (The precise encoder writes the four steps out; the decision
// search of prepass::sweep::normal calls this one.)
fn signed_oct_try(a: vec3<f32>, c00: vec2<f32>, off: vec2<f32>, best: vec3<f32>) -> vec3<f32> {
    let c = c00 + off;
    let d = signed_oct_lattice(c);
    let x = cross(a, d);
    let score = dot(x, x) / dot(d, d);
    return select(best, vec3<f32>(c, score), score < best.z);
}

// Precise: B from the sign of z (1023 for z > 0, else 0), and of the four codes floor(c) + {0, 1}^2
// around the continuous coordinates the one whose direction on that hemisphere is closest to n
// (by signed_oct_try's score for a = (s.x, s.y, |s.z|): mirroring both vectors in z leaves the
// cross product's squares as they are, so the score is the one against the signed direction);
// of equal scores the first in the order (0,0), (1,0), (0,1), (1,1). A code on the other
// hemisphere is never closer (its mirror image on this one is at most as far). Straight-line, as
// encode_normal_hemioct24: the candidates' (x, y) = (u - v, u + v - M) are (h, k) for c00, then
// (h + 1, k + 1), (h - 1, k + 1), (h, k + 2), and z = (M - |x|) - |y|: integers below 2^11, each
// D signed_oct_lattice's. The choice is a tree (the first of the smallest; every score is finite,
// below 48); the codes are taken from the bits of c00 + 2^23 (0x4b000000 + c00, exact; the high
// half's bias shifts out of the u32, the low half's is taken off).
fn encode_normal_signed_oct(n: vec3<f32>) -> u32 {
    let s = signed_oct_sanitize(n);
    let a = vec3<f32>(s.xy, abs(s.z));
    let c00 = floor(signed_oct_continuous(s));
    let h = c00.x - c00.y;
    let k = (c00.x + c00.y) - 1023.0;
    let k1 = k + 1.0;
    let x = vec4<f32>(h, h + 1.0, h - 1.0, h);
    let y = vec4<f32>(k, k1, k1, k + 2.0);
    let z = (vec4<f32>(1023.0) - abs(x)) - abs(y);
    let d0 = vec3<f32>(x.x, y.x, z.x);
    let d1 = vec3<f32>(x.y, y.y, z.y);
    let d2 = vec3<f32>(x.z, y.z, z.z);
    let d3 = vec3<f32>(x.w, y.w, z.w);
    let x0 = cross(a, d0);
    let x1 = cross(a, d1);
    let x2 = cross(a, d2);
    let x3 = cross(a, d3);
    let q = vec4<f32>(dot(x0, x0) / dot(d0, d0), dot(x1, x1) / dot(d1, d1), dot(x2, x2) / dot(d2, d2), dot(x3, x3) / dot(d3, d3));
    let j = min(q.z, q.w) < min(q.x, q.y);
    let i = select(q.y < q.x, q.w < q.z, j);
    let w = bitcast<vec2<u32>>(c00 + vec2<f32>(8388608.0)) + vec2<u32>(select(0u, 1u, i), select(0u, 1u, j));
    return ((w.x + (w.y << 10u)) - 0x4b000000u) | select(0u, 0x3ff00000u, s.z > 0.0);
}

// Rounding: the nearest code per axis (half to even) and B from the sign of z -- for finite
// vectors of normal components, the codes O3DE's encoder and a round-to-nearest RGB10A2 write
// give (the same arithmetic; the power-of-two scaling does not change p).
fn encode_normal_signed_oct_fast(n: vec3<f32>) -> u32 {
    let s = signed_oct_sanitize(n);
    let uv = vec2<u32>(round(signed_oct_continuous(s)));
    return uv.x | (uv.y << 10u) | select(0u, 0x3ff00000u, s.z > 0.0);
}

// The unit vector of a texel as O3DE's decoder reads it: the direction of (R - G, R + G - 1,
// (2B - 1)(1 - |x| - |y|)) on R, G, B = (u, v, b)/1023, i.e. of (1023 D.x, 1023 D.y,
// (2b - 1023) D.z) (signed_oct_decode_any_b). For the B the encoders write, 1023 and 0, that is
// D's direction with z's sign, and D itself is normalised: z negated (to -0 on the equator) for
// B = 0 -- z >= 0, so negating is setting its sign bit, B's lowest bit (bit 20) clear moved to
// bit 31 -- as before issue 60, so those decodes keep their bits. Bits 30-31 are ignored.
fn decode_normal_signed_oct(p: u32) -> vec3<f32> {
    let d = signed_oct_lattice(vec2<f32>(vec2<u32>(p, p >> 10u) & vec2<u32>(0x3ffu)));
    let b = (p >> 20u) & 0x3ffu;
    if (b != 0u && b != 0x3ffu) {
        return signed_oct_decode_any_b(d, b);
    }
    let z = bitcast<f32>(bitcast<u32>(d.z) | ((~p & 0x100000u) << 11u));
    return normalize(vec3<f32>(d.xy, z));
}

// Render-target form: the rgb10a2unorm channels to write, R = u/1023, G = v/1023, B = 1 for
// z > 0 and 0 otherwise (O3DE's B; B's ten bits in the word all equal bit 20), A = 0 (the
// renderer's). Any conforming write converts them back to the code.
fn encode_normal_signed_oct_unorm(n: vec3<f32>) -> vec4<f32> {
    let p = encode_normal_signed_oct(n);
    let k = vec2<u32>(p, p >> 10u) & vec2<u32>(0x3ffu);
    return vec4<f32>(vec2<f32>(k) / 1023.0, f32((p >> 20u) & 1u), 0.0);
}

// The unit vector from sampled rgb10a2unorm channels R, G, B: each taken to [0, 1] from its bits
// (NaN, negative values and -0 count as 0, values from 1 up to +Inf as 1, so no float operation
// sees a non-finite channel) and rounded back to its code, round(1023 c); then that texel
// decoded (B read as O3DE reads it: z > 0 for B's code at least 512). A is ignored.
fn decode_normal_signed_oct_unorm(c: vec4<f32>) -> vec3<f32> {
    let b = bitcast<vec3<u32>>(c.xyz);
    let x = select(select(b, vec3<u32>(0x3f800000u), b >= vec3<u32>(0x3f800000u)), vec3<u32>(0u), b > vec3<u32>(0x7f800000u));
    let k = vec3<u32>(round(bitcast<vec3<f32>>(x) * 1023.0));
    return decode_normal_signed_oct(k.x | (k.y << 10u) | (k.z << 20u));
}

// O3DE's reading of a texel whose B code b is neither 0 nor 1023 (no encoder writes one, a
// filtered or foreign texel may hold one): the direction of (1023 D.x, 1023 D.y,
// (2b - 1023) D.z), D from the texel's R and G -- integers below 2^20, exact in f32 (fused or
// not) -- normalised. On the equator z is -0 for b < 512 (0 times a negative factor).
fn signed_oct_decode_any_b(d: vec3<f32>, b: u32) -> vec3<f32> {
    return normalize(vec3<f32>(d.xy * 1023.0, d.z * (f32(b + b) - 1023.0)));
}
