//! Truevision TGA as the course writes it: uncompressed 24-bit true colour, the top row first
//! (the origin bit set). A whole image is written a run of pixels at a time ([`TgaWriter`]); a
//! render streamed strip by strip (the command line's) writes each strip's pixels at their place
//! in the file ([`TgaFile`]), in any order and from any thread. Both make the same bytes, and
//! neither needs a second copy of the pixels: the image crate's encoder copies the whole image to
//! swap its channels, 12 MB of fresh memory for a 2000×2000 picture.

use std::fs::File;
use std::io::Write;

use crate::platform::files::write_all_at;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Bytes of the header before the pixels.
pub(crate) const HEADER_BYTES: usize = 18;

/// Image type 2: uncompressed true colour.
const UNCOMPRESSED_TRUE_COLOUR: u8 = 2;

/// Image descriptor bit 5: the first row stored is the top one.
const TOP_ROW_FIRST: u8 = 0x20;

/// Pixels converted and written per call to the underlying writer.
const PIXELS_PER_WRITE: usize = 16_384;

/// The 18-byte header of a `width_px × height_px` image; sides above 65,535 pixels cannot be
/// stored.
fn header(width_px: u32, height_px: u32) -> std::io::Result<[u8; HEADER_BYTES]> {
    let side = |px: u32| {
        u16::try_from(px).map_err(|_| {
            std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!("{width_px}×{height_px}: a TGA image side is at most 65535 pixels"),
            )
        })
    };
    let mut header = [0u8; HEADER_BYTES];
    // No image ID, no colour map; the origin (x, y) is (0, 0).
    header[2] = UNCOMPRESSED_TRUE_COLOUR;
    header[12..14].copy_from_slice(&side(width_px)?.to_le_bytes());
    header[14..16].copy_from_slice(&side(height_px)?.to_le_bytes());
    header[16] = 24;
    header[17] = TOP_ROW_FIRST;
    Ok(header)
}

/// RGB pixels to the BGR order the file stores, where they are.
fn to_bgr(pixels: &mut [[u8; 3]]) {
    for pixel in pixels {
        pixel.swap(0, 2);
    }
}

fn invalid(message: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidInput, message)
}

/// Writes a TGA image: the header at once ([`Self::begin`]), then the pixels (RGB, top row
/// first) in as many calls to [`Self::write_pixels`] as the caller likes, then [`Self::finish`].
pub(crate) struct TgaWriter {
    /// Pixels still to come.
    pixels_left: usize,
    /// The pixels being written, as the file stores them (BGR).
    bgr: Vec<u8>,
}

impl TgaWriter {
    /// Writes the header of a `width_px × height_px` image to `out`.
    pub(crate) fn begin(
        out: &mut dyn Write,
        width_px: u32,
        height_px: u32,
    ) -> std::io::Result<Self> {
        out.write_all(&header(width_px, height_px)?)?;
        Ok(Self {
            pixels_left: width_px as usize * height_px as usize,
            bgr: Vec::new(),
        })
    }

    /// Writes the next `rgb` pixels (in storage order: rows top first, left to right) to `out`.
    pub(crate) fn write_pixels(
        &mut self,
        out: &mut dyn Write,
        rgb: &[[u8; 3]],
    ) -> std::io::Result<()> {
        if rgb.len() > self.pixels_left {
            return Err(invalid("more pixels than the TGA image holds".into()));
        }
        self.pixels_left -= rgb.len();
        for chunk in rgb.chunks(PIXELS_PER_WRITE) {
            self.bgr.clear();
            self.bgr.extend_from_slice(chunk.as_flattened());
            let (pixels, _) = self.bgr.as_chunks_mut::<3>();
            to_bgr(pixels);
            out.write_all(&self.bgr)?;
        }
        Ok(())
    }

    /// Checks that every pixel was written.
    pub(crate) fn finish(&self) -> std::io::Result<()> {
        if self.pixels_left != 0 {
            return Err(invalid(format!(
                "the TGA image is {} pixels short",
                self.pixels_left
            )));
        }
        Ok(())
    }
}

/// Writes a whole `width_px × height_px` image (RGB pixels, top row first) as TGA to `out`.
pub(crate) fn write_tga(
    out: &mut dyn Write,
    width_px: u32,
    height_px: u32,
    rgb: &[[u8; 3]],
) -> std::io::Result<()> {
    let mut writer = TgaWriter::begin(out, width_px, height_px)?;
    writer.write_pixels(out, rgb)?;
    writer.finish()
}

/// A TGA file written a strip of pixels at a time, in any order and from any thread, each strip
/// at its place: [`Self::begin`], [`Self::write_pixels_at`], [`Self::finish`].
pub(crate) struct TgaFile {
    pixel_count: usize,
    /// Pixels written so far.
    written: AtomicUsize,
}

