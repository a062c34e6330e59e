//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`], hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! * [`state`]: the loaded scene, the persisted settings
//! * [`job`]: the render worker's job (render + texture pixels off the UI thread)
//! * [`panels`]: the `*_ui` functions
//! * [`dialogs`]: native file dialogs on their own threads

pub mod dialogs;
pub mod job;
pub mod panels;
pub mod reload;
pub mod state;

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::Duration;

use egui::{Key, KeyboardShortcut, Modifiers, TextureHandle, TextureOptions};

use self::dialogs::{
    DialogAnswer, DialogKind, PendingDialog, dialog_unavailable_reason, spawn_dialog,
};
use self::job::{JobResult, ViewerJob, ViewerWorker, prepare_frame, start_worker};
use self::panels::{ShownImages, StatusLine};
use self::state::{ExportFormat, LoadedScene, Settings};
use crate::cli::ViewerRequest;
use crate::export::{ImageFormat, write_frame_images};
use crate::render::{Frame, Quality, View, check_image_size};

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
    colour: TextureHandle,
    depth: TextureHandle,
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
    submitted: Option<(View, u64, Quality)>,
    shown: Option<Shown>,
    scene_error: Option<String>,
    message: Option<(String, bool)>,
    path_text: String,
    dialog: Option<PendingDialog>,
    dialog_note: Option<&'static str>,
    export_job: Option<Receiver<Result<Vec<PathBuf>, String>>>,
    watcher: Option<reload::FileWatcher>,
    /// When the view, scene or quality last changed (for progressive refinement).
    last_change: std::time::Instant,
    /// What the last change was made to.
    last_wanted: Option<(View, u64, Quality)>,
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
            last_change: std::time::Instant::now(),
            last_wanted: None,
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
    pub fn frame_is_current(&self) -> bool {
        self.shown.as_ref().is_some_and(|s| {
            s.view == self.view
                && s.scene_epoch == self.scene_epoch
                && s.quality == self.settings.quality
        })
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

    /// Loads the scene at `path`; on failure the error is shown and the previous scene stays.
    /// The file is then watched and reloaded when it changes on disk.
    pub fn open(&mut self, path: &Path) {
        let size = (self.view.width_px, self.view.height_px);
        match LoadedScene::load(path, size) {
            Ok(loaded) => {
                self.adopt(loaded, false);
                self.settings.last_scene = Some(path.to_path_buf());
                self.path_text = path.display().to_string();
                self.ctx
                    .send_viewport_cmd(egui::ViewportCommand::Title(format!(
                        "raytracer — {}",
                        path.display()
                    )));
                let ctx = self.ctx.clone();
                self.watcher = match reload::FileWatcher::watch(path, move || ctx.request_repaint())
                {
                    Ok(watcher) => Some(watcher),
                    Err(error) => {
                        self.message = Some((format!("live reload is off: {error}"), true));
                        None
                    }
                };
            }
            Err(error) => self.scene_error = Some(error.to_string()),
        }
    }

    /// Reads the open file again. A broken file shows its error and the last good scene stays;
    /// a good one replaces the scene and keeps the user's camera unless it was still the file's.
    pub fn reload(&mut self) {
        let Some(path) = self.loaded.path.clone() else {
            self.message = Some((
                "the embedded default scene has no file to reload".into(),
                false,
            ));
            return;
        };
        let size = (self.view.width_px, self.view.height_px);
        match LoadedScene::load(&path, size) {
            Ok(loaded) => {
                let still_file_view = View {
                    width_px: self.loaded.file_view.width_px,
                    height_px: self.loaded.file_view.height_px,
                    ..self.view
                } == self.loaded.file_view;
                self.adopt(loaded, !still_file_view);
                self.message = Some((format!("reloaded {}", path.display()), false));
            }
            Err(error) => self.scene_error = Some(error.to_string()),
        }
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
            quality: self.settings.quality,
        };
        let (sender, receiver) = channel();
        let ctx = self.ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("export".into())
            .spawn(move || {
                let frame = match ready {
                    Some(frame) => Ok(frame),
                    None => prepare_frame(&job).map(|p| p.frame),
                };
                let outcome = frame.map_err(|e| e.to_string()).and_then(|frame| {
                    write_frame_images(
                        &frame,
                        view.depth_range,
                        &base_path,
                        format,
                        export.side_by_side,
                    )
                    .map_err(|e| e.to_string())
                });
                let _ = sender.send(outcome);
                ctx.request_repaint();
            });
        match spawned {
            Ok(_) => {
                self.export_job = Some(receiver);
                self.message = Some(("exporting…".into(), false));
            }
            Err(error) => self.message = Some((format!("export: cannot start: {error}"), true)),
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
                        shown.render_ms = render_ms;
                    }
                    None => {
                        self.shown = Some(Shown {
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
                DialogAnswer::Cancelled(_) => self.dialog = None,
            }
        }
        if let Some(receiver) = &self.export_job {
            match receiver.try_recv() {
                Ok(Ok(paths)) => {
                    let names: Vec<String> =
                        paths.iter().map(|p| p.display().to_string()).collect();
                    self.message = Some((format!("exported {}", names.join(", ")), false));
                    self.export_job = None;
                }
                Ok(Err(error)) => {
                    self.message = Some((format!("export failed: {error}"), true));
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
        match spawn_dialog(kind, &self.ctx, &self.settings.export.path) {
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
                .button("Reset view")
                .on_hover_text("Back to the file's camera")
                .clicked()
            {
                self.reset_view();
            }
            ui.toggle_value(&mut self.settings.show_controls, "Controls");
        });
    }

    fn side_panel_ui(&mut self, ui: &mut egui::Ui) {
        egui::ScrollArea::vertical().show(ui, |ui| {
            let ranges = self.loaded.ranges(&self.view);
            panels::controls_ui(ui, &mut self.view, &ranges);
            ui.separator();
            panels::quality_ui(ui, &mut self.settings.quality);
            ui.separator();
            let file = panels::file_ui(ui, &mut self.path_text);
            if let Some(path) = file.open_path {
                self.open(Path::new(path.trim()));
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
        let chosen = (self.view, self.scene_epoch, self.settings.quality);
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
        let wanted = (self.view, self.scene_epoch, quality);
        if self.submitted == Some(wanted) {
            return;
        }
        if let Some(worker) = &self.worker {
            worker.submit(ViewerJob {
                scene: Arc::clone(&self.loaded.scene),
                view: self.view,
                scene_epoch: self.scene_epoch,
                quality,
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

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        self.receive_frame(&ctx);
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
        let shown = self.shown.as_ref().map(|s| ShownImages {
            colour: &s.colour,
            depth: &s.depth,
            size_px: [s.frame.width_px, s.frame.height_px],
            depth_range: s.view.depth_range,
        });
        let (width_px, height_px) = egui::CentralPanel::default()
            .show(ui, |ui| panels::images_ui(ui, shown))
            .inner;
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
