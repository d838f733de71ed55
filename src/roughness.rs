//! Log-range specular exponent ("roughness") in 8 bits — the Rust twins of `wgsl/roughness.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! Killzone 2 stores the specular exponent "in log range to keep higher precision for low
//! exponents" (Michal Valient, "Deferred Rendering in Killzone 2", Guerrilla Games, Develop
//! Conference 2007); Resistance 2 keeps the spec power in the alpha of the normal buffer (Mark Lee,
//! "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009). Code `k ∈ [0, 255]` stands for the
//! power `max_power^(k/255)`, and a power `p ∈ [1, max_power]` encodes to the code nearest
//! `255·log2(p)/log2(max_power)` (ties upwards). Every step multiplies the power by the same factor
//! `2^(L/255)`, `L = log2(max_power)`, so the worst relative error of a round trip is the half step
//! `2^(L/510) − 1` (1.782 % for `max_power = 8192`) at every power, where 8-bit linear storage
//! loses everything at low powers (see `tests/roughness.rs` and the README's table).
//!
//! ## Exact for power-of-two ranges
//! When `max_power = 2^L` with integer `L ∈ [1, 127]` both directions are integer operations
//! on two tables ([`EXP2_STEPS`], [`BOUNDARY_STEPS`]) and are **exact** — the WGSL on every
//! adapter and these twins give the same bits:
//! - decode: `k·L = 255q + r`, so `max_power^(k/255) = 2^q · 2^(r/255)`; the table holds
//!   `2^(r/255)` correctly rounded and adding `q` to the exponent field is exact. The result is
//!   the correctly rounded power (≤ 0.5 ULP).
//! - encode: the boundary between codes `j` and `j+1` is `T_j = 2^((2j+1)L/510) = 2^Q·2^(R/510)`.
//!   The table holds the smallest `f32 ≥ 2^(R/510)`, so for every `f32` power the test
//!   `p ≥ T_j` is decided exactly by comparing bit patterns. A `log2` estimate picks a
//!   candidate code; WGSL's `log2` (3 ULP, or `2^-21` absolute on `[0.5, 2]`) puts it within
//!   `255·2^-21 ≈ 1.2e-4` codes of the exact `t = 255·log2(p)/L` (plus ≤ 3 ULP of `t` from
//!   the division, < 1e-4 codes), so where `t` is more than `2^-8` codes from a half-integer
//!   the candidate is the code, and nearer one the boundary on each side decides it exactly.
//!
//! WGSL's `exp2` is only promised to `3 + 2|x|` ULP (29 ULP at `x = 13`) and `log2` to 3 ULP,
//! so a decode written as `exp2(k·log2(max)/255)` cannot promise 2 ULP; the tables can.
//!
//! ## Other ranges
//! Any other `max_power ∈ (1, 2^127)` uses `log2`/`exp2`; those twins are not bit-identical to
//! an adapter (transcendentals). Bound from the WGSL accuracy rules (`u = 2^-24`, one ULP
//! `≤ 2u` relative): `x = k·log2(max)/255` is off by `≤ 12u·x` (log2 3 ULP, product, 2.5-ULP
//! division), which `exp2` turns into `12u·x·ln 2` relative, and `exp2` adds `(3 + 2x)` ULP: a
//! decode is within `12u·x·ln 2 + (3 + 2x)·2u` relative (measured on lavapipe: 4.1–14.2 ULP for
//! ranges 100.5, 1000 and 3e6 — more than 2 ULP, which only the power-of-two tables guarantee).
//! An encode can pick the neighbouring code only for powers within `19u·255` codes of a
//! boundary ([`bounds::encode_neighbour_margin`]).
//!
//! ## Bad input (identical in WGSL and Rust)
//! - `max_power` NaN or `≤ 1`: the range is the single power 1 — every power encodes to 0 and
//!   every code decodes to 1.0. `max_power > 2^127` (`+Inf` included) acts as `2^127`.
//! - power NaN, negative, `−0`, `0`, subnormal, or `≤ 1`: code 0. `+Inf` or `≥ max_power`: 255.
//! - codes above 255 decode as 255.

/// Largest code.
pub const CODE_MAX: u32 = 255;

