//! Running an emulated module on the adapter (feature `harness`).

use super::search::{DirectionTable, TABLE_MODE};
use super::{Emulated, Emulation, Policy, emulate};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output, Signature};

/// The `var<private>` an emulated evaluation sets to 1 when one of its operations leaves the
/// spec's domain (`core.wgsl`).
pub const UNDEFINED_FLAG: &str = "prepass_cf_undefined";

/// The table slots an evaluation under [`Policy::Searched`] read, as eight `u32` expressions
/// (`core.wgsl`'s `prepass_cf_touched`, in [`DirectionTable`]'s word order).
fn touched_words() -> Vec<String> {
    (0..8)
        .map(|k| format!("prepass_cf_touched[{k}u]"))
        .collect()
}

/// Up to this many elements (32 bytes each: 32 MiB), [`Policy::Upper`], [`Policy::Lower`] and
/// [`Policy::Seeded`] pass their fixed table as per-element columns, as the search
/// ([`super::search::climb`]) passes its tables, rather than as uniforms: the pipeline is
/// specialised to its arguments' feeds, and a suite that runs the policies and then searches the
/// same function compiles it once, not twice (on lavapipe an emulated lighting function takes
/// about 20 s to compile cold). Larger runs take the uniforms.
pub const FIXED_TABLE_AS_COLUMNS: u64 = 1 << 20;

/// A function of an emulated module, ready to run, with its "not defined by the spec" flag.
///
/// One pipeline per function for every policy but the identity: the flag is a tail word of the
/// values' own pipeline ([`Gpu::kernel_with_tail`]; the search's slot mask, of a second one
/// built only when asked for). [`Policy::Upper`], [`Policy::Lower`] and [`Policy::Seeded`] run
/// the [`Policy::Searched`] module with the table [`DirectionTable::UPPER`] or
/// [`DirectionTable::LOWER`] (per-element columns, as the search's tables, up to
/// [`FIXED_TABLE_AS_COLUMNS`] elements; uniforms beyond), or the seeded mode
/// ([`super::search::seeded_mode`]): the policies' own results (`tests/conforming.rs` checks
/// it), from the pipeline the search of the same function runs.
pub struct EmulatedKernel<'g> {
    /// The emulated module (under [`Policy::Upper`], [`Policy::Lower`] and [`Policy::Seeded`],
    /// the searched one).
    pub emulated: Emulated,
    policy: Policy,
    kernel: Kernel<'g>,
    /// Under Searched: the same wrapper with the slot mask in its tail too, compiled only if
    /// [`EmulatedKernel::touched`] runs (reading the mask keeps its bookkeeping alive, which
    /// costs the compiler more; the values' pipeline lets it fall away).
    masks: Option<Kernel<'g>>,
    /// The signature callers pass arguments for (a fixed table's two parameters removed).
    signature: Signature,
    /// Under Upper, Lower and Seeded: the table and the mode appended to every run.
    fixed: Option<(DirectionTable, [u32; 4])>,
}

