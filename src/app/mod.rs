//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`], hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! [`ViewerApp`] coordinates; each concern lives in a module of its own:
//! * [`state`]: the loaded scene, the persisted settings
//! * [`job`]: the render worker's job (render + texture pixels off the UI thread)
//! * [`frames`]: asking the worker for frames (progressive refinement) and taking them in
//! * [`scene_loading`]: opening and reloading scene files in the background
//! * [`actions`]: what the user can ask for ([`actions::Action`]), exports, dialogs
//! * [`confirm`]: asking before a write replaces files
//! * [`input`]: shortcuts, dropped files, keyboard and pointer navigation
//! * [`tasks`]: the one background-task type (loads, writes, dialogs)
//! * [`status`]: the typed status-bar message
//! * [`dialogs`]: native file dialogs; [`reload`]: watching the open file
//! * [`inspect`]: read access for tests and tools
//! * [`window`]: opening the window (or saying why none can be opened)
//! * [`ui`]: the drawing, one `*_ui` function per part

pub(crate) mod actions;
pub(crate) mod confirm;
pub(crate) mod dialogs;
pub(crate) mod frames;
pub(crate) mod input;
pub(crate) mod inspect;
pub mod job;
pub(crate) mod reload;
pub(crate) mod scene_loading;
pub mod state;
pub(crate) mod status;
pub(crate) mod tasks;
pub mod ui;
pub(crate) mod window;

use std::path::PathBuf;
use std::time::Duration;

use glam::DVec2;

use self::actions::Action;
use self::dialogs::{PendingDialog, dialog_unavailable_reason};
use self::frames::{Requests, Shown};
use self::job::{ViewerWorker, start_worker};
use self::scene_loading::PendingLoad;
use self::state::{LoadedScene, Settings};
use self::status::Status;
use self::tasks::Task;
use self::ui::images::{Footer, ShownImages, images_ui};
use self::ui::status_bar::{StatusLine, error_banner_ui, status_bar_ui};
use self::ui::{depth_section, file_sections, probe_text, toolbar, view_controls};
use crate::cli::ViewerRequest;
use crate::render::View;

pub use self::input::{KEY_ORBIT_RAD, KEY_PAN_FRACTION, KEY_ZOOM_FACTOR};
pub use self::window::{no_display_reason, run};

/// Image size used until the first layout tells the real one.
const INITIAL_SIZE_PX: (u32, u32) = (512, 512);

/// The pointer's and the pinned probe's positions (image pixels, y up).
#[derive(Debug, Clone, Copy, Default)]
struct ProbePoints {
    hover_px: Option<DVec2>,
    pinned_px: Option<DVec2>,
}