/// Bit patterns of `2^(r/255)` for `r = 0..254`, each correctly rounded to `f32` (generated
/// with 200-bit arithmetic; checked against `f64` in this module's tests). The WGSL holds the
/// same table (`LOG_ROUGHNESS_EXP2_STEPS`).
pub const EXP2_STEPS: [u32; 255] = [
    0x3f800000, 0x3f805931, 0x3f80b2a0, 0x3f810c4e, 0x3f81663a, 0x3f81c065, 0x3f821ace, 0x3f827577,
    0x3f82d05f, 0x3f832b86, 0x3f8386ed, 0x3f83e293, 0x3f843e79, 0x3f849a9f, 0x3f84f706, 0x3f8553ac,
    0x3f85b094, 0x3f860dbc, 0x3f866b25, 0x3f86c8cf, 0x3f8726ba, 0x3f8784e7, 0x3f87e356, 0x3f884206,
    0x3f88a0f8, 0x3f89002c, 0x3f895fa3, 0x3f89bf5c, 0x3f8a1f58, 0x3f8a7f97, 0x3f8ae019, 0x3f8b40de,
    0x3f8ba1e7, 0x3f8c0333, 0x3f8c64c3, 0x3f8cc697, 0x3f8d28af, 0x3f8d8b0b, 0x3f8dedac, 0x3f8e5092,
    0x3f8eb3bd, 0x3f8f172d, 0x3f8f7ae2, 0x3f8fdedc, 0x3f90431c, 0x3f90a7a2, 0x3f910c6e, 0x3f917181,
    0x3f91d6d9, 0x3f923c79, 0x3f92a25f, 0x3f93088c, 0x3f936f01, 0x3f93d5bc, 0x3f943cc0, 0x3f94a40b,
    0x3f950b9e, 0x3f957379, 0x3f95db9d, 0x3f964409, 0x3f96acbe, 0x3f9715bc, 0x3f977f03, 0x3f97e894,
    0x3f98526e, 0x3f98bc92, 0x3f9926ff, 0x3f9991b7, 0x3f99fcb9, 0x3f9a6806, 0x3f9ad39e, 0x3f9b3f80,
    0x3f9babae, 0x3f9c1827, 0x3f9c84ec, 0x3f9cf1fd, 0x3f9d5f59, 0x3f9dcd02, 0x3f9e3af7, 0x3f9ea939,
    0x3f9f17c7, 0x3f9f86a3, 0x3f9ff5cc, 0x3fa06542, 0x3fa0d506, 0x3fa14518, 0x3fa1b578, 0x3fa22626,
    0x3fa29723, 0x3fa3086e, 0x3fa37a09, 0x3fa3ebf2, 0x3fa45e2b, 0x3fa4d0b4, 0x3fa5438c, 0x3fa5b6b5,
    0x3fa62a2d, 0x3fa69df6, 0x3fa71210, 0x3fa7867b, 0x3fa7fb37, 0x3fa87044, 0x3fa8e5a3, 0x3fa95b53,
    0x3fa9d156, 0x3faa47aa, 0x3faabe52, 0x3fab354b, 0x3fabac98, 0x3fac2438, 0x3fac9c2b, 0x3fad1472,
    0x3fad8d0d, 0x3fae05fc, 0x3fae7f3f, 0x3faef8d6, 0x3faf72c2, 0x3fafed03, 0x3fb0679a, 0x3fb0e285,
    0x3fb15dc7, 0x3fb1d95e, 0x3fb2554c, 0x3fb2d18f, 0x3fb34e2a, 0x3fb3cb1b, 0x3fb44863, 0x3fb4c603,
    0x3fb543fa, 0x3fb5c249, 0x3fb640ef, 0x3fb6bfef, 0x3fb73f46, 0x3fb7bef6, 0x3fb83f00, 0x3fb8bf62,
    0x3fb9401e, 0x3fb9c134, 0x3fba42a4, 0x3fbac46d, 0x3fbb4692, 0x3fbbc911, 0x3fbc4beb, 0x3fbccf20,
    0x3fbd52b0, 0x3fbdd69c, 0x3fbe5ae4, 0x3fbedf89, 0x3fbf6489, 0x3fbfe9e7, 0x3fc06fa1, 0x3fc0f5b9,
    0x3fc17c2d, 0x3fc20300, 0x3fc28a31, 0x3fc311bf, 0x3fc399ad, 0x3fc421f9, 0x3fc4aaa4, 0x3fc533ae,
    0x3fc5bd17, 0x3fc646e1, 0x3fc6d10a, 0x3fc75b94, 0x3fc7e67e, 0x3fc871c9, 0x3fc8fd75, 0x3fc98982,
    0x3fca15f1, 0x3fcaa2c2, 0x3fcb2ff5, 0x3fcbbd8b, 0x3fcc4b83, 0x3fccd9dd, 0x3fcd689c, 0x3fcdf7bd,
    0x3fce8742, 0x3fcf172c, 0x3fcfa779, 0x3fd0382c, 0x3fd0c943, 0x3fd15abf, 0x3fd1eca0, 0x3fd27ee7,
    0x3fd31194, 0x3fd3a4a8, 0x3fd43821, 0x3fd4cc02, 0x3fd56049, 0x3fd5f4f8, 0x3fd68a0f, 0x3fd71f8d,
    0x3fd7b573, 0x3fd84bc2, 0x3fd8e27a, 0x3fd9799b, 0x3fda1125, 0x3fdaa919, 0x3fdb4176, 0x3fdbda3e,
    0x3fdc7370, 0x3fdd0d0d, 0x3fdda715, 0x3fde4188, 0x3fdedc67, 0x3fdf77b2, 0x3fe01369, 0x3fe0af8c,
    0x3fe14c1c, 0x3fe1e91a, 0x3fe28685, 0x3fe3245d, 0x3fe3c2a4, 0x3fe46158, 0x3fe5007c, 0x3fe5a00e,
    0x3fe6400f, 0x3fe6e080, 0x3fe78161, 0x3fe822b2, 0x3fe8c473, 0x3fe966a5, 0x3fea0948, 0x3feaac5c,
    0x3feb4fe2, 0x3febf3da, 0x3fec9844, 0x3fed3d21, 0x3fede271, 0x3fee8833, 0x3fef2e6a, 0x3fefd514,
    0x3ff07c32, 0x3ff123c5, 0x3ff1cbcc, 0x3ff27449, 0x3ff31d3a, 0x3ff3c6a2, 0x3ff47080, 0x3ff51ad4,
    0x3ff5c59f, 0x3ff670e0, 0x3ff71c99, 0x3ff7c8ca, 0x3ff87573, 0x3ff92294, 0x3ff9d02e, 0x3ffa7e40,
    0x3ffb2ccc, 0x3ffbdbd2, 0x3ffc8b51, 0x3ffd3b4b, 0x3ffdebc0, 0x3ffe9caf, 0x3fff4e1a,
];

