//! The supersampler: bands of rows in parallel, each band in tiles of columns. A tile evaluates
//! every sample of its pixels and of a halo around them (as far as the filter reaches), testing
//! a sample only against the discs of its 16-column strip, then filters its own pixels from those
//! samples straight into the frame. The tile's width is chosen so that its samples fit
//! [`TILE_BUDGET_BYTES`]: the working memory is bounded by the thread count, whatever the image
//! width, sample count and filter size ([`working_bytes`]).

use glam::Vec3;
use rayon::prelude::*;

use super::settings::{Filter, Sampling};
use crate::geometry::camera::PixelGrid;
use crate::render::depth_map::{DepthRange, quantize_f32};
use crate::render::disc::{Disc, nearest_hit, pixel_span};
use crate::scene::Scene;

/// One evaluated sample: its position from the image's bottom-left corner (pixels), colour and
/// depth grey.
#[derive(Debug, Clone, Copy)]
struct Sample {
    x: f32,
    y: f32,
    colour: Vec3,
    grey: f32,
}

/// Result of supersampling a frame.
pub(crate) struct Supersampled {
    /// 8-bit colour per pixel, top row first.
    pub(crate) colour: Vec<[u8; 3]>,
    /// Filtered depth grey in [0, 1] per pixel, top row first.
    pub(crate) depth_grey: Vec<f32>,
    /// Sample–disc tests performed.
    pub(crate) disc_tests: u64,
}

/// Rows per band when supersampling.
const SAMPLE_BAND_ROWS: usize = 16;

/// Columns per disc strip: within a band, samples are tested only against the discs of their
/// strip.
const TILE_COLUMNS: usize = 16;

/// The samples one tile may hold at once (the tile is narrower when samples are many).
pub(crate) const TILE_BUDGET_BYTES: usize = 32 << 20;

/// The halo around a tile: how many pixels the filter reaches beyond a pixel.
fn halo_of(sampling: &Sampling) -> usize {
    sampling.filter.support().ceil() as usize
}

/// Columns of pixels per tile: as many as fit [`TILE_BUDGET_BYTES`] with their halo, at least
/// [`TILE_COLUMNS`].
fn tile_columns(sampling: &Sampling) -> usize {
    let halo = halo_of(sampling);
    let per_column =
        (SAMPLE_BAND_ROWS + 2 * halo) * sampling.samples as usize * size_of::<Sample>();
    (TILE_BUDGET_BYTES / per_column.max(1))
        .saturating_sub(2 * halo)
        .max(TILE_COLUMNS)
}

/// The bytes one tile's samples take at most.
fn tile_bytes(sampling: &Sampling) -> usize {
    let halo = halo_of(sampling);
    (SAMPLE_BAND_ROWS + 2 * halo)
        * (tile_columns(sampling) + 2 * halo)
        * sampling.samples as usize
        * size_of::<Sample>()
}

/// The supersampler's working memory at most, besides the frame: one tile's samples for each
/// thread that can run a band at once.
pub(crate) fn working_bytes(sampling: &Sampling, threads: usize) -> usize {
    threads.max(1) * tile_bytes(sampling)
}

/// What every band shares: the grid, the settings and the colours of the spheres.
struct Shared<'a> {
    scene: &'a Scene,
    grid: &'a PixelGrid,
    depth_range: DepthRange,
    sampling: &'a Sampling,
    /// Colour per sphere (file order).
    palette: Vec<Vec3>,
    /// How many pixels the filter reaches beyond a pixel.
    halo: usize,
    /// Columns of pixels per tile.
    tile_columns: usize,
}

/// The pixels a tile's samples cover: its own and the halo the filter reads around them (rows
/// top first, both ends included).
#[derive(Clone, Copy)]
struct Tile {
    first_row: usize,
    last_row: usize,
    first_column: usize,
    last_column: usize,
}

/// Every sample of a tile: `per_pixel` samples for each pixel, row-major.
struct TileSamples {
    samples: Vec<Sample>,
    per_pixel: usize,
    tile: Tile,
}

impl TileSamples {
    fn width(&self) -> usize {
        self.tile.last_column - self.tile.first_column + 1
    }

    fn of_pixel(&self, row: usize, x: usize) -> &[Sample] {
        let index = (row - self.tile.first_row) * self.width() + (x - self.tile.first_column);
        let start = index * self.per_pixel;
        &self.samples[start..start + self.per_pixel]
    }
}

