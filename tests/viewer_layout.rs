//! The viewer's controls and probe at the window sizes people use, driven headlessly with
//! egui_kittest: sliders as wide as the panel whose steps follow the value, every line of the
//! probe readable (wrapped, and scrolled to when they do not fit), and the controls beside the
//! images in an 800-point window and over them, as tall as the window, in smaller ones; the
//! shortcuts overlay whole at those sizes; no-hit pixels on screen in a colour the map lacks.
#![cfg(feature = "gui")]

mod common;

use egui::accesskit::Role;
use egui::{Event, Modifiers, MouseWheelUnit, PointerButton, Pos2, Rect, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use raytracer::app::ViewerApp;
use raytracer::render::View;

use common::{click, drag, scene_path, settle, viewer_sized};

type App = Harness<'static, ViewerApp>;

fn view(harness: &App) -> View {
    *harness.state().view()
}

fn slider_rect(harness: &App, label: &str) -> Rect {
    harness.get_by_role_and_label(Role::Slider, label).rect()
}

/// Drags the slider `label` by `points` to the right from its centre.
fn drag_slider(harness: &mut App, label: &str, points: f32) {
    let from = slider_rect(harness, label).center();
    drag(
        harness,
        PointerButton::Primary,
        Modifiers::NONE,
        from,
        from + vec2(points, 0.0),
    );
}

#[test]
fn sliders_are_wide_in_a_wide_window_and_their_steps_follow_the_value() {
    // scene1_01: size 5, the depth range 9 … 10.
    let mut harness = viewer_sized(Some(scene_path("scene1_01.txt")), vec2(1600.0, 900.0), 1.0);
    for label in ["centre x", "size", "depth min"] {
        let width = slider_rect(&harness, label).width();
        assert!(width >= 340.0, "{label}: {width} points wide");
    }
    // A 45-point drag scales the size by less than 2 (the whole scene's range moved it by 12).
    let before = view(&harness);
    drag_slider(&mut harness, "size", 45.0);
    let ratio = view(&harness).size_world / before.size_world;
    assert!(ratio > 1.05 && ratio < 2.0, "size × {ratio}");
    // A 50-point drag moves depth min by less than half the range's width (1).
    let before = view(&harness).depth_range;
    drag_slider(&mut harness, "depth min", 50.0);
    let moved = view(&harness).depth_range.min_t - before.min_t;
    assert!(moved > 0.02 && moved < 0.5, "depth min moved by {moved}");
    // Once the drag ends the slider spans the new value's neighbourhood, as far as the new
    // range is wide: the same drag again moves it that much less.
    let after = view(&harness).depth_range;
    drag_slider(&mut harness, "depth min", 50.0);
    let again = view(&harness).depth_range.min_t - after.min_t;
    let narrower = (after.max_t - after.min_t) / (before.max_t - before.min_t);
    assert!(
        (again / (moved * narrower) - 1.0).abs() < 0.1,
        "the second drag moved {again}, the first {moved}, the range is {narrower} as wide"
    );
}

/// Pins the pixel at `pin` and hovers `hover` (both on the images).
fn pin_and_hover(harness: &mut App, pin: Pos2, hover: Pos2) {
    harness.hover_at(pin);
    harness.step();
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos: pin,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.hover_at(hover);
    harness.run_steps(3);
    assert!(harness.state().pinned_probe().is_some(), "a pinned pixel");
}

/// The rects of the probe's lines that start with `pinned` and `hover`, and of every line.
fn probe_line_rects(harness: &App) -> Vec<(String, Rect)> {
    harness
        .query_all_by_label_contains("")
        .filter_map(|node| {
            let rect = node.rect();
            let node = node.accesskit_node();
            let label = node.value().or_else(|| node.label())?;
            let probe = label.starts_with("pinned ")
                || label.starts_with("hover ")
                || label.starts_with("       ");
            probe.then_some((label, rect))
        })
        .collect()
}

/// The top of the status bar (its frame time, "… ms").
fn status_top(harness: &App) -> f32 {
    harness
        .query_all_by_label_contains(" ms")
        .map(|node| node.rect().top())
        .fold(f32::NEG_INFINITY, f32::max)
}

/// scene1_02 in a `size` window, the colour image's centre pinned and the depth image's hovered:
/// the viewer, the depth image's rectangle and the probe's lines.
fn pinned_and_hovered(size: egui::Vec2) -> (App, Rect, Vec<(String, Rect)>) {
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), size, 1.0);
    let colour = harness.get_by_label("colour image").rect();
    let depth = harness.get_by_label("depth image").rect();
    pin_and_hover(&mut harness, colour.center(), depth.center());
    let lines = probe_line_rects(&harness);
    (harness, depth, lines)
}

