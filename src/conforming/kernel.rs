//! Running an emulated module on the adapter (feature `harness`).

use super::{Emulated, Emulation, emulate};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output};

/// A function of an emulated module, ready to run, with its "not defined by the spec" twin.
pub struct EmulatedKernel<'g> {
    /// The emulated module.
    pub emulated: Emulated,
    values: Kernel<'g>,
    undefined: Option<Kernel<'g>>,
    touched: Option<[Kernel<'g>; 2]>,
}

impl<'g> EmulatedKernel<'g> {
    /// Emulate `source` as `emulation` says and prepare `function` on `gpu`.
    pub fn new(
        gpu: &'g Gpu,
        source: &str,
        function: &str,
        emulation: &Emulation,
    ) -> Result<Self, HarnessError> {
        let emulated =
            emulate(source, emulation).map_err(|e| HarnessError::Shader(e.to_string()))?;
        let missing = || HarnessError::Shader(format!("the module has no function `{function}`"));
        let mut touched = None;
        let (values, undefined) = if emulation.policy == super::Policy::Searched {
            // The table wrappers: the function's parameters, then the table's two halves.
            let (v, u) = emulated.table_functions(function).ok_or_else(|| {
                HarnessError::Shader(format!(
                    "`{function}` has no table wrapper (no result, or parameters it cannot spell)"
                ))
            })?;
            if let Some((a, b)) = emulated.touched_functions(function) {
                touched = Some([
                    gpu.kernel(&emulated.source, a)?,
                    gpu.kernel(&emulated.source, b)?,
                ]);
            }
            (
                gpu.kernel(&emulated.source, v)?,
                Some(gpu.kernel(&emulated.source, u)?),
            )
        } else {
            let emitted = emulated.function_name(function).ok_or_else(missing)?;
            let undefined = match emulated.undefined_function(function) {
                Some(u) => Some(gpu.kernel(&emulated.source, u)?),
                None => None,
            };
            (gpu.kernel(&emulated.source, emitted)?, undefined)
        };
        Ok(EmulatedKernel {
            emulated,
            values,
            undefined,
            touched,
        })
    }

    /// Under [`super::Policy::Searched`]: per element, the mask of the direction-table slots
    /// its evaluation read (arguments as for [`EmulatedKernel::run`]).
    pub fn touched(
        &self,
        args: &[Arg<'_>],
        n: u64,
    ) -> Result<Vec<super::search::DirectionTable>, HarnessError> {
        let [a, b] = self.touched.as_ref().ok_or_else(|| {
            HarnessError::Shader("slot masks exist under Policy::Searched only".into())
        })?;
        let (lo, hi) = std::thread::scope(|scope| {
            let hi = scope.spawn(move || b.run(args, n));
            (
                a.run(args, n),
                hi.join().expect("the mask kernel's thread panicked"),
            )
        });
        let (lo, hi) = (lo?, hi?);
        Ok(lo
            .as_u32()
            .chunks(4)
            .zip(hi.as_u32().chunks(4))
            .map(|(l, h)| {
                super::search::DirectionTable([l[0], l[1], l[2], l[3], h[0], h[1], h[2], h[3]])
            })
            .collect())
    }

    /// The kernel computing the function's values.
    pub fn values(&self) -> &Kernel<'g> {
        &self.values
    }

    /// Run `n` elements: the results, and per element whether an operation of its evaluation
    /// left the spec's domain (its result is then not defined by the spec). Under
    /// [`super::Policy::Searched`] the last two arguments are the direction table's halves
    /// ([`super::search::DirectionTable::args`], or a column of tables).
    ///
    /// The two kernels run on two threads: the first run of each compiles its pipeline, which on
    /// a CPU adapter (lavapipe) costs far more than the dispatch, and the two compile at once.
    pub fn run(&self, args: &[Arg<'_>], n: u64) -> Result<(Output, Vec<bool>), HarnessError> {
        let (out, flags) = std::thread::scope(|scope| {
            let flags = self
                .undefined
                .as_ref()
                .map(|k| scope.spawn(move || k.run(args, n)));
            let out = self.values.run(args, n);
            (
                out,
                flags.map(|h| h.join().expect("the flag kernel's thread panicked")),
            )
        });
        let out = out?;
        let flags = match flags {
            Some(f) => f?.as_u32().iter().map(|&f| f != 0).collect(),
            None => vec![false; out.len()],
        };
        Ok((out, flags))
    }
}
