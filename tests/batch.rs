//! `src/batch/`: every batch twin equals its scalar twin bit for bit, on every compiled level
//! this CPU has (scalar, SSE2, AVX2 where detected; NEON on aarch64) and through the plain
//! (detected-level, rayon-split) form:
//! - decoders with at most 24 input bits: every code (plus the ignored high bits set);
//! - 32-bit decoders: the scalar suites' stratified sample (`stratified_codes32`);
//! - encoders: the 2^24 spherical-Fibonacci directions, the adversarial set, the bad inputs
//!   and a grid of special values (NaN, ±Inf, ±0, subnormals, extremes);
//! - the `_vouched` encoders: bit for bit inside their contract (random, scaled and edge-case
//!   vectors), and a valid code, without a panic, on every other input;
//! - the slice contract (mismatched lengths panic) and unavailable levels panic.
//!
//! Pure CPU; each comparison streams in chunks of 2^18 so memory stays small. The speed beside
//! meshoptimizer is a benchmark (`bash .ci/bench` writes `docs/batch_bench.md`), not a test.

mod common;

use glam::Vec3;
use prepass::batch::{Level, depth24 as bd, normal as bn, roughness as br};
use prepass::depth24 as d24;
use prepass::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use prepass::precision::inputs::{ChannelError, sign_pattern, unorm8_channel};
use prepass::sweep::normal::{
    RenderTarget, adversarial_directions, bad_inputs, stratified_codes32,
};
use std::fmt::Debug;
use std::sync::OnceLock;

const CHUNK: usize = 1 << 18;

/// A value compared by its bits (so `-0.0 ≠ +0.0` and NaN payloads count).
trait Bits: Copy + Debug {
    fn bits(self) -> [u32; 4];
}
impl Bits for u32 {
    fn bits(self) -> [u32; 4] {
        [self, 0, 0, 0]
    }
}
impl Bits for f32 {
    fn bits(self) -> [u32; 4] {
        [self.to_bits(), 0, 0, 0]
    }
}
impl Bits for Vec3 {
    fn bits(self) -> [u32; 4] {
        [self.x.to_bits(), self.y.to_bits(), self.z.to_bits(), 0]
    }
}
impl Bits for [f32; 4] {
    fn bits(self) -> [u32; 4] {
        self.map(f32::to_bits)
    }
}
/// Substrate's word encoders' input `(n, roughness, flags)`: the flags are left out of the
/// four words, and shown by the failure message's `Debug` form beside them.
impl Bits for (Vec3, f32, u32) {
    fn bits(self) -> [u32; 4] {
        let (n, r, _) = self;
        [n.x.to_bits(), n.y.to_bits(), n.z.to_bits(), r.to_bits()]
    }
}

/// The levels under test: every one this CPU has. On x86_64 SSE2 must be among them, and AVX2
/// whenever the CPU reports it, so a run cannot pass on the scalar fallback alone.
fn levels() -> &'static [Level] {
    static L: OnceLock<Vec<Level>> = OnceLock::new();
    L.get_or_init(|| {
        let l = Level::all_available();
        #[cfg(target_arch = "x86_64")]
        {
            assert!(l.contains(&Level::Sse2), "x86_64 without SSE2 level: {l:?}");
            if std::is_x86_feature_detected!("avx2") {
                assert!(
                    l.contains(&Level::Avx2),
                    "AVX2 detected but not offered: {l:?}"
                );
            }
        }
        #[cfg(target_arch = "aarch64")]
        assert!(
            l.contains(&Level::Neon),
            "aarch64 without NEON level: {l:?}"
        );
        eprintln!(
            "batch levels under test: {l:?} (detected: {})",
            Level::detected()
        );
        l
    })
}

/// Compare `with(level)` for every SIMD level this CPU has, and `plain`, against `scalar` on
/// `inputs`; on a difference, name the first differing input with its bits and both outputs.
/// ([`Level::Scalar`] is the scalar twin itself, so it is not compared with itself.)
fn check<I: Bits, O: Bits + Default>(
    name: &str,
    inputs: &[I],
    scalar: impl Fn(I) -> O,
    with: impl Fn(Level, &[I], &mut [O]),
    plain: impl Fn(&[I], &mut [O]),
) {
    assert!(!inputs.is_empty(), "{name}: no inputs");
    // The plain form over the whole input at once, so rayon's split runs on long inputs.
    let mut all = vec![O::default(); inputs.len()];
    plain(inputs, &mut all);
    let mut want = vec![O::default(); CHUNK.min(inputs.len())];
    let mut got = want.clone();
    for (c, chunk) in inputs.chunks(CHUNK).enumerate() {
        let want = &mut want[..chunk.len()];
        let got = &mut got[..chunk.len()];
        for (w, &x) in want.iter_mut().zip(chunk) {
            *w = scalar(x);
        }
        let run = |form: &str, got: &[O]| {
            if let Some(i) = (0..chunk.len()).find(|&i| got[i].bits() != want[i].bits()) {
                panic!(
                    "{name} [{form}]: input #{} {:?} (bits {:08x?}): batch {:?} (bits {:08x?}) \
                     but scalar twin {:?} (bits {:08x?})",
                    c * CHUNK + i,
                    chunk[i],
                    chunk[i].bits(),
                    got[i],
                    got[i].bits(),
                    want[i],
                    want[i].bits()
                );
            }
        };
        for &level in levels().iter().filter(|&&l| l != Level::Scalar) {
            got.fill(O::default());
            with(level, chunk, got);
            run(&level.to_string(), got);
        }
        run("plain", &all[c * CHUNK..c * CHUNK + chunk.len()]);
    }
}

