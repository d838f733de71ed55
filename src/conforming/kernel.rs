//! Running an emulated module on the adapter (feature `harness`).

use super::search::{DirectionTable, TABLE_MODE};
use super::{Emulated, Emulation, Policy, emulate};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output, Signature};

/// The `var<private>` an emulated evaluation sets to 1 when one of its operations leaves the
/// spec's domain (`core.wgsl`).
pub const UNDEFINED_FLAG: &str = "prepass_cf_undefined";

/// The table slots an evaluation under [`Policy::Searched`] read, as eight `u32` expressions
/// (`core.wgsl`'s `prepass_cf_touched_lo` and `_hi`, in [`DirectionTable`]'s word order).
fn touched_words() -> Vec<String> {
    ["lo", "hi"]
        .into_iter()
        .flat_map(|h| ["x", "y", "z", "w"].map(|c| format!("prepass_cf_touched_{h}.{c}")))
        .collect()
}

/// [`Policy::Upper`], [`Policy::Lower`] and [`Policy::Seeded`] pass their fixed table as
/// per-element columns, as the search ([`super::search::climb`]) passes its tables, rather than
/// as uniforms: the pipeline is specialised to its arguments' feeds, and a suite that runs the
/// policies and then searches the same function compiles it once, not twice (on lavapipe an
/// emulated lighting function takes about 20 s to compile cold). Runs of more elements go in
/// slices of this many (the table columns: 32 bytes per element, 32 MiB), through the same
/// pipeline.
pub const FIXED_TABLE_AS_COLUMNS: u64 = 1 << 20;

/// A function of an emulated module, ready to run, with its "not defined by the spec" flag.
///
/// One pipeline per function for every policy but the identity: the flag is a tail word of the
/// values' own pipeline ([`Gpu::kernel_with_tail`]), and under the table wrappers so are the
/// direction-table slots the evaluation read, which the search asks for once per climb.
/// [`Policy::Upper`], [`Policy::Lower`] and [`Policy::Seeded`] run the [`Policy::Searched`]
/// module with the table [`DirectionTable::UPPER`] or [`DirectionTable::LOWER`] (per-element
/// columns, as the search's tables, in slices of [`FIXED_TABLE_AS_COLUMNS`] elements), or the
/// seeded mode ([`super::search::seeded_mode`]): the policies' own results
/// (`tests/conforming.rs` checks it), from the pipeline the search of the same function runs.
///
/// Why the slot words ride on every run rather than on a second pipeline built for the search:
/// the two compile alike (measured on lavapipe, cold, LLVM passes off, 2026-12-05: the
/// oct16 round trip 6.15 s with the slot words, 6.17 s without; `lpp_spot_light` 8.62 and
/// 8.65 s), so a search paid for a whole second compile, while keeping the bookkeeping alive
/// costs each run little (2^18 oct16 round trips 0.62 s against 0.59 s; xyz8 0.23 against
/// 0.21 s).
pub struct EmulatedKernel<'g> {
    /// The emulated module (under [`Policy::Upper`], [`Policy::Lower`] and [`Policy::Seeded`],
    /// the searched one).
    pub emulated: Emulated,
    policy: Policy,
    /// Values, then the flag, then under the table wrappers the eight slot-mask words.
    kernel: Kernel<'g>,
    /// The signature callers pass arguments for (a fixed table's two parameters removed).
    signature: Signature,
    /// Under Upper, Lower and Seeded: the table and the mode appended to every run.
    fixed: Option<(DirectionTable, [u32; 4])>,
}

