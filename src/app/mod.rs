//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`], hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! * [`state`]: the loaded scene, the persisted settings
//! * [`job`]: the render worker's job (render + texture pixels off the UI thread)
//! * [`images`]: the two images, their pointer gestures, the probe's lines
//! * [`depth_tools`]: the depth histogram with draggable ends, colour map and auto range
//! * [`panels`]: the side panel's sections and the status bar
//! * [`dialogs`]: native file dialogs on their own threads
//! * [`reload`]: watching the open file for changes
//! * [`loading`]: reading and parsing a scene file off the UI thread, with progress
//!
//! Navigation (mouse and keyboard) turns gestures into [`crate::explore::navigate`] calls; the probe is
//! [`crate::explore::probe`]; exports go through [`crate::export`].

pub mod depth_tools;
pub mod dialogs;
pub mod images;
pub mod job;
pub mod loading;
pub mod panels;
pub mod reload;
pub mod state;

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::Duration;

use egui::{Key, KeyboardShortcut, Modifiers, TextureHandle, TextureOptions};
use glam::DVec2;

use self::dialogs::{
    DialogAnswer, DialogKind, PendingDialog, dialog_unavailable_reason, spawn_dialog,
};
use self::images::{Footer, ImageGestures, ORBIT_RAD_PER_POINT, ShownImages};
use self::job::{DepthStyle, JobResult, ViewerJob, ViewerWorker, prepare_frame, start_worker};
use self::loading::{LoadKind, LoadState, PendingLoad};
use self::panels::StatusLine;
use self::state::{ExportFormat, LoadedScene, Settings};
use crate::cli::ViewerRequest;
use crate::explore::depth_stats::{DepthHistogram, auto_range};
use crate::explore::navigate;
use crate::explore::probe::{Probe, probe};
use crate::export::{ExportPlan, save_view_as_scene, write_export};
use crate::output::ImageFormat;
use crate::render::{Frame, Quality, View, check_image_size};

/// Keyboard pan step, as a fraction of the image's shorter side.
pub const KEY_PAN_FRACTION: f64 = 0.1;

/// Keyboard orbit step (Shift+arrow), radians.
pub const KEY_ORBIT_RAD: f64 = std::f64::consts::PI / 36.0;

/// Keyboard zoom step: `+` divides the size by this, `-` multiplies it.
pub const KEY_ZOOM_FACTOR: f64 = 1.25;

/// What the worker is asked for: a view of a scene load at a quality, its depth drawn in a style.
type Wanted = (View, u64, Quality, DepthStyle);

/// How long the view must stay unchanged before a preview is refined to the chosen quality.
pub const REFINE_DELAY: Duration = Duration::from_millis(150);

/// Image size used until the first layout tells the real one.
const INITIAL_SIZE_PX: (u32, u32) = (512, 512);

/// Opens the viewer window and runs it until closed.
pub fn run(request: ViewerRequest) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("raytracer")
            .with_inner_size([1280.0, 720.0])
            .with_min_inner_size([480.0, 320.0])
            .with_drag_and_drop(true),
        ..Default::default()
    };
    eframe::run_native(
        "raytracer",
        options,
        Box::new(|cc| Ok(Box::new(ViewerApp::new(cc, request)))),
    )
}

/// The frame on screen.
struct Shown {
    frame: Arc<Frame>,
    view: View,
    scene_epoch: u64,
    quality: Quality,
    depth_style: DepthStyle,
    colour: TextureHandle,
    depth: TextureHandle,
    histogram: Option<DepthHistogram>,
    render_ms: f64,
}

/// The viewer application.
pub struct ViewerApp {
    settings: Settings,
    loaded: LoadedScene,
    /// Incremented whenever another scene is loaded, so the same view of a new scene re-renders.
    scene_epoch: u64,
    view: View,
    worker: Option<ViewerWorker>,
    submitted: Option<Wanted>,
    shown: Option<Shown>,
    scene_error: Option<String>,
    message: Option<(String, bool)>,
    path_text: String,
    dialog: Option<PendingDialog>,
    dialog_note: Option<&'static str>,
    /// A background write (export or saved scene): the success or failure message.
    export_job: Option<Receiver<Result<String, String>>>,
    watcher: Option<reload::FileWatcher>,
    /// A scene file being read and parsed in the background.
    loading: Option<PendingLoad>,
    /// When the view, scene or quality last changed (for progressive refinement).
    last_change: std::time::Instant,
    /// What the last change was made to.
    last_wanted: Option<Wanted>,
    /// The pointer's position on an image (image pixels, y up), if over one.
    hover_px: Option<DVec2>,
    /// The pinned probe position (image pixels, y up).
    pinned_px: Option<DVec2>,
    ctx: egui::Context,
}

