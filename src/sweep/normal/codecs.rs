//! The encodings the normal sweeps measure: each one's WGSL functions, Rust twins and f64
//! reference, in one table.

use crate::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use crate::wgsl::{
    NORMAL_HEMIOCT, NORMAL_OCT, NORMAL_SIGNED_OCT, NORMAL_SNORM8, NORMAL_SUBSTRATE, NORMAL_XY_FP16,
    NORMAL_XYZ8, NORMAL_XYZ10,
};
use glam::Vec3;

/// How one field of a code counts its steps (see [`Codec::lanes`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LaneKind {
    /// An unsigned integer (unorm channels, octahedral coordinates).
    Unsigned,
    /// A two's complement integer (snorm channels).
    Signed,
    /// An f16, stepped through its ordered values (`±0` one value).
    F16,
}

/// One field of a code: `width` bits from bit `shift`, counted as `kind`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lane {
    /// The field's lowest bit.
    pub shift: u32,
    /// Its width in bits.
    pub width: u32,
    /// How a step is counted.
    pub kind: LaneKind,
}

const fn lanes<const N: usize>(width: u32, kind: LaneKind) -> [Lane; N] {
    let mut l = [Lane {
        shift: 0,
        width,
        kind,
    }; N];
    let mut i = 0;
    while i < N {
        l[i].shift = i as u32 * width;
        i += 1;
    }
    l
}

const UNORM8X3: [Lane; 3] = lanes(8, LaneKind::Unsigned);
const UNORM10X3: [Lane; 3] = lanes(10, LaneKind::Unsigned);
const SNORM8X3: [Lane; 3] = lanes(8, LaneKind::Signed);
const F16X2: [Lane; 2] = lanes(16, LaneKind::F16);
const OCT8: [Lane; 2] = lanes(8, LaneKind::Unsigned);
const OCT10: [Lane; 2] = lanes(10, LaneKind::Unsigned);
const OCT12: [Lane; 2] = lanes(12, LaneKind::Unsigned);
const OCT16: [Lane; 2] = lanes(16, LaneKind::Unsigned);
/// Substrate's word: u in bits 10–20, v in 21–31 (`crate::normal::substrate`).
const SUBSTRATE11: [Lane; 2] = [
    Lane {
        shift: substrate::U_SHIFT,
        width: 11,
        kind: LaneKind::Unsigned,
    },
    Lane {
        shift: substrate::V_SHIFT,
        width: 11,
        kind: LaneKind::Unsigned,
    },
];
/// O3DE's signed octahedron: u in bits 0–9, v in 10–19, z's sign in bit 20
/// (`crate::normal::signed_oct`).
const SIGNED_OCT10: [Lane; 3] = [
    Lane {
        shift: 0,
        width: 10,
        kind: LaneKind::Unsigned,
    },
    Lane {
        shift: 10,
        width: 10,
        kind: LaneKind::Unsigned,
    },
    Lane {
        shift: 20,
        width: 1,
        kind: LaneKind::Unsigned,
    },
];

/// One encoding: its WGSL functions, its Rust twins and its f64 reference encoder.
#[derive(Clone, Copy)]
pub struct Codec {
    /// Short name for tables (`oct24`, `oct24 fast`, …).
    pub name: &'static str,
    /// Bits of the code.
    pub bits: u32,
    /// The code's fields, for counting how many steps apart two codes are.
    pub lanes: &'static [Lane],
    /// The engines (and talks) that store this form, for the README's table (`—`: none found in
    /// `research/engines.md`'s survey).
    pub stored_by: &'static str,
    /// Whether it encodes view-space normals of one hemisphere only (`z ≥ 0`): its errors are
    /// measured over that hemisphere.
    pub hemisphere: bool,
    /// The WGSL file holding both functions.
    pub source: &'static str,
    /// WGSL encoder `fn(n: vec3<f32>) -> u32`.
    pub encode: &'static str,
    /// WGSL decoder `fn(p: u32) -> vec3<f32>`.
    pub decode: &'static str,
    /// Rust twin of the encoder.
    pub twin_encode: fn(Vec3) -> u32,
    /// Rust twin of the decoder.
    pub twin_decode: fn(u32) -> Vec3,
    /// The same algorithm in f64 (the survey's, for the octahedral codes).
    pub reference_encode: fn([f64; 3]) -> u32,
    /// The exact direction a code stands for, in f64.
    pub reference_decode: fn(u32) -> [f64; 3],
    /// Published targets (mean°, max°) from an independent float64 reproduction of the
    /// algorithm, where one exists.
    pub target: Option<(f64, f64)>,
    /// How the emulated sweeps of [`crate::sweep::conforming`] sample the inputs: 1 runs them at
    /// every input; `k > 1` at one input in `k` (hashed) and at the `1/k` of the inputs the adapter's
    /// round trip erred most on ([`crate::sweep::conforming::emulation_sample`]). The encoders
    /// that choose among candidates sample: the precise octahedral ones ([`PRECISE_SAMPLE`]) and
    /// the best-fit xyz8 one ([`BEST_FIT_SAMPLE`]); the rounding encoders run at every input.
    pub emulation_sample: usize,
}

