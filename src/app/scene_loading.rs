//! Opening and reloading scene files off the UI thread. A million-sphere file takes about a
//! second to read and parse; meanwhile the viewer keeps drawing (the previous scene stays on
//! screen and stays explorable) and, once a load has run for [`SHOW_PROGRESS_AFTER`], shows its
//! progress. A finished load is adopted here: an open replaces the view and watches the file, a
//! reload keeps the user's camera unless it was still the file's. [`OpenScene`] holds the open
//! scene with its load, watcher and error: the viewer's "scene and loading" feature.

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::ViewerApp;
use super::background::{Poll, Task};
use super::loaded_scene::LoadedScene;
use super::reload::FileWatcher;
use super::saved_views::SceneViews;
use super::status::Status;
use crate::render::View;

/// Loads shorter than this show no progress (most scenes load in a few milliseconds).
pub(crate) const SHOW_PROGRESS_AFTER: Duration = Duration::from_millis(500);

/// The open scene and what goes with it: the viewer's "scene and loading" feature.
pub(crate) struct OpenScene {
    /// The scene on screen.
    pub(crate) loaded: LoadedScene,
    /// Incremented whenever another scene is loaded, so the same view of a new scene re-renders.
    pub(crate) epoch: u64,
    /// The last failed open or reload's error, shown over the images until dismissed.
    pub(crate) error: Option<String>,
    /// A file that failed to open: Reload and the watcher try it again.
    pub(crate) failed_open: Option<PathBuf>,
    /// Watches the open file (or the failed one) for changes.
    pub(crate) watcher: Option<FileWatcher>,
    /// A load running in the background.
    pub(crate) loading: Option<PendingLoad>,
    /// "Save view as scene" is writing over the open scene (its reload keeps the save's message).
    pub(crate) saving_over: bool,
}

impl OpenScene {
    /// `loaded` open, nothing else going on.
    pub(crate) fn new(loaded: LoadedScene) -> Self {
        Self {
            loaded,
            epoch: 0,
            error: None,
            failed_open: None,
            watcher: None,
            loading: None,
            saving_over: false,
        }
    }
}

/// Why a scene is loaded: the viewer adopts a reload differently from an open.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LoadKind {
    /// A file the user opened.
    Open,
    /// The open file again (changed on disk, or Reload).
    Reload,
}

/// A load running in the background.
#[derive(Debug)]
pub(crate) struct PendingLoad {
    /// The file being loaded.
    pub(crate) path: PathBuf,
    /// Open or reload.
    pub(crate) kind: LoadKind,
    /// The scene comes as bytes, from no file (see [`LoadedScene::in_memory`]).
    pub(crate) from_bytes: bool,
    task: Task<Result<LoadedScene, String>>,
}

impl PendingLoad {
    /// Starts loading `path` (image size `size_px` for the scene's initial view).
    pub(crate) fn start(
        path: &Path,
        kind: LoadKind,
        size_px: (u32, u32),
        ctx: &egui::Context,
    ) -> std::io::Result<Self> {
        let thread_path = path.to_path_buf();
        let task = Task::spawn("scene-load", ctx, move |progress| {
            LoadedScene::load_with_progress(&thread_path, size_px, &|share| {
                progress.report(share);
            })
            .map_err(|error| error.to_string())
        })?;
        Ok(Self {
            path: path.to_path_buf(),
            kind,
            from_bytes: false,
            task,
        })
    }

    /// Starts parsing the scene `bytes` named `name` (a browser page's file).
    pub(crate) fn start_bytes(
        name: &str,
        bytes: std::sync::Arc<[u8]>,
        size_px: (u32, u32),
        ctx: &egui::Context,
    ) -> std::io::Result<Self> {
        let thread_name = name.to_owned();
        let task = Task::spawn("scene-load", ctx, move |_| {
            LoadedScene::from_bytes(&thread_name, &bytes, size_px)
                .map_err(|error| error.to_string())
        })?;
        Ok(Self {
            path: PathBuf::from(name),
            kind: LoadKind::Open,
            from_bytes: true,
            task,
        })
    }

