//! Exploring a scene in the real viewer, driven headlessly with egui_kittest: drag, wheel,
//! right-drag and keys move the `View` as the navigation math says; auto range brackets the
//! visible t; the probe names the sphere the oracle finds; dragging a histogram end moves the
//! range; exports carry lossless depth, the scene and the command line.
#![cfg(feature = "gui")]

use egui::{Event, Modifiers, PointerButton, Pos2, Rect, TouchPhase, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::{DVec2, DVec3};
use raytracer::app::ViewerApp;
use raytracer::app::depth_stats::visible_t;
use raytracer::app::navigate;
use raytracer::app::ui::gestures::ORBIT_RAD_PER_POINT;
use raytracer::app::ui::histogram::{MAX_HANDLE_LABEL, MIN_HANDLE_LABEL, histogram_axis};
use raytracer::explore::initial_depth_range;
use raytracer::oracle::ray_loop::render_reference;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{NO_HIT, View};

mod common;

use common::{click, drag, scene_path, settle};

fn viewer(input: &str) -> Harness<'static, ViewerApp> {
    common::viewer(Some(scene_path(input)))
}

fn view(harness: &Harness<'static, ViewerApp>) -> View {
    *harness.state().view()
}

fn image_rect(harness: &Harness<'static, ViewerApp>, label: &str) -> Rect {
    harness.get_by_label(label).rect()
}

