//! `-compare_output`, `-compare_depth` and `-diff` through the real binary in a temporary folder:
//! the user's images are made by the project's own variant renderer with known mistakes, written
//! to TGA and PNG files, and the binary must name exactly those mistakes (exit 3), name nothing
//! for exact images (exit 0) and for another scene's images, and refuse what it cannot compare.

#[path = "common/command.rs"]
mod command;
#[path = "common/compare_run.rs"]
mod compare_run;

use command::stderr;
use compare_run::{SCENE, compare, diagnosis, path, run, stdout, value, write_mistaken};

use image::RgbImage;
use raytracer::compare::{Mistake, MistakeSet};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::load_scene;

#[test]
fn each_mistake_and_each_pair_is_named_with_exit_three() {
    let folder = tempfile::tempdir().unwrap();
    let mut runs = 0;
    for (index, first) in Mistake::ALL.into_iter().enumerate() {
        let mut sets = vec![MistakeSet::of(&[first])];
        sets.extend(
            Mistake::ALL
                .into_iter()
                .skip(index + 1)
                .map(|second| MistakeSet::of(&[first, second]))
                // One tmin, one rule for depth outside the range.
                .filter(|set| set.is_possible()),
        );
        for set in sets {
            // Alternate the formats the course's students write.
            let extension = if runs % 2 == 0 { "tga" } else { "png" };
            write_mistaken(folder.path(), set, extension);
            let output = compare(folder.path(), extension, &[]);
            assert_eq!(output.status.code(), Some(3), "{set}: {}", stderr(&output));
            let words: Vec<String> = set.mistakes().iter().map(|m| m.word().to_owned()).collect();
            assert_eq!(diagnosis(&output), words, "{set}:\n{}", stdout(&output));
            assert_eq!(value(&output, "match"), "no");
            runs += 1;
        }
    }
    assert_eq!(runs, 15 + 103);
}

#[test]
fn exact_images_match_with_exit_zero_and_no_diagnosis() {
    let folder = tempfile::tempdir().unwrap();
    for name in ["scene1_02", "scene1_07"] {
        let scene = path(&format!("scenes/{name}.txt"));
        let scene = scene.to_str().unwrap();
        // The images as the binary itself writes them...
        let made = run(
            folder.path(),
            &[
                "-input", scene, "-output", "c.tga", "-depth", "-2", "12", "d.tga",
            ],
        );
        assert!(made.status.success(), "{}", stderr(&made));
        // ...and the course's reference image.
        let reference = path(&format!("tests/reference/output{}.png", &name[5..]));
        let output = run(
            folder.path(),
            &[
                "-input",
                scene,
                "-compare_output",
                "c.tga",
                "-compare_depth",
                "-2",
                "12",
                "d.tga",
            ],
        );
        assert_eq!(output.status.code(), Some(0), "{name}: {}", stderr(&output));
        assert_eq!(value(&output, "colour_pixels_differing"), "0");
        assert_eq!(value(&output, "depth_pixels_differing"), "0");
        assert_eq!(value(&output, "match"), "yes");
        assert_eq!(diagnosis(&output), ["none"]);
        let output = run(
            folder.path(),
            &[
                "-input",
                scene,
                "-compare_output",
                reference.to_str().unwrap(),
            ],
        );
        assert_eq!(
            output.status.code(),
            Some(0),
            "{name} reference: {}",
            stdout(&output)
        );
    }
}

#[test]
fn another_scene_s_images_name_nothing() {
    let folder = tempfile::tempdir().unwrap();
    let other = path("scenes/scene1_04.txt");
    let made = run(
        folder.path(),
        &[
            "-input",
            other.to_str().unwrap(),
            "-size",
            "120",
            "80",
            "-output",
            "colour.png",
            "-depth",
            "6",
            "10",
            "depth.png",
        ],
    );
    assert!(made.status.success(), "{}", stderr(&made));
    let output = compare(folder.path(), "png", &[]);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert_ne!(value(&output, "colour_pixels_differing"), "0");
    assert_eq!(diagnosis(&output), ["none"]);
}

