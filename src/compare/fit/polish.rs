//! The pixel map moved on both images, colour and depth, by a pattern search of small steps
//! (the silhouettes' least squares stop a hair off the fewest pixels wrong, and a lone sphere's
//! size trades with its depth ramp); a fitted tilt left out where the map, moved without it,
//! draws the images nearly as well; plainer maps beside a fitted one (a scale beside a matrix a
//! hair sheared or swapped); and what kind of map a model has (a known mistake's, diagonal,
//! turned a quarter).

use glam::DVec2;

use super::depth::{fit_depth, fit_depth_untilted};
use super::geometry::Affine;
use super::score::Scorer;
use super::starts::named_geometry;
use crate::compare::model::Model;

/// Rounds of the pattern search that moves the pixel map on the images, each with steps half
/// the last: the shift's last step is 0.2 / 2⁵ of a pixel.
const POLISH_ROUNDS: usize = 6;

/// Of [`POLISH_ROUNDS`], those that move the whole map (the matrix's last step is 0.0005 of
/// its entries); the rest move only the shift.
const WHOLE_MAP_ROUNDS: usize = 3;

/// Grey levels across the image beyond which a tilt is not tried without
/// ([`untilted_if_as_good`]): a tilt standing in for a sample a fraction of a pixel off moves
/// the depth by a few levels across the image (about 16 for the generated corpus's program 298),
/// a camera basis that is not orthogonal by hundreds.
const SMALL_TILT_LEVELS: f64 = 64.0;

/// Whether `model`'s pixel map has no off-diagonal part (a thousandth of its largest entry).
pub(super) fn is_diagonal(model: &Model, step: f64) -> bool {
    off_diagonal_share(model.pixels.relative_axes(step)) <= 1e-3
}

/// The larger off-diagonal entry of `m`, as a share of its largest entry.
fn off_diagonal_share(m: glam::DMat2) -> f64 {
    let largest = m.to_cols_array().iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if largest == 0.0 {
        return 0.0;
    }
    m.x_axis.y.abs().max(m.y_axis.x.abs()) / largest
}

