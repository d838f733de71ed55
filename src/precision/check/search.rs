//! [`PrecisionCheck::run_searched`]: the check on the emulated worst adapter, each case at the
//! worst direction table a search finds.

use super::*;

pub(super) struct Searching<'g> {
    pub(super) kernel: crate::conforming::EmulatedKernel<'g>,
    pub(super) table: std::sync::Mutex<crate::conforming::search::DirectionTable>,
}

/// What [`PrecisionCheck::run_searched`] did, in [`Passed::search`].
#[derive(Clone, Debug, PartialEq)]
pub struct SearchSummary {
    /// Inputs climbed: the first batch's worst at the start tables.
    pub inputs: usize,
    /// Of them, searched exhaustively (every assignment of the table slots they read).
    pub exhaustive: usize,
    /// Direction tables evaluated over the whole batch.
    pub evaluated: usize,
    /// The largest error at the fixed policies' tables (all upper, all lower).
    pub greedy_max: f64,
    /// The largest error found.
    pub found_max: f64,
    /// The table that gave it.
    pub table: crate::conforming::search::DirectionTable,
}

impl<'g> PrecisionCheck<'g> {
    /// [`PrecisionCheck::run`] on the emulated worst adapter, searched (a check built by
    /// [`PrecisionCheck::searched`]): every case is evaluated at the tables of the fixed
    /// policies (all upper, all lower: what [`PrecisionCheck::emulated`] gives under
    /// `Policy::Upper` and `Policy::Lower`) and at the other starts of `search` (seeded
    /// tables); the `searched_inputs` cases that erred most are climbed from every start
    /// ([`crate::conforming::search::climb`]: every assignment of the table slots a case reads
    /// where they are at most `search.exhaustive_slots`, steepest ascent elsewhere). Each case counts at the worst table found for it. A failure is shrunk
    /// at the table of the worst case (the table, not the input, is what the search chose).
    /// A NaN error ranks as +∞; a case undefined at every start table counts as undefined.
    pub fn run_searched<S, O, R>(
        &self,
        strategy: &S,
        reference: impl Fn(&S::Value) -> R,
        error: impl Fn(&O, &R) -> f64,
        bound: f64,
        search: &crate::conforming::search::SearchConfig,
        searched_inputs: usize,
    ) -> Result<Passed<S::Value>, CheckError<S::Value, O, R>>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        use crate::conforming::search::{DirectionTable, SearchConfig, climb};
        let Some(s) = &self.search else {
            return Err(CheckError::Setup(
                "run_searched needs a check built by PrecisionCheck::searched".into(),
            ));
        };
        let (inputs, seeds) = self.draw::<S, O, R>(strategy)?;
        // The types, checked as every run checks them (and one evaluation at the upper table).
        self.evaluate::<S::Value, O, R>(&inputs[..inputs.len().min(1)])?;
        let n = inputs.len();
        let refs: Vec<R> = inputs.iter().map(&reference).collect();
        let params = S::Value::param_types().len();
        let w = O::TYPE.words();
        let measure = |i: usize, out: &Output, e: usize| {
            let v = error(&O::from_words(&out.words()[e * w..(e + 1) * w]), &refs[i]);
            if v.is_nan() { f64::INFINITY } else { v }
        };
        let cols = columns_of(&inputs, params);
        let args: Vec<Arg<'_>> = cols
            .iter()
            .map(|c| Arg::Column(bytemuck::cast_slice(c)))
            .collect();
        // Every case at the fixed policies' tables (what Upper and Lower give), then at every
        // start of the search (the seeded tables explore mixtures): one dispatch each.
        let at = |starts: Vec<(&'static str, DirectionTable)>| {
            let config = SearchConfig {
                exhaustive_slots: 0,
                rounds: 0,
                starts,
            };
            climb(&s.kernel, &args, n, &measure, &config)
        };
        let fixed = vec![
            ("upper", DirectionTable::UPPER),
            ("lower", DirectionTable::LOWER),
        ];
        let greedy_max = at(fixed)?
            .iter()
            .map(|f| f.error)
            .fold(f64::NEG_INFINITY, f64::max);
        let mut found = at(search.starts.clone())?;
        // The worst cases at the starts, climbed.
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| found[b].error.total_cmp(&found[a].error));
        order.truncate(searched_inputs);
        let picked: Vec<S::Value> = order.iter().map(|&i| inputs[i].clone()).collect();
        let sub = columns_of(&picked, params);
        let sub_args: Vec<Arg<'_>> = sub
            .iter()
            .map(|c| Arg::Column(bytemuck::cast_slice(c)))
            .collect();
        let sub_measure = |k: usize, out: &Output, e: usize| measure(order[k], out, e);
        let climbed = climb(&s.kernel, &sub_args, order.len(), &sub_measure, search)?;
        let exhaustive = climbed
            .iter()
            .filter(|f| f.slots <= search.exhaustive_slots)
            .count();
        let mut evaluated: usize = found.iter().map(|f| f.evaluated).sum();
        for (&i, f) in order.iter().zip(climbed) {
            evaluated += f.evaluated;
            if f.error > found[i].error {
                found[i] = f;
            }
        }
        let (mut stats, mut failing, mut worst) = (ErrorStats::default(), 0u64, None);
        let (mut undefined, mut undefined_example) = (0u64, None);
        for (i, f) in found.iter().enumerate() {
            if f.error == f64::NEG_INFINITY {
                undefined += 1;
                undefined_example.get_or_insert_with(|| inputs[i].clone());
                continue;
            }
            stats.add(i as u64, f.error);
            failing += u64::from(fails(f.error, bound));
            if worst.is_none_or(|(_, e)| f.error > e) {
                worst = Some((i, f.error));
            }
        }
        let summary = SearchSummary {
            inputs: order.len(),
            exhaustive,
            evaluated,
            greedy_max,
            found_max: worst.map_or(f64::NEG_INFINITY, |(_, e)| e),
            table: worst.map_or(
                crate::conforming::search::DirectionTable::UPPER,
                |(i, _)| found[i].table,
            ),
        };
        match worst {
            Some((i, e)) if fails(e, bound) => {
                // Shrink (and report) at the worst case's table.
                *s.table.lock().unwrap_or_else(|p| p.into_inner()) = summary.table;
                let got = self.evaluate::<S::Value, O, R>(std::slice::from_ref(&inputs[i]))?;
                let got = got.into_iter().next().expect("one input, one result");
                let r = reference(&inputs[i]);
                let worst = Evaluated {
                    error: error(&got, &r),
                    input: inputs[i].clone(),
                    got,
                    reference: r,
                };
                let shape = (n as u64, failing, stats);
                let failure =
                    self.failure(strategy, seeds[i], worst, shape, &reference, &error, bound);
                *s.table.lock().unwrap_or_else(|p| p.into_inner()) =
                    crate::conforming::search::DirectionTable::UPPER;
                Err(failure)
            }
            _ => Ok(Passed {
                cases: n as u64,
                stats,
                worst: worst.map(|(i, _)| inputs[i].clone()),
                undefined,
                undefined_example,
                search: Some(summary),
            }),
        }
    }
}
