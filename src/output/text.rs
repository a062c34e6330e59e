//! Text in written pictures (the export legend, the difference picture): the public-domain 8×8
//! bitmap font of the `font8x8` crate, drawn pixel by pixel at an integer scale.

use font8x8::UnicodeFonts as _;
use image::{Rgb, RgbImage};

/// Width (and height) of one character at scale 1, pixels.
pub(crate) const CHAR_PX: u32 = 8;

/// Width of `text` at `scale`, pixels.
pub(crate) fn text_width(text: &str, scale: u32) -> u32 {
    text.chars().count() as u32 * CHAR_PX * scale
}

/// Writes `text` with its top-left corner at (`x`, `y`), each font pixel a `scale`×`scale`
/// square; characters outside the font are left blank, pixels outside the image are skipped.
pub(crate) fn draw_text(
    image: &mut RgbImage,
    text: &str,
    x: u32,
    y: u32,
    scale: u32,
    colour: Rgb<u8>,
) {
    for (index, c) in text.chars().enumerate() {
        let Some(rows) = font8x8::BASIC_FONTS.get(c) else {
            continue;
        };
        let left = x + index as u32 * CHAR_PX * scale;
        for (row, bits) in (0u32..).zip(rows) {
            for column in 0..CHAR_PX {
                // Bit 0 is the leftmost pixel.
                if bits & (1 << column) == 0 {
                    continue;
                }
                for dy in 0..scale {
                    for dx in 0..scale {
                        let (px, py) = (left + column * scale + dx, y + row * scale + dy);
                        if px < image.width() && py < image.height() {
                            image.put_pixel(px, py, colour);
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_character_is_drawn_inside_its_cell_and_a_space_is_blank() {
        let mut image = RgbImage::new(40, 10);
        draw_text(&mut image, "I I", 0, 0, 1, Rgb([255; 3]));
        let lit = |x0: u32, x1: u32| {
            (x0..x1)
                .flat_map(|x| (0..8).map(move |y| (x, y)))
                .filter(|&(x, y)| image.get_pixel(x, y)[0] == 255)
                .count()
        };
        assert!(lit(0, 8) > 6, "the first I");
        assert_eq!(lit(8, 16), 0, "the space");
        assert!(lit(16, 24) > 6, "the second I");
        assert_eq!(lit(24, 40), 0, "nothing after the text");
        assert_eq!(text_width("I I", 2), 48);
    }
}
