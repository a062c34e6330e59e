//! The depth range behind a depth image, when its maker does not remember it: a straight line
//! fitted to the image's grey levels against the exact t of each pixel (the ramp between the
//! clamped ends), read back as the t shown white and the t shown black, then rounded to the
//! coarsest step (1, ½, ¼, a tenth, …) that moves neither end by more than a level and a half
//! and draws their image as well as the fitted range (within a pixel in 2,000 of the ramp).
//!
//! A grey level g of the course's depth image is `255·(DMAX − t)/(DMAX − DMIN)` truncated, so the
//! pixel's true value lies in `[g, g + 1)`: the fit takes `g + ½` and drops what is off the line
//! by more than a few levels (another program's edge pixels, a mistake's spots) before fitting
//! again. Where white is far (`depth-reversed`), the line rises; where the picture is upside down
//! (`flipped-vertically`), or made with a mistake that changes where a pixel's ray hits
//! (`pixel-corners`, `stretched`, `no-square-root`, …), the t of that variant fits better: the
//! variant whose line holds the most pixels is taken. All are read back as the range the image was made over.

use image::RgbImage;

use super::difference::Difference;
use super::mistake::{Mistake, MistakeSet};
use super::variant::{Hits, depth_image, render_hits};
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::Scene;

/// Fewest pixels on the ramp a range is inferred from.
const MIN_RAMP_PIXELS: usize = 8;

/// The steps the range is rounded to, coarsest first, as denominators (1, ½, ¼, a tenth, …).
const STEPS_PER_UNIT: [f64; 9] = [1.0, 2.0, 4.0, 10.0, 20.0, 100.0, 1_000.0, 10_000.0, 1e6];

/// A line `level = a + b·t` fitted by least squares to `(t, level)` points.
fn fit_line(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    let mean_t = points.iter().map(|p| p.0).sum::<f64>() / n;
    let mean_level = points.iter().map(|p| p.1).sum::<f64>() / n;
    let (mut covariance, mut variance) = (0.0, 0.0);
    for &(t, level) in points {
        covariance += (t - mean_t) * (level - mean_level);
        variance += (t - mean_t) * (t - mean_t);
    }
    if variance <= 0.0 || covariance == 0.0 {
        return None;
    }
    let b = covariance / variance;
    Some((mean_level - b * mean_t, b))
}

/// Levels a pixel may lie off the line fitted before, at each refit: wide first, so that a
/// first line pulled by outliers still keeps the ramp.
const INLIER_LEVELS: [f64; 3] = [16.0, 4.0, 1.5];

/// The line through the ramp's pixels against `hits`'s t (upside down: the image's rows taken
/// from the bottom), refitted without the pixels off it; and how many pixels it holds.
fn fit_ramp(hits: &Hits, theirs: &RgbImage, upside_down: bool) -> Option<((f64, f64), usize)> {
    let (width, height) = theirs.dimensions();
    let mut points = Vec::new();
    for (x, row, pixel) in theirs.enumerate_pixels() {
        let [r, g, b] = pixel.0;
        if r != g || g != b || g == 0 || g == 255 {
            continue;
        }
        let source_row = if upside_down { height - 1 - row } else { row };
        let t = hits.t[(source_row * width + x) as usize];
        if t.is_finite() {
            points.push((t, f64::from(g) + 0.5));
        }
    }
    if points.len() < MIN_RAMP_PIXELS {
        return None;
    }
    let mut line = fit_line(&points)?;
    let mut inliers = points.clone();
    for levels in INLIER_LEVELS {
        inliers = points
            .iter()
            .copied()
            .filter(|&(t, level)| (line.0 + line.1 * t - level).abs() <= levels)
            .collect();
        if inliers.len() < MIN_RAMP_PIXELS {
            return None;
        }
        line = fit_line(&inliers)?;
    }
    (inliers.len() >= points.len() / 2).then_some((line, inliers.len()))
}

