//! Supersampling with the course's samplers and reconstruction filters (6.837 assignment 7):
//! `uniform` (an n×n grid), `random` and `jittered` (one random point in each cell of an n×n grid)
//! sample positions, and `box`, `tent` and `gaussian` filters whose radius (sigma) is in pixels.
//!
//! A pixel's colour is the filter-weighted mean of every sample within the filter's support —
//! its own and its neighbours' — normalised so the weights sum to 1. Where every contributing
//! sample shows the same colour, the pixel gets exactly that colour (interior pixels equal the
//! one-sample render). The depth image filters the **grey values** of the samples (a grey edge is
//! the mean of the greys, as the course's depth images are); the frame's raw t stays one centre
//! sample per pixel, so t, the pixel probe and lossless depth export are never blurred.
//!
//! Sample positions are seeded from (seed, pixel), so a render is the same whatever the thread
//! count, and the same flags give the same bytes.

use std::fmt;

use glam::Vec3;
use rayon::prelude::*;

use super::disc::{Disc, nearest_hit, pixel_span};
use crate::geometry::camera::PixelGrid;
use crate::render::depth_map::{DepthRange, quantize_f32};
use crate::render::rng::SplitMix64;
use crate::scene::Scene;

/// How sample positions are placed in a pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum Sampler {
    /// An n×n grid of cell centres (n² samples).
    Uniform,
    /// Independent uniformly random points.
    Random,
    /// One random point in each cell of an n×n grid (n² samples).
    Jittered,
}

impl Sampler {
    /// Every sampler, in the order menus list them.
    pub const ALL: [Sampler; 3] = [Sampler::Uniform, Sampler::Jittered, Sampler::Random];

    /// The course's name, as in `-<name>_samples`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Uniform => "uniform",
            Self::Random => "random",
            Self::Jittered => "jittered",
        }
    }

    /// Whether the sample count must be a perfect square.
    pub fn needs_square(self) -> bool {
        !matches!(self, Self::Random)
    }
}

/// A reconstruction filter; sizes in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum Filter {
    /// Weight 1 within `radius` along both axes.
    Box {
        /// Half-width, pixels.
        radius: f32,
    },
    /// Weight `1 − d/radius` within `radius` (d: distance from the pixel centre).
    Tent {
        /// Radius, pixels.
        radius: f32,
    },
    /// Weight `exp(−d² / 2σ²)` within 2σ.
    Gaussian {
        /// Standard deviation, pixels.
        sigma: f32,
    },
}

impl Filter {
    /// The default when samples are asked for without a filter: a box over the pixel itself.
    pub const PIXEL_BOX: Filter = Filter::Box { radius: 0.5 };

    /// The course's name, as in `-<name>_filter`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Box { .. } => "box",
            Self::Tent { .. } => "tent",
            Self::Gaussian { .. } => "gaussian",
        }
    }

    /// The size parameter (radius or sigma), pixels.
    pub fn size(self) -> f32 {
        match self {
            Self::Box { radius } | Self::Tent { radius } => radius,
            Self::Gaussian { sigma } => sigma,
        }
    }

    /// The same kind of filter with another size.
    pub fn with_size(self, size: f32) -> Self {
        match self {
            Self::Box { .. } => Self::Box { radius: size },
            Self::Tent { .. } => Self::Tent { radius: size },
            Self::Gaussian { .. } => Self::Gaussian { sigma: size },
        }
    }

    /// How far from a pixel centre samples can have weight, pixels.
    pub fn support(self) -> f32 {
        match self {
            Self::Box { radius } => radius * std::f32::consts::SQRT_2,
            Self::Tent { radius } => radius,
            Self::Gaussian { sigma } => 2.0 * sigma,
        }
    }

    /// The (unnormalised) weight of a sample at offset (dx, dy) pixels from the pixel centre.
    pub fn weight(self, dx: f32, dy: f32) -> f32 {
        match self {
            Self::Box { radius } => {
                if dx.abs() <= radius && dy.abs() <= radius {
                    1.0
                } else {
                    0.0
                }
            }
            Self::Tent { radius } => (1.0 - (dx * dx + dy * dy).sqrt() / radius).max(0.0),
            Self::Gaussian { sigma } => {
                let d2 = dx * dx + dy * dy;
                if d2 <= 4.0 * sigma * sigma {
                    (-d2 / (2.0 * sigma * sigma)).exp()
                } else {
                    0.0
                }
            }
        }
    }
}

