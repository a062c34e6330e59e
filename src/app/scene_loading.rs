//! Opening and reloading scene files off the UI thread. A million-sphere file takes about a
//! second to read and parse; meanwhile the viewer keeps drawing (the previous scene stays on
//! screen and stays explorable) and, once a load has run for [`SHOW_PROGRESS_AFTER`], shows its
//! progress. A finished load is adopted here: an open replaces the view and watches the file, a
//! reload keeps the user's camera unless it was still the file's. [`OpenScene`] holds the open
//! scene with its load, watcher and error: the viewer's "scene and loading" feature.

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::actions::Write;
use super::background::{Poll, Task};
use super::loaded_scene::LoadedScene;
use super::reload::FileWatcher;
use super::status::Status;
use crate::platform::files::same_file;
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
    pub(crate) fn poll(&mut self, ctx: &egui::Context) -> Option<(LoadedScene, PathBuf, LoadKind)> {
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

impl OpenScene {
    /// Starts loading the scene at `path` for a view of `view`'s size; once read, it replaces the
    /// scene on screen and is watched for changes. On failure the error is shown and the previous
    /// scene stays. A load started while another runs replaces it.
    pub(crate) fn open(&mut self, path: &Path, view: &View, ctx: &egui::Context) {
        self.start_load(path, LoadKind::Open, (view.width_px, view.height_px), ctx);
    }

    /// Opens the scene `bytes` named `name`, which came from no file the viewer can read (a
    /// browser page's dropped, picked or fetched file): as [`Self::open`], without a file to
    /// reload or watch.
    pub(crate) fn open_bytes(
        &mut self,
        name: &str,
        bytes: std::sync::Arc<[u8]>,
        view: &View,
        ctx: &egui::Context,
    ) {
        self.start_bytes(name, bytes, (view.width_px, view.height_px), ctx);
    }

    /// Reads the open file again (in the background); says why not when there is none. A broken
    /// file shows its error and the last good scene stays.
    pub(crate) fn reload(&mut self, view: &View, ctx: &egui::Context) -> Option<Status> {
        match self.reload_target() {
            Ok((path, kind)) => {
                self.start_load(&path, kind, (view.width_px, view.height_px), ctx);
                None
            }
            Err(status) => Some(status),
        }
    }

    /// Takes a finished reload in: it replaces the scene and keeps the user's camera in `view`
    /// unless it was still the file's. Says so, unless it is our own save's reload.
    pub(crate) fn adopt_reload(
        &mut self,
        loaded: LoadedScene,
        path: &Path,
        view: &mut View,
    ) -> Option<Status> {
        let still_file_view = View {
            width_px: self.loaded.file_view.width_px,
            height_px: self.loaded.file_view.height_px,
            ..*view
        } == self.loaded.file_view;
        self.adopt(loaded);
        if still_file_view {
            *view = self.file_view_at(view);
        }
        // After our own save over the open scene, the save's message stays.
        (!std::mem::take(&mut self.saving_over))
            .then(|| Status::info(format!("reloaded {}", path.display())))
    }

    /// Takes a newly opened scene in: on screen in its file's camera (at `view`'s size), its file
    /// watched through `ctx` (a scene from no file is not). Says that it is open, or that the file
    /// cannot be watched.
    pub(crate) fn adopt_opened(
        &mut self,
        loaded: LoadedScene,
        path: &Path,
        view: &mut View,
        ctx: &egui::Context,
    ) -> Status {
        self.failed_open = None;
        self.adopt(loaded);
        *view = self.file_view_at(view);
        let opened = Status::info(format!("opened {}", path.display()));
        if self.loaded.in_memory {
            // No file to watch.
            self.watcher = None;
            return opened;
        }
        let ctx = ctx.clone();
        match FileWatcher::watch(path, move || ctx.request_repaint()) {
            Ok(watcher) => {
                self.watcher = Some(watcher);
                opened
            }
            Err(error) => {
                self.watcher = None;
                Status::error(format!("live reload is off: {error}"))
            }
        }
    }

    /// Notes a `write` starting: "save view as scene" over the open scene reloads it, and that
    /// reload keeps the save's message.
    pub(crate) fn note_write(&mut self, write: &Write) {
        if let Write::SaveViewTo(path) = write {
            let open = self.loaded.path.as_deref();
            self.saving_over = open.is_some_and(|open| same_file(open, path));
        }
    }

    /// The open scene's file camera and depth range at `view`'s image size.
    fn file_view_at(&self, view: &View) -> View {
        View {
            width_px: view.width_px,
            height_px: view.height_px,
            ..self.loaded.file_view
        }
    }
}
