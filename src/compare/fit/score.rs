//! How well a model explains their images: the pixels its images differ in from theirs (colour:
//! any level; depth: more than one level, the course's allowance), with the renders of the hits
//! kept for the models that share them.

use std::collections::HashMap;
use std::sync::Arc;

use image::RgbImage;

use crate::compare::difference::Difference;
use rayon::prelude::*;

use crate::compare::model::{Model, Visible, colour_bytes};
use crate::compare::model_render::{
    Discs, Frame, Hits, colour_image, depth_image, depth_pixel, depth_quantity, render_hits_of,
};
use crate::render::View;
use crate::scene::Scene;

/// Levels a depth pixel may differ by and still count as the same (the course's depth rule).
pub const DEPTH_LEVELS_UNNOTICED: u8 = 1;

/// Renders of hits the scorer keeps at once; [`crate::render::memory::compare_bound_bytes`]
/// counts them.
pub const MAX_CACHED_HITS: usize = 6;

/// How many counts a scorer keeps ([`Scorer::count_beyond`]); past it, it starts again (a key
/// is a model's text, a few hundred bytes).
const MAX_KEPT_COUNTS: usize = 2048;

/// Pixels of an image above which candidates are screened, and maps polished, on a sample of
/// its pixels first ([`Scorer::samples`]).
pub const SAMPLED_ABOVE_PX: usize = 250_000;

/// The sample's stride in both axes, pixels.
pub const SAMPLE_STRIDE_PX: u32 = 4;

/// Sampled pixels a candidate may differ in beyond twice the best and still be counted in full.
pub const SCREEN_SLACK_PX: usize = 64;

/// The images to explain (at least one), the size of the view.
#[derive(Debug, Clone, Copy)]
pub struct Theirs<'a> {
    /// Their colour image.
    pub colour: Option<&'a RgbImage>,
    /// Their depth image.
    pub depth: Option<&'a RgbImage>,
}

/// The part of a model that decides the hits, as bits (to key the renders).
type HitKey = [u64; 16];

fn hit_key(model: &Model) -> HitKey {
    let axes = model.pixels.axes_world.to_cols_array();
    let rule = &model.hits;
    [
        axes[0].to_bits(),
        axes[1].to_bits(),
        axes[2].to_bits(),
        axes[3].to_bits(),
        model.pixels.origin_world.x.to_bits(),
        model.pixels.origin_world.y.to_bits(),
        model.t_ramp.x.to_bits(),
        model.t_ramp.y.to_bits(),
        model.t_ramp.z.to_bits(),
        rule.tmin.to_bits(),
        match rule.visible {
            Visible::Nearest => 0,
            Visible::FirstInFile => 1,
            Visible::LastInFile => 2,
        },
        u64::from(rule.later_wins_ties),
        u64::from(rule.far_when_near_refused) | u64::from(rule.far_only) << 1,
        u64::from(rule.square_root),
        model
            .drawn_px
            .map_or(u64::MAX, |(x, y)| u64::from(x) << 32 | u64::from(y)),
        model.samples.map_or(u64::MAX, |grid| {
            u64::from(grid.per_side) << 1 | u64::from(grid.last_wins)
        }),
    ]
}

/// Where the images of a model differ from theirs: one flag per pixel, top row first.
#[derive(Clone, PartialEq, Default)]
pub struct Unexplained {
    /// In the colour image (any level differs).
    pub colour: Option<Vec<bool>>,
    /// In the depth image (more than one level differs).
    pub depth: Option<Vec<bool>>,
}

impl std::fmt::Debug for Unexplained {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let count = |flags: &Option<Vec<bool>>| {
            flags
                .as_ref()
                .map(|flags| flags.iter().filter(|&&f| f).count())
        };
        f.debug_struct("Unexplained")
            .field("colour_pixels", &count(&self.colour))
            .field("depth_pixels", &count(&self.depth))
            .finish()
    }
}

impl Unexplained {
    /// How many pixels are flagged.
    pub fn count(&self) -> usize {
        [&self.colour, &self.depth]
            .into_iter()
            .flatten()
            .map(|flags| flags.iter().filter(|&&f| f).count())
            .sum()
    }
}

/// Scores models against their images.
pub struct Scorer<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// The camera, size and depth range compared.
    pub view: &'a View,
    /// Their images.
    pub theirs: Theirs<'a>,
    /// The scene's discs through the view, made once.
    pub discs: Discs,
    hits: HashMap<(HitKey, u32), Arc<Hits>>,
    order: Vec<(HitKey, u32)>,
    /// Counts made ([`Self::count_beyond`]), by the model (its exact `Debug` text: every field,
    /// each number to the bit) and what was counted: the fit asks for the same count again and
    /// again (three times in four on a course scene's depth image), and a count is a pass over
    /// every pixel.
    counted: HashMap<(String, u32, bool, u8), usize>,
    /// Models scored so far.
    pub evaluated: usize,
}

