//! Dense discs drawn tile by tile, front to back, with early termination. Each disc is placed
//! once (its rows and columns, conservative), listed in the bands of rows it touches and, within
//! a band, in the tiles of [`TILE_COLUMNS`] columns it reaches, in the order the discs come —
//! front to back by slices of depth (the depth order of dense frames). A tile draws its discs in
//! that order while the nearest t any disc still to come can have (a suffix minimum of `w − r`
//! over the band's list) is not beyond every pixel of the tile, and stops there: every disc after
//! it is hidden. A frame then costs what is visible in each tile, not what piles up behind it.
//!
//! Pixels are tested four at a time in SIMD lanes (`wide::f64x4`: two SSE2 registers on baseline
//! x86-64). Every lane computes exactly what the one-pixel test computes — `du = u − c_u`,
//! `du² + dv² ≤ r²`, `t = w − √(r² − du² − dv²)`, each operation correctly rounded — so the
//! picture is the same bit for bit; the choice between spheres does not depend on the order they
//! come in (the nearer t, and on an equal t the sphere first in the file). On a whole tile a disc
//! takes both groups of every row it may cover without a branch (which pixels a disc wins is
//! unpredictable, and a mispredicted branch costs more than the arithmetic it saves); on the
//! image's last, narrower tile, the groups its columns reach, each skipped when all its pixels
//! are already nearer than the disc can come.

use rayon::prelude::*;
use wide::{f64x4, u32x4};

use super::bins::BAND_ROWS;
use super::chord::Columns;
use super::hit::{take_ties, takes_pixel, test};
use super::placed::{Placed, PlacedPart, place_in_parts};
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;
use crate::render::phases::time;

/// Columns per tile (a tile is this many columns of a band's rows).
const TILE_COLUMNS: usize = 8;

/// Pixels per SIMD group.
const LANES: usize = 4;

/// Per set of lanes (bit `i` for lane `i`), a mask of all ones in those lanes.
const LANE_MASKS: [[u32; LANES]; 1 << LANES] = {
    let mut masks = [[0; LANES]; 1 << LANES];
    let mut set = 0;
    while set < 1 << LANES {
        let mut lane = 0;
        while lane < LANES {
            if set >> lane & 1 == 1 {
                masks[set][lane] = u32::MAX;
            }
            lane += 1;
        }
        set += 1;
    }
    masks
};

/// A band's pixels: its rows of t and sphere indices, `width` long, and the screen coordinates
/// of their centres.
struct BandPixels<'a> {
    t: &'a mut [f64],
    sphere: &'a mut [u32],
    width: usize,
    /// Screen u of each column's pixel centres.
    u_of_column: &'a [f64],
    /// Screen v of each of the band's rows.
    v_of_row: Vec<f64>,
}

/// Draws `discs` (best front to back; any order is exact) into `t` and `sphere` (row-major, top
/// row first), keeping a pixel's sphere where it is already nearer; bands of [`BAND_ROWS`] rows
/// in parallel. Returns the pixel–disc tests made.
pub(super) fn rasterise_discs_in_tiles(
    discs: &[Disc],
    grid: &PixelGrid,
    (t, sphere): (&mut [f64], &mut [u32]),
) -> u64 {
    let parts = time("bin", || place_in_parts(discs, grid));
    rasterise_placed_in_tiles(&parts, grid, (t, sphere))
}

/// [`rasterise_discs_in_tiles`] for discs already placed and binned: `parts`, consecutive parts
/// of the discs in the order they come.
pub(super) fn rasterise_placed_in_tiles(
    parts: &[PlacedPart],
    grid: &PixelGrid,
    (t, sphere): (&mut [f64], &mut [u32]),
) -> u64 {
    let columns = Columns::of(grid);
    let u_of_column: Vec<f64> = (0..grid.width_px)
        .map(|x| columns.u(f64::from(x)))
        .collect();
    time("draw", || {
        draw_bands(parts, grid, (t, sphere), &u_of_column)
    })
}

/// Draws each band's listed discs into its rows of `t` and `sphere`, bands in parallel. Returns the
/// pixel–disc tests made.
fn draw_bands(
    parts: &[PlacedPart],
    grid: &PixelGrid,
    (t, sphere): (&mut [f64], &mut [u32]),
    u_of_column: &[f64],
) -> u64 {
    let width = grid.width_px as usize;
    t.par_chunks_mut(width * BAND_ROWS)
        .zip(sphere.par_chunks_mut(width * BAND_ROWS))
        .enumerate()
        .map(|(band, (t, sphere))| {
            let mut band_discs =
                Vec::with_capacity(parts.iter().map(|part| part.band_len(band)).sum());
            for part in parts {
                band_discs.extend(part.band(band).copied());
            }
            let pixels = BandPixels {
                t,
                sphere,
                width,
                u_of_column,
                v_of_row: Vec::new(),
            };
            rasterise_band(&band_discs, grid, band * BAND_ROWS, pixels)
        })
        .sum()
}