#[test]
fn the_difference_picture_shows_theirs_the_exact_image_and_the_heat_map() {
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(folder.path(), MistakeSet::of(&[Mistake::Mirrored]), "png");
    let output = compare(folder.path(), "png", &["-diff", "diff.png"]);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let picture = image::open(folder.path().join("diff.png"))
        .unwrap()
        .to_rgb8();
    // 120-pixel images are drawn five times as large (panels at least 600 wide: a pixel is a
    // visible square): four panels (theirs, exact, heat map, unexplained) and five gaps of 8
    // across; two rows (colour, depth).
    assert_eq!(picture.width(), 4 * 600 + 5 * 8);
    let theirs: RgbImage = image::open(folder.path().join("colour.png"))
        .unwrap()
        .to_rgb8();
    let panel_top = 8 + 14;
    for (x, y) in [(3, 5), (60, 40), (110, 70)] {
        assert_eq!(
            picture.get_pixel(8 + 5 * x, panel_top + 5 * y),
            theirs.get_pixel(x, y),
            "their pixel ({x}, {y})"
        );
    }
    // The heat map is black where the images agree (the background corner) and coloured where
    // they differ.
    let heat_left = 8 + 2 * (600 + 8);
    assert_eq!(picture.get_pixel(heat_left, panel_top).0, [0, 0, 0]);
    let coloured = (0..600)
        .flat_map(|x| (0..400).map(move |y| (x, y)))
        .filter(|&(x, y)| picture.get_pixel(heat_left + x, panel_top + y).0 != [0, 0, 0])
        .count();
    let differing: usize = value(&output, "colour_pixels_differing").parse().unwrap();
    assert_eq!(
        coloured,
        25 * differing,
        "each differing pixel is 5×5 in the heat map"
    );
}

#[test]
fn the_difference_picture_shows_where_the_unexplained_pixels_are() {
    // Flipped, and a block of the colour image painted over: the flip is named in part, and the
    // fourth panel draws the block's differing pixels cyan and the flip's grey.
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(
        folder.path(),
        MistakeSet::of(&[Mistake::FlippedVertically]),
        "png",
    );
    let colour_path = folder.path().join("colour.png");
    let mut colour = image::open(&colour_path).unwrap().to_rgb8();
    for y in 0..80 {
        for x in 90..120 {
            colour.put_pixel(x, y, image::Rgb([255, 0, 255]));
        }
    }
    colour.save(&colour_path).unwrap();
    let output = compare(folder.path(), "png", &["-diff", "diff.png"]);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("diagnosis_partial: flipped-vertically"),
        "{}",
        stdout(&output)
    );
    let unexplained: usize = value(&output, "unexplained_pixels").parse().unwrap();
    assert!(unexplained > 1000, "{unexplained}");
    let picture = image::open(folder.path().join("diff.png"))
        .unwrap()
        .to_rgb8();
    let (panel_top, mask_left) = (8 + 14, 8 + 3 * (600 + 8));
    let cyan = [0, 230, 255];
    let mut in_block = 0;
    let mut grey = 0;
    for x in 0..600 {
        for y in 0..400 {
            match picture.get_pixel(mask_left + x, panel_top + y).0 {
                pixel if pixel == cyan => {
                    assert!(x >= 450, "cyan outside the block at ({x}, {y})");
                    in_block += 1;
                }
                [90, 90, 90] => grey += 1,
                _ => {}
            }
        }
    }
    assert_eq!(in_block, 25 * unexplained, "each pixel is 5×5");
    assert!(grey > 0, "the flip's pixels are drawn as explained");
}

#[test]
fn a_depth_image_without_its_range_is_compared_over_the_range_it_was_made_over() {
    // Made over 6.3 … 10.7 (not the course's numbers) and upside down: the range is read back
    // from the image, the comparison uses it, and the flip is named.
    let folder = tempfile::tempdir().unwrap();
    let scene = load_scene(&path(SCENE)).unwrap();
    let view = View::of_camera(&scene.camera, 120, 80, DepthRange::new(6.3, 10.7));
    let (_, depth) = render_variant(&scene, &view, MistakeSet::of(&[Mistake::FlippedVertically]));
    depth.save(folder.path().join("depth.png")).unwrap();
    let scene_path = path(SCENE);
    let scene_arg = scene_path.to_str().unwrap();
    let output = run(
        folder.path(),
        &["-input", scene_arg, "-compare_depth", "depth.png"],
    );
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert_eq!(value(&output, "depth_range_inferred"), "6.3 10.7");
    assert_eq!(diagnosis(&output), ["flipped-vertically"]);
    assert_eq!(value(&output, "unexplained_pixels"), "0");
    // With a range given, that range is used and said as given: nothing is said to be inferred,
    // and the range their image was drawn over is the depth-range statement's.
    let output = run(
        folder.path(),
        &[
            "-input",
            scene_arg,
            "-compare_depth",
            "6",
            "10",
            "depth.png",
        ],
    );
    assert_eq!(value(&output, "depth_range_given"), "6 10");
    assert!(!stdout(&output).contains("depth_range_inferred"));
    assert!(
        stdout(&output).contains("diagnosis: depth-range 6.3 10.7:"),
        "{}",
        stdout(&output)
    );
    assert_ne!(diagnosis(&output), ["flipped-vertically"]);
    // A range a coarse rounding would move by most of a grey level (6.385 to 6.4) is read back
    // finely enough that the exact image matches.
    let view = View::of_camera(&scene.camera, 120, 80, DepthRange::new(6.385, 10.0));
    let (_, depth) = render_variant(&scene, &view, MistakeSet::NONE);
    depth.save(folder.path().join("exact.png")).unwrap();
    let output = run(
        folder.path(),
        &["-input", scene_arg, "-compare_depth", "exact.png"],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stdout(&output));
    assert_ne!(value(&output, "depth_range_inferred"), "6.4 10");
    // An image with no grey ramp (all black) has no range to read: refused, nothing written.
    image::RgbImage::new(120, 80)
        .save(folder.path().join("black.png"))
        .unwrap();
    let output = run(
        folder.path(),
        &[
            "-input",
            scene_arg,
            "-compare_depth",
            "black.png",
            "-diff",
            "diff.png",
        ],
    );
    assert_eq!(output.status.code(), Some(1), "{}", stdout(&output));
    assert!(
        stderr(&output).contains(
            "-compare_depth 'black.png': cannot infer the depth range it was made over (no grey \
             ramp to fit): give it as -compare_depth DMIN DMAX FILE"
        ),
        "{}",
        stderr(&output)
    );
    assert!(!folder.path().join("diff.png").exists());
}

