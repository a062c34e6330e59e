//! What the viewer shows, read from outside: the view, the scene, the frame on screen, the probe,
//! the messages. The tests and tools (screenshots, benchmarks) drive the viewer through these
//! and through [`ViewerApp::apply`].

use std::time::Duration;

use glam::DVec2;

use super::ViewerApp;
use super::loaded_scene::LoadedScene;
use super::settings::Settings;
use super::ui::magnifier::Magnifier;
use crate::app::depth_stats::DepthHistogram;
use crate::app::probe::{Probe, probe};
use crate::render::{Frame, View};

impl ViewerApp {
    /// The view the controls currently describe.
    pub fn view(&self) -> &View {
        &self.viewing.view
    }

    /// Mutable access to the view (as the controls edit it).
    pub fn view_mut(&mut self) -> &mut View {
        &mut self.viewing.view
    }

    /// The scene on screen.
    pub fn loaded_scene(&self) -> &LoadedScene {
        &self.scene.loaded
    }

    /// The frame on screen, with the view it was rendered for.
    pub fn shown_frame(&self) -> Option<(&Frame, &View)> {
        self.frames
            .shown
            .as_ref()
            .map(|shown| (shown.frame.as_ref(), &shown.view))
    }

    /// The persisted settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The persisted settings, to change.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// The histogram of visible t of the frame on screen.
    pub fn histogram(&self) -> Option<&DepthHistogram> {
        self.frames
            .shown
            .as_ref()
            .and_then(|s| s.histogram.as_ref())
    }

    /// Probes the frame on screen at image position `px` (pixels, y up).
    pub(crate) fn probe_at(&self, px: DVec2) -> Option<Probe> {
        let shown = self.frames.shown.as_ref()?;
        if shown.scene_epoch != self.scene.epoch || !(px.x >= 0.0 && px.y >= 0.0) {
            return None;
        }
        let (x_px, y_up_px) = (px.x.floor() as u32, px.y.floor() as u32);
        probe(
            &self.scene.loaded.scene,
            &shown.view,
            &shown.frame,
            x_px,
            y_up_px,
        )
    }

    /// The pointer's position on an image (image pixels, y up), if it is over one.
    pub fn hover_px(&self) -> Option<DVec2> {
        self.viewing.probe.hover_px
    }

    /// The probe of the pixel under the pointer.
    pub fn hover_probe(&self) -> Option<Probe> {
        self.viewing.probe.hover_px.and_then(|px| self.probe_at(px))
    }

    /// The probe of the pinned point, where it is on the frame on screen (`None` when it is out
    /// of view or nothing is pinned).
    pub fn pinned_probe(&self) -> Option<Probe> {
        self.pinned_px().and_then(|px| self.probe_at(px))
    }

    /// The magnifier: which part of the frame the images show.
    pub fn magnifier(&self) -> Magnifier {
        self.viewing.magnifier
    }

    /// Whether the shortcuts overlay is open.
    pub fn help_open(&self) -> bool {
        self.panels.help_open
    }

    /// The error of the last scene that failed to load, if shown.
    pub fn scene_error(&self) -> Option<&str> {
        self.scene.error.as_deref()
    }

    /// The status bar's message and whether it is an error.
    pub fn message(&self) -> Option<(&str, bool)> {
        self.status
            .as_ref()
            .map(|s| (s.text.as_str(), s.is_error()))
    }

    /// True while an export or a saved view is being written.
    pub fn export_running(&self) -> bool {
        self.writes.task.is_some()
    }

    /// True while a scene file is being read.
    pub fn loading(&self) -> bool {
        self.scene.loading.is_some()
    }

    /// How many scenes have been loaded (an open or a reload each count one).
    pub fn scene_loads(&self) -> u64 {
        self.scene.epoch
    }

    /// Behaves from now on as where no file dialog can be shown (no desktop portal, no zenity):
    /// for tests and tools on machines that have one.
    pub fn without_file_dialogs(&mut self) {
        self.writes.dialog_note = Some(super::dialogs::NO_DIALOG);
    }

    /// Waits (for tests and tools) until the worker has nothing to do.
    pub fn wait_for_worker(&self, timeout: Duration) -> bool {
        self.frames
            .worker
            .as_ref()
            .is_none_or(|w| w.wait_idle(timeout))
    }

    /// The comparison on screen (Compare section), if any.
    pub fn comparison(&self) -> Option<&super::compare::ComparisonPixels> {
        self.compare.current.as_ref().map(|c| &c.pixels)
    }

    /// What the compared image shows.
    pub fn compare_show(&self) -> super::compare::CompareShow {
        self.compare.show
    }

    /// True while a comparison is being computed.
    pub fn comparing(&self) -> bool {
        self.compare.busy()
    }
}
