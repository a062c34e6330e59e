//! Helpers shared by the tests that compare images through the real binary (included by path):
//! running it in a folder, its `diagnosis:` statements and `name: value` lines, and the
//! every-mistake scene's images made with known mistakes by the project's variant renderer.
#![allow(dead_code)] // each test file uses its own share

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use raytracer::compare::MistakeSet;
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::load_scene;

pub(crate) fn path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

pub(crate) fn run(folder: &Path, arguments: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .current_dir(folder)
        .args(arguments)
        .output()
        .unwrap()
}

pub(crate) fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// The `diagnosis:` statements of a run, in order, by name (each line is `name values:
/// sentence`).
pub(crate) fn diagnosis(output: &Output) -> Vec<String> {
    stdout(output)
        .lines()
        .filter_map(|line| line.strip_prefix("diagnosis: "))
        .map(|statement| {
            let head = statement.split(':').next().unwrap_or(statement);
            head.split(' ').next().unwrap_or(head).to_owned()
        })
        .collect()
}

/// The value of the line `name: value`.
pub(crate) fn value(output: &Output, name: &str) -> String {
    let prefix = format!("{name}: ");
    stdout(output)
        .lines()
        .find_map(|line| line.strip_prefix(&prefix))
        .unwrap_or_else(|| panic!("no {name} in {}", stdout(output)))
        .to_owned()
}

pub(crate) const SCENE: &str = "tests/compare/every-mistake.txt";

/// Writes the images of `mistakes` on the every-mistake scene at 120×80, depth 6 … 10, as
/// `colour.EXT` and `depth.EXT`.
pub(crate) fn write_mistaken(folder: &Path, mistakes: MistakeSet, extension: &str) {
    let scene = load_scene(&path(SCENE)).unwrap();
    let view = View::of_camera(&scene.camera, 120, 80, DepthRange::new(6.0, 10.0));
    let (colour, depth) = render_variant(&scene, &view, mistakes);
    colour
        .save(folder.join(format!("colour.{extension}")))
        .unwrap();
    depth
        .save(folder.join(format!("depth.{extension}")))
        .unwrap();
}

pub(crate) fn compare(folder: &Path, extension: &str, more: &[&str]) -> Output {
    let scene = path(SCENE);
    let colour = format!("colour.{extension}");
    let depth = format!("depth.{extension}");
    let mut arguments = vec![
        "-input",
        scene.to_str().unwrap(),
        "-compare_output",
        &colour,
        "-compare_depth",
        "6",
        "10",
        &depth,
    ];
    arguments.extend_from_slice(more);
    run(folder, &arguments)
}