#[test]
fn the_size_comes_from_the_images_and_must_agree() {
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(folder.path(), MistakeSet::NONE, "png");
    // Without -size: 120×80 from the files.
    let output = compare(folder.path(), "png", &[]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    // With another -size: refused, nothing written.
    let output = compare(
        folder.path(),
        "png",
        &["-size", "200", "200", "-diff", "diff.png"],
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("is 120×80 pixels, but -size asks for 200×200"),
        "{}",
        stderr(&output)
    );
    assert!(!folder.path().join("diff.png").exists());
    // Two images of different sizes.
    image::RgbImage::new(10, 10)
        .save(folder.path().join("depth.png"))
        .unwrap();
    let output = compare(folder.path(), "png", &[]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains(
            "-compare_depth 'depth.png' is 10×10 pixels, but -compare_output 'colour.png' is 120×80"
        ),
        "{}",
        stderr(&output)
    );
}

#[test]
fn what_cannot_be_compared_is_refused_and_their_file_is_never_written() {
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(folder.path(), MistakeSet::NONE, "png");
    let before = std::fs::read(folder.path().join("colour.png")).unwrap();
    let scene = path(SCENE);
    let scene = scene.to_str().unwrap();
    let cases: [(&[&str], i32, &str); 4] = [
        (&["-input", scene, "-diff", "d.png"], 2, "-diff needs"),
        (
            &[
                "-input",
                scene,
                "-compare_output",
                "colour.png",
                "-diff",
                "colour.png",
            ],
            2,
            "refusing to write over it",
        ),
        (
            &["-input", scene, "-compare_output", "missing.png"],
            1,
            "cannot read the image",
        ),
        (
            &["-input", scene, "-compare_output", "colour.jpg"],
            2,
            "unknown format",
        ),
    ];
    for (arguments, status, message) in cases {
        let output = run(folder.path(), arguments);
        assert_eq!(
            output.status.code(),
            Some(status),
            "{arguments:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains(message),
            "{arguments:?}: {}",
            stderr(&output)
        );
    }
    // Not an image at all.
    std::fs::write(folder.path().join("text.png"), "not a picture").unwrap();
    let output = run(
        folder.path(),
        &["-input", scene, "-compare_output", "text.png"],
    );
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("cannot read the image"),
        "{}",
        stderr(&output)
    );
    assert_eq!(
        std::fs::read(folder.path().join("colour.png")).unwrap(),
        before
    );
}

/// An image of more than 250,000 pixels is fitted on a sample of its pixels (every fourth row
/// and column) where it can be: its depth map, the candidates screened, the map polished. The
/// answer must still be the mistakes it was made with, every pixel explained.
#[test]
fn a_large_depth_image_is_named_as_a_small_one_is() {
    let folder = tempfile::tempdir().unwrap();
    let scene_path = path("scenes/scene1_05.txt");
    let scene = load_scene(&scene_path).unwrap();
    let view = View::of_camera(&scene.camera, 560, 560, DepthRange::new(14.5, 19.5));
    let set = MistakeSet::of(&[Mistake::RawUp, Mistake::DepthReversed]);
    let (_, depth) = render_variant(&scene, &view, set);
    depth.save(folder.path().join("depth.png")).unwrap();
    let scene_argument = scene_path.to_str().unwrap();
    let output = run(
        folder.path(),
        &[
            "-input",
            scene_argument,
            "-compare_depth",
            "14.5",
            "19.5",
            "depth.png",
        ],
    );
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert_eq!(
        diagnosis(&output),
        ["depth-reversed", "raw-up"],
        "{}",
        stdout(&output)
    );
    assert_eq!(
        value(&output, "unexplained_pixels"),
        "0",
        "{}",
        stdout(&output)
    );
}
