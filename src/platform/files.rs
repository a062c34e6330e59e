//! Files where Unix and Windows differ:
//! * positional reads and writes ([`read_at`], [`write_all_at`]), so several threads read or
//!   write one open file at their own offsets (`pread`/`pwrite` on Unix, `ReadFile`/`WriteFile`
//!   with an offset on Windows);
//! * what a path is when it is not a file to read ([`not_a_file_to_read`]): folders, devices,
//!   sockets; named pipes are read (a scene written by another program);
//! * modes ([`create_new`], [`keep_mode`]): on Unix a new file gets the mode asked for less the
//!   umask, and a replaced file keeps its mode. Windows has no modes: a new file takes the
//!   permissions its folder passes on, and nothing is copied from a replaced file (a read-only
//!   attribute copied to a temporary file would stop it from being removed);
//! * [`rename_over`]: on Windows a file another program holds open cannot be replaced, and the
//!   error says so in words (the old file stays as it was);
//! * file identity ([`identity`], [`same_file`]): the same file by two names, links included.
//!   On Unix the device and inode from the file's metadata (opening a named pipe to ask would
//!   wait for a writer); on Windows the volume and file index through the `same-file` crate (the
//!   standard library's are not stable). A file that does not exist yet is its canonical folder
//!   and its name, the name compared without case on Windows and macOS, whose file systems
//!   usually ignore it.
//!
//! In a browser page (`wasm32`) there are no files: every call here fails with `Unsupported`.

use std::fs::File;
use std::path::{Path, PathBuf};

/// Reads into `buffer` from `offset` in `file`; returns how many bytes were read (0 at the end).
pub fn read_at(file: &File, buffer: &mut [u8], offset: u64) -> std::io::Result<usize> {
    #[cfg(unix)]
    {
        std::os::unix::fs::FileExt::read_at(file, buffer, offset)
    }
    #[cfg(windows)]
    {
        std::os::windows::fs::FileExt::seek_read(file, buffer, offset)
    }
    #[cfg(target_arch = "wasm32")]
    {
        let _ = (file, buffer, offset);
        Err(std::io::ErrorKind::Unsupported.into())
    }
}

/// Writes all of `bytes` at `offset` in `file`.
pub fn write_all_at(file: &File, bytes: &[u8], offset: u64) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        std::os::unix::fs::FileExt::write_all_at(file, bytes, offset)
    }
    #[cfg(windows)]
    {
        let (mut bytes, mut offset) = (bytes, offset);
        while !bytes.is_empty() {
            match std::os::windows::fs::FileExt::seek_write(file, bytes, offset) {
                Ok(0) => return Err(std::io::ErrorKind::WriteZero.into()),
                Ok(n) => {
                    bytes = &bytes[n..];
                    offset += n as u64;
                }
                Err(error) if error.kind() == std::io::ErrorKind::Interrupted => {}
                Err(error) => return Err(error),
            }
        }
        Ok(())
    }
    #[cfg(target_arch = "wasm32")]
    {
        let _ = (file, bytes, offset);
        Err(std::io::ErrorKind::Unsupported.into())
    }
}

/// What `metadata` describes when it is not something a scene can be read from (a regular file
/// or a named pipe): "a folder", "a character device", …; `None` when it can be read.
pub fn not_a_file_to_read(metadata: &std::fs::Metadata) -> Option<&'static str> {
    let file_type = metadata.file_type();
    if file_type.is_file() {
        return None;
    }
    if file_type.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if file_type.is_fifo() {
            return None;
        }
        if file_type.is_char_device() {
            return Some("a character device");
        }
        if file_type.is_block_device() {
            return Some("a block device");
        }
        if file_type.is_socket() {
            return Some("a socket");
        }
    }
    Some("not a file")
}

/// Creates `path`, which must not exist yet, for writing; on Unix with `mode` less the umask
/// (Windows has no modes: the folder's permissions apply).
pub fn create_new(path: &Path, mode: u32) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    std::os::unix::fs::OpenOptionsExt::mode(&mut options, mode);
    #[cfg(not(unix))]
    let _ = mode;
    options.open(path)
}

