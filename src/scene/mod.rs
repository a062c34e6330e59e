//! Scenes: the plain data model ([`Scene`]), the parser of the 6.837 assignment-1 text format
//! ([`parse_scene`], [`load_scene`]) and its typed errors, and the writer back to text
//! ([`scene_to_text`]).

mod error;
mod lexer;
mod model;
mod parse;
#[cfg(test)]
mod parse_tests;
mod writer;

pub use error::{Location, ParseError, ParseErrorKind};
pub use model::{
    Bounds, DEFAULT_BACKGROUND, DEFAULT_DIFFUSE, Material, OrthographicCamera, Scene, Sphere,
};
pub use parse::{
    MAX_GROUP_DEPTH, MAX_MAGNITUDE, parse_scene, parse_scene_bytes,
    parse_scene_bytes_with_progress, parse_scene_with_progress,
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
}

/// Reads and parses a scene file; errors name the path as given.
pub fn load_scene(path: &Path) -> Result<Scene, LoadError> {
    load_scene_with_progress(path, &|_| {})
}

/// Share of a load's progress given to reading the file (the rest is parsing).
const READ_SHARE: f64 = 0.1;

/// [`load_scene`], telling `progress` the share of the work done (0 to 1) as it goes: reading
/// the file in blocks, then parsing.
pub fn load_scene_with_progress(
    path: &Path,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Scene, LoadError> {
    use std::io::Read as _;
    let name = path.display().to_string();
    let io_error = |source| LoadError::Io {
        path: name.clone(),
        source,
    };
    let mut file = std::fs::File::open(path).map_err(io_error)?;
    let expected = file.metadata().map(|m| m.len()).unwrap_or(0).max(1);
    let mut bytes = Vec::with_capacity(usize::try_from(expected).unwrap_or(0));
    let mut block = vec![0u8; 1 << 20];
    loop {
        let read = match file.read(&mut block) {
            Ok(0) => break,
            Ok(read) => read,
            Err(error) if error.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(error) => return Err(io_error(error)),
        };
        bytes.extend_from_slice(&block[..read]);
        progress(READ_SHARE * (bytes.len() as f64 / expected as f64).min(1.0));
    }
    let parse_progress = |share: f64| progress(READ_SHARE + (1.0 - READ_SHARE) * share);
    let scene = parse_scene_bytes_with_progress(&bytes, &parse_progress)
        .map_err(|error| error.in_file(name.clone()))?;
    progress(1.0);
    Ok(scene)
}