/// `check` with the batch twin's two forms named once.
macro_rules! check {
    ($inputs:expr, $scalar:expr, $module:ident :: $f:ident, $fw:ident $(, $arg:expr)*) => {
        check(
            concat!(stringify!($module), "::", stringify!($f)),
            $inputs,
            $scalar,
            |l, s, d| $module::$fw(l, $($arg,)* s, d),
            |s, d| $module::$f($($arg,)* s, d),
        )
    };
}

/// The special values of one component: NaNs of both signs and a signalling one, ±Inf, ±0,
/// subnormals, the smallest normal, ±1, ±f32::MAX, a value that scales to subnormal beside a
/// large one.
fn special_components() -> Vec<f32> {
    [
        0x7fc0_0000u32,
        0xffc0_0001,
        0x7f80_0001,
        0x7f80_0000,
        0xff80_0000,
        0,
        0x8000_0000,
        1,
        0x8000_0001,
        0x007f_ffff,
        0x0080_0000,
        0x3f80_0000,
        0xbf80_0000,
        0x7f7f_ffff,
        0xff7f_ffff,
        0x0100_0000,
        0x3f00_0001,
        0xc2f6_e979,
    ]
    .map(f32::from_bits)
    .to_vec()
}

/// The encoders' inputs: the tier's Fibonacci directions (`common::tier::fibonacci_set`: 2^20,
/// 2^24 in the full tier), the adversarial set, the bad inputs, every
/// triple of special components, and the Fibonacci directions scaled by huge and tiny powers.
fn encoder_inputs() -> &'static [Vec3] {
    static V: OnceLock<Vec<Vec3>> = OnceLock::new();
    V.get_or_init(|| {
        let mut v: Vec<Vec3> = common::tier::fibonacci_set()
            .1
            .into_iter()
            .chain(adversarial_directions())
            .chain(bad_inputs().into_iter().map(|(b, _)| b))
            .map(Vec3::from_array)
            .collect();
        let s = special_components();
        for &x in &s {
            for &y in &s {
                for &z in &s {
                    v.push(Vec3::new(x, y, z));
                }
            }
        }
        let scaled: Vec<Vec3> = v
            .iter()
            .step_by(251)
            .flat_map(|&d| [d * 1e30, d * 3e-39, d * -7.5])
            .collect();
        v.extend(scaled);
        v
    })
}

/// Every 24-bit code, then the same codes with the ignored high byte set from a hash.
fn codes24() -> Vec<u32> {
    (0..1u32 << 24)
        .chain(
            (0..1u32 << 24)
                .step_by(7)
                .map(|c| c | (sign_pattern(c, false) << 29) | 1 << 24),
        )
        .collect()
}

/// 2^24 of the 2^30 xyz10 codes (an odd stride through all of them), the alpha bits varied.
fn codes30() -> Vec<u32> {
    (0..1u32 << 24)
        .map(|i| i.wrapping_mul(0x2f_f8a5) & 0x3fff_ffff | (sign_pattern(i, false) << 30))
        .collect()
}

/// Sampled channels of `codes` in `target`'s format: exact or ±3 ULP (as [`unorm_channels`]),
/// alpha anything, then the special values.
fn target_channels(codes: &[u32], target: RenderTarget) -> Vec<[f32; 4]> {
    let mut v = Vec::with_capacity(codes.len() + 64);
    for &p in codes {
        let error = if p.wrapping_mul(0x9e37_79b9) >> 31 == 0 {
            ChannelError::Exact
        } else {
            ChannelError::Ulps(3)
        };
        let s = sign_pattern(p, false);
        let c = [0, 1, 2].map(|k| target.perturbed(p, k, error, s >> k & 1 == 1));
        v.push([c[0], c[1], c[2], 0.25]);
    }
    let s = special_components();
    for (i, &x) in s.iter().enumerate() {
        v.push([x, s[(i + 1) % s.len()], s[(i + 5) % s.len()], 1.5]);
        v.push([0.5, x, -0.25, x]);
    }
    v
}

fn stratified() -> &'static [u32] {
    static S: OnceLock<Vec<u32>> = OnceLock::new();
    S.get_or_init(stratified_codes32)
}

/// Sampled rgba8unorm channels of `codes`: exact or ±3 ULP (WGSL's `unpack4x8unorm`
/// allowance; a hash of the code picks which), each channel pushed up or down by the sweeps'
/// sign pattern; plus out-of-range and NaN channels.
fn unorm_channels(codes: &[u32]) -> Vec<[f32; 4]> {
    let mut v = Vec::with_capacity(codes.len() + 64);
    for &p in codes {
        let error = if p.wrapping_mul(0x9e37_79b9) >> 31 == 0 {
            ChannelError::Exact
        } else {
            ChannelError::Ulps(3)
        };
        let s = sign_pattern(p, false) | (sign_pattern(p, true) << 3);
        v.push([0, 1, 2, 3].map(|k| unorm8_channel((p >> (8 * k)) & 0xff, error, s >> k & 1 == 1)));
    }
    let s = special_components();
    for (i, &x) in s.iter().enumerate() {
        v.push([x, s[(i + 1) % s.len()], s[(i + 5) % s.len()], 1.5]);
        v.push([0.5, x, -0.25, x]);
    }
    v
}