impl<'g> EmulatedKernel<'g> {
    /// Emulate `source` as `emulation` says and prepare `function` on `gpu`.
    pub fn new(
        gpu: &'g Gpu,
        source: &str,
        function: &str,
        emulation: &Emulation,
    ) -> Result<Self, HarnessError> {
        let shader = |e: super::EmulateError| HarnessError::Shader(e.to_string());
        let fixed = match emulation.policy {
            Policy::Upper => Some((DirectionTable::UPPER, TABLE_MODE)),
            Policy::Lower => Some((DirectionTable::LOWER, TABLE_MODE)),
            Policy::Seeded(seed) => Some((DirectionTable::UPPER, super::search::seeded_mode(seed))),
            _ => None,
        };
        let mut tail = vec![UNDEFINED_FLAG.to_string()];
        if fixed.is_some() || emulation.policy == Policy::Searched {
            let searched = Emulation {
                policy: Policy::Searched,
                ..*emulation
            };
            let emulated = emulate(source, &searched).map_err(shader)?;
            if let Some((wrapper, _)) = emulated.table_functions(function) {
                // A searched kernel given one table (`DirectionTable::args`) is the very
                // pipeline Upper and Lower use.
                let kernel = gpu.kernel_with_tail(&emulated.source, wrapper, &tail)?;
                tail.extend(touched_words());
                let masks = Some(gpu.kernel_with_tail(&emulated.source, wrapper, &tail)?);
                let mut signature = kernel.signature().clone();
                if fixed.is_some() {
                    signature.params.truncate(signature.params.len() - 3);
                }
                return Ok(EmulatedKernel {
                    emulated,
                    policy: emulation.policy,
                    kernel,
                    masks,
                    signature,
                    fixed,
                });
            }
            if fixed.is_none() {
                return Err(HarnessError::Shader(format!(
                    "`{function}` has no table wrapper (no result, or parameters it cannot spell)"
                )));
            }
        }
        // Identity, Seeded, and Upper/Lower where no table wrapper exists: the policy's module.
        let emulated = emulate(source, emulation).map_err(shader)?;
        let name = emulated.function_name(function).ok_or_else(|| {
            HarnessError::Shader(format!("the module has no function `{function}`"))
        })?;
        let kernel = gpu.kernel_with_tail(&emulated.source, name, &tail)?;
        Ok(EmulatedKernel {
            signature: kernel.signature().clone(),
            emulated,
            policy: emulation.policy,
            kernel,
            masks: None,
            fixed: None,
        })
    }

    /// The policy this kernel evaluates.
    pub fn policy(&self) -> Policy {
        self.policy
    }

    /// The parameters [`EmulatedKernel::run`] takes: the function's, and under
    /// [`Policy::Searched`] the direction table's two halves and the mode after them.
    pub fn signature(&self) -> &Signature {
        &self.signature
    }

    /// Values, tail words (flag first), for `args` with a fixed table appended: as columns up
    /// to [`FIXED_TABLE_AS_COLUMNS`] elements, the feed the search gives its tables, so that
    /// the policies' runs and a search of the same function share one compiled pipeline.
    fn run_tail(&self, args: &[Arg<'_>], n: u64) -> Result<(Output, Vec<u32>), HarnessError> {
        let Some((table, mode)) = self.fixed else {
            return self.kernel.run_with_tail(args, n);
        };
        let [h0, h1] = table.halves();
        let columns = n <= FIXED_TABLE_AS_COLUMNS;
        let (c0, c1) = if columns {
            (vec![h0; n as usize], vec![h1; n as usize])
        } else {
            (Vec::new(), Vec::new())
        };
        let mut all = args.to_vec();
        if columns {
            all.extend([Arg::column(&c0), Arg::column(&c1)]);
        } else {
            all.extend([Arg::Splat(h0), Arg::Splat(h1)]);
        }
        all.push(Arg::Splat(mode));
        self.kernel.run_with_tail(&all, n)
    }

    /// Under [`Policy::Searched`]: per element, the mask of the direction-table slots
    /// its evaluation read (arguments as for [`EmulatedKernel::run`]).
    pub fn touched(&self, args: &[Arg<'_>], n: u64) -> Result<Vec<DirectionTable>, HarnessError> {
        let masks = match (&self.masks, self.policy) {
            (Some(m), Policy::Searched) => m,
            _ => {
                return Err(HarnessError::Shader(
                    "slot masks exist under Policy::Searched only".into(),
                ));
            }
        };
        let (_, tail) = masks.run_with_tail(args, n)?;
        Ok(tail
            .chunks_exact(9)
            .map(|e| DirectionTable(std::array::from_fn(|k| e[1 + k])))
            .collect())
    }

    /// Run `n` elements: the results, and per element whether an operation of its evaluation
    /// left the spec's domain (its result is then not defined by the spec). Under
    /// [`Policy::Searched`] the last three arguments are the direction table's halves and the
    /// mode ([`DirectionTable::args`], or columns of tables and [`super::search::TABLE_MODE`]).
    pub fn run(&self, args: &[Arg<'_>], n: u64) -> Result<(Output, Vec<bool>), HarnessError> {
        let (out, tail) = self.run_tail(args, n)?;
        let stride = self.kernel.tail_words();
        let flags = tail.chunks_exact(stride).map(|e| e[0] != 0).collect();
        Ok((out, flags))
    }
}
