// prepass — octahedral unit-vector codes (Cigolle et al., "A Survey of Efficient Representations
// for Independent Unit Vectors", JCGT 2014), 2x8, 2x10, 2x12 and 2x16 bits.
// Rust twin: src/normal/oct.rs. Tests: tests/normal_oct.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Layout: u (from x) in the low N bits of the u32, v (from y) in the next N bits; the bits above
// 2N are left zero by the encoders and ignored by the decoders. Code k on an axis stands for the
// octahedron coordinate (2k - M)/M with M = 2^N - 1, so the decoded vector before normalising is
// the integer vector D = (2u - M, 2v - M, M - |2u - M| - |2v - M|) (folded when that z < 0),
// which every implementation computes exactly.
//
// Bad input (the robust encoders; the _vouched ones assume their contract, see "Vouched input"
// below): NaN anywhere, the zero vector and all-subnormal vectors encode as
// +z = (0, 0, 1); subnormal components count as zero; infinite components win (the direction of
// the infinities, e.g. (+Inf, 1, 0) -> +x); any finite length is fine (the map is scale-free).
// Decoders accept every bit pattern and return a finite unit vector.
//
// Written to be evaluated identically everywhere it matters: no a*b+c whose fusion would change
// the result (every multiply feeding an add is exact or goes through dot()/cross() as a whole),
// no common factors for an optimiser to pull out, NaN/Inf/subnormals found from bits.

// The input made safe: NaN or zero -> none (w = 0); infinities -> their signs; subnormal
// components -> signed zero; then scaled by an exact power of two so the largest component
// lies in [1, 4). w = 1 when valid.
fn oct_sanitize(n: vec3<f32>) -> vec4<f32> {
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
    let scale = bitcast<f32>(max(254u - e, 1u) << 23u);
    let s = c * scale;
    let sb = bitcast<vec3<u32>>(s);
    let s_sub = (sb & vec3<u32>(0x7f800000u)) == vec3<u32>(0u);
    return vec4<f32>(select(s, bitcast<vec3<f32>>(sb & vec3<u32>(0x80000000u)), s_sub), 1.0);
}

// The continuous code coordinates in [0, M)^2 of a sanitized vector (before rounding), M as an
// f32. The clamp stops two ULPs below 1, so t * M stays below M whichever way a conforming
// multiply rounds (for M < 2^24): floor() is then at most M - 1, and the precise encoder's
// candidates floor + 1 stay codes without a clamp of their own. Rounding still gives M there.
fn oct_continuous(s: vec3<f32>, m: f32) -> vec2<f32> {
    let a = abs(s);
    let l1 = (a.x + a.y) + a.z;
    var p = s.xy / l1;
    if (s.z < 0.0) {
        // Lower hemisphere: fold over the diagonals. The sign of +-0 counts as +.
        let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
        p = (vec2<f32>(1.0) - abs(p.yx)) * sgn;
    }
    // p * 0.5 is exact, so fusing the add cannot change the sum. 0.99999988... = 1 - 2^-23.
    let t = clamp(p * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(0.99999988079071044921875));
    return t * m;
}

// The integer direction D that code c (whole numbers, in f32) stands for (see the header), in
// f32: every value is an integer below 2^17, so every operation is exact on any conforming
// adapter, fused or not. z = M - |a| - |b|; when z < 0 the code is folded, and then
// |D.xy| = (M - |b|, M - |a|) = |(a, b)| + z. a and b are odd (M is odd), so sign() is +-1.
// mm is vec2(M), passed in so that a caller with a constant M pays for no splat.
fn oct_lattice(c: vec2<f32>, m: f32, mm: vec2<f32>) -> vec3<f32> {
    let ab = (c + c) - mm;
    let z = m - dot(abs(ab), vec2<f32>(1.0));
    return vec3<f32>(ab + sign(ab) * min(z, 0.0), z);
}

