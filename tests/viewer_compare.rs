//! The viewer's Compare section as a user meets it (egui_kittest): their image typed into the
//! section is put beside the exact render and diagnosed, the A/B flip and the difference view
//! replace the compared image on screen, the probe gives both values, a depth image is judged
//! under the range read back from it and then follows the depth range, messages stay current, and "Against the exact render" measures the chosen quality on the user's view.
//! Their images are made by the project's variant renderer and written as real files.
#![cfg(feature = "gui")]

mod common;

use std::path::Path;
use std::time::{Duration, Instant};

use egui::{Key, Modifiers, vec2};
use egui_kittest::kittest::Queryable;
use raytracer::app::compare::{CompareShow, CompareSource, ImageKind};
use raytracer::compare::{Mistake, MistakeSet};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Filter, Sampler, Sampling};
use raytracer::scene::load_scene;

use common::{click, compare_image, label_shown, settle, viewer, wait_for_comparison};

const SCENE: &str = "tests/compare/every-mistake.txt";

fn scene_file() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(SCENE)
}

/// Writes the colour and depth images of `mistakes` at 160×120, depth 6 … 10, into `folder`.
fn write_theirs(folder: &Path, mistakes: MistakeSet) -> (String, String) {
    let scene = load_scene(&scene_file()).unwrap();
    let view = View::of_camera(&scene.camera, 160, 120, DepthRange::new(6.0, 10.0));
    let (colour, depth) = render_variant(&scene, &view, mistakes);
    let colour_path = folder.join("theirs.tga");
    let depth_path = folder.join("theirs_depth.png");
    colour.save(&colour_path).unwrap();
    depth.save(&depth_path).unwrap();
    (
        colour_path.display().to_string(),
        depth_path.display().to_string(),
    )
}

#[test]
fn their_colour_image_is_diagnosed_flipped_and_probed() {
    let folder = tempfile::tempdir().unwrap();
    let mistakes = MistakeSet::of(&[Mistake::PixelCorners, Mistake::Mirrored]);
    let (colour, _) = write_theirs(folder.path(), mistakes);
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    compare_image(&mut harness, &colour);

    let comparison = harness.state().comparison().expect("a comparison").clone();
    assert!(matches!(comparison.source, CompareSource::File(_)));
    assert_eq!(comparison.diagnosis(), ["pixel-corners", "mirrored"]);
    assert!(label_shown(&harness, "diagnosis: pixel-corners, mirrored"));
    assert!(label_shown(&harness, "match: no"));
    // The view is held at the file's camera and their size, so the two line up.
    let view = *harness.state().view();
    assert_eq!((view.width_px, view.height_px), (160, 120));
    let scene = load_scene(&scene_file()).unwrap();
    assert_eq!(view.center_world, scene.camera.center_world);
    let (frame, _) = harness.state().shown_frame().unwrap();
    assert_eq!(frame.colour_image(), comparison.exact);
    // The difference is shown first, in place of the colour image; B flips to theirs and back.
    assert_eq!(harness.state().compare_show(), CompareShow::Difference);
    let differing = comparison.difference.pixels_differing();
    assert!(differing > 0);
    assert!(label_shown(
        &harness,
        &format!(
            "colour: difference, {} pixels",
            common::with_commas(differing)
        )
    ));
    // The heat map's scale is beside its caption, and only while the heat map shows.
    let scale = harness.get_by_label("heat map scale").rect();
    let colour = harness.get_by_label("colour image").rect();
    assert!(
        scale.bottom() <= colour.top() && scale.left() >= colour.left(),
        "{scale:?}"
    );
    harness.key_press(Key::B);
    harness.run_steps(2);
    assert_eq!(harness.state().compare_show(), CompareShow::Theirs);
    assert!(label_shown(&harness, "colour: theirs"));
    assert!(harness.query_by_label("heat map scale").is_none());
    harness.key_press(Key::B);
    harness.run_steps(2);
    assert_eq!(harness.state().compare_show(), CompareShow::Rendered);
    harness.key_press_modifiers(Modifiers::SHIFT, Key::B);
    harness.run_steps(2);
    assert_eq!(harness.state().compare_show(), CompareShow::Difference);

    // The probe over a differing pixel gives both values and the difference.
    let (x, row) = (0..160 * 120)
        .map(|i| (i % 160, i / 160))
        .find(|&(x, row)| comparison.difference.per_pixel[(row * 160 + x) as usize] > 0)
        .unwrap();
    let image = harness.get_by_label("colour image").rect();
    let fit = (image.width() / 160.0).min(image.height() / 120.0);
    let at = image.min + vec2((x as f32 + 0.5) * fit, (row as f32 + 0.5) * fit);
    harness.hover_at(at);
    harness.run_steps(3);
    let rgb = |image: &image::RgbImage| {
        let [r, g, b] = image.get_pixel(x, row).0;
        format!("{r} {g} {b}")
    };
    let line = format!(
        "theirs {} · exact {} · off by {}",
        rgb(&comparison.theirs),
        rgb(&comparison.exact),
        comparison.difference.per_pixel[(row * 160 + x) as usize]
    );
    assert!(label_shown(&harness, &line), "no probe line {line}");

    // Closing frees the view: it takes the window's size again.
    click(&mut harness, "Close comparison");
    settle(&mut harness);
    assert!(harness.state().comparison().is_none());
    let view = *harness.state().view();
    assert_ne!((view.width_px, view.height_px), (160, 120));
}

