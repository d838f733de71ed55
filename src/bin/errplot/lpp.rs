//! Light pre-pass specular reconstruction (`wgsl/lpp.wgsl`): Engel's `N·H^n` recovered
//! from the light buffer is exact for one light and an approximation for several; measured.

use crate::ctx::{Ctx, NEEDS_ADAPTER, num};
use prepass::sweep::lpp::multi_light_reconstruction;
use std::fmt::Write as _;

/// Light counts measured.
const LIGHTS: [usize; 5] = [1, 2, 4, 16, 64];

/// The table and its CSV.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    let pixels = if ctx.opts.quick() { 512 } else { 4096 };
    ctx.line("## Light pre-pass: specular reconstructed from the light buffer");
    ctx.line("");
    let Some(g) = ctx.gpu() else {
        ctx.line(format!(
            "P and the reconstruction run in WGSL: {NEEDS_ADAPTER}."
        ));
        ctx.line("");
        return Ok(());
    };
    let measured = LIGHTS
        .into_iter()
        .enumerate()
        .map(|(k, lights)| multi_light_reconstruction(g, lights, pixels, 0x5eed + k as u64))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    ctx.line(format!(
        "{pixels} random pixels (normal, view) per row, each lit by the given number of random \
         lights: P (`lpp_blinn_phong_light`) on the adapter per light, summed in f32 as additive \
         blending does, then `lpp_reconstruct_specular` against the exact sum of per-light \
         Blinn-Phong terms with exponent n·m (f64). The reconstruction is exact for one light and \
         an approximation for more. Data: `lpp_reconstruction.csv`."
    ));
    ctx.line("");
    ctx.line("| lights | max relative error | mean | RMS | max abs error / diffuse luminance | non-finite |");
    ctx.line("|---|---|---|---|---|---|");
    let mut csv = String::from(
        "lights,pixels,max_relative,mean_relative,rms_relative,max_abs_over_diffuse,non_finite\n",
    );
    for m in &measured {
        let lights = m.lights;
        ctx.line(format!(
            "| {lights} | {} | {} | {} | {} | {} |",
            num(m.relative.max),
            num(m.relative.mean()),
            num(m.relative.rms()),
            num(m.absolute_vs_diffuse.max),
            m.non_finite
        ));
        let _ = writeln!(
            csv,
            "{lights},{pixels},{},{},{},{},{}",
            m.relative.max,
            m.relative.mean(),
            m.relative.rms(),
            m.absolute_vs_diffuse.max,
            m.non_finite
        );
    }
    ctx.line("");
    ctx.csv("lpp_reconstruction.csv", &csv)
}
