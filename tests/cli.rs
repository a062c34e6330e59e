//! The real `raytracer` binary in a temporary folder: exit statuses (0 ok, 1 scene or file
//! error, 2 usage), one-line messages, and nothing written when a run fails. The cases shared
//! with the Windows `.exe` are in `tests/common/cli_cases.rs`; this file runs them against the
//! native binary and holds the ones only it runs.

#[path = "common/cli_cases.rs"]
mod cli_cases;
#[path = "common/command.rs"]
mod command;
#[path = "common/program.rs"]
mod program;

use program::Program;

use command::{names_in, stderr};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

fn run(folder: &Path, arguments: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap()
}

// The cases the Windows `.exe` runs too (`tests/common/cli_cases.rs`), against this binary.

#[test]
fn renders_and_exits_zero() {
    cli_cases::renders_and_exits_zero(&Program::native());
}

#[test]
fn either_output_alone_is_enough() {
    cli_cases::either_output_alone_is_enough(&Program::native());
}

#[test]
fn usage_errors_exit_two_with_one_line_and_write_nothing() {
    cli_cases::usage_errors_exit_two_with_one_line_and_write_nothing(&Program::native());
}

#[test]
fn scene_and_file_errors_exit_one_with_their_line_and_column() {
    cli_cases::scene_and_file_errors_exit_one_with_their_line_and_column(&Program::native());
}

#[test]
fn an_unwritable_output_leaves_every_old_file_as_it_was() {
    cli_cases::an_unwritable_output_leaves_every_old_file_as_it_was(&Program::native());
}

#[test]
fn an_output_that_names_the_input_or_another_output_is_refused() {
    cli_cases::an_output_that_names_the_input_or_another_output_is_refused(&Program::native());
}

#[test]
fn comparing_exits_zero_on_the_courses_image_and_three_on_another() {
    cli_cases::comparing_exits_zero_on_the_courses_image_and_three_on_another(&Program::native());
}

#[test]
fn help_prints_usage_and_exits_zero() {
    cli_cases::help_prints_usage_and_exits_zero(&Program::native());
}

#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    cli_cases::a_closed_pipe_ends_the_program_quietly(&Program::native());
}