/// The viewer application.
pub struct ViewerApp {
    settings: Settings,
    loaded: LoadedScene,
    /// Incremented whenever another scene is loaded, so the same view of a new scene re-renders.
    scene_epoch: u64,
    view: View,
    worker: Option<ViewerWorker>,
    requests: Requests,
    shown: Option<Shown>,
    scene_error: Option<String>,
    status: Option<Status>,
    /// The typed scene path of the file section.
    path_text: String,
    dialog: Option<PendingDialog>,
    /// Why no file dialog can be shown here, if none can.
    dialog_note: Option<&'static str>,
    /// A background write (export or saved scene): its outcome message.
    writing: Option<Task<Result<String, String>>>,
    watcher: Option<reload::FileWatcher>,
    loading: Option<PendingLoad>,
    probe: ProbePoints,
    /// The `raytracer` binary export scripts run.
    program: Option<PathBuf>,
    /// "Save view as scene" is writing over the open scene (its reload keeps the save's message).
    saving_open_scene: bool,
    /// A write that waits for the user to agree to replace files.
    pending_replace: Option<confirm::PendingReplace>,
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
        let (worker, status) = match start_worker(&cc.egui_ctx) {
            Ok(worker) => (Some(worker), None),
            Err(error) => (
                None,
                Some(Status::error(format!(
                    "cannot start the render thread: {error}"
                ))),
            ),
        };
        let loaded = LoadedScene::default_scene(INITIAL_SIZE_PX);
        let mut app = Self {
            settings,
            view: loaded.file_view,
            loaded,
            scene_epoch: 0,
            worker,
            requests: Requests::default(),
            shown: None,
            scene_error: None,
            status,
            path_text: String::new(),
            dialog: None,
            dialog_note: dialog_unavailable_reason(),
            writing: None,
            watcher: None,
            loading: None,
            probe: ProbePoints::default(),
            pending_replace: None,
            saving_open_scene: false,
            program: request.program.clone(),
            ctx: cc.egui_ctx.clone(),
        };
        let ctx = cc.egui_ctx.clone();
        crate::cli::process::set_wake(move || ctx.request_repaint());
        let startup_scene = request.input.or_else(|| app.settings.last_scene.clone());
        if let Some(path) = startup_scene {
            app.open(&path);
        }
        app
    }

    /// The side panel: view controls, depth tools, quality, file and export sections.
    fn side_panel_ui(&mut self, ui: &mut egui::Ui) -> Vec<Action> {
        let mut actions = Vec::new();
        egui::ScrollArea::vertical().show(ui, |ui| {
            let ranges = self.loaded.ranges(&self.view);
            view_controls::controls_ui(ui, &mut self.view, &ranges);
            if depth_section::depth_tools_ui(ui, &mut self.settings.depth).auto_range {
                actions.push(Action::AutoRange);
            }
            ui.separator();
            view_controls::quality_ui(ui, &mut self.settings.quality);
            ui.separator();
            let export = &mut self.settings.export;
            let file = file_sections::file_ui(ui, &mut self.path_text, &mut export.scene_path);
            if let Some(path) = file.open_path {
                actions.push(Action::Open(PathBuf::from(path.trim())));
            }
            if file.save_view {
                actions.push(Action::SaveViewTo(PathBuf::from(export.scene_path.trim())));
            }
            ui.separator();
            if file_sections::export_ui(ui, export, self.dialog_note).export_to_path {
                actions.push(Action::ExportTo(PathBuf::from(export.path.trim())));
            }
        });
        actions
    }

    /// What the status bar shows now.
    fn status_line(&self) -> StatusLine<'_> {
        let shown = self.shown.as_ref();
        StatusLine {
            render_ms: shown.map(|s| s.render_ms),
            size_px: shown.map(|s| [s.frame.width_px, s.frame.height_px]),
            precision: shown.map(|s| s.frame.precision),
            stage: shown.map(|s| match s.quality.sampling {
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
            scene_name: self.loaded.name(),
            busy: self.busy(),
            loading: self
                .loading
                .as_ref()
                .filter(|pending| pending.shows_progress())
                .map(|pending| (pending.path.display().to_string(), pending.fraction())),
            message: self.status.as_ref(),
        }
    }

    /// A render or a write is under way.
    fn busy(&self) -> bool {
        self.worker.as_ref().is_some_and(|w| !w.is_idle()) || self.writing.is_some()
    }

    /// The two images with the probe and the histogram; applies the gestures made on them.
    fn images_ui(&mut self, ui: &mut egui::Ui) {
        let probe_lines = probe_text::probe_lines(self.pinned_probe(), self.hover_probe());
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
            pinned: self.probe.pinned_px,
            depth_range: &mut self.view.depth_range,
            colour_map: style.colour_map,
            no_hit_rgb: style.no_hit_rgb,
        };
        let gestures = images_ui(ui, shown.as_ref(), footer);
        self.apply_gestures(&gestures);
        let (width_px, height_px) = gestures.wanted_px;
        if (width_px, height_px) != (self.view.width_px, self.view.height_px) {
            // The same world point stays under the pinned probe only in pixels of this size.
            self.probe.pinned_px = None;
        }
        self.view.width_px = width_px;
        self.view.height_px = height_px;
    }
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if crate::cli::process::stop_requested().is_some() {
            // A termination signal: close (eframe saves the settings on the way out).
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        self.receive_frame();
        self.poll_load();
        self.poll_background();
        self.handle_input(&ctx);

        let mut actions = Vec::new();
        egui::Panel::top("toolbar").show(ui, |ui| {
            actions.extend(toolbar::toolbar_ui(ui, &mut self.settings.show_controls));
        });
        if let Some(error) = self.scene_error.clone() {
            egui::Panel::top("scene_error").show(ui, |ui| {
                if error_banner_ui(ui, &error) {
                    self.scene_error = None;
                }
            });
        }
        egui::Panel::bottom("status").show(ui, |ui| status_bar_ui(ui, &self.status_line()));
        if self.settings.show_controls {
            // The images keep at least half of the window.
            let max_width = (0.5 * ui.available_width()).max(160.0);
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(330.0_f32.min(max_width))
                .max_size(max_width)
                .show(ui, |ui| actions.extend(self.side_panel_ui(ui)));
        }
        egui::CentralPanel::default().show(ui, |ui| self.images_ui(ui));
        self.confirm_ui(&ctx);
        for action in actions {
            self.apply(action);
        }
        self.submit_if_changed();
        if self.busy() {
            ctx.request_repaint_after(Duration::from_millis(100));
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }
}