#[test]
fn dispatch_levels_cover_the_simd_paths() {
    let l = levels();
    assert!(l.contains(&Level::Scalar));
    assert!(l.contains(&Level::detected()), "{l:?}");
    assert_eq!(
        *l.last().unwrap(),
        Level::detected(),
        "detected must be the best available"
    );
}

#[test]
#[should_panic(expected = "3 inputs but 4 outputs")]
fn mismatched_lengths_panic() {
    bn::encode_normal_oct32(&[Vec3::Z; 3], &mut [0u32; 4]);
}

#[test]
#[should_panic(expected = "is not available")]
fn unavailable_level_panics() {
    let missing = Level::ALL
        .into_iter()
        .find(|l| !l.available())
        .expect("no CPU has both SSE2 and NEON levels");
    bd::pack_depth24_with(missing, &[1], &mut [0]);
}

#[test]
fn depth24_all_codes_and_stratified() {
    let mut codes = codes24();
    codes.extend_from_slice(stratified());
    check!(
        &codes,
        d24::pack_depth24,
        bd::pack_depth24,
        pack_depth24_with
    );
    check!(
        &codes,
        d24::depth24_from_packed,
        bd::depth24_from_packed,
        depth24_from_packed_with
    );
    check!(
        &codes,
        d24::hyperbolic_depth_from_depth24,
        bd::hyperbolic_depth_from_depth24,
        hyperbolic_depth_from_depth24_with
    );
    check!(
        &codes,
        d24::unpack4x8unorm,
        bd::unpack4x8unorm,
        unpack4x8unorm_with
    );
    let rgb: Vec<Vec3> =
        unorm_channels(&(0..1u32 << 24).map(d24::pack_depth24).collect::<Vec<_>>())
            .into_iter()
            .map(|c| Vec3::new(c[0], c[1], c[2]))
            .collect();
    check!(
        &rgb,
        d24::depth24_from_rgb8,
        bd::depth24_from_rgb8,
        depth24_from_rgb8_with
    );
}

#[test]
fn normal_decoders_every_24_bit_code() {
    let codes = codes24();
    check!(
        &codes,
        xyz8::decode_normal_xyz8,
        bn::decode_normal_xyz8,
        decode_normal_xyz8_with
    );
    check!(
        &codes,
        oct::decode_normal_oct24_unity,
        bn::decode_normal_oct24_unity,
        decode_normal_oct24_unity_with
    );
    check!(
        &codes,
        snorm8::decode_normal_snorm8,
        bn::decode_normal_snorm8,
        decode_normal_snorm8_with
    );
    check!(
        &codes30(),
        xyz10::decode_normal_xyz10,
        bn::decode_normal_xyz10,
        decode_normal_xyz10_with
    );
    check!(
        &codes30(),
        oct::decode_normal_oct20,
        bn::decode_normal_oct20,
        decode_normal_oct20_with
    );
    check!(
        &codes,
        oct::decode_normal_oct16,
        bn::decode_normal_oct16,
        decode_normal_oct16_with
    );
    check!(
        &codes,
        oct::decode_normal_oct24,
        bn::decode_normal_oct24,
        decode_normal_oct24_with
    );
    check!(
        &codes,
        hemioct::decode_normal_hemioct24,
        bn::decode_normal_hemioct24,
        decode_normal_hemioct24_with
    );
    // The generic decoder at every size: exhaustive up to 2^20 codes, else every 61st code.
    for bits in 1..=16u32 {
        let n = 1u64 << (2 * bits);
        let step = if n <= 1 << 20 { 1 } else { 61 };
        let c: Vec<u32> = (0..n).step_by(step).map(|p| p as u32).collect();
        check(
            &format!("normal::decode_oct({bits})"),
            &c,
            |p| oct::decode(p, bits),
            |l, s, d| bn::decode_oct_with(l, bits, s, d),
            |s, d| bn::decode_oct(bits, s, d),
        );
    }
}

#[test]
fn normal_unorm_decoders_every_24_bit_code() {
    let snorm = target_channels(
        &(0..1u32 << 24).collect::<Vec<_>>(),
        RenderTarget::Rgba8Snorm,
    );
    check!(
        &snorm,
        snorm8::decode_normal_snorm8_snorm,
        bn::decode_normal_snorm8_snorm,
        decode_normal_snorm8_snorm_with
    );
    let rgb10 = target_channels(&codes30(), RenderTarget::Rgb10a2Unorm);
    check!(
        &rgb10,
        xyz10::decode_normal_xyz10_unorm,
        bn::decode_normal_xyz10_unorm,
        decode_normal_xyz10_unorm_with
    );
    check!(
        &rgb10,
        oct::decode_normal_oct20_unorm,
        bn::decode_normal_oct20_unorm,
        decode_normal_oct20_unorm_with
    );
    let ch = unorm_channels(&(0..1u32 << 24).collect::<Vec<_>>());
    check!(
        &ch,
        oct::decode_normal_oct24_unity_unorm,
        bn::decode_normal_oct24_unity_unorm,
        decode_normal_oct24_unity_unorm_with
    );
    check!(
        &ch,
        xyz8::decode_normal_xyz8_unorm,
        bn::decode_normal_xyz8_unorm,
        decode_normal_xyz8_unorm_with
    );
    check!(
        &ch,
        oct::decode_normal_oct16_unorm,
        bn::decode_normal_oct16_unorm,
        decode_normal_oct16_unorm_with
    );
    check!(
        &ch,
        oct::decode_normal_oct24_unorm,
        bn::decode_normal_oct24_unorm,
        decode_normal_oct24_unorm_with
    );
    check!(
        &ch,
        hemioct::decode_normal_hemioct24_unorm,
        bn::decode_normal_hemioct24_unorm,
        decode_normal_hemioct24_unorm_with
    );
}

