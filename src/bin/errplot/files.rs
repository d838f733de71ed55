//! The report's last section: every CSV file and its columns (the notebooks read these).

use crate::ctx::Ctx;

/// `(file, what one row is, columns)`. A section that writes a CSV adds its line here.
pub const CSV_FILES: &[(&str, &str, &str)] = &[
    (
        "depth_resolution.csv",
        "one distance for one depth format",
        "format (d24, d32f), convention (standard, reversed, reversed_infinite), near_m, far_m \
         (inf for the infinite projection), distance_m (view distance), resolution_m (distance \
         to the neighbouring stored value further away)",
    ),
    (
        "linear_depth_error.csv",
        "one distance bin of one linear-depth form",
        "form (stable, textbook), where (cpu or adapter), near_m, far_m, distance_m (bin \
         centre), max_relative_error (largest abs(z − z_exact)/z_exact of the codes in the bin)",
    ),
    (
        "linear_depth_grid.csv",
        "one depth path (D24 code, float standard, float reversed) at one stiff case",
        "path, near_m, far_over_near (inf = infinite projection), stable_max_ulp, \
         consts_max_ulp (f32 ULPs of the exact distance), stable_max_relative, \
         textbook_max_relative, b_over_z_minus_a_max_relative (inf: wrong-signed or infinite \
         result where the distance is finite)",
    ),
    (
        "depth24_recovery.csv",
        "one recovery function under one channel perturbation, all 2^24 codes",
        "function, channel_error, flip (sign pattern complemented), codes, mismatches (codes \
         not recovered exactly; empty without an adapter), max_code_error (codes)",
    ),
    (
        "depth24_hyperbolic.csv",
        "one formulation of d/(2^24−1), all 2^24 codes",
        "function, where (adapter or Rust twin), max_ulp, mean_ulp, rms_ulp (f32 ULPs against \
         the exact quotient), exact_roundtrip_failures, f32_roundtrip_failures, collisions",
    ),
    (
        "normal_error.csv",
        "one normal encoding over the Fibonacci directions",
        "encoding, bits, directions (counted: z ≥ 0 only for xy_fp16 and hemi-octahedral), \
         where (adapter or Rust twins), mean_deg, max_deg, rms_deg (angle between input and \
         decoded vector)",
    ),
    (
        "roughness_error.csv",
        "one 1/16-octave bin of specular powers for one 8-bit storage",
        "storage (log range, linear, affine), max_power, power_bin_start (lower edge of the bin), \
         max_relative_error, mean_relative_error (of decode(encode(p)) against p, every f32 \
         power in the bin)",
    ),
    (
        "roughness_ggx_error.csv",
        "one GGX roughness form over one engine's clamped range",
        "range (the engine whose clamp on r it is), form (linear r, Godot 7 bits + flag, log r), \
         r_min, max_relative_lobe_error, mean, rms (the worst relative error of the GGX lobe \
         D(n·h, α) over every n·h, for every f32 r in [r_min, 1], through the Rust twins)",
    ),
    (
        "lpp_reconstruction.csv",
        "one light count of the light pre-pass specular reconstruction",
        "lights, pixels, max_relative, mean_relative, rms_relative (against the exact per-light \
         Blinn-Phong sum), max_abs_over_diffuse (absolute error in units of the pixel's diffuse \
         luminance), non_finite (must be 0)",
    ),
    (
        "error_vs_cost.csv",
        "one encoding variant",
        "family, variant, bits (stored per value), unit (of the error columns), max_error, \
         mean_error, rms_error (empty when they need an adapter), error_measured (where, over \
         what), gpu_ns_per_eval (net of the empty-kernel baseline), gpu_gross_ns_per_eval, \
         gpu_timing_method (the three empty without an adapter, and on a software adapter \
         unless `--full`, which alone times there), cpu_ns_per_call (Rust twin, net of an empty loop), \
         spirv_instructions (naga SPIR-V, callees included), peer (true for a baseline from \
         another project, `tests/baselines/peer_*.wgsl`; its variant starts with `peer:`), then \
         per target chip (polaris10, vega10, navi21, navi31, skl, tgl, dg2, lnl) \
         CHIP_instructions, CHIP_alu, CHIP_latency (ACO), CHIP_inverse_throughput (ACO), \
         CHIP_cycles (brw): net per evaluation, static compiler estimates (`prepass::isa`)",
    ),
];

/// The table of files and columns.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    ctx.line("## Files");
    ctx.line("");
    ctx.line("| file | one row is | columns |");
    ctx.line("|---|---|---|");
    for (file, row, columns) in CSV_FILES {
        ctx.line(format!("| [`{file}`]({file}) | {row} | {columns} |"));
    }
    ctx.line("");
    Ok(())
}
