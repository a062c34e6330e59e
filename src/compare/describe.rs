//! From a model to its statements and back: [`describe`] says how a fitted [`Model`] differs from
//! the course's, as known mistakes where it sits on their points and as fitted values where it
//! does not; [`rebuild`] makes the model a list of statements describes. An answer's model is
//! always the one its statements rebuild, so what is said is what is scored.

use glam::{DMat2, DVec2, DVec3};

use super::deviation::{Deviation, RangeFrom};
use super::mistake::{Mistake, MistakeSet};
use super::model::{DepthMap, Model, Outside, PixelMap, Quantity, Visible, colour_bytes};
use crate::render::View;
use crate::scene::Scene;

/// Relative difference under which two fitted values are the same point.
const SAME: f64 = 1e-6;

/// Relative size under which a fitted matrix entry, or the difference of two fitted scales or
/// offsets (in pixels), is taken for zero: a fit stops anywhere in the range of values that draw
/// the same pixels, and a thousandth of a pixel across the image is not a claim to make.
const FITTED: f64 = 1e-3;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= FITTED * a.abs().max(b.abs()).max(1.0)
}

fn close2(a: DVec2, b: DVec2) -> bool {
    close(a.x, b.x) && close(a.y, b.y)
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= SAME * a.abs().max(b.abs()).max(1.0)
}

fn same2(a: DVec2, b: DVec2) -> bool {
    same(a.x, b.x) && same(a.y, b.y)
}

/// The pixel map as a program writes it: axes (a diagonal of signs and scales, or a matrix)
/// and where in its pixel each ray starts, in the program's own rows.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Placement {
    /// The axes in course pixel steps.
    relative: DMat2,
    /// Whether the axes are a diagonal.
    diagonal: bool,
    /// Where each ray starts in its pixel, in the program's rows (rows written top first count
    /// from the top).
    offset_px: DVec2,
}

impl Placement {
    fn of(map: &PixelMap, view: &View) -> Self {
        let relative = map.relative_axes(Model::step_world(view));
        let largest = relative
            .to_cols_array()
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        let diagonal = relative.x_axis.y.abs() <= FITTED * largest
            && relative.y_axis.x.abs() <= FITTED * largest;
        let own = map
            .sample_offset_px(view.width_px, view.height_px)
            .unwrap_or(DVec2::splat(0.5));
        let offset_px = if diagonal && relative.y_axis.y < 0.0 {
            DVec2::new(own.x, 1.0 - own.y)
        } else {
            own
        };
        Self {
            relative,
            diagonal,
            offset_px,
        }
    }

    fn map(&self, view: &View) -> PixelMap {
        let own = if self.diagonal && self.relative.y_axis.y < 0.0 {
            DVec2::new(self.offset_px.x, 1.0 - self.offset_px.y)
        } else {
            self.offset_px
        };
        PixelMap::of_relative(
            self.relative,
            own,
            view.width_px,
            view.height_px,
            Model::step_world(view),
        )
    }
}

/// The scales a non-square image's axes take at the named points `words` (stretched, raw-up).
fn named_scale(view: &View, words: MistakeSet) -> DVec2 {
    let model = Model::of_mistakes(view, words);
    let m = model.pixels.relative_axes(Model::step_world(view));
    DVec2::new(m.x_axis.x.abs(), m.y_axis.y.abs())
}

fn union(a: MistakeSet, b: MistakeSet) -> MistakeSet {
    MistakeSet::of(&[a.mistakes(), b.mistakes()].concat())
}

