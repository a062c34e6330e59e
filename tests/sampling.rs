//! Supersampling: interior pixels equal the one-sample render, edge pixels are mixtures of the
//! colours around them, the error against the area-average oracle (which shares no code with the
//! supersampler, and is itself checked against the exact area of a disc in a square) falls as
//! samples grow, raw t stays the centre sample, and the same settings give the same bytes (also
//! through the binary).

use std::path::Path;
use std::process::Command;

use raytracer::oracle::area::{AreaAverage, area_average, disc_area_in_square};
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Filter, Frame, Quality, Sampler, Sampling, View, render, render_with};
use raytracer::scene::{Scene, load_scene};

fn scene(name: &str) -> Scene {
    load_scene(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name),
    )
    .unwrap()
}

fn view(scene: &Scene, side: u32) -> View {
    View::of_camera(&scene.camera, side, side, DepthRange::new(8.0, 12.0))
}

fn supersampled(
    scene: &Scene,
    view: &View,
    sampler: Sampler,
    samples: u32,
    filter: Filter,
) -> Frame {
    let quality = Quality {
        sampling: Some(Sampling {
            sampler,
            samples,
            filter,
            seed: 11,
        }),
    };
    render_with(scene, view, &quality).unwrap()
}

#[test]
fn interior_pixels_equal_the_one_sample_render_and_edges_are_mixtures() {
    let scene = scene("scene1_02.txt");
    let view = view(&scene, 120);
    let one = render(&scene, &view).unwrap();
    let filters = [
        Filter::Box { radius: 0.5 },
        Filter::Tent { radius: 1.5 },
        Filter::Gaussian { sigma: 0.7 },
    ];
    for filter in filters {
        let aa = supersampled(&scene, &view, Sampler::Jittered, 16, filter);
        let reach = filter.support().ceil() as i64 + 1;
        let (mut interior, mut mixtures) = (0, 0);
        for y in 0..120i64 {
            for x in 0..120i64 {
                let index = one.index(x as u32, y as u32);
                // The one-sample spheres around the pixel, as far as the filter reaches.
                let mut around = Vec::new();
                for ny in (y - reach).max(0)..=(y + reach).min(119) {
                    for nx in (x - reach).max(0)..=(x + reach).min(119) {
                        around.push(one.index(nx as u32, ny as u32));
                    }
                }
                if around.iter().all(|&i| one.sphere[i] == one.sphere[index]) {
                    assert_eq!(
                        aa.colour[index], one.colour[index],
                        "{filter}: interior ({x}, {y})"
                    );
                    interior += 1;
                } else {
                    // An edge pixel: each channel lies between the colours around it.
                    let colour = aa.colour[index];
                    for (channel, &value) in colour.iter().enumerate() {
                        let values = around.iter().map(|&i| one.colour[i][channel]);
                        let (low, high) =
                            values.fold((255u8, 0u8), |(l, h), v| (l.min(v), h.max(v)));
                        assert!(
                            (low..=high).contains(&value),
                            "{filter}: edge ({x}, {y}) channel {channel}: {value} not in {low}..={high}"
                        );
                    }
                    let is_palette = around.iter().any(|&i| one.colour[i] == colour);
                    mixtures += usize::from(!is_palette);
                }
            }
        }
        assert!(interior > 8_000, "{filter}: {interior} interior pixels");
        assert!(
            mixtures > 200,
            "{filter}: only {mixtures} mixed edge pixels"
        );
        // The raw t stays the centre sample.
        assert!(aa.t == one.t, "{filter}: t must be the one-sample t");
    }
}

/// Mean absolute difference, in 8-bit levels per channel, between a frame's colours and the
/// oracle's area averages (quantised as images are).
fn mean_colour_error(frame: &Frame, oracle: &AreaAverage) -> f64 {
    let total: f64 = frame
        .colour
        .iter()
        .enumerate()
        .map(|(index, pixel)| {
            let exact = oracle.colour_u8(index);
            (0..3)
                .map(|c| (f64::from(pixel[c]) - f64::from(exact[c])).abs())
                .sum::<f64>()
        })
        .sum();
    total / (3 * frame.colour.len()) as f64
}

#[test]
fn the_oracle_matches_the_exact_area_of_a_disc_in_a_pixel() {
    // One disc on a black background: a pixel's exact colour is the share of its square the disc
    // covers. The oracle (64×64 rays a pixel) must be within its stated 2.8/n of that share.
    let scene = raytracer::scene::parse_scene(
        "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n\
         Background { color 0 0 0 }\n\
         Materials { numMaterials 1 PhongMaterial { diffuseColor 1 1 1 } }\n\
         Group { numObjects 1 MaterialIndex 0 Sphere { center 0.137 -0.211 0 radius 1.3 } }\n",
    )
    .unwrap();
    let view = View::of_camera(&scene.camera, 16, 16, DepthRange::new(8.0, 12.0));
    let n = 64;
    let oracle = area_average(&scene, &view, n).unwrap();
    let pixel = 4.0 / 16.0;
    let mut edge_pixels = 0;
    for row in 0..16u32 {
        for x in 0..16u32 {
            let y_up = 15 - row;
            let (x0, y0) = (
                (f64::from(x) - 8.0) * pixel,
                (f64::from(y_up) - 8.0) * pixel,
            );
            let share = disc_area_in_square(0.137, -0.211, 1.3, x0, y0, pixel) / (pixel * pixel);
            let got = oracle.colour[(row * 16 + x) as usize].x;
            assert!(
                (got - share).abs() <= 2.8 / f64::from(n),
                "pixel ({x}, {y_up}): oracle {got}, exact {share}"
            );
            edge_pixels += usize::from(share > 0.0 && share < 1.0);
        }
    }
    assert!(
        edge_pixels > 20,
        "the disc's edge crosses pixels: {edge_pixels}"
    );
}

