//! The supersampler: bands of rows in parallel; each band evaluates every sample of its rows and
//! of a halo of rows around them (as far as the filter reaches), testing a sample only against
//! the discs of its 16-column tile, then filters its own rows' pixels from those samples.

use glam::Vec3;
use rayon::prelude::*;

use super::{Filter, Sampling};
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

/// Columns per tile: within a band, samples are tested only against the discs of their tile.
const TILE_COLUMNS: usize = 16;

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
}

/// The halo rows (top first) the filter reads around a band's own rows.
#[derive(Clone, Copy)]
struct BandRows {
    halo_first: usize,
    halo_last: usize,
}

/// Every sample of a band's halo rows: `per_pixel` samples for each pixel, row-major from
/// `rows.halo_first`.
struct BandSamples {
    samples: Vec<Sample>,
    per_pixel: usize,
    width: usize,
    halo_first: usize,
}

impl BandSamples {
    fn of_pixel(&self, row: usize, x: usize) -> &[Sample] {
        let start = ((row - self.halo_first) * self.width + x) * self.per_pixel;
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

/// The discs whose rows touch `rows` (halo included, widened by a pixel), in file order.
fn discs_near_rows(discs: &[Disc], grid: &PixelGrid, rows: BandRows) -> Vec<Disc> {
    let height = grid.height_px as usize;
    let v_of = |row: usize| grid.v_of_row((height - 1 - row) as f64);
    let v_high = v_of(rows.halo_first) + grid.pixel_size_world;
    let v_low = v_of(rows.halo_last) - grid.pixel_size_world;
    discs
        .iter()
        .filter(|d| {
            let r = d.radius_sq.sqrt();
            d.v + r >= v_low && d.v - r <= v_high
        })
        .copied()
        .collect()
}

/// Evaluates every sample of the band's halo rows; returns them and the sample–disc tests made.
fn evaluate_samples(
    shared: &Shared<'_>,
    tiles: &[Vec<Disc>],
    rows: BandRows,
) -> (BandSamples, u64) {
    let grid = shared.grid;
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let per_pixel = shared.sampling.samples as usize;
    let mut samples =
        Vec::with_capacity((rows.halo_last - rows.halo_first + 1) * width * per_pixel);
    let mut tests = 0u64;
    for row in rows.halo_first..=rows.halo_last {
        let y_up = (height - 1 - row) as u32;
        for x in 0..width as u32 {
            let tile = &tiles[x as usize / TILE_COLUMNS];
            for (ox, oy) in shared.sampling.offsets(x, y_up) {
                let (px, py) = (x as f32 + ox, y_up as f32 + oy);
                let (u, v) = grid.screen_of_pixel_point(f64::from(px), f64::from(py));
                tests += tile.len() as u64;
                let (colour, grey) = match nearest_hit(tile, u, v) {
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
                samples.push(Sample {
                    x: px,
                    y: py,
                    colour,
                    grey,
                });
            }
        }
    }
    let band = BandSamples {
        samples,
        per_pixel,
        width,
        halo_first: rows.halo_first,
    };
    (band, tests)
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
    band: &BandSamples,
    rows: BandRows,
    halo: usize,
    row: usize,
    x: usize,
    y_up: f32,
) -> (Vec3, f32) {
    let (cx, cy) = (x as f32 + 0.5, y_up + 0.5);
    let mut sums = PixelSums {
        colour: Vec3::ZERO,
        grey: 0.0,
        weight: 0.0,
        first: None,
        uniform: true,
    };
    let rows_near =
        row.saturating_sub(halo).max(rows.halo_first)..=(row + halo).min(rows.halo_last);
    let columns_near = x.saturating_sub(halo)..=(x + halo).min(band.width - 1);
    for near_row in rows_near {
        for near_x in columns_near.clone() {
            for sample in band.of_pixel(near_row, near_x) {
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
            let own = band.of_pixel(row, x);
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

/// One band: its pixels' 8-bit colours and filtered greys, and the tests made.
fn supersample_band(
    shared: &Shared<'_>,
    discs: &[Disc],
    band: usize,
) -> (Vec<[u8; 3]>, Vec<f32>, u64) {
    let grid = shared.grid;
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let first = band * SAMPLE_BAND_ROWS;
    let last = (first + SAMPLE_BAND_ROWS).min(height) - 1;
    let rows = BandRows {
        halo_first: first.saturating_sub(shared.halo),
        halo_last: (last + shared.halo).min(height - 1),
    };
    let tiles = column_tiles(&discs_near_rows(discs, grid, rows), grid);
    let (samples, tests) = evaluate_samples(shared, &tiles, rows);
    let mut colour = Vec::with_capacity((last - first + 1) * width);
    let mut depth_grey = Vec::with_capacity(colour.capacity());
    for row in first..=last {
        let y_up = (height - 1 - row) as f32;
        for x in 0..width {
            let filter = shared.sampling.filter;
            let (pixel_colour, grey) =
                filter_pixel(filter, &samples, rows, shared.halo, row, x, y_up);
            colour.push(pixel_colour.to_array().map(quantize_f32));
            depth_grey.push(grey);
        }
    }
    (colour, depth_grey, tests)
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
        halo: sampling.filter.support().ceil() as usize,
    };
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let band_count = height.div_ceil(SAMPLE_BAND_ROWS);
    let bands_done = std::sync::atomic::AtomicUsize::new(0);
    let bands: Vec<(Vec<[u8; 3]>, Vec<f32>, u64)> = (0..band_count)
        .into_par_iter()
        .map(|band| {
            let result = supersample_band(&shared, discs, band);
            let done = bands_done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(done as f64 / band_count as f64);
            result
        })
        .collect();
    let mut result = Supersampled {
        colour: Vec::with_capacity(width * height),
        depth_grey: Vec::with_capacity(width * height),
        disc_tests: 0,
    };
    for (colour, grey, tests) in bands {
        result.colour.extend(colour);
        result.depth_grey.extend(grey);
        result.disc_tests += tests;
    }
    result
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
