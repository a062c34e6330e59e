//! The compare concept in the viewer ([`crate::compare`] is the concept itself; its panel is drawn
//! by the `compare_section` of the UI): put an image beside the exact render and say why it
//! differs, or measure the chosen quality against the exact render on the user's own view.
//!
//! * **Their image** (colour or depth, TGA or PNG): the exact render of the open scene's own
//!   camera at the image's size (what the course's command renders) is computed off the UI thread,
//!   with the difference, the diagnosis ([`crate::compare::diagnose`]) and a heat map. While it is
//!   open the view is held at the file's camera and the image's size, so the live render and their
//!   image line up pixel for pixel; the compared image shows the render, theirs (the A/B flip, `B`)
//!   or the difference (`Shift+B`), and the probe gives both values at the hovered pixel.
//! * **Against the exact render**: the view at the chosen quality against the exact render (and
//!   a high-sample one): mean error, share of pixels off by over 8 levels, frame time.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use web_time::Instant;

use egui::{ColorImage, TextureHandle, TextureOptions};
use image::RgbImage;

use super::ViewerApp;
use super::background::{Poll, Task};
use super::status::Status;
use crate::compare::picture::{heat_map, heat_map_marked};
use crate::compare::their_image::{decode_their_image, read_their_image};
use crate::compare::{Deviation, Difference, Theirs, diagnose, infer_depth_range};
use crate::render::depth_map::DepthRange;
use crate::render::sampling::Sampling;
use crate::render::{Quality, View, render_with};
use crate::scene::Scene;

/// Samples per pixel of the high-sample reference an anti-aliased picture is measured against.
pub(crate) const REFERENCE_SAMPLES: u32 = 256;

/// A picture is "off" where a channel differs from the exact one by more than this many levels.
pub(crate) const OFF_LEVELS: u8 = 8;

/// Which of the two images is compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ImageKind {
    /// The colour image.
    #[default]
    Colour,
    /// The depth image (grey, the view's depth range).
    Depth,
}

impl ImageKind {
    /// The index of the image on screen (0 colour, 1 depth).
    pub(crate) fn index(self) -> usize {
        match self {
            Self::Colour => 0,
            Self::Depth => 1,
        }
    }
}

/// What the compared image shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CompareShow {
    /// The live render.
    #[default]
    Rendered,
    /// Their image (or the picture at the chosen quality).
    Theirs,
    /// The heat map of the difference.
    Difference,
}

/// Where the compared picture came from.
#[derive(Debug, Clone, PartialEq)]
pub enum CompareSource {
    /// An image file the user opened.
    File(PathBuf),
    /// The current view at the chosen quality.
    Quality(QualityFigures),
}

/// The trade measured on the user's view: the chosen quality against the exact render.
#[derive(Debug, Clone, PartialEq)]
pub struct QualityFigures {
    /// The quality measured, in words.
    pub quality: String,
    /// Its frame time, milliseconds.
    pub frame_ms: f64,
    /// The exact render's frame time, milliseconds.
    pub exact_ms: f64,
    /// Mean difference from the exact render, levels (largest channel per pixel).
    pub mean_error_levels: f64,
    /// Share of pixels off the exact render by more than [`OFF_LEVELS`].
    pub share_off: f64,
    /// For anti-aliasing: the same two figures against a high-sample reference.
    pub against_reference: Option<(f64, f64)>,
}

/// A finished comparison (pixels on the CPU; the textures are made on the UI thread).
#[derive(Debug, Clone)]
pub struct ComparisonPixels {
    /// Where their picture came from.
    pub source: CompareSource,
    /// Which image it is.
    pub kind: ImageKind,
    /// The view both pictures are of.
    pub view: View,
    /// Their picture.
    pub theirs: RgbImage,
    /// The exact picture.
    pub exact: RgbImage,
    /// How they differ.
    pub difference: Difference,
    /// The statements that explain the difference (empty: none does, or none was looked for).
    pub statements: Vec<Deviation>,
    /// The alternatives of a near tie, each a `+`-joined list of statements (empty: no tie).
    pub alternatives: Vec<String>,
    /// When nothing explains it all: the statements that explain part of it.
    pub partial: Vec<Deviation>,
    /// Differing pixels no word named accounts for.
    pub unexplained_pixels: usize,
    /// A depth image's range, read back from it (`None`: a colour image, or no ramp to fit).
    pub depth_range_inferred: Option<DepthRange>,
    /// Where they are, one flag per pixel from the top row (cyan over the heat map).
    pub unexplained: Option<Vec<bool>>,
}

