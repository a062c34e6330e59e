//! Reading the image a user compares with the exact render: a file, a named pipe or bytes, TGA,
//! PNG or what else the `image` crate reads (by the name's extension unless the bytes say
//! otherwise), as an 8-bit RGB picture.
//!
//! Images come from strangers (a student's program, a class's submissions), so they are read
//! within bounds: a file of more than [`MAX_FILE_BYTES`] is not read past that size, and an image
//! whose header announces more than [`MAX_SIDE_PX`] pixels a side or more than [`MAX_DECODE_BYTES`]
//! of pixels (a small PNG of a huge image, a "decompression bomb") is refused before it is
//! decoded. The file is read as a stream, never sought, so a named pipe works as a file does;
//! its first bytes must be an image's, and a TGA is read no further than its header announces
//! ([`super::image_head`]): a device or an endless stream is refused at once. A PNG's chunks
//! that say nothing of its pixels (a colour profile, text) are left out before it is decoded.

use std::io::Read;
use std::path::Path;

use image::RgbImage;

use super::image_head::{HEAD_BYTES, announced_length, png_pixels_only};

/// The most bytes read of an image file (a 16384×16384 uncompressed 24-bit TGA is 768 MiB).
pub const MAX_FILE_BYTES: u64 = 800 << 20;
/// The longest side of an image read, in pixels.
pub const MAX_SIDE_PX: u32 = 16_384;
/// The most memory the decoder may take for the pixels (an 8-bit RGB image of 13,000×13,000; the
/// course's images are 200×200).
pub const MAX_DECODE_BYTES: u64 = 512 << 20;

/// Why an image to compare could not be read.
#[derive(Debug, thiserror::Error)]
pub enum TheirImageError {
    /// The file could not be read.
    #[error("cannot read '{path}': {source}")]
    Read {
        /// The file.
        path: String,
        /// The system's error.
        source: std::io::Error,
    },
    /// The file is larger than [`MAX_FILE_BYTES`].
    #[error("'{path}' is larger than {} MiB: not read", MAX_FILE_BYTES >> 20)]
    TooLarge {
        /// The file.
        path: String,
    },
    /// Its header announces another size than the one asked for: not decoded.
    #[error(
        "'{path}' is {}×{} pixels, not the {}×{} asked for",
        found.0, found.1, expected.0, expected.1
    )]
    OtherSize {
        /// The file.
        path: String,
        /// Its size, from its header.
        found: (u32, u32),
        /// The size asked for.
        expected: (u32, u32),
    },
    /// The bytes are not an image the decoder reads, or its header asks for more than the limits.
    #[error("cannot read the image '{path}': {message}")]
    Decode {
        /// The file (or the name the bytes came under).
        path: String,
        /// The decoder's words.
        message: String,
    },
}

impl TheirImageError {
    /// What went wrong, without the file's name (for a message that names it already).
    pub fn reason(&self) -> String {
        match self {
            Self::Read { source, .. } => source.to_string(),
            Self::TooLarge { .. } => format!("larger than {} MiB: not read", MAX_FILE_BYTES >> 20),
            Self::OtherSize {
                found, expected, ..
            } => format!(
                "{}×{} pixels, not the {}×{} asked for",
                found.0, found.1, expected.0, expected.1
            ),
            Self::Decode { message, .. } => message.clone(),
        }
    }
}

/// How long [`read_their_image_settled`] waits between two looks at a file being written.
const SETTLE_WAIT: std::time::Duration = std::time::Duration::from_millis(100);

/// How many looks [`read_their_image_settled`] takes before it says the last error: 3 s for a
/// program to finish writing its image.
const SETTLE_LOOKS: u32 = 30;

/// Reads their image as [`read_their_image`] does, once their program has finished writing it:
/// read only when its size holds for [`SETTLE_WAIT`], and read again while its bytes are not yet
/// a whole image, for [`SETTLE_LOOKS`] looks; then the last error. For a watched file, which
/// their program writes while the viewer looks (never in a page: it blocks its thread).
pub fn read_their_image_settled(path: &Path) -> Result<RgbImage, TheirImageError> {
    let size = || std::fs::metadata(path).map(|m| m.len()).ok();
    let mut last = None;
    for _ in 0..SETTLE_LOOKS {
        let before = size();
        std::thread::sleep(SETTLE_WAIT);
        if before.is_some() && before == size() {
            match read_their_image(path) {
                Ok(image) => return Ok(image),
                Err(error) => last = Some(error),
            }
        }
    }
    last.map_or_else(|| read_their_image(path), Err)
}

/// Reads an image file to compare (any size within the limits; TGA, PNG and what else the
/// `image` crate reads), as a stream: a named pipe is read as a file is.
pub fn read_their_image(path: &Path) -> Result<RgbImage, TheirImageError> {
    read_their_image_sized(path, None)
}

/// [`read_their_image`], refusing an image of another size than `expected` before it is
/// decoded ([`TheirImageError::OtherSize`]).
pub fn read_their_image_sized(
    path: &Path,
    expected: Option<(u32, u32)>,
) -> Result<RgbImage, TheirImageError> {
    let file = std::fs::File::open(path).map_err(|source| read_error(path, source))?;
    read_their_file_sized(file, path, expected)
}

