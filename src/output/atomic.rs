//! Atomic file writes: the bytes go to a temporary file in the destination's folder, which is then
//! renamed over the destination, so a failure never leaves a half-written file and never damages
//! the previous one. Also the check, made before any work, that a destination can be written.

use std::io::Write;
use std::path::{Path, PathBuf};

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

/// The folder a destination path writes into (`.` for a bare file name).
pub(crate) fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// `path` is not a folder and a temporary file can be created (and is removed) beside it.
pub(crate) fn check_folder_writable(path: &Path) -> Result<(), WriteError> {
    let io_error = |source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    };
    if path.is_dir() {
        return Err(io_error(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            "is a folder",
        )));
    }
    tempfile::Builder::new()
        .prefix(".raytracer-check-")
        .tempfile_in(folder_of(path))
        .map(drop)
        .map_err(io_error)
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    let io_error = |source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut temporary = tempfile::Builder::new()
        .prefix(".raytracer-")
        .suffix(".tmp")
        .tempfile_in(folder_of(path))
        .map_err(io_error)?;
    temporary.write_all(bytes).map_err(io_error)?;
    temporary.as_file().sync_all().map_err(io_error)?;
    temporary
        .persist(path)
        .map_err(|error| io_error(error.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::output::image_file::write_image;
    use image::{Rgb, RgbImage};

    fn sample_image() -> RgbImage {
        RgbImage::from_fn(3, 2, |x, y| Rgb([x as u8 * 100, y as u8 * 200, 7]))
    }

    #[test]
    fn atomic_write_replaces_and_failure_keeps_the_old_file() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("out.png");
        write_image(&path, &sample_image()).unwrap();
        let first = std::fs::read(&path).unwrap();
        // Unknown format: refused before anything is written.
        assert!(write_image(&folder.path().join("out.xyz"), &sample_image()).is_err());
        // Unwritable folder: error, old file untouched, no temporary left behind.
        let missing = folder.path().join("missing").join("out.png");
        let error = write_image(&missing, &sample_image()).unwrap_err();
        assert!(error.to_string().contains("cannot write"), "{error}");
        assert_eq!(std::fs::read(&path).unwrap(), first);
        let names: Vec<_> = std::fs::read_dir(folder.path()).unwrap().collect();
        assert_eq!(names.len(), 1, "only out.png remains: {names:?}");
    }
}
