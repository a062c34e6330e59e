//! The real binary in a real window: starts Xvfb, runs `raytracer -input scene1_01.txt`, takes
//! screenshots of the X screen (ImageMagick's `import`) until the first frame is up, and checks
//! that both images are on screen: the red disc of the colour image and, to its right, the grey
//! disc of the depth image (white at its centre, t = 9, darkening outwards).
//!
//! Needs `Xvfb` and `import` (cargo xtask test installs them); the test fails, with that message,
//! where they are missing.
#![cfg(feature = "gui")]

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use common::xvfb::{KillOnDrop, screenshot, start_xvfb, viewer_command};
use image::RgbImage;

/// Centroid and count of the pixels matching `predicate`.
fn blob(image: &RgbImage, predicate: impl Fn(&image::Rgb<u8>) -> bool) -> (f64, f64, usize) {
    blob_in_rows(image, 0..image.height(), predicate)
}

/// [`blob`] over the image rows `rows` only.
fn blob_in_rows(
    image: &RgbImage,
    rows: std::ops::Range<u32>,
    predicate: impl Fn(&image::Rgb<u8>) -> bool,
) -> (f64, f64, usize) {
    let (mut sx, mut sy, mut n) = (0.0, 0.0, 0usize);
    for (x, y, pixel) in image.enumerate_pixels() {
        if rows.contains(&y) && predicate(pixel) {
            sx += f64::from(x);
            sy += f64::from(y);
            n += 1;
        }
    }
    if n == 0 {
        (0.0, 0.0, 0)
    } else {
        (sx / n as f64, sy / n as f64, n)
    }
}

#[test]
fn real_window_shows_colour_and_depth_side_by_side() {
    // Painted with OpenGL unless asked otherwise.
    let shown = shows_both_images(None, &[]);
    assert_eq!(shown.renderer, "glow");
}

#[test]
fn real_window_painted_with_wgpu_when_asked_shows_both_images() {
    let shown = shows_both_images(Some("wgpu"), &[]);
    assert_eq!(shown.renderer, "wgpu");
}

/// Mesa finds no OpenGL driver (its Vulkan one is found apart).
const NO_OPENGL: [(&str, &str); 2] = [
    ("LIBGL_DRIVERS_PATH", "/nonexistent"),
    ("GALLIUM_DRIVER", "nonexistent"),
];

#[test]
fn where_opengl_cannot_start_the_window_is_painted_with_wgpu() {
    let Shown {
        renderer, stderr, ..
    } = shows_both_images(None, &NO_OPENGL);
    assert_eq!(renderer, "wgpu");
    assert!(
        stderr.contains("raytracer: OpenGL could not start (")
            && stderr.contains("painting with wgpu"),
        "the fallback is said: {stderr}"
    );
}

#[test]
fn opengl_asked_for_where_it_cannot_start_is_an_error_not_another_renderer() {
    let (_xvfb, display) = start_xvfb();
    let environment = [("RAYTRACER_RENDERER", "glow"), NO_OPENGL[0], NO_OPENGL[1]];
    let (status, stderr) = run_until_it_ends(
        &display,
        &environment,
        Duration::from_secs(60),
        "the viewer did not end within 60 s: it opened with another renderer",
    );
    assert_eq!(status, Some(1), "{stderr}");
    assert!(stderr.contains("cannot open the viewer window"), "{stderr}");
    assert!(!stderr.contains("painting with wgpu"), "{stderr}");
}

#[test]
fn an_unknown_renderer_is_refused_naming_the_choices() {
    // Checked before the display is: no X server is needed (none answers on this display).
    let (status, stderr) = run_until_it_ends(
        ":9999",
        &[("RAYTRACER_RENDERER", "vulkan")],
        Duration::from_secs(30),
        "the viewer did not end within 30 s: it opened instead of refusing",
    );
    assert_eq!(status, Some(2), "a usage error: {stderr}");
    assert_eq!(
        stderr.trim_end(),
        "raytracer: RAYTRACER_RENDERER is \"vulkan\": it must be glow (OpenGL) or wgpu"
    );
}

/// Runs the viewer on scene1_01 on `display` with the variables `environment` until it ends (it
/// fails with `late` after `within`): its exit status and standard error.
fn run_until_it_ends(
    display: &str,
    environment: &[(&str, &str)],
    within: Duration,
    late: &str,
) -> (Option<i32>, String) {
    let home = tempfile::tempdir().unwrap();
    let scene: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_01.txt");
    let child = viewer_command(display, home.path())
        .envs(environment.iter().copied())
        .arg("-input")
        .arg(&scene)
        .spawn()
        .unwrap();
    let mut viewer = KillOnDrop(child);
    let status = viewer.wait_within(within, late);
    (status.code(), viewer.stderr_text())
}

/// What a viewer with both images on screen showed of itself.
struct Shown {
    /// The renderer its frame log names.
    renderer: String,
    /// What it wrote on standard error.
    stderr: String,
}

/// The first pixel left of the red disc at `(x, y)` once past its black background.
fn frame_left_of(shot: &RgbImage, x: u32, y: u32) -> image::Rgb<u8> {
    let pixels = (0..x).rev().map(|x| *shot.get_pixel(x, y));
    pixels
        .skip_while(|p| p[0] > 250 && p[1] < 5 && p[2] < 5)
        .find(|p| p.0 != [0, 0, 0])
        .unwrap_or(image::Rgb([0, 0, 0]))
}

