//! A stop never splits a grading report, at the binary: `grade` stopped by SIGTERM or SIGINT at
//! any moment of its run, into a folder holding a previous report, leaves that report or the new
//! one whole (every file its `manifest.txt` lists is there) and nothing hidden beside it; and
//! what a killed run left (an unfinished folder, a previous report moved aside) is cleaned up by
//! the next run into the same place, while a running one's is left alone.
#![cfg(unix)]

#[path = "common/command.rs"]
mod command;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use command::{binary, run_in, stderr};

fn assignment() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assignment1.commands")
}

fn grade_args() -> Vec<String> {
    vec![
        "grade".into(),
        assignment().display().to_string(),
        "submissions".into(),
        "-o".into(),
        "report".into(),
    ]
}

/// A class of `students` submissions of distinct noise for scene1_02 (each compared).
fn noisy_class(root: &Path, students: u32) {
    for student in 0..students {
        let folder = root.join(format!("submissions/s{student:02}"));
        std::fs::create_dir_all(&folder).unwrap();
        let noise = image::RgbImage::from_fn(200, 200, |x, y| {
            let v = (x * 7919 + y * 104_729 + student * 15_485_863).wrapping_mul(2_654_435_761);
            image::Rgb([(v >> 24) as u8, (v >> 16) as u8, (v >> 8) as u8])
        });
        noise.save(folder.join("output1_02.png")).unwrap();
    }
}

/// Whether `report` is a whole report: its list is there and every entry it names is too.
fn whole(report: &Path) -> Result<(), String> {
    let list = std::fs::read_to_string(report.join("manifest.txt"))
        .map_err(|e| format!("no manifest.txt: {e}"))?;
    for line in list.lines().skip(1).filter(|l| !l.is_empty()) {
        if !report.join(line.trim_end_matches('/')).exists() {
            return Err(format!("'{line}' listed and missing"));
        }
    }
    Ok(())
}

#[test]
fn a_stop_at_any_moment_leaves_the_old_report_or_the_new_one_and_nothing_hidden() {
    let root = tempfile::tempdir().unwrap();
    noisy_class(root.path(), 3);
    let args = grade_args();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let first = run_in(root.path(), &args);
    assert!(first.status.success(), "{}", stderr(&first));
    whole(&root.path().join("report")).unwrap();
    // How long a whole run takes, to spread the stops over it and a little past its end.
    let started = Instant::now();
    assert!(run_in(root.path(), &args).status.success());
    let run = started.elapsed();
    let tries = 12_u32;
    let mut stopped_runs = 0;
    for attempt in 0..tries {
        let signal = if attempt % 2 == 0 { "-TERM" } else { "-INT" };
        let delay = run.mul_f64(1.2 * f64::from(attempt) / f64::from(tries));
        let mut child = std::process::Command::new(binary())
            .current_dir(root.path())
            .args(&args)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(delay);
        let _ = std::process::Command::new("kill")
            .args([signal, &child.id().to_string()])
            .status();
        let status = child.wait().unwrap();
        if status.code() != Some(0) {
            stopped_runs += 1;
        }
        let names = command::names_in(root.path());
        assert_eq!(
            names,
            ["report", "submissions"],
            "{signal} after {delay:?} ({status:?}): a report split or a folder left"
        );
        whole(&root.path().join("report"))
            .unwrap_or_else(|e| panic!("{signal} after {delay:?}: the report is not whole: {e}"));
    }
    assert!(stopped_runs > 0, "no run was stopped: nothing was tried");
}

