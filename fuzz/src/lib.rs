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
//! - [`DIFFERENTIAL`]: the Rust twin against its exact reference, within the documented bound;
//! - [`LIGHTING`]: the light pre-pass, aggregate-light and light-volume functions → their
//!   documented ranges and bad-input answers;
//! - [`BATCH`]: every `prepass::batch` slice twin equals its scalar twin, at every SIMD level.
//!
//! A builder family (`Projection`, scene: arbitrary input → `Ok` or a clear `Err`) is a new
//! table plus a three-line `fuzz_targets/builders.rs` and one line in `.ci/fuzz`.
//!
//! One file per table ([`decoders`], [`encoders`], [`differential`], [`builders`],
//! [`lighting`], [`batch`]); [`normal`] holds the rules every normal codec shares.

pub mod batch;
pub mod builders;
pub mod decoders;
pub mod differential;
pub mod encoders;
pub mod lighting;
pub mod normal;

pub use batch::BATCH;
pub use builders::BUILDERS;
pub use decoders::DECODERS;
pub use differential::DIFFERENTIAL;
pub use encoders::ENCODERS;
pub use lighting::LIGHTING;

use glam::Vec3;
use prepass::projection::{DepthConvention, Projection};

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

    /// Four `f32` bit patterns.
    pub fn vec4(&mut self) -> glam::Vec4 {
        glam::Vec4::new(self.f32(), self.f32(), self.f32(), self.f32())
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

/// Read a `Projection` from fuzz bytes: near/far bit patterns and a convention byte.
pub fn projection(i: &mut Input) -> Result<Projection, prepass::projection::ProjectionError> {
    let (near, far) = (i.f32(), i.f32());
    let conv = if i.u8() & 1 == 1 {
        DepthConvention::Reversed
    } else {
        DepthConvention::Standard
    };
    Projection::new(near, far, conv)
}

/// Every table with the name of its fuzz target (`fuzz_targets/<name>.rs`, `corpus/<name>/`).
pub const TABLES: &[(&str, &[Entry])] = &[
    ("builders", BUILDERS),
    ("decoders", DECODERS),
    ("encoders", ENCODERS),
    ("differential", DIFFERENTIAL),
    ("batch", BATCH),
    ("lighting", LIGHTING),
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
