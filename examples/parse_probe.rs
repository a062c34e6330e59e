//! scratch
use std::time::Instant;
fn main() {
    let scene = raytracer::oracle::random_scene(1, 1_000_000);
    let text = raytracer::scene::scene_to_text(&scene);
    let mut times = Vec::new();
    for _ in 0..15 {
        let s = Instant::now();
        let parsed = raytracer::scene::parse_scene(&text).unwrap();
        times.push(s.elapsed().as_secs_f64() * 1e3);
        assert_eq!(parsed.spheres.len(), 1_000_000);
    }
    times.sort_by(f64::total_cmp);
    println!(
        "parse 1M: min {:.0} median {:.0} ms ({:.0} MB)",
        times[0],
        times[2],
        text.len() as f64 / 1e6
    );
}
