//! [`DECODERS`]: any bytes in, a valid result out — depth codes, normal codes (every encoding,
//! bit size and render-target form), log roughness.

use crate::normal::{assert_unit, codec, oct_bits, rgb10a2_code, snorm8_code, unorm_bytes};
use crate::{Entry, Input};
use glam::Vec3;
use prepass::assert_within_abs;
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::normal::{hemioct, oct, signed_oct, snorm8, substrate, xy_fp16, xyz8, xyz10};
use prepass::roughness;
use prepass::roughness_ggx as ggx;

/// The documented per-channel rule of `depth24_from_rgb8`, stated independently: NaN → 0,
/// otherwise a byte nearest `255·clamp(c, 0, 1)`. The function rounds the f32 product, which is
/// within half an f32 ULP below 256 (2^-17) of the exact one, so a product just above a half
/// may round to a tie and go to the even byte (found by this target: 0.99803925 → 254).
#[track_caller]
fn assert_channel(c: f32, byte: u32, context: std::fmt::Arguments<'_>) {
    if c.is_nan() {
        assert_eq!(byte, 0, "{context}: a NaN channel gives byte 0");
        return;
    }
    let x = f64::from(c.clamp(0.0, 1.0)) * 255.0;
    assert_within_abs!(
        f64::from(byte),
        x,
        0.5 + 2f64.powi(-17),
        "assert_channel: half a byte + the f32 product's half ULP below 256 (2^-17)",
        "{context}"
    );
}

