//! [`ENCODERS`]: any bit patterns in (NaN, infinities, subnormals included), no panic, the
//! documented output — depth codes, normal codes (every encoding and bit size, precise and
//! rounding, render-target forms), log roughness, GGX roughness.

use crate::normal::{check_encoder, codec, oct_bits, rgb10a2_channels, snorm8_channels};
use crate::{Entry, Input};
use glam::Vec3;
use prepass::assert_within_abs;
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use prepass::roughness;
use prepass::roughness_ggx as ggx;

/// A normal encoder's twin.
type Encoder = fn(Vec3) -> u32;

/// A Substrate word encoder's twin (normal, roughness, flags).
type WordEncoder = fn(Vec3, f32, u32) -> u32;

/// Encoders: any bit patterns in, no panic, the documented output.
pub const ENCODERS: &[Entry] = &[
    Entry {
        name: "depth24::pack_depth24",
        check: |i| {
            let d = i.u32();
            let p = depth24::pack_depth24(d);
            let code = d.min(DEPTH24_MAX);
            assert_eq!(p >> 24, 0, "{d:#x}: alpha byte must be 0");
            assert_eq!(depth24::depth24_from_packed(p), code, "{d:#x}");
            let [r, g, b, _] = depth24::unpack4x8unorm(p);
            assert_eq!(
                depth24::depth24_from_rgb8(Vec3::new(r, g, b)),
                code,
                "{d:#x}"
            );
        },
    },
    Entry {
        name: "depth24::exact::nearest_code",
        check: |i| {
            let x = i.f32();
            match depth24::exact::nearest_code(x) {
                None => assert!(!(0.0..=1.0).contains(&x), "{x:?} has a code"),
                Some(c) => {
                    assert!(
                        (0.0..=1.0).contains(&x) && c <= DEPTH24_MAX,
                        "{x:?} → {c:#x}"
                    );
                    // x·(2^24 − 1) is exact in f64 (24 × 24 significand bits).
                    let t = f64::from(x) * f64::from(DEPTH24_MAX);
                    assert_within_abs!(
                        f64::from(c),
                        t,
                        0.5,
                        "the nearest code: half a code of the exact x·(2^24 − 1)",
                        "{x:?} → {c:#x}"
                    );
                }
            }
        },
    },
    Entry {
        name: "depth24::exact::hyperbolic_depth",
        check: |i| {
            let d = i.u32();
            let z = depth24::exact::hyperbolic_depth(d);
            assert!((0.0..=1.0).contains(&z), "{d:#x} → {z:?}");
        },
    },
    codec!(encoder; xyz8::encode_normal_xyz8, 24),
    codec!(unorm_form; xyz8::encode_normal_xyz8_unorm, xyz8::encode_normal_xyz8),
    codec!(encoder; xy_fp16::encode_normal_xy_fp16, 32),
    codec!(unorm_form; xy_fp16::encode_normal_xy_fp16_unorm, xy_fp16::encode_normal_xy_fp16),
    codec!(encoder; oct::encode_normal_oct16, 16),
    codec!(encoder; oct::encode_normal_oct16_fast, 16),
    codec!(unorm_form; oct::encode_normal_oct16_unorm, oct::encode_normal_oct16),
    codec!(encoder; oct::encode_normal_oct24, 24),
    codec!(encoder; oct::encode_normal_oct24_fast, 24),
    codec!(unorm_form; oct::encode_normal_oct24_unorm, oct::encode_normal_oct24),
    codec!(encoder; oct::encode_normal_oct32, 32),
    codec!(encoder; oct::encode_normal_oct32_fast, 32),
    codec!(unorm_form; oct::encode_normal_oct32_unorm, oct::encode_normal_oct32),
    Entry {
        name: "normal::oct::{encode_precise, encode_round} (1..=16 bits per axis)",
        check: |i| {
            let bits = oct_bits(i);
            let n = i.vec3();
            // Non-capturing closures cannot take `bits`: one entry per bit size is 16 entries,
            // so the sizes are checked through the generic functions directly.
            let precise = |v| oct::encode_precise(v, bits);
            let round = |v| oct::encode_round(v, bits);
            check_encoder(n, precise, 2 * bits, "encode_precise");
            check_encoder(n, round, 2 * bits, "encode_round");
        },
    },
    codec!(encoder; hemioct::encode_normal_hemioct24, 24),
    codec!(encoder; hemioct::encode_normal_hemioct24_fast, 24),
    codec!(unorm_form; hemioct::encode_normal_hemioct24_unorm, hemioct::encode_normal_hemioct24),
    Entry {
        name: "normal::sanitize",
        check: |i| {
            let n = i.vec3();
            let degenerate =
                n.is_nan() || n.to_array().iter().all(|c| !c.is_normal() && c.is_finite());
            match prepass::normal::sanitize(n) {
                None => assert!(degenerate, "{n:?} is a valid direction"),
                Some(s) => {
                    assert!(!degenerate, "{n:?} → {s:?}");
                    let m = s.abs().max_element();
                    assert!((1.0..4.0).contains(&m), "{n:?} → {s:?}: largest component");
                    assert!(
                        s.to_array().iter().all(|c| *c == 0.0 || c.is_normal()),
                        "{n:?} → {s:?}: subnormal left"
                    );
                }
            }
        },
    },
    Entry {
        name: "roughness::encode_log_roughness",
        check: |i| {
            let (a, b, max_power) = (i.f32(), i.f32(), i.f32());
            let code = roughness::encode_log_roughness(a, max_power);
            assert!(code <= 255, "{a:?}, {max_power:?} → {code}");
            let valid_range = !matches!(roughness::range(max_power), roughness::Range::Degenerate);
            if a.is_nan() || !valid_range || a <= 1.0 {
                assert_eq!(
                    code, 0,
                    "{a:?}, {max_power:?}: NaN, ≤ 1 or a degenerate range"
                );
            } else if a >= max_power.min(2f32.powi(127)) {
                assert_eq!(code, 255, "{a:?}, {max_power:?}: ≥ max_power");
            }
            // Monotonic in the power.
            if !a.is_nan() && !b.is_nan() {
                let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
                assert!(
                    roughness::encode_log_roughness(lo, max_power)
                        <= roughness::encode_log_roughness(hi, max_power),
                    "{lo:?} ≤ {hi:?} with {max_power:?}"
                );
            }
        },
    },
    Entry {
        name: "roughness::pack_normal_xyz8_log_roughness",
        check: |i| {
            let (normal, code) = (i.u32(), i.u32());
            let t = roughness::pack_normal_xyz8_log_roughness(normal, code);
            assert_eq!(t & 0xff_ffff, normal & 0xff_ffff, "{normal:#x} {code:#x}");
            assert_eq!(t >> 24, code.min(255), "{normal:#x} {code:#x}");
            assert_eq!(
                roughness::normal_xyz8_from_log_roughness_texel(t),
                normal & 0xff_ffff
            );
            assert_eq!(roughness::log_roughness_code_from_texel(t), code.min(255));
        },
    },
    codec!(encoder; xyz10::encode_normal_xyz10, 30),
    Entry {
        name: "normal::xyz10::encode_normal_xyz10_unorm",
        check: |i| {
            let n = i.vec3();
            let c = xyz10::encode_normal_xyz10_unorm(n);
            assert_eq!(c, rgb10a2_channels(xyz10::encode_normal_xyz10(n)), "{n:?}");
        },
    },
    codec!(encoder; snorm8::encode_normal_snorm8, 24),
    Entry {
        name: "normal::snorm8::encode_normal_snorm8_snorm",
        check: |i| {
            let n = i.vec3();
            let p = snorm8::encode_normal_snorm8(n);
            assert_eq!(
                snorm8::encode_normal_snorm8_snorm(n),
                snorm8_channels(p),
                "{n:?}"
            );
            assert!(
                p.to_le_bytes()[..3].iter().all(|&b| b != 0x80),
                "{n:?}: −128 written"
            );
        },
    },
    codec!(encoder; oct::encode_normal_oct24_unity, 24),
    codec!(encoder; oct::encode_normal_oct24_unity_fast, 24),
    codec!(unorm_form; oct::encode_normal_oct24_unity_unorm, oct::encode_normal_oct24_unity),
    Entry {
        name: "roughness_ggx::{encode_roughness_ggx8, encode_roughness_godot8, encode_roughness_ggx8_log} (+ _unorm)",
        check: |i| {
            let (r, s, flag) = (i.f32(), i.f32(), i.u32());
            let x = f64::from(r);
            // Exact nearest codes for every bit pattern (NaN → the roughest code).
            let lin = ggx::encode_roughness_ggx8(r);
            assert_eq!(lin, ggx::exact::linear_code(x, 255), "{r:?}");
            let k = ggx::exact::linear_code(x, 127);
            let g = ggx::encode_roughness_godot8(r, flag);
            assert_eq!(g, if flag != 0 { 255 - k } else { k }, "{r:?}, {flag:#x}");
            assert_eq!(ggx::roughness_godot8_is_dynamic(g), u32::from(flag != 0));
            let log = ggx::encode_roughness_ggx8_log(r);
            assert_eq!(log, ggx::exact::log_code(x), "{r:?}");
            // The render-target forms write exactly those bytes.
            for (c, b) in [
                (ggx::encode_roughness_ggx8_unorm(r), lin),
                (ggx::encode_roughness_godot8_unorm(r, flag), g),
                (ggx::encode_roughness_ggx8_log_unorm(r), log),
            ] {
                assert!((0.0..=1.0).contains(&c), "{r:?} → channel {c:?}");
                assert_eq!((c * 255.0).round() as u32, b, "{r:?}");
            }
            // Monotonic in r.
            if !r.is_nan() && !s.is_nan() {
                let (lo, hi) = if r <= s { (r, s) } else { (s, r) };
                assert!(ggx::encode_roughness_ggx8(lo) <= ggx::encode_roughness_ggx8(hi));
                assert!(ggx::encode_roughness_godot8(lo, 0) <= ggx::encode_roughness_godot8(hi, 0));
                assert!(ggx::encode_roughness_ggx8_log(lo) <= ggx::encode_roughness_ggx8_log(hi));
            }
        },
    },
    // Appended (the corpus picks entries by index).
    Entry {
        name: "normal::oct::encode_normal_oct*_vouched, *_fast_vouched (vouched input)",
        check: |i| {
            let n = i.vec3();
            // Any input: no panic. Inside the contract: the robust encoder's code.
            let pairs: [(Encoder, Encoder, &str); 6] = [
                (
                    oct::encode_normal_oct16_vouched,
                    oct::encode_normal_oct16,
                    "oct16",
                ),
                (
                    oct::encode_normal_oct16_fast_vouched,
                    oct::encode_normal_oct16_fast,
                    "oct16 fast",
                ),
                (
                    oct::encode_normal_oct24_vouched,
                    oct::encode_normal_oct24,
                    "oct24",
                ),
                (
                    oct::encode_normal_oct24_fast_vouched,
                    oct::encode_normal_oct24_fast,
                    "oct24 fast",
                ),
                (
                    oct::encode_normal_oct32_vouched,
                    oct::encode_normal_oct32,
                    "oct32",
                ),
                (
                    oct::encode_normal_oct32_fast_vouched,
                    oct::encode_normal_oct32_fast,
                    "oct32 fast",
                ),
            ];
            let inside = oct::is_vouched(n);
            for (vouched, robust, name) in pairs {
                let code = vouched(n);
                if inside {
                    assert_eq!(code, robust(n), "{name} vouched: {n:?}");
                }
            }
        },
    },
    Entry {
        name: "normal::substrate::{encode_substrate_normal, _fast, encode_substrate_word, _fast}",
        check: |i| {
            let (n, r, flags) = (i.vec3(), i.f32(), i.u32());
            let pairs: [(Encoder, WordEncoder, &str); 2] = [
                (
                    substrate::encode_substrate_normal,
                    substrate::encode_substrate_word,
                    "substrate",
                ),
                (
                    substrate::encode_substrate_normal_fast,
                    substrate::encode_substrate_word_fast,
                    "substrate fast",
                ),
            ];
            for (normal, word, name) in pairs {
                // The normal's bits are 10–31: the shared rules on the code shifted down.
                check_encoder(n, |v| normal(v) >> 10, 22, name);
                let w = normal(n);
                assert_eq!(w & 0x3ff, 0, "{name} {n:?}: roughness and flag bits set");
                let byte = ggx::encode_roughness_ggx8(r);
                assert_eq!(
                    word(n, r, flags),
                    normal(n) | (byte << 2) | (flags & 3),
                    "{name} word: {n:?}, {r:?}, {flags:#x}"
                );
                // The rounding and precise codes are written on codes 1..=2047 (never 0).
                let k = substrate::codes(w);
                assert!(k.min_element() >= 1, "{name} {n:?}: code 0 written");
            }
        },
    },
    codec!(encoder; oct::encode_normal_oct20, 20),
    codec!(encoder; oct::encode_normal_oct20_fast, 20),
    Entry {
        name: "normal::oct::encode_normal_oct20_unorm",
        check: |i| {
            // R and G hold u and v as unorm10; B and A are the renderer's, written 0.
            let n = i.vec3();
            let c = oct::encode_normal_oct20_unorm(n);
            assert_eq!(c, rgb10a2_channels(oct::encode_normal_oct20(n)), "{n:?}");
        },
    },
    Entry {
        name: "normal::xyz8::encode_normal_xyz8_best",
        check: |i| {
            let n = i.vec3();
            check_encoder(n, xyz8::encode_normal_xyz8_best, 24, "encoder");
            // Never farther than the rounding encoder's code (one of its candidates), up to
            // the derived scoring slack (twice BEST_FIT_SINE_SLACK, in sine ≈ radians).
            if let Some(s) = prepass::normal::sanitize(n) {
                let u = s.to_array().map(f64::from);
                let best = xyz8::exact::angle_to(u, xyz8::encode_normal_xyz8_best(n));
                let round = xyz8::exact::angle_to(u, xyz8::encode_normal_xyz8(n));
                let slack = 2.0 * f64::from(xyz8::BEST_FIT_SINE_SLACK) * 1.0001;
                assert!(
                    best <= round + slack,
                    "{n:?}: best fit {best:e} rad, rounding {round:e}"
                );
            }
        },
    },
    codec!(unorm_form; xyz8::encode_normal_xyz8_best_unorm, xyz8::encode_normal_xyz8_best),
    Entry {
        name: "normal::hemioct::encode_normal_hemioct24_vouched, _fast_vouched (vouched input)",
        check: |i| {
            let n = i.vec3();
            // Any input: no panic. Inside the contract: the robust encoder's code.
            let pairs: [(Encoder, Encoder, &str); 2] = [
                (
                    hemioct::encode_normal_hemioct24_vouched,
                    hemioct::encode_normal_hemioct24,
                    "hemioct24",
                ),
                (
                    hemioct::encode_normal_hemioct24_fast_vouched,
                    hemioct::encode_normal_hemioct24_fast,
                    "hemioct24 fast",
                ),
            ];
            let inside = hemioct::is_vouched(n);
            for (vouched, robust, name) in pairs {
                let code = vouched(n);
                if inside {
                    assert_eq!(code, robust(n), "{name} vouched: {n:?}");
                }
            }
        },
    },
    // The RGB10A2 texel: u, v in bits 0-19, B in bits 20-29 (0 or 1023), A = 0.
    codec!(encoder; signed_oct::encode_normal_signed_oct, 30),
    codec!(encoder; signed_oct::encode_normal_signed_oct_fast, 30),
    Entry {
        name: "normal::signed_oct::encode_normal_signed_oct_unorm, and z's sign bit",
        check: |i| {
            // R and G hold u and v as unorm10, B is 0 or 1023 (read here by its lowest bit,
            // bit 20), A is the renderer's (0).
            let n = i.vec3();
            let p = signed_oct::encode_normal_signed_oct(n);
            let mut want = rgb10a2_channels(p & 0xf_ffff);
            want[2] = ((p >> 20) & 1) as f32;
            assert_eq!(signed_oct::encode_normal_signed_oct_unorm(n), want, "{n:?}");
            // Both encoders write B = 1023 exactly when the sanitised z is positive (+z for the
            // degenerate inputs), else 0, and A = 0.
            let z = prepass::normal::sanitize(n).map_or(1.0, |s| s.z);
            for enc in [
                signed_oct::encode_normal_signed_oct,
                signed_oct::encode_normal_signed_oct_fast,
            ] {
                let b = if z > 0.0 { signed_oct::B_MASK } else { 0 };
                assert_eq!(enc(n) & 0xfff0_0000, b, "{n:?}");
            }
        },
    },
    codec!(encoder; oct::encode_normal_oct24_hdrp, 24),
    Entry {
        name: "normal::oct::encode_normal_oct24_hdrp: z's sign survives HDRP's floor",
        check: |i| {
            // A finite input with z ≠ 0 (or −0, which HDRP's CopySign counts +) decodes with
            // z of the sign HDRP's floor gives it.
            let n = i.vec3();
            let Some(s) = prepass::normal::sanitize(n) else {
                return;
            };
            let z = oct::decode_normal_oct24_unity(oct::encode_normal_oct24_hdrp(n)).z;
            assert_eq!(z >= 0.0, s.z >= 0.0, "{n:?} → z {z:?}");
        },
    },
    Entry {
        name: "roughness_ggx::{encode_roughness_urp8, encode_roughness_substrate8} (+ _unorm)",
        check: |i| {
            let (r, s) = (i.f32(), i.f32());
            let x = f64::from(r);
            // URP's smoothness byte: 255 − the exact nearest linear code.
            let urp = ggx::encode_roughness_urp8(r);
            assert_eq!(urp, 255 - ggx::exact::linear_code(x, 255), "{r:?}");
            let c = ggx::encode_roughness_urp8_unorm(r);
            assert_eq!((c * 255.0).round() as u32, urp, "{r:?}");
            // Substrate's PackR8 truncates on [+0, 1): at most one step from ⌊255·r⌋ (the f32
            // product's rounding), never above 254; elsewhere the linear code.
            let sub = ggx::encode_roughness_substrate8(r);
            if r.to_bits() < 0x3f80_0000 {
                assert!(sub <= 254, "{r:?} → {sub}");
                assert!(
                    (f64::from(sub) - (255.0 * x).floor()).abs() <= 1.0,
                    "{r:?} → {sub}"
                );
            } else {
                assert_eq!(sub, ggx::exact::linear_code(x, 255), "{r:?}");
            }
            if !r.is_nan() && !s.is_nan() {
                let (lo, hi) = if r <= s { (r, s) } else { (s, r) };
                assert!(ggx::encode_roughness_urp8(lo) >= ggx::encode_roughness_urp8(hi));
                if lo.to_bits() < 0x3f80_0000 && hi.to_bits() < 0x3f80_0000 && lo >= 0.0 {
                    assert!(
                        ggx::encode_roughness_substrate8(lo)
                            <= ggx::encode_roughness_substrate8(hi)
                    );
                }
            }
        },
    },
];

/// A fixed-size encoder ([`check_encoder`]) on a direction read from the input.
#[track_caller]
fn encoder(i: &mut Input, enc: fn(Vec3) -> u32, code_bits: u32) {
    check_encoder(i.vec3(), enc, code_bits, "encoder");
}

/// A render-target encoder: the unorm8 channels of its code's bytes.
#[track_caller]
fn unorm_form(i: &mut Input, enc_unorm: fn(Vec3) -> [f32; 4], enc: fn(Vec3) -> u32) {
    let n = i.vec3();
    assert_eq!(enc_unorm(n), depth24::unpack4x8unorm(enc(n)), "{n:?}");
}