#[test]
fn the_exact_image_matches_and_names_nothing() {
    let folder = tempfile::tempdir().unwrap();
    let (colour, _) = write_theirs(folder.path(), MistakeSet::NONE);
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    compare_image(&mut harness, &colour);
    let comparison = harness.state().comparison().expect("a comparison");
    assert_eq!(comparison.difference.pixels_differing(), 0);
    assert!(comparison.statements.is_empty());
    assert!(label_shown(&harness, "match: yes"));
    assert!(label_shown(&harness, "diagnosis: none needed"));
}

#[test]
fn a_depth_image_is_judged_under_the_range_read_from_it_then_follows_the_depth_range() {
    let folder = tempfile::tempdir().unwrap();
    let (_, depth) = write_theirs(folder.path(), MistakeSet::NONE);
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    harness.state_mut().view_mut().depth_range = DepthRange::new(5.0, 12.0);
    settle(&mut harness);
    click(&mut harness, "depth");
    compare_image(&mut harness, &depth);
    // Made over 6 … 10, it is judged under the range read from it, with no click: a match, and
    // the depth range above shows the range in use.
    let comparison = harness.state().comparison().unwrap().clone();
    assert_eq!(comparison.view.depth_range, DepthRange::new(6.0, 10.0));
    assert!(comparison.difference.depth_matches());
    assert!(label_shown(&harness, "match: yes"));
    assert!(label_shown(
        &harness,
        "judged under 6 … 10 (read from their image)"
    ));
    assert_eq!(
        harness.state().view().depth_range,
        DepthRange::new(6.0, 10.0)
    );
    assert!(!label_shown(&harness, "their range looks like"));
    // The user sets another range: it is judged again under theirs, and the one read back is
    // offered; taking it makes the comparison again, and they match.
    harness.state_mut().view_mut().depth_range = DepthRange::new(5.0, 12.0);
    harness.run_steps(2);
    wait_for_comparison(&mut harness);
    assert_eq!(
        harness.state().comparison().unwrap().view.depth_range,
        DepthRange::new(5.0, 12.0)
    );
    assert!(label_shown(&harness, "match: no"));
    assert!(label_shown(
        &harness,
        "judged under 5 … 12 (the depth range above)"
    ));
    assert!(label_shown(&harness, "their range looks like 6 … 10:"));
    // The range judged under is the viewer's: the statement says so, and never blames their
    // code's DMIN and DMAX for it.
    let statements = harness.state().comparison().unwrap().statements.clone();
    let range = statements
        .iter()
        .find(|s| s.word() == "depth-range")
        .expect("a depth-range statement");
    let sentence = range.explanation();
    assert!(
        sentence.contains("not over the viewer's depth range 5 … 12"),
        "{sentence}"
    );
    assert!(label_shown(&harness, &sentence));
    assert!(!label_shown(&harness, "check how DMIN"));
    assert!(!label_shown(&harness, "-depth 5 12"));
    click(&mut harness, "use it");
    harness.run_steps(2);
    wait_for_comparison(&mut harness);
    assert!(!label_shown(&harness, "their range looks like"));
    let comparison = harness.state().comparison().unwrap();
    assert_eq!(comparison.view.depth_range, DepthRange::new(6.0, 10.0));
    assert!(comparison.difference.depth_matches());
    assert!(label_shown(&harness, "match: yes"));
}

