//! The difference picture (`-diff`): for each compared image a row of their image, the exact one,
//! a heat map of the difference and, after a diagnosis, where the pixels are that no named mistake
//! explains, with a title over each, and a legend of the heat map's colours under them. Images
//! narrower than 600 pixels are enlarged (nearest neighbour) by a whole factor, so a single pixel
//! is a visible square and the text fits.

use image::{Rgb, RgbImage};

use super::difference::Difference;
use crate::output::text::{CHAR_PX, draw_text, text_width};

/// One row of the picture.
pub struct Row<'a> {
    /// What the row compares: "colour" or "depth".
    pub kind: &'a str,
    /// Their image.
    pub theirs: &'a RgbImage,
    /// The exact image.
    pub exact: &'a RgbImage,
    /// How they differ.
    pub difference: &'a Difference,
    /// After a diagnosis: the differing pixels no named mistake explains (one flag per pixel,
    /// row by row), drawn in a fourth panel.
    pub unexplained: Option<&'a [bool]>,
}

/// Space between and around the panels, pixels.
const GAP_PX: u32 = 8;

/// Height of a title line, pixels.
const TITLE_PX: u32 = CHAR_PX + 6;

/// Narrowest a panel is drawn; smaller images are enlarged by a whole factor (the course's
/// 200-pixel images three times: a single unexplained pixel is a square seen at a glance).
const MIN_PANEL_PX: u32 = 600;

/// Background of the picture.
const BACKGROUND: Rgb<u8> = Rgb([40, 40, 40]);

/// Text colour.
const TEXT: Rgb<u8> = Rgb([235, 235, 235]);

/// The heat map's colour of a difference of `levels` (0: black; 1 … 255 along inferno from its
/// dark red, so one level is still visible).
pub fn heat_colour(levels: u8) -> [u8; 3] {
    if levels == 0 {
        return [0, 0, 0];
    }
    let share = 0.3 + 0.7 * f64::from(levels - 1) / 254.0;
    let colour = colorous::INFERNO.eval_continuous(share);
    [colour.r, colour.g, colour.b]
}

/// Where a differing pixel no named mistake explains is drawn, in the unexplained panel and over
/// the viewer's heat map: cyan, a colour the heat map never takes.
pub const UNEXPLAINED: [u8; 3] = [0, 230, 255];

/// Where a differing pixel a named mistake explains is drawn in the unexplained panel.
const EXPLAINED: [u8; 3] = [90, 90, 90];

/// The unexplained panel: black where the images agree, grey where a named mistake explains the
/// difference, [`UNEXPLAINED`] where none does.
pub fn unexplained_map(difference: &Difference, unexplained: &[bool]) -> RgbImage {
    RgbImage::from_fn(difference.width_px, difference.height_px, |x, y| {
        let index = (y * difference.width_px + x) as usize;
        Rgb(if unexplained.get(index).copied().unwrap_or(false) {
            UNEXPLAINED
        } else if difference.per_pixel[index] > 0 {
            EXPLAINED
        } else {
            [0, 0, 0]
        })
    })
}

/// The heat map of `difference`, with the pixels flagged in `unexplained` drawn in
/// [`UNEXPLAINED`].
pub fn heat_map_marked(difference: &Difference, unexplained: &[bool]) -> RgbImage {
    let mut map = heat_map(difference);
    for (pixel, &flag) in map.pixels_mut().zip(unexplained) {
        if flag {
            *pixel = Rgb(UNEXPLAINED);
        }
    }
    map
}

/// The heat map of `difference` with only the `highlighted` pixels in colour, the rest dimmed
/// to a quarter of their grey: the pixels one statement of the answer explains.
pub fn heat_map_highlighted(difference: &Difference, highlighted: &[bool]) -> RgbImage {
    let mut map = heat_map(difference);
    for (pixel, &flag) in map.pixels_mut().zip(highlighted) {
        if !flag {
            let [r, g, b] = pixel.0;
            let grey = ((u16::from(r) + u16::from(g) + u16::from(b)) / 12) as u8;
            *pixel = Rgb([grey; 3]);
        }
    }
    map
}

/// The heat map of `difference`.
pub fn heat_map(difference: &Difference) -> RgbImage {
    RgbImage::from_fn(difference.width_px, difference.height_px, |x, y| {
        Rgb(heat_colour(
            difference.per_pixel[(y * difference.width_px + x) as usize],
        ))
    })
}

/// `image` enlarged `scale` times, nearest neighbour.
fn enlarged(image: &RgbImage, scale: u32) -> RgbImage {
    if scale == 1 {
        return image.clone();
    }
    image::imageops::resize(
        image,
        image.width() * scale,
        image.height() * scale,
        image::imageops::FilterType::Nearest,
    )
}

