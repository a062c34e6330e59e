//! The frames on screen: asking the render worker for the current view (progressive refinement:
//! a one-sample preview while the view changes, the chosen quality once it is still) and taking
//! the frames it finishes into the two textures.

use std::sync::Arc;
use web_time::{Duration, Instant};

use egui::{TextureHandle, TextureOptions};

use super::ViewerApp;
use super::frame_log::FrameLog;
use super::render_job::ViewerWorker;
use super::render_job::{DepthStyle, JobResult, ViewerJob};
use super::status::{Clears, Status};
use crate::explore::depth_stats::DepthHistogram;
use crate::render::{Frame, Quality, View};

/// The viewer's "frames" feature: the render worker, what was asked of it, the frame on screen
/// and, when the environment asks for it, the frame log.
pub(crate) struct Frames {
    /// The render worker (none when its thread could not start).
    pub(crate) worker: Option<ViewerWorker>,
    /// What was asked of the worker, and when.
    pub(crate) requests: Requests,
    /// The frame on screen.
    pub(crate) shown: Option<Shown>,
    /// Per-frame figures (`RAYTRACER_FRAME_LOG`).
    pub(crate) log: Option<FrameLog>,
}

/// How long the view must stay unchanged before a preview is refined to the chosen quality.
pub(crate) const REFINE_DELAY: Duration = Duration::from_millis(150);

/// What the worker is asked for: a view of a scene load at a quality, its depth drawn in a style.
pub(crate) type Wanted = (View, u64, Quality, DepthStyle);

/// The frame on screen.
pub(crate) struct Shown {
    pub(crate) frame: Arc<Frame>,
    pub(crate) view: View,
    pub(crate) scene_epoch: u64,
    pub(crate) quality: Quality,
    pub(crate) depth_style: DepthStyle,
    pub(crate) colour: TextureHandle,
    pub(crate) depth: TextureHandle,
    pub(crate) histogram: Option<DepthHistogram>,
    pub(crate) render_ms: f64,
}

/// What was asked of the worker and when the wanted picture last changed.
pub(crate) struct Requests {
    /// The last job submitted.
    pub(crate) submitted: Option<Wanted>,
    /// What the last change was made to.
    pub(crate) last_wanted: Option<Wanted>,
    /// When the view, scene or quality last changed.
    pub(crate) last_change: Instant,
    /// The last jobs submitted and when what they show was first wanted (the frame log's
    /// latency).
    pub(crate) changed_at: std::collections::VecDeque<(Wanted, Instant)>,
}

impl Default for Requests {
    fn default() -> Self {
        Self {
            submitted: None,
            last_wanted: None,
            last_change: Instant::now(),
            changed_at: std::collections::VecDeque::new(),
        }
    }
}

impl ViewerApp {
    /// How the depth texture is coloured now.
    pub(super) fn depth_style(&self) -> DepthStyle {
        DepthStyle {
            colour_map: self.settings.depth.colour_map,
            no_hit_rgb: self.settings.depth.no_hit_rgb(),
        }
    }

    /// True when the frame on screen is the current view of the current scene at the current
    /// quality. While a scene loads this is false: the frame will change once it is in.
    pub fn frame_is_current(&self) -> bool {
        let style = self.depth_style();
        self.scene.loading.is_none()
            && self.frames.shown.as_ref().is_some_and(|s| {
                s.view == self.viewing.view
                    && s.scene_epoch == self.scene.epoch
                    && s.quality == self.settings.quality
                    && s.depth_style == style
            })
    }

    /// Whether the frame on screen is a one-sample preview of a supersampled quality.
    pub fn showing_preview(&self) -> bool {
        self.frames.shown.as_ref().is_some_and(|s| {
            s.quality.sampling.is_none() && self.settings.quality.sampling.is_some()
        })
    }

    /// Progressive refinement: while the view keeps changing, one sample per pixel (a preview);
    /// once it has been still for [`REFINE_DELAY`], the chosen quality.
    pub(super) fn submit_if_changed(&mut self) {
        let style = self.depth_style();
        let chosen = (
            self.viewing.view,
            self.scene.epoch,
            self.settings.quality,
            style,
        );
        let requests = &mut self.frames.requests;
        if requests.last_wanted != Some(chosen) {
            requests.last_wanted = Some(chosen);
            requests.last_change = Instant::now();
        }
        let still_for = requests.last_change.elapsed();
        let refine = self.settings.quality.sampling.is_none() || still_for >= REFINE_DELAY;
        let quality = if refine {
            self.settings.quality
        } else {
            self.ctx
                .request_repaint_after(REFINE_DELAY.saturating_sub(still_for));
            Quality { sampling: None }
        };
        let wanted = (self.viewing.view, self.scene.epoch, quality, style);
        if requests.submitted == Some(wanted) {
            return;
        }
        if let Some(worker) = &self.frames.worker {
            worker.submit(ViewerJob {
                scene: Arc::clone(&self.scene.loaded.scene),
                view: self.viewing.view,
                scene_epoch: self.scene.epoch,
                quality,
                depth_style: style,
            });
            requests.submitted = Some(wanted);
            if requests.changed_at.len() == 8 {
                requests.changed_at.pop_front();
            }
            requests
                .changed_at
                .push_back((wanted, requests.last_change));
        }
    }

    /// Takes a frame the worker finished into the textures (or shows why it failed).
    pub(super) fn receive_frame(&mut self) {
        let Some(result) = self
            .frames
            .worker
            .as_ref()
            .and_then(super::super::render::worker::RenderWorker::take_finished)
        else {
            return;
        };
        let JobResult {
            job,
            output,
            render_time,
            ..
        } = result;
        let prepared = match output {
            Ok(prepared) => prepared,
            Err(error) => {
                self.status = Some(Status::view_error(error));
                return;
            }
        };
        let render_ms = render_time.as_secs_f64() * 1e3;
        if let Some(log) = &mut self.frames.log {
            let wanted = (job.view, job.scene_epoch, job.quality, job.depth_style);
            let changed_at = self
                .frames
                .requests
                .changed_at
                .iter()
                .find(|(submitted, _)| *submitted == wanted)
                .map(|&(_, at)| at);
            let size = [job.view.width_px, job.view.height_px];
            log.frame(render_ms, changed_at, size);
        }
        if let Some(shown) = &mut self.frames.shown {
            shown.colour.set(prepared.colour, TextureOptions::NEAREST);
            shown.depth.set(prepared.depth, TextureOptions::NEAREST);
            shown.frame = prepared.frame;
            shown.view = job.view;
            shown.scene_epoch = job.scene_epoch;
            shown.quality = job.quality;
            shown.depth_style = job.depth_style;
            shown.histogram = prepared.histogram;
            shown.render_ms = render_ms;
        } else {
            let colour = self
                .ctx
                .load_texture("colour", prepared.colour, TextureOptions::NEAREST);
            let depth = self
                .ctx
                .load_texture("depth", prepared.depth, TextureOptions::NEAREST);
            self.frames.shown = Some(Shown {
                frame: prepared.frame,
                view: job.view,
                scene_epoch: job.scene_epoch,
                quality: job.quality,
                depth_style: job.depth_style,
                colour,
                depth,
                histogram: prepared.histogram,
                render_ms,
            });
        }
        if self
            .status
            .as_ref()
            .is_some_and(|s| s.clears == Clears::WhenAFrameRenders)
        {
            self.status = None;
        }
        self.follow_depth();
    }
}