    /// The share of the load done, in [0, 1].
    pub(crate) fn fraction(&self) -> f32 {
        self.task.fraction()
    }

    /// Whether the load has run long enough to show its progress.
    pub(crate) fn shows_progress(&self) -> bool {
        self.task.elapsed() >= SHOW_PROGRESS_AFTER
    }
}

impl OpenScene {
    /// Starts loading the scene at `path` in the background (its initial view `size_px`); `ctx`
    /// is asked to repaint when it is in. A load that cannot start puts its error on screen.
    fn start_load(
        &mut self,
        path: &Path,
        kind: LoadKind,
        size_px: (u32, u32),
        ctx: &egui::Context,
    ) {
        match PendingLoad::start(path, kind, size_px, ctx) {
            Ok(pending) => self.loading = Some(pending),
            Err(error) => {
                self.error = Some(format!("{}: cannot start loading: {error}", path.display()));
            }
        }
    }

    /// Starts loading the scene `bytes` named `name`, as [`Self::start_load`].
    fn start_bytes(
        &mut self,
        name: &str,
        bytes: std::sync::Arc<[u8]>,
        size_px: (u32, u32),
        ctx: &egui::Context,
    ) {
        match PendingLoad::start_bytes(name, bytes, size_px, ctx) {
            Ok(pending) => self.loading = Some(pending),
            Err(error) => self.error = Some(format!("{name}: cannot start loading: {error}")),
        }
    }

    /// What Reload loads: a file that failed to open (it may have been fixed) or the open file;
    /// why not, for the embedded scene or one that came from a page.
    fn reload_target(&self) -> Result<(PathBuf, LoadKind), Status> {
        if let Some(failed) = &self.failed_open {
            return Ok((failed.clone(), LoadKind::Open));
        }
        let Some(path) = &self.loaded.path else {
            return Err(Status::info(
                "the embedded default scene has no file to reload",
            ));
        };
        if self.loaded.in_memory {
            return Err(Status::info(format!(
                "{} came from the page, not from a file: open it again to reload it",
                path.display()
            )));
        }
        Ok((path.clone(), LoadKind::Reload))
    }

    /// Takes a finished load: the scene, its file and why it was loaded. A failed one puts its
    /// error on screen (and a file that failed to open is watched, so that fixing it opens it);
    /// one still running asks `ctx` to look again soon.
    fn poll(&mut self, ctx: &egui::Context) -> Option<(LoadedScene, PathBuf, LoadKind)> {
        let pending = self.loading.as_ref()?;
        let result = match pending.task.poll() {
            Poll::Running => {
                let wait = if pending.shows_progress() {
                    Duration::from_millis(50)
                } else {
                    SHOW_PROGRESS_AFTER
                };
                ctx.request_repaint_after(wait);
                return None;
            }
            Poll::Done(result) => result,
            Poll::Lost => Err(format!(
                "{}: the loading thread stopped",
                pending.path.display()
            )),
        };
        let (path, kind, from_bytes) = (pending.path.clone(), pending.kind, pending.from_bytes);
        self.loading = None;
        match result {
            Ok(loaded) => Some((loaded, path, kind)),
            Err(error) => {
                self.error = Some(error);
                if kind == LoadKind::Open && !from_bytes {
                    self.failed_open = Some(path.clone());
                    let ctx = ctx.clone();
                    // A file that does not exist cannot be watched; Reload still tries it again.
                    self.watcher = FileWatcher::watch(&path, move || ctx.request_repaint()).ok();
                }
                None
            }
        }
    }

    /// Puts `loaded` on screen, a new load (the same view of it renders again), its error gone.
    fn adopt(&mut self, loaded: LoadedScene) {
        self.loaded = loaded;
        self.epoch += 1;
        self.error = None;
    }
}

impl ViewerApp {
    /// Starts loading the scene at `path` in the background; once read, it replaces the scene
    /// on screen and is watched for changes. On failure the error is shown and the previous scene
    /// stays. A load started while another runs replaces it.
    pub fn open(&mut self, path: &Path) {
        let size = (self.viewing.view.width_px, self.viewing.view.height_px);
        self.scene.start_load(path, LoadKind::Open, size, &self.ctx);
    }