/// Bit patterns of the smallest `f32 ≥ 2^(r/510)` for `r = 0..509` (code boundaries rounded up;
/// `2^0 = 1` is exact). The WGSL holds the same table (`LOG_ROUGHNESS_BOUNDARY_STEPS`).
pub const BOUNDARY_STEPS: [u32; 510] = [
    0x3f800000, 0x3f802c91, 0x3f805932, 0x3f8085e2, 0x3f80b2a1, 0x3f80df70, 0x3f810c4f, 0x3f81393d,
    0x3f81663b, 0x3f819348, 0x3f81c065, 0x3f81ed92, 0x3f821acf, 0x3f82481b, 0x3f827578, 0x3f82a2e4,
    0x3f82d05f, 0x3f82fdeb, 0x3f832b86, 0x3f835932, 0x3f8386ed, 0x3f83b4b8, 0x3f83e293, 0x3f84107e,
    0x3f843e79, 0x3f846c85, 0x3f849aa0, 0x3f84c8cb, 0x3f84f706, 0x3f852551, 0x3f8553ad, 0x3f858218,
    0x3f85b094, 0x3f85df20, 0x3f860dbc, 0x3f863c69, 0x3f866b25, 0x3f8699f2, 0x3f86c8cf, 0x3f86f7bd,
    0x3f8726bb, 0x3f8755c9, 0x3f8784e8, 0x3f87b417, 0x3f87e356, 0x3f8812a6, 0x3f884206, 0x3f887177,
    0x3f88a0f9, 0x3f88d08a, 0x3f89002d, 0x3f892fe0, 0x3f895fa4, 0x3f898f78, 0x3f89bf5d, 0x3f89ef52,
    0x3f8a1f59, 0x3f8a4f70, 0x3f8a7f98, 0x3f8aafd0, 0x3f8ae019, 0x3f8b1074, 0x3f8b40df, 0x3f8b715a,
    0x3f8ba1e7, 0x3f8bd285, 0x3f8c0333, 0x3f8c33f3, 0x3f8c64c3, 0x3f8c95a5, 0x3f8cc697, 0x3f8cf79b,
    0x3f8d28af, 0x3f8d59d5, 0x3f8d8b0c, 0x3f8dbc54, 0x3f8dedad, 0x3f8e1f17, 0x3f8e5093, 0x3f8e821f,
    0x3f8eb3bd, 0x3f8ee56c, 0x3f8f172d, 0x3f8f48ff, 0x3f8f7ae2, 0x3f8facd7, 0x3f8fdedd, 0x3f9010f4,
    0x3f90431d, 0x3f907557, 0x3f90a7a3, 0x3f90da00, 0x3f910c6f, 0x3f913eef, 0x3f917181, 0x3f91a425,
    0x3f91d6da, 0x3f9209a1, 0x3f923c79, 0x3f926f64, 0x3f92a260, 0x3f92d56d, 0x3f93088d, 0x3f933bbe,
    0x3f936f01, 0x3f93a256, 0x3f93d5bd, 0x3f940936, 0x3f943cc0, 0x3f94705d, 0x3f94a40b, 0x3f94d7cc,
    0x3f950b9f, 0x3f953f83, 0x3f95737a, 0x3f95a783, 0x3f95db9d, 0x3f960fca, 0x3f96440a, 0x3f96785b,
    0x3f96acbf, 0x3f96e135, 0x3f9715bd, 0x3f974a57, 0x3f977f04, 0x3f97b3c3, 0x3f97e894, 0x3f981d78,
    0x3f98526e, 0x3f988777, 0x3f98bc92, 0x3f98f1c0, 0x3f992700, 0x3f995c52, 0x3f9991b8, 0x3f99c72f,
    0x3f99fcba, 0x3f9a3257, 0x3f9a6807, 0x3f9a9dc9, 0x3f9ad39e, 0x3f9b0986, 0x3f9b3f81, 0x3f9b758e,
    0x3f9babaf, 0x3f9be1e2, 0x3f9c1828, 0x3f9c4e81, 0x3f9c84ed, 0x3f9cbb6b, 0x3f9cf1fd, 0x3f9d28a2,
    0x3f9d5f5a, 0x3f9d9624, 0x3f9dcd02, 0x3f9e03f3, 0x3f9e3af7, 0x3f9e720f, 0x3f9ea939, 0x3f9ee077,
    0x3f9f17c8, 0x3f9f4f2c, 0x3f9f86a3, 0x3f9fbe2e, 0x3f9ff5cc, 0x3fa02d7e, 0x3fa06542, 0x3fa09d1b,
    0x3fa0d506, 0x3fa10d06, 0x3fa14518, 0x3fa17d3e, 0x3fa1b578, 0x3fa1edc6, 0x3fa22627, 0x3fa25e9b,
    0x3fa29723, 0x3fa2cfbf, 0x3fa3086f, 0x3fa34132, 0x3fa37a09, 0x3fa3b2f4, 0x3fa3ebf3, 0x3fa42505,
    0x3fa45e2c, 0x3fa49766, 0x3fa4d0b4, 0x3fa50a17, 0x3fa5438d, 0x3fa57d17, 0x3fa5b6b5, 0x3fa5f067,
    0x3fa62a2e, 0x3fa66408, 0x3fa69df7, 0x3fa6d7fa, 0x3fa71211, 0x3fa74c3c, 0x3fa7867b, 0x3fa7c0cf,
    0x3fa7fb37, 0x3fa835b4, 0x3fa87044, 0x3fa8aaea, 0x3fa8e5a3, 0x3fa92071, 0x3fa95b54, 0x3fa9964b,
    0x3fa9d156, 0x3faa0c76, 0x3faa47ab, 0x3faa82f4, 0x3faabe52, 0x3faaf9c5, 0x3fab354c, 0x3fab70e8,
    0x3fabac99, 0x3fabe85e, 0x3fac2439, 0x3fac6028, 0x3fac9c2c, 0x3facd845, 0x3fad1473, 0x3fad50b6,
    0x3fad8d0d, 0x3fadc97a, 0x3fae05fc, 0x3fae4293, 0x3fae7f3f, 0x3faebc00, 0x3faef8d7, 0x3faf35c2,
    0x3faf72c3, 0x3fafafd9, 0x3fafed04, 0x3fb02a44, 0x3fb0679a, 0x3fb0a505, 0x3fb0e286, 0x3fb1201c,
    0x3fb15dc7, 0x3fb19b88, 0x3fb1d95f, 0x3fb2174b, 0x3fb2554c, 0x3fb29363, 0x3fb2d190, 0x3fb30fd2,
    0x3fb34e2a, 0x3fb38c98, 0x3fb3cb1b, 0x3fb409b5, 0x3fb44864, 0x3fb48728, 0x3fb4c603, 0x3fb504f4,
    0x3fb543fa, 0x3fb58317, 0x3fb5c249, 0x3fb60191, 0x3fb640f0, 0x3fb68064, 0x3fb6bfef, 0x3fb6ff90,
    0x3fb73f47, 0x3fb77f14, 0x3fb7bef7, 0x3fb7fef0, 0x3fb83f00, 0x3fb87f26, 0x3fb8bf63, 0x3fb8ffb6,
    0x3fb9401f, 0x3fb9809e, 0x3fb9c134, 0x3fba01e1, 0x3fba42a4, 0x3fba837e, 0x3fbac46e, 0x3fbb0575,
    0x3fbb4692, 0x3fbb87c6, 0x3fbbc911, 0x3fbc0a73, 0x3fbc4beb, 0x3fbc8d7a, 0x3fbccf20, 0x3fbd10dd,
    0x3fbd52b1, 0x3fbd949b, 0x3fbdd69d, 0x3fbe18b5, 0x3fbe5ae5, 0x3fbe9d2c, 0x3fbedf89, 0x3fbf21fe,
    0x3fbf648a, 0x3fbfa72d, 0x3fbfe9e7, 0x3fc02cb9, 0x3fc06fa2, 0x3fc0b2a2, 0x3fc0f5b9, 0x3fc138e8,
    0x3fc17c2e, 0x3fc1bf8c, 0x3fc20301, 0x3fc2468d, 0x3fc28a31, 0x3fc2cded, 0x3fc311c0, 0x3fc355ab,
    0x3fc399ad, 0x3fc3ddc7, 0x3fc421f9, 0x3fc46643, 0x3fc4aaa4, 0x3fc4ef1d, 0x3fc533ae, 0x3fc57857,
    0x3fc5bd18, 0x3fc601f1, 0x3fc646e1, 0x3fc68bea, 0x3fc6d10b, 0x3fc71643, 0x3fc75b94, 0x3fc7a0fd,
    0x3fc7e67e, 0x3fc82c18, 0x3fc871c9, 0x3fc8b793, 0x3fc8fd76, 0x3fc94370, 0x3fc98983, 0x3fc9cfae,
    0x3fca15f2, 0x3fca5c4e, 0x3fcaa2c3, 0x3fcae950, 0x3fcb2ff6, 0x3fcb76b4, 0x3fcbbd8b, 0x3fcc047b,
    0x3fcc4b83, 0x3fcc92a4, 0x3fccd9de, 0x3fcd2131, 0x3fcd689c, 0x3fcdb020, 0x3fcdf7be, 0x3fce3f74,
    0x3fce8743, 0x3fcecf2b, 0x3fcf172c, 0x3fcf5f47, 0x3fcfa77a, 0x3fcfefc6, 0x3fd0382c, 0x3fd080ab,
    0x3fd0c943, 0x3fd111f4, 0x3fd15abf, 0x3fd1a3a3, 0x3fd1eca1, 0x3fd235b7, 0x3fd27ee8, 0x3fd2c831,
    0x3fd31195, 0x3fd35b12, 0x3fd3a4a8, 0x3fd3ee58, 0x3fd43822, 0x3fd48205, 0x3fd4cc02, 0x3fd51619,
    0x3fd5604a, 0x3fd5aa94, 0x3fd5f4f9, 0x3fd63f77, 0x3fd68a0f, 0x3fd6d4c1, 0x3fd71f8d, 0x3fd76a74,
    0x3fd7b574, 0x3fd8008e, 0x3fd84bc3, 0x3fd89712, 0x3fd8e27b, 0x3fd92dfe, 0x3fd9799b, 0x3fd9c553,
    0x3fda1125, 0x3fda5d12, 0x3fdaa919, 0x3fdaf53b, 0x3fdb4177, 0x3fdb8dcd, 0x3fdbda3e, 0x3fdc26ca,
    0x3fdc7370, 0x3fdcc031, 0x3fdd0d0d, 0x3fdd5a04, 0x3fdda715, 0x3fddf441, 0x3fde4188, 0x3fde8eea,
    0x3fdedc67, 0x3fdf29ff, 0x3fdf77b2, 0x3fdfc580, 0x3fe01369, 0x3fe0616d, 0x3fe0af8d, 0x3fe0fdc7,
    0x3fe14c1d, 0x3fe19a8e, 0x3fe1e91a, 0x3fe237c2, 0x3fe28685, 0x3fe2d564, 0x3fe3245e, 0x3fe37373,
    0x3fe3c2a4, 0x3fe411f1, 0x3fe46159, 0x3fe4b0dd, 0x3fe5007c, 0x3fe55038, 0x3fe5a00f, 0x3fe5f001,
    0x3fe64010, 0x3fe6903a, 0x3fe6e081, 0x3fe730e3, 0x3fe78162, 0x3fe7d1fc, 0x3fe822b2, 0x3fe87385,
    0x3fe8c474, 0x3fe9157f, 0x3fe966a6, 0x3fe9b7e9, 0x3fea0949, 0x3fea5ac5, 0x3feaac5d, 0x3feafe12,
    0x3feb4fe3, 0x3feba1d0, 0x3febf3db, 0x3fec4601, 0x3fec9845, 0x3feceaa5, 0x3fed3d22, 0x3fed8fbb,
    0x3fede271, 0x3fee3544, 0x3fee8834, 0x3feedb41, 0x3fef2e6a, 0x3fef81b1, 0x3fefd514, 0x3ff02895,
    0x3ff07c32, 0x3ff0cfed, 0x3ff123c5, 0x3ff177ba, 0x3ff1cbcd, 0x3ff21ffc, 0x3ff27449, 0x3ff2c8b3,
    0x3ff31d3b, 0x3ff371e0, 0x3ff3c6a3, 0x3ff41b83, 0x3ff47080, 0x3ff4c59c, 0x3ff51ad4, 0x3ff5702b,
    0x3ff5c59f, 0x3ff61b31, 0x3ff670e1, 0x3ff6c6ae, 0x3ff71c9a, 0x3ff772a3, 0x3ff7c8cb, 0x3ff81f10,
    0x3ff87573, 0x3ff8cbf5, 0x3ff92294, 0x3ff97952, 0x3ff9d02e, 0x3ffa2728, 0x3ffa7e41, 0x3ffad578,
    0x3ffb2ccd, 0x3ffb8440, 0x3ffbdbd2, 0x3ffc3383, 0x3ffc8b52, 0x3ffce33f, 0x3ffd3b4c, 0x3ffd9377,
    0x3ffdebc0, 0x3ffe4428, 0x3ffe9cb0, 0x3ffef555, 0x3fff4e1a, 0x3fffa6fe,
];

