//! The speed/accuracy trade-off behind `docs/tradeoff.md` and `docs/tradeoff.svg`:
//!
//! ```sh
//! cargo run --release --example tradeoff
//! ```
//!
//! Renders a few scenes at every setting — samples 1…256, each sampler and filter,
//! and reduced-resolution previews — measures the time (median of several runs, all in
//! this one run) and the error against the area-average oracle (`raytracer::oracle::area`: 32×32
//! rays a pixel through the careful ray–sphere routine, sharing no code with the supersampler),
//! and marks the Pareto front.

#[path = "support/timing.rs"]
mod timing;

use std::fmt::Write as _;
use std::path::Path;

use plotters::prelude::*;
use raytracer::explore::initial_depth_range;
use raytracer::oracle::area::{AreaAverage, area_average};
use raytracer::oracle::random_scene;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Filter, Frame, Quality, Sampler, Sampling, View, render_with};
use raytracer::scene::{Scene, load_scene};
use timing::median_ms;

/// Side of the study images, pixels.
const SIDE_PX: u32 = 256;

/// Runs timed per setting (the median is reported).
const RUNS: usize = 5;

#[derive(Clone, Debug)]
struct Setting {
    name: String,
    quality: Quality,
    /// Render at 1/scale of the resolution and enlarge (nearest pixel): a preview.
    preview_scale: u32,
}

fn settings() -> Vec<Setting> {
    let mut all = Vec::new();
    let plain = |name: &str| Setting {
        name: name.into(),
        quality: Quality { sampling: None },
        preview_scale: 1,
    };
    all.push(plain("1 sample (exact)"));
    for scale in [2, 4] {
        all.push(Setting {
            name: format!("preview 1/{scale} resolution"),
            preview_scale: scale,
            ..plain("")
        });
    }
    let filters = [
        Filter::Box { radius: 0.5 },
        Filter::Tent { radius: 1.0 },
        Filter::Gaussian { sigma: 0.5 },
    ];
    for samples in [4, 16, 64, 256] {
        for sampler in Sampler::ALL {
            for filter in filters {
                all.push(Setting {
                    name: format!("{samples} {}, {filter}", sampler.name()),
                    quality: Quality {
                        sampling: Some(Sampling {
                            sampler,
                            samples,
                            filter,
                            seed: 0,
                        }),
                    },
                    preview_scale: 1,
                });
            }
        }
    }
    all
}

#[derive(Clone, Debug)]
struct Measured {
    setting: Setting,
    time_ms: f64,
    mean_error: f64,
    max_error: f64,
    wrong_fraction: f64,
    depth_error: f64,
    pareto: bool,
}

fn render_setting(scene: &Scene, view: &View, setting: &Setting) -> Frame {
    if setting.preview_scale == 1 {
        return render_with(scene, view, &setting.quality).expect("valid view");
    }
    let small = View {
        width_px: view.width_px / setting.preview_scale,
        height_px: view.height_px / setting.preview_scale,
        ..*view
    };
    let low = render_with(scene, &small, &setting.quality).expect("valid view");
    // Enlarge to full size, nearest pixel.
    let mut frame = low.clone();
    frame.width_px = view.width_px;
    frame.height_px = view.height_px;
    let pick = |x: u32, y: u32| {
        let sx = (x / setting.preview_scale).min(small.width_px - 1);
        let sy = (y / setting.preview_scale).min(small.height_px - 1);
        (sy * small.width_px + sx) as usize
    };
    let pixels = (0..view.height_px).flat_map(|y| (0..view.width_px).map(move |x| (x, y)));
    let indices: Vec<usize> = pixels.map(|(x, y)| pick(x, y)).collect();
    frame.colour = indices.iter().map(|&i| low.colour[i]).collect();
    frame.t = indices.iter().map(|&i| low.t[i]).collect();
    frame.sphere = indices.iter().map(|&i| low.sphere[i]).collect();
    frame.depth_grey = low
        .depth_grey
        .as_ref()
        .map(|(range, grey)| (*range, indices.iter().map(|&i| grey[i]).collect()));
    frame
}

/// Rays per pixel side of the area-average oracle.
const ORACLE_GRID: u32 = 32;