    /// Opens the scene `bytes` named `name`, which came from no file the viewer can read (a
    /// browser page's dropped, picked or fetched file): as [`Self::open`], without a file to
    /// reload or watch.
    pub fn open_bytes(&mut self, name: &str, bytes: std::sync::Arc<[u8]>) {
        let size = (self.viewing.view.width_px, self.viewing.view.height_px);
        self.scene.start_bytes(name, bytes, size, &self.ctx);
    }

    /// Reads the open file again (in the background). A broken file shows its error and the last
    /// good scene stays; a good one replaces the scene and keeps the user's camera unless it was
    /// still the file's.
    pub(crate) fn reload(&mut self) {
        match self.scene.reload_target() {
            Ok((path, kind)) => {
                let size = (self.viewing.view.width_px, self.viewing.view.height_px);
                self.scene.start_load(&path, kind, size, &self.ctx);
            }
            Err(status) => self.status = Some(status),
        }
    }

    /// Takes a finished load ([`OpenScene::poll`]) and puts it on screen: an open in the view it
    /// was last seen in, a reload in the user's camera unless that was still the file's.
    pub(super) fn poll_load(&mut self) {
        let Some((loaded, path, kind)) = self.scene.poll(&self.ctx) else {
            return;
        };
        match kind {
            LoadKind::Open => self.adopt_opened(loaded, &path),
            LoadKind::Reload => {
                let still_file_view = View {
                    width_px: self.scene.loaded.file_view.width_px,
                    height_px: self.scene.loaded.file_view.height_px,
                    ..self.viewing.view
                } == self.scene.loaded.file_view;
                self.adopt(loaded, !still_file_view);
                // After our own save over the open scene, the save's message stays.
                if !std::mem::take(&mut self.scene.saving_over) {
                    self.status = Some(Status::info(format!("reloaded {}", path.display())));
                }
            }
        }
    }

    /// Puts a newly opened scene on screen in the view it was last seen in (if it was), remembers
    /// it and watches its file.
    fn adopt_opened(&mut self, loaded: LoadedScene, path: &Path) {
        self.remember_view();
        self.scene.failed_open = None;
        // Exports are named after the scene on screen, unless the user chose a name.
        let export = &mut self.settings.export;
        if let Some(followed) = crate::export::export_path_following(
            &export.path,
            &crate::export::name_in_folder(self.scene.loaded.path.as_deref()),
            &crate::export::name_in_folder(Some(path)),
        ) {
            export.path = followed;
        }
        // An older message (an error of an earlier try included) is not left beside it.
        self.status = Some(Status::info(format!("opened {}", path.display())));
        self.adopt(loaded, false);
        if let Some(last) = self.settings.views.last.get(&SceneViews::key(path)) {
            self.viewing.view = last.applied_to(&self.viewing.view);
        }
        self.viewing.history.reset(&self.viewing.view);
        self.viewing.magnifier = Default::default();
        self.viewing.probe.pinned_world = None;
        self.panels.fields.path_text = path.display().to_string();
        self.set_title(&format!("raytracer — {}", path.display()));
        if self.scene.loaded.in_memory {
            // No file to open again at the next start, or to watch.
            self.scene.watcher = None;
            return;
        }
        self.settings.last_scene = Some(path.to_path_buf());
        let ctx = self.ctx.clone();
        self.scene.watcher = match FileWatcher::watch(path, move || ctx.request_repaint()) {
            Ok(watcher) => Some(watcher),
            Err(error) => {
                self.status = Some(Status::error(format!("live reload is off: {error}")));
                None
            }
        };
    }

    /// Puts `loaded` on screen; `keep_view` keeps the current camera and depth range.
    fn adopt(&mut self, loaded: LoadedScene, keep_view: bool) {
        self.scene.adopt(loaded);
        if !keep_view {
            self.viewing.view = View {
                width_px: self.viewing.view.width_px,
                height_px: self.viewing.view.height_px,
                ..self.scene.loaded.file_view
            };
        }
    }
}
