//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`](crate::render::View), hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! [`ViewerApp`] coordinates; each concern lives in a module of its own:
//! * [`settings`]: the settings that survive a restart
//! * [`loaded_scene`]: the scene on screen and where it came from
//! * [`render_job`]: the render worker's job (render + texture pixels off the UI thread);
//!   (the worker that runs the newest job is `platform::worker`)
//! * [`frame_log`]: per-frame figures for scripts that measure the real window
//! * [`render_requests`]: asking the worker for frames (progressive refinement) and taking them in
//! * [`scene_loading`]: opening and reloading scene files in the background
//! * [`actions`]: what the user can ask for ([`actions::Action`]), exports, dialogs
//! * [`compare`]: their image (or the chosen quality) against the exact render, the diagnosis
//! * [`confirm`]: asking before a write replaces files; [`writes`]: the writes' state
//! * [`course_files`]: the course's 200×200 TGA pair and command line for the open scene
//! * [`pixel_trace`]: the course's computation behind the pinned pixel, in a window
//! * [`saved_views`]: undo and redo, named views, the view each scene was last seen in
//! * [`viewing`]: auto range and follow, frame all, resets, undo and redo, named views
//! * [`input`]: shortcuts, dropped files, keyboard and pointer navigation
//! * [`navigate`]: pan, zoom at a point, orbit and "frame all" as math on a view
//! * [`probe`]: what one pixel of a frame shows; [`depth_stats`]: the histogram of visible t and
//!   the auto depth range
//! * [`layout`]: composing the panels, the drawer and the central area
//! * [`background`]: the one background-task type (loads, writes, dialogs)
//! * [`status`]: the typed status-bar message
//! * [`dialogs`]: native file dialogs; [`reload`]: watching the open file
//! * [`inspect`]: read access for tests and tools
//! * [`window`]: opening the window (or saying why none can be opened)
//! * [`web`]: in a browser page, files in as bytes and out as downloads; [`desktop`]: on the
//!   desktop, files out into the file system
//! * [`ui`]: the drawing, one `*_ui` function per part

pub(crate) mod actions;
pub(crate) mod background;
pub mod compare;
pub(crate) mod confirm;
pub(crate) mod course_files;
pub mod depth_stats;
#[cfg(not(target_arch = "wasm32"))]
pub mod desktop;
pub(crate) mod dialogs;
pub mod frame_log;
pub(crate) mod input;
pub(crate) mod inspect;
pub(crate) mod layout;
pub mod loaded_scene;
pub mod navigate;
pub(crate) mod pixel_trace;
pub mod probe;
pub(crate) mod reload;
pub mod render_job;
pub(crate) mod render_requests;
pub mod saved_views;
pub(crate) mod scene_loading;
pub mod settings;
pub(crate) mod status;
pub mod ui;
pub(crate) mod viewing;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub(crate) mod writes;

use self::dialogs::dialog_unavailable_reason;
use self::loaded_scene::LoadedScene;
use self::render_job::start_worker;
use self::saved_views::{SavedView, SceneViews};
use self::scene_loading::OpenScene;
use self::settings::Settings;
use self::status::{Clears, Status};
use crate::cli::ViewerRequest;

pub use self::input::{KEY_ORBIT_RAD, KEY_PAN_FRACTION, KEY_ZOOM_FACTOR};

/// Image size used until the first layout tells the real one.
const INITIAL_SIZE_PX: (u32, u32) = (512, 512);

