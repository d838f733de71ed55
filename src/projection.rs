//! `Projection`: near/far planes and depth convention, validated, with the constants the WGSL
//! per-pixel functions take (computed in f64, rounded once) and the exact forward maps
//! (view distance → window depth / 24-bit code) used as references.
//!
//! Conventions (spaces, handedness, depth, byte order, units, NaN policy): README, "Conventions".
//!
//! A renderer uploads one [`DepthUniform`] ([`Projection::depth_uniform`]) and calls WGSL
//! `view_z_from_depth_uniform` or `view_z_from_depth24_uniform`: the convention travels with
//! the constants. The per-convention constants (`depth_consts`, `reversed_depth_consts`,
//! `depth24_consts`) are refused for a projection of the other convention.
//!
//! View distance `vz` is the positive distance along the view axis (`+z` forward left-handed,
//! `−z` forward right-handed as wgpu/Bevy: then view-space z is `−vz`). Window depth in `[0, 1]`:
//! - standard: `z = f(vz − n) / ((f − n)·vz)` (near → 0, far → 1); infinite far: `z = 1 − n/vz`;
//! - reversed: `z = n(f − vz) / ((f − n)·vz)` (near → 1, far → 0); infinite far: `z = n/vz`.

use crate::depth24::DEPTH24_MAX;

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

    /// The uniform from that vector (the inverse of [`to_wgsl`](Self::to_wgsl)); the shader
    /// functions give the sky for vectors no [`Projection`] makes.
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

/// A rejected [`Projection`] parameter: which field, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct ProjectionError {
    /// The offending field: `"near"` or `"far"`.
    pub field: &'static str,
    /// What is wrong with it.
    pub reason: String,
}

impl std::fmt::Display for ProjectionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid projection `{}`: {}", self.field, self.reason)
    }
}

impl std::error::Error for ProjectionError {}

/// A perspective projection's depth mapping: `0 < near < far ≤ +∞`, standard or reversed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    near: f32,
    far: f32,
    convention: DepthConvention,
}

impl Projection {
    /// Validate and build. Errors name the field: `near` must be a positive normal float (subnormal
    /// near planes lose precision in every formula) small enough that `near·(2^24 − 1)` is a
    /// finite f32; `far` must be > near and not NaN, `+∞` allowed (infinite projection), and a
    /// finite far must keep `near/far` a normal float (far/near ≤ 2^126).
    pub fn new(near: f32, far: f32, convention: DepthConvention) -> Result<Self, ProjectionError> {
        let bad = |field, reason: String| Err(ProjectionError { field, reason });
        if near.is_nan() {
            return bad("near", "is NaN".into());
        }
        if near < f32::MIN_POSITIVE {
            return bad("near", format!("{near} is not a positive normal float"));
        }
        if near.is_infinite() {
            return bad("near", "is infinite".into());
        }
        // The 24-bit path scales near by 2^24 − 1 in f32: it must stay finite.
        if f64::from(near) * f64::from(DEPTH24_MAX) > f64::from(f32::MAX) {
            return bad(
                "near",
                format!("{near} is too large: near·(2^24 − 1) overflows f32"),
            );
        }
        if far.is_nan() {
            return bad("far", "is NaN".into());
        }
        if far <= near {
            return bad("far", format!("{far} is not greater than near = {near}"));
        }
        // n/f must be a normal float: a subnormal ratio loses its relative precision, and with it
        // the error bound of every reconstruction. Such a far plane is infinite in all but name.
        if far.is_finite() && f64::from(near) / f64::from(far) < f64::from(f32::MIN_POSITIVE) {
            return bad(
                "far",
                format!(
                    "far/near = {:e} exceeds 2^126: use an infinite far plane",
                    f64::from(far) / f64::from(near)
                ),
            );
        }
        Ok(Projection {
            near,
            far,
            convention,
        })
    }

    /// Near plane distance.
    pub fn near(&self) -> f32 {
        self.near
    }

    /// Far plane distance (`+∞` for an infinite projection).
    pub fn far(&self) -> f32 {
        self.far
    }

    /// The depth convention.
    pub fn convention(&self) -> DepthConvention {
        self.convention
    }

    /// Whether the far plane is at infinity.
    pub fn is_infinite(&self) -> bool {
        self.far.is_infinite()
    }

