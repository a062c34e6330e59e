//! Limits set for real on the real binary:
//!
//! * a CPU-time limit (`prlimit --cpu`, `ulimit -S -t`) reached while the images are made sends
//!   SIGXCPU; the run ends with 128 + its number and leaves no temporary file and no half output
//!   (signals sent with `kill`: `tests/robustness.rs`);
//! * a scene piped in under a memory limit that cannot hold it is refused with one line, exit 1,
//!   not aborted;
//! * a pixel's trace over a million spheres stays within the memory bound `-stats` states, and
//!   under a limit that holds the render but not the trace is refused naming `-trace`;
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
        text.starts_with(
            "raytracer: big.commands:4: the exact 8192×8192 images need about 1946 MB"
        ) && text.contains("MB is available"),
        "{text}"
    );
    assert_eq!(names_in(folder.path()), before);
}

#[test]
fn a_trace_over_a_million_spheres_is_within_the_stated_bound() {
    use std::fmt::Write as _;
    let folder = tempfile::tempdir().unwrap();
    let mut scene = String::from(
        "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n\
         Background { color 0 0 0 }\n\
         Materials { numMaterials 1 PhongMaterial { diffuseColor 1 0 0 } }\n\
         Group { numObjects 1000000 MaterialIndex 0\n",
    );
    for n in 0..1_000_000_u32 {
        let (x, y) = (
            f64::from(n % 1000) / 200.0 - 2.5,
            f64::from(n / 1000) / 200.0 - 2.5,
        );
        let _ = writeln!(scene, "Sphere {{ center {x} {y} 0 radius 0.002 }}");
    }
    scene.push_str("}\n");
    std::fs::write(folder.path().join("million.txt"), scene).unwrap();
    let arguments = [
        "-input",
        "million.txt",
        "-size",
        "200",
        "200",
        "-output",
        "o.tga",
        "-trace",
        "100",
        "100",
        "-stats",
    ];
    let (output, peak) = run_with_peak(
        Command::new(binary())
            .current_dir(folder.path())
            .args(arguments),
    );
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", command::stderr(&output));
    let figure = |text: &str, name: &str| -> f64 {
        text.lines()
            .find_map(|line| line.trim().strip_prefix(name))
            .and_then(|value| value.trim().trim_end_matches(',').parse().ok())
            .unwrap_or_else(|| panic!("no {name} in {}", &text[text.len().saturating_sub(2000)..]))
    };
    let (stated_peak, bound) = (
        figure(&text, "peak_memory_mb:"),
        figure(&text, "memory_bound_mb:"),
    );
    assert!(
        stated_peak <= bound && peak <= bound,
        "peak {peak} MB (stated {stated_peak}) over the stated bound {bound} MB"
    );
    // The answer as JSON holds the trace's lines too: still within the bound it states.
    std::fs::copy(folder.path().join("o.tga"), folder.path().join("mine.tga")).unwrap();
    let (output, peak) = run_with_peak(Command::new(binary()).current_dir(folder.path()).args([
        "-input",
        "million.txt",
        "-compare_output",
        "mine.tga",
        "-compare_format",
        "json",
        "-trace",
        "100",
        "100",
        "-stats",
    ]));
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", command::stderr(&output));
    let bound = figure(&text, "\"memory_bound_mb\":");
    assert!(
        peak <= bound,
        "as JSON: peak {peak} MB over the stated bound {bound} MB"
    );
    let document: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(document["trace"].as_array().map(Vec::len), Some(1_000_011));
    // Under 800 MB of address space, which holds the scene and its render but not the trace
    // beside them: refused with one line naming the trace (it aborted).
    let output = Command::new("prlimit")
        .arg("--as=800000000:800000000")
        .arg(binary())
        .current_dir(folder.path())
        .args([
            "-input",
            "million.txt",
            "-size",
            "200",
            "200",
            "-output",
            "p.tga",
        ])
        .args(["-trace", "100", "100"])
        .output()
        .unwrap();
    let said = command::assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{said}");
    assert!(
        said.contains("200×200 with -trace over 1000000 spheres needs about")
            && said
                .trim_end()
                .ends_with("MB is available: trace on a smaller scene, or leave out -trace"),
        "{said}"
    );
    assert!(!folder.path().join("p.tga").exists());
}

/// Runs `command` to its end, its output read as it comes, and its peak resident memory (VmHWM)
/// in MB, read while it runs: the high-water mark only rises, and the last reading comes after
/// the program's peak (it is then still writing its answer, which is read here).
fn run_with_peak(command: &mut Command) -> (std::process::Output, f64) {
    let child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let status_file = format!("/proc/{}/status", child.id());
    let done = std::sync::atomic::AtomicBool::new(false);
    std::thread::scope(|scope| {
        let watcher = scope.spawn(|| {
            let mut peak_kib = 0_u64;
            while !done.load(std::sync::atomic::Ordering::Relaxed) {
                let kib = std::fs::read_to_string(&status_file)
                    .ok()
                    .and_then(|status| {
                        status
                            .lines()
                            .find_map(|line| line.strip_prefix("VmHWM:"))
                            .and_then(|value| {
                                value.trim().trim_end_matches("kB").trim().parse().ok()
                            })
                    });
                peak_kib = peak_kib.max(kib.unwrap_or(0));
                std::thread::sleep(std::time::Duration::from_millis(2));
            }
            peak_kib as f64 * 1024.0 / 1e6
        });
        let output = child.wait_with_output().unwrap();
        done.store(true, std::sync::atomic::Ordering::Relaxed);
        (output, watcher.join().unwrap())
    })
}
