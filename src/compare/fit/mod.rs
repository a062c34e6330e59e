//! Fitting a [`Model`] of their ray caster to their images: where each pixel's ray starts
//! (least squares on the silhouettes, [`geometry`]), which hits it draws (searched,
//! [`hit_rule`]), the colour of its background and how it makes bytes, and how its depth image
//! is drawn (least squares on the grey ramp, [`depth`]). Every choice is judged by the pixels the
//! model's images still differ in from theirs ([`score`]); where a named point of the model (the
//! course's, or one of the known mistakes) draws their images as well as the fitted values, the
//! named point is kept.
//!
//! * [`labels`]: what each pixel of their image says about where the spheres are.
//! * [`geometry`]: the pixel map, by Levenberg–Marquardt.
//! * [`hit_rule`]: the depth test, tmin and roots.
//! * [`depth`]: the depth map.
//! * [`colour`]: the background and the rounding of bytes.
//! * [`sample_grid`]: several samples per pixel on a grid of the program's own.
//! * [`polish`]: the pixel map moved on both images; a tilt left out where it need not be.
//! * [`restart`]: a depth image alone left unexplained, fitted again from each named point.
//! * [`score`]: pixels left unexplained, with the renders kept.

pub mod bounds;
pub mod colour;
pub mod depth;
pub mod geometry;
pub mod hit_rule;
pub mod labels;
pub mod polish;
pub mod restart;
pub mod sample_grid;
pub mod score;
pub mod starts;

use glam::DVec2;

use self::colour::fit_colour;
use self::depth::fit_depth;
use self::geometry::{Affine, Problem};
use self::hit_rule::{search_hit_rule, search_tmin};
use self::labels::Labels;
use self::polish::{
    is_diagonal, is_named_map, plainer, polish_with_images, turned_a_quarter, untilted_if_as_good,
};
use self::sample_grid::{MAX_GRID_SPHERES, search_sample_grid};
use self::score::Scorer;
use self::starts::{block_square, differs_outside, named_geometry, only_block, starts};
use super::model::{Model, Visible, colour_bytes};

/// Levenberg–Marquardt steps from each start before the best few are carried on.
const FIRST_STEPS: usize = 6;

/// Steps for the starts carried on.
const MORE_STEPS: usize = 40;

/// Starts carried on after the first steps.
const STARTS_KEPT: usize = 5;

/// The place in the geometric results' order of a fitted map (named points come first on a tie,
/// then fits, then the starts themselves).
const FITTED: usize = usize::MAX - 1;

/// Rival maps kept from one geometric fit, at most.
const MAX_TIES: usize = 8;

/// Rounds of the hit rule's search.
pub(super) const RULE_ROUNDS: usize = 3;

/// What the fit found.
#[derive(Debug, Clone)]
pub struct Fitted {
    /// The model fitted.
    pub model: Model,
    /// Pixels its images still differ in from theirs.
    pub left: usize,
    /// Pixels the course's images differ in from theirs.
    pub differing_exact: usize,
    /// Other models scored on the way, with their pixels left (for near ties).
    pub seen: Vec<(usize, Model)>,
    /// Plainer models than the one fitted (a scale beside a matrix a hair sheared), with their
    /// pixels left: each is said and weighed before the models seen.
    pub plainer: Vec<(usize, Model)>,
}

