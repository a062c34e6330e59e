//! How long a scene file takes to become a scene, two ways, interleaved RUNS times in one
//! process: *load* (`load_scene`: read the file and parse it, what the command line and the
//! viewer do) and *parse* (`parse_scene` of text already in memory). Prints the medians in
//! milliseconds, load first:
//!
//! ```sh
//! cargo run --release --example parse_time -- SCENE [RUNS]
//! ```

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::path::Path;
use std::time::Instant;

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = arguments.first() else {
        eprintln!("usage: parse_time SCENE [RUNS]");
        std::process::exit(2);
    };
    let runs: usize = arguments.get(1).and_then(|r| r.parse().ok()).unwrap_or(9);
    let text = std::fs::read_to_string(path).expect("a readable scene file");
    let (mut load, mut parse) = (Vec::new(), Vec::new());
    for _ in 0..runs {
        let started = Instant::now();
        std::hint::black_box(raytracer::scene::load_scene(Path::new(path)).expect("a valid scene"));
        load.push(started.elapsed().as_secs_f64() * 1e3);
        let started = Instant::now();
        std::hint::black_box(raytracer::scene::parse_scene(&text).expect("a valid scene"));
        parse.push(started.elapsed().as_secs_f64() * 1e3);
    }
    println!("{:.1} {:.1}", median(load), median(parse));
}
