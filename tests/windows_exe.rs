//! The Windows build of the command line (`raytracer.exe`, x86_64-pc-windows-gnu, built without
//! the viewer) run under Wine: the promises of the command line that make sense on Windows. The
//! course's seven commands write the bytes the Linux binary writes (and the course's colour
//! images); bad scenes are refused with line and column; usage errors, comparisons, an output
//! that names the input or another output (case aside, as Windows names files); an unwritable
//! destination or one that another program holds open leaves every old file as it was; a
//! closed pipe ends the program quietly.
//!
//! `bash scripts/windows.sh test` builds the .exe and its test scaffolding and runs these with
//! `RAYTRACER_WINDOWS_EXE` naming it; a plain `cargo test` leaves them out (ignored).

#[path = "common/command.rs"]
mod command;

#[path = "../examples/support/course.rs"]
mod course;

use command::names_in;
use std::io::{BufRead as _, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The Windows binary under test.
fn exe() -> PathBuf {
    let exe = std::env::var_os("RAYTRACER_WINDOWS_EXE").expect(
        "RAYTRACER_WINDOWS_EXE names the Windows raytracer.exe (bash scripts/windows.sh test)",
    );
    PathBuf::from(exe)
}

/// The program's standard error without Wine's own lines: Wine itself sometimes reports a
/// hiccup of its client (one CI run got "wine client error:1ac: sendmsg: Socket operation on
/// non-socket" after the program's own message), which is not the program's output.
fn stderr(output: &Output) -> String {
    command::stderr(output)
        .split_inclusive('\n')
        .filter(|line| !line.starts_with("wine client error:"))
        .collect()
}

fn wine(program: &Path) -> Command {
    let mut command = Command::new("wine");
    command.arg(program).env("WINEDEBUG", "-all");
    command
}

/// The .exe in `folder` with `arguments` (paths relative to the folder, as a Windows user types
/// them).
fn run(folder: &Path, arguments: &[&str]) -> Output {
    wine(&exe())
        .current_dir(folder)
        .args(arguments)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

fn project_path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

/// Copies the course scene `name` into `folder`.
fn scene_in(folder: &Path, name: &str) {
    std::fs::copy(project_path(&format!("scenes/{name}")), folder.join(name)).unwrap();
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
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

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn a_malformed_scene_is_refused_with_its_line_and_column() {
    let folder = tempfile::tempdir().unwrap();
    std::fs::write(
        folder.path().join("broken.txt"),
        "OrthographicCamera {\r\n center 0 0 10\r\n direction 0 0 -1\r\n up 0 1 0\r\n}\r\n",
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
    assert_eq!(names_in(folder.path()), ["broken.txt"]);
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn usage_errors_exit_two_with_one_line_and_write_nothing() {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_01.txt");
    let scene = "scene1_01.txt";
    let cases: &[&[&str]] = &[
        &["-input", scene, "-size", "200", "-output", "c.png"],
        &["-input", scene, "-size", "200", "two", "-output", "c.png"],
        &["-input", scene, "-output", "c.bmp"],
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
        assert_eq!(message.lines().count(), 1, "{arguments:?}: {message}");
    }
    assert_eq!(names_in(folder.path()), [scene]);
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn comparing_exits_zero_on_the_courses_image_and_three_on_another() {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    for (reference, status, matched) in [("output1_02.png", 0, "yes"), ("output1_04.png", 3, "no")]
    {
        std::fs::copy(
            project_path(&format!("tests/reference/{reference}")),
            folder.path().join(reference),
        )
        .unwrap();
        let output = run(
            folder.path(),
            &["-input", "scene1_02.txt", "-compare_output", reference],
        );
        assert_eq!(
            output.status.code(),
            Some(status),
            "{reference}: {}",
            stderr(&output)
        );
        let text = String::from_utf8_lossy(&output.stdout);
        assert!(
            text.lines().any(|line| line == format!("match: {matched}")),
            "{reference}: {text}"
        );
    }
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn an_output_that_names_the_input_or_another_output_is_refused() {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    std::fs::copy(
        folder.path().join("scene1_02.txt"),
        folder.path().join("s.tga"),
    )
    .unwrap();
    std::fs::hard_link(folder.path().join("s.tga"), folder.path().join("hard.png")).unwrap();
    std::fs::create_dir(folder.path().join("sub")).unwrap();
    let original = std::fs::read(folder.path().join("s.tga")).unwrap();
    for arguments in [
        vec!["-input", "s.tga", "-output", ".\\s.tga"],
        vec!["-input", "s.tga", "-output", "S.TGA"],
        vec!["-input", "s.tga", "-depth", "8", "12", "hard.png"],
        vec![
            "-input",
            "scene1_02.txt",
            "-output",
            "out.tga",
            "-depth",
            "8",
            "12",
            "sub\\..\\out.tga",
        ],
        vec![
            "-input",
            "scene1_02.txt",
            "-output",
            "out.tga",
            "-depth",
            "8",
            "12",
            "OUT.tga",
        ],
    ] {
        let output = run(folder.path(), &arguments);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains("same file"),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert_eq!(
            std::fs::read(folder.path().join("s.tga")).unwrap(),
            original
        );
    }
    assert_eq!(
        names_in(folder.path()),
        ["hard.png", "s.tga", "scene1_02.txt", "sub"]
    );
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn an_unwritable_destination_leaves_every_old_file_as_it_was() {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_01.txt");
    std::fs::create_dir(folder.path().join("folder.png")).unwrap();
    std::fs::write(folder.path().join("c.png"), b"old colour").unwrap();
    // A read-only file: Windows does not replace it.
    let read_only = folder.path().join("read-only.png");
    std::fs::write(&read_only, b"old depth").unwrap();
    let mut permissions = std::fs::metadata(&read_only).unwrap().permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&read_only, permissions).unwrap();
    for depth in ["missing\\d.png", "folder.png", "read-only.png"] {
        let output = run(
            folder.path(),
            &[
                "-input",
                "scene1_01.txt",
                "-output",
                "c.png",
                "-depth",
                "9",
                "10",
                depth,
            ],
        );
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        let message = stderr(&output);
        assert!(
            message.starts_with(&format!("raytracer: {depth}: cannot write")),
            "{message}"
        );
        assert_eq!(message.lines().count(), 1, "{message}");
        assert_eq!(
            std::fs::read(folder.path().join("c.png")).unwrap(),
            b"old colour",
            "{depth}"
        );
        assert_eq!(std::fs::read(&read_only).unwrap(), b"old depth");
        assert_eq!(
            names_in(folder.path()),
            ["c.png", "folder.png", "read-only.png", "scene1_01.txt"]
        );
    }
}

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
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

#[ignore = "runs the Windows .exe under Wine: bash scripts/windows.sh test"]
#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    for arguments in [
        vec!["-help"],
        vec!["-input", "scene1_02.txt", "-output", "c.png", "-stats"],
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let output = wine(&exe())
            .current_dir(folder.path())
            .args(&arguments)
            .stdout(writer)
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        assert_eq!(
            output.status.code(),
            Some(0),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert_eq!(stderr(&output), "", "{arguments:?}: quiet");
    }
    assert!(folder.path().join("c.png").is_file(), "the render went on");
}
