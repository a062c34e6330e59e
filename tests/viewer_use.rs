//! The viewer as people use it, driven headlessly with egui_kittest: small and scaled windows,
//! precise control (fine drag, rejected values), undo and redo, named views and the view a scene
//! was last seen in, the magnifier's pixels against the frame, the shortcuts overlay, and the
//! course scenes opened from the menu that bundles them.
#![cfg(feature = "gui")]

mod common;

use std::time::{Duration, Instant};

use egui::accesskit::Role;
use egui::{Event, Key, Modifiers, MouseWheelUnit, PointerButton, Rect, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raytracer::app::ViewerApp;
use raytracer::app::ui::histogram::histogram_label_rects;
use raytracer::render::View;

use common::{click, drag, scene_path, settle, viewer, viewer_sized};

type App = Harness<'static, ViewerApp>;

fn view(harness: &App) -> View {
    *harness.state().view()
}

fn rect(harness: &App, label: &str) -> Rect {
    harness.get_by_label(label).rect()
}

/// Both images lie inside the window and each is at least `shortest` pixels on its short side.
fn assert_images_visible(harness: &App, window: Rect, shortest: u32) {
    for label in ["colour image", "depth image"] {
        let image = rect(harness, label);
        assert!(
            window.contains_rect(image),
            "{label} {image:?} inside {window:?}"
        );
    }
    let view = view(harness);
    assert!(
        view.width_px.min(view.height_px) >= shortest,
        "images {}×{} px",
        view.width_px,
        view.height_px
    );
}

#[test]
fn a_400_by_300_window_shows_both_images_and_the_controls_stay_reachable() {
    let size = vec2(400.0, 300.0);
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), size, 1.0);
    let window = Rect::from_min_size(egui::Pos2::ZERO, size);
    assert_images_visible(&harness, window, 130);
    // The toolbar's buttons are all on screen (the rest are in the More menu).
    for button in ["Open…", "Export…", "Controls", "More"] {
        assert!(window.contains_rect(rect(&harness, button)), "{button}");
    }
    // The controls open as a drawer over the images, their sliders on screen.
    click(&mut harness, "Controls");
    settle(&mut harness);
    let slider = harness
        .get_by_role_and_label(Role::Slider, "centre x")
        .rect();
    assert!(window.contains_rect(slider), "{slider:?}");
    slider_moves_the_view(&mut harness);
    // The images keep their size under the drawer.
    assert_images_visible(&harness, window, 130);
}

fn slider_moves_the_view(harness: &mut App) {
    let before = view(harness).center_world.x;
    harness
        .get_by_role_and_label(Role::Slider, "centre x")
        .set_value_accesskit(before + 0.5);
    harness.step();
    settle(harness);
    assert_eq!(view(harness).center_world.x, before + 0.5);
}

#[test]
fn an_800_by_600_window_shows_the_images_large_and_the_controls_beside_them() {
    let size = vec2(800.0, 600.0);
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), size, 1.0);
    let window = Rect::from_min_size(egui::Pos2::ZERO, size);
    assert_images_visible(&harness, window, 350);
    click(&mut harness, "Controls");
    settle(&mut harness);
    slider_moves_the_view(&mut harness);
}

#[test]
fn histogram_labels_never_overlap_in_narrow_or_scaled_windows() {
    for (size, scale) in [(vec2(400.0, 300.0), 1.0), (vec2(600.0, 450.0), 2.0)] {
        let mut harness = viewer_sized(Some(scene_path("scene1_03.txt")), size, scale);
        // Put the range's ends close together so their labels compete for room.
        {
            let range = &mut harness.state_mut().view_mut().depth_range;
            range.max_t = range.min_t + 0.01;
        }
        settle(&mut harness);
        harness.run_steps(2);
        let labels = histogram_label_rects(&harness.ctx);
        assert!(labels.len() >= 3, "{size:?}×{scale}: {labels:?}");
        for (i, a) in labels.iter().enumerate() {
            for b in &labels[i + 1..] {
                assert!(!a.intersects(*b), "{size:?}×{scale}: {a:?} overlaps {b:?}");
            }
        }
    }
}

