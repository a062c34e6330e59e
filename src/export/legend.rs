//! The legend under an exported side-by-side picture: the colour bar of the depth image's map
//! from near (left) to far (right), with the depth range's two ends written beside it
//! ([`crate::output::text`]), so the picture says what its greys mean wherever it goes.

use image::{Rgb, RgbImage};

use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Height of the strip, pixels.
pub(crate) const LEGEND_PX: u32 = 24;

/// Scale of the legend's text.
const TEXT_SCALE: u32 = 1;

/// Width of `text` in the legend, pixels.
fn text_width(text: &str) -> u32 {
    crate::output::text::text_width(text, TEXT_SCALE)
}

/// Writes `text` with its top-left corner at (x, y).
fn draw_text(image: &mut RgbImage, text: &str, x: u32, y: u32, colour: Rgb<u8>) {
    crate::output::text::draw_text(image, text, x, y, TEXT_SCALE, colour);
}

/// A number as the legend writes it: up to 6 significant digits, exponent form when long.
fn legend_number(value: f64) -> String {
    let plain = format!("{value:.6}");
    let plain = plain.trim_end_matches('0').trim_end_matches('.').to_owned();
    if plain.len() > 9 {
        format!("{value:.2e}")
    } else {
        plain
    }
}

/// `picture` with the legend strip added under it: the colour bar over `range` through `map`,
/// near at the left, with the range's ends written at its two ends.
pub(crate) fn with_legend(picture: &RgbImage, range: DepthRange, map: DepthColourMap) -> RgbImage {
    let (width, height) = picture.dimensions();
    let mut image = RgbImage::from_pixel(width, height + LEGEND_PX, Rgb([32, 32, 32]));
    image::imageops::replace(&mut image, picture, 0, 0);
    let (near, far) = (legend_number(range.min_t), legend_number(range.max_t));
    let margin = 4;
    let bar_left = margin + text_width(&near) + margin;
    let bar_right = width.saturating_sub(margin + text_width(&far) + margin);
    let bar_top = height + 6;
    for x in bar_left..bar_right.max(bar_left) {
        let share = f64::from(x - bar_left) / f64::from((bar_right - bar_left).max(1));
        let t = range.min_t + share * (range.max_t - range.min_t);
        let colour = Rgb(map.rgb(&range, t, [0, 0, 0]));
        for y in bar_top..bar_top + 12 {
            image.put_pixel(x, y, colour);
        }
    }
    let white = Rgb([235, 235, 235]);
    draw_text(&mut image, &near, margin, bar_top + 2, white);
    draw_text(&mut image, &far, bar_right + margin, bar_top + 2, white);
    image
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_strip_holds_the_colour_bar_from_near_to_far() {
        let picture = RgbImage::from_pixel(200, 50, Rgb([10, 20, 30]));
        let range = DepthRange::new(9.0, 10.5);
        let image = with_legend(&picture, range, DepthColourMap::Grey);
        assert_eq!(image.dimensions(), (200, 50 + LEGEND_PX));
        assert_eq!(
            *image.get_pixel(100, 10),
            Rgb([10, 20, 30]),
            "the picture stays"
        );
        // The bar: white (near) at its left, black (far) at its right, grey between.
        let y = 50 + 10;
        let bar: Vec<u8> = (0..200).map(|x| image.get_pixel(x, y)[0]).collect();
        let left = bar_left(&picture, range);
        assert!(
            bar[left as usize] >= 250,
            "near is white: {}",
            bar[left as usize]
        );
        let right = 200 - 4 - text_width("10.5") - 4 - 1;
        assert!(
            bar[right as usize] <= 5,
            "far is black: {}",
            bar[right as usize]
        );
        // The ends' numbers are written in white somewhere left of the bar.
        assert!((0..left).any(|x| image.get_pixel(x, 50 + 9) == &Rgb([235, 235, 235])));
    }

    fn bar_left(_picture: &RgbImage, range: DepthRange) -> u32 {
        4 + text_width(&legend_number(range.min_t)) + 4
    }
}
