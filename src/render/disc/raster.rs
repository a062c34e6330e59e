//! Rasterising: a band's pixels tested against the band's discs, each disc only on the columns
//! its chord can cover on a row; bands run in parallel and make a [`Frame`].
//!
//! In a type with rounding coarser than f64 (f32), a pixel whose decision that type cannot make
//! with certainty — within its error bound of a silhouette (`r² − d²`) or of a tie with the sphere
//! already there — is re-decided in f64, so coverage is exact in every mode and only t carries
//! the coarser rounding.

use rayon::prelude::*;

use super::Disc;
use super::bins::{BAND_ROWS, bin_discs, column_span};
use super::real::Real;
use super::shade::frame_from_hits;
use crate::geometry::camera::PixelGrid;
use crate::render::{Frame, NO_HIT, View};
use crate::scene::Scene;

/// A disc in the per-pixel type.
#[derive(Debug, Clone, Copy)]
struct DiscIn<R> {
    u: R,
    v: R,
    w: R,
    radius_sq: R,
}

impl<R: Real> DiscIn<R> {
    fn of(disc: &Disc) -> Self {
        Self {
            u: R::from_f64(disc.u),
            v: R::from_f64(disc.v),
            w: R::from_f64(disc.w),
            radius_sq: R::from_f64(disc.radius_sq),
        }
    }
}

/// The disc test at one pixel, in the per-pixel type.
struct PixelHit<R> {
    /// Squared screen distance from the disc's centre.
    distance_sq: R,
    /// r² − distance²: ≥ 0 inside the disc.
    rest: R,
    /// √max(rest, 0).
    root: R,
    /// t of the front surface (meaningful inside the disc).
    t: R,
}

/// Tests pixel column `u` (screen) against `disc` on a row `dv_sq` = (v − c_v)² away.
#[inline(always)]
fn pixel_hit<R: Real>(disc: &DiscIn<R>, u: R, dv_sq: R) -> PixelHit<R> {
    let du = u - disc.u;
    let distance_sq = du * du + dv_sq;
    let rest = disc.radius_sq - distance_sq;
    let root = (if rest > R::ZERO { rest } else { R::ZERO }).sqrt();
    PixelHit {
        distance_sq,
        rest,
        root,
        t: disc.w - root,
    }
}

/// One band's output buffers.
struct BandOut<'a, R> {
    /// t per pixel.
    t: &'a mut [R],
    /// Sphere per pixel.
    sphere: &'a mut [u32],
    /// Error bound of the stored t per pixel (only for types with [`Real::ROUNDOFF`] > 0).
    t_error: &'a mut [R],
}

/// One row's outputs.
struct RowOut<'a, R> {
    t: &'a mut [R],
    sphere: &'a mut [u32],
    /// Empty for exact types.
    t_error: &'a mut [R],
}

/// Where a disc's chord lies on one row: the columns to test and the row's screen v.
#[derive(Clone, Copy)]
struct Chord {
    first: usize,
    last: usize,
    v: f64,
}

/// Pixel-to-screen constants of a grid in the per-pixel type.
#[derive(Clone, Copy)]
struct Columns<R> {
    pixel_size: R,
    /// Added to a column index before scaling: `½ − width/2`.
    offset: R,
}

impl<R: Real> Columns<R> {
    fn of(grid: &PixelGrid) -> Self {
        Self {
            pixel_size: R::from_f64(grid.pixel_size_world),
            offset: R::from_f64(0.5 - 0.5 * f64::from(grid.width_px)),
        }
    }

    /// Screen u of column `x`'s centre.
    #[inline(always)]
    fn u(&self, x: usize) -> R {
        (R::from_f64(x as f64) + self.offset) * self.pixel_size
    }
}

/// A disc gathered for a band.
#[derive(Clone, Copy)]
struct BandDisc {
    disc: Disc,
    /// Its centre's column coordinate (`u / s + width/2 − ½`).
    centre_column: f64,
    /// The nearest t it can have anywhere: `w − r`, never above the t of any pixel it covers
    /// (correctly rounded square root and subtraction are monotonic).
    front_t: f64,
}

/// The band's discs gathered once, contiguous and in file order: the rows read them sequentially
/// instead of chasing indices across the whole scene (cache misses dominated).
fn gather_band_discs(
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
            front_t: disc.w - disc.radius_sq.sqrt(),
        }
    })
    .collect()
}

/// Columns per occlusion tile (a tile is this many columns of a band's rows).
const TILE_COLUMNS: usize = 16;

