//! Hostile conditions at the boundary where a user meets the command line: the real binary in a
//! temporary folder, with real files, links, umasks, file-size and process limits, closed pipes,
//! full devices and signals (limits and messages: `tests/robustness_limits.rs`). Each test names the promise it checks and asserts the outcome the
//! user sees: the exit status, the message, the files (intact, complete, with their modes) and
//! nothing left behind.

#[path = "common/command.rs"]
mod command;

use command::{assert_one_line_error, binary, names_in, run_in, run_shell, scene_path, stderr};
use std::os::unix::fs::PermissionsExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn scene_copy(folder: &Path, name: &str) -> PathBuf {
    let path = folder.join(name);
    std::fs::copy(scene_path("scene1_02.txt"), &path).unwrap();
    path
}

// --- 1. An output that names the input, or two outputs that name one file ---------------------

#[test]
fn an_output_that_is_the_input_by_another_name_is_refused_and_the_scene_survives() {
    let folder = tempfile::tempdir().unwrap();
    // A scene whose name ends in .tga, written to through "./".
    let scene = scene_copy(folder.path(), "s.tga");
    let original = std::fs::read(&scene).unwrap();
    let output = run_in(folder.path(), &["-input", "s.tga", "-output", "./s.tga"]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(stderr(&output).contains("s.tga"), "{}", stderr(&output));
    assert_eq!(std::fs::read(&scene).unwrap(), original);
    // Through a symbolic link and through a hard link, for each output flag.
    std::os::unix::fs::symlink(&scene, folder.path().join("link.png")).unwrap();
    std::fs::hard_link(&scene, folder.path().join("hard.pfm")).unwrap();
    for arguments in [
        vec!["-input", "s.tga", "-output", "link.png"],
        vec!["-input", "s.tga", "-depth", "8", "12", "link.png"],
        vec!["-input", "s.tga", "-depth16", "8", "12", "link.png"],
        vec!["-input", "s.tga", "-depth_raw", "hard.pfm"],
    ] {
        let output = run_in(folder.path(), &arguments);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert_eq!(std::fs::read(&scene).unwrap(), original, "{arguments:?}");
    }
    assert_eq!(names_in(folder.path()), ["hard.pfm", "link.png", "s.tga"]);
}

#[test]
fn two_outputs_naming_one_file_by_different_spellings_are_refused_before_rendering() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let scene = scene.to_str().unwrap();
    std::fs::create_dir(folder.path().join("sub")).unwrap();
    for arguments in [
        vec![
            "-input",
            scene,
            "-output",
            "out.tga",
            "-depth",
            "8",
            "12",
            "./out.tga",
        ],
        vec![
            "-input",
            scene,
            "-output",
            "out.tga",
            "-depth",
            "8",
            "12",
            "sub/../out.tga",
        ],
        vec![
            "-input", scene, "-depth", "8", "12", "d.png", "-depth16", "8", "12", "./d.png",
        ],
    ] {
        let output = run_in(folder.path(), &arguments);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert!(stderr(&output).contains("same file"), "{}", stderr(&output));
        assert_eq!(
            names_in(folder.path()),
            ["sub"],
            "{arguments:?} wrote nothing"
        );
    }
}

// --- 2. All or nothing --------------------------------------------------------------------

/// Runs the course scene at 640×640 into `colour` and `depth` (in a temporary folder where
/// both already exist) under a file-size limit of 100 kB, which a 1.2 MB TGA passes midway (the
/// same as a disk that fills up); checks the run fails with one line naming one of `failing`,
/// and leaves both old files as they were and nothing else.
fn a_limit_midway_replaces_nothing(colour: &str, depth: &str, failing: &[&str]) {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    // Old outputs the failed run must leave as they were.
    std::fs::write(folder.path().join(colour), b"old colour").unwrap();
    std::fs::write(folder.path().join(depth), b"old depth").unwrap();
    let output = Command::new("prlimit")
        .arg("--fsize=100000:100000")
        .arg(binary())
        .current_dir(folder.path())
        .args(["-input", scene.to_str().unwrap(), "-size", "640", "640"])
        .args(["-output", colour, "-depth", "8", "12", depth])
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        failing.iter().any(|name| text.contains(name)),
        "the message names the file: {text}"
    );
    assert!(
        !text.contains(".raytracer-"),
        "no temporary file named: {text}"
    );
    assert_eq!(
        std::fs::read(folder.path().join(colour)).unwrap(),
        b"old colour"
    );
    assert_eq!(
        std::fs::read(folder.path().join(depth)).unwrap(),
        b"old depth"
    );
    assert_eq!(
        names_in(folder.path()),
        [colour, depth],
        "no temporary file left"
    );
}

#[test]
fn when_one_output_cannot_be_written_no_earlier_file_is_replaced() {
    // The small PNG fits, the TGA does not.
    a_limit_midway_replaces_nothing("c.png", "d.tga", &["d.tga"]);
}

