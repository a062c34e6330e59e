//! The real viewer driven headlessly with egui_kittest: sliders change the `View` and, once the
//! worker finishes, the frame on screen; export writes the expected files; a broken scene shows
//! its error and keeps the previous frame; without a file the default scene is shown.
#![cfg(feature = "gui")]

use std::time::{Duration, Instant};

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raytracer::app::ViewerApp;
use raytracer::render::{Frame, View, render};

mod common;

use common::{click, scene_path, settle, viewer};

/// The frame on screen and its view, cloned.
fn shown(harness: &Harness<'static, ViewerApp>) -> (Frame, View) {
    let (frame, view) = harness.state().shown_frame().expect("a frame on screen");
    (frame.clone(), *view)
}

/// The frame on screen must be exactly what the library renders for the current view.
fn assert_shows_current_view(harness: &Harness<'static, ViewerApp>) {
    let app = harness.state();
    let (frame, view) = shown(harness);
    assert_eq!(view, *app.view());
    let expected = render(&app.loaded_scene().scene, &view).unwrap();
    assert!(
        frame == expected,
        "the frame on screen is not the library's render of the view"
    );
}

#[test]
fn without_a_file_the_default_scene_is_shown() {
    let harness = viewer(None);
    let app = harness.state();
    assert_eq!(app.loaded_scene().path, None);
    assert_eq!(
        app.loaded_scene().scene.spheres.len(),
        raytracer::scene::parse_scene(raytracer::DEFAULT_SCENE_TEXT)
            .unwrap()
            .spheres
            .len()
    );
    assert_shows_current_view(&harness);
    let (frame, view) = shown(&harness);
    // The render fills the image area: two images side by side, wider than tall here.
    assert!(view.width_px > 300 && view.height_px > 300, "{view:?}");
    let hit_pixels = frame
        .sphere
        .iter()
        .filter(|&&s| s != raytracer::render::NO_HIT)
        .count();
    assert!(
        hit_pixels > frame.pixel_count() / 20,
        "spheres are on screen"
    );
}

#[test]
fn every_slider_changes_the_view_and_the_frame() {
    type Field = fn(&View) -> f64;
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    // Open the collapsed direction/up section.
    harness.get_by_label("Direction and up").click();
    settle(&mut harness);

    let sliders: [(&str, f64, Field); 12] = [
        ("centre x", 0.7, |v| v.center_world.x),
        ("centre y", -0.4, |v| v.center_world.y),
        ("centre z", 12.0, |v| v.center_world.z),
        ("size", 2.5, |v| v.size_world),
        ("depth min", 9.5, |v| v.depth_range.min_t),
        ("depth max", 10.5, |v| v.depth_range.max_t),
        // Small turns keep the spheres in view (the camera is 12 units away).
        ("direction x", 0.05, |v| v.direction_world.x),
        ("direction y", -0.04, |v| v.direction_world.y),
        ("direction z", -0.8, |v| v.direction_world.z),
        ("up x", 0.5, |v| v.up_world.x),
        ("up y", 0.8, |v| v.up_world.y),
        ("up z", 0.25, |v| v.up_world.z),
    ];
    for (label, value, field) in sliders {
        let (before_frame, before_view) = shown(&harness);
        let slider = harness.get_by_role_and_label(Role::Slider, label);
        slider.scroll_to_me();
        slider.set_value_accesskit(value);
        harness.step();
        assert_eq!(
            field(harness.state().view()),
            value,
            "{label}: the view follows the slider"
        );
        settle(&mut harness);
        assert_shows_current_view(&harness);
        let (after_frame, after_view) = shown(&harness);
        assert_eq!(field(&after_view), value, "{label}");
        // Depth sliders change the depth image only; every other slider moves the picture.
        let changed = if label.starts_with("depth") {
            before_frame.depth_image(before_view.depth_range)
                != after_frame.depth_image(after_view.depth_range)
        } else {
            before_frame != after_frame
        };
        assert!(
            changed,
            "{label}: the frame on screen changed: {before_view:?} → {after_view:?}"
        );
        let hits = after_frame
            .sphere
            .iter()
            .filter(|&&s| s != raytracer::render::NO_HIT)
            .count();
        assert!(hits > 1000, "{label}: spheres stay in view ({hits} pixels)");
    }

    click(&mut harness, "Reset view");
    settle(&mut harness);
    let app = harness.state();
    let file_camera = &app.loaded_scene().scene.camera;
    assert_eq!(app.view().center_world, file_camera.center_world);
    assert_eq!(app.view().size_world, file_camera.size_world);
}

