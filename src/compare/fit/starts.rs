//! Where the fit of the pixel map starts from: the geometric named points (the course's map and
//! the known mistakes that move where rays start, a non-square image's strips and blocks), and
//! the plain starts (each axis flipped or swapped, zoomed in and out, the normalisers of a
//! non-square image swapped), from which Levenberg-Marquardt runs.

use glam::DVec2;

use super::geometry::Affine;
use super::score::{Scorer, Theirs};
use crate::compare::mistake::{Mistake, MistakeSet};
use crate::compare::model::Model;
use crate::compare::model_render::{colour_image, depth_image};

/// The geometric named points: the course's and the mistakes that move where rays start.
pub(super) fn named_geometry(view: &crate::render::View) -> Vec<(usize, Model)> {
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
pub(super) fn block_square(
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
pub(super) fn only_block(view: &crate::render::View, theirs: Theirs<'_>) -> Option<(u32, u32)> {
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

/// Whether the exact images differ from theirs outside the lower-left `side` square: where
/// they are the same there (a depth image's far spheres as black as the rest of that strip), a
/// flat strip says nothing of loops that stop at min(W, H).
pub(super) fn differs_outside(scorer: &mut Scorer<'_>, side: u32) -> bool {
    let course = Model::course(scorer.view);
    let (exact_colour, exact_depth) = {
        let hits = scorer.hits(&course);
        let view = scorer.view;
        (
            scorer
                .theirs
                .colour
                .map(|_| colour_image(scorer.scene, &hits, &course)),
            scorer
                .theirs
                .depth
                .map(|_| depth_image(view, &hits, &course)),
        )
    };
    let height = scorer.view.height_px;
    let outside = |a: &image::RgbImage, b: &image::RgbImage| {
        a.enumerate_pixels()
            .zip(b.pixels())
            .any(|((x, row, p), q)| (x >= side || height - 1 - row >= side) && p != q)
    };
    match (scorer.theirs.colour, exact_colour) {
        (Some(theirs), Some(exact)) => outside(theirs, &exact),
        _ => match (scorer.theirs.depth, exact_depth) {
            (Some(theirs), Some(exact)) => outside(theirs, &exact),
            _ => false,
        },
    }
}

/// The starts of the geometric fit: the course's map, mirrored, upside down, turned, with axes
/// swapped; for a non-square image also stretched and the square's strips.
pub(super) fn starts(width_px: u32, height_px: u32) -> Vec<Affine> {
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
    // Zoomed in and out: camera vectors that are not unit (a union of discs, as a depth image
    // alone shows it, can hold a fit far from the scale it has).
    for zoom in [0.8, 1.25] {
        starts.push(Affine {
            relative: glam::DMat2::from_diagonal(DVec2::splat(zoom)),
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
            for (sx, sy) in signs {
                starts.push(Affine {
                    relative: glam::DMat2::from_diagonal(DVec2::new(sx, sy)),
                    shift_px,
                });
            }
        }
    }
    starts
}
