//! One process rendering a scene file's own view RUNS times at WIDTH×HEIGHT (one sample per
//! pixel, as the command line does): prints the first frame's milliseconds (cold: a new
//! process, its memory and thread pool fresh) and the median of the others (warm); with GAP_MS,
//! each frame after that many milliseconds of idling. `scripts/command-vs-cpp.sh` puts them
//! beside the command's own figures:
//!
//! ```sh
//! cargo run --release --example render_time -- SCENE WIDTH HEIGHT [RUNS [GAP_MS]]
//! ```

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "support/frame_args.rs"]
mod frame_args;

use std::time::Instant;

use raytracer::render::render;

fn main() {
    let frame_args::FrameArgs {
        scene,
        view,
        runs,
        gap,
    } = frame_args::frame_args("render_time SCENE WIDTH HEIGHT [RUNS [GAP_MS]]", 21);
    let runs = runs.max(2);
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            std::thread::sleep(gap);
            let started = Instant::now();
            std::hint::black_box(render(&scene, &view).expect("renders"));
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    let first = times.remove(0);
    times.sort_by(f64::total_cmp);
    println!("{first:.2} {:.2}", times[times.len() / 2]);
}