#[test]
fn shift_drags_a_slider_at_a_tenth_of_the_speed() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let mut moved = Vec::new();
    for modifiers in [Modifiers::NONE, Modifiers::SHIFT, Modifiers::ALT] {
        harness
            .get_by_role_and_label(Role::Slider, "centre x")
            .set_value_accesskit(0.0);
        harness.step();
        settle(&mut harness);
        let slider = harness
            .get_by_role_and_label(Role::Slider, "centre x")
            .rect();
        let before = view(&harness).center_world.x;
        let from = slider.center();
        drag(
            &mut harness,
            PointerButton::Primary,
            modifiers,
            from,
            from + vec2(40.0, 0.0),
        );
        moved.push(view(&harness).center_world.x - before);
    }
    assert!(moved[0] > 0.0, "{moved:?}");
    for fine in &moved[1..] {
        let ratio = fine / moved[0];
        assert!(
            (ratio - 0.1).abs() < 0.03,
            "fine drag moved {ratio} of a drag: {moved:?}"
        );
    }
}

#[test]
fn an_invalid_value_is_shown_not_applied_and_does_not_block_later_edits() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let before = view(&harness);
    harness
        .get_by_role_and_label(Role::Slider, "size")
        .set_value_accesskit(0.0);
    harness.step();
    settle(&mut harness);
    assert_eq!(view(&harness).size_world, before.size_world, "not applied");
    assert!(
        harness.query_by_label_contains("not applied").is_some(),
        "shown as invalid"
    );
    // A later valid edit is applied, and the frame on screen is the view's.
    harness
        .get_by_role_and_label(Role::Slider, "centre y")
        .set_value_accesskit(before.center_world.y + 0.25);
    harness.step();
    settle(&mut harness);
    assert_eq!(view(&harness).center_world.y, before.center_world.y + 0.25);
    assert!(harness.state().frame_is_current());
    assert!(harness.query_by_label_contains("not applied").is_none());
}

fn press(harness: &mut App, modifiers: Modifiers, key: Key) {
    harness.key_press_modifiers(modifiers, key);
    harness.step();
    settle(harness);
}

