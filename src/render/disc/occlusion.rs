//! Occlusion culling for dense scenes: discs drawn front to back, and a disc hidden behind what
//! is already drawn in a band skipped (one level of hierarchical z per band).

use super::bins::{column_span, rows_of};
use super::chord::{BandDisc, Chord, Columns, PixelHit, RowOut, chord_on_row, pixel_hit};
use crate::geometry::camera::PixelGrid;

/// Columns per occlusion tile (a tile is this many columns of a band's rows).
const TILE_COLUMNS: usize = 4;

/// The farthest t among the pixels of `tile` in a band of rows `width` long; stops at the first
/// uncovered pixel (+∞).
fn farthest_in_tile(t: &[f64], width: usize, tile: usize) -> f64 {
    let columns = tile * TILE_COLUMNS..((tile + 1) * TILE_COLUMNS).min(width);
    let mut farthest = f64::NEG_INFINITY;
    for row in t.chunks(width) {
        for &t in &row[columns.clone()] {
            if t == f64::INFINITY {
                return t;
            }
            farthest = if t > farthest { t } else { farthest };
        }
    }
    farthest
}

/// Occlusion within a band: per tile of [`TILE_COLUMNS`] columns, the farthest t of its pixels (a
/// hierarchical z of one level). Discs come front to back (by `w − r`); a disc whose nearest t is
/// beyond the farthest t of every tile it touches cannot change a pixel and is skipped, so a frame
/// costs what is visible, not what piles up behind it. A tile's farthest t is recomputed only when
/// a disc was drawn over it and another asks (and at first: the band may already hold discs
/// drawn in an earlier pass).
struct Occlusion {
    farthest_t: Vec<f64>,
    stale: Vec<bool>,
}

impl Occlusion {
    fn new(width: usize) -> Self {
        let tiles = width.div_ceil(TILE_COLUMNS);
        Self {
            farthest_t: vec![f64::INFINITY; tiles],
            stale: vec![true; tiles],
        }
    }

    /// Whether `disc` (columns `first..=last` of the band) may be nearer than a pixel there.
    fn may_show(
        &mut self,
        disc: &BandDisc,
        (first, last): (usize, usize),
        t: &[f64],
        width: usize,
    ) -> bool {
        for tile in first / TILE_COLUMNS..=last / TILE_COLUMNS {
            // A stale value still bounds the tile from above (pixels only come nearer), so it is
            // recomputed only when it cannot hide the disc. On an equal t the disc may still win
            // the tie (an earlier sphere in the file).
            if disc.front_t > self.farthest_t[tile] {
                continue;
            }
            if self.stale[tile] {
                self.farthest_t[tile] = farthest_in_tile(t, width, tile);
                self.stale[tile] = false;
                if disc.front_t > self.farthest_t[tile] {
                    continue;
                }
            }
            return true;
        }
        false
    }

    /// Columns `first..=last` were drawn over: their tiles' farthest t may have come nearer.
    fn drawn(&mut self, (first, last): (usize, usize)) {
        for stale in &mut self.stale[first / TILE_COLUMNS..=last / TILE_COLUMNS] {
            *stale = true;
        }
    }
}

/// A band (rows from `first_row`, its t and sphere per pixel) with occlusion culling: discs front
/// to back, each drawn on all its rows of the band unless [`Occlusion`] shows it hidden.
pub(super) fn rasterise_band_front_to_back(
    band_discs: &[BandDisc],
    grid: &PixelGrid,
    first_row: usize,
    t: &mut [f64],
    sphere: &mut [u32],
) -> u64 {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let rows = t.len() / width;
    let columns = Columns::of(grid);
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    let mut occlusion = Occlusion::new(width);
    let mut disc_tests = 0u64;
    let last_row = first_row + rows - 1;
    for band_disc in band_discs {
        let disc = &band_disc.disc;
        let radius_px = band_disc.radius * inverse_pixel;
        let Some(span) = column_span(grid, band_disc.centre_column, radius_px, radius_px) else {
            continue;
        };
        // The rows it was binned for (none is drawn outside them), within the band.
        let Some((first, last)) = rows_of(grid, disc.v, band_disc.radius) else {
            continue;
        };
        let (first, last) = (first.max(first_row), last.min(last_row));
        if first > last || !occlusion.may_show(band_disc, span, t, width) {
            continue;
        }
        occlusion.drawn(span);
        for image_row in first..=last {
            let y_up = (height - 1 - image_row) as f64;
            let v = grid.v_of_row(y_up);
            let Some(chord) = chord_on_row(grid, disc, (band_disc.centre_column, radius_px), v)
            else {
                continue;
            };
            disc_tests += (chord.last - chord.first + 1) as u64;
            let row_in_band = image_row - first_row;
            let range = row_in_band * width..(row_in_band + 1) * width;
            let mut row = RowOut {
                t: &mut t[range.clone()],
                sphere: &mut sphere[range],
            };
            cover_chord_behind(band_disc, columns, chord, &mut row);
        }
    }
    disc_tests
}

/// A chord for discs that come front to back: a pixel already nearer than the
/// disc's nearest t is passed over without its square root.
#[inline]
fn cover_chord_behind(band_disc: &BandDisc, columns: Columns, chord: Chord, row: &mut RowOut) {
    let disc = &band_disc.disc;
    let front_t = band_disc.front_t;
    let dv = chord.v - disc.v;
    let dv_sq = dv * dv;
    let t_span = &mut row.t[chord.first..=chord.last];
    let sphere_span = &mut row.sphere[chord.first..=chord.last];
    // Indexed over spans of one length (no bounds checks), columns counted in f64.
    let mut x = chord.first as f64;
    for (t_px, sphere_px) in t_span.iter_mut().zip(sphere_span.iter_mut()) {
        let column = x;
        x += 1.0;
        if front_t > *t_px {
            continue;
        }
        let PixelHit { distance_sq, t } = pixel_hit(disc, columns.u(column), dv_sq);
        if distance_sq <= disc.radius_sq && (t < *t_px || (t == *t_px && disc.sphere < *sphere_px))
        {
            *t_px = t;
            *sphere_px = disc.sphere;
        }
    }
}
