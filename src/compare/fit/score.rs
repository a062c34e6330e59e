//! How well a model explains their images: the pixels its images differ in from theirs (colour:
//! any level; depth: more than one level, the course's allowance), with the renders of the hits
//! kept for the models that share them.

use std::collections::HashMap;
use std::sync::Arc;

use image::RgbImage;

use crate::compare::difference::Difference;
use rayon::prelude::*;

use crate::compare::model::{Model, Quantity, Visible, colour_bytes};
use crate::compare::model_render::{Hits, colour_image, depth_image, depth_pixel, render_hits};
use crate::render::View;
use crate::scene::Scene;

/// Levels a depth pixel may differ by and still count as the same (the course's depth rule).
pub const DEPTH_LEVELS_UNNOTICED: u8 = 1;

/// Renders of hits the scorer keeps at once; [`crate::render::memory::compare_bound_bytes`]
/// counts them.
pub const MAX_CACHED_HITS: usize = 6;

/// The images to explain (at least one), the size of the view.
#[derive(Debug, Clone, Copy)]
pub struct Theirs<'a> {
    /// Their colour image.
    pub colour: Option<&'a RgbImage>,
    /// Their depth image.
    pub depth: Option<&'a RgbImage>,
}

/// The part of a model that decides the hits, as bits (to key the renders).
type HitKey = [u64; 15];

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
    hits: HashMap<HitKey, Arc<Hits>>,
    order: Vec<HitKey>,
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
            hits: HashMap::new(),
            order: Vec::new(),
            evaluated: 0,
        }
    }

    /// The hits of `model`, rendered once while kept.
    pub fn hits(&mut self, model: &Model) -> Arc<Hits> {
        let key = hit_key(model);
        if let Some(hits) = self.hits.get(&key) {
            return Arc::clone(hits);
        }
        if self.order.len() >= MAX_CACHED_HITS {
            let oldest = self.order.remove(0);
            self.hits.remove(&oldest);
        }
        let hits = Arc::new(render_hits(self.scene, self.view, model));
        self.hits.insert(key, Arc::clone(&hits));
        self.order.push(key);
        hits
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
        let plain_depth = model.depth.quantity == Quantity::T
            && model.depth.at_zero.is_finite()
            && model.depth.per_unit.is_finite();
        if !plain_depth {
            let (colour, depth) = self.differences(model);
            return colour.map_or(0, |d| d.pixels_beyond(0))
                + depth.map_or(0, |d| d.pixels_beyond(DEPTH_LEVELS_UNNOTICED));
        }
        // Pixel by pixel, without making the images: the same count as
        // [`Self::differences`] gives, for a depth image of t.
        let hits = self.hits(model);
        let scene = self.scene;
        let colours: Vec<[u8; 3]> = scene
            .spheres
            .iter()
            .map(|s| colour_bytes(scene.sphere_colour(s), model.rounded))
            .collect();
        let background = model
            .background
            .unwrap_or_else(|| colour_bytes(scene.background, model.rounded));
        let (colour, depth) = (self.theirs.colour, self.theirs.depth);
        let far = |a: [u8; 3], b: [u8; 3], levels: u8| (0..3).any(|c| a[c].abs_diff(b[c]) > levels);
        (0..hits.t.len())
            .into_par_iter()
            .with_min_len(4096)
            .map(|index| {
                let (x, row) = (index as u32 % hits.width_px, index as u32 / hits.width_px);
                let mut count = 0;
                if let Some(colour) = colour {
                    let drawn = colours
                        .get(hits.sphere[index] as usize)
                        .copied()
                        .unwrap_or(background);
                    count += usize::from(far(drawn, colour.get_pixel(x, row).0, 0));
                }
                if let Some(depth) = depth {
                    let t = hits.t[index];
                    let q = if t == f64::INFINITY { f64::NAN } else { t };
                    let drawn = depth_pixel(model, q);
                    count += usize::from(far(
                        drawn,
                        depth.get_pixel(x, row).0,
                        DEPTH_LEVELS_UNNOTICED,
                    ));
                }
                count
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
