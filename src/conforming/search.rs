//! The worst-case search (feature `harness`): per input, the direction table that makes a
//! function's error largest, found by steepest-ascent hill climbing over the table's slots.
//!
//! Under [`Policy::Searched`](super::Policy::Searched) every free operation reads its end from
//! a 256-slot table, one bit per slot (1: the upper end of its interval, or the larger of two
//! forms; 0: the lower end or the smaller form); an operation at site `s` reads slot
//! `hash(s ^ context) % 256`, so the table is per site and per call context (each operation of
//! a static expression, each lane, each inner operation of an inherited builtin has its own
//! site; the rewrite gives every call of the module's own functions its own context, so two
//! calls of one helper, which an inlining compiler may round differently, have their own
//! slots). The table is an argument of
//! every element, so one dispatch evaluates many tables: each round of the climb runs, for every
//! input and every start, the current table and its 256 single-slot flips at once, and moves to
//! the best flip while one improves. Starts: the upper and lower tables (the greedy policies)
//! and a seeded one.
//!
//! Every table is a behaviour some conforming adapter may have (each operation within its spec
//! interval), so the worst found is a lower bound on the worst conforming adapter's error at
//! that input, never above it: a search that finds less than a derived bound says either that
//! the bound is loose or that the search missed. Two sites that hash to one slot move together;
//! the climb is local and can stop at a local maximum.

use super::EmulatedKernel;
use crate::harness::{Arg, HarnessError, Output};

/// One end per slot, 256 slots, as 8 words (slot `k` is bit `k % 32` of word `k / 32`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DirectionTable(pub [u32; 8]);

impl DirectionTable {
    /// Slots in a table.
    pub const SLOTS: usize = 256;
    /// Every site at its upper end: what [`Policy::Upper`](super::Policy::Upper) does.
    pub const UPPER: DirectionTable = DirectionTable([u32::MAX; 8]);
    /// Every site at its lower end: what [`Policy::Lower`](super::Policy::Lower) does.
    pub const LOWER: DirectionTable = DirectionTable([0; 8]);

    /// A table drawn from `seed` (xorshift).
    pub fn seeded(seed: u64) -> DirectionTable {
        let mut s = seed | 1;
        DirectionTable(std::array::from_fn(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 32) as u32
        }))
    }

    /// The same table with slot `slot` at its other end.
    pub fn flipped(self, slot: usize) -> DirectionTable {
        let mut t = self;
        t.0[slot / 32] ^= 1 << (slot % 32);
        t
    }

    /// Whether slot `slot` is at its upper end.
    pub fn upper(self, slot: usize) -> bool {
        self.0[slot / 32] >> (slot % 32) & 1 == 1
    }

    /// The two `vec4<u32>` halves the table wrappers take.
    pub fn halves(self) -> [[u32; 4]; 2] {
        let w = self.0;
        [[w[0], w[1], w[2], w[3]], [w[4], w[5], w[6], w[7]]]
    }

    /// The three trailing arguments that give every element this table (the halves, then
    /// [`TABLE_MODE`]).
    pub fn args(self) -> [Arg<'static>; 3] {
        let [a, b] = self.halves();
        [Arg::Splat(a), Arg::Splat(b), Arg::Splat(TABLE_MODE)]
    }
}

/// The table wrappers' last argument, `(mode, seed, 0, 0)`, for reading the direction table.
pub const TABLE_MODE: [u32; 4] = [0; 4];

/// The table wrappers' last argument for [`Policy::Seeded`](super::Policy::Seeded)`(seed)`:
/// each site's choice drawn per invocation from the seed as that policy draws it (the table
/// is then not read), so one compiled module serves every seed too.
pub fn seeded_mode(seed: u32) -> [u32; 4] {
    [1, seed, 0, 0]
}

