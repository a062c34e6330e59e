//! The course's command run RUNS times in one process, as the binary runs it once
//! (`raytracer::cli::run::run`: load, draw and write the files): prints the first run's
//! `render_ms` (cold: a new process, its memory and thread pool fresh) and the median of the
//! others' (warm). The files go to a temporary folder. `cargo xtask report command-vs-cpp` puts them
//! beside the command's own figures:
//!
//! ```sh
//! cargo run --release --example command_time -- SCENE WIDTH HEIGHT DMIN DMAX [RUNS]
//! ```

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use raytracer::cli::{Command, parse_command};

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let [scene, width, height, depth_min, depth_max, rest @ ..] = arguments.as_slice() else {
        eprintln!("usage: command_time SCENE WIDTH HEIGHT DMIN DMAX [RUNS]");
        std::process::exit(2);
    };
    let runs: usize = rest
        .first()
        .map_or(21, |r| r.parse().expect("a whole number"));
    let folder = tempfile::tempdir().expect("a temporary folder");
    let colour = folder.path().join("c.tga");
    let depth = folder.path().join("d.tga");
    let line = [
        "-input",
        scene,
        "-size",
        width,
        height,
        "-output",
        colour.to_str().expect("a path in UTF-8"),
        "-depth",
        depth_min,
        depth_max,
        depth.to_str().expect("a path in UTF-8"),
    ];
    let Ok(Command::Render(request)) = parse_command(line) else {
        panic!("a render request: {line:?}");
    };
    let mut render_ms: Vec<f64> = (0..runs.max(2))
        .map(|_| {
            let report = raytracer::cli::run::run(&request).expect("the command runs");
            let stats = report.stats_lines();
            let value = stats
                .lines()
                .find_map(|line| line.strip_prefix("render_ms: "))
                .expect("render_ms in the stats");
            value.parse().expect("a number")
        })
        .collect();
    let first = render_ms.remove(0);
    render_ms.sort_by(f64::total_cmp);
    println!("{first:.2} {:.2}", render_ms[render_ms.len() / 2]);
}