/// Gives `temporary`, about to replace a file described by `replaced`, that file's owner and
/// group where this process may set them (run as root, or a group of the user's own), and its
/// mode (Unix), without the set-id and sticky bits and without write for others. Nothing on
/// Windows (see the module docs).
pub fn keep_mode(replaced: &std::fs::Metadata, temporary: &Path) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt as _, PermissionsExt as _};
        // Another user's file replaced by root stays theirs. Where the owner cannot be set, the
        // group alone may be; where neither, the file is the replacing user's, as an editor's is.
        if std::os::unix::fs::chown(temporary, Some(replaced.uid()), Some(replaced.gid())).is_err()
        {
            let _ = std::os::unix::fs::chown(temporary, None, Some(replaced.gid()));
        }
        // Never the set-user-id, set-group-id or sticky bits, nor writable by everyone: an
        // image is not a program, and a file made for one user stays that user's.
        let mode = replaced.permissions().mode() & 0o775;
        std::fs::set_permissions(temporary, std::fs::Permissions::from_mode(mode))
    }
    #[cfg(not(unix))]
    {
        let _ = (replaced, temporary);
        Ok(())
    }
}

/// Whether an existing file at `path` can be replaced by a rename now. On Windows it cannot be
/// when it is read-only (the user marked it so; Windows programs do not replace such a file
/// unasked) or when another program holds it open without letting others delete it (as editors
/// and image viewers do): the file is opened for deletion, sharing everything, and closed again,
/// which fails exactly then. Unix replaces a file whatever its mode and whoever has it open.
/// Checked before any work and again just before the renames, so that a run that could not
/// replace every file replaces none (a program that opens a file between that check and the
/// rename is not caught).
pub fn check_replaceable(path: &Path) -> std::io::Result<()> {
    #[cfg(windows)]
    {
        use std::os::windows::fs::OpenOptionsExt as _;
        /// `DELETE` access; `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
        const DELETE: u32 = 0x0001_0000;
        const SHARE_ALL: u32 = 0x1 | 0x2 | 0x4;
        let Ok(metadata) = std::fs::metadata(path) else {
            return Ok(()); // nothing there to replace
        };
        if metadata.permissions().readonly() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::PermissionDenied,
                "the file is read-only; clear its read-only attribute to replace it",
            ));
        }
        if metadata.is_file()
            && let Err(error) = std::fs::OpenOptions::new()
                .access_mode(DELETE)
                .share_mode(SHARE_ALL)
                .open(path)
        {
            return Err(held_open(&error).unwrap_or(error));
        }
    }
    #[cfg(not(windows))]
    let _ = path;
    Ok(())
}

/// `error` in words when it says that another program holds the file (Windows'
/// `ERROR_SHARING_VIOLATION` or `ERROR_LOCK_VIOLATION`).
#[cfg(windows)]
fn held_open(error: &std::io::Error) -> Option<std::io::Error> {
    let code = error
        .raw_os_error()
        .filter(|code| [32, 33].contains(code))?;
    Some(std::io::Error::new(
        error.kind(),
        format!(
            "another program has the file open; close it there and try again (os error {code})"
        ),
    ))
}

/// Renames `from` over `to` (replacing it). On Windows a file that another program holds open
/// cannot be replaced (Windows reports a sharing violation, or denies access as it does for a
/// read-only file): the error says so in words, with the system's code.
pub fn rename_over(from: &Path, to: &Path) -> std::io::Result<()> {
    let renamed = std::fs::rename(from, to);
    #[cfg(windows)]
    if let Err(error) = &renamed {
        if let Some(held) = held_open(error) {
            return Err(held);
        }
        // ERROR_ACCESS_DENIED for a file that is there.
        if error.raw_os_error() == Some(5) && to.exists() {
            return Err(std::io::Error::new(
                error.kind(),
                "access denied: another program has the file open, or the file is read-only \
                 (os error 5)",
            ));
        }
    }
    renamed
}