/// `discs` listed per tile of [`TILE_COLUMNS`] columns (in file order, so ties keep the first
/// sphere): each disc goes to the tiles its screen u extent (widened by a pixel, as samples lie
/// anywhere in their pixel) overlaps.
fn column_tiles(discs: &[Disc], grid: &PixelGrid) -> Vec<Vec<Disc>> {
    let width = grid.width_px as usize;
    let tile_count = width.div_ceil(TILE_COLUMNS).max(1);
    let mut tiles = vec![Vec::new(); tile_count];
    // Column x spans u in [u_of(x) − ½·s, u_of(x) + ½·s]: x = u / s + width/2 − ½.
    let column_of = |u: f64| u / grid.pixel_size_world + 0.5 * f64::from(grid.width_px) - 0.5;
    for disc in discs {
        let radius = disc.radius_sq.sqrt();
        let Some((first, last)) = pixel_span(
            column_of(disc.u - radius),
            column_of(disc.u + radius),
            width.max(1) - 1,
        ) else {
            continue; // off the image, or NaN
        };
        for tile in &mut tiles[first / TILE_COLUMNS..=last / TILE_COLUMNS] {
            tile.push(*disc);
        }
    }
    tiles
}

/// The discs whose rows touch the rows of `tile` (widened by a pixel), in file order.
fn discs_near_rows(discs: &[Disc], grid: &PixelGrid, tile: Tile) -> Vec<Disc> {
    let height = grid.height_px as usize;
    let v_of = |row: usize| grid.v_of_row((height - 1 - row) as f64);
    let v_high = v_of(tile.first_row) + grid.pixel_size_world;
    let v_low = v_of(tile.last_row) - grid.pixel_size_world;
    discs
        .iter()
        .filter(|d| {
            let r = d.radius_sq.sqrt();
            d.v + r >= v_low && d.v - r <= v_high
        })
        .copied()
        .collect()
}

/// Evaluates every sample of `tile` into `samples` (reused between tiles); returns the
/// sample–disc tests made.
fn evaluate_samples(shared: &Shared<'_>, strips: &[Vec<Disc>], samples: &mut TileSamples) -> u64 {
    let grid = shared.grid;
    let height = grid.height_px as usize;
    let tile = samples.tile;
    samples.samples.clear();
    // Exactly the tile's samples: growing by doubling would overshoot the budget.
    let count = (tile.last_row - tile.first_row + 1)
        * (tile.last_column - tile.first_column + 1)
        * samples.per_pixel;
    samples.samples.reserve_exact(count);
    let mut tests = 0u64;
    for row in tile.first_row..=tile.last_row {
        let y_up = (height - 1 - row) as u32;
        for x in tile.first_column as u32..=tile.last_column as u32 {
            let strip = &strips[x as usize / TILE_COLUMNS];
            for (ox, oy) in shared.sampling.offsets(x, y_up) {
                let (px, py) = (x as f32 + ox, y_up as f32 + oy);
                let (u, v) = grid.screen_of_pixel_point(f64::from(px), f64::from(py));
                tests += strip.len() as u64;
                let (colour, grey) = match nearest_hit(strip, u, v) {
                    Some((t, sphere)) => (
                        shared
                            .palette
                            .get(sphere as usize)
                            .copied()
                            .unwrap_or(shared.scene.background),
                        shared.depth_range.grey(t) as f32,
                    ),
                    None => (shared.scene.background, 0.0),
                };
                samples.samples.push(Sample {
                    x: px,
                    y: py,
                    colour,
                    grey,
                });
            }
        }
    }
    tests
}

/// Sums of one pixel's weighted samples.
struct PixelSums {
    colour: Vec3,
    grey: f32,
    weight: f32,
    /// The first weighted sample, and whether every weighted sample equals it.
    first: Option<(Vec3, f32)>,
    uniform: bool,
}

/// The filtered colour and depth grey of pixel (x, row).
fn filter_pixel(
    filter: Filter,
    samples: &TileSamples,
    halo: usize,
    row: usize,
    x: usize,
    y_up: f32,
) -> (Vec3, f32) {
    let tile = samples.tile;
    let (cx, cy) = (x as f32 + 0.5, y_up + 0.5);
    let mut sums = PixelSums {
        colour: Vec3::ZERO,
        grey: 0.0,
        weight: 0.0,
        first: None,
        uniform: true,
    };
    let rows_near = row.saturating_sub(halo).max(tile.first_row)..=(row + halo).min(tile.last_row);
    let columns_near =
        x.saturating_sub(halo).max(tile.first_column)..=(x + halo).min(tile.last_column);
    for near_row in rows_near {
        for near_x in columns_near.clone() {
            for sample in samples.of_pixel(near_row, near_x) {
                let weight = filter.weight(sample.x - cx, sample.y - cy);
                if weight > 0.0 {
                    add_sample(&mut sums, sample, weight);
                }
            }
        }
    }
    match sums.first {
        // Every contributing sample agrees: exactly that value (no rounding drift).
        Some(value) if sums.uniform => value,
        Some(_) => (sums.colour / sums.weight, sums.grey / sums.weight),
        // No sample has weight (a filter smaller than the sample spacing): the mean of the
        // pixel's own samples.
        None => {
            let own = samples.of_pixel(row, x);
            let n = own.len().max(1) as f32;
            (
                own.iter().map(|s| s.colour).sum::<Vec3>() / n,
                own.iter().map(|s| s.grey).sum::<f32>() / n,
            )
        }
    }
}

