//! The Windows build of the command line (`raytracer.exe`, x86_64-pc-windows-gnu) run under
//! Wine. It runs every case of `tests/common/cli_cases.rs` (the same cases `tests/cli.rs` runs
//! against the native binary: exit statuses, one-line messages, bad scenes with line and column,
//! outputs that name the input or each other, with Windows' spellings and case folding, and
//! unwritable destinations, read-only files included), and the two only Windows has: the
//! course's seven commands write the bytes the Linux binary writes (and the course's colour
//! images), and a file another program holds open is not replaced.
//!
//! `cargo xtask windows test` builds the .exe and its test scaffolding and runs these with
//! `RAYTRACER_WINDOWS_EXE` naming it; a plain `cargo test` leaves them out (ignored).

#[path = "common/cli_cases.rs"]
mod cli_cases;
#[path = "common/command.rs"]
mod command;
#[path = "../examples/support/course.rs"]
mod course;
#[path = "common/program.rs"]
mod program;

use command::names_in;
use program::{Program, windows_exe as exe, wine};
use std::io::{BufRead as _, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The program's standard error without Wine's own lines.
fn stderr(output: &Output) -> String {
    Program::windows().stderr(output)
}

/// The .exe in `folder` with `arguments` (paths relative to the folder, as a Windows user types
/// them).
fn run(folder: &Path, arguments: &[&str]) -> Output {
    Program::windows().run(folder, arguments)
}

fn project_path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

/// Copies the course scene `name` into `folder`.
fn scene_in(folder: &Path, name: &str) {
    std::fs::copy(project_path(&format!("scenes/{name}")), folder.join(name)).unwrap();
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn the_course_commands_write_the_linux_binarys_bytes_and_the_courses_colours() {
    let windows = tempfile::tempdir().unwrap();
    let linux = tempfile::tempdir().unwrap();
    let sizes: [(&str, &str); 2] = [("200", "200"), ("203", "61")];
    for (number, depth_min, depth_max) in course::runs() {
        let (depth_min, depth_max) = (depth_min.as_str(), depth_max.as_str());
        let scene = format!("scene1_0{number}.txt");
        scene_in(windows.path(), &scene);
        scene_in(linux.path(), &scene);
        for (width, height) in sizes {
            let colour = format!("output1_0{number}_{width}.tga");
            let depth = format!("depth1_0{number}_{width}.tga");
            let arguments = [
                "-input", &scene, "-size", width, height, "-output", &colour, "-depth", depth_min,
                depth_max, &depth,
            ];
            let output = run(windows.path(), &arguments);
            assert!(output.status.success(), "{scene}: {}", stderr(&output));
            let status = Command::new(env!("CARGO_BIN_EXE_raytracer"))
                .current_dir(linux.path())
                .args(arguments)
                .status()
                .unwrap();
            assert!(status.success(), "{scene} on Linux");
            for name in [&colour, &depth] {
                let ours = std::fs::read(windows.path().join(name)).unwrap();
                let theirs = std::fs::read(linux.path().join(name)).unwrap();
                assert!(ours == theirs, "{name}: the Windows and Linux files differ");
            }
        }
        // The course's own colour image, pixel for pixel.
        let ours = image::open(windows.path().join(format!("output1_0{number}_200.tga")))
            .unwrap()
            .to_rgb8();
        let reference = image::open(project_path(&format!(
            "tests/reference/output1_0{number}.png"
        )))
        .unwrap()
        .to_rgb8();
        assert!(
            ours == reference,
            "scene1_0{number}: colour differs from the course's"
        );
    }
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn a_file_another_program_holds_open_is_not_replaced_and_the_error_says_why() {
    /// `hold_open.exe` holding a file, ended when dropped (also when an assertion fails).
    struct Holder(std::process::Child);
    impl Drop for Holder {
        fn drop(&mut self) {
            drop(self.0.stdin.take());
            let _ = self.0.wait();
        }
    }
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    // Another Windows program holds one of the images open (no sharing of writes or deletes):
    // the first output, then the second, which is replaced after the first.
    for held in ["c.tga", "d.tga"] {
        std::fs::write(folder.path().join("c.tga"), b"old colour").unwrap();
        std::fs::write(folder.path().join("d.tga"), b"old depth").unwrap();
        let mut child = wine(&exe().with_file_name("hold_open.exe"))
            .current_dir(folder.path())
            .arg(held)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        let mut said = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut said)
            .unwrap();
        let holder = Holder(child);
        assert_eq!(said.trim(), "held");
        let output = run(
            folder.path(),
            &[
                "-input",
                "scene1_02.txt",
                "-size",
                "40",
                "40",
                "-output",
                "c.tga",
                "-depth",
                "8",
                "12",
                "d.tga",
            ],
        );
        drop(holder);
        assert_eq!(output.status.code(), Some(1), "{held}: {}", stderr(&output));
        let message = stderr(&output);
        assert_eq!(message.lines().count(), 1, "{message}");
        assert!(
            message.starts_with(&format!("raytracer: {held}: cannot write: "))
                && message.contains("another program has the file open"),
            "{message}"
        );
        let now = std::fs::read(folder.path().join("c.tga")).unwrap();
        assert!(now == b"old colour", "{held}: c.tga was replaced");
        let now = std::fs::read(folder.path().join("d.tga")).unwrap();
        assert!(now == b"old depth", "{held}: d.tga was replaced");
        assert_eq!(
            names_in(folder.path()),
            ["c.tga", "d.tga", "scene1_02.txt"],
            "{held}: no temporary left"
        );
    }
}

// The cases the native binary runs too (`tests/common/cli_cases.rs`), against the `.exe`.

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn renders_and_exits_zero() {
    cli_cases::renders_and_exits_zero(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn either_output_alone_is_enough() {
    cli_cases::either_output_alone_is_enough(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn usage_errors_exit_two_with_one_line_and_write_nothing() {
    cli_cases::usage_errors_exit_two_with_one_line_and_write_nothing(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn scene_and_file_errors_exit_one_with_their_line_and_column() {
    cli_cases::scene_and_file_errors_exit_one_with_their_line_and_column(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn an_unwritable_output_leaves_every_old_file_as_it_was() {
    cli_cases::an_unwritable_output_leaves_every_old_file_as_it_was(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn an_output_that_names_the_input_or_another_output_is_refused() {
    cli_cases::an_output_that_names_the_input_or_another_output_is_refused(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn comparing_exits_zero_on_the_courses_image_and_three_on_another() {
    cli_cases::comparing_exits_zero_on_the_courses_image_and_three_on_another(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn help_prints_usage_and_exits_zero() {
    cli_cases::help_prints_usage_and_exits_zero(&Program::windows());
}

#[ignore = "runs the Windows .exe under Wine: cargo xtask windows test"]
#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    cli_cases::a_closed_pipe_ends_the_program_quietly(&Program::windows());
}
