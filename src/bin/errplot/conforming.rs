//! Beside each adapter figure, the worst conforming adapter's (`prepass::conforming`, the same
//! inputs under the upper, lower and seeded policies) and the derived bound that holds on every
//! conforming adapter.

use crate::ctx::{Ctx, NEEDS_ADAPTER, num};
use prepass::conforming::Policy;
use prepass::sweep::conforming::{
    MachineBound, SEARCHED_INPUTS, SEARCHED_NORMAL_INPUTS, linear_depth_figures_with,
    normal_figures,
};
use prepass::sweep::normal::{CODECS, Codec, adversarial_directions, fibonacci_directions};

/// The codecs the quick and default runs emulate (`--full`: all of them): one per kind of
/// encoder (rounding xyz, FP16 halves, the precise octahedral choice, RGB10A2's linear xyz,
/// snorm, the best-fit search). Each emulated codec is modules for lavapipe to compile, 8 to
/// 12 s for each precise octahedral one (oct16, oct20, oct32, Substrate's and the signed
/// octahedron's share oct24's choice or the hemi-octahedral one), and this section was the quick
/// report's longest (65 s of 110 s with every codec but the `_fast` and hemi-octahedral ones;
/// 2-core Xeon, 2026-12-06). The default run emulates these too: every codec, under one policy
/// at 2^14 directions, took over 6 minutes there (cold Mesa 25 shader cache, 2 cores).
const KIND_CODECS: [&str; 6] = [
    "xyz8",
    "xy fp16",
    "oct24",
    "xyz10",
    "snorm8",
    "xyz8 best-fit",
];

/// The codecs the quick run emulates: `KIND_CODECS`' rounding constructions, with oct24's
/// `_fast` encoder (and its decoder, the same as the precise one's) for the octahedral kind. The
/// precise choice's and the best-fit search's emulated modules are the longest for lavapipe to
/// compile (`PREPASS_LOG_COMPILES=1`: the precise oct24 encoder's about half of this section's
/// compile time in a quick run), so the smoke run leaves them to the default and full runs and
/// `tests/conforming.rs`, which emulate both.
const QUICK_CODECS: [&str; 5] = ["xyz8", "xy fp16", "oct24 fast", "xyz10", "snorm8"];

/// Fibonacci directions the default tier's normal round trips run at, on the adapter and
/// emulated: a sample of the full run's 2^18 (plus its adversarial directions), since each
/// emulated direction is a long kernel on a CPU adapter.
const DEFAULT_DIRECTIONS: u32 = 1 << 14;

