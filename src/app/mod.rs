//! The desktop viewer (feature `gui`): the colour and depth images side by side, live sliders,
//! open and export. The viewer only edits a [`View`](crate::render::View), hands (scene, view) jobs to a background
//! worker and uploads the textures it gets back; all rendering math is in the library.
//!
//! [`ViewerApp`] ([`viewer`]) coordinates: it holds each feature's state, routes input and
//! actions between them, and is what tests and tools drive the viewer through. Each concern lives
//! in a module of its own, and owns its behaviour on its own state:
//! * [`settings`]: the settings that survive a restart
//! * [`loaded_scene`]: the scene on screen and where it came from
//! * [`render_job`]: the render worker's job (render + texture pixels off the UI thread);
//!   (the worker that runs the newest job is `platform::worker`)
//! * [`frame_log`]: per-frame figures for scripts that measure the real window
//! * [`render_requests`]: asking the worker for frames (progressive refinement) and taking them in
//! * [`scene_loading`]: opening and reloading scene files in the background, and taking them in
//! * [`actions`]: what the user can ask for ([`actions::Action`], [`actions::Write`])
//! * [`compare`]: their image (or the chosen quality) against the exact render, the diagnosis
//! * [`confirm`]: asking before a write replaces files; [`writes`]: exports, the course files and
//!   saved views staged, file dialogs' answers, the write in flight
//! * [`course_files`]: the course's 200×200 TGA pair and command line for the open scene
//! * [`pixel_trace`]: the course's computation behind the pinned pixel, in a window
//! * [`saved_views`]: undo and redo, named views, the view each scene was last seen in
//! * [`viewing`]: navigation, auto range and follow, frame all, resets, undo and redo, named views
//! * [`input`]: shortcuts, dropped files, keyboard and pointer navigation, read into actions
//! * [`navigate`]: pan, zoom at a point, orbit and "frame all" as math on a view
//! * [`probe`]: what one pixel of a frame shows; [`depth_stats`]: the histogram of visible t and
//!   the auto depth range
//! * [`layout`]: composing the panels, the drawer and the central area
//! * [`background`]: the one background-task type (loads, writes, dialogs)
//! * [`status`]: the typed status-bar message
//! * [`dialogs`]: native file dialogs; [`reload`]: watching the open file
//! * [`seam`]: what the coordinator holds of where it runs; [`asked`]: what a seam asks of it;
//!   [`desktop`]: on the desktop, files by path and out into the file system; [`web`]: in a
//!   browser page, files in as bytes and out as downloads
//! * [`start`]: opening the window (or saying why none can be opened), or starting in a page
//! * [`ui`]: the drawing, one `*_ui` function per part

pub(crate) mod actions;
pub(crate) mod asked;
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
pub(crate) mod seam;
pub mod settings;
pub mod start;
pub(crate) mod status;
pub mod ui;
pub(crate) mod viewer;
pub(crate) mod viewing;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub(crate) mod writes;

pub use self::input::{KEY_ORBIT_RAD, KEY_PAN_FRACTION, KEY_ZOOM_FACTOR};
pub use self::viewer::ViewerApp;