impl ComparisonPixels {
    /// Each statement as its word and values (`zoom 1.118`).
    pub fn diagnosis(&self) -> Vec<String> {
        self.statements
            .iter()
            .map(Deviation::name_and_values)
            .collect()
    }
}

/// A comparison on screen.
pub(crate) struct Comparison {
    pub(crate) pixels: ComparisonPixels,
    pub(crate) theirs_texture: TextureHandle,
    pub(crate) heat_texture: TextureHandle,
}

/// The Compare section's state.
#[derive(Default)]
pub(crate) struct CompareState {
    /// The typed path of the image to open.
    pub(crate) path_text: String,
    /// Which image the typed path is compared with.
    pub(crate) kind: ImageKind,
    /// What the compared image shows.
    pub(crate) show: CompareShow,
    /// The comparison on screen.
    pub(crate) current: Option<Comparison>,
    /// A comparison being computed.
    pending: Option<Task<Result<ComparisonPixels, String>>>,
}

/// The exact picture of `kind` for `view`.
fn exact_picture(scene: &Scene, view: &View, kind: ImageKind) -> Result<RgbImage, String> {
    let frame = render_with(scene, view, &Quality::default()).map_err(|e| e.to_string())?;
    Ok(match kind {
        ImageKind::Colour => frame.colour_image(),
        ImageKind::Depth => frame.depth_image(view.depth_range),
    })
}

/// Compares `theirs` with the exact picture of the scene's own camera at their size (the depth
/// range of `depth_view`), and diagnoses the difference.
pub fn compare_file(
    scene: &Scene,
    path: &Path,
    theirs: RgbImage,
    kind: ImageKind,
    depth_view: &View,
) -> Result<ComparisonPixels, String> {
    let (width_px, height_px) = theirs.dimensions();
    let view = View::of_camera(&scene.camera, width_px, height_px, depth_view.depth_range);
    let exact = exact_picture(scene, &view, kind)?;
    let difference = Difference::of(&theirs, &exact);
    let given = match kind {
        ImageKind::Colour => Theirs {
            colour: Some(&theirs),
            depth: None,
        },
        ImageKind::Depth => Theirs {
            colour: None,
            depth: Some(&theirs),
        },
    };
    let diagnosis = diagnose(scene, &view, given);
    let depth_range_inferred = match kind {
        ImageKind::Colour => None,
        ImageKind::Depth => infer_depth_range(scene, &view, &theirs),
    };
    let unexplained = if diagnosis.stated().is_empty() && diagnosis.partial().is_empty() {
        None
    } else {
        match kind {
            ImageKind::Colour => diagnosis.unexplained.colour.clone(),
            ImageKind::Depth => diagnosis.unexplained.depth.clone(),
        }
    };
    Ok(ComparisonPixels {
        source: CompareSource::File(path.to_path_buf()),
        kind,
        view,
        exact,
        difference,
        statements: diagnosis.stated().to_vec(),
        alternatives: diagnosis
            .alternatives()
            .iter()
            .map(|set| {
                set.iter()
                    .map(Deviation::name_and_values)
                    .collect::<Vec<_>>()
                    .join(" + ")
            })
            .collect(),
        partial: diagnosis.partial().to_vec(),
        unexplained_pixels: diagnosis.unexplained_pixels(),
        unexplained,
        depth_range_inferred,
        theirs,
    })
}

