//! Headless rendering for the command line: check the request against the file system (no
//! output may be the input or another output under a different name, every output writable),
//! read the scene, check the render fits in memory, render, and write every output all or
//! nothing.

use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use image::RgbImage;

use super::compare::{
    CompareError, CompareReport, JSON_LINE_BYTES, TheirImages, compare, read_theirs,
    their_pixel_lines,
};
use super::error::UsageError;
use super::flags::Flag;
use super::progress::StepProgress;
use super::streamed::{StreamedError, render_streamed, streams};
use crate::cli::RenderRequest;
use crate::explore::trace::{TraceError, trace_pixel};
use crate::output::WriteError;
use crate::output::atomic::FileSet;
use crate::output::depth_file::{check_writable_raw, stage_depth_png16, stage_raw_depth};
use crate::output::image_file::{check_writable, stage_image};
use crate::platform::files::{FileIdentity, identity};
use crate::platform::memory::{available_memory_bytes, peak_memory_bytes};
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::memory::{
    BASELINE_BYTES, compare_bound_bytes, load_bound_bytes, render_bound_bytes,
    streamed_bound_bytes, trace_bound_bytes,
};
use crate::render::{
    Frame, Quality, View, ViewError, render_with_progress, renders_strip_by_strip,
};
use crate::scene::{LoadError, Scene, load_scene_with_progress};

/// Why a headless render failed: a usage error (exit status 2) or a scene, view, memory or file
/// error (exit status 1).
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The request names files that cannot go together (exit status 2).
    #[error(transparent)]
    Usage(#[from] UsageError),
    /// The scene could not be read.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// The view cannot be rendered.
    #[error(transparent)]
    View(#[from] ViewError),
    /// The render needs more memory than the program may use.
    #[error(
        "{width_px}×{height_px}{traced} needs about {needed_mb:.0} MB more memory, and \
         {available_mb:.0} MB is available: {advice}"
    )]
    Memory {
        /// Image width.
        width_px: u32,
        /// Image height.
        height_px: u32,
        /// What a pixel's trace adds to the render, in words (empty without `-trace`).
        traced: String,
        /// What to change.
        advice: &'static str,
        /// The render's bound, MB.
        needed_mb: f64,
        /// What the program may still use, MB.
        available_mb: f64,
    },
    /// An image could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// An image to compare could not be read or has the wrong size.
    #[error(transparent)]
    Compare(#[from] CompareError),
    /// The pixel to trace cannot be traced (exit status 2).
    #[error("-trace: {0}")]
    Trace(#[from] TraceError),
}

impl From<StreamedError> for RunError {
    fn from(error: StreamedError) -> Self {
        match error {
            StreamedError::View(error) => Self::View(error),
            StreamedError::Write(error) => Self::Write(error),
        }
    }
}

impl RunError {
    /// The exit status the program ends with.
    pub fn exit_status(&self) -> u8 {
        match self {
            Self::Usage(_) | Self::Trace(_) => 2,
            _ => 1,
        }
    }
}

/// What a headless render did, with its timings.
#[derive(Debug, Clone, PartialEq)]
pub struct RunReport {
    /// Spheres in the scene.
    pub(crate) sphere_count: usize,
    /// Time to read and parse the scene.
    pub(crate) parse: Duration,
    /// Time to render the frame; for the course's own command, streamed, the time to draw the
    /// strips and, at once, to colour, map and write them.
    pub(crate) render: Duration,
    /// Time to encode and write the images; for the streamed command, what follows the last
    /// strip (completing the files on disk, renaming them into place).
    pub(crate) write: Duration,
    /// Image size.
    pub(crate) size_px: (u32, u32),
    /// Samples per pixel (1 without supersampling).
    pub(crate) samples_per_pixel: u32,
    /// Worker threads rendering used.
    pub(crate) threads: usize,
    /// Sphere/disc tests performed.
    pub(crate) disc_tests: u64,
    /// The memory bound of this run (loading or rendering, whichever is larger), bytes
    /// ([`crate::render::memory`]).
    pub(crate) memory_bound: u64,
    /// What the comparison found (`-compare_output`, `-compare_depth`).
    pub compare: Option<CompareReport>,
    /// `-trace`: the computation behind the pixel, as text (with their pixel, comparing).
    pub trace: Option<String>,
}

impl RunReport {
    /// The `-stats` lines: one `name: value` per line.
    pub fn stats_lines(&self) -> String {
        let ms = |d: Duration| format!("{:.3}", d.as_secs_f64() * 1e3);
        let mb = |bytes: u64| format!("{:.1}", bytes as f64 / 1e6);
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
            ("memory_bound_mb", mb(self.memory_bound)),
            (
                "peak_memory_mb",
                peak_memory_bytes().map_or_else(|| "unknown".into(), mb),
            ),
        ]
        .iter()
        .fold(String::new(), |mut text, (name, value)| {
            let _ = writeln!(text, "{name}: {value}");
            text
        })
    }
}

