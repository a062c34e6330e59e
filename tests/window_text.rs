//! Text in other scripts in the real window: a scene in a folder and under a name written in
//! Chinese, Japanese, Korean, Cyrillic, Greek and Arabic is opened under Xvfb, and the viewer's
//! frame log says how many characters of the name, as the status bar shows it, no font has (each
//! would be drawn as a box). egui's own fonts cover Latin, Cyrillic and Greek; the rest must come
//! from the system's fonts (cargo xtask test installs a CJK font, WenQuanYi Micro Hei, beside
//! DejaVu Sans, which has Arabic).
//!
//! `RAYTRACER_KEEP_TEXT_SCREENSHOT=FILE` keeps the screenshot, to look at.
#![cfg(feature = "gui")]

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use common::xvfb::{KillOnDrop, screenshot, start_xvfb, viewer_command};

/// The folder and the file name: Chinese, then Japanese, Korean, Cyrillic, Greek and Arabic.
const FOLDER: &str = "作业一";
const FILE: &str = "場面_장면_сцена_σκηνή_مشهد.txt";

#[test]
fn a_scene_named_in_other_scripts_is_drawn_with_no_box() {
    let (_xvfb, display) = start_xvfb();
    let home = tempfile::tempdir().unwrap();
    let folder = home.path().join(FOLDER);
    std::fs::create_dir(&folder).unwrap();
    let scene = folder.join(FILE);
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_01.txt"),
        &scene,
    )
    .unwrap();
    let log = home.path().join("frames.log");
    let viewer = viewer_command(&display, home.path())
        .env("RAYTRACER_FRAME_LOG", &log)
        .arg("-input")
        .arg(&scene)
        .spawn()
        .unwrap();
    let mut viewer = KillOnDrop(viewer);

    // A frame on screen, then two more seconds (a font found on demand is in by then).
    let deadline = Instant::now() + Duration::from_secs(90);
    let mut shown_since = None;
    let lines = loop {
        if let Ok(Some(status)) = viewer.0.try_wait() {
            panic!("the viewer exited ({status}): {}", viewer.stderr_text());
        }
        let text = std::fs::read_to_string(&log).unwrap_or_default();
        if shown_since.is_none() && text.lines().any(|line| line.starts_with("frame ")) {
            shown_since = Some(Instant::now());
        }
        if shown_since.is_some_and(|at| at.elapsed() > Duration::from_secs(2)) {
            break text;
        }
        assert!(Instant::now() < deadline, "no frame after 90 s: {text}");
        std::thread::sleep(Duration::from_millis(200));
    };
    let keep = std::env::var_os("RAYTRACER_KEEP_TEXT_SCREENSHOT").map(PathBuf::from);
    if let Some(keep) = keep {
        let shot = screenshot(&display, &home.path().join("screen.png")).expect("a screenshot");
        shot.save(keep).unwrap();
    }
    let last = lines
        .lines()
        .rev()
        .find_map(|line| line.strip_prefix("missing-glyphs "))
        .unwrap_or_else(|| panic!("no missing-glyphs line in the frame log: {lines}"));
    let (count, name) = last.split_once(' ').unwrap();
    assert!(
        name.contains(FILE),
        "the status bar's name {name:?} is not the scene's"
    );
    assert_eq!(count, "0", "characters drawn as a box in {name:?}");
}