#[test]
fn typed_values_go_beyond_the_slider_range() {
    let mut harness = viewer(Some(scene_path("scene1_01.txt")));
    harness
        .get_by_role_and_label(Role::Slider, "size")
        .set_value_accesskit(1e6);
    harness.step();
    assert_eq!(harness.state().view().size_world, 1e6);
    settle(&mut harness);
    assert_shows_current_view(&harness);
}

#[test]
fn export_writes_colour_and_depth_with_the_expected_pixels() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    harness.state_mut().settings_mut().export.path =
        folder.path().join("shot.png").display().to_string();
    click(&mut harness, "Export to path");
    harness.step();
    assert!(harness.state().export_running() || harness.state().message().is_some());
    settle(&mut harness);
    let (message, is_error) = harness.state().message().unwrap();
    assert!(!is_error, "{message}");
    assert!(message.starts_with("exported"), "{message}");

    let (frame, view) = shown(&harness);
    let colour = image::open(folder.path().join("shot_colour.png"))
        .unwrap()
        .to_rgb8();
    let depth = image::open(folder.path().join("shot_depth.png"))
        .unwrap()
        .to_rgb8();
    let both = image::open(folder.path().join("shot_both.png"))
        .unwrap()
        .to_rgb8();
    assert!(colour == frame.colour_image(), "exported colour pixels");
    assert!(
        depth == frame.depth_image(view.depth_range),
        "exported depth pixels"
    );
    // Side by side (the two images above), with the legend strip under it (its bar, then a
    // line of text at 8 or 16 pixels).
    assert_eq!(both.width(), 2 * view.width_px);
    let strip = both.height() - view.height_px;
    assert!(strip == 40 || strip == 48, "a strip {strip} px high");
    let top = image::imageops::crop_imm(&both, 0, 0, view.width_px, view.height_px).to_image();
    assert!(top == colour, "the colour image on the left");
}

#[test]
fn export_at_a_typed_size_and_to_an_unwritable_path() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_01.txt")));
    {
        let settings = &mut harness.state_mut().settings_mut().export;
        settings.displayed_size = false;
        settings.size_px = [64, 48];
        settings.side_by_side = false;
        settings.format = raytracer::app::settings::ExportFormat::Tga;
        settings.path = folder.path().join("small").display().to_string();
    }
    click(&mut harness, "Export to path");
    settle(&mut harness);
    let colour = std::fs::read(folder.path().join("small_colour.tga")).unwrap();
    let colour = image::load_from_memory_with_format(&colour, image::ImageFormat::Tga).unwrap();
    assert_eq!((colour.width(), colour.height()), (64, 48));
    assert!(folder.path().join("small_depth.tga").exists());
    assert!(!folder.path().join("small_both.tga").exists());

    // Into a "folder" that is a file: the offer to create it fails, and says so.
    let file = folder.path().join("a file");
    std::fs::write(&file, "kept").unwrap();
    harness.state_mut().settings_mut().export.path = file.join("x.png").display().to_string();
    click(&mut harness, "Export to path");
    settle(&mut harness);
    click(&mut harness, "Create the folder and export");
    settle(&mut harness);
    let (message, is_error) = harness.state().message().unwrap();
    assert!(is_error, "{message}");
    assert!(message.contains("cannot create the folder"), "{message}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "kept");
}

