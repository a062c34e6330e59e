//! The same pixels on every target: each frame here (the course's seven scenes at the course's
//! size and at a non-square one, and a dense scene of 20,000 spheres) is reduced to a digest of
//! its colour bytes, its t values (their bits) and its sphere indices, and the digests must
//! equal the record committed in `tests/same_pixels.txt`.
//!
//! * Natively, `cargo test` checks the record (`RAYTRACER_BLESS=1 cargo test --test same_pixels`
//!   writes it again, for a deliberate change of the renderer).
//! * In WebAssembly, `cargo xtask web test` runs this file with wasm-bindgen-test under Node,
//!   so the page's renderer must give the native renderer's frames bit for bit.
//!
//! The digest (FNV-1a, 64 bits) is written here, sharing no code with the renderer.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test;

use raytracer::explore::initial_depth_range;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Frame, View, render};
use raytracer::scene::bundled::BUNDLED_SCENES;
use raytracer::scene::{Scene, parse_scene};

#[path = "../examples/support/course.rs"]
mod course;

const RECORD: &str = include_str!("same_pixels.txt");

/// The course's seven scenes as bundled in the program, with the depth ranges of the course's
/// command lines (`course::ranges`, from `scenes/assignment1.commands` compiled in; it reads no
/// file, so it runs in WebAssembly too).
fn course_scenes() -> Vec<(&'static str, &'static str, f64, f64)> {
    course::ranges()
        .iter()
        .map(|&(name, min_t, max_t)| {
            let file = format!("{name}.txt");
            let (_, text) = BUNDLED_SCENES
                .iter()
                .find(|(bundled, _)| *bundled == file)
                .unwrap();
            (name, *text, min_t, max_t)
        })
        .collect()
}

/// FNV-1a over the frame's colour bytes, t bits and sphere indices.
fn digest(frame: &Frame) -> u64 {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for &byte in bytes {
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(0x0100_0000_01b3);
        }
    };
    for rgb in &frame.colour {
        eat(rgb);
    }
    for t in &frame.t {
        eat(&t.to_bits().to_le_bytes());
    }
    for sphere in &frame.sphere {
        eat(&sphere.to_le_bytes());
    }
    hash
}

/// Each case's record line: `name digest`.
fn lines() -> Vec<String> {
    let mut cases: Vec<(String, Scene, View)> = Vec::new();
    for (name, text, min_t, max_t) in course_scenes() {
        let scene = parse_scene(text).unwrap();
        for (width, height) in [(200, 200), (203, 61)] {
            let view = View::of_camera(&scene.camera, width, height, DepthRange::new(min_t, max_t));
            cases.push((format!("{name} {width}x{height}"), scene.clone(), view));
        }
    }
    let dense = raytracer::oracle::dense_scene(1, 20_000);
    let mut view = View::of_camera(&dense.camera, 256, 192, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(&dense, &view);
    cases.push(("dense 20000 256x192".to_owned(), dense, view));
    cases
        .iter()
        .map(|(name, scene, view)| format!("{name} {:016x}", digest(&render(scene, view).unwrap())))
        .collect()
}

fn check_the_record() {
    let lines = lines();
    let record: Vec<&str> = RECORD.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(lines.len(), 15);
    assert_eq!(
        record, lines,
        "the frames differ from tests/same_pixels.txt"
    );
}

#[cfg(not(target_arch = "wasm32"))]
#[test]
fn native_frames_match_the_record() {
    if std::env::var_os("RAYTRACER_BLESS").is_some() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/same_pixels.txt");
        let text = format!(
            "# Frame digests (tests/same_pixels.rs): native and WebAssembly must both give these.\n{}\n",
            lines().join("\n")
        );
        std::fs::write(path, text).unwrap();
        return;
    }
    check_the_record();
}

#[cfg(target_arch = "wasm32")]
#[wasm_bindgen_test]
fn webassembly_frames_match_the_record() {
    check_the_record();
}
