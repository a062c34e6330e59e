//! One process rendering a scene file's own view RUNS times at WIDTH×HEIGHT (one sample per
//! pixel, as the command line does): prints the first frame's milliseconds (cold: a new
//! process, its memory and thread pool fresh) and the median of the others (warm).
//! `scripts/command-vs-cpp.sh` puts them beside the command's own render time:
//!
//! ```sh
//! cargo run --release --example render_time -- SCENE WIDTH HEIGHT [RUNS]
//! ```

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::time::Instant;

use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, render};

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let [path, width, height, rest @ ..] = arguments.as_slice() else {
        eprintln!("usage: render_time SCENE WIDTH HEIGHT [RUNS]");
        std::process::exit(2);
    };
    let number = |text: &str| text.parse::<u32>().expect("a whole number");
    let runs = rest.first().map_or(21, |r| number(r)).max(2);
    let scene = raytracer::scene::load_scene(std::path::Path::new(path)).expect("a scene");
    let view = View::of_camera(
        &scene.camera,
        number(width),
        number(height),
        DepthRange::new(0.0, 1.0),
    );
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let started = Instant::now();
            std::hint::black_box(render(&scene, &view).expect("renders"));
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    let first = times.remove(0);
    times.sort_by(f64::total_cmp);
    println!("{first:.2} {:.2}", times[times.len() / 2]);
}
