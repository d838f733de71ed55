//! Unit-normal encodings for G-buffers — the Rust twins of `wgsl/normal_*.wgsl`.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! | encoding | bits | WGSL | twin |
//! |---|---|---|---|
//! | x, y, z as unorm8 (Resistance 2), rounding or best-fit encoder (Godot 4's format) | 24 (+8 free) | `wgsl/normal_xyz8.wgsl` | [`xyz8`] |
//! | x, y, z as unorm10 in RGB10A2 (Unreal 5 GBufferA, Bevy's normal prepass) | 30 (+2 free) | `wgsl/normal_xyz10.wgsl` | [`xyz10`] |
//! | x, y, z as snorm8 (Unity URP's default normal target) | 24 (+8 free) | `wgsl/normal_snorm8.wgsl` | [`snorm8`] |
//! | view-space x, y as FP16 in RGBA8, z rebuilt (Killzone 2) | 32 | `wgsl/normal_xy_fp16.wgsl` | [`xy_fp16`] |
//! | octahedral, precise and rounding encoders (Cigolle et al. 2014) | 16, 24, 32 | `wgsl/normal_oct.wgsl` | [`oct`] |
//! | hemi-octahedral, view-space `z ≥ 0` only (for comparison) | 24 | `wgsl/normal_hemioct.wgsl` | [`hemioct`] |
//! | O3DE's signed octahedron: hemi-octahedral 10:10 of `(x, y, |z|)` and z's sign, in RGB10A2 | 21 (+11) | `wgsl/normal_signed_oct.wgsl` | [`signed_oct`] |
//! | octahedral 11:11 on a centred grid, with roughness and flags (Unreal 5 Substrate) | 22 (+10) | `wgsl/normal_substrate.wgsl` | [`substrate`] |
//!
//! **Twins.** Every encoder is bit-identical to its WGSL twin on a correctly rounded adapter
//! (checked on lavapipe over every tested input by `tests/normal_*.rs`), so a normal baked on the
//! CPU decodes exactly like one a shader wrote there. On any conforming adapter — which may round
//! `+ − ×` either way, err 2.5 ULP on `/` and 2 on `inverseSqrt`, fuse and reassociate — the
//! WGSL encoder's code (but the best fit's, whose promise is an angle:
//! [`xyz8::BEST_FIT_SINE_SLACK_CONFORMING`]) is within one code step of the twin's (per lane, two codes of one exact
//! direction counting as equal; for xy FP16, an f16 lane within one step of the subnormals that
//! the adapter flushes to ±0 counts as one step, and `pack2x16float` may pick either
//! neighbouring f16), every decode is finite and unit within
//! `prepass::sweep::conforming::UNIT_TOLERANCE_CONFORMING` (`18·2^-24`, derived there; feature `harness`), and the
//! precise encoders stay within 5× their correctly rounded optimality tolerance: checked under
//! the worst-case emulation by `tests/conforming.rs`; the figures are in `docs/figures.md`. The WGSL avoids the expressions an implementation may
//! legitimately evaluate differently: no `a*b + c` whose fusion into an fma would change the
//! result (the multiply is exact, or the sum is a `dot()`), no repeated factor an optimiser could
//! pull out (Mesa rewrites `a*b + a*c` into `a*(b + c)`), and NaN/Inf/subnormals found from bits.
//!
//! **Bad input, all encoders:** NaN in any component, the zero vector and vectors whose
//! components are all subnormal encode as `+z = (0, 0, 1)` (the view-space normal facing the
//! camera); subnormal components count as zero (adapters may flush them); infinite components
//! win (`(+Inf, 1, 0)` encodes `+x`, `(+Inf, −Inf, 5)` encodes `(1, −1, 0)/√2`); any finite length
//! is normalised (or, for the scale-free octahedral map, needs no normalising).
//! Decoders accept every bit pattern and return a finite unit vector.

/// Slack added to a derived angular bound when it is compared with a measured f32 round trip,
/// in degrees: the f32 input is normalised, encoded and decoded with a few roundings of
/// `2^-24` rad each, which a bound derived in exact arithmetic leaves out (`1e-5°` ≈ 10·2^-24 rad).
pub const F32_SLACK_DEG: f64 = 1e-5;

/// How far a decoded vector's length may be from 1: WGSL's `normalize` is `v·inverseSqrt(v·v)`
/// with `inverseSqrt` 2 ULP, the dot product's 3 roundings (≤ 1.5 ULP relative to `v·v`, so
/// ≤ 0.75 ULP on the length), and the final multiply 0.5 ULP per component: ≤ 3.25·2^-23,
/// rounded up to 4·2^-23 (lavapipe's measured worst is listed in the README). The Rust twins'
/// `v / sqrt(v·v)`, each step correctly rounded, stay inside it too. Used by the adapter suites
/// (`prepass::sweep::normal` re-exports it) and the fuzz targets.
pub const UNIT_TOLERANCE: f64 = 4.0 / 8_388_608.0;