#[test]
fn version_prints_the_version_and_the_commit_built_from() {
    // The commit, asked of git here (the binary was built from this checkout): the test's own
    // answer, not the build script's.
    let head = Command::new("git")
        .args(["rev-parse", "--short=12", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()
        .filter(|output| output.status.success())
        .map(|output| String::from_utf8_lossy(&output.stdout).trim().to_owned());
    let folder = tempfile::tempdir().unwrap();
    for flag in ["-version", "--version"] {
        let output = run(folder.path(), &[flag]);
        assert!(output.status.success(), "{flag}");
        let text = String::from_utf8(output.stdout).unwrap();
        let prefix = format!("raytracer {} (commit ", env!("CARGO_PKG_VERSION"));
        let commit = text
            .strip_prefix(&prefix)
            .and_then(|rest| rest.strip_suffix(")\n"))
            .unwrap_or_else(|| panic!("{flag}: {text:?}"));
        match &head {
            // A build with uncommitted changes says so after the commit.
            Some(head) => assert!(
                commit == head || commit == format!("{head}+changes"),
                "{flag}: {commit} is not {head}"
            ),
            None => assert_eq!(commit, "unknown", "{flag}: outside a git checkout"),
        }
    }
    assert_eq!(names_in(folder.path()), Vec::<String>::new());
}

#[test]
fn lossless_depth_files_hold_the_exact_t() {
    let folder = tempfile::tempdir().unwrap();
    let scene_file = scene_path("scene1_03.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene_file.to_str().unwrap(),
            "-size",
            "40",
            "30",
            "-depth_raw",
            "t.pfm",
            "-depth16",
            "8",
            "12",
            "d16.png",
            "-depth_colormap",
            "turbo",
            "-depth",
            "8",
            "12",
            "d.png",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let exr = run(
        folder.path(),
        &[
            "-input",
            scene_file.to_str().unwrap(),
            "-size",
            "40",
            "30",
            "-depth_raw",
            "t.exr",
        ],
    );
    assert!(exr.status.success(), "{}", stderr(&exr));
    assert_eq!(
        names_in(folder.path()),
        ["d.png", "d16.png", "t.exr", "t.pfm"]
    );

    let scene = raytracer::scene::load_scene(&scene_file).unwrap();
    let view = raytracer::render::View::of_camera(
        &scene.camera,
        40,
        30,
        raytracer::render::depth_map::DepthRange::new(8.0, 12.0),
    );
    let frame = raytracer::render::render(&scene, &view).unwrap();
    for name in ["t.pfm", "t.exr"] {
        let raw = raytracer::output::depth_file::read_raw_depth(&folder.path().join(name)).unwrap();
        assert_eq!((raw.width_px, raw.height_px), (40, 30), "{name}");
        let mut hits = 0;
        // Both are top row first.
        for (index, (&got, &t)) in raw.t.iter().zip(&frame.t).enumerate() {
            let expected = t as f32;
            assert!(
                got == expected || (got.is_infinite() && expected.is_infinite()),
                "{name} pixel {index}: {got} vs {expected}"
            );
            hits += usize::from(got.is_finite());
        }
        assert!(hits > 0 && hits < 40 * 30, "{name}: hits and misses");
    }
    let png16 = image::open(folder.path().join("d16.png")).unwrap();
    assert!(matches!(png16, image::DynamicImage::ImageLuma16(_)));
    let turbo = image::open(folder.path().join("d.png")).unwrap().to_rgb8();
    assert!(
        turbo.pixels().any(|p| p[0] != p[1] || p[1] != p[2]),
        "a colour map gives colours"
    );
}

#[test]
fn a_raw_depth_file_of_unknown_format_is_a_usage_error() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    let output = run(
        folder.path(),
        &["-input", scene.to_str().unwrap(), "-depth_raw", "t.tiff"],
    );
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("unknown format"),
        "{}",
        stderr(&output)
    );
    assert!(names_in(folder.path()).is_empty());
}

#[test]
fn the_removed_precision_flag_is_refused_and_nothing_is_written() {
    // The f32 and auto modes were removed (slower than f64 as well as less exact); a script that
    // still passes -precision gets a one-line usage error, and no image appears.
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-output",
            "c.tga",
            "-precision",
            "f32",
        ],
    );
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("unknown flag '-precision'"),
        "{}",
        stderr(&output)
    );
    assert!(names_in(folder.path()).is_empty());
}

#[test]
fn images_over_64_megapixels_are_refused() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    for size in [["8192", "8193"], ["16385", "1"], ["16384", "4097"]] {
        let output = run(
            folder.path(),
            &[
                "-input",
                scene.to_str().unwrap(),
                "-size",
                size[0],
                size[1],
                "-output",
                "c.png",
            ],
        );
        assert_eq!(output.status.code(), Some(2), "{size:?}");
        let text = stderr(&output);
        assert!(
            text.contains("out of range") && text.contains("67108864"),
            "{size:?}: {text}"
        );
    }
    assert!(names_in(folder.path()).is_empty());
}

#[test]
fn no_progress_bar_when_stderr_is_not_a_terminal() {
    // A load that takes a second (a named pipe fed slowly): on a terminal it would show a
    // progress bar after half a second; into a pipe, stderr stays empty.
    let folder = tempfile::tempdir().unwrap();
    let pipe = folder.path().join("slow.txt");
    assert!(
        Command::new("mkfifo")
            .arg(&pipe)
            .status()
            .unwrap()
            .success()
    );
    let text = std::fs::read(scene_path("scene1_02.txt")).unwrap();
    let writer = {
        let pipe = pipe.clone();
        std::thread::spawn(move || {
            use std::io::Write as _;
            let mut file = std::fs::OpenOptions::new().write(true).open(pipe).unwrap();
            file.write_all(&text[..40]).unwrap();
            file.flush().unwrap();
            std::thread::sleep(std::time::Duration::from_millis(1200));
            file.write_all(&text[40..]).unwrap();
        })
    };
    let output = run(folder.path(), &["-input", "slow.txt", "-output", "c.png"]);
    writer.join().unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(stderr(&output), "", "nothing on stderr");
}
