//! Precision sweeps that run the WGSL on the adapter and measure it against exact references
//! (feature `harness`). The tests assert on their results; `errplot` tabulates them.

pub mod conforming;
pub mod depth24;
pub mod linear_depth;
pub mod lpp;
pub mod normal;
pub mod roughness;

/// A small deterministic generator (SplitMix64) so every run measures the same scenes.
#[derive(Clone, Debug)]
pub struct SplitMix(pub u64);

impl SplitMix {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let u = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * u
    }

    /// A random direction in the hemisphere around +z (z ≥ `min_z`), not normalised.
    pub fn hemisphere(&mut self, min_z: f32) -> [f32; 3] {
        loop {
            let v = [
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(min_z, 1.0),
            ];
            let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if l2 > 0.01 && l2 <= 1.0 {
                return v;
            }
        }
    }
}
