//! [`Output`]: a run's results as raw words, with typed views.

use super::*;

/// The results of a run (or of one chunk of it): `len` values of type `ty`, as raw words.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// Type of each value.
    pub ty: ValueType,
    pub(super) words: Vec<u32>,
}

impl Output {
    /// Results of type `ty`, their words in order (runs put together from parts).
    pub(crate) fn from_words(ty: ValueType, words: Vec<u32>) -> Self {
        Output { ty, words }
    }

    /// Number of values.
    pub fn len(&self) -> usize {
        self.words.len() / self.ty.words()
    }

    /// Whether there are no values.
    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
    }

    /// The raw 32-bit words, lanes of each value consecutive.
    pub fn words(&self) -> &[u32] {
        &self.words
    }

    /// Take the raw words.
    pub fn into_words(self) -> Vec<u32> {
        self.words
    }

    /// Scalar `f32` results (or the lanes of vectors, flattened).
    pub fn as_f32(&self) -> &[f32] {
        bytemuck::cast_slice(&self.words)
    }

    /// Take the scalar `f32` results (or lanes) without copying them: the words' allocation is
    /// reused (a sweep's 2^24 results are 64 MiB, and a fresh copy costs its page faults).
    pub fn into_f32(self) -> Vec<f32> {
        self.words.into_iter().map(f32::from_bits).collect()
    }

    /// Scalar `u32` results (or lanes).
    pub fn as_u32(&self) -> &[u32] {
        &self.words
    }

    /// Scalar `i32` results (or lanes).
    pub fn as_i32(&self) -> &[i32] {
        bytemuck::cast_slice(&self.words)
    }

    /// `vec2<f32>` results. Panics if the result is not two lanes wide.
    pub fn as_vec2(&self) -> &[[f32; 2]] {
        assert_eq!(self.ty.lanes, 2, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }

    /// `vec3<f32>` results. Panics if the result is not three lanes wide.
    pub fn as_vec3(&self) -> &[[f32; 3]] {
        assert_eq!(self.ty.lanes, 3, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }

    /// `vec4<f32>` results. Panics if the result is not four lanes wide.
    pub fn as_vec4(&self) -> &[[f32; 4]] {
        assert_eq!(self.ty.lanes, 4, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }
}
