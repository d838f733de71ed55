//! Output levels and image error: the tone curve that turns the linear frame into 8-bit
//! levels, max / mean error in those levels, PSNR, and the false-colour error image.

/// The tone curve, linear colour → display value in [0, 1]: Reinhard `c/(1 + c)` then a 1/2.2
/// gamma. Monotonic, so a bound on a linear colour interval maps to a bound on levels
/// ([`super::bound`] uses that). Negative and NaN input count as 0.
pub fn tonemap(c: f32) -> f64 {
    tonemap64(f64::from(c))
}

/// [`tonemap`] of an `f64`.
pub fn tonemap64(c: f64) -> f64 {
    let c = if c > 0.0 { c } else { 0.0 };
    if c.is_infinite() {
        return 1.0;
    }
    (c / (1.0 + c)).powf(1.0 / 2.2)
}

/// The 8-bit level of a linear colour: `round(255·tonemap(c))`.
pub fn level(c: f32) -> u8 {
    (255.0 * tonemap(c)).round() as u8
}

/// The frame in 8-bit levels (alpha dropped).
pub fn to_rgb8(colour: &[[f32; 4]]) -> Vec<[u8; 3]> {
    colour
        .iter()
        .map(|c| [level(c[0]), level(c[1]), level(c[2])])
        .collect()
}

/// Pixels with a NaN or infinite channel (the check of the test and of `--compare`).
pub fn non_finite(colour: &[[f32; 4]]) -> usize {
    colour
        .iter()
        .filter(|c| c.iter().any(|x| !x.is_finite()))
        .count()
}

/// Error of one image against the reference, in 8-bit output levels over every channel.
#[derive(Clone, Copy, Debug)]
pub struct ErrorStats {
    /// Largest absolute difference.
    pub max: u8,
    /// Mean absolute difference.
    pub mean: f64,
    /// Peak signal-to-noise ratio, `10·log10(255² / MSE)` dB (`+∞` for identical images).
    pub psnr: f64,
}

/// Max, mean and PSNR of `got` against `reference` (same size).
pub fn error_stats(reference: &[[u8; 3]], got: &[[u8; 3]]) -> ErrorStats {
    let (mut max, mut sum, mut sq) = (0u8, 0f64, 0f64);
    for (a, b) in reference.iter().zip(got) {
        for k in 0..3 {
            let e = a[k].abs_diff(b[k]);
            max = max.max(e);
            sum += f64::from(e);
            sq += f64::from(e) * f64::from(e);
        }
    }
    let n = (reference.len() * 3).max(1) as f64;
    let mse = sq / n;
    ErrorStats {
        max,
        mean: sum / n,
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (255.0 * 255.0 / mse).log10()
        },
    }
}

/// Levels of error at which the false-colour ramp reaches white.
pub const FALSE_COLOUR_TOP: f64 = 32.0;

/// The false-colour error image: each pixel's largest channel error `e` on a log ramp
/// black (0) → blue (≈1) → magenta (≈3) → orange (≈7) → yellow (≈15) → white (≥ 32 levels).
pub fn false_colour(reference: &[[u8; 3]], got: &[[u8; 3]]) -> Vec<[u8; 3]> {
    const STOPS: [[f64; 3]; 6] = [
        [0.0, 0.0, 0.0],
        [0.0, 0.2, 1.0],
        [0.85, 0.1, 0.85],
        [1.0, 0.5, 0.0],
        [1.0, 0.95, 0.0],
        [1.0, 1.0, 1.0],
    ];
    reference
        .iter()
        .zip(got)
        .map(|(a, b)| {
            let e = (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0);
            let t = ((1.0 + f64::from(e)).log2() / (1.0 + FALSE_COLOUR_TOP).log2()).min(1.0);
            let x = t * (STOPS.len() - 1) as f64;
            let i = (x.floor() as usize).min(STOPS.len() - 2);
            let f = x - i as f64;
            let c =
                |k: usize| (255.0 * (STOPS[i][k] * (1.0 - f) + STOPS[i + 1][k] * f)).round() as u8;
            [c(0), c(1), c(2)]
        })
        .collect()
}
