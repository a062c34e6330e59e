//! Fitting how their depth image was drawn from the hits: a straight line from a quantity of
//! each hit (t, |t|, a coordinate of the hit point) to their grey levels, by least squares on the
//! ramp's pixels (those neither black nor white), dropping what lies off the line by more than a
//! few levels and fitting again; with t, a tilt across the image too (ray origins that slide
//! along the direction). Then the colour of the pixels no ray hits, the rule for values outside
//! the range, and the named points nearby: the range of the view (given, or as the user's
//! program may have misread it: reversed, t not along the unit direction), and round numbers
//! for the ends of the range.
//!
//! A grey level g of the course's depth image is `255·value` truncated, so the pixel's true
//! value lies in `[g, g + 1)`: the fit takes `g + ½` (`g` where levels are rounded).

use glam::DVec3;

use super::score::Scorer;
use crate::compare::model::{DepthMap, Model, Outside, Quantity, colour_bytes};
use crate::compare::model_render::{Frame, Hits, depth_quantity};
use crate::render::depth_map::DepthRange;

/// Fewest ramp pixels a line is fitted to.
const MIN_RAMP_PIXELS: usize = 8;

/// Levels a pixel may lie off the line fitted before, at each refit.
const INLIER_LEVELS: [f64; 3] = [16.0, 4.0, 1.5];

/// The steps the ends of a range are rounded to, coarsest first, as denominators.
const STEPS_PER_UNIT: [f64; 9] = [1.0, 2.0, 4.0, 10.0, 20.0, 100.0, 1_000.0, 10_000.0, 1e6];

/// Grey levels a tilt must move t by across the image to be fitted.
const MIN_TILT_LEVELS: f64 = 4.0;

/// How far an end of the range may be moved to round it, in grey levels of the range.
const ROUNDING_LEVELS: f64 = 1.5;

