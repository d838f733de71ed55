//! The fuzzed properties, as tables of entries: one table per fuzz target
//! (`fuzz_targets/<table>.rs`), one entry per public function. The first input byte picks the
//! entry, the rest is its input, so one target covers a whole family and CI's smoke time does not
//! grow with every function.
//!
//! Adding a function: write a `fn(&mut Input)` that reads its arguments and asserts the
//! documented property (panicking on a violation is how libFuzzer sees a bug), and add it to
//! the table of its family:
//! - [`DECODERS`]: any bytes → a finite (or in-range) result, as documented;
//! - [`ENCODERS`]: any bit patterns, `f32` NaN/Inf/subnormal included → no panic, the documented
//!   output;
//! - [`DIFFERENTIAL`]: the Rust twin against its exact reference, within the documented bound.
//!
//! A builder family (`Projection`, scene: arbitrary input → `Ok` or a clear `Err`) is a new
//! table plus a three-line `fuzz_targets/builders.rs` and one line in `.ci/fuzz`.

pub mod batch;

use glam::Vec3;
use prepass::depth24::{self, DEPTH24_MAX};
use prepass::linear_depth as ld;
use prepass::precision::metrics::ulp_error;
use prepass::projection::{DepthConvention, Projection};
use prepass::{assert_within, assert_within_abs};

/// The bytes of one fuzz input, read front to back; reads past the end give zeros, so every
/// input is valid for every entry.
pub struct Input<'a> {
    bytes: &'a [u8],
}

impl<'a> Input<'a> {
    /// Wrap raw bytes.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes }
    }

    /// Next byte (0 past the end).
    pub fn u8(&mut self) -> u8 {
        let (first, rest) = self
            .bytes
            .split_first()
            .map_or((0, &[][..]), |(f, r)| (*f, r));
        self.bytes = rest;
        first
    }

    /// Next four bytes, little-endian.
    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }

    /// Next four bytes as an `f32` bit pattern: NaNs, infinities, subnormals and signed zeros
    /// all occur.
    pub fn f32(&mut self) -> f32 {
        f32::from_bits(self.u32())
    }

    /// Three `f32` bit patterns.
    pub fn vec3(&mut self) -> Vec3 {
        Vec3::new(self.f32(), self.f32(), self.f32())
    }
}

/// One fuzzed function: a name for messages and the property check.
pub struct Entry {
    /// The public function it exercises.
    pub name: &'static str,
    /// Reads the arguments and asserts the documented behaviour.
    pub check: fn(&mut Input),
}

/// Run the entry picked by the first byte on the remaining bytes.
pub fn dispatch(table: &[Entry], data: &[u8]) {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let entry = &table[usize::from(pick) % table.len()];
    (entry.check)(&mut Input::new(rest));
}

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
];

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
];

/// The documented error of a linear-depth twin against its exact f64 distance: within `bound`
/// ULP (`from` names the bound), or `+Inf` exactly where the exact distance is beyond f32's
/// range.
#[track_caller]
fn assert_distance(got: f32, exact: f64, bound: f64, from: &str, context: std::fmt::Arguments<'_>) {
    if (exact as f32).is_infinite() {
        assert_eq!(got, f32::INFINITY, "{context}: beyond f32's range");
        return;
    }
    assert_within!(ulp_error(got, exact), bound, from, "{context}");
}