#[test]
fn a_flipped_depth_image_is_named_at_once_and_one_with_no_ramp_is_judged_under_the_viewers_range() {
    let folder = tempfile::tempdir().unwrap();
    let (_, depth) = write_theirs(folder.path(), MistakeSet::of(&[Mistake::FlippedVertically]));
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    harness.state_mut().view_mut().depth_range = DepthRange::new(5.0, 12.0);
    settle(&mut harness);
    click(&mut harness, "depth");
    compare_image(&mut harness, &depth);
    let comparison = harness.state().comparison().unwrap().clone();
    assert_eq!(comparison.view.depth_range, DepthRange::new(6.0, 10.0));
    assert_eq!(comparison.diagnosis(), ["flipped-vertically"]);
    assert!(label_shown(&harness, "diagnosis: flipped-vertically"));

    // All black: no ramp to read a range from; judged under the viewer's, and said so.
    let black = folder.path().join("black.png");
    image::RgbImage::new(160, 120).save(&black).unwrap();
    harness.get_by_label("image").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.step();
    harness
        .get_by_label("image")
        .type_text(&black.display().to_string());
    harness.step();
    click(&mut harness, "Compare image");
    wait_for_comparison(&mut harness);
    let comparison = harness.state().comparison().unwrap();
    assert_eq!(comparison.view.depth_range, DepthRange::new(6.0, 10.0));
    assert!(label_shown(
        &harness,
        "judged under 6 … 10 (the depth range above: no range can be read from their image)"
    ));
}

#[test]
fn messages_are_current_a_failed_comparison_leaves_no_old_result() {
    let folder = tempfile::tempdir().unwrap();
    let (colour, _) = write_theirs(folder.path(), MistakeSet::of(&[Mistake::Mirrored]));
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    let missing = folder.path().join("nonexistent.png").display().to_string();
    compare_image(&mut harness, &missing);
    assert!(harness.state().comparison().is_none());
    assert!(label_shown(&harness, "nonexistent.png"));
    // A later comparison that succeeds replaces the error.
    harness.get_by_label("image").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.step();
    harness.get_by_label("image").type_text(&colour);
    harness.step();
    click(&mut harness, "Compare image");
    wait_for_comparison(&mut harness);
    assert!(harness.state().comparison().is_some());
    assert!(!label_shown(&harness, "nonexistent.png"));
    assert!(label_shown(&harness, "theirs.tga: differs"));
    // A failed one takes the old result off the screen.
    harness.get_by_label("image").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.step();
    harness.get_by_label("image").type_text(&missing);
    harness.step();
    click(&mut harness, "Compare image");
    wait_for_comparison(&mut harness);
    assert!(harness.state().comparison().is_none());
    assert!(!label_shown(&harness, "diagnosis: mirrored"));
    assert!(label_shown(&harness, "nonexistent.png"));
}

