//! Scenes: the plain data model ([`Scene`]), the parser of the 6.837 assignment-1 text format
//! ([`parse_scene`], [`load_scene`]) and its typed errors.

mod error;
mod lexer;
mod model;
mod parse;
#[cfg(test)]
mod parse_tests;

pub use error::{Location, ParseError, ParseErrorKind};
pub use lexer::{Lexer, Token};
pub use model::{
    Bounds, DEFAULT_BACKGROUND, DEFAULT_DIFFUSE, Material, OrthographicCamera, Scene, Sphere,
};
pub use parse::{MAX_GROUP_DEPTH, MAX_MAGNITUDE, parse_scene, parse_scene_bytes};

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
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| LoadError::Io {
        path: name.clone(),
        source,
    })?;
    Ok(parse_scene_bytes(&bytes).map_err(|error| error.in_file(name))?)
}
