//! The depth range behind a depth image, when its maker does not remember it: the model of their
//! program fitted to the depth image alone ([`super::fit`]: where its rays start from the
//! silhouettes, which hits it draws, and a straight line from t to their grey levels on the
//! ramp between the clamped ends), read back as the t drawn white and the t drawn black, rounded
//! to the coarsest step (1, ½, ¼, a tenth, …) that moves neither end by more than a level and a
//! half and draws their image as well. A ramp whose white is far is read back as the same range
//! (the diagnosis then names `depth-reversed`).

use image::RgbImage;

use super::diagnosis::MAX_FITTED_SPHERES;
use super::fit::fit;
use super::fit::score::{Scorer, Theirs};
use super::model::{Model, Quantity};
use super::model_render::render_hits;
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::Scene;

/// The range `[DMIN, DMAX]` their depth image of `scene` was most likely made over, through
/// `view`'s camera at their size (see the module docs); `None` when the image holds no ramp to
/// fit (every pixel black or white, too few pixels, or no straight line from t).
pub fn infer_depth_range(scene: &Scene, view: &View, theirs: &RgbImage) -> Option<DepthRange> {
    if scene.spheres.len() > MAX_FITTED_SPHERES {
        // No model is fitted to so many spheres: the range is read by rank alone.
        return None;
    }
    let (width_px, height_px) = theirs.dimensions();
    // A range no image is drawn over, so that the fit's line is its own.
    let view = View {
        width_px,
        height_px,
        depth_range: DepthRange::new(-1e300, 1e300),
        ..*view
    };
    let mut scorer = Scorer::new(
        scene,
        &view,
        Theirs {
            colour: None,
            depth: Some(theirs),
        },
    );
    let fitted = fit(&mut scorer);
    let depth = fitted.model.depth;
    if depth.quantity != Quantity::T || fitted.left >= fitted.differing_exact {
        return None;
    }
    let (white_t, black_t) = depth.white_black_t();
    // Ends as printed: the fit's own rounding, without the last bits of the division.
    let clean = |t: f64| (t * 1e9).round() / 1e9;
    let (white_t, black_t) = (clean(white_t), clean(black_t));
    (white_t.is_finite() && black_t.is_finite() && white_t != black_t)
        .then(|| DepthRange::new(white_t.min(black_t), white_t.max(black_t)))
}

/// Fewest pixels of their depth image's ramp (greys 1 … 254) a range is read from by rank.
const MIN_RAMP_PX: usize = 50;

/// Share by which the pixels their depth image hits may differ in number from the exact image's
/// for their greys to be read by rank.
const AREA_SLACK: f64 = 0.05;