#[test]
fn a_streamed_command_that_cannot_write_its_files_replaces_none() {
    // The course's command writes its two TGA files strip by strip, at their places: a limit
    // met midway fails the run, and neither old file is touched.
    a_limit_midway_replaces_nothing("c.tga", "d.tga", &["c.tga", "d.tga"]);
}

#[test]
fn a_rename_that_fails_midway_puts_back_every_file_already_replaced() {
    // The second rename of the commit fails (an I/O error injected by strace, as a disk or a
    // network folder may give): the first file, already replaced, is put back; the second was
    // never touched; a new file that had been renamed into place is removed again.
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let scene = scene.to_str().unwrap();
    for existed in [true, false] {
        let colour = folder.path().join("keep.tga");
        let depth = folder.path().join("d.tga");
        if existed {
            std::fs::write(&colour, b"old colour").unwrap();
        } else {
            let _ = std::fs::remove_file(&colour);
        }
        std::fs::write(&depth, b"old depth").unwrap();
        let output = Command::new("strace")
            .current_dir(folder.path())
            .args(["-f", "-qq", "-o", "/dev/null"])
            .args(["-e", "trace=rename,renameat,renameat2"])
            .args(["-e", "inject=rename,renameat,renameat2:error=EIO:when=2"])
            .arg(binary())
            .args(["-input", scene, "-size", "50", "50"])
            .args(["-output", "keep.tga", "-depth", "9", "10", "d.tga"])
            .output()
            .expect("strace runs (cargo xtask test installs it)");
        let text = assert_one_line_error(&output);
        assert_eq!(output.status.code(), Some(1), "{text}");
        assert!(text.contains("d.tga: cannot write"), "{text}");
        if existed {
            assert!(
                std::fs::read(&colour).unwrap() == b"old colour",
                "keep.tga is not put back"
            );
        } else {
            assert!(!colour.exists(), "the new file is removed again");
        }
        assert!(
            std::fs::read(&depth).unwrap() == b"old depth",
            "d.tga replaced"
        );
        let mut left = names_in(folder.path());
        left.retain(|name| name.starts_with('.'));
        assert!(left.is_empty(), "left behind: {left:?}");
    }
}

