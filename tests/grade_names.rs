//! Names from a class shown as they are, at the binary: a name that reorders text shows its
//! control characters instead of obeying them; two names that are not UTF-8 never look alike,
//! and the page's command names the real file (run in bash, it finds it); a CSV cell starting
//! with TAB or carriage return is no formula; among letter-case variants the one chosen is the
//! first in byte order, whatever the folder's order; a line's file is its own (a `.tga` line
//! never grades the `.png` another line names); a folder that cannot be read is "unreadable",
//! not "missing" (run as `nobody` where the tests run as root); and any valid `-o` name works,
//! however long.
#![cfg(unix)]

#[path = "common/command.rs"]
mod command;

use std::ffi::OsStr;
use std::os::unix::ffi::OsStrExt;
use std::path::{Path, PathBuf};

use command::{run_in, stderr};
use serde_json::Value;

fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// A one-line assignment (scene1_01 at 50×50, the colour image `names[0]`, …) in `root`.
fn assignment(root: &Path, lines: &[&str]) -> PathBuf {
    std::fs::copy(scenes().join("scene1_01.txt"), root.join("scene1_01.txt")).unwrap();
    let mut text = String::new();
    for output in lines {
        text.push_str("raytracer -input scene1_01.txt -size 50 50 -output ");
        text.push_str(output);
        text.push('\n');
    }
    let path = root.join("assignment.commands");
    std::fs::write(&path, text).unwrap();
    path
}

/// A wrong image (all white) at `path`.
fn white_image(path: &Path) {
    image::RgbImage::from_pixel(50, 50, image::Rgb([255, 255, 255]))
        .save_with_format(path, image::ImageFormat::Tga)
        .unwrap();
}

fn grade(root: &Path, report: &str) -> std::process::Output {
    run_in(
        root,
        &["grade", "assignment.commands", "submissions", "-o", report],
    )
}

fn report_json(root: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(root.join("report/report.json")).unwrap()).unwrap()
}

/// The cells (status, found_as) of `submission` in report.json.
fn cells(report: &Value, submission: &str) -> Vec<(String, String)> {
    let found = report["submissions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == submission)
        .unwrap_or_else(|| panic!("no submission {submission}: {report}"));
    found["images"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["status"].as_str().unwrap_or("").to_owned(),
                c["found_as"].as_str().unwrap_or("").to_owned(),
            )
        })
        .collect()
}

#[test]
fn names_that_reorder_text_or_are_not_utf8_are_shown_as_they_are_and_commands_name_them() {
    let root = tempfile::tempdir().unwrap();
    assignment(root.path(), &["output.tga"]);
    let reordering = "alice\u{202E}gnp.exe";
    let folders: Vec<&OsStr> = vec![
        OsStr::new(reordering),
        OsStr::from_bytes(b"bad\xff"),
        OsStr::from_bytes(b"bad\xfe"),
        OsStr::new("\tcmd"),
        OsStr::new("\rcmd"),
    ];
    for folder in &folders {
        let folder = root.path().join("submissions").join(folder);
        std::fs::create_dir_all(&folder).unwrap();
        white_image(&folder.join("output.tga"));
    }
    let output = grade(root.path(), "report");
    assert!(output.status.success(), "{}", stderr(&output));
    let index = std::fs::read_to_string(root.path().join("report/index.html")).unwrap();
    assert!(index.contains("alice&lt;U+202E&gt;gnp.exe"), "{index}");
    assert!(!index.contains('\u{202E}'), "a control character obeyed");
    assert!(
        index.contains(r"bad\xFF") && index.contains(r"bad\xFE"),
        "{index}"
    );
    assert!(
        !index.contains('\u{FFFD}'),
        "a name shown as a replacement character"
    );

    // The page's command, run in bash from where grading ran, finds the file that is not UTF-8.
    let pages: Vec<String> = std::fs::read_dir(root.path().join("report/pages"))
        .unwrap()
        .map(|e| std::fs::read_to_string(e.unwrap().path()).unwrap())
        .collect();
    let page = pages
        .iter()
        .find(|p| p.contains(r"<h1>bad\xFF</h1>"))
        .expect("the page of bad\\xFF");
    let command = page
        .split("The same answer from the command line:</p><pre>")
        .nth(1)
        .and_then(|rest| rest.split("</pre>").next())
        .expect("a command")
        .replace("&#39;", "'")
        .replace("&amp;", "&");
    assert!(
        command.contains(r"$'submissions/bad\xFF/output.tga'"),
        "{command}"
    );
    let command = command.replacen("raytracer", command::binary(), 1);
    let ran = std::process::Command::new("bash")
        .current_dir(root.path())
        .args(["-c", &command])
        .output()
        .unwrap();
    assert!(ran.status.code() != Some(2), "{}", stderr(&ran));
    assert!(
        String::from_utf8_lossy(&ran.stdout).contains("differ"),
        "{}{}",
        String::from_utf8_lossy(&ran.stdout),
        stderr(&ran)
    );

    // No CSV cell starts a formula, TAB and carriage return included.
    let csv = std::fs::read_to_string(root.path().join("report/report.csv")).unwrap();
    assert!(csv.contains("\n'\tcmd,"), "{csv}");
    assert!(csv.contains("\n\"'\rcmd\","), "{csv:?}");
}