impl fmt::Display for Filter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.name(), self.size())
    }
}

/// Largest filter size accepted, pixels.
pub const MAX_FILTER_SIZE: f32 = 8.0;

/// Largest sample count per pixel accepted.
pub const MAX_SAMPLES: u32 = 1024;

/// Supersampling settings.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub struct Sampling {
    /// Where samples go in a pixel.
    pub sampler: Sampler,
    /// Samples per pixel (a perfect square for uniform and jittered).
    pub samples: u32,
    /// How samples are combined.
    pub filter: Filter,
    /// Seed of the random sample positions.
    pub seed: u64,
}

/// Why sampling settings are unusable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SamplingError {
    /// Zero or too many samples.
    #[error("samples per pixel must be 1..={MAX_SAMPLES}, found {0}")]
    SampleCount(u32),
    /// A grid sampler with a count that is not a square.
    #[error(
        "{sampler} sampling needs a perfect square number of samples (1, 4, 9, 16, …), found {samples}"
    )]
    NotSquare {
        /// The sampler's name.
        sampler: &'static str,
        /// The count given.
        samples: u32,
    },
    /// A filter size that is not a positive number up to [`MAX_FILTER_SIZE`].
    #[error("{filter} filter size must be in (0, {MAX_FILTER_SIZE}] pixels, found {size}")]
    FilterSize {
        /// The filter's name.
        filter: &'static str,
        /// The size given.
        size: f32,
    },
}

/// `n` if `count == n²`.
fn exact_square_root(count: u32) -> Option<u32> {
    let root = f64::from(count).sqrt().round() as u32;
    (root * root == count).then_some(root)
}

impl Sampling {
    /// Checks the settings.
    pub fn validate(&self) -> Result<(), SamplingError> {
        if !(1..=MAX_SAMPLES).contains(&self.samples) {
            return Err(SamplingError::SampleCount(self.samples));
        }
        if self.sampler.needs_square() && exact_square_root(self.samples).is_none() {
            return Err(SamplingError::NotSquare {
                sampler: self.sampler.name(),
                samples: self.samples,
            });
        }
        let size = self.filter.size();
        if !(size > 0.0 && size <= MAX_FILTER_SIZE) {
            return Err(SamplingError::FilterSize {
                filter: self.filter.name(),
                size,
            });
        }
        Ok(())
    }

    /// Sample offsets of pixel (x, y_up) within the pixel, each in [0, 1)² from its bottom-left.
    pub fn offsets(&self, x: u32, y_up: u32) -> Vec<(f32, f32)> {
        let mut rng = SplitMix64::new(
            self.seed
                ^ (u64::from(x)).wrapping_mul(0x9E37_79B9_7F4A_7C15)
                ^ (u64::from(y_up)).wrapping_mul(0xC2B2_AE3D_27D4_EB4F),
        );
        let mut unit = || rng.unit() as f32;
        let n = exact_square_root(self.samples).unwrap_or(1);
        let cell = 1.0 / n as f32;
        match self.sampler {
            Sampler::Uniform => (0..self.samples)
                .map(|i| {
                    (
                        (i % n) as f32 * cell + 0.5 * cell,
                        (i / n) as f32 * cell + 0.5 * cell,
                    )
                })
                .collect(),
            Sampler::Jittered => (0..self.samples)
                .map(|i| {
                    let (jx, jy) = (unit(), unit());
                    (
                        (i % n) as f32 * cell + jx * cell,
                        (i / n) as f32 * cell + jy * cell,
                    )
                })
                .collect(),
            Sampler::Random => (0..self.samples).map(|_| (unit(), unit())).collect(),
        }
    }
}

/// The normalised weights of `samples` (offsets in pixels from a pixel's centre) under `filter`:
/// they sum to 1, unless no sample has weight (then all are 0).
pub fn normalised_weights(filter: Filter, samples: &[(f32, f32)]) -> Vec<f32> {
    let weights: Vec<f32> = samples
        .iter()
        .map(|&(dx, dy)| filter.weight(dx, dy))
        .collect();
    let total: f32 = weights.iter().sum();
    if total > 0.0 {
        weights.iter().map(|w| w / total).collect()
    } else {
        weights
    }
}

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
    pub colour: Vec<[u8; 3]>,
    /// Filtered depth grey in [0, 1] per pixel, top row first.
    pub depth_grey: Vec<f32>,
    /// Sample–disc tests performed.
    pub disc_tests: u64,
}