// One step of the precise encoder's choice: the code c00 + off, scored by sin^2 of the angle
// between s and its direction D (|s x D|^2 / |D|^2, up to the common factor |s|^2), replaces
// the best so far (code in xy, score in z) only if its score is strictly smaller. Sine, not
// cosine: at oct32's 2e-5 rad a cosine is 1.0 in f32. One function for the score and the step:
// the four candidates share its code. |D|^2 as a float dot is exact while M^2 < 2^24 (8 and
// 12 bits per axis: integer squares and sums below 2^24), so it is the once-rounded |D|^2.
fn oct_try(s: vec3<f32>, m: f32, c00: vec2<f32>, off: vec2<f32>, best: vec3<f32>) -> vec3<f32> {
    let c = c00 + off;
    let d = oct_lattice(c, m, vec2<f32>(m));
    let x = cross(s, d);
    let score = dot(x, x) / dot(d, d);
    return select(best, vec3<f32>(c, score), score < best.z);
}

// oct_try for 16 bits per axis (M = 65535 written in), where |D|^2 (up to M^2 < 2^32) needs
// 32 bits: summed exactly in u32 and rounded once, as the narrower codes' dot is. A float dot
// would round each square and could flip a near-tie. Each |D| component k (a whole number, at
// most 65535) is read as an integer from the bits of k + 2^23, 0x4b000000 + k (the sum is
// exact): its low 16 bits are k, and the mask tells the compiler the squares are 16 x 16 bits
// (a full-rate multiply, where u32(k) would be clamped and multiplied at 32 bits). The choice reads the z lane of one
// vector compare (an instruction fewer than a scalar compare splatted to the select).
fn oct_try_wide(s: vec3<f32>, c00: vec2<f32>, off: vec2<f32>, best: vec3<f32>) -> vec3<f32> {
    let c = c00 + off;
    let d = oct_lattice(c, 65535.0, vec2<f32>(65535.0));
    let x = cross(s, d);
    let q = bitcast<vec3<u32>>(abs(d) + vec3<f32>(8388608.0)) & vec3<u32>(0xffffu);
    let sq = q * q;
    let cand = vec3<f32>(c, dot(x, x) / f32(sq.x + sq.y + sq.z));
    return select(best, cand, (cand < best).zzz);
}

// The survey's precise encoder, 8 or 12 bits per axis: of the four codes around the continuous
// coordinates (floor and floor + 1 per axis), the one whose decoded direction is closest to s,
// by oct_try's score (sin^2 of the angle, |s x D|^2 / |D|^2, the same expression per candidate);
// of equal scores the first in the order (0,0), (1,0), (0,1), (1,1), as oct_try's chain of
// strict comparisons chooses. Straight-line; written out rather than as four oct_try calls so
// that the candidates share their common parts:
// - D per candidate by oct_lattice's formula with (a_i, b_j) = 2 c - M, i, j in {0, 1} (lanes
//   (0,0), (1,0), (0,1), (1,1)): z = (M - |a_i|) - |b_j| (M - |a_i| once per i) and
//   (x, y) = (a, b) + sign(a, b) min(z, 0), sign() as clamp(, -1, 1) (a and b are odd). Every
//   value is an integer below 2^17, so every operation is exact on any conforming adapter,
//   fused or not, and each D is oct_lattice's bit for bit;
// - the choice as a tree: j = 1 if the (0,1)/(1,1) pair's smaller score is strictly below the
//   other pair's, then i within the chosen pair (strictly smaller second): the first of the
//   smallest, as the chain; scores are finite (below 48), so no NaN reaches a comparison;
// - the code from the bits of c00 + 2^23 (0x4b000000 + c00, exact): the bias of the high half
//   shifts out of the u32 (bits >= 8), the low half's is taken off.
fn oct_encode_precise(n: vec3<f32>, bits: u32) -> u32 {
    let s = oct_sanitize(n).xyz;
    return oct_choose(s, oct_continuous(s, f32((1u << bits) - 1u)), bits);
}