/// The viewer application: the coordinator. Each feature's state is a struct of its own (the
/// open scene, the view, the frames, the writes, the panels, the comparison); the coordinator
/// routes input and [`actions::Action`]s between them and draws the window.
pub struct ViewerApp {
    /// What survives a restart.
    settings: Settings,
    /// The scene on screen, its load, watcher and error.
    scene: OpenScene,
    /// The view, its history, the probe and the magnifier.
    viewing: viewing::Viewing,
    /// The frames asked of the render worker and the one on screen.
    frames: render_requests::Frames,
    /// Exports and saved scenes: the write in flight, the one waiting for a yes, file dialogs.
    writes: writes::Writes,
    /// The side panel's fields, the drawer and the shortcuts overlay.
    panels: layout::Panels,
    /// The Compare section: their image or the chosen quality against the exact render.
    compare: compare::CompareState,
    /// The status bar's message.
    status: Option<Status>,
    /// In a browser page: files on their way in.
    #[cfg(target_arch = "wasm32")]
    page: web::Page,
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
        let mut app = Self {
            settings,
            viewing: viewing::Viewing::new(loaded.file_view),
            scene: OpenScene::new(loaded),
            frames: render_requests::Frames {
                worker,
                requests: render_requests::Requests::default(),
                shown: None,
                log: frame_log::FrameLog::from_environment().map(|mut log| {
                    log.renderer(if cc.gl.is_some() { "glow" } else { "wgpu" });
                    log
                }),
            },
            writes: writes::Writes {
                task: None,
                pending_replace: None,
                dialog: None,
                dialog_note: dialog_unavailable_reason(),
                program: request.program.clone(),
            },
            panels: layout::Panels::default(),
            compare: compare::CompareState::default(),
            status,
            #[cfg(target_arch = "wasm32")]
            page: web::Page::default(),
            ctx: cc.egui_ctx.clone(),
        };
        let ctx = cc.egui_ctx.clone();
        crate::platform::process::set_wake(move || ctx.request_repaint());
        app.open_first(request.input);
        app
    }

    /// Shows what a feature had to say, if anything, in the status bar.
    fn say(&mut self, status: Option<Status>) {
        if let Some(status) = status {
            self.status = Some(status);
        }
    }

    /// Traces the pinned pixel of the frame on screen into the trace window.
    fn open_trace(&mut self) {
        let view = self.frames.shown.as_ref().map(|shown| &shown.view);
        match pixel_trace::trace_text(
            &self.scene.loaded.scene,
            view,
            self.pinned_px(),
            &self.compare,
        ) {
            Ok(text) => self.panels.trace = Some(text),
            Err(status) => self.status = Some(status),
        }
    }

    /// "Auto range" on the frame on screen (the settings' cut at each ends).
    pub fn auto_range(&mut self) {
        let shown = self.frames.shown.as_ref().map(|shown| &*shown.frame);
        let status = self
            .viewing
            .auto_range(shown, self.settings.depth.auto_cut_percent);
        self.say(status);
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

    /// Takes a finished frame in: a status waiting for one clears, and "follow" fits the depth
    /// range to it; a failed render says why.
    fn receive_frame(&mut self) {
        match self.frames.receive(&self.ctx) {
            None => {}
            Some(Err(error)) => self.status = Some(Status::view_error(error)),
            Some(Ok(())) => {
                if self
                    .status
                    .as_ref()
                    .is_some_and(|s| s.clears == Clears::WhenAFrameRenders)
                {
                    self.status = None;
                }
                let depth = &self.settings.depth;
                let shown = self.frames.shown.as_ref();
                let cut = depth.auto_cut_percent;
                self.viewing
                    .follow_depth(depth.follow, shown, self.scene.epoch, cut);
            }
        }
    }

    /// Remembers the view the open scene is in, to restore when it is opened again.
    fn remember_view(&mut self) {
        if let Some(path) = &self.scene.loaded.path {
            let key = SceneViews::key(path);
            self.settings
                .views
                .last
                .insert(key, SavedView::of(&self.viewing.view));
        }
    }
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if let Some(log) = &mut self.frames.log {
            log.ui(frame.info().cpu_usage);
        }
        if crate::platform::process::stop_requested().is_some() {
            // A termination signal: close (eframe saves the settings on the way out).
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        self.poll_platform();
        self.receive_frame();
        self.poll_load();
        self.poll_background();
        self.poll_comparison();
        self.handle_input(&ctx);
        let actions = self.layout_ui(ui);
        for action in actions {
            self.apply(action);
        }
        if self.frames.log.is_some() {
            let name = self.status_line().scene_name;
            if let Some(log) = &mut self.frames.log {
                log.missing_glyphs(&ctx, &name);
            }
        }
        self.viewing
            .history
            .observe(&self.viewing.view, web_time::Instant::now());
        let wanted = self.wanted();
        self.frames
            .submit_if_changed(&self.scene.loaded.scene, wanted, &self.ctx);
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
