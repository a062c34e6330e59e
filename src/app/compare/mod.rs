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
mod given;
mod kind;
mod pixels;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use egui::{ColorImage, TextureHandle, TextureOptions};
use image::RgbImage;

pub(crate) use given::Against;
use given::{Given, Job};
pub use kind::{ImageKind, dropped_image_kind, recognised_kind};
pub use pixels::{
    CompareShow, CompareSource, ComparisonPixels, QualityFigures, RangeSource, compare_file,
    compare_quality,
};
pub(crate) use pixels::{OFF_LEVELS, REFERENCE_SAMPLES};

use super::background::{Poll, Task};
use super::status::{Status, say};
use crate::compare::judge::their_depth_at;
use crate::compare::picture::{heat_map, heat_map_highlighted, heat_map_marked};
use crate::compare::their_image::{TheirImageError, read_their_image};
use crate::explore::trace::PixelTrace;
use crate::render::{Quality, View};
use crate::scene::Scene;

/// A comparison on screen.
pub(crate) struct Comparison {
    pub(crate) pixels: ComparisonPixels,
    pub(crate) theirs_texture: TextureHandle,
    pub(crate) heat_texture: TextureHandle,
    /// The image judged with it, if any: its picture and its difference.
    pub(crate) paired_textures: Option<(TextureHandle, TextureHandle)>,
    /// The differences with one statement's pixels highlighted: the statement's index, and the
    /// picture of each image (this one, then the one judged with it) where it explains pixels.
    highlight: Option<(usize, [Option<TextureHandle>; 2])>,
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
    /// Their images given and watched ([`given::Inputs`]).
    inputs: given::Inputs,
    /// How many times the comparison was closed, by the user or by another scene opened (a
    /// page stops its watches at each).
    pub(crate) closes: u64,
}
/// The pictures of one compared image: theirs, and the heat map of the difference (its
/// unexplained pixels marked), named with `suffix`.
fn textures(
    ctx: &egui::Context,
    pixels: &ComparisonPixels,
    suffix: &str,
) -> (TextureHandle, TextureHandle) {
    let theirs = ctx.load_texture(
        format!("compare theirs{suffix}"),
        to_colour_image(&pixels.theirs),
        TextureOptions::NEAREST,
    );
    let heat = ctx.load_texture(
        format!("compare heat{suffix}"),
        to_colour_image(&match &pixels.unexplained {
            Some(unexplained) => heat_map_marked(&pixels.difference, unexplained),
            None => heat_map(&pixels.difference),
        }),
        TextureOptions::NEAREST,
    );
    (theirs, heat)
}

/// An RGB image as an egui image.
fn to_colour_image(image: &RgbImage) -> ColorImage {
    ColorImage::from_rgb(
        [image.width() as usize, image.height() as usize],
        image.as_raw(),
    )
}

impl CompareState {
    /// Their image files being compared (and watched): one, or a colour and a depth image.
    pub(crate) fn watched_files(&self) -> [Option<&Path>; 2] {
        self.inputs.files()
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
        self.inputs.clear();
        self.closes += 1;
    }

