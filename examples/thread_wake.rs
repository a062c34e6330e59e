//! What waking the renderer's threads costs: a parallel step of the kind a frame is made of
//! (rayon's pool, as many equal tasks as four per thread, each about ITEM_US of work), run after
//! the pool has idled for each of several gaps. Rayon's threads spin a while after their last
//! task, then sleep; a step that comes after they slept waits for them to wake. The overhead is
//! the step's wall time over what its work takes on the threads there are (the tasks timed on
//! one thread beforehand).
//!
//! ```sh
//! cargo run --release --example thread_wake -- [RUNS [ITEM_US]]
//! ```
//!
//! Prints one line per gap: `gap_us<TAB>step_us<TAB>work_us<TAB>overhead_us`, each the median of
//! RUNS steps (default 101; ITEM_US default 20). `cargo xtask report thread-wake` runs it pinned to 1, 2,
//! 4, … cores.

use std::hint::black_box;
use std::time::{Duration, Instant};

use rayon::prelude::*;

/// Idle gaps before a step, microseconds: none, shorter than rayon's spin, and longer.
const GAPS_US: [u64; 5] = [0, 20, 200, 2_000, 20_000];

/// About `iterations` rounds of arithmetic the optimiser cannot remove.
fn work(iterations: u64) -> u64 {
    let mut x = black_box(0x9E37_79B9_7F4A_7C15u64);
    for _ in 0..iterations {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
    }
    x
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |at: usize, default: u64| {
        args.get(at).map_or(default, |arg| {
            arg.parse().unwrap_or_else(|_| {
                eprintln!("usage: thread_wake [RUNS [ITEM_US]] (whole numbers)");
                std::process::exit(2)
            })
        })
    };
    let runs = number(0, 101).max(1) as usize;
    let item_us = number(1, 20).max(1);
    // Iterations for one task of about ITEM_US on one thread.
    let probe = 100_000;
    let started = Instant::now();
    black_box(work(probe));
    let per_us = probe as f64 / started.elapsed().as_secs_f64() / 1e6;
    let iterations = (per_us * item_us as f64) as u64;
    let threads = rayon::current_num_threads();
    let tasks = 4 * threads;
    // The tasks' work on the threads there are: each thread's share, timed on one thread.
    let work_us = median(
        (0..runs)
            .map(|_| {
                let started = Instant::now();
                for _ in 0..tasks / threads {
                    black_box(work(iterations));
                }
                started.elapsed().as_secs_f64() * 1e6
            })
            .collect(),
    );
    let step = || {
        (0..tasks).into_par_iter().for_each(|_| {
            black_box(work(iterations));
        });
    };
    step();
    // Gap by gap: a step after the steps before it idled as long (a step's cost depends on how
    // long the machine idled before the step before it, too).
    for gap_us in GAPS_US {
        let steps: Vec<f64> = (0..runs)
            .map(|_| {
                if gap_us > 0 {
                    std::thread::sleep(Duration::from_micros(gap_us));
                }
                let started = Instant::now();
                step();
                started.elapsed().as_secs_f64() * 1e6
            })
            .collect();
        let step_us = median(steps);
        println!(
            "{gap_us}\t{step_us:.1}\t{work_us:.1}\t{:.1}",
            step_us - work_us
        );
    }
}
