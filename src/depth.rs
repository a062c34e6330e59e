//! The depth mapping (t → grey) and 8-bit quantisation, in one place.
//!
//! SPEC.md: `grey = clamp((depth_max − t) / (depth_max − depth_min), 0, 1)`; near is white, far is
//! black, pixels with no hit are black. Decisions where SPEC.md is silent:
//! * `depth_min > depth_max` is allowed and gives the **reversed ramp** the formula gives (near
//!   black, far white) — a way to look at a scene from behind; no-hit pixels stay black.
//! * `depth_min == depth_max` is a **step**: t ≤ depth_min is white, t > depth_min black (the limit
//!   of the ramp as the range shrinks to zero width); no division by zero.
//!
//! The mapping is computed in f64 from an f64 t, so narrow ranges far away stay exact.

/// The range of t mapped onto the grey ramp.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub struct DepthRange {
    /// t shown white.
    pub min_t: f64,
    /// t shown black.
    pub max_t: f64,
}

impl DepthRange {
    /// The range `[min_t, max_t]`.
    pub fn new(min_t: f64, max_t: f64) -> Self {
        Self { min_t, max_t }
    }

    /// Grey level in [0, 1] of a hit at `t` (`t = +∞` means no hit: black).
    pub fn grey(&self, t: f64) -> f64 {
        if t == f64::INFINITY || t.is_nan() {
            return 0.0;
        }
        let width = self.max_t - self.min_t;
        if width == 0.0 {
            return if t <= self.min_t { 1.0 } else { 0.0 };
        }
        ((self.max_t - t) / width).clamp(0.0, 1.0)
    }

    /// 8-bit grey of a hit at `t`.
    pub fn grey_u8(&self, t: f64) -> u8 {
        quantize_f64(self.grey(t))
    }
}

/// 8-bit quantisation by truncation, `clamp(floor(c·255), 0, 255)`, for colour channels (f32, as the
/// course computed them). NaN maps to 0.
pub fn quantize_f32(c: f32) -> u8 {
    let scaled = (c * 255.0).floor();
    if scaled >= 255.0 {
        255
    } else if scaled >= 0.0 {
        scaled as u8
    } else {
        0
    }
}

/// 8-bit quantisation by truncation of an f64 value in [0, 1]. NaN maps to 0.
pub fn quantize_f64(c: f64) -> u8 {
    let scaled = (c * 255.0).floor();
    if scaled >= 255.0 {
        255
    } else if scaled >= 0.0 {
        scaled as u8
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_is_white_far_is_black_and_outside_is_clamped() {
        let range = DepthRange::new(9.0, 10.0);
        assert_eq!(range.grey(9.0), 1.0);
        assert_eq!(range.grey(10.0), 0.0);
        assert_eq!(range.grey(9.5), 0.5);
        assert_eq!(range.grey(-100.0), 1.0);
        assert_eq!(range.grey(100.0), 0.0);
        assert_eq!(range.grey_u8(9.5), 127);
        assert_eq!(range.grey_u8(9.0), 255);
    }

    #[test]
    fn no_hit_is_black() {
        assert_eq!(DepthRange::new(9.0, 10.0).grey_u8(f64::INFINITY), 0);
        assert_eq!(DepthRange::new(10.0, 9.0).grey_u8(f64::INFINITY), 0);
        assert_eq!(DepthRange::new(5.0, 5.0).grey_u8(f64::INFINITY), 0);
    }

    #[test]
    fn reversed_range_gives_a_reversed_ramp() {
        let range = DepthRange::new(10.0, 9.0);
        assert_eq!(range.grey(9.0), 0.0);
        assert_eq!(range.grey(10.0), 1.0);
        assert_eq!(range.grey(9.25), 0.25);
    }

    #[test]
    fn empty_range_is_a_step() {
        let range = DepthRange::new(5.0, 5.0);
        assert_eq!(range.grey(4.0), 1.0);
        assert_eq!(range.grey(5.0), 1.0);
        assert_eq!(range.grey(5.000001), 0.0);
    }

    #[test]
    fn narrow_range_far_away_keeps_its_grey_levels() {
        let range = DepthRange::new(99_999.996, 100_000.001_5);
        // Midpoint of the range is mid-grey; f32 could not even represent these t apart.
        let mid = 0.5 * (99_999.996 + 100_000.001_5);
        assert_eq!(range.grey_u8(mid), 127);
        assert_eq!(range.grey_u8(99_999.996), 255);
        assert_eq!(range.grey_u8(100_000.001_5), 0);
    }

    #[test]
    fn quantisation_truncates_and_clamps() {
        assert_eq!(quantize_f32(0.1), 25);
        assert_eq!(quantize_f32(1.0), 255);
        assert_eq!(quantize_f32(1.5), 255);
        assert_eq!(quantize_f32(-0.2), 0);
        assert_eq!(quantize_f32(f32::NAN), 0);
        assert_eq!(quantize_f64(0.999), 254);
    }
}
