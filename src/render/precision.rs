//! Precision modes: `f64` (exact), `f32` (fast) and `auto`, which picks f32 only where f32 is
//! measured to be safe for the frame at hand (`docs/accuracy.md`).
//!
//! What f32 costs (the per-pixel arithmetic; projection and spans stay f64, camera-relative):
//! * **coverage** (which sphere a pixel shows) costs nothing: where f32 cannot decide with
//!   certainty — within its error bound of a silhouette or of a tie between two spheres — the
//!   kernel re-decides that pixel in f64 (`render::disc`). The picture's colours are exact in every
//!   mode.
//! * **depth**: t carries an absolute error of about `ε₃₂·(|w| + r)` (w: the sphere centre's
//!   distance along the view direction, from the camera centre), more near silhouettes. It is
//!   safe when that is far below one grey level of the depth range, `|depth_max − depth_min| / 255`.
//!
//! `auto` picks f32 when the depth error stays below [`F32_DEPTH_MARGIN`] of a grey level with a
//! factor 4 of headroom and every magnitude fits f32 comfortably; the error study checks that
//! inside that rule f32 and f64 give the same 8-bit images.

use std::fmt;
use std::str::FromStr;

use super::disc::Disc;
use crate::geometry::camera::PixelGrid;
use crate::render::depth_map::DepthRange;

/// Per-pixel arithmetic precision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum Precision {
    /// 64-bit: exact at every extreme the project tests (the command line's default).
    #[default]
    F64,
    /// 32-bit: faster where vector units are twice as wide; exact only inside its safe range.
    F32,
    /// f32 when the frame lies inside f32's safe range, else f64.
    Auto,
}

impl Precision {
    /// Every mode, in the order menus list them.
    pub const ALL: [Precision; 3] = [Precision::F64, Precision::F32, Precision::Auto];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::F64 => "f64",
            Self::F32 => "f32",
            Self::Auto => "auto",
        }
    }
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A precision name that is not `f64`, `f32` or `auto`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown precision '{0}': use f64, f32 or auto")]
pub struct UnknownPrecision(pub String);

impl FromStr for Precision {
    type Err = UnknownPrecision;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|p| p.name() == text)
            .ok_or_else(|| UnknownPrecision(text.to_owned()))
    }
}

/// f32's unit roundoff, 2⁻²⁴.
const F32_ROUNDOFF: f64 = 5.960_464_477_539_063e-8;

/// f32's t error must stay below this fraction of one grey level.
pub(crate) const F32_DEPTH_MARGIN: f64 = 1.0 / 16.0;

/// Largest magnitude f32 holds comfortably (squares of it stay finite, 2⁶⁰).
const F32_MAX_MAGNITUDE: f64 = 1.152_921_504_606_847e18;

/// Smallest radius f32 holds comfortably (its square stays normal, 2⁻⁶⁰).
const F32_MIN_RADIUS: f64 = 8.673_617_379_884_035e-19;

/// The discs that can show on this grid (discs entirely off screen do not count).
fn on_screen<'a>(discs: &'a [Disc], grid: &PixelGrid) -> impl Iterator<Item = &'a Disc> {
    let half_width = 0.5 * f64::from(grid.width_px) * grid.pixel_size_world;
    let half_height = 0.5 * f64::from(grid.height_px) * grid.pixel_size_world;
    discs.iter().filter(move |disc| {
        let radius = disc.radius_sq.sqrt();
        !(disc.u.abs() - radius > half_width || disc.v.abs() - radius > half_height)
    })
}

/// Whether f32 can hold every number of the per-pixel arithmetic of these discs on this grid:
/// magnitudes whose squares stay finite, radii whose squares stay normal. Where it cannot, the
/// f32 mode renders the frame in f64 (a number that overflows f32 would lose the sphere).
pub(crate) fn f32_fits(discs: &[Disc], grid: &PixelGrid) -> bool {
    let half_width = 0.5 * f64::from(grid.width_px) * grid.pixel_size_world;
    let half_height = 0.5 * f64::from(grid.height_px) * grid.pixel_size_world;
    let screen_extent = half_width.max(half_height);
    on_screen(discs, grid).all(|disc| {
        let radius = disc.radius_sq.sqrt();
        let largest = screen_extent
            .max(disc.u.abs() + radius)
            .max(disc.v.abs() + radius);
        largest <= F32_MAX_MAGNITUDE
            && disc.w.abs() + radius <= F32_MAX_MAGNITUDE
            && !(radius < F32_MIN_RADIUS && radius > 0.0)
    })
}

/// Whether f32 per-pixel arithmetic is safe for these discs on this grid and depth range (see the
/// module docs): the numbers fit f32, and its depth error stays far below a grey level.
pub(crate) fn f32_is_safe(discs: &[Disc], grid: &PixelGrid, depth_range: DepthRange) -> bool {
    let grey_level = (depth_range.max_t - depth_range.min_t).abs() / 255.0;
    if grey_level == 0.0 || !grey_level.is_finite() || !f32_fits(discs, grid) {
        return false;
    }
    on_screen(discs, grid).all(|disc| {
        let radius = disc.radius_sq.sqrt();
        let depth_error = F32_ROUNDOFF * 4.0 * (disc.w.abs() + radius);
        depth_error <= F32_DEPTH_MARGIN * grey_level
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn disc(w: f64, r: f64) -> Disc {
        Disc {
            u: 0.0,
            v: 0.0,
            w,
            radius_sq: r * r,
            sphere: 0,
        }
    }

    #[test]
    fn names_round_trip() {
        for precision in Precision::ALL {
            assert_eq!(precision.name().parse::<Precision>(), Ok(precision));
        }
        assert!("f16".parse::<Precision>().is_err());
    }

    #[test]
    fn course_like_frames_are_safe_in_f32() {
        let grid = PixelGrid::new(200, 200, 5.0);
        assert!(f32_is_safe(
            &[disc(10.0, 1.0)],
            &grid,
            DepthRange::new(9.0, 10.0)
        ));
    }

    #[test]
    fn far_narrow_depth_ranges_need_f64() {
        let grid = PixelGrid::new(200, 200, 5.0);
        let range = DepthRange::new(99_999.996, 100_000.001_5);
        assert!(!f32_is_safe(&[disc(1e5, 1.0)], &grid, range));
    }

    #[test]
    fn magnitudes_beyond_f32_need_f64() {
        let grid = PixelGrid::new(200, 200, 1.0);
        let huge = Disc {
            u: 1e20,
            ..disc(1e7, 1e20)
        };
        assert!(!f32_is_safe(&[huge], &grid, DepthRange::new(0.0, 1e30)));
        let tiny = disc(1.0, 1e-20);
        assert!(!f32_is_safe(&[tiny], &grid, DepthRange::new(0.0, 2.0)));
    }

    #[test]
    fn empty_depth_range_needs_f64() {
        let grid = PixelGrid::new(200, 200, 5.0);
        assert!(!f32_is_safe(
            &[disc(10.0, 1.0)],
            &grid,
            DepthRange::new(9.0, 9.0)
        ));
    }
}
