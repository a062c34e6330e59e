//! Where a report is made: a hidden folder beside the destination, moved into place when the
//! report is whole. The destination may be new, empty, or a previous report (replaced): one whose
//! list of what it wrote ([`Manifest`]) names every entry anywhere under it. A folder holding
//! anything else is refused before anything is written, naming the first such entry; replacing a
//! report removes exactly what its list names. A run that fails or is stopped (the signal handler
//! calls [`remove_unfinished_report`]) removes its unfinished folder and leaves the previous
//! report as it was.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, PoisonError};

use super::manifest::{Manifest, NotAReport};
use crate::platform::files::process_has_ended;

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
    /// The previous report's list, where one is replaced.
    previous: Option<Manifest>,
    committed: bool,
}

impl Staging {
    /// Checks `destination` and makes the folder the report is written to.
    pub(super) fn begin(destination: &Path) -> Result<Self, String> {
        let shown = destination.display();
        let name = stem_of(
            destination
                .file_name()
                .ok_or_else(|| format!("-o '{shown}': name a folder"))?,
        );
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
        remove_stale(&parent, &name, destination);
        let mut previous = None;
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
            Ok(_) if !is_empty(destination) => {
                previous = Some(Manifest::of_report(destination).map_err(|why| match why {
                    NotAReport::NoList => format!(
                        "-o '{shown}' holds files that are not a grading report: name a new or \
                         empty folder (nothing was written)"
                    ),
                    NotAReport::Stranger(entry) => format!(
                        "-o '{shown}' holds '{entry}', which is not part of the grading report \
                         there: move it out, or name a new or empty folder (nothing was written)"
                    ),
                    NotAReport::Unreadable(why) => {
                        format!("-o '{shown}' cannot be read through: {why} (nothing was written)")
                    }
                })?);
            }
            _ => {}
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
            previous,
            committed: false,
        })
    }

    /// The folder the report is written to.
    pub(super) fn folder(&self) -> &Path {
        &self.folder
    }

    /// Lists what the report holds, and moves it into place, replacing a previous one: of that,
    /// exactly what its list names is removed. Anything put into it while this run went on is
    /// kept, in a folder beside it that is named.
    pub(super) fn commit(mut self) -> Result<(), String> {
        let shown = self.destination.display().to_string();
        // A stop asked for from here on waits for the report to be in place and the previous
        // one removed (its clean-up takes this lock first): never the one moved aside and the
        // other not yet in place, nor a hidden folder left.
        let mut unfinished = UNFINISHED.lock().unwrap_or_else(PoisonError::into_inner);
        Manifest::write_for(&self.folder).map_err(|e| format!("-o '{shown}': {e}"))?;
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
        *unfinished = None;
        if had_old {
            let gone = self
                .previous
                .as_ref()
                .is_some_and(|previous| previous.remove_listed(&old));
            if !gone {
                let kept = kept_name(&self.destination);
                let _ = std::fs::rename(&old, &kept);
                eprintln!(
                    "raytracer: the previous report held files it did not write (put there while \
                     this run went on): they are kept in '{}'",
                    kept.display()
                );
            }
        }
        Ok(())
    }
}

/// A new name beside `destination` for what a previous report held that it did not write.
fn kept_name(destination: &Path) -> PathBuf {
    let name = destination
        .file_name()
        .map_or_else(|| "report".into(), stem_of);
    (1..)
        .map(|n| destination.with_file_name(format!("{name}.kept-{n}")))
        .find(|path| std::fs::symlink_metadata(path).is_err())
        .unwrap_or_else(|| destination.with_file_name(format!("{name}.kept")))
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

/// The longest name of a destination used as it is in the names of the folders beside it (a
/// file name is at most 255 bytes, and theirs add about 40).
const MAX_STEM_BYTES: usize = 150;

/// What names the folders of a run into the destination named `name`: the name itself, or
/// where it is long or not text, its start and a fingerprint of the whole name (two names
/// never share their folders).
fn stem_of(name: &std::ffi::OsStr) -> String {
    if let Some(text) = name.to_str()
        && text.len() <= MAX_STEM_BYTES
    {
        return text.to_owned();
    }
    let lossy = name.to_string_lossy();
    let mut cut = 100.min(lossy.len());
    while !lossy.is_char_boundary(cut) {
        cut -= 1;
    }
    // FNV-1a over the name's bytes.
    let fingerprint = name
        .as_encoded_bytes()
        .iter()
        .fold(0xcbf2_9ce4_8422_2325_u64, |hash, &byte| {
            (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3)
        });
    format!("{}-{fingerprint:016x}", &lossy[..cut])
}

/// Removes what runs into `destination` (their folders named from `name`) that have ended
/// without cleaning up (killed with SIGKILL, or a power cut) left beside it: their unfinished
/// folders (`.tmp`, `.removing`), and a previous report they had moved aside (`.old`) — put back
/// in place where none is there, or else what its list names removed (anything else in it is
/// kept). Folders of runs still going on are left alone.
fn remove_stale(parent: &Path, name: &str, destination: &Path) {
    let prefix = format!(".{name}.raytracer-grade-");
    let Ok(entries) = std::fs::read_dir(parent) else {
        return;
    };
    for entry in entries.flatten() {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        let Some((pid, kind)) = file_name
            .strip_prefix(&prefix)
            .and_then(|rest| rest.split_once('.'))
        else {
            continue;
        };
        let Ok(pid) = pid.parse::<u32>() else {
            continue;
        };
        let is_folder = entry.file_type().is_ok_and(|t| t.is_dir());
        if !is_folder || pid == std::process::id() || !process_has_ended(pid) {
            continue;
        }
        let path = entry.path();
        match kind {
            "tmp" | "removing" => {
                let _ = std::fs::remove_dir_all(&path);
            }
            "old" if std::fs::symlink_metadata(destination).is_err() => {
                let _ = std::fs::rename(&path, destination);
            }
            "old" => {
                if let Ok(listed) = Manifest::in_folder(&path) {
                    listed.remove_listed(&path);
                }
            }
            _ => {}
        }
    }
}
