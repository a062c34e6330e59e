//! Which statements the images need, and how far their values round: a statement left out
//! that leaves no more pixels unexplained than the images allow goes; a fitted value near a known
//! mistake is tried as that word; values are rounded as coarsely as the pixels left allow; a
//! depth range at the image's own nearest and farthest hits is said as normalised per image.

use glam::DVec2;

use super::describe::rebuild;
use super::deviation::{Deviation, PerImage};
use super::fit::score::Scorer;
use super::mistake::Mistake;
use super::model::{Model, Quantity};

/// Share of the exact render's differing pixels each statement must explain on its own (the
/// pixels that differ again when it is left out); one pixel at least.
pub(super) const NEEDED_SHARE: f64 = 0.01;

/// Share of all compared pixels a fitted value (not a known mistake) must explain on its own,
/// besides [`NEEDED_SHARE`] of the differing ones (or half of those, when they are fewer).
const FITTED_SHARE_OF_ALL: f64 = 0.001;

/// `statements` without those the images do not need (the cheapest to leave out first), and the
/// pixels the rest leave.
pub(super) fn needed(
    scorer: &mut Scorer<'_>,
    mut statements: Vec<Deviation>,
    differing_exact: usize,
) -> (Vec<Deviation>, usize) {
    let view = *scorer.view;
    let needed_px = (NEEDED_SHARE * differing_exact as f64).max(1.0);
    // A fitted value must also explain a share of the image itself: any value can be tuned to
    // catch a handful of pixels.
    let fitted_px = needed_px.max(
        (FITTED_SHARE_OF_ALL * scorer.compared_pixels() as f64).min(0.5 * differing_exact as f64),
    );
    let mut left = scorer.score(&rebuild(&view, &statements));
    loop {
        // Each statement left out, or a fitted value replaced by the known mistake nearest it;
        // with the pixels it must explain to stay.
        let mut simpler: Vec<(usize, f64, Vec<Deviation>)> = Vec::new();
        for (i, statement) in statements.iter().enumerate() {
            let threshold = if matches!(statement, Deviation::Word(_)) {
                needed_px
            } else {
                fitted_px
            };
            let mut without = statements.clone();
            without.remove(i);
            if let Some(named) = nearest_word(statement) {
                let mut replaced = without.clone();
                replaced.insert(i, named);
                simpler.push((0, threshold, replaced));
            }
            simpler.push((1, threshold, without));
        }
        let cheapest = simpler
            .into_iter()
            .map(|(order, threshold, candidate)| {
                let score = scorer.score(&rebuild(&view, &candidate));
                (score, order, threshold, candidate)
            })
            .filter(|(score, _, threshold, _)| {
                *score <= left || ((*score - left) as f64) < *threshold
            })
            .min_by_key(|(score, order, _, _)| (*score, *order));
        match cheapest {
            Some((score, _, _, candidate)) => {
                statements = candidate;
                left = score;
            }
            None => return (statements, left),
        }
    }
}

/// The known mistake a fitted statement comes nearest to, where it has one: a sample offset
/// near a pixel's corner is `pixel-corners`.
pub(super) fn nearest_word(statement: &Deviation) -> Option<Deviation> {
    match statement {
        Deviation::SampleOffset { offset_px } if offset_px.abs().max_element() < 0.25 => {
            Some(Deviation::Word(Mistake::PixelCorners))
        }
        Deviation::Tmin { tmin } if tmin.abs() < 0.05 => Some(Deviation::Word(Mistake::TminZero)),
        Deviation::NearRootOnly { tmin } if (tmin + 1.0).abs() < 0.05 => {
            Some(Deviation::Word(Mistake::TminMinusOne))
        }
        _ => None,
    }
}

