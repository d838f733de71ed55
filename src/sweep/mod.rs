//! Precision sweeps that run the WGSL on the adapter and measure it against exact references
//! (feature `harness`). The tests assert on their results; `errplot` tabulates them.

pub mod conforming;
pub mod depth24;
pub mod lighting;
pub mod linear_depth;
pub mod normal;
pub mod roughness;
