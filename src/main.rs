//! `raytracer`: the course-compatible command line. With `-output`/`-depth` it renders without a
//! window; otherwise it opens the viewer (feature `gui`). Exit status: 0 success, 1 scene or file
//! error, 2 usage error.

#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::ExitCode;

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use raytracer::cli::{Command, parse_command, usage};

fn main() -> ExitCode {
    let command = match parse_command(std::env::args_os().skip(1)) {
        Ok(command) => command,
        Err(error) => {
            eprintln!("raytracer: {error}");
            if error.wants_usage() {
                eprint!("\n{}", usage());
            }
            return ExitCode::from(2);
        }
    };
    match command {
        Command::Help => {
            print!("{}", usage());
            ExitCode::SUCCESS
        }
        Command::Render(request) => match raytracer::cli::run::run(&request) {
            Ok(report) => {
                if request.stats {
                    print!("{}", report.stats_lines());
                }
                ExitCode::SUCCESS
            }
            Err(error) => {
                eprintln!("raytracer: {error}");
                ExitCode::from(1)
            }
        },
        Command::View(request) => open_viewer(request),
    }
}

#[cfg(feature = "gui")]
fn open_viewer(request: raytracer::cli::ViewerRequest) -> ExitCode {
    match raytracer::app::run(request) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("raytracer: cannot open the viewer window: {error}");
            ExitCode::from(1)
        }
    }
}

#[cfg(not(feature = "gui"))]
fn open_viewer(_request: raytracer::cli::ViewerRequest) -> ExitCode {
    eprintln!(
        "raytracer: this build has no viewer (built without feature 'gui'); \
         give -output FILE and/or -depth DMIN DMAX FILE to render without a window"
    );
    ExitCode::from(2)
}