fn measure(scene: &Scene, view: &View, reference: &AreaAverage, setting: &Setting) -> Measured {
    let frame = render_setting(scene, view, setting);
    let time_ms = median_ms(RUNS, false, || {
        std::hint::black_box(render_setting(scene, view, setting));
    });
    let (mut sum, mut max, mut wrong) = (0f64, 0f64, 0usize);
    for (index, a) in frame.colour.iter().enumerate() {
        let b = reference.colour_u8(index);
        let errors = (0..3).map(|c| (f64::from(a[c]) - f64::from(b[c])).abs());
        let pixel_max = errors.clone().fold(0.0, f64::max);
        sum += errors.sum::<f64>() / 3.0;
        max = max.max(pixel_max);
        wrong += usize::from(pixel_max > 8.0);
    }
    let ours = frame.depth_image(view.depth_range);
    let depth_error = ours
        .pixels()
        .zip(&reference.grey)
        .map(|(a, grey)| (f64::from(a[0]) - (grey * 255.0).floor().clamp(0.0, 255.0)).abs())
        .sum::<f64>()
        / ours.pixels().len() as f64;
    let n = frame.colour.len() as f64;
    Measured {
        setting: setting.clone(),
        time_ms,
        mean_error: sum / n,
        max_error: max,
        wrong_fraction: wrong as f64 / n,
        depth_error,
        pareto: false,
    }
}

