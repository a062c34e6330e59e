//! Where the viewer's frame spends its time: each phase of `prepare_frame` (projection, the plan,
//! clearing, a dense frame's cull, sort and bin, and coarse depth, binning, drawing, shading,
//! histogram, textures; [`raytracer::render::phases`]) for a
//! scene file's own camera at WIDTH×HEIGHT pixels. The first frame in the process is the cold one
//! (fresh pages, threads starting); the warm figure is the median of the next RUNS frames, each
//! after GAP_MS of idling when given.
//! `cargo xtask report scaling` runs it pinned to 1, 2, 4, … cores, to show which phases stop scaling:
//!
//! ```sh
//! cargo run --release --example frame_phases -- SCENE WIDTH HEIGHT [RUNS [GAP_MS]]
//! ```
//!
//! Prints one line per phase, `name<TAB>cold ms<TAB>warm ms`, then the whole frame's as `frame`.
//! A phase run more than once in a frame (a pass's sort and bin, and drawing) is summed over the
//! frame; the histogram and the textures run at the same time, so the phases can add up to more
//! than the frame. On Linux a last line, `thread sleeps (count)`, gives how many times the process's
//! threads slept during the frame (their voluntary context switches, from `/proc/self/task`): a
//! thread that runs out of work sleeps, and the next parallel step waits for it to wake
//! (`docs/thread-wake.md`).

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "support/frame_args.rs"]
mod frame_args;

use std::time::Instant;

use raytracer::app::render_job::prepare_frame;
use raytracer::render::phases;

/// One frame's phases, summed by name in the order first seen, with the whole frame last.
type FramePhases = Vec<(&'static str, f64)>;

fn main() {
    let frame_args::FrameArgs { job, runs, gap } =
        frame_args::frame_args("frame_phases SCENE WIDTH HEIGHT [RUNS [GAP_MS]]", 15);
    let frame = || {
        let slept_before = thread_sleeps();
        let started = Instant::now();
        let (output, recorded) = phases::measure(|| prepare_frame(&job));
        let frame_ms = started.elapsed().as_secs_f64() * 1e3;
        let slept = thread_sleeps()
            .zip(slept_before)
            .map(|(after, before)| after.saturating_sub(before));
        std::hint::black_box(output.expect("renders"));
        let mut summed: FramePhases = Vec::new();
        for (name, ms) in recorded {
            match summed.iter_mut().find(|(seen, _)| *seen == name) {
                Some((_, total)) => *total += ms,
                None => summed.push((name, ms)),
            }
        }
        summed.push(("frame", frame_ms));
        if let Some(slept) = slept {
            summed.push((SLEEPS, slept as f64));
        }
        summed
    };
    let cold = frame();
    let warm: Vec<FramePhases> = (0..runs.max(1))
        .map(|_| {
            std::thread::sleep(gap);
            frame()
        })
        .collect();
    for (name, cold_ms) in cold {
        let mut times: Vec<f64> = warm
            .iter()
            .map(|phases| {
                phases
                    .iter()
                    .find(|(seen, _)| *seen == name)
                    .map_or(0.0, |p| p.1)
            })
            .collect();
        times.sort_by(f64::total_cmp);
        let warm = times[times.len() / 2];
        if name == SLEEPS {
            println!("{name}\t{cold_ms}\t{warm}");
        } else {
            println!("{name}\t{cold_ms:.2}\t{warm:.2}");
        }
    }
}

/// The last line's name: a count, not milliseconds.
const SLEEPS: &str = "thread sleeps (count)";

/// How many times the process's threads have slept so far (the sum of their voluntary context
/// switches); `None` where `/proc/self/task` cannot tell (not Linux). A thread that ended since
/// the last call, or ends while it is read, takes its count with it: the pool's threads live as
/// long as the process.
fn thread_sleeps() -> Option<u64> {
    let tasks = std::fs::read_dir("/proc/self/task").ok()?;
    let sleeps = tasks
        .flatten()
        .filter_map(|task| std::fs::read_to_string(task.path().join("status")).ok())
        .filter_map(|status| {
            status
                .lines()
                .find_map(|line| line.strip_prefix("voluntary_ctxt_switches:"))
                .and_then(|count| count.trim().parse::<u64>().ok())
        })
        .sum();
    Some(sleeps)
}
