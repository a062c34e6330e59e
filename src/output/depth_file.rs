//! Lossless depth files: the raw t of every pixel as 32-bit floats, in PFM (`.pfm`, the portable
//! float map: a text header, then little-endian floats with the **bottom row first**, as the format
//! says) or single-channel OpenEXR (`.exr`, channel `Z`, top row first, lossless ZIP compression),
//! with `+∞` where no ray hits; and the depth image as a 16-bit grey PNG mapped over a depth range.
//! Readers for both float formats come along (the tests read the files back; users' scripts can
//! too). Every write is atomic ([`super::atomic`]).

use std::io::Cursor;
use std::path::{Path, PathBuf};

use super::atomic::{Stage, WriteError, check_folder_writable, stage_bytes};
use crate::render::Frame;
use crate::render::depth_map::{DepthRange, quantize_u16};

/// Lossless depth formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum RawDepthFormat {
    /// Portable float map, one channel (`Pf`).
    Pfm,
    /// OpenEXR, one 32-bit float channel `Z`.
    Exr,
}

impl RawDepthFormat {
    /// Extensions accepted, as listed in error messages.
    pub(crate) const EXTENSIONS: &'static str = ".pfm, .exr";

    /// The format a path's extension names (case-insensitive).
    pub(crate) fn from_path(path: &Path) -> Option<Self> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("pfm") => Some(Self::Pfm),
            Some("exr") => Some(Self::Exr),
            _ => None,
        }
    }
}

/// Raw depth read back from a file: t per pixel, **top row first** (as [`Frame::t`]).
#[derive(Debug, Clone, PartialEq)]
pub struct RawDepth {
    /// Width in pixels.
    pub width_px: u32,
    /// Height in pixels.
    pub height_px: u32,
    /// t per pixel, top row first; `+∞` where no ray hits.
    pub t: Vec<f32>,
}

/// Why a depth file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ReadDepthError {
    /// The file could not be read.
    #[error("{}: cannot read: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The file is not a depth file this module writes.
    #[error("{}: not a one-channel float depth file: {reason}", path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
}

/// The frame's t as 32-bit floats, top row first (`+∞` stays `+∞`).
fn t_as_f32(frame: &Frame) -> Vec<f32> {
    frame.t.iter().map(|&t| t as f32).collect()
}

/// PFM bytes of a one-channel float image given top row first (written bottom row first).
pub(crate) fn encode_pfm(width_px: u32, height_px: u32, t_top_first: &[f32]) -> Vec<u8> {
    let header = format!("Pf\n{width_px} {height_px}\n-1.0\n");
    let mut bytes = Vec::with_capacity(header.len() + 4 * t_top_first.len());
    bytes.extend_from_slice(header.as_bytes());
    let width = width_px as usize;
    for row in t_top_first.chunks_exact(width.max(1)).rev() {
        for value in row {
            bytes.extend_from_slice(&value.to_le_bytes());
        }
    }
    bytes
}

/// Parses PFM bytes (one channel, either byte order) into t top row first.
pub(crate) fn decode_pfm(bytes: &[u8]) -> Result<RawDepth, String> {
    // Header: three whitespace-separated words after "Pf", then one whitespace byte.
    let mut words = Vec::new();
    let mut offset = 0;
    while words.len() < 4 {
        while bytes.get(offset).is_some_and(u8::is_ascii_whitespace) {
            offset += 1;
        }
        let start = offset;
        while bytes.get(offset).is_some_and(|b| !b.is_ascii_whitespace()) {
            offset += 1;
        }
        if start == offset {
            return Err("the header ends early".into());
        }
        words.push(String::from_utf8_lossy(&bytes[start..offset]).into_owned());
    }
    offset += 1; // the single whitespace byte before the data
    if words[0] != "Pf" {
        return Err(format!("expected 'Pf' (one channel), found '{}'", words[0]));
    }
    let number = |text: &str| {
        text.parse::<u32>()
            .map_err(|_| format!("bad size '{text}'"))
    };
    let (width_px, height_px) = (number(&words[1])?, number(&words[2])?);
    let scale: f64 = words[3]
        .parse()
        .map_err(|_| format!("bad scale '{}'", words[3]))?;
    let little_endian = scale < 0.0;
    let count = width_px as usize * height_px as usize;
    let data = bytes.get(offset..).unwrap_or_default();
    if data.len() != 4 * count {
        return Err(format!(
            "expected {} bytes of data for {width_px}×{height_px}, found {}",
            4 * count,
            data.len()
        ));
    }
    let values: Vec<f32> = data
        .chunks_exact(4)
        .map(|b| {
            let b = [b[0], b[1], b[2], b[3]];
            if little_endian {
                f32::from_le_bytes(b)
            } else {
                f32::from_be_bytes(b)
            }
        })
        .collect();
    let width = (width_px as usize).max(1);
    let t = values
        .chunks_exact(width)
        .rev()
        .flatten()
        .copied()
        .collect();
    Ok(RawDepth {
        width_px,
        height_px,
        t,
    })
}