// The precise encoders' choice for a scaled input s (largest magnitude in [1, 4), or zero) and
// its continuous coordinates c: the body of oct_encode_precise, shared with the vouched form.
fn oct_choose(s: vec3<f32>, c: vec2<f32>, bits: u32) -> u32 {
    let m = f32((1u << bits) - 1u);
    let c00 = floor(c);
    let ab0 = (c00 + c00) - vec2<f32>(m);
    let ab1 = ab0 + vec2<f32>(2.0);
    let a = vec4<f32>(ab0.x, ab1.x, ab0.x, ab1.x);
    let b = vec4<f32>(ab0.y, ab0.y, ab1.y, ab1.y);
    let ta = vec2<f32>(m) - abs(vec2<f32>(ab0.x, ab1.x));
    let z = vec4<f32>(ta, ta) - abs(b);
    let mz = min(z, vec4<f32>(0.0));
    let x = a + clamp(a, vec4<f32>(-1.0), vec4<f32>(1.0)) * mz;
    let y = b + clamp(b, vec4<f32>(-1.0), vec4<f32>(1.0)) * mz;
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
    return (w.x + (w.y << bits)) - 0x4b000000u;
}

// oct_encode_precise at 16 bits per axis, with oct_try_wide's exact |D|^2 (a u32 sum of the
// squares, rounded once; each square from the bits of |D_k| + 2^23, see oct_try_wide).
fn oct_encode_precise_wide(n: vec3<f32>) -> u32 {
    let s = oct_sanitize(n).xyz;
    return oct_choose_wide(s, oct_continuous(s, 65535.0));
}

// oct_choose at 16 bits per axis: the body of oct_encode_precise_wide, shared with the vouched
// form.
fn oct_choose_wide(s: vec3<f32>, c: vec2<f32>) -> u32 {
    let m = 65535.0;
    let c00 = floor(c);
    let ab0 = (c00 + c00) - vec2<f32>(m);
    let ab1 = ab0 + vec2<f32>(2.0);
    let a = vec4<f32>(ab0.x, ab1.x, ab0.x, ab1.x);
    let b = vec4<f32>(ab0.y, ab0.y, ab1.y, ab1.y);
    let ta = vec2<f32>(m) - abs(vec2<f32>(ab0.x, ab1.x));
    let z = vec4<f32>(ta, ta) - abs(b);
    let mz = min(z, vec4<f32>(0.0));
    let x = a + clamp(a, vec4<f32>(-1.0), vec4<f32>(1.0)) * mz;
    let y = b + clamp(b, vec4<f32>(-1.0), vec4<f32>(1.0)) * mz;
    let d0 = vec3<f32>(x.x, y.x, z.x);
    let d1 = vec3<f32>(x.y, y.y, z.y);
    let d2 = vec3<f32>(x.z, y.z, z.z);
    let d3 = vec3<f32>(x.w, y.w, z.w);
    let x0 = cross(s, d0);
    let x1 = cross(s, d1);
    let x2 = cross(s, d2);
    let x3 = cross(s, d3);
    let big = vec4<f32>(8388608.0);
    let mask = vec4<u32>(0xffffu);
    let qx = bitcast<vec4<u32>>(abs(x) + big) & mask;
    let qy = bitcast<vec4<u32>>(abs(y) + big) & mask;
    let qz = bitcast<vec4<u32>>(abs(z) + big) & mask;
    let dd = vec4<f32>((qx * qx + qy * qy) + qz * qz);
    let q = vec4<f32>(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)) / dd;
    let j = min(q.z, q.w) < min(q.x, q.y);
    let i = select(q.y < q.x, q.w < q.z, j);
    let w = bitcast<vec2<u32>>(c00 + vec2<f32>(8388608.0)) + vec2<u32>(select(0u, 1u, i), select(0u, 1u, j));
    return (w.x + (w.y << 16u)) - 0x4b000000u;
}

// The plain rounding encoder: nearest code per axis (round half to even).
fn oct_encode_round(n: vec3<f32>, bits: u32) -> u32 {
    let m = f32((1u << bits) - 1u);
    let uv = vec2<u32>(round(oct_continuous(oct_sanitize(n).xyz, m)));
    return uv.x | (uv.y << bits);
}

