//! Viewer latency: the work between a slider change and a frame ready to upload — rendering a
//! 1024×1024 view and preparing both texture images (what the viewer's worker does) — for each
//! course scene and for generated scenes of 1,000 and 100,000 spheres; and, alone, the depth
//! histogram of a dense frame (the part of that work that counts every pixel's t) and the grey
//! depth image (the part that maps every pixel's t).

use std::hint::black_box;
use std::path::Path;
use std::sync::Arc;

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{Criterion, criterion_group, criterion_main};
use raytracer::app::depth_stats::DepthHistogram;
use raytracer::app::render_job::{HISTOGRAM_BINS, ViewerJob, prepare_frame};
use raytracer::explore::initial_depth_range;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::{Scene, load_scene};

/// The viewer's job for a 1024×1024 view of `scene` through its own camera.
fn job_1024x1024(scene: Scene) -> ViewerJob {
    let mut view = View::of_camera(&scene.camera, 1024, 1024, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(&scene, &view);
    ViewerJob {
        scene: Arc::new(scene),
        view,
        scene_epoch: 0,
        quality: Default::default(),
        depth_style: Default::default(),
    }
}

fn viewer_frame_1024x1024(c: &mut Criterion) {
    let mut group = c.benchmark_group("viewer_frame_1024x1024");
    group.sample_size(30);
    for number in 1..=7 {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/scene1_0{number}.txt"));
        let job = job_1024x1024(load_scene(&path).expect("course scene"));
        group.bench_function(format!("scene1_0{number}"), |b| {
            b.iter(|| prepare_frame(black_box(&job)));
        });
    }
    for count in [1_000usize, 100_000] {
        let job = job_1024x1024(raytracer::oracle::random_scene(1, count));
        group.bench_function(format!("generated_{count}"), |b| {
            b.iter(|| prepare_frame(black_box(&job)));
        });
    }
    for count in [100_000usize, 1_000_000] {
        let job = job_1024x1024(raytracer::oracle::dense_scene(7, count));
        group.bench_function(format!("dense_{count}"), |b| {
            b.iter(|| prepare_frame(black_box(&job)));
        });
    }
    group.finish();
}

/// The depth histogram the viewer draws, of a 1024×1024 frame of the dense 100,000-sphere scene.
fn depth_histogram_1024x1024(c: &mut Criterion) {
    let job = job_1024x1024(raytracer::oracle::dense_scene(7, 100_000));
    let frame = raytracer::render::render(&job.scene, &job.view).expect("renders");
    let mut group = c.benchmark_group("depth_histogram_1024x1024");
    group.sample_size(50);
    group.bench_function("dense_100000", |b| {
        b.iter(|| DepthHistogram::new(black_box(&frame), HISTOGRAM_BINS));
    });
    group.finish();
}

/// The grey depth image of a 1024×1024 frame (what the depth texture and a depth file start
/// from), of the course's scene1_02 and of the dense 100,000-sphere scene.
fn depth_image_1024x1024(c: &mut Criterion) {
    let mut group = c.benchmark_group("depth_image_1024x1024");
    group.sample_size(50);
    let course = load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_02.txt"))
        .expect("the course scene");
    for (name, scene) in [
        ("scene1_02", course),
        ("dense_100000", raytracer::oracle::dense_scene(7, 100_000)),
    ] {
        let job = job_1024x1024(scene);
        let frame = raytracer::render::render(&job.scene, &job.view).expect("renders");
        group.bench_function(name, |b| {
            b.iter(|| black_box(&frame).depth_image(job.view.depth_range));
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    viewer_frame_1024x1024,
    depth_histogram_1024x1024,
    depth_image_1024x1024
);
criterion_main!(benches);
