//! The course's own command — one sample per pixel, `-output` and `-depth` as TGA — rendered and
//! written a strip of rows at a time ([`crate::render::disc::Strip`]): the thread that draws a
//! strip colours it, maps its depth greys and writes both at their place in the two files, so
//! the command never holds the whole frame or either image. In a fresh process that memory is
//! what costs most (the kernel hands over and zeroes every page on first touch); the files are
//! the bytes the whole-frame path writes.
//!
//! Everything else (supersampling, comparisons, PNG, 16-bit and raw depth) renders the whole
//! frame first.

use std::cell::RefCell;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use super::flags::Flag;
use super::progress::StepProgress;
use crate::cli::RenderRequest;
use crate::output::WriteError;
use crate::output::atomic::{FileSet, Staged, Staging};
use crate::output::image_file::ImageFormat;
use crate::output::tga::TgaFile;
use crate::output::writeback::Writeback;
use crate::render::depth_map::{DepthColourMap, DepthPainter};
use crate::render::disc::{Palette, Strip};
use crate::render::{Quality, View, ViewError, render_strips};
use crate::scene::Scene;

/// Whether `request` is one the streamed path renders: one sample per pixel, no comparison,
/// and its only outputs an `-output` and/or `-depth` TGA.
pub(super) fn streams(request: &RenderRequest) -> bool {
    let tga = |path: &Path| ImageFormat::from_path(path).is_ok_and(|f| f == ImageFormat::Tga);
    let outputs = request.outputs.each();
    request.quality == Quality::default()
        && request.compare.is_none()
        && !outputs.is_empty()
        && outputs
            .iter()
            .all(|output| matches!(output.flag, Flag::Output | Flag::Depth) && tga(output.path))
}

/// Why a streamed run failed.
#[derive(Debug, thiserror::Error)]
pub(super) enum StreamedError {
    /// The view cannot be rendered.
    #[error(transparent)]
    View(#[from] ViewError),
    /// A file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
}

/// What a streamed run did.
pub(super) struct Streamed {
    /// Time spent drawing the strips and, at once, colouring, mapping and writing them
    /// (projection and binning included).
    pub(super) render: Duration,
    /// Time spent after the last strip: waiting for the early sync under way, completing the
    /// files on disk and renaming them into place.
    pub(super) write: Duration,
    /// Pixel–disc tests made.
    pub(super) disc_tests: u64,
}

/// One TGA being written strip by strip, each strip at its place.
struct Output {
    staging: Staging,
    tga: TgaFile,
}

impl Output {
    fn begin(path: &Path, view: &View) -> Result<Self, StreamedError> {
        let mut staging = Staging::begin(path, 0o666)?;
        let tga = TgaFile::begin(staging.file()?, view.width_px, view.height_px);
        let tga = tga.map_err(|source| staging.error(source))?;
        Ok(Self { staging, tga })
    }

    /// Writes `rgb`, the pixels from index `first_pixel` on.
    fn write(&self, first_pixel: usize, rgb: &mut [[u8; 3]]) -> Result<(), StreamedError> {
        let file = self.staging.file_to_share()?;
        let written = self.tga.write_pixels_at(file, first_pixel, rgb);
        written.map_err(|source| self.staging.error(source).into())
    }

    /// Checks every pixel was written and syncs the file.
    fn finish(self) -> Result<Staged, StreamedError> {
        self.tga
            .finish()
            .map_err(|source| self.staging.error(source))?;
        Ok(self.staging.finish()?)
    }
}

thread_local! {
    /// Each thread's pixels of the strip it is writing, kept from strip to strip.
    static STRIP_RGB: RefCell<Vec<[u8; 3]>> = const { RefCell::new(Vec::new()) };
}

/// Runs `write` on this thread's pixel buffer, `pixels` long (or on a new one, should it be in
/// use already).
fn with_strip_rgb<R>(pixels: usize, write: impl FnOnce(&mut [[u8; 3]]) -> R) -> R {
    STRIP_RGB.with(|rgb| match rgb.try_borrow_mut() {
        Ok(mut rgb) => {
            rgb.resize(pixels, [0; 3]);
            write(&mut rgb[..pixels])
        }
        Err(_) => write(&mut vec![[0; 3]; pixels]),
    })
}

/// Renders `request` (one that [`streams`]) of `scene` through `view` and writes its files all
/// or nothing.
pub(super) fn render_streamed(
    request: &RenderRequest,
    scene: &Scene,
    view: &View,
) -> Result<Streamed, StreamedError> {
    let colour = request
        .outputs
        .colour
        .as_deref()
        .map(|path| Output::begin(path, view))
        .transpose()?;
    let depth = request
        .outputs
        .depth
        .as_ref()
        .map(|depth| Output::begin(&depth.path, view))
        .transpose()?;
    let width = view.width_px as usize;
    let palette = Palette::of(scene, width * view.height_px as usize);
    let painter = DepthPainter::new(
        view.depth_range,
        request.depth_colour_map,
        DepthColourMap::FILE_NO_HIT,
    );
    let outputs: Vec<&Output> = colour.iter().chain(depth.iter()).collect();
    let mut handles = Vec::new();
    for output in &outputs {
        let handle = output.staging.file_to_share()?.try_clone();
        handles.push(handle.map_err(|source| output.staging.error(source))?);
    }
    let bar = StepProgress::start("rendering");
    let rows_written = AtomicUsize::new(0);
    let height = f64::from(view.height_px);
    let started = Instant::now();
    let (disc_tests, render, synced_early) = std::thread::scope(|scope| {
        let writeback = Writeback::start(scope, handles);
        // Each strip coloured, mapped and written by the thread that drew it.
        let disc_tests = render_strips(scene, view, |strip: Strip<'_>| {
            let first_pixel = strip.first_row * width;
            with_strip_rgb(strip.t.len(), |rgb| {
                if let Some(colour) = &colour {
                    palette.colour(strip.sphere, rgb);
                    colour.write(first_pixel, rgb)?;
                }
                if let Some(depth) = &depth {
                    painter.paint(strip.t, rgb);
                    depth.write(first_pixel, rgb)?;
                }
                Ok::<_, StreamedError>(())
            })?;
            writeback.written();
            let rows = strip.t.len() / width;
            let done = rows_written.fetch_add(rows, Ordering::Relaxed) + rows;
            bar.report(done as f64 / height);
            Ok::<_, StreamedError>(())
        });
        let render = started.elapsed();
        (disc_tests, render, writeback.stop())
    });
    let disc_tests = disc_tests?;
    // A file an early sync could not put on the disk is not put in place.
    if let Err((index, source)) = synced_early
        && let Some(output) = outputs.get(index)
    {
        return Err(output.staging.error(source).into());
    }
    drop(outputs);
    // Both files synced at once.
    let (colour, depth) = rayon::join(
        || colour.map(Output::finish).transpose(),
        || depth.map(Output::finish).transpose(),
    );
    let mut files = FileSet::new();
    for staged in [colour?, depth?].into_iter().flatten() {
        files.push(staged);
    }
    files.commit()?;
    Ok(Streamed {
        render,
        write: started.elapsed().saturating_sub(render),
        disc_tests,
    })
}