#[test]
fn against_the_exact_render_measures_the_chosen_quality_on_this_view() {
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    harness.state_mut().settings_mut().quality.sampling = Some(Sampling {
        sampler: Sampler::Uniform,
        samples: 4,
        filter: Filter::Box { radius: 0.5 },
        seed: 1,
    });
    settle(&mut harness);
    click(&mut harness, "Against the exact render");
    wait_for_comparison(&mut harness);
    let comparison = harness.state().comparison().expect("a measurement").clone();
    let CompareSource::Quality(figures) = &comparison.source else {
        panic!("{:?}", comparison.source)
    };
    // Anti-aliased edges differ from the exact one-sample picture, and less from 256 samples.
    assert!(figures.mean_error_levels > 0.0, "{figures:?}");
    assert!(
        figures.share_off > 0.0 && figures.share_off < 0.2,
        "{figures:?}"
    );
    let (reference_mean, _) = figures.against_reference.expect("against 256 samples");
    assert!(reference_mean < figures.mean_error_levels, "{figures:?}");
    assert!(figures.frame_ms > 0.0);
    let view = *harness.state().view();
    assert_eq!(comparison.view, view);
    assert!(label_shown(&harness, "mean error"));
    assert!(label_shown(&harness, "against 256 samples"));
    assert_eq!(harness.state().compare_show(), CompareShow::Difference);
    // The measurement is of this view: moving the camera closes it.
    harness.state_mut().view_mut().center_world.x += 0.5;
    harness.run_steps(2);
    assert!(harness.state().comparison().is_none());
}

#[test]
fn a_mistake_beside_an_unknown_one_is_shown_in_part_with_the_unexplained_pixels() {
    // Flipped, and a block painted over: the flip explains most of it, nothing all of it.
    let folder = tempfile::tempdir().unwrap();
    let scene = load_scene(&scene_file()).unwrap();
    let view = View::of_camera(&scene.camera, 160, 120, DepthRange::new(6.0, 10.0));
    let (mut colour, _) =
        render_variant(&scene, &view, MistakeSet::of(&[Mistake::FlippedVertically]));
    for y in 0..120 {
        for x in 0..30 {
            colour.put_pixel(x, y, image::Rgb([255, 0, 255]));
        }
    }
    let path = folder.path().join("theirs.png");
    colour.save(&path).unwrap();
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    compare_image(&mut harness, &path.display().to_string());
    let comparison = harness.state().comparison().expect("a comparison");
    assert!(comparison.statements.is_empty());
    let partial: Vec<&str> = comparison
        .partial
        .iter()
        .map(raytracer::compare::Deviation::word)
        .collect();
    assert_eq!(partial, ["flipped-vertically"]);
    assert!(label_shown(
        &harness,
        "diagnosis: in part: flipped-vertically"
    ));
    let unexplained = comparison.unexplained_pixels;
    assert!((2_000..=3_600).contains(&unexplained), "{unexplained}");
    assert!(label_shown(
        &harness,
        &format!("unexplained pixels: {unexplained} (cyan in the difference)")
    ));
    // They are marked where they are: in the painted block, none outside it.
    let flags = comparison
        .unexplained
        .clone()
        .expect("the unexplained pixels' places");
    let flagged = |inside: bool| {
        (0..160 * 120)
            .filter(|&i| flags[i] && ((i % 160) < 30) == inside)
            .count()
    };
    assert_eq!(flagged(true), unexplained);
    assert_eq!(flagged(false), 0);
    // The probe says so over a pixel of the block, and not over one the flip explains.
    let image = harness.get_by_label("colour image").rect();
    let fit = (image.width() / 160.0).min(image.height() / 120.0);
    let block = (0..160 * 120).find(|&i| flags[i]).unwrap();
    let explained = (0..160 * 120)
        .find(|&i| !flags[i] && comparison.difference.per_pixel[i] > 0)
        .unwrap();
    for (index, marked) in [(block, true), (explained, false)] {
        let (x, row) = ((index % 160) as f32, (index / 160) as f32);
        harness.hover_at(image.min + vec2((x + 0.5) * fit, (row + 0.5) * fit));
        harness.run_steps(3);
        assert!(label_shown(&harness, "off by"), "no probe line");
        assert_eq!(
            label_shown(&harness, "· unexplained"),
            marked,
            "pixel {index}"
        );
    }
}

