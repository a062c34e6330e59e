//! The viewer's coordinator, [`ViewerApp`]: it holds each feature's state, routes input and
//! [`Action`]s between them, takes in background work, draws through [`super::layout`]; tests
//! drive it through its read access (view, frame, probe, messages) and [`ViewerApp::apply`].

use std::path::Path;
use std::time::Duration;

use glam::DVec2;

use super::actions::{Action, Write};
use super::confirm::{self, Answer};
use super::depth_stats::DepthHistogram;
use super::loaded_scene::LoadedScene;
use super::probe::{Probe, point_of_probe};
use super::saved_views::SceneViews;
use super::scene_loading::{LoadKind, OpenScene};
use super::settings::Settings;
use super::status::{self, Status};
use super::ui::magnifier::Magnifier;
use super::{compare, input, layout, pixel_trace, render_requests, viewing, writes};
use crate::cli::ViewerRequest;
use crate::render::{Frame, View};

/// The viewer application: the coordinator of the features' states (the open scene, the view,
/// the frames, the writes, the panels, the comparison).
pub struct ViewerApp {
    /// What survives a restart.
    pub(super) settings: Settings,
    /// The scene on screen, its load, watcher and error.
    pub(super) scene: OpenScene,
    /// The view, its history, the probe and the magnifier.
    pub(super) viewing: viewing::Viewing,
    /// The frames asked of the render worker and the one on screen.
    pub(super) frames: render_requests::Frames,
    /// Exports and saved scenes: the write in flight, the one waiting for a yes, file dialogs.
    pub(super) writes: writes::Writes,
    /// The side panel's fields, the drawer and the shortcuts overlay.
    pub(super) panels: layout::Panels,
    /// The Compare section: their image or the chosen quality against the exact render.
    pub(super) compare: compare::CompareState,
    /// The status bar's message.
    pub(super) status: Option<Status>,
    /// In a browser page: files on their way in.
    #[cfg(target_arch = "wasm32")]
    pub(super) page: super::web::Page,
    pub(super) ctx: egui::Context,
}

impl ViewerApp {
    /// Creates the viewer: settings from eframe's storage, the scene from the request (or the last
    /// scene, or the embedded default), and the render worker.
    pub fn new(cc: &eframe::CreationContext<'_>, request: ViewerRequest) -> Self {
        let settings = Settings::from_storage(cc.storage, request.size_px);
        input::claim_zoom_keys(&cc.egui_ctx);
        let (frames, status) = render_requests::Frames::start(&cc.egui_ctx, cc.gl.is_some());
        let loaded = LoadedScene::default_scene();
        let mut app = Self {
            settings,
            viewing: viewing::Viewing::new(loaded.file_view),
            scene: OpenScene::new(loaded),
            frames,
            writes: writes::Writes::new(request.program.clone()),
            panels: layout::Panels::default(),
            compare: compare::CompareState::default(),
            status,
            #[cfg(target_arch = "wasm32")]
            page: super::web::Page::default(),
            ctx: cc.egui_ctx.clone(),
        };
        app.open_first(request.input);
        app
    }

    /// What a comparison started now is made against.
    pub(super) fn against(&self) -> compare::Against {
        compare::Against {
            ctx: self.ctx.clone(),
            scene: std::sync::Arc::clone(&self.scene.loaded.scene),
            view: self.viewing.view,
        }
    }

    /// Shows what a feature had to say, if anything, in the status bar.
    pub(super) fn say(&mut self, said: Option<Status>) {
        status::say(&mut self.status, said);
    }

    /// "Auto range" on the frame on screen (the settings' cut at each ends).
    pub fn auto_range(&mut self) {
        self.carry_out(Action::AutoRange);
    }

    /// "Frame all" on the open scene.
    pub fn frame_all(&mut self) {
        self.viewing.frame_all(&self.scene.loaded.scene);
    }

    /// The frame the settings, the view and the open scene ask for.
    fn wanted(&self) -> render_requests::Wanted {
        render_requests::Frames::wanted(self.viewing.view, self.scene.epoch, &self.settings)
    }

    /// True when the frame on screen is the current view of the current scene at the current
    /// quality. While a scene loads this is false: the frame will change once it is in.
    pub fn frame_is_current(&self) -> bool {
        self.scene.loading.is_none() && self.frames.shows(self.wanted())
    }

    /// Whether the frame on screen is a one-sample preview of a supersampled quality.
    pub fn showing_preview(&self) -> bool {
        self.frames.shows_preview_of(&self.settings.quality)
    }

    /// Starts loading the scene at `path` in the background ([`OpenScene::open`]); once read, it
    /// replaces the scene on screen.
    pub fn open(&mut self, path: &Path) {
        self.scene.open(path, &self.viewing.view, &self.ctx);
    }

    /// Opens the scene `bytes` named `name` (a browser page's file), as [`Self::open`].
    pub fn open_bytes(&mut self, name: &str, bytes: std::sync::Arc<[u8]>) {
        self.scene
            .open_bytes(name, bytes, &self.viewing.view, &self.ctx);
    }