/// How to search.
#[derive(Clone, Debug)]
pub struct SearchConfig {
    /// Inputs whose evaluation reads at most this many slots are searched exhaustively: every
    /// assignment of those slots.
    pub exhaustive_slots: u32,
    /// The most climbing steps per start (inputs that read more slots).
    pub rounds: usize,
    /// Where each climb starts, with a name for reports.
    pub starts: Vec<(&'static str, DirectionTable)>,
}

impl Default for SearchConfig {
    /// Exhaustive up to 16 slots (65,536 tables); beyond, 24 steps from the upper, the lower
    /// and two seeded tables.
    fn default() -> Self {
        SearchConfig {
            exhaustive_slots: 16,
            rounds: 24,
            starts: vec![
                ("upper", DirectionTable::UPPER),
                ("lower", DirectionTable::LOWER),
                ("seeded", DirectionTable::seeded(0x9e37_79b9_7f4a_7c15)),
                ("seeded", DirectionTable::seeded(0x2545_f491_4f6c_dd1d)),
            ],
        }
    }
}

/// What the search found at one input.
#[derive(Clone, Debug)]
pub struct Found {
    /// The worst table found.
    pub table: DirectionTable,
    /// The error there (as the caller's `error` measures it).
    pub error: f64,
    /// The largest error of the start tables (the greedy policies' at that input among them).
    pub start_error: f64,
    /// How it was found: `exhaustive`, or the start the worst climb began from.
    pub how: &'static str,
    /// Slots the evaluation reads (from any start table).
    pub slots: u32,
    /// Tables evaluated for this input.
    pub evaluated: usize,
    /// The slots read, as a mask.
    pub mask: DirectionTable,
}

impl Found {
    fn with_mask(mut self, mask: DirectionTable) -> Self {
        self.mask = mask;
        self
    }
}

/// Each element `(input, table)` of `plan` run: the kernel's output (element `e` is `plan[e]`)
/// and, per element, whether an operation left the spec's domain. One dispatch. `inputs` are
/// the function's own arguments, as [`climb`] takes them; the search uses this to read the
/// results at the tables it found (a suite checking its promises at the worst combination).
pub fn run_at(
    kernel: &EmulatedKernel<'_>,
    inputs: &[Arg<'_>],
    count: usize,
    plan: &[(usize, DirectionTable)],
) -> Result<(Output, Vec<bool>), HarnessError> {
    let (out, flags, _) = run_plan(kernel, inputs, count, plan, false)?;
    Ok((out, flags))
}

/// [`run_at`], and with `masks` the slots each element read (from the same pipeline and
/// dispatch: [`EmulatedKernel::run_touched`]); the masks are empty otherwise.
fn run_plan(
    kernel: &EmulatedKernel<'_>,
    inputs: &[Arg<'_>],
    count: usize,
    plan: &[(usize, DirectionTable)],
    masks: bool,
) -> Result<(Output, Vec<bool>, Vec<DirectionTable>), HarnessError> {
    let n = plan.len();
    let mut columns: Vec<Vec<u8>> = Vec::new();
    for arg in inputs {
        if let Arg::Column(bytes) = arg {
            let w = bytes.len() / count.max(1); // bytes per element
            let mut col = Vec::with_capacity(n * w);
            for &(i, _) in plan {
                col.extend_from_slice(&bytes[i * w..(i + 1) * w]);
            }
            columns.push(col);
        }
    }
    let mut halves = [Vec::with_capacity(n * 4), Vec::with_capacity(n * 4)];
    for &(_, t) in plan {
        let [a, b] = t.halves();
        halves[0].extend(a);
        halves[1].extend(b);
    }
    let mut args: Vec<Arg<'_>> = Vec::with_capacity(inputs.len() + 2);
    let mut next_column = columns.iter();
    for arg in inputs {
        match arg {
            Arg::Column(_) => args.push(Arg::Column(next_column.next().expect("one per column"))),
            Arg::Splat(w) => args.push(Arg::Splat(*w)),
            Arg::Index { .. } => {
                return Err(HarnessError::Shader(
                    "the search feeds inputs as columns or splats, not index feeds".into(),
                ));
            }
        }
    }
    args.push(Arg::column(&halves[0]));
    args.push(Arg::column(&halves[1]));
    args.push(Arg::Splat(TABLE_MODE));
    if masks {
        return kernel.run_touched(&args, n as u64);
    }
    let (out, flags) = kernel.run(&args, n as u64)?;
    Ok((out, flags, Vec::new()))
}

/// Each element of `plan` evaluated: its error, or −∞ where an operation left the spec's
/// domain; with `masks`, also the slots each element read (empty otherwise).
fn evaluate(
    kernel: &EmulatedKernel<'_>,
    inputs: &[Arg<'_>],
    count: usize,
    plan: &[(usize, DirectionTable)],
    error: &dyn Fn(usize, &Output, usize) -> f64,
    masks: bool,
) -> Result<(Vec<f64>, Vec<DirectionTable>), HarnessError> {
    let (out, flags, masks) = run_plan(kernel, inputs, count, plan, masks)?;
    let errors = plan
        .iter()
        .enumerate()
        .map(|(e, &(i, _))| {
            if flags[e] {
                f64::NEG_INFINITY
            } else {
                error(i, &out, e)
            }
        })
        .collect();
    Ok((errors, masks))
}

fn slots_of(mask: DirectionTable) -> Vec<usize> {
    (0..DirectionTable::SLOTS)
        .filter(|&k| mask.upper(k))
        .collect()
}

/// Search the worst direction table for each of `count` inputs of `kernel` (built with
/// [`Policy::Searched`](super::Policy::Searched)). `inputs` are the function's own arguments:
/// columns of `count` elements, or splats. `error(i, out, e)` is the error of element `e` of
/// `out` as a result for input `i`; an element whose evaluation left the spec's domain counts
/// as no error (its result is not defined by the spec).
///
/// First the slots each input's evaluation reads are found from the start tables. An input
/// reading at most `config.exhaustive_slots` slots gets every assignment of them (one
/// dispatch for all such inputs); the others climb: steepest ascent from each start, each step
/// one dispatch of the current table and every single flip of a read slot.
pub fn climb(
    kernel: &EmulatedKernel<'_>,
    inputs: &[Arg<'_>],
    count: usize,
    error: &dyn Fn(usize, &Output, usize) -> f64,
    config: &SearchConfig,
) -> Result<Vec<Found>, HarnessError> {
    let starts = config.starts.len();
    let plan: Vec<(usize, DirectionTable)> = (0..count)
        .flat_map(|i| config.starts.iter().map(move |&(_, t)| (i, t)))
        .collect();
    let (start_errors, masks) = evaluate(kernel, inputs, count, &plan, error, true)?;
    let mut found: Vec<Found> = (0..count)
        .map(|i| {
            let mut mask = DirectionTable::LOWER;
            for s in 0..starts {
                for (w, m) in mask.0.iter_mut().zip(masks[i * starts + s].0) {
                    *w |= m;
                }
            }
            let (s, &e) = start_errors[i * starts..(i + 1) * starts]
                .iter()
                .enumerate()
                .max_by(|a, b| a.1.total_cmp(b.1))
                .expect("at least one start");
            Found {
                table: config.starts[s].1,
                error: e,
                start_error: e,
                how: config.starts[s].0,
                slots: mask.0.iter().map(|w| w.count_ones()).sum(),
                evaluated: starts,
                mask: DirectionTable::LOWER,
            }
            .with_mask(mask)
        })
        .collect();
    // Exhaustive where the read slots are few.
    let small: Vec<usize> = (0..count)
        .filter(|&i| found[i].slots <= config.exhaustive_slots)
        .collect();
    let mut plan = Vec::new();
    for &i in &small {
        let slots = slots_of(found[i].mask);
        for bits in 0u32..1 << slots.len() {
            let mut t = DirectionTable::LOWER;
            for (j, &k) in slots.iter().enumerate() {
                if bits >> j & 1 == 1 {
                    t = t.flipped(k);
                }
            }
            plan.push((i, t));
        }
    }
    if !plan.is_empty() {
        let (errors, _) = evaluate(kernel, inputs, count, &plan, error, false)?;
        for (&(i, t), &e) in plan.iter().zip(&errors) {
            let f = &mut found[i];
            f.evaluated += 1;
            if e > f.error {
                (f.table, f.error, f.how) = (t, e, "exhaustive");
            }
        }
        for &i in &small {
            if found[i].how != "exhaustive" {
                found[i].how = "exhaustive (no table beat the starts)";
            }
        }
    }
    // Steepest ascent over the read slots elsewhere, from every start.
    let big: Vec<usize> = (0..count)
        .filter(|&i| found[i].slots > config.exhaustive_slots)
        .collect();
    let mut lanes: Vec<(usize, usize, DirectionTable, f64)> = big
        .iter()
        .flat_map(|&i| (0..starts).map(move |s| (i, s)))
        .map(|(i, s)| (i, s, config.starts[s].1, start_errors[i * starts + s]))
        .collect();
    for _ in 0..config.rounds {
        if lanes.is_empty() {
            break;
        }
        let mut plan = Vec::new();
        let mut spans = Vec::new();
        for &(i, _, t, _) in &lanes {
            let slots = slots_of(found[i].mask);
            spans.push((plan.len(), slots.clone()));
            plan.extend(slots.iter().map(|&k| (i, t.flipped(k))));
        }
        let (errors, _) = evaluate(kernel, inputs, count, &plan, error, false)?;
        let mut next = Vec::new();
        for (l, (at, slots)) in lanes.iter().zip(spans) {
            let (i, s, t, here) = *l;
            found[i].evaluated += slots.len();
            let best = (0..slots.len()).max_by(|&a, &b| errors[at + a].total_cmp(&errors[at + b]));
            if let Some(b) = best
                && errors[at + b] > here
            {
                let (t2, e2) = (t.flipped(slots[b]), errors[at + b]);
                if e2 > found[i].error {
                    (found[i].table, found[i].error, found[i].how) = (t2, e2, config.starts[s].0);
                }
                next.push((i, s, t2, e2));
            }
        }
        lanes = next;
    }
    Ok(found)
}