/// How [`encode_log_roughness`] and [`decode_log_roughness`] treat a `max_power`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Range {
    /// `max_power` NaN or `≤ 1`: only power 1 (code 0).
    Degenerate,
    /// `max_power = 2^L`, `L ∈ [1, 127]` (values above `2^127` act as `2^127`): exact tables.
    PowerOfTwo(u32),
    /// Any other `max_power ∈ (1, 2^127)`: `log2`/`exp2`.
    General(f32),
}

/// Classify `max_power` as both sides do (the WGSL's `log_roughness_range_log2`).
pub fn range(max_power: f32) -> Range {
    let b = max_power.to_bits();
    if (b & 0x7fff_ffff) > 0x7f80_0000 || (b >> 31) != 0 || b <= 0x3f80_0000 {
        Range::Degenerate
    } else if b >= 0x7f00_0000 {
        Range::PowerOfTwo(127)
    } else if b & 0x7f_ffff == 0 {
        Range::PowerOfTwo((b >> 23) - 127)
    } else {
        Range::General(max_power)
    }
}

pub(crate) fn boundary_bits(j: u32, l: u32) -> u32 {
    let n = (2 * j + 1) * l;
    BOUNDARY_STEPS[(n % 510) as usize] + ((n / 510) << 23)
}

/// The 8-bit code of a specular power: the integer nearest `255·log2(power)/log2(max_power)`,
/// ties upwards, clamped to `[0, 255]`.
///
/// **Error bound:** exact for power-of-two `max_power` (bit-identical to the WGSL, checked over
/// every `f32` power in `[1, 8192]` on the adapter). Otherwise computed with `log2` and may
/// differ from the exact code for powers within a few ULP of a code boundary.
///
/// **Bad input:** see the [module docs](self): NaN/negative/`≤ 1` → 0, `+Inf`/`≥ max_power`
/// → 255, degenerate `max_power` → 0.
pub fn encode_log_roughness(power: f32, max_power: f32) -> u32 {
    let b = power.to_bits();
    let r = range(max_power);
    if r == Range::Degenerate
        || (b & 0x7fff_ffff) > 0x7f80_0000
        || (b >> 31) != 0
        || b <= 0x3f80_0000
    {
        return 0;
    }
    match r {
        Range::PowerOfTwo(l) => {
            // Candidate from log2 (error ≪ half a code), corrected exactly by the boundaries.
            let t = 255.0 * power.log2() / l as f32;
            let mut k = (t + 0.5).floor().clamp(0.0, 255.0) as u32;
            // Near a boundary (within 2^-8 codes, 30× the estimate's error) decide exactly.
            if (t.fract() - 0.5).abs() < 0.003_906_25 {
                if k > 0 && b < boundary_bits(k - 1, l) {
                    k -= 1;
                } else if k < CODE_MAX && b >= boundary_bits(k, l) {
                    k += 1;
                }
            }
            k
        }
        Range::General(m) => {
            if b >= m.to_bits() {
                return CODE_MAX;
            }
            let t = 255.0 * power.log2() / m.log2();
            (t + 0.5).floor().clamp(0.0, 255.0) as u32
        }
        Range::Degenerate => 0,
    }
}

