//! Hostile conditions at the boundary where a user meets the command line: the real binary in a
//! temporary folder, with real files, links, umasks, file-size and process limits, closed pipes,
//! full devices and signals. Each test names the promise it checks and asserts the outcome the
//! user sees: the exit status, the message, the files (intact, complete, with their modes) and
//! nothing left behind.

#[path = "common/command.rs"]
mod command;

use command::{names_in, stderr};
use std::os::unix::fs::{MetadataExt as _, PermissionsExt as _};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn binary() -> &'static str {
    env!("CARGO_BIN_EXE_raytracer")
}

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

fn run_in(folder: &Path, arguments: &[&str]) -> Output {
    Command::new(binary())
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap()
}

/// Runs the binary through `sh -c` (for umask and ulimit), in `folder`.
fn run_shell(folder: &Path, script: &str, arguments: &[&str]) -> Output {
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
fn assert_one_line_error(output: &Output) -> String {
    let text = stderr(output);
    assert!(!text.contains("panicked"), "a panic: {text}");
    assert_ne!(output.status.code(), Some(101), "a panic: {text}");
    assert!(text.lines().count() <= 1, "more than one line: {text}");
    text
}

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
            .expect("strace runs (scripts/test.sh installs it)");
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
    // writing to that folder removes those of processes that have ended, and never a live
    // process's, nor a kept old file.
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

// --- 8. Closed pipes and full devices --------------------------------------------------------

#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    for arguments in [
        vec!["-help"],
        vec![
            "-input",
            scene.to_str().unwrap(),
            "-output",
            "c.png",
            "-stats",
        ],
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let output = Command::new(binary())
            .current_dir(folder.path())
            .args(&arguments)
            .stdout(writer)
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        assert_one_line_error(&output);
        assert_eq!(
            output.status.code(),
            Some(0),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert_eq!(stderr(&output), "", "{arguments:?}: quiet");
    }
    // A usage error with stderr closed: still exit 2, no panic.
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let output = Command::new(binary())
        .arg("-bogus")
        .stderr(writer)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
}

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

// --- 9. Input size ------------------------------------------------------------------------

#[test]
fn inputs_that_never_end_or_are_too_large_are_refused_with_the_limit() {
    let folder = tempfile::tempdir().unwrap();
    let started = Instant::now();
    let output = run_in(folder.path(), &["-input", "/dev/zero", "-output", "c.png"]);
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("/dev/zero") && text.contains("not a regular file"),
        "{text}"
    );
    // A 2 GiB file (sparse: no disk used) is refused before it is read.
    let big = folder.path().join("big.txt");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(2 << 30)
        .unwrap();
    let output = run_in(folder.path(), &["-input", "big.txt", "-output", "c.png"]);
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("big.txt") && text.contains("1 GiB"),
        "states the limit: {text}"
    );
    assert!(
        started.elapsed() < Duration::from_secs(20),
        "refused without reading"
    );
    assert_eq!(names_in(folder.path()), ["big.txt"]);
}

#[test]
fn a_pipe_that_goes_on_past_the_limit_is_refused_with_it() {
    // A named pipe has no length to check beforehand: the reading stops once more than 1 GiB
    // has come, with the limit in the error, and nothing is written.
    let folder = tempfile::tempdir().unwrap();
    let pipe = folder.path().join("endless.txt");
    let made = std::process::Command::new("mkfifo")
        .arg(&pipe)
        .status()
        .unwrap();
    assert!(made.success());
    let writer = std::thread::spawn(move || {
        use std::io::Write as _;
        let mut file = std::fs::OpenOptions::new().write(true).open(pipe).unwrap();
        let block = vec![b' '; 1 << 20];
        // 1 GiB and 64 MiB, unless the reader goes away first (then writing fails).
        let mut written = 0usize;
        while written < (1 << 30) + (64 << 20) && file.write_all(&block).is_ok() {
            written += block.len();
        }
        written
    });
    let output = run_in(
        folder.path(),
        &["-input", "endless.txt", "-output", "c.png"],
    );
    let written = writer.join().unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("endless.txt") && text.contains("past 1 GiB"),
        "states the limit: {text}"
    );
    assert!(written > 1 << 30, "read past the limit: {written} bytes");
    assert_eq!(names_in(folder.path()), ["endless.txt"]);
}