    /// `n/f` in f64 (0 for an infinite far plane).
    fn ratio(&self) -> f64 {
        if self.is_infinite() {
            0.0
        } else {
            f64::from(self.near) / f64::from(self.far)
        }
    }

    /// The depth uniform for this projection, in its convention: what a renderer uploads for
    /// WGSL `view_z_from_depth_uniform` (float depth) and `view_z_from_depth24_uniform`
    /// (24-bit codes). See [`DepthUniform`].
    ///
    /// ```
    /// use prepass::projection::{DepthConvention, Projection};
    /// let p = Projection::new(0.1, f32::INFINITY, DepthConvention::Reversed)?;
    /// let k = p.depth_uniform();
    /// assert_eq!(k.convention(), DepthConvention::Reversed);
    /// let vz = prepass::linear_depth::view_z_from_depth_uniform(0.01, k); // n/z = 10
    /// assert!((vz - 10.0).abs() < 1e-5);
    /// # Ok::<(), prepass::projection::ProjectionError>(())
    /// ```
    pub fn depth_uniform(&self) -> DepthUniform {
        let near_times_max = self.near_times_max();
        DepthUniform {
            near: self.near,
            near_over_far: self.ratio() as f32,
            one_minus_near_over_far: self.one_minus_ratio() as f32,
            signed_near_times_max: match self.convention {
                DepthConvention::Standard => near_times_max,
                DepthConvention::Reversed => -near_times_max,
            },
        }
    }

    /// `n·(2^24 − 1)`, the exact product rounded once (it fits an f64).
    fn near_times_max(&self) -> f32 {
        (f64::from(self.near) * f64::from(DEPTH24_MAX)) as f32
    }

    /// An error unless this projection has convention `want` (for the per-convention
    /// constants).
    fn expect(&self, want: DepthConvention, wgsl: &str) -> Result<(), ProjectionError> {
        if self.convention == want {
            return Ok(());
        }
        Err(ProjectionError {
            field: "convention",
            reason: format!(
                "`{wgsl}` reads {want:?} depth, but this projection is {:?}: use \
                 `depth_uniform()` (either convention) or the matching constants",
                self.convention
            ),
        })
    }

    /// Constants for WGSL `view_z_from_depth24_consts(d, k)`: `k = (n·(2^24 − 1), n/f)`, each
    /// computed in f64 and rounded once. The codes that function reads are of standard depth,
    /// so a reversed projection is an error (its codes read through
    /// `view_z_from_depth24_uniform`). Upload [`Depth24Consts::to_wgsl`].
    pub fn depth24_consts(&self) -> Result<Depth24Consts, ProjectionError> {
        self.expect(DepthConvention::Standard, "view_z_from_depth24_consts")?;
        Ok(Depth24Consts {
            near_times_max: self.near_times_max(),
            near_over_far: self.ratio() as f32,
        })
    }

    /// Constants for WGSL `view_z_from_depth_consts(z, k)`: `k = (n, n/f, (f − n)/f)`
    /// (`(0, 1)` in the last two when infinite), the last two computed in f64 and rounded
    /// once. A reversed projection is an error. Upload [`DepthConsts::to_wgsl`].
    pub fn depth_consts(&self) -> Result<DepthConsts, ProjectionError> {
        self.expect(DepthConvention::Standard, "view_z_from_depth_consts")?;
        Ok(DepthConsts {
            near: self.near,
            near_over_far: self.ratio() as f32,
            one_minus_near_over_far: self.one_minus_ratio() as f32,
        })
    }

    /// `(f − n)/f` in f64 (1 for an infinite far plane).
    fn one_minus_ratio(&self) -> f64 {
        if self.is_infinite() {
            1.0
        } else {
            (f64::from(self.far) - f64::from(self.near)) / f64::from(self.far)
        }
    }

    /// Constants for WGSL `view_z_from_reversed_depth_consts(z, k)`:
    /// `k = (n, (f − n)/f, n/f)` (`(1, 0)` in the last two when infinite), the last two computed
    /// in f64 and rounded once. A standard projection is an error. Upload
    /// [`ReversedDepthConsts::to_wgsl`].
    pub fn reversed_depth_consts(&self) -> Result<ReversedDepthConsts, ProjectionError> {
        self.expect(
            DepthConvention::Reversed,
            "view_z_from_reversed_depth_consts",
        )?;
        Ok(ReversedDepthConsts {
            near: self.near,
            one_minus_near_over_far: self.one_minus_ratio() as f32,
            near_over_far: self.ratio() as f32,
        })
    }

