//! Judging their images against the exact ones: the one procedure behind the command line's
//! `-compare_output`/`-compare_depth` and the viewer's Compare section, so that both give the
//! same answer for the same images.
//!
//! A depth image is judged under the range given, or, with none, under the range read back from
//! it: first from the depth image alone ([`infer_depth_range`]), then from the answer's own
//! model, kept where the exact images under it differ from theirs in fewer pixels. Given a
//! range, the range their image was drawn over is still read back from the answer, so a user
//! who gave the wrong one is told.

use image::RgbImage;

use super::depth_range::range_by_rank;
use super::describe::rebuild;
use super::fit::score::Scorer;
use super::model::{Model, Quantity};
use super::model_render::{self, depth_pixel, depth_quantity, hit_of_pixel};
use super::{
    Deviation, Diagnosis, Difference, RangeFrom, Theirs, Unexplained, Verdict, diagnose,
    infer_depth_range,
};
use crate::explore::trace::TheirDepth;
use crate::render::depth_map::DepthRange;
use crate::render::{Frame, View};
use crate::scene::Scene;

/// Their depth image was given without a range, and none could be read back from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("cannot infer the depth range it was made over (no grey ramp to fit)")]
pub struct NoDepthRange;

/// Their images judged: the range used, the differences and the answer.
#[derive(Debug, Clone)]
pub struct Judgement {
    /// The view judged: the scene's camera at their size, the depth range the depth image was
    /// judged under (given, or read back).
    pub view: View,
    /// With a depth image: the range it was most likely drawn over, as the answer reads it
    /// (`Some(None)`: none could be read, or depth is not of t). `None` without a depth image.
    pub depth_range_inferred: Option<Option<DepthRange>>,
    /// What their program does differently.
    pub diagnosis: Diagnosis,
    /// The exact colour image (with their colour image).
    pub exact_colour: Option<RgbImage>,
    /// The exact depth image under [`Self::view`]'s range (with their depth image).
    pub exact_depth: Option<RgbImage>,
    /// Their colour image against the exact one.
    pub colour: Option<Difference>,
    /// Their depth image against the exact one.
    pub depth: Option<Difference>,
}

impl Judgement {
    /// Whether the images match by the course's rule (colour identical; depth within one level on
    /// at most 0.1% of the pixels).
    pub fn matches(&self) -> bool {
        self.colour.as_ref().is_none_or(Difference::colour_matches)
            && self.depth.as_ref().is_none_or(Difference::depth_matches)
    }
}

/// Judges `theirs` (all of one size) against `exact`, the exact one-sample frame of the scene's
/// own camera at that size. `range`: the depth range their depth image was drawn over, or `None`
/// to read it back from the image ([`NoDepthRange`] when it has no ramp to read).
pub fn judge(
    scene: &Scene,
    exact: &Frame,
    theirs: Theirs<'_>,
    range: Option<DepthRange>,
) -> Result<Judgement, NoDepthRange> {
    let view = View::of_camera(
        &scene.camera,
        exact.width_px,
        exact.height_px,
        range.unwrap_or(DepthRange::new(0.0, 1.0)),
    );
    let mut depth_range_inferred = None;
    // A range read back by fitting the model, and one read by rank (what a mirror or a flip
    // keeps): the second is tried where the first is missing or its answer is not one brief
    // statement.
    let by_rank = match (theirs.depth, range) {
        (Some(depth), None) => range_by_rank(scene, &view, depth),
        _ => None,
    };
    let mut view = match (theirs.depth, range) {
        (Some(depth), None) => {
            let read = infer_depth_range(scene, &view, depth)
                .or(by_rank)
                .ok_or(NoDepthRange)?;
            depth_range_inferred = Some(Some(read));
            View {
                depth_range: read,
                ..view
            }
        }
        _ => view,
    };
    let mut diagnosis = diagnose(scene, &view, theirs);
    if let Some(ranked) = by_rank
        && ranked != view.depth_range
        && !(diagnosis.verdict == Verdict::Explained && diagnosis.stated().len() <= 1)
    {
        let other = View {
            depth_range: ranked,
            ..view
        };
        let again = diagnose(scene, &other, theirs);
        if answer_key(&again) < answer_key(&diagnosis) {
            depth_range_inferred = Some(Some(ranked));
            view = other;
            diagnosis = again;
        }
    }
    if theirs.depth.is_some() && range.is_none() {
        // Read back with both images, the range their program used may differ from the one the
        // depth image alone suggested: the answer's own is kept where the answer under it
        // explains more of their pixels, or as much with fewer statements, or as much as
        // briefly while the exact images under it differ from theirs in fewer pixels.
        if let Some(fitted) = stated_range(&diagnosis) {
            let refitted = diagnose(
                scene,
                &View {
                    depth_range: fitted,
                    ..view
                },
                theirs,
            );
            if answer_key(&refitted) < answer_key(&diagnosis) {
                depth_range_inferred = Some(Some(fitted));
                view.depth_range = fitted;
                diagnosis = refitted;
            }
        }
    }
    if range.is_none() {
        diagnosis = diagnosis.with_range_from(RangeFrom::ReadBack);
    }
    if theirs.depth.is_some() && range.is_some() {
        // The range their depth image was drawn over, as the answer reads it: the one given,
        // unless the answer says another (or a quantity other than t: none to read).
        depth_range_inferred = Some(model_range(&diagnosis));
    }
    let exact_colour = theirs.colour.map(|_| exact.colour_image());
    let exact_depth = theirs.depth.map(|_| exact.depth_image(view.depth_range));
    let difference = |a: Option<&RgbImage>, b: &Option<RgbImage>| match (a, b) {
        (Some(a), Some(b)) => Some(Difference::of(a, b)),
        _ => None,
    };
    Ok(Judgement {
        colour: difference(theirs.colour, &exact_colour),
        depth: difference(theirs.depth, &exact_depth),
        view,
        depth_range_inferred,
        diagnosis,
        exact_colour,
        exact_depth,
    })
}

