//! The viewer's render job: a [`RenderWorker`] whose job renders the frame **and** prepares the
//! texture pixels of both images off the UI thread, so the UI only uploads them
//! (`TextureHandle::set`).

use std::sync::Arc;

use egui::{Color32, ColorImage};
use rayon::prelude::*;

use crate::render::worker::{RenderResult, RenderWorker};
use crate::render::{Frame, Quality, View, ViewError, render_with};
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
    /// Precision and other quality knobs.
    pub quality: Quality,
}

/// A rendered frame with the pixels of its two textures.
#[derive(Debug, Clone)]
pub struct PreparedFrame {
    /// The frame (colour, t, sphere per pixel).
    pub frame: Arc<Frame>,
    /// Colour image pixels.
    pub colour: ColorImage,
    /// Depth image pixels (grey over the view's depth range).
    pub depth: ColorImage,
}

/// The worker's output for one job.
pub type JobOutput = Result<PreparedFrame, ViewError>;

/// A finished job as the UI receives it.
pub type JobResult = RenderResult<ViewerJob, JobOutput>;

/// Renders `job` and prepares both texture images (what the worker runs).
pub fn prepare_frame(job: &ViewerJob) -> JobOutput {
    let frame = render_with(&job.scene, &job.view, &job.quality)?;
    let size = [frame.width_px as usize, frame.height_px as usize];
    let colour = ColorImage::new(
        size,
        frame
            .colour
            .par_iter()
            .map(|&[r, g, b]| Color32::from_rgb(r, g, b))
            .collect(),
    );
    let range = job.view.depth_range;
    let depth = ColorImage::new(
        size,
        frame
            .t
            .par_iter()
            .map(|&t| Color32::from_gray(range.grey_u8(t)))
            .collect(),
    );
    Ok(PreparedFrame {
        frame: Arc::new(frame),
        colour,
        depth,
    })
}

/// The viewer's worker type.
pub type ViewerWorker = RenderWorker<ViewerJob, JobOutput>;

/// Starts the viewer's worker; it asks `ctx` for a repaint whenever a frame lands.
pub fn start_worker(ctx: &egui::Context) -> std::io::Result<ViewerWorker> {
    let ctx = ctx.clone();
    RenderWorker::new(prepare_frame, move || ctx.request_repaint())
}
