//! How two images of the same size differ: per pixel the largest channel difference, the count of
//! pixels that differ and the largest difference, and the course's rule for "the same picture"
//! (colour identical; depth within one grey level on at most 0.1% of the pixels).

use image::RgbImage;

/// Share of a depth image's pixels that may be one grey level off (the course rendered in f32).
pub const DEPTH_OFF_BY_ONE_SHARE: f64 = 0.001;

/// The difference of two images.
#[derive(Debug, Clone, PartialEq)]
pub struct Difference {
    /// Image width, pixels.
    pub width_px: u32,
    /// Image height, pixels.
    pub height_px: u32,
    /// Per pixel (top row first), the largest difference of its three channels, 0 to 255.
    pub per_pixel: Vec<u8>,
}

impl Difference {
    /// The difference of `a` and `b`, which must be the same size.
    pub fn of(a: &RgbImage, b: &RgbImage) -> Self {
        debug_assert_eq!(a.dimensions(), b.dimensions());
        let per_pixel = a
            .pixels()
            .zip(b.pixels())
            .map(|(p, q)| {
                (0..3)
                    .map(|channel| p.0[channel].abs_diff(q.0[channel]))
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        Self {
            width_px: a.width(),
            height_px: a.height(),
            per_pixel,
        }
    }

    /// How many pixels differ at all.
    pub fn pixels_differing(&self) -> usize {
        self.pixels_beyond(0)
    }

    /// How many pixels differ by more than `levels`.
    pub fn pixels_beyond(&self, levels: u8) -> usize {
        self.per_pixel.iter().filter(|&&d| d > levels).count()
    }

    /// The largest difference, 0 to 255.
    pub fn max_difference(&self) -> u8 {
        self.per_pixel.iter().copied().max().unwrap_or(0)
    }

    /// Mean difference over all pixels, in levels.
    pub fn mean_difference(&self) -> f64 {
        if self.per_pixel.is_empty() {
            return 0.0;
        }
        self.per_pixel.iter().map(|&d| f64::from(d)).sum::<f64>() / self.per_pixel.len() as f64
    }

    /// The course's rule for colour images: identical.
    pub fn colour_matches(&self) -> bool {
        self.pixels_differing() == 0
    }

    /// The course's rule for depth images: no pixel off by more than one level, and at most
    /// [`DEPTH_OFF_BY_ONE_SHARE`] of them off by one.
    pub fn depth_matches(&self) -> bool {
        let off_by_one = self.pixels_differing();
        self.pixels_beyond(1) == 0
            && off_by_one as f64 <= DEPTH_OFF_BY_ONE_SHARE * self.per_pixel.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgb;

    #[test]
    fn counts_the_largest_channel_difference_per_pixel() {
        let a = RgbImage::from_pixel(4, 1, Rgb([10, 20, 30]));
        let mut b = a.clone();
        b.put_pixel(1, 0, Rgb([10, 25, 30]));
        b.put_pixel(3, 0, Rgb([9, 20, 30]));
        let difference = Difference::of(&a, &b);
        assert_eq!(difference.per_pixel, vec![0, 5, 0, 1]);
        assert_eq!(difference.pixels_differing(), 2);
        assert_eq!(difference.pixels_beyond(1), 1);
        assert_eq!(difference.max_difference(), 5);
        assert!(!difference.colour_matches());
        assert!(!difference.depth_matches());
    }

    #[test]
    fn depth_allows_one_level_on_a_thousandth_of_the_pixels() {
        let a = RgbImage::from_pixel(100, 20, Rgb([100; 3]));
        let mut b = a.clone();
        b.put_pixel(0, 0, Rgb([101; 3]));
        b.put_pixel(1, 0, Rgb([99; 3]));
        assert!(Difference::of(&a, &b).depth_matches(), "2 of 2000 pixels");
        b.put_pixel(2, 0, Rgb([99; 3]));
        assert!(!Difference::of(&a, &b).depth_matches(), "3 of 2000 pixels");
    }
}
