//! Fuzz target: arbitrary bytes through the scene parser and, when they parse, a small render in
//! every precision mode and the depth mapping. Any panic, hang or runaway allocation is a bug.
#![no_main]

use libfuzzer_sys::fuzz_target;
use raytracer::render::depth_map::DepthRange;
use raytracer::explore::initial_depth_range;
use raytracer::render::{Precision, Quality, View, render_with};
use raytracer::scene::parse_scene_bytes;

fuzz_target!(|bytes: &[u8]| {
    let Ok(scene) = parse_scene_bytes(bytes) else {
        return;
    };
    let mut view = View::of_camera(&scene.camera, 8, 6, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(&scene, &view);
    for precision in Precision::ALL {
        if let Ok(frame) = render_with(&scene, &view, &Quality { precision }) {
            assert!(frame.t.iter().all(|t| !t.is_nan()));
            let _ = frame.depth_image(view.depth_range);
        }
    }
});