/// The t each pixel of another program's image may have been drawn from: the exact one, and
/// each mistake that changes which sphere a pixel hits or where (alone, with `pixel-corners`, and
/// with `pixel-corners` and `stretched`, the placements most programs share).
fn hit_variants() -> Vec<MistakeSet> {
    let placed = [
        MistakeSet::NONE,
        MistakeSet::of(&[Mistake::PixelCorners]),
        MistakeSet::of(&[Mistake::PixelCorners, Mistake::Stretched]),
    ];
    let mut sets = vec![MistakeSet::NONE];
    for mistake in Mistake::ALL.into_iter().filter(|m| m.changes_hits()) {
        for base in placed {
            let set = base.with(mistake);
            if !sets.contains(&set) {
                sets.push(set);
            }
        }
    }
    sets
}

/// How far an end of the range may be moved to round it, in grey levels of the range.
const ROUNDING_LEVELS: f64 = 1.5;

/// The range `[DMIN, DMAX]` their depth image of `scene` was most likely made over, through
/// `view`'s camera at their size (see the module docs); `None` when the image holds no ramp to
/// fit (every pixel black or white, too few pixels, or no straight line).
pub fn infer_depth_range(scene: &Scene, view: &View, theirs: &RgbImage) -> Option<DepthRange> {
    let (width_px, height_px) = theirs.dimensions();
    let view = View {
        width_px,
        height_px,
        ..*view
    };
    // The placement and orientation whose line holds the most pixels.
    let mut best: Option<((f64, f64), usize, Hits, bool)> = None;
    for variant in hit_variants() {
        let hits = render_hits(scene, &view, variant);
        let mut found = None;
        for upside_down in [false, true] {
            if let Some((line, held)) = fit_ramp(&hits, theirs, upside_down)
                && best.as_ref().is_none_or(|(_, most, _, _)| held > *most)
                && found.is_none_or(|(_, most, _): (_, usize, _)| held > most)
            {
                found = Some((line, held, upside_down));
            }
        }
        if let Some((line, held, upside_down)) = found {
            best = Some((line, held, hits, upside_down));
        }
    }
    let ((a, b), held, hits, upside_down) = best?;
    // White (level 255) and black (level 0) along the line; a rising line is a reversed ramp.
    let (white_t, black_t) = ((255.0 - a) / b, -a / b);
    if !white_t.is_finite() || !black_t.is_finite() {
        return None;
    }
    let fitted = DepthRange::new(white_t.min(black_t), white_t.max(black_t));
    // How many pixels of their image a range draws otherwise (by any level: the course's rule
    // allows few off by one), from the variant's t as the fit saw it.
    let mut made_with = MistakeSet::NONE;
    if b > 0.0 {
        made_with = made_with.with(Mistake::DepthReversed);
    }
    if upside_down {
        made_with = made_with.with(Mistake::FlippedVertically);
    }
    let differing = |range: DepthRange| {
        let view = View {
            depth_range: range,
            ..view
        };
        Difference::of(&depth_image(&view, &hits, made_with), theirs).pixels_differing()
    };
    let fitted_differing = differing(fitted);
    let allowed = fitted_differing + (held / 2000).max(1);
    // The coarsest rounding that moves neither end by more than the fit can tell, and draws
    // their image as well as the fitted range does (a rounding that moves an end by most of a
    // level shows as pixels off).
    let slack = ROUNDING_LEVELS * (fitted.max_t - fitted.min_t) / 255.0;
    let round = |value: f64, per_unit: f64| (value * per_unit).round() / per_unit;
    STEPS_PER_UNIT
        .iter()
        .map(|&per_unit| {
            DepthRange::new(round(fitted.min_t, per_unit), round(fitted.max_t, per_unit))
        })
        .find(|&range| {
            range.min_t < range.max_t
                && (range.min_t - fitted.min_t).abs() <= slack
                && (range.max_t - fitted.max_t).abs() <= slack
                && differing(range) <= allowed
        })
        .or(Some(fitted))
}