#[test]
fn normal_decoders_32_bit_stratified() {
    let codes = stratified();
    check!(
        codes,
        oct::decode_normal_oct32,
        bn::decode_normal_oct32,
        decode_normal_oct32_with
    );
    check!(
        codes,
        xy_fp16::decode_normal_xy_fp16,
        bn::decode_normal_xy_fp16,
        decode_normal_xy_fp16_with
    );
    // The render-target forms on every 4th code of the sample (2^24 + ~2^18 codes).
    let ch = unorm_channels(&codes.iter().copied().step_by(4).collect::<Vec<_>>());
    check!(
        &ch,
        oct::decode_normal_oct32_unorm,
        bn::decode_normal_oct32_unorm,
        decode_normal_oct32_unorm_with
    );
    check!(
        &ch,
        xy_fp16::decode_normal_xy_fp16_unorm,
        bn::decode_normal_xy_fp16_unorm,
        decode_normal_xy_fp16_unorm_with
    );
}

#[test]
fn normal_precise_encoders() {
    let v = encoder_inputs();
    check!(
        v,
        oct::encode_normal_oct16,
        bn::encode_normal_oct16,
        encode_normal_oct16_with
    );
    check!(
        v,
        oct::encode_normal_oct20,
        bn::encode_normal_oct20,
        encode_normal_oct20_with
    );
    check!(
        v,
        oct::encode_normal_oct24,
        bn::encode_normal_oct24,
        encode_normal_oct24_with
    );
    check!(
        v,
        oct::encode_normal_oct32,
        bn::encode_normal_oct32,
        encode_normal_oct32_with
    );
    check!(
        v,
        hemioct::encode_normal_hemioct24,
        bn::encode_normal_hemioct24,
        encode_normal_hemioct24_with
    );
    check!(
        v,
        substrate::encode_substrate_normal,
        bn::encode_substrate_normal,
        encode_substrate_normal_with
    );
}

/// Every 2^22 Substrate normal code (the roughness and flag bits carry noise) and the rounding
/// encoder.
#[test]
fn substrate_every_code_and_rounding_encoder() {
    let codes: Vec<u32> = (0..1u32 << 22)
        .map(|k| (k << 10) | (k.wrapping_mul(2_654_435_761) >> 22))
        .collect();
    check!(
        &codes,
        substrate::decode_substrate_normal,
        bn::decode_substrate_normal,
        decode_substrate_normal_with
    );
    let v = encoder_inputs();
    check!(
        v,
        substrate::encode_substrate_normal_fast,
        bn::encode_substrate_normal_fast,
        encode_substrate_normal_fast_with
    );
}

/// O3DE's signed octahedron: every 2^21 code (bits 21–31 carrying noise: every B, read as O3DE
/// reads it, and A) through the decoder,
/// the render-target decoder on every code's exact channels and on channels read from special
/// bit patterns (NaN, ±Inf, ±0, subnormals, B either side of 1/2), and the precise, rounding and
/// render-target encoders over the encoder inputs.
#[test]
fn signed_oct_every_code_and_encoders() {
    let codes: Vec<u32> = (0..1u32 << 21)
        .map(|k| k | (k.wrapping_mul(2_654_435_761) & !0x1f_ffff))
        .collect();
    check!(
        &codes,
        signed_oct::decode_normal_signed_oct,
        bn::decode_normal_signed_oct,
        decode_normal_signed_oct_with
    );
    let k = |x: u32| (x & 0x3ff) as f32 / 1023.0;
    let mut channels: Vec<[f32; 4]> = (0..1u32 << 21)
        .map(|p| [k(p), k(p >> 10), ((p >> 20) & 1) as f32, 0.5])
        .collect();
    let s = special_components();
    let b = [0.0, 1.0, 511.0 / 1023.0, 512.0 / 1023.0, 0.5, 0.7];
    for &x in &s {
        for &y in &s {
            for &z in s.iter().chain(&b) {
                channels.push([x, y, z, x]);
            }
        }
    }
    check!(
        &channels,
        signed_oct::decode_normal_signed_oct_unorm,
        bn::decode_normal_signed_oct_unorm,
        decode_normal_signed_oct_unorm_with
    );
    let v = encoder_inputs();
    check!(
        v,
        signed_oct::encode_normal_signed_oct,
        bn::encode_normal_signed_oct,
        encode_normal_signed_oct_with
    );
    check!(
        v,
        signed_oct::encode_normal_signed_oct_fast,
        bn::encode_normal_signed_oct_fast,
        encode_normal_signed_oct_fast_with
    );
    check!(
        v,
        signed_oct::encode_normal_signed_oct_unorm,
        bn::encode_normal_signed_oct_unorm,
        encode_normal_signed_oct_unorm_with
    );
}

