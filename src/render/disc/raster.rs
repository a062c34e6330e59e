//! Rasterising: a band's pixels tested against the band's discs, each disc only on the columns
//! its chord can cover on a row; bands run in parallel and make a [`Frame`]. All per-pixel
//! arithmetic is f64 (`docs/accuracy.md` says why there is no f32 mode).

use rayon::prelude::*;

use super::bins::{BAND_ROWS, bin_discs};
use super::chord::{BandDisc, Chord, Columns, RowOut, chord_on_row, gather_band_discs};
use super::coarse_depth::CoarseDepth;
use super::depth_order::{Depths, Plan};
use super::hit::test;
use super::screen_disc::Disc;
use super::shade::frame_from_hits;
use super::tiles::{rasterise_discs_in_tiles, rasterise_placed_in_tiles};
use crate::geometry::camera::PixelGrid;
use crate::render::frame::{Frame, NO_HIT};
use crate::render::phases::time;
use crate::render::view::View;
use crate::scene::Scene;

/// Fills one band (rows `first_row..first_row + rows`, top first) of t and sphere indices;
/// returns the pixel–disc tests made.
pub(super) fn rasterise_band(
    discs: &[Disc],
    list: impl Iterator<Item = u32>,
    grid: &PixelGrid,
    first_row: usize,
    (t, sphere): (&mut [f64], &mut [u32]),
) -> u64 {
    let band_discs = gather_band_discs(discs, list, grid);
    rasterise_band_in_order(&band_discs, grid, first_row, t, sphere)
}

/// [`rasterise_band`] in file order, row by row (frames with few discs, or fewer than six over a
/// pixel on average).
fn rasterise_band_in_order(
    band_discs: &[BandDisc],
    grid: &PixelGrid,
    first_row: usize,
    t: &mut [f64],
    sphere: &mut [u32],
) -> u64 {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let columns = Columns::of(grid);
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    let mut disc_tests = 0u64;
    let rows = t.chunks_mut(width).zip(sphere.chunks_mut(width));
    for (row_in_band, (t, sphere)) in rows.enumerate() {
        let mut row = RowOut { t, sphere };
        let y_up = (height - 1 - (first_row + row_in_band)) as f64;
        let v = grid.v_of_row(y_up);
        for BandDisc {
            disc,
            centre_column,
            radius,
            ..
        } in band_discs
        {
            let reach = (*centre_column, radius * inverse_pixel);
            let Some(chord) = chord_on_row(grid, disc, reach, v) else {
                continue;
            };
            disc_tests += (chord.last - chord.first + 1) as u64;
            cover_chord_exact(disc, columns, chord, &mut row);
        }
    }
    disc_tests
}

/// Discs in file order: the disc replaces the pixel's sphere where it covers the pixel and is
/// strictly nearer (so a tie keeps the sphere first in the file). Over slices (no bounds checks),
/// branch-free selects.
#[inline]
fn cover_chord_exact(disc: &Disc, columns: Columns, chord: Chord, row: &mut RowOut) {
    let dv = chord.v - disc.v;
    let dv_sq = dv * dv;
    let t_span = &mut row.t[chord.first..=chord.last];
    let sphere_span = &mut row.sphere[chord.first..=chord.last];
    // Spans of one length (no bounds checks), columns counted in f64.
    let mut x = chord.first as f64;
    for (t_px, sphere_px) in t_span.iter_mut().zip(sphere_span.iter_mut()) {
        let du = columns.u(x) - disc.u;
        x += 1.0;
        // In file order a tie never goes to the later disc ([`super::hit::wins_tie`]): only a
        // nearer disc takes the pixel.
        let hit = test(disc, du * du, dv_sq, *t_px);
        let closer = hit.nearer;
        let t = hit.t;
        *t_px = if closer { t } else { *t_px };
        *sphere_px = if closer { disc.sphere } else { *sphere_px };
    }
}

/// How many times over the first pass's discs (the nearest) cover the image; each later pass
/// ends where the passes so far cover it twice as many times as before.
pub(super) const FIRST_PASS_LAYERS: f64 = 4.0;

