//! The measurements behind `docs/performance.md` and `docs/performance.svg`:
//!
//! ```sh
//! cargo run --release --example performance
//! ```
//!
//! All figures come from this one run (medians of several repetitions), so ratios compare like
//! with like on a shared, noisy machine. Peak memory of the million-sphere case is measured in a
//! child process of its own (`VmHWM` of /proc/self/status).

#[path = "support/timing.rs"]
mod timing;

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

#[cfg(all(feature = "mimalloc", not(target_os = "macos")))]
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use plotters::prelude::*;
use raytracer::explore::initial_depth_range;
use raytracer::oracle::ray_loop::render_reference;
use raytracer::output::{ImageFormat, encode};
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, render};
use raytracer::scene::{Scene, parse_scene};
use raytracer::{oracle::random_scene, scene::scene_to_text};
use timing::median_ms;

fn view_of(scene: &Scene, side: u32) -> View {
    let mut view = View::of_camera(&scene.camera, side, side, DepthRange::new(0.0, 1.0));
    view.depth_range = initial_depth_range(scene, &view);
    view
}

/// The whole command: parse, render, encode a TGA (written to memory; the disk is not measured).
fn whole_command(text: &str, side: u32, oracle: bool) {
    let scene = parse_scene(text).expect("valid scene");
    let view = view_of(&scene, side);
    let frame = if oracle {
        render_reference(&scene, &view)
    } else {
        render(&scene, &view)
    }
    .expect("valid view");
    std::hint::black_box(encode(&frame.colour_image(), ImageFormat::Tga).expect("encodes"));
}

fn peak_memory_mb() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb / 1024.0)
}

/// Child mode: load the scene file at `path` (a million spheres), render it once, print peak
/// memory — what `raytracer -input FILE -size 1024 1024 …` holds at most.
fn million_child(path: &Path) {
    let scene = raytracer::scene::load_scene(path).expect("valid scene");
    let view = view_of(&scene, 1024);
    std::hint::black_box(render(&scene, &view).expect("valid view"));
    println!("{:.1}", peak_memory_mb().unwrap_or(f64::NAN));
}

/// Median time of the viewer's work for a 1024×1024 view of `scene`: what passes between a
/// slider change and a frame ready to upload.
fn viewer_frame_ms(scene: &Scene, runs: usize) -> f64 {
    let job = raytracer::app::render_job::ViewerJob {
        scene: std::sync::Arc::new(scene.clone()),
        view: view_of(scene, 1024),
        scene_epoch: 0,
        quality: Default::default(),
        depth_style: Default::default(),
    };
    median_ms(runs, true, || {
        std::hint::black_box(raytracer::app::render_job::prepare_frame(&job).ok());
    })
}

/// The table of the last window report (`docs/window-frame-times.md`, which
/// `cargo xtask report window-frame-times` writes: it needs Xvfb and xdotool, so it runs apart), as a
/// section of this report: the same views in the real window beside this run's dense rows.
fn in_window_section() -> String {
    let source = "docs/window-frame-times.md";
    let mut section = String::from("\n## In the real window\n\n");
    match std::fs::read_to_string(source) {
        Ok(report) => {
            section.push_str(
                "The same views in the real window, copied from the last run of `cargo xtask report window-frame-times` ([window-frame-times.md](window-frame-times.md), which says how each column is measured; it runs apart, under Xvfb, so its figures come from its own run, not this one; `cargo xtask report sync` copies it again after each run):\n\n<!-- from docs/window-frame-times.md -->\n",
            );
            for line in report.lines().filter(|line| line.starts_with('|')) {
                section.push_str(line);
                section.push('\n');
            }
        }
        Err(error) => {
            let _ = writeln!(
                section,
                "No window report to copy ({source}: {error}); `cargo xtask report window-frame-times` makes one."
            );
        }
    }
    section
}

struct Course {
    name: String,
    /// The viewer's work for a 1024×1024 view (render, textures, histogram).
    viewer_ms: f64,
    render_ms: f64,
    oracle_ms: f64,
    command_ms: f64,
    oracle_command_ms: f64,
}

/// A dense scene at 1024×1024 (`raytracer::oracle::dense_scene`).
struct Dense {
    count: usize,
    /// Discs over a pixel on average (their areas in pixels, summed, over the pixels).
    depth_complexity: f64,
    /// Pixel–disc tests the render made per pixel.
    tests_per_pixel: f64,
    render_ms: f64,
    viewer_ms: f64,
}