/// The view a request renders: the scene's camera at the requested size and depth range (of
/// `-depth`, else of `-depth16`).
pub(crate) fn request_view(scene: &Scene, request: &RenderRequest) -> View {
    let range = request.outputs.depth_range().unwrap_or(DepthRange::UNUSED);
    View::of_camera(&scene.camera, request.width_px, request.height_px, range)
}

/// Every output of a request with its flag, the comparison's picture last.
fn outputs(request: &RenderRequest) -> Vec<(Flag, &Path)> {
    let mut outputs: Vec<(Flag, &Path)> = request
        .outputs
        .each()
        .iter()
        .map(|output| (output.flag, output.path))
        .collect();
    if let Some(path) = request.compare.as_ref().and_then(|c| c.diff.as_ref()) {
        outputs.push((Flag::Diff, path.as_path()));
    }
    outputs
}

/// Every file a request reads: the scene and the images to compare.
fn inputs(request: &RenderRequest) -> Vec<(Flag, &Path)> {
    let mut inputs = vec![(Flag::Input, request.input.as_path())];
    if let Some(compare) = &request.compare {
        if let Some(path) = &compare.colour {
            inputs.push((Flag::CompareOutput, path.as_path()));
        }
        if let Some(depth) = &compare.depth {
            inputs.push((Flag::CompareDepth, depth.path.as_path()));
        }
    }
    inputs
}

/// Refuses a request whose outputs include a file it reads, or name one file twice, by any
/// spelling or link.
fn check_distinct_files(request: &RenderRequest) -> Result<(), UsageError> {
    let mut seen: Vec<(Flag, &Path, FileIdentity)> = Vec::new();
    for (flag, path) in inputs(request) {
        if let Some(input) = identity(path) {
            seen.push((flag, path, input));
        }
    }
    for (flag, path) in outputs(request) {
        let Some(id) = identity(path) else { continue };
        if let Some((first, first_path, _)) = seen.iter().find(|(_, _, other)| *other == id) {
            return Err(UsageError::SameFile {
                first: *first,
                first_path: first_path.display().to_string(),
                second: flag,
                second_path: path.display().to_string(),
            });
        }
        seen.push((flag, path, id));
    }
    Ok(())
}

/// Refuses work whose memory bound (`bound` bytes) exceeds what the program may still use. The
/// program itself ([`BASELINE_BYTES`] of the bound) is running already, and what it holds is
/// not available any more: the part of the bound the run adds is what must fit. `traced_spheres`:
/// the spheres a pixel's trace goes over, where the bound counts one.
fn check_memory(
    request: &RenderRequest,
    bound: u64,
    traced_spheres: Option<usize>,
) -> Result<u64, RunError> {
    let added = bound.saturating_sub(BASELINE_BYTES);
    match available_memory_bytes() {
        Some(available) if added > available => Err(RunError::Memory {
            width_px: request.width_px,
            height_px: request.height_px,
            traced: traced_spheres.map_or_else(String::new, |spheres| {
                format!(" with -trace over {spheres} spheres")
            }),
            advice: if traced_spheres.is_some() {
                "trace on a smaller scene, or leave out -trace"
            } else {
                "choose a smaller -size or fewer samples"
            },
            needed_mb: added as f64 / 1e6,
            available_mb: available as f64 / 1e6,
        }),
        _ => Ok(bound),
    }
}

