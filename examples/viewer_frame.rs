//! The benchmark figure for a view the real window showed: the viewer's work for one frame
//! (render, both textures, histogram: `raytracer::app::job::prepare_frame`) of a scene file's own
//! camera at WIDTH×HEIGHT pixels, median of RUNS, in milliseconds. `scripts/window-frame-times.sh`
//! puts it beside the frame times the window logged:
//!
//! ```sh
//! cargo run --release --example viewer_frame -- SCENE WIDTH HEIGHT [RUNS]
//! ```

#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::sync::Arc;
use std::time::Instant;

use raytracer::app::job::{ViewerJob, prepare_frame};
use raytracer::explore::initial_depth_range;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let [path, width, height, rest @ ..] = arguments.as_slice() else {
        eprintln!("usage: viewer_frame SCENE WIDTH HEIGHT [RUNS]");
        std::process::exit(2);
    };
    let number = |text: &str| text.parse::<u32>().expect("a whole number");
    let runs = rest.first().map_or(31, |r| number(r));
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
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let started = Instant::now();
            std::hint::black_box(prepare_frame(&job).expect("renders"));
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!("{:.2}", times[times.len() / 2]);
}