impl ViewerApp {
    /// Creates the viewer: settings from eframe's storage, the scene from the request (or the last
    /// scene, or the embedded default), and the render worker.
    pub fn new(cc: &eframe::CreationContext<'_>, request: ViewerRequest) -> Self {
        let mut settings: Settings = cc
            .storage
            .and_then(|storage| eframe::get_value(storage, eframe::APP_KEY))
            .unwrap_or_default();
        if let Some((width, height)) = request.size_px {
            settings.export.displayed_size = false;
            settings.export.size_px = [width, height];
        }
        if let Some(precision) = request.precision {
            settings.quality.precision = precision;
        }
        let mut message = None;
        let worker = match start_worker(&cc.egui_ctx) {
            Ok(worker) => Some(worker),
            Err(error) => {
                message = Some((format!("cannot start the render thread: {error}"), true));
                None
            }
        };
        let loaded = LoadedScene::default_scene(INITIAL_SIZE_PX);
        let mut app = Self {
            settings,
            view: loaded.file_view,
            loaded,
            scene_epoch: 0,
            worker,
            submitted: None,
            shown: None,
            scene_error: None,
            message,
            path_text: String::new(),
            dialog: None,
            dialog_note: dialog_unavailable_reason(),
            export_job: None,
            watcher: None,
            loading: None,
            last_change: std::time::Instant::now(),
            last_wanted: None,
            hover_px: None,
            pinned_px: None,
            ctx: cc.egui_ctx.clone(),
        };
        let startup_scene = request.input.or_else(|| app.settings.last_scene.clone());
        if let Some(path) = startup_scene {
            app.open(&path);
        }
        app
    }

    /// The view the controls currently describe.
    pub fn view(&self) -> &View {
        &self.view
    }

    /// Mutable access to the view (as the controls edit it).
    pub fn view_mut(&mut self) -> &mut View {
        &mut self.view
    }

    /// The scene on screen.
    pub fn loaded_scene(&self) -> &LoadedScene {
        &self.loaded
    }

    /// The frame on screen, with the view it was rendered for.
    pub fn shown_frame(&self) -> Option<(&Frame, &View)> {
        self.shown
            .as_ref()
            .map(|shown| (shown.frame.as_ref(), &shown.view))
    }

    /// True when the frame on screen is the current view of the current scene at the current
    /// quality.
    /// While a scene loads this is false: the frame will change once it is in.
    pub fn frame_is_current(&self) -> bool {
        let style = self.depth_style();
        self.loading.is_none()
            && self.shown.as_ref().is_some_and(|s| {
                s.view == self.view
                    && s.scene_epoch == self.scene_epoch
                    && s.quality == self.settings.quality
                    && s.depth_style == style
            })
    }

    /// The persisted settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// How the depth texture is coloured now.
    fn depth_style(&self) -> DepthStyle {
        DepthStyle {
            colour_map: self.settings.depth.colour_map,
            no_hit_rgb: self.settings.depth.no_hit_rgb(),
        }
    }

    /// The histogram of visible t of the frame on screen.
    pub fn histogram(&self) -> Option<&DepthHistogram> {
        self.shown.as_ref().and_then(|s| s.histogram.as_ref())
    }

    /// Probes the frame on screen at image position `px` (pixels, y up).
    pub fn probe_at(&self, px: DVec2) -> Option<Probe> {
        let shown = self.shown.as_ref()?;
        if shown.scene_epoch != self.scene_epoch || !(px.x >= 0.0 && px.y >= 0.0) {
            return None;
        }
        let (x_px, y_up_px) = (px.x.floor() as u32, px.y.floor() as u32);
        probe(&self.loaded.scene, &shown.view, &shown.frame, x_px, y_up_px)
    }

    /// The pointer's position on an image (image pixels, y up), if it is over one.
    pub fn hover_px(&self) -> Option<DVec2> {
        self.hover_px
    }