/// Rust twins against their exact references, within the documented bound.
pub const DIFFERENTIAL: &[Entry] = &[
    Entry {
        name: "depth24::hyperbolic_depth_from_depth24 vs exact::hyperbolic_depth",
        check: |i| {
            let d = i.u32();
            let got = depth24::hyperbolic_depth_from_depth24(d);
            let err = ulp_error(got, depth24::exact::hyperbolic_depth(d));
            assert_within!(
                err,
                0.5,
                "documented: correctly rounded, ≤ 0.5 ULP",
                "{d:#x} → {got:?}"
            );
        },
    },
    Entry {
        name: "depth24::depth24_from_rgb8 within ±0.49/255 vs exact code",
        check: |i| {
            let code = i.u32() & DEPTH24_MAX;
            // Each channel moved by up to ±0.49 of a byte step (a signed byte scaled to ±0.49):
            // the documented exactness region.
            let bytes = [code >> 16, (code >> 8) & 0xff, code & 0xff];
            let rgb = bytes.map(|b| {
                let off = f64::from(i.u8() as i8) / 128.0 * 0.49;
                ((f64::from(b) + off) / 255.0) as f32
            });
            let got = depth24::depth24_from_rgb8(Vec3::from(rgb));
            assert_eq!(got, code, "{rgb:?}");
        },
    },
    Entry {
        name: "linear_depth::view_z_from_depth24 vs exact (linear_depth::bounds::DEPTH24_CORRECTLY_ROUNDED: the Rust twin rounds correctly)",
        check: |i| {
            let d = i.u32();
            let Ok(p) = projection(i) else { return };
            let got = ld::view_z_from_depth24(d, p.near(), p.far());
            let e = ld::exact::view_z_from_depth24(d, p.near(), p.far());
            assert_distance(
                got,
                e,
                ld::bounds::DEPTH24_CORRECTLY_ROUNDED,
                "linear_depth::bounds::DEPTH24_CORRECTLY_ROUNDED",
                format_args!("{d:#x} {p:?}: {got} vs {e}"),
            );
        },
    },
    Entry {
        name: "linear_depth::view_z_from_depth / _reversed_ vs exact (linear_depth::bounds::FLOAT_CORRECTLY_ROUNDED)",
        check: |i| {
            let z = i.f32();
            let Ok(p) = projection(i) else { return };
            if z.is_nan() {
                return; // NaN → NaN is a decoder property, not an error bound
            }
            let (n, f) = (p.near(), p.far());
            let (got, e) = match p.convention() {
                DepthConvention::Standard => (
                    ld::view_z_from_depth(z, n, f),
                    ld::exact::view_z_from_depth(z, n, f),
                ),
                DepthConvention::Reversed => (
                    ld::view_z_from_reversed_depth(z, n, f),
                    ld::exact::view_z_from_reversed_depth(z, n, f),
                ),
            };
            assert_distance(
                got,
                e,
                ld::bounds::FLOAT_CORRECTLY_ROUNDED,
                "linear_depth::bounds::FLOAT_CORRECTLY_ROUNDED",
                format_args!("{z:?} {p:?}: {got} vs {e}"),
            );
        },
    },
];

/// Read a `Projection` from fuzz bytes: near/far bit patterns and a convention byte.
fn projection(i: &mut Input) -> Result<Projection, prepass::projection::ProjectionError> {
    let (near, far) = (i.f32(), i.f32());
    let conv = if i.u8() & 1 == 1 {
        DepthConvention::Reversed
    } else {
        DepthConvention::Standard
    };
    Projection::new(near, far, conv)
}

