//! Timing for the reports' examples: the median wall time of a few runs. Shared by
//! `examples/performance.rs` and `examples/tradeoff.rs` (included by path).

use std::time::Instant;

/// The median of `runs` timed runs of `run`, in milliseconds (`warm_up`: one untimed run first).
pub(crate) fn median_ms(runs: usize, warm_up: bool, mut run: impl FnMut()) -> f64 {
    if warm_up {
        run();
    }
    let mut times: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let started = Instant::now();
            run();
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}