    /// The probe of the pixel under the pointer.
    pub fn hover_probe(&self) -> Option<Probe> {
        self.hover_px.and_then(|px| self.probe_at(px))
    }

    /// The probe of the pinned pixel.
    pub fn pinned_probe(&self) -> Option<Probe> {
        self.pinned_px.and_then(|px| self.probe_at(px))
    }

    /// "Auto range": fits the depth range to the t visible in the frame on screen, ignoring
    /// the settings' percentage at each end. Says so when no sphere is visible.
    pub fn auto_range(&mut self) {
        let cut = self.settings.depth.auto_cut_percent;
        match self.shown.as_ref().and_then(|s| auto_range(&s.frame, cut)) {
            Some(range) => self.view.depth_range = range,
            None => {
                self.message = Some(("auto range: no sphere is visible".into(), false));
            }
        }
    }

    /// "Frame all": fits centre and size to the scene's bounds (direction and up stay).
    pub fn frame_all(&mut self) {
        self.view = navigate::frame_all(&self.loaded.scene, &self.view);
    }

    /// Applies pointer gestures on the images: pan, orbit, zoom, hover and pin.
    pub fn apply_gestures(&mut self, gestures: &ImageGestures) {
        if gestures.pan_px != DVec2::ZERO {
            self.view = navigate::pan(&self.view, gestures.pan_px);
        }
        if gestures.orbit_points != DVec2::ZERO {
            let turn = gestures.orbit_points * ORBIT_RAD_PER_POINT;
            self.orbit(turn.x, turn.y);
        }
        if let Some((factor, anchor_px)) = gestures.zoom {
            self.view = navigate::zoom_at(&self.view, factor, anchor_px);
        }
        self.hover_px = gestures.hover_px;
        if let Some(px) = gestures.clicked_px {
            self.pinned_px = Some(px);
        }
        if gestures.unpin {
            self.pinned_px = None;
        }
    }

    /// The probe's lines: the pinned pixel, then the hovered one.
    fn probe_lines(&self) -> Vec<String> {
        let mut lines = Vec::new();
        for (name, probe) in [
            ("pinned", self.pinned_probe()),
            ("hover", self.hover_probe()),
        ] {
            if let Some(probe) = probe {
                lines.extend(describe_probe(name, &probe));
            }
        }
        lines
    }

    /// Orbits around the scene's centre: `yaw_rad` as a drag to the right, `pitch_rad` up.
    fn orbit(&mut self, yaw_rad: f64, pitch_rad: f64) {
        let pivot = navigate::orbit_pivot(&self.loaded.scene);
        self.view = navigate::orbit(&self.view, pivot, yaw_rad, pitch_rad);
    }

    /// The error of the last scene that failed to load, if shown.
    pub fn scene_error(&self) -> Option<&str> {
        self.scene_error.as_deref()
    }

    /// The status bar's message and whether it is an error.
    pub fn message(&self) -> Option<(&str, bool)> {
        self.message.as_ref().map(|(m, e)| (m.as_str(), *e))
    }

    /// True while an export runs.
    pub fn export_running(&self) -> bool {
        self.export_job.is_some()
    }

    /// The persisted settings.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// Waits (for tests and tools) until the worker has nothing to do.
    pub fn wait_for_worker(&self, timeout: Duration) -> bool {
        self.worker.as_ref().is_none_or(|w| w.wait_idle(timeout))
    }

    /// Starts loading the scene at `path` in the background; once read, it replaces the scene
    /// on screen and is watched for changes. On failure the error is shown and the previous scene
    /// stays. A load started while another runs replaces it.
    pub fn open(&mut self, path: &Path) {
        self.start_load(path, LoadKind::Open);
    }

    /// Reads the open file again (in the background). A broken file shows its error and the last
    /// good scene stays; a good one replaces the scene and keeps the user's camera unless it was
    /// still the file's.
    pub fn reload(&mut self) {
        let Some(path) = self.loaded.path.clone() else {
            self.message = Some((
                "the embedded default scene has no file to reload".into(),
                false,
            ));
            return;
        };
        self.start_load(&path, LoadKind::Reload);
    }

    /// True while a scene file is being read.
    pub fn loading(&self) -> bool {
        self.loading.is_some()
    }

