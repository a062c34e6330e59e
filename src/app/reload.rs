//! Live reload: watches the open scene file (through its folder, since editors often save by
//! writing a new file and renaming it over the old one) and reports a change once the file has
//! been quiet for [`SETTLE_TIME`], so a save in several steps reloads once.

use std::path::Path;
#[cfg(not(target_arch = "wasm32"))]
use std::path::PathBuf;
use std::sync::{Arc, Mutex, PoisonError};
use web_time::{Duration, Instant};

#[cfg(not(target_arch = "wasm32"))]
use notify::{EventKind, RecursiveMode, Watcher};

/// Why a file cannot be watched.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) type WatchError = notify::Error;
/// Why a file cannot be watched: a browser page has no files to watch.
#[cfg(target_arch = "wasm32")]
pub(crate) type WatchError = std::io::Error;

/// How long the file must be quiet before it is reloaded.
pub(crate) const SETTLE_TIME: Duration = Duration::from_millis(150);

/// Watches one file.
pub(crate) struct FileWatcher {
    #[cfg(not(target_arch = "wasm32"))]
    _watcher: notify::RecommendedWatcher,
    last_change: Arc<Mutex<Option<Instant>>>,
}

/// What the watcher has seen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum WatchState {
    /// Nothing since the last reload.
    Quiet,
    /// The file changed and is still settling; ask again after this long.
    Settling(Duration),
    /// The file changed and has settled: reload it.
    Changed,
}

impl FileWatcher {
    /// In a browser page: no file can be watched.
    #[cfg(target_arch = "wasm32")]
    pub(crate) fn watch(
        _path: &Path,
        _on_event: impl Fn() + Send + 'static,
    ) -> Result<Self, WatchError> {
        Err(std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "a browser page cannot watch files",
        ))
    }

    /// Starts watching `path`; `on_event` runs (on the watcher's thread) for every change, e.g. to
    /// request a repaint.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn watch(
        path: &Path,
        on_event: impl Fn() + Send + 'static,
    ) -> Result<Self, WatchError> {
        let target: PathBuf = std::fs::canonicalize(path)?;
        let folder = target
            .parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        let name = target.file_name().map(ToOwned::to_owned);
        let last_change = Arc::new(Mutex::new(None));
        let seen = Arc::clone(&last_change);
        let mut watcher =
            notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
                let Ok(event) = event else { return };
                // Changes only: reading the file (as the viewer's own reload does) raises access
                // events, which must not reload it again.
                let relevant = matches!(
                    event.kind,
                    EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_)
                ) && event
                    .paths
                    .iter()
                    .any(|p| p.file_name().map(ToOwned::to_owned) == name);
                if relevant {
                    *seen.lock().unwrap_or_else(PoisonError::into_inner) = Some(Instant::now());
                    on_event();
                }
            })?;
        watcher.watch(&folder, RecursiveMode::NonRecursive)?;
        Ok(Self {
            _watcher: watcher,
            last_change,
        })
    }

    /// Whether the file changed; a `Changed` answer is given once per change.
    pub(crate) fn poll(&self) -> WatchState {
        let mut last = self
            .last_change
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        match *last {
            None => WatchState::Quiet,
            Some(at) if at.elapsed() >= SETTLE_TIME => {
                *last = None;
                WatchState::Changed
            }
            Some(at) => WatchState::Settling(SETTLE_TIME.saturating_sub(at.elapsed())),
        }
    }
}
