//! Writing files so that nothing a user has is lost:
//!
//! * **All or nothing**: a [`FileSet`] writes every file of a run to a temporary file beside its
//!   destination first (synced to disk), and only when all of them are complete renames them over
//!   their destinations. A failure on any file leaves every old file as it was: while the renames
//!   run, each file they replace is kept under a second name (a hard link, or a copy where the
//!   file system has none), and a rename that fails puts every file already replaced back. A
//!   terminating signal waits for the renames to end (they take microseconds), so it never
//!   splits them. What remains is a power cut between two renames.
//! * **Modes** (Unix): a new file gets the mode the umask gives (0644 under the usual 022); a
//!   replaced file keeps the mode it had, without set-id bits or write for others. Windows has no
//!   modes ([`crate::platform::files`]).
//! * **Links**: a destination that is a symbolic link is written through, as `cp` and the shell
//!   do: the file it leads to is replaced and the link stays; one that leads to something other
//!   than a regular file (a device such as `/dev/null`, a pipe) is refused.
//! * **Nothing left behind**: a temporary file is removed when its write fails or is abandoned;
//!   [`remove_temporary_files`] removes the ones still open when the program is stopped by a
//!   signal (the binary calls it from its signal handler thread).
//!
//! Also the check, made before any work, that a destination can be written.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::PoisonError;
use std::sync::atomic::Ordering;

use super::temporary::{COMMITTING, TEMPORARY_COUNTER, Temporary, open_temporaries};
pub use super::temporary::{TEMPORARY_PREFIX, remove_temporary_files};
use crate::platform::files::{self, folder_of};

/// Why a file could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// The extension names no supported format.
    #[error("{}: unknown format; use one of {expected}", path.display())]
    UnknownFormat {
        /// The destination.
        path: PathBuf,
        /// The extensions that would do, as a list for the message.
        expected: &'static str,
    },
    /// A rename failed, and a file already replaced could not be put back.
    #[error("{}: cannot write: {source}; and {not_put_back}", path.display())]
    NotPutBack {
        /// The destination whose rename failed.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
        /// Each file that could not be put back, why, and where its old content is.
        not_put_back: String,
    },
    /// Creating, writing or renaming failed.
    #[error("{}: cannot write: {source}", path.display())]
    Io {
        /// The destination.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The encoder refused the image.
    #[error("{}: cannot encode: {source}", path.display())]
    Encode {
        /// The destination.
        path: PathBuf,
        /// The encoder's reason.
        source: image::ImageError,
    },
}

/// One staged file: its complete content in a temporary file, synced, and where it goes.
pub(crate) struct Staged {
    temporary: Temporary,
    destination: PathBuf,
}

/// A file being staged a piece at a time: [`Staging::begin`], write to [`Staging::file`], then
/// [`Staging::finish`] and [`FileSet::push`]. Dropped unfinished, its temporary file is removed.
pub(crate) struct Staging {
    staged: Staged,
}

impl Staging {
    /// Creates the temporary file for `destination` (with `mode` before the umask). A symbolic
    /// link is written through: the file it leads to is replaced, and the link stays.
    pub(crate) fn begin(destination: &Path, mode: u32) -> Result<Self, WriteError> {
        let destination = &files::through_links_to_write(destination)
            .map_err(|source| io_error(destination, source))?;
        let error = |source| io_error(destination, source);
        check_not_special(destination).map_err(error)?;
        let temporary = Temporary::create(folder_of(destination), mode).map_err(error)?;
        Ok(Self {
            staged: Staged {
                temporary,
                destination: destination.to_path_buf(),
            },
        })
    }

    /// The temporary file, to write the content to.
    pub(crate) fn file(&mut self) -> Result<&mut File, WriteError> {
        let destination = &self.staged.destination;
        match self.staged.temporary.file.as_mut() {
            Some(file) => Ok(file),
            None => Err(io_error(
                destination,
                std::io::Error::other("the temporary file is closed"),
            )),
        }
    }

    /// The temporary file, to write the content to from several threads at once (positional
    /// writes).
    pub(crate) fn file_to_share(&self) -> Result<&File, WriteError> {
        match self.staged.temporary.file.as_ref() {
            Some(file) => Ok(file),
            None => Err(self.error(std::io::Error::other("the temporary file is closed"))),
        }
    }