    fn start_load(&mut self, path: &Path, kind: LoadKind) {
        let size = (self.view.width_px, self.view.height_px);
        let ctx = self.ctx.clone();
        match PendingLoad::start(path, kind, size, move || ctx.request_repaint()) {
            Ok(pending) => self.loading = Some(pending),
            Err(error) => {
                self.scene_error =
                    Some(format!("{}: cannot start loading: {error}", path.display()));
            }
        }
    }

    /// Takes a finished load: adopts the scene (an open also watches the file) or shows the
    /// error.
    fn poll_load(&mut self) {
        let Some(pending) = &self.loading else {
            return;
        };
        let result = match pending.poll() {
            LoadState::Running => {
                if pending.shows_progress() {
                    self.ctx.request_repaint_after(Duration::from_millis(50));
                } else {
                    self.ctx.request_repaint_after(loading::SHOW_PROGRESS_AFTER);
                }
                return;
            }
            LoadState::Done(result) => result,
        };
        let (path, kind) = (pending.path.clone(), pending.kind);
        self.loading = None;
        let loaded = match result {
            Ok(loaded) => loaded,
            Err(error) => {
                self.scene_error = Some(error);
                return;
            }
        };
        match kind {
            LoadKind::Open => self.adopt_opened(loaded, &path),
            LoadKind::Reload => {
                let still_file_view = View {
                    width_px: self.loaded.file_view.width_px,
                    height_px: self.loaded.file_view.height_px,
                    ..self.view
                } == self.loaded.file_view;
                self.adopt(loaded, !still_file_view);
                self.message = Some((format!("reloaded {}", path.display()), false));
            }
        }
    }

    /// Puts a newly opened scene on screen, remembers it and watches its file.
    fn adopt_opened(&mut self, loaded: LoadedScene, path: &Path) {
        self.adopt(loaded, false);
        self.pinned_px = None;
        self.settings.last_scene = Some(path.to_path_buf());
        self.path_text = path.display().to_string();
        self.ctx
            .send_viewport_cmd(egui::ViewportCommand::Title(format!(
                "raytracer — {}",
                path.display()
            )));
        let ctx = self.ctx.clone();
        self.watcher = match reload::FileWatcher::watch(path, move || ctx.request_repaint()) {
            Ok(watcher) => Some(watcher),
            Err(error) => {
                self.message = Some((format!("live reload is off: {error}"), true));
                None
            }
        };
    }

    /// Puts `loaded` on screen; `keep_view` keeps the current camera and depth range.
    fn adopt(&mut self, loaded: LoadedScene, keep_view: bool) {
        let (width_px, height_px) = (self.view.width_px, self.view.height_px);
        self.loaded = loaded;
        if !keep_view {
            self.view = View {
                width_px,
                height_px,
                ..self.loaded.file_view
            };
        }
        self.scene_epoch += 1;
        self.scene_error = None;
    }

    /// Restores the file's camera and initial depth range, keeping the image size.
    pub fn reset_view(&mut self) {
        let (width_px, height_px) = (self.view.width_px, self.view.height_px);
        self.view = View {
            width_px,
            height_px,
            ..self.loaded.file_view
        };
    }

    /// Exports the current view to `base_path` (see [`crate::export::ExportPaths`]) on a
    /// background thread; the outcome appears in the status bar.
    pub fn export_to(&mut self, base_path: PathBuf) {
        let export = self.settings.export.clone();
        let format = match export.format {
            ExportFormat::Png => ImageFormat::Png,
            ExportFormat::Tga => ImageFormat::Tga,
        };
        let mut view = self.view;
        if !export.displayed_size {
            view.width_px = export.size_px[0];
            view.height_px = export.size_px[1];
            if let Err(error) = check_image_size(view.width_px, view.height_px) {
                self.message = Some((format!("export: {error}"), true));
                return;
            }
        }
        let plan = ExportPlan {
            base_path,
            format,
            side_by_side: export.side_by_side,
            colour_map: self.settings.depth.colour_map,
            extra_depth: export.extra_depth,
        };
        let quality = self.settings.quality;
        // Reuse the frame on screen when it is exactly what would be exported.
        let ready = self
            .shown
            .as_ref()
            .filter(|s| {
                s.view == view
                    && s.scene_epoch == self.scene_epoch
                    && s.quality == self.settings.quality
            })
            .map(|s| Arc::clone(&s.frame));
        let job = ViewerJob {
            scene: Arc::clone(&self.loaded.scene),
            view,
            scene_epoch: self.scene_epoch,
            quality,
            depth_style: DepthStyle::default(),
        };
        self.write_in_background("exporting…", move || {
            let frame = match ready {
                Some(frame) => frame,
                None => prepare_frame(&job).map_err(|e| e.to_string())?.frame,
            };
            let written = write_export(&job.scene, &view, &quality, &frame, &plan)
                .map_err(|e| e.to_string())?;
            let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
            Ok(format!("exported {}", names.join(", ")))
        });
    }