/// OpenEXR bytes of a one-channel (`Z`) 32-bit float image given top row first.
pub(crate) fn encode_exr(
    width_px: u32,
    height_px: u32,
    t_top_first: &[f32],
) -> Result<Vec<u8>, exr::error::Error> {
    use exr::prelude::*;
    let width = width_px as usize;
    let channel = AnyChannel::new("Z", FlatSamples::F32(t_top_first.to_vec()));
    let layer = Layer::new(
        (width, height_px as usize),
        LayerAttributes::named("depth"),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(vec![channel])),
    );
    let mut bytes = Vec::new();
    Image::from_layer(layer)
        .write()
        .to_buffered(Cursor::new(&mut bytes))?;
    Ok(bytes)
}

/// Parses OpenEXR bytes holding one 32-bit float channel into t top row first.
pub(crate) fn decode_exr(bytes: &[u8]) -> Result<RawDepth, String> {
    use exr::prelude::*;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_buffered(Cursor::new(bytes))
        .map_err(|e| e.to_string())?;
    let layer = image.layer_data;
    let channels = &layer.channel_data.list;
    let [channel] = channels.as_slice() else {
        return Err(format!("expected one channel, found {}", channels.len()));
    };
    let FlatSamples::F32(t) = &channel.sample_data else {
        return Err("the channel is not 32-bit float".into());
    };
    let to_u32 = |n: usize| u32::try_from(n).map_err(|_| "image too large".to_owned());
    Ok(RawDepth {
        width_px: to_u32(layer.size.width())?,
        height_px: to_u32(layer.size.height())?,
        t: t.clone(),
    })
}

/// Stages `frame`'s raw t for `path` as PFM or OpenEXR, chosen by the extension.
pub(crate) fn stage_raw_depth(
    set: &mut dyn Stage,
    frame: &Frame,
    path: &Path,
) -> Result<(), WriteError> {
    let format = RawDepthFormat::from_path(path).ok_or_else(|| WriteError::UnknownFormat {
        path: path.to_path_buf(),
        expected: RawDepthFormat::EXTENSIONS,
    })?;
    let t = t_as_f32(frame);
    let bytes = match format {
        RawDepthFormat::Pfm => encode_pfm(frame.width_px, frame.height_px, &t),
        RawDepthFormat::Exr => {
            encode_exr(frame.width_px, frame.height_px, &t).map_err(|e| WriteError::Encode {
                path: path.to_path_buf(),
                source: image::ImageError::IoError(std::io::Error::other(e.to_string())),
            })?
        }
    };
    stage_bytes(set, path, &bytes)
}

/// Checks, without touching `path`, that a raw depth file (`.pfm`, `.exr`) could be written there.
pub(crate) fn check_writable_raw(path: &Path) -> Result<(), WriteError> {
    if RawDepthFormat::from_path(path).is_none() {
        return Err(WriteError::UnknownFormat {
            path: path.to_path_buf(),
            expected: RawDepthFormat::EXTENSIONS,
        });
    }
    check_folder_writable(path)
}