#[test]
fn error_against_the_area_oracle_falls_as_samples_grow() {
    let scene = scene("showcase_torus_knot.txt");
    let view = View::of_camera(&scene.camera, 48, 48, DepthRange::new(5.0, 15.0));
    // The oracle shares no code with the supersampler (area.rs): 64×64 rays a pixel.
    let oracle = area_average(&scene, &view, 64).unwrap();
    for sampler in Sampler::ALL {
        let errors: Vec<f64> = [1, 4, 16, 64, 256]
            .iter()
            .map(|&n| {
                mean_colour_error(
                    &supersampled(&scene, &view, sampler, n, Filter::PIXEL_BOX),
                    &oracle,
                )
            })
            .collect();
        for pair in errors.windows(2) {
            assert!(
                pair[1] < pair[0],
                "{}: errors {errors:?} must fall",
                sampler.name()
            );
        }
        // At 256 samples the supersampler is within a level of the area average on average.
        assert!(errors[4] < 1.0, "{}: {errors:?}", sampler.name());
    }
}

#[test]
fn supersampled_depth_filters_the_greys() {
    let scene = scene("scene1_02.txt");
    let view = view(&scene, 80);
    let one = render(&scene, &view).unwrap();
    let aa = supersampled(
        &scene,
        &view,
        Sampler::Uniform,
        9,
        Filter::Tent { radius: 1.0 },
    );
    let sharp = one.depth_image(view.depth_range);
    let soft = aa.depth_image(view.depth_range);
    assert_ne!(sharp, soft, "edges are softened");
    let differing = sharp
        .pixels()
        .zip(soft.pixels())
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differing < sharp.len() / 3 / 4,
        "only edges change ({differing} pixels)"
    );
    // Another range than the one rendered falls back to the raw centre-sample t.
    let other = DepthRange::new(9.0, 11.0);
    assert_eq!(aa.depth_image(other), one.depth_image(other));
}

#[test]
fn same_settings_same_frame_whatever_the_threads() {
    let scene = scene("showcase_torus_knot.txt");
    let view = View::of_camera(&scene.camera, 97, 61, DepthRange::new(5.0, 15.0));
    let render_on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                supersampled(
                    &scene,
                    &view,
                    Sampler::Random,
                    7,
                    Filter::Gaussian { sigma: 0.6 },
                )
            })
    };
    let a = render_on(1);
    assert!(a == render_on(3), "thread count must not change the frame");
}

#[test]
fn the_same_flags_give_identical_bytes_twice() {
    let folder = tempfile::tempdir().unwrap();
    let input = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_06.txt");
    let mut outputs = Vec::new();
    for run in 0..2 {
        let colour = folder.path().join(format!("c{run}.tga"));
        let depth = folder.path().join(format!("d{run}.png"));
        let status = Command::new(env!("CARGO_BIN_EXE_raytracer"))
            .arg("-input")
            .arg(&input)
            .args([
                "-size",
                "90",
                "70",
                "-jittered_samples",
                "9",
                "-gaussian_filter",
                "0.7",
                "-output",
            ])
            .arg(&colour)
            .args(["-depth", "3", "7"])
            .arg(&depth)
            .status()
            .unwrap();
        assert!(status.success());
        outputs.push((
            std::fs::read(colour).unwrap(),
            std::fs::read(depth).unwrap(),
        ));
    }
    assert!(outputs[0] == outputs[1], "same flags, same bytes");
}

#[test]
fn stats_print_one_name_value_per_line() {
    let input = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/scene1_02.txt");
    let folder = tempfile::tempdir().unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .arg("-input")
        .arg(&input)
        .args([
            "-size",
            "50",
            "40",
            "-uniform_samples",
            "4",
            "-stats",
            "-output",
        ])
        .arg(folder.path().join("c.png"))
        .output()
        .unwrap();
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    for name in [
        "parse_ms",
        "render_ms",
        "write_ms",
        "spheres",
        "width",
        "height",
        "samples_per_pixel",
        "threads",
        "disc_tests",
    ] {
        assert!(
            text.lines()
                .any(|line| line.starts_with(&format!("{name}: "))),
            "{name}: {text}"
        );
    }
    assert!(
        text.contains("spheres: 5\n")
            && text.contains("width: 50\n")
            && text.contains("samples_per_pixel: 4\n")
    );
    let tests: u64 = text
        .lines()
        .find_map(|line| line.strip_prefix("disc_tests: "))
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        tests >= 50 * 40 * 4,
        "every sample is tested against at least one disc: {tests}"
    );
}