#[test]
fn broken_scene_shows_its_error_and_keeps_the_previous_frame() {
    let folder = tempfile::tempdir().unwrap();
    let broken = folder.path().join("broken.txt");
    std::fs::write(
        &broken,
        "OrthographicCamera {\n center 0 0 10\n direction 0 0 -1\n up 0 1 0\n size 5\n}\n\
         Group {\n numObjects 1\n Sphere { center 0 0 0 }\n}\n",
    )
    .unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let (before, _) = shown(&harness);

    harness
        .get_by_label("path")
        .set_text_value_accesskit(&broken.display().to_string());
    click(&mut harness, "Open path");
    settle(&mut harness);

    let expected = format!("{}:9:24: expected 'radius', found '}}'", broken.display());
    assert_eq!(harness.state().scene_error(), Some(expected.as_str()));
    // The error is on screen, and the previous scene and frame stay.
    harness.run_steps(2);
    assert!(
        harness.query_all_by_value(&expected).next().is_some(),
        "error on screen"
    );
    assert_eq!(
        harness.state().loaded_scene().path,
        Some(scene_path("scene1_02.txt"))
    );
    // The error banner takes some height, so the frame may be re-rendered at the new size: of
    // the same scene, through the same camera.
    let (after, after_view) = shown(&harness);
    assert_shows_current_view(&harness);
    if (after.width_px, after.height_px) == (before.width_px, before.height_px) {
        assert!(before == after, "the previous frame stays");
    }
    let previous = raytracer::scene::load_scene(&scene_path("scene1_02.txt")).unwrap();
    assert_eq!(
        harness.state().loaded_scene().scene.spheres,
        previous.spheres
    );
    assert_eq!(after_view.center_world, previous.camera.center_world);

    // Fixing the file and opening it again clears the error.
    std::fs::write(&broken, std::fs::read(scene_path("scene1_01.txt")).unwrap()).unwrap();
    click(&mut harness, "Open path");
    settle(&mut harness);
    assert_eq!(harness.state().scene_error(), None);
    assert_eq!(harness.state().loaded_scene().path, Some(broken));
    assert_shows_current_view(&harness);
}

#[test]
fn resizing_the_window_re_renders_at_the_new_size() {
    let mut harness = viewer(Some(scene_path("scene1_01.txt")));
    let (_, before) = shown(&harness);
    harness.set_size(egui::vec2(900.0, 560.0));
    settle(&mut harness);
    let (_, after) = shown(&harness);
    assert!(after.width_px < before.width_px && after.height_px < before.height_px);
    assert_shows_current_view(&harness);
}

