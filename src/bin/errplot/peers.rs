//! Peers as baselines: what renderers and codecs people already use, re-implemented in WGSL from
//! their descriptions (`tests/baselines/peer_*.wgsl`, one file per peer) and measured on the same
//! inputs with the same three costs as the shipped functions, plus the dominance check
//! ("does any peer have no more error and no more cost, one of them strictly less?").
//!
//! This file depends on the `prepass` crate only, so `tests/errplot_peers.rs` includes it too
//! (`#[path]`) and checks the SPIR-V-count dominance on the adapter the tests use.

#![allow(dead_code)] // each includer uses part of it

use prepass::harness::{Arg, Gpu};
use prepass::precision::metrics::{ErrorStats, angle_degrees, relative_error, widen3};

/// Bevy's G-buffer oct24 and its `−near/d` depth.
pub const BEVY: &str = include_str!("../../../tests/baselines/peer_bevy.wgsl");
/// meshoptimizer's octahedral filter (encode, scalar decode).
pub const MESHOPT: &str = include_str!("../../../tests/baselines/peer_meshopt.wgsl");
/// The JCGT 2014 survey's precise encoder as published (largest f32 dot) and its snorm decode.
pub const SURVEY: &str = include_str!("../../../tests/baselines/peer_survey.wgsl");
/// Unreal 5's GBufferA normal (`n·0.5 + 0.5` in RGB10A2), which Bevy's normal prepass stores too,
/// and Substrate's top-layer normal (octahedral 11:11 on a centred grid, truncated).
pub const UNREAL: &str = include_str!("../../../tests/baselines/peer_unreal.wgsl");
/// Unity HDRP's normal buffer: octahedral 12:12 in three bytes (`u32(f·4095.5)`).
pub const UNITY: &str = include_str!("../../../tests/baselines/peer_unity.wgsl");
/// Unity URP's default normal target (xyz in RGBA8 snorm).
pub const URP: &str = include_str!("../../../tests/baselines/peer_urp.wgsl");
/// Godot 4's best-fit normal (lookup-table scale, RGBA8), its lookup texel computed inline.
pub const GODOT: &str = include_str!("../../../tests/baselines/peer_godot.wgsl");
/// O3DE's signed octahedron (RGB10A2: hemi-octahedral 10:10 of `(x, y, |z|)`, z's sign in B).
pub const O3DE: &str = include_str!("../../../tests/baselines/peer_o3de.wgsl");
/// LYGIA's `linearizeDepth` and `depth2viewZ` (OpenGL conventions, finite far).
pub const LYGIA: &str = include_str!("../../../tests/baselines/peer_lygia.wgsl");

/// Name prefix of every peer row (CSV, tables, plots).
pub const PREFIX: &str = "peer:";

/// A peer normal codec: WGSL encoder `fn(vec3<f32>) -> u32` and decoder `fn(u32) -> vec3<f32>`.
pub struct NormalPeer {
    /// Label (after [`PREFIX`]).
    pub name: &'static str,
    /// Information bits of the code.
    pub bits: u32,
    /// Its WGSL file.
    pub source: &'static str,
    /// Encoder function.
    pub encode: &'static str,
    /// Decoder function.
    pub decode: &'static str,
}

