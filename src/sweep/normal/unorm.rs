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
    use crate::precision::inputs::unorm8_channel;
    forms(
        gpu,
        codec,
        (encode_unorm, decode_unorm),
        lanes,
        inputs,
        &|p, k| crate::depth24::unpack4x8unorm(p)[k],
        &|p, k, error, down| unorm8_channel((p >> (8 * k)) & 0xff, error, down),
    )
}

/// The check both forms share: channel `k` of code `p` is `exact(p, k)` when written, and
/// `perturbed(p, k, error, down)` when sampled under each of the recovery cases (channel `k`
/// pushed down by bit `k mod 3` of the code's sign pattern).
#[allow(clippy::type_complexity)]
fn forms(
    gpu: &Gpu,
    codec: &Codec,
    (encode_rt, decode_rt): (&str, &str),
    lanes: usize,
    inputs: &[[f32; 3]],
    exact: &dyn Fn(u32, usize) -> f32,
    perturbed: &dyn Fn(u32, usize, crate::precision::inputs::ChannelError, bool) -> f32,
) -> Result<UnormForms, HarnessError> {
    use crate::precision::inputs::sign_pattern;
    let n = inputs.len() as u64;
    let mut f = UnormForms::default();
    let channels = gpu
        .kernel(codec.source, encode_rt)?
        .run(&[Arg::column(inputs)], n)?
        .into_words();
    let codes: Vec<u32> = inputs
        .iter()
        .map(|v| (codec.twin_encode)(Vec3::from(*v)))
        .collect();
    f.encode = Mismatches::count(&channels, |k| exact(codes[k / lanes], k % lanes).to_bits());
    let want = gpu
        .kernel(codec.source, codec.decode)?
        .run(&[Arg::column(&codes)], n)?
        .into_words();
    let dec = gpu.kernel(codec.source, decode_rt)?;
    for (error, flip) in crate::sweep::depth24::RECOVERY_CASES {
        let c: Vec<f32> = codes
            .iter()
            .flat_map(|&p| {
                let signs = sign_pattern(p, flip);
                (0..lanes).map(move |k| perturbed(p, k, error, (signs >> (k % 3)) & 1 == 1))
            })
            .collect();
        let got = dec.run(&[Arg::column(&c)], n)?.into_words();
        f.decode.merge(Mismatches::count(&got, |k| want[k]), 0);
    }
    Ok(f)
}

/// A render-target format of a three-channel normal code (the fourth channel is the renderer's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderTarget {
    /// `rgb10a2unorm`: x, y, z in 10-bit fields (bits 0–29), channel `k/1023`; alpha zero.
    Rgb10a2Unorm,
    /// `rgba8snorm`: x, y, z as two's complement bytes 0–2, channel `b/127`; alpha zero.
    Rgba8Snorm,
    /// `rgb10a2unorm` holding O3DE's signed octahedron (`crate::normal::signed_oct`): R and G
    /// the 10-bit codes in bits 0–19, `k/1023`; B (1023 for z > 0, else 0) in bits 20–29: the
    /// word is the texel, so its fields are `Rgb10a2Unorm`'s; alpha zero.
    Rgb10a2SignedOct,
}

impl RenderTarget {
    /// The integer each of the first three channels holds, and the channel's scale.
    fn fields(self, p: u32) -> ([i32; 3], f64) {
        match self {
            Self::Rgb10a2Unorm => (crate::normal::xyz10::fields(p).map(|k| k as i32), 1023.0),
            Self::Rgba8Snorm => (crate::normal::snorm8::bytes(p), 127.0),
            // The word is the texel: B (1023 or 0) in bits 20–29.
            Self::Rgb10a2SignedOct => (crate::normal::xyz10::fields(p).map(|k| k as i32), 1023.0),
        }
    }

    /// The channels a conforming write of code `p`'s form stores and a sampler returns exactly:
    /// `field/scale` (correctly rounded), alpha 0.
    pub fn channels(self, p: u32) -> [f32; 4] {
        let (f, s) = self.fields(p);
        [
            (f64::from(f[0]) / s) as f32,
            (f64::from(f[1]) / s) as f32,
            (f64::from(f[2]) / s) as f32,
            0.0,
        ]
    }

    /// Channel `lane` (0–2) of code `p` as a sampler might return it under `error` (a few ULPs,
    /// or an offset in steps of this format), pushed down when `down`.
    pub fn perturbed(
        self,
        p: u32,
        lane: usize,
        error: crate::precision::inputs::ChannelError,
        down: bool,
    ) -> f32 {
        use crate::precision::inputs::ChannelError;
        let (f, s) = self.fields(p);
        let exact = self.channels(p)[lane];
        match error {
            ChannelError::Exact => exact,
            ChannelError::Ulps(u) => crate::precision::metrics::step_ulps(
                exact,
                if down { -i64::from(u) } else { i64::from(u) },
            ),
            ChannelError::Offset(o) => {
                let o = if down { -o } else { o };
                ((f64::from(f[lane]) + o) / s) as f32
            }
        }
    }
}

/// [`unorm_forms`] for the formats of [`RenderTarget`]: `encode_rt(n) -> vec4<f32>` must write
/// exactly [`RenderTarget::channels`] of the Rust encoder's code, and `decode_rt(c: vec4<f32>)`
/// must return the code path's decode bit for bit from exact channels, channels moved 3 ULPs and
/// channels moved 0.45 of a step, each both ways.
pub fn render_target_forms(
    gpu: &Gpu,
    codec: &Codec,
    encode_rt: &str,
    decode_rt: &str,
    target: RenderTarget,
    inputs: &[[f32; 3]],
) -> Result<UnormForms, HarnessError> {
    forms(
        gpu,
        codec,
        (encode_rt, decode_rt),
        4,
        inputs,
        &|p, k| target.channels(p)[k],
        // The fourth channel is the renderer's: anything.
        &|p, k, error, down| {
            if k == 3 {
                0.5
            } else {
                target.perturbed(p, k, error, down)
            }
        },
    )
}
