// prepass — GGX perceptual roughness r in 8 bits, as the engines store it (alpha = r^2): linear r
// in a unorm8 channel (Bevy, Unreal's GBuffer, Unity HDRP), URP's smoothness 1 - r, Unreal
// Substrate's truncated byte, Godot's 7 bits plus a dynamic-object flag, and a log curve on r
// (hence on alpha) that prepass measures against them.
// Rust twin: src/roughness_ggx.rs. Tests: tests/roughness_ggx.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// GGX (Walter, Marschner, Li, Torrance, "Microfacet Models for Refraction through Rough
// Surfaces", EGSR 2007) with Burley's perceptual remapping alpha = r^2 (Brent Burley, "Physically
// Based Shading at Disney", SIGGRAPH 2012 course): D(n.h) = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
//
// Encoders (Substrate's aside: it truncates, as PackR8) pick the code nearest to r exactly (no f32 rounding of n·r can move a code): the
// candidate floor(n·r + 1/2) from f32 arithmetic is within one code, and the boundary between
// codes j and j+1, r = (j + 1/2)/n with n = 2^m - 1, is tested as (2^m·r - (j + 1/2)) >= r,
// whose subtraction is exact (Sterbenz) wherever the test is close. Ties (only r = 1/2 is one)
// go upwards. So the codes are exact on every conforming adapter, and equal the Rust twin's.
//
// Bad input (same on both sides): NaN encodes as the roughest code (r = 1, the lobe with the
// lowest peak); negative values, -0, subnormals and -Inf encode as 0 (the log curve: its
// smoothest code, r = 2^-6); +Inf and anything >= 1 as the roughest code. Codes above 255 decode
// as 255. A render-target channel that is NaN counts as 0; channels are clamped to [0, 1].

// The code nearest n·r for r in [0, 1], n = 2^m - 1 (scale = 2^m = n + 1), ties upwards; NaN
// gives n. Exact: see the header.
fn ggx_linear_code(r: f32, scale: f32) -> u32 {
    let b = bitcast<u32>(r);
    let n = scale - 1.0;
    if ((b & 0x7fffffffu) > 0x7f800000u || (b < 0x80000000u && b >= 0x3f800000u)) {
        return u32(n); // NaN, >= 1, +Inf
    }
    if (b >= 0x80000000u) {
        return 0u; // negative, -0, -Inf
    }
    var k = min(u32(floor(r * n + 0.5)), u32(n));
    let h = r * scale; // exact: a power-of-two scaling
    if (k > 0u && h - (f32(k) - 0.5) < r) {
        k = k - 1u;
    } else if (k < u32(n) && h - (f32(k) + 0.5) >= r) {
        k = k + 1u;
    }
    return k;
}

// The byte of a unorm8 channel value: round(255 c), c taken to [0, 1] from its bits (NaN,
// negative values and -0 count as 0, values from 1 up to +Inf as 1: no float operation sees a
// non-finite channel).
fn ggx_unorm_byte(c: f32) -> u32 {
    let bits = bitcast<u32>(c);
    let x = select(select(bits, 0x3f800000u, bits >= 0x3f800000u), 0u, bits > 0x7f800000u);
    return u32(round(bitcast<f32>(x) * 255.0));
}

// ---- linear r in 8 bits (Bevy, Unreal's GBuffer, HDRP) ----

// The byte nearest 255·r (r clamped to [0, 1]; NaN -> 255), ties upwards.
fn encode_roughness_ggx8(r: f32) -> u32 {
    return ggx_linear_code(r, 256.0);
}

// The perceptual roughness b/255 of byte b, as a unorm8 channel reads; codes above 255 read as 255.
fn decode_roughness_ggx8(p: u32) -> f32 {
    return f32(min(p, 255u)) / 255.0;
}

// GGX alpha = r^2 of byte b (the square of decode_roughness_ggx8, rounded once more).
fn decode_roughness_ggx8_alpha(p: u32) -> f32 {
    let r = decode_roughness_ggx8(p);
    return r * r;
}

// Render-target form: the r8unorm channel to write for encode_roughness_ggx8(r).
fn encode_roughness_ggx8_unorm(r: f32) -> f32 {
    return unpack4x8unorm(encode_roughness_ggx8(r)).x;
}