#[test]
fn a_pinned_and_a_hovered_pixel_are_read_whole_at_1600_by_900() {
    let (harness, depth, lines) = pinned_and_hovered(vec2(1600.0, 900.0));
    assert!(lines.len() >= 8, "two hits of four lines: {lines:?}");
    let status_top = status_top(&harness);
    for (line, rect) in &lines {
        assert!(
            rect.bottom() <= status_top && rect.right() <= depth.left(),
            "{line:?} at {rect:?}: cut (status bar at {status_top}, depth image from {})",
            depth.left()
        );
    }
}

#[test]
fn at_800_by_600_the_probe_wraps_its_lines_and_scrolls_to_the_last() {
    let (mut harness, depth, lines) = pinned_and_hovered(vec2(800.0, 600.0));
    // Nothing is cut on the right: the longest lines wrap onto a second row (of 11-point text).
    for (line, rect) in &lines {
        assert!(rect.right() <= depth.left(), "{line:?} at {rect:?}");
    }
    assert!(
        lines.iter().any(|(_, r)| r.height() >= 2.0 * 11.0),
        "no line wraps: {lines:?}"
    );
    // The lines do not all fit: the wheel over them scrolls the last one into view.
    let status_top = status_top(&harness);
    let last = |harness: &App| probe_line_rects(harness).last().unwrap().1;
    assert!(last(&harness).bottom() > status_top, "all fit: {lines:?}");
    let over_lines = lines[0].1.center();
    harness.hover_at(over_lines);
    for _ in 0..20 {
        harness.event(Event::MouseWheel {
            unit: MouseWheelUnit::Line,
            delta: vec2(0.0, -3.0),
            modifiers: Modifiers::NONE,
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
        });
        harness.step();
    }
    harness.run_steps(10);
    let last = last(&harness);
    assert!(
        last.bottom() <= status_top,
        "the last line at {last:?} (status bar at {status_top})"
    );
}

#[test]
fn at_800_by_600_the_controls_push_the_images_aside_instead_of_covering_them() {
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(800.0, 600.0), 1.0);
    click(&mut harness, "Controls");
    settle(&mut harness);
    let slider = slider_rect(&harness, "centre x");
    for label in ["colour image", "depth image"] {
        let image = harness.get_by_label(label).rect();
        assert!(
            image.left() >= slider.right(),
            "{label} at {image:?}, a slider at {slider:?}"
        );
        assert!(image.width() >= 200.0, "{label}: {image:?}");
    }
}

#[test]
fn the_drawer_of_a_small_window_grows_with_the_window() {
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(500.0, 300.0), 1.0);
    click(&mut harness, "Controls");
    settle(&mut harness);
    let drawer = |harness: &App| {
        harness
            .get_by_role_and_label(Role::Window, "View controls")
            .rect()
    };
    let small = drawer(&harness);
    assert!(small.height() < 300.0, "{small:?}");
    harness.set_size(vec2(600.0, 900.0));
    settle(&mut harness);
    let grown = drawer(&harness);
    assert!(grown.height() > 700.0, "{small:?} then {grown:?}");
}

