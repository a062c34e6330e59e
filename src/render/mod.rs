//! Rendering: [`render`] turns a [`Scene`] seen through a [`View`] into a [`Frame`];
//! [`render_with`] takes a [`Quality`] (supersampling).
//!
//! * [`disc`]: the fast path. Orthographic rays are parallel, so each sphere is projected once per
//!   frame (in f64, relative to the camera centre) to a disc on the screen; a pixel hits it iff its
//!   screen point lies in the disc, and t follows from the disc's depth. Bands of rows run in
//!   parallel.
//! * [`sampling`]: supersampling with the course's samplers and filters.
//! * [`depth_map`]: t → grey and colour maps, 8- and 16-bit quantisation.
//! * [`rng`]: the seeded generator behind random sample positions.
//! * [`phases`]: a frame's phases timed, to see where its time goes.

pub mod depth_map;
pub mod disc;
mod frame;
pub mod memory;
pub mod phases;
pub mod rng;
pub(crate) mod sampling;
mod view;

pub use frame::{Frame, NO_HIT};
pub use sampling::{Filter, Sampler, Sampling, SamplingError};
pub use view::{MAX_PIXELS, MAX_SIDE_PX, View, ViewError, check_image_size};

use crate::scene::Scene;

/// How to render: the knob that trades speed for accuracy. The per-pixel arithmetic is always
/// f64 (exact); an f32 mode was slower as well as less exact, and was removed.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "gui", serde(default))]
pub struct Quality {
    /// Supersampling; `None` is one sample at each pixel centre (course-exact).
    pub sampling: Option<Sampling>,
}

impl Quality {
    /// In words, for the status bar and the Compare section: "1 sample" or the sampling's own
    /// description.
    pub fn describe(&self) -> String {
        self.sampling
            .map_or_else(|| "1 sample".to_owned(), |sampling| sampling.describe())
    }
}

/// Renders `scene` through `view`, one sample at each pixel centre: colour, t and sphere per pixel.
/// Deterministic: the same input gives the same frame, whatever the thread count.
pub fn render(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    render_with(scene, view, &Quality::default())
}

/// Renders with the given quality. With sampling, the colour
/// and the depth greys are supersampled ([`sampling`]) and t stays the centre sample.
pub fn render_with(scene: &Scene, view: &View, quality: &Quality) -> Result<Frame, ViewError> {
    render_with_progress(scene, view, quality, &|_| {})
}

/// Renders `scene` through `view`, one sample at each pixel centre, a strip of rows at a time:
/// `consume` gets each strip's t and spheres ([`disc::Strip`]), in parallel and in no fixed
/// order, the same pixels [`render`] makes. Returns the pixel–disc tests made.
pub(crate) fn render_strips<E: From<ViewError> + Send>(
    scene: &Scene,
    view: &View,
    consume: impl Fn(disc::Strip<'_>) -> Result<(), E> + Sync + Send,
) -> Result<u64, E> {
    on_the_pool(|| {
        let basis = view.validate()?;
        let grid = view.grid();
        let (discs, depths) = disc::project_discs_with_depths(scene, view, &basis);
        disc::rasterise_strips(&grid, &discs, &depths, consume)
    })
}

/// Runs `work` on a thread of rayon's pool (in place when already on one). A frame is a chain of
/// parallel steps with serial work between them: run from a thread outside the pool, that thread
/// hands each step to the pool and sleeps until it is done, and each of the pool's threads that
/// ran out of work sleeps too, so every step waits for threads to wake. On a pool thread the
/// serial work runs where the steps begin and end, and the thread waits for a step's last tasks
/// by taking part in them (`examples/frame_phases` counts the sleeps: docs/scaling.md).
pub(crate) fn on_the_pool<R: Send>(work: impl FnOnce() -> R + Send) -> R {
    rayon::scope(|_| work())
}

/// Whether [`render_strips`] draws `scene` through `view` strip by strip (`true`) or draws the
/// whole frame first (a dense frame, drawn front to back): what its memory bound needs to know
/// ([`memory::streamed_bound_bytes`]).
pub(crate) fn renders_strip_by_strip(scene: &Scene, view: &View) -> Result<bool, ViewError> {
    let basis = view.validate()?;
    Ok(disc::draws_in_file_order(scene, view, &basis))
}

/// [`render_with`], telling `progress` the share of the frame done (0 to 1): as bands of rows
/// finish when supersampling (the long renders), once at the end otherwise.
pub(crate) fn render_with_progress(
    scene: &Scene,
    view: &View,
    quality: &Quality,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Frame, ViewError> {
    if let Some(sampling) = &quality.sampling {
        sampling.validate()?;
    }
    let basis = view.validate()?;
    let grid = view.grid();
    let frame = on_the_pool(|| {
        let (discs, depths) = disc::project_discs_with_depths(scene, view, &basis);
        let mut frame = disc::rasterise_frame(scene, view, &grid, &discs, &depths);
        if let Some(sampling) = &quality.sampling {
            let supersampled =
                sampling::supersample(scene, &discs, &grid, view.depth_range, sampling, progress);
            frame.colour = supersampled.colour;
            frame.depth_grey = Some((view.depth_range, supersampled.depth_grey));
            frame.disc_tests += supersampled.disc_tests;
        }
        frame
    });
    progress(1.0);
    Ok(frame)
}
