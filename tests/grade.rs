//! Grading a class at the boundary where a teacher meets it: the real binary, the course's
//! assignment file (`scenes/assignment1.commands`) and a folder of submissions made as students make
//! them — exact images, images with a known mistake (the oracle's mistaken ray caster), names in
//! another letter case or format, and what a careless or hostile student hands in: empty,
//! garbage, wrong-sized and bomb images, links out of the folder, a named pipe, a folder named
//! with HTML. Each is a cell of the report, never a stop; nothing is written outside the report.
#![cfg(unix)]

#[path = "common/command.rs"]
mod command;
#[path = "common/png_header.rs"]
mod png_header;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use command::{binary, run_in, stderr};
use raytracer::compare::Mistake;
use raytracer::compare::MistakeSet;
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::load_scene;
use serde_json::Value;

fn assignment() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assignment1.commands")
}

/// Every path under `root` (files and folders), relative to it.
fn tree(root: &Path) -> BTreeSet<PathBuf> {
    let mut found = BTreeSet::new();
    let mut folders = vec![root.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let entry = entry.unwrap();
            let path = entry.path();
            if entry.file_type().unwrap().is_dir() {
                folders.push(path.clone());
            }
            found.insert(path.strip_prefix(root).unwrap().to_path_buf());
        }
    }
    found
}

/// Writes the exact images of the assignment's seven lines into `folder` (the binary's own
/// command lines, run there).
fn exact_submission(folder: &Path) {
    std::fs::create_dir_all(folder).unwrap();
    let text = std::fs::read_to_string(assignment()).unwrap();
    for line in text.lines().filter(|l| l.starts_with("raytracer ")) {
        let mut words: Vec<String> = line.split_whitespace().skip(1).map(str::to_owned).collect();
        words[1] = assignment()
            .parent()
            .unwrap()
            .join(&words[1])
            .display()
            .to_string();
        let words: Vec<&str> = words.iter().map(String::as_str).collect();
        let output = run_in(folder, &words);
        assert!(output.status.success(), "{line}: {}", stderr(&output));
    }
}

/// The cell of `submission`'s image `file` in report.json.
fn cell<'a>(report: &'a Value, submission: &str, file: &str) -> &'a Value {
    let found = report["submissions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == submission)
        .unwrap_or_else(|| panic!("no submission {submission}"));
    found["images"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["file"] == file)
        .unwrap_or_else(|| panic!("{submission}: no image {file}"))
}