/// The specular power a code stands for: `max_power^(code/255)`.
///
/// **Error bound:** for power-of-two `max_power` the correctly rounded value (≤ 0.5 ULP; every
/// code checked on the adapter against 200-bit references), bit-identical to the WGSL. For
/// other ranges `exp2(code·log2(max_power)/255)`: WGSL allows `3 + 2|x|` ULP for `exp2` plus
/// the propagated `log2` error; this twin uses Rust's `log2`/`exp2` and is not bit-identical.
/// Code 255 returns `max_power` itself in every range.
///
/// **Bad input:** codes above 255 decode as 255; degenerate `max_power` → 1.0.
pub fn decode_log_roughness(code: u32, max_power: f32) -> f32 {
    let k = code.min(CODE_MAX);
    match range(max_power) {
        Range::Degenerate => 1.0,
        Range::PowerOfTwo(l) => {
            let n = k * l;
            f32::from_bits(EXP2_STEPS[(n % 255) as usize] + ((n / 255) << 23))
        }
        Range::General(m) => {
            if k == CODE_MAX {
                m
            } else {
                (k as f32 * m.log2() / 255.0).exp2()
            }
        }
    }
}

/// One RGBA8 texel holding an xyz8 normal in bytes 0–2 (as the xyz8 normal encoder packs it)
/// and a roughness code in byte 3 (alpha). Byte 3 of `normal_xyz8` is ignored; codes above 255
/// saturate to 255. Exact (bit operations).
pub fn pack_normal_xyz8_log_roughness(normal_xyz8: u32, code: u32) -> u32 {
    (normal_xyz8 & 0x00ff_ffff) | (code.min(CODE_MAX) << 24)
}