// The roughness from a sampled r8unorm channel: the byte rounded back (so unpack4x8unorm's 3-ULP
// error or a +-0.49/255 filter cannot change it), then decoded.
fn decode_roughness_ggx8_unorm(c: f32) -> f32 {
    return decode_roughness_ggx8(ggx_unorm_byte(c));
}

// ---- Unity URP: smoothness 1 - r in GBuffer2's alpha (UnityGBuffer.hlsl) ----

// URP's smoothness byte for roughness r: 255 - encode_roughness_ggx8(r), the byte nearest
// 255 (1 - r) exactly (the tie r = 1/2 goes to 127). NaN -> 0 (smoothness 0, the roughest).
fn encode_roughness_urp8(r: f32) -> u32 {
    return 255u - encode_roughness_ggx8(r);
}

// The roughness 1 - b/255 of URP's smoothness byte b, as (255 - b)/255 (one rounding); codes
// above 255 read as 255 (r = 0).
fn decode_roughness_urp8(p: u32) -> f32 {
    return decode_roughness_ggx8(255u - min(p, 255u));
}

// Render-target form: the r8unorm channel (URP's GBuffer2 alpha) to write for
// encode_roughness_urp8(r).
fn encode_roughness_urp8_unorm(r: f32) -> f32 {
    return unpack4x8unorm(encode_roughness_urp8(r)).x;
}

// The roughness from a sampled URP smoothness channel: the byte rounded back, then decoded.
fn decode_roughness_urp8_unorm(c: f32) -> f32 {
    return decode_roughness_urp8(ggx_unorm_byte(c));
}

// ---- Unreal Substrate: PackR8 / UnpackR8 (Unreal's shader library, as Substrate.ush calls them) ----

// Substrate's roughness byte, uint(saturate(r) * 255): truncated, Unreal's bytes where the
// product rounds as Unreal's GPU rounds it. +0 <= r < 1 exactly when its bits are below 1's;
// elsewhere (NaN, +-Inf, r >= 1, negative values, -0) the linear encoder's code (NaN -> 255).
fn encode_roughness_substrate8(r: f32) -> u32 {
    if (bitcast<u32>(r) < 0x3f800000u) {
        return u32(r * 255.0);
    }
    return encode_roughness_ggx8(r);
}

// Substrate's UnpackR8, b * (1/255): the reciprocal rounded to f32, one more rounding; codes
// above 255 read as 255.
fn decode_roughness_substrate8(p: u32) -> f32 {
    return f32(min(p, 255u)) * (1.0 / 255.0);
}

// ---- Godot 4 (Forward+): 7 bits of roughness and a dynamic-object flag in one unorm8 ----
// Godot writes w = r·127/255 to the normal-roughness buffer's alpha, and 1 - w for dynamic
// objects (servers/rendering/renderer_rd/shaders/forward_clustered/scene_forward_clustered.glsl,
// MODE_RENDER_NORMAL_ROUGHNESS), and reads it back with normal_roughness_compatibility
// (forward_clustered/scene_forward_clustered_inc.glsl): c > 0.5 is dynamic and becomes 1 - c,
// then r = c / (127/255). As bytes: k = round(127 r) for static objects, 255 - k for dynamic
// ones, so bit 7 is the flag and the low 7 bits are k, or 127 - k for dynamic objects.

// The byte for roughness r (k nearest 127·r, ties upwards; NaN -> 127) and the flag
// (dynamic_object != 0): k, or 255 - k for a dynamic object.
fn encode_roughness_godot8(r: f32, dynamic_object: u32) -> u32 {
    let k = ggx_linear_code(r, 128.0);
    return select(k, 255u - k, dynamic_object != 0u);
}

// The roughness of a Godot byte, computed as Godot computes it from the channel b/255: c > 0.5
// (a dynamic object) becomes 1 - c, then c / (127/255). Codes above 255 read as 255.
fn decode_roughness_godot8(p: u32) -> f32 {
    let c = f32(min(p, 255u)) / 255.0;
    let s = select(c, 1.0 - c, c > 0.5);
    return s / (127.0 / 255.0);
}

// 1 when a Godot byte marks a dynamic object (bit 7), else 0; codes above 255 read as 255.
fn roughness_godot8_is_dynamic(p: u32) -> u32 {
    return min(p, 255u) >> 7u;
}