/// Marks the points that no other point beats on both time and mean error.
fn mark_pareto(points: &mut [Measured]) {
    for i in 0..points.len() {
        let dominated = points.iter().enumerate().any(|(j, other)| {
            j != i
                && other.time_ms <= points[i].time_ms
                && other.mean_error <= points[i].mean_error
                && (other.time_ms < points[i].time_ms || other.mean_error < points[i].mean_error)
        });
        points[i].pareto = !dominated;
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scenes: Vec<(String, Scene)> = vec![
        (
            "scene1_02".into(),
            load_scene(Path::new("scenes/scene1_02.txt"))?,
        ),
        (
            "scene1_06".into(),
            load_scene(Path::new("scenes/scene1_06.txt"))?,
        ),
        (
            "torus knot (400)".into(),
            load_scene(Path::new("scenes/showcase_torus_knot.txt"))?,
        ),
        ("random (10,000)".into(), random_scene(2, 10_000)),
    ];
    let settings = settings();
    let mut results: Vec<(String, Vec<Measured>)> = Vec::new();
    for (name, scene) in &scenes {
        let mut view = View::of_camera(&scene.camera, SIDE_PX, SIDE_PX, DepthRange::new(0.0, 1.0));
        view.depth_range = initial_depth_range(scene, &view);
        let reference = area_average(scene, &view, ORACLE_GRID)?;
        let mut measured: Vec<Measured> = settings
            .iter()
            .map(|setting| {
                let m = measure(scene, &view, &reference, setting);
                eprintln!(
                    "{name}: {} {:.2} ms, error {:.3}",
                    m.setting.name, m.time_ms, m.mean_error
                );
                m
            })
            .collect();
        mark_pareto(&mut measured);
        results.push((name.clone(), measured));
    }
    write_plot(&results, Path::new("docs/tradeoff.svg"))?;
    std::fs::write("docs/tradeoff.md", report(&results))?;
    eprintln!("wrote docs/tradeoff.md and docs/tradeoff.svg");
    Ok(())
}

fn report(results: &[(String, Vec<Measured>)]) -> String {
    let mut md = String::new();
    let _ = writeln!(md, "# Speed against accuracy\n");
    let _ = writeln!(
        md,
        "Generated by `cargo run --release --example tradeoff` (do not edit by hand). Each scene is \
         rendered at {SIDE_PX}×{SIDE_PX} with every setting; time is the median of {RUNS} renders, all \
         cores, in one run on one machine. Errors are against each pixel's area average \
         (`raytracer::oracle::area`: {ORACLE_GRID}×{ORACLE_GRID} rays a pixel through the careful \
         ray–sphere routine, sharing no code with the supersampler), quantised to 8 bits:\n"
    );
    let _ = writeln!(
        md,
        "* **mean / max error** — colour error in 8-bit levels, mean over pixels and channels / largest;"
    );
    let _ = writeln!(
        md,
        "* **wrong** — pixels off by more than 8 levels in some channel;"
    );
    let _ = writeln!(
        md,
        "* **depth** — mean error of the 8-bit depth image in grey levels;"
    );
    let _ = writeln!(
        md,
        "* **front** — on the Pareto front (no other setting is both faster and more accurate).\n"
    );
    let _ = writeln!(md, "![time against error](tradeoff.svg)\n");
    highlights(&mut md, results);
    for (name, measured) in results {
        let _ = writeln!(md, "## {name}\n");
        let _ = writeln!(
            md,
            "| setting | ms | mean error | max error | wrong | depth | front |\n|---|---|---|---|---|---|---|"
        );
        let mut sorted = measured.clone();
        sorted.sort_by(|a, b| a.time_ms.total_cmp(&b.time_ms));
        for m in sorted {
            let _ = writeln!(
                md,
                "| {} | {:.2} | {:.3} | {:.0} | {:.2}% | {:.3} | {} |",
                m.setting.name,
                m.time_ms,
                m.mean_error,
                m.max_error,
                100.0 * m.wrong_fraction,
                m.depth_error,
                if m.pareto { "●" } else { "" }
            );
        }
        let _ = writeln!(md);
    }
    md
}

fn write_plot(
    results: &[(String, Vec<Measured>)],
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, 2));
    for (panel, (name, measured)) in panels.iter().zip(results) {
        let (t_low, t_high) = measured.iter().fold((f64::INFINITY, 0f64), |(lo, hi), m| {
            (lo.min(m.time_ms), hi.max(m.time_ms))
        });
        let (e_low, e_high) = measured.iter().fold((f64::INFINITY, 0f64), |(lo, hi), m| {
            (lo.min(m.mean_error), hi.max(m.mean_error))
        });
        let mut chart = ChartBuilder::on(panel)
            .caption(name, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(
                (t_low * 0.8..t_high * 1.25).log_scale(),
                (e_low.max(1e-3) * 0.8..e_high * 1.25).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("time (ms, log)")
            .y_desc("mean colour error (levels, log)")
            .draw()?;
        let colour_of = |m: &Measured| match &m.setting.quality.sampling {
            None if m.setting.preview_scale > 1 => RGBColor(150, 150, 150),
            None => RGBColor(30, 30, 30),
            Some(s) => match s.sampler {
                Sampler::Uniform => RGBColor(30, 110, 220),
                Sampler::Jittered => RGBColor(40, 170, 80),
                Sampler::Random => RGBColor(230, 120, 20),
            },
        };
        chart.draw_series(measured.iter().map(|m| {
            Circle::new(
                (m.time_ms, m.mean_error.max(1e-3)),
                4,
                colour_of(m).filled(),
            )
        }))?;
        let mut front: Vec<&Measured> = measured.iter().filter(|m| m.pareto).collect();
        front.sort_by(|a, b| a.time_ms.total_cmp(&b.time_ms));
        chart
            .draw_series(LineSeries::new(
                front.iter().map(|m| (m.time_ms, m.mean_error.max(1e-3))),
                BLACK.stroke_width(1),
            ))?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLACK.stroke_width(1)));
        for (label, colour) in [
            ("1 sample", RGBColor(30, 30, 30)),
            ("preview (lower resolution)", RGBColor(150, 150, 150)),
            ("uniform", RGBColor(30, 110, 220)),
            ("jittered", RGBColor(40, 170, 80)),
            ("random", RGBColor(230, 120, 20)),
        ] {
            chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
                .label(label)
                .legend(move |(x, y)| Circle::new((x + 9, y), 4, colour.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// The settings the README quotes, for the first course scene and the random scene: ms, mean
/// error and the share of wrong pixels.
fn highlights(md: &mut String, results: &[(String, Vec<Measured>)]) {
    const SETTINGS: [&str; 6] = [
        "1 sample (exact)",
        "preview 1/2 resolution",
        "4 uniform, box 0.5",
        "16 uniform, box 0.5",
        "64 uniform, box 0.5",
        "256 uniform, box 0.5",
    ];
    let scenes: Vec<&(String, Vec<Measured>)> = results
        .iter()
        .filter(|(name, _)| name == "scene1_02" || name.starts_with("random"))
        .collect();
    let _ = writeln!(md, "## Highlights\n");
    let mut header = "| setting |".to_owned();
    for (name, _) in &scenes {
        let _ = write!(header, " {name} ms | mean error | wrong |");
    }
    let _ = writeln!(md, "{header}\n|---|{}", "---|---|---|".repeat(scenes.len()));
    for setting in SETTINGS {
        let mut row = format!("| {setting} |");
        for (_, measured) in &scenes {
            match measured.iter().find(|m| m.setting.name == setting) {
                Some(m) => {
                    let _ = write!(
                        row,
                        " {:.2} | {:.3} | {:.2}% |",
                        m.time_ms,
                        m.mean_error,
                        100.0 * m.wrong_fraction
                    );
                }
                None => row.push_str(" — | — | — |"),
            }
        }
        let _ = writeln!(md, "{row}");
    }
    let _ = writeln!(md);
}