/// The dense scenes' figures.
fn dense(count: usize) -> Dense {
    let scene = raytracer::oracle::dense_scene(7, count);
    let view = view_of(&scene, 1024);
    let pixel = view.size_world / 1024.0;
    let depth_complexity = scene
        .spheres
        .iter()
        .map(|s| std::f64::consts::PI * (s.radius_world / pixel).powi(2))
        .sum::<f64>()
        / (1024.0 * 1024.0);
    let runs = if count >= 1_000_000 { 5 } else { 11 };
    let tests = render(&scene, &view).map_or(0, |frame| frame.disc_tests());
    Dense {
        count,
        depth_complexity,
        tests_per_pixel: tests as f64 / (1024.0 * 1024.0),
        render_ms: median_ms(runs, true, || {
            std::hint::black_box(render(&scene, &view).ok());
        }),
        viewer_ms: viewer_frame_ms(&scene, runs),
    }
}

struct Generated {
    count: usize,
    megabytes: f64,
    parse_ms: f64,
    render_ms: f64,
    brute_ms: Option<f64>,
    viewer_ms: f64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let arguments: Vec<String> = std::env::args().collect();
    if let [_, flag, path] = arguments.as_slice()
        && flag == "--million-child"
    {
        million_child(Path::new(path));
        return Ok(());
    }
    let mut course = Vec::new();
    for n in 1..=7 {
        let text = std::fs::read_to_string(format!("scenes/scene1_0{n}.txt"))?;
        let scene = parse_scene(&text)?;
        let view = view_of(&scene, 2000);
        let entry = Course {
            name: format!("scene1_0{n}"),
            viewer_ms: viewer_frame_ms(&scene, 15),
            render_ms: median_ms(15, true, || {
                std::hint::black_box(render(&scene, &view).ok());
            }),
            oracle_ms: median_ms(3, true, || {
                std::hint::black_box(render_reference(&scene, &view).ok());
            }),
            command_ms: median_ms(9, true, || whole_command(&text, 2000, false)),
            oracle_command_ms: median_ms(3, true, || whole_command(&text, 2000, true)),
        };
        eprintln!(
            "{}: {:.2} ms render, {:.0} ms oracle",
            entry.name, entry.render_ms, entry.oracle_ms
        );
        course.push(entry);
    }

    let mut generated = Vec::new();
    for count in [10usize, 1_000, 100_000, 1_000_000] {
        let text = scene_to_text(&random_scene(1, count));
        let runs = if count >= 100_000 { 3 } else { 9 };
        let parse_ms = median_ms(runs, true, || {
            std::hint::black_box(parse_scene(&text).ok());
        });
        let scene = parse_scene(&text)?;
        let view = view_of(&scene, 1024);
        let render_ms = median_ms(runs, true, || {
            std::hint::black_box(render(&scene, &view).ok());
        });
        let brute_ms = (count <= 1_000).then(|| {
            median_ms(1, true, || {
                std::hint::black_box(render_reference(&scene, &view).ok());
            })
        });
        let viewer_ms = viewer_frame_ms(&scene, runs);
        eprintln!("{count}: parse {parse_ms:.1} ms, render {render_ms:.2} ms");
        generated.push(Generated {
            count,
            megabytes: text.len() as f64 / 1e6,
            parse_ms,
            render_ms,
            brute_ms,
            viewer_ms,
        });
    }
    let dense: Vec<Dense> = [100_000, 1_000_000]
        .into_iter()
        .map(|count| {
            let figures = dense(count);
            eprintln!("dense {count}: render {:.1} ms", figures.render_ms);
            figures
        })
        .collect();
    let million_file = tempfile::NamedTempFile::new()?;
    std::fs::write(
        million_file.path(),
        scene_to_text(&random_scene(1, 1_000_000)),
    )?;
    let own = std::env::current_exe()?;
    let child = Command::new(own)
        .arg("--million-child")
        .arg(million_file.path())
        .output()?;
    let peak_mb: f64 = String::from_utf8_lossy(&child.stdout)
        .trim()
        .parse()
        .unwrap_or(f64::NAN);

