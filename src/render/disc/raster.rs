//! Rasterising: a band's pixels tested against the band's discs, each disc only on the columns
//! its chord can cover on a row; bands run in parallel and make a [`Frame`].
//!
//! In a type with rounding coarser than f64 (f32), a pixel whose decision that type cannot make
//! with certainty — within its error bound of a silhouette (`r² − d²`) or of a tie with the sphere
//! already there — is re-decided in f64, so coverage is exact in every mode and only t carries
//! the coarser rounding.

use rayon::prelude::*;

use super::Disc;
use super::bins::{BAND_ROWS, bin_discs};
use super::chord::{
    BandDisc, Chord, Columns, DiscIn, PixelHit, RowOut, chord_on_row, gather_band_discs, pixel_hit,
};
use super::occlusion::{
    CULL_MIN_DISCS, CULL_MIN_DISCS_PER_PIXEL, discs_per_pixel, front_to_back,
    rasterise_band_front_to_back,
};
use super::real::Real;
use super::shade::frame_from_hits;
use crate::geometry::camera::PixelGrid;
use crate::render::{Frame, NO_HIT, View};
use crate::scene::Scene;

/// One band's output buffers.
struct BandOut<'a, R> {
    /// t per pixel.
    t: &'a mut [R],
    /// Sphere per pixel.
    sphere: &'a mut [u32],
    /// Error bound of the stored t per pixel (only for types with [`Real::ROUNDOFF`] > 0).
    t_error: &'a mut [R],
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
        rasterise_band_front_to_back(&band_discs, grid, first_row, out.t, out.sphere)
    } else {
        rasterise_band_in_order(discs, &band_discs, grid, first_row, out)
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
