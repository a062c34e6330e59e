//! The arguments the frame-timing examples share: `SCENE WIDTH HEIGHT [RUNS [GAP_MS]]`, the
//! scene loaded and the viewer's job for its own camera's view at that size.

use std::sync::Arc;

use raytracer::app::render_job::ViewerJob;
use raytracer::explore::initial_depth_range;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;

/// The viewer's job to time (a scene file's own camera at the size asked for, the depth range the
/// viewer starts with, one sample, the default depth style), and how many times.
pub(crate) struct FrameArgs {
    pub(crate) job: ViewerJob,
    pub(crate) runs: u32,
    /// Idle time before each frame (0: frames back to back).
    pub(crate) gap: std::time::Duration,
}

/// Reads `SCENE WIDTH HEIGHT [RUNS [GAP_MS]]` (RUNS `default_runs` and GAP_MS 0 when absent);
/// exits with `usage` on anything else.
pub(crate) fn frame_args(usage: &str, default_runs: u32) -> FrameArgs {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let [path, width, height, rest @ ..] = arguments.as_slice() else {
        eprintln!("usage: {usage}");
        std::process::exit(2);
    };
    let number = |text: &str| text.parse::<u32>().expect("a whole number");
    let runs = rest.first().map_or(default_runs, |r| number(r));
    let gap_ms = rest.get(1).map_or(0, |gap| number(gap));
    let scene = raytracer::scene::load_scene(std::path::Path::new(path)).expect("a scene");
    let mut view = View::of_camera(
        &scene.camera,
        number(width),
        number(height),
        DepthRange::new(0.0, 1.0),
    );
    view.depth_range = initial_depth_range(&scene, &view);
    let job = ViewerJob {
        scene: Arc::new(scene),
        view,
        scene_epoch: 0,
        quality: Default::default(),
        depth_style: Default::default(),
    };
    FrameArgs {
        job,
        runs,
        gap: std::time::Duration::from_millis(u64::from(gap_ms)),
    }
}