impl<'a> Scorer<'a> {
    /// A scorer of `theirs` for `scene` through `view`.
    pub fn new(scene: &'a Scene, view: &'a View, theirs: Theirs<'a>) -> Self {
        Self {
            scene,
            view,
            theirs,
            discs: Discs::of(scene, view),
            hits: HashMap::new(),
            order: Vec::new(),
            counted: HashMap::new(),
            evaluated: 0,
        }
    }

    /// The hits of `model`, rendered once while kept.
    pub fn hits(&mut self, model: &Model) -> Arc<Hits> {
        self.hits_every(model, 1)
    }

    /// The hits of `model` at the pixels of every `stride`th row and column, rendered once while
    /// kept.
    fn hits_every(&mut self, model: &Model, stride: u32) -> Arc<Hits> {
        let key = (hit_key(model), stride);
        if let Some(hits) = self.hits.get(&key) {
            return Arc::clone(hits);
        }
        if self.order.len() >= MAX_CACHED_HITS {
            let oldest = self.order.remove(0);
            self.hits.remove(&oldest);
        }
        let hits = Arc::new(render_hits_of(&self.discs, self.view, model, stride));
        self.hits.insert(key, Arc::clone(&hits));
        self.order.push(key);
        hits
    }

    /// Whether an image of this view is large enough ([`SAMPLED_ABOVE_PX`]) that its depth map
    /// is fitted, candidates screened and a map polished on a sample of its pixels: every
    /// [`SAMPLE_STRIDE_PX`]th row and column.
    pub fn samples(&self) -> bool {
        (self.view.width_px as usize) * (self.view.height_px as usize) > SAMPLED_ABOVE_PX
    }

    /// The stride of the sample: [`SAMPLE_STRIDE_PX`] where [`Self::samples`], else 1.
    fn stride(&self) -> u32 {
        if self.samples() { SAMPLE_STRIDE_PX } else { 1 }
    }

    /// The pixels of one image in the sample (all of them where the image is not sampled).
    pub fn sampled_pixels(&self) -> usize {
        let stride = self.stride();
        (self.view.width_px.div_ceil(stride) as usize)
            * (self.view.height_px.div_ceil(stride) as usize)
    }

    /// [`Self::score`] on the sample of pixels ([`Self::samples`]; every pixel of an image
    /// that is not sampled).
    pub fn sampled_score(&mut self, model: &Model) -> usize {
        self.count(model, self.stride())
    }

    /// Of `candidates`, the index of the first with the fewest pixels of the sample differing
    /// ([`Self::sampled_score`]), with that count.
    pub fn sampled_best_of(&mut self, candidates: &[Model]) -> Option<(usize, usize)> {
        let mut best: Option<(usize, usize)> = None;
        for (index, candidate) in candidates.iter().enumerate() {
            let score = self.sampled_score(candidate);
            if best.is_none_or(|(_, s)| score < s) {
                best = Some((index, score));
            }
        }
        best
    }

    /// The pixels of the sample ([`Self::samples`]) where `model`'s depth image differs from
    /// theirs by any level.
    pub fn sampled_depth_levels_off(&mut self, model: &Model) -> usize {
        self.count_beyond(model, self.stride(), false, 0)
    }

    /// How the images of `model` differ from theirs (colour, depth).
    pub fn differences(&mut self, model: &Model) -> (Option<Difference>, Option<Difference>) {
        let hits = self.hits(model);
        let (scene, view, theirs) = (self.scene, self.view, self.theirs);
        (
            theirs
                .colour
                .map(|theirs| Difference::of(&colour_image(scene, &hits, model), theirs)),
            theirs
                .depth
                .map(|theirs| Difference::of(&depth_image(view, &hits, model), theirs)),
        )
    }

    /// The pixels the images of `model` differ in from theirs (colour: any level; depth: more
    /// than [`DEPTH_LEVELS_UNNOTICED`]).
    pub fn score(&mut self, model: &Model) -> usize {
        self.evaluated += 1;
        self.count(model, 1)
    }

    /// The score of each of `candidates`, or `None` for one screened out: on an image of more
    /// than [`SAMPLED_ABOVE_PX`] pixels each candidate is first counted on a sample (every
    /// [`SAMPLE_STRIDE_PX`]th row and column), and only those within twice the best sample's
    /// count (and [`SCREEN_SLACK_PX`]) are scored in full: one left out would differ in about
    /// twice as many pixels as the best.
    pub fn scores_of(&mut self, candidates: &[Model]) -> Vec<Option<usize>> {
        let kept: Vec<bool> = if self.samples() && candidates.len() > 1 {
            let sampled: Vec<usize> = candidates
                .iter()
                .map(|candidate| self.sampled_score(candidate))
                .collect();
            let best = sampled.iter().copied().min().unwrap_or(0);
            sampled
                .iter()
                .map(|&count| count <= 2 * best + SCREEN_SLACK_PX)
                .collect()
        } else {
            vec![true; candidates.len()]
        };
        candidates
            .iter()
            .zip(kept)
            .map(|(candidate, kept)| kept.then(|| self.score(candidate)))
            .collect()
    }