/// The statements' values rounded as far as the pixels left allow.
pub(super) fn rounded(
    scorer: &mut Scorer<'_>,
    mut statements: Vec<Deviation>,
    left: usize,
) -> Vec<Deviation> {
    let view = *scorer.view;
    let round = |v: f64, decimals: i32| {
        let scale = 10f64.powi(decimals);
        (v * scale).round() / scale
    };
    for i in 0..statements.len() {
        for decimals in 1..=6 {
            let candidate = match statements[i] {
                Deviation::SampleOffset { offset_px } => Deviation::SampleOffset {
                    offset_px: offset_px.map(|v| round(v, decimals)),
                },
                Deviation::CropNotCentred { offset_px } => Deviation::CropNotCentred {
                    offset_px: offset_px.map(|v| round(v, decimals)),
                },
                Deviation::Scaled { factor } => {
                    // The same factor on both axes first (a zoom), then each its own.
                    let mean = 0.5 * (factor.x + factor.y);
                    let mut with = statements.clone();
                    with[i] = Deviation::Scaled {
                        factor: DVec2::splat(round(mean, decimals + 1)),
                    };
                    if factor.x != factor.y && scorer.score(&rebuild(&view, &with)) <= left {
                        statements = with;
                        break;
                    }
                    Deviation::Scaled {
                        factor: factor.map(|v| round(v, decimals)),
                    }
                }
                Deviation::Axes { relative }
                    if relative.x_axis.x > 0.0 && relative.y_axis.y > 0.0 =>
                {
                    // A map the images hardly tell from a plain scale (a lone disc turns
                    // freely): the scale.
                    let diagonal = DVec2::new(relative.x_axis.x, relative.y_axis.y);
                    Deviation::Scaled {
                        factor: diagonal.map(|v| round(v, decimals + 2)),
                    }
                }
                Deviation::SwappedAxes { relative } => {
                    // A picture that looks the same swapped (a lone disc at the centre): each
                    // axis's scale, unswapped.
                    Deviation::Scaled {
                        factor: DVec2::new(relative.x_axis.y.abs(), relative.y_axis.x.abs())
                            .map(|v| round(v, decimals + 2)),
                    }
                }
                Deviation::Tilt { per_unit } => Deviation::Tilt {
                    per_unit: per_unit.map(|v| round(v, decimals)),
                },
                Deviation::Tmin { tmin } => Deviation::Tmin {
                    tmin: round(tmin, decimals),
                },
                Deviation::NearRootOnly { tmin } => Deviation::NearRootOnly {
                    tmin: round(tmin, decimals),
                },
                _ => break,
            };
            let mut with = statements.clone();
            with[i] = candidate;
            if scorer.score(&rebuild(&view, &with)) <= left {
                statements = with;
                break;
            }
        }
    }
    statements
}

/// A `depth-range` statement whose ends are the nearest and farthest hits of the image at round
/// greys (multiples of a tenth of white) is said as normalised per image.
pub(super) fn per_image(scorer: &mut Scorer<'_>, statements: &mut [Deviation], model: &Model) {
    if model.depth.quantity != Quantity::T {
        return;
    }
    let hits = scorer.hits(model);
    let (near_t, far_t) = hits
        .t
        .iter()
        .filter(|t| t.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    if near_t.partial_cmp(&far_t) != Some(std::cmp::Ordering::Less) {
        return;
    }
    let grey = |t: f64| 255.0 * model.depth.value(t);
    let round_grey = |g: f64| (g / 25.5 - (g / 25.5).round()).abs() * 25.5 <= 1.0;
    for statement in statements.iter_mut() {
        if let Deviation::DepthRange { per_image, .. } = statement {
            let (near_grey, far_grey) = (grey(near_t), grey(far_t));
            if round_grey(near_grey) && round_grey(far_grey) && (near_grey - far_grey).abs() > 25.0
            {
                *per_image = Some(PerImage {
                    near_t,
                    near_grey: (near_grey / 25.5).round() * 25.5,
                    far_t,
                    far_grey: (far_grey / 25.5).round() * 25.5,
                });
            }
        }
    }
}