fn add_sample(sums: &mut PixelSums, sample: &Sample, weight: f32) {
    match sums.first {
        None => sums.first = Some((sample.colour, sample.grey)),
        Some((colour, grey)) => {
            sums.uniform &= colour == sample.colour && grey == sample.grey;
        }
    }
    sums.colour += weight * sample.colour;
    sums.grey += weight * sample.grey;
    sums.weight += weight;
}

/// One band, tile by tile: its pixels' 8-bit colours and filtered greys into `colour` and
/// `grey` (the band's rows of the frame); returns the tests made.
fn supersample_band(
    shared: &Shared<'_>,
    discs: &[Disc],
    band: usize,
    colour: &mut [[u8; 3]],
    grey: &mut [f32],
) -> u64 {
    let grid = shared.grid;
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let first_row = band * SAMPLE_BAND_ROWS;
    let last_row = (first_row + SAMPLE_BAND_ROWS).min(height) - 1;
    let halo = shared.halo;
    let rows = Tile {
        first_row: first_row.saturating_sub(halo),
        last_row: (last_row + halo).min(height - 1),
        first_column: 0,
        last_column: width - 1,
    };
    let strips = column_tiles(&discs_near_rows(discs, grid, rows), grid);
    let mut samples = TileSamples {
        samples: Vec::new(),
        per_pixel: shared.sampling.samples as usize,
        tile: rows,
    };
    let mut tests = 0u64;
    for first_column in (0..width).step_by(shared.tile_columns) {
        let last_column = (first_column + shared.tile_columns).min(width) - 1;
        samples.tile = Tile {
            first_column: first_column.saturating_sub(halo),
            last_column: (last_column + halo).min(width - 1),
            ..rows
        };
        tests += evaluate_samples(shared, &strips, &mut samples);
        for row in first_row..=last_row {
            let y_up = (height - 1 - row) as f32;
            for x in first_column..=last_column {
                let filter = shared.sampling.filter;
                let (pixel_colour, pixel_grey) = filter_pixel(filter, &samples, halo, row, x, y_up);
                let index = (row - first_row) * width + x;
                colour[index] = pixel_colour.to_array().map(quantize_f32);
                grey[index] = pixel_grey;
            }
        }
    }
    tests
}

/// Supersamples `scene` on `grid` (see the module docs). `discs` are the frame's projected discs.
pub(crate) fn supersample(
    scene: &Scene,
    discs: &[Disc],
    grid: &PixelGrid,
    depth_range: DepthRange,
    sampling: &Sampling,
    progress: &(dyn Fn(f64) + Sync),
) -> Supersampled {
    let shared = Shared {
        scene,
        grid,
        depth_range,
        sampling,
        palette: scene
            .spheres
            .iter()
            .map(|s| scene.sphere_colour(s))
            .collect(),
        halo: halo_of(sampling),
        tile_columns: tile_columns(sampling),
    };
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let band_count = height.div_ceil(SAMPLE_BAND_ROWS);
    let bands_done = std::sync::atomic::AtomicUsize::new(0);
    let mut colour = vec![[0u8; 3]; width * height];
    let mut depth_grey = vec![0f32; width * height];
    let disc_tests = colour
        .par_chunks_mut(width * SAMPLE_BAND_ROWS)
        .zip(depth_grey.par_chunks_mut(width * SAMPLE_BAND_ROWS))
        .enumerate()
        .map(|(band, (colour, grey))| {
            let tests = supersample_band(&shared, discs, band, colour, grey);
            let done = bands_done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(done as f64 / band_count as f64);
            tests
        })
        .sum();
    Supersampled {
        colour,
        depth_grey,
        disc_tests,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::rng::SplitMix64;

    #[test]
    fn column_tiles_hold_every_disc_a_sample_can_hit_in_file_order() {
        let grid = PixelGrid::new(100, 60, 5.0);
        let mut rng = SplitMix64::new(3);
        let discs: Vec<Disc> = (0..400)
            .map(|sphere| {
                let radius = rng.log_uniform(1e-3, 2.0);
                Disc {
                    u: rng.uniform(-3.5, 3.5),
                    v: 0.0,
                    w: 0.0,
                    radius_sq: radius * radius,
                    sphere,
                }
            })
            .collect();
        let tiles = column_tiles(&discs, &grid);
        let half_pixel = 0.5 * grid.pixel_size_world;
        for x in 0..grid.width_px {
            let centre = grid.u_of_column(f64::from(x));
            let tile = &tiles[x as usize / TILE_COLUMNS];
            for disc in &discs {
                let radius = disc.radius_sq.sqrt();
                // Some point of the pixel's column lies within the disc's u extent.
                let reachable = disc.u + radius >= centre - half_pixel
                    && disc.u - radius <= centre + half_pixel;
                if reachable {
                    assert!(tile.contains(disc), "column {x}: disc {}", disc.sphere);
                }
            }
            assert!(tile.windows(2).all(|pair| pair[0].sphere < pair[1].sphere));
        }
    }
}