/// The range their depth image was made over, read by rank: their greys of hit pixels, nearest
/// first, beside the exact t of the exact hits, nearest first, fitted by a straight line (near
/// white, or far white, whichever fits better), its ends rounded to the coarsest step that moves
/// neither by more than a level and a half. A picture moved pixel by pixel — mirrored, flipped,
/// turned — keeps its greys and only moves them, so this reads its range where a fit of where
/// its rays go cannot tell the picture's symmetries apart; `None` when their image hits a
/// different number of pixels (more than [`AREA_SLACK`] apart), or holds no ramp.
pub fn range_by_rank(scene: &Scene, view: &View, theirs: &RgbImage) -> Option<DepthRange> {
    let (width_px, height_px) = theirs.dimensions();
    let view = View {
        width_px,
        height_px,
        ..*view
    };
    let hits = render_hits(scene, &view, &Model::course(&view));
    let mut exact_t: Vec<f64> = hits.t.iter().copied().filter(|t| t.is_finite()).collect();
    let pixels = hits.t.len();
    // Their no-hit colour: the most common grey when it covers about as many pixels as the
    // exact image leaves empty, else black.
    let mut counts = [0usize; 256];
    for pixel in theirs.pixels() {
        counts[usize::from(pixel.0[0])] += 1;
    }
    let empty = pixels - exact_t.len();
    let (common, common_count) = (0..256).map(|g| (g, counts[g])).max_by_key(|&(_, c)| c)?;
    let no_hit = if (common_count as f64 - empty as f64).abs() <= AREA_SLACK * pixels as f64 {
        common
    } else {
        0
    };
    let mut greys: Vec<f64> = theirs
        .pixels()
        .map(|pixel| usize::from(pixel.0[0]))
        .filter(|&g| g != no_hit)
        .map(|g| g as f64)
        .collect();
    if exact_t.len() < MIN_RAMP_PX
        || (greys.len() as f64 - exact_t.len() as f64).abs() > AREA_SLACK * exact_t.len() as f64
    {
        return None;
    }
    exact_t.sort_by(f64::total_cmp);
    greys.sort_by(|a, b| b.total_cmp(a));
    let at_rank = |values: &[f64], rank: usize, of: usize| values[rank * values.len() / of];
    let of = exact_t.len().min(greys.len());
    // Near white: the i-th nearest t beside the i-th whitest grey; far white: the i-th
    // farthest.
    let fit = |reversed: bool| {
        let rows: Vec<(f64, f64)> = (0..of)
            .map(|i| {
                let t = if reversed {
                    at_rank(&exact_t, of - 1 - i, of)
                } else {
                    at_rank(&exact_t, i, of)
                };
                (t, at_rank(&greys, i, of))
            })
            .filter(|&(_, g)| (1.0..=254.0).contains(&g))
            .collect();
        line_through(&rows)
    };
    let (a, b, _) = [fit(false), fit(true)]
        .into_iter()
        .flatten()
        .min_by(|x, y| x.2.total_cmp(&y.2))?;
    if b == 0.0 {
        return None;
    }
    // grey + ½ = a + b·t: white at (255 − a)/b, black at −a/b.
    let (white_t, black_t) = ((255.0 - a) / b, -a / b);
    let level_t = (black_t - white_t).abs() / 255.0;
    let rounded = [1.0, 0.5, 0.25, 0.1, 0.05, 0.01, 0.001]
        .into_iter()
        .map(|step| {
            (
                (white_t / step).round() * step,
                (black_t / step).round() * step,
            )
        })
        .find(|&(w, k)| {
            (w - white_t).abs() <= 1.5 * level_t && (k - black_t).abs() <= 1.5 * level_t
        })
        .unwrap_or((white_t, black_t));
    let clean = |t: f64| (t * 1e9).round() / 1e9;
    let (white_t, black_t) = (clean(rounded.0), clean(rounded.1));
    (white_t.is_finite() && black_t.is_finite() && white_t != black_t)
        .then(|| DepthRange::new(white_t.min(black_t), white_t.max(black_t)))
}

/// The least-squares line `grey + ½ = a + b·t` through `rows` (t, grey): a, b and the mean
/// squared residual; `None` with fewer than [`MIN_RAMP_PX`] rows or no spread of t.
fn line_through(rows: &[(f64, f64)]) -> Option<(f64, f64, f64)> {
    if rows.len() < MIN_RAMP_PX {
        return None;
    }
    let n = rows.len() as f64;
    let mean_t = rows.iter().map(|r| r.0).sum::<f64>() / n;
    let mean_g = rows.iter().map(|r| r.1 + 0.5).sum::<f64>() / n;
    let spread: f64 = rows.iter().map(|r| (r.0 - mean_t).powi(2)).sum();
    if spread <= 0.0 {
        return None;
    }
    let b = rows
        .iter()
        .map(|r| (r.0 - mean_t) * (r.1 + 0.5 - mean_g))
        .sum::<f64>()
        / spread;
    let a = mean_g - b * mean_t;
    let residual = rows
        .iter()
        .map(|r| (r.1 + 0.5 - a - b * r.0).powi(2))
        .sum::<f64>()
        / n;
    Some((a, b, residual))
}