/// Makes each output of `request` from `frame` and stages it, with the difference picture
/// `diff`, then commits them all. Two streams run at once — the colour side (difference picture,
/// colour image) and the depth side (depth image, 16-bit and raw depth) — each making and writing
/// one output at a time, so at most two outputs' pixels exist besides the frame.
fn write_outputs(
    request: &RenderRequest,
    frame: &Frame,
    diff: Option<&RgbImage>,
) -> Result<(), WriteError> {
    let colour_side = || {
        let mut files = FileSet::new();
        if let (Some(path), Some(picture)) =
            (request.compare.as_ref().and_then(|c| c.diff.as_ref()), diff)
        {
            stage_image(&mut files, path, picture)?;
        }
        if let Some(path) = &request.outputs.colour {
            stage_image(&mut files, path, &frame.colour_image())?;
        }
        Ok::<_, WriteError>(files)
    };
    let depth_side = || {
        let mut files = FileSet::new();
        if let Some(depth) = &request.outputs.depth {
            let map = request.depth_colour_map;
            let image = frame.depth_image_mapped(depth.range, map, DepthColourMap::FILE_NO_HIT);
            stage_image(&mut files, &depth.path, &image)?;
        }
        if let Some(depth) = &request.outputs.depth16 {
            stage_depth_png16(&mut files, frame, depth.range, &depth.path)?;
        }
        if let Some(path) = &request.outputs.depth_raw {
            stage_raw_depth(&mut files, frame, path)?;
        }
        Ok::<_, WriteError>(files)
    };
    // A failed side drops the other's staged files with it: nothing is replaced.
    let (colour, depth) = rayon::join(colour_side, depth_side);
    let mut files = colour?;
    files.append(depth?);
    files.commit().map(drop)
}