    /// Takes a finished load in ([`OpenScene::poll`]): an open in the view it was last seen in,
    /// a reload in the user's camera unless that was still the file's.
    fn receive_scene(&mut self) {
        let Some((loaded, path, kind)) = self.scene.poll(&self.ctx) else {
            return;
        };
        let view = &mut self.viewing.view;
        if kind == LoadKind::Reload {
            let status = self.scene.adopt_reload(loaded, &path, view);
            return self.say(status);
        }
        let previous = self.scene.loaded.path.as_deref();
        self.settings
            .follow_open(previous, view, &path, loaded.in_memory);
        // An older message (an error of an earlier try included) is not left beside it.
        self.status = Some(self.scene.adopt_opened(loaded, &path, view, &self.ctx));
        self.compare.close(); // Their image was of the scene before: not judged against this.
        let last = self.settings.views.last.get(&SceneViews::key(&path));
        self.viewing.opened(last);
        self.panels.fields.path_text = path.display().to_string();
        self.set_title(&format!("raytracer — {}", path.display()));
    }

    /// Carries out `write` now if it replaces nothing, else asks ([`confirm::wait_for_yes`]); one
    /// that cannot start is refused before a folder it would make is offered (a page has none).
    fn write_or_ask(&mut self, write: Write) {
        let missing_folder = self.missing_export_folder(&write);
        let written = self.written();
        let asked =
            self.writes
                .files_of(&write, missing_folder.is_some(), &self.settings, &written);
        let (scene, compared) = (
            self.scene.loaded.path.as_deref(),
            self.compare.watched_files(),
        );
        let guarded = confirm::Guarded { scene, compared };
        match asked.map(|files| confirm::wait_for_yes(write, missing_folder, files, guarded)) {
            Ok(Ok(write)) => self.write_now(write),
            Ok(Err(pending)) => self.writes.pending_replace = Some(pending),
            Err(refused) => self.status = Some(refused),
        }
    }

    /// Carries out `write` (the user has agreed to replace what it replaces).
    fn write_now(&mut self, write: Write) {
        self.scene.note_write(&write);
        match self.writes.stage(write, &self.settings, &self.written()) {
            Ok(staged) => self.write_files(staged.running, staged.done, staged.stage),
            Err(status) => self.status = Some(status),
        }
    }

