//! The comparison and the diagnosis, on the library: the variant renderer without mistakes
//! agrees with the exact renderer; each known mistake, alone and with any other, is named from
//! the images it makes; exact images and an unrelated scene's images name nothing.

use std::path::{Path, PathBuf};

use image::RgbImage;
use raytracer::compare::{Difference, Mistake, MistakeSet, Theirs, diagnose, render_variant};
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, render};
use raytracer::scene::{Scene, load_scene};

fn path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

fn scene(relative: &str) -> Scene {
    load_scene(&path(relative)).unwrap()
}

/// The scene on which every mistake shows (its file says how).
fn every_mistake() -> (Scene, View) {
    let scene = scene("tests/compare/every-mistake.txt");
    let view = View::of_camera(&scene.camera, 120, 80, DepthRange::new(6.0, 10.0));
    (scene, view)
}

/// The exact images, by the product's renderer.
fn exact(scene: &Scene, view: &View) -> (RgbImage, RgbImage) {
    let frame = render(scene, view).unwrap();
    (frame.colour_image(), frame.depth_image(view.depth_range))
}

fn both<'a>(images: &'a (RgbImage, RgbImage)) -> Theirs<'a> {
    Theirs {
        colour: Some(&images.0),
        depth: Some(&images.1),
    }
}

/// The course scenes with the depth ranges of the course's reference images.
const COURSE: [(&str, f64, f64); 7] = [
    ("scene1_01", 9.0, 10.0),
    ("scene1_02", 8.0, 12.0),
    ("scene1_03", 8.0, 12.0),
    ("scene1_04", 12.0, 17.0),
    ("scene1_05", 14.5, 19.5),
    ("scene1_06", 3.0, 7.0),
    ("scene1_07", -2.0, 2.0),
];

#[test]
fn without_mistakes_the_variant_renderer_agrees_with_the_exact_renderer() {
    let mut compared = 0;
    for (name, min_t, max_t) in COURSE {
        let scene = scene(&format!("scenes/{name}.txt"));
        for (width, height) in [(200, 200), (160, 90), (37, 61)] {
            let view = View::of_camera(&scene.camera, width, height, DepthRange::new(min_t, max_t));
            let (colour, depth) = render_variant(&scene, &view, MistakeSet::NONE);
            let (exact_colour, exact_depth) = exact(&scene, &view);
            let colour = Difference::of(&colour, &exact_colour);
            let depth = Difference::of(&depth, &exact_depth);
            assert!(
                colour.colour_matches(),
                "{name} {width}×{height}: {} px",
                colour.pixels_differing()
            );
            assert!(
                depth.depth_matches(),
                "{name} {width}×{height}: {} px",
                depth.pixels_differing()
            );
            compared += 1;
        }
    }
    assert_eq!(compared, 21);
}

#[test]
fn every_mistake_changes_the_test_scene() {
    let (scene, view) = every_mistake();
    let exact = render_variant(&scene, &view, MistakeSet::NONE);
    for mistake in Mistake::ALL {
        let made = render_variant(&scene, &view, MistakeSet::of(&[mistake]));
        let changed = Difference::of(&made.0, &exact.0).pixels_differing()
            + Difference::of(&made.1, &exact.1).pixels_beyond(1);
        assert!(changed > 0, "{mistake} changes nothing");
    }
}

#[test]
fn each_mistake_alone_is_named() {
    let (scene, view) = every_mistake();
    for mistake in Mistake::ALL {
        let set = MistakeSet::of(&[mistake]);
        let theirs = render_variant(&scene, &view, set);
        let diagnosis = diagnose(&scene, &view, both(&theirs));
        assert_eq!(diagnosis.mistakes, set, "{mistake}: {diagnosis:?}");
        assert_eq!(diagnosis.differing_left, 0, "{mistake}");
    }
}