/// How good an answer under a range read back is, smaller better: the pixels it leaves
/// unexplained, then how many statements it makes, then how many pixels the exact images under
/// that range differ in.
fn answer_key(answer: &Diagnosis) -> (usize, usize, usize) {
    (
        answer.unexplained_pixels(),
        answer.stated().len() + answer.partial().len(),
        answer.differing_exact,
    )
}

/// For each of `statements` (an answer's, said of `view`), the pixels it explains on its own:
/// those where the images drawn without it differ from `theirs` and the images drawn with all of
/// them do not. What a viewer highlights when a statement is pointed at.
pub fn explained_by_each(
    scene: &Scene,
    view: &View,
    theirs: Theirs<'_>,
    statements: &[Deviation],
) -> Vec<Unexplained> {
    let mut scorer = Scorer::new(scene, view, theirs);
    let with_all = scorer.unexplained(&rebuild(view, statements));
    let only = |without: &Option<Vec<bool>>, with: &Option<Vec<bool>>| match (without, with) {
        (Some(without), Some(with)) => Some(
            without
                .iter()
                .zip(with)
                .map(|(&without, &with)| without && !with)
                .collect(),
        ),
        _ => None,
    };
    (0..statements.len())
        .map(|i| {
            let mut without = statements.to_vec();
            without.remove(i);
            let left = scorer.unexplained(&rebuild(view, &without));
            Unexplained {
                colour: only(&left.colour, &with_all.colour),
                depth: only(&left.depth, &with_all.depth),
            }
        })
        .collect()
}

/// What their program drew at pixel (`x`, `y_up`) of their depth image, whose grey there is
/// `their_grey`, as `model` (an answer's model of their program, [`Diagnosis::stated_model`])
/// says: their no-hit grey, a hit outside their range, or a hit over their range;
/// [`TheirDepth::Unexplained`] where the model draws that pixel otherwise. `None` when their
/// depth is not of t.
pub fn their_depth_at(
    scene: &Scene,
    view: &View,
    model: &Model,
    (x, y_up): (u32, u32),
    their_grey: u8,
) -> Option<TheirDepth> {
    if model.depth.quantity != Quantity::T || x >= view.width_px || y_up >= view.height_px {
        return None;
    }
    let drawn = hit_of_pixel(scene, view, model, x, y_up);
    let t = drawn.map_or(f64::INFINITY, |(t, _)| t);
    let q = depth_quantity(
        view,
        &model_render::Frame::of(view),
        model,
        t,
        x,
        view.height_px - 1 - y_up,
    );
    if depth_pixel(model, q)[0] != their_grey {
        return Some(TheirDepth::Unexplained);
    }
    // As the answer says them: to nine decimals.
    let clean = |t: f64| (t * 1e9).round() / 1e9;
    let (white_t, black_t) = model.depth.white_black_t();
    let (white_t, black_t) = (clean(white_t), clean(black_t));
    Some(match drawn {
        None => TheirDepth::NoHit,
        Some(_) if !(0.0..=1.0).contains(&model.depth.value(q)) => {
            TheirDepth::Outside { white_t, black_t }
        }
        Some(_) => TheirDepth::Hit { white_t, black_t },
    })
}

/// The depth range a statement of the answer names (a range of t, one for all images).
fn stated_range(diagnosis: &Diagnosis) -> Option<DepthRange> {
    diagnosis
        .stated()
        .iter()
        .find_map(|statement| match statement {
            Deviation::DepthRange {
                white_t,
                black_t,
                per_image: None,
                ..
            } => Some(DepthRange::new(
                white_t.min(*black_t),
                white_t.max(*black_t),
            )),
            _ => None,
        })
}

/// The range of t the answer's model draws depth over (`None`: depth of another quantity, or no
/// finite range).
fn model_range(diagnosis: &Diagnosis) -> Option<DepthRange> {
    let depth = &diagnosis.model.depth;
    if depth.quantity != Quantity::T {
        return None;
    }
    let (white, black) = depth.white_black_t();
    let clean = |t: f64| (t * 1e9).round() / 1e9;
    (white.is_finite() && black.is_finite() && white != black)
        .then(|| DepthRange::new(clean(white.min(black)), clean(white.max(black))))
}
