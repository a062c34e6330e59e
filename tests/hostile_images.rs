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
use png_header::{black_png_with_profile, png};

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

#[test]
fn a_colour_profile_or_a_stream_that_is_no_image_is_never_read_into_memory() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    let scene = scene.to_str().unwrap();
    // A black 200×200 PNG whose colour profile (2.5 MB in the file) inflates to 400 MB: its
    // pixels are compared, and the run's peak stays within the bound -stats states.
    std::fs::write(
        folder.path().join("profile.png"),
        black_png_with_profile(200, 200, 400 << 20),
    )
    .unwrap();
    let output = run_in(
        folder.path(),
        &[
            "-input",
            scene,
            "-size",
            "200",
            "200",
            "-compare_output",
            "profile.png",
            "-stats",
        ],
    );
    let text = String::from_utf8_lossy(&output.stdout).into_owned() + &command::stderr(&output);
    assert!(text.contains("colour_pixels_differing:"), "{text}");
    let figure = |name: &str| -> f64 {
        text.lines()
            .find_map(|line| line.strip_prefix(name))
            .and_then(|value| value.trim().parse().ok())
            .unwrap_or_else(|| panic!("no {name} in {text}"))
    };
    let (peak, bound) = (figure("peak_memory_mb:"), figure("memory_bound_mb:"));
    assert!(
        peak <= bound,
        "peak {peak} MB over the stated bound {bound} MB"
    );
    // A device, and a named pipe that never ends, are refused by their first bytes at once.
    std::os::unix::fs::symlink("/dev/zero", folder.path().join("zero.tga")).unwrap();
    std::os::unix::fs::symlink("/dev/urandom", folder.path().join("noise.png")).unwrap();
    let pipe = folder.path().join("endless.tga");
    assert!(
        Command::new("mkfifo")
            .arg(&pipe)
            .status()
            .unwrap()
            .success()
    );
    let writer = std::thread::spawn(move || {
        use std::io::Write as _;
        let mut fifo = std::fs::OpenOptions::new().write(true).open(pipe).unwrap();
        // Until the reader has gone (a broken pipe).
        while fifo.write_all(&[7_u8; 1 << 16]).is_ok() {}
    });
    for name in ["zero.tga", "noise.png", "endless.tga"] {
        let started = Instant::now();
        let output = run_limited(
            folder.path(),
            300 << 20,
            &["-input", scene, "-compare_output", name],
        );
        let text = assert_one_line_error(&output);
        assert!(
            text.contains(name) && text.contains("its first bytes are not those of an image"),
            "{name}: {text}"
        );
        assert!(
            started.elapsed() < Duration::from_secs(10),
            "{name}: {:?}",
            started.elapsed()
        );
    }
    writer.join().unwrap();
}
