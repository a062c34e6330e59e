//! Live reload and the file dialogs' fallback, driven through the real viewer (egui_kittest):
//! an editor's save in several quick writes reloads once, a save that renames a new file over the
//! scene reloads it, reading the file (as the viewer itself does) reloads nothing, and where no
//! file dialog can be shown the window says so, Open… does nothing else, and the typed export
//! paths do the job; another scene opened closes the comparison made against the one before;
//! their two images dropped at once are judged together, and again when their program writes them.
#![cfg(feature = "gui")]

mod common;
#[path = "common/compare_run.rs"]
mod compare_run;

use std::time::{Duration, Instant};

use common::{click, scene_path, settle, viewer};
use egui_kittest::kittest::Queryable;

type Harness = egui_kittest::Harness<'static, raytracer::app::ViewerApp>;

/// Steps the viewer for `duration`, settling at the end.
fn run_for(harness: &mut Harness, duration: Duration) {
    let until = Instant::now() + duration;
    while Instant::now() < until {
        harness.step();
        std::thread::sleep(Duration::from_millis(10));
    }
    settle(harness);
}

/// Steps until `condition` holds (at most 20 s).
fn wait_until(harness: &mut Harness, condition: impl Fn(&raytracer::app::ViewerApp) -> bool) {
    let deadline = Instant::now() + Duration::from_secs(20);
    while !condition(harness.state()) {
        assert!(Instant::now() < deadline, "the condition was not reached");
        harness.step();
        std::thread::sleep(Duration::from_millis(10));
    }
    settle(harness);
}

#[test]
fn a_burst_of_writes_reloads_once() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &file).unwrap();
    let mut harness = viewer(Some(file.clone()));
    let loads = harness.state().scene_loads();
    // Five writes 20 ms apart (an editor writing in pieces), the last one the whole new scene.
    let text = std::fs::read(scene_path("scene1_01.txt")).unwrap();
    for piece in 1..=5 {
        std::fs::write(&file, &text[..text.len() * piece / 5]).unwrap();
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
    wait_until(&mut harness, |app| app.scene_loads() > loads);
    run_for(&mut harness, Duration::from_millis(800));
    assert_eq!(harness.state().scene_loads(), loads + 1, "one reload");
    assert_eq!(harness.state().loaded_scene().scene.spheres.len(), 1);
    assert!(harness.state().scene_error().is_none());
}

#[test]
fn a_save_that_renames_a_new_file_over_the_scene_reloads_it() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &file).unwrap();
    let mut harness = viewer(Some(file.clone()));
    let loads = harness.state().scene_loads();
    let new = folder.path().join(".scene.txt.swp");
    std::fs::copy(scene_path("scene1_01.txt"), &new).unwrap();
    std::fs::rename(&new, &file).unwrap();
    wait_until(&mut harness, |app| app.scene_loads() > loads);
    assert_eq!(harness.state().loaded_scene().scene.spheres.len(), 1);
}

#[test]
fn reading_the_scene_file_reloads_nothing() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &file).unwrap();
    let mut harness = viewer(Some(file.clone()));
    let loads = harness.state().scene_loads();
    for _ in 0..5 {
        let _ = std::fs::read(&file).unwrap();
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
    run_for(&mut harness, Duration::from_millis(800));
    assert_eq!(
        harness.state().scene_loads(),
        loads,
        "reads are not changes"
    );
    // A change to another file in the folder reloads nothing either.
    std::fs::write(folder.path().join("notes.txt"), b"x").unwrap();
    run_for(&mut harness, Duration::from_millis(800));
    assert_eq!(harness.state().scene_loads(), loads);
}