/// The colour image of `view` at `quality` against the exact one (and, with anti-aliasing, a
/// high-sample reference of the same sampler and filter).
pub fn compare_quality(
    scene: &Scene,
    view: &View,
    quality: &Quality,
) -> Result<ComparisonPixels, String> {
    let timed = |quality: &Quality| {
        let started = Instant::now();
        let frame = render_with(scene, view, quality).map_err(|e| e.to_string())?;
        Ok::<_, String>((frame.colour_image(), started.elapsed().as_secs_f64() * 1e3))
    };
    let (theirs, frame_ms) = timed(quality)?;
    let (exact, exact_ms) = timed(&Quality::default())?;
    let difference = Difference::of(&theirs, &exact);
    let figures = |difference: &Difference| {
        let total = difference.per_pixel.len().max(1) as f64;
        (
            difference.mean_difference(),
            difference.pixels_beyond(OFF_LEVELS) as f64 / total,
        )
    };
    let (mean_error_levels, share_off) = figures(&difference);
    let against_reference = match quality.sampling {
        Some(sampling) => {
            let reference_quality = Quality {
                sampling: Some(Sampling {
                    samples: REFERENCE_SAMPLES,
                    ..sampling
                }),
            };
            let (reference, _) = timed(&reference_quality)?;
            Some(figures(&Difference::of(&theirs, &reference)))
        }
        None => None,
    };
    Ok(ComparisonPixels {
        source: CompareSource::Quality(QualityFigures {
            quality: quality.describe(),
            frame_ms,
            exact_ms,
            mean_error_levels,
            share_off,
            against_reference,
        }),
        kind: ImageKind::Colour,
        view: *view,
        theirs,
        exact,
        difference,
        statements: Vec::new(),
        alternatives: Vec::new(),
        partial: Vec::new(),
        unexplained_pixels: 0,
        unexplained: None,
        depth_range_inferred: None,
    })
}

/// An RGB image as an egui image.
fn to_colour_image(image: &RgbImage) -> ColorImage {
    ColorImage::from_rgb(
        [image.width() as usize, image.height() as usize],
        image.as_raw(),
    )
}

impl CompareState {
    /// A comparison is being computed.
    pub(crate) fn busy(&self) -> bool {
        self.pending.is_some()
    }

    /// The size the view is held at while their image is compared.
    pub(crate) fn held_size_px(&self) -> Option<(u32, u32)> {
        let current = self.current.as_ref()?;
        matches!(current.pixels.source, CompareSource::File(_))
            .then(|| current.pixels.theirs.dimensions())
    }

    /// Starts `work` (a comparison) in the background; `ctx` repaints when it is done.
    fn start(
        &mut self,
        ctx: &egui::Context,
        work: impl FnOnce() -> Result<ComparisonPixels, String> + Send + 'static,
    ) -> Option<Status> {
        match Task::spawn("compare", ctx, move |_| work()) {
            Ok(task) => {
                self.pending = Some(task);
                None
            }
            Err(error) => Some(Status::error(format!(
                "cannot start the comparison: {error}"
            ))),
        }
    }

    /// Closes the comparison (the view is free again).
    pub(crate) fn close(&mut self) {
        self.current = None;
        self.pending = None;
        self.show = CompareShow::Rendered;
    }

    /// Their depth image on screen, compared at another depth range than `depth_range`: its
    /// file, to compare again.
    fn stale_depth_file(&self, depth_range: DepthRange) -> Option<PathBuf> {
        let pixels = &self.current.as_ref()?.pixels;
        let CompareSource::File(path) = &pixels.source else {
            return None;
        };
        (pixels.kind == ImageKind::Depth && pixels.view.depth_range != depth_range)
            .then(|| path.clone())
    }

    /// Takes a finished comparison in, its textures made through `ctx`. `Ok(Some(view))` with
    /// their image: the view to hold (the file's camera at their size); an error when it failed.
    fn poll(&mut self, ctx: &egui::Context) -> Result<Option<View>, Status> {
        let Some(task) = &self.pending else {
            return Ok(None);
        };
        let pixels = match task.poll() {
            Poll::Running => return Ok(None),
            Poll::Done(Ok(pixels)) => pixels,
            Poll::Done(Err(error)) => {
                self.pending = None;
                return Err(Status::error(format!("compare: {error}")));
            }
            Poll::Lost => {
                self.pending = None;
                return Err(Status::error("compare: the comparison stopped"));
            }
        };
        self.pending = None;
        let first = self.current.is_none();
        let hold = matches!(pixels.source, CompareSource::File(_)).then_some(pixels.view);
        let theirs_texture = ctx.load_texture(
            "compare theirs",
            to_colour_image(&pixels.theirs),
            TextureOptions::NEAREST,
        );
        let heat_texture = ctx.load_texture(
            "compare heat",
            to_colour_image(&match &pixels.unexplained {
                Some(unexplained) => heat_map_marked(&pixels.difference, unexplained),
                None => heat_map(&pixels.difference),
            }),
            TextureOptions::NEAREST,
        );
        if first || matches!(pixels.source, CompareSource::Quality(_)) {
            self.show = CompareShow::Difference;
        }
        self.current = Some(Comparison {
            pixels,
            theirs_texture,
            heat_texture,
        });
        Ok(hold)
    }

