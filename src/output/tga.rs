//! Truevision TGA as the course writes it: uncompressed 24-bit true colour, the top row first
//! (the origin bit set). One writer takes the pixels a run of rows at a time, so a whole image
//! and a render streamed strip by strip (the command line's) make the same bytes, and neither needs a
//! second copy of the pixels: the image crate's encoder copies the whole image to swap its
//! channels, 12 MB of fresh memory for a 2000×2000 picture.

use std::io::Write;

/// Bytes of the header before the pixels.
pub(crate) const HEADER_BYTES: usize = 18;

/// Image type 2: uncompressed true colour.
const UNCOMPRESSED_TRUE_COLOUR: u8 = 2;

/// Image descriptor bit 5: the first row stored is the top one.
const TOP_ROW_FIRST: u8 = 0x20;

/// Pixels converted and written per call to the underlying writer.
const PIXELS_PER_WRITE: usize = 16_384;

/// The 18-byte header of a `width_px × height_px` image (each side at most 65,535).
fn header(width_px: u16, height_px: u16) -> [u8; HEADER_BYTES] {
    let mut header = [0u8; HEADER_BYTES];
    // No image ID, no colour map; the origin (x, y) is (0, 0).
    header[2] = UNCOMPRESSED_TRUE_COLOUR;
    header[12..14].copy_from_slice(&width_px.to_le_bytes());
    header[14..16].copy_from_slice(&height_px.to_le_bytes());
    header[16] = 24;
    header[17] = TOP_ROW_FIRST;
    header
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
    /// Writes the header of a `width_px × height_px` image to `out`. Sides above 65,535 pixels
    /// cannot be stored.
    pub(crate) fn begin(
        out: &mut dyn Write,
        width_px: u32,
        height_px: u32,
    ) -> std::io::Result<Self> {
        let side = |px: u32| {
            u16::try_from(px).map_err(|_| {
                std::io::Error::new(
                    std::io::ErrorKind::InvalidInput,
                    format!("{width_px}×{height_px}: a TGA image side is at most 65535 pixels"),
                )
            })
        };
        out.write_all(&header(side(width_px)?, side(height_px)?))?;
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
        self.count(rgb.len())?;
        for chunk in rgb.chunks(PIXELS_PER_WRITE) {
            self.bgr.clear();
            self.bgr.extend_from_slice(chunk.as_flattened());
            let (pixels, _) = self.bgr.as_chunks_mut::<3>();
            to_bgr(pixels);
            out.write_all(&self.bgr)?;
        }
        Ok(())
    }

    /// [`Self::write_pixels`] of pixels the caller does not need again: their channels are
    /// swapped where they are, and they are written in one call.
    pub(crate) fn write_pixels_in_place(
        &mut self,
        out: &mut dyn Write,
        rgb: &mut [[u8; 3]],
    ) -> std::io::Result<()> {
        self.count(rgb.len())?;
        to_bgr(rgb);
        out.write_all(rgb.as_flattened())
    }

    /// Counts `pixels` more as written.
    fn count(&mut self, pixels: usize) -> std::io::Result<()> {
        if pixels > self.pixels_left {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                "more pixels than the TGA image holds",
            ));
        }
        self.pixels_left -= pixels;
        Ok(())
    }

    /// Checks that every pixel was written.
    pub(crate) fn finish(&self) -> std::io::Result<()> {
        if self.pixels_left != 0 {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!("the TGA image is {} pixels short", self.pixels_left),
            ));
        }
        Ok(())
    }
}

/// RGB pixels to the BGR order the file stores, where they are.
fn to_bgr(pixels: &mut [[u8; 3]]) {
    for pixel in pixels {
        pixel.swap(0, 2);
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
        for (index, run) in all.chunks(300 * 9 + 17).enumerate() {
            if index % 2 == 0 {
                runs.write_pixels(&mut out, run).unwrap();
            } else {
                runs.write_pixels_in_place(&mut out, &mut run.to_vec())
                    .unwrap();
            }
        }
        runs.finish().unwrap();
        assert_eq!(out, whole);
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
        assert!(
            long.write_pixels_in_place(&mut out, &mut [[0; 3]; 3])
                .is_err()
        );
        assert!(TgaWriter::begin(&mut out, 70_000, 1).is_err());
    }
}