    /// "Save view as scene": writes the scene with the current camera to `path` (in the
    /// background; the outcome appears in the status bar).
    pub fn save_view_to(&mut self, path: PathBuf) {
        let scene = Arc::clone(&self.loaded.scene);
        let view = self.view;
        self.write_in_background("saving the view…", move || {
            save_view_as_scene(&scene, &view, &path).map_err(|e| e.to_string())?;
            Ok(format!("saved the view as {}", path.display()))
        });
    }

    /// Runs `write` on a thread of its own; its message lands in the status bar.
    fn write_in_background(
        &mut self,
        running: &str,
        write: impl FnOnce() -> Result<String, String> + Send + 'static,
    ) {
        if self.export_job.is_some() {
            self.message = Some(("wait: a file is still being written".into(), true));
            return;
        }
        let (sender, receiver) = channel();
        let ctx = self.ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("export".into())
            .spawn(move || {
                let _ = sender.send(write());
                ctx.request_repaint();
            });
        match spawned {
            Ok(_) => {
                self.export_job = Some(receiver);
                self.message = Some((running.into(), false));
            }
            Err(error) => self.message = Some((format!("cannot start writing: {error}"), true)),
        }
    }

    fn receive_frame(&mut self, ctx: &egui::Context) {
        let Some(result) = self.worker.as_ref().and_then(|w| w.take_finished()) else {
            return;
        };
        let JobResult {
            job,
            output,
            render_time,
            ..
        } = result;
        match output {
            Ok(prepared) => {
                let render_ms = render_time.as_secs_f64() * 1e3;
                let scene_epoch = job.scene_epoch;
                match &mut self.shown {
                    Some(shown) => {
                        shown.colour.set(prepared.colour, TextureOptions::NEAREST);
                        shown.depth.set(prepared.depth, TextureOptions::NEAREST);
                        shown.frame = prepared.frame;
                        shown.view = job.view;
                        shown.scene_epoch = scene_epoch;
                        shown.quality = job.quality;
                        shown.depth_style = job.depth_style;
                        shown.histogram = prepared.histogram;
                        shown.render_ms = render_ms;
                    }
                    None => {
                        self.shown = Some(Shown {
                            depth_style: job.depth_style,
                            histogram: prepared.histogram,
                            colour: ctx.load_texture(
                                "colour",
                                prepared.colour,
                                TextureOptions::NEAREST,
                            ),
                            depth: ctx.load_texture(
                                "depth",
                                prepared.depth,
                                TextureOptions::NEAREST,
                            ),
                            frame: prepared.frame,
                            view: job.view,
                            scene_epoch,
                            quality: job.quality,
                            render_ms,
                        });
                    }
                }
                if self
                    .message
                    .as_ref()
                    .is_some_and(|(m, _)| m.starts_with("view: "))
                {
                    self.message = None;
                }
            }
            Err(error) => self.message = Some((format!("view: {error}"), true)),
        }
    }

    fn poll_background(&mut self) {
        if let Some(dialog) = &self.dialog {
            match dialog.poll() {
                DialogAnswer::Waiting => {}
                DialogAnswer::Chosen(DialogKind::Open, path) => {
                    self.dialog = None;
                    self.open(&path);
                }
                DialogAnswer::Chosen(DialogKind::Export, path) => {
                    self.dialog = None;
                    self.settings.export.path = path.display().to_string();
                    self.export_to(path);
                }
                DialogAnswer::Chosen(DialogKind::SaveScene, path) => {
                    self.dialog = None;
                    self.settings.export.scene_path = path.display().to_string();
                    self.save_view_to(path);
                }
                DialogAnswer::Cancelled(_) => self.dialog = None,
            }
        }
        if let Some(receiver) = &self.export_job {
            match receiver.try_recv() {
                Ok(Ok(done)) => {
                    self.message = Some((done, false));
                    self.export_job = None;
                }
                Ok(Err(error)) => {
                    self.message = Some((format!("writing failed: {error}"), true));
                    self.export_job = None;
                }
                Err(TryRecvError::Empty) => {}
                Err(TryRecvError::Disconnected) => {
                    self.message = Some(("export failed: the export thread stopped".into(), true));
                    self.export_job = None;
                }
            }
        }
    }