    /// The A/B flip: the render and their image in turn.
    pub(crate) fn flip(&mut self) {
        if self.current.is_some() {
            self.show = match self.show {
                CompareShow::Theirs => CompareShow::Rendered,
                _ => CompareShow::Theirs,
            };
        }
    }

    /// The difference view on and off.
    pub(crate) fn toggle_difference(&mut self) {
        if self.current.is_some() {
            self.show = match self.show {
                CompareShow::Difference => CompareShow::Rendered,
                _ => CompareShow::Difference,
            };
        }
    }

    /// The probe's line for the compared image at pixel `px` (y up): theirs, exact, difference.
    pub(crate) fn probe_line(&self, px: glam::DVec2) -> Option<String> {
        let pixels = &self.current.as_ref()?.pixels;
        let (width, height) = pixels.theirs.dimensions();
        if px.x < 0.0 || px.y < 0.0 || px.x >= f64::from(width) || px.y >= f64::from(height) {
            return None;
        }
        let (x, row) = (px.x as u32, height - 1 - px.y as u32);
        let rgb = |image: &RgbImage| {
            let [r, g, b] = image.get_pixel(x, row).0;
            format!("{r} {g} {b}")
        };
        let name = match pixels.source {
            CompareSource::File(_) => "theirs",
            CompareSource::Quality(_) => "chosen",
        };
        let index = (row * width + x) as usize;
        let unexplained = pixels
            .unexplained
            .as_ref()
            .is_some_and(|flags| flags.get(index).copied().unwrap_or(false));
        Some(format!(
            "{name} {} · exact {} · off by {}{}",
            rgb(&pixels.theirs),
            rgb(&pixels.exact),
            pixels.difference.per_pixel[index],
            if unexplained { " · unexplained" } else { "" }
        ))
    }
}

impl ViewerApp {
    /// Opens the image at `path` and compares it with the exact render of the open scene.
    pub(crate) fn compare_with_file(&mut self, path: PathBuf, kind: ImageKind) {
        self.compare_theirs(path, kind, read_their_image);
    }

    /// Compares the image `bytes` named `name` (a browser page's dropped or picked file) with the
    /// exact render, as [`Self::compare_with_file`] does a file.
    pub fn compare_with_bytes(&mut self, name: &str, bytes: Arc<[u8]>, kind: ImageKind) {
        self.compare_theirs(name.into(), kind, move |path| {
            decode_their_image(path, &bytes)
        });
    }

    /// Compares the image `read` gets for `path` with the exact render, in the background.
    fn compare_theirs(
        &mut self,
        path: PathBuf,
        kind: ImageKind,
        read: impl FnOnce(&Path) -> Result<RgbImage, String> + Send + 'static,
    ) {
        let scene = Arc::clone(&self.scene.loaded.scene);
        let depth_view = self.viewing.view;
        self.compare.kind = kind;
        let status = self.compare.start(&self.ctx, move || {
            compare_file(&scene, &path, read(&path)?, kind, &depth_view)
        });
        self.say(status);
    }

    /// Measures the chosen quality against the exact render on the current view.
    pub(crate) fn compare_quality(&mut self) {
        let scene = Arc::clone(&self.scene.loaded.scene);
        let view = self.viewing.view;
        let quality = self.settings.quality;
        let status = self
            .compare
            .start(&self.ctx, move || compare_quality(&scene, &view, &quality));
        self.say(status);
    }

    /// Takes a finished comparison in ([`CompareState::poll`]); with their image, holds the view
    /// at the file's camera and their size, keeping the depth range. A depth comparison follows
    /// the depth range: it is made again when it changes.
    pub(crate) fn poll_comparison(&mut self) {
        if !self.compare.busy() {
            if let Some(path) = self.compare.stale_depth_file(self.viewing.view.depth_range) {
                self.compare_with_file(path, ImageKind::Depth);
            }
            return;
        }
        match self.compare.poll(&self.ctx) {
            Ok(None) => {}
            Ok(Some(view)) => {
                self.viewing.view = View {
                    depth_range: self.viewing.view.depth_range,
                    ..view
                };
            }
            Err(status) => self.status = Some(status),
        }
    }
}
