//! Helpers shared by the viewer tests: the real app in an egui_kittest harness, waiting for it
//! to settle, and clicking a widget the way a user does.
#![allow(dead_code)] // each test file uses its own share

pub(crate) mod xvfb;

use std::path::{Path, PathBuf};

use egui::{Event, Modifiers, PointerButton, Pos2};
use std::time::{Duration, Instant};

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raytracer::app::ViewerApp;
use raytracer::cli::ViewerRequest;

/// A scene shipped in `scenes/`.
pub(crate) fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

/// The viewer in a 1000×700-point window on `input` (the embedded default scene for `None`),
/// settled.
pub(crate) fn viewer(input: Option<PathBuf>) -> Harness<'static, ViewerApp> {
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_eframe(move |cc| {
            ViewerApp::new(
                cc,
                ViewerRequest {
                    input,
                    ..Default::default()
                },
            )
        });
    settle(&mut harness);
    harness
}

/// Steps the UI until the frame on screen is the current view (no scene loading), nothing is
/// being written and no smooth scroll is still running.
pub(crate) fn settle(harness: &mut Harness<'static, ViewerApp>) {
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.step();
        let scrolling = harness.ctx.input(egui::InputState::is_scrolling);
        let app = harness.state();
        if app.frame_is_current() && !app.export_running() && !scrolling {
            return;
        }
        assert!(Instant::now() < deadline, "the viewer did not settle");
        app.wait_for_worker(Duration::from_millis(20));
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Scrolls the widget labelled `label` into view, moves the pointer onto it (a press where the
/// pointer has not been yet belongs to the widget under its last position), then clicks it.
pub(crate) fn click(harness: &mut Harness<'static, ViewerApp>, label: &str) {
    // Changes made to the state directly show in the layout a pass later.
    harness.run_steps(2);
    harness.get_by_label(label).scroll_to_me();
    // The scroll is animated, and the accessibility tree describes the previous pass: step until
    // the widget stays where it is.
    harness.run_steps(2);
    let mut rect = harness.get_by_label(label).rect();
    for _ in 0..60 {
        harness.step();
        let now = harness.get_by_label(label).rect();
        if now == rect {
            break;
        }
        rect = now;
    }
    harness.step();
    harness.get_by_label(label).hover();
    harness.step();
    harness.get_by_label(label).click();
    harness.step();
}

/// Presses `button` at `from`, moves to `to` in a few steps and releases.
pub(crate) fn drag(
    harness: &mut Harness<'static, ViewerApp>,
    button: PointerButton,
    modifiers: Modifiers,
    from: Pos2,
    to: Pos2,
) {
    harness.event(Event::ModifiersChanged(modifiers));
    harness.hover_at(from);
    harness.step();
    harness.event(Event::PointerButton {
        pos: from,
        button,
        pressed: true,
        modifiers,
    });
    harness.step();
    for step in 1..=4 {
        harness.hover_at(from + (to - from) * (step as f32 / 4.0));
        harness.step();
    }
    harness.event(Event::PointerButton {
        pos: to,
        button,
        pressed: false,
        modifiers,
    });
    harness.step();
    harness.event(Event::ModifiersChanged(Modifiers::NONE));
    harness.event(Event::PointerGone);
    settle(harness);
}

/// The viewer in a window of `size` points at `pixels_per_point` on `input`, settled.
pub(crate) fn viewer_sized(
    input: Option<PathBuf>,
    size: egui::Vec2,
    pixels_per_point: f32,
) -> Harness<'static, ViewerApp> {
    let mut harness = Harness::builder()
        .with_size(size)
        .with_pixels_per_point(pixels_per_point)
        .build_eframe(move |cc| {
            ViewerApp::new(
                cc,
                ViewerRequest {
                    input,
                    ..Default::default()
                },
            )
        });
    settle(&mut harness);
    harness
}

/// Steps until no comparison is being computed and the frame on screen is current.
pub(crate) fn wait_for_comparison(harness: &mut Harness<'static, ViewerApp>) {
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        harness.step();
        if !harness.state().comparing() {
            break;
        }
        assert!(Instant::now() < deadline, "the comparison did not finish");
        std::thread::sleep(Duration::from_millis(5));
    }
    settle(harness);
    harness.run_steps(2);
}

/// Types `path` into the Compare section's image field and presses "Compare image".
pub(crate) fn compare_image(harness: &mut Harness<'static, ViewerApp>, path: &str) {
    harness.get_by_label("image").scroll_to_me();
    harness.run_steps(3);
    harness.get_by_label("image").click();
    harness.step();
    harness.get_by_label("image").type_text(path);
    harness.step();
    click(harness, "Compare image");
    wait_for_comparison(harness);
}

/// Whether a widget whose label contains `text` is shown.
pub(crate) fn label_shown(harness: &Harness<'static, ViewerApp>, text: &str) -> bool {
    harness.query_by_label_contains(text).is_some()
}

/// A file dropped on the window, as the desktop's integration hands it over: by its path.
#[derive(Debug)]
pub(crate) struct DroppedOnTheWindow(pub(crate) PathBuf);

impl egui::DroppedFile for DroppedOnTheWindow {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|error| error.to_string())
    }
}

/// `n` with its thousands separated by commas, as the viewer writes counts.
pub(crate) fn with_commas(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, digit) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(digit);
    }
    out
}