/// [`Codec::emulation_sample`] of the precise octahedral encoders (oct16 to oct32, hemioct24,
/// Substrate's, the signed octahedron): every emulated operation is a call, and their four
/// scored candidates made each one's three emulated sweeps over 434,204 inputs 15 to 30 s of
/// CPU (2-core Xeon, 2026-12-06). A policy moves their code only at a near-tie of two
/// candidates, where the adapter's round trip errs about as much as the emulated one: the
/// sample's second part, the inputs the adapter erred most on, holds their worst.
pub const PRECISE_SAMPLE: usize = 4;

/// [`Codec::emulation_sample`] of the best-fit xyz8 encoder: its loop of 128 planes costs about
/// 100 rounding encodes, and at one input in 16 its three emulated sweeps were still 65 s of
/// `every_normal_encoding_under_emulation`'s 240 s of CPU (2026-12-06).
pub const BEST_FIT_SAMPLE: usize = 64;

/// The default tier's emulation sample of the codecs whose [`Codec::emulation_sample`] is 1
/// (the rounding encoders and the decoder-only forms): see [`default_tier_sample`].
pub const ROUNDING_DEFAULT_TIER_SAMPLE: usize = 8;

/// The emulation sample of `c` in the default tier (`bash .ci/test`; the full tier,
/// `PREPASS_FULL=1`, emulates every input): the rounding encoders at one input in
/// [`ROUNDING_DEFAULT_TIER_SAMPLE`], the encoders that choose at four times their
/// [`Codec::emulation_sample`] (precise octahedral 1 in 16, best fit 1 in 256), each with
/// [`crate::sweep::conforming::emulation_sample`]'s rule: one input in `k` by a hash of its
/// index, plus the `1/k` of the inputs the adapter's round trip erred most on.
///
/// Why it holds the worst: a policy moves a code only where the exact value lies within a few
/// ULPs of a rounding boundary or of a tie between candidates (the emulation's code is within
/// one step of the twin's, asserted), and there the adapter's code is one of the two a
/// conforming adapter may give, so the emulated round trip errs by at most the decoder's
/// allowance more than the adapter's round trip at an input with the same error: the inputs
/// the adapter erred most on, kept whole, are where the emulated worst lies. Over 434,204
/// inputs the kept part is 54,275 inputs for a rounding encoder, 27,137 for a precise one and
/// 1,696 for the best fit. `tests/conforming.rs` (`default_tier_sample_finds_the_full_tiers_worst`)
/// checks that the sample's worst equals every input's on a rounding and a precise encoder.
pub fn default_tier_sample(c: &Codec) -> usize {
    match c.emulation_sample {
        1 => ROUNDING_DEFAULT_TIER_SAMPLE,
        k => 4 * k,
    }
}

fn xyfp16_ref_encode(n: [f64; 3]) -> u32 {
    let u = crate::normal::exact::unit(n).unwrap_or([0.0, 0.0, 1.0]);
    let h = |x: f64| u32::from(half::f16::from_f64(x.clamp(-1.0, 1.0)).to_bits());
    h(u[0]) | (h(u[1]) << 16)
}

fn xyfp16_ref_decode(p: u32) -> [f64; 3] {
    let h = |b: u32| f64::from(half::f16::from_bits(b as u16).to_f32());
    let (x, y) = (h(p).clamp(-1.0, 1.0), h(p >> 16).clamp(-1.0, 1.0));
    let (x, y) = (
        if x.is_nan() { 0.0 } else { x },
        if y.is_nan() { 0.0 } else { y },
    );
    crate::normal::exact::unit([x, y, (1.0 - x * x - y * y).max(0.0).sqrt()])
        .unwrap_or([0.0, 0.0, 1.0])
}