/// The packed xyz8 normal of a texel from [`pack_normal_xyz8_log_roughness`] (bytes 0–2,
/// byte 3 zero). Exact.
pub fn normal_xyz8_from_log_roughness_texel(texel: u32) -> u32 {
    texel & 0x00ff_ffff
}

/// The roughness code of such a texel (byte 3). Exact.
pub fn log_roughness_code_from_texel(texel: u32) -> u32 {
    texel >> 24
}

/// The worst relative round-trip error of log-range storage: half a step, `2^(L/510) − 1`
/// with `L = log2(max_power)` (f64). NaN propagates; `max_power = 1` gives 0 and `+∞` gives
/// `+∞`.
pub fn quantisation_limit(max_power: f64) -> f64 {
    (max_power.log2() / 510.0).exp2() - 1.0
}

/// Error bounds of the general-range (not power-of-two `max_power`) round trip, relative, kept
/// once: `tests/roughness.rs` asserts them on the adapter and under the worst-case emulation.
/// (Power-of-two ranges are exact on every conforming adapter: integer encoder, table decoder.)
///
/// With `u = 2^-24` and one ULP ≤ `2u` relative, on any conforming adapter (WGSL accuracy
/// rules), `L = log2(max_power)`:
/// - **encode** `t = 255·log2(p)/L`: each `log2` within 3 ULP (`6u`), the product rounded to
///   either neighbour (`2u`), the division 2.5 ULP (`5u`), plus `6u` for `L`'s own `log2`: `t` is
///   off by `≤ 19u·t ≤ 19u·255` codes; a power that close to a code boundary may take the other
///   code, costing at most `19u·255·(L/255)·ln 2 = 19u·L·ln 2` more relative error;
/// - **decode** `x = k·L/255`: off by `≤ (6 + 2 + 5)u·x`, adding `13u·x·ln 2` relative; `exp2`
///   adds `(3 + 2x)` ULP `≤ (3 + 2x)·2u`; with `x ≤ L`.
pub mod bounds {
    const U: f64 = 1.0 / 16_777_216.0;

