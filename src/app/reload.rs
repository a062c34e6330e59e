//! Live reload: watches the open scene file (through its folder, since editors often save by
//! writing a new file and renaming it over the old one) and reports a change once the file has
//! been quiet for [`SETTLE_TIME`], so a save in several steps reloads once.

use std::path::Path;
use std::sync::{Arc, Mutex, PoisonError};
use web_time::{Duration, Instant};

use crate::platform::watch::{Watch, watch_file};

/// Why a file cannot be watched.
pub(crate) use crate::platform::watch::WatchError;

/// How long the file must be quiet before it is reloaded.
pub(crate) const SETTLE_TIME: Duration = Duration::from_millis(150);

/// Watches one file.
pub(crate) struct FileWatcher {
    _watch: Watch,
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
    /// Starts watching `path` ([`watch_file`]); `on_event` runs (on the watcher's thread) for
    /// every change, e.g. to request a repaint.
    pub(crate) fn watch(
        path: &Path,
        on_event: impl Fn() + Send + 'static,
    ) -> Result<Self, WatchError> {
        let last_change = Arc::new(Mutex::new(None));
        let seen = Arc::clone(&last_change);
        let watch = watch_file(path, move || {
            *seen.lock().unwrap_or_else(PoisonError::into_inner) = Some(Instant::now());
            on_event();
        })?;
        Ok(Self {
            _watch: watch,
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
