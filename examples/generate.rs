//! Writes a seeded random scene of N spheres (the benchmarks' workload) as a scene file:
//!
//! ```sh
//! cargo run --release --example generate -- 1000000 generated_1e6.txt [seed]
//! cargo run --release --example generate -- --dense 100000 dense_1e5.txt [seed]
//! ```
//!
//! The same (count, seed) always gives the same file; see `raytracer::oracle::random_scene` and,
//! with `--dense`, `raytracer::oracle::dense_scene` (every pixel covered many times over).

use std::process::ExitCode;

fn main() -> ExitCode {
    let mut arguments: Vec<String> = std::env::args().skip(1).collect();
    let dense = arguments.first().is_some_and(|a| a == "--dense");
    if dense {
        arguments.remove(0);
    }
    let (Some(count), Some(path)) = (arguments.first(), arguments.get(1)) else {
        eprintln!("usage: generate [--dense] COUNT FILE [SEED]");
        return ExitCode::from(2);
    };
    let Ok(count) = count.parse::<usize>() else {
        eprintln!("generate: COUNT must be a whole number, found '{count}'");
        return ExitCode::from(2);
    };
    let seed = match arguments.get(2).map(|s| s.parse::<u64>()) {
        None => 1,
        Some(Ok(seed)) => seed,
        Some(Err(_)) => {
            eprintln!("generate: SEED must be a whole number");
            return ExitCode::from(2);
        }
    };
    let scene = if dense {
        raytracer::oracle::dense_scene(seed, count)
    } else {
        raytracer::oracle::random_scene(seed, count)
    };
    let text = raytracer::scene::scene_to_text(&scene);
    match raytracer::output::write_atomically(std::path::Path::new(path), text.as_bytes()) {
        Ok(()) => {
            eprintln!(
                "wrote {count} spheres (seed {seed}) to {path}, {} bytes",
                text.len()
            );
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("generate: {error}");
            ExitCode::from(1)
        }
    }
}
