//! Searching for a grid of samples: a program that traces several samples per pixel on a grid of
//! its own over the screen (often a fixed size, 1024 a side, whatever the image's) and lets the
//! last (or first) sample that hits set the pixel draws every sphere up to a pixel larger. Each
//! grid of a few sizes — a whole number of samples per pixel, or a round number over the screen
//! — is tried with the model fitted so far, both orders, its depth map fitted again.

use super::depth::fit_depth_quickly;
use super::score::Scorer;
use crate::compare::model::{Model, SampleGrid};

/// Scenes of more spheres than this are not searched for a grid: each pixel traces all its
/// samples against every sphere.
pub const MAX_GRID_SPHERES: usize = 256;

/// Grid sizes over the screen tried beside whole numbers of samples per pixel (those of at most
/// [`MOST_PER_PIXEL`] samples a pixel along a side).
const ROUND_SIDES: [u32; 8] = [256, 500, 512, 1000, 1024, 2000, 2048, 4096];

/// Samples per pixel along a side tried.
const PER_PIXEL: [u32; 5] = [2, 3, 4, 5, 6];

/// The most samples per pixel along a side a grid tried may have.
const MOST_PER_PIXEL: u32 = 6;

/// Pixels their image must light beyond the exact one's silhouettes, and times as many as it
/// leaves dark within them, for a grid to be looked for.
const GROWN_PX: usize = 20;

/// Whether their image lights clearly more pixels around the exact silhouettes than it leaves
/// dark within them (a pixel is lit where it is not the image's most common colour).
fn silhouettes_grew(scorer: &mut Scorer<'_>) -> bool {
    let Some(theirs) = scorer.theirs.colour.or(scorer.theirs.depth) else {
        return false;
    };
    let Some(empty) = super::labels::most_common(theirs) else {
        return false;
    };
    let exact = scorer.hits(&Model::course(scorer.view));
    let (mut grown, mut lost) = (0, 0);
    for (pixel, t) in theirs.pixels().zip(&exact.t) {
        match (pixel.0 != empty, t.is_finite()) {
            (true, false) => grown += 1,
            (false, true) => lost += 1,
            _ => {}
        }
    }
    grown >= GROWN_PX && grown >= 3 * lost
}

/// The model with a sample grid where one draws their images better than `model` (its grid, if
/// any, tried again among the others); `seen` gets every model scored.
pub fn search_sample_grid(
    scorer: &mut Scorer<'_>,
    model: &Model,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    if !silhouettes_grew(scorer) {
        return *model;
    }
    let view = *scorer.view;
    let course = Model::course(&view);
    let longer = view.width_px.max(view.height_px);
    let mut sides: Vec<u32> = PER_PIXEL.iter().map(|k| k * longer).collect();
    sides.extend(
        ROUND_SIDES
            .iter()
            .copied()
            .filter(|&side| side > longer && side <= MOST_PER_PIXEL * longer),
    );
    sides.sort_unstable();
    sides.dedup();
    let mut candidates = Vec::new();
    for per_side in sides {
        for last_wins in [true, false] {
            // The grid's samples lie where the course's screen puts them: no map of its own.
            let mut with = *model;
            with.pixels = course.pixels;
            with.samples = Some(SampleGrid {
                per_side,
                last_wins,
            });
            candidates.push(fit_depth_quickly(scorer, &with));
        }
    }
    let scores = scorer.scores_of(&candidates);
    let mut best = (scorer.score(model), *model);
    for (candidate, score) in candidates.into_iter().zip(scores) {
        if let Some(score) = score {
            seen.push((score, candidate));
            if score < best.0 {
                best = (score, candidate);
            }
        }
    }
    best.1
}