/// The section: linear depth and normal encodings, adapter beside emulation beside bound.
pub fn section(ctx: &mut Ctx) -> Result<(), String> {
    ctx.line("## On every conforming adapter");
    ctx.line("");
    ctx.line(
        "WGSL lets an adapter round `+ − ×` to either neighbour, err 2.5 ULP on `/`, flush \
         subnormals, fuse and reassociate. Each figure below is measured on this adapter and on \
         the same adapter emulating the worst conforming one (`prepass::conforming`: every free \
         operation at the upper end, the lower end, or a seeded choice of both), beside the \
         bound derived from the WGSL accuracy table.",
    );
    ctx.line("");
    let Some(gpu) = ctx.gpu() else {
        ctx.line(format!("({NEEDS_ADAPTER})"));
        ctx.line("");
        return Ok(());
    };
    let (quick, full) = (ctx.opts.quick(), ctx.opts.full());
    // What each tier emulates. The default emulates KIND_CODECS (compiling each codec's
    // emulated modules is most of this section) and cuts what multiplies the emulated
    // execution: linear depth under the upper and lower policies (each free operation at either end; the seeded mixes are `--full`'s) with 8 searched
    // inputs; the normal encodings at DEFAULT_DIRECTIONS Fibonacci directions under the upper
    // policy, not searched (`--full`: 2^18 plus the adversarial set, three policies, searched).
    let policies = ctx.opts.pick::<&[Policy]>(
        &[Policy::Upper, Policy::Seeded(1)],
        &[Policy::Upper, Policy::Lower],
        &Policy::WORST,
    );
    let searched = ctx.opts.pick(8, 8, SEARCHED_INPUTS);
    let mut inputs = fibonacci_directions(ctx.opts.pick(1 << 12, DEFAULT_DIRECTIONS, 1 << 18));
    if full {
        inputs.extend(adversarial_directions());
    }
    let normal_policies: &[Policy] = if full {
        &[Policy::Upper, Policy::Lower, Policy::Seeded(1)]
    } else {
        &[Policy::Upper]
    };
    // The round-trip search compiles one more emulated module per codec: `--full` only.
    let normal_searched = if full { SEARCHED_NORMAL_INPUTS } else { 0 };
    let emulated: &[&str] = if quick { &QUICK_CODECS } else { &KIND_CODECS };
    let codecs: Vec<Codec> = CODECS
        .into_iter()
        .filter(|c| full || emulated.contains(&c.name))
        .collect();
    // The two families on two threads: most of each is the driver compiling emulated modules,
    // one thread per module, and this section is the report's longest.
    let (linear, normals) = std::thread::scope(|s| {
        // The report shows no machine-derived bound (tests/linear_depth.rs derives and
        // publishes it): not derived here.
        let linear =
            s.spawn(|| linear_depth_figures_with(gpu, policies, searched, MachineBound::Skip));
        let normals = normal_figures(gpu, &codecs, &inputs, normal_policies, normal_searched);
        (
            linear.join().expect("the linear-depth figures' thread"),
            normals,
        )
    });
    let (linear, normals) = (
        linear.map_err(|e| e.to_string())?,
        normals.map_err(|e| e.to_string())?,
    );
    let names: Vec<String> = policies.iter().map(Policy::to_string).collect();
    ctx.line(format!(
        "Linear depth over the stiff grid, sampled (`sweep::linear_depth::sampled_worst`); \
         emulated: {}.",
        names.join(", ")
    ));
    ctx.line("");
    ctx.line(format!(
        "Searched: `conforming::search` at the {searched} inputs the policies erred most on{}.",
        if full {
            ""
        } else {
            " (`--full`: all five policies, 32 inputs searched)"
        }
    ));
    ctx.line("");
    ctx.line("| function | max ULP (adapter) | max ULP (worst emulated) | max ULP (searched) | bound, correctly rounded | bound, conforming |");
    ctx.line("|---|---|---|---|---|---|");
    let mut csv = String::from(
        "family,variant,adapter,worst_emulated,bound_correctly_rounded,bound_conforming\n",
    );
    for r in &linear {
        ctx.line(format!(
            "| `{}` | {} | {} | {} | {} | {} |",
            r.function,
            num(r.adapter),
            num(r.emulated),
            num(r.searched),
            num(r.bound_correctly_rounded),
            num(r.bound_conforming)
        ));
        csv.push_str(&format!(
            "linear_depth_ulp,{},{},{},{},{}\n",
            r.function, r.adapter, r.emulated, r.bound_correctly_rounded, r.bound_conforming
        ));
    }
    ctx.line("");
    let names: Vec<String> = normal_policies.iter().map(Policy::to_string).collect();
    ctx.line(format!(
        "Normal encodings, round trip over {} directions (degrees); emulated: {}.",
        inputs.len(),
        names.join(", ")
    ));
    ctx.line("");
    if normal_searched > 0 {
        ctx.line(format!(
            "Searched: the round trip (encode, then decode, as one function) at the \
             {normal_searched} inputs the policies erred most on."
        ));
    } else if quick {
        ctx.line(
            "Quick run: not searched (—), and the rounding encoders only (`QUICK_CODECS`: no \
             precise octahedral choice, no best-fit search; the default run emulates one codec \
             of every kind, `tests/conforming.rs` every codec under every policy, searched).",
        );
    } else {
        ctx.line(format!(
            "Default run: one codec per kind of encoder (`KIND_CODECS`, {} of {}), {} of the \
             full run's 2^18 Fibonacci directions (and not its adversarial ones), the upper \
             policy only, not searched (—); `--full` for all (`tests/conforming.rs` measures \
             every codec under every policy, searched).",
            codecs.len(),
            CODECS.len(),
            inputs.len()
        ));
    }
    ctx.line("");
    ctx.line("| encoding | max° (adapter) | max° (worst emulated) | max° (searched) | mean° (adapter) | mean° (worst emulated) | codes ≠ twin (emulated) | max \\|len − 1\\| (emulated) |");
    ctx.line("|---|---|---|---|---|---|---|---|");
    for r in &normals {
        let worst = r.emulated_max.iter().copied().fold(0.0, f64::max);
        let searched = if r.searched_inputs > 0 {
            num(r.searched)
        } else {
            "—".to_string()
        };
        ctx.line(format!(
            "| {} | {} | {} | {searched} | {} | {} | {} | {} |",
            r.name,
            num(r.adapter.max),
            num(worst),
            num(r.adapter.mean()),
            num(r.emulated_mean),
            r.twin_changed,
            num(r.max_len_error)
        ));
        csv.push_str(&format!(
            "normal_round_trip_deg,{},{},{},,\n",
            r.name, r.adapter.max, worst
        ));
    }
    ctx.line("");
    ctx.line(format!(
        "Decodes are unit within the conforming budget {} (`sweep::conforming::UNIT_TOLERANCE_CONFORMING`).",
        num(prepass::sweep::conforming::UNIT_TOLERANCE_CONFORMING)
    ));
    ctx.line("");
    ctx.csv("conforming.csv", &csv)
}

#[cfg(test)]
mod tests {
    /// A misspelt name would drop its codec from quick and default runs without a word.
    #[test]
    fn kind_codecs_are_codecs() {
        for q in super::KIND_CODECS.into_iter().chain(super::QUICK_CODECS) {
            assert!(
                prepass::sweep::normal::CODECS.iter().any(|c| c.name == q),
                "KIND_CODECS or QUICK_CODECS names `{q}`, which is not in sweep::normal::CODECS"
            );
        }
    }
}