#[test]
fn a_link_is_written_through_and_never_to_a_device_or_with_set_id_bits() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let scene = scene.to_str().unwrap();
    let link = |target: &str, name: &str| {
        std::os::unix::fs::symlink(target, folder.path().join(name)).unwrap();
    };
    // One file by two names through a link whose target does not exist yet: refused.
    link("o.tga", "link.tga");
    let output = run_in(
        folder.path(),
        &[
            "-input", scene, "-output", "o.tga", "-depth", "8", "12", "link.tga",
        ],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(2), "{text}");
    assert!(text.contains("same file"), "{text}");
    assert!(!folder.path().join("o.tga").exists());
    // A link to a file: the file gets the picture (its mode kept without the set-user-id bit
    // and write for others), the link stays a link.
    let real = folder.path().join("real.png");
    std::fs::write(&real, b"old").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o4777)).unwrap();
    link("real.png", "out.png");
    let output = run_in(folder.path(), &["-input", scene, "-output", "out.png"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let out = folder.path().join("out.png");
    assert!(
        std::fs::symlink_metadata(&out)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(
        image::open(&real).is_ok(),
        "the link's target holds the picture"
    );
    let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o7777;
    assert_eq!(mode, 0o775);
    // A link to a device: refused, the device untouched, the link still a link.
    link("/dev/null", "null.png");
    let output = run_in(folder.path(), &["-input", scene, "-output", "null.png"]);
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(text.contains("not a regular file"), "{text}");
    assert!(
        std::fs::symlink_metadata(folder.path().join("null.png"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(!std::fs::metadata("/dev/null").unwrap().is_file());
}

// --- 3. Modes -----------------------------------------------------------------------------

#[test]
fn new_files_follow_the_umask_and_replaced_files_keep_their_mode() {
    use std::os::unix::fs::MetadataExt as _;
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let scene = scene.to_str().unwrap();
    let mode = |name: &str| {
        std::fs::metadata(folder.path().join(name))
            .unwrap()
            .permissions()
            .mode()
            & 0o777
    };
    let output = run_shell(
        folder.path(),
        "umask 022; exec",
        &["-input", scene, "-output", "c.png", "-depth_raw", "t.pfm"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!((mode("c.png"), mode("t.pfm")), (0o644, 0o644));
    let output = run_shell(
        folder.path(),
        "umask 007; exec",
        &["-input", scene, "-output", "n.tga"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(mode("n.tga"), 0o660);
    // A replaced file keeps the mode it had, whatever the umask.
    std::fs::set_permissions(
        folder.path().join("c.png"),
        std::fs::Permissions::from_mode(0o640),
    )
    .unwrap();
    let output = run_shell(
        folder.path(),
        "umask 000; exec",
        &["-input", scene, "-output", "c.png"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(mode("c.png"), 0o640);
    // Another user's file replaced by root keeps its owner and group (where the tests run as
    // root; another user cannot give a file away).
    let path = folder.path().join("c.png");
    if std::os::unix::fs::chown(&path, Some(65534), Some(65534)).is_ok() {
        let output = run_shell(
            folder.path(),
            "exec",
            &["-input", scene, "-output", "c.png"],
        );
        assert!(output.status.success(), "{}", stderr(&output));
        let metadata = std::fs::metadata(&path).unwrap();
        assert_eq!((metadata.uid(), metadata.gid()), (65534, 65534));
        assert_eq!(mode("c.png"), 0o640);
    }
}

// --- 4. Temporary files on signals and limits -----------------------------------------------

/// Starts a render of a large image and sends `signal` once its temporary output exists.
/// Returns the exit status, or `None` if the write finished before it could be caught.
fn interrupt_a_write(folder: &Path, signal: &str) -> Option<std::process::ExitStatus> {
    let scene = scene_path("scene1_02.txt");
    let mut child = Command::new(binary())
        .current_dir(folder)
        .args(["-input", scene.to_str().unwrap(), "-size", "8192", "4096"])
        .args(["-output", "c.tga", "-depth", "8", "12", "d.tga"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        if child.try_wait().unwrap().is_some() {
            return None;
        }
        let writing = names_in(folder)
            .iter()
            .any(|n| n.starts_with(".raytracer-"));
        if writing {
            let id = child.id().to_string();
            let sent = Command::new("kill").args([signal, &id]).status().unwrap();
            assert!(sent.success());
            return Some(child.wait().unwrap());
        }
        assert!(
            Instant::now() < deadline,
            "the render never started writing"
        );
        std::thread::sleep(Duration::from_millis(1));
    }
}

#[test]
fn a_termination_signal_during_the_write_leaves_no_temporary_file() {
    for (signal, code) in [
        ("-TERM", 143),
        ("-INT", 130),
        ("-QUIT", 131),
        ("-USR1", 138),
        ("-ALRM", 142),
        ("-XCPU", 152),
        ("-PROF", 155),
        ("-IO", 157),
        ("-PWR", 158),
    ] {
        let folder = tempfile::tempdir().unwrap();
        let status = (0..5)
            .find_map(|_| interrupt_a_write(folder.path(), signal))
            .expect("a write was caught in five tries");
        assert_eq!(
            status.code(),
            Some(code),
            "{signal}: exit 128 + the signal's number"
        );
        let left: Vec<String> = names_in(folder.path());
        assert!(
            left.iter().all(|n| !n.starts_with(".raytracer-")),
            "{signal}: temporary files left: {left:?}"
        );
        assert!(
            left.is_empty(),
            "{signal}: no output is half there: {left:?}"
        );
    }
}

#[test]
fn a_killed_run_s_temporary_files_are_removed_by_the_next_run_in_that_folder() {
    // A run killed with SIGKILL (nothing can be caught) leaves its temporary files; the next run
    // writing to that folder removes those of processes that have ended (left an hour ago at
    // least), and never a live process's, nor a kept old file.
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let stale = || -> Vec<String> {
        names_in(folder.path())
            .into_iter()
            .filter(|n| n.starts_with(".raytracer-"))
            .collect()
    };
    for _ in 0..20 {
        let _ = interrupt_a_write(folder.path(), "-KILL");
        if !stale().is_empty() {
            break;
        }
    }
    assert!(!stale().is_empty(), "no killed run left a temporary file");
    // Left two hours ago (a file touched in the last hour may be another machine's).
    let two_hours_ago = std::time::SystemTime::now() - Duration::from_secs(7200);
    for name in stale() {
        std::fs::File::options()
            .write(true)
            .open(folder.path().join(name))
            .unwrap()
            .set_modified(two_hours_ago)
            .unwrap();
    }
    // A live process's temporary file (this test's own process id) and a kept old file stay.
    let live = format!(".raytracer-{}-0-0.tmp", std::process::id());
    std::fs::write(folder.path().join(&live), b"live").unwrap();
    std::fs::write(folder.path().join(".raytracer-1-0.old"), b"old").unwrap();
    let output = run_in(
        folder.path(),
        &["-input", scene.to_str().unwrap(), "-output", "new.png"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let left: Vec<String> = names_in(folder.path())
        .into_iter()
        .filter(|n| n.starts_with(".raytracer-"))
        .collect();
    assert_eq!(left, [".raytracer-1-0.old".to_owned(), live]);
}

// --- 8. Full devices (closed pipes: `tests/common/cli_cases.rs`) ----------------------------------------------------

#[test]
fn a_full_device_is_a_one_line_error() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let output = Command::new(binary())
        .arg("-help")
        .stdout(full)
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(
        text.contains("No space left") || text.contains("no space"),
        "{text}"
    );
}