    /// How far from a code boundary (in codes) a general-range encode may still take the
    /// neighbouring code: `t` is off by at most `19u·t ≤ 19u·255` (the encode step above).
    /// Power-of-two ranges decide every boundary exactly: their margin is 0.
    pub fn encode_neighbour_margin() -> f64 {
        19.0 * U * 255.0
    }

    /// A power-of-two range's decode, relative: the table entry correctly rounded and the
    /// exponent added exactly, so `≤ 0.5 ULP ≤ u` on every conforming adapter.
    pub const POWER_OF_TWO_DECODE: f64 = U;

    /// Any range's decode against `max_power^(k/255)`, relative: [`POWER_OF_TWO_DECODE`] for
    /// `2^L`, else [`general_range_decode`] plus `u` for the second-order terms its first-order
    /// sum drops (below 1e-10 for `L ≤ 127`) and the f64 reference's own error (1e-16).
    pub fn decode(max_power: f32) -> f64 {
        if max_power.log2().fract() == 0.0 {
            POWER_OF_TWO_DECODE
        } else {
            general_range_decode(max_power) + U
        }
    }

    /// Any range's round trip, relative: for `2^L` the half step plus the decode's rounding,
    /// `q + u·(1 + q)` with `q` = [`super::quantisation_limit`] (exact code, correctly rounded
    /// power), else [`general_range`].
    pub fn round_trip(max_power: f32) -> f64 {
        if max_power.log2().fract() == 0.0 {
            let q = super::quantisation_limit(f64::from(max_power));
            q + U * (1.0 + q)
        } else {
            general_range(max_power)
        }
    }

    /// The decode part: `13u·L·ln 2 + (3 + 2L)·2u`.
    pub fn general_range_decode(max_power: f32) -> f64 {
        let l = f64::from(max_power).log2();
        13.0 * U * l * std::f64::consts::LN_2 + (3.0 + 2.0 * l) * 2.0 * U
    }

    /// The whole round trip: the quantisation limit, the encode part `19u·L·ln 2`, the decode
    /// part, and `u` for the comparison in f64.
    pub fn general_range(max_power: f32) -> f64 {
        let l = f64::from(max_power).log2();
        super::quantisation_limit(f64::from(max_power))
            + 19.0 * U * l * std::f64::consts::LN_2
            + general_range_decode(max_power)
            + U
    }
}

