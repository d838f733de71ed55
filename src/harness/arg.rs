//! [`Arg`]: how each argument of a batch reaches the function (a column, a splat, an index).

use super::*;

/// One argument of a batch run.
#[derive(Clone, Copy, Debug)]
pub enum Arg<'a> {
    /// One value per element, as raw bytes (`n × words × 4` of them); see [`Arg::column`].
    Column(&'a [u8]),
    /// One value for every element, passed in a uniform buffer as a renderer passes uniforms.
    /// Holds the value's bits, lanes in order; unused lanes are ignored.
    Splat([u32; 4]),
    /// Element `i` receives the bits `start + i` (wrapping), read as the parameter's scalar
    /// type: every 24-bit code, or every `f32` bit pattern in a range, without uploading them.
    /// Scalar parameters only.
    Index {
        /// Bits given to element 0.
        start: u32,
    },
}

impl<'a> Arg<'a> {
    /// A column from any plain-old-data slice: `&[f32]`, `&[u32]`, `&[[f32; 3]]`, `&[glam::Vec3]`…
    pub fn column<T: bytemuck::NoUninit>(values: &'a [T]) -> Self {
        Arg::Column(bytemuck::cast_slice(values))
    }

    /// The same `f32` for every element.
    pub fn splat_f32(x: f32) -> Self {
        Arg::Splat([x.to_bits(), 0, 0, 0])
    }

    /// The same `u32` for every element.
    pub fn splat_u32(x: u32) -> Self {
        Arg::Splat([x, 0, 0, 0])
    }

    /// The same vector for every element (up to 4 `f32` lanes).
    pub fn splat_vec(lanes: &[f32]) -> Self {
        let mut w = [0u32; 4];
        for (slot, x) in w.iter_mut().zip(lanes) {
            *slot = x.to_bits();
        }
        Arg::Splat(w)
    }

    pub(super) fn feed(&self) -> Feed {
        match self {
            Arg::Column(_) => Feed::Column,
            Arg::Splat(_) => Feed::Splat,
            Arg::Index { .. } => Feed::Index,
        }
    }
}
