//! The legend under an exported side-by-side picture: the colour bar of the depth image's map
//! from near (left) to far (right), with what its ends mean written under them ("near 9.000",
//! "far 10.000", and "t", the axis, between them; [`crate::output::text`]), so the picture says
//! what its greys mean wherever it goes. The text is drawn at twice the font's size where the
//! picture is wide enough.

use image::{Rgb, RgbImage};

use crate::export::numbers::range_ends;
use crate::output::text::{CHAR_PX, draw_text, text_width};
use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Space around the bar and the text, pixels.
const MARGIN_PX: u32 = 6;

/// Height of the colour bar, pixels.
const BAR_PX: u32 = 14;

/// The legend's text colour, light on the strip's dark grey.
const TEXT_RGB: Rgb<u8> = Rgb([235, 235, 235]);

/// The strip's background.
const STRIP_RGB: Rgb<u8> = Rgb([32, 32, 32]);

/// The axis's name, written under the middle of the bar where there is room.
const AXIS_NAME: &str = "t";

/// What the legend writes under the bar's two ends, and at what scale: "near A" / "far B" at
/// scale 2 where they fit `width`, else at scale 1, else "A" / "B" at scale 1.
fn legend_words(range: DepthRange, width: u32) -> ([String; 2], u32) {
    let [near, far] = range_ends(range.min_t, range.max_t);
    let named = [format!("near {near}"), format!("far {far}")];
    let fits = |words: &[String; 2], scale: u32| {
        text_width(&words[0], scale) + text_width(&words[1], scale) + 3 * MARGIN_PX <= width
    };
    if fits(&named, 2) {
        (named, 2)
    } else if fits(&named, 1) {
        (named, 1)
    } else {
        ([near, far], 1)
    }
}

/// Height of the strip whose text is drawn at `scale`.
fn strip_px(scale: u32) -> u32 {
    MARGIN_PX + BAR_PX + MARGIN_PX + CHAR_PX * scale + MARGIN_PX
}

/// `picture` with the legend strip added under it: the colour bar over `range` through `map`,
/// near at the left, "near …" under its left end, "far …" under its right end and "t" between.
pub(crate) fn with_legend(picture: &RgbImage, range: DepthRange, map: DepthColourMap) -> RgbImage {
    let (width, height) = picture.dimensions();
    let ([near, far], scale) = legend_words(range, width);
    let mut image = RgbImage::from_pixel(width, height + strip_px(scale), STRIP_RGB);
    image::imageops::replace(&mut image, picture, 0, 0);
    let (bar_left, bar_right) = (MARGIN_PX, width.saturating_sub(MARGIN_PX));
    let bar_top = height + MARGIN_PX;
    for x in bar_left..bar_right.max(bar_left) {
        let share = f64::from(x - bar_left) / f64::from((bar_right - bar_left - 1).max(1));
        let t = range.min_t + share * (range.max_t - range.min_t);
        let colour = Rgb(map.rgb(&range, t, [0, 0, 0]));
        for y in bar_top..bar_top + BAR_PX {
            image.put_pixel(x, y, colour);
        }
    }
    let text_top = bar_top + BAR_PX + MARGIN_PX;
    draw_text(&mut image, &near, bar_left, text_top, scale, TEXT_RGB);
    let far_left = bar_right.saturating_sub(text_width(&far, scale));
    draw_text(&mut image, &far, far_left, text_top, scale, TEXT_RGB);
    // "t" under the middle, where it clears both ends' words.
    let axis_width = text_width(AXIS_NAME, scale);
    let axis_left = (width.saturating_sub(axis_width)) / 2;
    let near_right = bar_left + text_width(&near, scale);
    if axis_left >= near_right + MARGIN_PX && axis_left + axis_width + MARGIN_PX <= far_left {
        draw_text(&mut image, AXIS_NAME, axis_left, text_top, scale, TEXT_RGB);
    }
    image
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixels of `text` drawn alone at (x, y) and scale: what the legend must hold there.
    fn holds_text(image: &RgbImage, text: &str, x: u32, y: u32, scale: u32) -> bool {
        let width = text_width(text, scale);
        let mut alone = RgbImage::from_pixel(width, CHAR_PX * scale, STRIP_RGB);
        draw_text(&mut alone, text, 0, 0, scale, TEXT_RGB);
        alone
            .enumerate_pixels()
            .all(|(dx, dy, pixel)| image.get_pixel(x + dx, y + dy) == pixel)
    }

    #[test]
    fn the_strip_holds_the_colour_bar_from_near_to_far_and_says_which_is_which() {
        let picture = RgbImage::from_pixel(400, 50, Rgb([10, 20, 30]));
        let range = DepthRange::new(9.0, 10.5);
        let image = with_legend(&picture, range, DepthColourMap::Grey);
        assert_eq!(image.dimensions(), (400, 50 + strip_px(2)));
        assert_eq!(
            *image.get_pixel(100, 10),
            Rgb([10, 20, 30]),
            "the picture stays"
        );
        // The bar: white (near) at its left end, black (far) at its right end.
        let y = 50 + MARGIN_PX + BAR_PX / 2;
        assert_eq!(image.get_pixel(MARGIN_PX, y)[0], 255, "near is white");
        assert_eq!(
            image.get_pixel(400 - MARGIN_PX - 1, y)[0],
            0,
            "far is black"
        );
        // Under its ends, at twice the font's size, "near 9.000" and "far 10.500"; "t" between.
        let text_top = 50 + MARGIN_PX + BAR_PX + MARGIN_PX;
        assert!(holds_text(&image, "near 9.000", MARGIN_PX, text_top, 2));
        let far_left = 400 - MARGIN_PX - text_width("far 10.500", 2);
        assert!(holds_text(&image, "far 10.500", far_left, text_top, 2));
        assert!(holds_text(&image, "t", 200 - CHAR_PX, text_top, 2));
    }

    #[test]
    fn narrow_pictures_get_smaller_text_then_the_numbers_alone() {
        let range = DepthRange::new(540.954387, 1312.918088);
        let words = |width| legend_words(range, width);
        assert_eq!(
            words(400),
            (["near 541.0".to_owned(), "far 1,312.9".to_owned()], 2)
        );
        assert_eq!(
            words(200),
            (["near 541.0".to_owned(), "far 1,312.9".to_owned()], 1)
        );
        assert_eq!(words(100), (["541.0".to_owned(), "1,312.9".to_owned()], 1));
        // The strip is as tall as its text needs.
        for (width, scale) in [(20, 1), (100, 1), (200, 1), (400, 2)] {
            let picture = RgbImage::new(width, 10);
            let image = with_legend(&picture, range, DepthColourMap::Turbo);
            assert_eq!(image.height() - 10, strip_px(scale), "{width}");
        }
    }
}