/// Runs the viewer on scene1_01 with `RAYTRACER_RENDERER` set to `renderer` (unset with `None`)
/// and the variables `environment` until both images are on screen.
fn shows_both_images(renderer: Option<&str>, environment: &[(&str, &str)]) -> Shown {
    let (_xvfb, display) = start_xvfb();
    let home = tempfile::tempdir().unwrap();
    let scene: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_01.txt");
    let log = home.path().join("frames.log");
    let mut command = viewer_command(&display, home.path());
    command
        .env("RAYTRACER_FRAME_LOG", &log)
        .envs(environment.iter().copied());
    if let Some(renderer) = renderer {
        command.env("RAYTRACER_RENDERER", renderer);
    }
    let viewer = command.arg("-input").arg(&scene).spawn().unwrap();
    let mut viewer = KillOnDrop(viewer);

    let shot_path = home.path().join("screen.png");
    let deadline = Instant::now() + Duration::from_secs(90);
    loop {
        if let Ok(Some(status)) = viewer.0.try_wait() {
            panic!(
                "the viewer exited early ({status}): {}",
                viewer.stderr_text()
            );
        }
        if let Some(shot) = screenshot(&display, &shot_path) {
            let red = blob(&shot, |p| p[0] > 250 && p[1] < 5 && p[2] < 5);
            // White near the red disc's rows: the depth disc's centre (the histogram's legend
            // strip below the depth image has white too).
            let red_row = red.1 as u32;
            let white = blob_in_rows(&shot, red_row.saturating_sub(60)..red_row + 60, |p| {
                p[0] > 245 && p[0] == p[1] && p[1] == p[2]
            });
            let mid_grey = blob(&shot, |p| {
                (60..200).contains(&p[0]) && p[0] == p[1] && p[1] == p[2]
            });
            if red.2 > 2000 && white.2 > 20 && mid_grey.2 > 2000 {
                // The depth disc is to the right of the colour disc, at the same height.
                assert!(
                    white.0 > red.0 + 100.0,
                    "depth right of colour: {white:?} {red:?}"
                );
                assert!(
                    (white.1 - red.1).abs() < 20.0,
                    "same height: {white:?} {red:?}"
                );
                // A frame shows where the colour image ends: left of the disc, past the image's
                // black background, a line lighter than the panel.
                let frame = frame_left_of(&shot, red.0 as u32, red_row);
                assert!(
                    frame[0] == frame[1] && frame[1] == frame[2] && (70..=200).contains(&frame[0]),
                    "no frame left of the colour image: {frame:?}"
                );
                // The default window's screenshot (the tests run at once).
                let keep = std::env::var_os("RAYTRACER_KEEP_SCREENSHOT").map(PathBuf::from);
                if let Some(keep) = keep.filter(|_| renderer.is_none() && environment.is_empty()) {
                    shot.save(keep).unwrap();
                }
                let log = std::fs::read_to_string(&log).unwrap();
                let first = log.lines().next().unwrap_or_default();
                let renderer = first
                    .strip_prefix("renderer ")
                    .unwrap_or_else(|| panic!("no renderer line first in the frame log: {log}"))
                    .to_owned();
                let _ = viewer.0.kill();
                let _ = viewer.0.wait();
                return Shown {
                    renderer,
                    stderr: viewer.stderr_text(),
                };
            }
        }
        assert!(Instant::now() < deadline, "no frame on screen after 90 s");
        std::thread::sleep(Duration::from_millis(500));
    }
}

/// Live reload with no input at all: the scene file is edited on disk (its sphere turns from red
/// to green) while nobody touches the window, and the window shows the new scene by itself.
#[test]
fn an_edited_scene_appears_without_any_input() {
    let (_xvfb, display) = start_xvfb();
    let home = tempfile::tempdir().unwrap();
    let scene = home.path().join("scene.txt");
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_01.txt"))
            .unwrap();
    std::fs::write(&scene, &text).unwrap();
    let viewer = viewer_command(&display, home.path())
        .arg("-input")
        .arg(&scene)
        .spawn()
        .unwrap();
    let mut viewer = KillOnDrop(viewer);
    let shot_path = home.path().join("screen.png");
    let disc_of = |shot: &RgbImage, channel: usize| {
        blob(shot, |p| {
            p[channel] > 250 && (0..3).all(|c| c == channel || p[c] < 5)
        })
        .2
    };
    let wait_for = |viewer: &mut KillOnDrop, channel: usize, seconds: u64| {
        let deadline = Instant::now() + Duration::from_secs(seconds);
        loop {
            if let Ok(Some(status)) = viewer.0.try_wait() {
                panic!("the viewer exited ({status}): {}", viewer.stderr_text());
            }
            if screenshot(&display, &shot_path).is_some_and(|shot| disc_of(&shot, channel) > 2000) {
                return true;
            }
            if Instant::now() > deadline {
                return false;
            }
            std::thread::sleep(Duration::from_millis(300));
        }
    };
    assert!(
        wait_for(&mut viewer, 0, 90),
        "no red disc on screen after 90 s"
    );
    // Let the first frames pass, then edit the file as an editor would.
    std::thread::sleep(Duration::from_secs(1));
    std::fs::write(
        &scene,
        text.replace("diffuseColor 1 0 0", "diffuseColor 0 1 0"),
    )
    .unwrap();
    assert!(
        wait_for(&mut viewer, 1, 10),
        "the edited scene (a green disc) was not shown within 10 s without input"
    );
}