/// The best-fit encoder's batch twins (the scalar twin per element) over every 16th of the
/// tier's Fibonacci directions (`common::tier::fibonacci_set`) and every other encoder input (adversarial, bad, special components).
#[test]
fn normal_best_fit_encoder() {
    let v = encoder_inputs();
    let fib = 1 << common::tier::fibonacci_log2();
    let sub: Vec<Vec3> = v[..fib]
        .iter()
        .step_by(16)
        .chain(&v[fib..])
        .copied()
        .collect();
    check!(
        &sub,
        xyz8::encode_normal_xyz8_best,
        bn::encode_normal_xyz8_best,
        encode_normal_xyz8_best_with
    );
    check!(
        &sub,
        xyz8::encode_normal_xyz8_best_unorm,
        bn::encode_normal_xyz8_best_unorm,
        encode_normal_xyz8_best_unorm_with
    );
}

#[test]
fn normal_rounding_encoders() {
    let v = encoder_inputs();
    check!(
        v,
        xyz8::encode_normal_xyz8,
        bn::encode_normal_xyz8,
        encode_normal_xyz8_with
    );
    check!(
        v,
        xyz10::encode_normal_xyz10,
        bn::encode_normal_xyz10,
        encode_normal_xyz10_with
    );
    check!(
        v,
        oct::encode_normal_oct20_fast,
        bn::encode_normal_oct20_fast,
        encode_normal_oct20_fast_with
    );
    check!(
        v,
        oct::encode_normal_oct24_unity_fast,
        bn::encode_normal_oct24_unity_fast,
        encode_normal_oct24_unity_fast_with
    );
    check!(
        v,
        snorm8::encode_normal_snorm8,
        bn::encode_normal_snorm8,
        encode_normal_snorm8_with
    );
    check!(
        v,
        xy_fp16::encode_normal_xy_fp16,
        bn::encode_normal_xy_fp16,
        encode_normal_xy_fp16_with
    );
    check!(
        v,
        oct::encode_normal_oct16_fast,
        bn::encode_normal_oct16_fast,
        encode_normal_oct16_fast_with
    );
    check!(
        v,
        oct::encode_normal_oct24_fast,
        bn::encode_normal_oct24_fast,
        encode_normal_oct24_fast_with
    );
    check!(
        v,
        oct::encode_normal_oct32_fast,
        bn::encode_normal_oct32_fast,
        encode_normal_oct32_fast_with
    );
    check!(
        v,
        hemioct::encode_normal_hemioct24_fast,
        bn::encode_normal_hemioct24_fast,
        encode_normal_hemioct24_fast_with
    );
}

/// The render-target encoders and the generic octahedral encoders at every size, on every 16th
/// encoder input (the per-size encoders above cover all of them; these add one unpack, or
/// another `bits`, to the same lanes).
#[test]
fn normal_unorm_and_generic_encoders() {
    let v: Vec<Vec3> = encoder_inputs().iter().copied().step_by(16).collect();
    let v = &v[..];
    check!(
        v,
        xyz8::encode_normal_xyz8_unorm,
        bn::encode_normal_xyz8_unorm,
        encode_normal_xyz8_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct24_unity,
        bn::encode_normal_oct24_unity,
        encode_normal_oct24_unity_with
    );
    check!(
        v,
        oct::encode_normal_oct24_unity_unorm,
        bn::encode_normal_oct24_unity_unorm,
        encode_normal_oct24_unity_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct24_hdrp,
        bn::encode_normal_oct24_hdrp,
        encode_normal_oct24_hdrp_with
    );
    check!(
        v,
        xyz10::encode_normal_xyz10_unorm,
        bn::encode_normal_xyz10_unorm,
        encode_normal_xyz10_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct20_unorm,
        bn::encode_normal_oct20_unorm,
        encode_normal_oct20_unorm_with
    );
    check!(
        v,
        snorm8::encode_normal_snorm8_snorm,
        bn::encode_normal_snorm8_snorm,
        encode_normal_snorm8_snorm_with
    );
    check!(
        v,
        xy_fp16::encode_normal_xy_fp16_unorm,
        bn::encode_normal_xy_fp16_unorm,
        encode_normal_xy_fp16_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct16_unorm,
        bn::encode_normal_oct16_unorm,
        encode_normal_oct16_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct24_unorm,
        bn::encode_normal_oct24_unorm,
        encode_normal_oct24_unorm_with
    );
    check!(
        v,
        oct::encode_normal_oct32_unorm,
        bn::encode_normal_oct32_unorm,
        encode_normal_oct32_unorm_with
    );
    check!(
        v,
        hemioct::encode_normal_hemioct24_unorm,
        bn::encode_normal_hemioct24_unorm,
        encode_normal_hemioct24_unorm_with
    );
    let w: Vec<Vec3> = v.iter().copied().step_by(8).collect();
    for bits in 1..=16u32 {
        check(
            &format!("normal::encode_oct_precise({bits})"),
            &w,
            |n| oct::encode_precise(n, bits),
            |l, s, d| bn::encode_oct_precise_with(l, bits, s, d),
            |s, d| bn::encode_oct_precise(bits, s, d),
        );
        check(
            &format!("normal::encode_oct_round({bits})"),
            &w,
            |n| oct::encode_round(n, bits),
            |l, s, d| bn::encode_oct_round_with(l, bits, s, d),
            |s, d| bn::encode_oct_round(bits, s, d),
        );
    }
}