/// `model` with its pixel map moved, by a pattern search of small steps, to draw their images
/// (colour and depth) in the fewest pixels wrong. On a large image the search counts a sample
/// of the pixels ([`Scorer::sampled_score`]), and the map found is kept only where it draws
/// every pixel as well as `model`'s.
pub(super) fn polish_with_images(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Model {
    let polished = polish_on(scorer, model, step, &[0, 1, 2, 3, 4, 5], true);
    if scorer.samples() && scorer.score(&polished) > scorer.score(model) {
        return *model;
    }
    polished
}

/// Plainer models than `model`, with the pixels each leaves: its map made diagonal where it is a
/// hair sheared ([`diagonal_if_near`]), swapped back where it is swapped ([`unswapped`], its
/// depth ramp fitted again along the axes as they are now), and its rays through the pixels'
/// centres where they start a fraction of a pixel off ([`centred`]). Each is said and weighed
/// before the models seen on the way, and stated where it draws their pixels as well.
pub(super) fn plainer(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Vec<(usize, Model)> {
    let mut plainer = Vec::new();
    if let Some(diagonal) = diagonal_if_near(scorer, model, step) {
        plainer.push((scorer.score(&diagonal), diagonal));
    }
    if let Some(turned) = unswapped(scorer, model, step) {
        let mut turned = fit_depth(scorer, &turned);
        turned = polish_with_images(scorer, &turned, step);
        if is_diagonal(&turned, step) {
            plainer.push((scorer.score(&turned), turned));
        }
    }
    // Each map so far (the fitted one first) with its rays through the pixels' centres.
    let maps: Vec<Model> = std::iter::once(*model)
        .chain(plainer.iter().map(|(_, m)| *m))
        .collect();
    for map in maps {
        if let Some(centred) = centred(scorer, &map, step) {
            plainer.push((scorer.score(&centred), centred));
        }
    }
    plainer
}

/// Largest offset of a sample from its pixel's centre (in pixels, on either axis) tried without
/// it by [`centred`]: on a lone sphere a few hundredths of a pixel trade with the depth ramp's
/// tilt and the axes' scales.
const NEAR_CENTRE_PX: f64 = 0.25;

/// `model` with its rays through the pixels' centres, where its samples start off them by less
/// than [`NEAR_CENTRE_PX`] on a diagonal map: the scales moved on the images with the shift held
/// and the depth map fitted again. A depth image alone of one sphere can be drawn nearly as well
/// by an offset of 0.04 pixels as by the tilt their program has, and the story without the offset
/// is the shorter one where it draws their pixels as well.
fn centred(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Option<Model> {
    let view = *scorer.view;
    let affine = Affine::of_map(&model.pixels, view.width_px, view.height_px, step);
    let offset = model
        .pixels
        .sample_offset_px(view.width_px, view.height_px)?
        - DVec2::splat(0.5);
    if affine.shift_px == DVec2::ZERO
        || offset.abs().max_element() >= NEAR_CENTRE_PX
        || !is_diagonal(model, step)
    {
        return None;
    }
    let mut centred = *model;
    centred.pixels = Affine {
        relative: affine.relative,
        shift_px: DVec2::ZERO,
    }
    .pixel_map(view.width_px, view.height_px, step);
    for _ in 0..2 {
        centred = polish_on(scorer, &centred, step, &[0, 3], false);
        if scorer.theirs.depth.is_some() {
            centred = fit_depth(scorer, &centred);
        }
    }
    Some(centred)
}

/// Largest off-diagonal part of a fitted matrix (of its largest entry) tried without it by
/// [`diagonal_if_near`]: a shear of a degree or two is what a fit on a few silhouettes' edges
/// can settle on in place of a plain scale.
const NEAR_DIAGONAL: f64 = 0.05;

/// `model`'s pixel map made diagonal (its off-diagonal part dropped) and moved on the images
/// with its scales and shift only, where that part is small ([`NEAR_DIAGONAL`]): a fit that
/// stops on a matrix a hair sheared leaves the plain scale untried, and the scale is the shorter
/// story where it draws their pixels as well.
fn diagonal_if_near(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Option<Model> {
    let view = *scorer.view;
    let affine = Affine::of_map(&model.pixels, view.width_px, view.height_px, step);
    let m = affine.relative;
    if is_diagonal(model, step) || off_diagonal_share(m) > NEAR_DIAGONAL {
        return None;
    }
    let mut diagonal = *model;
    diagonal.pixels = Affine {
        relative: glam::DMat2::from_diagonal(DVec2::new(m.x_axis.x, m.y_axis.y)),
        shift_px: affine.shift_px,
    }
    .pixel_map(view.width_px, view.height_px, step);
    Some(polish_on(scorer, &diagonal, step, &[0, 3, 4, 5], true))
}

/// `model`'s pixel map with its axes swapped back, where they are swapped (diagonal turned a
/// quarter): each pixel axis keeps the scale it had, now along its own screen axis, and the
/// depth ramp turns with it; moved on the images with its scales and shift only. A lone disc at
/// the centre looks the same swapped, and the plain scale is the shorter story.
fn unswapped(scorer: &mut Scorer<'_>, model: &Model, step: f64) -> Option<Model> {
    // Swapped, or a hair sheared beside swapped ([`NEAR_DIAGONAL`]).
    let turned = turned_a_quarter(model).pixels.relative_axes(step);
    if is_diagonal(model, step) || off_diagonal_share(turned) > NEAR_DIAGONAL {
        return None;
    }
    let view = *scorer.view;
    let affine = Affine::of_map(&model.pixels, view.width_px, view.height_px, step);
    let m = affine.relative;
    let mut turned = *model;
    turned.pixels = Affine {
        relative: glam::DMat2::from_diagonal(DVec2::new(m.x_axis.y, m.y_axis.x)),
        shift_px: affine.shift_px,
    }
    .pixel_map(view.width_px, view.height_px, step);
    turned.t_ramp = glam::DVec3::new(model.t_ramp.y, model.t_ramp.x, model.t_ramp.z);
    Some(polish_on(scorer, &turned, step, &[0, 3, 4, 5], true))
}

/// The pattern search of [`polish_with_images`], on [`Scorer::sampled_score`], moving the map's
/// parameters `whole` ([`Affine::to_array`]'s order) in the first rounds, and then its shift
/// where `shift_free` (else `whole` again, finer).
fn polish_on(
    scorer: &mut Scorer<'_>,
    model: &Model,
    step: f64,
    whole: &[usize],
    shift_free: bool,
) -> Model {
    let view = *scorer.view;
    let (width, height) = (view.width_px, view.height_px);
    let with = |values: [f64; 6]| {
        let mut m = *model;
        m.pixels = Affine::of_array(values).pixel_map(width, height, step);
        m
    };
    let start = Affine::of_map(&model.pixels, width, height, step).to_array();
    let mut best = (scorer.sampled_score(model), start);
    let mut steps = [0.004, 0.004, 0.004, 0.004, 0.2, 0.2];
    for round in 0..POLISH_ROUNDS {
        // The whole map in the first rounds; then only where it starts, finer.
        let parameters: &[usize] = if round < WHOLE_MAP_ROUNDS || !shift_free {
            whole
        } else {
            &[4, 5]
        };
        let mut moved = true;
        while moved && best.0 > 0 {
            moved = false;
            for &i in parameters {
                for sign in [-1.0, 1.0] {
                    let mut values = best.1;
                    values[i] += sign * steps[i];
                    let score = scorer.sampled_score(&with(values));
                    if score < best.0 {
                        best = (score, values);
                        moved = true;
                    }
                }
            }
        }
        for s in &mut steps {
            *s *= 0.5;
        }
    }
    with(best.1)
}

/// `model` with its pixel map's axes swapped (a map turned a quarter is diagonal so).
pub(super) fn turned_a_quarter(model: &Model) -> Model {
    let mut turned = *model;
    let axes = model.pixels.axes_world;
    turned.pixels.axes_world = glam::DMat2::from_cols(axes.y_axis, axes.x_axis);
    turned
}

/// Whether `model`'s pixel map and tilt are the course's or those of a known mistake.
pub(super) fn is_named_map(view: &crate::render::View, model: &Model) -> bool {
    named_geometry(view)
        .iter()
        .any(|(_, point)| point.pixels == model.pixels && point.t_ramp == model.t_ramp)
}

/// `model` without its tilt where the map, moved on the images without it, draws them nearly as
/// well (within a thousandth of the pixels compared): a sample a fraction of a pixel off moves
/// each depth by a little, which a tilt of a few grey levels can stand in for.
pub(super) fn untilted_if_as_good(scorer: &mut Scorer<'_>, model: Model, step: f64) -> Model {
    if model.t_ramp == glam::DVec3::ZERO || scorer.theirs.depth.is_none() {
        return model;
    }
    // A named point's tilt (the up vector as written) is a word of its own; a tilt of many
    // levels is more than a sample a fraction of a pixel off can stand in for.
    let view = *scorer.view;
    let corner = |x: u32, y: u32| {
        model
            .pixels
            .screen_of(DVec2::new(f64::from(x), f64::from(y)))
    };
    let extent = (corner(view.width_px, view.height_px) - corner(0, 0)).abs();
    let levels = (model.t_ramp.x.abs() * extent.x + model.t_ramp.y.abs() * extent.y)
        * model.depth.per_unit.abs()
        * 255.0;
    if is_named_map(&view, &model) || levels > SMALL_TILT_LEVELS {
        return model;
    }
    let mut untilted = model;
    untilted.t_ramp = glam::DVec3::ZERO;
    for _ in 0..2 {
        untilted = polish_with_images(scorer, &untilted, step);
        untilted = fit_depth_untilted(scorer, &untilted);
    }
    let margin = (scorer.compared_pixels() / 1000).max(10);
    if scorer.score(&untilted) <= scorer.score(&model) + margin {
        untilted
    } else {
        model
    }
}