// Render-target form: the unorm8 channel to write for encode_roughness_godot8(r, dynamic_object).
fn encode_roughness_godot8_unorm(r: f32, dynamic_object: u32) -> f32 {
    return unpack4x8unorm(encode_roughness_godot8(r, dynamic_object)).x;
}

// The roughness from a sampled Godot channel: the byte rounded back, then decoded as Godot does.
fn decode_roughness_godot8_unorm(c: f32) -> f32 {
    return decode_roughness_godot8(ggx_unorm_byte(c));
}

// ---- log r in 8 bits: code k stands for r = 2^(6k/255 - 6), r in [1/64, 1] ----
// Equal steps in log r are equal steps in log alpha (alpha = 2^(12k/255 - 12)), so every code
// has the same relative precision: the curve that the tests' search finds best for the GGX lobe
// over the clamped range the engines shade (r >= 0.02 in Unreal, 0.089 in Bevy). It is the
// log-range codec of roughness.wgsl on p = 64 r with max_power 2^6, and exact the same way:
// integer operations on two tables, the same bits on every adapter.

// 2^(j/255) for j = 0..254, correctly rounded to f32 (bit patterns; roughness.wgsl's table).
var<private> GGX_LOG_EXP2_STEPS: array<u32, 255> = array<u32, 255>(
    0x3f800000u, 0x3f805931u, 0x3f80b2a0u, 0x3f810c4eu, 0x3f81663au, 0x3f81c065u, 0x3f821aceu, 0x3f827577u,
    0x3f82d05fu, 0x3f832b86u, 0x3f8386edu, 0x3f83e293u, 0x3f843e79u, 0x3f849a9fu, 0x3f84f706u, 0x3f8553acu,
    0x3f85b094u, 0x3f860dbcu, 0x3f866b25u, 0x3f86c8cfu, 0x3f8726bau, 0x3f8784e7u, 0x3f87e356u, 0x3f884206u,
    0x3f88a0f8u, 0x3f89002cu, 0x3f895fa3u, 0x3f89bf5cu, 0x3f8a1f58u, 0x3f8a7f97u, 0x3f8ae019u, 0x3f8b40deu,
    0x3f8ba1e7u, 0x3f8c0333u, 0x3f8c64c3u, 0x3f8cc697u, 0x3f8d28afu, 0x3f8d8b0bu, 0x3f8dedacu, 0x3f8e5092u,
    0x3f8eb3bdu, 0x3f8f172du, 0x3f8f7ae2u, 0x3f8fdedcu, 0x3f90431cu, 0x3f90a7a2u, 0x3f910c6eu, 0x3f917181u,
    0x3f91d6d9u, 0x3f923c79u, 0x3f92a25fu, 0x3f93088cu, 0x3f936f01u, 0x3f93d5bcu, 0x3f943cc0u, 0x3f94a40bu,
    0x3f950b9eu, 0x3f957379u, 0x3f95db9du, 0x3f964409u, 0x3f96acbeu, 0x3f9715bcu, 0x3f977f03u, 0x3f97e894u,
    0x3f98526eu, 0x3f98bc92u, 0x3f9926ffu, 0x3f9991b7u, 0x3f99fcb9u, 0x3f9a6806u, 0x3f9ad39eu, 0x3f9b3f80u,
    0x3f9babaeu, 0x3f9c1827u, 0x3f9c84ecu, 0x3f9cf1fdu, 0x3f9d5f59u, 0x3f9dcd02u, 0x3f9e3af7u, 0x3f9ea939u,
    0x3f9f17c7u, 0x3f9f86a3u, 0x3f9ff5ccu, 0x3fa06542u, 0x3fa0d506u, 0x3fa14518u, 0x3fa1b578u, 0x3fa22626u,
    0x3fa29723u, 0x3fa3086eu, 0x3fa37a09u, 0x3fa3ebf2u, 0x3fa45e2bu, 0x3fa4d0b4u, 0x3fa5438cu, 0x3fa5b6b5u,
    0x3fa62a2du, 0x3fa69df6u, 0x3fa71210u, 0x3fa7867bu, 0x3fa7fb37u, 0x3fa87044u, 0x3fa8e5a3u, 0x3fa95b53u,
    0x3fa9d156u, 0x3faa47aau, 0x3faabe52u, 0x3fab354bu, 0x3fabac98u, 0x3fac2438u, 0x3fac9c2bu, 0x3fad1472u,
    0x3fad8d0du, 0x3fae05fcu, 0x3fae7f3fu, 0x3faef8d6u, 0x3faf72c2u, 0x3fafed03u, 0x3fb0679au, 0x3fb0e285u,
    0x3fb15dc7u, 0x3fb1d95eu, 0x3fb2554cu, 0x3fb2d18fu, 0x3fb34e2au, 0x3fb3cb1bu, 0x3fb44863u, 0x3fb4c603u,
    0x3fb543fau, 0x3fb5c249u, 0x3fb640efu, 0x3fb6bfefu, 0x3fb73f46u, 0x3fb7bef6u, 0x3fb83f00u, 0x3fb8bf62u,
    0x3fb9401eu, 0x3fb9c134u, 0x3fba42a4u, 0x3fbac46du, 0x3fbb4692u, 0x3fbbc911u, 0x3fbc4bebu, 0x3fbccf20u,
    0x3fbd52b0u, 0x3fbdd69cu, 0x3fbe5ae4u, 0x3fbedf89u, 0x3fbf6489u, 0x3fbfe9e7u, 0x3fc06fa1u, 0x3fc0f5b9u,
    0x3fc17c2du, 0x3fc20300u, 0x3fc28a31u, 0x3fc311bfu, 0x3fc399adu, 0x3fc421f9u, 0x3fc4aaa4u, 0x3fc533aeu,
    0x3fc5bd17u, 0x3fc646e1u, 0x3fc6d10au, 0x3fc75b94u, 0x3fc7e67eu, 0x3fc871c9u, 0x3fc8fd75u, 0x3fc98982u,
    0x3fca15f1u, 0x3fcaa2c2u, 0x3fcb2ff5u, 0x3fcbbd8bu, 0x3fcc4b83u, 0x3fccd9ddu, 0x3fcd689cu, 0x3fcdf7bdu,
    0x3fce8742u, 0x3fcf172cu, 0x3fcfa779u, 0x3fd0382cu, 0x3fd0c943u, 0x3fd15abfu, 0x3fd1eca0u, 0x3fd27ee7u,
    0x3fd31194u, 0x3fd3a4a8u, 0x3fd43821u, 0x3fd4cc02u, 0x3fd56049u, 0x3fd5f4f8u, 0x3fd68a0fu, 0x3fd71f8du,
    0x3fd7b573u, 0x3fd84bc2u, 0x3fd8e27au, 0x3fd9799bu, 0x3fda1125u, 0x3fdaa919u, 0x3fdb4176u, 0x3fdbda3eu,
    0x3fdc7370u, 0x3fdd0d0du, 0x3fdda715u, 0x3fde4188u, 0x3fdedc67u, 0x3fdf77b2u, 0x3fe01369u, 0x3fe0af8cu,
    0x3fe14c1cu, 0x3fe1e91au, 0x3fe28685u, 0x3fe3245du, 0x3fe3c2a4u, 0x3fe46158u, 0x3fe5007cu, 0x3fe5a00eu,
    0x3fe6400fu, 0x3fe6e080u, 0x3fe78161u, 0x3fe822b2u, 0x3fe8c473u, 0x3fe966a5u, 0x3fea0948u, 0x3feaac5cu,
    0x3feb4fe2u, 0x3febf3dau, 0x3fec9844u, 0x3fed3d21u, 0x3fede271u, 0x3fee8833u, 0x3fef2e6au, 0x3fefd514u,
    0x3ff07c32u, 0x3ff123c5u, 0x3ff1cbccu, 0x3ff27449u, 0x3ff31d3au, 0x3ff3c6a2u, 0x3ff47080u, 0x3ff51ad4u,
    0x3ff5c59fu, 0x3ff670e0u, 0x3ff71c99u, 0x3ff7c8cau, 0x3ff87573u, 0x3ff92294u, 0x3ff9d02eu, 0x3ffa7e40u,
    0x3ffb2cccu, 0x3ffbdbd2u, 0x3ffc8b51u, 0x3ffd3b4bu, 0x3ffdebc0u, 0x3ffe9cafu, 0x3fff4e1au,
);