/// Steps the UI until `condition` holds (file events arrive on another thread).
fn wait_until(harness: &mut Harness<'static, ViewerApp>, condition: impl Fn(&ViewerApp) -> bool) {
    let deadline = Instant::now() + Duration::from_secs(20);
    while !condition(harness.state()) {
        assert!(Instant::now() < deadline, "condition not reached");
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn live_reload_keeps_the_last_good_scene_when_the_file_turns_into_garbage() {
    let folder = tempfile::tempdir().unwrap();
    let live = folder.path().join("live.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &live).unwrap();
    let mut harness = viewer(Some(live.clone()));
    let (before, _) = shown(&harness);

    std::fs::write(&live, b"OrthographicCamera {\n center 0 0 \xff\xfe garbage").unwrap();
    wait_until(&mut harness, |app| app.scene_error().is_some());
    let error = harness.state().scene_error().unwrap().to_owned();
    assert!(
        error.starts_with(&format!("{}:2:", live.display())),
        "{error}"
    );
    assert_eq!(harness.state().loaded_scene().scene.spheres.len(), 5);
    settle(&mut harness);
    // The error banner takes some height, so the frame is re-rendered, from the last good scene.
    assert_shows_current_view(&harness);
    let (after, _) = shown(&harness);
    let hits = |frame: &Frame| {
        frame
            .sphere
            .iter()
            .filter(|&&s| s != raytracer::render::NO_HIT)
            .count()
    };
    assert!(
        hits(&after) > hits(&before) / 2,
        "the last good scene stays on screen"
    );

    // Saving a good file again reloads it and clears the error.
    std::fs::write(&live, std::fs::read(scene_path("scene1_01.txt")).unwrap()).unwrap();
    wait_until(&mut harness, |app| {
        app.scene_error().is_none() && app.loaded_scene().scene.spheres.len() == 1
    });
    settle(&mut harness);
    assert_shows_current_view(&harness);
}

#[test]
fn reload_button_reads_the_file_again() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.txt");
    std::fs::copy(scene_path("scene1_01.txt"), &file).unwrap();
    let mut harness = viewer(Some(file.clone()));
    std::fs::write(&file, std::fs::read(scene_path("scene1_02.txt")).unwrap()).unwrap();
    click(&mut harness, "Reload");
    settle(&mut harness);
    assert_eq!(harness.state().loaded_scene().scene.spheres.len(), 5);
    assert_shows_current_view(&harness);
}

#[test]
fn supersampling_shows_a_preview_while_moving_then_refines() {
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let quality = raytracer::render::Quality {
        sampling: Some(raytracer::render::Sampling {
            sampler: raytracer::render::Sampler::Jittered,
            samples: 16,
            filter: raytracer::render::Filter::Tent { radius: 1.0 },
            seed: 0,
        }),
    };
    harness.state_mut().settings_mut().quality = quality;
    settle(&mut harness);
    let refined = |harness: &Harness<'static, ViewerApp>| {
        let app = harness.state();
        let (frame, view) = shown(harness);
        assert!(!app.showing_preview());
        let expected =
            raytracer::render::render_with(&app.loaded_scene().scene, &view, &quality).unwrap();
        assert!(
            frame == expected,
            "the refined frame is the supersampled render"
        );
    };
    refined(&harness);

    // Move: the first frame of the new view is a one-sample preview.
    harness
        .get_by_role_and_label(Role::Slider, "centre x")
        .set_value_accesskit(0.4);
    harness.step();
    wait_until(&mut harness, |app| {
        app.shown_frame()
            .is_some_and(|(_, view)| view.center_world.x == 0.4)
    });
    assert!(harness.state().showing_preview(), "a preview first");
    let (preview, view) = shown(&harness);
    assert!(preview == render(&harness.state().loaded_scene().scene, &view).unwrap());
    // Still: refined to the chosen quality.
    settle(&mut harness);
    refined(&harness);
}

#[test]
fn a_slow_load_keeps_the_viewer_responsive_and_shows_progress() {
    use std::io::Write as _;
    // A named pipe as the scene file: the load blocks until this test writes the scene, as a
    // huge file on a slow disk would.
    let folder = tempfile::tempdir().unwrap();
    let pipe = folder.path().join("slow.txt");
    let made = std::process::Command::new("mkfifo")
        .arg(&pipe)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let spheres_before = harness.state().loaded_scene().scene.spheres.len();
    harness.state_mut().open(&pipe);
    assert!(harness.state().loading());

    // The UI keeps drawing frames quickly; the previous scene stays explorable.
    let started = Instant::now();
    while started.elapsed() < Duration::from_millis(700) {
        let step = Instant::now();
        harness.step();
        assert!(
            step.elapsed() < Duration::from_millis(200),
            "a frame took {:?}",
            step.elapsed()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(harness.state().loading());
    assert_eq!(
        harness.state().loaded_scene().scene.spheres.len(),
        spheres_before
    );
    harness.state_mut().view_mut().size_world *= 0.5;
    harness.run_steps(2);
    assert!(
        harness.query_by_label_contains("loading ").is_some(),
        "after half a second the status bar shows the load"
    );

    // Write the scene: the load finishes and the new scene is on screen.
    let mut writer = std::fs::OpenOptions::new().write(true).open(&pipe).unwrap();
    writer
        .write_all(
            b"OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n\
              Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }\n",
        )
        .unwrap();
    drop(writer);
    wait_until(&mut harness, |app| !app.loading());
    settle(&mut harness);
    assert_eq!(harness.state().loaded_scene().scene.spheres.len(), 1);
    assert!(harness.query_by_label_contains("loading ").is_none());
    assert_eq!(harness.state().scene_error(), None);
}