#[test]
fn a_stop_while_the_previous_report_is_replaced_waits_for_it() {
    let root = tempfile::tempdir().unwrap();
    noisy_class(root.path(), 1);
    // Many submissions (empty: a page each, nothing compared) make a previous report whose
    // removal takes long enough to be stopped in.
    for student in 0..3000 {
        std::fs::create_dir(root.path().join(format!("submissions/e{student:04}"))).unwrap();
    }
    let args = grade_args();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    assert!(run_in(root.path(), &args).status.success());
    for signal in ["-TERM", "-INT"] {
        let mut child = std::process::Command::new(binary())
            .current_dir(root.path())
            .args(&args)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        // The moment the previous report is moved aside.
        let started = Instant::now();
        while !command::names_in(root.path())
            .iter()
            .any(|name| name.starts_with(".report.raytracer-grade-") && name.contains(".old"))
        {
            assert!(
                child.try_wait().unwrap().is_none(),
                "the run ended before its previous report was seen moved aside"
            );
            assert!(started.elapsed() < Duration::from_secs(120));
        }
        let _ = std::process::Command::new("kill")
            .args([signal, &child.id().to_string()])
            .status();
        let status = child.wait().unwrap();
        assert_eq!(
            command::names_in(root.path()),
            ["report", "submissions"],
            "{signal} ({status:?}): the previous report left beside the new one"
        );
        whole(&root.path().join("report")).unwrap();
    }
    // A file put into the previous report after the run checked it is kept, and said.
    let child = std::process::Command::new(binary())
        .current_dir(root.path())
        .args(&args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    while !command::names_in(root.path())
        .iter()
        .any(|name| name.starts_with(".report.raytracer-grade-") && name.contains(".tmp"))
    {
        std::thread::sleep(Duration::from_millis(1));
    }
    std::fs::write(root.path().join("report/pages/notes.txt"), "mine").unwrap();
    let output = child.wait_with_output().unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("they are kept in 'report.kept-1'"),
        "{}",
        stderr(&output)
    );
    assert_eq!(
        std::fs::read_to_string(root.path().join("report.kept-1/pages/notes.txt")).unwrap(),
        "mine"
    );
    assert_eq!(
        command::names_in(&root.path().join("report.kept-1")),
        ["pages"],
        "only what the report did not write is kept"
    );
    whole(&root.path().join("report")).unwrap();
}

#[test]
fn what_a_killed_run_left_is_cleaned_up_and_a_running_ones_is_not() {
    let root = tempfile::tempdir().unwrap();
    noisy_class(root.path(), 1);
    let args = grade_args();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    assert!(run_in(root.path(), &args).status.success());
    // A run killed between its two moves: the previous report aside, its own unfinished. No
    // process has a number this large.
    let gone = 2_000_000_000_u32;
    let aside = root
        .path()
        .join(format!(".report.raytracer-grade-{gone}.old"));
    std::fs::rename(root.path().join("report"), &aside).unwrap();
    let unfinished = root
        .path()
        .join(format!(".report.raytracer-grade-{gone}.tmp"));
    std::fs::create_dir_all(unfinished.join("pages")).unwrap();
    std::fs::write(unfinished.join("pages/0001.html"), "half").unwrap();
    // A run still going on (this test's own process) has its folder left alone.
    let running = root.path().join(format!(
        ".report.raytracer-grade-{}.tmp",
        std::process::id()
    ));
    std::fs::create_dir(&running).unwrap();
    let again = run_in(root.path(), &args);
    assert!(again.status.success(), "{}", stderr(&again));
    let running_name = running.file_name().unwrap().to_string_lossy().into_owned();
    assert_eq!(
        command::names_in(root.path()),
        [running_name.as_str(), "report", "submissions"]
    );
    whole(&root.path().join("report")).unwrap();
    // A previous report a killed run moved aside, with the report back in place since: what
    // its list names is removed, and a file of the user's in it is kept.
    let copy = |from: &Path, to: &Path| {
        let status = std::process::Command::new("cp")
            .args(["-R"])
            .arg(from)
            .arg(to)
            .status()
            .unwrap();
        assert!(status.success());
    };
    copy(&root.path().join("report"), &aside);
    std::fs::write(aside.join("notes.txt"), "mine").unwrap();
    assert!(run_in(root.path(), &args).status.success());
    assert_eq!(command::names_in(&aside), ["notes.txt"]);
}
