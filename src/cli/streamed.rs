//! The course's own command — one sample per pixel, `-output` and `-depth` as TGA — rendered and
//! written a strip of rows at a time ([`crate::render::disc::Strip`]): each strip's colours and
//! depth greys go straight into the two files, so the command never holds the whole frame or
//! either image. On a fresh process that memory is what costs most (the kernel hands over and
//! zeroes every page on first touch); the files are the bytes the whole-frame path writes.
//!
//! Everything else (supersampling, comparisons, PNG, 16-bit and raw depth) renders the whole
//! frame first.

use std::path::Path;
use std::time::{Duration, Instant};

use super::progress::StepProgress;
use crate::cli::RenderRequest;
use crate::output::WriteError;
use crate::output::atomic::{FileSet, Staged, Staging};
use crate::output::image_file::ImageFormat;
use crate::output::tga::TgaWriter;
use crate::output::writeback::Writeback;
use crate::render::depth_map::{DepthColourMap, DepthPainter};
use crate::render::disc::{Palette, Strip};
use crate::render::{Quality, View, ViewError, render_strips};
use crate::scene::Scene;

/// Whether `request` is one the streamed path renders: one sample per pixel, no comparison,
/// and its only outputs an `-output` and/or `-depth` TGA.
pub(super) fn streams(request: &RenderRequest) -> bool {
    let tga = |path: &Path| ImageFormat::from_path(path).is_ok_and(|f| f == ImageFormat::Tga);
    let colour = request.colour_output.as_deref();
    let depth = request
        .depth_output
        .as_ref()
        .map(|depth| depth.path.as_path());
    request.quality == Quality::default()
        && request.compare.is_none()
        && request.depth16_output.is_none()
        && request.depth_raw_output.is_none()
        && (colour.is_some() || depth.is_some())
        && colour.is_none_or(tga)
        && depth.is_none_or(tga)
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
    /// Time spent after the last strip: completing the files on disk and renaming them.
    pub(super) write: Duration,
    /// Pixel–disc tests made.
    pub(super) disc_tests: u64,
}

/// One TGA being written strip by strip, with the pixels of the current strip.
struct Output {
    staging: Staging,
    tga: TgaWriter,
    rgb: Vec<[u8; 3]>,
}

impl Output {
    fn begin(path: &Path, view: &View) -> Result<Self, StreamedError> {
        let mut staging = Staging::begin(path, 0o666)?;
        let tga = TgaWriter::begin(staging.file()?, view.width_px, view.height_px);
        let tga = tga.map_err(|source| staging.error(source))?;
        Ok(Self {
            staging,
            tga,
            rgb: Vec::new(),
        })
    }

    /// Makes the strip's `pixels` with `make` and writes them.
    fn write(
        &mut self,
        pixels: usize,
        make: impl FnOnce(&mut [[u8; 3]]),
    ) -> Result<(), StreamedError> {
        self.rgb.resize(pixels, [0; 3]);
        make(&mut self.rgb);
        let written = (self.tga).write_pixels_in_place(self.staging.file()?, &mut self.rgb);
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

/// Renders `request` (one that [`streams`]) of `scene` through `view` and writes its files all
/// or nothing.
pub(super) fn render_streamed(
    request: &RenderRequest,
    scene: &Scene,
    view: &View,
) -> Result<Streamed, StreamedError> {
    let mut colour = request
        .colour_output
        .as_deref()
        .map(|path| Output::begin(path, view))
        .transpose()?;
    let mut depth = request
        .depth_output
        .as_ref()
        .map(|depth| Output::begin(&depth.path, view))
        .transpose()?;
    let palette = Palette::of(scene, view.width_px as usize * view.height_px as usize);
    let painter = DepthPainter::new(
        view.depth_range,
        request.depth_colour_map,
        DepthColourMap::FILE_NO_HIT,
    );
    let mut handles = Vec::new();
    for output in colour.iter_mut().chain(depth.iter_mut()) {
        let handle = output.staging.file()?.try_clone();
        handles.push(handle.map_err(|source| output.staging.error(source))?);
    }
    let bar = StepProgress::start("rendering");
    let height = f64::from(view.height_px);
    let started = Instant::now();
    let disc_tests = std::thread::scope(|scope| {
        let mut writeback = Writeback::start(scope, handles);
        let disc_tests = render_strips(scene, view, |strip: Strip<'_>| {
            // The two files at once.
            let (colour, depth) = rayon::join(
                || {
                    let colour = colour.as_mut()?;
                    Some(colour.write(strip.sphere.len(), |rgb| palette.colour(strip.sphere, rgb)))
                },
                || {
                    let depth = depth.as_mut()?;
                    Some(depth.write(strip.t.len(), |rgb| painter.paint(strip.t, rgb)))
                },
            );
            colour.transpose()?;
            depth.transpose()?;
            writeback.written();
            let rows = strip.t.len() / view.width_px as usize;
            bar.report((strip.first_row + rows) as f64 / height);
            Ok::<_, StreamedError>(())
        });
        writeback.stop();
        disc_tests
    })?;
    let render = started.elapsed();
    let finishing = Instant::now();
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
        write: finishing.elapsed(),
        disc_tests,
    })
}