#[test]
fn a_class_is_graded_cell_by_cell_and_nothing_outside_the_report_is_written() {
    let root = tempfile::tempdir().unwrap();
    let subs = root.path().join("submissions");
    let outside = root.path().join("elsewhere");
    exact_submission(&outside);
    exact_submission(&subs.join("exact"));

    // A known mistake: rays through pixel corners, scene1_02, drawn by the oracle's caster.
    let mistaken = subs.join("corners");
    std::fs::create_dir_all(&mistaken).unwrap();
    let scene = load_scene(&assignment().parent().unwrap().join("scene1_02.txt")).unwrap();
    let view = View::of_camera(
        &scene.camera,
        200,
        200,
        DepthRange {
            min_t: 8.0,
            max_t: 12.0,
        },
    );
    let (colour, depth) = render_variant(&scene, &view, MistakeSet::of(&[Mistake::PixelCorners]));
    colour.save(mistaken.join("output1_02.png")).unwrap();
    depth.save(mistaken.join("depth1_02.png")).unwrap();

    // Another letter case and format.
    let cased = subs.join("cased");
    std::fs::create_dir_all(&cased).unwrap();
    std::fs::copy(
        subs.join("exact/output1_01.tga"),
        cased.join("Output1_01.tga"),
    )
    .unwrap();
    // The same name in another case is taken before the other format.
    image::RgbImage::new(200, 200)
        .save(cased.join("OUTPUT1_01.png"))
        .unwrap();
    image::open(subs.join("exact/depth1_01.tga"))
        .unwrap()
        .save(cased.join("Depth1_01.png"))
        .unwrap();

    // What a careless or hostile student hands in.
    let broken = subs.join("broken");
    std::fs::create_dir_all(&broken).unwrap();
    std::fs::write(broken.join("output1_01.tga"), b"").unwrap();
    std::fs::write(broken.join("output1_02.tga"), b"not an image at all").unwrap();
    image::RgbImage::new(100, 100)
        .save(broken.join("output1_03.png"))
        .unwrap();
    std::fs::write(
        broken.join("depth1_04.png"),
        png_header::png(16_384, 32_767, &[0x78, 0x9c]),
    )
    .unwrap();
    std::os::unix::fs::symlink(
        outside.join("output1_05.tga"),
        broken.join("output1_05.tga"),
    )
    .unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(broken.join("output1_06.tga"))
        .status()
        .unwrap();
    assert!(made.success());
    let html_name = "<img src=x onerror=alert(1)>";
    exact_submission(&subs.join(html_name));
    std::os::unix::fs::symlink(&outside, subs.join("linked")).unwrap();

    let before = tree(root.path());
    let output = run_in(
        root.path(),
        &[
            "grade",
            assignment().to_str().unwrap(),
            "submissions",
            "-o",
            "report",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let said = String::from_utf8_lossy(&output.stdout);
    assert!(said.contains("graded 5 submissions × 14 images"), "{said}");

    // Nothing outside the report was written, and nothing was left beside it.
    let after: BTreeSet<PathBuf> = tree(root.path())
        .into_iter()
        .filter(|path| !path.starts_with("report"))
        .collect();
    assert_eq!(before, after);

    let report: Value =
        serde_json::from_slice(&std::fs::read(root.path().join("report/report.json")).unwrap())
            .unwrap();
    let status = |submission: &str, file: &str| {
        cell(&report, submission, file)["status"]
            .as_str()
            .unwrap()
            .to_owned()
    };
    for file in [
        "output1_01.tga",
        "depth1_04.tga",
        "output1_07.tga",
        "depth1_07.tga",
    ] {
        assert_eq!(status("exact", file), "match", "{file}");
        assert_eq!(status(html_name, file), "match", "{file}");
    }
    // Letter case and format forgiven, and said.
    for (file, found) in [
        ("output1_01.tga", "Output1_01.tga"),
        ("depth1_01.tga", "Depth1_01.png"),
    ] {
        assert_eq!(status("cased", file), "match");
        assert_eq!(cell(&report, "cased", file)["found_as"], found);
    }
    assert_eq!(status("cased", "output1_02.tga"), "missing");

    // The known mistake is stated, as -compare_output with -compare_depth states it for the same
    // files.
    let corners = cell(&report, "corners", "output1_02.tga");
    assert_eq!(corners["status"], "differs");
    let alone = run_in(
        root.path(),
        &[
            "-input",
            assignment()
                .parent()
                .unwrap()
                .join("scene1_02.txt")
                .to_str()
                .unwrap(),
            "-size",
            "200",
            "200",
            "-compare_output",
            "submissions/corners/output1_02.png",
            "-compare_depth",
            "8",
            "12",
            "submissions/corners/depth1_02.png",
            "-compare_format",
            "json",
        ],
    );
    let alone: Value = serde_json::from_slice(&alone.stdout).unwrap();
    assert_eq!(corners["answer"]["statements"], alone["statements"]);
    let words: Vec<&str> = corners["answer"]["statements"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(words, ["pixel-corners"], "{corners}");
    assert_eq!(report["deviation_totals"]["pixel-corners"], 1);

    // Each hostile file is a cell, with why.
    for (file, wanted, why) in [
        ("output1_01.tga", "unreadable", "an empty file"),
        ("output1_02.tga", "unreadable", ""),
        ("output1_03.tga", "wrong size", "100×100"),
        (
            "depth1_04.tga",
            "unreadable",
            "announces an image larger than this program reads",
        ),
        ("output1_05.tga", "unreadable", "a link: not followed"),
        ("output1_06.tga", "unreadable", "not a regular file"),
    ] {
        let found = cell(&report, "broken", file);
        assert_eq!(found["status"], wanted, "{file}: {found}");
        assert!(
            found["short"].as_str().unwrap().contains(why),
            "{file}: {found}"
        );
    }
    let linked = report["submissions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "linked")
        .unwrap();
    assert_eq!(linked["skipped"], "a link: not followed");

    // Names from submissions are shown as text.
    let index = std::fs::read_to_string(root.path().join("report/index.html")).unwrap();
    assert!(!index.contains(html_name));
    assert!(index.contains("&lt;img src=x onerror=alert(1)&gt;"));
    for page in std::fs::read_dir(root.path().join("report/pages")).unwrap() {
        let text = std::fs::read_to_string(page.unwrap().path()).unwrap();
        assert!(!text.contains(html_name));
    }
    let csv = std::fs::read_to_string(root.path().join("report/report.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 5 * 14 + 1, "{csv}");
}

#[test]
fn a_report_replaces_a_previous_one_and_never_a_folder_of_other_files() {
    let root = tempfile::tempdir().unwrap();
    exact_submission(&root.path().join("submissions/one"));
    let grade = |report: &str| {
        run_in(
            root.path(),
            &[
                "grade",
                assignment().to_str().unwrap(),
                "submissions",
                "-o",
                report,
            ],
        )
    };
    assert!(grade("report").status.success());
    let again = grade("report");
    assert!(again.status.success(), "{}", stderr(&again));
    assert_eq!(
        command::names_in(root.path()),
        ["report", "submissions"],
        "the previous report is gone, not kept beside"
    );

    // A report the user has added anything to, anywhere under it, is no longer only a report:
    // the run is refused before anything is written, naming what is not the report's.
    for (added, named) in [
        ("report/notes.txt", "'notes.txt'"),
        ("report/pages/notes.txt", "'pages/notes.txt'"),
        ("report/pictures/mine/notes.txt", "'pictures/mine'"),
    ] {
        let added = root.path().join(added);
        std::fs::create_dir_all(added.parent().unwrap()).unwrap();
        std::fs::write(&added, "my notes").unwrap();
        let before = tree(root.path());
        let refused = grade("report");
        assert_eq!(refused.status.code(), Some(1), "{}", stderr(&refused));
        assert!(stderr(&refused).contains(named), "{}", stderr(&refused));
        assert_eq!(tree(root.path()), before);
        assert_eq!(std::fs::read_to_string(&added).unwrap(), "my notes");
        std::fs::remove_file(&added).unwrap();
    }
    std::fs::remove_dir(root.path().join("report/pictures/mine")).unwrap();
    // A link in it, even to the report's own file, is not what it wrote.
    std::os::unix::fs::symlink("../index.html", root.path().join("report/pages/link")).unwrap();
    let refused = grade("report");
    assert!(
        stderr(&refused).contains("'pages/link'"),
        "{}",
        stderr(&refused)
    );
    std::fs::remove_file(root.path().join("report/pages/link")).unwrap();
    let again = grade("report");
    assert!(again.status.success(), "{}", stderr(&again));

    // A class inside the report, or a report inside the class, is refused: replacing the
    // report would take the class with it.
    exact_submission(&root.path().join("report/exact/class/two"));
    let before = tree(root.path());
    let class_inside = run_in(
        root.path(),
        &[
            "grade",
            assignment().to_str().unwrap(),
            "report/exact/class",
            "-o",
            "report",
        ],
    );
    assert_eq!(class_inside.status.code(), Some(1));
    assert!(
        stderr(&class_inside).contains("holds the submissions folder"),
        "{}",
        stderr(&class_inside)
    );
    assert_eq!(tree(root.path()), before);
    std::fs::remove_dir_all(root.path().join("report/exact/class")).unwrap();
    let report_inside = grade("submissions/report");
    assert_eq!(report_inside.status.code(), Some(1));
    assert!(
        stderr(&report_inside).contains("is inside the submissions folder"),
        "{}",
        stderr(&report_inside)
    );
    assert_eq!(command::names_in(&root.path().join("submissions")), ["one"]);

    std::fs::create_dir(root.path().join("mine")).unwrap();
    std::fs::write(root.path().join("mine/notes.txt"), "my notes").unwrap();
    let before = tree(root.path());
    let refused = grade("mine");
    assert_eq!(refused.status.code(), Some(1));
    assert!(
        stderr(&refused).contains("holds files that are not a grading report"),
        "{}",
        stderr(&refused)
    );
    assert_eq!(tree(root.path()), before);
    assert_eq!(
        std::fs::read_to_string(root.path().join("mine/notes.txt")).unwrap(),
        "my notes"
    );
}

#[test]
fn a_wrong_assignment_line_is_named_with_its_line_and_nothing_is_written() {
    let root = tempfile::tempdir().unwrap();
    std::fs::create_dir(root.path().join("submissions")).unwrap();
    std::fs::write(
        root.path().join("a.txt"),
        "# two lines\nraytracer -input s.txt -output a.tga\nraytracer -input s.txt -output ../b.tga\n",
    )
    .unwrap();
    let before = tree(root.path());
    let output = run_in(
        root.path(),
        &["grade", "a.txt", "submissions", "-o", "report"],
    );
    assert_eq!(output.status.code(), Some(1));
    let text = stderr(&output);
    assert!(text.starts_with("raytracer: a.txt:3: '../b.tga'"), "{text}");
    assert_eq!(tree(root.path()), before);
    let usage = std::process::Command::new(binary())
        .args(["grade", "a.txt"])
        .output()
        .unwrap();
    assert_eq!(usage.status.code(), Some(2));
}

#[test]
fn a_stopped_run_leaves_no_report_and_no_unfinished_folder() {
    let root = tempfile::tempdir().unwrap();
    // Forty submissions of distinct noise: each is compared (none shares an answer).
    for student in 0..40_u32 {
        let folder = root.path().join(format!("submissions/s{student:02}"));
        std::fs::create_dir_all(&folder).unwrap();
        let noise = image::RgbImage::from_fn(200, 200, |x, y| {
            let v = (x * 7919 + y * 104_729 + student * 15_485_863).wrapping_mul(2_654_435_761);
            image::Rgb([(v >> 24) as u8, (v >> 16) as u8, (v >> 8) as u8])
        });
        noise.save(folder.join("output1_02.png")).unwrap();
    }
    let mut child = std::process::Command::new(binary())
        .current_dir(root.path())
        .args([
            "grade",
            assignment().to_str().unwrap(),
            "submissions",
            "-o",
            "report",
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let unfinished = || {
        command::names_in(root.path())
            .into_iter()
            .any(|name| name.starts_with(".report.raytracer-grade-"))
    };
    let started = std::time::Instant::now();
    while !unfinished() {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it was stopped"
        );
        assert!(started.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let stopped = std::process::Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(stopped.success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(128 + 15), "{status:?}");
    assert_eq!(command::names_in(root.path()), ["submissions"]);
}
