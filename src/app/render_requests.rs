//! The frames on screen: asking the render worker for the current view (progressive refinement:
//! a one-sample preview while the view changes, the chosen quality once it is still) and taking
//! the frames it finishes into the two textures.

use std::sync::Arc;
use web_time::{Duration, Instant};

use egui::{TextureHandle, TextureOptions};

use glam::DVec2;

use super::frame_log::FrameLog;
use super::probe::{Probe, probe};
use super::render_job::{DepthStyle, JobResult, ViewerJob};
use super::render_job::{ViewerWorker, start_worker};
use super::settings::{DepthDisplay, Settings};
use super::status::{Clears, Status};
use crate::app::depth_stats::DepthHistogram;
use crate::render::{Frame, Quality, View, ViewError};
use crate::scene::Scene;

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

impl Frames {
    /// Starts the render worker through `ctx` (and the frame log, when the environment asks for
    /// it, naming the renderer: glow when `gl`, else wgpu); says why when the worker cannot start.
    pub(crate) fn start(ctx: &egui::Context, gl: bool) -> (Self, Option<Status>) {
        let (worker, status) = match start_worker(ctx) {
            Ok(worker) => (Some(worker), None),
            Err(error) => (
                None,
                Some(Status::error(format!(
                    "cannot start the render thread: {error}"
                ))),
            ),
        };
        let log = FrameLog::from_environment().map(|mut log| {
            log.renderer(if gl { "glow" } else { "wgpu" });
            log
        });
        let frames = Self {
            worker,
            requests: Requests::default(),
            shown: None,
            log,
        };
        (frames, status)
    }

    /// The size of the frame on screen (pixels), if one is.
    pub(crate) fn size_px(&self) -> Option<[u32; 2]> {
        self.shown
            .as_ref()
            .map(|s| [s.frame.width_px, s.frame.height_px])
    }

    /// Probes the frame on screen at image position `px` (pixels, y up), if it is a frame of
    /// `scene` at load `epoch`.
    pub(crate) fn probe_at(&self, scene: &Scene, epoch: u64, px: DVec2) -> Option<Probe> {
        let shown = self.shown.as_ref()?;
        if shown.scene_epoch != epoch || !(px.x >= 0.0 && px.y >= 0.0) {
            return None;
        }
        let (x_px, y_up_px) = (px.x.floor() as u32, px.y.floor() as u32);
        probe(scene, &shown.view, &shown.frame, x_px, y_up_px)
    }

    /// True when the frame on screen is `wanted` (a view of a scene load at a quality, in a
    /// depth style).
    pub(crate) fn shows(&self, wanted: Wanted) -> bool {
        let (view, epoch, quality, style) = wanted;
        self.shown.as_ref().is_some_and(|s| {
            s.view == view
                && s.scene_epoch == epoch
                && s.quality == quality
                && s.depth_style == style
        })
    }

    /// Progressive refinement: while `chosen` (of `scene`) keeps changing, one sample per pixel
    /// (a preview); once it has been still for [`REFINE_DELAY`], its own quality. Asks `ctx` for
    /// a repaint when the refinement is due.
    pub(crate) fn submit_if_changed(
        &mut self,
        scene: &Arc<Scene>,
        chosen: Wanted,
        ctx: &egui::Context,
    ) {
        let (view, epoch, chosen_quality, style) = chosen;
        let requests = &mut self.requests;
        if requests.last_wanted != Some(chosen) {
            requests.last_wanted = Some(chosen);
            requests.last_change = Instant::now();
        }
        let still_for = requests.last_change.elapsed();
        let refine = chosen_quality.sampling.is_none() || still_for >= REFINE_DELAY;
        let quality = if refine {
            chosen_quality
        } else {
            ctx.request_repaint_after(REFINE_DELAY.saturating_sub(still_for));
            Quality { sampling: None }
        };
        let wanted = (view, epoch, quality, style);
        if requests.submitted == Some(wanted) {
            return;
        }
        if let Some(worker) = &self.worker {
            worker.submit(ViewerJob {
                scene: Arc::clone(scene),
                view,
                scene_epoch: epoch,
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

    /// Takes a finished frame in ([`Self::receive`]) and says so in `status`: a message waiting
    /// for a frame clears, a failed render says why. True when a new frame is on screen.
    pub(crate) fn take_in(&mut self, ctx: &egui::Context, status: &mut Option<Status>) -> bool {
        match self.receive(ctx) {
            None => false,
            Some(Err(error)) => {
                *status = Some(Status::view_error(error));
                false
            }
            Some(Ok(())) => {
                if status
                    .as_ref()
                    .is_some_and(|s| s.clears == Clears::WhenAFrameRenders)
                {
                    *status = None;
                }
                true
            }
        }
    }

    /// Takes a frame the worker finished into the textures (made through `ctx` the first time).
    /// `None` when none finished; the render's error when it failed.
    fn receive(&mut self, ctx: &egui::Context) -> Option<Result<(), ViewError>> {
        let JobResult {
            job,
            output,
            render_time,
            ..
        } = self.worker.as_ref()?.take_finished()?;
        let prepared = match output {
            Ok(prepared) => prepared,
            Err(error) => return Some(Err(error)),
        };
        let render_ms = render_time.as_secs_f64() * 1e3;
        if let Some(log) = &mut self.log {
            let wanted = (job.view, job.scene_epoch, job.quality, job.depth_style);
            let changed_at = self
                .requests
                .changed_at
                .iter()
                .find(|(submitted, _)| *submitted == wanted)
                .map(|&(_, at)| at);
            let size = [job.view.width_px, job.view.height_px];
            log.frame(render_ms, changed_at, size);
        }
        if let Some(shown) = &mut self.shown {
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
            let colour = ctx.load_texture("colour", prepared.colour, TextureOptions::NEAREST);
            let depth = ctx.load_texture("depth", prepared.depth, TextureOptions::NEAREST);
            self.shown = Some(Shown {
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
        Some(Ok(()))
    }
}

/// How the depth texture is coloured under the depth settings.
pub(crate) fn depth_style(depth: &DepthDisplay) -> DepthStyle {
    DepthStyle {
        colour_map: depth.colour_map,
        no_hit_rgb: depth.no_hit_rgb(),
    }
}

impl Frames {
    /// The frame the settings ask for of `view` on the scene load `epoch`.
    pub(crate) fn wanted(view: View, epoch: u64, settings: &Settings) -> Wanted {
        (view, epoch, settings.quality, depth_style(&settings.depth))
    }

    /// Whether the frame on screen is a one-sample preview of the supersampled `quality`.
    pub(crate) fn shows_preview_of(&self, quality: &Quality) -> bool {
        self.shown
            .as_ref()
            .is_some_and(|s| s.quality.sampling.is_none() && quality.sampling.is_some())
    }
}