// --- 10. Supersampling memory --------------------------------------------------------------

/// Runs the binary and samples its peak resident memory (VmHWM) until it exits.
fn run_measuring_peak(folder: &Path, arguments: &[&str]) -> (Output, u64) {
    let mut child = Command::new(binary())
        .current_dir(folder)
        .args(arguments)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let status_path = format!("/proc/{}/status", child.id());
    let mut peak_kib = 0u64;
    while child.try_wait().unwrap().is_none() {
        if let Ok(status) = std::fs::read_to_string(&status_path)
            && let Some(line) = status.lines().find(|l| l.starts_with("VmHWM:"))
        {
            let kib: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
            peak_kib = peak_kib.max(kib);
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let output = child.wait_with_output().unwrap();
    (output, peak_kib * 1024)
}

fn stats_value(output: &Output, name: &str) -> f64 {
    let text = String::from_utf8_lossy(&output.stdout);
    text.lines()
        .find_map(|line| line.strip_prefix(&format!("{name}: ")))
        .unwrap_or_else(|| panic!("no {name} in {text}"))
        .parse()
        .unwrap()
}

#[test]
fn supersampling_memory_stays_within_the_stated_bound() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    // Wide, many samples, a wide filter: every band used to hold all its samples at once
    // (16 rows and a halo of 8 on each side × 2048 columns × 64 samples × 24 bytes ≈ 100 MB,
    // once per thread); tiles now hold 32 MB each.
    let (output, peak) = run_measuring_peak(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-size",
            "2048",
            "16",
            "-uniform_samples",
            "64",
            "-gaussian_filter",
            "4",
            "-output",
            "c.png",
            "-stats",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let bound = stats_value(&output, "memory_bound_mb") * 1e6;
    let reported = stats_value(&output, "peak_memory_mb") * 1e6;
    assert!(
        peak as f64 <= bound,
        "peak {peak} B over the bound {bound} B"
    );
    assert!(
        reported <= bound,
        "reported peak {reported} B over the bound {bound} B"
    );
    assert!(
        bound < 400e6,
        "the bound is small for a 2048×48 image: {bound} B"
    );
}

#[test]
fn a_request_that_cannot_fit_in_memory_is_refused_with_the_figure() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let scene = scene.to_str().unwrap();
    // 600 MB of address space: the binary runs, a whole 64 Mpx frame (more than a gigabyte)
    // cannot.
    let limited = |arguments: &[&str]| {
        Command::new("prlimit")
            .arg("--as=600000000:600000000")
            .arg(binary())
            .current_dir(folder.path())
            .args(["-input", scene, "-size", "8192", "8192"])
            .args(arguments)
            .output()
            .unwrap()
    };
    // A PNG is encoded from the whole frame.
    let output = limited(&["-output", "c.png"]);
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("MB") && text.contains("memory"),
        "says the figure: {text}"
    );
    assert!(names_in(folder.path()).is_empty());
    // The course's own command is drawn and written strip by strip: it fits, and writes both.
    let output = limited(&["-output", "c.tga", "-depth", "8", "12", "d.tga"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(names_in(folder.path()), ["c.tga", "d.tga"]);
    let tga_bytes = 18 + 8192 * 8192 * 3;
    for name in ["c.tga", "d.tga"] {
        let length = std::fs::metadata(folder.path().join(name)).unwrap().len();
        assert_eq!(length, tga_bytes, "{name}");
    }
}

#[test]
fn small_runs_are_not_refused_for_memory_the_program_already_holds() {
    // Under 250 MB of address space, most of it reserved by the program itself before any
    // work (code, libraries, thread stacks), a 200×200 render (a peak of about 20 MB) and a 1×1
    // one run: the check counts what the run adds.
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    for size in ["200", "1"] {
        let output = Command::new("prlimit")
            .arg("--as=250000000:250000000")
            .arg(binary())
            .current_dir(folder.path())
            .args(["-input", scene.to_str().unwrap(), "-size", size, size])
            .args(["-output", "c.png"])
            .output()
            .unwrap();
        assert!(output.status.success(), "{size}: {}", stderr(&output));
    }
}

// --- 11. No thread can be created -----------------------------------------------------------

#[test]
fn without_threads_the_render_still_runs_on_one() {
    let folder = tempfile::tempdir().unwrap();
    std::fs::set_permissions(folder.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
    let scene = folder.path().join("scene.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &scene).unwrap();
    std::fs::set_permissions(&scene, std::fs::Permissions::from_mode(0o644)).unwrap();
    // The unprivileged user may not reach the build folder (a checkout in a private folder): it
    // runs a copy of the binary from the open one.
    let program = folder.path().join("raytracer");
    std::fs::copy(binary(), &program).unwrap();
    std::fs::set_permissions(&program, std::fs::Permissions::from_mode(0o755)).unwrap();
    // Limited to one process: no thread can be started. The limit does not bind root, so as
    // root the run is made as an unprivileged user (setpriv); as anyone else, as that user.
    let is_root = std::fs::metadata(&program).unwrap().uid() == 0;
    let mut command = if is_root {
        let mut command = Command::new("setpriv");
        command
            .args(["--reuid=65534", "--regid=65534", "--clear-groups"])
            .arg("prlimit");
        command
    } else {
        Command::new("prlimit")
    };
    let output = command
        .arg("--nproc=1:1")
        .arg(&program)
        .current_dir(folder.path())
        .args(["-input", "scene.txt", "-output", "c.png", "-stats"])
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(0), "{text}");
    assert_eq!(stats_value(&output, "threads"), 1.0);
    let picture = image::open(folder.path().join("c.png")).unwrap();
    assert_eq!(picture.width(), 200);
}

// --- 12. Camera sizes the arithmetic cannot resolve -----------------------------------------

#[test]
fn a_camera_too_small_to_resolve_is_refused_with_the_reason() {
    let folder = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(scene_path("scene1_01.txt")).unwrap();
    let size_line = text
        .lines()
        .find(|l| l.trim_start().starts_with("size"))
        .unwrap();
    for size in ["1e-308", "1e-200"] {
        let tiny = text.replace(size_line, &format!("    size {size}"));
        std::fs::write(folder.path().join("tiny.txt"), tiny).unwrap();
        let output = run_in(folder.path(), &["-input", "tiny.txt", "-output", "c.png"]);
        let message = assert_one_line_error(&output);
        assert_eq!(output.status.code(), Some(1), "{size}: {message}");
        assert!(message.contains("tiny.txt:"), "names the line: {message}");
        assert!(
            message.contains("1e-150"),
            "states the smallest size: {message}"
        );
    }
    assert_eq!(names_in(folder.path()), ["tiny.txt"]);
}

// --- Also expected -----------------------------------------------------------------------

#[test]
fn an_empty_input_path_a_byte_order_mark_and_comments_get_clear_answers() {
    let folder = tempfile::tempdir().unwrap();
    let output = run_in(folder.path(), &["-input", "", "-output", "c.png"]);
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(2), "{text}");
    assert!(text.contains("-input") && text.contains("empty"), "{text}");
    // A UTF-8 byte-order mark (as some Windows editors write) is accepted.
    let scene = std::fs::read(scene_path("scene1_01.txt")).unwrap();
    let mut with_bom = b"\xEF\xBB\xBF".to_vec();
    with_bom.extend_from_slice(&scene);
    std::fs::write(folder.path().join("bom.txt"), with_bom).unwrap();
    let output = run_in(folder.path(), &["-input", "bom.txt", "-output", "bom.png"]);
    assert!(output.status.success(), "{}", stderr(&output));
    // A comment: the format has none, and the message says so.
    for comment in ["# my scene", "// my scene"] {
        let text = format!("{comment}\n{}", String::from_utf8_lossy(&scene));
        std::fs::write(folder.path().join("c.txt"), text).unwrap();
        let output = run_in(folder.path(), &["-input", "c.txt", "-output", "c.png"]);
        let message = assert_one_line_error(&output);
        assert_eq!(output.status.code(), Some(1), "{message}");
        assert!(message.contains("c.txt:1:1"), "{message}");
        assert!(message.contains("no comments"), "{message}");
    }
}

#[test]
fn without_a_display_the_viewer_says_so_in_one_line() {
    let output = Command::new(binary())
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(
        text.contains("no display") && text.contains("-output"),
        "{text}"
    );
}

// --- 13. What the user typed, in messages; numbers kept in 32 bits ------------------------------

#[test]
fn what_the_user_typed_reaches_the_terminal_escaped_and_shortened() {
    let folder = tempfile::tempdir().unwrap();
    // A file name with a newline and a colour escape sequence: one line, no raw escape.
    let output = run_in(
        folder.path(),
        &["-input", "a\nb\u{1b}[31m.txt", "-output", "c.png"],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(!text.contains('\u{1b}'), "{text:?}");
    assert!(text.contains("a\\nb\\u{1b}[31m.txt"), "{text}");
    // A 120 KB value is cut in the middle, saying how much was left out.
    let long = "7".repeat(120_000);
    let output = run_in(
        folder.path(),
        &["-input", "s.txt", "-size", &long, "10", "-output", "c.png"],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(2), "{text}");
    assert!(text.len() < 600, "{} bytes", text.len());
    assert!(text.contains("characters left out"), "{text}");
}

#[test]
fn numbers_are_not_narrowed_into_false_answers() {
    let folder = tempfile::tempdir().unwrap();
    // A colour channel beyond the 32-bit range (but within the documented 1e150) is accepted:
    // the background shows full red.
    let text = std::fs::read_to_string(scene_path("scene1_01.txt")).unwrap();
    let background = text
        .lines()
        .find(|line| line.contains("Background"))
        .unwrap();
    let bright = text.replace(background, "Background { color 1e39 0 0 }");
    std::fs::write(folder.path().join("bright.txt"), bright).unwrap();
    let output = run_in(
        folder.path(),
        &[
            "-input",
            "bright.txt",
            "-output",
            "c.png",
            "-size",
            "20",
            "20",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let picture = image::open(folder.path().join("c.png")).unwrap().to_rgb8();
    assert_eq!(picture.get_pixel(0, 0).0, [255, 0, 0]);
    // A filter size that 32 bits would make 0 is refused as given, not as "0".
    let output = run_in(
        folder.path(),
        &[
            "-input",
            "bright.txt",
            "-output",
            "t.png",
            "-tent_filter",
            "1e-50",
        ],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(2), "{text}");
    assert!(text.contains("'1e-50'"), "{text}");
    // A depth range wider than the largest number is refused with the reason, nothing written.
    let output = run_in(
        folder.path(),
        &["-input", "bright.txt", "-depth", "-1e308", "1e308", "d.png"],
    );
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(2), "{text}");
    assert!(text.contains("DMAX − DMIN"), "{text}");
    assert!(!folder.path().join("d.png").exists());
}

#[test]
fn a_missing_scene_is_said_before_anything_about_the_display() {
    // A display that is set but not there: the missing file is the answer.
    let folder = tempfile::tempdir().unwrap();
    let output = Command::new(binary())
        .current_dir(folder.path())
        .env("DISPLAY", ":99")
        .env_remove("WAYLAND_DISPLAY")
        .args(["-input", "missing.txt"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(text.starts_with("raytracer: missing.txt: "), "{text}");
}