/// Reads the image file `file` (opened from `path`) as [`read_their_image`] does: for a file
/// opened as checked (a submission's, opened without following a link).
pub fn read_their_file(file: std::fs::File, path: &Path) -> Result<RgbImage, TheirImageError> {
    read_their_file_sized(file, path, None)
}

/// [`read_their_file`], where an image whose header announces another size than `expected` is
/// refused before it is decoded ([`TheirImageError::OtherSize`]): a grader's class of wrong-sized
/// images takes no memory for their pixels.
pub fn read_their_file_sized(
    file: std::fs::File,
    path: &Path,
    expected: Option<(u32, u32)>,
) -> Result<RgbImage, TheirImageError> {
    // A regular file's length is known: one too large is not read at all.
    if file
        .metadata()
        .is_ok_and(|m| m.is_file() && m.len() > MAX_FILE_BYTES)
    {
        return Err(TheirImageError::TooLarge {
            path: path.display().to_string(),
        });
    }
    let mut stream = file.take(MAX_FILE_BYTES + 1);
    let mut bytes = Vec::new();
    // The first bytes say whether it is an image, and a TGA how long it can be: a device, an
    // endless stream or a file of garbage is not read further.
    (&mut stream)
        .take(HEAD_BYTES as u64)
        .read_to_end(&mut bytes)
        .map_err(|source| read_error(path, source))?;
    let announced = if bytes.is_empty() {
        None
    } else {
        announced_length(&bytes).map_err(|message| TheirImageError::Decode {
            path: path.display().to_string(),
            message,
        })?
    };
    let most = announced.map_or(MAX_FILE_BYTES, |length| length.min(MAX_FILE_BYTES));
    (&mut stream)
        .take((most + 1).saturating_sub(bytes.len() as u64))
        .read_to_end(&mut bytes)
        .map_err(|source| read_error(path, source))?;
    if bytes.len() as u64 > most {
        if announced.is_none() || most == MAX_FILE_BYTES {
            return Err(TheirImageError::TooLarge {
                path: path.display().to_string(),
            });
        }
        // A TGA needs no more than its header announces: what follows is not read.
        bytes.truncate(most as usize);
    }
    decode_their_image_sized(path, &bytes, expected)
}

/// A failure to read `path`.
fn read_error(path: &Path, source: std::io::Error) -> TheirImageError {
    TheirImageError::Read {
        path: path.display().to_string(),
        source,
    }
}

/// Decodes the image `bytes` named `name` (the format by the name's extension, as for a file,
/// unless the bytes say otherwise), as an 8-bit RGB picture, within the limits.
pub fn decode_their_image(name: &Path, bytes: &[u8]) -> Result<RgbImage, TheirImageError> {
    decode_their_image_sized(name, bytes, None)
}

/// [`decode_their_image`], refusing an image of another size than `expected` before it is
/// decoded.
fn decode_their_image_sized(
    name: &Path,
    bytes: &[u8],
    expected: Option<(u32, u32)>,
) -> Result<RgbImage, TheirImageError> {
    let decode_error = |message: String| TheirImageError::Decode {
        path: name.display().to_string(),
        message,
    };
    if !bytes.is_empty() {
        announced_length(&bytes[..bytes.len().min(HEAD_BYTES)]).map_err(decode_error)?;
    }
    // A PNG's colour profile and text say nothing of its pixels, and may inflate to gigabytes.
    let pixels_only = png_pixels_only(bytes);
    let bytes = pixels_only.as_deref().unwrap_or(bytes);
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_SIDE_PX);
    limits.max_image_height = Some(MAX_SIDE_PX);
    limits.max_alloc = Some(MAX_DECODE_BYTES);
    let reader = || {
        let mut reader = image::ImageReader::new(std::io::Cursor::new(bytes));
        if let Ok(format) = image::ImageFormat::from_path(name) {
            reader.set_format(format);
        }
        let mut reader = reader
            .with_guessed_format()
            .map_err(|error| decode_error(error.to_string()))?;
        reader.limits(limits.clone());
        Ok::<_, TheirImageError>(reader)
    };
    // The header first: its size is refused before a byte of pixels is decoded.
    let (width, height) = reader()?
        .into_dimensions()
        .map_err(|error| decode_error(limit_message(&error)))?;
    if let Some(expected) = expected
        && (width, height) != expected
    {
        return Err(TheirImageError::OtherSize {
            path: name.display().to_string(),
            found: (width, height),
            expected,
        });
    }
    // The 8-bit RGB copy may be made beside the decoded pixels: it must fit too.
    if u64::from(width) * u64::from(height) * 3 > MAX_DECODE_BYTES {
        return Err(decode_error(format!(
            "{width}×{height} pixels is more than this program reads ({} MiB of pixels)",
            MAX_DECODE_BYTES >> 20
        )));
    }
    let image = reader()?
        .decode()
        .map_err(|error| decode_error(limit_message(&error)))?;
    Ok(image.into_rgb8())
}

/// The decoder's error, in this program's words where it is a limit.
fn limit_message(error: &image::ImageError) -> String {
    match error {
        image::ImageError::Limits(_) => format!(
            "its header announces an image larger than this program reads (at most \
             {MAX_SIDE_PX} pixels a side, {} MiB of pixels): {error}",
            MAX_DECODE_BYTES >> 20
        ),
        _ => error.to_string(),
    }
}
