//! What grading holds per cell, at the binary: classes of 10,000 and 20,000 empty submissions
//! (140,000 and 280,000 cells, each "missing") graded with the course's assignment, the peak
//! resident memory of each run sampled from `/proc`; the difference per added cell is what
//! docs/grading.md states ("a few hundred bytes per cell"), held here under 512 bytes (the JSON
//! and CSV forms are written as they are made: held whole, they took several times that).
//! And a class of huge images of the wrong size (valid 13000×13000 PNGs of a few MB each) is
//! graded under a memory limit that holds one such image's pixels but not two: another size is
//! said from the header, the pixels never decoded. `--memory MB` sets the budget the
//! submissions are marked within: one at a time where it holds one.
#![cfg(target_os = "linux")]

#[path = "common/command.rs"]
mod command;
#[path = "common/png_header.rs"]
mod png_header;

use std::path::Path;
use std::process::{Command, Stdio};

use command::binary;

/// The most bytes grading may hold per cell.
const MAX_BYTES_PER_CELL: u64 = 512;

/// Grades `submissions` empty folders in `root` and returns the run's peak resident memory
/// (VmHWM, sampled until it exits), in bytes.
fn peak_grading_empty_class(root: &Path, submissions: usize) -> u64 {
    let class = root.join(format!("class{submissions}"));
    std::fs::create_dir(&class).unwrap();
    for n in 0..submissions {
        std::fs::create_dir(class.join(format!("s{n:05}"))).unwrap();
    }
    let assignment = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assignment1.commands");
    let child = Command::new(binary())
        .current_dir(root)
        .arg("grade")
        .arg(&assignment)
        .arg(&class)
        .args(["-o", &format!("report{submissions}")])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (output, peak) = command::wait_measuring_peak(child);
    assert!(output.status.success(), "{}", command::stderr(&output));
    peak
}

#[test]
fn grading_holds_a_few_hundred_bytes_per_cell() {
    let root = tempfile::tempdir().unwrap();
    let small = peak_grading_empty_class(root.path(), 10_000);
    let large = peak_grading_empty_class(root.path(), 20_000);
    // 10,000 more submissions of 14 images each.
    let per_cell = large.saturating_sub(small) / 140_000;
    println!("peaks {small} and {large} bytes: {per_cell} bytes per cell");
    assert!(
        per_cell <= MAX_BYTES_PER_CELL,
        "{per_cell} bytes per cell (peaks {small} and {large} bytes)"
    );
}

#[test]
fn huge_images_of_another_size_are_said_from_their_headers_under_a_memory_limit() {
    let root = tempfile::tempdir().unwrap();
    let side = 13_000_u32;
    let black = png_header::png(
        side,
        side,
        &png_header::zlib_of_zeros(u64::from(side) * (1 + 3 * u64::from(side))),
    );
    for student in 0..4 {
        let folder = root.path().join(format!("class/s{student}"));
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("output1_01.png"), &black).unwrap();
    }
    let assignment = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assignment1.commands");
    // 1.5 GiB of address space: one image's 507 MB of pixels, decoded with its RGB copy, fits;
    // two threads decoding at once do not.
    let output = Command::new("prlimit")
        .arg("--as=1610612736:1610612736")
        .arg(binary())
        .current_dir(root.path())
        .arg("grade")
        .arg(&assignment)
        .args(["class", "-o", "report"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", command::stderr(&output));
    let report = std::fs::read_to_string(root.path().join("report/report.csv")).unwrap();
    let wrong: Vec<&str> = report
        .lines()
        .filter(|line| line.contains("output1_01.tga") && line.contains("wrong size"))
        .collect();
    assert_eq!(wrong.len(), 4, "{report}");
    assert!(wrong[0].contains("13000×13000"), "{}", wrong[0]);
}

#[test]
fn a_memory_budget_sets_how_many_submissions_are_marked_at_once() {
    let root = tempfile::tempdir().unwrap();
    for student in 0..3 {
        std::fs::create_dir_all(root.path().join(format!("class/s{student}"))).unwrap();
    }
    let assignment = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assignment1.commands");
    let grade = |extra: &[&str]| {
        Command::new(binary())
            .current_dir(root.path())
            .arg("grade")
            .arg(&assignment)
            .args(["class", "-o", "report"])
            .args(extra)
            .output()
            .unwrap()
    };
    let at_once = || -> (u64, f64) {
        let report: serde_json::Value =
            serde_json::from_slice(&std::fs::read(root.path().join("report/report.json")).unwrap())
                .unwrap();
        (
            report["marked_at_once"].as_u64().unwrap(),
            report["memory_budget_mb"].as_f64().unwrap_or(f64::NAN),
        )
    };
    // Marking a submission of the course's 200×200 lines is bounded at about 16 MB: 20 MB holds
    // one, 32 MB two, and 12 MB still marks one (never none).
    let threads = std::thread::available_parallelism().map_or(1, usize::from) as u64;
    for (budget, expected) in [(12, 1), (20, 1), (32, 2.min(threads)), (100_000, threads)] {
        let output = grade(&["--memory", &budget.to_string()]);
        assert!(output.status.success(), "{}", command::stderr(&output));
        assert_eq!(at_once(), (expected, budget as f64), "--memory {budget}");
    }
    for wrong in [&["--memory", "0"][..], &["--memory", "lots"], &["--memory"]] {
        let output = grade(wrong);
        assert_eq!(output.status.code(), Some(2), "{wrong:?}");
        assert!(
            command::stderr(&output).contains("--memory needs the memory grading may use, in MB"),
            "{}",
            command::stderr(&output)
        );
    }
}
