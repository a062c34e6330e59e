//! Fitting where each pixel's ray starts (the model's [`PixelMap`], an affine map of six
//! numbers) to the silhouettes of their image, by Levenberg–Marquardt least squares.
//!
//! Each pixel whose label (its sphere colour, the background, "some sphere") disagrees with what
//! the model draws there gives a residual: how far, in pixels, its screen point must move for the
//! model to agree — into the nearest disc of its colour, or out of the disc drawn over it (or
//! across the curve where that sphere and its own meet in t). Its gradient is the disc's
//! normal, so the map's Jacobian is exact. Pixels that no move of the map can mend (a sphere
//! refused by tmin) give none. The parameters are the map's axes in units of the course's pixel
//! step and its translation in pixels from the image's centre, `screen = step·(M·p + β)`; the
//! course's map is `M = I, β = 0`. A tiny pull towards the start keeps the directions the images
//! cannot tell (a lone disc's rotation) where they started.

use glam::{DMat2, DVec2};
use rayon::prelude::*;

use super::labels::{Label, Labels};
use crate::compare::model::{Model, PixelMap};
use crate::compare::model_render::{Disc, Discs, Tiles, hit_at, ramp_at};

/// Images up to this many pixels are fitted on every pixel; larger ones on a sample.
const ALL_PIXELS_UP_TO: u64 = 90_000;

/// Pixels per chunk of the sums (fixed, so that the order of addition never changes).
const SUM_CHUNK: usize = 4096;

/// Times the polish halves its steps.
const POLISH_HALVINGS: usize = 5;

/// Largest axis entry (in course steps) and translation (in image sides) a fit may reach.
const MAX_RELATIVE_AXIS: f64 = 8.0;

/// Residuals beyond this many pixels weigh less and less (Cauchy's loss): a sphere their
/// program does not draw at all (a tmin, no depth test) should not drag the map.
const ROBUST_PX: f64 = 4.0;

/// Pull towards the start, per parameter, as a share of the pixels fitted (see the module
/// docs).
const PULL: f64 = 1e-4;

/// The six parameters: `M` by columns, then `β`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine {
    /// Axes in units of the course's pixel step.
    pub relative: DMat2,
    /// Translation in course pixel steps, from the image's centre.
    pub shift_px: DVec2,
}

impl Affine {
    /// The course's map.
    pub const COURSE: Self = Self {
        relative: DMat2::IDENTITY,
        shift_px: DVec2::ZERO,
    };

    /// The image's centre in pixel points, negated: pixel point p sits at (p + centre) course
    /// pixel steps from it.
    pub(super) fn centre(width_px: u32, height_px: u32) -> DVec2 {
        DVec2::new(
            0.5 - 0.5 * f64::from(width_px),
            0.5 - 0.5 * f64::from(height_px),
        )
    }

    /// The pixel map of these parameters for a `width × height` image with the course's pixel
    /// step `step`.
    pub fn pixel_map(&self, width_px: u32, height_px: u32, step: f64) -> PixelMap {
        let centre = Self::centre(width_px, height_px);
        PixelMap {
            axes_world: self.relative * step,
            origin_world: (self.relative * centre + self.shift_px) * step,
        }
    }

    /// The parameters of `map`.
    pub fn of_map(map: &PixelMap, width_px: u32, height_px: u32, step: f64) -> Self {
        let relative = map.axes_world * (1.0 / step);
        Self {
            relative,
            shift_px: map.origin_world / step - relative * Self::centre(width_px, height_px),
        }
    }

    /// The six numbers: `M` by columns, then `β`.
    pub fn to_array(self) -> [f64; 6] {
        let m = self.relative.to_cols_array();
        [m[0], m[1], m[2], m[3], self.shift_px.x, self.shift_px.y]
    }

    /// The parameters of six numbers ([`Self::to_array`]).
    pub fn of_array(a: [f64; 6]) -> Self {
        Self {
            relative: DMat2::from_cols_array(&[a[0], a[1], a[2], a[3]]),
            shift_px: DVec2::new(a[4], a[5]),
        }
    }