#[test]
fn every_pair_of_mistakes_is_named() {
    let (scene, view) = every_mistake();
    let mut named = 0;
    let mut ambiguous = Vec::new();
    for (index, first) in Mistake::ALL.into_iter().enumerate() {
        for second in Mistake::ALL.into_iter().skip(index + 1) {
            let set = MistakeSet::of(&[first, second]);
            if !set.is_possible() {
                continue; // one tmin, one rule for depth outside the range
            }
            let theirs = render_variant(&scene, &view, set);
            let diagnosis = diagnose(&scene, &view, both(&theirs));
            if diagnosis.mistakes.is_empty() && !diagnosis.alternatives.is_empty() {
                // Two sets make exactly these images: naming one would be a guess.
                assert!(
                    diagnosis.alternatives.contains(&set),
                    "{set}: {diagnosis:?}"
                );
                ambiguous.push(set.to_string());
                continue;
            }
            assert_eq!(diagnosis.mistakes, set, "{set}: {diagnosis:?}");
            named += 1;
        }
    }
    assert!(ambiguous.is_empty(), "ambiguous pairs: {ambiguous:?}");
    assert_eq!(named, 103);
}

#[test]
fn exact_images_name_nothing() {
    for (name, min_t, max_t) in COURSE {
        let scene = scene(&format!("scenes/{name}.txt"));
        let view = View::of_camera(&scene.camera, 200, 200, DepthRange::new(min_t, max_t));
        let images = exact(&scene, &view);
        let diagnosis = diagnose(&scene, &view, both(&images));
        assert_eq!(diagnosis.mistakes, MistakeSet::NONE, "{name}");
        assert_eq!(diagnosis.differing_exact, 0, "{name}");
    }
}

#[test]
fn images_of_another_scene_name_nothing() {
    // Every course scene's images against every other course scene: never a word.
    let mut compared = 0;
    for (name, min_t, max_t) in COURSE {
        let scene = scene(&format!("scenes/{name}.txt"));
        let view = View::of_camera(&scene.camera, 200, 200, DepthRange::new(min_t, max_t));
        for (other, other_min, other_max) in COURSE {
            if other == name {
                continue;
            }
            let other_scene = scene_named(other);
            let other_view = View::of_camera(
                &other_scene.camera,
                200,
                200,
                DepthRange::new(other_min, other_max),
            );
            let theirs = exact(&other_scene, &other_view);
            let diagnosis = diagnose(&scene, &view, both(&theirs));
            if diagnosis.differing_exact == 0 {
                continue; // the two scenes make the same picture
            }
            assert_eq!(
                diagnosis.mistakes,
                MistakeSet::NONE,
                "{name} against {other}: {diagnosis:?}"
            );
            // Not even in part.
            assert_eq!(
                diagnosis.partial,
                MistakeSet::NONE,
                "{name} against {other}: {diagnosis:?}"
            );
            compared += 1;
        }
    }
    assert!(compared >= 40, "{compared}");
}

fn scene_named(name: &str) -> Scene {
    scene(&format!("scenes/{name}.txt"))
}

#[test]
fn on_the_course_scenes_each_mistake_that_shows_is_named_and_never_another() {
    // 200×200 as the course renders, 200×120 for the stretched image; the course's depth range
    // and its middle half (where depth outside the range shows).
    let mut named = Vec::new();
    let ranges = COURSE.iter().flat_map(|&(name, min_t, max_t)| {
        let quarter = 0.25 * (max_t - min_t);
        [
            (name, min_t, max_t),
            (name, min_t + quarter, max_t - quarter),
        ]
    });
    for (name, min_t, max_t) in ranges {
        let scene = scene_named(name);
        for mistake in Mistake::ALL {
            let (width, height) = if mistake == Mistake::Stretched {
                (200, 120)
            } else {
                (200, 200)
            };
            let view = View::of_camera(&scene.camera, width, height, DepthRange::new(min_t, max_t));
            let set = MistakeSet::of(&[mistake]);
            let theirs = render_variant(&scene, &view, set);
            let diagnosis = diagnose(&scene, &view, both(&theirs));
            if diagnosis.differing_exact == 0 {
                continue; // the mistake does not show on this scene
            }
            if diagnosis.mistakes.is_empty() {
                // Only when another set makes exactly the same images.
                assert!(
                    diagnosis.alternatives.contains(&set),
                    "{name} {mistake}: {diagnosis:?}"
                );
            } else {
                assert_eq!(diagnosis.mistakes, set, "{name} {mistake}");
                named.push(format!("{name} {mistake}"));
            }
        }
    }
    // Every mistake shows, and is named, on at least one course scene; but no two course spheres
    // tie, so last-wins shows only on the every-mistake scene.
    for mistake in Mistake::ALL.into_iter().filter(|&m| m != Mistake::LastWins) {
        assert!(
            named
                .iter()
                .any(|case| case.ends_with(&format!(" {mistake}"))),
            "{mistake} is named on no course scene: {named:?}"
        );
    }
}

