//! The README's pictures of exploring a scene, rendered from the real viewer driven by
//! egui_kittest (wgpu; Mesa's lavapipe where there is no GPU). Run through
//! `cargo xtask screenshots readme`, which numbers the marked spots with ImageMagick:
//!
//! ```sh
//! cargo run --example screenshots -- OUT_FOLDER
//! ```
//!
//! Writes `OUT_FOLDER/explore.png`, `OUT_FOLDER/orbit.png` and `OUT_FOLDER/compare.png` (the
//! Compare section with an image rendered with the `pixel-corners` mistake), and for each a
//! `.marks` file of `x y` lines (pixels): the spots the annotations point at, in the README's
//! order, and a `.names` file: the repository's files the picture shows (`file:PATH`, the scene
//! the viewer has open), which the chore writes down in docs/pictures.tsv.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use egui::{Event, Modifiers, PointerButton, Pos2, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raytracer::app::ViewerApp;
use raytracer::cli::ViewerRequest;
use raytracer::export::ExtraDepth;
use raytracer::output::depth_file::RawDepthFormat;
use raytracer::render::depth_map::DepthColourMap;

type App = Harness<'static, ViewerApp>;

fn settle(harness: &mut App) {
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        harness.step();
        let app = harness.state();
        if app.frame_is_current() && !app.export_running() {
            return;
        }
        assert!(Instant::now() < deadline, "the viewer did not settle");
        app.wait_for_worker(Duration::from_millis(20));
    }
}

fn centre(harness: &App, label: &str) -> Pos2 {
    harness.get_by_label(label).rect().center()
}

fn press(harness: &mut App, pos: Pos2, button: PointerButton, pressed: bool) {
    harness.event(Event::PointerButton {
        pos,
        button,
        pressed,
        modifiers: Modifiers::NONE,
    });
    harness.step();
}

fn save(harness: &mut App, folder: &Path, name: &str, marks: &[Pos2]) {
    harness.run_steps(3);
    let image = harness.render().expect("the UI renders (wgpu)");
    image.save(folder.join(format!("{name}.png"))).unwrap();
    let mut text = String::new();
    for mark in marks {
        writeln!(text, "{} {}", mark.x.round(), mark.y.round()).unwrap();
    }
    std::fs::write(folder.join(format!("{name}.marks")), text).unwrap();
    let shown = harness
        .state()
        .loaded_scene()
        .path
        .as_ref()
        .map(|path| format!("file:{}", path.display()))
        .unwrap_or_default();
    std::fs::write(folder.join(format!("{name}.names")), shown).unwrap();
    println!("wrote {}", folder.join(format!("{name}.png")).display());
}

/// The viewer at 1280×720 on `scene`, rendered with wgpu.
fn viewer(scene: PathBuf) -> App {
    Harness::builder()
        .with_size(vec2(1280.0, 720.0))
        .wgpu()
        .build_eframe(move |cc| {
            ViewerApp::new(
                cc,
                ViewerRequest {
                    input: Some(scene),
                    ..Default::default()
                },
            )
        })
}

fn main() {
    let folder =
        std::path::absolute(std::env::args().nth(1).unwrap_or_else(|| "target".into())).unwrap();
    std::fs::create_dir_all(&folder).unwrap();
    // A path relative to the package, so the pictures show no machine's folders.
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    let mut harness = viewer(PathBuf::from("scenes/showcase_torus_knot.txt"));
    {
        let settings = harness.state_mut().settings_mut();
        settings.depth.colour_map = DepthColourMap::Turbo;
        settings.depth.mark_no_hit = true;
        settings.export.extra_depth = ExtraDepth::Raw(RawDepthFormat::Exr);
    }
    settle(&mut harness);
    harness.state_mut().auto_range();
    settle(&mut harness);

    // Pin a pixel on a sphere, then hover another one.
    let colour = harness.get_by_label("colour image").rect();
    let (frame, _) = harness.state().shown_frame().unwrap();
    let size = [frame.width_px as f32, frame.height_px as f32];
    let to_pos = |x: f32, y_up: f32| {
        Pos2::new(
            colour.min.x + x / size[0] * colour.width(),
            colour.max.y - y_up / size[1] * colour.height(),
        )
    };
    let frame = frame.clone();
    let hit_near = |fx: f32, fy: f32| {
        // The hit pixel nearest to the fraction (fx, fy) of the image.
        let (tx, ty) = (fx * size[0], fy * size[1]);
        let mut best = (f32::INFINITY, 0.0, 0.0);
        for y in (0..frame.height_px).step_by(3) {
            for x in (0..frame.width_px).step_by(3) {
                if frame.t[frame.index(x, y)].is_finite() {
                    let d = (x as f32 - tx).hypot(y as f32 - ty);
                    if d < best.0 {
                        best = (d, x as f32 + 0.5, y as f32 + 0.5);
                    }
                }
            }
        }
        to_pos(best.1, best.2)
    };
    let pin = hit_near(0.3, 0.65);
    harness.hover_at(pin);
    harness.step();
    press(&mut harness, pin, PointerButton::Primary, true);
    press(&mut harness, pin, PointerButton::Primary, false);
    let hover = hit_near(0.7, 0.4);
    harness.hover_at(hover);
    harness.run_steps(3);

    let depth = harness.get_by_label("depth image").rect();
    let probe_text = centre(&harness, "Unpin") + vec2(60.0, 0.0);
    let max_handle = centre(&harness, raytracer::app::ui::histogram::MAX_HANDLE_LABEL);
    let legend = Pos2::new(depth.center().x, max_handle.y + 20.0);
    let marks = [
        colour.center(),                // 1 drag, wheel, right-drag
        pin,                            // 2 the pinned probe
        probe_text,                     // 3 the probe's lines
        max_handle,                     // 4 a draggable end of the depth range
        legend,                         // 5 the legend
        centre(&harness, "Auto range"), // 6 auto range
        centre(&harness, "turbo"),      // 7 colour maps
        centre(&harness, "Frame all"),  // 8 frame all, reset, save view
    ];
    save(&mut harness, &folder, "explore", &marks);

    // Orbit: a right-drag across the colour image, then frame all.
    harness.event(Event::PointerGone);
    let from = colour.center();
    harness.hover_at(from);
    harness.step();
    press(&mut harness, from, PointerButton::Secondary, true);
    for step in 1..=6 {
        harness.hover_at(from + vec2(25.0 * step as f32, -12.0 * step as f32));
        harness.step();
    }
    let to = from + vec2(150.0, -72.0);
    press(&mut harness, to, PointerButton::Secondary, false);
    harness.event(Event::PointerGone);
    harness.state_mut().frame_all();
    harness.state_mut().settings_mut().depth.colour_map = DepthColourMap::Viridis;
    harness.state_mut().auto_range();
    settle(&mut harness);
    harness.state_mut().auto_range();
    settle(&mut harness);
    let marks = [from, to];
    save(&mut harness, &folder, "orbit", &marks);
    compare(&folder);
}

