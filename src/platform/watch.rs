//! Watching a file for changes. On the desktop a file is watched through its folder (editors
//! often save by writing a new file and renaming it over the old one) with the `notify` crate,
//! and only changes count: reading the file raises access events, which must not. A browser page
//! has no files to watch.

use std::path::Path;
#[cfg(not(target_arch = "wasm32"))]
use std::path::PathBuf;

/// Why a file cannot be watched.
#[cfg(not(target_arch = "wasm32"))]
pub type WatchError = notify::Error;
/// Why a file cannot be watched: a browser page has no files to watch.
#[cfg(target_arch = "wasm32")]
pub type WatchError = std::io::Error;

/// A file being watched; the watching stops when it is dropped.
pub struct Watch {
    #[cfg(not(target_arch = "wasm32"))]
    _watcher: notify::RecommendedWatcher,
}

/// Starts watching `path`: `on_change` runs (on the watcher's thread) each time the file is
/// created, modified or removed.
#[cfg(not(target_arch = "wasm32"))]
pub fn watch_file(path: &Path, on_change: impl Fn() + Send + 'static) -> Result<Watch, WatchError> {
    use notify::{EventKind, RecursiveMode, Watcher as _};
    let target: PathBuf = std::fs::canonicalize(path)?;
    let folder = target
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let name = target.file_name().map(ToOwned::to_owned);
    let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
        let Ok(event) = event else { return };
        let relevant = matches!(
            event.kind,
            EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_)
        ) && event
            .paths
            .iter()
            .any(|p| p.file_name().map(ToOwned::to_owned) == name);
        if relevant {
            on_change();
        }
    })?;
    watcher.watch(&folder, RecursiveMode::NonRecursive)?;
    Ok(Watch { _watcher: watcher })
}

/// In a browser page: no file can be watched.
#[cfg(target_arch = "wasm32")]
pub fn watch_file(
    _path: &Path,
    _on_change: impl Fn() + Send + 'static,
) -> Result<Watch, WatchError> {
    Err(std::io::Error::new(
        std::io::ErrorKind::Unsupported,
        "a browser page cannot watch files",
    ))
}
