//! The Killzone 2 xy-FP16 "myth": how many visible view-space normals have `z < 0`, and what
//! decoding them costs.

use super::inputs::fibonacci_directions;
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{ErrorStats, angle_degrees, widen3};
use crate::wgsl::NORMAL_XY_FP16;

/// The Killzone 2 xy-FP16 "myth" for one field of view (square viewport, `fov_deg` across both
/// axes): which visible normals have view-space `z < 0`, and what decoding them costs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Myth {
    /// Field of view, degrees.
    pub fov_deg: f64,
    /// Pixel centres sampled (a `grid × grid` screen).
    pub pixels: u64,
    /// Pixels where some visible normal has `z < 0` (every pixel off the optical axis).
    pub pixels_with_negative_z: u64,
    /// Of the visible normals (uniform over each pixel's visible hemisphere), the fraction with
    /// `z < 0`, averaged over the screen (exactly `θ/π` per pixel, θ = angle off axis).
    pub visible_fraction_negative_z: f64,
    /// The same, analytic: mean of `θ/π` over the pixel centres.
    pub visible_fraction_analytic: f64,
    /// Worst angular error (degrees) of `decode(encode(n))` on the adapter over the sampled
    /// visible normals with `z < 0`.
    pub worst_error_deg: f64,
    /// Mean error (degrees) over the sampled visible normals with `z < 0`.
    pub mean_error_negative_deg: f64,
    /// The analytic worst case, `2·θ_corner` (a normal at grazing incidence at the corner).
    pub worst_error_analytic_deg: f64,
}

/// Measure [`Myth`] on a `grid × grid` screen with `normals` Fibonacci normals per pixel's
/// visible hemisphere (the hemisphere facing the camera along that pixel's view ray), each
/// encoded and decoded by the WGSL xy-FP16 functions.
pub fn killzone_myth(
    gpu: &Gpu,
    fov_deg: f64,
    grid: u32,
    normals: u32,
) -> Result<Myth, HarnessError> {
    let t = (fov_deg.to_radians() / 2.0).tan();
    let sphere: Vec<[f64; 3]> = fibonacci_directions(2 * normals)
        .into_iter()
        .map(widen3)
        .filter(|d| d[2] > 0.0)
        .collect();
    let mut m = Myth {
        fov_deg,
        ..Default::default()
    };
    let enc = gpu.kernel(NORMAL_XY_FP16, "encode_normal_xy_fp16")?;
    let dec = gpu.kernel(NORMAL_XY_FP16, "decode_normal_xy_fp16")?;
    let (mut frac_sum, mut analytic_sum, mut neg_err) = (0.0, 0.0, ErrorStats::default());
    for py in 0..grid {
        let mut inputs: Vec<[f32; 3]> = Vec::new();
        let mut row_neg = vec![0u64; grid as usize];
        for px in 0..grid {
            let sx = (2.0 * (f64::from(px) + 0.5) / f64::from(grid) - 1.0) * t;
            let sy = (2.0 * (f64::from(py) + 0.5) / f64::from(grid) - 1.0) * t;
            // w: towards the camera from the surface (minus the view ray), unit.
            let w = crate::normal::exact::unit([-sx, -sy, 1.0]).expect("finite");
            let theta = w[2].clamp(-1.0, 1.0).acos();
            analytic_sum += theta / std::f64::consts::PI;
            // Rotate the +z hemisphere onto the one around w (Rodrigues, axis z × w).
            let axis = [-w[1], w[0], 0.0];
            let s = (axis[0] * axis[0] + axis[1] * axis[1]).sqrt();
            let k = if s > 0.0 {
                [axis[0] / s, axis[1] / s, 0.0]
            } else {
                [1.0, 0.0, 0.0]
            };
            let c = w[2];
            for d in &sphere {
                let kd = k[0] * d[0] + k[1] * d[1];
                let kxd = [k[1] * d[2], -k[0] * d[2], k[0] * d[1] - k[1] * d[0]];
                let r: [f64; 3] =
                    std::array::from_fn(|j| d[j] * c + kxd[j] * s + k[j] * kd * (1.0 - c));
                if r[2] < 0.0 {
                    row_neg[px as usize] += 1;
                    inputs.push(r.map(|x| x as f32));
                }
            }
        }
        for &c in &row_neg {
            m.pixels += 1;
            frac_sum += c as f64 / sphere.len() as f64;
            m.pixels_with_negative_z += u64::from(c > 0);
        }
        if inputs.is_empty() {
            continue;
        }
        let codes = enc
            .run(&[Arg::column(&inputs)], inputs.len() as u64)?
            .into_words();
        let out = dec.run(&[Arg::column(&codes)], codes.len() as u64)?;
        for (i, v) in out.as_vec3().iter().enumerate() {
            neg_err.add(i as u64, angle_degrees(widen3(inputs[i]), widen3(*v)));
        }
    }
    let corner_theta = (2f64.sqrt() * t).atan();
    m.visible_fraction_negative_z = frac_sum / m.pixels as f64;
    m.visible_fraction_analytic = analytic_sum / m.pixels as f64;
    m.worst_error_deg = neg_err.max;
    m.mean_error_negative_deg = neg_err.mean();
    m.worst_error_analytic_deg = 2.0 * corner_theta.to_degrees();
    Ok(m)
}