    fn open_dialog(&mut self, kind: DialogKind) {
        if let Some(reason) = self.dialog_note {
            self.message = Some((reason.into(), true));
            return;
        }
        if self.dialog.is_some() {
            return;
        }
        let suggested = match kind {
            DialogKind::SaveScene => &self.settings.export.scene_path,
            _ => &self.settings.export.path,
        };
        match spawn_dialog(kind, &self.ctx, suggested) {
            Ok(dialog) => self.dialog = Some(dialog),
            Err(error) => {
                self.message = Some((format!("cannot open a file dialog: {error}"), true))
            }
        }
    }

    fn handle_input(&mut self, ctx: &egui::Context) {
        let open = KeyboardShortcut::new(Modifiers::COMMAND, Key::O);
        let save = KeyboardShortcut::new(Modifiers::COMMAND, Key::S);
        let reload = KeyboardShortcut::new(Modifiers::COMMAND, Key::R);
        let (open_pressed, save_pressed, reload_pressed, dropped) = ctx.input_mut(|input| {
            (
                input.consume_shortcut(&open),
                input.consume_shortcut(&save),
                input.consume_shortcut(&reload),
                input
                    .raw
                    .dropped_files
                    .iter()
                    .map(|file| file.path().to_path_buf())
                    .find(|path| !path.as_os_str().is_empty()),
            )
        });
        if open_pressed {
            self.open_dialog(DialogKind::Open);
        }
        if save_pressed {
            self.open_dialog(DialogKind::Export);
        }
        if reload_pressed {
            self.reload();
        }
        match self.watcher.as_ref().map(reload::FileWatcher::poll) {
            Some(reload::WatchState::Changed) => self.reload(),
            Some(reload::WatchState::Settling(wait)) => ctx.request_repaint_after(wait),
            _ => {}
        }
        if let Some(path) = dropped {
            self.open(&path);
        }
        self.navigation_keys(ctx);
    }

    /// Keyboard navigation while no text field or slider has the keyboard: arrows move the
    /// camera, Shift+arrows orbit, `+`/`-` zoom at the image centre, F frames all, Home resets,
    /// A fits the depth range, Escape unpins the probe.
    fn navigation_keys(&mut self, ctx: &egui::Context) {
        if ctx.memory(|memory| memory.focused().is_some()) {
            return;
        }
        let (shift, pressed) = ctx.input(|input| {
            let keys = [
                Key::ArrowLeft,
                Key::ArrowRight,
                Key::ArrowUp,
                Key::ArrowDown,
                Key::Plus,
                Key::Equals,
                Key::Minus,
                Key::F,
                Key::Home,
                Key::A,
                Key::Escape,
            ];
            let pressed: Vec<Key> = keys
                .into_iter()
                .filter(|&key| input.key_pressed(key))
                .collect();
            (input.modifiers.shift, pressed)
        });
        let (width, height) = (
            f64::from(self.view.width_px),
            f64::from(self.view.height_px),
        );
        let step_px = KEY_PAN_FRACTION * width.min(height);
        let centre_px = DVec2::new(0.5 * width, 0.5 * height);
        for key in pressed {
            let arrow = match key {
                Key::ArrowLeft => Some(DVec2::NEG_X),
                Key::ArrowRight => Some(DVec2::X),
                Key::ArrowUp => Some(DVec2::Y),
                Key::ArrowDown => Some(DVec2::NEG_Y),
                _ => None,
            };
            match (key, arrow) {
                (_, Some(direction)) if shift => {
                    let turn = direction * KEY_ORBIT_RAD;
                    self.orbit(turn.x, turn.y);
                }
                // The camera moves along the arrow: the picture moves the other way.
                (_, Some(direction)) => {
                    self.view = navigate::pan(&self.view, -direction * step_px);
                }
                (Key::Plus | Key::Equals, _) => {
                    self.view = navigate::zoom_at(&self.view, 1.0 / KEY_ZOOM_FACTOR, centre_px);
                }
                (Key::Minus, _) => {
                    self.view = navigate::zoom_at(&self.view, KEY_ZOOM_FACTOR, centre_px);
                }
                (Key::F, _) => self.frame_all(),
                (Key::Home, _) => self.reset_view(),
                (Key::A, _) => self.auto_range(),
                (Key::Escape, _) => self.pinned_px = None,
                _ => {}
            }
        }
    }

