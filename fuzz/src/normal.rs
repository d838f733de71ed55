//! The rules every normal codec documents (`prepass::normal`'s module docs), checked by the
//! decoder and encoder tables: decoders give finite unit vectors for every bit pattern; encoders
//! map NaN, the zero vector and all-subnormal vectors to the code of `+z`, let infinite
//! components win, and ignore the length of the input (every encoder starts with
//! `prepass::normal::sanitize`, which scales by an exact power of two).

use crate::Input;
use glam::Vec3;
use prepass::assert_within_abs;
use prepass::normal::UNIT_TOLERANCE;

/// A decoded normal: finite, and of unit length within [`UNIT_TOLERANCE`].
#[track_caller]
pub fn assert_unit(v: Vec3, context: std::fmt::Arguments<'_>) {
    assert!(v.is_finite(), "{context}: decoded {v:?} is not finite");
    assert_within_abs!(
        v.as_dvec3().length(),
        1.0,
        UNIT_TOLERANCE,
        "prepass::normal::UNIT_TOLERANCE (normalisation rounding, derived there)",
        "{context}: decoded {v:?}"
    );
}

/// The bytes the `_unorm` decoders document reading: `round(255·clamp(c, 0, 1))` per channel
/// (ties to even, as WGSL's `round`), NaN → 0, byte k from channel k.
pub fn unorm_bytes(c: [f32; 4]) -> u32 {
    c.iter().enumerate().fold(0, |acc, (k, &x)| {
        let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        acc | (((x * 255.0).round_ties_even() as u32) << (8 * k))
    })
}

/// The rgb10a2unorm channels the xyz10 render-target encoder documents writing: `k/1023` for the
/// fields at bits 0, 10, 20, alpha 0.
pub fn rgb10a2_channels(p: u32) -> [f32; 4] {
    let k = |s: u32| ((p >> s) & 0x3ff) as f32 / 1023.0;
    [k(0), k(10), k(20), 0.0]
}

/// The code the xyz10 render-target decoder documents reading: each of x, y, z taken to
/// `[0, 1]` (NaN, negative values and −0 as 0, 1 up to +∞ as 1), `round(1023·c)` (ties to even).
pub fn rgb10a2_code(c: [f32; 4]) -> u32 {
    (0..3).fold(0, |acc, k| {
        let x = c[k];
        let x = if x.is_nan() || x.is_sign_negative() {
            0.0
        } else {
            x.min(1.0)
        };
        acc | (((x * 1023.0).round_ties_even() as u32) << (10 * k))
    })
}

/// The rgba8snorm channels the snorm8 render-target encoder documents writing: `b/127` for the
/// signed bytes 0–2, alpha 0.
pub fn snorm8_channels(p: u32) -> [f32; 4] {
    let b = |s: u32| f32::from((p >> s) as u8 as i8) / 127.0;
    [b(0), b(8), b(16), 0.0]
}

/// The code the snorm8 render-target decoder documents reading: each of x, y, z taken to
/// `[−1, 1]` (NaN as 0), `round(127·c)` (ties to even) as a two's complement byte.
pub fn snorm8_code(c: [f32; 4]) -> u32 {
    (0..3).fold(0, |acc, k| {
        let x = c[k];
        let x = if x.is_nan() { 0.0 } else { x.clamp(-1.0, 1.0) };
        acc | ((((x * 127.0).round_ties_even() as i32 as u32) & 0xff) << (8 * k))
    })
}

/// The vector an input with infinite components stands for: `±1` where infinite, signed zero
/// elsewhere (`prepass::normal::sanitize`'s rule).
pub fn signs(n: Vec3) -> Vec3 {
    Vec3::from_array(n.to_array().map(|c| {
        if c.is_infinite() {
            c.signum()
        } else {
            0.0f32.copysign(c)
        }
    }))
}

/// Check one encoder's code for `n`, given the codes it gives `+z`, `2n` and [`signs`]`(n)`:
/// the code fits `code_bits`; NaN, zero and all-subnormal inputs give `+z`'s code; inputs with
/// an infinity give the code of their signs; otherwise, when `2n` stays finite and every
/// non-zero component is at least 2^-100 of the largest, the length does not matter (`2n`
/// encodes like `n`). (Closer to the largest component's 2^-126, `sanitize`'s power-of-two
/// scaling flushes a component for one length and not the other, and a folded code can take
/// the sign of that zero: found by this target.)
#[track_caller]
pub fn check_code(n: Vec3, code: u32, z: u32, n2: u32, sign: u32, code_bits: u32, what: &str) {
    if code_bits < 32 {
        assert_eq!(
            code >> code_bits,
            0,
            "{what} {n:?} → {code:#x}: bits above the code"
        );
    }
    let a = n.to_array();
    if n.is_nan() || a.iter().all(|c| !c.is_normal() && c.is_finite()) {
        assert_eq!(code, z, "{what} {n:?}: NaN, zero or all-subnormal → +z");
    } else if a.iter().any(|c| c.is_infinite()) {
        assert_eq!(code, sign, "{what} {n:?}: infinite components win");
    } else if a.iter().all(|&c| {
        let m = n.abs().max_element();
        c == 0.0 || (c.is_normal() && (c * 2.0).is_finite() && c.abs() >= m * 2f32.powi(-100))
    }) {
        assert_eq!(code, n2, "{what} {n:?}: scale-free (2n encodes like n)");
    }
}

/// [`check_code`] for the encoder `enc` (named `what` in messages), whose codes have
/// `code_bits` bits.
#[track_caller]
pub fn check_encoder(n: Vec3, enc: impl Fn(Vec3) -> u32, code_bits: u32, what: &str) {
    check_code(
        n,
        enc(n),
        enc(Vec3::Z),
        enc(n * 2.0),
        enc(signs(n)),
        code_bits,
        what,
    );
}

/// The bits per axis of the generic octahedral codes (`oct::{encode_precise, encode_round,
/// decode}`), read from one byte: `1..=16`.
pub fn oct_bits(i: &mut Input) -> u32 {
    u32::from(i.u8() % 16) + 1
}

/// An [`Entry`](crate::Entry) named `normal::<module>::<f>` whose check is
/// `check(input, module::f, args…)`: `codec!(check; module::f, args…)`. For the decoder
/// and encoder tables' codecs that one shared check covers (a code's bit size, a render-target
/// form's code function); the others write the `Entry` out by hand.
macro_rules! codec {
    ($check:ident; $module:ident :: $f:ident $(, $arg:expr)*) => {
        $crate::Entry {
            name: concat!("normal::", stringify!($module), "::", stringify!($f)),
            check: |i| $check(i, $module::$f $(, $arg)*),
        }
    };
}
pub(crate) use codec;