macro_rules! oct_refs {
    ($bits:literal, $p:ident, $r:ident, $d:ident) => {
        fn $p(n: [f64; 3]) -> u32 {
            oct::exact::encode_precise(n, $bits)
        }
        fn $r(n: [f64; 3]) -> u32 {
            oct::exact::encode_round(n, $bits)
        }
        fn $d(p: u32) -> [f64; 3] {
            oct::exact::decode(p, $bits)
        }
    };
}
oct_refs!(8, oct16_ref_p, oct16_ref_r, oct16_ref_d);
oct_refs!(10, oct20_ref_p, oct20_ref_r, oct20_ref_d);
oct_refs!(12, oct24_ref_p, oct24_ref_r, oct24_ref_d);
oct_refs!(16, oct32_ref_p, oct32_ref_r, oct32_ref_d);

macro_rules! oct_codec {
    ($name:literal, $stored:literal, $bits:literal, $lanes:expr, $enc:ident, $dec:ident, $twin:path, $twin_dec:path, $r:ident, $d:ident, $t:expr, $sample:expr) => {
        Codec {
            name: $name,
            stored_by: $stored,
            bits: 2 * $bits,
            lanes: $lanes,
            hemisphere: false,
            source: NORMAL_OCT,
            encode: stringify!($enc),
            decode: stringify!($dec),
            twin_encode: $twin,
            twin_decode: $twin_dec,
            reference_encode: $r,
            reference_decode: $d,
            target: $t,
            emulation_sample: $sample,
        }
    };
}