// ---- Vouched input: for vectors a scene vouches for (its own interpolated normals) ----
// The contract: every component finite; every non-zero component at least 2^-126 max(1, |n|inf)
// in magnitude (no subnormals, and none so small beside the largest that oct_sanitize's scaling
// would make it subnormal); 0 < |n|inf = max(|x|, |y|, |z|) <= 2^124. Within it each vouched
// encoder returns the robust encoder's code bit for bit on a correctly rounded adapter
// (oct_sanitize would change nothing but an exact power-of-two scale, and the projection
// s.xy / |s|_1 does not see that scale), so the robust forms' error bounds hold; on any
// conforming adapter every intermediate is finite and each axis a code in [0, M]. Outside it
// (NaN, +-Inf, subnormals, |n|inf > 2^124) WGSL leaves the result indeterminate: some u32,
// which every decoder accepts (bits above 2N may be set; the decoders ignore them). The zero
// vector is outside too: the precise vouched encoders still give +z for it, as the robust ones
// (one max in about 130 instructions), the fast ones leave it indeterminate (0 / 0).

// The octahedral projection (oct_continuous's p, before the map to codes) of a vouched vector
// n with l1 = |n|_1 (or more, for the zero vector): n.xy / l1, folded when n.z < 0 (the sign
// of +-0 counts as +). In the contract |n|_1, a sum of non-negative normal floats, lies in
// [2^-126, 3 * 2^124]: no overflow, and the divisor inside the spec's [2^-126, 2^126] for `/`.
fn oct_project_vouched(n: vec3<f32>, l1: f32) -> vec2<f32> {
    let p = n.xy / l1;
    if (n.z < 0.0) {
        let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
        return (vec2<f32>(1.0) - abs(p.yx)) * sgn;
    }
    return p;
}

// A vouched vector times oct_sanitize's power of two 2^(127 - e), e the biased exponent of its
// largest magnitude (largest then in [1, 2)): exact in the contract (every non-zero component
// stays at least 2^-126), so it is oct_sanitize's vector bit for bit; zero stays zero. The
// precise encoders' scores need it (|s x D|^2 of an unscaled 2^124 would overflow).
fn oct_scale_vouched(n: vec3<f32>) -> vec3<f32> {
    let a = abs(n);
    let e = bitcast<u32>(max(max(a.x, a.y), a.z)) >> 23u;
    return n * bitcast<f32>((254u - e) << 23u);
}

// The continuous code coordinates (as oct_continuous's) of a vouched vector scaled by
// oct_scale_vouched, for the precise encoders: its L1 norm kept at least 2^-126, which changes
// no in-contract vector and gives the zero vector p = 0, the code of +z, as oct_sanitize's +z.
fn oct_continuous_vouched(s: vec3<f32>, m: f32) -> vec2<f32> {
    let a = abs(s);
    let p = oct_project_vouched(s, max((a.x + a.y) + a.z, 1.1754943508222875e-38));
    let t = clamp(p * 0.5 + 0.5, vec2<f32>(0.0), vec2<f32>(0.99999988079071044921875));
    return t * m;
}

// oct_encode_precise for a vouched vector: no sanitising, the same choice.
fn oct_encode_precise_vouched(n: vec3<f32>, bits: u32) -> u32 {
    let s = oct_scale_vouched(n);
    return oct_choose(s, oct_continuous_vouched(s, f32((1u << bits) - 1u)), bits);
}

// oct_encode_precise_wide for a vouched vector.
fn oct_encode_precise_wide_vouched(n: vec3<f32>) -> u32 {
    let s = oct_scale_vouched(n);
    return oct_choose_wide(s, oct_continuous_vouched(s, 65535.0));
}

// The rounding encoder's code per axis, round(t M) (half to even), for a vouched vector:
// unscaled, and without oct_continuous's clamp, which changes no code: p is in [-1, 1] up to
// the division's error, so t = p/2 + 1/2 is in [0, 1] up to a few ULP, and round(t M) of a t
// above oct_continuous's top 1 - 2^-23 is M, as rounding the top gives; below 0 it is -0.
fn oct_round_vouched(n: vec3<f32>, m: f32) -> vec2<f32> {
    let a = abs(n);
    let t = oct_project_vouched(n, (a.x + a.y) + a.z) * 0.5 + 0.5;
    return round(t * m);
}

// oct_encode_round for a vouched vector, 8 or 12 bits per axis: the code u + v 2^bits summed in
// f32 (whole numbers below 2^24: exact, fused or not) and converted once.
fn oct_encode_round_vouched(n: vec3<f32>, bits: u32) -> u32 {
    let r = oct_round_vouched(n, f32((1u << bits) - 1u));
    return u32(r.y * f32(1u << bits) + r.x);
}