/// The pixel map (and, for named points, the tilt) that fits the labels best under `model`'s
/// other parts.
pub(super) fn fit_geometry(
    problem: &Problem<'_>,
    model: &Model,
    from: &[Affine],
    view: &crate::render::View,
    ties: &mut Vec<Model>,
) -> Model {
    let (width, height) = (view.width_px, view.height_px);
    let step = problem.step;
    let with = |affine: &Affine| {
        let mut m = *model;
        m.pixels = affine.pixel_map(width, height, step);
        m
    };
    let mut first: Vec<(f64, Affine)> = from
        .iter()
        .map(|start| {
            let (affine, cost) = problem.fit(model, *start, FIRST_STEPS);
            (cost, affine)
        })
        .collect();
    first.sort_by(|a, b| a.0.total_cmp(&b.0));
    // The starts themselves compete too: a fit dragged by pixels only another hit rule
    // explains must not replace a start that was right. Each fit is then set on the simplest
    // named point near it that draws the labels as well.
    let mut results: Vec<(usize, usize, Model)> = Vec::new();
    for start in from {
        let candidate = with(start);
        results.push((problem.disagreeing(&candidate), usize::MAX, candidate));
    }
    let named = named_geometry(view);
    let corners = [
        DVec2::ZERO,
        DVec2::new(f64::from(width), 0.0),
        DVec2::new(0.0, f64::from(height)),
        DVec2::new(f64::from(width), f64::from(height)),
    ];
    let tolerance = (problem.labels.per_pixel.len() / 1000).max(2);
    let mut anchors: Vec<Model> = results.iter().map(|r| r.2).collect();
    for (_, affine) in first.into_iter().take(STARTS_KEPT) {
        let (affine, _) = problem.fit(model, affine, MORE_STEPS);
        let fitted = with(&affine);
        results.push((problem.disagreeing(&fitted), FITTED, fitted));
        anchors.push(fitted);
    }
    // The best fit polished (the least squares stop a hair off the fewest pixels wrong).
    if let Some(best_fit) = results
        .iter_mut()
        .filter(|r| r.1 == FITTED)
        .min_by_key(|r| r.0)
    {
        let affine = Affine::of_map(&best_fit.2.pixels, width, height, step);
        let polished = with(&problem.polish(model, affine));
        *best_fit = (problem.disagreeing(&polished), FITTED, polished);
    }
    // The named points near a start or a fit.
    for (complexity, point) in &named {
        let near = anchors.iter().any(|anchor| {
            corners.iter().all(|&c| {
                (point.pixels.screen_of(c) - anchor.pixels.screen_of(c)).length() <= 3.0 * step
            })
        });
        if near {
            let mut candidate = *model;
            candidate.pixels = point.pixels;
            candidate.t_ramp = point.t_ramp;
            results.push((problem.disagreeing(&candidate), *complexity, candidate));
        }
    }
    // Fewest disagreeing, then named (the fewest words), then the map nearest the course's (a
    // disc looks the same mirrored: say it is not).
    let off_course = |m: &Model| {
        let relative = m.pixels.relative_axes(step) - glam::DMat2::IDENTITY;
        (relative.x_axis.length() + relative.y_axis.length()) * 1e6
    };
    results.sort_by(|a, b| {
        (a.0, a.1)
            .cmp(&(b.0, b.1))
            .then(off_course(&a.2).total_cmp(&off_course(&b.2)))
    });
    // The best, but a named point within the tolerance of it before a fitted map.
    if let Some(first_named) = results.iter().position(|r| r.1 < FITTED)
        && results[first_named].0 <= results[0].0 + tolerance
    {
        let named = results.remove(first_named);
        results.insert(0, named);
    }
    let Some(&(best, _, chosen)) = results.first() else {
        return *model;
    };
    // Other maps that draw the labels as well (within the tolerance) are rivals: a symmetric
    // scene, or a fitted map beside a named point.
    for (disagreeing, _, other) in results.iter().skip(1) {
        // Maps that move no pixel centre by a thousandth of a pixel are the same map.
        let same_map = |a: &Model, b: &Model| {
            corners
                .iter()
                .all(|&c| (a.pixels.screen_of(c) - b.pixels.screen_of(c)).length() <= 1e-3 * step)
        };
        if *disagreeing <= best + tolerance
            && ties.len() < MAX_TIES
            && !same_map(other, &chosen)
            && !ties.iter().any(|t: &Model| same_map(t, other))
        {
            ties.push(*other);
        }
    }
    chosen
}