    /// What a write started now writes: the scene on screen in the view on screen.
    fn written(&self) -> writes::Written<'_> {
        writes::Written {
            loaded: &self.scene.loaded,
            epoch: self.scene.epoch,
            view: self.viewing.view,
            shown: self.frames.shown.as_ref(),
        }
    }

    /// Carries out `action`. A one-shot view change is a step of the history of its own.
    pub(crate) fn apply(&mut self, action: Action) {
        let one_shot = matches!(
            action,
            Action::FrameAll
                | Action::ResetView
                | Action::ResetDepth
                | Action::AutoRange
                | Action::UseDepthRange(_)
                | Action::GoToView(_)
        );
        let before = self.viewing.view;
        self.carry_out(action);
        if one_shot {
            self.viewing.history.one_shot(&before, &self.viewing.view);
        }
    }

    /// Hands `action` to the feature that carries it out; what it says goes to the status bar.
    fn carry_out(&mut self, action: Action) {
        let path = self.scene.loaded.path.as_deref();
        let status = match action {
            Action::Reload => self.scene.reload(&self.viewing.view, &self.ctx),
            Action::AutoRange => {
                let shown = self.frames.shown.as_ref().map(|shown| &*shown.frame);
                let cut = self.settings.depth.auto_cut_percent;
                self.viewing.auto_range(shown, cut)
            }
            Action::Trace => {
                let view = self.frames.shown.as_ref().map(|shown| &shown.view);
                let px = self.viewing.pinned_px(self.frames.shown.as_ref());
                let scene = &self.scene.loaded.scene;
                pixel_trace::open(&mut self.panels.trace, scene, view, px, &self.compare)
            }
            Action::Undo => self.viewing.undo(),
            Action::Redo => self.viewing.redo(),
            Action::NameView(name) => Some(self.viewing.name_view(
                &mut self.settings.views,
                path,
                &name,
            )),
            Action::CompareImage(path, kind) => self.compare.with_file(&self.against(), path, kind),
            Action::CompareQuality => {
                let quality = self.settings.quality;
                self.compare.with_quality(&self.against(), quality)
            }
            other => return self.carry_out_quietly(other),
        };
        self.say(status);
    }

    /// Hands `action`, one that says nothing, to the feature that carries it out.
    fn carry_out_quietly(&mut self, action: Action) {
        let path = self.scene.loaded.path.as_deref();
        match action {
            Action::OpenDialog(kind) => self.open_dialog(kind),
            Action::Open(path) => self.open_path(&path),
            Action::OpenBundled(index) => {
                if let Some((name, text)) = crate::scene::bundled::BUNDLED_SCENES.get(index) {
                    self.open_bytes(name, std::sync::Arc::from(text.as_bytes()));
                }
            }
            Action::FrameAll => self.frame_all(),
            Action::ResetView => self.viewing.reset_view(&self.scene.loaded.file_view),
            Action::ResetDepth => self.viewing.reset_depth(&self.scene.loaded.file_view),
            Action::UseDepthRange(range) => self.viewing.view.depth_range = range,
            Action::GoToView(index) => {
                self.viewing
                    .go_to_view(&mut self.settings.views, path, index);
            }
            Action::ForgetView(index) => {
                viewing::forget_view(&mut self.settings.views, path, index);
            }
            Action::ToggleHelp => self.panels.help_open = !self.panels.help_open,
            Action::ResetMagnifier => self.viewing.magnifier = Default::default(),
            Action::Write(write) => self.write_or_ask(write),
            Action::Confirmed(Answer::Write(write)) => self.write_now(write),
            // Into the new folder, asking again should anything be there meanwhile.
            Action::Confirmed(Answer::CreateFolder(folder, write)) => {
                match writes::create_folder(&folder) {
                    Ok(()) => self.write_or_ask(write),
                    Err(status) => self.status = Some(status),
                }
            }
            Action::Navigate(navigation) => {
                let (scene, size_px) = (&self.scene.loaded.scene, self.frames.size_px());
                self.viewing.navigate(navigation, scene, size_px);
            }
            Action::Pin(px) => {
                // The point itself is pinned, so the pin stays on it while the view moves.
                if let Some(probe) = self.probe_at(px) {
                    self.viewing.probe.pinned_world = Some(point_of_probe(&probe));
                }
            }
            Action::Unpin => self.viewing.probe.pinned_world = None,
            Action::CompareShow(show) => self.compare.show_if_open(show),
            Action::CompareFlip => self.compare.flip(),
            Action::CompareDifference => self.compare.toggle_difference(),
            Action::CompareClose => self.compare.close(),
            Action::Reload // (said above)
            | Action::AutoRange
            | Action::Undo
            | Action::Redo
            | Action::NameView(_)
            | Action::Trace
            | Action::CompareImage(..)
            | Action::CompareQuality => {}
        }
    }

    // What the viewer shows, read from outside: the tests and tools (screenshots, benchmarks)
    // drive the viewer through these and through `apply`.

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
        let scene = &self.scene.loaded.scene;
        self.frames.probe_at(scene, self.scene.epoch, px)
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
        let px = self.viewing.pinned_px(self.frames.shown.as_ref());
        px.and_then(|px| self.probe_at(px))
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

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if let Some(log) = &mut self.frames.log {
            log.ui(frame.info().cpu_usage);
        }
        self.poll_platform();
        if self.frames.take_in(&self.ctx, &mut self.status) {
            let (depth, shown) = (&self.settings.depth, self.frames.shown.as_ref());
            self.viewing.follow_depth(depth, shown, self.scene.epoch);
        }
        self.receive_scene();
        let (export, compare_path) = (&mut self.settings.export, &mut self.compare.path_text);
        let (saving_over, status) = (&mut self.scene.saving_over, &mut self.status);
        if let Some(action) = self
            .writes
            .take_in(export, compare_path, saving_over, status)
        {
            self.apply(action);
        }
        let (scene, view) = (&self.scene.loaded.scene, &mut self.viewing.view);
        self.compare.take_in(&ctx, scene, view, &mut self.status);
        let (help_open, watcher) = (self.panels.help_open, self.scene.watcher.as_ref());
        let input = input::read(&ctx, watcher, help_open, &self.viewing.view);
        for action in input.actions {
            self.apply(action);
        }
        self.say(input.refused);
        for file in input.dropped {
            self.open_dropped(file);
        }
        let window = layout::Window {
            settings: &mut self.settings,
            scene: &mut self.scene,
            viewing: &mut self.viewing,
            frames: &self.frames,
            writes: &mut self.writes,
            panels: &mut self.panels,
            compare: &mut self.compare,
            status: self.status.as_ref(),
        };
        for action in window.ui(ui) {
            self.apply(action);
        }
        if let Some(log) = &mut self.frames.log {
            log.missing_glyphs(&ctx, &self.scene.loaded.name());
        }
        self.viewing.observe();
        let (scene, wanted) = (&self.scene.loaded.scene, self.wanted());
        if !self.first_scene_on_its_way() {
            self.frames.submit_if_changed(scene, wanted, &self.ctx);
        }
        if layout::busy(&self.frames, &self.writes, &self.compare) {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    /// The page's handle reads the app through this (`app::web::WebHandle`).
    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(self)
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        let open = self.scene.loaded.path.as_deref();
        self.settings.views.remember(open, &self.viewing.view);
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }
}
