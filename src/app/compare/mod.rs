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

pub(crate) mod gallery;
mod pixels;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use egui::{ColorImage, TextureHandle, TextureOptions};
use image::RgbImage;

pub use pixels::{
    CompareShow, CompareSource, ComparisonPixels, ImageKind, QualityFigures, RangeSource,
    compare_file, compare_quality, recognised_kind,
};
pub(crate) use pixels::{OFF_LEVELS, REFERENCE_SAMPLES};

use super::background::{Poll, Task};
use super::reload::{FileWatcher, WatchState};
use super::status::{Status, say};
use crate::compare::judge::their_depth_at;
use crate::compare::picture::{heat_map, heat_map_highlighted, heat_map_marked};
use crate::compare::their_image::{TheirImageError, read_their_image, read_their_image_settled};
use crate::explore::trace::PixelTrace;
use crate::render::depth_map::DepthRange;
use crate::render::{Quality, View};
use crate::scene::Scene;

/// A comparison on screen.
pub(crate) struct Comparison {
    pub(crate) pixels: ComparisonPixels,
    pub(crate) theirs_texture: TextureHandle,
    pub(crate) heat_texture: TextureHandle,
    /// The difference with one statement's pixels highlighted: the statement's index, and the
    /// picture.
    highlight: Option<(usize, TextureHandle)>,
}

/// The Compare section's state.
#[derive(Default)]
pub(crate) struct CompareState {
    /// The typed path of the image to open.
    pub(crate) path_text: String,
    /// Which image the typed path is compared with.
    pub(crate) kind: ImageKind,
    /// The kind was clicked: the next comparison judges the image as that kind, whatever its
    /// content or name say (and one on screen is judged again at once).
    pub(crate) kind_forced: bool,
    /// What the compared image shows.
    pub(crate) show: CompareShow,
    /// The comparison on screen.
    pub(crate) current: Option<Comparison>,
    /// A comparison being computed.
    pending: Option<Task<Result<ComparisonPixels, String>>>,
    /// The statement of the answer pointed at (hovered), if any.
    pointed: Option<usize>,
    /// The gallery's pictures of the known mistakes.
    pub(crate) gallery: gallery::Gallery,
    /// Their image file, watched: when their program writes it again it is compared again.
    /// With the kind it was given and whether that kind was clicked.
    watched: Option<(PathBuf, ImageKind, bool, FileWatcher)>,
}
/// An RGB image as an egui image.
fn to_colour_image(image: &RgbImage) -> ColorImage {
    ColorImage::from_rgb(
        [image.width() as usize, image.height() as usize],
        image.as_raw(),
    )
}

impl CompareState {
    /// Their image file being compared (and watched).
    pub(crate) fn watched_file(&self) -> Option<&Path> {
        self.watched.as_ref().map(|(path, ..)| path.as_path())
    }

