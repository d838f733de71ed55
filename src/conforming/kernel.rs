//! Running an emulated module on the adapter (feature `harness`).

use super::{Emulated, Emulation, emulate};
use crate::harness::{Arg, Gpu, HarnessError, Kernel, Output};

/// A function of an emulated module, ready to run, with its "not defined by the spec" twin.
pub struct EmulatedKernel<'g> {
    /// The emulated module.
    pub emulated: Emulated,
    values: Kernel<'g>,
    undefined: Option<Kernel<'g>>,
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
        let emitted = emulated.function_name(function).ok_or_else(|| {
            HarnessError::Shader(format!("the module has no function `{function}`"))
        })?;
        let values = gpu.kernel(&emulated.source, emitted)?;
        let undefined = match emulated.undefined_function(function) {
            Some(u) => Some(gpu.kernel(&emulated.source, u)?),
            None => None,
        };
        Ok(EmulatedKernel {
            emulated,
            values,
            undefined,
        })
    }

    /// The kernel computing the function's values.
    pub fn values(&self) -> &Kernel<'g> {
        &self.values
    }

    /// Run `n` elements: the results, and per element whether an operation of its evaluation
    /// left the spec's domain (its result is then not defined by the spec).
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
