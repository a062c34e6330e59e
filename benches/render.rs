//! Rendering benchmarks: the fast disc path (all cores) against the straightforward
//! single-threaded oracle loop, measured in the same run. Workloads are named
//! `<what>_<scene>_<width>x<height>`.

use std::hint::black_box;
use std::path::Path;

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{Criterion, criterion_group, criterion_main};
use raytracer::depth::DepthRange;
use raytracer::render::reference::render_reference;
use raytracer::render::{View, render};
use raytracer::scene::load_scene;

fn scene1_02_2000x2000(c: &mut Criterion) {
    let scene = load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_02.txt"))
        .expect("course scene");
    let view = View::of_camera(&scene.camera, 2000, 2000, DepthRange::new(8.0, 12.0));
    let mut group = c.benchmark_group("render_scene1_02_2000x2000");
    group.sample_size(10);
    group.bench_function("fast_discs_parallel", |b| {
        b.iter(|| render(black_box(&scene), black_box(&view)))
    });
    group.bench_function("oracle_loop_single_thread", |b| {
        b.iter(|| render_reference(black_box(&scene), black_box(&view)))
    });
    group.finish();
}

criterion_group!(benches, scene1_02_2000x2000);
criterion_main!(benches);
