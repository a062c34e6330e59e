//! Limits set for real on the real binary:
//!
//! * a CPU-time limit (`prlimit --cpu`, `ulimit -S -t`) reached while the images are made sends
//!   SIGXCPU; the run ends with 128 + its number and leaves no temporary file and no half output
//!   (signals sent with `kill`: `tests/robustness.rs`);
//! * a scene piped in under a memory limit that cannot hold it is refused with one line, exit 1,
//!   not aborted;
//! * a class graded at a size whose exact images the memory limit cannot hold is refused with
//!   the line and both figures, before any is drawn, not aborted.
#![cfg(target_os = "linux")]

#[path = "common/command.rs"]
mod command;

use std::io::Write as _;
use std::process::{Command, Stdio};

use command::{binary, names_in, scene_path};

#[test]
fn a_cpu_time_limit_reached_ends_the_run_cleanly() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    // 64 samples a pixel at 4096²: minutes of CPU, far past the one-second limit.
    // The soft limit at 1 s sends SIGXCPU; the hard one, SIGKILL, well after (a batch system's
    // limits; with the two equal the kernel sends both at once).
    let output = Command::new("prlimit")
        .arg("--cpu=1:30")
        .arg(binary())
        .current_dir(folder.path())
        .args([
            "-input",
            scene.to_str().unwrap(),
            "-size",
            "4096",
            "4096",
            "-random_samples",
            "64",
            "-output",
            "c.tga",
            "-depth",
            "8",
            "12",
            "d.tga",
        ])
        .output()
        .unwrap();
    assert_eq!(
        output.status.code(),
        Some(128 + 24),
        "ended by SIGXCPU, as 152: {:?} {}",
        output.status,
        command::stderr(&output)
    );
    assert_eq!(names_in(folder.path()), Vec::<String>::new());
}

#[test]
fn a_piped_scene_that_memory_cannot_hold_is_refused_not_aborted() {
    let folder = tempfile::tempdir().unwrap();
    // 700 MB of address space; the input goes on until the program stops reading.
    let mut child = Command::new("prlimit")
        .arg("--as=700000000:700000000")
        .arg(binary())
        .current_dir(folder.path())
        .args(["-input", "/dev/stdin", "-output", "o.tga"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        let spaces = vec![b' '; 1 << 20];
        // Ends when the program closes the pipe (or after 2 GB, past any limit).
        for _ in 0..2048 {
            if input.write_all(&spaces).is_err() {
                break;
            }
        }
    });
    let output = child.wait_with_output().unwrap();
    writer.join().unwrap();
    let text = command::assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("/dev/stdin") && text.contains("not enough memory"),
        "{text}"
    );
    assert_eq!(names_in(folder.path()), Vec::<String>::new());
}

#[test]
fn a_class_whose_exact_images_memory_cannot_hold_is_refused_not_aborted() {
    let folder = tempfile::tempdir().unwrap();
    let scenes = scene_path("scene1_01.txt").parent().unwrap().to_path_buf();
    let lines = std::fs::read_to_string(scenes.join("assignment1.commands"))
        .unwrap()
        .replace("-size 200 200", "-size 8192 8192");
    std::fs::write(folder.path().join("big.commands"), lines).unwrap();
    for n in 1..=7 {
        let name = format!("scene1_0{n}.txt");
        std::fs::copy(scenes.join(&name), folder.path().join(&name)).unwrap();
    }
    std::fs::create_dir(folder.path().join("class")).unwrap();
    let before = names_in(folder.path());
    let output = Command::new("prlimit")
        .arg(format!("--as={0}:{0}", 3_u64 << 30))
        .arg(binary())
        .current_dir(folder.path())
        .args(["grade", "big.commands", "class", "-o", "report"])
        .output()
        .unwrap();
    let text = command::assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.starts_with("raytracer: big.commands:4: the exact 8192×8192 images need about 1946 MB")
            && text.contains("MB is available"),
        "{text}"
    );
    assert_eq!(names_in(folder.path()), before);
}