/// Steps for `duration` (the history makes a step of a view still for 400 ms).
fn wait(harness: &mut App, duration: Duration) {
    let until = Instant::now() + duration;
    while Instant::now() < until {
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn undo_and_redo_step_through_view_changes_a_burst_at_a_time() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let start = view(&harness).center_world;
    // A burst of five key presses: one step.
    for _ in 0..5 {
        press(&mut harness, Modifiers::NONE, Key::ArrowLeft);
    }
    let after_burst = view(&harness).center_world;
    wait(&mut harness, Duration::from_millis(500));
    press(&mut harness, Modifiers::NONE, Key::ArrowUp);
    let after_up = view(&harness).center_world;
    assert!(after_burst != start && after_up != after_burst);
    press(&mut harness, Modifiers::COMMAND, Key::Z);
    assert_eq!(
        view(&harness).center_world,
        after_burst,
        "the up move undone"
    );
    press(&mut harness, Modifiers::COMMAND, Key::Z);
    assert_eq!(
        view(&harness).center_world,
        start,
        "the burst undone in one step"
    );
    press(&mut harness, Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    assert_eq!(view(&harness).center_world, after_burst);
    press(&mut harness, Modifiers::COMMAND, Key::Y);
    assert_eq!(view(&harness).center_world, after_up);
}

#[test]
fn home_after_an_idle_wait_or_at_once_is_a_step_and_undo_brings_the_view_back() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let start = view(&harness).center_world;
    // A move, then no frame at all for longer than the history waits (an idle window), then
    // Home: Ctrl+Z brings the moved view back.
    press(&mut harness, Modifiers::NONE, Key::ArrowLeft);
    let moved = view(&harness).center_world;
    std::thread::sleep(Duration::from_millis(600));
    press(&mut harness, Modifiers::NONE, Key::Home);
    assert_eq!(view(&harness).center_world, start);
    press(&mut harness, Modifiers::COMMAND, Key::Z);
    assert_eq!(view(&harness).center_world, moved, "the move before Home");
    // Arrow moves and Home at once: the moves are a step of their own, and redo brings Home.
    press(&mut harness, Modifiers::NONE, Key::ArrowUp);
    press(&mut harness, Modifiers::NONE, Key::ArrowUp);
    let up = view(&harness).center_world;
    press(&mut harness, Modifiers::NONE, Key::Home);
    press(&mut harness, Modifiers::COMMAND, Key::Z);
    assert_eq!(
        view(&harness).center_world,
        up,
        "the arrow moves before Home"
    );
    press(&mut harness, Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    assert_eq!(view(&harness).center_world, start, "Home again");
}

#[test]
fn named_views_are_kept_per_scene_and_go_back_to_the_named_camera() {
    let folder = tempfile::tempdir().unwrap();
    let scene = folder.path().join("a.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &scene).unwrap();
    let mut harness = viewer(Some(scene.clone()));
    press(&mut harness, Modifiers::NONE, Key::ArrowRight);
    let named = view(&harness);
    click(&mut harness, "name");
    harness.get_by_label("name").type_text("left side");
    harness.step();
    click(&mut harness, "Add view");
    settle(&mut harness);
    press(&mut harness, Modifiers::NONE, Key::Home);
    assert_ne!(view(&harness).center_world, named.center_world);
    click(&mut harness, "Go to left side");
    settle(&mut harness);
    assert_eq!(view(&harness).center_world, named.center_world);
    assert_eq!(view(&harness).depth_range, named.depth_range);
    let key = scene.display().to_string();
    let kept = &harness.state().settings().views.named[&key];
    assert_eq!(kept.len(), 1);
    click(&mut harness, "Forget left side");
    settle(&mut harness);
    assert!(harness.query_by_label("Go to left side").is_none());
}

#[test]
fn a_scene_opened_again_comes_back_in_the_view_it_was_left_in() {
    let folder = tempfile::tempdir().unwrap();
    let (a, b) = (folder.path().join("a.txt"), folder.path().join("b.txt"));
    std::fs::copy(scene_path("scene1_02.txt"), &a).unwrap();
    std::fs::copy(scene_path("scene1_03.txt"), &b).unwrap();
    let mut harness = viewer(Some(a.clone()));
    press(&mut harness, Modifiers::NONE, Key::ArrowDown);
    press(&mut harness, Modifiers::NONE, Key::Plus);
    let left = view(&harness);
    harness.state_mut().open(&b);
    settle(&mut harness);
    assert_ne!(view(&harness).center_world, left.center_world);
    harness.state_mut().open(&a);
    settle(&mut harness);
    assert_eq!(view(&harness).center_world, left.center_world);
    assert_eq!(view(&harness).size_world, left.size_world);
    // Reset view goes to the file's own camera; the depth range stays.
    press(&mut harness, Modifiers::NONE, Key::Home);
    assert_eq!(
        view(&harness).center_world,
        harness.state().loaded_scene().file_view.center_world
    );
    assert_eq!(view(&harness).depth_range, left.depth_range);
}

#[test]
fn the_magnifier_enlarges_the_frame_and_probes_the_pixel_under_the_pointer() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let image = rect(&harness, "colour image");
    let frame_size = {
        let (frame, _) = harness.state().shown_frame().unwrap();
        [frame.width_px, frame.height_px]
    };
    // Ctrl+wheel over the image's centre: magnify, with no new render.
    let epoch_frame = harness.state().shown_frame().unwrap().0.clone();
    harness.hover_at(image.center());
    harness.step();
    for _ in 0..6 {
        harness.event(Event::MouseWheel {
            unit: MouseWheelUnit::Point,
            delta: vec2(0.0, 120.0),
            modifiers: Modifiers::COMMAND,
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
        });
        harness.step();
    }
    settle(&mut harness);
    let magnifier = harness.state().magnifier();
    assert!(magnifier.zoom >= 4.0, "magnified {}×", magnifier.zoom);
    assert!(
        *harness.state().shown_frame().unwrap().0 == epoch_frame,
        "no new render"
    );
    // The zoom kept the point under the pointer where it was: the frame's centre pixel.
    let centre_probe = harness
        .state()
        .hover_probe()
        .expect("a probe at the centre");
    assert!(
        centre_probe.x_px.abs_diff(frame_size[0] / 2) <= 1
            && centre_probe.y_up_px.abs_diff(frame_size[1] / 2) <= 1,
        "the centre pixel stayed under the pointer: {centre_probe:?} in {frame_size:?}"
    );
    // The pixel under the pointer, computed here from the magnified region.
    let zoom = magnifier.zoom;
    let (w, h) = (f64::from(frame_size[0]), f64::from(frame_size[1]));
    let region_size = (w / zoom, h / zoom);
    let region_min = (
        (magnifier.centre.x * w - 0.5 * region_size.0).clamp(0.0, w - region_size.0),
        (magnifier.centre.y * h - 0.5 * region_size.1).clamp(0.0, h - region_size.1),
    );
    let drawn = harness.get_by_label("colour image").rect();
    let pointer = drawn.min + vec2(drawn.width() * 0.3, drawn.height() * 0.6);
    harness.hover_at(pointer);
    harness.run_steps(2);
    let expected_x =
        region_min.0 + f64::from((pointer.x - drawn.min.x) / drawn.width()) * region_size.0;
    let expected_y =
        region_min.1 + f64::from((drawn.max.y - pointer.y) / drawn.height()) * region_size.1;
    let probe = harness
        .state()
        .hover_probe()
        .expect("a probe under the pointer");
    assert_eq!(
        (probe.x_px, probe.y_up_px),
        (expected_x as u32, expected_y as u32)
    );
    let (frame, _) = harness.state().shown_frame().unwrap();
    let index = frame.index(probe.x_px, probe.y_up_px);
    assert_eq!(
        probe.colour_rgb, frame.colour[index],
        "the probe's colour is the frame's"
    );
    // 1 fits the whole image again.
    harness.event(Event::PointerGone);
    press(&mut harness, Modifiers::NONE, Key::Num1);
    assert_eq!(harness.state().magnifier().zoom, 1.0);
}

#[test]
fn f1_and_question_mark_open_the_shortcuts_overlay_and_escape_closes_it() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    press(&mut harness, Modifiers::NONE, Key::F1);
    assert!(
        harness
            .query_by_label_contains("Shortcuts and gestures")
            .is_some()
    );
    assert!(
        harness
            .query_by_label_contains("magnify the images themselves")
            .is_some()
    );
    // The build it is, as `raytracer -version` prints it.
    let version = format!("raytracer {} (commit ", env!("CARGO_PKG_VERSION"));
    assert!(harness.query_by_label_contains(&version).is_some());
    press(&mut harness, Modifiers::NONE, Key::Escape);
    assert!(!harness.state().help_open());
    harness.event(Event::Text("?".into()));
    harness.step();
    settle(&mut harness);
    assert!(harness.state().help_open());
}

#[test]
fn the_course_scenes_menu_opens_a_bundled_scene_and_replaces_an_old_error() {
    let mut harness = viewer(None);
    settle(&mut harness);
    // An error of an earlier try: a file that is not there.
    click(&mut harness, "path");
    harness.get_by_label("path").type_text("nonexistent.txt");
    harness.step();
    click(&mut harness, "Open path");
    settle(&mut harness);
    let shown_error = |harness: &App| {
        harness
            .state()
            .scene_error()
            .map(str::to_owned)
            .or_else(|| {
                harness
                    .state()
                    .message()
                    .filter(|(_, error)| *error)
                    .map(|(text, _)| text.to_owned())
            })
    };
    assert!(
        shown_error(&harness).is_some_and(|text| text.contains("nonexistent.txt")),
        "{:?}",
        shown_error(&harness)
    );
    click(&mut harness, "Course scenes");
    harness.run_steps(2);
    click(&mut harness, "scene1_04.txt");
    settle(&mut harness);
    let expected = raytracer::scene::load_scene(&scene_path("scene1_04.txt")).unwrap();
    let loaded = harness.state().loaded_scene();
    assert_eq!(*loaded.scene, expected);
    assert_eq!(loaded.name(), "scene1_04.txt");
    // The opening replaces the old error.
    assert_eq!(shown_error(&harness), None);
    let (text, error) = harness.state().message().expect("a message");
    assert!(!error && text.contains("opened scene1_04.txt"), "{text}");
}