/// Draws a band's discs (in the order listed) into the band's `pixels`, its first row
/// `first_row` of the image. Returns the pixel–disc tests made.
#[inline(never)]
fn rasterise_band(
    band_discs: &[Placed],
    grid: &PixelGrid,
    first_row: usize,
    mut pixels: BandPixels,
) -> u64 {
    let width = pixels.width;
    let height = grid.height_px as usize;
    let rows = pixels.t.len() / width;
    pixels.v_of_row = (first_row..first_row + rows)
        .map(|row| grid.v_of_row((height - 1 - row) as f64))
        .collect();
    // The nearest t of each disc and of all after it in the list (NaN, which never hits, left
    // out).
    let mut nearest_to_come = vec![f64::INFINITY; band_discs.len() + 1];
    for (at, placed) in band_discs.iter().enumerate().rev() {
        nearest_to_come[at] = placed.front_t.min(nearest_to_come[at + 1]);
    }
    // Per tile, the discs that reach it, in the order listed (a counting sort). Most discs reach
    // one or two tiles: the first two are written without a branch on how many, a write past a
    // disc's last tile landing in a slot of that tile that a later disc overwrites, or in the
    // one spare slot each tile's list has (never read); a tile past the last takes such writes.
    let tiles = width.div_ceil(TILE_COLUMNS);
    let tile_of = |column: u32| column as usize / TILE_COLUMNS;
    // Discs per tile from a difference array: +1 at a disc's first tile, −1 after its last.
    let mut reach = vec![0i32; tiles + 1];
    for placed in band_discs {
        reach[tile_of(placed.columns.0)] += 1;
        reach[tile_of(placed.columns.1) + 1] -= 1;
    }
    let (mut starts, mut counts) = (vec![0u32; tiles + 1], vec![0u32; tiles + 1]);
    let (mut count, mut start) = (0i32, 0u32);
    for tile in 0..=tiles {
        count += reach[tile];
        // A count never falls below zero: every −1 follows its +1.
        counts[tile] = count.unsigned_abs();
        starts[tile] = start;
        start += counts[tile] + 1;
    }
    let mut lists = vec![0u32; start as usize];
    let mut cursors = starts.clone();
    for (at, placed) in (0u32..).zip(band_discs) {
        let (first, last) = (tile_of(placed.columns.0), tile_of(placed.columns.1));
        lists[cursors[first] as usize] = at;
        cursors[first] += 1;
        lists[cursors[first + 1] as usize] = at;
        cursors[first + 1] += u32::from(last > first);
        for cursor in &mut cursors[(first + 2).min(last + 1)..=last] {
            lists[*cursor as usize] = at;
            *cursor += 1;
        }
    }
    let band = Band {
        discs: band_discs,
        nearest_to_come: &nearest_to_come,
        first_row,
        last_row: first_row + rows - 1,
    };
    let mut disc_tests = 0;
    for tile in 0..tiles {
        let list = &lists[starts[tile] as usize..][..counts[tile] as usize];
        let columns = (
            tile * TILE_COLUMNS,
            ((tile + 1) * TILE_COLUMNS).min(width) - 1,
        );
        if !list.is_empty() {
            disc_tests += draw_tile(&band, list, columns, &mut pixels);
        }
    }
    disc_tests
}

/// A band's discs as its tiles read them.
struct Band<'a> {
    discs: &'a [Placed],
    /// Per position in `discs`: the nearest t of it and all after it.
    nearest_to_come: &'a [f64],
    /// The band's image rows.
    first_row: usize,
    last_row: usize,
}

/// Draws a tile's discs (`list`: positions in the band's list) over its `columns` until all
/// those still to come lie behind every pixel of the tile. Returns the pixel–disc tests made.
fn draw_tile(band: &Band, list: &[u32], columns: (usize, usize), pixels: &mut BandPixels) -> u64 {
    // The tile's farthest t (+∞ while a pixel is uncovered), and the pixels still uncovered as a
    // bit set; when pixels came nearer since `farthest` was worked out (`stale`), it is an
    // upper bound, worked out again once every pixel is covered and it might end the tile.
    let (mut farthest, mut uncovered) = tile_depth(pixels, columns);
    let mut stale = false;
    let mut disc_tests = 0;
    for &at in list {
        let at = at as usize;
        let placed = &band.discs[at];
        let nearest_to_come = band.nearest_to_come[at];
        if stale && uncovered == 0 && (farthest == f64::INFINITY || nearest_to_come > farthest) {
            farthest = tile_depth(pixels, columns).0;
            stale = false;
        }
        if nearest_to_come > farthest {
            break;
        }
        if placed.front_t > farthest {
            continue;
        }
        // Rows within the band, columns within the tile.
        let rows = (
            (placed.rows.0 as usize).max(band.first_row) - band.first_row,
            (placed.rows.1 as usize).min(band.last_row) - band.first_row,
        );
        let span = (
            (placed.columns.0 as usize).max(columns.0),
            (placed.columns.1 as usize).min(columns.1),
        );
        let (tests, taken) = if columns.1 + 1 - columns.0 == TILE_COLUMNS {
            draw_disc_on_whole_tile(placed, rows, columns.0, pixels)
        } else {
            draw_disc(placed, rows, span, columns.0, pixels)
        };
        disc_tests += tests;
        stale |= taken != 0;
        uncovered &= !taken;
    }
    disc_tests
}