/// The folder a path names a file in (`.` for a bare file name).
pub fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// Opens `path` to read where it is a regular file, checked on the handle opened, so that it
/// cannot be swapped between a check and the open: a link at its last step is not followed
/// (`O_NOFOLLOW`), a named pipe or a device is opened without blocking (`O_NONBLOCK`) and
/// refused. The error says which in words ("a link: not followed", "not a regular file").
/// On Windows the link itself is opened (`FILE_FLAG_OPEN_REPARSE_POINT`) and refused.
pub fn open_regular_file(path: &Path) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt as _;
        let flags = rustix::fs::OFlags::NOFOLLOW | rustix::fs::OFlags::NONBLOCK;
        options.custom_flags(flags.bits() as i32);
    }
    #[cfg(windows)]
    {
        use std::os::windows::fs::OpenOptionsExt as _;
        const FILE_FLAG_OPEN_REPARSE_POINT: u32 = 0x0020_0000;
        options.custom_flags(FILE_FLAG_OPEN_REPARSE_POINT);
    }
    let file = match options.open(path) {
        Ok(file) => file,
        // A link at the last step (ELOOP on Linux and macOS, EMLINK on FreeBSD).
        #[cfg(unix)]
        Err(error)
            if error.raw_os_error() == Some(rustix::io::Errno::LOOP.raw_os_error())
                || error.raw_os_error() == Some(rustix::io::Errno::MLINK.raw_os_error()) =>
        {
            return Err(std::io::Error::other("a link: not followed"));
        }
        Err(error) => return Err(error),
    };
    let metadata = file.metadata()?;
    if metadata.file_type().is_symlink() {
        return Err(std::io::Error::other("a link: not followed"));
    }
    if !metadata.is_file() {
        return Err(std::io::Error::other("not a regular file"));
    }
    Ok(file)
}

/// Whether the process `pid` has ended (so a temporary file it left is stale). `false` where it
/// cannot be told: it may run as another user (it exists), or this is not Unix.
pub fn process_has_ended(pid: u32) -> bool {
    #[cfg(unix)]
    {
        let Some(pid) = i32::try_from(pid)
            .ok()
            .and_then(rustix::process::Pid::from_raw)
        else {
            return false;
        };
        matches!(
            rustix::process::test_kill_process(pid),
            Err(rustix::io::Errno::SRCH)
        )
    }
    #[cfg(not(unix))]
    {
        let _ = pid;
        false
    }
}

/// A file's identity; see the module docs.
#[derive(Debug, PartialEq, Eq)]
pub enum FileIdentity {
    /// A file that exists, by device and inode.
    #[cfg(unix)]
    Existing {
        /// Its device.
        device: u64,
        /// Its inode.
        inode: u64,
    },
    /// A file that exists, by volume and file index.
    #[cfg(windows)]
    Existing(same_file::Handle),
    /// A file to be created: its canonical folder joined with its name.
    New(PathBuf),
}

/// Symbolic links a path is followed through before giving up (as the kernel does).
const MAX_LINKS: usize = 40;

/// The file to write for `path`: [`through_links`], where a loop of links, or more than the
/// kernel follows, is an error (as `cp` and the shell refuse it), and a link that leads to
/// something other than a file (a pipe through `/dev/stdout`, a device) is left as it is, so that
/// what it leads to is judged, not a name the kernel made up (`pipe:[N]`).
pub fn through_links_to_write(path: &Path) -> std::io::Result<PathBuf> {
    let leads_to_a_file_or_nothing =
        |link: &Path| std::fs::metadata(link).map_or(true, |metadata| metadata.is_file());
    follow_links(path, leads_to_a_file_or_nothing).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "too many levels of symbolic links (a loop?): nothing written",
        )
    })
}

/// The file `path` names once its symbolic links are followed, as `cp` and the shell follow
/// them when they write: each link's target, relative to the link's folder, until a name that
/// is no link (which need not exist yet). A loop or an unreadable link ends the walk there.
pub fn through_links(path: &Path) -> PathBuf {
    follow_links(path, |_| true).unwrap_or_else(|last| last)
}

/// Follows `path`'s symbolic links, each target relative to the link's folder, while `follow`
/// takes the link: the name reached (no link, an unreadable one, or one `follow` refused), or
/// `Err` with the last name when links remain after [`MAX_LINKS`].
fn follow_links(path: &Path, follow: impl Fn(&Path) -> bool) -> Result<PathBuf, PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..=MAX_LINKS {
        let is_link = std::fs::symlink_metadata(&current)
            .is_ok_and(|metadata| metadata.file_type().is_symlink());
        if !is_link || !follow(&current) {
            return Ok(current);
        }
        let Ok(target) = std::fs::read_link(&current) else {
            return Ok(current);
        };
        current = if target.is_absolute() {
            target
        } else {
            folder_of(&current).join(target)
        };
    }
    Err(current)
}

