//! The command line's promises as cases, each run against a [`Program`]: `tests/cli.rs` runs every
//! one against the native binary, `tests/windows_exe.rs` against the Windows `.exe` under Wine.
//! Each case works in a temporary folder with relative paths, as a user types them, and asserts
//! what the user sees: the exit status (0 done, 1 scene or file error, 2 usage, 3 a comparison
//! that differs), the one-line message, and the files (nothing written on error, every old file
//! as it was). Where the platforms differ (a path's separator, names that differ by case, a
//! read-only file) the case asks the program.
//!
//! `tests/layout.rs` checks that both runners run every case here.
#![allow(dead_code)] // a runner that lacks a case fails the layout test, not the build

use super::command::{names_in, scene_path};
use super::program::Program;
use std::path::Path;
use std::process::Stdio;

fn project_path(relative: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

/// Copies the course scene `name` into `folder`.
fn scene_in(folder: &Path, name: &str) {
    std::fs::copy(scene_path(name), folder.join(name)).unwrap();
}

pub(crate) fn renders_and_exits_zero(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    let output = program.run(
        folder.path(),
        &[
            "-input",
            "scene1_02.txt",
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
    assert!(output.status.success(), "{}", program.stderr(&output));
    assert_eq!(names_in(folder.path()), ["c.png", "d.tga", "scene1_02.txt"]);
    let colour = image::open(folder.path().join("c.png")).unwrap();
    assert_eq!((colour.width(), colour.height()), (64, 48));
    let depth = image::open(folder.path().join("d.tga")).unwrap();
    assert_eq!((depth.width(), depth.height()), (64, 48));
}

pub(crate) fn either_output_alone_is_enough(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_01.txt");
    for (arguments, written) in [
        (vec!["-depth", "9", "10", "d.png"], "d.png"),
        (vec!["-output", "c.tga"], "c.tga"),
    ] {
        let output = program.run(
            folder.path(),
            &[&["-input", "scene1_01.txt"], arguments.as_slice()].concat(),
        );
        assert!(output.status.success(), "{}", program.stderr(&output));
        assert!(folder.path().join(written).is_file(), "{written}");
    }
    assert_eq!(names_in(folder.path()), ["c.tga", "d.png", "scene1_01.txt"]);
}

pub(crate) fn usage_errors_exit_two_with_one_line_and_write_nothing(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    let scene = "scene1_01.txt";
    scene_in(folder.path(), scene);
    let cases: &[&[&str]] = &[
        &["-input", scene, "-size", "200", "-output", "c.png"],
        &["-input", scene, "-size", "200", "two", "-output", "c.png"],
        &["-input", scene, "-output", "c.bmp"],
        &["-input", scene, "-output", "c.png", "-bogus"],
        &["-input", scene, "-depth", "9", "x", "d.png"],
        &["-output", "c.png"],
    ];
    for arguments in cases {
        let output = program.run(folder.path(), arguments);
        let message = program.stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{arguments:?}: {message}");
        assert!(message.starts_with("raytracer: "), "{message}");
        // One line; an unknown flag adds the usage text after a blank line.
        if arguments.contains(&"-bogus") {
            assert!(message.contains("\nusage:"), "{message}");
        } else {
            assert_eq!(message.lines().count(), 1, "{arguments:?}: {message}");
        }
    }
    assert_eq!(names_in(folder.path()), [scene]);
}

pub(crate) fn scene_and_file_errors_exit_one_with_their_line_and_column(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    // The same mistake with Unix and with Windows line endings: the same line and column.
    for ending in ["\n", "\r\n"] {
        let scene = [
            "OrthographicCamera {",
            " center 0 0 10",
            " direction 0 0 -1",
        ]
        .into_iter()
        .chain([" up 0 1 0", "}", ""])
        .collect::<Vec<_>>()
        .join(ending);
        std::fs::write(folder.path().join("broken.txt"), scene).unwrap();
        let output = program.run(folder.path(), &["-input", "broken.txt", "-output", "c.png"]);
        assert_eq!(output.status.code(), Some(1), "{ending:?}");
        assert_eq!(
            program.stderr(&output),
            "raytracer: broken.txt:5:1: expected 'size', found '}'\n",
            "{ending:?}"
        );
    }
    let output = program.run(
        folder.path(),
        &["-input", "missing.txt", "-output", "c.png"],
    );
    assert_eq!(output.status.code(), Some(1));
    let message = program.stderr(&output);
    assert!(message.starts_with("raytracer: missing.txt: "), "{message}");
    assert_eq!(message.lines().count(), 1, "{message}");
    scene_in(folder.path(), "scene1_01.txt");
    let nowhere = program.path(&["no", "such", "dir", "c.png"]);
    let output = program.run(
        folder.path(),
        &["-input", "scene1_01.txt", "-output", &nowhere],
    );
    assert_eq!(output.status.code(), Some(1));
    let message = program.stderr(&output);
    assert!(
        message.starts_with(&format!("raytracer: {nowhere}: cannot write")),
        "{message}"
    );
    assert_eq!(names_in(folder.path()), ["broken.txt", "scene1_01.txt"]);
}

pub(crate) fn an_unwritable_output_leaves_every_old_file_as_it_was(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_01.txt");
    std::fs::create_dir(folder.path().join("folder.png")).unwrap();
    std::fs::write(folder.path().join("c.png"), b"old colour").unwrap();
    let mut destinations = vec![program.path(&["missing", "d.png"]), "folder.png".to_owned()];
    let mut names = vec!["c.png", "folder.png", "scene1_01.txt"];
    // A read-only file: Windows does not replace it (where the tests run as root, Linux would).
    let read_only = folder.path().join("read-only.png");
    if program.is_windows() {
        std::fs::write(&read_only, b"old depth").unwrap();
        let mut permissions = std::fs::metadata(&read_only).unwrap().permissions();
        permissions.set_readonly(true);
        std::fs::set_permissions(&read_only, permissions).unwrap();
        destinations.push("read-only.png".to_owned());
        names.insert(2, "read-only.png");
    }
    for depth in &destinations {
        let output = program.run(
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
        let message = program.stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{message}");
        assert!(
            message.starts_with(&format!("raytracer: {depth}: cannot write")),
            "{message}"
        );
        assert_eq!(message.lines().count(), 1, "{message}");
        assert_eq!(
            std::fs::read(folder.path().join("c.png")).unwrap(),
            b"old colour",
            "{depth}: c.png was replaced"
        );
        if program.is_windows() {
            assert_eq!(std::fs::read(&read_only).unwrap(), b"old depth");
        }
        assert_eq!(names_in(folder.path()), names, "{depth}");
    }
}

pub(crate) fn an_output_that_names_the_input_or_another_output_is_refused(program: &Program) {
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
    let here = program.path(&[".", "s.tga"]);
    let round = program.path(&["sub", "..", "out.tga"]);
    let mut cases = vec![
        vec!["-input", "s.tga", "-output", &here],
        vec!["-input", "s.tga", "-depth", "8", "12", "hard.png"],
        colour_then_depth(&round),
    ];
    if program.folds_case() {
        cases.push(vec!["-input", "s.tga", "-output", "S.TGA"]);
        cases.push(colour_then_depth("OUT.tga"));
    }
    for arguments in cases {
        let output = program.run(folder.path(), &arguments);
        let message = program.stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{arguments:?}: {message}");
        assert!(message.contains("same file"), "{arguments:?}: {message}");
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

/// Scene 1-02 into `out.tga` and its depth into `depth`.
fn colour_then_depth(depth: &str) -> Vec<&str> {
    vec![
        "-input",
        "scene1_02.txt",
        "-output",
        "out.tga",
        "-depth",
        "8",
        "12",
        depth,
    ]
}

pub(crate) fn comparing_exits_zero_on_the_courses_image_and_three_on_another(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    for (reference, status, matched) in [("output1_02.png", 0, "yes"), ("output1_04.png", 3, "no")]
    {
        std::fs::copy(
            project_path(&format!("tests/reference/{reference}")),
            folder.path().join(reference),
        )
        .unwrap();
        let output = program.run(
            folder.path(),
            &["-input", "scene1_02.txt", "-compare_output", reference],
        );
        let message = program.stderr(&output);
        assert_eq!(output.status.code(), Some(status), "{reference}: {message}");
        let text = String::from_utf8_lossy(&output.stdout);
        assert!(
            text.lines().any(|line| line == format!("match: {matched}")),
            "{reference}: {text}"
        );
    }
}

pub(crate) fn help_prints_usage_and_exits_zero(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    let output = program.run(folder.path(), &["-help"]);
    assert!(output.status.success(), "{}", program.stderr(&output));
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(text.contains("-depth DMIN DMAX FILE"), "{text}");
    // The colour maps' names come from the map's own list, never a placeholder.
    assert!(
        text.contains("depth image colours: grey, turbo or viridis (default grey)"),
        "{text}"
    );
    assert!(!text.contains('{'), "{text}");
    assert!(names_in(folder.path()).is_empty());
}

pub(crate) fn a_closed_pipe_ends_the_program_quietly(program: &Program) {
    let folder = tempfile::tempdir().unwrap();
    scene_in(folder.path(), "scene1_02.txt");
    for arguments in [
        vec!["-help"],
        vec!["-input", "scene1_02.txt", "-output", "c.png", "-stats"],
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let output = program
            .command()
            .current_dir(folder.path())
            .args(&arguments)
            .stdout(writer)
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        let message = program.stderr(&output);
        assert_eq!(output.status.code(), Some(0), "{arguments:?}: {message}");
        assert_eq!(message, "", "{arguments:?}: quiet");
    }
    assert!(folder.path().join("c.png").is_file(), "the render went on");
    // A usage error with standard error closed: still exit 2.
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let output = program
        .command()
        .current_dir(folder.path())
        .arg("-bogus")
        .stderr(writer)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
}