fn assert_close(a: f64, b: f64, tolerance: f64, what: &str) {
    assert!(
        (a - b).abs() <= tolerance * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

#[test]
fn dragging_an_image_pans_the_camera_in_the_screen_plane() {
    let mut harness = viewer("scene1_02.txt");
    let before = view(&harness);
    let rect = image_rect(&harness, "colour image");
    let from = rect.center();
    drag(
        &mut harness,
        PointerButton::Primary,
        Modifiers::NONE,
        from,
        from + vec2(60.0, -30.0),
    );
    let after = view(&harness);
    let basis = before.validate().unwrap();
    let pixel_world = before.grid().pixel_size_world;
    // Pixels per point of the image on screen (1:1 when the frame fills its half).
    let px_per_point = f64::from(before.width_px) / f64::from(rect.width());
    let moved = after.center_world - before.center_world;
    // The picture follows the pointer: the centre moves against the drag (x right, y up).
    assert_close(
        moved.dot(basis.horizontal),
        -60.0 * px_per_point * pixel_world,
        0.03,
        "horizontal move",
    );
    assert_close(
        moved.dot(basis.screen_up),
        -30.0 * px_per_point * pixel_world,
        0.03,
        "vertical move",
    );
    assert!(moved.dot(basis.direction).abs() < 1e-12, "t is unchanged");
    assert_eq!(after.size_world, before.size_world);
    assert_eq!(after.direction_world, before.direction_world);
    assert_eq!(after.depth_range, before.depth_range);
}

#[test]
fn the_wheel_zooms_at_the_cursor() {
    let mut harness = viewer("scene1_02.txt");
    let before = view(&harness);
    let rect = image_rect(&harness, "depth image");
    let anchor = rect.min + vec2(0.25 * rect.width(), 0.3 * rect.height());
    harness.hover_at(anchor);
    harness.step();
    harness.event(Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: vec2(0.0, 120.0),
        phase: TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: Modifiers::NONE,
    });
    settle(&mut harness);
    let after = view(&harness);
    // 120 points of scroll up: half of a doubling, the size shrinks by √2.
    assert_close(
        after.size_world / before.size_world,
        0.5_f64.sqrt(),
        1e-3,
        "zoom factor",
    );
    // The world point under the cursor stays under it.
    let anchor_px = harness
        .state()
        .hover_px()
        .expect("the pointer is on the image");
    let expected_px = DVec2::new(
        f64::from((anchor.x - rect.min.x) / rect.width()) * f64::from(before.width_px),
        f64::from((rect.max.y - anchor.y) / rect.height()) * f64::from(before.height_px),
    );
    assert!(
        (anchor_px - expected_px).length() < 1.0,
        "{anchor_px} vs {expected_px}"
    );
    let world_at = |v: &View| {
        let basis = v.validate().unwrap();
        let (u, w) = v.grid().screen_of_pixel_point(anchor_px.x, anchor_px.y);
        v.center_world + u * basis.horizontal + w * basis.screen_up
    };
    let drift = (world_at(&after) - world_at(&before)).length();
    assert!(
        drift < 1e-9 * before.size_world,
        "anchor moved by {drift} world units"
    );
    assert!(
        after.center_world != before.center_world,
        "off-centre anchor"
    );
}

#[test]
fn right_drag_and_shift_drag_orbit_around_the_scene_centre() {
    let mut harness = viewer("scene1_03.txt");
    let pivot = navigate::orbit_pivot(&harness.state().loaded_scene().scene);
    for (button, modifiers) in [
        (PointerButton::Secondary, Modifiers::NONE),
        (PointerButton::Primary, Modifiers::SHIFT),
    ] {
        let before = view(&harness);
        let from = image_rect(&harness, "colour image").center();
        drag(
            &mut harness,
            button,
            modifiers,
            from,
            from + vec2(80.0, 0.0),
        );
        let after = view(&harness);
        let old = before.direction_world.normalize();
        let new = after.direction_world.normalize();
        assert_close(
            old.angle_between(new),
            80.0 * ORBIT_RAD_PER_POINT,
            0.05,
            "turned angle",
        );
        // A horizontal drag turns about the screen's up axis: up stays, the distance to the
        // pivot stays, and up is still perpendicular to the direction.
        assert!(after.up_world.normalize().dot(new).abs() < 1e-9);
        let distance = |v: &View| (v.center_world - pivot).length();
        assert_close(
            distance(&after),
            distance(&before),
            1e-9,
            "distance to pivot",
        );
        assert!(
            (after.up_world.normalize() - before.validate().unwrap().screen_up).length() < 1e-9
        );
        assert_eq!(after.size_world, before.size_world);
    }
}

#[test]
fn keys_pan_orbit_zoom_frame_all_and_reset() {
    let mut harness = viewer("scene1_02.txt");
    let file_view = view(&harness);
    let basis = file_view.validate().unwrap();

    harness.key_press(egui::Key::ArrowRight);
    settle(&mut harness);
    let moved = view(&harness).center_world - file_view.center_world;
    let step = raytracer::app::KEY_PAN_FRACTION
        * f64::from(file_view.width_px.min(file_view.height_px))
        * file_view.grid().pixel_size_world;
    assert_close(
        moved.dot(basis.horizontal),
        step,
        1e-9,
        "arrow moves the camera right",
    );

    let before = view(&harness);
    harness.key_press(egui::Key::Plus);
    settle(&mut harness);
    assert_close(
        view(&harness).size_world,
        before.size_world / raytracer::app::KEY_ZOOM_FACTOR,
        1e-12,
        "+ zooms in",
    );

    let before = view(&harness);
    harness.key_press_modifiers(Modifiers::SHIFT, egui::Key::ArrowRight);
    settle(&mut harness);
    let angle = before
        .direction_world
        .normalize()
        .angle_between(view(&harness).direction_world.normalize());
    assert_close(
        angle,
        raytracer::app::KEY_ORBIT_RAD,
        1e-9,
        "Shift+arrow orbits",
    );

    let before = view(&harness);
    harness.key_press(egui::Key::F);
    settle(&mut harness);
    let scene = harness.state().loaded_scene().scene.clone();
    assert_eq!(view(&harness), navigate::frame_all(&scene, &before));

    harness.key_press(egui::Key::Home);
    settle(&mut harness);
    assert_eq!(view(&harness), file_view);
}

#[test]
fn frame_all_button_shows_every_sphere() {
    let mut harness = viewer("scene1_05.txt");
    harness.state_mut().view_mut().size_world *= 0.05;
    settle(&mut harness);
    let before = view(&harness);
    click(&mut harness, "Frame all");
    settle(&mut harness);
    let scene = harness.state().loaded_scene().scene.clone();
    assert_eq!(view(&harness), navigate::frame_all(&scene, &before));
    // Spheres show, and the border stays empty: the margin.
    let (frame, _) = harness.state().shown_frame().unwrap();
    assert!(frame.sphere.iter().any(|&s| s != NO_HIT));
    let (w, h) = (frame.width_px, frame.height_px);
    for x in 0..w {
        assert_eq!(frame.sphere[frame.index(x, 0)], NO_HIT);
        assert_eq!(frame.sphere[frame.index(x, h - 1)], NO_HIT);
    }
}

#[test]
fn auto_range_brackets_the_visible_t() {
    let mut harness = viewer("scene1_03.txt");
    harness.state_mut().view_mut().depth_range = DepthRange::new(-100.0, 500.0);
    harness.state_mut().settings_mut().depth.auto_cut_percent = 0.0;
    settle(&mut harness);
    click(&mut harness, "Auto range");
    settle(&mut harness);
    let (frame, shown_view) = harness.state().shown_frame().unwrap();
    let visible = visible_t(frame);
    let low = visible.iter().copied().fold(f64::INFINITY, f64::min);
    let high = visible.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(shown_view.depth_range, DepthRange::new(low, high));
    assert!(low < high);

    // With a cut, the range lies inside and leaves out a share of the visible pixels.
    harness.state_mut().settings_mut().depth.auto_cut_percent = 10.0;
    harness.state_mut().auto_range();
    settle(&mut harness);
    let range = view(&harness).depth_range;
    assert!(range.min_t >= low && range.max_t <= high && range.min_t < range.max_t);
    assert!(range.min_t > low || range.max_t < high, "{range:?}");
}

#[test]
fn the_probe_reports_the_sphere_under_the_pointer_a_click_pins_it_and_trace_shows_its_computation()
{
    let mut harness = viewer("scene1_04.txt");
    let (frame, shown_view) = {
        let (frame, view) = harness.state().shown_frame().unwrap();
        (frame.clone(), *view)
    };
    let scene = harness.state().loaded_scene().scene.clone();
    let oracle = render_reference(&scene, &shown_view).unwrap();
    let rect = image_rect(&harness, "colour image");
    let to_pos = |x: u32, y_up: u32| {
        Pos2::new(
            rect.min.x + (x as f32 + 0.5) / frame.width_px as f32 * rect.width(),
            rect.max.y - (y_up as f32 + 0.5) / frame.height_px as f32 * rect.height(),
        )
    };
    // A pixel of each sphere that shows (the first pixel found, scanning rows).
    let mut targets: Vec<(u32, u32)> = Vec::new();
    for y_up in (0..frame.height_px).step_by(7) {
        for x in (0..frame.width_px).step_by(7) {
            let sphere = oracle.sphere[oracle.index(x, y_up)];
            if sphere != NO_HIT
                && !targets
                    .iter()
                    .any(|&(tx, ty)| oracle.sphere[oracle.index(tx, ty)] == sphere)
            {
                targets.push((x, y_up));
            }
        }
    }
    assert!(targets.len() >= 3, "{targets:?}");
    targets.push((1, 1)); // the background
    for &(x, y_up) in &targets {
        harness.hover_at(to_pos(x, y_up));
        harness.run_steps(2);
        let probe = harness
            .state()
            .hover_probe()
            .expect("a probe under the pointer");
        assert!(
            probe.x_px.abs_diff(x) <= 1 && probe.y_up_px.abs_diff(y_up) <= 1,
            "probed ({}, {}) for ({x}, {y_up})",
            probe.x_px,
            probe.y_up_px
        );
        let index = oracle.index(probe.x_px, probe.y_up_px);
        match probe.hit {
            None => assert_eq!(oracle.sphere[index], NO_HIT),
            Some(hit) => {
                assert_eq!(hit.sphere_index, oracle.sphere[index]);
                assert_eq!(hit.t, frame.t[index]);
                assert!((hit.t - oracle.t[index]).abs() <= 1e-14 * hit.t.abs());
                let sphere = &scene.spheres[hit.sphere_index as usize];
                assert_eq!(hit.material_index, sphere.material);
                let off_surface =
                    (hit.point_world - sphere.center_world).length() - sphere.radius_world;
                assert!(off_surface.abs() < 1e-9 * sphere.radius_world.max(1.0));
            }
        }
    }
    // A click pins the pixel; hovering elsewhere leaves the pin; the lines show both.
    let (x, y_up) = targets[0];
    harness.get_by_label("colour image").hover();
    harness.hover_at(to_pos(x, y_up));
    harness.step();
    harness.event(Event::PointerButton {
        pos: to_pos(x, y_up),
        button: PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.step();
    harness.event(Event::PointerButton {
        pos: to_pos(x, y_up),
        button: PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run_steps(2);
    let pinned = harness.state().pinned_probe().expect("a pinned probe");
    assert_eq!(
        pinned.hit.map(|h| h.sphere_index),
        Some(oracle.sphere[oracle.index(pinned.x_px, pinned.y_up_px)])
    );
    harness.hover_at(to_pos(1, 1));
    harness.run_steps(2);
    assert_eq!(harness.state().pinned_probe(), Some(pinned));
    let sphere_line = format!("sphere #{}", pinned.hit.unwrap().sphere_index);
    assert!(
        harness
            .query_all_by_label_contains(&sphere_line)
            .next()
            .is_some(),
        "the probe's lines name the sphere"
    );
    // Trace: the course's computation behind the pinned pixel, in a window; it sees the
    // oracle's sphere, and its colour bytes are the frame's.
    click(&mut harness, "Trace");
    harness.run_steps(3);
    let sphere = oracle.sphere[oracle.index(pinned.x_px, pinned.y_up_px)];
    let [r, g, b] = pinned.colour_rgb;
    for expected in [
        format!("pixel: x {} y {} of", pinned.x_px, pinned.y_up_px),
        format!("hit: sphere {sphere} at t = "),
        format!("floor(255·colour) = {r} {g} {b}"),
    ] {
        assert!(
            harness.query_by_label_contains(&expected).is_some(),
            "the trace says {expected}"
        );
    }
    assert!(harness.query_by_label_contains("Pixel trace").is_some());
    click(&mut harness, "Unpin");
    harness.run_steps(2);
    assert_eq!(harness.state().pinned_probe(), None);
}

#[test]
fn dragging_a_histogram_end_moves_the_depth_range() {
    let mut harness = viewer("scene1_03.txt");
    let scene = harness.state().loaded_scene().scene.clone(); // the t seen, not the course's
    harness.state_mut().view_mut().depth_range = initial_depth_range(&scene, &view(&harness));
    settle(&mut harness);
    let before = view(&harness).depth_range;
    let histogram = harness.state().histogram().expect("a histogram").clone();
    for (label, to_the_left) in [(MAX_HANDLE_LABEL, true), (MIN_HANDLE_LABEL, false)] {
        let range = view(&harness).depth_range;
        let handle = harness.get_by_label(label).rect();
        let bars_width = harness
            .get_by_label("depth image")
            .rect()
            .width()
            .min(f32::MAX);
        let shift = if to_the_left { -40.0 } else { 40.0 };
        drag(
            &mut harness,
            PointerButton::Primary,
            Modifiers::NONE,
            handle.center(),
            handle.center() + vec2(shift, 0.0),
        );
        let after = view(&harness).depth_range;
        // The end moved by the t that 40 points of the axis span, the other end stayed.
        let (low, high) = histogram_axis(&histogram, &range);
        let expected_shift = f64::from(shift) / f64::from(bars_width) * (high - low);
        if to_the_left {
            assert_eq!(after.min_t, range.min_t);
            assert_close(after.max_t - range.max_t, expected_shift, 0.1, "max end");
        } else {
            assert_eq!(after.max_t, range.max_t);
            assert_close(after.min_t - range.min_t, expected_shift, 0.1, "min end");
        }
    }
    let after = view(&harness).depth_range;
    assert!(after.min_t > before.min_t && after.max_t < before.max_t);
    // The depth image on screen follows the new range.
    let (_, shown_view) = harness.state().shown_frame().unwrap();
    assert_eq!(shown_view.depth_range, after);
}

#[test]
fn export_writes_raw_depth_scene_and_command_and_save_view_writes_the_camera() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer("scene1_02.txt");
    // Look from elsewhere first, so the saved camera is not the file's.
    harness.key_press(egui::Key::ArrowLeft);
    harness.key_press(egui::Key::Minus);
    settle(&mut harness);
    {
        let settings = harness.state_mut().settings_mut();
        settings.depth.colour_map = raytracer::render::depth_map::DepthColourMap::Viridis;
        settings.export.extra_depth =
            raytracer::export::ExtraDepth::Raw(raytracer::output::depth_file::RawDepthFormat::Exr);
        settings.export.path = folder.path().join("shot.png").display().to_string();
        settings.export.scene_path = folder.path().join("view.txt").display().to_string();
    }
    settle(&mut harness);
    click(&mut harness, "Export to path");
    settle(&mut harness);
    let (message, is_error) = harness.state().message().unwrap();
    assert!(!is_error && message.starts_with("exported"), "{message}");
    let (frame, shown_view) = {
        let (frame, view) = harness.state().shown_frame().unwrap();
        (frame.clone(), *view)
    };
    let raw = raytracer::output::depth_file::read_raw_depth(&folder.path().join("shot_depth.exr"))
        .unwrap();
    assert_eq!(raw.t.len(), frame.t.len());
    for (&got, &t) in raw.t.iter().zip(&frame.t) {
        assert!(got == t as f32 || (got.is_infinite() && t.is_infinite()));
    }
    let depth = image::open(folder.path().join("shot_depth.png"))
        .unwrap()
        .to_rgb8();
    assert!(
        depth
            == frame.depth_image_mapped(
                shown_view.depth_range,
                raytracer::render::depth_map::DepthColourMap::Viridis,
                [0, 0, 0]
            )
    );
    let command = std::fs::read_to_string(folder.path().join("shot_command.sh")).unwrap();
    assert!(command.contains("-depth_colormap viridis"), "{command}");
    assert!(command.contains("-depth_raw shot_depth.exr"), "{command}");
    let exported_scene =
        raytracer::scene::load_scene(&folder.path().join("shot_scene.txt")).unwrap();
    assert_eq!(exported_scene.camera.center_world, shown_view.center_world);

    click(&mut harness, "Save view as scene");
    settle(&mut harness);
    let (message, is_error) = harness.state().message().unwrap();
    assert!(
        !is_error && message.starts_with("saved the view"),
        "{message}"
    );
    let saved = raytracer::scene::load_scene(&folder.path().join("view.txt")).unwrap();
    let current = view(&harness);
    assert_eq!(saved.camera.center_world, current.center_world);
    assert_eq!(saved.camera.size_world, current.size_world);
    assert_eq!(saved.camera.direction_world, current.direction_world);
    assert_eq!(saved.spheres, harness.state().loaded_scene().scene.spheres);
    assert_ne!(current.center_world, DVec3::ZERO);
}
