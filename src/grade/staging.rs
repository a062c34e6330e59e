//! Where a report is made: a hidden folder beside the destination, moved into place when the
//! report is whole. The destination may be new, empty, or a previous report (replaced); a folder
//! holding anything else is refused before anything is written. A run that fails or is stopped
//! (the signal handler calls [`remove_unfinished_report`]) removes its unfinished folder and
//! leaves the previous report as it was.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, PoisonError};

use super::report::{REPORT_ENTRIES, REPORT_FORMAT};

/// The unfinished report folder of this run, for the signal handler.
static UNFINISHED: Mutex<Option<PathBuf>> = Mutex::new(None);

/// Removes this run's unfinished report folder, if any (for the signal handler).
pub fn remove_unfinished_report() {
    let mut unfinished = UNFINISHED.lock().unwrap_or_else(PoisonError::into_inner);
    let Some(folder) = unfinished.take() else {
        return;
    };
    // The grading threads go on writing pictures while this runs: moved aside first, the folder
    // takes no new file by its name (its subfolders are made with `create_dir`, never
    // `create_dir_all`, so nothing makes it again), and a removal that met a file made between
    // its listing and its last step is tried again.
    let aside = folder.with_extension("removing");
    let target = if std::fs::rename(&folder, &aside).is_ok() {
        aside
    } else {
        folder
    };
    for _ in 0..50 {
        if std::fs::remove_dir_all(&target).is_ok() || !target.exists() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
}

/// A report being made.
pub(super) struct Staging {
    folder: PathBuf,
    destination: PathBuf,
    committed: bool,
}

impl Staging {
    /// Checks `destination` and makes the folder the report is written to.
    pub(super) fn begin(destination: &Path) -> Result<Self, String> {
        let shown = destination.display();
        match std::fs::symlink_metadata(destination) {
            Ok(metadata) if metadata.file_type().is_symlink() => {
                return Err(format!(
                    "-o '{shown}' is a link: name the folder itself (nothing was written)"
                ));
            }
            Ok(metadata) if !metadata.is_dir() => {
                return Err(format!(
                    "-o '{shown}' exists and is not a folder (nothing was written)"
                ));
            }
            Ok(_) if !is_empty(destination) && !holds_a_report(destination) => {
                return Err(format!(
                    "-o '{shown}' holds files that are not a grading report: name a new or empty \
                     folder (nothing was written)"
                ));
            }
            _ => {}
        }
        let name = destination
            .file_name()
            .ok_or_else(|| format!("-o '{shown}': name a folder"))?
            .to_string_lossy()
            .into_owned();
        let parent = match destination.parent() {
            Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if !parent.is_dir() {
            return Err(format!(
                "-o '{shown}': the folder '{}' does not exist",
                parent.display()
            ));
        }
        let folder = parent.join(format!(
            ".{name}.raytracer-grade-{}.tmp",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&folder);
        *UNFINISHED.lock().unwrap_or_else(PoisonError::into_inner) = Some(folder.clone());
        std::fs::create_dir(&folder)
            .map_err(|e| format!("-o '{shown}': cannot make the report beside it: {e}"))?;
        Ok(Self {
            folder,
            destination: destination.to_path_buf(),
            committed: false,
        })
    }

    /// The folder the report is written to.
    pub(super) fn folder(&self) -> &Path {
        &self.folder
    }

    /// Moves the report into place, replacing a previous one.
    pub(super) fn commit(mut self) -> Result<(), String> {
        let shown = self.destination.display().to_string();
        let old = self.folder.with_extension("old");
        let had_old = self.destination.exists();
        if had_old {
            std::fs::rename(&self.destination, &old)
                .map_err(|e| format!("-o '{shown}': cannot move the previous report aside: {e}"))?;
        }
        if let Err(error) = std::fs::rename(&self.folder, &self.destination) {
            if had_old {
                let _ = std::fs::rename(&old, &self.destination);
            }
            return Err(format!(
                "-o '{shown}': cannot put the report in place: {error}"
            ));
        }
        self.committed = true;
        *UNFINISHED.lock().unwrap_or_else(PoisonError::into_inner) = None;
        if had_old {
            let _ = std::fs::remove_dir_all(&old);
        }
        Ok(())
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        if !self.committed {
            remove_unfinished_report();
        }
    }
}

/// Whether `folder` holds nothing.
fn is_empty(folder: &Path) -> bool {
    std::fs::read_dir(folder).is_ok_and(|mut entries| entries.next().is_none())
}

/// Whether `folder` holds a report this program wrote and nothing else: its `report.json` says
/// so, and every entry is one a report has.
fn holds_a_report(folder: &Path) -> bool {
    let Ok(entries) = std::fs::read_dir(folder) else {
        return false;
    };
    for entry in entries {
        let Ok(entry) = entry else { return false };
        if !REPORT_ENTRIES.contains(&entry.file_name().to_string_lossy().as_ref()) {
            return false;
        }
    }
    let Ok(file) = std::fs::File::open(folder.join("report.json")) else {
        return false;
    };
    let mut start = String::new();
    let _ = file.take(4096).read_to_string(&mut start);
    start.contains(&format!("\"format\": \"{REPORT_FORMAT}\""))
}
