//! Rivals that say the answer's map again: of two maps that differ only in where rays start (the
//! other statements the same, whatever their values), the one nearer the course's is said, for a
//! symmetric scene looks the same turned and the least change is the answer; nor is the same map
//! said with other numbers a rival. A mirror is no nearer the course than a flip, though: the two
//! say different programs, and a tie between them is said as one.

use super::describe::rebuild;
use super::deviation::Deviation;
use super::mistake::Mistake;
use super::model::Model;
use crate::render::View;

/// Whether `rival` says `answer`'s map again (the other statements the same, as the caller
/// checks): with a fitted map farther from the course's, unless the one is mirrored and the other
/// flipped, or one that puts every corner within a pixel of the answer's.
pub(super) fn same_map_farther(view: &View, rival: &[Deviation], answer: &[Deviation]) -> bool {
    let turns = |list: &[Deviation]| {
        let turn = |m: Mistake| list.contains(&Deviation::Word(m));
        (turn(Mistake::Mirrored), turn(Mistake::FlippedVertically))
    };
    let (theirs, ours) = (turns(rival), turns(answer));
    let other_turn = theirs != ours && theirs != (false, false) && ours != (false, false);
    rival.iter().any(Deviation::is_geometric)
        && ((off_course(view, rival) > 1.01 * off_course(view, answer) + 1e-3 && !other_turn)
            || same_map(view, rival, answer))
}

/// How far the pixel map `statements` describe lies from the course's (its axes, in course
/// pixel steps).
fn off_course(view: &View, statements: &[Deviation]) -> f64 {
    let model = rebuild(view, statements);
    let relative = model.pixels.relative_axes(Model::step_world(view)) - glam::DMat2::IDENTITY;
    relative.x_axis.length() + relative.y_axis.length()
}

/// Whether the pixel maps `a` and `b` describe put every corner of the image within a pixel
/// of each other: the same picture, said with other numbers.
fn same_map(view: &View, a: &[Deviation], b: &[Deviation]) -> bool {
    let (a, b) = (rebuild(view, a), rebuild(view, b));
    let step = Model::step_world(view);
    let (w, h) = (f64::from(view.width_px), f64::from(view.height_px));
    [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)]
        .iter()
        .all(|&(x, y)| {
            let corner = glam::DVec2::new(x, y);
            (a.pixels.screen_of(corner) - b.pixels.screen_of(corner)).length() <= step
        })
}
