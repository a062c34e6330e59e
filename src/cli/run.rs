//! Headless rendering for the command line: read the scene, render, write the requested images.

use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use crate::cli::RenderRequest;
use crate::cli::progress::StepProgress;
use crate::output::WriteError;
use crate::output::depth_file::check_writable_raw;
use crate::output::depth_file::{write_depth_png16, write_raw_depth};
use crate::output::image_file::{check_writable, write_image};
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::{View, ViewError, render_with_progress};
use crate::scene::{LoadError, Scene, load_scene_with_progress};

/// Why a headless render failed (the program exits with status 1).
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The scene could not be read.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// The view cannot be rendered.
    #[error(transparent)]
    View(#[from] ViewError),
    /// An image could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
}

/// What a headless render did, with its timings.
#[derive(Debug, Clone, PartialEq)]
pub struct RunReport {
    /// Spheres in the scene.
    pub(crate) sphere_count: usize,
    /// Time to read and parse the scene.
    pub(crate) parse: Duration,
    /// Time to render the frame.
    pub(crate) render: Duration,
    /// Time to encode and write the images.
    pub(crate) write: Duration,
    /// Image size.
    pub(crate) size_px: (u32, u32),
    /// Samples per pixel (1 without supersampling).
    pub(crate) samples_per_pixel: u32,
    /// Worker threads rendering used.
    pub(crate) threads: usize,
    /// Sphere/disc tests performed.
    pub(crate) disc_tests: u64,
    /// The precision used.
    pub(crate) precision: crate::render::Precision,
}

impl RunReport {
    /// The `-stats` lines: one `name: value` per line.
    pub fn stats_lines(&self) -> String {
        let ms = |d: Duration| format!("{:.3}", d.as_secs_f64() * 1e3);
        [
            ("parse_ms", ms(self.parse)),
            ("render_ms", ms(self.render)),
            ("write_ms", ms(self.write)),
            ("spheres", self.sphere_count.to_string()),
            ("width", self.size_px.0.to_string()),
            ("height", self.size_px.1.to_string()),
            ("samples_per_pixel", self.samples_per_pixel.to_string()),
            ("threads", self.threads.to_string()),
            ("disc_tests", self.disc_tests.to_string()),
            ("precision", self.precision.to_string()),
        ]
        .iter()
        .fold(String::new(), |mut text, (name, value)| {
            let _ = writeln!(text, "{name}: {value}");
            text
        })
    }
}

/// The depth range used when only a colour image is asked for (it does not affect the output).
const UNUSED_DEPTH_RANGE: DepthRange = DepthRange {
    min_t: 0.0,
    max_t: 1.0,
};

/// The view a request renders: the scene's camera at the requested size and depth range (of
/// `-depth`, else of `-depth16`).
pub(crate) fn request_view(scene: &Scene, request: &RenderRequest) -> View {
    let range = request
        .depth_output
        .as_ref()
        .or(request.depth16_output.as_ref())
        .map_or(UNUSED_DEPTH_RANGE, |depth| depth.range);
    View::of_camera(&scene.camera, request.width_px, request.height_px, range)
}

/// Runs a headless render request. Every output is checked for writability first, so a run that
/// cannot write all its files writes none.
pub fn run(request: &RenderRequest) -> Result<RunReport, RunError> {
    let image_outputs = request
        .colour_output
        .iter()
        .chain(request.depth_output.iter().map(|depth| &depth.path))
        .chain(request.depth16_output.iter().map(|depth| &depth.path));
    for path in image_outputs {
        check_writable(path)?;
    }
    if let Some(path) = &request.depth_raw_output {
        check_writable_raw(path)?;
    }
    let started = Instant::now();
    let scene = {
        let bar = StepProgress::start("loading");
        load_scene_with_progress(&request.input, &|share| bar.report(share))?
    };
    let parse = started.elapsed();

    let started = Instant::now();
    let view = request_view(&scene, request);
    let frame = {
        let bar = StepProgress::start("rendering");
        render_with_progress(&scene, &view, &request.quality, &|share| bar.report(share))?
    };
    let render = started.elapsed();

    let started = Instant::now();
    let map = request.depth_colour_map;
    let outputs: [Option<(&Path, _)>; 2] = [
        request
            .colour_output
            .as_deref()
            .map(|path| (path, frame.colour_image())),
        request.depth_output.as_ref().map(|depth| {
            (
                depth.path.as_path(),
                frame.depth_image_mapped(depth.range, map, DepthColourMap::FILE_NO_HIT),
            )
        }),
    ];
    for (path, image) in outputs.into_iter().flatten() {
        write_image(path, &image)?;
    }
    if let Some(depth) = &request.depth16_output {
        write_depth_png16(&frame, depth.range, &depth.path)?;
    }
    if let Some(path) = &request.depth_raw_output {
        write_raw_depth(&frame, path)?;
    }
    Ok(RunReport {
        sphere_count: scene.spheres.len(),
        parse,
        render,
        write: started.elapsed(),
        size_px: (request.width_px, request.height_px),
        samples_per_pixel: request.quality.sampling.map_or(1, |s| s.samples),
        threads: rayon::current_num_threads(),
        disc_tests: frame.disc_tests,
        precision: frame.precision,
    })
}