    /// Exact window depth of view distance `vz` under this projection's convention (f64).
    pub fn depth_from_view_z(&self, vz: f64) -> f64 {
        let (n, f) = (f64::from(self.near), f64::from(self.far));
        let standard = if self.is_infinite() {
            1.0 - n / vz
        } else {
            f * (vz - n) / ((f - n) * vz)
        };
        match self.convention {
            DepthConvention::Standard => standard,
            DepthConvention::Reversed => {
                if self.is_infinite() {
                    n / vz
                } else {
                    n * (f - vz) / ((f - n) * vz)
                }
            }
        }
    }

    /// The 24-bit code a depth buffer stores for view distance `vz`: the nearest integer to
    /// `depth · (2^24 − 1)`, clamped to the code range (standard convention codes are what
    /// [`crate::linear_depth::view_z_from_depth24`] reads; for a reversed projection the code is
    /// of the reversed depth).
    pub fn depth24_from_view_z(&self, vz: f64) -> u32 {
        let z = self.depth_from_view_z(vz).clamp(0.0, 1.0);
        (z * f64::from(DEPTH24_MAX)).round() as u32
    }

    /// View distance from a float window depth in this projection's convention (the Rust twin
    /// of the matching WGSL function; see [`crate::linear_depth`]).
    pub fn view_z_from_depth(&self, z: f32) -> f32 {
        crate::linear_depth::view_z_from_depth_uniform(z, self.depth_uniform())
    }

    /// `tan(fov/2)` along x and y, the `tan_half_fov` of WGSL `frustum_ray_rh` /
    /// `fullscreen_triangle_ray_rh` (and the left-handed forms), for the matrix
    /// [`perspective_rh`](Self::perspective_rh)`(fov_y, aspect)` builds: `(aspect·t, t)` with
    /// `t = tan(fov_y/2)`, computed in f64 and rounded once. For a matrix of your own use
    /// [`crate::position::tan_half_fov_of`].
    pub fn tan_half_fov(fov_y: f32, aspect: f32) -> [f32; 2] {
        let t = (f64::from(fov_y) / 2.0).tan();
        [(f64::from(aspect) * t) as f32, t as f32]
    }

