//! Rendering and parsing benchmarks (`cargo bench --bench render`): the binned disc renderer
//! (all cores) against the straightforward single-threaded loop over every sphere per pixel,
//! measured in the same run, and the parser's throughput. Workloads:
//!
//! * `course_2000x2000/<scene>`: each course scene at 2000×2000;
//! * `generated_1024x1024/<binned|brute_force>/<spheres>`: seeded scenes of
//!   [`raytracer::oracle::random_scene`] with 10 to 1,000,000 spheres (brute force only up to
//!   1,000: beyond, one frame takes minutes);
//! * `dense_1024x1024/render/<spheres>`: [`raytracer::oracle::dense_scene`] with 100,000 and
//!   1,000,000 spheres (every pixel covered about 10 and 100 times over);
//! * `parse/<spheres>`: the scene text of those scenes, in bytes per second.

use std::hint::black_box;
use std::path::Path;

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use raytracer::explore::initial_depth_range;
use raytracer::oracle::ray_loop::render_reference;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, render};
use raytracer::scene::{Scene, load_scene, parse_scene};
use raytracer::{oracle::random_scene, scene::scene_to_text};

/// Sphere counts of the generated scenes.
const GENERATED_COUNTS: [usize; 4] = [10, 1_000, 100_000, 1_000_000];

fn view_of(scene: &Scene, side_px: u32) -> View {
    let mut view = View::of_camera(&scene.camera, side_px, side_px, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(scene, &view);
    view
}

fn course_2000x2000(c: &mut Criterion) {
    let mut group = c.benchmark_group("course_2000x2000");
    group.sample_size(20);
    for number in 1..=7 {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/scene1_0{number}.txt"));
        let scene = load_scene(&path).expect("course scene");
        let view = view_of(&scene, 2000);
        group.bench_function(format!("scene1_0{number}"), |b| {
            b.iter(|| render(black_box(&scene), black_box(&view)));
        });
    }
    group.bench_function("scene1_02_brute_force", |b| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_02.txt");
        let scene = load_scene(&path).expect("course scene");
        let view = view_of(&scene, 2000);
        b.iter(|| render_reference(black_box(&scene), black_box(&view)));
    });
    group.finish();
}

fn generated_1024x1024(c: &mut Criterion) {
    let mut group = c.benchmark_group("generated_1024x1024");
    group.sample_size(10);
    for count in GENERATED_COUNTS {
        let scene = random_scene(1, count);
        let view = view_of(&scene, 1024);
        group.bench_with_input(BenchmarkId::new("binned", count), &count, |b, _| {
            b.iter(|| render(black_box(&scene), black_box(&view)));
        });
        if count <= 1_000 {
            group.bench_with_input(BenchmarkId::new("brute_force", count), &count, |b, _| {
                b.iter(|| render_reference(black_box(&scene), black_box(&view)));
            });
        }
    }
    group.finish();
}

fn dense_1024x1024(c: &mut Criterion) {
    let mut group = c.benchmark_group("dense_1024x1024");
    group.sample_size(10);
    for count in [100_000usize, 1_000_000] {
        let scene = raytracer::oracle::dense_scene(7, count);
        let view = view_of(&scene, 1024);
        let id = BenchmarkId::new("render", count);
        group.bench_with_input(id, &count, |b, _| {
            b.iter(|| render(black_box(&scene), black_box(&view)));
        });
    }
    group.finish();
}

fn parse(c: &mut Criterion) {
    let mut group = c.benchmark_group("parse");
    group.sample_size(10);
    for count in GENERATED_COUNTS {
        let text = scene_to_text(&random_scene(1, count));
        group.throughput(Throughput::Bytes(text.len() as u64));
        group.bench_with_input(BenchmarkId::from_parameter(count), &text, |b, text| {
            b.iter(|| parse_scene(black_box(text)));
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    course_2000x2000,
    generated_1024x1024,
    dense_1024x1024,
    parse
);
criterion_main!(benches);