/// Runs a headless render request. Nothing is written unless every output can be: the files are
/// checked before rendering and written all or nothing after it. Images to compare are read
/// first; without `-size` the render takes their size.
pub fn run(request: &RenderRequest) -> Result<RunReport, RunError> {
    check_distinct_files(request)?;
    let theirs = match &request.compare {
        Some(compare) => {
            let size = request
                .size_given
                .then_some((request.width_px, request.height_px));
            read_theirs(compare, size)?
        }
        None => TheirImages::default(),
    };
    let sized;
    let request = match theirs.size_px() {
        Some((width_px, height_px)) if !request.size_given => {
            sized = RenderRequest {
                width_px,
                height_px,
                ..request.clone()
            };
            &sized
        }
        _ => request,
    };
    for (flag, path) in outputs(request) {
        match flag {
            Flag::DepthRaw => check_writable_raw(path)?,
            _ => check_writable(path)?,
        }
    }
    let file_bytes = std::fs::metadata(&request.input).map_or(0, |m| m.len());
    let load_bound = check_memory(request, load_bound_bytes(file_bytes), None)?;
    let started = Instant::now();
    let scene = {
        let bar = StepProgress::start("loading");
        load_scene_with_progress(&request.input, &|share| bar.report(share))?
    };
    let parse = started.elapsed();
    let view = request_view(&scene, request);
    // A pixel's trace holds a record and a line of text per sphere: checked before it is made.
    let trace_bound = request
        .trace
        .map_or(0, |_| trace_bound_bytes(scene.spheres.len()));
    let traced_spheres = request.trace.map(|_| scene.spheres.len());
    if trace_bound > 0 {
        check_memory(request, BASELINE_BYTES + trace_bound, traced_spheres)?;
    }
    let traced = match request.trace {
        Some((x_px, y_up_px)) => Some(trace_pixel(
            &scene,
            &view,
            x_px,
            y_up_px,
            known_depth_range(request),
        )?),
        None => None,
    };
    // Its text is counted before it is made: a line holds a dozen numbers printed in full, some
    // 150 bytes or, at the extremes of f64, thousands.
    let (trace_bound, trace_text_bytes) = match &traced {
        Some(traced) => {
            let text = traced.text_bytes();
            // As JSON, the answer holds a copy of the text, each line quoted.
            let as_json = request
                .answer_as_json()
                .then(|| text + traced.spheres.len() as u64 * JSON_LINE_BYTES);
            let counted = traced.records_bytes() + text + as_json.unwrap_or(0);
            if counted > trace_bound {
                check_memory(request, BASELINE_BYTES + counted, traced_spheres)?;
            }
            (counted, text)
        }
        None => (0, 0),
    };
    let streamed = streams(request);
    let measuring = Instant::now();
    let render_bound = if streamed {
        // A dense frame is drawn whole before it is streamed.
        let whole_frame = !renders_strip_by_strip(&scene, &view)?;
        streamed_bound_bytes(
            request.width_px,
            request.height_px,
            scene.spheres.len(),
            whole_frame,
            rayon::current_num_threads(),
        )
    } else {
        render_bound_bytes(
            request.width_px,
            request.height_px,
            scene.spheres.len(),
            request.quality.sampling.as_ref(),
            rayon::current_num_threads(),
        )
    };
    let measured = measuring.elapsed();
    let compare_bound = request.compare.as_ref().map_or(0, |_| {
        compare_bound_bytes(request.width_px, request.height_px)
    });
    let memory_bound = check_memory(
        request,
        render_bound + compare_bound + trace_bound,
        traced_spheres,
    )?
    .max(load_bound);

    if streamed {
        let streamed = render_streamed(request, &scene, &view)?;
        return Ok(RunReport {
            sphere_count: scene.spheres.len(),
            parse,
            // Measuring the frame's density is part of rendering it.
            render: measured + streamed.render,
            write: streamed.write,
            size_px: (request.width_px, request.height_px),
            samples_per_pixel: 1,
            threads: rayon::current_num_threads(),
            disc_tests: streamed.disc_tests,
            memory_bound,
            compare: None,
            trace: traced.map(|traced| traced.text_sized(trace_text_bytes)),
        });
    }
    let started = Instant::now();
    let frame = {
        let bar = StepProgress::start("rendering");
        render_with_progress(&scene, &view, &request.quality, &|share| bar.report(share))?
    };
    let render = started.elapsed();

    let (compare_report, diff) = match &request.compare {
        Some(wanted) => {
            // Compared with the exact picture: one sample per pixel in f64.
            let exact_owned;
            let exact = if request.quality == Quality::default() {
                &frame
            } else {
                exact_owned = crate::render::render(&scene, &view)?;
                &exact_owned
            };
            let (report, picture) = compare(&scene, wanted, &theirs, exact)?;
            (Some(report), picture)
        }
        None => (None, None),
    };

    let trace = traced.map(|mut traced| {
        if traced.depth_range.is_none() {
            traced.depth_range = compare_report.as_ref().and_then(|r| r.depth_range_used);
        }
        let mut text = traced.text_sized(trace_text_bytes);
        text.push_str(&their_pixel_lines(
            &scene,
            &theirs,
            &traced,
            compare_report.as_ref(),
        ));
        text
    });
    let started = Instant::now();
    write_outputs(request, &frame, diff.as_ref())?;
    Ok(RunReport {
        sphere_count: scene.spheres.len(),
        parse,
        render,
        write: started.elapsed(),
        size_px: (request.width_px, request.height_px),
        samples_per_pixel: request.quality.sampling.map_or(1, |s| s.samples),
        threads: rayon::current_num_threads(),
        disc_tests: frame.disc_tests,
        memory_bound,
        compare: compare_report,
        trace,
    })
}

/// The depth range a request names: its depth output's, else the range given with their depth
/// image.
fn known_depth_range(request: &RenderRequest) -> Option<DepthRange> {
    request
        .outputs
        .depth_range()
        .or_else(|| request.compare.as_ref()?.depth.as_ref()?.range)
}