/// Renders one centre sample per pixel from projected `discs` (with their `depths`).
///
/// Dense frames (many discs, six or more over a pixel on average:
/// [`super::depth_order::CULL_MIN_DISCS_PER_PIXEL`]) go in passes of depth slices, front to back:
/// the first draws the nearest discs that cover the image [`FIRST_PASS_LAYERS`] times; each later
/// one the next slices, covering twice as many layers as all before it, but only the discs that
/// the coarse depth of what is drawn so far does not hide ([`CoarseDepth`]). Within a pass, each
/// tile stops where the discs still to come lie behind it ([`super::tiles`]). Ties still go to
/// the first sphere in the file whatever the order.
pub(crate) fn rasterise_frame(
    scene: &Scene,
    view: &View,
    grid: &PixelGrid,
    discs: &[Disc],
    depths: &Depths,
) -> Frame {
    let plan = time("plan", || Plan::of(discs, depths, grid, FIRST_PASS_LAYERS));
    let (t, sphere, disc_tests) = rasterise_hits(grid, discs, plan);
    let mut frame = time("shade", || frame_from_hits(scene, view, t, sphere));
    frame.disc_tests = disc_tests;
    frame
}

/// The t and sphere of every pixel (top row first) of a frame drawn as `plan` says, and the
/// pixel–disc tests made.
pub(super) fn rasterise_hits(
    grid: &PixelGrid,
    discs: &[Disc],
    plan: Plan,
) -> (Vec<f64>, Vec<u32>, u64) {
    let pixels = grid.width_px as usize * grid.height_px as usize;
    // "No hit" everywhere, written in parallel (a `vec![…; n]` fills serially).
    let (mut t, mut sphere) = time("clear", || {
        let t: Vec<f64> = (0..pixels).into_par_iter().map(|_| f64::INFINITY).collect();
        let sphere: Vec<u32> = (0..pixels).into_par_iter().map(|_| NO_HIT).collect();
        (t, sphere)
    });
    let mut out = (t.as_mut_slice(), sphere.as_mut_slice());
    let disc_tests = match plan {
        Plan::FileOrder => rasterise_discs(discs, grid, Order::File, &mut out),
        Plan::AnyOrder => rasterise_discs(discs, grid, Order::FrontToBack, &mut out),
        Plan::Passes(mut passes) => {
            let mut disc_tests = 0;
            for pass in 0..passes.count() {
                if passes.is_empty(pass) {
                    continue;
                }
                let drawn =
                    (pass > 0).then(|| time("coarse depth", || CoarseDepth::of(out.0, grid)));
                let parts = passes.take(pass, drawn.as_ref(), grid);
                disc_tests += rasterise_placed_in_tiles(&parts, grid, (out.0, out.1));
            }
            disc_tests
        }
    };
    (t, sphere, disc_tests)
}

/// The order discs come in to [`rasterise_discs`].
#[derive(Clone, Copy)]
enum Order {
    /// File order: drawn row by row.
    File,
    /// Front to back: drawn tile by tile, each tile stopping where the rest is hidden
    /// ([`super::tiles`]).
    FrontToBack,
}

/// Draws `discs`, coming in `order`, into `t` and `sphere` (kept where already nearer), band by
/// band in parallel. Returns the pixel–disc tests.
fn rasterise_discs(
    discs: &[Disc],
    grid: &PixelGrid,
    order: Order,
    (t, sphere): &mut (&mut [f64], &mut [u32]),
) -> u64 {
    if let Order::FrontToBack = order {
        return rasterise_discs_in_tiles(discs, grid, (t, sphere));
    }
    let width = grid.width_px as usize;
    let bands = time("bin", || bin_discs(discs, grid));
    time("draw", || {
        t.par_chunks_mut(width * BAND_ROWS)
            .zip(sphere.par_chunks_mut(width * BAND_ROWS))
            .enumerate()
            .map(|(band, out)| {
                let first_row = band * BAND_ROWS;
                rasterise_band(discs, bands.band(band), grid, first_row, out)
            })
            .sum()
    })
}
