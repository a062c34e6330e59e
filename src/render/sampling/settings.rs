//! What a user chooses for supersampling: the [`Sampler`] that places sample positions, the
//! reconstruction [`Filter`] and its radius, and the [`Sampling`] that holds them with the sample
//! count (checked: [`SamplingError`]).

use std::fmt;

use crate::render::rng::SplitMix64;

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
    pub(crate) fn needs_square(self) -> bool {
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
    pub(crate) fn size(self) -> f32 {
        match self {
            Self::Box { radius } | Self::Tent { radius } => radius,
            Self::Gaussian { sigma } => sigma,
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
    pub(crate) fn weight(self, dx: f32, dy: f32) -> f32 {
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
pub(crate) const MAX_FILTER_SIZE: f32 = 8.0;

/// Largest sample count per pixel accepted.
pub(crate) const MAX_SAMPLES: u32 = 1024;

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
    #[error("samples per pixel must be from 1 to {MAX_SAMPLES}, found {0}")]
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
    /// The settings in words, as the status bar and the Compare section show them:
    /// "4 uniform samples, box 0.5".
    pub fn describe(&self) -> String {
        format!(
            "{} {} samples, {}",
            self.samples,
            self.sampler.name(),
            self.filter
        )
    }

    /// Checks the settings.
    pub(crate) fn validate(&self) -> Result<(), SamplingError> {
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
    pub(crate) fn offsets(&self, x: u32, y_up: u32) -> Vec<(f32, f32)> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn sampling(sampler: Sampler, samples: u32, filter: Filter) -> Sampling {
        Sampling {
            sampler,
            samples,
            filter,
            seed: 7,
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
