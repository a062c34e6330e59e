//! Writing images: the format is chosen by the file's extension (`.tga`: uncompressed 24-bit with
//! the top row first; `.png`), and every write is atomic — the bytes go to a temporary file in
//! the destination's folder, which is then renamed over the destination, so a failure never leaves
//! a half-written file and never damages the previous one.

use std::io::Write;
use std::path::{Path, PathBuf};

use image::codecs::png::PngEncoder;
use image::codecs::tga::TgaEncoder;
use image::{ExtendedColorType, ImageEncoder, RgbImage};

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
    pub const EXTENSIONS: &'static str = ".tga, .png";

    /// The format a path's extension names (case-insensitive).
    pub fn from_path(path: &Path) -> Result<Self, ExportError> {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match extension.as_deref() {
            Some("tga") => Ok(Self::Tga),
            Some("png") => Ok(Self::Png),
            _ => Err(ExportError::UnknownFormat {
                path: path.to_path_buf(),
            }),
        }
    }
}

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The extension names no supported format.
    #[error("{}: unknown image format; use one of {}", path.display(), ImageFormat::EXTENSIONS)]
    UnknownFormat {
        /// The destination.
        path: PathBuf,
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

/// Encodes `image` in `format`.
pub fn encode(image: &RgbImage, format: ImageFormat) -> Result<Vec<u8>, image::ImageError> {
    let mut bytes = Vec::new();
    let (width, height) = image.dimensions();
    match format {
        ImageFormat::Tga => TgaEncoder::new(&mut bytes).disable_rle().write_image(
            image.as_raw(),
            width,
            height,
            ExtendedColorType::Rgb8,
        )?,
        ImageFormat::Png => PngEncoder::new(&mut bytes).write_image(
            image.as_raw(),
            width,
            height,
            ExtendedColorType::Rgb8,
        )?,
    }
    Ok(bytes)
}

/// Writes `image` to `path` in the format its extension names, atomically.
pub fn write_image(path: &Path, image: &RgbImage) -> Result<(), ExportError> {
    let format = ImageFormat::from_path(path)?;
    let bytes = encode(image, format).map_err(|source| ExportError::Encode {
        path: path.to_path_buf(),
        source,
    })?;
    write_atomically(path, &bytes)
}

/// The folder a destination path writes into (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// Checks, without touching `path`, that a file could be written there: the format is known,
/// `path` is not a folder, and a temporary file can be created (and is removed) in its folder.
pub fn check_writable(path: &Path) -> Result<(), ExportError> {
    ImageFormat::from_path(path)?;
    check_folder_writable(path)
}

/// [`check_writable`] for a raw depth file (`.pfm`, `.exr`).
pub fn check_writable_raw(path: &Path) -> Result<(), ExportError> {
    if crate::depth_file::RawDepthFormat::from_path(path).is_none() {
        return Err(ExportError::UnknownFormat {
            path: path.to_path_buf(),
        });
    }
    check_folder_writable(path)
}

/// `path` is not a folder and a temporary file can be created (and is removed) beside it.
fn check_folder_writable(path: &Path) -> Result<(), ExportError> {
    let io_error = |source| ExportError::Io {
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
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), ExportError> {
    let io_error = |source| ExportError::Io {
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

/// The files one export writes, derived from a base path `dir/stem.ext`:
/// `dir/stem_colour.ext`, `dir/stem_depth.ext` and (optionally) `dir/stem_both.ext`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExportPaths {
    /// Colour image.
    pub colour: PathBuf,
    /// Depth image.
    pub depth: PathBuf,
    /// Colour and depth side by side.
    pub side_by_side: PathBuf,
}

impl ExportPaths {
    /// Paths for base `path`; `format` applies when the path's extension names no format.
    pub fn new(path: &Path, format: ImageFormat) -> Self {
        let format = ImageFormat::from_path(path).unwrap_or(format);
        let extension = match format {
            ImageFormat::Tga => "tga",
            ImageFormat::Png => "png",
        };
        let has_format = ImageFormat::from_path(path).is_ok();
        let stem = if has_format {
            path.file_stem()
        } else {
            path.file_name()
        }
        .map_or_else(|| "raytracer".into(), |s| s.to_string_lossy().into_owned());
        let with_suffix =
            |suffix: &str| path.with_file_name(format!("{stem}_{suffix}.{extension}"));
        Self {
            colour: with_suffix("colour"),
            depth: with_suffix("depth"),
            side_by_side: with_suffix("both"),
        }
    }
}

/// Writes the colour and depth images of `frame` (and, if asked, both side by side) to the
/// paths of [`ExportPaths::new`]; returns the paths written. Each file is written atomically.
pub fn write_frame_images(
    frame: &crate::render::Frame,
    depth_range: crate::depth::DepthRange,
    base_path: &Path,
    format: ImageFormat,
    side_by_side: bool,
) -> Result<Vec<PathBuf>, ExportError> {
    let paths = ExportPaths::new(base_path, format);
    write_image(&paths.colour, &frame.colour_image())?;
    write_image(&paths.depth, &frame.depth_image(depth_range))?;
    let mut written = vec![paths.colour, paths.depth];
    if side_by_side {
        write_image(&paths.side_by_side, &frame.side_by_side_image(depth_range))?;
        written.push(paths.side_by_side);
    }
    Ok(written)
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
    fn export_paths_add_suffixes_and_keep_the_folder() {
        let paths = ExportPaths::new(Path::new("shots/view.tga"), ImageFormat::Png);
        assert_eq!(paths.colour, Path::new("shots/view_colour.tga"));
        assert_eq!(paths.depth, Path::new("shots/view_depth.tga"));
        assert_eq!(paths.side_by_side, Path::new("shots/view_both.tga"));
        let paths = ExportPaths::new(Path::new("view"), ImageFormat::Png);
        assert_eq!(paths.colour, Path::new("view_colour.png"));
        let paths = ExportPaths::new(Path::new("view.v2"), ImageFormat::Tga);
        assert_eq!(paths.depth, Path::new("view.v2_depth.tga"));
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
