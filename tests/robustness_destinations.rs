//! Destinations that cannot be written as asked, for real, with the real binary:
//!
//! * an immutable file (`chattr +i`, which needs the capability to set it; where the test
//!   cannot, it says so and checks nothing): the run fails with the reason, the file is
//!   unchanged, the message says nothing false (the file was never changed, so nothing "could not
//!   be put back"), and no hidden file is left beside it;
//! * a link that leads to itself: refused as `cp` refuses it, the link left as it was;
//! * a link to a pipe (`o.tga` → `/dev/stdout`, into `| cat`): "not a regular file", as the pipe
//!   itself is.
#![cfg(target_os = "linux")]

#[path = "common/command.rs"]
mod command;

use std::process::{Command, Stdio};

use command::{assert_one_line_error, names_in, run_in, scene_path};

/// Clears the immutable flag when the test ends, pass or fail (the folder can then be removed).
struct Mutable<'a>(&'a std::path::Path);

impl Drop for Mutable<'_> {
    fn drop(&mut self) {
        let _ = Command::new("chattr").arg("-i").arg(self.0).status();
    }
}

/// Runs `-output o.tga` in `folder`, which must fail with one line, exit 1: that line.
fn refused_writing_o_tga(folder: &std::path::Path) -> String {
    let scene = scene_path("scene1_01.txt");
    let output = run_in(
        folder,
        &["-input", scene.to_str().unwrap(), "-output", "o.tga"],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    text
}

#[test]
fn an_immutable_destination_is_left_as_it_was_and_nothing_false_is_said() {
    let folder = tempfile::tempdir().unwrap();
    let destination = folder.path().join("o.tga");
    std::fs::write(&destination, b"their old picture").unwrap();
    let set = Command::new("chattr")
        .arg("+i")
        .arg(&destination)
        .output()
        .unwrap();
    let _mutable = Mutable(&destination);
    if !set.status.success() {
        eprintln!(
            "not checked: chattr +i is refused here ({})",
            String::from_utf8_lossy(&set.stderr).trim()
        );
        return;
    }
    let text = refused_writing_o_tga(folder.path());
    assert!(text.contains("o.tga"), "{text}");
    assert!(!text.contains("put back"), "a false statement: {text}");
    assert!(!text.contains(".old"), "a false statement: {text}");
    assert_eq!(std::fs::read(&destination).unwrap(), b"their old picture");
    assert_eq!(names_in(folder.path()), ["o.tga"], "files left beside it");
}

#[test]
fn a_link_that_leads_to_itself_is_refused_and_left_as_it_was() {
    let folder = tempfile::tempdir().unwrap();
    let link = folder.path().join("o.tga");
    std::os::unix::fs::symlink("o.tga", &link).unwrap();
    let text = refused_writing_o_tga(folder.path());
    assert!(
        text.contains("o.tga") && text.contains("too many levels of symbolic links"),
        "{text}"
    );
    let still = std::fs::symlink_metadata(&link).unwrap();
    assert!(still.file_type().is_symlink(), "the link was replaced");
    assert_eq!(names_in(folder.path()), ["o.tga"], "files left beside it");
}

#[test]
fn a_link_to_a_pipe_is_not_a_regular_file() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_01.txt");
    // Standard output is a pipe read by this test: o.tga leads to it through /dev/stdout.
    std::os::unix::fs::symlink("/dev/stdout", folder.path().join("o.tga")).unwrap();
    let output = Command::new(command::binary())
        .current_dir(folder.path())
        .args(["-input", scene.to_str().unwrap(), "-output", "o.tga"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("o.tga") && text.contains("not a regular file"),
        "{text}"
    );
    assert!(output.stdout.is_empty());
    assert_eq!(names_in(folder.path()), ["o.tga"], "files left beside it");
}