    fn toolbar_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            if ui
                .button("Open…")
                .on_hover_text("Open a scene file (Ctrl+O)")
                .clicked()
            {
                self.open_dialog(DialogKind::Open);
            }
            if ui
                .button("Export…")
                .on_hover_text("Export colour and depth images (Ctrl+S)")
                .clicked()
            {
                self.open_dialog(DialogKind::Export);
            }
            if ui
                .button("Reload")
                .on_hover_text(
                    "Read the scene file again (Ctrl+R); it also reloads by itself when it changes",
                )
                .clicked()
            {
                self.reload();
            }
            if ui
                .button("Frame all")
                .on_hover_text("Fit centre and size to the whole scene (F)")
                .clicked()
            {
                self.frame_all();
            }
            if ui
                .button("Reset view")
                .on_hover_text("Back to the file's camera (Home)")
                .clicked()
            {
                self.reset_view();
            }
            if ui
                .button("Save view as scene…")
                .on_hover_text("Write the scene with the current camera to a file")
                .clicked()
            {
                self.open_dialog(DialogKind::SaveScene);
            }
            ui.toggle_value(&mut self.settings.show_controls, "Controls")
                .on_hover_text(
                    "Drag an image to pan, wheel to zoom, right-drag or Shift-drag to orbit; \
                     arrows, Shift+arrows, + and - do the same from the keyboard",
                );
        });
    }

    fn side_panel_ui(&mut self, ui: &mut egui::Ui) {
        egui::ScrollArea::vertical().show(ui, |ui| {
            let ranges = self.loaded.ranges(&self.view);
            panels::controls_ui(ui, &mut self.view, &ranges);
            let depth = depth_tools::depth_tools_ui(ui, &mut self.settings.depth);
            if depth.auto_range {
                self.auto_range();
            }
            ui.separator();
            panels::quality_ui(ui, &mut self.settings.quality);
            ui.separator();
            let file = panels::file_ui(
                ui,
                &mut self.path_text,
                &mut self.settings.export.scene_path,
            );
            if let Some(path) = file.open_path {
                self.open(Path::new(path.trim()));
            }
            if file.save_view {
                let path = PathBuf::from(self.settings.export.scene_path.trim());
                self.save_view_to(path);
            }
            ui.separator();
            let export = panels::export_ui(ui, &mut self.settings.export, self.dialog_note);
            if export.export_to_path {
                let path = PathBuf::from(self.settings.export.path.trim());
                self.export_to(path);
            }
        });
    }

    /// Progressive refinement: while the view keeps changing, one sample per pixel (a preview);
    /// once it has been still for [`REFINE_DELAY`], the chosen quality.
    fn submit_if_changed(&mut self) {
        let style = self.depth_style();
        let chosen = (self.view, self.scene_epoch, self.settings.quality, style);
        if self.last_wanted != Some(chosen) {
            self.last_wanted = Some(chosen);
            self.last_change = std::time::Instant::now();
        }
        let still_for = self.last_change.elapsed();
        let refine = self.settings.quality.sampling.is_none() || still_for >= REFINE_DELAY;
        let quality = if refine {
            self.settings.quality
        } else {
            self.ctx
                .request_repaint_after(REFINE_DELAY.saturating_sub(still_for));
            Quality {
                sampling: None,
                ..self.settings.quality
            }
        };
        let wanted = (self.view, self.scene_epoch, quality, style);
        if self.submitted == Some(wanted) {
            return;
        }
        if let Some(worker) = &self.worker {
            worker.submit(ViewerJob {
                scene: Arc::clone(&self.loaded.scene),
                view: self.view,
                scene_epoch: self.scene_epoch,
                quality,
                depth_style: style,
            });
            self.submitted = Some(wanted);
        }
    }

    /// Whether the frame on screen is a one-sample preview of a supersampled quality.
    pub fn showing_preview(&self) -> bool {
        self.shown.as_ref().is_some_and(|s| {
            s.quality.sampling.is_none() && self.settings.quality.sampling.is_some()
        })
    }
}

