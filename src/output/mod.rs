//! Writing files: atomic writes ([`atomic`], with the temporary files of `temporary`), 8-bit image files chosen by extension
//! ([`image_file`]; TGA written row by row by [`tga`]), and lossless depth files (PFM, OpenEXR) and 16-bit depth PNGs
//! ([`depth_file`]), text drawn into pictures ([`text`]) and words quoted for a shell ([`shell`]). Nothing here knows about the
//! command line or the viewer.

pub mod atomic;
pub mod depth_file;
pub(crate) mod image_file;
pub(crate) mod shell;
mod temporary;
pub(crate) mod text;
pub(crate) mod tga;
pub(crate) mod writeback;

pub use atomic::{WriteError, write_atomically};
pub use depth_file::RawDepthFormat;
pub use image_file::{ImageFormat, encode, write_image};