    write_plot(&generated, Path::new("docs/performance.svg"))?;
    std::fs::write(
        "docs/performance.md",
        report(&course, &generated, &dense, peak_mb),
    )?;
    eprintln!("wrote docs/performance.md and docs/performance.svg");
    Ok(())
}

fn report(course: &[Course], generated: &[Generated], dense: &[Dense], peak_mb: f64) -> String {
    let mut md = String::new();
    let threads = rayon::current_num_threads();
    let _ = writeln!(md, "# Performance\n");
    let _ = writeln!(
        md,
        "Generated by `cargo run --release --example performance` (do not edit by hand): medians of \
         repeated runs, all in one run, {threads} worker threads. The machine is shared and noisy; \
         compare ratios within a table. The criterion benchmarks (`cargo bench`) measure the same \
         workloads with confidence intervals.\n"
    );
    let _ = writeln!(md, "## Targets\n");
    let _ = writeln!(md, "| target | measured | met |\n|---|---|---|");
    let million = generated.iter().find(|g| g.count == 1_000_000);
    let slowest_course = course.iter().map(|c| c.render_ms).fold(0.0, f64::max);
    let least_speed_up = course
        .iter()
        .map(|c| c.oracle_command_ms / c.command_ms)
        .fold(f64::INFINITY, f64::min);
    let slowest_viewer = generated
        .iter()
        .filter(|g| g.count <= 100_000)
        .map(|g| g.viewer_ms)
        .chain(course.iter().map(|c| c.viewer_ms))
        .fold(0.0, f64::max);
    let dense_viewer = |count| {
        dense
            .iter()
            .find(|d| d.count == count)
            .map_or(f64::NAN, |d| d.viewer_ms)
    };
    let rows: [(&str, f64, &str, bool); 8] = [
        (
            "1,000,000 spheres: parse ≤ 250 ms",
            million.map_or(f64::NAN, |g| g.parse_ms),
            "ms",
            million.is_some_and(|g| g.parse_ms <= 250.0),
        ),
        (
            "dense 100,000 spheres: viewer frame 1024×1024 ≤ 16 ms",
            dense_viewer(100_000),
            "ms",
            dense_viewer(100_000) <= 16.0,
        ),
        (
            "dense 1,000,000 spheres: viewer frame 1024×1024 ≤ 50 ms",
            dense_viewer(1_000_000),
            "ms",
            dense_viewer(1_000_000) <= 50.0,
        ),
        (
            "1,000,000 spheres: render 1024×1024 ≤ 50 ms",
            million.map_or(f64::NAN, |g| g.render_ms),
            "ms",
            million.is_some_and(|g| g.render_ms <= 50.0),
        ),
        (
            "1,000,000 spheres: peak memory ≤ 300 MB",
            peak_mb,
            "MB",
            peak_mb <= 300.0,
        ),
        (
            "course scenes at 2000×2000: render ≤ 4 ms (slowest scene)",
            slowest_course,
            "ms",
            slowest_course <= 4.0,
        ),
        (
            "course scenes: whole command ≥ 20× the straightforward loop (least speed-up)",
            least_speed_up,
            "×",
            least_speed_up >= 20.0,
        ),
        (
            "viewer: ≤ 16 ms per 1024×1024 frame, course scenes and up to 100,000 spheres (slowest)",
            slowest_viewer,
            "ms",
            slowest_viewer <= 16.0,
        ),
    ];
    for (target, value, unit, met) in rows {
        let _ = writeln!(
            md,
            "| {target} | {value:.1} {unit} | {} |",
            if met { "yes" } else { "**no**" }
        );
    }
    let _ = writeln!(md);
    let _ = writeln!(md, "## Course scenes at 2000×2000\n");
    let _ = writeln!(
        md,
        "*render*: the disc renderer, all cores. *oracle*: the straightforward loop — one ray per pixel against every sphere, one thread. *command*: parse + render + encode the TGA (in memory).\n"
    );
    let _ = writeln!(
        md,
        "| scene | render ms | oracle ms | render speed-up | command ms | oracle command ms | command speed-up | viewer frame 1024² ms |\n|---|---|---|---|---|---|---|---|"
    );
    for c in course {
        let _ = writeln!(
            md,
            "| {} | {:.2} | {:.0} | {:.1}× | {:.2} | {:.0} | {:.1}× | {:.2} |",
            c.name,
            c.render_ms,
            c.oracle_ms,
            c.oracle_ms / c.render_ms,
            c.command_ms,
            c.oracle_command_ms,
            c.oracle_command_ms / c.command_ms,
            c.viewer_ms
        );
    }
    let _ = writeln!(md, "\n## Dense scenes at 1024×1024\n");
    let _ = writeln!(
        md,
        "`raytracer::oracle::dense_scene`: spheres of radius 0.2 to 1.0 in a 100-unit cube, seen whole (`generate --dense N FILE` writes the file). *discs per pixel*: the discs' areas summed over the image's, how many discs lie over a pixel on average; *tests per pixel*: the pixel–disc tests the exact render made — the discs drawn front to back, hidden ones skipped. *viewer*: render, both textures and the histogram.\n"
    );
    let _ = writeln!(
        md,
        "| spheres | discs per pixel | tests per pixel | render ms | viewer frame ms |\n|---|---|---|---|---|"
    );
    for d in dense {
        let _ = writeln!(
            md,
            "| {} | {:.1} | {:.1} | {:.1} | {:.1} |",
            d.count, d.depth_complexity, d.tests_per_pixel, d.render_ms, d.viewer_ms
        );
    }
    let _ = writeln!(
        md,
        "\nThe whole command against a plain C++ ray caster: [command-vs-cpp.md](command-vs-cpp.md).\n"
    );
    md.push_str(&in_window_section());
    let _ = writeln!(md, "\n## Generated scenes at 1024×1024\n");
    let _ = writeln!(
        md,
        "Seeded scenes of `raytracer::oracle::random_scene` (`cargo run --release --example generate -- N FILE`). *viewer*: render + both textures, the viewer's work per frame.\n"
    );
    let _ = writeln!(
        md,
        "| spheres | text MB | parse ms | parse MB/s | render ms | brute force ms | viewer frame ms |\n|---|---|---|---|---|---|---|"
    );
    for g in generated {
        let _ = writeln!(
            md,
            "| {} | {:.2} | {:.1} | {:.0} | {:.2} | {} | {:.2} |",
            g.count,
            g.megabytes,
            g.parse_ms,
            g.megabytes / (g.parse_ms / 1e3),
            g.render_ms,
            g.brute_ms.map_or("—".to_owned(), |ms| format!("{ms:.0}")),
            g.viewer_ms
        );
    }
    let _ = writeln!(
        md,
        "\nPeak memory of loading a scene file of 1,000,000 spheres and rendering it at 1024×1024 (file text, scene, discs, bins, frame; a process of its own, `VmHWM`): **{peak_mb:.0} MB**.\n"
    );
    let _ = writeln!(md, "![render time against sphere count](performance.svg)");
    md
}