/// How `model` differs from the course's for `view` (its range the one asked for), in the
/// order the answer prints: known mistakes in their order, then the fitted values.
pub fn describe(scene: &Scene, view: &View, model: &Model) -> Vec<Deviation> {
    let mut words = MistakeSet::NONE;
    let mut more = Vec::new();
    let placement = Placement::of(&model.pixels, view);
    // Where rays start.
    if placement.diagonal {
        let m = placement.relative;
        if m.x_axis.x < 0.0 {
            words = words.with(Mistake::Mirrored);
        }
        if m.y_axis.y < 0.0 {
            words = words.with(Mistake::FlippedVertically);
        }
        let scale = DVec2::new(m.x_axis.x.abs(), m.y_axis.y.abs());
        let mut choices = vec![MistakeSet::NONE];
        if view.width_px != view.height_px {
            choices.push(MistakeSet::of(&[Mistake::Stretched]));
        }
        for choice in [
            MistakeSet::of(&[Mistake::RawUp]),
            MistakeSet::of(&[Mistake::RawUp, Mistake::Stretched]),
        ] {
            // Raw-up only where the tilt of t is its own.
            let point = Model::of_mistakes(view, union(words, choice));
            if (view.width_px != view.height_px || !choice.contains(Mistake::Stretched))
                && same(model.t_ramp.y, point.t_ramp.y)
            {
                choices.push(choice);
            }
        }
        let ratio = |choice: MistakeSet| scale / named_scale(view, choice);
        let exact = choices
            .iter()
            .copied()
            .find(|&c| same2(ratio(c), DVec2::ONE));
        let uniform = choices
            .iter()
            .copied()
            .find(|&c| close(ratio(c).x, ratio(c).y));
        match (exact, uniform) {
            (Some(choice), _) => words = union(words, choice),
            (None, Some(choice)) => {
                words = union(words, choice);
                more.push(Deviation::Scaled {
                    factor: DVec2::splat(ratio(choice).x),
                });
            }
            (None, None) => more.push(Deviation::Scaled { factor: scale }),
        }
    } else {
        let m = placement.relative;
        let largest = m.to_cols_array().iter().fold(0.0f64, |a, v| a.max(v.abs()));
        if m.x_axis.x.abs() <= FITTED * largest && m.y_axis.y.abs() <= FITTED * largest {
            more.push(Deviation::SwappedAxes { relative: m });
        } else {
            more.push(Deviation::Axes { relative: m });
        }
    }
    let offset = placement.offset_px;
    if close2(offset, DVec2::ZERO) {
        words = words.with(Mistake::PixelCorners);
    } else if !close2(offset, DVec2::splat(0.5)) {
        let strip = 0.5 * (f64::from(view.width_px) - f64::from(view.height_px)).abs();
        let off = (offset - DVec2::splat(0.5)).abs();
        let is_strip = view.width_px != view.height_px
            && ((off.x <= 0.5 && (off.y - strip).abs() <= 0.75 && view.width_px > view.height_px)
                || (off.y <= 0.5
                    && (off.x - strip).abs() <= 0.75
                    && view.height_px > view.width_px));
        if is_strip {
            more.push(Deviation::CropNotCentred { offset_px: offset });
        } else {
            more.push(Deviation::SampleOffset { offset_px: offset });
        }
    }
    let expected_ramp = if words.contains(Mistake::RawUp) {
        Model::of_mistakes(view, words).t_ramp
    } else {
        DVec3::ZERO
    };
    let tilt = DVec2::new(
        model.t_ramp.x - expected_ramp.x,
        model.t_ramp.y - expected_ramp.y,
    );
    if tilt != DVec2::ZERO && !same2(model.t_ramp.truncate(), expected_ramp.truncate()) {
        more.push(Deviation::Tilt { per_unit: tilt });
    }
    if let Some(drawn_px) = model.drawn_px {
        more.push(Deviation::OnlyBlock { drawn_px });
    }
    if let Some(grid) = model.samples {
        more.push(Deviation::SampleGrid {
            per_side: grid.per_side,
            last_wins: grid.last_wins,
        });
    }
    // Which hits are drawn.
    let rule = model.hits;
    match rule.visible {
        Visible::Nearest => {}
        Visible::FirstInFile => more.push(Deviation::NoDepthTest { last_wins: false }),
        Visible::LastInFile => more.push(Deviation::NoDepthTest { last_wins: true }),
    }
    if rule.later_wins_ties && rule.visible == Visible::Nearest {
        words = words.with(Mistake::LastWins);
    }
    if rule.far_only {
        words = words.with(Mistake::FarRoot);
    }
    match (rule.tmin, rule.far_when_near_refused || rule.far_only) {
        (tmin, _) if tmin == f64::NEG_INFINITY => {}
        (0.0, true) => words = words.with(Mistake::TminZero),
        (tmin, _) if tmin == -1.0 && (!rule.far_when_near_refused || rule.far_only) => {
            words = words.with(Mistake::TminMinusOne);
        }
        (tmin, true) if rule.far_when_near_refused && !rule.far_only => {
            more.push(Deviation::Tmin { tmin });
        }
        (tmin, _) => more.push(Deviation::NearRootOnly { tmin }),
    }
    if !rule.square_root {
        words = words.with(Mistake::NoSquareRoot);
    }
    // Bytes.
    if model.rounded {
        words = words.with(Mistake::Rounded);
    }
    let scene_background = colour_bytes(scene.background, model.rounded);
    if let Some(bytes) = model.background
        && bytes != scene_background
    {
        more.push(Deviation::Background {
            bytes,
            scene: scene_background,
        });
    }
    // The depth image.
    let depth = model.depth;
    if depth.quantity != Quantity::T {
        more.push(Deviation::DepthQuantity {
            quantity: depth.quantity,
        });
    }
    let given = DepthMap::of_range(view.depth_range);
    let scaled = |map: DepthMap| DepthMap {
        per_unit: map.per_unit / view.direction_world.length(),
        ..map
    };
    let reversed = |map: DepthMap| DepthMap {
        at_zero: 1.0 - map.at_zero,
        per_unit: -map.per_unit,
        ..map
    };
    let same_map = |a: DepthMap, b: DepthMap| {
        (same(a.at_zero, b.at_zero) && same(a.per_unit, b.per_unit))
            || (a.at_zero.is_nan() && b.at_zero.is_nan())
    };
    if same_map(depth, given) {
    } else if same_map(depth, reversed(given)) {
        words = words.with(Mistake::DepthReversed);
    } else if same_map(depth, scaled(given)) {
        words = words.with(Mistake::UnnormalizedDirection);
    } else if same_map(depth, reversed(scaled(given))) {
        words = words
            .with(Mistake::DepthReversed)
            .with(Mistake::UnnormalizedDirection);
    } else {
        let (white_t, black_t) = depth.white_black_t();
        more.push(Deviation::DepthRange {
            white_t,
            black_t,
            given: (view.depth_range.min_t, view.depth_range.max_t),
            per_image: None,
            from: RangeFrom::Given,
        });
    }
    match depth.outside {
        Outside::Clamp => {}
        Outside::Wrap => words = words.with(Mistake::DepthNoClamp),
        Outside::Black => words = words.with(Mistake::DepthOutsideBlack),
        Outside::Colour(bytes) => more.push(Deviation::DepthOutside { bytes }),
    }
    if depth.no_hit != [0; 3] {
        more.push(Deviation::DepthNoHit {
            bytes: depth.no_hit,
            scene_background,
        });
    }
    let mut all: Vec<Deviation> = words.mistakes().into_iter().map(Deviation::Word).collect();
    all.extend(more);
    all
}

