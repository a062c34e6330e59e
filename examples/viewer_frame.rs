//! The benchmark figure for a view the real window showed: the viewer's work for one frame
//! (render, both textures, histogram: `raytracer::app::render_job::prepare_frame`) of a scene file's own
//! camera at WIDTH×HEIGHT pixels, median of RUNS, in milliseconds; with GAP_MS, each frame after
//! that many milliseconds of idling, as frames come in a window (its threads asleep, its caches
//! cooled by whatever else ran). `cargo xtask report window-frame-times` puts both beside the frame times
//! the window logged:
//!
//! ```sh
//! cargo run --release --example viewer_frame -- SCENE WIDTH HEIGHT [RUNS [GAP_MS]]
//! ```

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "support/frame_args.rs"]
mod frame_args;

use std::time::Instant;

use raytracer::app::render_job::prepare_frame;

fn main() {
    let frame_args::FrameArgs { job, runs, gap } =
        frame_args::frame_args("viewer_frame SCENE WIDTH HEIGHT [RUNS [GAP_MS]]", 31);
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            std::thread::sleep(gap);
            let started = Instant::now();
            std::hint::black_box(prepare_frame(&job).expect("renders"));
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!("{:.2}", times[times.len() / 2]);
}