/// Rows per band when supersampling.
const SAMPLE_BAND_ROWS: usize = 16;

/// Columns per tile: within a band, samples are tested only against the discs of their tile.
const TILE_COLUMNS: usize = 16;

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

/// Supersamples `scene` on `grid` (see the module docs). `discs` are the frame's projected discs.
pub(crate) fn supersample(
    scene: &Scene,
    discs: &[Disc],
    grid: &PixelGrid,
    depth_range: DepthRange,
    sampling: &Sampling,
    progress: &(dyn Fn(f64) + Sync),
) -> Supersampled {
    let bands_done = std::sync::atomic::AtomicUsize::new(0);
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let halo = sampling.filter.support().ceil() as usize;
    let palette: Vec<Vec3> = scene
        .spheres
        .iter()
        .map(|s| scene.sphere_colour(s))
        .collect();
    // Bands of rows (top first) with a halo of rows above and below for the filter; each band
    // lists the discs whose rows it touches, widened by the halo.
    let band_count = height.div_ceil(SAMPLE_BAND_ROWS);
    let bands: Vec<(Vec<[u8; 3]>, Vec<f32>, u64)> = (0..band_count)
        .into_par_iter()
        .map(|band| {
            let first_row = band * SAMPLE_BAND_ROWS;
            let last_row = (first_row + SAMPLE_BAND_ROWS).min(height) - 1;
            let halo_first = first_row.saturating_sub(halo);
            let halo_last = (last_row + halo).min(height - 1);
            // Screen v range of these rows, widened by a pixel: the discs that can be hit.
            let v_of = |row: usize| grid.v_of_row((height - 1 - row) as f64);
            let v_high = v_of(halo_first) + grid.pixel_size_world;
            let v_low = v_of(halo_last) - grid.pixel_size_world;
            let local: Vec<Disc> = discs
                .iter()
                .filter(|d| {
                    let r = d.radius_sq.sqrt();
                    d.v + r >= v_low && d.v - r <= v_high
                })
                .copied()
                .collect();
            let tiles = column_tiles(&local, grid);
            let mut tests = 0u64;
            // Evaluate every sample of the halo rows.
            let rows = halo_last - halo_first + 1;
            let mut samples: Vec<Vec<Sample>> = Vec::with_capacity(rows * width);
            for row in halo_first..=halo_last {
                let y_up = (height - 1 - row) as u32;
                for x in 0..width as u32 {
                    let pixel_samples = sampling
                        .offsets(x, y_up)
                        .into_iter()
                        .map(|(ox, oy)| {
                            let (px, py) = (x as f32 + ox, y_up as f32 + oy);
                            let (u, v) = grid.screen_of_pixel_point(f64::from(px), f64::from(py));
                            let tile = &tiles[x as usize / TILE_COLUMNS];
                            tests += tile.len() as u64;
                            let hit = nearest_hit(tile, u, v);
                            let (colour, grey) = match hit {
                                Some((t, sphere)) => (
                                    palette
                                        .get(sphere as usize)
                                        .copied()
                                        .unwrap_or(scene.background),
                                    depth_range.grey(t) as f32,
                                ),
                                None => (scene.background, 0.0),
                            };
                            Sample {
                                x: px,
                                y: py,
                                colour,
                                grey,
                            }
                        })
                        .collect();
                    samples.push(pixel_samples);
                }
            }
            // Filter the band's own rows.
            let mut colour = Vec::with_capacity((last_row - first_row + 1) * width);
            let mut depth_grey = Vec::with_capacity(colour.capacity());
            for row in first_row..=last_row {
                let y_up = (height - 1 - row) as f32;
                for x in 0..width {
                    let (cx, cy) = (x as f32 + 0.5, y_up + 0.5);
                    let mut sum_colour = Vec3::ZERO;
                    let (mut sum_grey, mut sum_weight) = (0f32, 0f32);
                    let mut first: Option<(Vec3, f32)> = None;
                    let mut uniform = true;
                    let rows_near =
                        row.saturating_sub(halo).max(halo_first)..=(row + halo).min(halo_last);
                    let columns_near = x.saturating_sub(halo)..=(x + halo).min(width - 1);
                    for near_row in rows_near {
                        for near_x in columns_near.clone() {
                            for sample in &samples[(near_row - halo_first) * width + near_x] {
                                let weight = sampling.filter.weight(sample.x - cx, sample.y - cy);
                                if weight <= 0.0 {
                                    continue;
                                }
                                match first {
                                    None => first = Some((sample.colour, sample.grey)),
                                    Some((c, g)) => {
                                        uniform &= c == sample.colour && g == sample.grey;
                                    }
                                }
                                sum_colour += weight * sample.colour;
                                sum_grey += weight * sample.grey;
                                sum_weight += weight;
                            }
                        }
                    }
                    let (pixel_colour, pixel_grey) = match first {
                        Some(value) if uniform => value,
                        Some(_) => (sum_colour / sum_weight, sum_grey / sum_weight),
                        // No sample has weight (a filter smaller than the sample spacing): the
                        // mean of the pixel's own samples.
                        None => {
                            let own = &samples[(row - halo_first) * width + x];
                            let n = own.len().max(1) as f32;
                            (
                                own.iter().map(|s| s.colour).sum::<Vec3>() / n,
                                own.iter().map(|s| s.grey).sum::<f32>() / n,
                            )
                        }
                    };
                    colour.push(pixel_colour.to_array().map(quantize_f32));
                    depth_grey.push(pixel_grey);
                }
            }
            let done = bands_done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(done as f64 / band_count as f64);
            (colour, depth_grey, tests)
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

    fn sampling(sampler: Sampler, samples: u32, filter: Filter) -> Sampling {
        Sampling {
            sampler,
            samples,
            filter,
            seed: 7,
        }
    }

    #[test]
    fn every_filter_s_weights_sum_to_one() {
        let filters = [
            Filter::Box { radius: 0.5 },
            Filter::Box { radius: 1.3 },
            Filter::Tent { radius: 1.0 },
            Filter::Tent { radius: 2.5 },
            Filter::Gaussian { sigma: 0.4 },
            Filter::Gaussian { sigma: 1.5 },
        ];
        let mut rng = SplitMix64::new(3);
        for filter in filters {
            for _ in 0..100 {
                let samples: Vec<(f32, f32)> = (0..40)
                    .map(|_| (rng.uniform(-3.0, 3.0) as f32, rng.uniform(-3.0, 3.0) as f32))
                    .chain([(0.0, 0.0)])
                    .collect();
                let sum: f32 = normalised_weights(filter, &samples).iter().sum();
                assert!((sum - 1.0).abs() < 1e-5, "{filter}: {sum}");
            }
        }
    }

    #[test]
    fn grid_samplers_need_squares_and_sizes_are_checked() {
        assert!(
            sampling(Sampler::Uniform, 9, Filter::PIXEL_BOX)
                .validate()
                .is_ok()
        );
        assert!(
            sampling(Sampler::Uniform, 8, Filter::PIXEL_BOX)
                .validate()
                .is_err()
        );
        assert!(
            sampling(Sampler::Jittered, 2, Filter::PIXEL_BOX)
                .validate()
                .is_err()
        );
        assert!(
            sampling(Sampler::Random, 7, Filter::PIXEL_BOX)
                .validate()
                .is_ok()
        );
        assert!(
            sampling(Sampler::Random, 0, Filter::PIXEL_BOX)
                .validate()
                .is_err()
        );
        assert!(
            sampling(Sampler::Random, 4, Filter::Box { radius: 0.0 })
                .validate()
                .is_err()
        );
        assert!(
            sampling(Sampler::Random, 4, Filter::Gaussian { sigma: f32::NAN })
                .validate()
                .is_err()
        );
    }

    #[test]
    fn offsets_lie_in_the_pixel_and_are_seeded() {
        for sampler in Sampler::ALL {
            let s = sampling(sampler, 16, Filter::PIXEL_BOX);
            let offsets = s.offsets(12, 34);
            assert_eq!(offsets.len(), 16);
            assert!(
                offsets
                    .iter()
                    .all(|&(x, y)| (0.0..1.0).contains(&x) && (0.0..1.0).contains(&y))
            );
            assert_eq!(
                offsets,
                s.offsets(12, 34),
                "same pixel, same seed, same offsets"
            );
        }
        let jittered = sampling(Sampler::Jittered, 4, Filter::PIXEL_BOX).offsets(0, 0);
        // One per quadrant.
        for (i, &(x, y)) in jittered.iter().enumerate() {
            assert_eq!(((x >= 0.5) as usize) + 2 * ((y >= 0.5) as usize), i);
        }
        let uniform = sampling(Sampler::Uniform, 4, Filter::PIXEL_BOX).offsets(5, 5);
        assert_eq!(
            uniform,
            vec![(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)]
        );
    }
}