// oct_encode_round_vouched at 16 bits per axis, where u + v 2^16 needs 32 bits: each axis read
// from the bits of round(t M) + 2^23 (exact), as oct_encode_precise reads its code: the bias of
// v shifts out of the u32, u's is taken off.
fn oct_encode_round_wide_vouched(n: vec3<f32>) -> u32 {
    let w = bitcast<vec2<u32>>(oct_round_vouched(n, 65535.0) + vec2<f32>(8388608.0));
    return (w.x + (w.y << 16u)) - 0x4b000000u;
}

// The unit vector of code p with `bits` bits per axis: its integer direction D, normalised.
fn oct_decode(p: u32, bits: u32) -> vec3<f32> {
    let m = (1u << bits) - 1u;
    let uv = vec2<u32>(p & m, (p >> bits) & m);
    let mf = f32(m);
    return normalize(oct_lattice(vec2<f32>(uv), mf, vec2<f32>(mf)));
}

// Byte k of the u32 from a unorm8 channel: round(255 c), c taken to [0, 1] from its bits (NaN,
// negative values and -0 count as 0, values from 1 up to +Inf as 1: no float operation sees a
// non-finite channel).
fn oct_unorm_bytes(c: vec4<f32>) -> u32 {
    let bits = bitcast<vec4<u32>>(c);
    let x = select(select(bits, vec4<u32>(0x3f800000u), bits >= vec4<u32>(0x3f800000u)), vec4<u32>(0u), bits > vec4<u32>(0x7f800000u));
    let b = vec4<u32>(round(bitcast<vec4<f32>>(x) * 255.0));
    return b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u);
}

// ---- 2 x 8 bits (RG8) ----
// The 2x8-bit code whose direction is closest to n: u in bits 0-7, v in bits 8-15.
fn encode_normal_oct16(n: vec3<f32>) -> u32 {
    return oct_encode_precise(n, 8u);
}
// The 2x8-bit code by rounding each axis: cheaper, not always the closest direction.
fn encode_normal_oct16_fast(n: vec3<f32>) -> u32 {
    return oct_encode_round(n, 8u);
}
// encode_normal_oct16 for a vector the scene vouches for (the contract above the vouched
// helpers): the same code, without the bad-input handling.
fn encode_normal_oct16_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_precise_vouched(n, 8u);
}
// encode_normal_oct16_fast for a vector the scene vouches for: the same code, cheaper.
fn encode_normal_oct16_fast_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_round_vouched(n, 8u);
}
// The unit vector of a 2x8-bit code; bits 16-31 are ignored.
fn decode_normal_oct16(p: u32) -> vec3<f32> {
    return oct_decode(p, 8u);
}
// Render-target form: the rg8unorm channels to write, and the decode of sampled channels
// (bytes rounded back, so exact under unpack4x8unorm's 3-ULP error or a +-0.49/255 filter).
fn encode_normal_oct16_unorm(n: vec3<f32>) -> vec2<f32> {
    return unpack4x8unorm(encode_normal_oct16(n)).xy;
}
// The unit vector from sampled rg8unorm channels (bytes rounded back, then decoded).
fn decode_normal_oct16_unorm(c: vec2<f32>) -> vec3<f32> {
    return oct_decode(oct_unorm_bytes(vec4<f32>(c, 0.0, 0.0)), 8u);
}