/// A tile's pixels as a bit set: bit `row · TILE_COLUMNS + column` for the pixel `row` rows down
/// and `column` columns right of the tile's top left.
type TilePixels = u64;
const _: () = assert!(BAND_ROWS * TILE_COLUMNS <= TilePixels::BITS as usize);

/// The farthest t among a tile's pixels (+∞ when one is uncovered), and its uncovered pixels.
fn tile_depth(pixels: &BandPixels, (first, last): (usize, usize)) -> (f64, TilePixels) {
    let mut uncovered: TilePixels = 0;
    if last + 1 - first == TILE_COLUMNS {
        // A whole tile: its rows in groups of four.
        let infinity = f64x4::splat(f64::INFINITY);
        let mut farthest = f64x4::splat(f64::NEG_INFINITY);
        for (row, t_row) in pixels.t.chunks_exact(pixels.width).enumerate() {
            for (group, t) in t_row[first..=last].chunks_exact(LANES).enumerate() {
                let t = f64x4::new([t[0], t[1], t[2], t[3]]);
                farthest = farthest.max(t);
                let bit = row * TILE_COLUMNS + group * LANES;
                uncovered |= TilePixels::from(t.simd_eq(infinity).to_bitmask()) << bit;
            }
        }
        let farthest = farthest.to_array();
        return (
            farthest[0]
                .max(farthest[1])
                .max(farthest[2].max(farthest[3])),
            uncovered,
        );
    }
    let mut farthest = f64::NEG_INFINITY;
    for (row, t_row) in pixels.t.chunks_exact(pixels.width).enumerate() {
        for (column, &t) in t_row[first..=last].iter().enumerate() {
            farthest = if t > farthest { t } else { farthest };
            uncovered |= TilePixels::from(t == f64::INFINITY) << (row * TILE_COLUMNS + column);
        }
    }
    (farthest, uncovered)
}

/// [`draw_disc`] over a whole tile's width (from column `tile_column`): every row of `rows`
/// takes the same two groups of four, without branches but for ties (rare) — a mispredicted
/// branch costs more than the arithmetic it would save on these few pixels.
#[inline]
fn draw_disc_on_whole_tile(
    placed: &Placed,
    (first_row, last_row): (usize, usize),
    tile_column: usize,
    pixels: &mut BandPixels,
) -> (u64, TilePixels) {
    const _: () = assert!(TILE_COLUMNS == 2 * LANES);
    let disc = &placed.disc;
    let width = pixels.width;
    let u = &pixels.u_of_column[tile_column..tile_column + TILE_COLUMNS];
    let centre_u = f64x4::splat(disc.u);
    let du = [
        f64x4::new([u[0], u[1], u[2], u[3]]) - centre_u,
        f64x4::new([u[4], u[5], u[6], u[7]]) - centre_u,
    ];
    let du_sq = [du[0] * du[0], du[1] * du[1]];
    let mut took: TilePixels = 0;
    for row in first_row..=last_row {
        let dv = pixels.v_of_row[row] - disc.v;
        let dv_sq = f64x4::splat(dv * dv);
        let at = row * width + tile_column..row * width + tile_column + TILE_COLUMNS;
        let (Some(t_px), Some(sphere_px)) =
            (pixels.t.get_mut(at.clone()), pixels.sphere.get_mut(at))
        else {
            continue;
        };
        let mut taken: u32 = 0;
        let mut tied: u32 = 0;
        let mut t_new = [0.0; TILE_COLUMNS];
        let mut t_hit = [0.0; TILE_COLUMNS];
        for (group, &du_sq) in du_sq.iter().enumerate() {
            let lanes = group * LANES..(group + 1) * LANES;
            let o = &t_px[lanes.clone()];
            let t_old = f64x4::new([o[0], o[1], o[2], o[3]]);
            let hit = test(disc, du_sq, dv_sq, t_old);
            taken |= hit.nearer.to_bitmask() << lanes.start;
            tied |= hit.tied.to_bitmask() << lanes.start;
            t_new[lanes.clone()].copy_from_slice(&hit.nearer.select(hit.t, t_old).to_array());
            t_hit[lanes].copy_from_slice(&hit.t.to_array());
        }
        take_ties(
            disc.sphere,
            (tied, |lane| t_hit[lane]),
            sphere_px,
            (&mut taken, &mut t_new),
        );
        t_px.copy_from_slice(&t_new);
        let sphere = u32x4::splat(disc.sphere);
        for (group, sphere_px) in sphere_px.chunks_exact_mut(LANES).enumerate() {
            let take = u32x4::new(LANE_MASKS[(taken >> (group * LANES) & 0b1111) as usize]);
            let old = u32x4::new([sphere_px[0], sphere_px[1], sphere_px[2], sphere_px[3]]);
            sphere_px.copy_from_slice(&(old ^ ((old ^ sphere) & take)).to_array());
        }
        took |= TilePixels::from(taken) << (row * TILE_COLUMNS);
    }
    let rows = (last_row + 1).saturating_sub(first_row) as u64;
    (rows * TILE_COLUMNS as u64, took)
}