/// The normal-codec peers.
pub const NORMAL_PEERS: [NormalPeer; 13] = [
    NormalPeer {
        name: "bevy gbuffer oct24 (×4095)",
        bits: 24,
        source: BEVY,
        encode: "peer_bevy_gbuffer_normal_encode",
        decode: "peer_bevy_gbuffer_normal_decode",
    },
    NormalPeer {
        name: "meshopt oct K=8",
        bits: 16,
        source: MESHOPT,
        encode: "peer_meshopt_oct8_encode",
        decode: "peer_meshopt_oct8_decode",
    },
    NormalPeer {
        name: "meshopt oct K=12",
        bits: 24,
        source: MESHOPT,
        encode: "peer_meshopt_oct12_encode",
        decode: "peer_meshopt_oct12_decode",
    },
    NormalPeer {
        name: "meshopt oct K=16",
        bits: 32,
        source: MESHOPT,
        encode: "peer_meshopt_oct16_encode",
        decode: "peer_meshopt_oct16_decode",
    },
    NormalPeer {
        name: "survey precise16 (f32 dot)",
        bits: 16,
        source: SURVEY,
        encode: "peer_survey_precise16_encode",
        decode: "peer_survey_precise16_decode",
    },
    NormalPeer {
        name: "survey precise24 (f32 dot)",
        bits: 24,
        source: SURVEY,
        encode: "peer_survey_precise24_encode",
        decode: "peer_survey_precise24_decode",
    },
    NormalPeer {
        name: "survey precise32 (f32 dot)",
        bits: 32,
        source: SURVEY,
        encode: "peer_survey_precise32_encode",
        decode: "peer_survey_precise32_decode",
    },
    NormalPeer {
        name: "unreal/bevy xyz10 (n·0.5 + 0.5)",
        bits: 30,
        source: UNREAL,
        encode: "peer_unreal_gbuffer_normal_encode",
        decode: "peer_unreal_gbuffer_normal_decode",
    },
    NormalPeer {
        name: "urp snorm8",
        bits: 24,
        source: URP,
        encode: "peer_urp_normal_encode",
        decode: "peer_urp_normal_decode",
    },
    NormalPeer {
        name: "unity hdrp oct 12:12 (×4095.5)",
        bits: 24,
        source: UNITY,
        encode: "peer_unity_normal_encode",
        decode: "peer_unity_normal_decode",
    },
    NormalPeer {
        name: "unreal substrate oct 11:11 (trunc)",
        bits: 22,
        source: UNREAL,
        encode: "peer_unreal_substrate_normal_encode",
        decode: "peer_unreal_substrate_normal_decode",
    },
    NormalPeer {
        name: "godot best-fit xyz8 (lookup texel inline)",
        bits: 24,
        source: GODOT,
        encode: "peer_godot_normal_encode",
        decode: "peer_godot_normal_decode",
    },
    NormalPeer {
        name: "o3de signed oct 10:10 + sign (rgb10a2)",
        bits: 21,
        source: O3DE,
        encode: "peer_o3de_signed_oct_encode",
        decode: "peer_o3de_signed_oct_decode",
    },
];

/// A peer's round trip on the adapter: error over all inputs, over those with z ≥ 0 (to compare
/// with the hemisphere-only shipped encodings), and the codes (timing input for its decoder).
pub struct PeerRoundTrip {
    /// Angle (degrees) over every input.
    pub error: ErrorStats,
    /// Angle (degrees) over the inputs with z ≥ 0.
    pub error_upper: ErrorStats,
    /// The encoder's codes.
    pub codes: Vec<u32>,
}

/// Encode `dirs` with the peer's WGSL encoder and decode with its WGSL decoder, on the adapter.
pub fn normal_round_trip(
    gpu: &Gpu,
    p: &NormalPeer,
    dirs: &[[f32; 3]],
) -> Result<PeerRoundTrip, String> {
    let n = dirs.len() as u64;
    let codes = gpu
        .kernel(p.source, p.encode)
        .and_then(|k| k.run(&[Arg::column(dirs)], n))
        .map_err(|e| format!("{}: {e}", p.encode))?
        .into_words();
    let decoded = gpu
        .kernel(p.source, p.decode)
        .and_then(|k| k.run(&[Arg::column(&codes)], n))
        .map_err(|e| format!("{}: {e}", p.decode))?
        .as_vec3()
        .to_vec();
    let (mut error, mut error_upper) = (ErrorStats::default(), ErrorStats::default());
    for (i, (&d, &r)) in dirs.iter().zip(&decoded).enumerate() {
        let a = angle_degrees(widen3(d), widen3(r));
        error.add(i as u64, a);
        if d[2] >= 0.0 {
            error_upper.add(i as u64, a);
        }
    }
    Ok(PeerRoundTrip {
        error,
        error_upper,
        codes,
    })
}

/// A peer depth function `fn(d: u32, near: f32, far: f32) -> f32` of a standard-Z 24-bit code;
/// `negated`: it returns view-space z (negative in front), so the distance is its negation
/// (exact, and not charged to its cost).
pub struct DepthPeer {
    /// Label (after [`PREFIX`]).
    pub name: &'static str,
    /// WGSL function in [`LYGIA`].
    pub function: &'static str,
    /// Returns −distance.
    pub negated: bool,
}

/// The standard-Z D24 depth peers (LYGIA).
pub const DEPTH24_PEERS: [DepthPeer; 2] = [
    DepthPeer {
        name: "lygia linearizeDepth",
        function: "peer_lygia_linearize_depth24",
        negated: false,
    },
    DepthPeer {
        name: "lygia depth2viewZ (negated)",
        function: "peer_lygia_depth2viewz24",
        negated: true,
    },
];