// The smallest f32 >= 2^(j/510) for j = 0..509 (bit patterns): code boundaries rounded up.
var<private> GGX_LOG_BOUNDARY_STEPS: array<u32, 510> = array<u32, 510>(
    0x3f800000u, 0x3f802c91u, 0x3f805932u, 0x3f8085e2u, 0x3f80b2a1u, 0x3f80df70u, 0x3f810c4fu, 0x3f81393du,
    0x3f81663bu, 0x3f819348u, 0x3f81c065u, 0x3f81ed92u, 0x3f821acfu, 0x3f82481bu, 0x3f827578u, 0x3f82a2e4u,
    0x3f82d05fu, 0x3f82fdebu, 0x3f832b86u, 0x3f835932u, 0x3f8386edu, 0x3f83b4b8u, 0x3f83e293u, 0x3f84107eu,
    0x3f843e79u, 0x3f846c85u, 0x3f849aa0u, 0x3f84c8cbu, 0x3f84f706u, 0x3f852551u, 0x3f8553adu, 0x3f858218u,
    0x3f85b094u, 0x3f85df20u, 0x3f860dbcu, 0x3f863c69u, 0x3f866b25u, 0x3f8699f2u, 0x3f86c8cfu, 0x3f86f7bdu,
    0x3f8726bbu, 0x3f8755c9u, 0x3f8784e8u, 0x3f87b417u, 0x3f87e356u, 0x3f8812a6u, 0x3f884206u, 0x3f887177u,
    0x3f88a0f9u, 0x3f88d08au, 0x3f89002du, 0x3f892fe0u, 0x3f895fa4u, 0x3f898f78u, 0x3f89bf5du, 0x3f89ef52u,
    0x3f8a1f59u, 0x3f8a4f70u, 0x3f8a7f98u, 0x3f8aafd0u, 0x3f8ae019u, 0x3f8b1074u, 0x3f8b40dfu, 0x3f8b715au,
    0x3f8ba1e7u, 0x3f8bd285u, 0x3f8c0333u, 0x3f8c33f3u, 0x3f8c64c3u, 0x3f8c95a5u, 0x3f8cc697u, 0x3f8cf79bu,
    0x3f8d28afu, 0x3f8d59d5u, 0x3f8d8b0cu, 0x3f8dbc54u, 0x3f8dedadu, 0x3f8e1f17u, 0x3f8e5093u, 0x3f8e821fu,
    0x3f8eb3bdu, 0x3f8ee56cu, 0x3f8f172du, 0x3f8f48ffu, 0x3f8f7ae2u, 0x3f8facd7u, 0x3f8fdeddu, 0x3f9010f4u,
    0x3f90431du, 0x3f907557u, 0x3f90a7a3u, 0x3f90da00u, 0x3f910c6fu, 0x3f913eefu, 0x3f917181u, 0x3f91a425u,
    0x3f91d6dau, 0x3f9209a1u, 0x3f923c79u, 0x3f926f64u, 0x3f92a260u, 0x3f92d56du, 0x3f93088du, 0x3f933bbeu,
    0x3f936f01u, 0x3f93a256u, 0x3f93d5bdu, 0x3f940936u, 0x3f943cc0u, 0x3f94705du, 0x3f94a40bu, 0x3f94d7ccu,
    0x3f950b9fu, 0x3f953f83u, 0x3f95737au, 0x3f95a783u, 0x3f95db9du, 0x3f960fcau, 0x3f96440au, 0x3f96785bu,
    0x3f96acbfu, 0x3f96e135u, 0x3f9715bdu, 0x3f974a57u, 0x3f977f04u, 0x3f97b3c3u, 0x3f97e894u, 0x3f981d78u,
    0x3f98526eu, 0x3f988777u, 0x3f98bc92u, 0x3f98f1c0u, 0x3f992700u, 0x3f995c52u, 0x3f9991b8u, 0x3f99c72fu,
    0x3f99fcbau, 0x3f9a3257u, 0x3f9a6807u, 0x3f9a9dc9u, 0x3f9ad39eu, 0x3f9b0986u, 0x3f9b3f81u, 0x3f9b758eu,
    0x3f9babafu, 0x3f9be1e2u, 0x3f9c1828u, 0x3f9c4e81u, 0x3f9c84edu, 0x3f9cbb6bu, 0x3f9cf1fdu, 0x3f9d28a2u,
    0x3f9d5f5au, 0x3f9d9624u, 0x3f9dcd02u, 0x3f9e03f3u, 0x3f9e3af7u, 0x3f9e720fu, 0x3f9ea939u, 0x3f9ee077u,
    0x3f9f17c8u, 0x3f9f4f2cu, 0x3f9f86a3u, 0x3f9fbe2eu, 0x3f9ff5ccu, 0x3fa02d7eu, 0x3fa06542u, 0x3fa09d1bu,
    0x3fa0d506u, 0x3fa10d06u, 0x3fa14518u, 0x3fa17d3eu, 0x3fa1b578u, 0x3fa1edc6u, 0x3fa22627u, 0x3fa25e9bu,
    0x3fa29723u, 0x3fa2cfbfu, 0x3fa3086fu, 0x3fa34132u, 0x3fa37a09u, 0x3fa3b2f4u, 0x3fa3ebf3u, 0x3fa42505u,
    0x3fa45e2cu, 0x3fa49766u, 0x3fa4d0b4u, 0x3fa50a17u, 0x3fa5438du, 0x3fa57d17u, 0x3fa5b6b5u, 0x3fa5f067u,
    0x3fa62a2eu, 0x3fa66408u, 0x3fa69df7u, 0x3fa6d7fau, 0x3fa71211u, 0x3fa74c3cu, 0x3fa7867bu, 0x3fa7c0cfu,
    0x3fa7fb37u, 0x3fa835b4u, 0x3fa87044u, 0x3fa8aaeau, 0x3fa8e5a3u, 0x3fa92071u, 0x3fa95b54u, 0x3fa9964bu,
    0x3fa9d156u, 0x3faa0c76u, 0x3faa47abu, 0x3faa82f4u, 0x3faabe52u, 0x3faaf9c5u, 0x3fab354cu, 0x3fab70e8u,
    0x3fabac99u, 0x3fabe85eu, 0x3fac2439u, 0x3fac6028u, 0x3fac9c2cu, 0x3facd845u, 0x3fad1473u, 0x3fad50b6u,
    0x3fad8d0du, 0x3fadc97au, 0x3fae05fcu, 0x3fae4293u, 0x3fae7f3fu, 0x3faebc00u, 0x3faef8d7u, 0x3faf35c2u,
    0x3faf72c3u, 0x3fafafd9u, 0x3fafed04u, 0x3fb02a44u, 0x3fb0679au, 0x3fb0a505u, 0x3fb0e286u, 0x3fb1201cu,
    0x3fb15dc7u, 0x3fb19b88u, 0x3fb1d95fu, 0x3fb2174bu, 0x3fb2554cu, 0x3fb29363u, 0x3fb2d190u, 0x3fb30fd2u,
    0x3fb34e2au, 0x3fb38c98u, 0x3fb3cb1bu, 0x3fb409b5u, 0x3fb44864u, 0x3fb48728u, 0x3fb4c603u, 0x3fb504f4u,
    0x3fb543fau, 0x3fb58317u, 0x3fb5c249u, 0x3fb60191u, 0x3fb640f0u, 0x3fb68064u, 0x3fb6bfefu, 0x3fb6ff90u,
    0x3fb73f47u, 0x3fb77f14u, 0x3fb7bef7u, 0x3fb7fef0u, 0x3fb83f00u, 0x3fb87f26u, 0x3fb8bf63u, 0x3fb8ffb6u,
    0x3fb9401fu, 0x3fb9809eu, 0x3fb9c134u, 0x3fba01e1u, 0x3fba42a4u, 0x3fba837eu, 0x3fbac46eu, 0x3fbb0575u,
    0x3fbb4692u, 0x3fbb87c6u, 0x3fbbc911u, 0x3fbc0a73u, 0x3fbc4bebu, 0x3fbc8d7au, 0x3fbccf20u, 0x3fbd10ddu,
    0x3fbd52b1u, 0x3fbd949bu, 0x3fbdd69du, 0x3fbe18b5u, 0x3fbe5ae5u, 0x3fbe9d2cu, 0x3fbedf89u, 0x3fbf21feu,
    0x3fbf648au, 0x3fbfa72du, 0x3fbfe9e7u, 0x3fc02cb9u, 0x3fc06fa2u, 0x3fc0b2a2u, 0x3fc0f5b9u, 0x3fc138e8u,
    0x3fc17c2eu, 0x3fc1bf8cu, 0x3fc20301u, 0x3fc2468du, 0x3fc28a31u, 0x3fc2cdedu, 0x3fc311c0u, 0x3fc355abu,
    0x3fc399adu, 0x3fc3ddc7u, 0x3fc421f9u, 0x3fc46643u, 0x3fc4aaa4u, 0x3fc4ef1du, 0x3fc533aeu, 0x3fc57857u,
    0x3fc5bd18u, 0x3fc601f1u, 0x3fc646e1u, 0x3fc68beau, 0x3fc6d10bu, 0x3fc71643u, 0x3fc75b94u, 0x3fc7a0fdu,
    0x3fc7e67eu, 0x3fc82c18u, 0x3fc871c9u, 0x3fc8b793u, 0x3fc8fd76u, 0x3fc94370u, 0x3fc98983u, 0x3fc9cfaeu,
    0x3fca15f2u, 0x3fca5c4eu, 0x3fcaa2c3u, 0x3fcae950u, 0x3fcb2ff6u, 0x3fcb76b4u, 0x3fcbbd8bu, 0x3fcc047bu,
    0x3fcc4b83u, 0x3fcc92a4u, 0x3fccd9deu, 0x3fcd2131u, 0x3fcd689cu, 0x3fcdb020u, 0x3fcdf7beu, 0x3fce3f74u,
    0x3fce8743u, 0x3fcecf2bu, 0x3fcf172cu, 0x3fcf5f47u, 0x3fcfa77au, 0x3fcfefc6u, 0x3fd0382cu, 0x3fd080abu,
    0x3fd0c943u, 0x3fd111f4u, 0x3fd15abfu, 0x3fd1a3a3u, 0x3fd1eca1u, 0x3fd235b7u, 0x3fd27ee8u, 0x3fd2c831u,
    0x3fd31195u, 0x3fd35b12u, 0x3fd3a4a8u, 0x3fd3ee58u, 0x3fd43822u, 0x3fd48205u, 0x3fd4cc02u, 0x3fd51619u,
    0x3fd5604au, 0x3fd5aa94u, 0x3fd5f4f9u, 0x3fd63f77u, 0x3fd68a0fu, 0x3fd6d4c1u, 0x3fd71f8du, 0x3fd76a74u,
    0x3fd7b574u, 0x3fd8008eu, 0x3fd84bc3u, 0x3fd89712u, 0x3fd8e27bu, 0x3fd92dfeu, 0x3fd9799bu, 0x3fd9c553u,
    0x3fda1125u, 0x3fda5d12u, 0x3fdaa919u, 0x3fdaf53bu, 0x3fdb4177u, 0x3fdb8dcdu, 0x3fdbda3eu, 0x3fdc26cau,
    0x3fdc7370u, 0x3fdcc031u, 0x3fdd0d0du, 0x3fdd5a04u, 0x3fdda715u, 0x3fddf441u, 0x3fde4188u, 0x3fde8eeau,
    0x3fdedc67u, 0x3fdf29ffu, 0x3fdf77b2u, 0x3fdfc580u, 0x3fe01369u, 0x3fe0616du, 0x3fe0af8du, 0x3fe0fdc7u,
    0x3fe14c1du, 0x3fe19a8eu, 0x3fe1e91au, 0x3fe237c2u, 0x3fe28685u, 0x3fe2d564u, 0x3fe3245eu, 0x3fe37373u,
    0x3fe3c2a4u, 0x3fe411f1u, 0x3fe46159u, 0x3fe4b0ddu, 0x3fe5007cu, 0x3fe55038u, 0x3fe5a00fu, 0x3fe5f001u,
    0x3fe64010u, 0x3fe6903au, 0x3fe6e081u, 0x3fe730e3u, 0x3fe78162u, 0x3fe7d1fcu, 0x3fe822b2u, 0x3fe87385u,
    0x3fe8c474u, 0x3fe9157fu, 0x3fe966a6u, 0x3fe9b7e9u, 0x3fea0949u, 0x3fea5ac5u, 0x3feaac5du, 0x3feafe12u,
    0x3feb4fe3u, 0x3feba1d0u, 0x3febf3dbu, 0x3fec4601u, 0x3fec9845u, 0x3feceaa5u, 0x3fed3d22u, 0x3fed8fbbu,
    0x3fede271u, 0x3fee3544u, 0x3fee8834u, 0x3feedb41u, 0x3fef2e6au, 0x3fef81b1u, 0x3fefd514u, 0x3ff02895u,
    0x3ff07c32u, 0x3ff0cfedu, 0x3ff123c5u, 0x3ff177bau, 0x3ff1cbcdu, 0x3ff21ffcu, 0x3ff27449u, 0x3ff2c8b3u,
    0x3ff31d3bu, 0x3ff371e0u, 0x3ff3c6a3u, 0x3ff41b83u, 0x3ff47080u, 0x3ff4c59cu, 0x3ff51ad4u, 0x3ff5702bu,
    0x3ff5c59fu, 0x3ff61b31u, 0x3ff670e1u, 0x3ff6c6aeu, 0x3ff71c9au, 0x3ff772a3u, 0x3ff7c8cbu, 0x3ff81f10u,
    0x3ff87573u, 0x3ff8cbf5u, 0x3ff92294u, 0x3ff97952u, 0x3ff9d02eu, 0x3ffa2728u, 0x3ffa7e41u, 0x3ffad578u,
    0x3ffb2ccdu, 0x3ffb8440u, 0x3ffbdbd2u, 0x3ffc3383u, 0x3ffc8b52u, 0x3ffce33fu, 0x3ffd3b4cu, 0x3ffd9377u,
    0x3ffdebc0u, 0x3ffe4428u, 0x3ffe9cb0u, 0x3ffef555u, 0x3fff4e1au, 0x3fffa6feu,
);

