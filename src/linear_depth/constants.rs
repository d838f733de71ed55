//! The constants the per-pixel functions of [`crate::linear_depth`] read, one type per WGSL
//! `k` vector, in the order the WGSL reads it, and the depth convention they carry.
//!
//! They live beside the functions that read them; [`crate::projection::Projection`] builds them
//! (and `prepass::projection` re-exports them at their old paths), so this module names
//! `Projection` in docs only.

/// Which end of the depth range the near plane maps to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthConvention {
    /// Near → 0, far → 1 (the convention of the Resistance 2 and Killzone 2 slides).
    Standard,
    /// Near → 1, far → 0 (reversed-Z: float depth's precision where distances are large).
    Reversed,
}

impl DepthConvention {
    /// The `u32` the WGSL takes for a convention (the `reversed` argument of
    /// `light_volume_window_depth`, `light_volume_sphere_depth_bounds` and
    /// `light_volume_sphere_depth_bounds24`): 0 standard, 1 reversed. The WGSL reads any
    /// non-zero value as reversed.
    pub fn to_wgsl(self) -> u32 {
        match self {
            Self::Standard => 0,
            Self::Reversed => 1,
        }
    }
}

/// The per-pixel constants of WGSL `view_z_from_depth24_consts(d, k)` (standard convention, 24-bit
/// code `d`): `vz = near_times_max / ((2^24 − 1 − d) + d·near_over_far)`. From
/// [`Projection::depth24_consts`]; [`to_wgsl`](Self::to_wgsl) gives the `k: vec2<f32>` to upload.
///
/// [`Projection::depth24_consts`]: crate::projection::Projection::depth24_consts
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct Depth24Consts {
    /// `n·(2^24 − 1)`: the near plane in code units, the formula's numerator (`k.x`).
    pub near_times_max: f32,
    /// `n/f`, exactly 0 for an infinite far plane: the weight of the code in the denominator
    /// (`k.y`).
    pub near_over_far: f32,
}

impl Depth24Consts {
    /// The vector the WGSL takes, in its order: `(near_times_max, near_over_far)`.
    pub fn to_wgsl(self) -> [f32; 2] {
        [self.near_times_max, self.near_over_far]
    }

    /// The constants from that vector (the inverse of [`to_wgsl`](Self::to_wgsl)).
    pub fn from_wgsl(k: [f32; 2]) -> Self {
        Self {
            near_times_max: k[0],
            near_over_far: k[1],
        }
    }
}

/// The per-pixel constants of WGSL `view_z_from_depth_consts(z, k)` (standard convention, float
/// depth `z`): `vz = near / ((1 − z) + z·near_over_far)` for `z ≥ 0.5` and
/// `near / (1 − z·one_minus_near_over_far)` below. From [`Projection::depth_consts`];
/// [`to_wgsl`](Self::to_wgsl) gives the `k: vec3<f32>` to upload.
///
/// [`Projection::depth_consts`]: crate::projection::Projection::depth_consts
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct DepthConsts {
    /// `n`, the near plane (`k.x`).
    pub near: f32,
    /// `n/f`, exactly 0 for an infinite far plane (`k.y`).
    pub near_over_far: f32,
    /// `(f − n)/f = 1 − n/f`, exactly 1 for an infinite far plane (`k.z`).
    pub one_minus_near_over_far: f32,
}

impl DepthConsts {
    /// The vector the WGSL takes, in its order: `(near, near_over_far, one_minus_near_over_far)`.
    pub fn to_wgsl(self) -> [f32; 3] {
        [self.near, self.near_over_far, self.one_minus_near_over_far]
    }

    /// The constants from that vector (the inverse of [`to_wgsl`](Self::to_wgsl)).
    pub fn from_wgsl(k: [f32; 3]) -> Self {
        Self {
            near: k[0],
            near_over_far: k[1],
            one_minus_near_over_far: k[2],
        }
    }
}

/// The per-pixel constants of WGSL `view_z_from_reversed_depth_consts(z, k)` (reversed
/// convention, float depth `z`): `vz = near / (z·one_minus_near_over_far + near_over_far)`. From
/// [`Projection::reversed_depth_consts`]; [`to_wgsl`](Self::to_wgsl) gives the `k: vec3<f32>` to
/// upload. The order differs from [`DepthConsts`]: it is the order the WGSL reads.
///
/// [`Projection::reversed_depth_consts`]: crate::projection::Projection::reversed_depth_consts
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct ReversedDepthConsts {
    /// `n`, the near plane (`k.x`).
    pub near: f32,
    /// `(f − n)/f = 1 − n/f`, exactly 1 for an infinite far plane: the weight of `z` (`k.y`).
    pub one_minus_near_over_far: f32,
    /// `n/f`, exactly 0 for an infinite far plane: the denominator at `z = 0` (`k.z`).
    pub near_over_far: f32,
}

impl ReversedDepthConsts {
    /// The vector the WGSL takes, in its order: `(near, one_minus_near_over_far, near_over_far)`.
    pub fn to_wgsl(self) -> [f32; 3] {
        [self.near, self.one_minus_near_over_far, self.near_over_far]
    }

    /// The constants from that vector (the inverse of [`to_wgsl`](Self::to_wgsl)).
    pub fn from_wgsl(k: [f32; 3]) -> Self {
        Self {
            near: k[0],
            one_minus_near_over_far: k[1],
            near_over_far: k[2],
        }
    }
}

