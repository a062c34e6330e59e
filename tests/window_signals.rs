//! The real viewer window under Xvfb, stopped by a termination signal: it closes the way Ctrl+Q
//! or the close button does, saving its settings (here, the scene it had open), and ends with
//! 128 + the signal's number; started again without a file, it reopens that scene.
#![cfg(feature = "gui")]

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use common::xvfb::{KillOnDrop, screenshot, start_xvfb, viewer_command};

/// Every file under `folder`, read as text.
fn texts_under(folder: &Path) -> Vec<String> {
    let mut texts = Vec::new();
    let Ok(entries) = std::fs::read_dir(folder) else {
        return texts;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            texts.extend(texts_under(&path));
        } else if let Ok(text) = std::fs::read_to_string(&path) {
            texts.push(text);
        }
    }
    texts
}

#[test]
fn sigterm_saves_the_settings_before_the_viewer_ends() {
    let (_xvfb, display) = start_xvfb();
    let home = tempfile::tempdir().unwrap();
    // A scene under a name no setting holds yet, with a colour no other scene has: an orange
    // background.
    let scene: PathBuf = home.path().join("signalled-scene.txt");
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_02.txt"))
            .unwrap();
    let background = text.lines().find(|l| l.contains("Background")).unwrap();
    std::fs::write(
        &scene,
        text.replace(background, "Background { color 1 0.5 0 }"),
    )
    .unwrap();
    let child = viewer_command(&display, home.path())
        .arg("-input")
        .arg(&scene)
        .spawn()
        .unwrap();
    let mut viewer = KillOnDrop(child);
    // Wait for the window to draw the scene (its green discs), so the scene has been opened.
    let shot = home.path().join("screen.png");
    let deadline = Instant::now() + Duration::from_secs(90);
    loop {
        assert!(
            viewer.0.try_wait().unwrap().is_none(),
            "the viewer ended early"
        );
        let green = screenshot(&display, &shot).map_or(0, |image| {
            image
                .pixels()
                .filter(|p| p[1] > 200 && p[0] < 60 && p[2] < 60)
                .count()
        });
        if green > 2000 {
            break;
        }
        assert!(Instant::now() < deadline, "no frame on screen after 90 s");
        std::thread::sleep(Duration::from_millis(300));
    }
    // Nothing saved yet (eframe saves every 30 s and on exit).
    let name = scene.display().to_string();
    assert!(
        texts_under(&home.path().join("data"))
            .iter()
            .all(|t| !t.contains(&name))
    );
    let sent = std::process::Command::new("kill")
        .args(["-TERM", &viewer.0.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let status = viewer.wait_within(
        Duration::from_secs(30),
        "the viewer did not end after SIGTERM",
    );
    assert_eq!(status.code(), Some(143), "exit 128 + 15");
    assert!(
        texts_under(&home.path().join("data"))
            .iter()
            .any(|t| t.contains(&name)),
        "the settings name the open scene"
    );
    drop(viewer);

    // Started again without a file, it reopens that scene.
    let mut again = KillOnDrop(viewer_command(&display, home.path()).spawn().unwrap());
    wait_for_orange(&mut again, &display, &shot);
}

/// Waits until the window shows the orange background of the test's scene (so it has opened
/// it).
fn wait_for_orange(viewer: &mut KillOnDrop, display: &str, shot: &Path) {
    let deadline = Instant::now() + Duration::from_secs(90);
    loop {
        assert!(
            viewer.0.try_wait().unwrap().is_none(),
            "the viewer ended early"
        );
        let orange = screenshot(display, shot).map_or(0, |image| {
            image
                .pixels()
                .filter(|p| p[0] == 255 && p[1] == 127 && p[2] == 0)
                .count()
        });
        if orange > 2000 {
            return;
        }
        assert!(
            Instant::now() < deadline,
            "no orange frame on screen after 90 s"
        );
        std::thread::sleep(Duration::from_millis(300));
    }
}
