//! Limits and messages at the boundary where a user meets the command line: the real binary in
//! a temporary folder, with input-size, memory, address-space and process limits, hostile
//! numbers and names, and no display. (Files, links, modes, signals and pipes:
//! `tests/robustness.rs`.)

#[path = "common/command.rs"]
mod command;

use std::os::unix::fs::{MetadataExt as _, PermissionsExt as _};
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use command::{assert_one_line_error, binary, names_in, run_in, scene_path, stderr};

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
    let child = Command::new(binary())
        .current_dir(folder)
        .args(arguments)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    command::wait_measuring_peak(child)
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
fn comparing_images_stays_within_the_stated_bound_and_is_refused_when_it_cannot_fit() {
    // Their images with a mistake at 768² (the diagnosis tries dozens of renders; it keeps six
    // at once): the peak stays within the bound -stats states.
    let folder = tempfile::tempdir().unwrap();
    let scene_file = scene_path("scene1_07.txt");
    let scene = raytracer::scene::load_scene(&scene_file).unwrap();
    let view = raytracer::render::View::of_camera(
        &scene.camera,
        768,
        768,
        raytracer::render::depth_map::DepthRange::new(-2.0, 2.0),
    );
    let mistakes = raytracer::compare::MistakeSet::of(&[raytracer::compare::Mistake::PixelCorners]);
    let (colour, depth) = raytracer::oracle::mistaken::render_variant(&scene, &view, mistakes);
    colour.save(folder.path().join("mine.png")).unwrap();
    depth.save(folder.path().join("mine_depth.png")).unwrap();
    let scene_arg = scene_file.to_str().unwrap();
    let compare = [
        "-input",
        scene_arg,
        "-compare_output",
        "mine.png",
        "-compare_depth",
        "mine_depth.png",
        "-diff",
        "diff.png",
        "-stats",
    ];
    let (output, peak) = run_measuring_peak(folder.path(), &compare);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let bound = stats_value(&output, "memory_bound_mb") * 1e6;
    assert!(
        peak as f64 <= bound,
        "peak {peak} B over the bound {bound} B"
    );
    std::fs::remove_file(folder.path().join("diff.png")).unwrap();
    // Under a limit the comparison cannot fit in, it is refused before any work, with the
    // figure, and nothing is written.
    let output = Command::new("prlimit")
        .arg("--as=350000000:350000000")
        .arg(binary())
        .current_dir(folder.path())
        .args(compare)
        .output()
        .unwrap();
    let text = assert_one_line_error(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(text.contains("MB more memory"), "{text}");
    assert!(!folder.path().join("diff.png").exists());
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