impl<'g> EmulatedKernel<'g> {
    /// Emulate `source` as `emulation` says and prepare `function` on `gpu`.
    ///
    /// Refuses a host it cannot trust: under every policy but [`Policy::Identity`] it first
    /// runs [`super::check_host`] on `gpu` (once per adapter and process, the verdict kept) and
    /// returns its [`HarnessError::UnfitHost`], naming the helper and input that came back
    /// wrong, where the emulation's error-free transformations as the adapter compiles them
    /// do not give what `+ − ×` rounded to nearest give (a host that contracts, reassociates
    /// or flushes there). Those transformations (TwoSum, Dekker's product, the fused `a·b + c`
    /// built from them) place every result the emulation chooses; where they are wrong its
    /// results could leave the spec's intervals unnoticed. The identity policy evaluates the
    /// original operations, needs none of that, and skips the check.
    pub fn new(
        gpu: &'g Gpu,
        source: &str,
        function: &str,
        emulation: &Emulation,
    ) -> Result<Self, HarnessError> {
        if emulation.policy != Policy::Identity {
            super::check_host(gpu)?;
        }
        let shader = |e: super::EmulateError| HarnessError::Shader(e.to_string());
        let fixed = match emulation.policy {
            Policy::Upper => Some((DirectionTable::UPPER, TABLE_MODE)),
            Policy::Lower => Some((DirectionTable::LOWER, TABLE_MODE)),
            Policy::Seeded(seed) => Some((DirectionTable::UPPER, super::search::seeded_mode(seed))),
            _ => None,
        };
        let flag = vec![UNDEFINED_FLAG.to_string()];
        if fixed.is_some() || emulation.policy == Policy::Searched {
            let searched = Emulation {
                policy: Policy::Searched,
                ..*emulation
            };
            let emulated = emulate(source, &searched).map_err(shader)?;
            if let Some((wrapper, _)) = emulated.table_functions(function) {
                // A searched kernel given one table (`DirectionTable::args`) is the very
                // pipeline Upper and Lower use.
                let mut tail = flag.clone();
                tail.extend(touched_words());
                let kernel = gpu.kernel_with_tail(&emulated.source, wrapper, &tail)?;
                let mut signature = kernel.signature().clone();
                if fixed.is_some() {
                    signature.params.truncate(signature.params.len() - 3);
                }
                return Ok(EmulatedKernel {
                    emulated,
                    policy: emulation.policy,
                    kernel,
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
        let kernel = gpu.kernel_with_tail(&emulated.source, name, &flag)?;
        Ok(EmulatedKernel {
            signature: kernel.signature().clone(),
            emulated,
            policy: emulation.policy,
            kernel,
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

    /// Values and tail words (flag first, then the slot mask where the pipeline has one:
    /// `keep` words per element at most, and how many that is), for `args` with a fixed
    /// table appended as columns, the feed the search gives its tables, so that the policies'
    /// runs and a search of the same function share one compiled pipeline; in slices of
    /// [`FIXED_TABLE_AS_COLUMNS`] elements.
    fn run_tail(
        &self,
        args: &[Arg<'_>],
        n: u64,
        keep: usize,
    ) -> Result<(Output, Vec<u32>, usize), HarnessError> {
        let stride = keep.min(self.kernel.tail_words());
        let Some((table, mode)) = self.fixed else {
            let (out, tail) = self.kernel.run_with_tail_prefix(args, n, keep)?;
            return Ok((out, tail, stride));
        };
        let [h0, h1] = table.halves();
        let slice = n.min(FIXED_TABLE_AS_COLUMNS);
        let (c0, c1) = (vec![h0; slice as usize], vec![h1; slice as usize]);
        let (mut words, mut tail) = (Vec::new(), Vec::new());
        let mut first = 0;
        while first < n {
            let count = slice.min(n - first);
            let mut all: Vec<Arg<'_>> = args
                .iter()
                .map(|a| match *a {
                    Arg::Column(bytes) => {
                        let w = bytes.len() / n as usize;
                        Arg::Column(&bytes[first as usize * w..(first + count) as usize * w])
                    }
                    Arg::Index { start } => Arg::Index {
                        start: start.wrapping_add(first as u32),
                    },
                    splat => splat,
                })
                .collect();
            let c = count as usize;
            all.extend([
                Arg::column(&c0[..c]),
                Arg::column(&c1[..c]),
                Arg::Splat(mode),
            ]);
            let (out, t) = self.kernel.run_with_tail_prefix(&all, count, keep)?;
            if count == n {
                return Ok((out, t, stride)); // one slice: its results as they are
            }
            words.extend_from_slice(out.words());
            tail.extend(t);
            first += count;
        }
        let ty = self.kernel.signature().result;
        Ok((Output::from_words(ty, words), tail, stride))
    }

    /// Under [`Policy::Searched`]: per element, the mask of the direction-table slots
    /// its evaluation read (arguments as for [`EmulatedKernel::run`]).
    pub fn touched(&self, args: &[Arg<'_>], n: u64) -> Result<Vec<DirectionTable>, HarnessError> {
        Ok(self.run_touched(args, n)?.2)
    }

    /// Under [`Policy::Searched`]: [`EmulatedKernel::run`] and [`EmulatedKernel::touched`] of
    /// one evaluation.
    pub fn run_touched(
        &self,
        args: &[Arg<'_>],
        n: u64,
    ) -> Result<(Output, Vec<bool>, Vec<DirectionTable>), HarnessError> {
        if self.policy != Policy::Searched {
            return Err(HarnessError::Shader(
                "slot masks exist under Policy::Searched only".into(),
            ));
        }
        let (out, tail, stride) = self.run_tail(args, n, 9)?;
        let (flags, masks) = tail
            .chunks_exact(stride)
            .map(|e| (e[0] != 0, DirectionTable(std::array::from_fn(|k| e[1 + k]))))
            .unzip();
        Ok((out, flags, masks))
    }

    /// Run `n` elements: the results, and per element whether an operation of its evaluation
    /// left the spec's domain (its result is then not defined by the spec). Under
    /// [`Policy::Searched`] the last three arguments are the direction table's halves and the
    /// mode ([`DirectionTable::args`], or columns of tables and [`super::search::TABLE_MODE`]).
    pub fn run(&self, args: &[Arg<'_>], n: u64) -> Result<(Output, Vec<bool>), HarnessError> {
        let (out, flags) = self.run_flags(args, n)?;
        Ok((out, flags.into_iter().map(|w| w != 0).collect()))
    }

    /// [`EmulatedKernel::run`] with each evaluation's flag word as it is: bit 1 where an
    /// arithmetic helper left the domain (a result not finite, a divisor or argument outside
    /// its range), bit 2 where an operation no arithmetic helper sees (`min`, `max`, `clamp`,
    /// `abs`, `floor`, comparisons, the identity's builtins, `u32` or `i32` of an f32) had a
    /// ±Inf or NaN operand, or `unpack2x16float` gave one.
    pub fn run_flags(&self, args: &[Arg<'_>], n: u64) -> Result<(Output, Vec<u32>), HarnessError> {
        let (out, tail, _) = self.run_tail(args, n, 1)?;
        Ok((out, tail))
    }
}
