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
//! * [`score`]: pixels left unexplained, with the renders kept.

pub mod depth;
pub mod geometry;
pub mod hit_rule;
pub mod labels;
pub mod score;

use glam::DVec2;

use self::depth::fit_depth;
use self::geometry::{Affine, Problem};
use self::hit_rule::search_hit_rule;
use self::labels::Labels;
use self::score::{Scorer, Theirs};
use super::mistake::{Mistake, MistakeSet};
use super::model::{Model, colour_bytes};
use super::model_render::discs;

/// Levenberg–Marquardt steps from each start before the best few are carried on.
const FIRST_STEPS: usize = 6;

/// Steps for the starts carried on.
const MORE_STEPS: usize = 40;

/// Starts carried on after the first steps.
const STARTS_KEPT: usize = 3;

/// Rival maps kept from one geometric fit, at most.
const MAX_TIES: usize = 8;

/// Rounds of the hit rule's search.
const RULE_ROUNDS: usize = 3;

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
}

/// The geometric named points: the course's and the mistakes that move where rays start.
fn named_geometry(view: &crate::render::View) -> Vec<(usize, Model)> {
    let words = [
        Mistake::PixelCorners,
        Mistake::Stretched,
        Mistake::FlippedVertically,
        Mistake::Mirrored,
        Mistake::RawUp,
    ];
    let mut named: Vec<(usize, Model)> = (0u32..1 << words.len())
        .map(|bits| {
            let set = MistakeSet::of(
                &words
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| bits & (1 << i) != 0)
                    .map(|(_, m)| *m)
                    .collect::<Vec<_>>(),
            );
            (set.len(), Model::of_mistakes(view, set))
        })
        .collect();
    // A non-square image drawn only in its min(W, H) square, the whole camera square there.
    if view.width_px != view.height_px {
        for (complexity, offset) in [(2, 0.5), (3, 0.0)] {
            let mut model = Model::course(view);
            model.pixels = block_square(view, view.width_px.min(view.height_px), offset);
            named.push((complexity, model));
        }
    }
    // Rays through the far corner of each pixel, (x + 1)/W.
    let mut far_corner = Model::course(view);
    far_corner.pixels = crate::compare::model::PixelMap::of_relative(
        glam::DMat2::IDENTITY,
        DVec2::ONE,
        view.width_px,
        view.height_px,
        Model::step_world(view),
    );
    named.push((1, far_corner));
    // A non-square image's strips of the camera square: its side, from the square's edge.
    let (w, h) = (view.width_px, view.height_px);
    if w != h {
        let strip = 0.5 * (f64::from(w) - f64::from(h)).abs();
        for corner in [0.0, 0.5] {
            for sign in [-1.0, 1.0] {
                let offset = if w > h {
                    DVec2::new(corner, corner + sign * strip)
                } else {
                    DVec2::new(corner + sign * strip, corner)
                };
                let mut model = Model::course(view);
                model.pixels = crate::compare::model::PixelMap::of_relative(
                    glam::DMat2::IDENTITY,
                    offset,
                    w,
                    h,
                    Model::step_world(view),
                );
                named.push((if corner == 0.0 { 2 } else { 1 }, model));
            }
        }
    }
    named
}

/// The map that shows the whole camera square in the lower-left `side`² block, each ray at
/// `offset` in its pixel.
fn block_square(
    view: &crate::render::View,
    side: u32,
    offset: f64,
) -> crate::compare::model::PixelMap {
    let pixel = view.size_world / f64::from(side);
    crate::compare::model::PixelMap {
        axes_world: glam::DMat2::from_diagonal(DVec2::splat(pixel)),
        origin_world: DVec2::splat((offset - 0.5 * f64::from(side)) * pixel),
    }
}

/// The block `(columns, rows)` of a non-square image that is all its program drew, when the
/// rest of their image (colour, else depth) is one flat colour.
fn only_block(view: &crate::render::View, theirs: Theirs<'_>) -> Option<(u32, u32)> {
    let (width, height) = (view.width_px, view.height_px);
    let image = theirs.colour.or(theirs.depth)?;
    if width == height {
        return None;
    }
    let side = width.min(height);
    let mut outside = image
        .enumerate_pixels()
        .filter(|(x, row, _)| *x >= side || height - 1 - *row >= side)
        .map(|(_, _, pixel)| pixel.0);
    let first = outside.next()?;
    outside
        .all(|colour| colour == first)
        .then_some((side, side))
}