pub mod hemioct;
pub mod oct;
pub mod signed_oct;
pub mod snorm8;
pub mod substrate;
pub mod xy_fp16;
pub mod xyz10;
pub mod xyz8;

use glam::Vec3;

/// The shared first step of every encoder: the input made safe to normalise.
///
/// Returns `None` for NaN anywhere, the zero vector and all-subnormal vectors (the encoders'
/// degenerate cases). Otherwise: if any component is infinite, the vector of their signs
/// (`±1` where infinite, signed zero elsewhere); subnormal components become zero of the same
/// sign; then the vector is scaled by an exact power of two so that its largest component lies
/// in `[1, 4)` (no overflow or underflow in a dot product), and components that scaling made
/// subnormal become signed zero. Exact: only sign changes, flushes and power-of-two scaling.
pub fn sanitize(n: Vec3) -> Option<Vec3> {
    let c = n.to_array();
    if c.iter().any(|x| x.is_nan()) {
        return None;
    }
    scale_to_unit_range(signs_or_flushed(c))
}

/// `x` with its exponent and mantissa cleared: `±0` of `x`'s sign.
fn signed_zero(x: f32) -> f32 {
    f32::from_bits(x.to_bits() & 0x8000_0000)
}

/// `x`, or `±0` of its sign when it is subnormal (as adapters that flush see it).
fn flush(x: f32) -> f32 {
    if x.to_bits() & 0x7f80_0000 == 0 {
        signed_zero(x)
    } else {
        x
    }
}

/// The middle step of [`sanitize`] on NaN-free components: if any is infinite, the vector of
/// their signs (`±1` where infinite, signed zero elsewhere); otherwise subnormals flushed.
pub(crate) fn signs_or_flushed(c: [f32; 3]) -> [f32; 3] {
    if c.iter().any(|x| x.is_infinite()) {
        c.map(|x| {
            if x.is_infinite() {
                f32::from_bits((x.to_bits() & 0x8000_0000) | 0x3f80_0000)
            } else {
                signed_zero(x)
            }
        })
    } else {
        c.map(flush)
    }
}

/// The last step of [`sanitize`]: `None` for the zero vector, else `c` times the exact power of
/// two that puts its largest magnitude in `[1, 4)`, components made subnormal flushed.
pub(crate) fn scale_to_unit_range(c: [f32; 3]) -> Option<Vec3> {
    let m = c[0].abs().max(c[1].abs()).max(c[2].abs());
    if m == 0.0 {
        return None;
    }
    let e = (m.to_bits() >> 23) & 0xff;
    let scale = f32::from_bits((254 - e).max(1) << 23);
    Some(Vec3::from_array(c.map(|x| flush(x * scale))))
}

/// The per-channel unorm encoders' body (xyz8, xyz10): the unit vector `u` of the sanitised `n`
/// (`+z` for the degenerate cases), each coordinate as `round(m·(u/2 + 1/2))` (half to even)
/// in the `width`-bit field `k` (x at bit 0).
pub(crate) fn encode_unorm_xyz(n: Vec3, m: f32, width: u32) -> u32 {
    let s = sanitize(n).unwrap_or(Vec3::Z);
    let u = s / dot(s, s).sqrt();
    let c = (u * 0.5 + 0.5).clamp(Vec3::ZERO, Vec3::ONE);
    let k = (c * m).to_array().map(|x| x.round_ties_even() as u32);
    k[0] | (k[1] << width) | (k[2] << (2 * width))
}

/// The per-channel unorm decoders' body (xyz8, xyz10): `normalize(2k − m)` of the three
/// `width`-bit fields `k` of `p` (x at bit 0; bits above `3·width` ignored).
pub(crate) fn decode_unorm_xyz(p: u32, m: i32, width: u32) -> Vec3 {
    let mask = (1 << width) - 1;
    let d = [p, p >> width, p >> (2 * width)].map(|k| (2 * (k & mask) as i32 - m) as f32);
    normalize(Vec3::from_array(d))
}

/// `dot(a, b)` as WGSL implementations evaluate it without fusion: `(a.x·b.x + a.y·b.y) + a.z·b.z`,
/// each operation rounded.
pub(crate) fn dot(a: Vec3, b: Vec3) -> f32 {
    (a.x * b.x + a.y * b.y) + a.z * b.z
}

