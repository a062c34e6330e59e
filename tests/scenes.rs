//! Every scene shipped with the project parses: the files in `scenes/` and the embedded default.

use raytracer::scene::{load_scene, parse_scene};

#[test]
fn every_file_in_scenes_parses() {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut parsed = 0;
    for entry in std::fs::read_dir(&folder).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "txt") {
            let scene = load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
            assert!(!scene.spheres.is_empty(), "{}", path.display());
            parsed += 1;
        }
    }
    assert!(
        parsed >= 10,
        "7 course scenes and at least 3 showcase scenes, found {parsed}"
    );
}

#[test]
fn embedded_default_scene_parses() {
    let scene = parse_scene(raytracer::DEFAULT_SCENE_TEXT).unwrap();
    assert!(scene.spheres.len() > 10);
}