/// Below this many discs in a band, occlusion culling does not pay for its sort.
const CULL_MIN_DISCS: usize = 64;

/// The farthest t among the pixels of `tile` in a band of rows `width` long; stops at the first
/// uncovered pixel (+∞).
fn farthest_in_tile<R: Real>(t: &[R], width: usize, tile: usize) -> f64 {
    let columns = tile * TILE_COLUMNS..((tile + 1) * TILE_COLUMNS).min(width);
    let mut farthest = f64::NEG_INFINITY;
    for row in t.chunks(width) {
        for &t in &row[columns.clone()] {
            let t = t.to_f64();
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
    fn may_show<R: Real>(
        &mut self,
        disc: &BandDisc,
        (first, last): (usize, usize),
        t: &[R],
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

/// The columns of the row at screen `v` that `disc`'s chord may cover (in f64, conservative; the
/// per-pixel test decides).
fn chord_on_row(grid: &PixelGrid, disc: &Disc, centre_column: f64, v: f64) -> Option<Chord> {
    let dv = v - disc.v;
    let chord_sq = disc.radius_sq - dv * dv;
    if chord_sq.is_nan() || chord_sq < -disc.radius_sq * 1e-6 {
        return None;
    }
    let half_chord_px = chord_sq.max(0.0).sqrt() * (1.0 / grid.pixel_size_world);
    let (first, last) = column_span(grid, centre_column, half_chord_px)?;
    Some(Chord { first, last, v })
}

/// Fills one band (rows `first_row..first_row + rows`, top first) of t and sphere indices;
/// returns the pixel–disc tests made.
fn rasterise_band<R: Real>(
    discs: &[Disc],
    list: impl Iterator<Item = u32>,
    grid: &PixelGrid,
    first_row: usize,
    out: BandOut<'_, R>,
    front_to_back: bool,
) -> u64 {
    let band_discs = gather_band_discs(discs, list, grid);
    if front_to_back {
        rasterise_band_front_to_back(&band_discs, grid, first_row, out)
    } else {
        rasterise_band_in_order(discs, &band_discs, grid, first_row, out)
    }
}

/// `discs` sorted by their nearest t (`w − r`), front to back, in parallel.
///
/// The order only decides how much is culled, never the picture (a hidden disc stays hidden, and
/// ties go by file index whatever the order), so an approximate order does: a counting sort into
/// [`DEPTH_BUCKETS`] slices of the depth range, file order within a slice. Linear in the discs.
fn front_to_back(discs: &[Disc]) -> Vec<Disc> {
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
const CULL_MIN_DISCS_PER_PIXEL: f64 = 6.0;

/// How many discs lie over a pixel on average: their areas (each at most the image's) summed,
/// over the image's area.
fn discs_per_pixel(discs: &[Disc], grid: &PixelGrid) -> f64 {
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

/// [`rasterise_band`] for exact types with occlusion culling: discs front to back, each drawn on
/// all its rows of the band unless [`Occlusion`] shows it hidden.
fn rasterise_band_front_to_back<R: Real>(
    band_discs: &[BandDisc],
    grid: &PixelGrid,
    first_row: usize,
    BandOut { t, sphere, .. }: BandOut<'_, R>,
) -> u64 {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let rows = t.len() / width;
    let columns = Columns::<R>::of(grid);
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
                t_error: &mut [],
            };
            cover_chord_behind(band_disc, columns, chord, &mut row);
        }
    }
    disc_tests
}

/// [`cover_chord_exact`] for discs that come front to back: a pixel already nearer than the
/// disc's nearest t is passed over without its square root.
#[inline]
fn cover_chord_behind<R: Real>(
    band_disc: &BandDisc,
    columns: Columns<R>,
    chord: Chord,
    row: &mut RowOut<R>,
) {
    let disc = &band_disc.disc;
    let front_t = R::from_f64(band_disc.front_t);
    let disc_in = DiscIn::<R>::of(disc);
    let dv = R::from_f64(chord.v) - disc_in.v;
    let dv_sq = dv * dv;
    let t_span = &mut row.t[chord.first..=chord.last];
    let sphere_span = &mut row.sphere[chord.first..=chord.last];
    for ((x, t_px), sphere_px) in (chord.first..).zip(t_span).zip(sphere_span) {
        if front_t > *t_px {
            continue;
        }
        let PixelHit { distance_sq, t, .. } = pixel_hit(&disc_in, columns.u(x), dv_sq);
        if distance_sq <= disc_in.radius_sq
            && (t < *t_px || (t == *t_px && disc.sphere < *sphere_px))
        {
            *t_px = t;
            *sphere_px = disc.sphere;
        }
    }
}

/// [`rasterise_band`] in file order, row by row (f32, and bands with few discs).
fn rasterise_band_in_order<R: Real>(
    discs: &[Disc],
    band_discs: &[BandDisc],
    grid: &PixelGrid,
    first_row: usize,
    BandOut { t, sphere, t_error }: BandOut<'_, R>,
) -> u64 {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let columns = Columns::<R>::of(grid);
    let refine = R::ROUNDOFF > 0.0;
    let mut disc_tests = 0u64;
    let rows = t.chunks_mut(width).zip(sphere.chunks_mut(width));
    for (row_in_band, (t, sphere)) in rows.enumerate() {
        let t_error: &mut [R] = if refine {
            &mut t_error[row_in_band * width..(row_in_band + 1) * width]
        } else {
            &mut []
        };
        let mut row = RowOut { t, sphere, t_error };
        let y_up = (height - 1 - (first_row + row_in_band)) as f64;
        let v = grid.v_of_row(y_up);
        for BandDisc {
            disc,
            centre_column,
            ..
        } in band_discs
        {
            let Some(chord) = chord_on_row(grid, disc, *centre_column, v) else {
                continue;
            };
            disc_tests += (chord.last - chord.first + 1) as u64;
            if refine {
                cover_chord_refined(discs, disc, grid, columns, chord, &mut row);
            } else {
                cover_chord_exact(disc, columns, chord, &mut row);
            }
        }
    }
    disc_tests
}

/// Exact types (f64), discs in file order: the disc replaces the pixel's sphere where it covers
/// the pixel and is strictly nearer (so a tie keeps the sphere first in the file). Over slices (no
/// bounds checks), branch-free selects.
#[inline]
fn cover_chord_exact<R: Real>(disc: &Disc, columns: Columns<R>, chord: Chord, row: &mut RowOut<R>) {
    let disc_in = DiscIn::<R>::of(disc);
    let dv = R::from_f64(chord.v) - disc_in.v;
    let dv_sq = dv * dv;
    let t_span = &mut row.t[chord.first..=chord.last];
    let sphere_span = &mut row.sphere[chord.first..=chord.last];
    for ((x, t_px), sphere_px) in (chord.first..).zip(t_span).zip(sphere_span) {
        let PixelHit { distance_sq, t, .. } = pixel_hit(&disc_in, columns.u(x), dv_sq);
        let closer = distance_sq <= disc_in.radius_sq && t < *t_px;
        *t_px = if closer { t } else { *t_px };
        *sphere_px = if closer { disc.sphere } else { *sphere_px };
    }
}

/// Error bounds of R's arithmetic for `disc` on a row's chord: how close to the silhouette
/// (`r² − d²`) a decision is uncertain, and t's error (a flat part plus one that grows towards
/// the silhouette as `steep / √(r² − d²)`).
struct ErrorBounds<R> {
    coverage: R,
    t_flat: R,
    t_steep: R,
}

impl<R: Real> ErrorBounds<R> {
    fn of(disc: &Disc, grid: &PixelGrid, chord: Chord) -> Self {
        let radius = disc.radius_sq.sqrt();
        let largest = disc
            .u
            .abs()
            .max(disc.v.abs())
            .max(chord.v.abs())
            .max(grid.u_of_column(chord.first as f64).abs())
            .max(grid.u_of_column(chord.last as f64).abs())
            + radius;
        let coverage = 32.0 * R::ROUNDOFF * largest * largest;
        Self {
            coverage: R::from_f64(coverage),
            t_flat: R::from_f64(8.0 * R::ROUNDOFF * (disc.w.abs() + radius)),
            t_steep: R::from_f64(coverage),
        }
    }
}

/// Coarse types (f32): as [`cover_chord_exact`], but a pixel whose decision is within the
/// error bounds is re-decided in f64.
fn cover_chord_refined<R: Real>(
    discs: &[Disc],
    disc: &Disc,
    grid: &PixelGrid,
    columns: Columns<R>,
    chord: Chord,
    row: &mut RowOut<R>,
) {
    let disc_in = DiscIn::<R>::of(disc);
    let dv = R::from_f64(chord.v) - disc_in.v;
    let dv_sq = dv * dv;
    let bounds = ErrorBounds::<R>::of(disc, grid, chord);
    for x in chord.first..=chord.last {
        let PixelHit { rest, root, t, .. } = pixel_hit(&disc_in, columns.u(x), dv_sq);
        let t_error = bounds.t_flat + bounds.t_steep.div(root);
        let uncertain_coverage = rest.abs() <= bounds.coverage;
        let uncertain_order =
            row.sphere[x] != NO_HIT && (t - row.t[x]).abs() <= t_error + row.t_error[x];
        if uncertain_coverage || uncertain_order {
            let u = grid.u_of_column(x as f64);
            decide_in_f64(discs, disc, u, chord.v, &mut row.t[x], &mut row.sphere[x]);
            if row.sphere[x] == disc.sphere {
                row.t_error[x] = R::ZERO;
            }
        } else if rest >= R::ZERO && t < row.t[x] {
            row.t[x] = t;
            row.sphere[x] = disc.sphere;
            row.t_error[x] = t_error;
        }
    }
}

/// Decides the pixel at screen (u, v) in f64: `disc` against the sphere already there.
fn decide_in_f64<R: Real>(
    discs: &[Disc],
    disc: &Disc,
    u: f64,
    v: f64,
    t_out: &mut R,
    sphere_out: &mut u32,
) {
    let Some(t) = disc.hit_t(u, v) else {
        return;
    };
    let current = discs
        .get(*sphere_out as usize)
        .and_then(|d| d.hit_t(u, v))
        .unwrap_or(f64::INFINITY);
    if t < current {
        *t_out = R::from_f64(t);
        *sphere_out = disc.sphere;
    } else if current.is_finite() {
        *t_out = R::from_f64(current);
    }
}

/// Renders one centre sample per pixel from projected `discs`, per-pixel arithmetic in `R`.
pub(crate) fn rasterise_frame<R: Real>(
    scene: &Scene,
    view: &View,
    grid: &PixelGrid,
    discs: &[Disc],
) -> Frame {
    let grid = *grid;
    // Exact types with many discs: bands list them front to back and cull what is hidden (ties
    // still go to the first sphere in the file). f32 keeps file order: its uncertain decisions
    // are re-made in f64 against the sphere there, by index.
    let sorted;
    let (discs, front_to_back_order) = if R::ROUNDOFF == 0.0
        && discs.len() >= CULL_MIN_DISCS
        && discs_per_pixel(discs, &grid) >= CULL_MIN_DISCS_PER_PIXEL
    {
        sorted = front_to_back(discs);
        (sorted.as_slice(), true)
    } else {
        (discs, false)
    };
    let bands = bin_discs(discs, &grid);
    let width = view.width_px as usize;
    let height = view.height_px as usize;
    // "No hit" everywhere, written in parallel (a `vec![…; n]` fills serially).
    let mut t: Vec<f64> = (0..width * height)
        .into_par_iter()
        .map(|_| f64::INFINITY)
        .collect();
    let mut sphere: Vec<u32> = (0..width * height)
        .into_par_iter()
        .map(|_| NO_HIT)
        .collect();
    let disc_tests = t
        .par_chunks_mut(width * BAND_ROWS)
        .zip(sphere.par_chunks_mut(width * BAND_ROWS))
        .enumerate()
        .map(|(band, (t_band, sphere_band))| {
            let list = bands.band(band);
            let first_row = band * BAND_ROWS;
            // f64: written in place.
            if let Some(t_in_place) = R::as_self_slice(t_band) {
                let out = BandOut {
                    t: t_in_place,
                    sphere: sphere_band,
                    t_error: &mut [],
                };
                return rasterise_band(discs, list, &grid, first_row, out, front_to_back_order);
            }
            // f32: a scratch band, widened into the frame's f64 t.
            let mut scratch = vec![R::INFINITY; t_band.len()];
            let mut t_error = vec![R::ZERO; t_band.len()];
            let out = BandOut {
                t: &mut scratch,
                sphere: sphere_band,
                t_error: &mut t_error,
            };
            let tests = rasterise_band(discs, list, &grid, first_row, out, front_to_back_order);
            for (out, value) in t_band.iter_mut().zip(&scratch) {
                *out = value.to_f64();
            }
            tests
        })
        .sum::<u64>();
    let mut frame = frame_from_hits(scene, view, t, sphere, R::PRECISION);
    frame.disc_tests = disc_tests;
    frame
}