/// The Compare section: a course scene rendered with rays through pixel corners, typed into the
/// section, diagnosed, with the difference shown in place of the colour image and a pixel probed.
fn compare(folder: &Path) {
    use raytracer::compare::{Mistake, MistakeSet};
    use raytracer::oracle::mistaken::render_variant;
    let scene_path = PathBuf::from("scenes/scene1_03.txt");
    let scene = raytracer::scene::load_scene(&scene_path).unwrap();
    let view = raytracer::render::View::of_camera(
        &scene.camera,
        200,
        200,
        raytracer::render::depth_map::DepthRange::new(8.0, 12.0),
    );
    let (theirs, _) = render_variant(&scene, &view, MistakeSet::of(&[Mistake::PixelCorners]));
    // Relative to the package, so the picture names no machine's folders.
    let theirs_path = "target/theirs_scene1_03.tga";
    theirs.save(theirs_path).unwrap();
    let mut harness = viewer(scene_path);
    settle(&mut harness);
    harness.get_by_label("image").scroll_to_me();
    harness.run_steps(3);
    harness.get_by_label("image").click();
    harness.step();
    harness.get_by_label("image").type_text(theirs_path);
    harness.step();
    let button = centre(&harness, "Compare image");
    harness.hover_at(button);
    harness.step();
    press(&mut harness, button, PointerButton::Primary, true);
    press(&mut harness, button, PointerButton::Primary, false);
    let deadline = Instant::now() + Duration::from_secs(120);
    while harness.state().comparing() || harness.state().comparison().is_none() {
        assert!(Instant::now() < deadline, "the comparison did not finish");
        harness.step();
        std::thread::sleep(Duration::from_millis(5));
    }
    settle(&mut harness);
    harness.run_steps(3);
    // Hover a pixel where the two differ: the probe gives both values.
    let comparison = harness.state().comparison().unwrap().clone();
    let (width, height) = comparison.theirs.dimensions();
    let index = comparison
        .difference
        .per_pixel
        .iter()
        .enumerate()
        .filter(|&(_, &d)| d > 0)
        .map(|(i, _)| i)
        .nth(40)
        .unwrap();
    let (x, row) = (index as u32 % width, index as u32 / width);
    let colour = harness.get_by_label("colour image").rect();
    let fit = (colour.width() / width as f32).min(colour.height() / height as f32);
    let hover = colour.min + vec2((x as f32 + 0.5) * fit, (row as f32 + 0.5) * fit);
    harness.hover_at(hover);
    harness.run_steps(3);
    let heat = colour.min + vec2(40.0, 40.0);
    // Right of the diagnosis's line (a badge sits above and left of its spot), clear of the
    // match line above it.
    let diagnosis = harness
        .query_by_label_contains("diagnosis:")
        .unwrap()
        .rect()
        .right_center()
        + vec2(28.0, 14.0);
    let probe = harness
        .query_by_label_contains("· off by")
        .unwrap()
        .rect()
        .left_center()
        + vec2(30.0, 0.0);
    let marks = [
        heat,                              // 1 the difference in place of the render
        centre(&harness, "Compare image"), // 2 their image, typed or chosen
        diagnosis,                         // 3 counts, match and the diagnosis
        hover,                             // 4 a differing pixel
        probe,                             // 5 both values at it
    ];
    save(&mut harness, folder, "compare", &marks);
}
