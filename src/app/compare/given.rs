//! Their images given to the Compare section, and when they are judged again.
//!
//! An image is given by a typed path, a file dialog, a drop, or (on the page) its bytes. Where an
//! image of the other kind, at the same size, is on screen, the two are judged together, as the
//! grader does (a colour image then its depth image, or both dropped at once); an image of the
//! same kind, or another size, replaces what is on screen. The comparison is made again when
//! their program writes a watched file again, when the other kind is clicked, and when a depth
//! image's range is set ([`Inputs::again`]).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use image::RgbImage;

use super::kind::{ImageKind, recognised_kind};
use super::pixels::{CompareSource, ComparisonPixels, compare_file};
use crate::app::reload::{FileWatcher, WatchState};
use crate::compare::their_image::{TheirImageError, read_their_image_settled};
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::Scene;

/// How an image's pixels are had: a file read, a page's bytes decoded, or pixels on screen.
type Reader = Box<dyn FnOnce(&Path) -> Result<RgbImage, TheirImageError> + Send>;

/// An image to judge.
pub(crate) struct Given {
    /// Its name (its file's path).
    path: PathBuf,
    /// The kind it is taken for.
    kind: ImageKind,
    /// The kind is fixed (clicked, or known from the comparison it was in): its content and name
    /// are not asked.
    forced: bool,
    /// How its pixels are had.
    read: Reader,
}

impl Given {
    /// The image `read` gets for `path`, taken for `kind` (`forced`: whatever its content says).
    pub(crate) fn new(
        path: PathBuf,
        kind: ImageKind,
        forced: bool,
        read: impl FnOnce(&Path) -> Result<RgbImage, TheirImageError> + Send + 'static,
    ) -> Self {
        Self {
            path,
            kind,
            forced,
            read: Box::new(read),
        }
    }
}

/// What a comparison is made against: the open scene, the view on screen, and the context woken
/// when the comparison is done.
pub(crate) struct Against {
    pub(crate) ctx: egui::Context,
    pub(crate) scene: Arc<Scene>,
    pub(crate) view: View,
}

/// A comparison of their image to make: the image, the images that may be judged with it, and
/// the depth range (`None`: the one read back from their depth image).
pub(crate) struct Job {
    given: Given,
    partners: Vec<Given>,
    range: Option<DepthRange>,
}

impl Job {
    /// `given`, with the images of `current` (on screen) as its possible partners.
    pub(crate) fn beside(given: Given, current: Option<&ComparisonPixels>) -> Self {
        Self {
            given,
            partners: on_screen(current),
            range: None,
        }
    }

    /// The kind the image is given as.
    pub(crate) fn kind(&self) -> ImageKind {
        self.given.kind
    }

    /// The work, to run off the UI thread: the image read, its kind recognised where it is not
    /// fixed and no range is given ([`recognised_kind`], said in the answer when it is not the
    /// kind given), and judged with the first partner of the other kind at the same size.
    pub(crate) fn work(
        self,
        against: &Against,
    ) -> impl FnOnce() -> Result<ComparisonPixels, String> + Send + 'static {
        let scene = Arc::clone(&against.scene);
        let fallback = against.view.depth_range;
        move || {
            let Self {
                given,
                partners,
                range,
            } = self;
            let path = given.path;
            let theirs = (given.read)(&path).map_err(|error| error.to_string())?;
            let (kind, assumed) = if given.forced || range.is_some() {
                (given.kind, None)
            } else {
                recognised_kind(&scene, &path, &theirs, given.kind)
            };
            // A partner that cannot be read (gone, or being written) leaves this one alone.
            // (Never the same file: an image is not judged with its own older version.)
            let partner = partners
                .into_iter()
                .find(|partner| partner.kind != kind && partner.path != path)
                .and_then(|partner| {
                    let image = (partner.read)(&partner.path).ok()?;
                    (image.dimensions() == theirs.dimensions()).then_some((partner.path, image))
                });
            let mut pixels = compare_file(&scene, &path, theirs, kind, partner, range, fallback)?;
            pixels.kind_assumed = assumed;
            Ok(pixels)
        }
    }
}

/// The images on screen as pixels to judge again, each as the kind it was judged as.
fn on_screen(current: Option<&ComparisonPixels>) -> Vec<Given> {
    let Some(pixels) = current.filter(|p| matches!(p.source, CompareSource::File(_))) else {
        return Vec::new();
    };
    pixels
        .images()
        .filter_map(|image| {
            let CompareSource::File(path) = &image.source else {
                return None;
            };
            let theirs = image.theirs.clone();
            Some(Given::new(path.clone(), image.kind, true, move |_| {
                Ok(theirs)
            }))
        })
        .collect()
}

/// Their image file, watched: written again, the comparison is made again.
struct Watched {
    path: PathBuf,
    /// The kind it was given as, and whether that kind is fixed.
    kind: ImageKind,
    forced: bool,
    watcher: FileWatcher,
}

/// Their images given and watched: the files watched (the image given last first, then the one
/// judged with it), and an image given while a comparison was being computed, judged when that
/// one is done (so two images dropped at once are judged together).
#[derive(Default)]
pub(crate) struct Inputs {
    watched: Vec<Watched>,
    queued: Option<Given>,
}

