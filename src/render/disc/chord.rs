//! The per-pixel primitives the rasterisers share: the disc test at a pixel, where a disc's chord
//! lies on a row, and a band's discs gathered once. All in f64.

use super::Disc;
use super::bins::column_span;
use crate::geometry::camera::PixelGrid;

/// The disc test at one pixel.
pub(super) struct PixelHit {
    /// Squared screen distance from the disc's centre.
    pub(super) distance_sq: f64,
    /// t of the front surface (meaningful inside the disc).
    pub(super) t: f64,
}

/// Tests pixel column `u` (screen) against `disc` on a row `dv_sq` = (v − c_v)² away.
#[inline(always)]
pub(super) fn pixel_hit(disc: &Disc, u: f64, dv_sq: f64) -> PixelHit {
    let du = u - disc.u;
    let distance_sq = du * du + dv_sq;
    let rest = disc.radius_sq - distance_sq;
    let root = (if rest > 0.0 { rest } else { 0.0 }).sqrt();
    PixelHit {
        distance_sq,
        t: disc.w - root,
    }
}

/// One row's outputs.
pub(super) struct RowOut<'a> {
    pub(super) t: &'a mut [f64],
    pub(super) sphere: &'a mut [u32],
}

/// Where a disc's chord lies on one row: the columns to test and the row's screen v.
#[derive(Clone, Copy)]
pub(super) struct Chord {
    pub(super) first: usize,
    pub(super) last: usize,
    pub(super) v: f64,
}

/// Pixel-to-screen constants of a grid.
#[derive(Clone, Copy)]
pub(super) struct Columns {
    pub(super) pixel_size: f64,
    /// Added to a column index before scaling: `½ − width/2`.
    pub(super) offset: f64,
}

impl Columns {
    pub(super) fn of(grid: &PixelGrid) -> Self {
        Self {
            pixel_size: grid.pixel_size_world,
            offset: 0.5 - 0.5 * f64::from(grid.width_px),
        }
    }

    /// Screen u of the centre of the column whose index, as f64, is `x` (whole numbers are exact
    /// in f64, so a loop counts columns in f64 and saves a conversion per pixel).
    #[inline(always)]
    pub(super) fn u(&self, x: f64) -> f64 {
        (x + self.offset) * self.pixel_size
    }
}

/// A disc gathered for a band.
#[derive(Clone, Copy)]
pub(super) struct BandDisc {
    pub(super) disc: Disc,
    /// Its centre's column coordinate (`u / s + width/2 − ½`).
    pub(super) centre_column: f64,
    /// The nearest t it can have anywhere: `w − r`, never above the t of any pixel it covers
    /// (correctly rounded square root and subtraction are monotonic).
    pub(super) front_t: f64,
    /// Its radius, `√r²`.
    pub(super) radius: f64,
}

/// The band's discs gathered once, contiguous and in the order listed: the rows read them
/// sequentially instead of chasing indices across the whole scene (cache misses dominated).
pub(super) fn gather_band_discs(
    discs: &[Disc],
    list: impl Iterator<Item = u32>,
    grid: &PixelGrid,
) -> Vec<BandDisc> {
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    let centre_column_offset = 0.5 * f64::from(grid.width_px) - 0.5;
    list.map(|index| {
        let disc = discs[index as usize];
        BandDisc {
            disc,
            centre_column: disc.u * inverse_pixel + centre_column_offset,
            front_t: disc.front_t(),
            radius: disc.radius_sq.sqrt(),
        }
    })
    .collect()
}

/// The columns of the row at screen `v` that `disc`'s chord may cover (in f64, conservative; the
/// per-pixel test decides).
pub(super) fn chord_on_row(
    grid: &PixelGrid,
    disc: &Disc,
    centre_column: f64,
    v: f64,
) -> Option<Chord> {
    let dv = v - disc.v;
    let chord_sq = disc.radius_sq - dv * dv;
    if chord_sq.is_nan() || chord_sq < -disc.radius_sq * 1e-6 {
        return None;
    }
    let half_chord_px = chord_sq.max(0.0).sqrt() * (1.0 / grid.pixel_size_world);
    let (first, last) = column_span(grid, centre_column, half_chord_px)?;
    Some(Chord { first, last, v })
}