/// Least squares of `target ≈ Σ cᵢ·xᵢ` over `rows` of `N` regressors.
fn least_squares<const N: usize>(rows: &[([f64; N], f64)]) -> Option<[f64; N]> {
    let mut a = [[0.0; N]; N];
    let mut b = [0.0; N];
    for (x, target) in rows {
        for i in 0..N {
            b[i] += x[i] * target;
            for j in 0..N {
                a[i][j] += x[i] * x[j];
            }
        }
    }
    for col in 0..N {
        let pivot = (col..N).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        // Also false for NaN: no solution.
        if a[pivot][col].abs().partial_cmp(&1e-12) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..N {
            let factor = a[row][col] / a[col][col];
            let pivot_row = a[col];
            for (value, above) in a[row].iter_mut().zip(pivot_row).skip(col) {
                *value -= factor * above;
            }
            b[row] -= factor * b[col];
        }
    }
    let mut x = [0.0; N];
    for row in (0..N).rev() {
        let mut sum = b[row];
        for k in row + 1..N {
            sum -= a[row][k] * x[k];
        }
        x[row] = sum / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The line (or plane) through `rows`, refitted without the rows off it; `None` when too few
/// rows hold it or fewer than half.
fn robust_fit<const N: usize>(rows: &[([f64; N], f64)]) -> Option<[f64; N]> {
    if rows.len() < MIN_RAMP_PIXELS {
        return None;
    }
    let mut fit = least_squares(rows)?;
    let predict = |fit: &[f64; N], x: &[f64; N]| (0..N).map(|i| fit[i] * x[i]).sum::<f64>();
    let mut held = rows.len();
    for levels in INLIER_LEVELS {
        let inliers: Vec<([f64; N], f64)> = rows
            .iter()
            .filter(|(x, target)| (predict(&fit, x) - target).abs() <= levels)
            .copied()
            .collect();
        if inliers.len() < MIN_RAMP_PIXELS {
            return None;
        }
        held = inliers.len();
        fit = least_squares(&inliers)?;
    }
    (held >= rows.len() / 2).then_some(fit)
}

/// Most ramp pixels a line is fitted to: a larger ramp (a large image) is sampled evenly, to
/// bound the time of the fits.
const MAX_RAMP_PIXELS: usize = 65_536;

/// Their grey ramp: the pixels neither black nor white where the model hits, with the level
/// each stands for (`g + ½`, or `g` where levels are rounded); at most [`MAX_RAMP_PIXELS`].
fn ramp_pixels(theirs: &image::RgbImage, hits: &Hits, rounded: bool) -> Vec<(usize, f64)> {
    let half_level = if rounded { 0.0 } else { 0.5 };
    let ramp: Vec<(usize, f64)> = theirs
        .pixels()
        .enumerate()
        .filter_map(|(index, pixel)| {
            let [r, g, b] = pixel.0;
            (r == g && g == b && g != 0 && g != 255 && hits.t[index].is_finite())
                .then_some((index, f64::from(g) + half_level))
        })
        .collect();
    if ramp.len() <= MAX_RAMP_PIXELS {
        return ramp;
    }
    let every = ramp.len().div_ceil(MAX_RAMP_PIXELS);
    ramp.into_iter().step_by(every).collect()
}

/// What a program may do with a value outside the range (besides drawing it in a colour): the
/// one list both the fitted and the named maps try.
const OUTSIDE_RULES: [Outside; 3] = [Outside::Clamp, Outside::Wrap, Outside::Black];

/// The quantities a depth image may map.
const QUANTITIES: [Quantity; 8] = [
    Quantity::T,
    Quantity::AbsT,
    Quantity::Coordinate(0),
    Quantity::Coordinate(1),
    Quantity::Coordinate(2),
    Quantity::AbsCoordinate(0),
    Quantity::AbsCoordinate(1),
    Quantity::AbsCoordinate(2),
];

/// The model with the depth map (and, with t, the tilt) that draws their depth image best.
pub fn fit_depth(scorer: &mut Scorer<'_>, model: &Model) -> Model {
    fit_depth_tilted_or_not(scorer, model, true)
}

/// [`fit_depth`] with the model's tilt kept as it is (no tilt fitted).
pub fn fit_depth_untilted(scorer: &mut Scorer<'_>, model: &Model) -> Model {
    fit_depth_tilted_or_not(scorer, model, false)
}

/// [`fit_depth`], with a tilt fitted or not.
fn fit_depth_tilted_or_not(scorer: &mut Scorer<'_>, model: &Model, tilt: bool) -> Model {
    let Some(theirs) = scorer.theirs.depth else {
        return *model;
    };
    let view = *scorer.view;
    let hits = scorer.hits(model);
    let ramp = ramp_pixels(theirs, &hits, model.rounded);
    let mut candidates = vec![*model];
    let mut tilted = None;
    let frame = Frame::of(&view);
    for quantity in QUANTITIES {
        let mut with = *model;
        with.depth.quantity = quantity;
        let rows: Vec<([f64; 2], f64)> = ramp
            .iter()
            .map(|&(index, level)| {
                let (x, row) = (index as u32 % hits.width_px, index as u32 / hits.width_px);
                let q = depth_quantity(&view, &frame, &with, hits.t[index], x, row);
                ([1.0, q], level)
            })
            .collect();
        if let Some([a, b]) = robust_fit(&rows) {
            let mut fitted = with;
            fitted.depth.at_zero = a / 255.0;
            fitted.depth.per_unit = b / 255.0;
            candidates.push(fitted);
        }
        if tilt && quantity == Quantity::T {
            tilted = tilted_fit(&hits, model, &with, &ramp);
        }
    }
    let mut best = pick(scorer, &candidates, *model);
    // A tilt only where it draws clearly more pixels right: two more numbers fit some of the
    // noise of the grey levels.
    if let Some(tilted) = tilted {
        let margin = (scorer.sampled_pixels() / 1000).max(10);
        if scorer.sampled_score(&tilted) + margin < scorer.sampled_score(&best) {
            best = tilted;
        }
    }
    // The colour where nothing is hit, and values outside the range.
    let no_hit_seen = most_common_where(theirs, &hits.t, |t| t == f64::INFINITY);
    let background = colour_bytes(scorer.scene.background, best.rounded);
    let mut more = Vec::new();
    for no_hit in [[0; 3], no_hit_seen.unwrap_or([0; 3]), background] {
        for outside in OUTSIDE_RULES.into_iter().chain([Outside::Colour(no_hit)]) {
            let mut with = best;
            with.depth.no_hit = no_hit;
            with.depth.outside = outside;
            more.push(with);
        }
    }
    best = pick(scorer, &more, best);
    best = round_range(scorer, best);
    snap_to_range(scorer, best)
}

/// The depth map of `with` fitted to t plus a tilt, `t + ramp_u·u + ramp_v·v` at each pixel's
/// screen point, where the tilt moves the grey by a few levels across the image (less is the
/// noise of the levels themselves).
fn tilted_fit(hits: &Hits, model: &Model, with: &Model, ramp: &[(usize, f64)]) -> Option<Model> {
    let (width, height) = (hits.width_px, hits.height_px);
    let screen = |index: usize| {
        let (x, row) = ((index as u32 % width), (index as u32 / width));
        let pixel = glam::DVec2::new(f64::from(x), f64::from(height - 1 - row));
        model.pixels.screen_of(pixel)
    };
    let rows: Vec<([f64; 4], f64)> = ramp
        .iter()
        .map(|&(index, level)| {
            let s = screen(index);
            ([1.0, hits.t[index], s.x, s.y], level)
        })
        .collect();
    let spread = |axis: usize| {
        let values = ramp.iter().map(|&(index, _)| screen(index)[axis]);
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        (hi - lo).max(0.0)
    };
    let [a, b, cx, cy] = robust_fit(&rows)?;
    if b == 0.0 || cx.abs() * spread(0) + cy.abs() * spread(1) < MIN_TILT_LEVELS {
        return None;
    }
    let mut fitted = *with;
    fitted.depth.at_zero = a / 255.0;
    fitted.depth.per_unit = b / 255.0;
    fitted.t_ramp = DVec3::new(
        model.t_ramp.x + cx / b,
        model.t_ramp.y + cy / b,
        model.t_ramp.z,
    );
    Some(fitted)
}

/// The model with the depth map of `model`, or of the range asked for, or a line fitted to t,
/// whichever draws their depth image best: the few candidates a search over hit rules can
/// afford for each rule it tries ([`fit_depth`] fits the rule it keeps in full).
pub fn fit_depth_quickly(scorer: &mut Scorer<'_>, model: &Model) -> Model {
    let Some(theirs) = scorer.theirs.depth else {
        return *model;
    };
    let hits = scorer.hits(model);
    let ramp = ramp_pixels(theirs, &hits, model.rounded);
    let rows: Vec<([f64; 2], f64)> = ramp
        .iter()
        .map(|&(index, level)| ([1.0, hits.t[index]], level))
        .collect();
    let mut candidates = Vec::new();
    let given = DepthMap::of_range(scorer.view.depth_range);
    let line = robust_fit(&rows);
    // The model's rules for outside and no hit, and the course's.
    for (outside, no_hit) in [
        (model.depth.outside, model.depth.no_hit),
        (Outside::Clamp, [0; 3]),
    ] {
        let mut with_given = *model;
        with_given.depth = DepthMap {
            outside,
            no_hit,
            ..given
        };
        candidates.push(with_given);
        if let Some([a, b]) = line {
            let mut fitted = with_given;
            fitted.depth.at_zero = a / 255.0;
            fitted.depth.per_unit = b / 255.0;
            candidates.push(fitted);
        }
        // A rule can move the hits so that the tilt fitted before no longer fits.
        let mut with_t = with_given;
        with_t.depth.quantity = Quantity::T;
        candidates.extend(tilted_fit(&hits, model, &with_t, &ramp));
    }
    pick(scorer, &candidates, *model)
}

/// The candidate whose images differ from theirs in the fewest pixels (the first on a tie).
fn pick(scorer: &mut Scorer<'_>, candidates: &[Model], first: Model) -> Model {
    let all: Vec<Model> = std::iter::once(first)
        .chain(candidates.iter().copied())
        .collect();
    scorer
        .sampled_best_of(&all)
        .map_or(first, |(index, _)| all[index])
}

/// The most common colour of `image` among pixels whose t satisfies `keep`.
fn most_common_where(
    image: &image::RgbImage,
    t: &[f64],
    keep: impl Fn(f64) -> bool,
) -> Option<[u8; 3]> {
    let mut counts: std::collections::HashMap<[u8; 3], usize> = std::collections::HashMap::new();
    for (pixel, &t) in image.pixels().zip(t) {
        if keep(t) {
            *counts.entry(pixel.0).or_default() += 1;
        }
    }
    counts
        .into_iter()
        .max_by_key(|&(colour, count)| (count, colour))
        .map(|(colour, _)| colour)
}

/// The view's range, as given or as a program may misread it (reversed, t along the direction
/// as written), where it draws their image as well as the fit.
fn snap_to_range(scorer: &mut Scorer<'_>, fitted: Model) -> Model {
    let view = *scorer.view;
    let given = DepthMap::of_range(view.depth_range);
    let mut candidates = Vec::new();
    for reversed in [false, true] {
        for scaled in [false, true] {
            let mut map = given;
            if scaled {
                map.per_unit /= view.direction_world.length();
            }
            if reversed {
                map.at_zero = 1.0 - map.at_zero;
                map.per_unit = -map.per_unit;
            }
            let rules = [[0; 3], fitted.depth.no_hit]
                .into_iter()
                .flat_map(|no_hit| OUTSIDE_RULES.map(|outside| (outside, no_hit)));
            for (outside, no_hit) in
                std::iter::once((fitted.depth.outside, fitted.depth.no_hit)).chain(rules)
            {
                let mut with = fitted;
                with.depth = DepthMap {
                    outside,
                    no_hit,
                    ..map
                };
                with.t_ramp = DVec3::ZERO;
                candidates.push(with);
                let mut tilted = with;
                tilted.t_ramp = fitted.t_ramp;
                candidates.push(tilted);
            }
        }
    }
    let fitted_score = scorer.sampled_score(&fitted);
    // The named map that draws best (the first on a tie), where it draws as well as the fit.
    match scorer.sampled_best_of(&candidates) {
        Some((index, score)) if score <= fitted_score => candidates[index],
        _ => fitted,
    }
}

/// Pixels of the sample ([`Scorer::samples`]) where `model`'s depth image differs from theirs by
/// any level.
fn levels_off(scorer: &mut Scorer<'_>, model: &Model) -> usize {
    if scorer.theirs.depth.is_none() {
        return 0;
    }
    scorer.sampled_depth_levels_off(model)
}

/// The fitted range's ends rounded: of the steps that move neither end by more than the fit can
/// tell, the coarsest of those that draw their image best, and only where that is as well as
/// the fit's own ends (a range off by a tenth of a level still moves a few pixels across a
/// level, and the course's match allows few).
fn round_range(scorer: &mut Scorer<'_>, fitted: Model) -> Model {
    if fitted.depth.quantity != Quantity::T
        || fitted.depth == DepthMap::of_range(scorer.view.depth_range)
    {
        return fitted;
    }
    let (white, black) = fitted.depth.white_black_t();
    if !(white.is_finite() && black.is_finite()) || white == black {
        return fitted;
    }
    // Every step's rounding scored; the coarsest of those that draw best, the fit's own ends
    // where none draws as well. The score lets a level go; between equals, the grey levels
    // themselves must agree as the course's match asks (all but 0.1% of the pixels).
    let slack = ROUNDING_LEVELS * (white - black).abs() / 255.0;
    let round = |value: f64, per_unit: f64| (value * per_unit).round() / per_unit;
    let mut candidates = vec![fitted];
    for per_unit in STEPS_PER_UNIT {
        let (w, b) = (round(white, per_unit), round(black, per_unit));
        if w == b || (w - white).abs() > slack || (b - black).abs() > slack {
            continue;
        }
        let mut with = fitted;
        let map = DepthMap::of_range(DepthRange::new(w, b));
        with.depth.at_zero = map.at_zero;
        with.depth.per_unit = map.per_unit;
        candidates.push(with);
    }
    let scores: Vec<usize> = candidates
        .iter()
        .map(|candidate| scorer.sampled_score(candidate))
        .collect();
    let best_score = scores.iter().copied().min().unwrap_or(0);
    // The levels counted only where the score is the best (nowhere else are they compared).
    let scored: Vec<(usize, usize, Model)> = candidates
        .iter()
        .zip(scores)
        .map(|(candidate, score)| {
            let off = if score == best_score {
                levels_off(scorer, candidate)
            } else {
                usize::MAX
            };
            (score, off, *candidate)
        })
        .collect();
    let fewest_off = scored
        .iter()
        .filter(|s| s.0 == best_score)
        .map(|s| s.1)
        .min()
        .unwrap_or(0);
    let allowed_off = fewest_off + scorer.sampled_pixels() / 1000;
    // The rounded ends from the coarsest step; the fit's own last.
    let rounded = scored[1..]
        .iter()
        .chain(&scored[..1])
        .find(|s| s.0 == best_score && s.1 <= allowed_off);
    if let Some(&(_, _, chosen)) = rounded {
        return chosen;
    }
    fitted
}