/// The ranges the roughness tests use, every power-of-two class's edges, the degenerate ones
/// and general ranges.
fn max_powers() -> Vec<f32> {
    let mut m: Vec<f32> = (1..=127).map(|l| f32::from_bits((127 + l) << 23)).collect();
    m.extend([
        f32::INFINITY,
        f32::MAX,
        f32::NAN,
        1.0,
        0.5,
        -8.0,
        0.0,
        f32::NEG_INFINITY,
        1000.0,
        100.5,
        3e6,
        f32::from_bits(0x3f80_0001),
        1.5e38,
    ]);
    m
}

#[test]
fn roughness_decode_every_code() {
    let codes: Vec<u32> = (0..1024).chain([u32::MAX, 1 << 31, 256, 0xffff]).collect();
    for m in max_powers() {
        check(
            &format!("roughness::decode_log_roughness(max {m:e})"),
            &codes,
            |k| prepass::roughness::decode_log_roughness(k, m),
            |l, s, d| br::decode_log_roughness_with(l, m, s, d),
            |s, d| br::decode_log_roughness(m, s, d),
        );
    }
}

/// The power-of-two encoder is a different evaluation of the same exact function (its
/// candidate comes from a polynomial, `src/batch/roughness.rs`), so it is checked densely:
/// every `f32` in `[1, 2]` at range 2 (`L = 1`, where the candidate's error in codes is
/// largest; the error depends only on the significand), every 3rd `f32` in `[1, 8192]` at
/// the tests' range 8192, every 61st `f32` in `[1, 2^127]` at range 2^127; and for every range every
/// 64th pattern of the stratified 32-bit sample read as `f32` (NaNs, negatives, subnormals and
/// huge powers among them). Why every 61st is enough at 2^127: the candidate's error in codes is
/// the polynomial's (a function of the significand, swept whole at range 2) scaled by `1/L`, so
/// the wide range is there to cross every exponent, and an odd stride puts about 137,000
/// inputs in each of its 127 binades, at shifting significands. (Until 2026-12-05 the code took
/// every 5th, 213 million inputs, against this comment's 61st: the test took 8.6 s, now 3.0 s
/// on a 2-core Xeon.)
#[test]
fn roughness_encode() {
    let span = |lo: f32, hi: f32, step: usize| -> Vec<f32> {
        (lo.to_bits()..=hi.to_bits())
            .step_by(step)
            .map(f32::from_bits)
            .collect()
    };
    for (max, powers) in [
        (2.0, span(1.0, 2.0, 1)),
        (8192.0, span(1.0, 8192.0, 3)),
        (
            f32::from_bits(0x7f00_0000),
            span(1.0, f32::from_bits(0x7f00_0000), 61),
        ),
    ] {
        check(
            &format!("roughness::encode_log_roughness(max {max:e}, dense)"),
            &powers,
            |p| prepass::roughness::encode_log_roughness(p, max),
            |l, s, d| br::encode_log_roughness_with(l, max, s, d),
            |s, d| br::encode_log_roughness(max, s, d),
        );
    }
    let sparse: Vec<f32> = stratified()
        .iter()
        .step_by(64)
        .map(|&b| f32::from_bits(b))
        .collect();
    for m in max_powers().into_iter().step_by(3) {
        check(
            &format!("roughness::encode_log_roughness(max {m:e})"),
            &sparse,
            |p| prepass::roughness::encode_log_roughness(p, m),
            |l, s, d| br::encode_log_roughness_with(l, m, s, d),
            |s, d| br::encode_log_roughness(m, s, d),
        );
    }
}

/// GGX roughness (`prepass::batch::roughness_ggx`): every code and the stratified 32-bit sample
/// through the decoders; every `f32` in `[0, 1]` with a stride of 7 (every code at many
/// significands), every `f32` within 64 ULP of each linear code boundary (where the exact
/// quantiser's boundary test decides) and of each `k/255` (where Substrate's truncation steps),
/// and the stratified sample (NaNs, infinities, negatives, subnormals, huge values) through the
/// encoders, Godot's with both flags.
#[test]
fn roughness_ggx_encoders_and_decoders() {
    use prepass::batch::roughness_ggx as bg;
    use prepass::roughness_ggx as g;
    let codes: Vec<u32> = (0..1024)
        .chain(stratified().iter().step_by(16).copied())
        .collect();
    check!(
        &codes,
        g::decode_roughness_ggx8,
        bg::decode_roughness_ggx8,
        decode_roughness_ggx8_with
    );
    check!(
        &codes,
        g::decode_roughness_godot8,
        bg::decode_roughness_godot8,
        decode_roughness_godot8_with
    );
    check!(
        &codes,
        g::decode_roughness_ggx8_log,
        bg::decode_roughness_ggx8_log,
        decode_roughness_ggx8_log_with
    );
    check!(
        &codes,
        g::decode_roughness_urp8,
        bg::decode_roughness_urp8,
        decode_roughness_urp8_with
    );
    check!(
        &codes,
        g::decode_roughness_substrate8,
        bg::decode_roughness_substrate8,
        decode_roughness_substrate8_with
    );
    let mut rs: Vec<f32> = (0..=0x3f80_0000u32)
        .step_by(7)
        .map(f32::from_bits)
        .collect();
    for n in [127.0f64, 255.0] {
        for j in 0..n as u32 {
            let c = (((f64::from(j) + 0.5) / n) as f32).to_bits();
            rs.extend((c - 64..=c + 64).map(f32::from_bits));
        }
    }
    // Substrate's truncation boundaries k/255.
    for k in 1..=255u32 {
        let c = ((f64::from(k) / 255.0) as f32).to_bits();
        rs.extend((c - 64..=c + 64).map(f32::from_bits));
    }
    rs.extend(stratified().iter().step_by(16).map(|&b| f32::from_bits(b)));
    check!(
        &rs,
        g::encode_roughness_ggx8,
        bg::encode_roughness_ggx8,
        encode_roughness_ggx8_with
    );
    check!(
        &rs,
        g::encode_roughness_urp8,
        bg::encode_roughness_urp8,
        encode_roughness_urp8_with
    );
    check!(
        &rs,
        g::encode_roughness_substrate8,
        bg::encode_roughness_substrate8,
        encode_roughness_substrate8_with
    );
    for flag in [0u32, 1, u32::MAX] {
        check(
            &format!("roughness_ggx::encode_roughness_godot8(flag {flag:#x})"),
            &rs,
            |r| g::encode_roughness_godot8(r, flag),
            |l, s, d| bg::encode_roughness_godot8_with(l, flag, s, d),
            |s, d| bg::encode_roughness_godot8(flag, s, d),
        );
    }
    let sparse: Vec<f32> = rs.iter().step_by(5).copied().collect();
    check!(
        &sparse,
        g::encode_roughness_ggx8_log,
        bg::encode_roughness_ggx8_log,
        encode_roughness_ggx8_log_with
    );
}