/// WGSL's `normalize(v)` as lavapipe evaluates it: `v / sqrt(dot(v, v))`, each step correctly
/// rounded (measured bit-identical on lavapipe; `v * (1/sqrt(v·v))` differs in the last bit of
/// about half the results). Other adapters may use `v * inverseSqrt(v·v)` (2 ULP): the length
/// then moves by a few ULP, the direction only by the final per-component rounding,
/// ≤ 2^-24·√2 rad.
pub(crate) fn normalize(v: Vec3) -> Vec3 {
    v / dot(v, v).sqrt()
}

/// The precise encoders' score of a candidate code with exact integer direction `d`:
/// `|s × D|² / |D|²` (sin² of the angle between `s` and `D`, times `|s|²`), as the WGSL
/// computes it: `|D|²` exact, then one rounding (the WGSL's float `dot(d, d)` is exact while
/// `M² < 2^24`, i.e. at 8 and 12 bits; `oct_try_wide` sums 16-bit codes' squares in `u32`); the
/// cross product and `dot` rounded per operation.
pub(crate) fn sin2_to(s: Vec3, d: glam::IVec3) -> f32 {
    let ad = d.abs().as_uvec3();
    let sq = ad * ad;
    let len2 = (sq.x + sq.y + sq.z) as f32;
    let d = d.as_vec3();
    let x = Vec3::new(
        s.y * d.z - s.z * d.y,
        s.z * d.x - s.x * d.z,
        s.x * d.y - s.y * d.x,
    );
    dot(x, x) / len2
}

/// Exact `f64` helpers shared by the encodings' references.
pub mod exact {
    /// Of `codes`, the one whose direction (`decode`) is closest in angle to `n` (the first of
    /// equal angles): the precise encoders' f64 reference over their candidates.
    pub fn closest(n: [f64; 3], codes: [u32; 4], decode: impl Fn(u32) -> [f64; 3]) -> u32 {
        let mut best = (f64::INFINITY, 0);
        for p in codes {
            let e = crate::precision::metrics::angle_degrees(n, decode(p));
            if e < best.0 {
                best = (e, p);
            }
        }
        best.1
    }

    /// The per-channel unorm encoders' reference: the field nearest `m·(u/2 + 1/2)` per
    /// coordinate of the unit vector `u` of `n` (`+z` for the zero vector; half to even), field
    /// `k` at bit `k·width`.
    pub fn encode_unorm_xyz(n: [f64; 3], m: f64, width: u32) -> u32 {
        let u = unit(n).unwrap_or([0.0, 0.0, 1.0]);
        u.iter().enumerate().fold(0, |acc, (k, &x)| {
            acc | ((((x * 0.5 + 0.5) * m).round_ties_even() as u32) << (width * k as u32))
        })
    }

    /// The direction of the odd-integer vector `2k − m` of the `width`-bit fields of `p`.
    pub fn decode_unorm_xyz(p: u32, m: i32, width: u32) -> [f64; 3] {
        let mask = (1 << width) - 1;
        let d = [p, p >> width, p >> (2 * width)].map(|k| f64::from(2 * (k & mask) as i32 - m));
        unit(d).expect("odd integers are never all zero")
    }

    /// `v / |v|` in f64 (`None` for the zero vector).
    pub fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        (l > 0.0 && l.is_finite()).then(|| v.map(|x| x / l))
    }
}

/// A vouched encoder and its robust sibling.
#[cfg(test)]
type VouchedPair = (fn(Vec3) -> u32, fn(Vec3) -> u32);

/// The vouched encoders' unit tests' random draws (`oct`'s and `hemioct`'s): 200,000 xorshift
/// vectors, half with exponents near 1 (unit vectors) and half of any bits (so many fall outside
/// the contract, some on its edges), each also scaled by 0.75, 1e-30 and 1e30. Every pair's
/// vouched twin never panics and, where `is_vouched` holds, gives its robust twin's code; at
/// least a quarter of the draws must be inside the contract, or the check says little.
#[cfg(test)]
fn vouched_draws_agree(pairs: &[VouchedPair], is_vouched: fn(Vec3) -> bool) {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let (mut inside, mut total) = (0, 0);
    for k in 0..200_000 {
        let r = next();
        let comp = |bits: u64| {
            let b = bits as u32;
            if k % 2 == 0 {
                f32::from_bits((b & 0x807f_ffff) | ((120 + (b >> 23) % 10) << 23))
            } else {
                f32::from_bits(b)
            }
        };
        let n = Vec3::new(comp(r), comp(r >> 21 ^ next()), comp(next()));
        for v in [n, n * 0.75, n * 1e-30, n * 1e30] {
            total += 1;
            let ok = is_vouched(v);
            inside += usize::from(ok);
            for (vouched, robust) in pairs {
                let code = vouched(v);
                if ok {
                    assert_eq!(code, robust(v), "{v:?}");
                }
            }
        }
    }
    assert!(
        inside * 4 > total,
        "{inside} of {total} inside the contract"
    );
}