/// Reads a PFM or OpenEXR depth file (as [`stage_raw_depth`] writes them).
pub fn read_raw_depth(path: &Path) -> Result<RawDepth, ReadDepthError> {
    let format_error = |reason: String| ReadDepthError::Format {
        path: path.to_path_buf(),
        reason,
    };
    let format = RawDepthFormat::from_path(path)
        .ok_or_else(|| format_error(format!("use one of {}", RawDepthFormat::EXTENSIONS)))?;
    let bytes = std::fs::read(path).map_err(|source| ReadDepthError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    match format {
        RawDepthFormat::Pfm => decode_pfm(&bytes),
        RawDepthFormat::Exr => decode_exr(&bytes),
    }
    .map_err(format_error)
}

/// The 16-bit grey depth image of `frame` over `range` (`floor(grey·65535)`, no hit 0), top row
/// first.
pub(crate) fn depth_image_u16(
    frame: &Frame,
    range: DepthRange,
) -> image::ImageBuffer<image::Luma<u16>, Vec<u16>> {
    let pixels = frame
        .t
        .iter()
        .map(|&t| quantize_u16(range.grey(t)))
        .collect();
    // The buffer has exactly width × height values, so this always succeeds; an empty image is
    // the (unreachable) fallback rather than a panic.
    image::ImageBuffer::from_raw(frame.width_px, frame.height_px, pixels).unwrap_or_default()
}

/// Stages the 16-bit grey PNG of `frame`'s depth over `range` for `path` (must end in `.png`).
pub(crate) fn stage_depth_png16(
    set: &mut dyn Stage,
    frame: &Frame,
    range: DepthRange,
    path: &Path,
) -> Result<(), WriteError> {
    let is_png = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        return Err(WriteError::UnknownFormat {
            path: path.to_path_buf(),
            expected: ".png",
        });
    }
    let mut bytes = Vec::new();
    image::DynamicImage::ImageLuma16(depth_image_u16(frame, range))
        .write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png)
        .map_err(|source| WriteError::Encode {
            path: path.to_path_buf(),
            source,
        })?;
    stage_bytes(set, path, &bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::atomic::FileSet;
    use crate::render::NO_HIT;

    fn write_raw_depth(frame: &Frame, path: &Path) -> Result<(), WriteError> {
        let mut set = FileSet::new();
        stage_raw_depth(&mut set, frame, path)?;
        set.commit().map(drop)
    }

    fn write_depth_png16(frame: &Frame, range: DepthRange, path: &Path) -> Result<(), WriteError> {
        let mut set = FileSet::new();
        stage_depth_png16(&mut set, frame, range, path)?;
        set.commit().map(drop)
    }

    fn frame() -> Frame {
        // 3×2, top row first; one no-hit pixel.
        let t = vec![1.5, -2.25, f64::INFINITY, 1e5 + 0.1, 7.0, 0.0];
        Frame {
            width_px: 3,
            height_px: 2,
            colour: vec![[0; 3]; 6],
            sphere: t
                .iter()
                .map(|t: &f64| if t.is_finite() { 0 } else { NO_HIT })
                .collect(),
            t,
            depth_grey: None,
            disc_tests: 0,
        }
    }

    #[test]
    fn pfm_is_bottom_row_first_little_endian() {
        let bytes = encode_pfm(3, 2, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let header = b"Pf\n3 2\n-1.0\n";
        assert_eq!(&bytes[..header.len()], header);
        let first = f32::from_le_bytes(bytes[header.len()..header.len() + 4].try_into().unwrap());
        assert_eq!(first, 4.0, "the bottom row comes first");
        let back = decode_pfm(&bytes).unwrap();
        assert_eq!(back.t, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn pfm_and_exr_files_read_back_exactly() {
        let folder = tempfile::tempdir().unwrap();
        let frame = frame();
        let expected: Vec<f32> = frame.t.iter().map(|&t| t as f32).collect();
        for name in ["depth.pfm", "depth.exr", "DEPTH.EXR"] {
            let path = folder.path().join(name);
            write_raw_depth(&frame, &path).unwrap();
            let back = read_raw_depth(&path).unwrap();
            assert_eq!((back.width_px, back.height_px), (3, 2), "{name}");
            assert_eq!(back.t.len(), 6);
            for (read, want) in back.t.iter().zip(&expected) {
                assert_eq!(read.to_bits(), want.to_bits(), "{name}");
            }
            assert_eq!(back.t[2], f32::INFINITY);
        }
        assert!(matches!(
            write_raw_depth(&frame, &folder.path().join("depth.png")),
            Err(WriteError::UnknownFormat { .. })
        ));
    }

    #[test]
    fn malformed_pfm_is_an_error_not_a_panic() {
        for bytes in [
            &b""[..],
            b"PF\n1 1\n-1\n0000",
            b"Pf\n2 2\n-1\n\0\0\0\0",
            b"Pf\nx 1\n-1\n\0\0\0\0",
            b"Pf 1",
        ] {
            assert!(decode_pfm(bytes).is_err());
        }
        assert!(decode_exr(b"not an exr").is_err());
    }

    #[test]
    fn sixteen_bit_png_maps_the_range() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("depth16.png");
        let range = DepthRange::new(0.0, 8.0);
        write_depth_png16(&frame(), range, &path).unwrap();
        let read = image::open(&path).unwrap().into_luma16();
        assert_eq!(read.dimensions(), (3, 2));
        // t = 1.5 → grey 6.5/8 → floor(0.8125 · 65535) = 53247; t = −2.25 → white; no hit → 0.
        assert_eq!(read.get_pixel(0, 0).0[0], 53247);
        assert_eq!(read.get_pixel(1, 0).0[0], 65535);
        assert_eq!(read.get_pixel(2, 0).0[0], 0);
        assert_eq!(read.get_pixel(1, 1).0[0], quantize_u16(1.0 / 8.0));
        assert!(write_depth_png16(&frame(), range, &folder.path().join("d.tga")).is_err());
    }

    #[test]
    fn a_big_endian_pfm_from_another_program_reads_with_its_rows_flipped() {
        // Written by hand as another program would: a positive scale means big-endian, and
        // the rows run bottom to top.
        let mut bytes = b"Pf\n2 2\n1.0\n".to_vec();
        for value in [1.0f32, 2.0, 3.0, f32::INFINITY] {
            bytes.extend_from_slice(&value.to_be_bytes());
        }
        let depth = decode_pfm(&bytes).unwrap();
        assert_eq!((depth.width_px, depth.height_px), (2, 2));
        assert_eq!(depth.t, [3.0, f32::INFINITY, 1.0, 2.0], "top row first");
    }

    #[test]
    fn truncated_and_foreign_exr_files_are_errors_not_panics() {
        use exr::prelude::*;
        let t = [1.5f32, -2.0, f32::INFINITY, 4.0, 5.0, 6.0];
        let whole = encode_exr(3, 2, &t).unwrap();
        assert_eq!(decode_exr(&whole).unwrap().t, t);
        for length in [0, 4, 20, whole.len() / 2, whole.len() - 1] {
            assert!(decode_exr(&whole[..length]).is_err(), "{length} bytes");
        }
        // Another program's EXR with two channels: an error that says so.
        let channels = vec![
            AnyChannel::new("R", FlatSamples::F32(t.to_vec())),
            AnyChannel::new("G", FlatSamples::F32(t.to_vec())),
        ];
        let layer = Layer::new(
            (3, 2),
            LayerAttributes::named("rgb"),
            Encoding::UNCOMPRESSED,
            AnyChannels::sort(SmallVec::from_vec(channels)),
        );
        let mut bytes = Vec::new();
        Image::from_layer(layer)
            .write()
            .to_buffered(Cursor::new(&mut bytes))
            .unwrap();
        let error = decode_exr(&bytes).unwrap_err();
        assert!(error.contains("one channel"), "{error}");
    }
}
