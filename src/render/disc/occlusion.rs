//! Occlusion culling for dense scenes: discs drawn front to back, and a disc hidden behind what
//! is already drawn in a band skipped (one level of hierarchical z per band).

use rayon::prelude::*;

use super::Disc;
use super::bins::column_span;
use super::chord::{BandDisc, Chord, Columns, PixelHit, RowOut, chord_on_row, pixel_hit};
use crate::geometry::camera::PixelGrid;

/// Columns per occlusion tile (a tile is this many columns of a band's rows).
const TILE_COLUMNS: usize = 16;

/// Below this many discs in a band, occlusion culling does not pay for its sort.
pub(super) const CULL_MIN_DISCS: usize = 64;

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
/// a disc was drawn over it and another asks.
struct Occlusion {
    farthest_t: Vec<f64>,
    stale: Vec<bool>,
}

impl Occlusion {
    fn new(width: usize) -> Self {
        let tiles = width.div_ceil(TILE_COLUMNS);
        Self {
            farthest_t: vec![f64::INFINITY; tiles],
            stale: vec![false; tiles],
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

/// `discs` sorted by their nearest t (`w − r`), front to back, in parallel.
///
/// The order only decides how much is culled, never the picture (a hidden disc stays hidden, and
/// ties go by file index whatever the order), so an approximate order does: a counting sort into
/// [`DEPTH_BUCKETS`] slices of the depth range, file order within a slice. Linear in the discs.
pub(super) fn front_to_back(discs: &[Disc]) -> Vec<Disc> {
    let fronts: Vec<f64> = discs
        .par_iter()
        .map(|disc| disc.w - disc.radius_sq.sqrt())
        .collect();
    let (nearest, farthest) = fronts
        .par_iter()
        .filter(|front| front.is_finite())
        .fold(
            || (f64::INFINITY, f64::NEG_INFINITY),
            |(low, high), &front| (low.min(front), high.max(front)),
        )
        .reduce(
            || (f64::INFINITY, f64::NEG_INFINITY),
            |a, b| (a.0.min(b.0), a.1.max(b.1)),
        );
    let span = farthest - nearest;
    if !(span > 0.0 && span.is_finite()) {
        return discs.to_vec();
    }
    let scale = DEPTH_BUCKETS as f64 / span;
    // NaN and +∞ go last, −∞ first (the saturating conversion).
    let bucket_of = |front: f64| {
        let slice = if front.is_nan() {
            f64::INFINITY
        } else {
            (front - nearest) * scale
        };
        (slice as usize).min(DEPTH_BUCKETS - 1)
    };
    let buckets: Vec<u16> = fronts.par_iter().map(|&f| bucket_of(f) as u16).collect();
    let mut starts = vec![0usize; DEPTH_BUCKETS + 1];
    for &bucket in &buckets {
        starts[usize::from(bucket) + 1] += 1;
    }
    for bucket in 0..DEPTH_BUCKETS {
        starts[bucket + 1] += starts[bucket];
    }
    let mut sorted = vec![
        Disc {
            u: 0.0,
            v: 0.0,
            w: 0.0,
            radius_sq: 0.0,
            sphere: 0,
        };
        discs.len()
    ];
    for (disc, &bucket) in discs.iter().zip(&buckets) {
        let slot = &mut starts[usize::from(bucket)];
        sorted[*slot] = *disc;
        *slot += 1;
    }
    sorted
}

/// Below this many discs over a pixel on average, sorting costs more than culling saves (measured
/// with `examples/performance.rs`: the random scenes of 100,000 and 1,000,000 spheres lie about
/// three deep and were slower culled; the dense ones lie 10 and 100 deep and were 3 to 4× faster).
pub(super) const CULL_MIN_DISCS_PER_PIXEL: f64 = 6.0;

/// How many discs lie over a pixel on average: their areas (each at most the image's) summed,
/// over the image's area.
pub(super) fn discs_per_pixel(discs: &[Disc], grid: &PixelGrid) -> f64 {
    let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
    let pixel_area = grid.pixel_size_world * grid.pixel_size_world;
    let covered: f64 = discs
        .par_iter()
        .map(|disc| (std::f64::consts::PI * disc.radius_sq / pixel_area).min(pixels))
        .sum();
    covered / pixels
}

/// Slices of the depth range the front-to-back order sorts discs into.
const DEPTH_BUCKETS: usize = 4096;

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
    for band_disc in band_discs {
        let disc = &band_disc.disc;
        let radius_px = disc.radius_sq.sqrt() * inverse_pixel;
        let Some(span) = column_span(grid, band_disc.centre_column, radius_px) else {
            continue;
        };
        if !occlusion.may_show(band_disc, span, t, width) {
            continue;
        }
        occlusion.drawn(span);
        for row_in_band in 0..rows {
            let y_up = (height - 1 - (first_row + row_in_band)) as f64;
            let v = grid.v_of_row(y_up);
            let Some(chord) = chord_on_row(grid, disc, band_disc.centre_column, v) else {
                continue;
            };
            disc_tests += (chord.last - chord.first + 1) as u64;
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
    for ((x, t_px), sphere_px) in (chord.first..).zip(t_span).zip(sphere_span) {
        if front_t > *t_px {
            continue;
        }
        let PixelHit { distance_sq, t } = pixel_hit(disc, columns.u(x), dv_sq);
        if distance_sq <= disc.radius_sq && (t < *t_px || (t == *t_px && disc.sphere < *sphere_px))
        {
            *t_px = t;
            *sphere_px = disc.sphere;
        }
    }
}
