//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`], hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! [`ViewerApp`] coordinates; each concern lives in a module of its own:
//! * [`state`]: the loaded scene, the persisted settings
//! * [`job`]: the render worker's job (render + texture pixels off the UI thread)
//! * [`frame_log`]: per-frame figures for scripts that measure the real window
//! * [`frames`]: asking the worker for frames (progressive refinement) and taking them in
//! * [`scene_loading`]: opening and reloading scene files in the background
//! * [`actions`]: what the user can ask for ([`actions::Action`]), exports, dialogs
//! * [`compare`]: their image (or the chosen quality) against the exact render, the diagnosis
//! * [`confirm`]: asking before a write replaces files
//! * [`views`]: undo and redo, named views, the view each scene was last seen in
//! * [`view_actions`]: auto range and follow, frame all, resets, undo and redo, named views
//! * [`input`]: shortcuts, dropped files, keyboard and pointer navigation
//! * [`layout`]: composing the panels, the drawer and the central area
//! * [`tasks`]: the one background-task type (loads, writes, dialogs)
//! * [`status`]: the typed status-bar message
//! * [`dialogs`]: native file dialogs; [`reload`]: watching the open file
//! * [`inspect`]: read access for tests and tools
//! * [`window`]: opening the window (or saying why none can be opened)
//! * [`web`]: in a browser page, files in as bytes and out as downloads
//! * [`ui`]: the drawing, one `*_ui` function per part

pub(crate) mod actions;
pub mod compare;
pub(crate) mod confirm;
pub(crate) mod dialogs;
pub mod frame_log;
pub(crate) mod frames;
pub(crate) mod input;
pub(crate) mod inspect;
pub mod job;
pub(crate) mod layout;
pub(crate) mod reload;
pub(crate) mod scene_loading;
pub mod state;
pub(crate) mod status;
pub(crate) mod tasks;
pub mod ui;
pub(crate) mod view_actions;
pub mod views;
#[cfg(target_arch = "wasm32")]
pub mod web;
#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod window;

use std::path::PathBuf;

use glam::{DVec2, DVec3};

use self::dialogs::{PendingDialog, dialog_unavailable_reason};
use self::frames::{Requests, Shown};
use self::job::{ViewerWorker, start_worker};
use self::scene_loading::PendingLoad;
use self::state::{LoadedScene, Settings};
use self::status::Status;
use self::tasks::Task;
use self::ui::magnifier::Magnifier;
use self::views::{History, SavedView, SceneViews};
use crate::cli::ViewerRequest;
use crate::render::View;

pub use self::input::{KEY_ORBIT_RAD, KEY_PAN_FRACTION, KEY_ZOOM_FACTOR};
#[cfg(not(target_arch = "wasm32"))]
pub use self::window::{environment_problem, no_display_reason, run};

/// Image size used until the first layout tells the real one.
const INITIAL_SIZE_PX: (u32, u32) = (512, 512);

/// The pointer's position (image pixels, y up) and the pinned point (world coordinates, so the
/// pin stays on what was pinned while the view moves).
#[derive(Debug, Clone, Copy, Default)]
struct ProbePoints {
    hover_px: Option<DVec2>,
    pinned_world: Option<DVec3>,
}

/// What the side panel's fields hold between frames.
#[derive(Debug, Clone, Default)]
struct Fields {
    /// The typed scene path of the file section.
    path_text: String,
    /// The name typed for a new named view.
    view_name: String,
    /// A view edit that was not applied, and why.
    invalid_edit: Option<String>,
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
    /// A file that failed to open: Reload and the watcher try it again.
    failed_open: Option<PathBuf>,
    status: Option<Status>,
    fields: Fields,
    dialog: Option<PendingDialog>,
    /// Why no file dialog can be shown here, if none can.
    dialog_note: Option<&'static str>,
    /// A background write (export or saved scene): its outcome message.
    writing: Option<Task<Result<String, String>>>,
    watcher: Option<reload::FileWatcher>,
    loading: Option<PendingLoad>,
    probe: ProbePoints,
    magnifier: Magnifier,
    history: History,
    /// The shortcuts and gestures overlay is open.
    help_open: bool,
    /// The controls drawer of narrow windows is open.
    drawer_open: bool,
    /// The camera the depth range was last fitted for in "follow" mode.
    followed: Option<SavedView>,
    /// The `raytracer` binary export scripts run.
    program: Option<PathBuf>,
    /// "Save view as scene" is writing over the open scene (its reload keeps the save's message).
    saving_open_scene: bool,
    /// A write that waits for the user to agree to replace files.
    pending_replace: Option<confirm::PendingReplace>,
    /// The Compare section: their image or the chosen quality against the exact render.
    compare: compare::CompareState,
    /// Per-frame figures, when the environment asks for them.
    frame_log: Option<frame_log::FrameLog>,
    /// In a browser page: files on their way in.
    #[cfg(target_arch = "wasm32")]
    page: web::Page,
    ctx: egui::Context,
}

