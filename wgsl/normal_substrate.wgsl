// prepass — Unreal 5 Substrate's 32-bit top-layer word: an octahedral normal on an 11:11 centred
// grid, 8 bits of perceptual roughness and 2 flag bits.
// Rust twin: src/normal/substrate.rs. Tests: tests/normal_substrate.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Source: Unreal Engine 5, Engine/Shaders/Private/Substrate/Substrate.ush, as summarised in
// prepass's survey of engine G-buffers; Unreal's source is not public and the search
// tools found no copy of that file, so the layout below is the survey's, not re-read from it:
// per axis the octahedral coordinate x in [-1, 1] is written as k = trunc(clamp(x*1023 + 1024,
// 0, 2047)) and read as x = (k - 1024)/1023; the word is normal22 << 10 | roughness8 << 2 |
// flags2. Assumed (not verified against the source): u (from x) in the low 11 bits of normal22
// (word bits 10-20), v (from y) in the high 11 (bits 21-31); roughness read as b/255.
// The fold is Unreal's UnitVectorToOctahedron / OctahedronToUnitVector (the survey's octahedron,
// lower half folded over the diagonals, the sign of 0 counting as +).
//
// The grid is centred: code 1024 is x = 0 exactly, codes 1..2047 span [-1, 1], and code 0 stands
// for x = -1024/1023, just outside the square; Unreal's fold still gives it a direction (the
// one just across the square's edge) and the decoder here returns that direction too. So the
// decoded vector before normalising is 1/1023 times the integer vector
// D = (a, b, 1023 - |a| - |b|), a = k_u - 1024, b = k_v - 1024, folded when that z < 0:
// D.xy = (a, b) + sgn(a, b) z, sgn(0) = +1 (= (1023 - |b|, 1023 - |a|) with a's and b's signs).
// Every value is an integer below 2^12: exact in f32 on any conforming adapter.
//
// Bad input: as the octahedral encoders (wgsl/normal_oct.wgsl): NaN anywhere, the zero vector
// and all-subnormal vectors encode as +z; subnormal components count as zero; infinite components
// win; any finite length is fine. Roughness as encode_roughness_ggx8 (wgsl/roughness_ggx.wgsl):
// the byte nearest 255 r, r clamped to [0, 1], NaN -> 255 (the roughest). Flags: only the low 2
// bits are stored. Decoders accept every bit pattern: a finite unit vector, a roughness in
// [0, 1], flags in [0, 3].
//
// Written to be evaluated identically everywhere it matters: no a*b+c whose fusion would change
// the result, NaN/Inf/subnormals found from bits. The helpers are file-local copies of
// normal_oct.wgsl's and roughness_ggx.wgsl's (WGSL has no imports; names are unique so the files
// compose).

