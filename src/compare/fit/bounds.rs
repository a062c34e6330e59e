//! A start from the bounds of what is drawn: on a depth image alone, the box around every pixel
//! their program hit beside the box around the exact image's gives a plain scale and shift of
//! the pixel map (a lone sphere's disc its width and height), mirrored or flipped as their greys'
//! ramp tells. The silhouettes' fit from a depth image can settle on a longer story (the map
//! turned a quarter, the far root, no depth test) where a zoom draws every pixel.

use glam::{DMat2, DVec2};

use super::depth::fit_depth;
use super::geometry::Affine;
use super::polish::polish_with_images;
use super::score::Scorer;
use crate::compare::model::Model;
use crate::compare::model_render::depth_image;

/// Largest ratio of the two boxes' sides (either way) taken as a start.
const MAX_SCALE: f64 = 4.0;

/// The box `(low, high)` in pixel points `(x, y_up)` around the pixels of `image` that are not
/// `empty`; `None` where every pixel is.
fn bounds(image: &image::RgbImage, empty: [u8; 3]) -> Option<(DVec2, DVec2)> {
    let height = image.height();
    let mut low = DVec2::splat(f64::INFINITY);
    let mut high = DVec2::splat(f64::NEG_INFINITY);
    for (x, row, pixel) in image.enumerate_pixels() {
        if pixel.0 != empty {
            let point = DVec2::new(f64::from(x), f64::from(height - 1 - row));
            low = low.min(point);
            high = high.max(point);
        }
    }
    low.x.is_finite().then_some((low, high))
}

/// `model` (fitted to a depth image alone) with the map that puts the exact image's box of hits
/// on theirs, upright, mirrored, flipped and both, each with its depth map fitted again and the
/// map moved on the image, with the pixels each leaves: a scene alike mirrored and flipped is
/// drawn as well both ways, and both are rivals. None without a depth image, or where either
/// image hits nothing or the boxes' sides differ by more than [`MAX_SCALE`].
fn from_bounds(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Vec<(usize, Model)> {
    let view = *scorer.view;
    let Some(depth) = scorer.theirs.depth else {
        return Vec::new();
    };
    let Some(theirs) = bounds(depth, model.depth.no_hit) else {
        return Vec::new();
    };
    let course = Model::course(&view);
    let hits = scorer.hits(&course);
    let Some(exact) = bounds(&depth_image(&view, &hits, &course), course.depth.no_hit) else {
        return Vec::new();
    };
    let side = |(low, high): (DVec2, DVec2)| high - low + DVec2::ONE;
    let scale = side(exact) / side(theirs);
    if !(scale.min_element() >= 1.0 / MAX_SCALE && scale.max_element() <= MAX_SCALE) {
        return Vec::new();
    }
    let centre_of = |(low, high): (DVec2, DVec2)| 0.5 * (low + high);
    // Pixel point p is at (R (p + c) + s) · step on the screen, the course's at (p + c) · step.
    let c = Affine::centre(view.width_px, view.height_px);
    let mut each = Vec::new();
    for signs in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
        let relative = DMat2::from_diagonal(scale * DVec2::from(signs));
        let shift_px = centre_of(exact) + c - relative * (centre_of(theirs) + c);
        let mut candidate = *model;
        candidate.pixels =
            Affine { relative, shift_px }.pixel_map(view.width_px, view.height_px, step);
        candidate.hits = course.hits;
        candidate.t_ramp = course.t_ramp;
        candidate.samples = None;
        candidate = fit_depth(scorer, &candidate);
        for _ in 0..2 {
            candidate = polish_with_images(scorer, &candidate, step);
            candidate = fit_depth(scorer, &candidate);
        }
        each.push((scorer.score(&candidate), candidate));
    }
    each
}

/// `model`, or the best map [`from_bounds`] gives where it draws a depth image alone in fewer
/// pixels wrong (each noted in `seen`).
pub(super) fn better_from_bounds(
    scorer: &mut Scorer<'_>,
    model: Model,
    step: f64,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    let left = scorer.score(&model);
    if scorer.theirs.colour.is_some() || left == 0 {
        return model;
    }
    let each = from_bounds(scorer, &model, step);
    seen.extend(each.iter().copied());
    match each.into_iter().min_by_key(|(score, _)| *score) {
        Some((score, candidate)) if score < left => candidate,
        _ => model,
    }
}
