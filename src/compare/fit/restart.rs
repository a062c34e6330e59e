//! A depth image alone that the fit leaves unexplained, fitted again from each named point of
//! the map (the course's, mirrored, upside down, stretched, …), the hit rule searched from the
//! course's at each.
//!
//! A depth image tells only where something is hit, not which sphere: a flipped picture of a
//! program that also refuses some hits (a tmin of zero) is a few discs that the fit from the
//! plain starts matches with the wrong spheres, and the hit rule searched from there finds
//! nothing. From the named point that is their map, the hit rule is found at once; the map is
//! then fitted again from the few points that leave at most nine tenths of what the first fit
//! left, with the black pixels the rule draws grey taken for empty.
//! Bounded: only small scenes and images (the course's) are fitted again.

use super::geometry::{Affine, Problem};
use super::hit_rule::search_hit_rule;
use super::labels::{Labels, with_black_where_grey};
use super::score::Scorer;
use super::starts::{named_geometry, starts};
use super::{RULE_ROUNDS, fit_geometry};
use crate::compare::fit::depth::fit_depth;
use crate::compare::model::Model;
use crate::compare::model_render::depth_image;

/// Scenes of more spheres than this are not fitted again: each restart renders the scene some
/// hundred times, and the course's scenes hold a handful.
const MAX_RESTART_SPHERES: usize = 256;

/// Images of more pixels than this (256²) are not fitted again, for the same reason: the
/// course's images are 200².
const MAX_RESTART_PIXELS: usize = 256 * 256;

/// The share of an image's pixels left unexplained (1 in this many) below which no restart is
/// made: the rule that calls an answer explained.
const EXPLAINED_ONE_IN: usize = 100;

/// The named points whose map is fitted again, at most.
const REFITTED: usize = 4;

/// A named point's map is fitted again only where the point under its hit rule leaves at most
/// this many tenths of the pixels `model` leaves.
const CLEARLY_BETTER_TENTHS: usize = 9;

/// A model fitted from one of the named points that leaves fewer pixels unexplained than
/// `model`, where `model` leaves more than 1% of the image, with the rival maps of its fit (none
/// for a named point taken as it is: the other points are in `seen`); `None` where none does
/// better. The named points are tried simplest first, the search stopping at one that explains
/// every pixel; the map is fitted again from the few best.
pub(super) fn from_named_points(
    scorer: &mut Scorer<'_>,
    labels: &Labels,
    model: &Model,
    seen: &mut Vec<(usize, Model)>,
) -> Option<(Model, Vec<Model>)> {
    let depth = scorer.theirs.depth?;
    let view = *scorer.view;
    let (width, height) = (view.width_px, view.height_px);
    let pixels = (width as usize) * (height as usize);
    let entry_left_px = scorer.score(model);
    if entry_left_px <= pixels / EXPLAINED_ONE_IN
        || pixels > MAX_RESTART_PIXELS
        || scorer.scene.spheres.len() > MAX_RESTART_SPHERES
    {
        return None;
    }
    let discs = scorer.discs.clone();
    let step = Model::step_world(&view);
    let mut best: Option<(usize, Model, Vec<Model>)> = None;
    let mut keep = |score: usize, candidate: Model, ties: Vec<Model>| {
        if score < best.as_ref().map_or(entry_left_px, |b| b.0) {
            best = Some((score, candidate, ties));
        }
    };
    let course = Model::course(&view);
    let mut named = named_geometry(&view);
    named.sort_by_key(|&(complexity, _)| complexity);
    // Each named point under the hit rule searched from the course's: cheap, and what tells
    // their map from the others.
    let mut ruled: Vec<(usize, Model)> = Vec::new();
    let mut explained_all = false;
    for (_, point) in named {
        let mut start = *model;
        start.pixels = point.pixels;
        start.t_ramp = point.t_ramp;
        start.hits = course.hits;
        start = fit_depth(scorer, &start);
        let candidate = search_hit_rule(scorer, &start, RULE_ROUNDS, seen);
        let score = scorer.score(&candidate);
        seen.push((score, candidate));
        keep(score, candidate, Vec::new());
        if score == 0 {
            explained_all = true;
            break;
        }
        ruled.push((score, candidate));
    }
    // The map fitted again only from the few that clearly draw more of their image than the
    // first fit did: the refit takes most of the time, and a picture that is no depth image of
    // the scene (noise) would pay it from every point.
    let clearly_better_px = entry_left_px * CLEARLY_BETTER_TENTHS / 10;
    ruled.sort_by_key(|&(score, _)| score);
    for (_, start) in ruled
        .into_iter()
        .filter(|&(score, _)| score <= clearly_better_px)
        .take(REFITTED)
    {
        if explained_all {
            break;
        }
        // From where it is, with the black pixels where the rule draws a clear grey taken for
        // the background (black says nothing of a depth image's hits by itself).
        let hits = scorer.hits(&start);
        let drawn = depth_image(&view, &hits, &start);
        let relabelled = with_black_where_grey(labels, depth, &drawn);
        let problem = Problem {
            discs: &discs,
            sample: Problem::sample_of(&relabelled),
            labels: &relabelled,
            step,
        };
        let mut from = starts(width, height);
        from.insert(0, Affine::of_map(&start.pixels, width, height, step));
        let mut ties = Vec::new();
        let refitted = fit_geometry(&problem, &start, &from, &view, &mut ties);
        let refitted = fit_depth(scorer, &refitted);
        let candidate = search_hit_rule(scorer, &refitted, RULE_ROUNDS, seen);
        let score = scorer.score(&candidate);
        seen.push((score, candidate));
        keep(score, candidate, ties);
        explained_all = score == 0;
    }
    best.map(|(_, model, ties)| (model, ties))
}
