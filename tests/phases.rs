//! The frame's phase timings (`raytracer::render::phases`), which `examples/frame_phases` and
//! `cargo xtask report scaling` report: a dense frame names every phase of its passes, a sparse one its
//! own, and a measurement reports its own work alone.

use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, phases, render};
use raytracer::scene::Scene;

fn measured_names(scene: &Scene) -> Vec<&'static str> {
    let view = View::of_camera(&scene.camera, 160, 96, DepthRange::new(0.0, 1.0));
    let (frame, recorded) = phases::measure(|| render(scene, &view));
    assert!(frame.is_ok());
    assert!(recorded.iter().all(|&(_, ms)| ms >= 0.0), "{recorded:?}");
    recorded.into_iter().map(|(name, _)| name).collect()
}

#[test]
fn a_frame_names_its_phases_and_a_measurement_reports_its_own_work_alone() {
    let dense = measured_names(&raytracer::oracle::dense_scene(7, 200_000));
    for phase in [
        "project",
        "plan",
        "clear",
        "cull",
        "sort and bin",
        "draw",
        "coarse depth",
        "shade",
    ] {
        assert!(
            dense.contains(&phase),
            "dense frame without {phase:?}: {dense:?}"
        );
    }
    let sparse = measured_names(&raytracer::oracle::random_scene(3, 50));
    for phase in ["project", "bin", "draw", "shade"] {
        assert!(
            sparse.contains(&phase),
            "sparse frame without {phase:?}: {sparse:?}"
        );
    }
    assert!(
        !sparse.contains(&"cull"),
        "a sparse frame is not culled: {sparse:?}"
    );
    // A measurement reports its own work alone, not a frame drawn before it unmeasured.
    let scene = raytracer::oracle::random_scene(3, 50);
    let view = View::of_camera(&scene.camera, 96, 64, DepthRange::new(0.0, 1.0));
    render(&scene, &view).unwrap();
    let (_, recorded) = phases::measure(|| render(&scene, &view));
    let projections = recorded
        .iter()
        .filter(|(name, _)| *name == "project")
        .count();
    assert_eq!(projections, 1, "{recorded:?}");
}
