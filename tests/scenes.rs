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

#[test]
fn loading_reports_progress_up_to_one() {
    use std::sync::Mutex;
    // A file of several read blocks, so reading reports more than once.
    let scene = raytracer::oracle::random_scene(7, 40_000);
    let text = raytracer::scene::scene_to_text(&scene);
    assert!(text.len() > 2 << 20, "{} bytes", text.len());
    let folder = tempfile::tempdir().unwrap();
    let path = folder.path().join("big.txt");
    std::fs::write(&path, &text).unwrap();
    let seen = Mutex::new(Vec::new());
    let loaded = raytracer::scene::load_scene_with_progress(&path, &|fraction| {
        seen.lock().unwrap().push(fraction);
    })
    .unwrap();
    assert_eq!(loaded.spheres.len(), 40_000);
    let seen = seen.into_inner().unwrap();
    assert!(seen.len() >= 3, "{seen:?}");
    assert!(seen.windows(2).all(|pair| pair[0] <= pair[1]), "{seen:?}");
    assert_eq!(seen.last(), Some(&1.0));
    assert!(seen.iter().all(|f| (0.0..=1.0).contains(f)));
}

#[test]
fn a_big_file_read_in_two_halves_loads_to_the_scene_its_text_parses_to() {
    // Over the size from which a file is read as two halves at once, with an odd length.
    let scene = raytracer::oracle::random_scene(3, 90_000);
    let mut text = raytracer::scene::scene_to_text(&scene);
    if text.len().is_multiple_of(2) {
        text.push('\n');
    }
    assert!(text.len() > 8 << 20, "{} bytes", text.len());
    let folder = tempfile::tempdir().unwrap();
    let path = folder.path().join("big.txt");
    std::fs::write(&path, &text).unwrap();
    let loaded = load_scene(&path).unwrap();
    assert_eq!(loaded, parse_scene(&text).unwrap());
    assert_eq!(loaded.spheres.len(), 90_000);
}
