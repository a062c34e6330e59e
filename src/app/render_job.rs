//! The viewer's render job: a [`RenderWorker`] whose job renders the frame **and** prepares the
//! texture pixels of both images off the UI thread, so the UI only uploads them
//! (`TextureHandle::set`).

use std::sync::Arc;

use egui::{Color32, ColorImage};
use rayon::prelude::*;

use crate::app::depth_stats::DepthHistogram;
use crate::platform::worker::{RenderResult, RenderWorker};
use crate::render::depth_map::DepthColourMap;
use crate::render::phases::time;
use crate::render::{Frame, Quality, View, ViewError, on_the_pool, render_with};
use crate::scene::Scene;

/// What the worker renders: a scene through a view.
#[derive(Debug, Clone)]
pub struct ViewerJob {
    /// The scene.
    pub scene: Arc<Scene>,
    /// The view, including image size and depth range.
    pub view: View,
    /// Which scene load this job belongs to (the viewer counts loads).
    pub scene_epoch: u64,
    /// Quality: samples per pixel.
    pub quality: Quality,
    /// How the depth texture is coloured.
    pub depth_style: DepthStyle,
}

/// How the depth texture is coloured: the map and the colour of no-hit pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DepthStyle {
    /// One of [`DepthColourMap::ALL`].
    pub(crate) colour_map: DepthColourMap,
    /// Colour of pixels where no ray hits.
    pub(crate) no_hit_rgb: [u8; 3],
}

impl Default for DepthStyle {
    fn default() -> Self {
        Self {
            colour_map: DepthColourMap::Grey,
            no_hit_rgb: [0; 3],
        }
    }
}

/// Bins of the histogram of visible t drawn under the depth image.
pub const HISTOGRAM_BINS: usize = 128;

/// A rendered frame with the pixels of its two textures.
#[derive(Debug, Clone)]
pub struct PreparedFrame {
    /// The frame (colour, t, sphere per pixel).
    pub(crate) frame: Arc<Frame>,
    /// Colour image pixels.
    pub(crate) colour: ColorImage,
    /// Depth image pixels (the view's depth range through the job's colour map).
    pub(crate) depth: ColorImage,
    /// Distribution of the visible t, `None` when no pixel hits.
    pub(crate) histogram: Option<DepthHistogram>,
}

/// The worker's output for one job.
pub(crate) type JobOutput = Result<PreparedFrame, ViewError>;

/// A finished job as the UI receives it.
pub(crate) type JobResult = RenderResult<ViewerJob, JobOutput>;

/// Renders `job` and prepares both texture images (what the worker runs).
pub fn prepare_frame(job: &ViewerJob) -> JobOutput {
    // All of it on the pool's threads, the render's steps and the textures' alike.
    on_the_pool(|| {
        let frame = render_with(&job.scene, &job.view, &job.quality)?;
        let size = [frame.width_px as usize, frame.height_px as usize];
        // The histogram alongside the two textures.
        let (histogram, (colour, depth)) = rayon::join(
            || time("histogram", || DepthHistogram::new(&frame, HISTOGRAM_BINS)),
            || time("textures", || textures(job, &frame, size)),
        );
        Ok(PreparedFrame {
            frame: Arc::new(frame),
            colour,
            depth,
            histogram,
        })
    })
}

/// The colour and depth textures of `frame` (the depth through [`Frame::depth_pixels`], as files
/// have it, with the style's colour for no-hit pixels).
fn textures(job: &ViewerJob, frame: &Frame, size: [usize; 2]) -> (ColorImage, ColorImage) {
    let to_colour32 = |[r, g, b]: [u8; 3]| Color32::from_rgb(r, g, b);
    let colour = ColorImage::new(
        size,
        frame
            .colour
            .par_iter()
            .map(|&rgb| to_colour32(rgb))
            .collect(),
    );
    let DepthStyle {
        colour_map,
        no_hit_rgb,
    } = job.depth_style;
    let depth_pixels =
        frame.depth_pixels(job.view.depth_range, colour_map, no_hit_rgb, to_colour32);
    (colour, ColorImage::new(size, depth_pixels))
}

/// The viewer's worker type.
pub(crate) type ViewerWorker = RenderWorker<ViewerJob, JobOutput>;

/// Starts the viewer's worker; it asks `ctx` for a repaint whenever a frame lands.
pub(crate) fn start_worker(ctx: &egui::Context) -> std::io::Result<ViewerWorker> {
    let ctx = ctx.clone();
    RenderWorker::new(prepare_frame, move || ctx.request_repaint())
}
