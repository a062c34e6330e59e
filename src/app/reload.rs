//! Live reload: watches the open scene file through its folder (editors often save by writing a
//! new file and renaming it over the old one) with notify's debouncer, which reports a path once
//! it has been quiet for [`SETTLE_TIME`], so a save in several steps reloads once. Only changes
//! count (created, modified, removed, renamed): reading the file — our own reload among others —
//! raises access events, which must not reload it again. (notify's mini debouncer drops the
//! event kinds, so it cannot tell a read from a write.)

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use notify_debouncer_full::notify::{self, EventKind, RecommendedWatcher, RecursiveMode};
use notify_debouncer_full::{DebounceEventResult, Debouncer, RecommendedCache, new_debouncer};

/// How long the file must be quiet before it is reloaded.
pub(crate) const SETTLE_TIME: Duration = Duration::from_millis(150);

/// Watches one file.
pub(crate) struct FileWatcher {
    _debouncer: Debouncer<RecommendedWatcher, RecommendedCache>,
    changed: Arc<AtomicBool>,
}

/// What the watcher has seen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum WatchState {
    /// Nothing since the last reload.
    Quiet,
    /// The file changed and has settled: reload it.
    Changed,
}

impl FileWatcher {
    /// Starts watching `path`; `on_change` runs (on the watcher's thread) once a change has
    /// settled, e.g. to request a repaint.
    pub(crate) fn watch(
        path: &Path,
        on_change: impl Fn() + Send + 'static,
    ) -> notify::Result<Self> {
        let target: PathBuf = std::fs::canonicalize(path)?;
        let folder = target
            .parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        let name = target.file_name().map(ToOwned::to_owned);
        let changed = Arc::new(AtomicBool::new(false));
        let seen = Arc::clone(&changed);
        let mut debouncer =
            new_debouncer(SETTLE_TIME, None, move |events: DebounceEventResult| {
                let Ok(events) = events else { return };
                let ours = events.iter().any(|event| {
                    let change = matches!(
                        event.kind,
                        EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_)
                    );
                    change
                        && event
                            .paths
                            .iter()
                            .any(|path| path.file_name().map(ToOwned::to_owned) == name)
                });
                if ours {
                    seen.store(true, Ordering::Release);
                    on_change();
                }
            })?;
        debouncer.watch(&folder, RecursiveMode::NonRecursive)?;
        Ok(Self {
            _debouncer: debouncer,
            changed,
        })
    }

    /// Whether the file changed; a `Changed` answer is given once per change.
    pub(crate) fn poll(&self) -> WatchState {
        if self.changed.swap(false, Ordering::Acquire) {
            WatchState::Changed
        } else {
            WatchState::Quiet
        }
    }
}
