//! The render-target (unorm channel) forms of an encoding, checked against its code path.

use super::codecs::Codec;
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::Mismatches;
use glam::Vec3;

/// Checks of one encoding's render-target (unorm channel) form.
#[derive(Clone, Debug, Default)]
pub struct UnormForms {
    /// Channels from the WGSL `encode_*_unorm` that differ (bits) from `unpack4x8unorm` of the
    /// Rust encoder's code.
    pub encode: Mismatches<u32>,
    /// Decodes of perturbed channels (exact, ±3 ULP, ±0.45/255, each both ways) whose bits differ
    /// from the WGSL decoder's result for the code itself.
    pub decode: Mismatches<u32>,
}

/// Check `encode_unorm(n) -> vecL<f32>` and `decode_unorm(c: vecL<f32>) -> vec3<f32>` (L = 2 or 4
/// channels) of `codec` against its code path over `inputs`.
pub fn unorm_forms(
    gpu: &Gpu,
    codec: &Codec,
    encode_unorm: &str,
    decode_unorm: &str,
    lanes: usize,
    inputs: &[[f32; 3]],
) -> Result<UnormForms, HarnessError> {
    use crate::precision::inputs::{sign_pattern, unorm8_channel};
    let n = inputs.len() as u64;
    let mut f = UnormForms::default();
    let channels = gpu
        .kernel(codec.source, encode_unorm)?
        .run(&[Arg::column(inputs)], n)?
        .into_words();
    let codes: Vec<u32> = inputs
        .iter()
        .map(|v| (codec.twin_encode)(Vec3::from(*v)))
        .collect();
    f.encode = Mismatches::count(&channels, |k| {
        crate::depth24::unpack4x8unorm(codes[k / lanes])[k % lanes].to_bits()
    });
    let want = gpu
        .kernel(codec.source, codec.decode)?
        .run(&[Arg::column(&codes)], n)?
        .into_words();
    let dec = gpu.kernel(codec.source, decode_unorm)?;
    for (error, flip) in crate::sweep::depth24::RECOVERY_CASES {
        let c: Vec<f32> = codes
            .iter()
            .flat_map(|&p| {
                let signs = sign_pattern(p, flip);
                (0..lanes).map(move |k| {
                    unorm8_channel((p >> (8 * k)) & 0xff, error, (signs >> (k % 3)) & 1 == 1)
                })
            })
            .collect();
        let got = dec.run(&[Arg::column(&c)], n)?.into_words();
        f.decode.merge(Mismatches::count(&got, |k| want[k]), 0);
    }
    Ok(f)
}