/// Substrate's whole-word encoders: every 4th encoder input, each with a roughness (every
/// `f32` within 3 ULP of each byte boundary `(k + 1/2)/255`, the special components, a spread
/// of `[0, 1]`) and flags (a hash with every high bit pattern) beside it.
#[test]
fn substrate_word_encoders() {
    let mut rs = special_components();
    for k in 0..255u32 {
        let c = ((f64::from(k) + 0.5) / 255.0) as f32;
        rs.extend((c.to_bits() - 3..=c.to_bits() + 3).map(f32::from_bits));
    }
    rs.extend((0..=4096).map(|k| k as f32 / 4096.0));
    let words: Vec<(Vec3, f32, u32)> = encoder_inputs()
        .iter()
        .step_by(4)
        .enumerate()
        .map(|(i, &n)| {
            let i = i as u32;
            (n, rs[i as usize % rs.len()], i.wrapping_mul(0x9e37_79b9))
        })
        .collect();
    check!(
        &words,
        |(n, r, f)| substrate::encode_substrate_word(n, r, f),
        bn::encode_substrate_word,
        encode_substrate_word_with
    );
    check!(
        &words,
        |(n, r, f)| substrate::encode_substrate_word_fast(n, r, f),
        bn::encode_substrate_word_fast,
        encode_substrate_word_fast_with
    );
}

/// splitmix64: the vouched tests' deterministic random stream.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Inputs inside a vouched contract (`inside`): the encoder inputs that are; the Fibonacci
/// directions (every 64th) scaled by every power of two from 2^-126 to 2^124 and by
/// non-powers; 2^21 random vectors (a random largest exponent over the whole range, the other
/// components up to 40 binades below it or zero, random signs and significands); and edge
/// cases: axes at the extremes, components at exactly the contract's least magnitude
/// `2^-126·max(1, ‖n‖∞)`, `‖n‖∞ = 2^124`, and (for hemioct) negative `z` of any finite size.
fn vouched_inputs(inside: fn(Vec3) -> bool) -> Vec<Vec3> {
    let mut v: Vec<Vec3> = encoder_inputs().to_vec();
    let fib: Vec<Vec3> = encoder_inputs()[..1 << common::tier::fibonacci_log2()]
        .iter()
        .step_by(64)
        .copied()
        .collect();
    for (k, e) in (-126i32..=124).enumerate() {
        let p = 2f32.powi(e);
        v.extend(fib.iter().skip(k % 7).step_by(7).map(|&d| d * p));
    }
    for scale in [3.7e-30f32, 1.0e-3, 0.75, 7.5, 1.7e37, 1.3e-37, 2.1e37] {
        v.extend(fib.iter().step_by(3).map(|&d| d * scale));
    }
    let mut st = 0x5eed_u64;
    for _ in 0..1 << 21 {
        let r = splitmix(&mut st);
        let top = 1 + (r % 251) as u32; // biased exponent of the largest, 2^-126..2^124
        let comp = |r: u64| {
            if r & 0xf == 0 {
                return 0.0;
            }
            let e = top.saturating_sub(((r >> 4) % 41) as u32).max(1);
            let sign = ((r >> 12) & 1) as u32;
            f32::from_bits(sign << 31 | e << 23 | ((r >> 13) as u32 & 0x7f_ffff))
        };
        let r2 = splitmix(&mut st);
        v.push(Vec3::new(comp(r), comp(r2), comp(r2 >> 32)));
    }
    let (min, max) = (f32::MIN_POSITIVE, oct::VOUCHED_MAX);
    for s in [min, 1.0, 1.5, max] {
        for a in [Vec3::X, Vec3::Y, Vec3::Z] {
            v.extend([a * s, -a * s]);
        }
    }
    let least = max * min; // 2^-2, the least non-zero magnitude beside 2^124
    v.extend([
        Vec3::new(max, least, 0.0),
        Vec3::new(-least, max, -least),
        Vec3::new(least, -least, max),
        Vec3::new(max, -max, max),
        Vec3::new(1.0, min, -min),
        Vec3::new(min, min, min),
        Vec3::new(-min, min, -min),
        Vec3::new(0.5, -0.25, 1e-30),
        Vec3::new(1e-3, 2e-3, -f32::MAX),
        Vec3::new(-3.0, 0.0, -1e38),
        Vec3::new(1.0, 0.0, -0.0),
        Vec3::new(0.0, -min, -2.0),
    ]);
    v.retain(|&n| inside(n));
    v
}

