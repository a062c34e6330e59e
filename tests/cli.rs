//! The real `raytracer` binary in a temporary folder: exit statuses (0 ok, 1 scene or file
//! error, 2 usage), one-line messages, and nothing written when a run fails.

#[path = "common/command.rs"]
mod command;

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

#[test]
fn renders_and_exits_zero() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-size",
            "64",
            "48",
            "-output",
            "c.png",
            "-depth",
            "8",
            "12",
            "d.tga",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(names_in(folder.path()), ["c.png", "d.tga"]);
    let colour = image::open(folder.path().join("c.png")).unwrap();
    assert_eq!((colour.width(), colour.height()), (64, 48));
}

#[test]
fn either_output_alone_is_enough() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-depth",
            "9",
            "10",
            "d.png",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(names_in(folder.path()), ["d.png"]);
}

#[test]
fn usage_errors_exit_two_with_one_line_and_write_nothing() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    let scene = scene.to_str().unwrap();
    let cases: &[&[&str]] = &[
        &["-input", scene, "-size", "200", "-output", "c.png"],
        &["-input", scene, "-size", "200", "two", "-output", "c.png"],
        &["-input", scene, "-output", "c.bmp"],
        &["-input", scene, "-output", "c.png", "-bogus"],
        &["-input", scene, "-depth", "9", "x", "d.png"],
        &["-output", "c.png"],
    ];
    for arguments in cases {
        let output = run(folder.path(), arguments);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{arguments:?}: {}",
            stderr(&output)
        );
        let message = stderr(&output);
        assert!(message.starts_with("raytracer: "), "{message}");
        // One line; an unknown flag adds the usage text after a blank line.
        if arguments.contains(&"-bogus") {
            assert!(message.contains("\nusage:"), "{message}");
        } else {
            assert_eq!(message.lines().count(), 1, "{arguments:?}: {message}");
        }
    }
    assert!(names_in(folder.path()).is_empty());
}

#[test]
fn an_unwritable_output_is_refused_before_any_file_is_written() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    std::fs::create_dir(folder.path().join("folder.png")).unwrap();
    for depth in ["missing/d.png", "folder.png"] {
        let output = run(
            folder.path(),
            &[
                "-input",
                scene.to_str().unwrap(),
                "-output",
                "c.png",
                "-depth",
                "9",
                "10",
                depth,
            ],
        );
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        assert!(
            stderr(&output).contains("cannot write"),
            "{}",
            stderr(&output)
        );
        assert_eq!(
            names_in(folder.path()),
            ["folder.png"],
            "c.png must not be written"
        );
    }
}

#[test]
fn scene_and_file_errors_exit_one() {
    let folder = tempfile::tempdir().unwrap();
    std::fs::write(
        folder.path().join("broken.txt"),
        "OrthographicCamera {\n center 0 0 10\n direction 0 0 -1\n up 0 1 0\n}\n",
    )
    .unwrap();
    let output = run(folder.path(), &["-input", "broken.txt", "-output", "c.png"]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        stderr(&output),
        "raytracer: broken.txt:5:1: expected 'size', found '}'\n"
    );

    let output = run(
        folder.path(),
        &["-input", "missing.txt", "-output", "c.png"],
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).starts_with("raytracer: missing.txt: "),
        "{}",
        stderr(&output)
    );

    let scene = scene_path("scene1_01.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-output",
            "no/such/dir/c.png",
        ],
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("no/such/dir/c.png: cannot write"),
        "{}",
        stderr(&output)
    );
    assert_eq!(names_in(folder.path()), ["broken.txt"]);
}

#[test]
fn help_prints_usage_and_exits_zero() {
    let folder = tempfile::tempdir().unwrap();
    let output = run(folder.path(), &["-help"]);
    assert!(output.status.success());
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(text.contains("-depth DMIN DMAX FILE"), "{text}");
    // The colour maps' names come from the map's own list, never a placeholder.
    assert!(
        text.contains("depth image colours: grey, turbo or viridis (default grey)"),
        "{text}"
    );
    assert!(!text.contains('{'), "{text}");
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