impl ViewerApp {
    /// Creates the viewer: settings from eframe's storage, the scene from the request (or the last
    /// scene, or the embedded default), and the render worker.
    #[cfg_attr(target_arch = "wasm32", allow(clippy::needless_pass_by_value))]
    pub fn new(cc: &eframe::CreationContext<'_>, request: ViewerRequest) -> Self {
        let mut settings: Settings = cc
            .storage
            .and_then(|storage| eframe::get_value(storage, eframe::APP_KEY))
            .unwrap_or_default();
        if let Some((width, height)) = request.size_px {
            settings.export.displayed_size = false;
            settings.export.size_px = [width, height];
        }
        // Ctrl+plus and Ctrl+minus zoom the camera; the interface keeps its size.
        cc.egui_ctx
            .options_mut(|options| options.zoom_with_keyboard = false);
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
        let mut history = History::default();
        history.reset(&loaded.file_view);
        #[cfg_attr(target_arch = "wasm32", allow(unused_mut))]
        let mut app = Self {
            settings,
            view: loaded.file_view,
            loaded,
            scene_epoch: 0,
            worker,
            requests: Requests::default(),
            shown: None,
            scene_error: None,
            failed_open: None,
            status,
            fields: Fields::default(),
            dialog: None,
            dialog_note: dialog_unavailable_reason(),
            writing: None,
            watcher: None,
            loading: None,
            probe: ProbePoints::default(),
            magnifier: Magnifier::default(),
            history,
            help_open: false,
            drawer_open: false,
            followed: None,
            program: request.program.clone(),
            saving_open_scene: false,
            pending_replace: None,
            compare: compare::CompareState::default(),
            frame_log: frame_log::FrameLog::from_environment().map(|mut log| {
                log.renderer(if cc.gl.is_some() { "glow" } else { "wgpu" });
                log
            }),
            #[cfg(target_arch = "wasm32")]
            page: web::Page::default(),
            ctx: cc.egui_ctx.clone(),
        };
        let ctx = cc.egui_ctx.clone();
        crate::platform::process::set_wake(move || ctx.request_repaint());
        // A page opens the scene its address names (`?scene=`), not the last one: that was a
        // file the page has no access to any more.
        #[cfg(target_arch = "wasm32")]
        if let Some(address) = web::scene_parameter() {
            app.page.fetch_scene(&address, &cc.egui_ctx);
        }
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(path) = request.input.or_else(|| app.settings.last_scene.clone()) {
            app.open(&path);
        }
        app
    }

    /// Remembers the view the open scene is in, to restore when it is opened again.
    fn remember_view(&mut self) {
        if let Some(path) = &self.loaded.path {
            let key = SceneViews::key(path);
            self.settings
                .views
                .last
                .insert(key, SavedView::of(&self.view));
        }
    }
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if let Some(log) = &mut self.frame_log {
            log.ui(frame.info().cpu_usage);
        }
        if crate::platform::process::stop_requested().is_some() {
            // A termination signal: close (eframe saves the settings on the way out).
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        #[cfg(target_arch = "wasm32")]
        self.poll_page();
        self.receive_frame();
        self.poll_load();
        self.poll_background();
        self.poll_comparison();
        self.handle_input(&ctx);
        let actions = self.layout_ui(ui);
        for action in actions {
            self.apply(action);
        }
        self.history.observe(&self.view, web_time::Instant::now());
        self.submit_if_changed();
        if self.busy() {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    /// The page's handle reads the app through this (`app::web::WebHandle`).
    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(self)
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        self.remember_view();
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }
}