/// The model the statements `deviations` describe, for `view`.
pub fn rebuild(view: &View, deviations: &[Deviation]) -> Model {
    let words = MistakeSet::of(
        &deviations
            .iter()
            .filter_map(|d| match d {
                Deviation::Word(m) => Some(*m),
                _ => None,
            })
            .collect::<Vec<_>>(),
    );
    let mut model = Model::of_mistakes(view, words);
    let mut placement = Placement::of(&model.pixels, view);
    for deviation in deviations {
        match *deviation {
            Deviation::SwappedAxes { relative } | Deviation::Axes { relative } => {
                let own = model
                    .pixels
                    .sample_offset_px(view.width_px, view.height_px)
                    .unwrap_or(DVec2::splat(0.5));
                placement = Placement {
                    relative,
                    diagonal: false,
                    offset_px: own,
                };
            }
            Deviation::Scaled { factor } => {
                placement.relative.x_axis *= factor.x;
                placement.relative.y_axis *= factor.y;
            }
            _ => {}
        }
    }
    for deviation in deviations {
        if let Deviation::SampleOffset { offset_px } | Deviation::CropNotCentred { offset_px } =
            *deviation
        {
            placement.offset_px = offset_px;
        }
    }
    model.pixels = placement.map(view);
    for deviation in deviations {
        match *deviation {
            Deviation::Tilt { per_unit } => {
                model.t_ramp.x += per_unit.x;
                model.t_ramp.y += per_unit.y;
            }
            Deviation::NoDepthTest { last_wins } => {
                model.hits.visible = if last_wins {
                    Visible::LastInFile
                } else {
                    Visible::FirstInFile
                };
            }
            Deviation::OnlyBlock { drawn_px } => model.drawn_px = Some(drawn_px),
            Deviation::SampleGrid {
                per_side,
                last_wins,
            } => {
                model.samples = Some(crate::compare::model::SampleGrid {
                    per_side,
                    last_wins,
                });
            }
            Deviation::Tmin { tmin } => {
                model.hits.tmin = tmin;
                model.hits.far_when_near_refused = true;
            }
            Deviation::NearRootOnly { tmin } => {
                model.hits.tmin = tmin;
                model.hits.far_when_near_refused = false;
            }
            Deviation::Background { bytes, .. } => model.background = Some(bytes),
            Deviation::DepthRange {
                white_t, black_t, ..
            } => {
                let map =
                    DepthMap::of_range(crate::render::depth_map::DepthRange::new(white_t, black_t));
                model.depth.at_zero = map.at_zero;
                model.depth.per_unit = map.per_unit;
            }
            Deviation::DepthQuantity { quantity } => model.depth.quantity = quantity,
            Deviation::DepthOutside { bytes } => model.depth.outside = Outside::Colour(bytes),
            Deviation::DepthNoHit { bytes, .. } => model.depth.no_hit = bytes,
            _ => {}
        }
    }
    model
}
