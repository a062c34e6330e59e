//! A frame-wide, coarse depth test: once the nearest discs are drawn, the farthest t in each
//! square tile of pixels bounds what a disc behind can still change, so discs hidden everywhere
//! they could reach are culled before they are binned (hierarchical z over the frame in two
//! levels, tiles and blocks of tiles, beside the per-tile stop of the tile rasteriser).

use rayon::prelude::*;

use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

/// The larger of `far` and `t` (NaN: `far`).
#[inline]
fn farther(far: f64, t: f64) -> f64 {
    if t > far { t } else { far }
}

/// Below this many pixels from the image's centre, a disc's extent is known to the pixel.
const EXACT_PX: f64 = (1u64 << 40) as f64;

/// Pixels per side of a tile.
const TILE_PX: usize = 8;

/// Tiles per side of a block.
const BLOCK_TILES: usize = 8;

/// Cells across the longer side of the image: discs are grouped by the cell of their centre, and
/// a group wholly behind what is drawn around its cell is dropped without a look at its discs.
const CELLS: usize = 16;

/// Where a disc's centre lies in pixel coordinates: column from the left, row from the top, with
/// pixel centres at whole numbers.
#[derive(Clone, Copy)]
struct PixelCoordinates {
    /// Column coordinate of screen u = 0: `width/2 − ½`.
    centre_column: f64,
    /// Row coordinate of screen v = 0: `height/2 − ½`.
    centre_row: f64,
    inverse_pixel: f64,
}

impl PixelCoordinates {
    fn of(grid: &PixelGrid) -> Self {
        Self {
            centre_column: 0.5 * f64::from(grid.width_px) - 0.5,
            centre_row: 0.5 * f64::from(grid.height_px) - 0.5,
            inverse_pixel: 1.0 / grid.pixel_size_world,
        }
    }

    /// (column, row) of `disc`'s centre; rows count from the top, screen v grows upwards.
    #[inline]
    fn of_disc(&self, disc: &Disc) -> (f64, f64) {
        (
            disc.u * self.inverse_pixel + self.centre_column,
            self.centre_row - disc.v * self.inverse_pixel,
        )
    }
}

/// Square cells of the screen that group discs by their centre.
#[derive(Clone, Copy)]
pub(super) struct Cells {
    /// Pixels per side, a whole number of tiles.
    pub(super) px: usize,
    pub(super) across: usize,
    pub(super) down: usize,
    pixels: PixelCoordinates,
    /// The largest r² for which a disc centred in a cell reaches no further than the cells
    /// around it (its radius and a pixel of margin within a cell's side).
    pub(super) reaching_neighbours_radius_sq: f64,
}

impl Cells {
    pub(super) fn of(grid: &PixelGrid) -> Self {
        let (width, height) = (grid.width_px as usize, grid.height_px as usize);
        let px = width.max(height).div_ceil(CELLS).next_multiple_of(TILE_PX);
        let reach_world = (px as f64 - 1.0) * grid.pixel_size_world;
        Self {
            px,
            across: width.div_ceil(px),
            down: height.div_ceil(px),
            pixels: PixelCoordinates::of(grid),
            reaching_neighbours_radius_sq: reach_world * reach_world,
        }
    }

    /// The cell of `disc`'s centre, clamped to the image's cells (NaN: the first).
    pub(super) fn of_disc(&self, disc: &Disc) -> usize {
        let (column, row) = self.pixels.of_disc(disc);
        let side = self.px as f64;
        let cell = |at: f64, count: usize| {
            let cell = if at > 0.0 { (at / side) as usize } else { 0 };
            cell.min(count - 1)
        };
        cell(row, self.down) * self.across + cell(column, self.across)
    }
}

/// The farthest t per tile of [`TILE_PX`]² pixels and per block of [`BLOCK_TILES`]² tiles (+∞
/// where a pixel is still uncovered).
pub(super) struct CoarseDepth {
    tiles_across: usize,
    tiles_down: usize,
    tile_farthest_t: Vec<f64>,
    blocks_across: usize,
    block_farthest_t: Vec<f64>,
    pixels: PixelCoordinates,
}

impl CoarseDepth {
    /// The tiles and blocks of `t` (row-major, top row first) on `grid`.
    pub(super) fn of(t: &[f64], grid: &PixelGrid) -> Self {
        let width = grid.width_px as usize;
        let tiles_across = width.div_ceil(TILE_PX);
        let tiles_down = (grid.height_px as usize).div_ceil(TILE_PX);
        let tile_farthest_t: Vec<f64> = t
            .par_chunks(width * TILE_PX)
            .flat_map_iter(|rows| {
                let mut farthest = vec![f64::NEG_INFINITY; tiles_across];
                for row in rows.chunks(width) {
                    for (tile, pixels) in farthest.iter_mut().zip(row.chunks(TILE_PX)) {
                        *tile = pixels.iter().copied().fold(*tile, farther);
                    }
                }
                farthest
            })
            .collect();
        let blocks_across = tiles_across.div_ceil(BLOCK_TILES);
        let mut block_farthest_t =
            vec![f64::NEG_INFINITY; blocks_across * tiles_down.div_ceil(BLOCK_TILES)];
        for (tile_row, tiles) in tile_farthest_t.chunks(tiles_across).enumerate() {
            let blocks = &mut block_farthest_t[tile_row / BLOCK_TILES * blocks_across..];
            for (block, tiles) in blocks.iter_mut().zip(tiles.chunks(BLOCK_TILES)) {
                *block = tiles.iter().copied().fold(*block, farther);
            }
        }
        Self {
            tiles_across,
            tiles_down,
            tile_farthest_t,
            blocks_across,
            block_farthest_t,
            pixels: PixelCoordinates::of(grid),
        }
    }