/// The starts of the geometric fit: the course's map, mirrored, upside down, turned, with axes
/// swapped; for a non-square image also stretched and the square's strips.
fn starts(width_px: u32, height_px: u32) -> Vec<Affine> {
    let mut starts = Vec::new();
    let signs = [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)];
    for (sx, sy) in signs {
        starts.push(Affine {
            relative: glam::DMat2::from_diagonal(DVec2::new(sx, sy)),
            shift_px: DVec2::ZERO,
        });
        starts.push(Affine {
            relative: glam::DMat2::from_cols(DVec2::new(0.0, sy), DVec2::new(sx, 0.0)),
            shift_px: DVec2::ZERO,
        });
    }
    if width_px != height_px {
        let (w, h) = (f64::from(width_px), f64::from(height_px));
        let longer = w.max(h);
        starts.push(Affine {
            relative: glam::DMat2::from_diagonal(DVec2::new(longer / w, longer / h)),
            shift_px: DVec2::ZERO,
        });
        let strip = 0.5 * (w - h).abs();
        // W and H swapped in the normalisers: each axis over the other's length, the long axis
        // from the middle of its side or from either end, the short from either end.
        let k = longer / w.min(h);
        for long in [-1.0, 0.0, 1.0] {
            for short in [-1.0, 1.0] {
                let (relative, shift_px) = if w > h {
                    (
                        DVec2::new(k, 1.0),
                        DVec2::new(long * k * strip, short * strip),
                    )
                } else {
                    (
                        DVec2::new(1.0, k),
                        DVec2::new(short * strip, long * k * strip),
                    )
                };
                starts.push(Affine {
                    relative: glam::DMat2::from_diagonal(relative),
                    shift_px,
                });
            }
        }
        for sign in [-1.0, 1.0] {
            let shift_px = if w > h {
                DVec2::new(0.0, sign * strip)
            } else {
                DVec2::new(sign * strip, 0.0)
            };
            starts.push(Affine {
                relative: glam::DMat2::IDENTITY,
                shift_px,
            });
        }
    }
    starts
}

/// The pixel map (and, for named points, the tilt) that fits the labels best under `model`'s
/// other parts.
fn fit_geometry(
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
        results.push((problem.disagreeing(&fitted), usize::MAX, fitted));
        anchors.push(fitted);
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
    if let Some(first_named) = results.iter().position(|r| r.1 != usize::MAX)
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
        if *disagreeing <= best + tolerance
            && ties.len() < MAX_TIES
            && other.pixels != chosen.pixels
            && !ties.iter().any(|t: &Model| t.pixels == other.pixels)
        {
            ties.push(*other);
        }
    }
    chosen
}

/// The background and the rounding of bytes that draw their colour image best.
fn fit_colour(
    scorer: &mut Scorer<'_>,
    model: &Model,
    seen_background: Option<[u8; 3]>,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    if scorer.theirs.colour.is_none() {
        return *model;
    }
    let mut best = (scorer.score(model), *model);
    // Known mistakes before fitted values: on a tie the first is kept, the rest are seen.
    for (rounded, background) in [
        (false, None),
        (true, None),
        (false, seen_background),
        (true, seen_background),
    ] {
        let mut candidate = *model;
        candidate.rounded = rounded;
        candidate.background = background;
        let score = scorer.score(&candidate);
        seen.push((score, candidate));
        if score < best.0 {
            best = (score, candidate);
        }
    }
    best.1
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
    };
    if differing_exact == 0 || scene.spheres.is_empty() {
        return fitted;
    }
    let step = Model::step_world(&view);
    let discs = discs(scene, &view);
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
    let block = only_block(&view, scorer.theirs);
    let mut from = starts(view.width_px, view.height_px);
    if let Some((columns, rows)) = block {
        for (index, label) in labels.per_pixel.iter_mut().enumerate() {
            let (x, row) = (index as u32 % view.width_px, index as u32 / view.width_px);
            if x >= columns || view.height_px - 1 - row >= rows {
                *label = labels::Label::Unknown;
            }
        }
        // The whole camera square in the block.
        from.push(Affine::of_map(
            &block_square(&view, columns.min(rows), 0.5),
            view.width_px,
            view.height_px,
            step,
        ));
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
    } else {
        model = searched;
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
        ties.clear();
        model = fit_geometry(&problem, &model, &from, &view, &mut ties);
        model = fit_depth(scorer, &model);
        model = search_hit_rule(scorer, &model, RULE_ROUNDS, &mut seen);
    }
    model = fit_colour(scorer, &model, seen_background, &mut seen);
    model = fit_depth(scorer, &model);
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
            (scorer.score(&rival), rival)
        })
        .collect();
    rivals.append(&mut seen);
    let seen = rivals;
    fitted.seen = seen;
    fitted
}
