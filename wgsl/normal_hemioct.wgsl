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
// Bad input (the robust encoders; the _vouched ones assume their contract, see "Vouched input"
// below): as wgsl/normal_oct.wgsl (NaN, zero, all-subnormal -> +z; infinities win; any finite
// length). A negative z is first clamped to 0 (the nearest point of the hemisphere, on the
// equator); (0, 0, -1) thereby becomes the zero vector and encodes +z.

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
    return hemioct_choose(s, hemioct_continuous(s, 4095u));
}
// The precise encoder's choice for a sanitized (or vouched and scaled) input s and its
// continuous coordinates c: the body of encode_normal_hemioct24, shared with its vouched form.
fn hemioct_choose(s: vec3<f32>, c: vec2<f32>) -> u32 {
    let c00 = floor(c);
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

// ---- Vouched input: for vectors a scene vouches for (its own interpolated normals) ----
// The contract, on c = (x, y, max(z, 0)), the hemisphere's clamp of n (kept: an interpolated
// view-space normal at a silhouette can point slightly away from the camera): every component
// of n finite; every non-zero component of c at least 2^-126 max(1, |c|inf) in magnitude (no
// subnormals, and none so small beside the largest that hemioct_sanitize's scaling would make
// it subnormal); 0 < |c|inf = max(|x|, |y|, max(z, 0)) <= 2^124: normal_oct.wgsl's contract,
// applied to c, so a negative z may be any finite value (the clamp drops it). Within it each
// vouched encoder returns the robust encoder's code bit for bit on a correctly rounded adapter
// (hemioct_sanitize would change nothing but an exact power-of-two scale of c, which the
// projection c.xy / |c|_1 does not see), so the robust forms' error bounds hold. Outside it
// (NaN, +-Inf, subnormals, |c|inf > 2^124) WGSL leaves the result indeterminate: some u32, which
// the decoder accepts (bits 24-31 may be set; the decoder ignores them). |c|inf = 0 (the zero
// vector, or (0, 0, z <= 0)) is outside too: the precise vouched encoder still gives +z for it,
// as the robust one does (a max on the L1 norm), the fast one leaves it indeterminate (0 / 0).

// c = (x, y, max(z, 0)) times hemioct_sanitize's power of two 2^(127 - e), e the biased exponent
// of its largest magnitude: exact in the contract (every non-zero component stays at least
// 2^-126), so it is hemioct_sanitize's vector bit for bit; zero stays zero. The exponent is c's,
// not n's: scaled by |z| of a negative z, a small c would lose bits to underflow in the scores.
fn hemioct_scale_vouched(n: vec3<f32>) -> vec3<f32> {
    let c = vec3<f32>(n.xy, max(n.z, 0.0));
    let e = bitcast<u32>(max(max(abs(c.x), abs(c.y)), c.z)) >> 23u;
    return c * bitcast<f32>((254u - e) << 23u);
}

// hemioct_continuous of a vouched vector scaled by hemioct_scale_vouched, for the precise
// encoder: its L1 norm, in the contract at least 2^-126 (so unchanged), kept there, so a zero c
// gives p = 0, the code of +z, as hemioct_sanitize's +z does. (A copy rather than a shared
// helper, so hemioct_continuous, and the _fast encoder's SPIR-V, stay as they were.)
fn hemioct_continuous_vouched(s: vec3<f32>, m: u32) -> vec2<f32> {
    let l1 = max((abs(s.x) + abs(s.y)) + s.z, 1.1754943508222875e-38);
    let p = s.xy / l1;
    let q = vec2<f32>(p.x + p.y, p.x - p.y);
    return clamp(q * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(0.99999988079071044921875)) * f32(m);
}

// encode_normal_hemioct24 for a vector the scene vouches for (the contract above): no
// sanitising, the same choice.
fn encode_normal_hemioct24_vouched(n: vec3<f32>) -> u32 {
    let s = hemioct_scale_vouched(n);
    return hemioct_choose(s, hemioct_continuous_vouched(s, 4095u));
}

// encode_normal_hemioct24_fast for a vector the scene vouches for: unscaled (every sum of the
// L1 norm, of non-negative normal floats at most 3 * 2^124, commutes with the power of two, so
// does a correctly rounded quotient; the divisor lies in the spec's [2^-126, 2^126] for `/`),
// and without hemioct_continuous's clamp, which changes no code: |p.x| + |p.y| <= 1 up to a few
// ULP, so t = q/2 + 1/2 is in [0, 1] up to a few ULP, and round(t M) of a t above the clamp's
// top 1 - 2^-23 is M, as rounding the top gives; below 0 it is -0. The code u + v 2^12 is summed
// in f32 (whole numbers below 2^24: exact, fused or not) and converted once.
fn encode_normal_hemioct24_fast_vouched(n: vec3<f32>) -> u32 {
    let p = n.xy / ((abs(n.x) + abs(n.y)) + max(n.z, 0.0));
    let r = round((vec2<f32>(p.x + p.y, p.x - p.y) * 0.5 + 0.5) * 4095.0);
    return u32(r.y * 4096.0 + r.x);
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
