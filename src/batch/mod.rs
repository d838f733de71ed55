//! Batch twins: every encoder and decoder of [`crate::normal`], [`crate::depth24`],
//! [`crate::roughness`] and the byte forms of [`crate::roughness_ggx`] over slices, vectorised, **bit-identical to the scalar twins for every
//! input** (NaN, infinities, subnormals and out-of-range codes included), so data encoded here
//! decodes exactly like the WGSL's on a correctly rounded adapter. (The `_vouched` normal
//! encoders are bit-identical on every input inside their contract; outside it they return
//! some valid code: [`normal`].)
//!
//! | family | batch twins | scalar twins |
//! |---|---|---|
//! | normals: xyz8, xyz10, snorm8, xy FP16, oct16/20/24/32 (precise, rounding, vouched), hemioct24 (also vouched), signed octahedron, Substrate (normal and whole word), `_unorm` forms | [`normal`] | [`crate::normal`] |
//! | 24-bit depth: pack, recover (packed, RGB8), hyperbolic depth, `unpack4x8unorm` | [`depth24`] | [`crate::depth24`] |
//! | log-range roughness: encode, decode | [`roughness`] | [`crate::roughness`] |
//! | GGX roughness in 8 bits: linear, Godot, log curve; encode, decode | [`roughness_ggx`] | [`crate::roughness_ggx`] |
//!
//! ## Names and the slice contract
//! Each batch twin has the name of its scalar twin and takes its parameters (the bits of a
//! generic octahedral code, a roughness range) first, then `src: &[In]`, then
//! `dst: &mut [Out]`, writing `dst[i] = scalar_twin(src[i])`. **`src` and `dst` must have the
//! same length: a mismatch panics** (naming the function and both lengths) before anything is
//! written. Every function comes in two forms:
//! - `name(…, src, dst)`: the best [`Level`] this CPU supports ([`Level::detected`]); with the
//!   `rayon` feature, batches of at least [`PAR_THRESHOLD`] elements are cut into chunks of
//!   [`PAR_CHUNK`] run on rayon's global pool (the output is the same: each element is computed
//!   on its own);
//! - `name_with(level, …, src, dst)`: exactly that level, on the calling thread (what the tests
//!   and the benchmark use to exercise and time each level); panics if this CPU lacks `level`.
//!
//! ## How it is vectorised, and why no SIMD crate
//! Each codec's per-element body is written once as branch-free Rust (selects instead of
//! branches, integer bit operations for the NaN/Inf/subnormal rules, wrapping integer arithmetic
//! on values bounded far below overflow, so that overflow checks — on in this crate's release
//! profile — add no branch), evaluating **the same IEEE operations in the same order as the
//! scalar twin**. A loop over the slices is then compiled once per [`Level`]: for the CPU's
//! baseline (SSE2 on `x86_64`, NEON on `aarch64`) and, on `x86_64`, again inside a
//! `#[target_feature(enable = "avx2")]` function chosen at run time by
//! `is_x86_feature_detected!`. LLVM vectorises these loops (8 lanes with AVX2, 4 with SSE2 or
//! NEON; the exceptions, scalar but branch-free, are in [`roughness`]). Bit-identity holds
//! because Rust never contracts `a·b + c` into an FMA nor reassociates, and `+ − × / sqrt` are
//! correctly rounded in SSE, AVX and NEON just as in scalar code. Two scalar operations are
//! replaced by exact equivalents that vectorise without SSE4.1:
//! `round_ties_even(x)` for `0 ≤ x < 2^23` is the bit pattern of `x + 2^23` minus that of
//! `2^23` (the addition rounds to an integer, ties to even), and `floor(x)` for `x ≥ 0` is the
//! truncating `x as i32`.
//!
//! We chose std's `is_x86_feature_detected!` and `#[target_feature]` over a crate: `wide`
//! picks its implementation from compile-time `cfg(target_feature)`, so a default `x86_64`
//! build gets its SSE2 path only, and AVX2 at run time would still need this dispatch;
//! `multiversion` generates exactly this dispatch (a `target_feature` clone and a detection
//! check) but hides the per-level functions the tests call; `pulp` would mean rewriting every
//! codec in its SIMD-type API for the same instructions. The dispatch is a dozen lines here.
//! The speed against meshoptimizer's filters is measured by `benches/batch.rs` (`.ci/bench`,
//! `docs/batch_bench.md`).
//!
//! `tests/batch.rs` checks every level this CPU has against the scalar twins: every code of
//! each decoder with at most 24 input bits, the stratified 32-bit sample, and the 2^24
//! Fibonacci directions plus the adversarial set for every encoder.

pub mod depth24;
pub mod normal;
pub mod roughness;
pub mod roughness_ggx;

/// Batches at least this long are split across rayon's pool by the plain (non-`_with`) batch
/// functions when the `rayon` feature is on: 2^16 elements, enough work per batch (tens of µs
/// or more at every codec's single-thread rate, `benches/batch.rs`) that the split's own cost
/// is small beside it.
pub const PAR_THRESHOLD: usize = 1 << 16;

/// Chunk length of the rayon split: 2^14 elements (≤ 256 KiB of input and output per chunk, so
/// a chunk stays in a core's L2 cache).
pub const PAR_CHUNK: usize = 1 << 14;

/// A compiled form of the batch loops.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Level {
    /// The scalar twin called once per element (the reference; every CPU).
    Scalar,
    /// `x86_64` baseline: 4-lane SSE2 (the loop compiled with the build's target features).
    Sse2,
    /// `x86_64` with AVX2, detected at run time: 8 lanes.
    Avx2,
    /// `aarch64` baseline: 4-lane NEON.
    Neon,
}