    /// Takes the comparison off the screen (a failed one, or one closed); their file stays
    /// watched, so a good version written later is compared.
    fn drop_result(&mut self) {
        self.current = None;
        self.pending = None;
        self.show = CompareShow::Rendered;
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
        let (theirs_texture, heat_texture) = textures(ctx, &pixels, "");
        let paired_textures = pixels
            .paired
            .as_deref()
            .map(|paired| textures(ctx, paired, " paired"));
        if first || matches!(pixels.source, CompareSource::Quality(_)) {
            self.show = CompareShow::Difference;
        }
        self.current = Some(Comparison {
            pixels,
            theirs_texture,
            heat_texture,
            paired_textures,
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
        let together = match &pixels.paired {
            Some(paired) => format!(" with {}, together", paired.name()),
            None => String::new(),
        };
        let matches = pixels.images().all(ComparisonPixels::matches);
        Some(Status::info(format!(
            "compared {}{together}: {}",
            path.display(),
            if matches { "match" } else { "differs" }
        )))
    }

    /// Points at the statement `index` of the answer on screen (`None`: at none): while it is
    /// pointed at, each compared image (both of a pair) shows its difference with the pixels
    /// the statement explains there highlighted (made once through `ctx`).
    pub(crate) fn point_at(&mut self, ctx: &egui::Context, index: Option<usize>) {
        self.pointed = index;
        let (Some(index), Some(current)) = (index, &mut self.current) else {
            return;
        };
        if current.highlight.as_ref().is_some_and(|(i, _)| *i == index) {
            return;
        }
        let texture = |pixels: &ComparisonPixels| match pixels.explained_by.get(index) {
            Some(Some(flags)) => Some(ctx.load_texture(
                "compare highlight",
                to_colour_image(&heat_map_highlighted(&pixels.difference, flags)),
                TextureOptions::NEAREST,
            )),
            _ => None,
        };
        let pixels = &current.pixels;
        let textures = [texture(pixels), pixels.paired.as_deref().and_then(texture)];
        current.highlight = Some((index, textures));
    }

    /// While a statement is pointed at, for the compared image (`paired`: the one judged with
    /// it): its difference with the statement's pixels highlighted, the statement's index and
    /// how many of that image's pixels it explains.
    pub(crate) fn highlighted(&self, paired: bool) -> Option<(&TextureHandle, usize, usize)> {
        let current = self.current.as_ref()?;
        let (index, textures) = current.highlight.as_ref()?;
        let (pixels, texture) = if paired {
            (current.pixels.paired.as_deref()?, textures[1].as_ref()?)
        } else {
            (&current.pixels, textures[0].as_ref()?)
        };
        (self.pointed == Some(*index)).then(|| {
            let count = pixels.explained_by[*index]
                .as_ref()
                .map_or(0, |flags| flags.iter().filter(|&&f| f).count());
            (texture, *index, count)
        })
    }

    /// Their pixel beside a trace of it, while their image is compared at the traced size: its
    /// value and, for a depth image, the t its grey stands for (both images of a pair).
    pub(crate) fn their_pixel(&self, scene: &Scene, traced: &PixelTrace) -> Option<String> {
        let pixels = &self.current.as_ref()?.pixels;
        if !matches!(pixels.source, CompareSource::File(_))
            || pixels.theirs.dimensions() != traced.size_px
        {
            return None;
        }
        let row = traced.size_px.1 - 1 - traced.y_up_px;
        let mut images: Vec<&ComparisonPixels> = pixels.images().collect();
        images.sort_by_key(|image| image.kind.index());
        let lines = images.into_iter().map(|image| {
            let pixel = image.theirs.get_pixel(traced.x_px, row).0;
            match image.kind {
                ImageKind::Colour => traced.their_colour_line(pixel),
                ImageKind::Depth => {
                    let drew = image.model.as_ref().and_then(|model| {
                        their_depth_at(
                            scene,
                            &image.view,
                            model,
                            (traced.x_px, traced.y_up_px),
                            pixel[0],
                        )
                    });
                    PixelTrace {
                        depth_range: Some(image.view.depth_range),
                        ..traced.clone()
                    }
                    .their_depth_line(pixel[0], drew)
                }
            }
        });
        Some(lines.collect())
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

    /// The probe's lines for the compared images at pixel `px` (y up): theirs, exact,
    /// difference; one line for each image of a pair, named by its kind.
    pub(crate) fn probe_lines(&self, px: glam::DVec2) -> Vec<String> {
        let Some(current) = &self.current else {
            return Vec::new();
        };
        let paired = current.pixels.paired.is_some();
        let mut images: Vec<&ComparisonPixels> = current.pixels.images().collect();
        images.sort_by_key(|image| image.kind.index());
        images
            .into_iter()
            .filter_map(|pixels| probe_line(pixels, px, paired))
            .collect()
    }
}

/// The probe's line for one compared image at pixel `px` (y up), named by its kind when it is
/// one of a pair.
fn probe_line(pixels: &ComparisonPixels, px: glam::DVec2, paired: bool) -> Option<String> {
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
        CompareSource::File(_) if paired => format!("{} theirs", pixels.kind.word()),
        CompareSource::File(_) => "theirs".to_owned(),
        CompareSource::Quality(_) => "chosen".to_owned(),
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

impl CompareState {
    /// Opens the image at `path` and compares it with the exact render of the open scene (with
    /// the image of the other kind on screen, if any, as a pair), and watches the file, to
    /// compare it again when their program writes it again.
    pub(crate) fn with_file(
        &mut self,
        against: &Against,
        path: PathBuf,
        kind: ImageKind,
    ) -> Option<Status> {
        self.inputs
            .watch(&path, kind, self.kind_forced, &against.ctx);
        self.with_image(against, path, kind, read_their_image)
    }

    /// Compares the image `read` gets for `path` (a file, or a browser page's dropped or picked
    /// file: its bytes, decoded) with the exact render; with the image of the other kind on
    /// screen, if any, as a pair. Given while another comparison is computed, it waits for it.
    pub(crate) fn with_image(
        &mut self,
        against: &Against,
        path: PathBuf,
        kind: ImageKind,
        read: impl FnOnce(&Path) -> Result<RgbImage, TheirImageError> + Send + 'static,
    ) -> Option<Status> {
        let forced = std::mem::take(&mut self.kind_forced);
        let given = Given::new(path, kind, forced, read);
        if self.busy() {
            self.inputs.queue(given);
            return None;
        }
        let job = Job::beside(given, self.current.as_ref().map(|c| &c.pixels));
        self.run(against, job)
    }

    /// Starts `job` in the background.
    fn run(&mut self, against: &Against, job: Job) -> Option<Status> {
        self.kind = job.kind();
        let work = job.work(against);
        self.start(&against.ctx, work)
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
    /// (and settled) is read and judged again, and so is the image on screen when the other
    /// kind is clicked; an image given while one was judged is judged next.
    pub(crate) fn take_in(
        &mut self,
        ctx: &egui::Context,
        scene: &Arc<Scene>,
        view: &mut View,
        status: &mut Option<Status>,
    ) {
        if !self.busy() {
            // (Asked only between comparisons: a change seen while one runs waits for it.)
            let (changed, settling) = self.inputs.poll();
            let mut clicked = self.kind_forced.then_some(self.kind);
            let current = self.current.as_ref().map(|c| &c.pixels);
            let job = self
                .inputs
                .again(current, &mut clicked, changed, view.depth_range);
            if self.kind_forced && clicked.is_none() {
                self.kind_forced = false;
            }
            if let Some(job) = job {
                let against = Against {
                    ctx: ctx.clone(),
                    scene: Arc::clone(scene),
                    view: *view,
                };
                let said = self.run(&against, job);
                say(status, said);
            } else if let Some(wait) = settling {
                ctx.request_repaint_after(wait);
            }
            return;
        }
        match self.poll(ctx) {
            Ok(None) => {}
            Ok(Some((held, kind))) => {
                self.kind = kind;
                let has_depth = self
                    .current
                    .as_ref()
                    .is_some_and(|c| c.pixels.images().any(|i| i.kind == ImageKind::Depth));
                let depth_range = if has_depth {
                    held.depth_range
                } else {
                    view.depth_range
                };
                *view = View {
                    depth_range,
                    ..held
                };
                if let Some(current) = &self.current {
                    self.inputs.keep_on_screen(&current.pixels);
                }
                *status = self.done_message();
            }
            Err(error) => *status = Some(error),
        }
        // The next look comes at once: an image waits, or a watched file changed meanwhile.
        if !self.busy() {
            ctx.request_repaint();
        }
    }
}