    /// [`Self::score`] over the pixels of every `stride`th row and column (all at 1).
    fn count(&mut self, model: &Model, stride: u32) -> usize {
        self.count_beyond(model, stride, true, DEPTH_LEVELS_UNNOTICED)
    }

    /// The pixels of every `stride`th row and column where the images of `model` differ from
    /// theirs: the colour image (where `with_colour`) by any level, the depth image by more than
    /// `depth_levels`.
    fn count_beyond(
        &mut self,
        model: &Model,
        stride: u32,
        with_colour: bool,
        depth_levels: u8,
    ) -> usize {
        let key = (format!("{model:?}"), stride, with_colour, depth_levels);
        if let Some(&count) = self.counted.get(&key) {
            return count;
        }
        if self.counted.len() >= MAX_KEPT_COUNTS {
            self.counted.clear();
        }
        let count = self.count_beyond_now(model, stride, with_colour, depth_levels);
        self.counted.insert(key, count);
        count
    }

    /// [`Self::count_beyond`], counted now.
    fn count_beyond_now(
        &mut self,
        model: &Model,
        stride: u32,
        with_colour: bool,
        depth_levels: u8,
    ) -> usize {
        let colour = self
            .theirs
            .colour
            .filter(|_| with_colour)
            .map(|image| image.as_raw().as_slice());
        let depth = self.theirs.depth.map(|image| image.as_raw().as_slice());
        let width = self.view.width_px as usize;
        let stride = stride.max(1) as usize;
        // A map of finite ends, counted pixel by pixel; a zero-width range through the images.
        if !(model.depth.at_zero.is_finite() && model.depth.per_unit.is_finite()) {
            let (colour_difference, depth_difference) = self.differences(model);
            let sampled = |index: usize| {
                (index % width).is_multiple_of(stride) && (index / width).is_multiple_of(stride)
            };
            let beyond = |difference: Option<Difference>, levels: u8| {
                difference.map_or(0, |d| {
                    d.per_pixel
                        .iter()
                        .enumerate()
                        .filter(|&(index, &level)| level > levels && sampled(index))
                        .count()
                })
            };
            return beyond(colour_difference.filter(|_| with_colour), 0)
                + beyond(depth_difference, depth_levels);
        }
        // Pixel by pixel, without making the images: the same count as
        // [`Self::differences`] gives.
        let hits = self.hits_every(model, stride as u32);
        let scene = self.scene;
        let colours: Vec<[u8; 3]> = scene
            .spheres
            .iter()
            .map(|s| colour_bytes(scene.sphere_colour(s), model.rounded))
            .collect();
        let background = model
            .background
            .unwrap_or_else(|| colour_bytes(scene.background, model.rounded));
        let (view, frame) = (self.view, Frame::of(self.view));
        let far = |a: [u8; 3], b: &[u8], levels: u8| (0..3).any(|c| a[c].abs_diff(b[c]) > levels);
        // `sampled`: the index in the hits; (`x`, `row`): the pixel in their images.
        let pixel = |sampled: usize, x: usize, row: usize| {
            let index = row * width + x;
            let mut count = 0;
            if let Some(colour) = colour {
                let drawn = colours
                    .get(hits.sphere[sampled] as usize)
                    .copied()
                    .unwrap_or(background);
                count += usize::from(far(drawn, &colour[3 * index..3 * index + 3], 0));
            }
            if let Some(depth) = depth {
                let t = hits.t[sampled];
                let q = depth_quantity(view, &frame, model, t, x as u32, row as u32);
                let drawn = depth_pixel(model, q);
                count += usize::from(far(drawn, &depth[3 * index..3 * index + 3], depth_levels));
            }
            count
        };
        let sampled_width = hits.width_px as usize;
        (0..hits.height_px as usize)
            .into_par_iter()
            .with_min_len((4096 / sampled_width).max(1))
            .map(|sampled_row| {
                (0..sampled_width)
                    .map(|sampled_x| {
                        pixel(
                            sampled_row * sampled_width + sampled_x,
                            sampled_x * stride,
                            sampled_row * stride,
                        )
                    })
                    .sum::<usize>()
            })
            .sum()
    }

    /// Where the images of `model` differ from theirs.
    pub fn unexplained(&mut self, model: &Model) -> Unexplained {
        let (colour, depth) = self.differences(model);
        let flags = |difference: Difference, levels: u8| {
            difference.per_pixel.iter().map(|&d| d > levels).collect()
        };
        Unexplained {
            colour: colour.map(|d| flags(d, 0)),
            depth: depth.map(|d| flags(d, DEPTH_LEVELS_UNNOTICED)),
        }
    }

    /// Pixels compared in all (each image's pixels).
    pub fn compared_pixels(&self) -> usize {
        let pixels = (self.view.width_px as usize) * (self.view.height_px as usize);
        pixels
            * (usize::from(self.theirs.colour.is_some()) + usize::from(self.theirs.depth.is_some()))
    }
}