/// The identity of the file `path` names (through its links); `None` when not even its folder
/// exists.
pub fn identity(path: &Path) -> Option<FileIdentity> {
    let path = &through_links(path);
    if let Some(existing) = existing_identity(path) {
        return Some(existing);
    }
    let folder = std::fs::canonicalize(folder_of(path)).ok()?;
    let name = path.file_name()?;
    let name = if cfg!(any(windows, target_os = "macos")) {
        name.to_string_lossy().to_lowercase().into()
    } else {
        name.to_owned()
    };
    Some(FileIdentity::New(folder.join(name)))
}

#[cfg(unix)]
fn existing_identity(path: &Path) -> Option<FileIdentity> {
    use std::os::unix::fs::MetadataExt as _;
    let metadata = std::fs::metadata(path).ok()?;
    Some(FileIdentity::Existing {
        device: metadata.dev(),
        inode: metadata.ino(),
    })
}

#[cfg(windows)]
fn existing_identity(path: &Path) -> Option<FileIdentity> {
    std::fs::metadata(path).ok()?;
    same_file::Handle::from_path(path)
        .ok()
        .map(FileIdentity::Existing)
}

/// A browser page has no files.
#[cfg(target_arch = "wasm32")]
fn existing_identity(_path: &Path) -> Option<FileIdentity> {
    None
}

/// Whether `a` and `b` name the same file.
pub fn same_file(a: &Path, b: &Path) -> bool {
    matches!((identity(a), identity(b)), (Some(x), Some(y)) if x == y)
}

/// A file open for writing whose every sync fails, for tests: on Unix the writing end of a pipe
/// (`fsync` refuses pipes); on Windows a file opened for reading only (`FlushFileBuffers` needs
/// write access; a pipe's would wait for its reader).
#[cfg(test)]
pub(crate) fn file_that_cannot_sync(folder: &Path) -> File {
    #[cfg(unix)]
    {
        let _ = folder;
        let (_reader, writer) = std::io::pipe().unwrap();
        File::from(std::os::fd::OwnedFd::from(writer))
    }
    #[cfg(windows)]
    {
        let path = folder.join("cannot-sync");
        std::fs::write(&path, b"").unwrap();
        File::open(path).unwrap()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_and_links_of_one_file_are_the_same_file() {
        let folder = tempfile::tempdir().unwrap();
        let file = folder.path().join("a.txt");
        std::fs::write(&file, b"x").unwrap();
        std::fs::create_dir(folder.path().join("sub")).unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(&file, folder.path().join("link")).unwrap();
        #[cfg(not(unix))]
        std::fs::hard_link(&file, folder.path().join("link")).unwrap();
        std::fs::hard_link(&file, folder.path().join("hard")).unwrap();
        for other in ["sub/../a.txt", "./a.txt", "link", "hard"] {
            assert!(same_file(&file, &folder.path().join(other)), "{other}");
        }
        // Files that do not exist yet: by folder and name.
        let new = folder.path().join("new.png");
        assert!(same_file(&new, &folder.path().join("sub/../new.png")));
        assert!(!same_file(&new, &folder.path().join("other.png")));
        assert!(!same_file(&file, &new));
    }

    #[test]
    fn positional_writes_and_reads_land_at_their_offsets() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("positions");
        let file = create_new(&path, 0o600).unwrap();
        write_all_at(&file, b"world", 6).unwrap();
        write_all_at(&file, b"hello ", 0).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"hello world");
        let file = File::open(&path).unwrap();
        let mut buffer = [0u8; 5];
        assert_eq!(read_at(&file, &mut buffer, 6).unwrap(), 5);
        assert_eq!(&buffer, b"world");
        assert_eq!(read_at(&file, &mut buffer, 11).unwrap(), 0, "the end");
        assert!(create_new(&path, 0o600).is_err(), "it exists");
    }

    #[test]
    fn folders_are_not_files_to_read_and_files_are() {
        let folder = tempfile::tempdir().unwrap();
        let metadata = std::fs::metadata(folder.path()).unwrap();
        assert_eq!(not_a_file_to_read(&metadata), Some("a folder"));
        let file = folder.path().join("scene.txt");
        std::fs::write(&file, b"x").unwrap();
        assert_eq!(not_a_file_to_read(&std::fs::metadata(&file).unwrap()), None);
    }
}
