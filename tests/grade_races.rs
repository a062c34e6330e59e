//! A student who can still write to their folder while the class is graded, at the binary: each
//! of 300 submissions' image is swapped, over and over while `grade` runs, between a wrong image,
//! a link to another student's exact image and a named pipe with no writer. A file is opened
//! once and checked on the handle, so no cell is ever graded through the link (a "match"), and
//! no pipe blocks the run.
#![cfg(unix)]

#[path = "common/command.rs"]
mod command;

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use command::binary;
use serde_json::Value;

const SUBMISSIONS: usize = 300;

#[test]
fn a_file_swapped_for_a_link_or_a_pipe_while_grading_is_never_read_through_it() {
    let root = tempfile::tempdir().unwrap();
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_01.txt"),
        root.path().join("scene1_01.txt"),
    )
    .unwrap();
    std::fs::write(
        root.path().join("assignment.commands"),
        "raytracer -input scene1_01.txt -size 50 50 -output x.tga\n",
    )
    .unwrap();
    // Another student's exact image, outside the class.
    let exact = root.path().join("exact.tga");
    command::exact_scene1_01_at_50(root.path(), &exact);
    let wrong = root.path().join("wrong.tga");
    image::RgbImage::from_pixel(50, 50, image::Rgb([255, 255, 255]))
        .save_with_format(&wrong, image::ImageFormat::Tga)
        .unwrap();
    let folders: Vec<PathBuf> = (0..SUBMISSIONS)
        .map(|n| root.path().join(format!("submissions/s{n:03}")))
        .collect();
    for folder in &folders {
        std::fs::create_dir_all(folder).unwrap();
        std::fs::copy(&wrong, folder.join("x.tga")).unwrap();
    }
    let done = Arc::new(AtomicBool::new(false));
    let swapper = {
        let done = Arc::clone(&done);
        let folders = folders.clone();
        std::thread::spawn(move || {
            let mut turn = 0_usize;
            while !done.load(Ordering::Relaxed) {
                for folder in &folders {
                    let staged = folder.join("staged");
                    let _ = std::fs::remove_file(&staged);
                    // Each way in turn, put in place by a rename (the name is always there).
                    let made = match turn % 3 {
                        0 => std::os::unix::fs::symlink(&exact, &staged).is_ok(),
                        1 => std::process::Command::new("mkfifo")
                            .arg(&staged)
                            .status()
                            .is_ok_and(|s| s.success()),
                        _ => std::fs::copy(&wrong, &staged).is_ok(),
                    };
                    if made {
                        let _ = std::fs::rename(&staged, folder.join("x.tga"));
                    }
                }
                turn += 1;
            }
        })
    };
    let mut child = std::process::Command::new(binary())
        .current_dir(root.path())
        .args([
            "grade",
            "assignment.commands",
            "submissions",
            "-o",
            "report",
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            done.store(true, Ordering::Relaxed);
            panic!("grading blocked (a named pipe opened as a file?)");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    done.store(true, Ordering::Relaxed);
    swapper.join().unwrap();
    assert!(status.success(), "{status:?}");
    let report: Value =
        serde_json::from_slice(&std::fs::read(root.path().join("report/report.json")).unwrap())
            .unwrap();
    let statuses: Vec<String> = report["submissions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["images"][0]["status"].as_str().unwrap().to_owned())
        .collect();
    assert_eq!(statuses.len(), SUBMISSIONS);
    let matched = statuses.iter().filter(|s| *s == "match").count();
    assert_eq!(matched, 0, "graded through a link: {statuses:?}");
}