    /// `source` as the error of writing this file.
    pub(crate) fn error(&self, source: std::io::Error) -> WriteError {
        io_error(&self.staged.destination, source)
    }

    /// Syncs the content to disk: the file is complete.
    pub(crate) fn finish(mut self) -> Result<Staged, WriteError> {
        let synced = self.file()?.sync_all();
        synced.map_err(|source| self.error(source))?;
        Ok(self.staged)
    }
}

/// Where a file's content goes once encoded: a [`FileSet`] (temporary files renamed over their
/// destinations, all or nothing) or [`FilesInMemory`] (a browser page's downloads).
pub trait Stage {
    /// Stages the file `destination` with the content `write` produces; `executable` for a
    /// script.
    fn stage_file(
        &mut self,
        destination: &Path,
        executable: bool,
        write: &mut dyn FnMut(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError>;
}

impl Stage for FileSet {
    fn stage_file(
        &mut self,
        destination: &Path,
        executable: bool,
        write: &mut dyn FnMut(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError> {
        let mode = if executable { 0o777 } else { 0o666 };
        self.stage_with_mode(destination, mode, write)
    }
}

/// Files kept in memory, by name, in the order staged (what a browser page downloads).
#[derive(Debug, Default)]
pub struct FilesInMemory {
    /// Each file's destination and content.
    pub files: Vec<(PathBuf, Vec<u8>)>,
}

impl Stage for FilesInMemory {
    fn stage_file(
        &mut self,
        destination: &Path,
        _executable: bool,
        write: &mut dyn FnMut(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError> {
        let mut bytes = Vec::new();
        write(&mut bytes)?;
        self.files.push((destination.to_path_buf(), bytes));
        Ok(())
    }
}

/// [`Stage::stage_file`] with these bytes.
pub(crate) fn stage_bytes(
    set: &mut dyn Stage,
    destination: &Path,
    bytes: &[u8],
) -> Result<(), WriteError> {
    set.stage_file(destination, false, &mut |out| {
        out.write_all(bytes)
            .map_err(|source| io_error(destination, source))
    })
}

/// Files written all or nothing: [`FileSet::stage`] each, then [`FileSet::commit`].
#[derive(Default)]
pub struct FileSet {
    staged: Vec<Staged>,
}

impl FileSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Writes a file's content (through `write`) to a temporary file beside `destination` and
    /// syncs it; nothing is replaced yet.
    pub fn stage(
        &mut self,
        destination: &Path,
        write: impl FnOnce(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError> {
        self.stage_with_mode(destination, 0o666, write)
    }

    /// [`Self::stage`] for a script: executable where the umask lets files be read.
    pub fn stage_executable(
        &mut self,
        destination: &Path,
        write: impl FnOnce(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError> {
        self.stage_with_mode(destination, 0o777, write)
    }

    /// [`Self::stage`] with these bytes.
    pub fn stage_bytes(&mut self, destination: &Path, bytes: &[u8]) -> Result<(), WriteError> {
        self.stage(destination, |out| {
            out.write_all(bytes)
                .map_err(|source| io_error(destination, source))
        })
    }

    fn stage_with_mode(
        &mut self,
        destination: &Path,
        mode: u32,
        write: impl FnOnce(&mut dyn Write) -> Result<(), WriteError>,
    ) -> Result<(), WriteError> {
        let mut staging = Staging::begin(destination, mode)?;
        let mut out = BufWriter::new(staging.file()?);
        write(&mut out)?;
        let flushed = out.flush();
        drop(out);
        flushed.map_err(|source| staging.error(source))?;
        self.push(staging.finish()?);
        Ok(())
    }

    /// Adds a file staged a piece at a time ([`Staging`]).
    pub(crate) fn push(&mut self, staged: Staged) {
        self.staged.push(staged);
    }

    /// Adds the files `other` staged after this set's.
    pub fn append(&mut self, mut other: FileSet) {
        self.staged.append(&mut other.staged);
    }

    /// Renames every staged file over its destination, in the order staged. A replaced file's
    /// mode is kept. All or nothing: a rename that fails puts back every file replaced before it
    /// (see the module docs). Returns the destinations.
    pub fn commit(self) -> Result<Vec<PathBuf>, WriteError> {
        // Every destination can be replaced now, or none is (on Windows, a file another
        // program holds open or a read-only one).
        for staged in &self.staged {
            files::check_replaceable(&staged.destination)
                .map_err(|source| io_error(&staged.destination, source))?;
        }
        let _committing = COMMITTING.lock().unwrap_or_else(PoisonError::into_inner);
        // Each file to be replaced, kept under a second name until every rename has succeeded.
        let mut kept: Vec<Option<OldFile>> = Vec::with_capacity(self.staged.len());
        for staged in &self.staged {
            match keep_old(staged) {
                Ok(old) => kept.push(old),
                Err(error) => {
                    // Nothing is replaced: the old files kept so far go.
                    for old in kept.into_iter().flatten() {
                        old.forget();
                    }
                    return Err(error);
                }
            }
        }
        let mut written: Vec<PathBuf> = Vec::with_capacity(self.staged.len());
        for mut staged in self.staged {
            // Closed before the rename (Windows cannot rename an open file).
            staged.temporary.file = None;
            if let Err(source) = files::rename_over(&staged.temporary.path, &staged.destination) {
                return Err(put_back(&written, &mut kept, staged.destination, source));
            }
            open_temporaries().remove(&staged.temporary.path);
            written.push(staged.destination);
        }
        // Every rename succeeded: the old files go.
        for old in kept.into_iter().flatten() {
            old.forget();
        }
        Ok(written)
    }
}

/// Gives `staged`'s temporary file the mode of the file it replaces, and keeps that file under a
/// second name (`None`: there is none).
fn keep_old(staged: &Staged) -> Result<Option<OldFile>, WriteError> {
    let destination = &staged.destination;
    let error = |source| io_error(destination, source);
    if let Ok(existing) = std::fs::metadata(destination) {
        files::keep_mode(&existing, &staged.temporary.path).map_err(error)?;
    }
    match std::fs::symlink_metadata(destination) {
        Ok(_) => OldFile::keep(destination).map(Some).map_err(error),
        Err(_) => Ok(None),
    }
}

/// A replaced file's old content, kept under a hidden name beside it while the renames run.
struct OldFile {
    /// The hidden name.
    path: PathBuf,
}

impl OldFile {
    /// Keeps `destination` under a new hidden name in its folder: a hard link, or a copy.
    fn keep(destination: &Path) -> std::io::Result<Self> {
        let folder = folder_of(destination);
        loop {
            let number = TEMPORARY_COUNTER.fetch_add(1, Ordering::Relaxed);
            let path = folder.join(format!(
                "{TEMPORARY_PREFIX}{}-{number}.old",
                std::process::id()
            ));
            let linked = std::fs::hard_link(destination, &path);
            match linked {
                Ok(()) => return Ok(Self { path }),
                Err(error) if error.kind() == std::io::ErrorKind::AlreadyExists => {}
                Err(_) => {
                    // No hard links here (or none allowed for this file): a copy.
                    let created = match files::create_new(&path, 0o600) {
                        Ok(copy) => copy,
                        Err(error) if error.kind() == std::io::ErrorKind::AlreadyExists => continue,
                        Err(error) => return Err(error),
                    };
                    // The copy is closed at the end of the block (before it may be removed).
                    let copied = {
                        let mut copy = created;
                        File::open(destination)
                            .and_then(|mut from| std::io::copy(&mut from, &mut copy))
                            .and_then(|_| copy.sync_all())
                    };
                    if let Err(error) = copied {
                        let _ = std::fs::remove_file(&path);
                        return Err(error);
                    }
                    if let Ok(existing) = std::fs::metadata(destination)
                        && let Err(error) = files::keep_mode(&existing, &path)
                    {
                        let _ = std::fs::remove_file(&path);
                        return Err(error);
                    }
                    return Ok(Self { path });
                }
            }
        }
    }

    /// Whether `destination` still holds the old content: the same file (a hard link), or the
    /// same bytes (a copy).
    fn holds_what_is_in(&self, destination: &Path) -> bool {
        files::same_file(&self.path, destination)
            || matches!(
                (std::fs::read(&self.path), std::fs::read(destination)),
                (Ok(old), Ok(now)) if old == now
            )
    }

    /// The old content is not needed any more.
    fn forget(self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// After the rename over `failed` went wrong with `source`: puts back every file in `written`
/// (its old content where there was one, nothing where there was none) and `failed` itself (a
/// network file system may report a rename that happened as failed), and forgets the other old
/// files. The error names each file that could not be put back.
fn put_back(
    written: &[PathBuf],
    kept: &mut [Option<OldFile>],
    failed: PathBuf,
    source: std::io::Error,
) -> WriteError {
    let mut not_put_back = Vec::new();
    let destinations: Vec<&PathBuf> = written.iter().chain(std::iter::once(&failed)).collect();
    for (index, destination) in destinations.into_iter().enumerate().rev() {
        let is_failed = index == written.len();
        match kept[index].take() {
            Some(old) => {
                // Over a rename that did not happen, both names are one file and this does
                // nothing; the second name then goes.
                match files::rename_over(&old.path, destination) {
                    Ok(()) => old.forget(),
                    // The file that could not be replaced could not be put back either: it
                    // never changed (an immutable file, another user's in a sticky folder).
                    Err(_) if is_failed && old.holds_what_is_in(destination) => old.forget(),
                    Err(error) => not_put_back.push(format!(
                        "'{}' could not be put back ({error}): its old content is in '{}'",
                        destination.display(),
                        old.path.display()
                    )),
                }
            }
            None => match std::fs::remove_file(destination) {
                Ok(()) => {}
                Err(error) if is_failed && error.kind() == std::io::ErrorKind::NotFound => {}
                Err(error) => not_put_back.push(format!(
                    "the new '{}' could not be removed again ({error})",
                    destination.display()
                )),
            },
        }
    }
    for old in kept.iter_mut().filter_map(Option::take) {
        old.forget();
    }
    if not_put_back.is_empty() {
        io_error(&failed, source)
    } else {
        WriteError::NotPutBack {
            path: failed,
            source,
            not_put_back: not_put_back.join("; "),
        }
    }
}

fn io_error(path: &Path, source: std::io::Error) -> WriteError {
    WriteError::Io {
        path: path.to_path_buf(),
        source,
    }
}

fn is_a_folder() -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::IsADirectory, "is a folder")
}

/// A destination (its links followed) that is there must be a regular file: never a folder, a
/// device (a link to `/dev/null`), a named pipe or a socket.
fn check_not_special(destination: &Path) -> std::io::Result<()> {
    match std::fs::metadata(destination) {
        Ok(metadata) if metadata.is_dir() => Err(is_a_folder()),
        Ok(metadata) if !metadata.is_file() => Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "not a regular file (a device, a pipe or a socket): give a file to write",
        )),
        _ => Ok(()),
    }
}

/// `path` (its links followed) is not a folder or a device, a temporary file can be created (and
/// is removed) beside it, and the file there, if any, can be replaced.
pub(crate) fn check_folder_writable(path: &Path) -> Result<(), WriteError> {
    let path = &files::through_links_to_write(path).map_err(|source| io_error(path, source))?;
    check_not_special(path).map_err(|source| io_error(path, source))?;
    Temporary::create(folder_of(path), 0o600)
        .and_then(|probe| {
            probe.remove().map_err(|error| {
                std::io::Error::new(
                    error.kind(),
                    format!(
                        "the folder lets files be created but not removed ({error}), so a run \
                         would leave its temporary files there"
                    ),
                )
            })
        })
        .and_then(|()| files::check_replaceable(path))
        .map_err(|source| io_error(path, source))
}

/// Writes `bytes` to `path` alone, all or nothing (a [`FileSet`] of one file).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    let mut set = FileSet::new();
    set.stage_bytes(path, bytes)?;
    set.commit().map(drop)
}

#[cfg(test)]
#[path = "atomic_tests.rs"]
mod tests;
