//! Images to compare that come from strangers, at the boundary where a user meets the command
//! line: the real binary in a temporary folder. A header announcing a huge image (a few bytes
//! standing for gigabytes of pixels) is refused before a pixel is decoded, under a memory limit
//! too; an image read from a named pipe is compared as the same bytes in a file are.
#![cfg(unix)]

#[path = "common/command.rs"]
mod command;
#[path = "common/png_header.rs"]
mod png_header;

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use command::{assert_one_line_error, binary, run_in, scene_path};
use png_header::png;

/// Runs the binary in `folder` with its address space limited to `bytes`.
fn run_limited(folder: &Path, bytes: u64, arguments: &[&str]) -> Output {
    Command::new("prlimit")
        .arg(format!("--as={bytes}:{bytes}"))
        .arg(binary())
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap()
}

#[test]
fn an_image_whose_header_announces_too_much_is_refused_before_it_is_decoded() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    let scene = scene.to_str().unwrap();
    // 16384×32767 (1.6 GB of pixels) behind a header and a few bytes; and 16000×16000, each side
    // within the limit but 768 MB of pixels.
    for (name, width, height, said) in [
        (
            "bomb.png",
            16_384,
            32_767,
            "announces an image larger than this program reads",
        ),
        (
            "wide.png",
            16_000,
            16_000,
            "16000×16000 pixels is more than this program reads",
        ),
    ] {
        std::fs::write(folder.path().join(name), png(width, height, &[0x78, 0x9c])).unwrap();
        for limit in [None, Some(1_500_000_000)] {
            let arguments = ["-input", scene, "-compare_output", name];
            let started = Instant::now();
            let output = match limit {
                None => run_in(folder.path(), &arguments),
                Some(bytes) => run_limited(folder.path(), bytes, &arguments),
            };
            let text = assert_one_line_error(&output);
            assert_eq!(output.status.code(), Some(1), "{name} {limit:?}: {text}");
            assert!(
                text.contains(name) && text.contains(said),
                "{name} {limit:?}: {text}"
            );
            assert!(
                started.elapsed() < Duration::from_secs(20),
                "{name}: refused only after {:?}",
                started.elapsed()
            );
        }
    }
}

#[test]
fn an_image_from_a_named_pipe_is_compared_as_the_file_is() {
    let folder = tempfile::tempdir().unwrap();
    let pipe = folder.path().join("theirs.png");
    let made = Command::new("mkfifo").arg(&pipe).status().unwrap();
    assert!(made.success());
    let exact =
        std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/output1_01.png"))
            .unwrap();
    let writer = {
        let pipe = pipe.clone();
        std::thread::spawn(move || std::fs::write(pipe, exact))
    };
    let scene = scene_path("scene1_01.txt");
    let output = run_in(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-size",
            "200",
            "200",
            "-compare_output",
            "theirs.png",
        ],
    );
    writer.join().unwrap().unwrap();
    let text = String::from_utf8_lossy(&output.stdout);
    assert_eq!(
        output.status.code(),
        Some(0),
        "{text}{}",
        command::stderr(&output)
    );
    assert!(text.lines().any(|line| line == "match: yes"), "{text}");
}
