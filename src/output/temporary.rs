//! The temporary files a run writes beside its destinations (`.raytracer-PID-N-NANOS.tmp`):
//! created and registered under one lock, so that [`remove_temporary_files`] (the signal
//! handler's clean-up) finds every one still being written and none is created after it; removed when dropped unless renamed over their
//! destination; and, once per run and folder, the ones a process that has ended left behind are
//! removed ([`sweep_stale_temporaries`]).

use std::collections::BTreeSet;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, PoisonError};

use crate::platform::files;

/// The temporary files being written now, for [`remove_temporary_files`].
static OPEN_TEMPORARIES: Mutex<BTreeSet<PathBuf>> = Mutex::new(BTreeSet::new());

/// Makes temporary names unique within the process.
pub(super) static TEMPORARY_COUNTER: AtomicU64 = AtomicU64::new(0);

/// Prefix of every temporary file the program writes (hidden, and named for what it is).
pub const TEMPORARY_PREFIX: &str = ".raytracer-";

pub(super) fn open_temporaries() -> std::sync::MutexGuard<'static, BTreeSet<PathBuf>> {
    OPEN_TEMPORARIES
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
}

/// Held while a file set (`FileSet`) renames its files, so that a signal handler never runs between two
/// renames.
pub(super) static COMMITTING: Mutex<()> = Mutex::new(());

/// Removes every temporary file still being written. For the signal handler and the program's
/// last step: the program is about to exit without running destructors. Waits for renames
/// under way to end first, and lets no commit start after it.
pub fn remove_temporary_files() {
    let committing = COMMITTING.lock().unwrap_or_else(PoisonError::into_inner);
    let registry = open_temporaries();
    for path in registry.iter() {
        let _ = std::fs::remove_file(path);
    }
    // The program ends now: no commit may start after this clean-up, nor any temporary file be
    // created (either would be left), so neither lock is ever released.
    std::mem::forget(registry);
    std::mem::forget(committing);
}

/// A temporary file beside a destination: registered for signal cleanup as it is created,
/// removed on drop unless it was renamed over the destination.
pub(super) struct Temporary {
    pub(super) path: PathBuf,
    pub(super) file: Option<File>,
}

impl Temporary {
    /// Creates a new temporary file in `folder` with `mode` (before the umask).
    pub(super) fn create(folder: &Path, mode: u32) -> std::io::Result<Self> {
        sweep_stale_temporaries(folder);
        loop {
            let number = TEMPORARY_COUNTER.fetch_add(1, Ordering::Relaxed);
            let nanos = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.subsec_nanos());
            let name = format!(
                "{TEMPORARY_PREFIX}{}-{number}-{nanos:08x}.tmp",
                std::process::id()
            );
            let path = folder.join(name);
            // Created and registered under the registry's lock: a clean-up that runs meanwhile
            // (a signal's) either finds the file registered or keeps it from being created.
            let mut registry = open_temporaries();
            match files::create_new(&path, mode) {
                Ok(file) => {
                    registry.insert(path.clone());
                    return Ok(Self {
                        path,
                        file: Some(file),
                    });
                }
                Err(error) if error.kind() != std::io::ErrorKind::AlreadyExists => {
                    return Err(error);
                }
                Err(_) => {}
            }
        }
    }
}

impl Temporary {
    /// Removes the file now, saying whether that worked (a folder may let files be created but
    /// not removed).
    pub(super) fn remove(mut self) -> std::io::Result<()> {
        self.file = None;
        open_temporaries().remove(&self.path);
        std::fs::remove_file(&self.path)
    }
}

/// How long a temporary file of a process that has ended must have been left before it is
/// removed as stale.
const STALE_AFTER: std::time::Duration = std::time::Duration::from_secs(3600);

/// Folders whose stale temporary files this run has removed already.
static SWEPT_FOLDERS: Mutex<BTreeSet<PathBuf>> = Mutex::new(BTreeSet::new());

/// Removes, once per run and folder, the temporary files (`.raytracer-PID-….tmp`) that a process
/// no longer running left there at least [`STALE_AFTER`] ago (one killed by SIGKILL or a power
/// cut). A kept old file
/// (`….old`) is never removed: it may hold the only copy of a file's old content. Where it cannot
/// be told whether the process still runs (Windows), nothing is removed.
fn sweep_stale_temporaries(folder: &Path) {
    let first_time = SWEPT_FOLDERS
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .insert(folder.to_path_buf());
    if !first_time {
        return;
    }
    let Ok(entries) = std::fs::read_dir(folder) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(name) = name.to_str() else { continue };
        let pid = name
            .strip_prefix(TEMPORARY_PREFIX)
            .filter(|_| Path::new(name).extension().is_some_and(|e| e == "tmp"))
            .and_then(|rest| rest.split('-').next())
            .and_then(|pid| pid.parse::<u32>().ok());
        // Left for an hour at least: a folder shared with another machine (a network folder, a
        // container's mount) may hold a file another machine's process of that number writes.
        let idle_for = entry
            .metadata()
            .and_then(|metadata| metadata.modified())
            .ok()
            .and_then(|modified| modified.elapsed().ok());
        if let Some(pid) = pid
            && pid != std::process::id()
            && idle_for.is_some_and(|idle| idle >= STALE_AFTER)
            && files::process_has_ended(pid)
        {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        // Closed before it is removed (Windows cannot remove an open file).
        self.file = None;
        if open_temporaries().remove(&self.path) {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}
