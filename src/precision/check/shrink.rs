//! Shrinking a failure on the adapter: replayable value trees (`runner`) and the speculative
//! walk that evaluates several decision levels per dispatch.

use super::*;

/// 64-bit mixer (splitmix64's finaliser): independent-looking seeds from consecutive indices.
pub(super) fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A runner whose random source is fixed by `(seed, case)`, so the case's value tree can be
/// regenerated identically at any time.
pub(super) fn runner(seed: u64, case: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    let mut s = mix(seed ^ mix(case));
    for chunk in bytes.chunks_mut(8) {
        s = mix(s);
        chunk.copy_from_slice(&s.to_le_bytes());
    }
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &bytes),
    )
}

impl<'g> PrecisionCheck<'g> {
    /// proptest's shrinking walk from the failing input drawn as `case` (fail → simplify, pass → complicate, stop when the tree has no
    /// move left), `speculation_depth` decisions per dispatch.
    pub(super) fn shrink<S, O, R>(
        &self,
        strategy: &S,
        case: u64,
        reference: &impl Fn(&S::Value) -> R,
        error: &impl Fn(&O, &R) -> f64,
        bound: f64,
    ) -> ShrinkResult<S::Value, O, R>
    where
        S: Strategy,
        S::Value: WgslArgs,
        O: WgslValue,
    {
        let cfg = self.config;
        let depth = cfg.speculation_depth.clamp(1, 10) as usize;
        // The tree after the first simplify and then `path` (true = simplify, false =
        // complicate); None when a move along the way was refused (that branch has ended).
        let tree_at = |path: &[bool]| -> Option<S::Tree> {
            let mut tree = strategy.new_tree(&mut runner(cfg.seed, case)).ok()?;
            let moved = std::iter::once(&true).chain(path).all(|&s| {
                if s {
                    tree.simplify()
                } else {
                    tree.complicate()
                }
            });
            moved.then_some(tree)
        };
        let mut out = Shrunk {
            best: None,
            steps: 0,
            truncated: false,
            dispatches: 0,
            evaluations: 0,
        };
        let mut frontier: Vec<bool> = Vec::new();
        loop {
            // Every node of the next `depth` decision levels below the frontier, breadth first:
            // node j's children are 2j+1 (after simplify: it failed) and 2j+2 (after complicate).
            let mut nodes: Vec<Option<S::Value>> = vec![None; (1 << depth) - 1];
            for j in 0..nodes.len() {
                // A move below a refused move does not exist either.
                if j == 0 || nodes[(j - 1) / 2].is_some() {
                    let mut path = frontier.clone();
                    path.extend_from_slice(&suffix_of(j));
                    nodes[j] = tree_at(&path).map(|t| t.current());
                }
            }
            if nodes[0].is_none() {
                return Ok(out);
            }
            let live: Vec<usize> = (0..nodes.len()).filter(|&j| nodes[j].is_some()).collect();
            let batch: Vec<S::Value> = live.iter().map(|&j| nodes[j].clone().unwrap()).collect();
            let got = self.evaluate::<S::Value, O, R>(&batch)?;
            out.dispatches += 1;
            out.evaluations += batch.len() as u64;
            let mut results: Vec<Option<O>> = vec![None; nodes.len()];
            for (&j, g) in live.iter().zip(got) {
                results[j] = Some(g);
            }
            // Follow the real outcomes down the evaluated levels.
            let mut j = 0usize;
            let mut walked = Vec::new();
            loop {
                let Some(g) = results[j].take() else {
                    return Ok(out); // the tree refused this move: shrinking is over
                };
                if out.steps >= cfg.max_shrink_steps {
                    out.truncated = true;
                    return Ok(out);
                }
                out.steps += 1;
                let input = nodes[j].take().expect("evaluated nodes exist");
                let r = reference(&input);
                let e = error(&g, &r);
                let failed = fails(e, bound);
                if failed {
                    out.best = Some(Evaluated {
                        input,
                        got: g,
                        reference: r,
                        error: e,
                    });
                }
                walked.push(failed);
                j = 2 * j + if failed { 1 } else { 2 };
                if j >= nodes.len() {
                    break;
                }
            }
            frontier.extend_from_slice(&walked);
        }
    }
}

/// The decisions leading from the root of a breadth-first binary tree to node `j`
/// (children of `j` are `2j + 1` = simplify and `2j + 2` = complicate).
pub(super) fn suffix_of(mut j: usize) -> Vec<bool> {
    let mut path = Vec::new();
    while j > 0 {
        path.push(j % 2 == 1);
        j = (j - 1) / 2;
    }
    path.reverse();
    path
}

pub(super) type ShrinkResult<I, O, R> = Result<Shrunk<I, O, R>, CheckError<I, O, R>>;

pub(super) struct Shrunk<I, O, R> {
    /// The last failing candidate (the simplest found), if any candidate failed.
    pub(super) best: Option<Evaluated<I, O, R>>,
    pub(super) steps: u32,
    pub(super) truncated: bool,
    pub(super) dispatches: u32,
    pub(super) evaluations: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suffixes_follow_breadth_first_numbering() {
        assert_eq!(suffix_of(0), Vec::<bool>::new());
        assert_eq!(suffix_of(1), vec![true]);
        assert_eq!(suffix_of(2), vec![false]);
        assert_eq!(suffix_of(3), vec![true, true]);
        assert_eq!(suffix_of(6), vec![false, false]);
        assert_eq!(suffix_of(5), vec![false, true]);
    }

    #[test]
    fn regenerated_trees_replay_identically() {
        use proptest::prelude::*;
        let s = (any::<u32>(), -1e6f32..1e6);
        let path = [true, false, true, true, false];
        let walk = || {
            let mut t = s.new_tree(&mut runner(7, 3)).unwrap();
            for &p in &path {
                if p {
                    t.simplify();
                } else {
                    t.complicate();
                }
            }
            t.current()
        };
        assert_eq!(walk(), walk());
    }
}