// The code of r: nearest to 255·(log2 r + 6)/6 (ties upwards at the geometric midpoints); r at
// or below 1/64 (negative, -0, subnormal, -Inf) -> 0; r >= 1, +Inf and NaN -> 255.
fn encode_roughness_ggx8_log(r: f32) -> u32 {
    let b = bitcast<u32>(r);
    if ((b & 0x7fffffffu) > 0x7f800000u || (b < 0x80000000u && b >= 0x3f800000u)) {
        return 255u;
    }
    if (b >= 0x80000000u || b <= 0x3c800000u) {
        return 0u; // negative, -0, -Inf, and everything up to 2^-6
    }
    // p = 64 r in (1, 64), exactly; positive floats order like their bit patterns.
    let pb = b + (6u << 23u);
    let t = 255.0 * log2(bitcast<f32>(pb)) / 6.0;
    var k = min(u32(floor(t + 0.5)), 255u);
    // log2's error (3 ULP, or 2^-21 absolute near 1) keeps the candidate within one code; the
    // boundaries T_j = 2^((2j + 1)·6/510) on either side decide exactly.
    if (k > 0u) {
        let n = (2u * k - 1u) * 6u;
        if (pb < GGX_LOG_BOUNDARY_STEPS[n % 510u] + ((n / 510u) << 23u)) {
            return k - 1u;
        }
    }
    if (k < 255u) {
        let n = (2u * k + 1u) * 6u;
        if (pb >= GGX_LOG_BOUNDARY_STEPS[n % 510u] + ((n / 510u) << 23u)) {
            return k + 1u;
        }
    }
    return k;
}