/// Three lines describing a probe: where the pixel is, what its ray hits, and where.
pub fn describe_probe(name: &str, probe: &Probe) -> Vec<String> {
    let short = images::short_number;
    let mut lines = vec![format!(
        "{name:<6} pixel ({}, {}) · screen ({}, {})",
        probe.x_px,
        probe.y_up_px,
        short(probe.screen_world.x),
        short(probe.screen_world.y)
    )];
    match &probe.hit {
        None => lines.push("       no hit".to_owned()),
        Some(hit) => {
            let material = match hit.material_index {
                Some(index) => format!(
                    "material #{index} ({}, {}, {})",
                    short(f64::from(hit.diffuse_colour.x)),
                    short(f64::from(hit.diffuse_colour.y)),
                    short(f64::from(hit.diffuse_colour.z))
                ),
                None => "default material (white)".to_owned(),
            };
            lines.push(format!(
                "       t {} · sphere #{} · {material}",
                short(hit.t),
                hit.sphere_index
            ));
            lines.push(format!(
                "       hit at world ({}, {}, {})",
                short(hit.point_world.x),
                short(hit.point_world.y),
                short(hit.point_world.z)
            ));
        }
    }
    lines
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        self.receive_frame(&ctx);
        self.poll_load();
        self.poll_background();
        self.handle_input(&ctx);

        egui::Panel::top("toolbar").show(ui, |ui| self.toolbar_ui(ui));
        if let Some(error) = self.scene_error.clone() {
            egui::Panel::top("scene_error").show(ui, |ui| {
                if panels::error_banner_ui(ui, &error) {
                    self.scene_error = None;
                }
            });
        }
        let busy = self.worker.as_ref().is_some_and(|w| !w.is_idle()) || self.export_job.is_some();
        let scene_name = self.loaded.name();
        let status = StatusLine {
            render_ms: self.shown.as_ref().map(|s| s.render_ms),
            size_px: self
                .shown
                .as_ref()
                .map(|s| [s.frame.width_px, s.frame.height_px]),
            precision: self.shown.as_ref().map(|s| s.frame.precision),
            stage: self.shown.as_ref().map(|s| match s.quality.sampling {
                _ if self.showing_preview() => "preview (1 sample)".to_owned(),
                Some(sampling) => format!(
                    "{} {} samples, {}",
                    sampling.samples,
                    sampling.sampler.name(),
                    sampling.filter
                ),
                None => "1 sample".to_owned(),
            }),
            sphere_count: self.loaded.scene.spheres.len(),
            scene_name: &scene_name,
            busy,
            loading: self
                .loading
                .as_ref()
                .filter(|pending| pending.shows_progress())
                .map(|pending| (pending.path.display().to_string(), pending.fraction())),
            message: self.message.as_ref().map(|(m, e)| (m.as_str(), *e)),
        };
        egui::Panel::bottom("status").show(ui, |ui| panels::status_bar_ui(ui, &status));
        if self.settings.show_controls {
            // The images keep at least half of the window.
            let max_width = (0.5 * ui.available_width()).max(160.0);
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(330.0_f32.min(max_width))
                .max_size(max_width)
                .show(ui, |ui| self.side_panel_ui(ui));
        }
        let probe_lines = self.probe_lines();
        let style = self.depth_style();
        let shown = self.shown.as_ref().map(|s| ShownImages {
            colour: &s.colour,
            depth: &s.depth,
            size_px: [s.frame.width_px, s.frame.height_px],
            depth_range: s.view.depth_range,
            histogram: s.histogram.as_ref(),
        });
        let footer = Footer {
            probe_lines: &probe_lines,
            pinned: self.pinned_px,
            depth_range: &mut self.view.depth_range,
            colour_map: style.colour_map,
            no_hit_rgb: style.no_hit_rgb,
        };
        let gestures = egui::CentralPanel::default()
            .show(ui, |ui| images::images_ui(ui, shown, footer))
            .inner;
        self.apply_gestures(&gestures);
        let (width_px, height_px) = gestures.wanted_px;
        if (width_px, height_px) != (self.view.width_px, self.view.height_px) {
            // The same world point stays under the pinned probe only in pixels of this size.
            self.pinned_px = None;
        }
        self.view.width_px = width_px;
        self.view.height_px = height_px;
        self.submit_if_changed();
        if busy {
            ctx.request_repaint_after(Duration::from_millis(100));
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }
}