impl Inputs {
    /// Watches their file at `path`, given as `kind` (`forced`: clicked); `ctx` wakes at each
    /// change.
    pub(crate) fn watch(
        &mut self,
        path: &Path,
        kind: ImageKind,
        forced: bool,
        ctx: &egui::Context,
    ) {
        let ctx = ctx.clone();
        if let Ok(watcher) = FileWatcher::watch(path, move || ctx.request_repaint()) {
            self.watched.retain(|watched| watched.path != path);
            let path = path.to_path_buf();
            let watched = Watched {
                path,
                kind,
                forced,
                watcher,
            };
            self.watched.insert(0, watched);
        }
    }

    /// The files watched: one, or a colour and a depth image.
    pub(crate) fn files(&self) -> [Option<&Path>; 2] {
        let path = |index: usize| self.watched.get(index).map(|w| w.path.as_path());
        [path(0), path(1)]
    }

    /// Watches nothing, and forgets an image waiting.
    pub(crate) fn clear(&mut self) {
        self.watched.clear();
        self.queued = None;
    }

    /// `given` waits for the comparison being computed.
    pub(crate) fn queue(&mut self, given: Given) {
        self.queued = Some(given);
    }

    /// Whether a watched file changed (and settled) since the last look, and else how long to
    /// wait for one still settling.
    pub(crate) fn poll(&self) -> (bool, Option<Duration>) {
        let states: Vec<WatchState> = self.watched.iter().map(|w| w.watcher.poll()).collect();
        let settling = states.iter().find_map(|state| match state {
            WatchState::Settling(wait) => Some(*wait),
            _ => None,
        });
        (states.contains(&WatchState::Changed), settling)
    }

    /// What to judge again now, if anything (asked between comparisons; `current` is on
    /// screen): an image waiting; the watched files when one `changed` (read again; an image on
    /// screen not watched stays beside them); the other kind clicked (`clicked`, taken: the
    /// images on screen swap kinds); or a depth image judged under another range than
    /// `depth_range` (judged under it).
    pub(crate) fn again(
        &mut self,
        current: Option<&ComparisonPixels>,
        clicked: &mut Option<ImageKind>,
        changed: bool,
        depth_range: DepthRange,
    ) -> Option<Job> {
        if let Some(queued) = self.queued.take() {
            return Some(Job::beside(queued, current));
        }
        if changed {
            // A partner that cannot be read now (being written, or gone) stays as it is on
            // screen, so the pair holds.
            let shown_pixels = |path: &Path| {
                let mut images = current.into_iter().flat_map(ComparisonPixels::images);
                let image =
                    images.find(|i| matches!(&i.source, CompareSource::File(p) if p == path));
                image.map(|image| image.theirs.clone())
            };
            let mut files = self.watched.iter().enumerate().map(|(index, watched)| {
                let fallback = (index > 0).then(|| shown_pixels(&watched.path)).flatten();
                let read = move |file: &Path| {
                    read_their_image_settled(file).or_else(|error| fallback.ok_or(error))
                };
                Given::new(watched.path.clone(), watched.kind, watched.forced, read)
            });
            let given = files.next()?;
            let mut partners: Vec<Given> = files.collect();
            let watched: Vec<&Path> = self.watched.iter().map(|w| w.path.as_path()).collect();
            partners.extend(
                on_screen(current)
                    .into_iter()
                    .filter(|image| !watched.contains(&image.path.as_path())),
            );
            let range = None;
            return Some(Job {
                given,
                partners,
                range,
            });
        }
        // Asked at every frame: the images on screen are copied only when a job is made.
        let pixels = current.filter(|p| matches!(p.source, CompareSource::File(_)))?;
        let clicked = clicked.take_if(|kind| *kind != pixels.kind);
        let has_depth = pixels.images().any(|i| i.kind == ImageKind::Depth);
        let range_moved = has_depth && pixels.view.depth_range != depth_range;
        if clicked.is_none() && !range_moved {
            return None;
        }
        let mut images = on_screen(Some(pixels));
        let first = images.remove(0);
        let Some(kind) = clicked else {
            return Some(Job {
                given: first,
                partners: images,
                range: Some(depth_range),
            });
        };
        // The other kind clicked: the image is judged as that at once, its partner as the other.
        for watched in &mut self.watched {
            let now = if watched.path == first.path {
                kind
            } else {
                kind.other()
            };
            (watched.kind, watched.forced) = (now, true);
        }
        let partners = images
            .into_iter()
            .map(|partner| Given {
                kind: kind.other(),
                ..partner
            })
            .collect();
        let given = Given { kind, ..first };
        Some(Job {
            given,
            partners,
            range: None,
        })
    }

    /// Keeps watching only the files of `current` (an image replaced is no longer watched) and
    /// an image waiting, each as the kind it was judged as, the image given last first.
    pub(crate) fn keep_on_screen(&mut self, current: &ComparisonPixels) {
        let judged: Vec<(PathBuf, ImageKind)> = current
            .images()
            .filter_map(|image| match &image.source {
                CompareSource::File(path) => Some((path.clone(), image.kind)),
                CompareSource::Quality(_) => None,
            })
            .collect();
        let queued = self.queued.as_ref().map(|given| given.path.clone());
        self.watched.retain_mut(|watched| {
            let Some((_, kind)) = judged.iter().find(|(path, _)| *path == watched.path) else {
                // An image waiting to be judged stays watched.
                return queued.as_ref() == Some(&watched.path);
            };
            // The kind it was judged as; still recognised again at each write unless clicked.
            watched.kind = *kind;
            true
        });
        self.watched.sort_by_key(|watched| {
            judged
                .iter()
                .position(|(path, _)| *path == watched.path)
                .unwrap_or(0)
        });
    }
}
