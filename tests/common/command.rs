//! Helpers shared by the tests that run the real binary (included by path, so that they need no
//! viewer): running it in a folder (directly or through `sh -c`), its one-line errors, its standard
//! error as text, the names in a folder, its peak memory (Linux), and the exact course picture
//! it draws.
#![allow(dead_code)] // each test file uses its own share

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The run's standard error, as text.
pub(crate) fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The names in `folder`, sorted (hidden ones too).
pub(crate) fn names_in(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

pub(crate) fn binary() -> &'static str {
    env!("CARGO_BIN_EXE_raytracer")
}

pub(crate) fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

pub(crate) fn run_in(folder: &Path, arguments: &[&str]) -> Output {
    Command::new(binary())
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap()
}

/// Runs the binary through `sh -c` (for umask and ulimit), in `folder`.
pub(crate) fn run_shell(folder: &Path, script: &str, arguments: &[&str]) -> Output {
    Command::new("sh")
        .current_dir(folder)
        .arg("-c")
        .arg(format!("{script} \"$0\" \"$@\""))
        .arg(binary())
        .args(arguments)
        .output()
        .unwrap()
}

/// The one-line error the program printed, with no panic and no backtrace.
pub(crate) fn assert_one_line_error(output: &Output) -> String {
    let text = stderr(output);
    assert!(!text.contains("panicked"), "a panic: {text}");
    assert_ne!(output.status.code(), Some(101), "a panic: {text}");
    assert!(text.lines().count() <= 1, "more than one line: {text}");
    text
}

/// Waits for `child` (started with its output piped or not) while sampling its peak resident
/// memory (`VmHWM` in `/proc`, every 5 ms); returns its output and the peak in bytes (0 where
/// `/proc` cannot be read).
pub(crate) fn wait_measuring_peak(mut child: std::process::Child) -> (Output, u64) {
    let status_path = format!("/proc/{}/status", child.id());
    let mut peak_kib = 0_u64;
    while child.try_wait().unwrap().is_none() {
        if let Ok(status) = std::fs::read_to_string(&status_path)
            && let Some(line) = status.lines().find(|l| l.starts_with("VmHWM:"))
        {
            let kib: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
            peak_kib = peak_kib.max(kib);
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    (child.wait_with_output().unwrap(), peak_kib * 1024)
}

/// Writes the exact colour image of scene1_01 at 50×50 to `path` (the binary's own picture),
/// running it in `folder`.
pub(crate) fn exact_scene1_01_at_50(folder: &Path, path: &Path) {
    let scene = scene_path("scene1_01.txt");
    let output = run_in(
        folder,
        &[
            "-input",
            scene.to_str().unwrap(),
            "-size",
            "50",
            "50",
            "-output",
            path.to_str().unwrap(),
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
}
