// prepass — 24-bit depth codes stored in RGBA8 texels.
// Rust twin: src/depth24.rs. Tests: tests/depth24.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Byte 0 (r, the low byte of a packed u32) holds the code's most significant byte, byte 2 (b)
// the least; byte 3 (alpha) is not part of the code.

// Recover a 24-bit code from the unorm channels a sampler returns. Each channel is rounded back
// to its byte before the bytes are weighted: unrounded, the 65536 weight on r magnifies the
// channel's conversion error (3 ULP in WGSL's unpack4x8unorm, more on some texture units) into
// wrong codes. Exact while every channel is within ±0.49/255 of byte/255.
// Bad input: each channel is taken to [0, 1] from its bits, which finite-math optimisation cannot
// remove: NaN, negative values and -0 count as 0, values from 1 up to +Inf as 1, so no float
// operation sees a non-finite channel.
fn depth24_from_rgb8(rgb: vec3<f32>) -> u32 {
    let bits = bitcast<vec3<u32>>(rgb);
    let x = select(select(bits, vec3<u32>(0x3f800000u), bits >= vec3<u32>(0x3f800000u)), vec3<u32>(0u), bits > vec3<u32>(0x7f800000u));
    let b = vec3<u32>(round(bitcast<vec3<f32>>(x) * 255.0));
    return (b.x << 16u) | (b.y << 8u) | b.z;
}

// Recover a 24-bit code from a texel read as one u32 (rgba8uint view or storage buffer), by bit
// operations: byte 0 is the most significant byte, byte 3 is ignored.
fn depth24_from_packed(p: u32) -> u32 {
    return ((p & 0xffu) << 16u) | (p & 0xff00u) | ((p >> 16u) & 0xffu);
}

// A 24-bit code to the u32 whose bytes an RGBA8 target stores (r = most significant byte,
// alpha = 0). Codes above 2^24 - 1 saturate to 2^24 - 1.
fn pack_depth24(d: u32) -> u32 {
    let c = min(d, 0xffffffu);
    return ((c >> 16u) & 0xffu) | (c & 0xff00u) | ((c & 0xffu) << 16u);
}

// d / (2^24 - 1), correctly rounded to f32, from integer operations only.
// The quotient's binary expansion is the 24-bit code repeated forever, so its f32 significand is
// the code rotated left by its leading-zero count, and the bits below (that rotation again, a
// fraction m/(2^24-1) > 1/2 of an ULP, never a tie) always round it up by one ULP.
// Codes above 2^24 - 1 saturate to 1.0.
fn hyperbolic_depth_from_depth24(d: u32) -> f32 {
    let code = min(d, 0xffffffu);
    if (code == 0u) {
        return 0.0;
    }
    if (code == 0xffffffu) {
        return 1.0;
    }
    let lz = countLeadingZeros(code) - 8u;
    let m = ((code << lz) | (code >> (24u - lz))) & 0xffffffu;
    return bitcast<f32>(((126u - lz) << 23u) + (m + 1u - 0x800000u));
}