    fn within_bounds(&self, width_px: u32, height_px: u32) -> bool {
        let longest = f64::from(width_px.max(height_px));
        self.relative
            .to_cols_array()
            .iter()
            .all(|v| v.abs() <= MAX_RELATIVE_AXIS)
            && self.shift_px.abs().max_element() <= 2.0 * longest
            && self.relative.determinant().abs() > 1e-3
    }
}

/// What the fit works on: the scene's discs, the labels, the model's other parts.
pub struct Problem<'a> {
    /// The spheres projected on the screen.
    pub discs: &'a Discs,
    /// Their image's labels.
    pub labels: &'a Labels,
    /// The course's pixel step, world units.
    pub step: f64,
    /// The pixels fitted, as `(x, y_up)`.
    pub sample: Vec<(u32, u32)>,
}

/// Signed distance of `screen` from `disc`'s rim (negative inside), world units, and its
/// gradient.
fn rim(disc: &Disc, screen: DVec2) -> (f64, DVec2) {
    let offset = screen - disc.center_uv;
    let length = offset.length();
    let normal = if length > 0.0 {
        offset / length
    } else {
        DVec2::X
    };
    (length - disc.radius, normal)
}

impl Problem<'_> {
    /// The pixels to fit: all of them in a small image; else every pixel within two of a
    /// change of label and a grid of the rest.
    pub fn sample_of(labels: &Labels) -> Vec<(u32, u32)> {
        let (width, height) = (labels.width_px, labels.height_px);
        if u64::from(width) * u64::from(height) <= ALL_PIXELS_UP_TO {
            return (0..height)
                .flat_map(|y| (0..width).map(move |x| (x, y)))
                .collect();
        }
        let stride = ((u64::from(width) * u64::from(height) / 30_000) as f64)
            .sqrt()
            .ceil() as u32;
        let label = |x: u32, y: u32| labels.at(x, y);
        let mut sample = Vec::new();
        for y in 0..height {
            for x in 0..width {
                let here = label(x, y);
                let near_edge = (x.saturating_sub(2)..=(x + 2).min(width - 1)).any(|nx| {
                    (y.saturating_sub(2)..=(y + 2).min(height - 1)).any(|ny| label(nx, ny) != here)
                });
                if near_edge || (x % stride == 0 && y % stride == 0) {
                    sample.push((x, y));
                }
            }
        }
        sample
    }

    /// The residual (pixels) of pixel `(x, y_up)` under `model`, and its gradient with respect
    /// to the screen point (per world unit of distance, so per pixel of residual per pixel of
    /// move); `None` when the pixel agrees or no move of the map can mend it.
    fn residual(&self, model: &Model, tiles: &Tiles, x: u32, y_up: u32) -> Option<(f64, DVec2)> {
        let label = self.labels.at(x, y_up);
        if label == Label::Unknown {
            return None;
        }
        let pixel = DVec2::new(f64::from(x), f64::from(y_up));
        let screen = model.pixels.screen_of(pixel);
        let shift = ramp_at(model, screen);
        let candidates = tiles.at(x, y_up);
        let drawn = hit_at(model, self.discs, candidates, screen, shift);
        if self.labels.agrees(label, drawn.map(|h| h.1)) {
            return None;
        }
        let step = self.step;
        // Out of the disc drawn over the pixel.
        let leave = |index: u32| {
            let (distance, normal) = rim(&self.discs[index as usize], screen);
            (-distance / step, -normal)
        };
        // Into the nearest disc of `spheres`.
        let enter = |spheres: &mut dyn Iterator<Item = u32>| {
            spheres
                .map(|index| rim(&self.discs[index as usize], screen))
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map(|(distance, normal)| (distance / step, normal))
        };
        match label {
            Label::Background => drawn.map(|(_, index)| leave(index)),
            Label::AnyHit => {
                let (distance, normal) = enter(&mut candidates.iter().copied())?;
                (distance > 0.0).then_some((distance, normal))
            }
            Label::Class(class) => {
                let own = &self.labels.spheres_of_class[class as usize];
                let in_tile = candidates
                    .iter()
                    .copied()
                    .filter(|i| self.labels.class_of_sphere[*i as usize] == class);
                let nearest = enter(&mut in_tile.clone())
                    .or_else(|| (own.len() <= 256).then(|| enter(&mut own.iter().copied()))?)?;
                if nearest.0 > 0.0 {
                    return Some(nearest);
                }
                // Inside a disc of its colour but another sphere drawn over it: out of that one.
                drawn.map(|(_, index)| leave(index))
            }
            Label::Unknown => None,
        }
    }

    /// The robust cost of `affine` under `model` (Cauchy's loss summed), and the weighted
    /// normal equations' `JᵀWJ` and `JᵀWr` (6×6 and 6, row major).
    fn normal_equations(&self, model: &Model, affine: &Affine) -> (f64, [f64; 36], [f64; 6]) {
        let (width, height) = (self.labels.width_px, self.labels.height_px);
        let mut model = *model;
        model.pixels = affine.pixel_map(width, height, self.step);
        let tiles = Tiles::of(&model, self.discs, width, height);
        let centre = Affine::centre(width, height);
        let identity = || (0.0, [0.0; 36], [0.0; 6]);
        // Sums per fixed chunk, added in order: the same fit on any number of threads.
        let partial: Vec<(f64, [f64; 36], [f64; 6])> = self
            .sample
            .par_chunks(SUM_CHUNK)
            .map(|chunk| {
                let mut sums = identity();
                for &(x, y_up) in chunk {
                    if let Some((r, g)) = self.residual(&model, &tiles, x, y_up) {
                        // p_c = pixel + ½ − side/2.
                        let p = DVec2::new(f64::from(x), f64::from(y_up)) + centre;
                        let j = [g.x * p.x, g.y * p.x, g.x * p.y, g.y * p.y, g.x, g.y];
                        // Cauchy's loss and its weight.
                        let ratio = r / ROBUST_PX;
                        sums.0 += ROBUST_PX * ROBUST_PX * (1.0 + ratio * ratio).ln();
                        let weight = 1.0 / (1.0 + ratio * ratio);
                        for a in 0..6 {
                            sums.2[a] += weight * j[a] * r;
                            for b in 0..6 {
                                sums.1[a * 6 + b] += weight * j[a] * j[b];
                            }
                        }
                    }
                }
                sums
            })
            .collect();
        partial.into_iter().fold(identity(), |mut a, b| {
            a.0 += b.0;
            for i in 0..36 {
                a.1[i] += b.1[i];
            }
            for i in 0..6 {
                a.2[i] += b.2[i];
            }
            a
        })
    }

    /// How many sampled pixels disagree with `model` under `affine`.
    fn disagreeing_sampled(&self, model: &Model, affine: &Affine) -> usize {
        let (width, height) = (self.labels.width_px, self.labels.height_px);
        let mut model = *model;
        model.pixels = affine.pixel_map(width, height, self.step);
        let tiles = Tiles::of(&model, self.discs, width, height);
        self.sample
            .par_chunks(SUM_CHUNK)
            .map(|chunk| {
                chunk
                    .iter()
                    .filter(|&&(x, y_up)| {
                        let pixel = DVec2::new(f64::from(x), f64::from(y_up));
                        let screen = model.pixels.screen_of(pixel);
                        let shift = ramp_at(&model, screen);
                        let drawn = hit_at(&model, self.discs, tiles.at(x, y_up), screen, shift);
                        !self
                            .labels
                            .agrees(self.labels.at(x, y_up), drawn.map(|h| h.1))
                    })
                    .count()
            })
            .sum()
    }

    /// The parameters near `start` that draw the fewest sampled pixels wrong, by a pattern search
    /// (each number moved up and down by a step that halves when no move helps): the least
    /// squares stop where their stand-in for the count does, a hair off it.
    pub fn polish(&self, model: &Model, start: Affine) -> Affine {
        let (width, height) = (self.labels.width_px, self.labels.height_px);
        let mut best = (self.disagreeing_sampled(model, &start), start.to_array());
        // Steps: a hundredth of the axes, half a pixel of the shift, then halving.
        let mut steps = [0.01, 0.01, 0.01, 0.01, 0.5, 0.5];
        for _ in 0..POLISH_HALVINGS {
            let mut moved = true;
            while moved && best.0 > 0 {
                moved = false;
                for i in 0..6 {
                    for sign in [-1.0, 1.0] {
                        let mut values = best.1;
                        values[i] += sign * steps[i];
                        let candidate = Affine::of_array(values);
                        if !candidate.within_bounds(width, height) {
                            continue;
                        }
                        let count = self.disagreeing_sampled(model, &candidate);
                        if count < best.0 {
                            best = (count, values);
                            moved = true;
                        }
                    }
                }
            }
            for step in &mut steps {
                *step *= 0.5;
            }
        }
        Affine::of_array(best.1)
    }

    /// How many labelled pixels of the whole image disagree with `model` (its pixel map as is).
    pub fn disagreeing(&self, model: &Model) -> usize {
        let (width, height) = (self.labels.width_px, self.labels.height_px);
        let tiles = Tiles::of(model, self.discs, width, height);
        (0..height)
            .into_par_iter()
            .map(|y_up| {
                (0..width)
                    .filter(|&x| {
                        let label = self.labels.at(x, y_up);
                        let pixel = DVec2::new(f64::from(x), f64::from(y_up));
                        let screen = model.pixels.screen_of(pixel);
                        let shift = ramp_at(model, screen);
                        let drawn = hit_at(model, self.discs, tiles.at(x, y_up), screen, shift);
                        !self.labels.agrees(label, drawn.map(|h| h.1))
                    })
                    .count()
            })
            .sum()
    }

    /// Levenberg–Marquardt from `start`, at most `iterations` steps; the parameters reached and
    /// their sum of squared residuals.
    pub fn fit(&self, model: &Model, start: Affine, iterations: usize) -> (Affine, f64) {
        let (width, height) = (self.labels.width_px, self.labels.height_px);
        let pull = PULL * self.sample.len() as f64;
        let start_array = start.to_array();
        let prior = |a: &[f64; 6]| {
            a.iter()
                .zip(&start_array)
                .map(|(v, s)| pull * (v - s) * (v - s))
                .sum::<f64>()
        };
        let mut current = start;
        let (mut cost, mut jtj, mut jtr) = self.normal_equations(model, &current);
        cost += prior(&current.to_array());
        let mut lambda = 1e-3;
        for _ in 0..iterations {
            if cost <= 1e-12 {
                break;
            }
            let mut improved = false;
            for _ in 0..8 {
                let values = current.to_array();
                let mut a = jtj;
                let mut b = [0.0; 6];
                for i in 0..6 {
                    a[i * 6 + i] += lambda * jtj[i * 6 + i].max(1e-9) + pull;
                    b[i] = -jtr[i] - pull * (values[i] - start_array[i]);
                }
                let Some(delta) = solve6(a, b) else {
                    lambda *= 10.0;
                    continue;
                };
                let mut next = values;
                for i in 0..6 {
                    next[i] += delta[i];
                }
                let candidate = Affine::of_array(next);
                if !candidate.within_bounds(width, height) {
                    lambda *= 10.0;
                    continue;
                }
                let (c, cj, cr) = self.normal_equations(model, &candidate);
                let c = c + prior(&next);
                if c < cost {
                    current = candidate;
                    cost = c;
                    jtj = cj;
                    jtr = cr;
                    lambda = (lambda / 4.0).max(1e-9);
                    improved = true;
                    break;
                }
                lambda *= 6.0;
            }
            if !improved {
                break;
            }
        }
        (current, cost)
    }
}

/// Solves the 6×6 system `a·x = b` by Gaussian elimination with partial pivoting.
fn solve6(mut a: [f64; 36], mut b: [f64; 6]) -> Option<[f64; 6]> {
    for col in 0..6 {
        let pivot =
            (col..6).max_by(|&i, &j| a[i * 6 + col].abs().total_cmp(&a[j * 6 + col].abs()))?;
        if a[pivot * 6 + col].abs() < 1e-300 || !a[pivot * 6 + col].is_finite() {
            return None;
        }
        if pivot != col {
            for k in 0..6 {
                a.swap(col * 6 + k, pivot * 6 + k);
            }
            b.swap(col, pivot);
        }
        for row in col + 1..6 {
            let factor = a[row * 6 + col] / a[col * 6 + col];
            for k in col..6 {
                a[row * 6 + k] -= factor * a[col * 6 + k];
            }
            b[row] -= factor * b[col];
        }
    }
    let mut x = [0.0; 6];
    for row in (0..6).rev() {
        let mut sum = b[row];
        for k in row + 1..6 {
            sum -= a[row * 6 + k] * x[k];
        }
        x[row] = sum / a[row * 6 + row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}