/// Fits a model to their images (see the module docs).
pub fn fit(scorer: &mut Scorer<'_>) -> Fitted {
    let view = *scorer.view;
    let scene = scorer.scene;
    let course = Model::course(&view);
    let differing_exact = scorer.score(&course);
    let mut fitted = Fitted {
        model: course,
        left: differing_exact,
        differing_exact,
        seen: Vec::new(),
        plainer: Vec::new(),
    };
    if differing_exact == 0 || scene.spheres.is_empty() {
        return fitted;
    }
    let step = Model::step_world(&view);
    let discs = scorer.discs.clone();
    let depth_no_hit = scorer
        .theirs
        .depth
        .and_then(labels::most_common)
        .filter(|&c| c != [255; 3])
        .unwrap_or([0; 3]);
    // What their image says of the silhouettes, and their background.
    let (mut labels, seen_background): (Labels, Option<[u8; 3]>) = match scorer.theirs.colour {
        Some(colour) => {
            let scene_background = colour_bytes(scene.background, false);
            let seen = labels::background_candidate(scene, colour).map(|(c, _)| c);
            let background = match seen {
                Some(c) if c != colour_bytes(scene.background, true) => c,
                _ => scene_background,
            };
            (
                labels::of_colour(scene, colour, background),
                seen.filter(|&c| c != scene_background),
            )
        }
        None => match scorer.theirs.depth {
            // What no ray hits is most of a depth image, in its most common colour (black,
            // or the background where a program fills with it), unless that is white.
            Some(depth) => (labels::of_depth(scene, depth, depth_no_hit), None),
            None => return fitted,
        },
    };
    // A non-square image whose part beyond the min(W, H) square is one flat colour may have
    // been drawn only there: that part says nothing of the map.
    let block = only_block(&view, scorer.theirs).filter(|&(side, _)| differs_outside(scorer, side));
    let mut from = starts(view.width_px, view.height_px);
    if let Some((columns, rows)) = block {
        for (index, label) in labels.per_pixel.iter_mut().enumerate() {
            let (x, row) = (index as u32 % view.width_px, index as u32 / view.width_px);
            if x >= columns || view.height_px - 1 - row >= rows {
                *label = labels::Label::Unknown;
            }
        }
        // The whole camera square in the block, upright, mirrored or upside down.
        let square = Affine::of_map(
            &block_square(&view, columns.min(rows), 0.5),
            view.width_px,
            view.height_px,
            step,
        );
        for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0)] {
            let signs = glam::DMat2::from_diagonal(DVec2::new(sx, sy));
            // Flipping an axis about the block's centre.
            let centre = DVec2::splat(0.5 * f64::from(columns.min(rows)))
                - 0.5 * DVec2::new(f64::from(view.width_px), f64::from(view.height_px));
            let mirrored_centre = square.relative * centre;
            from.push(Affine {
                relative: square.relative * signs,
                shift_px: square.shift_px + mirrored_centre - square.relative * signs * centre,
            });
        }
    }
    let mut problem = Problem {
        discs: &discs,
        sample: Problem::sample_of(&labels),
        labels: &labels,
        step,
    };
    let relabelled;
    let mut model = course;
    model.background = seen_background;
    model.drawn_px = block;
    if scorer.theirs.colour.is_none() {
        model.depth.no_hit = depth_no_hit;
    }
    let mut seen = Vec::new();
    let mut ties = Vec::new();
    model = fit_geometry(&problem, &model, &from, &view, &mut ties);
    model = fit_colour(scorer, &model, seen_background, &mut seen);
    model = fit_depth(scorer, &model);
    if scorer.theirs.depth.is_some() && scorer.score(&model) > 0 {
        // Silhouettes that say little (a sphere filling the image): the depth ramp places the
        // map, the range fitted again as it moves.
        let mut moved = model;
        for _ in 0..3 {
            moved = polish_with_images(scorer, &moved, step);
            moved = fit_depth(scorer, &moved);
        }
        // Only for clearly more pixels right: a map a hair off the silhouettes' trades with the
        // depth line's ends on a few pixels.
        let pixels = (view.width_px as usize) * (view.height_px as usize);
        if scorer.score(&moved) + (pixels / 1000).max(10) < scorer.score(&model) {
            model = moved;
        }
    }
    // A hit rule that draws their images from the course's own map: a sphere refused shows
    // what lies behind it, which the silhouettes' fit under the course's rule may explain by a
    // map turned or skewed (no known mistake's, none diagonal, none a quarter turn from it).
    // Kept aside, and taken at the end where it draws their images better than the fit that
    // follows.
    let at_course = (scorer.score(&model) > 0
        && !is_named_map(&view, &model)
        && !is_diagonal(&model, step)
        && !is_diagonal(&turned_a_quarter(&model), step))
    .then(|| {
        let mut at_course = model;
        at_course.pixels = course.pixels;
        at_course.t_ramp = course.t_ramp;
        search_hit_rule(scorer, &at_course, RULE_ROUNDS, &mut seen)
    });
    let searched = search_hit_rule(scorer, &model, RULE_ROUNDS, &mut seen);
    if searched.hits != model.hits {
        // The silhouettes again under the rule found, from where they were.
        let mut from = starts(view.width_px, view.height_px);
        from.insert(
            0,
            Affine::of_map(&searched.pixels, view.width_px, view.height_px, step),
        );
        ties.clear();
        model = fit_geometry(&problem, &searched, &from, &view, &mut ties);
        model = fit_depth(scorer, &model);
        model = search_hit_rule(scorer, &model, RULE_ROUNDS, &mut seen);
        // The map fitted again must earn its place.
        if scorer.score(&searched) < scorer.score(&model) {
            model = searched;
        }
    } else {
        model = searched;
    }
    if scorer.score(&model) > 0 && model.hits.visible == Visible::Nearest {
        // No depth test drags the silhouettes far from where a nearest-hit fit puts them: each
        // file order is tried with the map fitted again under it.
        for visible in [Visible::FirstInFile, Visible::LastInFile] {
            let mut candidate = model;
            candidate.hits.visible = visible;
            candidate.hits.later_wins_ties = false;
            // From where the map is, and from the course's.
            let from = [
                Affine::of_map(&model.pixels, view.width_px, view.height_px, step),
                Affine::COURSE,
            ];
            let mut candidate_ties = Vec::new();
            candidate = fit_geometry(&problem, &candidate, &from, &view, &mut candidate_ties);
            candidate = fit_depth(scorer, &candidate);
            let score = scorer.score(&candidate);
            seen.push((score, candidate));
            if score < scorer.score(&model) {
                model = search_hit_rule(scorer, &candidate, RULE_ROUNDS, &mut seen);
                ties = candidate_ties;
            }
        }
    }
    if let (None, Some(depth)) = (scorer.theirs.colour, scorer.theirs.depth) {
        // A depth image alone: black pixels where the model fitted so far draws a clear grey
        // are empty too (a smaller sphere), so the map is fitted again with them.
        let hits = scorer.hits(&model);
        let drawn = crate::compare::model_render::depth_image(&view, &hits, &model);
        relabelled = labels::with_black_where_grey(&labels, depth, &drawn);
        problem = Problem {
            discs: &discs,
            sample: Problem::sample_of(&relabelled),
            labels: &relabelled,
            step,
        };
        let mut from = starts(view.width_px, view.height_px);
        from.insert(
            0,
            Affine::of_map(&model.pixels, view.width_px, view.height_px, step),
        );
        let mut relabelled_ties = Vec::new();
        let mut refitted = fit_geometry(&problem, &model, &from, &view, &mut relabelled_ties);
        refitted = fit_depth(scorer, &refitted);
        refitted = search_hit_rule(scorer, &refitted, RULE_ROUNDS, &mut seen);
        // The map fitted again must earn its place.
        if scorer.score(&refitted) <= scorer.score(&model) {
            model = refitted;
            ties = relabelled_ties;
        }
    }
    if scorer.theirs.colour.is_none() && scorer.score(&model) > 0 {
        // A depth image alone: its silhouettes look alike mirrored or flipped about the image's
        // centre on a scene that is alike so, and the ramp of greys tells which.
        let affine = Affine::of_map(&model.pixels, view.width_px, view.height_px, step);
        for signs in [(-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
            let mut candidate = model;
            candidate.pixels = Affine {
                relative: affine.relative * glam::DMat2::from_diagonal(DVec2::from(signs)),
                shift_px: affine.shift_px,
            }
            .pixel_map(view.width_px, view.height_px, step);
            candidate = fit_depth(scorer, &candidate);
            let score = scorer.score(&candidate);
            seen.push((score, candidate));
            if score < scorer.score(&model) {
                model = candidate;
            }
        }
    }
    // A depth image alone: the map from the boxes around what is drawn.
    model = bounds::better_from_bounds(scorer, model, step, &mut seen);
    if let Some(at_course) = at_course
        && scorer.score(&at_course) < scorer.score(&model)
    {
        model = at_course;
        ties.clear();
    }
    model = fit_colour(scorer, &model, seen_background, &mut seen);
    model = fit_depth(scorer, &model);
    model = untilted_if_as_good(scorer, model, step);
    if scorer.score(&model) > 0 {
        // A tmin of any value, last: searched earlier, it can lead the map astray.
        model = search_tmin(scorer, &model, &mut seen);
    }
    if scorer.score(&model) > 0 && scene.spheres.len() <= MAX_GRID_SPHERES {
        model = search_sample_grid(scorer, &model, &mut seen);
    }
    if scorer.theirs.colour.is_none()
        && let Some((restarted, restarted_ties)) =
            restart::from_named_points(scorer, &labels, &model, &mut seen)
    {
        model = restarted;
        ties = restarted_ties;
    }
    // A plain scale beside a matrix a hair sheared, or swapped: the shorter story.
    fitted.plainer = plainer(scorer, &model, step);
    if scorer.theirs.depth.is_some() {
        // The depth range asked for, with the map moved to draw both images best: a lone
        // sphere's size and its depth ramp trade against each other, and the silhouettes alone
        // leave the scale a little off, which a fitted range then makes up for.
        let mut given = model;
        let named = crate::compare::model::DepthMap::of_range(view.depth_range);
        given.depth.at_zero = named.at_zero;
        given.depth.per_unit = named.per_unit;
        if given.depth != model.depth {
            let polished = polish_with_images(scorer, &given, step);
            seen.push((scorer.score(&polished), polished));
        }
    }
    fitted.left = scorer.score(&model);
    if fitted.left > differing_exact {
        fitted.model = course;
        fitted.left = differing_exact;
    } else {
        fitted.model = model;
    }
    // Rival maps first: they are what a symmetric scene offers.
    let mut rivals: Vec<(usize, Model)> = ties
        .into_iter()
        .map(|tie| {
            let mut rival = fitted.model;
            rival.pixels = tie.pixels;
            rival.t_ramp = tie.t_ramp;
            // A tilt fitted under the answer's map runs along its screen axes: under another
            // map it is fitted again (a flip of a scene that looks the same turned a quarter).
            if fitted.model.t_ramp != glam::DVec3::ZERO && rival.t_ramp != fitted.model.t_ramp {
                rival = fit_depth(scorer, &rival);
            }
            // A plain (diagonal) map beside a fitted matrix is given the same care: moved to
            // draw both images best, as the answer's own map was.
            if is_diagonal(&rival, step) && !is_diagonal(&fitted.model, step) {
                rival = polish_with_images(scorer, &rival, step);
            }
            (scorer.score(&rival), rival)
        })
        .collect();
    rivals.append(&mut seen);
    let seen = rivals;
    fitted.seen = seen;
    fitted
}
