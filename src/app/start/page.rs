//! The page's script's way in (`wasm32`): [`WebHandle`] starts the viewer on a canvas with the
//! page's seam ([`Page`]), and reads what is on screen for tests and tools (the viewer's canvas
//! has no DOM to query).

use std::sync::Arc;

use wasm_bindgen::prelude::*;

use crate::app::viewer::ViewerApp;
use crate::app::web::Page;
use crate::app::{layout, render_job};
use crate::platform::browser::scene_parameter;

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
                    page.attach(&cc.egui_ctx);
                    let request = crate::cli::ViewerRequest::default();
                    Ok(Box::new(ViewerApp::with_seam(cc, request, page)))
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
            !layout::busy(&app.frames, &app.writes, &app.compare)
                && app.scene.loading.is_none()
                && app.seam.inbox_empty()
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
            render_job::ViewerJob {
                scene,
                view,
                scene_epoch: 0,
                quality: crate::render::Quality::default(),
                depth_style: render_job::DepthStyle::default(),
            }
        })?;
        let mut times: Vec<f64> = (0..runs.max(1))
            .map(|_| {
                let started = web_time::Instant::now();
                let _ = std::hint::black_box(render_job::prepare_frame(&job));
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
