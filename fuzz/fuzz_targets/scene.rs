//! Fuzz target: arbitrary bytes through the scene parser. Any text must parse to the same scene
//! or the same error on two threads (the split parser, which files reach from 4 MB, from 0 bytes
//! here). What parses must
//! * write back to text that parses to the same scene (`scene_to_text`),
//! * render a small view with no NaN t,
//! * supersample and map depth without a panic.
//!
//! Any panic, hang or runaway allocation is a bug.
#![no_main]

use libfuzzer_sys::fuzz_target;
use raytracer::explore::initial_depth_range;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Filter, Quality, Sampler, Sampling, View, render_with};
use raytracer::scene::{parse_scene, parse_scene_bytes, parse_scene_split_from, scene_to_text};

fuzz_target!(|bytes: &[u8]| {
    // A planted crash, for the fuzz script's own test that a crash fails the run.
    if std::env::var_os("RAYTRACER_FUZZ_PLANTED_CRASH").is_some() && bytes == b"planted crash" {
        panic!("the planted crash");
    }
    let parsed = parse_scene_bytes(bytes);
    if let Ok(text) = std::str::from_utf8(bytes) {
        assert_eq!(parse_scene_split_from(text, 0), parsed, "split parse differs");
    }
    let Ok(scene) = parsed else {
        return;
    };
    let written = scene_to_text(&scene);
    assert_eq!(parse_scene(&written).as_ref(), Ok(&scene), "{written}");

    let mut view = View::of_camera(&scene.camera, 8, 6, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(&scene, &view);
    let render = |sampling| render_with(&scene, &view, &Quality { sampling });
    let Ok(exact) = render(None) else {
        return;
    };
    assert!(exact.t.iter().all(|t| !t.is_nan()));
    let sampling = Sampling {
        sampler: Sampler::Jittered,
        samples: 4,
        filter: Filter::Tent { radius: 1.0 },
        seed: 1,
    };
    let supersampled = render(Some(sampling)).expect("renders where one sample does");
    let _ = supersampled.depth_image(view.depth_range);
});