/// Builders: arbitrary input → `Ok` with usable constants, or an `Err` naming a field; never a
/// panic.
pub const BUILDERS: &[Entry] = &[
    Entry {
        name: "projection::Projection::new",
        check: |i| match projection(i) {
            Ok(p) => {
                // Documented: every per-pixel constant is finite and n·(2^24 − 1), n/f are normal
                // or zero (n/f = 0 exactly when far = +Inf).
                let k24 = p.depth24_consts().to_wgsl();
                let k = p.depth_consts().to_wgsl();
                let kr = p.reversed_depth_consts().to_wgsl();
                for c in k24.iter().chain(&k).chain(&kr) {
                    assert!(c.is_finite() && *c >= 0.0, "{p:?}: constant {c}");
                }
                assert!(k24[0].is_normal(), "{p:?}");
                assert_eq!(k24[1] == 0.0, p.is_infinite(), "{p:?}");
                assert!(k24[1] == 0.0 || k24[1].is_normal(), "{p:?}: n/f subnormal");
            }
            Err(e) => {
                assert!(e.field == "near" || e.field == "far", "{e}");
                assert!(e.to_string().contains(e.field));
            }
        },
    },
    Entry {
        name: "scene::Scene::{roots, gbuffer}",
        check: |i| {
            use prepass::scene::{DepthChoice, DepthStorage, PositionChoice, Scene};
            let b = i.u8();
            let storage = [
                DepthStorage::Float32,
                DepthStorage::Code24,
                DepthStorage::Code24Rgba8,
            ][usize::from(b % 3)];
            let convention = if b & 4 == 0 {
                DepthConvention::Standard
            } else {
                DepthConvention::Reversed
            };
            let position = [
                PositionChoice::None,
                PositionChoice::View,
                PositionChoice::World,
                PositionChoice::CameraRelative,
            ][usize::from((b >> 3) % 4)];
            use prepass::scene::{
                LightBuffers, LightingChoice, Lights, NormalChoice, NormalEncoding,
                RoughnessChoice, Specular,
            };
            let (n, l) = (i.u8(), i.u8());
            let scene = Scene {
                depth: DepthChoice {
                    storage,
                    convention,
                    infinite_far: b & 0x40 != 0,
                },
                position,
                normal: NormalChoice {
                    encoding: [None]
                        .into_iter()
                        .chain(NormalEncoding::ALL.map(Some))
                        .nth(usize::from(n % 7))
                        .flatten(),
                    fast_encoder: n & 0x80 != 0,
                },
                roughness: if n & 0x40 != 0 {
                    RoughnessChoice::Log8
                } else {
                    RoughnessChoice::None
                },
                lighting: LightingChoice {
                    lights: [
                        Lights::None,
                        Lights::Point,
                        Lights::Spot,
                        Lights::PointAndSpot,
                    ][usize::from(l % 4)],
                    specular: [Specular::None, Specular::BlinnPhong, Specular::Phong]
                        [usize::from((l >> 2) % 3)],
                    buffers: if l & 0x10 != 0 {
                        LightBuffers::Two
                    } else {
                        LightBuffers::One
                    },
                    aggregate_vertex_lights: l & 0x20 != 0,
                    light_volumes: l & 0x40 != 0,
                },
            };
            match (scene.roots(), scene.gbuffer()) {
                (Ok(roots), Ok(g)) => {
                    assert!(!roots.is_empty());
                    let (w, h, s) = (
                        u64::from(i.u32() >> 16),
                        u64::from(i.u32() >> 16),
                        u64::from(i.u8() % 8 + 1),
                    );
                    assert_eq!(g.memory_bytes(w, h, s), g.bytes_per_pixel() * w * h * s);
                }
                (Err(e), Err(_)) => assert!(!e.fields.is_empty(), "{e}"),
                (r, g) => panic!("roots and gbuffer disagree on validity: {r:?} / {g:?}"),
            }
        },
    },
];

/// Every table with the name of its fuzz target (`fuzz_targets/<name>.rs`, `corpus/<name>/`).
pub const TABLES: &[(&str, &[Entry])] = &[
    ("builders", BUILDERS),
    ("decoders", DECODERS),
    ("encoders", ENCODERS),
    ("differential", DIFFERENTIAL),
    ("batch", batch::BATCH),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Replays the committed corpus through the properties without libFuzzer (plain
    /// `cargo test` in `fuzz/`, stable toolchain).
    #[test]
    fn committed_corpus_passes() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus");
        let mut n = 0;
        for &(target, table) in TABLES {
            for f in std::fs::read_dir(root.join(target)).expect("corpus directory") {
                dispatch(table, &std::fs::read(f.unwrap().path()).unwrap());
                n += 1;
            }
        }
        assert!(n > 0, "empty corpus");
    }

    /// Every target file has a table and a corpus, and every table a target.
    #[test]
    fn targets_and_tables_match() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut files: Vec<String> = std::fs::read_dir(root.join("fuzz_targets"))
            .unwrap()
            .map(|e| {
                e.unwrap()
                    .path()
                    .file_stem()
                    .unwrap()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect();
        files.sort();
        let mut names: Vec<String> = TABLES.iter().map(|(n, _)| n.to_string()).collect();
        names.sort();
        assert_eq!(files, names);
        for (n, table) in TABLES {
            assert!(!table.is_empty(), "{n} is empty");
            assert!(root.join("corpus").join(n).is_dir(), "no corpus/{n}");
        }
    }
}