// ---- 2 x 10 bits (R and G of an RGB10A2 texel; B's 10 bits and A's 2 left to the renderer) ----
// The 2x10-bit code whose direction is closest to n: u in bits 0-9, v in bits 10-19.
fn encode_normal_oct20(n: vec3<f32>) -> u32 {
    return oct_encode_precise(n, 10u);
}
// The 2x10-bit code by rounding each axis: cheaper, not always the closest direction.
fn encode_normal_oct20_fast(n: vec3<f32>) -> u32 {
    return oct_encode_round(n, 10u);
}
// The unit vector of a 2x10-bit code; bits 20-31 are ignored.
fn decode_normal_oct20(p: u32) -> vec3<f32> {
    return oct_decode(p, 10u);
}
// Render-target form: the rgb10a2unorm channels to write, u/1023 and v/1023 in R and G (B and A
// 0 here: they are the renderer's, e.g. a 10-bit roughness and two flag bits; the decoder
// ignores them). Any conforming write converts k/1023 back to k.
fn encode_normal_oct20_unorm(n: vec3<f32>) -> vec4<f32> {
    let p = encode_normal_oct20(n);
    return vec4<f32>(vec2<f32>(vec2<u32>(p, p >> 10u) & vec2<u32>(0x3ffu)) / 1023.0, 0.0, 0.0);
}
// The unit vector from sampled rgb10a2unorm channels R and G: each taken to [0, 1] from its bits
// (NaN, negative values and -0 count as 0, values from 1 up to +Inf as 1, so no float operation
// sees a non-finite channel) and rounded back to its code, round(1023 c). B and A ignored.
fn decode_normal_oct20_unorm(c: vec4<f32>) -> vec3<f32> {
    let b = bitcast<vec2<u32>>(c.xy);
    let x = select(select(b, vec2<u32>(0x3f800000u), b >= vec2<u32>(0x3f800000u)), vec2<u32>(0u), b > vec2<u32>(0x7f800000u));
    let k = vec2<u32>(round(bitcast<vec2<f32>>(x) * 1023.0));
    return oct_decode(k.x | (k.y << 10u), 10u);
}
// ---- 2 x 12 bits (three bytes of an RGBA8 texel; alpha left zero for the material) ----
// The 2x12-bit code whose direction is closest to n: u in bits 0-11, v in bits 12-23.
fn encode_normal_oct24(n: vec3<f32>) -> u32 {
    return oct_encode_precise(n, 12u);
}
// The 2x12-bit code by rounding each axis: cheaper, not always the closest direction.
fn encode_normal_oct24_fast(n: vec3<f32>) -> u32 {
    return oct_encode_round(n, 12u);
}
// encode_normal_oct24 for a vector the scene vouches for (the contract above the vouched
// helpers): the same code, without the bad-input handling.
fn encode_normal_oct24_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_precise_vouched(n, 12u);
}
// encode_normal_oct24_fast for a vector the scene vouches for: the same code, cheaper.
fn encode_normal_oct24_fast_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_round_vouched(n, 12u);
}
// The unit vector of a 2x12-bit code; bits 24-31 are ignored.
fn decode_normal_oct24(p: u32) -> vec3<f32> {
    return oct_decode(p, 12u);
}
// The rgba8unorm channels to write for encode_normal_oct24(n) (alpha 0, for the material).
fn encode_normal_oct24_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_oct24(n));
}
// The unit vector from sampled rgba8unorm channels (bytes rounded back; alpha ignored).
fn decode_normal_oct24_unorm(c: vec4<f32>) -> vec3<f32> {
    return oct_decode(oct_unorm_bytes(c), 12u);
}

// ---- 2 x 16 bits (a whole RGBA8 texel, or RG16) ----
// The 2x16-bit code whose direction is closest to n: u in bits 0-15, v in bits 16-31.
fn encode_normal_oct32(n: vec3<f32>) -> u32 {
    return oct_encode_precise_wide(n);
}
// The 2x16-bit code by rounding each axis: cheaper, not always the closest direction.
fn encode_normal_oct32_fast(n: vec3<f32>) -> u32 {
    return oct_encode_round(n, 16u);
}
// encode_normal_oct32 for a vector the scene vouches for (the contract above the vouched
// helpers): the same code, without the bad-input handling.
fn encode_normal_oct32_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_precise_wide_vouched(n);
}
// encode_normal_oct32_fast for a vector the scene vouches for: the same code, cheaper.
fn encode_normal_oct32_fast_vouched(n: vec3<f32>) -> u32 {
    return oct_encode_round_wide_vouched(n);
}
// The unit vector of a 2x16-bit code (every bit pattern decodes).
fn decode_normal_oct32(p: u32) -> vec3<f32> {
    return oct_decode(p, 16u);
}
// The rgba8unorm channels to write for encode_normal_oct32(n) (all four bytes of the code).
fn encode_normal_oct32_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_oct32(n));
}
// The unit vector from sampled rgba8unorm channels (bytes rounded back, then decoded).
fn decode_normal_oct32_unorm(c: vec4<f32>) -> vec3<f32> {
    return oct_decode(oct_unorm_bytes(c), 16u);
}

