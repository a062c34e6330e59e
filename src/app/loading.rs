//! Loading a scene file off the UI thread. A million-sphere file takes about a second to read
//! and parse; meanwhile the viewer keeps drawing (the previous scene stays on screen and stays
//! explorable) and, once a load has run for [`SHOW_PROGRESS_AFTER`], shows its progress.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::{Duration, Instant};

use super::state::LoadedScene;

/// Loads shorter than this show no progress (most scenes load in a few milliseconds).
pub const SHOW_PROGRESS_AFTER: Duration = Duration::from_millis(500);

/// Progress is shared as parts per million of the whole load.
const PROGRESS_SCALE: f64 = 1_000_000.0;

/// Why a scene was loaded: the viewer adopts a reload differently from an open.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadKind {
    /// A file the user opened.
    Open,
    /// The open file again (changed on disk, or Reload).
    Reload,
}

/// A load running on its own thread.
#[derive(Debug)]
pub struct PendingLoad {
    /// The file being loaded.
    pub path: PathBuf,
    /// Open or reload.
    pub kind: LoadKind,
    started: Instant,
    progress: Arc<AtomicU32>,
    answer: Receiver<Result<LoadedScene, String>>,
}

/// The state of a pending load.
#[derive(Debug)]
pub enum LoadState {
    /// Still running.
    Running,
    /// Done: the scene, or the error to show.
    Done(Result<LoadedScene, String>),
}

impl PendingLoad {
    /// Starts loading `path` (image size `size_px` for the scene's initial view); `on_done` is
    /// called from the loading thread when the answer is ready (to wake the UI).
    pub fn start(
        path: &Path,
        kind: LoadKind,
        size_px: (u32, u32),
        on_done: impl FnOnce() + Send + 'static,
    ) -> std::io::Result<Self> {
        let (sender, answer) = channel();
        let progress = Arc::new(AtomicU32::new(0));
        let shared = Arc::clone(&progress);
        let thread_path = path.to_path_buf();
        std::thread::Builder::new()
            .name("scene-load".into())
            .spawn(move || {
                let report = |fraction: f64| {
                    let parts = (fraction.clamp(0.0, 1.0) * PROGRESS_SCALE) as u32;
                    shared.store(parts, Ordering::Relaxed);
                };
                let loaded = LoadedScene::load_with_progress(&thread_path, size_px, &report)
                    .map_err(|error| error.to_string());
                // The viewer may have closed or started another load; then nobody listens.
                let _ = sender.send(loaded);
                on_done();
            })?;
        Ok(Self {
            path: path.to_path_buf(),
            kind,
            started: Instant::now(),
            progress,
            answer,
        })
    }

    /// Checks for the answer without blocking.
    pub fn poll(&self) -> LoadState {
        match self.answer.try_recv() {
            Ok(result) => LoadState::Done(result),
            Err(TryRecvError::Empty) => LoadState::Running,
            Err(TryRecvError::Disconnected) => LoadState::Done(Err(format!(
                "{}: the loading thread stopped",
                self.path.display()
            ))),
        }
    }

    /// The share of the load done, in [0, 1].
    pub fn fraction(&self) -> f32 {
        (f64::from(self.progress.load(Ordering::Relaxed)) / PROGRESS_SCALE) as f32
    }

    /// Whether the load has run long enough to show its progress.
    pub fn shows_progress(&self) -> bool {
        self.started.elapsed() >= SHOW_PROGRESS_AFTER
    }
}
