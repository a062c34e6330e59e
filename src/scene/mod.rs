//! Scenes: the plain data model ([`Scene`]), the parser of the 6.837 assignment-1 text format
//! ([`parse_scene`], [`load_scene`]) and its typed errors, and the writer back to text
//! ([`scene_to_text`]); the scenes bundled with the program ([`bundled`]).

mod ahead;
pub mod bundled;
mod error;
mod lexer;
mod model;
mod parse;
#[cfg(test)]
mod parse_tests;
mod read;
mod split;
mod writer;

pub use error::{Location, ParseError, ParseErrorKind};
pub use model::{
    Bounds, DEFAULT_BACKGROUND, DEFAULT_DIFFUSE, Material, OrthographicCamera, Scene, Sphere,
};
pub use parse::{MAX_GROUP_DEPTH, MAX_MAGNITUDE, MIN_VIEW_SIZE};
pub use read::{
    parse_scene, parse_scene_bytes, parse_scene_bytes_with_progress, parse_scene_split_from,
    parse_scene_with_progress,
};
pub use writer::scene_to_text;

use std::path::Path;

/// Reading a scene file failed: the file could not be read, or its text is not a valid scene.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The file could not be read.
    #[error("{path}: {source}")]
    Io {
        /// The path as given.
        path: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The text is not a valid scene.
    #[error(transparent)]
    Parse(#[from] ParseError),
    /// The path names something that is not a file to read a scene from.
    #[error("{path}: not a regular file ({kind}): give a scene file")]
    NotAFile {
        /// The path as given.
        path: String,
        /// What it is instead.
        kind: &'static str,
    },
    /// The file is larger than scene files are read.
    #[error("{path}: {size} — scene files are read up to 1 GiB (about 8 million spheres)")]
    TooLarge {
        /// The path as given.
        path: String,
        /// The size, as far as known.
        size: String,
    },
}

/// Largest scene file read: 1 GiB (about 8 million spheres), so that a wrong path (a device, a
/// huge file) is refused instead of filling the memory.
pub const MAX_SCENE_BYTES: u64 = 1 << 30;

/// Refuses what is not a file that ends: devices, sockets, folders. Regular files and named
/// pipes (a scene written by another program) are read.
fn check_file_type(metadata: &std::fs::Metadata, name: &str) -> Result<(), LoadError> {
    match crate::platform::files::not_a_file_to_read(metadata) {
        None => Ok(()),
        Some(kind) => Err(LoadError::NotAFile {
            path: name.to_owned(),
            kind,
        }),
    }
}

/// Reads and parses a scene file; errors name the path as given.
pub fn load_scene(path: &Path) -> Result<Scene, LoadError> {
    load_scene_with_progress(path, &|_| {})
}

/// Bytes read between two progress reports while loading.
const READ_BLOCK_BYTES: u64 = 1 << 20;

/// Share of a load's progress given to reading the file (the rest is parsing).
const READ_SHARE: f64 = 0.1;

/// Regular files of at least this many bytes are read as two halves at once.
const READ_IN_HALVES_MIN_BYTES: u64 = 8 << 20;

/// Reads the first `length` bytes of `file` (a regular file) as two halves at once, each on a
/// thread of its own with positional reads, telling `progress` how many bytes the first half
/// has read (twice that: the halves go at the same pace). On a fresh process every page of the
/// buffer is memory the kernel hands over and zeroes on first touch: on two cores, that takes
/// half as long. Returns the bytes up to the first short read (a file that shrank meanwhile):
/// never a gap.
fn read_in_halves(
    file: &std::fs::File,
    length: usize,
    progress: &(dyn Fn(usize) + Sync),
) -> std::io::Result<Vec<u8>> {
    /// Fills `buffer` from `offset` on, a block at a time; returns how much was read (less at
    /// the end of the file).
    fn read_at(
        file: &std::fs::File,
        buffer: &mut [u8],
        offset: usize,
        progress: &dyn Fn(usize),
    ) -> std::io::Result<usize> {
        let mut read = 0;
        while read < buffer.len() {
            let block = (buffer.len() - read).min(READ_BLOCK_BYTES as usize);
            let at = (offset + read) as u64;
            match crate::platform::files::read_at(file, &mut buffer[read..read + block], at) {
                Ok(0) => break,
                Ok(n) => read += n,
                Err(error) if error.kind() == std::io::ErrorKind::Interrupted => {}
                Err(error) => return Err(error),
            }
            progress(read);
        }
        Ok(read)
    }
    let mut bytes = vec![0u8; length];
    let half = length / 2;
    let at_once = std::thread::scope(|scope| {
        let (first, second) = bytes.split_at_mut(half);
        let second_half = std::thread::Builder::new()
            .name("read-ahead".into())
            .spawn_scoped(scope, move || read_at(file, second, half, &|_| {}))
            .ok()?;
        let first_read = read_at(file, first, 0, &|read| progress(2 * read));
        let second_read = second_half
            .join()
            .unwrap_or_else(|_| Err(std::io::Error::other("the reading thread failed")));
        Some((first_read, second_read))
    });
    // No thread could start: this one reads both.
    let (first_read, second_read) = at_once.unwrap_or_else(|| {
        let (first, second) = bytes.split_at_mut(half);
        let first_read = read_at(file, first, 0, &|read| progress(read));
        (first_read, read_at(file, second, half, &|_| {}))
    });
    let (first_read, second_read) = (first_read?, second_read?);
    let whole = if first_read < half {
        first_read
    } else {
        half + second_read
    };
    bytes.truncate(whole);
    Ok(bytes)
}

/// [`load_scene`], telling `progress` the share of the work done (0 to 1) as it goes: reading
/// the file in blocks, then parsing.
pub fn load_scene_with_progress(
    path: &Path,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Scene, LoadError> {
    use std::io::{Read as _, Seek as _};
    // Never backwards (halves report as they read, and a file may shrink meanwhile).
    let reported = std::sync::Mutex::new(0.0f64);
    let progress = &|share: f64| {
        let mut reported = reported
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if share >= *reported {
            *reported = share;
            progress(share);
        }
    };
    let name = path.display().to_string();
    let io_error = |source| LoadError::Io {
        path: name.clone(),
        source,
    };
    let mut file = std::fs::File::open(path).map_err(io_error)?;
    let metadata = file.metadata().map_err(io_error)?;
    check_file_type(&metadata, &name)?;
    if metadata.len() > MAX_SCENE_BYTES {
        return Err(LoadError::TooLarge {
            path: name,
            size: format!("the file is {} bytes", metadata.len()),
        });
    }
    let expected = metadata.len().max(1);
    let length = usize::try_from(metadata.len()).unwrap_or(0);
    let mut bytes = if metadata.is_file() && metadata.len() >= READ_IN_HALVES_MIN_BYTES {
        let bytes = read_in_halves(&file, length, &|read| {
            progress(READ_SHARE * (read as f64 / expected as f64).min(1.0));
        })
        .map_err(io_error)?;
        // What the file holds beyond (it grew), read on from there.
        file.seek(std::io::SeekFrom::Start(bytes.len() as u64))
            .map_err(io_error)?;
        bytes
    } else {
        Vec::with_capacity(length)
    };
    loop {
        // Room for a whole block first, asked for so that a refusal is an error, not an abort
        // (a pipe under a memory limit): `read_to_end` then reads into that room and never
        // grows the list itself.
        let room = usize::try_from(READ_BLOCK_BYTES).unwrap_or(usize::MAX) + 64;
        if bytes.try_reserve(room).is_err() {
            return Err(io_error(std::io::Error::new(
                std::io::ErrorKind::OutOfMemory,
                format!(
                    "not enough memory to read more than {} MB of it",
                    bytes.len() / 1_000_000
                ),
            )));
        }
        // Straight into the list's spare room (one copy, not two), a block at a time for the
        // progress; `read_to_end` retries interrupted reads.
        match (&mut file).take(READ_BLOCK_BYTES).read_to_end(&mut bytes) {
            Ok(0) => break,
            Ok(_) => {}
            Err(error) => return Err(io_error(error)),
        }
        // A pipe's length is not known beforehand: stop at the limit.
        if bytes.len() as u64 > MAX_SCENE_BYTES {
            return Err(LoadError::TooLarge {
                path: name,
                size: "the input goes on past 1 GiB".into(),
            });
        }
        progress(READ_SHARE * (bytes.len() as f64 / expected as f64).min(1.0));
    }
    let parse_progress = |share: f64| progress(READ_SHARE + (1.0 - READ_SHARE) * share);
    let scene = parse_scene_bytes_with_progress(&bytes, &parse_progress)
        .map_err(|error| error.in_file(name.clone()))?;
    progress(1.0);
    Ok(scene)
}

/// A scene from bytes that did not come from a file (a browser page's dropped or fetched file),
/// named `name` in errors: the same size limit and the same errors, with line and column, as a
/// file gets.
pub fn load_scene_from_bytes(name: &str, bytes: &[u8]) -> Result<Scene, LoadError> {
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(LoadError::TooLarge {
            path: name.to_owned(),
            size: format!("the file is {} bytes", bytes.len()),
        });
    }
    parse_scene_bytes_with_progress(bytes, &|_| {}).map_err(|error| error.in_file(name).into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_read_what_the_file_holds_up_to_where_it_ends() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("bytes");
        let content: Vec<u8> = (0..3_000_001u32).map(|i| (i % 251) as u8).collect();
        std::fs::write(&path, &content).unwrap();
        let file = std::fs::File::open(&path).unwrap();
        // The whole file, past one read block per half.
        assert_eq!(
            read_in_halves(&file, content.len(), &|_| {}).unwrap(),
            content
        );
        // A file shorter than its length said (it shrank): what is there, without a gap.
        for asked in [content.len() + 10, 2 * content.len() - 2, 5 * content.len()] {
            let read = read_in_halves(&file, asked, &|_| {}).unwrap();
            assert_eq!(read, content, "asked for {asked}");
        }
        // Less than the file holds: the first bytes.
        let read = read_in_halves(&file, 1001, &|_| {}).unwrap();
        assert_eq!(read, &content[..1001]);
    }
}