    /// Per cell of `cells`: the farthest t over the cell and the cells around it (what a disc
    /// centred in the cell, no larger than a cell, can reach).
    pub(super) fn farthest_around_cells(&self, cells: &Cells) -> Vec<f64> {
        let tiles_per_cell = cells.px / TILE_PX;
        let mut farthest = vec![f64::NEG_INFINITY; cells.across * cells.down];
        for (tile_row, tiles) in self.tile_farthest_t.chunks(self.tiles_across).enumerate() {
            let cell_row =
                &mut farthest[tile_row / tiles_per_cell * cells.across..][..cells.across];
            for (cell, tiles) in cell_row.iter_mut().zip(tiles.chunks(tiles_per_cell)) {
                *cell = tiles.iter().copied().fold(*cell, farther);
            }
        }
        let at = |row: usize, column: usize| farthest[row * cells.across + column];
        let mut around = vec![f64::NEG_INFINITY; farthest.len()];
        for row in 0..cells.down {
            for column in 0..cells.across {
                let rows = row.saturating_sub(1)..=(row + 1).min(cells.down - 1);
                let columns = column.saturating_sub(1)..=(column + 1).min(cells.across - 1);
                around[row * cells.across + column] = rows
                    .flat_map(|r| columns.clone().map(move |c| (r, c)))
                    .map(|(r, c)| at(r, c))
                    .fold(f64::NEG_INFINITY, farther);
            }
        }
        around
    }

    /// Whether `disc` may be as near as a pixel it can reach: false only when its nearest t lies
    /// beyond the farthest t of every tile its pixel extent (widened by a pixel each side)
    /// touches, since then its t at every pixel is too. Off the image: false.
    pub(super) fn may_show(&self, disc: &Disc) -> bool {
        let front = disc.front_t();
        let radius_px = disc.radius_sq.sqrt() * self.pixels.inverse_pixel + 1.0;
        let (column, row) = self.pixels.of_disc(disc);
        // Beyond 2⁴⁰ pixels the pixel of margin drowns in the rounding of these sums: kept
        // (binning drops what misses the image).
        if !(radius_px < EXACT_PX && column.abs() < EXACT_PX && row.abs() < EXACT_PX) {
            return true;
        }
        let (Some(columns), Some(rows)) = (
            tile_span(column - radius_px, column + radius_px, self.tiles_across),
            tile_span(row - radius_px, row + radius_px, self.tiles_down),
        ) else {
            return false;
        };
        let block_columns = columns.0 / BLOCK_TILES..=columns.1 / BLOCK_TILES;
        let mut blocks = (rows.0 / BLOCK_TILES..=rows.1 / BLOCK_TILES).flat_map(|block_row| {
            self.block_farthest_t[block_row * self.blocks_across..][block_columns.clone()].iter()
        });
        if blocks.all(|&farthest| front > farthest) {
            return false;
        }
        (rows.0..=rows.1).any(|tile_row| {
            let tiles = &self.tile_farthest_t[tile_row * self.tiles_across..];
            tiles[columns.0..=columns.1]
                .iter()
                .any(|&farthest| front <= farthest)
        })
    }
}

/// The tiles `[first, last]` (of `tiles`) holding pixel coordinates `[low, high]`, whole pixels
/// rounded outwards; `None` when none does or on NaN.
#[inline]
fn tile_span(low: f64, high: f64, tiles: usize) -> Option<(usize, usize)> {
    let end = (tiles * TILE_PX) as f64;
    // NaN fails both tests.
    if !(high >= -1.0 && low < end) {
        return None;
    }
    // Pixel centres at whole coordinates: pixels `ceil(low)..=floor(high)`, widened to whole
    // tiles; truncation (below `end`) stands in for floor.
    let first = if low >= 0.0 { low as usize } else { 0 };
    let last = if high < end {
        high as usize + 1
    } else {
        tiles * TILE_PX - 1
    };
    Some((first / TILE_PX, (last / TILE_PX).min(tiles - 1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tile_spans_hold_every_pixel_in_the_range() {
        let mut rng = crate::render::rng::SplitMix64::new(9);
        let tiles = 13;
        let pixels = tiles * TILE_PX;
        for _ in 0..100_000 {
            let centre = rng.uniform(-20.0, pixels as f64 + 20.0);
            let half = rng.log_uniform(1e-3, 60.0);
            let (low, high) = (centre - half, centre + half);
            let inside: Vec<usize> = (0..pixels)
                .filter(|&k| low <= k as f64 && k as f64 <= high)
                .collect();
            match tile_span(low, high, tiles) {
                Some((first, last)) => {
                    assert!(first <= last && last < tiles);
                    for k in inside {
                        assert!((first..=last).contains(&(k / TILE_PX)), "{low} {high} {k}");
                    }
                }
                None => assert!(inside.is_empty(), "{low} {high}"),
            }
        }
        assert_eq!(tile_span(f64::NAN, 3.0, tiles), None);
    }
}