/// Decoders: any bytes in, a valid result out.
pub const DECODERS: &[Entry] = &[
    Entry {
        name: "depth24::depth24_from_rgb8",
        check: |i| {
            let rgb = i.vec3();
            let d = depth24::depth24_from_rgb8(rgb);
            assert!(d <= DEPTH24_MAX, "{rgb:?} → {d:#x}");
            let bytes = [d >> 16, (d >> 8) & 0xff, d & 0xff];
            for (c, b) in rgb.to_array().into_iter().zip(bytes) {
                assert_channel(
                    c,
                    b,
                    format_args!("{rgb:?} → {d:#x}: channel {c:?} gave byte {b}"),
                );
            }
        },
    },
    Entry {
        name: "depth24::depth24_from_packed",
        check: |i| {
            let p = i.u32();
            let d = depth24::depth24_from_packed(p);
            let b = p.to_le_bytes().map(u32::from);
            assert_eq!(d, b[0] << 16 | b[1] << 8 | b[2], "{p:#x}");
        },
    },
    Entry {
        name: "depth24::hyperbolic_depth_from_depth24",
        check: |i| {
            let d = i.u32();
            let z = depth24::hyperbolic_depth_from_depth24(d);
            assert!((0.0..=1.0).contains(&z), "{d:#x} → {z:?}");
            assert_eq!(
                depth24::exact::nearest_code(z),
                Some(d.min(DEPTH24_MAX)),
                "{d:#x}"
            );
        },
    },
    Entry {
        name: "depth24::unpack4x8unorm",
        check: |i| {
            let p = i.u32();
            let c = depth24::unpack4x8unorm(p);
            for (x, b) in c.into_iter().zip(p.to_le_bytes()) {
                assert!((0.0..=1.0).contains(&x), "{p:#x} → {c:?}");
                assert_eq!((x * 255.0).round() as u8, b, "{p:#x} → {c:?}");
            }
        },
    },
    Entry {
        name: "normal::xyz8::decode_normal_xyz8",
        check: |i| {
            let p = i.u32();
            let v = xyz8::decode_normal_xyz8(p);
            assert_unit(v, format_args!("{p:#x}"));
            assert_eq!(
                v,
                xyz8::decode_normal_xyz8(p & 0xff_ffff),
                "{p:#x}: byte 3 ignored"
            );
        },
    },
    codec!(unorm_decoder; xyz8::decode_normal_xyz8_unorm, xyz8::decode_normal_xyz8),
    Entry {
        name: "normal::xy_fp16::decode_normal_xy_fp16",
        check: |i| {
            let p = i.u32();
            assert_unit(xy_fp16::decode_normal_xy_fp16(p), format_args!("{p:#x}"));
        },
    },
    codec!(unorm_decoder; xy_fp16::decode_normal_xy_fp16_unorm, xy_fp16::decode_normal_xy_fp16),
    codec!(code_decoder; oct::decode_normal_oct16, 16),
    Entry {
        name: "normal::oct::decode_normal_oct16_unorm",
        check: |i| {
            // The rg8unorm form: channels 2 and 3 do not exist (the Rust form takes them as 0).
            let c = [i.f32(), i.f32(), 0.0, 0.0];
            let v = oct::decode_normal_oct16_unorm(c);
            assert_unit(v, format_args!("{c:?}"));
            assert_eq!(v, oct::decode_normal_oct16(unorm_bytes(c)), "{c:?}");
        },
    },
    codec!(code_decoder; oct::decode_normal_oct24, 24),
    codec!(unorm_decoder; oct::decode_normal_oct24_unorm, oct::decode_normal_oct24),
    codec!(code_decoder; oct::decode_normal_oct32, 32),
    codec!(unorm_decoder; oct::decode_normal_oct32_unorm, oct::decode_normal_oct32),
    Entry {
        name: "normal::oct::decode (1..=16 bits per axis)",
        check: |i| {
            let bits = oct_bits(i);
            let p = i.u32();
            let v = oct::decode(p, bits);
            assert_unit(v, format_args!("{p:#x}, {bits} bits"));
            let mask = (1u64 << (2 * bits)) - 1;
            assert_eq!(
                v,
                oct::decode(p & mask as u32, bits),
                "{p:#x}: high bits ignored"
            );
        },
    },
    codec!(code_decoder; hemioct::decode_normal_hemioct24, 24),
    codec!(unorm_decoder; hemioct::decode_normal_hemioct24_unorm, hemioct::decode_normal_hemioct24),
    Entry {
        name: "roughness::decode_log_roughness",
        check: |i| {
            let (code, max_power) = (i.u32(), i.f32());
            let p = roughness::decode_log_roughness(code, max_power);
            // Documented: a power in [1, max_power] (max_power acts as 2^127 from 2^127 up,
            // a degenerate range gives 1); codes above 255 decode as 255.
            assert!(
                p.is_finite() && p >= 1.0,
                "{code:#x}, {max_power:?} → {p:?}"
            );
            let top = if max_power >= 2f32.powi(127) {
                2f32.powi(127)
            } else {
                max_power
            };
            assert!(p <= top.max(1.0), "{code:#x}, {max_power:?} → {p:?}");
            assert_eq!(
                p.to_bits(),
                roughness::decode_log_roughness(code.min(255), max_power).to_bits(),
                "{code:#x}"
            );
        },
    },
    Entry {
        name: "roughness::{normal_xyz8_from_log_roughness_texel, log_roughness_code_from_texel}",
        check: |i| {
            let t = i.u32();
            assert_eq!(
                roughness::normal_xyz8_from_log_roughness_texel(t),
                t & 0xff_ffff
            );
            assert_eq!(roughness::log_roughness_code_from_texel(t), t >> 24);
        },
    },
    Entry {
        name: "normal::xyz10::decode_normal_xyz10",
        check: |i| {
            let p = i.u32();
            let v = xyz10::decode_normal_xyz10(p);
            assert_unit(v, format_args!("{p:#x}"));
            assert_eq!(
                v,
                xyz10::decode_normal_xyz10(p & 0x3fff_ffff),
                "{p:#x}: alpha ignored"
            );
        },
    },
    Entry {
        name: "normal::xyz10::decode_normal_xyz10_unorm",
        check: |i| {
            let c = [i.f32(), i.f32(), i.f32(), i.f32()];
            let v = xyz10::decode_normal_xyz10_unorm(c);
            assert_unit(v, format_args!("{c:?}"));
            assert_eq!(v, xyz10::decode_normal_xyz10(rgb10a2_code(c)), "{c:?}");
        },
    },
    Entry {
        name: "normal::snorm8::decode_normal_snorm8",
        check: |i| {
            let p = i.u32();
            let v = snorm8::decode_normal_snorm8(p);
            assert_unit(v, format_args!("{p:#x}"));
            assert_eq!(
                v,
                snorm8::decode_normal_snorm8(p & 0xff_ffff),
                "{p:#x}: byte 3 ignored"
            );
            // −128 reads as −127.
            let q = (0..3).fold(p & 0xff_ffff, |q, k| {
                if (q >> (8 * k)) & 0xff == 0x80 {
                    q + (1 << (8 * k))
                } else {
                    q
                }
            });
            assert_eq!(v, snorm8::decode_normal_snorm8(q), "{p:#x}: −128 as −127");
        },
    },
    Entry {
        name: "normal::snorm8::decode_normal_snorm8_snorm",
        check: |i| {
            let c = [i.f32(), i.f32(), i.f32(), i.f32()];
            let v = snorm8::decode_normal_snorm8_snorm(c);
            assert_unit(v, format_args!("{c:?}"));
            assert_eq!(v, snorm8::decode_normal_snorm8(snorm8_code(c)), "{c:?}");
        },
    },
    Entry {
        name: "normal::oct::decode_normal_oct24_unity",
        check: |i| {
            let p = i.u32();
            let v = oct::decode_normal_oct24_unity(p);
            assert_unit(v, format_args!("{p:#x}"));
            assert_eq!(
                v,
                oct::decode_normal_oct24(oct::unity_word(p)),
                "{p:#x}: oct24's word"
            );
        },
    },
    codec!(unorm_decoder; oct::decode_normal_oct24_unity_unorm, oct::decode_normal_oct24_unity),
    Entry {
        name: "roughness_ggx decoders (code, channel)",
        check: |i| {
            let (p, c) = (i.u32(), i.f32());
            let b = p.min(255);
            for (name, v, lo) in [
                ("decode_roughness_ggx8", ggx::decode_roughness_ggx8(p), 0.0),
                (
                    "decode_roughness_ggx8_alpha",
                    ggx::decode_roughness_ggx8_alpha(p),
                    0.0,
                ),
                (
                    "decode_roughness_godot8",
                    ggx::decode_roughness_godot8(p),
                    0.0,
                ),
                (
                    "decode_roughness_ggx8_log",
                    ggx::decode_roughness_ggx8_log(p),
                    1.0 / 64.0,
                ),
                (
                    "decode_roughness_ggx8_log_alpha",
                    ggx::decode_roughness_ggx8_log_alpha(p),
                    1.0 / 4096.0,
                ),
                (
                    "decode_roughness_ggx8_unorm",
                    ggx::decode_roughness_ggx8_unorm(c),
                    0.0,
                ),
                (
                    "decode_roughness_godot8_unorm",
                    ggx::decode_roughness_godot8_unorm(c),
                    0.0,
                ),
                (
                    "decode_roughness_ggx8_log_unorm",
                    ggx::decode_roughness_ggx8_log_unorm(c),
                    1.0 / 64.0,
                ),
            ] {
                assert!((lo..=1.0).contains(&v), "{name}: {p:#x}, {c:?} → {v:?}");
            }
            assert_eq!(ggx::decode_roughness_ggx8(p), ggx::decode_roughness_ggx8(b));
            assert_eq!(
                ggx::decode_roughness_godot8(p),
                ggx::decode_roughness_godot8(b)
            );
            assert_eq!(
                ggx::decode_roughness_ggx8_log(p),
                ggx::decode_roughness_ggx8_log(b)
            );
            assert_eq!(ggx::roughness_godot8_is_dynamic(p), b >> 7);
        },
    },
    Entry {
        name: "normal::substrate::{decode_substrate_normal, decode_substrate_roughness, substrate_flags}",
        check: |i| {
            let p = i.u32();
            let v = substrate::decode_substrate_normal(p);
            assert_unit(v, format_args!("{p:#x}"));
            assert_eq!(
                v,
                substrate::decode_substrate_normal(p & !0x3ff),
                "{p:#x}: bits 0–9 ignored"
            );
            let r = substrate::decode_substrate_roughness(p);
            assert!((0.0..=1.0).contains(&r), "{p:#x} → {r:?}");
            assert_eq!(r, ggx::decode_roughness_ggx8((p >> 2) & 0xff), "{p:#x}");
            assert!(substrate::substrate_flags(p) <= 3);
        },
    },
    codec!(code_decoder; oct::decode_normal_oct20, 20),
    Entry {
        name: "normal::oct::decode_normal_oct20_unorm",
        check: |i| {
            // R and G as xyz10's channels; B and A ignored.
            let c = [i.f32(), i.f32(), i.f32(), i.f32()];
            let v = oct::decode_normal_oct20_unorm(c);
            assert_unit(v, format_args!("{c:?}"));
            assert_eq!(
                v,
                oct::decode_normal_oct20(rgb10a2_code(c) & 0xf_ffff),
                "{c:?}"
            );
        },
    },
    codec!(code_decoder; signed_oct::decode_normal_signed_oct, 30),
    Entry {
        name: "normal::signed_oct::decode_normal_signed_oct_unorm",
        check: |i| {
            // R, G and B as xyz10's channels, then the texel decoded; A ignored.
            let c = [i.f32(), i.f32(), i.f32(), i.f32()];
            let v = signed_oct::decode_normal_signed_oct_unorm(c);
            assert_unit(v, format_args!("{c:?}"));
            let k = rgb10a2_code(c);
            assert_eq!(
                v,
                signed_oct::decode_normal_signed_oct(k & 0x3fff_ffff),
                "{c:?}"
            );
        },
    },
    Entry {
        name: "roughness_ggx::{decode_roughness_urp8, decode_roughness_substrate8} (+ _unorm)",
        check: |i| {
            let (p, c) = (i.u32(), i.f32());
            let b = p.min(255);
            // URP: (255 − b)/255, one rounding; Substrate's UnpackR8: b·(1/255), two.
            let urp = ggx::decode_roughness_urp8(p);
            assert_eq!(urp, (255 - b) as f32 / 255.0, "{p:#x}");
            let sub = ggx::decode_roughness_substrate8(p);
            let exact = f64::from(b) / 255.0;
            assert_within_abs!(
                f64::from(sub),
                exact,
                exact * ggx::bounds::SUBSTRATE_DECODE_REL,
                "roughness_ggx::bounds::SUBSTRATE_DECODE_REL, relative (two f32 roundings)",
                "decode_roughness_substrate8({p:#x})"
            );
            let u = ggx::decode_roughness_urp8_unorm(c);
            assert!((0.0..=1.0).contains(&u), "{c:?} → {u:?}");
        },
    },
];

/// A code decoder with `bits` bits of code: a finite unit vector for every pattern, the bits
/// above the code ignored.
#[track_caller]
fn code_decoder(i: &mut Input, decode: fn(u32) -> Vec3, bits: u32) {
    let p = i.u32();
    let v = decode(p);
    assert_unit(v, format_args!("{p:#x}"));
    if bits < 32 {
        assert_eq!(
            v,
            decode(p & ((1 << bits) - 1)),
            "{p:#x}: high bits ignored"
        );
    }
}

/// A render-target decoder: the code decoder of the channels' bytes (`unorm_bytes`).
#[track_caller]
fn unorm_decoder(i: &mut Input, decode_unorm: fn([f32; 4]) -> Vec3, decode: fn(u32) -> Vec3) {
    let c = [i.f32(), i.f32(), i.f32(), i.f32()];
    let v = decode_unorm(c);
    assert_unit(v, format_args!("{c:?}"));
    assert_eq!(v, decode(unorm_bytes(c)), "{c:?}");
}