#[test]
fn a_files_letter_case_variant_and_its_other_format_are_chosen_by_a_stated_rule() {
    let root = tempfile::tempdir().unwrap();
    assignment(root.path(), &["output.tga", "other.png"]);
    // The same two variants made in either order: the folder's own order differs, the choice
    // does not (the first in byte order: OUTPUT.TGA before Output.tga).
    for (folder, order) in [
        ("a", ["OUTPUT.TGA", "Output.tga"]),
        ("b", ["Output.tga", "OUTPUT.TGA"]),
    ] {
        let folder = root.path().join("submissions").join(folder);
        std::fs::create_dir_all(&folder).unwrap();
        for name in order {
            if name == "OUTPUT.TGA" {
                command::exact_scene1_01_at_50(root.path(), &folder.join(name));
            } else {
                white_image(&folder.join(name));
            }
        }
    }
    // output.tga's other format, which no other line names, is its file.
    let folder = root.path().join("submissions/c");
    std::fs::create_dir_all(&folder).unwrap();
    command::exact_scene1_01_at_50(root.path(), &folder.join("output.png"));
    let output = grade(root.path(), "report");
    assert!(output.status.success(), "{}", stderr(&output));
    let report = report_json(root.path());
    for submission in ["a", "b"] {
        assert_eq!(
            cells(&report, submission)[0],
            ("match".to_owned(), "OUTPUT.TGA".to_owned()),
            "{submission}"
        );
    }
    assert_eq!(
        cells(&report, "c")[0],
        ("match".to_owned(), "output.png".to_owned())
    );
}

#[test]
fn a_lines_file_is_its_own() {
    let root = tempfile::tempdir().unwrap();
    // Two lines: one names x.tga, the other x.png. A submission with x.png alone has no x.tga:
    // the first line's cell is missing, never the other line's file graded.
    assignment(root.path(), &["x.tga", "x.png"]);
    let alone = root.path().join("submissions/alone");
    std::fs::create_dir_all(&alone).unwrap();
    command::exact_scene1_01_at_50(root.path(), &alone.join("x.png"));
    let output = grade(root.path(), "report");
    assert!(output.status.success(), "{}", stderr(&output));
    let alone_cells = cells(&report_json(root.path()), "alone");
    assert_eq!(alone_cells[0].0, "missing", "{alone_cells:?}");
    assert_eq!(alone_cells[1], ("match".to_owned(), String::new()));
}

#[test]
fn an_unreadable_folder_is_said_unreadable_not_missing() {
    use std::os::unix::fs::PermissionsExt;
    let root = tempfile::tempdir().unwrap();
    assignment(root.path(), &["x.tga"]);
    let locked = root.path().join("submissions/locked");
    std::fs::create_dir_all(&locked).unwrap();
    command::exact_scene1_01_at_50(root.path(), &locked.join("x.tga"));
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o000)).unwrap();
    // Permissions do not stop root: there the grader runs as `nobody` (util-linux's setpriv),
    // in a folder it may write.
    let as_root = std::fs::read_dir(&locked).is_ok();
    let mut command = if as_root {
        std::fs::set_permissions(root.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
        let mut command = std::process::Command::new("setpriv");
        command.args(["--reuid", "65534", "--regid", "65534", "--clear-groups"]);
        command.arg(command::binary());
        command
    } else {
        std::process::Command::new(command::binary())
    };
    let output = command
        .current_dir(root.path())
        .args([
            "grade",
            "assignment.commands",
            "submissions",
            "-o",
            "report",
        ])
        .output()
        .expect("setpriv, to run the grader as another user than root");
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o755)).unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    let locked_cells = cells(&report_json(root.path()), "locked");
    assert_eq!(locked_cells[0].0, "unreadable", "{locked_cells:?}");
    let csv = std::fs::read_to_string(root.path().join("report/report.csv")).unwrap();
    assert!(csv.contains("its folder cannot be read"), "{csv}");
}

#[test]
fn any_valid_report_name_works_however_long() {
    let root = tempfile::tempdir().unwrap();
    assignment(root.path(), &["output.tga"]);
    let folder = root.path().join("submissions/one");
    std::fs::create_dir_all(&folder).unwrap();
    command::exact_scene1_01_at_50(root.path(), &folder.join("output.tga"));
    let long = "r".repeat(250);
    for _ in 0..2 {
        let output = grade(root.path(), &long);
        assert!(output.status.success(), "{}", stderr(&output));
    }
    assert_eq!(
        command::names_in(root.path()).len(),
        4,
        "{:?}",
        command::names_in(root.path())
    );
    assert!(root.path().join(&long).join("manifest.txt").is_file());
}
