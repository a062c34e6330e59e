//! The viewer in a browser page (`wasm32`): what a page does where the desktop uses files.
//!
//! * Files come in as bytes: dropped on the page, chosen with the browser's file input, or
//!   fetched from the page's own site (`?scene=URL`, or a URL typed in the path field). They land
//!   in the [`Page`]'s inbox and the viewer takes them at its next frame.
//! * Exports and saved views leave as downloads.
//! * Settings and views are kept in the browser's storage by eframe.
//!
//! A page has no threads here: loads, comparisons and exports run on the page's thread, and the
//! render worker renders one frame per page frame (see `platform/worker.rs`).

use std::path::Path;
use std::sync::Arc;

use wasm_bindgen::prelude::*;

use crate::compare::their_image::decode_their_image;
use crate::platform::browser::{download, download_name, scene_parameter, set_title};

use super::actions::{Action, Write};
use super::compare::dropped_image_kind;
use super::dialogs::DialogKind;
mod page_files;

use super::status::Status;
use super::viewer::ViewerApp;
use super::writes::Stager;
use crate::output::atomic::FilesInMemory;
pub(crate) use page_files::Page;
use page_files::Purpose;

impl ViewerApp {
    /// A page opens the scene its address names (`?scene=`), not the last one (that was a file
    /// the page has no access to any more); it has no command line. That scene is asked for
    /// before the viewer starts (`WebHandle::start`), which gives the viewer the page it comes to.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(super) fn open_first(&mut self, _input: Option<std::path::PathBuf>) {}

    /// True while the scene the page's address names is on its way: until it comes (or fails),
    /// the page renders no frame of the embedded default scene, which would only pass by.
    pub(super) fn first_scene_on_its_way(&self) -> bool {
        self.frames.shown.is_none() && self.page.fetching_scene()
    }

    /// A page's files are downloads: there is no folder an export would have to create.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(super) fn missing_export_folder(&self, _write: &Write) -> Option<std::path::PathBuf> {
        None
    }

    /// A file dropped on the page: the page gives its name, and its bytes are read later.
    pub(super) fn open_dropped(&mut self, file: egui::DroppedFileHandle) {
        self.page.read_dropped(file);
    }

    /// Names the page (and eframe's viewport) `title`.
    pub(super) fn set_title(&self, title: &str) {
        self.ctx
            .send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
        set_title(title);
    }

    /// Takes in the files that came to the page since the last frame. The watches stop when the
    /// comparison is closed (by the user, or by another scene opened).
    pub(super) fn poll_platform(&mut self) {
        self.page.stop_watching_at(self.compare.closes);
        for incoming in self.page.take() {
            let bytes: Arc<[u8]> = match incoming.bytes {
                Ok(bytes) => bytes.into(),
                Err(error) => {
                    let message = if error.starts_with(&incoming.name) {
                        error
                    } else {
                        format!("{}: {error}", incoming.name)
                    };
                    match incoming.purpose {
                        Purpose::Open => self.scene.error = Some(message),
                        _ => self.status = Some(Status::error(message)),
                    }
                    continue;
                }
            };
            let name = incoming.name;
            let compared_as = match incoming.purpose {
                Purpose::Open => None,
                Purpose::Compare(kind) => Some(kind),
                Purpose::ByName => dropped_image_kind(&name),
                // A watched image written again is compared again (its watch stops when the
                // comparison is closed or another scene opened: below).
                Purpose::Rewritten(kind) => Some(kind),
            };
            let Some(kind) = compared_as else {
                self.open_bytes(&name, bytes);
                continue;
            };
            let read = move |path: &Path| decode_their_image(path, &bytes);
            let against = self.against();
            let status = self.compare.with_image(&against, name.into(), kind, read);
            self.say(status);
        }
    }

    /// Opens the scene at `path`: in a page, the path field holds an address on the page's
    /// site, fetched.
    pub(super) fn open_path(&mut self, path: &std::path::Path) {
        self.page.fetch_scene(&path.to_string_lossy(), None);
    }

    /// In a browser page: the browser's file chooser to open a scene or an image; export and save
    /// download at once (the browser asks where, or saves to its downloads folder).
    pub(super) fn open_dialog(&mut self, kind: DialogKind) {
        let chosen = match kind {
            DialogKind::Open => self.page.pick(Purpose::Open, ".txt,text/plain"),
            // Where the browser can, the image picked is watched, as the desktop watches it.
            DialogKind::CompareImage(kind) if self.page.pick_watched(kind) => Ok(()),
            DialogKind::CompareImage(kind) => self
                .page
                .pick(Purpose::Compare(kind), ".png,.tga,image/png"),
            DialogKind::Export => {
                let base = std::path::PathBuf::from(self.settings.export.path.trim());
                self.apply(Action::Write(Write::ExportTo(base)));
                Ok(())
            }
            DialogKind::SaveScene => {
                let path = std::path::PathBuf::from(self.settings.export.scene_path.trim());
                self.apply(Action::Write(Write::SaveViewTo(path)));
                Ok(())
            }
        };
        if let Err(error) = chosen {
            self.status = Some(Status::error(format!("cannot choose a file: {error}")));
        }
    }

    /// The page's way to write the files `stage` stages: each downloaded now, named by its last
    /// part (the desktop writes them: `app::desktop`); the status bar says `done` (what was
    /// written: "exported", or the course files' range and size) and names them.
    #[expect(
        clippy::needless_pass_by_value,
        reason = "the desktop's side moves the message into the thread that writes"
    )]
    pub(super) fn write_files(&mut self, _running: &str, done: String, stage: Stager) {
        let mut memory = FilesInMemory::default();
        let outcome = stage(&mut memory).and_then(|()| {
            let mut names = Vec::new();
            for (path, bytes) in &memory.files {
                let name = download_name(path);
                download(&name, bytes)?;
                names.push(name);
            }
            Ok(format!("{done} {} (downloaded)", names.join(", ")))
        });
        self.status = Some(match outcome {
            Ok(message) => Status::info(message),
            Err(error) => Status::error(format!("download failed: {error}")),
        });
    }
}

