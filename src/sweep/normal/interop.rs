//! The engines' own writes of a normal, for the interop checks: what a render target stores when
//! an engine's shader outputs its channel values and the format's conversion quantises them.

/// How far, in channel units, a unit f32 input and the encoder's re-normalised copy of it can
/// put a channel apart: the input's length is within `2^-24` of 1 (each component correctly
/// rounded from an f64 unit vector), the encoder's `dot` adds 1.5 ULP to the squared length
/// (0.75 to the length), `sqrt` and the quotient 0.5 each, so `u` is within `2.75·2^-24` of `n`
/// per unit of length; the unorm forms' `·0.5 + 0.5` halves that and each side rounds its add by
/// at most `2^-25`. Bounded above by `4·2^-24` for both the unorm and the snorm channel.
pub const RENORMALISE_CHANNEL: f64 = 4.0 / 16_777_216.0;

/// The integer each of x, y, z holds when an engine writes the f32 channel values `c` (already
/// computed in f32, e.g. `n·0.5 + 0.5`) to a render target whose conversion is
/// `round(scale·clamp(c))`, with `None` in a lane whose exact `scale·c` lies within
/// `scale·`[`RENORMALISE_CHANNEL`] of a tie (`k + 1/2`): there, a format may round either way
/// and a re-normalised input may land on the other side.
pub fn engine_write(c: [f32; 3], scale: f64, signed: bool) -> [Option<i64>; 3] {
    let lo = if signed { -1.0 } else { 0.0 };
    c.map(|x| {
        let v = f64::from(x).clamp(lo, 1.0) * scale;
        let frac = v - v.floor();
        ((frac - 0.5).abs() > scale * RENORMALISE_CHANNEL).then(|| v.round() as i64)
    })
}