/// Relative error of view distance of every 24-bit code through a peer, on the adapter, against
/// the exact distance of the code (`prepass::linear_depth::exact::view_z_from_depth24`).
pub fn depth24_errors(gpu: &Gpu, p: &DepthPeer, near: f32, far: f32) -> Result<ErrorStats, String> {
    let n = u64::from(prepass::depth24::DEPTH24_MAX) + 1;
    let out = gpu
        .kernel(LYGIA, p.function)
        .and_then(|k| {
            k.run(
                &[
                    Arg::Index { start: 0 },
                    Arg::splat_f32(near),
                    Arg::splat_f32(far),
                ],
                n,
            )
        })
        .map_err(|e| format!("{}: {e}", p.function))?;
    let mut s = ErrorStats::default();
    for (d, &v) in out.as_f32().iter().enumerate() {
        let got = if p.negated { -v } else { v };
        let exact = prepass::linear_depth::exact::view_z_from_depth24(d as u32, near, far);
        s.add(d as u64, relative_error(f64::from(got), exact));
    }
    Ok(s)
}

/// Float depths for the reversed-infinite family: `count` values spread evenly in ULP space
/// over `[2^-20, 1]` (view distances from `near` to `2^20·near`, where f32 depth keeps 24 bits).
pub fn reversed_depths(count: u32) -> Vec<f32> {
    let (lo, hi) = ((2f32).powi(-20).to_bits(), 1f32.to_bits());
    (0..count)
        .map(|k| {
            f32::from_bits(lo + ((u64::from(hi - lo) * u64::from(k)) / u64::from(count - 1)) as u32)
        })
        .collect()
}

/// Relative error of view distance from reversed-infinite depths `z` (exact: `near/z` in f64)
/// of `values` (what a function returned for each `z`; negated first when `negated`).
pub fn reversed_errors(z: &[f32], values: &[f32], near: f32, negated: bool) -> ErrorStats {
    let mut s = ErrorStats::default();
    for (i, (&z, &v)) in z.iter().zip(values).enumerate() {
        let got = if negated { -v } else { v };
        s.add(
            i as u64,
            relative_error(f64::from(got), f64::from(near) / f64::from(z)),
        );
    }
    s
}

/// One point of a Pareto plot for the dominance check.
#[derive(Clone, Debug)]
pub struct Point {
    /// Family (points are compared within a family only).
    pub family: String,
    /// Function name (peers carry [`PREFIX`]).
    pub name: String,
    /// Information bits (0 for functions that store nothing).
    pub bits: u32,
    /// Max error, as compared.
    pub max_error: f64,
    /// Max error over z ≥ 0 (peers of normal codecs), to compare with a hemisphere-only one.
    pub max_error_upper: Option<f64>,
    /// The shipped function is measured over z ≥ 0 only.
    pub upper_only: bool,
    /// The cost compared (SPIR-V instructions, or GPU ns).
    pub cost: f64,
}

impl Point {
    /// Whether this is a peer.
    pub fn is_peer(&self) -> bool {
        self.name.starts_with(PREFIX)
    }
}

/// Whether `peer` dominates `shipped`: same family, no more bits (it stores no more), max error
/// ≤ and cost ≤, at least one of the two strictly less. A hemisphere-only shipped function is
/// compared with the peer's error over z ≥ 0.
pub fn dominates(peer: &Point, shipped: &Point) -> bool {
    if peer.family != shipped.family || peer.bits > shipped.bits {
        return false;
    }
    let e = if shipped.upper_only {
        peer.max_error_upper.unwrap_or(peer.max_error)
    } else {
        peer.max_error
    };
    e <= shipped.max_error
        && peer.cost <= shipped.cost
        && (e < shipped.max_error || peer.cost < shipped.cost)
}

/// Whether `name` is a shipped function: neither a peer nor one of the crate's own test
/// baselines (`baseline_*`, `tests/baselines/`).
pub fn is_shipped(name: &str) -> bool {
    !name.starts_with(PREFIX) && !name.starts_with("baseline_")
}

/// For each shipped point, the peers that dominate it (in input order).
pub fn dominance(points: &[Point]) -> Vec<(String, Vec<String>)> {
    points
        .iter()
        .filter(|s| is_shipped(&s.name))
        .map(|s| {
            (
                s.name.clone(),
                points
                    .iter()
                    .filter(|p| p.is_peer() && dominates(p, s))
                    .map(|p| p.name.clone())
                    .collect(),
            )
        })
        .collect()
}