/// Changes `count` pixels of `image`, spread by a seeded sequence, to colours far from theirs.
fn speckle(image: &mut RgbImage, count: usize, seed: u64) {
    let mut state = seed;
    let (width, height) = image.dimensions();
    for _ in 0..count {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let index = (state >> 33) % u64::from(width * height);
        let (x, y) = (
            (index % u64::from(width)) as u32,
            (index / u64::from(width)) as u32,
        );
        let pixel = image.get_pixel_mut(x, y);
        pixel.0 = pixel.0.map(|c| c.wrapping_add(128));
    }
}

#[test]
fn a_mistaken_image_with_a_little_noise_is_still_named() {
    // Stray pixels (a student's image saved lossily, a few pixels touched up) within the rule:
    // a tenth of the differing pixels and 1% of all.
    let (scene, view) = every_mistake();
    let set = MistakeSet::of(&[Mistake::FlippedVertically]);
    let mut theirs = render_variant(&scene, &view, set);
    let exact_differing = diagnose(&scene, &view, both(&theirs)).differing_exact;
    speckle(&mut theirs.0, 60, 1);
    speckle(&mut theirs.1, 60, 2);
    let diagnosis = diagnose(&scene, &view, both(&theirs));
    assert!(exact_differing > 1_500, "{exact_differing}");
    assert_eq!(diagnosis.mistakes, set, "{diagnosis:?}");
    assert!(
        diagnosis.differing_left > 0 && diagnosis.differing_left <= 120,
        "{diagnosis:?}"
    );
    // Past the rule (2% of all pixels changed), the same mistake is no longer the whole answer.
    speckle(&mut theirs.0, 400, 3);
    let diagnosis = diagnose(&scene, &view, both(&theirs));
    assert_eq!(diagnosis.mistakes, MistakeSet::NONE, "{diagnosis:?}");
}

#[test]
fn a_mistake_beside_something_unknown_is_named_in_part() {
    // Their colour image is flipped, and a block of it is painted over (a mistake outside the
    // vocabulary): no set explains it all, the flip explains most.
    let (scene, view) = every_mistake();
    let set = MistakeSet::of(&[Mistake::FlippedVertically]);
    let mut theirs = render_variant(&scene, &view, set);
    for y in 0..view.height_px {
        for x in 0..30 {
            theirs.0.put_pixel(x, y, image::Rgb([255, 0, 255]));
        }
    }
    let diagnosis = diagnose(&scene, &view, both(&theirs));
    assert_eq!(diagnosis.mistakes, MistakeSet::NONE, "{diagnosis:?}");
    assert_eq!(diagnosis.partial, set, "{diagnosis:?}");
    // What is left is about the painted block (30 × 80 pixels), no more.
    assert!(
        (2_000..=2_400).contains(&diagnosis.differing_left),
        "{diagnosis:?}"
    );
}

#[test]
fn two_mistakes_that_make_the_same_picture_are_both_offered_and_neither_named() {
    // scene1_02 is symmetric: upside down and mirrored, it looks the same.
    let scene = scene("scenes/scene1_02.txt");
    let view = View::of_camera(&scene.camera, 120, 80, DepthRange::new(8.0, 12.0));
    let theirs = render_variant(&scene, &view, MistakeSet::of(&[Mistake::FlippedVertically]));
    let diagnosis = diagnose(
        &scene,
        &view,
        Theirs {
            colour: Some(&theirs.0),
            depth: None,
        },
    );
    assert_eq!(diagnosis.mistakes, MistakeSet::NONE, "{diagnosis:?}");
    assert_eq!(diagnosis.partial, MistakeSet::NONE, "{diagnosis:?}");
    assert_eq!(
        diagnosis.alternatives,
        [
            MistakeSet::of(&[Mistake::FlippedVertically]),
            MistakeSet::of(&[Mistake::Mirrored])
        ],
        "{diagnosis:?}"
    );
}