/// Exact references (f64) for this module.
pub mod exact {
    /// `max_power^(code/255)` in f64 (relative error ~1e-16). Codes above 255 count as 255,
    /// like the twin; a NaN `max_power` propagates.
    pub fn decode(code: u32, max_power: f64) -> f64 {
        (max_power.log2() * f64::from(code.min(255)) / 255.0).exp2()
    }

    /// The code nearest `255·log2(p)/log2(max_power)` in log range (ties upwards), clamped, for
    /// `p ≥ 1` finite and `max_power > 1`. f64 `log2` is within 1e-16 relative, which decides
    /// every `f32` power correctly except exact ties (which `log2` of a power of two returns
    /// exactly). Outside that domain: powers below 1 clamp to code 0, above `max_power` to
    /// 255, and NaN gives code 0 (the float-to-integer cast).
    pub fn encode(p: f64, max_power: f64) -> u32 {
        let t = 255.0 * p.log2() / max_power.log2();
        (t + 0.5).floor().clamp(0.0, 255.0) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tables against f64 `exp2` (error ≤ 1e-16 relative): each entry must be the
    /// correctly rounded (resp. rounded-up) value, with the f64 value far (> 1e-12 of an ULP
    /// interval) from any decision point so f64 cannot have misjudged it.
    #[test]
    fn tables_are_correctly_rounded() {
        for (r, &bits) in EXP2_STEPS.iter().enumerate() {
            let x = (r as f64 / 255.0).exp2();
            let v = f64::from(f32::from_bits(bits));
            let ulp = 2f64.powi(-23);
            crate::assert_within_abs!(
                x,
                v,
                < 0.5 * ulp * (1.0 - 1e-9),
                "doc above: correctly rounded, and f64 (1e-16) far from the half-ULP decision point",
                "EXP2_STEPS[{r}]"
            );
        }
        for (r, &bits) in BOUNDARY_STEPS.iter().enumerate() {
            let x = (r as f64 / 510.0).exp2();
            let v = f64::from(f32::from_bits(bits));
            let prev = f64::from(f32::from_bits(bits - 1));
            if r == 0 {
                assert_eq!(v, 1.0);
                continue;
            }
            let margin = "doc above: rounded up, and f64 (1e-16) far from the decision point";
            crate::assert_at_least!(v, > x * (1.0 + 1e-15), margin, "BOUNDARY_STEPS[{r}]");
            crate::assert_within!(prev, < x * (1.0 - 1e-15), margin, "BOUNDARY_STEPS[{r}] − 1 ULP");
        }
    }

    #[test]
    fn ends_and_midpoints() {
        assert_eq!(encode_log_roughness(1.0, 8192.0), 0);
        assert_eq!(encode_log_roughness(8192.0, 8192.0), 255);
        assert_eq!(decode_log_roughness(0, 8192.0), 1.0);
        assert_eq!(decode_log_roughness(255, 8192.0), 8192.0);
        // A tie: (2j+1)·13 ≡ 0 (mod 510) has no solution (510 = 2·255 and 2j+1 odd, 13 ∤ 510),
        // but with L = 2, j = 127: boundary 2^(255·2/510) = 2 exactly; ties go up.
        assert_eq!(encode_log_roughness(2.0, 4.0), 128);
        assert_eq!(
            encode_log_roughness(f32::from_bits(2.0f32.to_bits() - 1), 4.0),
            127
        );
    }

    #[test]
    fn bad_input() {
        for m in [f32::NAN, 1.0, 0.5, -8.0, 0.0, f32::NEG_INFINITY] {
            assert_eq!(range(m), Range::Degenerate);
            assert_eq!(encode_log_roughness(100.0, m), 0);
            assert_eq!(decode_log_roughness(200, m), 1.0);
        }
        assert_eq!(range(f32::INFINITY), Range::PowerOfTwo(127));
        for p in [f32::NAN, -1.0, -0.0, 0.0, 1e-40, 0.5, f32::NEG_INFINITY] {
            assert_eq!(encode_log_roughness(p, 8192.0), 0, "{p}");
        }
        assert_eq!(encode_log_roughness(f32::INFINITY, 8192.0), 255);
        assert_eq!(encode_log_roughness(1e9, 8192.0), 255);
        assert_eq!(decode_log_roughness(1000, 8192.0), 8192.0);
        let t = pack_normal_xyz8_log_roughness(0xff12_3456, 999);
        assert_eq!(t, 0xff12_3456);
        assert_eq!(normal_xyz8_from_log_roughness_texel(t), 0x12_3456);
        assert_eq!(log_roughness_code_from_texel(t), 255);
    }
}