#[test]
fn a_statement_pointed_at_shows_its_meaning_and_picture_and_highlights_its_pixels() {
    let folder = tempfile::tempdir().unwrap();
    let mistakes = MistakeSet::of(&[Mistake::PixelCorners, Mistake::Mirrored]);
    let (colour, _) = write_theirs(folder.path(), mistakes);
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    compare_image(&mut harness, &colour);
    let comparison = harness.state().comparison().unwrap().clone();
    assert_eq!(comparison.diagnosis(), ["pixel-corners", "mirrored"]);
    // Each statement explains pixels of its own; the two sets are not the same.
    let counts: Vec<usize> = comparison
        .explained_by
        .iter()
        .map(|flags| flags.as_ref().unwrap().iter().filter(|&&f| f).count())
        .collect();
    assert!(counts.iter().all(|&n| n > 0), "{counts:?}");
    assert_ne!(comparison.explained_by[0], comparison.explained_by[1]);
    assert!(harness.query_by_label_contains("what it means").is_none());
    harness.get_by_label_contains("mirrored: ").scroll_to_me();
    harness.run_steps(3);
    harness.get_by_label_contains("mirrored: ").hover();
    harness.run_steps(4);
    assert!(label_shown(&harness, "what it means"));
    assert!(label_shown(&harness, "in the gallery"));
    assert!(label_shown(
        &harness,
        &format!(
            "colour: the {} pixels mirrored explains",
            common::with_commas(counts[1])
        )
    ));
    // Pointed away, the difference is back.
    harness.hover_at(egui::pos2(1.0, 1.0));
    harness.run_steps(4);
    assert!(!label_shown(&harness, "pixels mirrored explains"));
}

#[test]
fn their_image_written_again_is_compared_again() {
    let folder = tempfile::tempdir().unwrap();
    let (colour, _) = write_theirs(folder.path(), MistakeSet::of(&[Mistake::Mirrored]));
    let mut harness = viewer(Some(scene_file()));
    settle(&mut harness);
    compare_image(&mut harness, &colour);
    assert_eq!(
        harness.state().comparison().unwrap().diagnosis(),
        ["mirrored"]
    );
    // Their program, fixed, writes the file again: the comparison follows with no click.
    write_theirs(folder.path(), MistakeSet::NONE);
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.step();
        let matched = harness
            .state()
            .comparison()
            .is_some_and(|c| c.difference.pixels_differing() == 0);
        if matched && !harness.state().comparing() {
            break;
        }
        assert!(
            Instant::now() < deadline,
            "their new image was not compared"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    settle(&mut harness);
    harness.run_steps(2);
    assert!(label_shown(&harness, "match: yes"));
}

/// A depth image given as colour (the default), named "mine.png", is judged as a depth image by its
/// content, and says so; one click on "colour" judges it again at once, as clicked.
#[test]
fn a_depth_image_given_as_colour_is_recognised_and_one_click_judges_it_as_clicked() {
    use egui::accesskit::Role::RadioButton;
    let folder = tempfile::tempdir().unwrap();
    let plain = folder.path().join("mine.png");
    std::fs::rename(write_theirs(folder.path(), MistakeSet::NONE).1, &plain).unwrap();
    let mut harness = viewer(Some(scene_file()));
    compare_image(&mut harness, &plain.display().to_string());
    let comparison = harness.state().comparison().unwrap().clone();
    assert_eq!(comparison.kind, ImageKind::Depth);
    assert!(comparison.difference.depth_matches() && label_shown(&harness, "match: yes"));
    let assumed = comparison.kind_assumed.expect("what was assumed is said");
    let said = "judged as a depth image: every pixel is grey";
    assert!(assumed.starts_with(said), "{assumed}");
    let offered = format!("{assumed}; click colour above to judge it as a colour image");
    assert!(label_shown(&harness, &offered));
    harness.get_by_role_and_label(RadioButton, "colour").hover();
    harness.step();
    harness.get_by_role_and_label(RadioButton, "colour").click();
    harness.run_steps(3);
    wait_for_comparison(&mut harness);
    let comparison = harness.state().comparison().unwrap();
    assert_eq!(comparison.kind, ImageKind::Colour);
    assert_eq!(comparison.kind_assumed, None);
    assert!(label_shown(&harness, "match: no"));
}