    /// Shows `show` in the compared image, when a comparison is open.
    pub(crate) fn show_if_open(&mut self, show: CompareShow) {
        if self.current.is_some() {
            self.show = show;
        }
    }

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
        self.drop_result();
        self.watched = None;
    }

    /// Takes the comparison off the screen (a failed one, or one closed); their file stays
    /// watched, so a good version written later is compared.
    fn drop_result(&mut self) {
        self.current = None;
        self.pending = None;
        self.show = CompareShow::Rendered;
    }

    /// Their depth image on screen, compared at another depth range than `depth_range`: its
    /// name and pixels, to compare again (the image is not read again: a page has no file).
    fn stale_depth_image(&self, depth_range: DepthRange) -> Option<(PathBuf, RgbImage)> {
        let pixels = &self.current.as_ref()?.pixels;
        let CompareSource::File(path) = &pixels.source else {
            return None;
        };
        (pixels.kind == ImageKind::Depth && pixels.view.depth_range != depth_range)
            .then(|| (path.clone(), pixels.theirs.clone()))
    }

    /// Takes a finished comparison in, its textures made through `ctx`. `Ok(Some((view, kind)))`
    /// with their image: the view to hold (the file's camera at their size, the depth range it
    /// was judged under) and which image it is; an error when it failed.
    fn poll(&mut self, ctx: &egui::Context) -> Result<Option<(View, ImageKind)>, Status> {
        let Some(task) = &self.pending else {
            return Ok(None);
        };
        let pixels = match task.poll() {
            Poll::Running => return Ok(None),
            Poll::Done(Ok(pixels)) => pixels,
            Poll::Done(Err(error)) => {
                // The old result is not left on screen as if it answered this one.
                self.drop_result();
                return Err(Status::error(format!("compare: {error}")));
            }
            Poll::Lost => {
                self.drop_result();
                return Err(Status::error("compare: the comparison stopped"));
            }
        };
        self.pending = None;
        let first = self.current.is_none();
        let hold =
            matches!(pixels.source, CompareSource::File(_)).then_some((pixels.view, pixels.kind));
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
            highlight: None,
        });
        Ok(hold)
    }

    /// The message of a comparison just finished (it replaces any older one, an error of an
    /// earlier try included).
    fn done_message(&self) -> Option<Status> {
        let pixels = &self.current.as_ref()?.pixels;
        let CompareSource::File(path) = &pixels.source else {
            return None;
        };
        let matches = match pixels.kind {
            ImageKind::Colour => pixels.difference.colour_matches(),
            ImageKind::Depth => pixels.difference.depth_matches(),
        };
        Some(Status::info(format!(
            "compared {}: {}",
            path.display(),
            if matches { "match" } else { "differs" }
        )))
    }

    /// Points at the statement `index` of the answer on screen (`None`: at none): while it is
    /// pointed at, the compared image shows the difference with the pixels it explains
    /// highlighted (made once through `ctx`).
    pub(crate) fn point_at(&mut self, ctx: &egui::Context, index: Option<usize>) {
        self.pointed = index;
        let (Some(index), Some(current)) = (index, &mut self.current) else {
            return;
        };
        if current.highlight.as_ref().is_some_and(|(i, _)| *i == index) {
            return;
        }
        current.highlight = match current.pixels.explained_by.get(index) {
            Some(Some(flags)) => Some((
                index,
                ctx.load_texture(
                    "compare highlight",
                    to_colour_image(&heat_map_highlighted(&current.pixels.difference, flags)),
                    TextureOptions::NEAREST,
                ),
            )),
            _ => None,
        };
    }

    /// While a statement is pointed at: the difference with its pixels highlighted, the
    /// statement's index and how many pixels it explains.
    pub(crate) fn highlighted(&self) -> Option<(&TextureHandle, usize, usize)> {
        let current = self.current.as_ref()?;
        let (index, texture) = current.highlight.as_ref()?;
        (self.pointed == Some(*index)).then(|| {
            let count = current.pixels.explained_by[*index]
                .as_ref()
                .map_or(0, |flags| flags.iter().filter(|&&f| f).count());
            (texture, *index, count)
        })
    }

    /// Their pixel beside a trace of it, while their image is compared at the traced size: its
    /// value and, for a depth image, the t its grey stands for.
    pub(crate) fn their_pixel(&self, scene: &Scene, traced: &PixelTrace) -> Option<String> {
        let pixels = &self.current.as_ref()?.pixels;
        if !matches!(pixels.source, CompareSource::File(_))
            || pixels.theirs.dimensions() != traced.size_px
        {
            return None;
        }
        let row = traced.size_px.1 - 1 - traced.y_up_px;
        let pixel = pixels.theirs.get_pixel(traced.x_px, row).0;
        Some(match pixels.kind {
            ImageKind::Colour => traced.their_colour_line(pixel),
            ImageKind::Depth => {
                let drew = pixels.model.as_ref().and_then(|model| {
                    their_depth_at(
                        scene,
                        &pixels.view,
                        model,
                        (traced.x_px, traced.y_up_px),
                        pixel[0],
                    )
                });
                PixelTrace {
                    depth_range: Some(pixels.view.depth_range),
                    ..traced.clone()
                }
                .their_depth_line(pixel[0], drew)
            }
        })
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

/// What a comparison is made against: the open scene, the view on screen, and the context woken
/// when the comparison is done.
pub(crate) struct Against {
    pub(crate) ctx: egui::Context,
    pub(crate) scene: Arc<Scene>,
    pub(crate) view: View,
}

impl CompareState {
    /// Opens the image at `path` and compares it with the exact render of the open scene (and
    /// watches the file, to compare it again when their program writes it again).
    pub(crate) fn with_file(
        &mut self,
        against: &Against,
        path: PathBuf,
        kind: ImageKind,
    ) -> Option<Status> {
        let ctx = against.ctx.clone();
        let forced = self.kind_forced;
        let watched = FileWatcher::watch(&path, move || ctx.request_repaint())
            .ok()
            .map(|watcher| (path.clone(), kind, forced, watcher));
        let status = self.with_image(against, path, kind, read_their_image);
        self.watched = watched;
        status
    }

    /// Compares the image `read` gets for `path` (a file, or a browser page's dropped or picked
    /// file: its bytes, decoded) with the exact render, unwatched.
    pub(crate) fn with_image(
        &mut self,
        against: &Against,
        path: PathBuf,
        kind: ImageKind,
        read: impl FnOnce(&Path) -> Result<RgbImage, TheirImageError> + Send + 'static,
    ) -> Option<Status> {
        self.watched = None;
        let forced = std::mem::take(&mut self.kind_forced);
        self.theirs(against, path, kind, None, forced, read)
    }

    /// Compares the image `read` gets for `path` with the exact render, in the background: a
    /// depth image under `range`, or with `None` under the range read back from it. As `kind`
    /// where it was clicked (`forced`) or a range is given; else as the kind its content and
    /// name say ([`recognised_kind`]), which the answer says when it is not `kind`.
    fn theirs(
        &mut self,
        against: &Against,
        path: PathBuf,
        kind: ImageKind,
        range: Option<DepthRange>,
        forced: bool,
        read: impl FnOnce(&Path) -> Result<RgbImage, TheirImageError> + Send + 'static,
    ) -> Option<Status> {
        let scene = Arc::clone(&against.scene);
        let fallback = against.view.depth_range;
        self.kind = kind;
        self.start(&against.ctx, move || {
            let theirs = read(&path).map_err(|error| error.to_string())?;
            let (kind, assumed) = if forced || range.is_some() {
                (kind, None)
            } else {
                recognised_kind(&scene, &path, &theirs, kind)
            };
            let mut pixels = compare_file(&scene, &path, theirs, kind, range, fallback)?;
            pixels.kind_assumed = assumed;
            Ok(pixels)
        })
    }

    /// Measures `quality` against the exact render on the view on screen.
    pub(crate) fn with_quality(&mut self, against: &Against, quality: Quality) -> Option<Status> {
        let scene = Arc::clone(&against.scene);
        let view = against.view;
        self.start(&against.ctx, move || {
            compare_quality(&scene, &view, &quality)
        })
    }

    /// Takes a finished comparison in ([`CompareState::poll`]); with their image, holds `view`
    /// at the file's camera and their size, and says the outcome in `status`. A depth image sets
    /// the depth range to the one it was judged under (read back from it), and follows the depth
    /// range after: it is judged again under the range the user sets. Their file written again
    /// (and settled) is read and judged again.
    pub(crate) fn take_in(
        &mut self,
        ctx: &egui::Context,
        scene: &Arc<Scene>,
        view: &mut View,
        status: &mut Option<Status>,
    ) {
        // Made only when a comparison starts again, not on every frame.
        let against = |view: View| Against {
            ctx: ctx.clone(),
            scene: Arc::clone(scene),
            view,
        };
        // (Asked only between comparisons: a change seen while one runs waits for it.)
        let seen = self
            .watched
            .as_ref()
            .filter(|_| !self.busy())
            .map(|(path, kind, forced, watcher)| (path, *kind, *forced, watcher.poll()));
        match seen {
            Some((path, kind, forced, WatchState::Changed)) => {
                let path = path.clone();
                let again = against(*view);
                let said = self.theirs(&again, path, kind, None, forced, read_their_image_settled);
                say(status, said);
                return;
            }
            Some((_, _, _, WatchState::Settling(wait))) => ctx.request_repaint_after(wait),
            _ => {}
        }
        if !self.busy() {
            // The other kind clicked: their image on screen is judged as that at once.
            if self.kind_forced
                && let Some(current) = &self.current
                && let CompareSource::File(path) = &current.pixels.source
                && current.pixels.kind != self.kind
            {
                let (path, theirs, kind) = (path.clone(), current.pixels.theirs.clone(), self.kind);
                self.kind_forced = false;
                if let Some(watched) = &mut self.watched {
                    (watched.1, watched.2) = (kind, true);
                }
                let again = against(*view);
                let said = self.theirs(&again, path, kind, None, true, move |_| Ok(theirs));
                say(status, said);
                return;
            }
            let range = view.depth_range;
            if let Some((path, theirs)) = self.stale_depth_image(range) {
                let again = against(*view);
                let said = self.theirs(
                    &again,
                    path,
                    ImageKind::Depth,
                    Some(range),
                    true,
                    move |_| Ok(theirs),
                );
                say(status, said);
            }
            return;
        }
        match self.poll(ctx) {
            Ok(None) => {}
            Ok(Some((held, kind))) => {
                self.kind = kind;
                let depth_range = match kind {
                    ImageKind::Depth => held.depth_range,
                    ImageKind::Colour => view.depth_range,
                };
                *view = View {
                    depth_range,
                    ..held
                };
                *status = self.done_message();
            }
            Err(error) => *status = Some(error),
        }
    }
}
