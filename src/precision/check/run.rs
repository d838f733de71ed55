//! Drawing inputs, evaluating them on the adapter in one batch, and [`PrecisionCheck::run`].

use super::*;

/// Run `kernel` once over `inputs`, each parameter's bits in a column of its own.
/// The inputs' argument columns (`params` of them), as words.
pub(super) fn columns_of<I: WgslArgs>(inputs: &[I], params: usize) -> Vec<Vec<u32>> {
    let mut columns = vec![Vec::with_capacity(inputs.len() * 4); params];
    for x in inputs {
        x.push_columns(&mut columns);
    }
    columns
}

/// Run `inputs` (then the `extra` arguments) through `kernel`: results and tail words.
pub(super) fn run_batch_with_tail<I: WgslArgs>(
    kernel: &Kernel<'_>,
    inputs: &[I],
    extra: &[Arg<'_>],
) -> Result<(Output, Vec<u32>), HarnessError> {
    let params = kernel.signature().params.len() - extra.len();
    let columns = columns_of(inputs, params);
    let mut args: Vec<Arg<'_>> = columns
        .iter()
        .map(|c| Arg::Column(bytemuck::cast_slice(c)))
        .collect();
    args.extend_from_slice(extra);
    kernel.run_with_tail(&args, inputs.len() as u64)
}

/// An error fails unless it is within the bound; NaN (unmeasurable) fails.
pub(super) fn fails(error: f64, bound: f64) -> bool {
    error.is_nan() || error > bound
}

impl<'g> PrecisionCheck<'g> {
    /// Run the function on the adapter for every input, in one batch.
    ///
    /// Returns the results in input order; fails with [`CheckError::Setup`] when `I` or `O` do
    /// not match the function's signature.
    pub fn evaluate<I: WgslArgs, O: WgslValue, R>(
        &self,
        inputs: &[I],
    ) -> Result<Vec<O>, CheckError<I, O, R>> {
        let sig = self.kernel.signature();
        let mut want: Vec<ValueType> = sig.params.iter().map(|p| p.ty).collect();
        if self.search.is_some() {
            want.truncate(want.len() - 3); // the direction table's halves and the mode
        }
        if I::param_types() != want || O::TYPE != sig.result {
            let show = |ts: &[ValueType]| {
                ts.iter()
                    .map(|t| t.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            return Err(CheckError::Setup(format!(
                "`{}` is fn({}) -> {}, but the strategy gives ({}) and the metric reads {}",
                sig.function,
                show(&want),
                sig.result,
                show(&I::param_types()),
                O::TYPE
            )));
        }
        let (out, _) = run_batch_with_tail(&self.kernel, inputs, &self.table_args())?;
        Ok(out
            .words()
            .chunks(O::TYPE.words())
            .map(O::from_words)
            .collect())
    }

    /// Under emulation, whether each input's result is left undefined by the spec (all `false`
    /// otherwise).
    pub(super) fn undefined_flags<I: WgslArgs, O: WgslValue, R>(
        &self,
        inputs: &[I],
    ) -> Result<Vec<bool>, CheckError<I, O, R>> {
        if self.kernel.tail_words() == 0 {
            return Ok(Vec::new());
        }
        let (_, flags) = run_batch_with_tail(&self.kernel, inputs, &self.table_args())?;
        Ok(flags.iter().map(|&f| f != 0).collect())
    }

    /// Draw `cases` inputs; case k's tree comes from `runner(seed, k')`, k' counting rejections
    /// too, so it can be regenerated later for shrinking. The inputs and their draw numbers.
    #[allow(clippy::type_complexity)]
    pub(super) fn draw<S, O, R>(
        &self,
        strategy: &S,
    ) -> Result<(Vec<S::Value>, Vec<u64>), CheckError<S::Value, O, R>>
    where
        S: Strategy,
    {
        let cfg = self.config;
        let mut seeds = Vec::with_capacity(cfg.cases as usize);
        let mut inputs = Vec::with_capacity(cfg.cases as usize);
        let mut draw = 0u64;
        let mut rejects = 0u32;
        while inputs.len() < cfg.cases as usize {
            match strategy.new_tree(&mut runner(cfg.seed, draw)) {
                Ok(tree) => {
                    seeds.push(draw);
                    inputs.push(tree.current());
                }
                Err(why) => {
                    rejects += 1;
                    if rejects > cfg.max_rejects {
                        return Err(CheckError::Setup(format!(
                            "the strategy rejected {rejects} draws (last: {why})"
                        )));
                    }
                }
            }
            draw += 1;
        }
        Ok((inputs, seeds))
    }

    /// Check that `error(wgsl_result, reference(input)) ≤ bound` for `cases` inputs drawn from
    /// `strategy`, evaluated on the adapter in one batch; on failure, shrink the worst input on
    /// the adapter and report both (see the module docs).
    ///
    /// `O`, the WGSL result type, is read from the metric's first parameter; a NaN error is a
    /// failure.
    pub fn run<S, O, R>(
        &self,
        strategy: &S,
        reference: impl Fn(&S::Value) -> R,
        error: impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> Result<Passed<S::Value>, CheckError<S::Value, O, R>>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let (inputs, seeds) = self.draw::<S, O, R>(strategy)?;
        let outputs = self.evaluate::<S::Value, O, R>(&inputs)?;
        let undefined = self.undefined_flags::<S::Value, O, R>(&inputs)?;
        let (mut undefined_count, mut undefined_example) = (0u64, None);
        let mut stats = ErrorStats::default();
        let mut failing = 0u64;
        let mut worst: Option<(usize, f64)> = None;
        let rank = |e: f64| if e.is_nan() { f64::INFINITY } else { e };
        let mut worst_any: Option<(usize, f64)> = None;
        let mut refs = Vec::with_capacity(inputs.len());
        for (i, (x, got)) in inputs.iter().zip(&outputs).enumerate() {
            if undefined.get(i).copied().unwrap_or(false) {
                undefined_count += 1;
                undefined_example.get_or_insert_with(|| x.clone());
                refs.push(reference(x));
                continue;
            }
            let r = reference(x);
            let e = error(got, &r);
            refs.push(r);
            stats.add(i as u64, e);
            if worst_any.is_none_or(|(_, w)| rank(e) > rank(w)) {
                worst_any = Some((i, e));
            }
            if fails(e, bound) {
                failing += 1;
                if worst.is_none_or(|(_, w)| rank(e) > rank(w)) {
                    worst = Some((i, e));
                }
            }
        }
        let Some((w, w_err)) = worst else {
            return Ok(Passed {
                cases: inputs.len() as u64,
                stats,
                worst: worst_any.map(|(i, _)| inputs[i].clone()),
                undefined: undefined_count,
                undefined_example,
                search: None,
            });
        };
        let worst = Evaluated {
            input: inputs[w].clone(),
            got: outputs[w].clone(),
            reference: refs.swap_remove(w),
            error: w_err,
        };
        let shape = (inputs.len() as u64, failing, stats);
        Err(self.failure(strategy, seeds[w], worst, shape, &reference, &error, bound))
    }

    /// The failure at `worst` (drawn as `case`), shrunk; `shape` is the batch's case count,
    /// failing count and statistics.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn failure<S, O, R>(
        &self,
        strategy: &S,
        case: u64,
        worst: Evaluated<S::Value, O, R>,
        shape: (u64, u64, ErrorStats),
        reference: &impl Fn(&S::Value) -> R,
        error: &impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> CheckError<S::Value, O, R>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let shrink = match self.shrink(strategy, case, reference, error, bound) {
            Ok(s) => s,
            Err(e) => return e,
        };
        let shrank = shrink.best.is_some();
        // Nothing simpler failed: the worst input is its own shrink.
        let shrunk = shrink.best.unwrap_or_else(|| Evaluated {
            input: worst.input.clone(),
            got: worst.got.clone(),
            reference: reference(&worst.input),
            error: worst.error,
        });
        let (cases, failing, stats) = shape;
        CheckError::Failed(Box::new(Failure {
            function: self.function.clone(),
            bound,
            cases,
            failing,
            stats,
            worst,
            shrunk,
            shrank,
            shrink_steps: shrink.steps,
            shrink_truncated: shrink.truncated,
            shrink_dispatches: shrink.dispatches,
            shrink_evaluations: shrink.evaluations,
            seed: self.config.seed,
        }))
    }
}
