//! `raytracer`: the course-compatible command line. With `-output`/`-depth` it renders without a
//! window; otherwise it opens the viewer (feature `gui`). Exit status: 0 success, 1 scene or file
//! error, 2 usage error, 3 compared images differ (`-compare_output`, `-compare_depth`),
//! 128 + n when stopped by signal n.

#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[cfg(not(target_arch = "wasm32"))]
use std::process::ExitCode;

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[cfg(not(target_arch = "wasm32"))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[cfg(not(target_arch = "wasm32"))]
use raytracer::{
    cli::{Command, VERSION_LINE, parse_command, usage},
    output::atomic::remove_temporary_files,
    platform::console::{PrintError, one_line, print_err, print_out},
    platform::process::{OnSignal, handle_termination_signals, start_thread_pool},
};

/// In a browser page the viewer is started by the page's script, through this handle
/// (`cargo xtask web` builds the page).
#[cfg(all(target_arch = "wasm32", feature = "gui"))]
pub use raytracer::app::start::page::WebHandle;

/// In a browser page there is no command line: the page's script starts the viewer.
#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    let command = match parse_command(std::env::args_os().skip(1)) {
        Ok(command) => command,
        Err(error) => {
            print_err(&format!("raytracer: {}\n", one_line(&error.to_string())));
            if error.wants_usage() {
                print_err(&format!("\n{}", usage()));
            }
            return ExitCode::from(2);
        }
    };
    if let Err(error) = start_thread_pool() {
        print_err(&format!(
            "raytracer: cannot start the rendering threads: {error}\n"
        ));
        return ExitCode::from(1);
    }
    match command {
        Command::Help => print_or_fail(&usage(), ExitCode::SUCCESS),
        Command::Version => print_or_fail(&format!("{VERSION_LINE}\n"), ExitCode::SUCCESS),
        Command::Render(request) => {
            handle_termination_signals(OnSignal::Exit, remove_temporary_files);
            match raytracer::cli::run::run(&request) {
                Ok(mut report) => {
                    let json = request.answer_as_json();
                    // The trace's text is moved, not copied: over a million spheres it is some
                    // 150 MB, made with room for what follows it.
                    let mut text = if json {
                        String::new()
                    } else {
                        report.trace.take().unwrap_or_default()
                    };
                    if request.stats && !json {
                        text.push_str(&report.stats_lines());
                    }
                    let mut status = ExitCode::SUCCESS;
                    if let Some(compared) = &report.compare {
                        if json {
                            let stats = request.stats.then(|| report.stats_lines());
                            text.push_str(
                                &compared.json(stats.as_deref(), report.trace.as_deref()),
                            );
                        } else {
                            text.push_str(&compared.lines());
                        }
                        if !compared.matches() {
                            status = ExitCode::from(3);
                        }
                    }
                    if text.is_empty() {
                        status
                    } else {
                        print_or_fail(&text, status)
                    }
                }
                Err(error) => {
                    // Stopped by a signal: its clean-up removed what this was writing.
                    raytracer::platform::process::end_as_stopped_if_asked();
                    print_err(&format!("raytracer: {}\n", one_line(&error.to_string())));
                    ExitCode::from(error.exit_status())
                }
            }
        }
        Command::Grade(request) => {
            handle_termination_signals(OnSignal::Exit, raytracer::grade::remove_unfinished_report);
            match raytracer::grade::grade(&request) {
                Ok(class) => print_or_fail(
                    &format!(
                        "{}\nreport: {}\n",
                        class.summary(),
                        request.report.join("index.html").display()
                    ),
                    ExitCode::SUCCESS,
                ),
                Err(error) => {
                    // Stopped by a signal: its clean-up removed what this was writing.
                    raytracer::platform::process::end_as_stopped_if_asked();
                    print_err(&format!("raytracer: {}\n", one_line(&error.to_string())));
                    ExitCode::from(1)
                }
            }
        }
        Command::View(mut request) => {
            request.program = std::env::current_exe().ok();
            open_viewer(request)
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
/// Prints `text` to standard output and ends with `status`: quietly if the reader has gone (a
/// closed pipe), with a one-line error (status 1) if the output cannot be written.
fn print_or_fail(text: &str, status: ExitCode) -> ExitCode {
    match print_out(text) {
        Ok(()) | Err(PrintError::Closed) => status,
        Err(PrintError::Failed(error)) => {
            print_err(&format!(
                "raytracer: cannot write to standard output: {error}\n"
            ));
            ExitCode::from(1)
        }
    }
}

#[cfg(all(feature = "gui", not(target_arch = "wasm32")))]
fn open_viewer(request: raytracer::cli::ViewerRequest) -> ExitCode {
    // A scene file that cannot be read is said first, whatever the display.
    if let Some(input) = &request.input
        && let Err(error) = std::fs::metadata(input)
    {
        print_err(&format!(
            "raytracer: {}\n",
            one_line(&format!("{}: {error}", input.display()))
        ));
        return ExitCode::from(1);
    }
    if let Some(problem) = raytracer::app::start::window::environment_problem() {
        print_err(&format!("raytracer: {problem}\n"));
        return ExitCode::from(2);
    }
    if let Some(reason) = raytracer::app::start::window::no_display_reason() {
        print_err(&format!("raytracer: {reason}\n"));
        return ExitCode::from(1);
    }
    handle_termination_signals(OnSignal::CloseViewer, remove_temporary_files);
    let outcome = raytracer::app::start::window::run(request);
    remove_temporary_files();
    if let Some(signal) = raytracer::platform::process::stop_requested() {
        return ExitCode::from(raytracer::platform::process::exit_status_of(signal));
    }
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            print_err(&format!(
                "raytracer: {}\n",
                one_line(&format!("cannot open the viewer window: {error}"))
            ));
            ExitCode::from(1)
        }
    }
}

#[cfg(all(not(feature = "gui"), not(target_arch = "wasm32")))]
fn open_viewer(_request: raytracer::cli::ViewerRequest) -> ExitCode {
    print_err(
        "raytracer: this build has no viewer (built without feature 'gui'); \
         give -output FILE and/or -depth DMIN DMAX FILE to render without a window\n",
    );
    ExitCode::from(2)
}