/// The one depth uniform: the constants of WGSL `view_z_from_depth_uniform(z, k)` (float depth)
/// and `view_z_from_depth24_uniform(d, k)` (24-bit codes), for either convention, in one
/// `vec4<f32>` (16 bytes, `#[repr(C)]`, no padding: `Pod` with feature `bytemuck`):
///
/// `k = (n, n/f, (f − n)/f, ±n·(2^24 − 1))`, the sign bit of `k.w` set for a reversed
/// projection.
///
/// [`Projection::depth_uniform`] makes one from a checked projection, so the convention travels
/// with the constants: a reversed projection cannot hand a shader standard constants. Each entry
/// is computed in f64 and rounded once; the WGSL reads the same values the per-convention
/// `*_consts` functions read, so results (and error bounds, `linear_depth::bounds`) are those
/// of `view_z_from_depth_consts` / `view_z_from_reversed_depth_consts` /
/// `view_z_from_depth24_consts`, bit for bit.
///
/// The fields are public, and [`from_wgsl`](Self::from_wgsl) (or, with feature `bytemuck`, a
/// cast from bytes) makes one from any four floats. Those promises hold for such a value only
/// where it equals a `depth_uniform()` result: the convention is whatever the sign bit of `k.w`
/// says; entries no projection can give (`n` or `|k.w|` not positive and finite, a ratio outside
/// `[+0, 1]`) give the sky; other entries give the formula's value on them, with no bound.
///
/// ```
/// use prepass::linear_depth::{SKY, view_z_from_depth_uniform as view_z};
/// use prepass::projection::{DepthConvention, DepthUniform, Projection};
/// let k = Projection::new(0.1, 100.0, DepthConvention::Standard)?.depth_uniform();
/// assert_eq!(view_z(0.5, DepthUniform::from_wgsl(k.to_wgsl())), view_z(0.5, k));
/// let flipped = DepthUniform { signed_near_times_max: -k.signed_near_times_max, ..k };
/// assert_eq!(flipped.convention(), DepthConvention::Reversed); // the sign bit decides
/// assert_ne!(view_z(0.25, flipped), view_z(0.25, k));
/// assert_eq!(view_z(0.5, DepthUniform { near: -0.1, ..k }), SKY);
/// assert_eq!(view_z(0.5, DepthUniform { near_over_far: 2.0, ..k }), SKY);
/// # Ok::<(), prepass::projection::ProjectionError>(())
/// ```
///
/// [`Projection::depth_uniform`]: crate::projection::Projection::depth_uniform
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct DepthUniform {
    /// `n`, the near plane (`k.x`).
    pub near: f32,
    /// `n/f`, exactly 0 for an infinite far plane (`k.y`).
    pub near_over_far: f32,
    /// `(f − n)/f`, exactly 1 for an infinite far plane (`k.z`).
    pub one_minus_near_over_far: f32,
    /// `n·(2^24 − 1)`, negated for a reversed projection: the 24-bit numerator, and by its sign
    /// the convention (`k.w`).
    pub signed_near_times_max: f32,
}

impl DepthUniform {
    /// The vector the WGSL takes, in its order.
    pub fn to_wgsl(self) -> [f32; 4] {
        [
            self.near,
            self.near_over_far,
            self.one_minus_near_over_far,
            self.signed_near_times_max,
        ]
    }

    /// The uniform from that vector (the inverse of [`to_wgsl`](Self::to_wgsl)), unchecked. The
    /// shader functions give the sky for entries no [`Projection`] can give (`n` or `|k.w|` not
    /// positive and finite, a ratio outside `[+0, 1]`); other vectors no projection makes give
    /// the formula's value on them, with no bound (see the type's doc).
    ///
    /// [`Projection`]: crate::projection::Projection
    pub fn from_wgsl(k: [f32; 4]) -> Self {
        Self {
            near: k[0],
            near_over_far: k[1],
            one_minus_near_over_far: k[2],
            signed_near_times_max: k[3],
        }
    }

    /// The 16 bytes a uniform buffer holds (little-endian `vec4<f32>`), without bytemuck.
    pub fn to_le_bytes(self) -> [u8; 16] {
        let mut out = [0; 16];
        for (o, k) in out.chunks_exact_mut(4).zip(self.to_wgsl()) {
            o.copy_from_slice(&k.to_le_bytes());
        }
        out
    }

    /// The convention the sign of `k.w` carries.
    pub fn convention(self) -> DepthConvention {
        if self.signed_near_times_max.is_sign_negative() {
            DepthConvention::Reversed
        } else {
            DepthConvention::Standard
        }
    }
}

// SAFETY: four f32 fields, `#[repr(C)]`, no padding; every bit pattern is a valid value.
#[cfg(feature = "bytemuck")]
#[cfg_attr(docsrs, doc(cfg(feature = "bytemuck")))]
unsafe impl bytemuck::Zeroable for DepthUniform {}
// SAFETY: as above; `Copy + 'static`.
#[cfg(feature = "bytemuck")]
#[cfg_attr(docsrs, doc(cfg(feature = "bytemuck")))]
unsafe impl bytemuck::Pod for DepthUniform {}