#[test]
fn a_scene_error_leaves_the_depth_images_caption_readable() {
    let folder = tempfile::tempdir().unwrap();
    let broken = folder.path().join("broken.txt");
    std::fs::write(&broken, "OrthographicCamera { center 0 0 10 size }\n").unwrap();
    let harness = viewer_sized(Some(broken), vec2(1280.0, 720.0), 1.0);
    let error = harness.get_by_label_contains("broken.txt").rect();
    let captions: Vec<Rect> = harness
        .query_all_by_label_contains("near …")
        .map(|node| node.rect())
        .collect();
    assert!(!captions.is_empty(), "the depth image's caption");
    for caption in captions {
        assert!(
            !caption.intersects(error),
            "the error at {error:?} covers the caption at {caption:?}"
        );
    }
}

#[test]
fn the_shortcuts_overlay_fits_a_900_point_high_window_without_scrolling() {
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(1600.0, 900.0), 1.0);
    harness.key_press(egui::Key::F1);
    harness.run_steps(10);
    let overlay = harness
        .get_by_role_and_label(Role::Window, "Shortcuts and gestures")
        .rect();
    // The first row and the last (the overlay's own key), both in the overlay.
    for row in ["pan the camera", "this overlay"] {
        let rect = harness.get_by_label_contains(row).rect();
        assert!(
            overlay.contains_rect(rect),
            "{row:?} at {rect:?}, the overlay {overlay:?}"
        );
    }
    assert!(overlay.bottom() <= 900.0, "{overlay:?}");
}

#[test]
fn the_shortcuts_overlay_shows_every_row_whole_at_the_window_sizes_people_use() {
    for (width, height) in [
        (1280.0, 720.0),
        (1024.0, 768.0),
        (800.0, 600.0),
        (640.0, 480.0),
    ] {
        let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(width, height), 1.0);
        harness.key_press(egui::Key::F1);
        harness.run_steps(10);
        let size = format!("{width}×{height}");
        let window = harness.get_by_role_and_label(Role::Window, "Shortcuts and gestures");
        let overlay = window.rect();
        assert!(
            overlay.left() >= 0.0 && overlay.right() <= width,
            "{size}: the overlay at {overlay:?}"
        );
        // Every key and description lies across the overlay, none under another.
        let labels: Vec<(String, Rect)> = window
            .query_all_by_role(Role::Label)
            .map(|node| {
                let rect = node.rect();
                let node = node.accesskit_node();
                (
                    node.value().or_else(|| node.label()).unwrap_or_default(),
                    rect,
                )
            })
            .collect();
        let rows = labels
            .iter()
            .filter(|(text, _)| text.contains("the camera"))
            .count();
        assert!(
            rows >= 3,
            "{size}: {rows} rows about the camera found in {labels:?}"
        );
        for (i, (text, rect)) in labels.iter().enumerate() {
            assert!(
                rect.left() >= overlay.left() && rect.right() <= overlay.right(),
                "{size}: {text:?} at {rect:?}, the overlay {overlay:?}"
            );
            // Where the window is wide and high enough for two columns, nothing is scrolled:
            // every row lies above the overlay's bottom too.
            if width >= 1000.0 && height >= 560.0 {
                assert!(
                    rect.bottom() <= overlay.bottom(),
                    "{size}: {text:?} at {rect:?}, the overlay {overlay:?}"
                );
            }
            for (other, other_rect) in &labels[i + 1..] {
                assert!(
                    !rect.shrink(1.0).intersects(other_rect.shrink(1.0)),
                    "{size}: {text:?} at {rect:?} under {other:?} at {other_rect:?}"
                );
            }
        }
    }
}

/// Pixels of `shot` inside `rect` (points, at one pixel a point) within 6 of `rgb` in each channel.
fn pixels_near(shot: &image::RgbaImage, rect: Rect, rgb: [u8; 3]) -> usize {
    let (x0, y0) = (rect.left().ceil() as u32, rect.top().ceil() as u32);
    let (x1, y1) = (rect.right().floor() as u32, rect.bottom().floor() as u32);
    (y0..y1.min(shot.height()))
        .flat_map(|y| (x0..x1.min(shot.width())).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let pixel = shot.get_pixel(x, y).0;
            (0..3).all(|c| pixel[c].abs_diff(rgb[c]) <= 6)
        })
        .count()
}