    /// A right-handed (−z forward, wgpu/Bevy) perspective matrix with this depth mapping, for
    /// `fov_y` radians and `aspect` = width/height. Clip-space `z/w` is the window depth above;
    /// entries are computed in f64 and rounded once.
    pub fn perspective_rh(&self, fov_y: f32, aspect: f32) -> glam::Mat4 {
        let (n, f) = (f64::from(self.near), f64::from(self.far));
        let fy = 1.0 / (f64::from(fov_y) / 2.0).tan();
        let fx = fy / f64::from(aspect);
        // clip.z = c·(−vz) + e and clip.w = vz give z/w = the window depth of the module docs.
        let (c, e) = match (self.convention, self.is_infinite()) {
            (DepthConvention::Standard, false) => (f / (n - f), n * f / (n - f)),
            (DepthConvention::Standard, true) => (-1.0, -n),
            (DepthConvention::Reversed, false) => (n / (f - n), n * f / (f - n)),
            (DepthConvention::Reversed, true) => (0.0, n),
        };
        glam::Mat4::from_cols(
            glam::Vec4::new(fx as f32, 0.0, 0.0, 0.0),
            glam::Vec4::new(0.0, fy as f32, 0.0, 0.0),
            glam::Vec4::new(0.0, 0.0, c as f32, -1.0),
            glam::Vec4::new(0.0, 0.0, e as f32, 0.0),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_field() {
        let s = DepthConvention::Standard;
        assert_eq!(Projection::new(0.0, 1.0, s).unwrap_err().field, "near");
        assert_eq!(Projection::new(-1.0, 1.0, s).unwrap_err().field, "near");
        assert_eq!(Projection::new(f32::NAN, 1.0, s).unwrap_err().field, "near");
        assert_eq!(Projection::new(1e-40, 1.0, s).unwrap_err().field, "near");
        assert_eq!(
            Projection::new(f32::INFINITY, f32::INFINITY, s)
                .unwrap_err()
                .field,
            "near"
        );
        assert_eq!(Projection::new(1.0, 1.0, s).unwrap_err().field, "far");
        assert_eq!(Projection::new(1.0, 0.5, s).unwrap_err().field, "far");
        assert_eq!(Projection::new(1.0, f32::NAN, s).unwrap_err().field, "far");
        let e = Projection::new(1.0, 0.5, s).unwrap_err().to_string();
        assert!(e.contains("`far`") && e.contains("0.5"), "{e}");
        assert!(Projection::new(0.1, f32::INFINITY, s).is_ok());
    }

    #[test]
    fn named_constants_reach_the_wgsl_in_its_order() {
        let p = Projection::new(0.5, 100.0, DepthConvention::Standard).unwrap();
        let pr = Projection::new(0.5, 100.0, DepthConvention::Reversed).unwrap();
        let k24 = p.depth24_consts().unwrap();
        assert_eq!(k24.to_wgsl(), [k24.near_times_max, k24.near_over_far]);
        assert_eq!(Depth24Consts::from_wgsl(k24.to_wgsl()), k24);
        let k = p.depth_consts().unwrap();
        assert_eq!(
            k.to_wgsl(),
            [k.near, k.near_over_far, k.one_minus_near_over_far]
        );
        assert_eq!(DepthConsts::from_wgsl(k.to_wgsl()), k);
        let kr = pr.reversed_depth_consts().unwrap();
        assert_eq!(
            kr.to_wgsl(),
            [kr.near, kr.one_minus_near_over_far, kr.near_over_far]
        );
        assert_eq!(ReversedDepthConsts::from_wgsl(kr.to_wgsl()), kr);
        assert_eq!((k.near_over_far, kr.near_over_far), (0.005, 0.005));
        for (proj, sign) in [(p, 1.0), (pr, -1.0)] {
            let u = proj.depth_uniform();
            assert_eq!(u.to_wgsl(), [0.5, 0.005, 0.995, sign * k24.near_times_max]);
            assert_eq!(DepthUniform::from_wgsl(u.to_wgsl()), u);
            assert_eq!(u.convention(), proj.convention());
            assert_eq!(u.to_le_bytes()[..4], 0.5f32.to_le_bytes());
        }
    }

    #[test]
    fn per_convention_constants_refuse_the_other_convention() {
        let s = Projection::new(0.5, 100.0, DepthConvention::Standard).unwrap();
        let r = Projection::new(0.5, 100.0, DepthConvention::Reversed).unwrap();
        assert_eq!(r.depth_consts().unwrap_err().field, "convention");
        assert_eq!(r.depth24_consts().unwrap_err().field, "convention");
        assert_eq!(s.reversed_depth_consts().unwrap_err().field, "convention");
        let e = r.depth_consts().unwrap_err().to_string();
        assert!(e.contains("depth_uniform"), "{e}");
    }

    #[test]
    fn tan_half_fov_matches_the_matrix() {
        let p = Projection::new(0.1, f32::INFINITY, DepthConvention::Reversed).unwrap();
        let (fov_y, aspect) = (1.2f32, 16.0 / 9.0);
        let t = Projection::tan_half_fov(fov_y, aspect);
        let m = crate::position::tan_half_fov_of(p.perspective_rh(fov_y, aspect));
        for (a, b) in t.into_iter().zip(m) {
            // The matrix entries are rounded once, their reciprocals once more: 2 ULP apart at most.
            assert!((a - b).abs() <= 2.0 * f32::EPSILON * a, "{t:?} vs {m:?}");
        }
        assert!((t[1] - 0.6f32.tan()).abs() < 1e-6);
    }

    #[test]
    fn matrices_agree_with_the_depth_maps() {
        for conv in [DepthConvention::Standard, DepthConvention::Reversed] {
            for far in [100.0f32, f32::INFINITY] {
                let p = Projection::new(0.5, far, conv).unwrap();
                let m = p.perspective_rh(1.0, 1.5);
                for vz in [0.5f32, 1.0, 7.0, 99.0] {
                    let clip = m * glam::Vec4::new(0.0, 0.0, -vz, 1.0);
                    let z = clip.z / clip.w;
                    let want = p.depth_from_view_z(f64::from(vz));
                    // glam builds the matrix in f32: a few f32 ULPs of slack on values ≤ 1.
                    crate::assert_within_abs!(
                        f64::from(z),
                        want,
                        < 1e-6,
                        "comment above: glam's f32 matrix, a few f32 ULPs on values ≤ 1",
                        "{conv:?} far {far} vz {vz}"
                    );
                }
            }
        }
    }
}
