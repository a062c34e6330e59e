//! Limits that end the program by a signal, set for real: a CPU-time limit (`prlimit --cpu`, `ulimit -S -t`) reached
//! while the images are written sends SIGXCPU; the run ends with 128 + its number and leaves no
//! temporary file and no half output. (Signals sent with `kill`: `tests/robustness.rs`.)
#![cfg(target_os = "linux")]

#[path = "common/command.rs"]
mod command;

use std::process::Command;

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