/// How long the viewer waits, at most, for the scene the page's address names before it starts,
/// milliseconds. A scene that comes later is drawn when it comes (the page meanwhile draws no
/// frame of the default scene).
const FIRST_SCENE_WAIT_MS: i32 = 200;

/// What the page's script holds: it starts the viewer on a canvas and, for tests and tools, reads
/// what is on screen (the viewer's canvas has no DOM to query).
#[wasm_bindgen]
pub struct WebHandle {
    runner: eframe::WebRunner,
}

#[wasm_bindgen]
impl WebHandle {
    /// A handle whose viewer is not started yet. Rust panics are reported to the console.
    #[wasm_bindgen(constructor)]
    #[expect(clippy::new_without_default, reason = "a JavaScript constructor")]
    pub fn new() -> Self {
        eframe::WebLogger::init(log::LevelFilter::Warn).ok();
        Self {
            runner: eframe::WebRunner::new(),
        }
    }

    /// Starts the viewer on `canvas`: the embedded default scene, or the scene the page's
    /// address names (`?scene=`), whose fetch the page's script may have made already (`asked`,
    /// made beside the .wasm's). That scene is given up to [`FIRST_SCENE_WAIT_MS`] to come
    /// before eframe starts, so that it is the first frame drawn (tests/web/first_frame.mjs).
    pub async fn start(
        &self,
        canvas: web_sys::HtmlCanvasElement,
        asked: Option<js_sys::Promise>,
    ) -> Result<(), JsValue> {
        let page = Page::default();
        if let Some(address) = scene_parameter() {
            page.fetch_scene(&address, asked);
            page.scenes_in(FIRST_SCENE_WAIT_MS).await;
        }
        self.runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(move |cc| {
                    let mut app = ViewerApp::new(cc, crate::cli::ViewerRequest::default());
                    page.attach(&cc.egui_ctx);
                    app.page = page;
                    Ok(Box::new(app))
                }),
            )
            .await
    }

    /// Stops the viewer.
    pub fn destroy(&self) {
        self.runner.destroy();
    }

    /// Whether the viewer has panicked (the page then says so).
    pub fn has_panicked(&self) -> bool {
        self.runner.has_panicked()
    }

    /// The panic's message, if the viewer has panicked.
    pub fn panic_message(&self) -> Option<String> {
        self.runner.panic_summary().map(|summary| summary.message())
    }

    /// The open scene's name ("default scene" for the embedded one).
    pub fn scene_name(&self) -> Option<String> {
        self.with_app(|app| app.scene.loaded.name())
    }

    /// Why the last scene could not be opened, if it could not.
    pub fn scene_error(&self) -> Option<String> {
        self.with_app(|app| app.scene.error.clone()).flatten()
    }

    /// The status bar's message.
    pub fn message(&self) -> Option<String> {
        self.with_app(|app| app.status.as_ref().map(|s| s.text.clone()))
            .flatten()
    }

    /// True while nothing is loading, rendering or being compared, and the frame on screen is
    /// of the current view at the full quality.
    pub fn settled(&self) -> bool {
        self.with_app(|app| {
            !super::layout::busy(&app.frames, &app.writes, &app.compare)
                && app.scene.loading.is_none()
                && app.page.inbox_empty()
                && app.frame_is_current()
        })
        .unwrap_or(false)
    }

    /// The view: `[centre x, y, z, size, depth min, depth max, width, height]` (world units,
    /// then pixels).
    pub fn view(&self) -> Option<Vec<f64>> {
        self.with_app(|app| {
            let v = &app.viewing.view;
            vec![
                v.center_world.x,
                v.center_world.y,
                v.center_world.z,
                v.size_world,
                v.depth_range.min_t,
                v.depth_range.max_t,
                f64::from(v.width_px),
                f64::from(v.height_px),
            ]
        })
    }

    /// The depth image's colour map: "Grey", "Turbo" or "Viridis" (a setting the browser's
    /// storage keeps).
    pub fn colour_map(&self) -> Option<String> {
        self.with_app(|app| format!("{:?}", app.settings.depth.colour_map))
    }

    /// The frame on screen: `[width, height]`.
    pub fn frame_size(&self) -> Option<Vec<u32>> {
        self.with_app(|app| {
            app.frames
                .shown
                .as_ref()
                .map(|shown| vec![shown.frame.width_px, shown.frame.height_px])
        })
        .flatten()
    }

    /// Which scene the frame on screen is of: 0 for the embedded default scene the page starts
    /// with, one more for each scene opened since.
    pub fn frame_scene_epoch(&self) -> Option<u64> {
        self.with_app(|app| app.frames.shown.as_ref().map(|shown| shown.scene_epoch))
            .flatten()
    }

    /// The colour image on screen, 3 bytes a pixel, top row first.
    pub fn colour_rgb(&self) -> Option<Vec<u8>> {
        self.with_app(|app| {
            app.frames
                .shown
                .as_ref()
                .map(|shown| shown.frame.colour_image().into_raw())
        })
        .flatten()
    }

    /// The statements the comparison on screen makes, each as the command line prints it after
    /// `diagnosis: ` (empty when none is open or none is made).
    pub fn diagnosis(&self) -> Vec<String> {
        self.with_app(|app| {
            app.compare.current.as_ref().map_or_else(Vec::new, |c| {
                c.pixels
                    .statements
                    .iter()
                    .map(crate::compare::Deviation::said)
                    .collect()
            })
        })
        .unwrap_or_default()
    }

    /// The names of the images the comparison on screen judged, each as `kind name` (two when a
    /// colour and a depth image were judged together).
    pub fn compared(&self) -> Vec<String> {
        self.with_app(|app| {
            let current = app.compare.current.as_ref();
            current.map_or_else(Vec::new, |c| {
                let images = c.pixels.images();
                images
                    .map(|i| format!("{} {}", i.kind.word(), i.name()))
                    .collect()
            })
        })
        .unwrap_or_default()
    }

    /// How long the last frame took to render, in milliseconds (0 before the first).
    pub fn render_ms(&self) -> f64 {
        self.with_app(|app| {
            app.frames
                .shown
                .as_ref()
                .map_or(0.0, |shown| shown.render_ms)
        })
        .unwrap_or(0.0)
    }

    /// The viewer's work for one frame (render, both textures, histogram: what the render worker
    /// does) of the open scene's own camera at `width`×`height`, median of `runs`, in
    /// milliseconds: the page's figure beside `examples/viewer_frame` on the desktop.
    pub fn frame_ms(&self, width: u32, height: u32, runs: u32) -> Option<f64> {
        let job = self.with_app(|app| {
            let scene = Arc::clone(&app.scene.loaded.scene);
            let mut view = crate::render::View::of_camera(
                &scene.camera,
                width,
                height,
                crate::render::depth_map::DepthRange::new(0.0, 1.0),
            );
            view.depth_range = crate::explore::initial_depth_range(&scene, &view);
            super::render_job::ViewerJob {
                scene,
                view,
                scene_epoch: 0,
                quality: crate::render::Quality::default(),
                depth_style: super::render_job::DepthStyle::default(),
            }
        })?;
        let mut times: Vec<f64> = (0..runs.max(1))
            .map(|_| {
                let started = web_time::Instant::now();
                let _ = std::hint::black_box(super::render_job::prepare_frame(&job));
                started.elapsed().as_secs_f64() * 1e3
            })
            .collect();
        times.sort_by(f64::total_cmp);
        Some(times[times.len() / 2])
    }

    fn with_app<T>(&self, read: impl FnOnce(&ViewerApp) -> T) -> Option<T> {
        self.runner.app_mut::<ViewerApp>().map(|app| read(&app))
    }
}
