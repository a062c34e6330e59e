//! Rendering: [`render`] turns a [`Scene`] seen through a [`View`] into a [`Frame`];
//! [`render_with`] takes a [`Quality`] (precision mode).
//!
//! * [`disc`]: the fast path. Orthographic rays are parallel, so each sphere is projected once per
//!   frame (in f64, relative to the camera centre) to a disc on the screen; a pixel hits it iff its
//!   screen point lies in the disc, and t follows from the disc's depth. Bands of rows run in
//!   parallel.
//! * [`precision`]: f64 / f32 / auto, and when f32 is safe.
//! * [`reference`]: the oracle — one world-space ray per pixel against every sphere through the
//!   careful ray–sphere routine of [`crate::intersect`], single-threaded. Tests compare against it.
//! * [`worker`]: a background worker for interactive use.

pub mod disc;
mod frame;
pub mod high_precision;
pub mod precision;
pub mod reference;
mod view;
pub mod worker;

pub use frame::{Frame, NO_HIT};
pub use precision::Precision;
pub use view::{MAX_PIXELS, MAX_SIDE_PX, View, ViewError, check_image_size};

use crate::scene::Scene;

/// How to render: the knobs that trade speed for accuracy.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub struct Quality {
    /// Per-pixel arithmetic precision.
    pub precision: Precision,
}

/// Renders `scene` through `view` in exact (f64) precision: colour, t and sphere per pixel.
/// Deterministic: the same input gives the same frame, whatever the thread count.
pub fn render(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    render_with(scene, view, &Quality::default())
}

/// Renders with the given quality. `Precision::Auto` resolves per frame
/// ([`precision::f32_is_safe`]); the frame records the precision used.
pub fn render_with(scene: &Scene, view: &View, quality: &Quality) -> Result<Frame, ViewError> {
    match quality.precision {
        Precision::F64 => disc::render_discs_in::<f64>(scene, view, false),
        Precision::F32 => disc::render_discs_in::<f32>(scene, view, false),
        Precision::Auto => disc::render_discs_in::<f64>(scene, view, true),
    }
}