// The input made safe (normal_oct.wgsl's oct_sanitize): NaN or zero -> none (w = 0); infinities
// -> their signs; subnormal components -> signed zero; then scaled by an exact power of two so
// the largest component lies in [1, 4). w = 1 when valid.
fn substrate_sanitize(n: vec3<f32>) -> vec4<f32> {
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

// The continuous centred coordinates q = 1023 p of a sanitized vector, p its octahedral
// projection (folded when s.z < 0), p clamped to [-1, 1 - 2^-23]: the code is q + 1024. The top
// keeps 1023 p below 1023 whichever way a conforming multiply rounds (the exact product,
// 1023 - 1023 2^-23, lies between 1023 - 2 ulp and 1023 - ulp), so floor(q) <= 1022 and the
// precise encoder's candidates floor + 1 stay codes; rounding still gives 1023 there. No add
// follows the multiply, so nothing can be fused.
fn substrate_continuous(s: vec3<f32>) -> vec2<f32> {
    let a = abs(s);
    let l1 = (a.x + a.y) + a.z;
    var p = s.xy / l1;
    if (s.z < 0.0) {
        // Lower hemisphere: fold over the diagonals. The sign of +-0 counts as +.
        let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
        p = (vec2<f32>(1.0) - abs(p.yx)) * sgn;
    }
    let t = clamp(p, vec2<f32>(-1.0), vec2<f32>(0.99999988079071044921875));
    return t * 1023.0;
}

// The precise choice for a scaled input s and its centred coordinates q: of the four codes
// floor(q) + {0, 1}^2 (+ 1024), the one whose integer direction D (header) is closest to s, by
// sin^2 of the angle (|s x D|^2 / |D|^2), first of equal scores in the order (0,0), (1,0),
// (0,1), (1,1) -- normal_oct.wgsl's oct_choose on the centred grid. The candidates' a, b lie in
// [-1023, 1023]; when z < 0 neither is 0, so clamp(a, -1, 1) is the sign. |D|_1 = 1023, so
// dot(d, d) <= 1023^2 < 2^24 is exact. Returns normal22 << 10 (u in bits 10-20, v in 21-31).
fn substrate_choose(s: vec3<f32>, q: vec2<f32>) -> u32 {
    let ab0 = floor(q);
    let ab1 = ab0 + vec2<f32>(1.0);
    let a = vec4<f32>(ab0.x, ab1.x, ab0.x, ab1.x);
    let b = vec4<f32>(ab0.y, ab0.y, ab1.y, ab1.y);
    let ta = vec2<f32>(1023.0) - abs(vec2<f32>(ab0.x, ab1.x));
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
    let sc = vec4<f32>(dot(x0, x0) / dot(d0, d0), dot(x1, x1) / dot(d1, d1), dot(x2, x2) / dot(d2, d2), dot(x3, x3) / dot(d3, d3));
    let j = min(sc.z, sc.w) < min(sc.x, sc.y);
    let i = select(sc.y < sc.x, sc.w < sc.z, j);
    let k = vec2<u32>(ab0 + vec2<f32>(1024.0)) + vec2<u32>(select(0u, 1u, i), select(0u, 1u, j));
    return (k.x << 10u) | (k.y << 21u);
}

// The integer direction D of centred codes k (header), in f32 (exact).
fn substrate_lattice(k: vec2<u32>) -> vec3<f32> {
    let ab = vec2<f32>(k) - vec2<f32>(1024.0);
    let z = 1023.0 - (abs(ab.x) + abs(ab.y));
    let sgn = select(vec2<f32>(-1.0), vec2<f32>(1.0), ab >= vec2<f32>(0.0));
    return vec3<f32>(ab + sgn * min(z, 0.0), z);
}

// The byte nearest 255 r for r in [0, 1], ties upwards; NaN, >= 1 and +Inf give 255; negative,
// -0 and -Inf give 0 (roughness_ggx.wgsl's ggx_linear_code at 8 bits; exact on every conforming
// adapter, see that file's header).
fn substrate_roughness_byte(r: f32) -> u32 {
    let b = bitcast<u32>(r);
    if ((b & 0x7fffffffu) > 0x7f800000u || (b < 0x80000000u && b >= 0x3f800000u)) {
        return 255u;
    }
    if (b >= 0x80000000u) {
        return 0u;
    }
    var k = min(u32(floor(r * 255.0 + 0.5)), 255u);
    let h = r * 256.0; // exact: a power-of-two scaling
    if (k > 0u && h - (f32(k) - 0.5) < r) {
        k = k - 1u;
    } else if (k < 255u && h - (f32(k) + 0.5) >= r) {
        k = k + 1u;
    }
    return k;
}

// The normal's bits of the word (roughness and flags zero) whose direction is closest to n among
// the four codes around it (near the square's edges a code mirrored across the edge can be
// closer still; the error stays within the rounding encoder's bound, see the Rust twin).
fn encode_substrate_normal(n: vec3<f32>) -> u32 {
    let s = substrate_sanitize(n).xyz;
    return substrate_choose(s, substrate_continuous(s));
}

// The normal's bits of the word by rounding each centred coordinate (half to even): cheaper,
// not always the closest direction.
fn encode_substrate_normal_fast(n: vec3<f32>) -> u32 {
    let k = vec2<u32>(round(substrate_continuous(substrate_sanitize(n).xyz)) + vec2<f32>(1024.0));
    return (k.x << 10u) | (k.y << 21u);
}

// The whole word: the closest normal, the roughness byte nearest 255 r, the low 2 bits of flags.
fn encode_substrate_word(n: vec3<f32>, roughness: f32, flags: u32) -> u32 {
    return encode_substrate_normal(n) | (substrate_roughness_byte(roughness) << 2u) | (flags & 3u);
}

// The whole word with the rounding normal encoder.
fn encode_substrate_word_fast(n: vec3<f32>, roughness: f32, flags: u32) -> u32 {
    return encode_substrate_normal_fast(n) | (substrate_roughness_byte(roughness) << 2u) | (flags & 3u);
}

// The unit normal of a word (its bits 10-31; every bit pattern decodes, code 0 included).
fn decode_substrate_normal(word: u32) -> vec3<f32> {
    return normalize(substrate_lattice(vec2<u32>((word >> 10u) & 0x7ffu, word >> 21u)));
}

// The perceptual roughness b/255 of the word's byte b (bits 2-9).
fn decode_substrate_roughness(word: u32) -> f32 {
    return f32((word >> 2u) & 0xffu) / 255.0;
}

// The word's 2 flag bits (bits 0-1).
fn substrate_flags(word: u32) -> u32 {
    return word & 3u;
}