/// A plotted line: name, colour, (sphere count, ms) points.
type Series<'a> = (&'a str, RGBColor, Vec<(f64, f64)>);

fn write_plot(generated: &[Generated], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (800, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let t_max = generated
        .iter()
        .flat_map(|g| [g.render_ms, g.brute_ms.unwrap_or(0.0), g.parse_ms])
        .fold(1.0, f64::max);
    let t_min = generated
        .iter()
        .map(|g| g.render_ms.min(g.parse_ms))
        .fold(f64::INFINITY, f64::min);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "1024×1024 frame time against sphere count",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (5.0..2e6f64).log_scale(),
            (t_min * 0.5..t_max * 2.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("spheres (log)")
        .y_desc("milliseconds (log)")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    let series: [Series; 3] = [
        (
            "render (binned discs, all cores)",
            RGBColor(40, 170, 80),
            generated
                .iter()
                .map(|g| (g.count as f64, g.render_ms))
                .collect(),
        ),
        (
            "brute force (every sphere per pixel, one thread)",
            RGBColor(200, 40, 40),
            generated
                .iter()
                .filter_map(|g| g.brute_ms.map(|b| (g.count as f64, b)))
                .collect(),
        ),
        (
            "parse",
            RGBColor(30, 110, 220),
            generated
                .iter()
                .map(|g| (g.count as f64, g.parse_ms))
                .collect(),
        ),
    ];
    for (label, colour, points) in series {
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
            .label(label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2))
            });
        chart.draw_series(
            points
                .into_iter()
                .map(|p| Circle::new(p, 4, colour.filled())),
        )?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
