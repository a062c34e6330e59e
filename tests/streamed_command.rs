//! The course's own command (`-output` and `-depth` as TGA, one sample per pixel) is drawn and
//! written a strip of rows at a time. These tests run the real binary in a temporary folder and
//! read its files back with the image crate's decoder:
//!
//! * against the straightforward ray loop (`oracle::ray_loop`: one world-space ray per pixel
//!   against every sphere) and the general depth mapping `DepthRange::grey_u8`, on the course
//!   scenes at sizes whose rows are no whole number of strips, shorter than one strip, and wider
//!   than tall;
//! * against the whole-frame render, which `tests/render.rs` checks against the ray loop, on
//!   scenes too big for the loop: the dense ones, drawn front to back in passes (handed on in
//!   strips afterwards), and a sparse one of many spheres (drawn strip by strip);
//! * the files of the course's command equal, byte for byte, what the whole-frame path writes
//!   for the same pixels (the same command with a lossless depth file as well), and replacing
//!   files leaves no temporary file behind;
//! * the course's command never holds a whole frame (its peak memory, by `-stats`, is below
//!   what the frame alone takes), so it is the streamed path these tests run.

use std::path::{Path, PathBuf};
use std::process::Command;

use image::RgbImage;
use raytracer::render::depth_map::{DepthColourMap, DepthRange};
use raytracer::render::{NO_HIT, View, render};
use raytracer::scene::{Scene, load_scene};

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

fn run(folder: &Path, arguments: &[&str]) {
    let output = Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{arguments:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
}

fn load_tga(path: &Path) -> RgbImage {
    let bytes = std::fs::read(path).unwrap();
    image::load_from_memory_with_format(&bytes, image::ImageFormat::Tga)
        .unwrap()
        .to_rgb8()
}

/// Runs the course command on `scene_file` at `width × height` with a grey depth over
/// `(min, max)`; returns the colour and depth images read back.
fn course_command(
    folder: &Path,
    scene_file: &Path,
    (width, height): (u32, u32),
    (min, max): (f64, f64),
) -> (RgbImage, RgbImage) {
    let (w, h) = (width.to_string(), height.to_string());
    let (min, max) = (min.to_string(), max.to_string());
    let input = scene_file.to_str().unwrap();
    run(
        folder,
        &[
            "-input", input, "-size", &w, &h, "-output", "c.tga", "-depth", &min, &max, "d.tga",
        ],
    );
    (
        load_tga(&folder.join("c.tga")),
        load_tga(&folder.join("d.tga")),
    )
}

/// The colour and grey depth images a frame's t and spheres make, pixel by pixel, through the
/// general mapping: a pixel of sphere `s` gets its material's colour read from the scene,
/// `floor(c·255)`.
fn images_of(
    scene: &Scene,
    frame: &raytracer::render::Frame,
    range: DepthRange,
) -> (RgbImage, RgbImage) {
    let quantise = |c: f32| (c * 255.0).clamp(0.0, 255.0).floor() as u8;
    let colour = |index: usize| {
        let rgb = match frame.sphere[index] {
            NO_HIT => scene.background,
            sphere => scene.spheres[sphere as usize]
                .material
                .map_or(glam::Vec3::ONE, |m| {
                    scene.materials[m as usize].diffuse_colour
                }),
        };
        image::Rgb(rgb.to_array().map(quantise))
    };
    let width = frame.width_px;
    let at = |x: u32, y: u32| (y * width + x) as usize;
    (
        RgbImage::from_fn(width, frame.height_px, |x, y| colour(at(x, y))),
        RgbImage::from_fn(width, frame.height_px, |x, y| {
            image::Rgb([range.grey_u8(frame.t[at(x, y)]); 3])
        }),
    )
}

#[test]
fn the_course_command_draws_what_the_ray_loop_sees() {
    let folder = tempfile::tempdir().unwrap();
    // Rows: fewer than one strip, a strip and a bit, several strips and a ragged end; wider and
    // taller than square.
    let cases = [
        ("scene1_01.txt", (200, 200), (9.0, 10.0)),
        ("scene1_02.txt", (131, 47), (8.0, 12.0)),
        ("scene1_03.txt", (90, 301), (8.0, 12.0)),
        ("scene1_07.txt", (257, 129), (-2.0, 2.0)),
    ];
    for (name, size, (min, max)) in cases {
        let path = scene_path(name);
        let (colour, depth) = course_command(folder.path(), &path, size, (min, max));
        let scene = load_scene(&path).unwrap();
        let range = DepthRange::new(min, max);
        let view = View::of_camera(&scene.camera, size.0, size.1, range);
        let reference = raytracer::oracle::ray_loop::render_reference(&scene, &view).unwrap();
        let (wanted_colour, wanted_depth) = images_of(&scene, &reference, range);
        assert_eq!(colour, wanted_colour, "{name} {size:?}: colour");
        assert_eq!(depth, wanted_depth, "{name} {size:?}: depth");
    }
}

/// Writes `scene` as a file in `folder`.
fn scene_file(folder: &Path, name: &str, scene: &Scene) -> PathBuf {
    let path = folder.join(name);
    std::fs::write(&path, raytracer::scene::scene_to_text(scene)).unwrap();
    path
}

#[test]
fn dense_and_crowded_scenes_draw_what_the_whole_frame_draws() {
    let folder = tempfile::tempdir().unwrap();
    // 80,000 dense spheres lie about eight deep: drawn in passes.
    let dense = raytracer::oracle::dense_scene(4, 80_000);
    let random = raytracer::oracle::random_scene(9, 30_000);
    for (name, scene, size) in [
        ("dense.txt", dense, (300, 277)),
        ("random.txt", random, (333, 300)),
    ] {
        let path = scene_file(folder.path(), name, &scene);
        let scene = load_scene(&path).unwrap();
        let view = View::of_camera(&scene.camera, size.0, size.1, DepthRange::new(0.0, 1.0));
        let frame = render(&scene, &view).unwrap();
        let hit: Vec<f64> = frame.t.iter().copied().filter(|t| t.is_finite()).collect();
        assert!(
            hit.len() > frame.t.len() / 10,
            "{name}: {} pixels hit",
            hit.len()
        );
        let (near, far) = hit
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
                (lo.min(t), hi.max(t))
            });
        let range = DepthRange::new(near, far);
        let (colour, depth) = course_command(folder.path(), &path, size, (near, far));
        assert_eq!(colour, frame.colour_image(), "{name}: colour");
        assert_eq!(
            depth,
            frame.depth_image_mapped(range, DepthColourMap::Grey, [0; 3]),
            "{name}: depth"
        );
    }
}

