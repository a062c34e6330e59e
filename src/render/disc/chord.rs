//! What the rasterisers share besides the hit test ([`super::hit`]): where a disc's chord
//! lies on a row, and a band's discs gathered once. All in f64.

use super::bins::column_span;
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

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
            radius: disc.radius_sq.sqrt(),
        }
    })
    .collect()
}

/// The columns of the row at screen `v` that `disc` (radius `radius_px` pixels) may cover on it
/// (in f64, conservative; the per-pixel test decides).
pub(super) fn chord_on_row(
    grid: &PixelGrid,
    disc: &Disc,
    (centre_column, radius_px): (f64, f64),
    v: f64,
) -> Option<Chord> {
    let dv = v - disc.v;
    let chord_sq = disc.radius_sq - dv * dv;
    if chord_sq.is_nan() || chord_sq < -disc.radius_sq * 1e-6 {
        return None;
    }
    let half_chord_px = chord_sq.max(0.0).sqrt() * (1.0 / grid.pixel_size_world);
    let (first, last) = column_span(grid, centre_column, half_chord_px, radius_px)?;
    Some(Chord { first, last, v })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::rng::SplitMix64;

    /// A disc of radius `radius_px` pixels centred at pixel coordinates (`column`, `row` from the
    /// top) on `grid`.
    fn disc_at(grid: &PixelGrid, column: f64, row: f64, radius_px: f64) -> Disc {
        let s = grid.pixel_size_world;
        let radius = radius_px * s;
        Disc {
            u: grid.u_of_column(column),
            v: grid.v_of_row(f64::from(grid.height_px) - 1.0 - row),
            w: 10.0,
            radius_sq: radius * radius,
            sphere: 0,
        }
    }

    #[test]
    fn spans_hold_every_pixel_the_exact_test_accepts_and_little_more() {
        // Points, discs of a few pixels and of thousands; centred on pixel centres with whole
        // radii (rims through pixel centres: ties of the exact test), anywhere else, and off the
        // image; pixel sizes that are and are not powers of two. Every pixel whose centre passes
        // the exact test (worked out here, pixel by pixel) must lie in the disc's rows and in its
        // chord's columns on its row; and the chord may reach at most a pixel beyond the pixels
        // the disc covers on the row.
        let mut rng = SplitMix64::new(41);
        let (mut accepted, mut rows_checked) = (0u64, 0u64);
        for case in 0..3_000 {
            let (width, height) = (1 + case % 61, 1 + (case * 7) % 53);
            let size_world = if case % 2 == 0 {
                f64::from(width.max(height)) * 0.125
            } else {
                rng.log_uniform(1e-3, 1e4)
            };
            let grid = PixelGrid::new(width, height, size_world);
            let whole = case % 3 == 0;
            let pick = |rng: &mut SplitMix64, count: u32| {
                let at = rng.uniform(-8.0, f64::from(count) + 8.0);
                if whole { at.round() } else { at }
            };
            let (column, row) = (pick(&mut rng, width), pick(&mut rng, height));
            let radius_px = match case % 5 {
                0 => 0.0,
                1 => rng.uniform(0.0, 12.0).round(),
                2 => rng.log_uniform(1e-4, 3.0),
                3 => rng.log_uniform(3.0, 5_000.0),
                _ => rng.uniform(0.0, 40.0),
            };
            let disc = disc_at(&grid, column, row, radius_px);
            let inverse_pixel = 1.0 / grid.pixel_size_world;
            let radius = disc.radius_sq.sqrt();
            let centre_column = disc.u * inverse_pixel + 0.5 * f64::from(width) - 0.5;
            let rows = super::super::bins::rows_of(&grid, disc.v, radius);
            for image_row in 0..height as usize {
                let v = grid.v_of_row(f64::from(height) - 1.0 - image_row as f64);
                let covered: Vec<usize> = (0..width as usize)
                    .filter(|&x| disc.hit_t(grid.u_of_column(x as f64), v).is_some())
                    .collect();
                let chord = chord_on_row(&grid, &disc, (centre_column, radius * inverse_pixel), v);
                for &x in &covered {
                    accepted += 1;
                    let in_rows =
                        rows.is_some_and(|(first, last)| (first..=last).contains(&image_row));
                    assert!(in_rows, "case {case}: row {image_row} of {rows:?}");
                    let chord =
                        chord.unwrap_or_else(|| panic!("case {case}: no chord on row {image_row}"));
                    assert!(
                        (chord.first..=chord.last).contains(&x),
                        "case {case}: column {x} outside {}..={} on row {image_row}",
                        chord.first,
                        chord.last
                    );
                }
                if let (Some(chord), Some(&first), Some(&last)) =
                    (chord, covered.first(), covered.last())
                {
                    rows_checked += 1;
                    assert!(
                        chord.first + 1 >= first && chord.last <= last + 1,
                        "case {case}: chord {}..={} around {first}..={last}",
                        chord.first,
                        chord.last
                    );
                }
            }
        }
        assert!(
            accepted > 100_000 && rows_checked > 10_000,
            "{accepted} {rows_checked}"
        );
    }
}
