//! [`Frame`]: a rendered picture — colour, raw t and the visible sphere per pixel — and its 8-bit
//! colour and depth images.

use image::RgbImage;
use rayon::prelude::*;

use crate::render::depth_map::{DepthColourMap, DepthPainter, DepthRange};

/// Sphere index of pixels that no sphere covers.
pub const NO_HIT: u32 = u32::MAX;

/// A rendered picture. Pixels are stored row-major with the **top row first** (as image files
/// store them): pixel (x, y) with y = 0 the bottom row is at index `(height − 1 − y)·width + x`.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Width in pixels.
    pub width_px: u32,
    /// Height in pixels.
    pub height_px: u32,
    /// 8-bit colour per pixel (`floor(c·255)` of the material's colour, clamped).
    pub colour: Vec<[u8; 3]>,
    /// t of the visible hit per pixel, along the unit view direction from the screen plane;
    /// `+∞` where no sphere is hit.
    pub t: Vec<f64>,
    /// Index (file order) of the visible sphere per pixel, [`NO_HIT`] where none.
    pub sphere: Vec<u32>,
    /// Supersampled frames: the filtered depth grey per pixel (in [0, 1], top row first) and the
    /// range it was mapped with. The raw `t` stays one centre sample per pixel.
    pub depth_grey: Option<(DepthRange, Vec<f32>)>,
    /// Sphere/disc tests performed (pixel–disc and sample–disc).
    pub(crate) disc_tests: u64,
}

impl Frame {
    /// Sphere/disc tests the render performed (pixel–disc and sample–disc): the work a frame
    /// cost, beside its time.
    pub fn disc_tests(&self) -> u64 {
        self.disc_tests
    }

    /// Storage index of pixel (x, y) with y = 0 the bottom row.
    pub fn index(&self, x: u32, y_up: u32) -> usize {
        (self.height_px - 1 - y_up) as usize * self.width_px as usize + x as usize
    }

    /// Number of pixels.
    pub fn pixel_count(&self) -> usize {
        self.width_px as usize * self.height_px as usize
    }

    /// The 8-bit colour image (`floor(c·255)`, clamped), top row first.
    pub fn colour_image(&self) -> RgbImage {
        // Storage is top row first, as images are: a flat copy.
        image_from_pixels(self.width_px, self.height_px, self.colour.clone())
    }

    /// The 8-bit depth image over `range` (grey in all three channels), top row first. A
    /// supersampled frame uses its filtered greys when `range` is the one they were made with.
    pub fn depth_image(&self, range: DepthRange) -> RgbImage {
        self.depth_image_mapped(range, DepthColourMap::Grey, [0, 0, 0])
    }

    /// The 8-bit depth image over `range` through a colour map, top row first; no-hit pixels
    /// are `no_hit`. With [`DepthColourMap::Grey`] and black for no hit this is
    /// [`Self::depth_image`]. A supersampled frame maps its filtered greys (no hit decided by the
    /// centre sample).
    pub fn depth_image_mapped(
        &self,
        range: DepthRange,
        map: DepthColourMap,
        no_hit: [u8; 3],
    ) -> RgbImage {
        let pixels = self.depth_pixels(range, map, no_hit, |rgb| rgb);
        image_from_pixels(self.width_px, self.height_px, pixels)
    }

    /// The depth image's pixels (see [`Self::depth_image_mapped`]), top row first, each made
    /// from its RGB by `pixel` (the viewer makes texture pixels): the one place where t becomes
    /// a depth colour.
    pub(crate) fn depth_pixels<P: Send>(
        &self,
        range: DepthRange,
        map: DepthColourMap,
        no_hit: [u8; 3],
        pixel: impl Fn([u8; 3]) -> P + Sync,
    ) -> Vec<P> {
        let filtered = self
            .depth_grey
            .as_ref()
            .filter(|(grey_range, _)| *grey_range == range)
            .map(|(_, grey)| grey);
        if filtered.is_none() {
            return DepthPainter::new(range, map, no_hit).pixels(&self.t, pixel);
        }
        (0..self.t.len())
            .into_par_iter()
            .map(|index| {
                let t = self.t[index];
                let rgb = match filtered {
                    Some(grey) if map == DepthColourMap::Grey && no_hit == [0; 3] => {
                        [crate::render::depth_map::quantize_f32(grey[index]); 3]
                    }
                    Some(_) | None if t == f64::INFINITY || t.is_nan() => no_hit,
                    Some(grey) => map.rgb_of_grey(f64::from(grey[index])),
                    None => map.rgb(&range, t, no_hit),
                };
                pixel(rgb)
            })
            .collect()
    }
}

/// An image of `width × height` pixels given top row first.
fn image_from_pixels(width: u32, height: u32, pixels: Vec<[u8; 3]>) -> RgbImage {
    // The pixel count always matches (frames hold width × height pixels); an empty image
    // would only stand in for a broken frame.
    RgbImage::from_raw(width, height, pixels.into_flattened())
        .unwrap_or_else(|| RgbImage::new(width, height))
}