#[test]
fn without_file_dialogs_the_window_says_so_and_typed_paths_work() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    harness.state_mut().without_file_dialogs();
    harness.run_steps(2);
    // The export section says so under its path field.
    assert!(
        harness
            .query_by_label_contains("no file dialog is available")
            .is_some()
    );
    // Open… says there is no dialog and does nothing else: the scene is not opened again, and
    // the view's history stays.
    harness.state_mut().view_mut().center_world.x += 0.5;
    settle(&mut harness);
    let loads = harness.state().scene_loads();
    let moved = harness.state().view().center_world;
    let said = |harness: &Harness| {
        harness
            .query_all_by_label_contains("no file dialog is available")
            .count()
    };
    let before = said(&harness);
    click(&mut harness, "Open…");
    run_for(&mut harness, Duration::from_millis(300));
    assert_eq!(harness.state().scene_loads(), loads);
    assert_eq!(harness.state().view().center_world, moved);
    assert!(said(&harness) > before, "the status bar says so too");
    // Export… and Ctrl+S use the typed export path; Save view as scene… the typed scene path.
    harness.state_mut().settings_mut().export.path =
        folder.path().join("typed.png").display().to_string();
    harness.state_mut().settings_mut().export.scene_path =
        folder.path().join("typed.txt").display().to_string();
    click(&mut harness, "Export…");
    settle(&mut harness);
    assert!(folder.path().join("typed_colour.png").exists());
    std::fs::remove_file(folder.path().join("typed_colour.png")).unwrap();
    let shortcut = egui::KeyboardShortcut::new(egui::Modifiers::COMMAND, egui::Key::S);
    harness.key_press_modifiers(shortcut.modifiers, shortcut.logical_key);
    harness.run_steps(3);
    settle(&mut harness);
    // The other files of the export exist now: the viewer asks before replacing them.
    click(&mut harness, "Replace");
    settle(&mut harness);
    assert!(
        folder.path().join("typed_colour.png").exists(),
        "Ctrl+S exported"
    );
    click(&mut harness, "Save view as scene…");
    settle(&mut harness);
    assert!(folder.path().join("typed.txt").exists());
}

/// Their image compared, then another scene opened: the comparison (made against the scene
/// before) goes with it, and their file, written again, is not judged against the new scene.
#[test]
fn opening_another_scene_closes_the_comparison_of_the_one_before() {
    let folder = tempfile::tempdir().unwrap();
    let theirs = folder.path().join("output1_02.png");
    std::fs::copy(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/output1_02.png"),
        &theirs,
    )
    .unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    common::compare_image(&mut harness, &theirs.display().to_string());
    assert!(
        harness
            .state()
            .comparison()
            .unwrap()
            .difference
            .colour_matches()
    );
    let loads = harness.state().scene_loads();
    harness.state_mut().open(&scene_path("scene1_04.txt"));
    wait_until(&mut harness, |app| {
        app.scene_loads() > loads && !app.loading()
    });
    assert!(harness.state().comparison().is_none());
    // Their program writes its file again: nothing is compared against scene1_04.
    std::fs::copy(
        folder.path().join("output1_02.png"),
        folder.path().join("again.png"),
    )
    .unwrap();
    std::fs::rename(folder.path().join("again.png"), &theirs).unwrap();
    run_for(&mut harness, Duration::from_secs(2));
    assert!(harness.state().comparison().is_none() && !harness.state().comparing());
}

