//! 8-bit image files: the format is chosen by the file's extension (`.tga`: uncompressed 24-bit
//! with the top row first, written by [`super::tga`]; `.png`); every write is atomic
//! ([`super::atomic`]).

use std::io::Write;
use std::path::Path;

use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder, RgbImage};

use super::atomic::{FileSet, Stage, WriteError, check_folder_writable};

/// Image file formats the program writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    /// Truevision TGA, uncompressed 24-bit.
    Tga,
    /// PNG, 8-bit RGB.
    Png,
}

impl ImageFormat {
    /// Extensions accepted, as listed in error messages.
    pub(crate) const EXTENSIONS: &'static str = ".tga, .png";

    /// The format a path's extension names (case-insensitive).
    pub(crate) fn from_path(path: &Path) -> Result<Self, WriteError> {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match extension.as_deref() {
            Some("tga") => Ok(Self::Tga),
            Some("png") => Ok(Self::Png),
            _ => Err(WriteError::UnknownFormat {
                path: path.to_path_buf(),
                expected: Self::EXTENSIONS,
            }),
        }
    }
}

/// Encodes `image` in `format` into `out`.
pub(crate) fn encode_into(
    image: &RgbImage,
    format: ImageFormat,
    out: &mut dyn Write,
) -> Result<(), image::ImageError> {
    let (width, height) = image.dimensions();
    match format {
        ImageFormat::Tga => {
            let (pixels, _) = image.as_raw().as_chunks::<3>();
            super::tga::write_tga(out, width, height, pixels).map_err(image::ImageError::IoError)
        }
        ImageFormat::Png => {
            PngEncoder::new(out).write_image(image.as_raw(), width, height, ExtendedColorType::Rgb8)
        }
    }
}

/// Encodes `image` in `format`.
pub fn encode(image: &RgbImage, format: ImageFormat) -> Result<Vec<u8>, image::ImageError> {
    // A TGA's size is known: room for it at once, not by doubling (each time a fresh copy).
    let mut bytes = match format {
        ImageFormat::Tga => Vec::with_capacity(super::tga::HEADER_BYTES + image.as_raw().len()),
        ImageFormat::Png => Vec::new(),
    };
    encode_into(image, format, &mut bytes)?;
    Ok(bytes)
}

/// Stages `image` in the format `path`'s extension names, streamed into the file set's temporary
/// file (no second copy of the pixels in memory).
pub(crate) fn stage_image(
    set: &mut dyn Stage,
    path: &Path,
    image: &RgbImage,
) -> Result<(), WriteError> {
    let format = ImageFormat::from_path(path)?;
    set.stage_file(path, false, &mut |out| {
        encode_into(image, format, out).map_err(|source| match source {
            image::ImageError::IoError(source) => WriteError::Io {
                path: path.to_path_buf(),
                source,
            },
            source => WriteError::Encode {
                path: path.to_path_buf(),
                source,
            },
        })
    })
}

/// Writes `image` to `path` in the format its extension names, all or nothing.
pub fn write_image(path: &Path, image: &RgbImage) -> Result<(), WriteError> {
    let mut set = FileSet::new();
    stage_image(&mut set, path, image)?;
    set.commit().map(drop)
}

/// Checks, without touching `path`, that a file could be written there: the format is known,
/// `path` is not a folder, and a temporary file can be created (and is removed) in its folder.
pub(crate) fn check_writable(path: &Path) -> Result<(), WriteError> {
    ImageFormat::from_path(path)?;
    check_folder_writable(path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgb;

    fn sample_image() -> RgbImage {
        RgbImage::from_fn(3, 2, |x, y| Rgb([x as u8 * 100, y as u8 * 200, 7]))
    }

    #[test]
    fn writability_is_checked_without_leaving_files() {
        let folder = tempfile::tempdir().unwrap();
        assert!(check_writable(&folder.path().join("a.png")).is_ok());
        assert!(check_writable(&folder.path().join("missing/a.png")).is_err());
        assert!(check_writable(&folder.path().join("a.gif")).is_err());
        std::fs::create_dir(folder.path().join("d.png")).unwrap();
        let error = check_writable(&folder.path().join("d.png")).unwrap_err();
        assert!(error.to_string().contains("is a folder"), "{error}");
        let names: Vec<_> = std::fs::read_dir(folder.path()).unwrap().collect();
        assert_eq!(names.len(), 1, "only the folder d.png: {names:?}");
    }

    #[test]
    fn format_follows_the_extension() {
        assert_eq!(
            ImageFormat::from_path(Path::new("a.TGA")).unwrap(),
            ImageFormat::Tga
        );
        assert_eq!(
            ImageFormat::from_path(Path::new("b/c.png")).unwrap(),
            ImageFormat::Png
        );
        assert!(ImageFormat::from_path(Path::new("c.jpg")).is_err());
        assert!(ImageFormat::from_path(Path::new("noext")).is_err());
    }

    #[test]
    fn tga_is_uncompressed_24_bit_top_row_first() {
        let bytes = encode(&sample_image(), ImageFormat::Tga).unwrap();
        assert_eq!(bytes[2], 2, "image type 2: uncompressed true-colour");
        assert_eq!(bytes[16], 24, "24 bits per pixel");
        assert_eq!(bytes[17] & 0x20, 0x20, "origin bit: top row first");
        assert_eq!(
            bytes.len(),
            18 + 3 * 2 * 3,
            "header + raw pixels, no compression"
        );
        let decoded = image::load_from_memory_with_format(&bytes, image::ImageFormat::Tga)
            .unwrap()
            .to_rgb8();
        assert_eq!(decoded, sample_image());
    }

    #[test]
    fn png_round_trips() {
        let bytes = encode(&sample_image(), ImageFormat::Png).unwrap();
        let decoded = image::load_from_memory(&bytes).unwrap().to_rgb8();
        assert_eq!(decoded, sample_image());
    }
}