/// Every encoding: xyz8, xy FP16, octahedral 16/20/24/32 precise and fast, hemi-octahedral 24
/// precise and fast (errors of the hemisphere-only codes are measured over `z ≥ 0`), then the
/// engines' forms: xyz10 (RGB10A2), snorm8 xyz, Unreal Substrate's 11:11 centred octahedron
/// (its word's normal bits; roughness and flags zero), precise and fast, xyz8's best-fit
/// encoder (Godot 4's), and O3DE's signed octahedron (RGB10A2), precise and fast.
pub const CODECS: [Codec; 19] = [
    Codec {
        name: "xyz8",
        stored_by: "Resistance 2; Godot 4 (this decoder; its encoder is `xyz8 best-fit`) — Godot reads: exact; writes: per-channel rounding, not Godot's best fit (docs/figures.md, Engine interop)",
        bits: 24,
        lanes: &UNORM8X3,
        hemisphere: false,
        source: NORMAL_XYZ8,
        encode: "encode_normal_xyz8",
        decode: "decode_normal_xyz8",
        twin_encode: xyz8::encode_normal_xyz8,
        twin_decode: xyz8::decode_normal_xyz8,
        reference_encode: xyz8::exact::encode,
        reference_decode: xyz8::exact::decode,
        target: Some((0.170, 0.390)),
        emulation_sample: 1,
    },
    Codec {
        name: "xy fp16",
        stored_by: "Killzone 2",
        bits: 32,
        lanes: &F16X2,
        hemisphere: true,
        source: NORMAL_XY_FP16,
        encode: "encode_normal_xy_fp16",
        decode: "decode_normal_xy_fp16",
        twin_encode: xy_fp16::encode_normal_xy_fp16,
        twin_decode: xy_fp16::decode_normal_xy_fp16,
        reference_encode: xyfp16_ref_encode,
        reference_decode: xyfp16_ref_decode,
        target: None,
        emulation_sample: 1,
    },
    oct_codec!(
        "oct16",
        "Unreal 5 mobile deferred (8:8) — reads: exact; writes: prepass's code, a few words differ (docs/figures.md, Engine interop)",
        8,
        &OCT8,
        encode_normal_oct16,
        decode_normal_oct16,
        oct::encode_normal_oct16,
        oct::decode_normal_oct16,
        oct16_ref_p,
        oct16_ref_d,
        Some((0.315, 0.636)),
        PRECISE_SAMPLE
    ),
    oct_codec!(
        "oct16 fast",
        "Unreal 5 mobile deferred (8:8) — reads: exact; writes: prepass's code, a few words differ (docs/figures.md, Engine interop)",
        8,
        &OCT8,
        encode_normal_oct16_fast,
        decode_normal_oct16,
        oct::encode_normal_oct16_fast,
        oct::decode_normal_oct16,
        oct16_ref_r,
        oct16_ref_d,
        Some((0.337, 0.951)),
        1
    ),
    oct_codec!(
        "oct20",
        "— (O3DE's RGB10A2 layout is the row `signed oct`)",
        10,
        &OCT10,
        encode_normal_oct20,
        decode_normal_oct20,
        oct::encode_normal_oct20,
        oct::decode_normal_oct20,
        oct20_ref_p,
        oct20_ref_d,
        None,
        PRECISE_SAMPLE
    ),
    oct_codec!(
        "oct20 fast",
        "— (O3DE's RGB10A2 layout is the row `signed oct`)",
        10,
        &OCT10,
        encode_normal_oct20_fast,
        decode_normal_oct20,
        oct::encode_normal_oct20_fast,
        oct::decode_normal_oct20,
        oct20_ref_r,
        oct20_ref_d,
        None,
        1
    ),
    oct_codec!(
        "oct24",
        "Bevy deferred (the same word); Unity URP (`_unity`: its byte order), HDRP (`_hdrp`: with HDRP's z floor) — reads: exact; writes: prepass's code, some words differ (docs/figures.md, Engine interop)",
        12,
        &OCT12,
        encode_normal_oct24,
        decode_normal_oct24,
        oct::encode_normal_oct24,
        oct::decode_normal_oct24,
        oct24_ref_p,
        oct24_ref_d,
        Some((0.0195, 0.0395)),
        PRECISE_SAMPLE
    ),
    oct_codec!(
        "oct24 fast",
        "Bevy deferred (the same word); Unity URP (`_unity`: its byte order), HDRP (`_hdrp`: with HDRP's z floor) — reads: exact; writes: prepass's code, some words differ (docs/figures.md, Engine interop)",
        12,
        &OCT12,
        encode_normal_oct24_fast,
        decode_normal_oct24,
        oct::encode_normal_oct24_fast,
        oct::decode_normal_oct24,
        oct24_ref_r,
        oct24_ref_d,
        Some((0.0209, 0.0591)),
        1
    ),
    oct_codec!(
        "oct32",
        "—",
        16,
        &OCT16,
        encode_normal_oct32,
        decode_normal_oct32,
        oct::encode_normal_oct32,
        oct::decode_normal_oct32,
        oct32_ref_p,
        oct32_ref_d,
        Some((0.00122, 0.00246)),
        PRECISE_SAMPLE
    ),
    oct_codec!(
        "oct32 fast",
        "—",
        16,
        &OCT16,
        encode_normal_oct32_fast,
        decode_normal_oct32,
        oct::encode_normal_oct32_fast,
        oct::decode_normal_oct32,
        oct32_ref_r,
        oct32_ref_d,
        Some((0.00131, 0.00369)),
        1
    ),
    Codec {
        name: "hemioct24",
        stored_by: "—",
        bits: 24,
        lanes: &OCT12,
        hemisphere: true,
        source: NORMAL_HEMIOCT,
        encode: "encode_normal_hemioct24",
        decode: "decode_normal_hemioct24",
        twin_encode: hemioct::encode_normal_hemioct24,
        twin_decode: hemioct::decode_normal_hemioct24,
        reference_encode: hemioct::exact::encode_precise,
        reference_decode: hemioct::exact::decode,
        target: None,
        emulation_sample: PRECISE_SAMPLE,
    },
    Codec {
        name: "hemioct24 fast",
        stored_by: "—",
        bits: 24,
        lanes: &OCT12,
        hemisphere: true,
        source: NORMAL_HEMIOCT,
        encode: "encode_normal_hemioct24_fast",
        decode: "decode_normal_hemioct24",
        twin_encode: hemioct::encode_normal_hemioct24_fast,
        twin_decode: hemioct::decode_normal_hemioct24,
        reference_encode: hemioct::exact::encode_round,
        reference_decode: hemioct::exact::decode,
        target: None,
        emulation_sample: 1,
    },
    Codec {
        name: "xyz10",
        stored_by: "Unreal 5 GBufferA (modelled as a unorm write of n·0.5 + 0.5 from the project's notes: Unreal's source is private, not transcribed); Bevy normal prepass — reads: exact; writes: normalised first, alpha 0 where Bevy writes 1 (docs/figures.md, Engine interop)",
        bits: 30,
        lanes: &UNORM10X3,
        hemisphere: false,
        source: NORMAL_XYZ10,
        encode: "encode_normal_xyz10",
        decode: "decode_normal_xyz10",
        twin_encode: xyz10::encode_normal_xyz10,
        twin_decode: xyz10::decode_normal_xyz10,
        reference_encode: xyz10::exact::encode,
        reference_decode: xyz10::exact::decode,
        target: None,
        emulation_sample: 1,
    },
    Codec {
        name: "snorm8",
        stored_by: "Unity URP (default target) — reads: exact; writes: URP's texels but at ties (docs/figures.md, Engine interop)",
        bits: 24,
        lanes: &SNORM8X3,
        hemisphere: false,
        source: NORMAL_SNORM8,
        encode: "encode_normal_snorm8",
        decode: "decode_normal_snorm8",
        twin_encode: snorm8::encode_normal_snorm8,
        twin_decode: snorm8::decode_normal_snorm8,
        reference_encode: snorm8::exact::encode,
        reference_decode: snorm8::exact::decode,
        target: None,
        emulation_sample: 1,
    },
    Codec {
        name: "substrate",
        stored_by: "Unreal 5 Substrate (top-layer word, with roughness and flags)",
        bits: 22,
        lanes: &SUBSTRATE11,
        hemisphere: false,
        source: NORMAL_SUBSTRATE,
        encode: "encode_substrate_normal",
        decode: "decode_substrate_normal",
        twin_encode: substrate::encode_substrate_normal,
        twin_decode: substrate::decode_substrate_normal,
        reference_encode: substrate::exact::encode_precise,
        reference_decode: substrate::exact::decode,
        target: None,
        emulation_sample: PRECISE_SAMPLE,
    },
    Codec {
        name: "substrate fast",
        stored_by: "Unreal 5 Substrate (top-layer word, with roughness and flags)",
        bits: 22,
        lanes: &SUBSTRATE11,
        hemisphere: false,
        source: NORMAL_SUBSTRATE,
        encode: "encode_substrate_normal_fast",
        decode: "decode_substrate_normal",
        twin_encode: substrate::encode_substrate_normal_fast,
        twin_decode: substrate::decode_substrate_normal,
        reference_encode: substrate::exact::encode_round,
        reference_decode: substrate::exact::decode,
        target: None,
        emulation_sample: 1,
    },
    Codec {
        name: "xyz8 best-fit",
        stored_by: "Godot 4 (Forward+ normal_roughness, best-fit normals) — reads: exact; writes: the nearest code, not always Godot's lookup-table texel (docs/figures.md, Engine interop)",
        bits: 24,
        lanes: &UNORM8X3,
        hemisphere: false,
        source: NORMAL_XYZ8,
        encode: "encode_normal_xyz8_best",
        decode: "decode_normal_xyz8",
        twin_encode: xyz8::encode_normal_xyz8_best,
        twin_decode: xyz8::decode_normal_xyz8,
        reference_encode: xyz8::exact::encode_best,
        reference_decode: xyz8::exact::decode,
        target: None,
        emulation_sample: BEST_FIT_SAMPLE,
    },
    Codec {
        name: "signed oct",
        stored_by: "O3DE (Atom's signed octahedron in RGB10A2) — reads: exact, every B; writes: `_fast` the engine's texels, precise prepass's code (docs/figures.md, Engine interop)",
        bits: 21,
        lanes: &SIGNED_OCT10,
        hemisphere: false,
        source: NORMAL_SIGNED_OCT,
        encode: "encode_normal_signed_oct",
        decode: "decode_normal_signed_oct",
        twin_encode: signed_oct::encode_normal_signed_oct,
        twin_decode: signed_oct::decode_normal_signed_oct,
        reference_encode: signed_oct::exact::encode_precise,
        reference_decode: signed_oct::exact::decode,
        target: None,
        emulation_sample: PRECISE_SAMPLE,
    },
    Codec {
        name: "signed oct fast",
        stored_by: "O3DE (Atom's signed octahedron in RGB10A2) — reads: exact, every B; writes: `_fast` the engine's texels, precise prepass's code (docs/figures.md, Engine interop)",
        bits: 21,
        lanes: &SIGNED_OCT10,
        hemisphere: false,
        source: NORMAL_SIGNED_OCT,
        encode: "encode_normal_signed_oct_fast",
        decode: "decode_normal_signed_oct",
        twin_encode: signed_oct::encode_normal_signed_oct_fast,
        twin_decode: signed_oct::decode_normal_signed_oct,
        reference_encode: signed_oct::exact::encode_round,
        reference_decode: signed_oct::exact::decode,
        target: None,
        emulation_sample: 1,
    },
];

/// The codec named `name` in [`CODECS`].
pub fn codec(name: &str) -> &'static Codec {
    CODECS
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no codec {name}"))
}
