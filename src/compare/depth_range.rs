//! The depth range behind a depth image, when its maker does not remember it: the model of their
//! program fitted to the depth image alone ([`super::fit`]: where its rays start from the
//! silhouettes, which hits it draws, and a straight line from t to their grey levels on the
//! ramp between the clamped ends), read back as the t drawn white and the t drawn black, rounded
//! to the coarsest step (1, ½, ¼, a tenth, …) that moves neither end by more than a level and a
//! half and draws their image as well. A ramp whose white is far is read back as the same range
//! (the diagnosis then names `depth-reversed`).

use image::RgbImage;

use super::fit::fit;
use super::fit::score::{Scorer, Theirs};
use super::model::Quantity;
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::Scene;

/// The range `[DMIN, DMAX]` their depth image of `scene` was most likely made over, through
/// `view`'s camera at their size (see the module docs); `None` when the image holds no ramp to
/// fit (every pixel black or white, too few pixels, or no straight line from t).
pub fn infer_depth_range(scene: &Scene, view: &View, theirs: &RgbImage) -> Option<DepthRange> {
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
