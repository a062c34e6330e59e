//! Rendering: [`render`] turns a [`Scene`] seen through a [`View`] into a [`Frame`].
//!
//! * [`disc`]: the fast path. Orthographic rays are parallel, so each sphere is projected once per
//!   frame (in f64, relative to the camera centre) to a disc on the screen; a pixel hits it iff its
//!   screen point lies in the disc, and t follows from the disc's depth. Rows run in parallel.
//! * [`reference`]: the oracle — one world-space ray per pixel against every sphere through the
//!   careful ray–sphere routine of [`crate::intersect`], single-threaded. Tests compare against it.

pub mod disc;
mod frame;
pub mod reference;
mod view;
pub mod worker;

pub use frame::{Frame, NO_HIT};
pub use view::{MAX_PIXELS, MAX_SIDE_PX, View, ViewError, check_image_size};

use crate::scene::Scene;

/// Renders `scene` through `view` with the fast disc path: colour, t and sphere per pixel.
/// Deterministic: the same input gives the same frame, whatever the thread count.
pub fn render(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    disc::render_discs(scene, view)
}