#[test]
fn the_files_are_the_whole_frame_paths_bytes_and_replacing_them_leaves_nothing_behind() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let input = scene.to_str().unwrap();
    let common = [
        "-input",
        input,
        "-size",
        "413",
        "250",
        "-depth_colormap",
        "turbo",
    ];
    // Whole frame: a lossless depth file as well makes the command render the frame whole.
    let mut whole = common.to_vec();
    whole.extend(["-output", "w.tga", "-depth", "8", "12", "wd.tga"]);
    whole.extend(["-depth_raw", "w.pfm"]);
    run(folder.path(), &whole);
    // Streamed, twice: the second run replaces the first run's files.
    let mut streamed = common.to_vec();
    streamed.extend(["-output", "s.tga", "-depth", "8", "12", "sd.tga"]);
    std::fs::write(folder.path().join("s.tga"), b"an older file").unwrap();
    run(folder.path(), &streamed);
    run(folder.path(), &streamed);
    let read = |name: &str| std::fs::read(folder.path().join(name)).unwrap();
    assert_eq!(read("s.tga"), read("w.tga"));
    assert_eq!(read("sd.tga"), read("wd.tga"));
    let mut names: Vec<String> = std::fs::read_dir(folder.path())
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["s.tga", "sd.tga", "w.pfm", "w.tga", "wd.tga"]);
}

/// The peak memory `-stats` reports of `arguments`, in MB.
fn peak_memory_mb(folder: &Path, arguments: &[&str]) -> f64 {
    let output = Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .current_dir(folder)
        .args(arguments)
        .arg("-stats")
        .output()
        .unwrap();
    assert!(output.status.success(), "{arguments:?}");
    let stats = String::from_utf8(output.stdout).unwrap();
    let line = stats
        .lines()
        .find_map(|line| line.strip_prefix("peak_memory_mb: "))
        .unwrap_or_else(|| panic!("no peak in {stats}"));
    line.parse().unwrap()
}

#[test]
fn the_course_command_never_holds_a_whole_frame() {
    let folder = tempfile::tempdir().unwrap();
    let scene = scene_path("scene1_02.txt");
    let input = scene.to_str().unwrap();
    let size = ["-size", "2000", "2000"];
    // t, sphere and colour per pixel: 15 bytes, 60 MB at 2000×2000.
    let frame_mb = 15.0 * 2000.0 * 2000.0 / 1e6;
    let mut streamed = vec!["-input", input];
    streamed.extend(size);
    streamed.extend(["-output", "c.tga", "-depth", "9", "10", "d.tga"]);
    let peak = peak_memory_mb(folder.path(), &streamed);
    assert!(peak < frame_mb, "streamed: {peak} MB");
    // The same frame written as PNG holds it whole: the measure tells the two apart.
    let mut whole = vec!["-input", input];
    whole.extend(size);
    whole.extend(["-output", "c.png"]);
    let peak = peak_memory_mb(folder.path(), &whole);
    assert!(peak > frame_mb, "whole: {peak} MB");
}
