//! The viewer's coordinator, [`ViewerApp`]: it holds each feature's state, routes input and
//! [`Action`]s between them, takes in background work, draws through [`super::layout`]; tests
//! drive it through its read access (view, frame, probe, messages) and [`ViewerApp::apply`].

use std::path::Path;
use std::time::Duration;

use glam::DVec2;

use super::actions::{Action, Write};
use super::asked::Asked;
use super::confirm::Answer;
use super::depth_stats::DepthHistogram;
use super::loaded_scene::LoadedScene;
use super::probe::{Probe, point_of_probe};
use super::saved_views::SceneViews;
use super::scene_loading::{LoadKind, OpenScene};
use super::seam::Seam;
use super::settings::Settings;
use super::status::{self, Status};
use super::ui::magnifier::Magnifier;
use super::{compare, input, layout, pixel_trace, render_requests, viewing, writes};
use crate::cli::ViewerRequest;
use crate::compare::their_image::decode_their_image;
use crate::render::{Frame, View};
use crate::scene::bundled::BUNDLED_SCENES;

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
    /// Where the viewer runs: the desktop, or a browser page with its files on their way in.
    pub(super) seam: Seam,
    pub(super) ctx: egui::Context,
}

impl ViewerApp {
    /// Creates the viewer: settings from eframe's storage, the scene from the request (or the last
    /// scene, or the embedded default), and the render worker.
    pub fn new(cc: &eframe::CreationContext<'_>, request: ViewerRequest) -> Self {
        Self::with_seam(cc, request, Seam::default())
    }