/// The vouched encoders: bit for bit inside the contract (and for the precise forms on the
/// vectors they define outside it, the zero vector and hemioct's zero clamp: +z); on every
/// encoder input, inside or not, every level returns a valid code and does not panic.
#[test]
fn normal_vouched_encoders() {
    type Pair = (
        &'static str,
        fn(Vec3) -> u32,
        fn(Level, &[Vec3], &mut [u32]),
        fn(&[Vec3], &mut [u32]),
        u32,
    );
    let oct_pairs: [Pair; 6] = [
        (
            "oct16",
            oct::encode_normal_oct16_vouched,
            bn::encode_normal_oct16_vouched_with,
            bn::encode_normal_oct16_vouched,
            0xffff,
        ),
        (
            "oct16 fast",
            oct::encode_normal_oct16_fast_vouched,
            bn::encode_normal_oct16_fast_vouched_with,
            bn::encode_normal_oct16_fast_vouched,
            0xffff,
        ),
        (
            "oct24",
            oct::encode_normal_oct24_vouched,
            bn::encode_normal_oct24_vouched_with,
            bn::encode_normal_oct24_vouched,
            0xff_ffff,
        ),
        (
            "oct24 fast",
            oct::encode_normal_oct24_fast_vouched,
            bn::encode_normal_oct24_fast_vouched_with,
            bn::encode_normal_oct24_fast_vouched,
            0xff_ffff,
        ),
        (
            "oct32",
            oct::encode_normal_oct32_vouched,
            bn::encode_normal_oct32_vouched_with,
            bn::encode_normal_oct32_vouched,
            u32::MAX,
        ),
        (
            "oct32 fast",
            oct::encode_normal_oct32_fast_vouched,
            bn::encode_normal_oct32_fast_vouched_with,
            bn::encode_normal_oct32_fast_vouched,
            u32::MAX,
        ),
    ];
    let hemi_pairs: [Pair; 2] = [
        (
            "hemioct24",
            hemioct::encode_normal_hemioct24_vouched,
            bn::encode_normal_hemioct24_vouched_with,
            bn::encode_normal_hemioct24_vouched,
            0xff_ffff,
        ),
        (
            "hemioct24 fast",
            hemioct::encode_normal_hemioct24_fast_vouched,
            bn::encode_normal_hemioct24_fast_vouched_with,
            bn::encode_normal_hemioct24_fast_vouched,
            0xff_ffff,
        ),
    ];
    // The vectors the precise forms define outside the contract: a zero vector (for hemioct,
    // a zero clamp `(0, 0, z ≤ 0)`) encodes +z.
    let zeros = [Vec3::ZERO, Vec3::new(-0.0, 0.0, -0.0)];
    let zero_clamps = [
        Vec3::ZERO,
        Vec3::new(-0.0, 0.0, -0.0),
        Vec3::new(0.0, -0.0, -3.0),
    ];
    for (pairs, inside, zeros) in [
        (
            &oct_pairs[..],
            oct::is_vouched as fn(Vec3) -> bool,
            &zeros[..],
        ),
        (&hemi_pairs[..], hemioct::is_vouched, &zero_clamps[..]),
    ] {
        let v = vouched_inputs(inside);
        eprintln!("vouched inputs inside the contract: {}", v.len());
        // The set's size, as a check that it was built whole: 3.9 M in the default tier
        // (2^20 Fibonacci directions), 18 M in the full tier (2^24).
        let least = common::tier::by_tier(3_500_000, 18_000_000);
        assert!(
            v.len() > least,
            "{} vouched inputs, fewer than {least}",
            v.len()
        );
        for &(name, scalar, with, plain, _) in pairs {
            check(&format!("normal::{name} vouched"), &v, scalar, with, plain);
            if !name.ends_with("fast") {
                check(
                    &format!("normal::{name} vouched, zero"),
                    zeros,
                    scalar,
                    with,
                    plain,
                );
            }
        }
    }
    // Outside the contract: a valid code from every level, no panic.
    let all = encoder_inputs();
    let mut out = vec![0u32; all.len()];
    for &(name, _, with, plain, mask) in oct_pairs.iter().chain(&hemi_pairs) {
        for &level in levels() {
            with(level, all, &mut out);
            if let Some(i) = out.iter().position(|&c| c & !mask != 0) {
                panic!(
                    "{name} vouched [{level}]: {:?} gives {:#x}, not a code",
                    all[i], out[i]
                );
            }
        }
        plain(all, &mut out);
        assert!(
            out.iter().all(|&c| c & !mask == 0),
            "{name} vouched [plain]"
        );
    }
}