impl TgaFile {
    /// Writes the header of a `width_px × height_px` image at the start of `file`.
    pub(crate) fn begin(file: &File, width_px: u32, height_px: u32) -> std::io::Result<Self> {
        write_all_at(file, &header(width_px, height_px)?, 0)?;
        Ok(Self {
            pixel_count: width_px as usize * height_px as usize,
            written: AtomicUsize::new(0),
        })
    }

    /// Writes `rgb`, the pixels from index `first_pixel` on (storage order: rows top first), at
    /// their place in `file`. Their channels are swapped where they are: the caller does not
    /// need them again.
    pub(crate) fn write_pixels_at(
        &self,
        file: &File,
        first_pixel: usize,
        rgb: &mut [[u8; 3]],
    ) -> std::io::Result<()> {
        if first_pixel + rgb.len() > self.pixel_count {
            return Err(invalid(format!(
                "pixels {first_pixel}.. beyond the {} of the TGA image",
                self.pixel_count
            )));
        }
        to_bgr(rgb);
        let offset = HEADER_BYTES + 3 * first_pixel;
        write_all_at(file, rgb.as_flattened(), offset as u64)?;
        self.written.fetch_add(rgb.len(), Ordering::Relaxed);
        Ok(())
    }

    /// Checks that as many pixels were written as the image holds (the caller writes each once).
    pub(crate) fn finish(&self) -> std::io::Result<()> {
        let written = self.written.load(Ordering::Relaxed);
        if written != self.pixel_count {
            return Err(invalid(format!(
                "the TGA image has {written} of its {} pixels",
                self.pixel_count
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::{ExtendedColorType, ImageEncoder, RgbImage};

    /// A seeded image of odd size (no two rows alike, every channel distinct).
    fn picture(width: u32, height: u32) -> RgbImage {
        let mut rng = crate::render::rng::SplitMix64::new(7);
        RgbImage::from_fn(width, height, |_, _| {
            let bits = rng.next_u64();
            image::Rgb([bits as u8, (bits >> 8) as u8, (bits >> 16) as u8])
        })
    }

    fn pixels(image: &RgbImage) -> Vec<[u8; 3]> {
        image.pixels().map(|p| p.0).collect()
    }

    #[test]
    fn the_bytes_are_the_image_crates_uncompressed_tga() {
        for (width, height) in [(1, 1), (3, 2), (257, 19), (1000, 3)] {
            let image = picture(width, height);
            let mut theirs = Vec::new();
            image::codecs::tga::TgaEncoder::new(&mut theirs)
                .disable_rle()
                .write_image(image.as_raw(), width, height, ExtendedColorType::Rgb8)
                .unwrap();
            let mut ours = Vec::new();
            write_tga(&mut ours, width, height, &pixels(&image)).unwrap();
            assert_eq!(ours, theirs, "{width}×{height}");
        }
    }

    #[test]
    fn rows_written_in_any_runs_make_the_same_file_and_decode_to_the_image() {
        let image = picture(300, 70);
        let all = pixels(&image);
        let mut whole = Vec::new();
        write_tga(&mut whole, 300, 70, &all).unwrap();
        let mut out = Vec::new();
        let mut runs = TgaWriter::begin(&mut out, 300, 70).unwrap();
        for run in all.chunks(300 * 9 + 17) {
            runs.write_pixels(&mut out, run).unwrap();
        }
        runs.finish().unwrap();
        assert_eq!(out, whole);
        // Strips at their places, last first, in a file.
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("strips.tga");
        let file = File::create(&path).unwrap();
        let tga = TgaFile::begin(&file, 300, 70).unwrap();
        assert!(tga.finish().is_err(), "no pixel written yet");
        let strip_pixels = 300 * 9 + 17;
        for (index, strip) in all.chunks(strip_pixels).enumerate().rev() {
            let first = index * strip_pixels;
            tga.write_pixels_at(&file, first, &mut strip.to_vec())
                .unwrap();
        }
        tga.finish().unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), whole);
        let decoded = image::load_from_memory_with_format(&whole, image::ImageFormat::Tga)
            .unwrap()
            .to_rgb8();
        assert_eq!(decoded, image);
    }

    #[test]
    fn too_few_or_too_many_pixels_and_huge_sides_are_errors() {
        let mut out = Vec::new();
        let short = TgaWriter::begin(&mut out, 4, 4).unwrap();
        assert!(short.finish().is_err());
        let mut long = TgaWriter::begin(&mut out, 2, 1).unwrap();
        assert!(long.write_pixels(&mut out, &[[0; 3]; 3]).is_err());
        assert!(TgaWriter::begin(&mut out, 70_000, 1).is_err());
        let folder = tempfile::tempdir().unwrap();
        let file = File::create(folder.path().join("a.tga")).unwrap();
        let tga = TgaFile::begin(&file, 2, 2).unwrap();
        assert!(tga.write_pixels_at(&file, 3, &mut [[0; 3]; 2]).is_err());
        tga.write_pixels_at(&file, 0, &mut [[0; 3]; 3]).unwrap();
        assert!(tga.finish().is_err(), "a pixel short");
        assert!(TgaFile::begin(&file, 1, 70_000).is_err());
    }
}