    /// The viewer on `seam` (a page's script gives the page it started: `start::page`).
    pub(super) fn with_seam(
        cc: &eframe::CreationContext<'_>,
        request: ViewerRequest,
        seam: Seam,
    ) -> Self {
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
            seam,
            ctx: cc.egui_ctx.clone(),
        };
        let last = app.settings.last_scene.as_deref();
        if let Some(path) = app.seam.first_scene(request.input, last) {
            app.open(&path);
        }
        app
    }

    /// Carries out what the seam asked for.
    fn take_asked(&mut self, asked: impl IntoIterator<Item = Asked>) {
        for asked in asked {
            match asked {
                Asked::Open(path) => self.open(&path),
                Asked::OpenBytes(name, bytes) => self.open_bytes(&name, bytes),
                Asked::Apply(action) => self.apply(action),
                Asked::Say(status) => self.status = Some(status),
                Asked::SceneError(message) => self.scene.error = Some(message),
                Asked::CompareBytes(name, kind, bytes) => {
                    let read = move |path: &Path| decode_their_image(path, &bytes);
                    let said = self
                        .compare
                        .with_image(&self.against(), name.into(), kind, read);
                    self.say(said);
                }
            }
        }
    }

    /// What a comparison started now is made against.
    fn against(&self) -> compare::Against {
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
        self.seam
            .set_title(&self.ctx, &format!("raytracer — {}", path.display()));
    }

    /// Carries out `write` now if it replaces nothing, else asks ([`writes::Writer`]); the seam
    /// writes its files.
    fn write_or_ask(&mut self, write: Write) {
        let typed_folder = &self.settings.export.path;
        let missing_folder = self.seam.missing_export_folder(&write, typed_folder);
        let staged = self.writer().write_or_ask(write, missing_folder);
        self.write_staged(staged);
    }

    /// Hands the files staged to the seam to write; or says why they were not.
    fn write_staged(&mut self, staged: Option<Result<writes::StagedWrite, Status>>) {
        let status = match staged {
            Some(Ok(staged)) => {
                let said = (staged.running, staged.done);
                let (writes, ctx) = (&mut self.writes, &self.ctx);
                self.seam.write_files(writes, ctx, said, staged.stage)
            }
            Some(Err(status)) => status,
            None => return,
        };
        self.status = Some(status);
    }

    /// What a write needs of the viewer's features.
    fn writer(&mut self) -> writes::Writer<'_> {
        writes::Writer {
            writes: &mut self.writes,
            settings: &self.settings,
            scene: &mut self.scene,
            compared: self.compare.watched_files(),
            view: self.viewing.view,
            shown: self.frames.shown.as_ref(),
        }
    }

    /// Carries out `action`. A one-shot view change is a step of the history of its own.
    pub(crate) fn apply(&mut self, action: Action) {
        let one_shot = action.is_one_shot();
        let before = self.viewing.view;
        self.carry_out(action);
        if one_shot {
            self.viewing.history.one_shot(&before, &self.viewing.view);
        }
    }

    /// Hands `action` to the feature that carries it out; what it says goes to the status bar.
    fn carry_out(&mut self, action: Action) {
        let status = match action {
            action if action.is_the_views() => {
                let inputs = viewing::ViewInputs {
                    loaded: &self.scene.loaded,
                    shown: self.frames.shown.as_ref(),
                    views: &mut self.settings.views,
                    auto_cut_percent: self.settings.depth.auto_cut_percent,
                };
                self.viewing.carry_out(action, inputs)
            }
            Action::Reload => self.scene.reload(&self.viewing.view, &self.ctx),
            Action::Trace => {
                let view = self.frames.shown.as_ref().map(|shown| &shown.view);
                let px = self.viewing.pinned_px(self.frames.shown.as_ref());
                let scene = &self.scene.loaded.scene;
                pixel_trace::open(&mut self.panels.trace, scene, view, px, &self.compare)
            }
            Action::CompareImage(path, kind) => self.compare.with_file(&self.against(), path, kind),
            Action::CompareQuality => {
                let quality = self.settings.quality;
                self.compare.with_quality(&self.against(), quality)
            }
            other => return self.carry_out_quietly(other),
        };
        self.say(status);
    }

    /// Hands `action`, one that says nothing, to the feature that carries it out (the seam's
    /// requests, what it asks for, are carried out in turn).
    fn carry_out_quietly(&mut self, action: Action) {
        let asked = match action {
            Action::OpenDialog(kind) => {
                let (writes, export) = (&mut self.writes, &self.settings.export);
                self.seam.open_dialog(kind, writes, export, &self.ctx)
            }
            Action::Open(path) => self.seam.open_path(&path),
            Action::OpenBundled(index) => BUNDLED_SCENES
                .get(index)
                .map(|(name, text)| Asked::OpenBytes((*name).into(), text.as_bytes().into())),
            Action::ToggleHelp => {
                self.panels.help_open = !self.panels.help_open;
                None
            }
            Action::Write(write) => return self.write_or_ask(write),
            Action::Confirmed(Answer::Write(write)) => {
                let staged = self.writer().write_now(write);
                return self.write_staged(Some(staged));
            }
            // Into the new folder, asking again should anything be there meanwhile.
            Action::Confirmed(Answer::CreateFolder(folder, write)) => {
                match writes::create_folder(&folder) {
                    Ok(()) => return self.write_or_ask(write),
                    Err(status) => Some(Asked::Say(status)),
                }
            }
            Action::Pin(px) => {
                // The point itself is pinned, so the pin stays on it while the view moves.
                if let Some(probe) = self.probe_at(px) {
                    self.viewing.probe.pinned_world = Some(point_of_probe(&probe));
                }
                None
            }
            Action::CompareShow(show) => return self.compare.show_if_open(show),
            Action::CompareFlip => return self.compare.flip(),
            Action::CompareDifference => return self.compare.toggle_difference(),
            Action::CompareClose => return self.compare.close(),
            _ => None, // (carried out in carry_out)
        };
        self.take_asked(asked);
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
        self.frames.shown.as_ref()?.histogram.as_ref()
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
        let status = self.status.as_ref()?;
        Some((status.text.as_str(), status.is_error()))
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
        let worker = self.frames.worker.as_ref();
        worker.is_none_or(|worker| worker.wait_idle(timeout))
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
        let asked = self.seam.poll(&self.ctx, self.compare.closes);
        self.take_asked(asked);
        if self.frames.take_in(&self.ctx, &mut self.status) {
            let (depth, shown) = (&self.settings.depth, self.frames.shown.as_ref());
            self.viewing.follow_depth(depth, shown, self.scene.epoch);
        }
        self.receive_scene();
        let (export, compare_path) = (&mut self.settings.export, &mut self.compare.path_text);
        let (saving_over, status) = (&mut self.scene.saving_over, &mut self.status);
        let action = self
            .writes
            .take_in(export, compare_path, saving_over, status);
        action.into_iter().for_each(|action| self.apply(action));
        let (scene, view) = (&self.scene.loaded.scene, &mut self.viewing.view);
        self.compare.take_in(&ctx, scene, view, &mut self.status);
        let (help_open, watcher) = (self.panels.help_open, self.scene.watcher.as_ref());
        let input = input::read(&ctx, watcher, help_open, &self.viewing.view);
        for action in input.actions {
            self.apply(action);
        }
        self.say(input.refused);
        for file in input.dropped {
            let asked = self.seam.dropped(file, self.compare.kind);
            self.take_asked(asked);
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
        if self.frames.shown.is_some() || !self.seam.first_scene_on_its_way() {
            self.frames.submit_if_changed(scene, wanted, &self.ctx);
        }
        if layout::busy(&self.frames, &self.writes, &self.compare) {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    /// The page's handle reads the app through this (`app::start::page::WebHandle`).
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