/// The difference picture of `rows` (all images the same size).
pub fn difference_picture(rows: &[Row<'_>]) -> RgbImage {
    let Some(first) = rows.first() else {
        return RgbImage::from_pixel(1, 1, BACKGROUND);
    };
    let (width, height) = first.theirs.dimensions();
    let scale = MIN_PANEL_PX.div_ceil(width.max(1)).max(1);
    let (panel_w, panel_h) = (width * scale, height * scale);
    let columns = if rows.iter().any(|row| row.unexplained.is_some()) {
        4
    } else {
        3
    };
    let picture_w = columns * panel_w + (columns + 1) * GAP_PX;
    let row_h = TITLE_PX + panel_h + GAP_PX;
    let legend_h = TITLE_PX + 12 + GAP_PX + if columns == 4 { TITLE_PX } else { 0 };
    let picture_h = GAP_PX + rows.len() as u32 * row_h + legend_h;
    let mut picture = RgbImage::from_pixel(picture_w, picture_h, BACKGROUND);
    for (index, row) in (0u32..).zip(rows) {
        let top = GAP_PX + index * row_h;
        let heat = heat_map(row.difference);
        let mut panels = vec![
            (row.theirs.clone(), format!("{}: theirs", row.kind)),
            (row.exact.clone(), "exact".to_owned()),
            (
                heat,
                format!(
                    "{} px differ, max {}",
                    row.difference.pixels_differing(),
                    row.difference.max_difference()
                ),
            ),
        ];
        if let Some(unexplained) = row.unexplained {
            let count = unexplained.iter().filter(|&&flag| flag).count();
            panels.push((
                unexplained_map(row.difference, unexplained),
                format!("unexplained: {count} px"),
            ));
        }
        for (column, (image, title)) in (0u32..).zip(&panels) {
            let left = GAP_PX + column * (panel_w + GAP_PX);
            draw_text(&mut picture, title, left, top + 2, 1, TEXT);
            image::imageops::replace(
                &mut picture,
                &enlarged(image, scale),
                i64::from(left),
                i64::from(top + TITLE_PX),
            );
        }
    }
    // The legend: the heat map's colours from one level to 255.
    let top = GAP_PX + rows.len() as u32 * row_h;
    draw_text(
        &mut picture,
        "difference in levels (none: black)",
        GAP_PX,
        top + 2,
        1,
        TEXT,
    );
    let bar_top = top + TITLE_PX;
    draw_text(&mut picture, "1", GAP_PX, bar_top + 2, 1, TEXT);
    let bar_left = GAP_PX + text_width("1", 1) + GAP_PX;
    let bar_right = picture_w - GAP_PX - text_width("255", 1) - GAP_PX;
    for x in bar_left..bar_right {
        let levels = 1 + (254 * (x - bar_left) / (bar_right - bar_left - 1).max(1)) as u8;
        for y in bar_top..bar_top + 12 {
            picture.put_pixel(x, y, Rgb(heat_colour(levels)));
        }
    }
    draw_text(
        &mut picture,
        "255",
        bar_right + GAP_PX,
        bar_top + 2,
        1,
        TEXT,
    );
    if columns == 4 {
        let line_top = bar_top + 12 + 4;
        let mut left = GAP_PX;
        for (text, colour) in [
            ("unexplained panel: ", TEXT),
            ("grey", Rgb(EXPLAINED)),
            (" explained by the words named, ", TEXT),
            ("cyan", Rgb(UNEXPLAINED)),
            (" not", TEXT),
        ] {
            draw_text(&mut picture, text, left, line_top, 1, colour);
            left += text_width(text, 1);
        }
    }
    picture
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_heat_map_is_black_where_equal_and_visible_for_one_level() {
        assert_eq!(heat_colour(0), [0, 0, 0]);
        let one = heat_colour(1);
        assert!(
            one.iter().map(|&c| u32::from(c)).sum::<u32>() > 60,
            "{one:?}"
        );
        let most = heat_colour(255);
        assert!(
            most.iter().map(|&c| u32::from(c)).sum::<u32>() > 500,
            "{most:?}"
        );
    }

    #[test]
    fn each_row_holds_theirs_the_exact_image_and_the_heat_map() {
        let theirs = RgbImage::from_pixel(200, 100, Rgb([200, 10, 10]));
        let mut exact = theirs.clone();
        exact.put_pixel(5, 7, Rgb([0, 10, 10]));
        let difference = Difference::of(&theirs, &exact);
        let picture = difference_picture(&[Row {
            kind: "colour",
            theirs: &theirs,
            exact: &exact,
            difference: &difference,
            unexplained: None,
        }]);
        // 200 pixels wide: drawn three times as large, each pixel a 3×3 square.
        let panel_top = GAP_PX + TITLE_PX;
        let column_left = |column: u32| GAP_PX + column * (600 + GAP_PX);
        let at = |column: u32, x: u32, y: u32| {
            *picture.get_pixel(column_left(column) + x, panel_top + y)
        };
        for (dx, dy) in [(0, 0), (2, 2)] {
            assert_eq!(at(0, 15 + dx, 21 + dy), Rgb([200, 10, 10]));
            assert_eq!(at(1, 15 + dx, 21 + dy), Rgb([0, 10, 10]));
            assert_eq!(at(2, 15 + dx, 21 + dy), Rgb(heat_colour(200)));
        }
        assert_eq!(at(1, 18, 21), Rgb([200, 10, 10]));
        assert_eq!(at(2, 18, 21), Rgb([0, 0, 0]));
    }
}