impl Level {
    /// Every level, in order of preference from the slowest.
    pub const ALL: [Level; 4] = [Level::Scalar, Level::Sse2, Level::Avx2, Level::Neon];

    /// Whether this CPU (and this build's target) can run `self`.
    pub fn available(self) -> bool {
        match self {
            Level::Scalar => true,
            Level::Sse2 => cfg!(target_arch = "x86_64"),
            Level::Avx2 => {
                #[cfg(target_arch = "x86_64")]
                {
                    std::is_x86_feature_detected!("avx2")
                }
                #[cfg(not(target_arch = "x86_64"))]
                {
                    false
                }
            }
            Level::Neon => cfg!(target_arch = "aarch64"),
        }
    }

    /// The levels this CPU can run, [`Level::Scalar`] first.
    pub fn all_available() -> Vec<Level> {
        Self::ALL.into_iter().filter(|l| l.available()).collect()
    }

    /// The fastest level this CPU can run: AVX2 where detected, else SSE2 on `x86_64`, NEON on
    /// `aarch64`, the scalar twins elsewhere. (std caches the detection: one atomic load.)
    pub fn detected() -> Level {
        if Level::Avx2.available() {
            Level::Avx2
        } else if cfg!(target_arch = "x86_64") {
            Level::Sse2
        } else if cfg!(target_arch = "aarch64") {
            Level::Neon
        } else {
            Level::Scalar
        }
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Level::Scalar => "scalar",
            Level::Sse2 => "sse2",
            Level::Avx2 => "avx2",
            Level::Neon => "neon",
        })
    }
}

/// The slice contract: panics unless `src` and `dst` have the same length.
#[track_caller]
pub(crate) fn check_lengths(name: &str, src: usize, dst: usize) {
    assert!(
        src == dst,
        "prepass::batch::{name}: {src} inputs but {dst} outputs (the slices must have equal lengths)"
    );
}

/// Panics with a clear message unless this CPU has `level`.
#[track_caller]
pub(crate) fn check_level(name: &str, level: Level) {
    assert!(
        level.available(),
        "prepass::batch::{name}: level {level} is not available on this CPU/target (available: {:?})",
        Level::all_available()
    );
}

/// `round_ties_even(x)` for `0 ≤ x < 2^23`, exactly: `x + 2^23` rounds to the integer nearest
/// `x` (ties to even; its ULP is 1), whose bit pattern is `0x4b00_0000` plus that integer.
/// Vectorises without SSE4.1's `roundps`. (NaN or out-of-range `x` give garbage; callers
/// clamp first.)
#[inline(always)]
pub(crate) fn round_even_small(x: f32) -> u32 {
    (x + 8_388_608.0).to_bits().wrapping_sub(0x4b00_0000)
}

/// One batch twin in both forms (see the module docs). `$scalar` is the scalar twin applied
/// per element, `$lane` the vectorisable body; both are closures over the parameters.
macro_rules! batch_fn {
    (
        $(#[$doc:meta])*
        $name:ident, $with:ident, $path:expr,
        ($($arg:ident : $aty:ty),*), $in:ty => $out:ty,
        scalar: $scalar:expr,
        lane: $lane:expr $(,)?
    ) => {
        $(#[$doc])*
        ///
        /// Runs at [`Level::detected`](crate::batch::Level::detected) (split across rayon's pool
        /// for long batches with the `rayon` feature). **Panics** if `src.len() != dst.len()`.
        #[track_caller]
        pub fn $name($($arg: $aty,)* src: &[$in], dst: &mut [$out]) {
            $crate::batch::check_lengths($path, src.len(), dst.len());
            let level = $crate::batch::Level::detected();
            #[cfg(feature = "rayon")]
            if src.len() >= $crate::batch::PAR_THRESHOLD {
                use rayon::prelude::*;
                src.par_chunks($crate::batch::PAR_CHUNK)
                    .zip(dst.par_chunks_mut($crate::batch::PAR_CHUNK))
                    .for_each(|(s, d)| $with(level, $($arg,)* s, d));
                return;
            }
            $with(level, $($arg,)* src, dst)
        }

        #[doc = concat!("[`", stringify!($name), "`] at exactly `level`, on the calling thread.")]
        ///
        /// **Panics** if `src.len() != dst.len()`, or if this CPU lacks `level`
        /// ([`Level::available`](crate::batch::Level::available)).
        #[track_caller]
        pub fn $with(level: $crate::batch::Level, $($arg: $aty,)* src: &[$in], dst: &mut [$out]) {
            $crate::batch::check_lengths($path, src.len(), dst.len());
            $crate::batch::check_level($path, level);
            #[inline(always)]
            fn body($($arg: $aty,)* src: &[$in], dst: &mut [$out]) {
                let lane = $lane;
                for (d, s) in dst.iter_mut().zip(src) {
                    *d = lane(*s);
                }
            }
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            fn avx2($($arg: $aty,)* src: &[$in], dst: &mut [$out]) {
                body($($arg,)* src, dst)
            }
            match level {
                $crate::batch::Level::Scalar => {
                    let scalar = $scalar;
                    for (d, s) in dst.iter_mut().zip(src) {
                        *d = scalar(*s);
                    }
                }
                #[cfg(target_arch = "x86_64")]
                $crate::batch::Level::Avx2 => {
                    // SAFETY: `check_level` above confirmed that this CPU has AVX2.
                    unsafe { avx2($($arg,)* src, dst) }
                }
                _ => body($($arg,)* src, dst),
            }
        }
    };
}
pub(crate) use batch_fn;
