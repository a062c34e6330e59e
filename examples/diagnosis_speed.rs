//! How long a user waits for the diagnosis: the whole command
//! (`raytracer -input … -compare_output … -compare_depth … …`, a new process each time: load,
//! render the exact images, fit the model, say it) on real students' images and on images with
//! known mistakes at 200² and 1024² (both images, or one), and on random scenes of 1,000 to
//! 1,000,000 spheres (a model is fitted to scenes of up to `MAX_FITTED_SPHERES`), the median of
//! RUNS runs. Writes `docs/diagnosis-speed.md`.
//! Needs the release binary beside this example (`cargo build --release` first):
//!
//! ```sh
//! cargo build --release && cargo run --release --example diagnosis_speed [-- RUNS]
//! ```

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use raytracer::compare::diagnosis::MAX_FITTED_SPHERES;
use raytracer::compare::{Mistake, MistakeSet};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;

/// One comparison timed: what it is, the scene, their two images and the range asked for.
struct Case {
    what: String,
    scene: PathBuf,
    colour: Option<PathBuf>,
    depth: Option<PathBuf>,
    range: (f64, f64),
    size_px: u32,
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The release binary beside this example (`target/release/raytracer`).
fn binary() -> PathBuf {
    let example = std::env::current_exe().expect("the example's path");
    let binary = example
        .parent()
        .and_then(Path::parent)
        .expect("target/release")
        .join(format!("raytracer{}", std::env::consts::EXE_SUFFIX));
    assert!(
        binary.exists(),
        "{} is missing: run `cargo build --release` first",
        binary.display()
    );
    binary
}

/// A case whose images are a real program's, from `tests/corpus/`.
fn corpus_case(program: &str, number: &str, range: (f64, f64), what: &str) -> Case {
    let folder = root().join("tests/corpus").join(program);
    Case {
        what: format!("{what} (`tests/corpus/{program}`, scene1_{number})"),
        scene: root().join(match number {
            "03" => "scenes/scene1_03.txt",
            _ => "scenes/scene1_05.txt",
        }),
        colour: Some(folder.join(format!("output1_{number}.png"))),
        depth: Some(folder.join(format!("depth1_{number}.png"))),
        range,
        size_px: 200,
    }
}

/// A case whose images the project's variant renderer makes with `mistakes`.
fn made_case(
    folder: &Path,
    scene_name: &'static str,
    size_px: u32,
    range: (f64, f64),
    mistakes: &[Mistake],
) -> Case {
    let scene = raytracer::scene::load_scene(&root().join(format!("scenes/{scene_name}.txt")))
        .expect("the scene loads");
    let view = View::of_camera(
        &scene.camera,
        size_px,
        size_px,
        DepthRange::new(range.0, range.1),
    );
    let set = MistakeSet::of(mistakes);
    let (colour, depth) = render_variant(&scene, &view, set);
    let stem = format!(
        "{scene_name}-{size_px}-{}",
        set.to_string().replace(" + ", "-")
    );
    let colour_path = folder.join(format!("{stem}.png"));
    let depth_path = folder.join(format!("{stem}-depth.png"));
    colour.save(&colour_path).expect("writes the colour image");
    depth.save(&depth_path).expect("writes the depth image");
    Case {
        what: format!("known mistakes: {set} ({scene_name})"),
        scene: root().join(format!("scenes/{scene_name}.txt")),
        colour: Some(colour_path),
        depth: Some(depth_path),
        range,
        size_px,
    }
}

/// A case on a seeded random scene of `count` spheres (`raytracer::oracle::random_scene`, the
/// benchmarks' workload) at 200², its images made by the variant renderer with `mistakes`, its
/// depth range the exact image's nearest to farthest hit.
fn large_case(folder: &Path, count: usize, mistakes: &[Mistake]) -> Case {
    let scene = raytracer::oracle::random_scene(1, count);
    let scene_path = folder.join(format!("random-{count}.txt"));
    if !scene_path.exists() {
        std::fs::write(&scene_path, raytracer::scene::scene_to_text(&scene))
            .expect("writes the scene");
    }
    let wide = View::of_camera(&scene.camera, 200, 200, DepthRange::new(0.0, 1.0));
    let exact = raytracer::render::render(&scene, &wide).expect("renders");
    let (near, far) = exact
        .t
        .iter()
        .filter(|t| t.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    let range = (near.floor(), far.ceil());
    let view = View {
        depth_range: DepthRange::new(range.0, range.1),
        ..wide
    };
    let set = MistakeSet::of(mistakes);
    let (colour, depth) = render_variant(&scene, &view, set);
    let stem = format!("random-{count}-{}", set.to_string().replace(" + ", "-"));
    let colour_path = folder.join(format!("{stem}.png"));
    let depth_path = folder.join(format!("{stem}-depth.png"));
    colour.save(&colour_path).expect("writes the colour image");
    depth.save(&depth_path).expect("writes the depth image");
    Case {
        what: format!("known mistakes: {set} (a random scene of {count} spheres)"),
        scene: scene_path,
        colour: Some(colour_path),
        depth: Some(depth_path),
        range,
        size_px: 200,
    }
}

/// The slowest single image: a depth image alone that no model of a ray caster draws (grey
/// noise from a fixed seed, scene1_04 at 200²), which the fit tries from every start and named
/// point (`compare/fit/restart.rs`) before it says so.
fn noise_case(folder: &Path) -> Case {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let noise = image::RgbImage::from_fn(200, 200, |_, _| {
        // xorshift64: the same picture every run.
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let grey = (state >> 56) as u8;
        image::Rgb([grey; 3])
    });
    let path = folder.join("noise-depth.png");
    noise.save(&path).expect("writes the noise image");
    Case {
        what: "a depth image that no model draws (seeded grey noise, scene1_04), depth image only"
            .to_owned(),
        scene: root().join("scenes/scene1_04.txt"),
        colour: None,
        depth: Some(path),
        range: (12.0, 17.0),
        size_px: 200,
    }
}

/// `case` with only its colour image, or only its depth image.
fn only(case: &Case, colour: bool) -> Case {
    Case {
        what: format!(
            "{}, {} image only",
            case.what,
            if colour { "colour" } else { "depth" }
        ),
        scene: case.scene.clone(),
        colour: case.colour.clone().filter(|_| colour),
        depth: case.depth.clone().filter(|_| !colour),
        range: case.range,
        size_px: case.size_px,
    }
}

/// Runs the command once: its seconds and the `diagnosis` lines it printed.
fn run_once(binary: &Path, case: &Case) -> (f64, Vec<String>) {
    let mut command = Command::new(binary);
    command.arg("-input").arg(&case.scene);
    if let Some(colour) = &case.colour {
        command.arg("-compare_output").arg(colour);
    }
    if let Some(depth) = &case.depth {
        command
            .arg("-compare_depth")
            .arg(case.range.0.to_string())
            .arg(case.range.1.to_string())
            .arg(depth);
    }
    let start = Instant::now();
    let output = command.output().expect("the binary runs");
    let seconds = start.elapsed().as_secs_f64();
    assert_eq!(
        output.status.code(),
        Some(3),
        "{}: {}",
        case.what,
        String::from_utf8_lossy(&output.stderr)
    );
    let said = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter(|line| line.starts_with("diagnosis"))
        .map(|line| {
            // The name and values, without the sentence.
            let mut parts = line.splitn(3, ": ");
            let kind = parts.next().unwrap_or_default();
            let name = parts.next().unwrap_or_default();
            // "none (no model fitted: …)": the reason in short.
            let name = if name.starts_with("none (no model fitted") {
                "none (no model fitted: too many spheres)"
            } else {
                name
            };
            format!("{kind}: {name}")
        })
        .collect();
    (seconds, said)
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map_or(3, |r| r.parse().expect("RUNS: a whole number"));
    let binary = binary();
    let folder = tempfile::tempdir().expect("a temporary folder");
    let raw_up = made_case(
        folder.path(),
        "scene1_05",
        1024,
        (14.5, 19.5),
        &[Mistake::RawUp, Mistake::DepthReversed],
    );
    let cases = [
        corpus_case(
            "moonlightcc",
            "05",
            (14.5, 19.5),
            "a real program: camera vectors not unit, depth per image",
        ),
        corpus_case(
            "n2man",
            "03",
            (8.0, 12.0),
            "a real program: pixel corners, a zoom",
        ),
        made_case(
            folder.path(),
            "scene1_02",
            200,
            (8.0, 12.0),
            &[Mistake::PixelCorners, Mistake::DepthReversed],
        ),
        only(&raw_up, true),
        only(&raw_up, false),
        made_case(
            folder.path(),
            "scene1_02",
            1024,
            (8.0, 12.0),
            &[Mistake::PixelCorners, Mistake::Mirrored],
        ),
        raw_up,
        noise_case(folder.path()),
    ]
    .into_iter()
    .chain(
        [
            1_000,
            10_000,
            MAX_FITTED_SPHERES,
            MAX_FITTED_SPHERES + 1,
            1_000_000,
        ]
        .into_iter()
        .flat_map(|count| {
            [
                large_case(
                    folder.path(),
                    count,
                    &[Mistake::PixelCorners, Mistake::Mirrored],
                ),
                large_case(
                    folder.path(),
                    count,
                    &[Mistake::FlippedVertically, Mistake::DepthReversed],
                ),
            ]
        }),
    )
    .collect::<Vec<_>>();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let mut table = String::new();
    let _ = writeln!(
        table,
        "| their images | size | whole command, median of {runs} (s) | what it said |"
    );
    let _ = writeln!(table, "|---|---|---|---|");
    for case in &cases {
        let mut seconds = Vec::new();
        let mut said = Vec::new();
        for _ in 0..runs {
            let (s, lines) = run_once(&binary, case);
            seconds.push(s);
            said = lines;
        }
        seconds.sort_by(f64::total_cmp);
        let median = seconds[seconds.len() / 2];
        println!("{}: {median:.2} s: {said:?}", case.what);
        let _ = writeln!(
            table,
            "| {} | {}² | {median:.2} | {} |",
            case.what,
            case.size_px,
            said.join("<br>")
        );
    }
    let text = format!(
        "# How long the diagnosis takes\n\n\
         The whole command a user runs, a new process each time (load the scene, render the \
         exact colour and depth images, compare, fit the model of their program, say it), on \
         colour and depth images together unless a row says one, on a machine with {threads} \
         hardware threads. \
         Generated by `cargo build --release && cargo run --release --example diagnosis_speed` \
         (`examples/diagnosis_speed.rs`); the images with known mistakes are made by the \
         project's variant renderer. A model of their program is fitted to scenes of up to \
         {MAX_FITTED_SPHERES} spheres; on a larger one the command compares the pixels and says \
         why it says nothing more (`diagnosis: none (no model fitted: …)`), the rows of 20,001 \
         and 1,000,000 spheres.\n\n{table}"
    );
    let path = root().join("docs/diagnosis-speed.md");
    std::fs::write(&path, text).expect("writes docs/diagnosis-speed.md");
    println!("wrote {}", path.display());
}