/// Their program writing the watched image in two parts, 0.6 s apart (half of its bytes, then
/// all): the viewer waits for the whole image, with no error shown and the old comparison kept on
/// screen meanwhile, then compares it.
#[test]
fn their_image_still_being_written_is_waited_for() {
    let folder = tempfile::tempdir().unwrap();
    let reference = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference");
    let theirs = folder.path().join("output1_02.png");
    std::fs::copy(reference.join("output1_03.png"), &theirs).unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    common::compare_image(&mut harness, &theirs.display().to_string());
    assert!(
        !harness
            .state()
            .comparison()
            .unwrap()
            .difference
            .colour_matches()
    );
    let bytes = std::fs::read(reference.join("output1_02.png")).unwrap();
    std::fs::write(&theirs, &bytes[..bytes.len() / 2]).unwrap();
    let whole_at = Instant::now() + Duration::from_millis(600);
    let deadline = Instant::now() + Duration::from_secs(30);
    let mut written = false;
    loop {
        harness.step();
        let app = harness.state();
        if let Some((message, true)) = app.message() {
            panic!("an error was shown while their file was being written: {message}");
        }
        assert!(app.comparison().is_some(), "the comparison left the screen");
        if app.comparison().unwrap().difference.colour_matches() && !app.comparing() {
            break;
        }
        if !written && Instant::now() >= whole_at {
            std::fs::write(&theirs, &bytes).unwrap();
            written = true;
        }
        assert!(
            Instant::now() < deadline,
            "the whole image was not compared"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    assert!(written);
}

/// Steps until the comparison on screen is a pair judged, and `condition` holds of it (at most
/// 120 s: each pair is diagnosed).
fn wait_for_pair(
    harness: &mut Harness,
    condition: impl Fn(&raytracer::app::compare::ComparisonPixels) -> bool,
) {
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        harness.step();
        let app = harness.state();
        let paired = app.comparison().filter(|c| c.paired.is_some());
        if !app.comparing() && paired.is_some_and(&condition) {
            break;
        }
        assert!(Instant::now() < deadline, "the pair was not judged");
        std::thread::sleep(Duration::from_millis(10));
    }
    settle(harness);
    harness.run_steps(2);
}

/// Their colour and depth images dropped on the window at once are judged together, as the
/// command line judges the pair: the answer names what neither image says alone (last-wins from
/// the colour, depth-reversed from the depth), and both images are shown in place of the render.
/// The probe and the pixel trace give both images' values; a statement pointed at highlights its
/// pixels in each image where it explains any. When their program, fixed, writes both again, the
/// pair is judged again and matches.
#[test]
fn their_two_images_dropped_at_once_are_judged_together_as_the_command_line_judges_them() {
    use raytracer::compare::{Mistake, MistakeSet};
    let folder = tempfile::tempdir().unwrap();
    let program = MistakeSet::of(&[Mistake::DepthReversed, Mistake::LastWins]);
    compare_run::write_mistaken(folder.path(), program, "tga");
    let mut said = compare_run::diagnosis(&compare_run::compare(folder.path(), "tga", &[]));
    said.sort();
    assert_eq!(said, ["depth-reversed", "last-wins"]);
    let mut harness = viewer(Some(compare_run::path(compare_run::SCENE)));
    for name in ["colour.tga", "depth.tga"] {
        let file = common::DroppedOnTheWindow(folder.path().join(name));
        harness
            .input_mut()
            .dropped_files
            .push(std::sync::Arc::new(file));
    }
    wait_for_pair(&mut harness, |_| true);
    let comparison = harness.state().comparison().unwrap().clone();
    let mut kinds = [comparison.kind, comparison.paired.as_ref().unwrap().kind];
    kinds.sort_by_key(|kind| *kind == raytracer::app::compare::ImageKind::Depth);
    assert_eq!(
        kinds,
        [
            raytracer::app::compare::ImageKind::Colour,
            raytracer::app::compare::ImageKind::Depth
        ]
    );
    let mut names: Vec<String> = comparison
        .diagnosis()
        .iter()
        .map(|statement| statement.split(' ').next().unwrap().to_owned())
        .collect();
    names.sort();
    assert_eq!(names, said, "the viewer's answer is the command line's");
    // Each sentence of the pair, its counts measured on the files: the exact images written by
    // the binary at the same size and range, compared byte by byte with theirs.
    let scene = compare_run::path(compare_run::SCENE);
    let arguments = ["-input", scene.to_str().unwrap(), "-size", "120", "80"];
    let exact = [
        "-output",
        "exact.tga",
        "-depth",
        "6",
        "10",
        "exact_depth.tga",
    ];
    let written = compare_run::run(folder.path(), &[&arguments[..], &exact[..]].concat());
    assert!(written.status.success());
    let read = |name: &str| image::open(folder.path().join(name)).unwrap().to_rgb8();
    let images = [
        ("colour", read("colour.tga"), read("exact.tga")),
        ("depth", read("depth.tga"), read("exact_depth.tga")),
    ];
    let differing = |(_, theirs, exact): &(&str, image::RgbImage, image::RgbImage)| {
        theirs
            .pixels()
            .zip(exact.pixels())
            .filter(|(a, b)| a != b)
            .count()
    };
    let (colour, depth) = (differing(&images[0]), differing(&images[1]));
    assert!(colour > 0 && depth > 0);
    let other = comparison.paired.as_ref().unwrap();
    let named = format!(
        "judged together with the {} image {}, as the grader does",
        if other.kind == raytracer::app::compare::ImageKind::Depth {
            "depth"
        } else {
            "colour"
        },
        other.name()
    );
    assert!(common::label_shown(&harness, &named), "{named}");
    for (kind, count) in [("colour", colour), ("depth", depth)] {
        let counted = format!("{kind}: pixels differing: {count} (");
        assert!(common::label_shown(&harness, &counted), "{counted}");
    }
    assert!(common::label_shown(
        &harness,
        "match: no (colour differs, depth differs)"
    ));
    let (message, error) = harness.state().message().unwrap();
    let said = format!(
        "compared {} with {}, together: differs",
        comparison.name(),
        other.name()
    );
    assert!(!error && message == said, "{message}");
    for caption in ["colour: difference", "depth: difference"] {
        assert!(common::label_shown(&harness, caption), "{caption}");
    }
    // The probe over a pixel where both differ gives both images' values, each named.
    let (x, row) = (0..120 * 80)
        .map(|i| (i % 120, i / 120))
        .find(|&(x, row)| {
            images
                .iter()
                .all(|(_, t, e)| t.get_pixel(x, row) != e.get_pixel(x, row))
        })
        .unwrap();
    let shown = harness.get_by_label("colour image").rect();
    let fit = (shown.width() / 120.0).min(shown.height() / 80.0);
    let at = egui::vec2((x as f32 + 0.5) * fit, (row as f32 + 0.5) * fit);
    harness.hover_at(shown.min + at);
    harness.run_steps(3);
    for (kind, theirs, exact) in &images {
        let rgb = |image: &image::RgbImage| {
            let [r, g, b] = image.get_pixel(x, row).0;
            format!("{r} {g} {b}")
        };
        let line = format!(
            "{kind} theirs {} · exact {} · off by",
            rgb(theirs),
            rgb(exact)
        );
        assert!(common::label_shown(&harness, &line), "no probe line {line}");
    }
    // Both captions say the pictures were judged together.
    let together = harness.query_all_by_label_contains(", judged together (Shift+B");
    assert_eq!(together.count(), 2);
    // A statement pointed at highlights the pixels it explains in each image of the pair
    // where it explains any, the count that image's own.
    let both = [&comparison, comparison.paired.as_deref().unwrap()];
    for (index, name) in comparison.diagnosis().iter().enumerate() {
        let name = name.split(' ').next().unwrap();
        harness
            .get_by_label_contains(&format!("{name}: "))
            .scroll_to_me();
        harness.run_steps(3);
        harness.get_by_label_contains(&format!("{name}: ")).hover();
        harness.run_steps(4);
        let mut highlighted = 0;
        for image in both {
            let count = image.explained_by[index]
                .as_ref()
                .map_or(0, |flags| flags.iter().filter(|&&f| f).count());
            let kind = match image.kind {
                raytracer::app::compare::ImageKind::Colour => "colour",
                raytracer::app::compare::ImageKind::Depth => "depth",
            };
            let caption = format!(
                "{kind}: the {} pixels {name} explains",
                common::with_commas(count)
            );
            if count > 0 {
                assert!(common::label_shown(&harness, &caption), "{caption}");
                highlighted += 1;
            }
        }
        assert!(highlighted > 0, "{name} explains no pixel in either image");
        harness.hover_at(egui::pos2(1.0, 1.0));
        harness.run_steps(4);
    }
    // Pinned there and traced, the trace gives both images' values at that pixel, each beside
    // the exact one.
    let pixel_at = shown.min + at;
    for pressed in [true, false] {
        harness.event(egui::Event::PointerButton {
            pos: pixel_at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        harness.step();
    }
    harness.run_steps(2);
    click(&mut harness, "Trace");
    harness.run_steps(3);
    let value = |image: &image::RgbImage| image.get_pixel(x, row).0;
    let [r, g, b] = value(&images[0].1);
    let [er, eg, eb] = value(&images[0].2);
    let (grey, exact_grey) = (value(&images[1].1)[0], value(&images[1].2)[0]);
    for line in [
        format!("theirs, colour: {r} {g} {b} (exact {er} {eg} {eb})"),
        format!("theirs, depth: grey {grey} (exact {exact_grey})"),
    ] {
        assert!(
            harness.query_by_label_contains(&line).is_some(),
            "the trace says {line}"
        );
    }
    click(&mut harness, "Unpin");
    harness.run_steps(2);
    compare_run::write_mistaken(folder.path(), MistakeSet::NONE, "tga");
    wait_for_pair(&mut harness, |c| {
        c.images()
            .all(raytracer::app::compare::ComparisonPixels::matches)
    });
    assert!(common::label_shown(&harness, "match: yes"));
}

/// Their file, taken for a depth image by its content, written again as a colour image: it is
/// recognised again (the kind was guessed, not clicked) and judged alone, never beside its own
/// older version.
#[test]
fn their_file_written_again_as_the_other_kind_is_recognised_again_and_judged_alone() {
    use raytracer::app::compare::ImageKind;
    let folder = tempfile::tempdir().unwrap();
    compare_run::write_mistaken(folder.path(), raytracer::compare::MistakeSet::NONE, "png");
    let mine = folder.path().join("mine.png");
    std::fs::copy(folder.path().join("depth.png"), &mine).unwrap();
    let mut harness = viewer(Some(compare_run::path(compare_run::SCENE)));
    common::compare_image(&mut harness, &mine.display().to_string());
    assert_eq!(harness.state().comparison().unwrap().kind, ImageKind::Depth);
    let again = folder.path().join("again.png");
    std::fs::copy(folder.path().join("colour.png"), &again).unwrap();
    std::fs::rename(&again, &mine).unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.step();
        let app = harness.state();
        if !app.comparing()
            && app
                .comparison()
                .is_some_and(|c| c.kind == ImageKind::Colour)
        {
            break;
        }
        assert!(
            Instant::now() < deadline,
            "not judged again as a colour image"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    let comparison = harness.state().comparison().unwrap();
    assert!(
        comparison.paired.is_none(),
        "paired with its own older version"
    );
    assert!(comparison.matches());
}