// r = 2^(6k/255 - 6) of code k, correctly rounded; codes above 255 decode as 255 (r = 1).
fn decode_roughness_ggx8_log(p: u32) -> f32 {
    let n = min(p, 255u) * 6u;
    return bitcast<f32>(GGX_LOG_EXP2_STEPS[n % 255u] + ((n / 255u) << 23u) - (6u << 23u));
}

// alpha = r^2 = 2^(12k/255 - 12) of code k, correctly rounded (no squaring); codes above 255
// decode as 255 (alpha = 1).
fn decode_roughness_ggx8_log_alpha(p: u32) -> f32 {
    let n = min(p, 255u) * 12u;
    return bitcast<f32>(GGX_LOG_EXP2_STEPS[n % 255u] + ((n / 255u) << 23u) - (12u << 23u));
}

// Render-target form: the r8unorm channel to write for encode_roughness_ggx8_log(r).
fn encode_roughness_ggx8_log_unorm(r: f32) -> f32 {
    return unpack4x8unorm(encode_roughness_ggx8_log(r)).x;
}

// The roughness from a sampled r8unorm channel holding a log code (byte rounded back).
fn decode_roughness_ggx8_log_unorm(c: f32) -> f32 {
    return decode_roughness_ggx8_log(ggx_unorm_byte(c));
}
