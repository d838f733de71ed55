//! The worker pool the sweeps fold their inputs on: scoped threads, one range per core (eight at most).

/// Split `0..n` over the available cores and fold each part with `f`.
pub(super) fn par_fold<T: Send>(
    n: usize,
    f: impl Fn(std::ops::Range<usize>) -> T + Sync,
) -> Vec<T> {
    let threads = std::thread::available_parallelism()
        .map_or(1, |p| p.get())
        .min(8);
    let step = n.div_ceil(threads).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..n)
            .step_by(step)
            .map(|a| {
                let f = &f;
                s.spawn(move || f(a..(a + step).min(n)))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("worker"))
            .collect()
    })
}
