//! Sweeps for the light pre-pass maths (`wgsl/lpp.wgsl`): Engel's specular reconstruction
//! against per-light Blinn-Phong for 1–64 random lights, run on the adapter.

use crate::harness::{Arg, Gpu, HarnessError};
use crate::lighting::lpp::exact;
use crate::precision::metrics::{ErrorStats, relative_error};
use crate::sweep::SplitMix;

/// The error of the one-buffer reconstruction for one light count.
#[derive(Clone, Debug, Default)]
pub struct MultiLight {
    /// Lights per pixel.
    pub lights: usize,
    /// Pixels measured.
    pub pixels: usize,
    /// Relative error of `lpp_reconstruct_specular` against per-light Blinn-Phong with exponent
    /// `n_i·m` (f64), over pixels whose exact specular is at least `1e-6` of their diffuse
    /// luminance (elsewhere both are negligible).
    pub relative: ErrorStats,
    /// Absolute error in units of the pixel's diffuse luminance `Σ N·L·att·lum(c)` (all pixels).
    pub absolute_vs_diffuse: ErrorStats,
    /// Pixels whose accumulated ratio `a/lum(rgb)` exceeded 1 before the exponent (clamped).
    pub ratio_above_one: usize,
    /// Non-finite reconstructed values (must be 0).
    pub non_finite: usize,
}

/// Run `lights` random lights (random white-to-coloured colours, attenuation in (0, 1], light
/// exponent `n ∈ [4, 64]`, material exponent `m ∈ [1, 8]`) over `pixels` random normals and
/// views: P on the adapter per light, summed in f32 as fp32 additive blending would, then the
/// reconstruction on the adapter, against the exact per-light Blinn-Phong (f64).
pub fn multi_light_reconstruction(
    gpu: &Gpu,
    lights: usize,
    pixels: usize,
    seed: u64,
) -> Result<MultiLight, HarnessError> {
    let src = crate::wgsl::LPP;
    let p_kernel = gpu.kernel(src, "lpp_blinn_phong_light")?;
    let c_kernel = gpu.kernel(src, "lpp_reconstruct_specular")?;
    let mut rng = SplitMix(seed);
    let normals: Vec<[f32; 3]> = (0..pixels).map(|_| rng.hemisphere(0.2)).collect();
    let eyes: Vec<[f32; 3]> = (0..pixels).map(|_| rng.hemisphere(0.1)).collect();
    let material: Vec<f32> = (0..pixels).map(|_| rng.range(1.0, 8.0).round()).collect();
    let mut sum = vec![[0.0f32; 4]; pixels];
    // (to_light, lum(colour), att, n) per pixel per light, for the exact reference.
    let mut per_pixel: Vec<Vec<exact::Light>> = vec![Vec::new(); pixels];
    for _ in 0..lights {
        let to_light: Vec<[f32; 3]> = (0..pixels).map(|_| rng.hemisphere(-0.3)).collect();
        let colour: Vec<[f32; 3]> = (0..pixels)
            .map(|_| {
                let w = rng.range(0.2, 1.0);
                [w * rng.range(0.5, 1.0), w * rng.range(0.5, 1.0), w]
            })
            .collect();
        let att: Vec<f32> = (0..pixels).map(|_| rng.range(0.05, 1.0)).collect();
        let n: Vec<f32> = (0..pixels).map(|_| rng.range(4.0, 64.0).round()).collect();
        let out = p_kernel.run(
            &[
                Arg::column(&normals),
                Arg::column(&eyes),
                Arg::column(&to_light),
                Arg::column(&colour),
                Arg::column(&att),
                Arg::column(&n),
            ],
            pixels as u64,
        )?;
        for (i, v) in out.as_vec4().iter().enumerate() {
            for k in 0..4 {
                sum[i][k] += v[k];
            }
            let c = colour[i].map(f64::from);
            let lum = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            per_pixel[i].push((
                to_light[i].map(f64::from),
                lum,
                f64::from(att[i]),
                f64::from(n[i]),
            ));
        }
    }
    let rec = c_kernel.run(&[Arg::column(&sum), Arg::column(&material)], pixels as u64)?;
    let mut r = MultiLight {
        lights,
        pixels,
        ..Default::default()
    };
    for (i, &got) in rec.as_f32().iter().enumerate() {
        if !got.is_finite() {
            r.non_finite += 1;
            continue;
        }
        let normal = normals[i].map(f64::from);
        let eye = eyes[i].map(f64::from);
        let want = exact::multi_light_specular(normal, eye, &per_pixel[i], f64::from(material[i]));
        let diffuse_lum: f64 = per_pixel[i]
            .iter()
            .map(|&(l, lum, att, _)| exact::lpp_cosines(normal, eye, l).0 * att * lum)
            .sum();
        let s = sum[i];
        let lum = 0.2126 * s[0] + 0.7152 * s[1] + 0.0722 * s[2];
        if s[3] > lum {
            r.ratio_above_one += 1;
        }
        if diffuse_lum > 0.0 {
            r.absolute_vs_diffuse
                .add(i as u64, (f64::from(got) - want).abs() / diffuse_lum);
            if want >= 1e-6 * diffuse_lum {
                r.relative
                    .add(i as u64, relative_error(f64::from(got), want));
            }
        }
    }
    Ok(r)
}