// ---- 2 x 12 bits in Unity's bytes (HDRP's normal buffer, URP's accurate G-buffer normals) ----
// Unity (com.unity.render-pipelines.core, ShaderLibrary/Packing.hlsl: PackFloat2To888 and
// Unpack888ToFloat2 around PackNormalOctQuadEncode) stores oct24's grid -- code k stands for
// k/4095 in [0, 1], read back as k/4095 * 2 - 1 -- in other bytes: byte 0 the low 8 bits of u,
// byte 1 the low 8 bits of v, byte 2 the high 4 bits of u | the high 4 bits of v << 4. These
// functions are oct24's with that byte order; byte 3 is left zero (HDRP keeps the perceptual
// smoothness there) and ignored. Unity's own quantiser, u32(f * 4095.5), is neither round nor
// floor; the encoders here write the closest code (or the rounded one, _fast).

// oct24's word (u in bits 0-11, v in 12-23) in Unity's byte order.
fn oct_unity_bytes(p: u32) -> u32 {
    let u = p & 0xfffu;
    let v = (p >> 12u) & 0xfffu;
    return (u & 0xffu) | ((v & 0xffu) << 8u) | ((u >> 8u) << 16u) | ((v >> 8u) << 20u);
}

// Unity's bytes as oct24's word; byte 3 ignored.
fn oct_unity_word(p: u32) -> u32 {
    let u = (p & 0xffu) | (((p >> 16u) & 0xfu) << 8u);
    let v = ((p >> 8u) & 0xffu) | (((p >> 20u) & 0xfu) << 8u);
    return u | (v << 12u);
}

// The 2x12-bit code whose direction is closest to n, in Unity's bytes.
fn encode_normal_oct24_unity(n: vec3<f32>) -> u32 {
    return oct_unity_bytes(encode_normal_oct24(n));
}
// The 2x12-bit code, in Unity's bytes, that HDRP's reader takes as its own writer's
// (EncodeIntoNormalBuffer, com.unity.render-pipelines.high-definition/Runtime/Material/
// NormalBuffer.hlsl): the closest code to n after |z| is raised to at least |n|/1024 (HDRP's
// 1/1024 for unit normals), z's sign kept (-0 as +), so that z's sign survives the G-buffer.
// encode_normal_oct24_unity floors nothing (as URP writes). The bytes are not HDRP's own
// (it quantises by u32(f * 4095.5)); the direction is closer.
fn encode_normal_oct24_hdrp(n: vec3<f32>) -> u32 {
    let s = oct_sanitize(n).xyz;
    let za = max(abs(s.z), length(s) * (1.0 / 1024.0));
    let h = vec3<f32>(s.xy, select(-za, za, s.z >= 0.0));
    return oct_unity_bytes(oct_choose(h, oct_continuous(h, 4095.0), 12u));
}
// The 2x12-bit code by rounding each axis, in Unity's bytes.
fn encode_normal_oct24_unity_fast(n: vec3<f32>) -> u32 {
    return oct_unity_bytes(encode_normal_oct24_fast(n));
}
// The unit vector of a 2x12-bit code in Unity's bytes; byte 3 is ignored.
fn decode_normal_oct24_unity(p: u32) -> vec3<f32> {
    return decode_normal_oct24(oct_unity_word(p));
}
// Render-target form: the rgba8unorm channels to write (alpha 0: Unity's smoothness goes there).
fn encode_normal_oct24_unity_unorm(n: vec3<f32>) -> vec4<f32> {
    return unpack4x8unorm(encode_normal_oct24_unity(n));
}
// The unit vector from sampled rgba8unorm channels in Unity's bytes (bytes rounded back; alpha
// ignored).
fn decode_normal_oct24_unity_unorm(c: vec4<f32>) -> vec3<f32> {
    return decode_normal_oct24_unity(oct_unorm_bytes(c));
}
