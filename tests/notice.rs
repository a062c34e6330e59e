//! The third-party notice every download carries (`THIRD-PARTY-LICENSES.html`, committed, made
//! by `cargo xtask release notice` with cargo-about) is the notice of the crates the programs are
//! built from today:
//! * `cargo xtask release notice-check` (which `cargo xtask release build` runs first) passes on
//!   the repository as it is;
//! * in a copy of the files it reads, a crate's version changed in `Cargo.lock`, or a feature
//!   changed in `Cargo.toml`, fails it with the command to run; a change of a build profile in
//!   `Cargo.toml`, which picks no other crate, does not.

use std::path::Path;
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

const NOTICE: &str = "THIRD-PARTY-LICENSES.html";

/// `release.sh notice-check` run on the repository at `folder`.
fn notice_check(folder: &Path) -> Output {
    Command::new("bash")
        .arg(folder.join("xtask/chores/release.sh"))
        .arg("notice-check")
        .current_dir(folder)
        .output()
        .expect("bash runs")
}

/// A folder holding the files the check reads, as the repository holds them.
fn copy_of_the_inputs() -> tempfile::TempDir {
    let folder = tempfile::tempdir().expect("a temporary folder");
    for folder_name in ["xtask/chores", "xtask/lib"] {
        std::fs::create_dir_all(folder.path().join(folder_name)).expect("a folder");
    }
    for file in [
        "xtask/chores/release.sh",
        "xtask/lib/dist.sh",
        "Cargo.toml",
        "Cargo.lock",
        "about.toml",
        "about.hbs",
        NOTICE,
    ] {
        std::fs::copy(root().join(file), folder.path().join(file)).expect("a copy");
    }
    folder
}

fn replace_in(folder: &Path, file: &str, from: &str, to: &str) {
    let path = folder.join(file);
    let text = std::fs::read_to_string(&path).expect("the file reads");
    assert!(text.contains(from), "{file} holds {from:?}");
    std::fs::write(&path, text.replacen(from, to, 1)).expect("the file writes");
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn the_committed_notice_is_made_from_todays_crates() {
    let output = notice_check(root());
    assert!(
        output.status.success(),
        "{NOTICE} is out of date: {}",
        stderr(&output)
    );
    let notice = std::fs::read_to_string(root().join(NOTICE)).expect("the notice reads");
    // The notice names the crates the programs are built from (a few of the chosen ones).
    for name in ["eframe", "egui", "glam", "image", "rayon"] {
        assert!(
            notice.contains(&format!(">{name} ")),
            "the notice names the crate {name}"
        );
    }
}

/// In a copy of the inputs with `from` replaced by `to` in `file`, the check fails and names the
/// command that makes the notice again.
fn fails_and_says_what_to_run(change: &str, file: &str, from: &str, to: &str) {
    let copy = copy_of_the_inputs();
    replace_in(copy.path(), file, from, to);
    let output = notice_check(copy.path());
    assert!(!output.status.success(), "{change} fails the check");
    assert!(
        stderr(&output).contains("run `cargo xtask release notice`"),
        "{change}: it says what to run: {}",
        stderr(&output)
    );
}

#[test]
fn another_crate_version_or_feature_fails_the_check_and_says_what_to_run() {
    let copy = copy_of_the_inputs();
    assert!(
        notice_check(copy.path()).status.success(),
        "the copy passes as the repository does: {}",
        stderr(&notice_check(copy.path()))
    );

    // A build profile picks no other crate: the notice stays current.
    replace_in(
        copy.path(),
        "Cargo.toml",
        "[profile.release]\n",
        "[profile.release]\nincremental = false\n",
    );
    let output = notice_check(copy.path());
    assert!(
        output.status.success(),
        "a profile's change keeps the notice: {}",
        stderr(&output)
    );

    // A feature of the program's crates: the notice must be made again.
    fails_and_says_what_to_run(
        "a feature's change",
        "Cargo.toml",
        "\"persistence\",",
        "\"persistence\", \"accesskit\",",
    );
    // Another version of a crate in Cargo.lock.
    fails_and_says_what_to_run(
        "a crate's version",
        "Cargo.lock",
        "name = \"glam\"\nversion = \"0.34.",
        "name = \"glam\"\nversion = \"0.35.",
    );
}