/// Draws one disc on `rows` of the band over columns `first..=last` of the tile whose first
/// column is `tile_column`, in groups of [`LANES`] aligned on the row. Returns the tests made and
/// the pixels it took.
#[inline]
fn draw_disc(
    placed: &Placed,
    (first_row, last_row): (usize, usize),
    (first, last): (usize, usize),
    tile_column: usize,
    pixels: &mut BandPixels,
) -> (u64, TilePixels) {
    let disc = &placed.disc;
    let width = pixels.width;
    let front_t = f64x4::splat(placed.front_t);
    let centre_u = f64x4::splat(disc.u);
    let whole_groups_end = width / LANES * LANES;
    let mut tests = 0;
    let mut took: TilePixels = 0;
    for row in first_row..=last_row {
        let dv = pixels.v_of_row[row] - disc.v;
        let dv_sq_scalar = dv * dv;
        let dv_sq = f64x4::splat(dv_sq_scalar);
        let t_row = &mut pixels.t[row * width..(row + 1) * width];
        let sphere_row = &mut pixels.sphere[row * width..(row + 1) * width];
        // Whole groups from the span's first to its last, then what lies beyond the row's whole
        // groups one pixel at a time.
        let start = first / LANES * LANES;
        let end = ((last / LANES + 1) * LANES).min(whole_groups_end);
        let mut bit = row * TILE_COLUMNS + start - tile_column;
        if start < end {
            let groups = t_row[start..end]
                .chunks_exact_mut(LANES)
                .zip(sphere_row[start..end].chunks_exact_mut(LANES))
                .zip(pixels.u_of_column[start..end].chunks_exact(LANES));
            for ((t_px, sphere_px), u) in groups {
                let group_bit = bit;
                bit += LANES;
                let t_old = f64x4::new([t_px[0], t_px[1], t_px[2], t_px[3]]);
                // Pixels already nearer than the disc can come are final for it.
                let open = t_old.simd_ge(front_t);
                if !open.any() {
                    continue;
                }
                tests += LANES as u64;
                let du = f64x4::new([u[0], u[1], u[2], u[3]]) - centre_u;
                let hit = test(disc, du * du, dv_sq, t_old);
                if !(hit.inside & open).any() {
                    continue;
                }
                // A pixel already nearer than the disc can come is not open: its t is below
                // the disc's, so neither nearer nor tied holds there.
                let mut taken = hit.nearer.to_bitmask();
                let mut t_new = hit.nearer.select(hit.t, t_old).to_array();
                // The lanes' t read only for a tie (rare), not for every group.
                take_ties(
                    disc.sphere,
                    (hit.tied.to_bitmask(), |lane| hit.t.to_array()[lane]),
                    sphere_px,
                    (&mut taken, &mut t_new),
                );
                if taken == 0 {
                    continue;
                }
                took |= TilePixels::from(taken) << group_bit;
                t_px.copy_from_slice(&t_new);
                for (lane, sphere) in sphere_px.iter_mut().enumerate() {
                    *sphere = if taken >> lane & 1 == 1 {
                        disc.sphere
                    } else {
                        *sphere
                    };
                }
            }
        }
        for column in first.max(whole_groups_end)..=last {
            tests += 1;
            let du = pixels.u_of_column[column] - disc.u;
            let (t_px, sphere_px) = (&mut t_row[column], &mut sphere_row[column]);
            let (takes, t) = takes_pixel(disc, (du * du, dv_sq_scalar), (*t_px, *sphere_px));
            if takes {
                *t_px = t;
                *sphere_px = disc.sphere;
                took |= 1 << (row * TILE_COLUMNS + column - tile_column);
            }
        }
    }
    (tests, took)
}

#[cfg(test)]
#[path = "tiles_tests.rs"]
mod tests;