#[test]
fn no_hit_pixels_on_screen_are_dark_blue_on_grey_and_light_grey_on_turbo() {
    // scene1_02's spheres leave most of the image without a hit.
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(1280.0, 720.0), 1.0);
    let (frame, _) = harness.state().shown_frame().unwrap();
    let no_hit = frame.t.iter().filter(|t| t.is_infinite()).count();
    assert!(no_hit > 10_000, "{no_hit} no-hit pixels");
    let (navy, light_grey) = ([24, 36, 96], [200, 200, 200]);
    let depth = harness.get_by_label("depth image").rect();
    let shot = harness.render().expect("the UI renders (wgpu)");
    assert!(pixels_near(&shot, depth, navy) > 5_000, "grey: dark blue");
    click(&mut harness, "turbo");
    settle(&mut harness);
    let depth = harness.get_by_label("depth image").rect();
    let shot = harness.render().expect("the UI renders (wgpu)");
    assert!(
        pixels_near(&shot, depth, light_grey) > 5_000,
        "turbo: light grey"
    );
    assert_eq!(pixels_near(&shot, depth, navy), 0, "turbo: no dark blue");
}

/// The pixel trace opens sized to its lines at the body text size: no line is cut off at the
/// window's edge (it opened 620 points wide with its lines cut), within the window it opens in.
#[test]
fn the_pixel_trace_opens_wide_enough_for_its_lines() {
    let mut harness = viewer_sized(Some(scene_path("scene1_02.txt")), vec2(1200.0, 800.0), 1.0);
    let image = harness.get_by_label("colour image").rect();
    for pressed in [true, false] {
        harness.hover_at(image.center());
        harness.step();
        harness.event(Event::PointerButton {
            pos: image.center(),
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    click(&mut harness, "Trace");
    harness.run_steps(4);
    let text = harness.get_by_label_contains("pixel: x ");
    let line = text.rect();
    let window = harness
        .get_all_by_role(Role::Window)
        .find(|w| w.accesskit_node().label().as_deref() == Some("Pixel trace"))
        .expect("the trace window")
        .accesskit_node()
        .bounding_box()
        .unwrap();
    // Wider than the 620 points it opened at, and every line within it (long ones wrap).
    assert!(window.width() > 1000.0, "{window:?}");
    assert!(
        line.max.x as f64 <= window.x1 && line.min.x as f64 >= window.x0,
        "{line:?} in {window:?}"
    );
}

/// Each statement under "diagnosis:" is drawn at the body text size (it was small, about 8 px
/// tall at 1:1): its label is as tall as its words laid out in the body font at its width.
#[test]
fn statements_are_drawn_at_the_body_text_size() {
    use raytracer::compare::{Mistake, MistakeSet};
    let folder = tempfile::tempdir().unwrap();
    let scene = raytracer::scene::load_scene(&scene_path("scene1_03.txt")).unwrap();
    let range = raytracer::render::depth_map::DepthRange::new(8.0, 12.0);
    let view = View::of_camera(&scene.camera, 200, 200, range);
    let corners = MistakeSet::of(&[Mistake::PixelCorners]);
    let (colour, _) = raytracer::oracle::mistaken::render_variant(&scene, &view, corners);
    let theirs = folder.path().join("theirs.png");
    colour.save(&theirs).unwrap();
    let mut harness = viewer_sized(Some(scene_path("scene1_03.txt")), vec2(1000.0, 700.0), 1.0);
    common::compare_image(&mut harness, &theirs.display().to_string());
    let statement = harness.get_by_label_contains("pixel-corners: rays pass through");
    let rect = statement.rect();
    let said = &harness.state().comparison().unwrap().statements[0];
    let text = format!("{}: {}", said.name_and_values(), said.explanation());
    let ctx = harness.ctx.clone();
    let body = egui::TextStyle::Body.resolve(&ctx.global_style());
    let galley = ctx.fonts_mut(|fonts| {
        fonts.layout(
            text.to_string(),
            body,
            egui::Color32::WHITE,
            rect.width() + 1.0,
        )
    });
    assert!(
        (galley.size().y - rect.height()).abs() <= 2.0,
        "{} px tall, {} in the body font",
        rect.height(),
        galley.size().y
    );
}
