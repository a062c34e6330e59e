//! # raytracer
//!
//! Ray casting of MIT 6.837 assignment-1 scenes: an orthographic camera and flat-coloured spheres
//! in groups. The library is the product's core; the `raytracer` binary (`src/main.rs`) only
//! turns its arguments into a [`cli::Command`] and runs it, headless or in the viewer.
//!
//! The pipeline: scene text → [`scene::parse_scene`] → [`scene::Scene`] (plain, validated data) →
//! [`render::render`] with a [`render::View`] → [`render::Frame`] (colour, t and sphere per pixel)
//! → 8-bit images ([`render::Frame::colour_image`], [`render::Frame::depth_image`]) → files
//! ([`output`]).
//!
//! Conventions (docs/spec.md): `horizontal = normalize(d × up)`, `screen_up = horizontal × d`; pixel
//! (x, y), y = 0 the bottom row, samples its centre; `size` spans the longer image side; rays
//! start at t = −∞ (a sphere behind the camera centre is seen); t is measured along the unit
//! direction from the screen plane; ties go to the sphere first in the file.
//!
//! Layers, from the bottom; each imports only from the layers above it in this list:
//! * [`platform`]: everything that differs by operating system (files, signals, console,
//!   memory); no other module names `std::os::unix`, `std::os::windows` or a signal
//! * [`geometry`]: camera basis and pixel grid, the careful ray–sphere routine
//! * [`scene`]: model, lexer, parser (typed errors with line and column), writer
//! * [`render`]: view, frame, the disc rasteriser, sampling, depth mapping
//! * [`oracle`] (feature `oracle`): the straightforward loop and the double-double reference,
//!   for tests and studies only
//! * [`explore`]: slider and depth ranges, the pixel trace
//! * [`output`]: atomic writes, image encoders, lossless depth files, text in pictures, shell quoting
//! * [`compare`]: the known mistakes, the variant renderer that makes them, image differences,
//!   the diagnosis and the difference picture
//! * [`cli`]: the flag table (parsing, usage, writing a request back), running a request,
//!   progress bars
//! * `export` (feature `gui`): everything one export from the viewer writes, and the command that
//!   makes it again
//! * [`grade`]: grading a class — every submission's images against the exact ones, explained,
//!   in one report
//! * `app` (feature `gui`): the desktop viewer, with the math only its controls use (navigation,
//!   the probe, depth statistics) and its render worker
//!
//! Without default features the library and the binary have no UI dependency (no eframe, egui,
//! rfd or notify): a headless renderer for servers and CI.

#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
// Items are `pub(crate)` unless a caller outside the crate (the binary, tests, benchmarks,
// examples) needs them, so the dead-code lint finds what nothing calls, with the viewer and
// without it: what only the viewer uses (navigation, the probe, the depth histogram, the render
// worker, exports) is built only with it, in `app` and `export`.

#[cfg(feature = "gui")]
pub mod app;
pub mod cli;
pub mod compare;
pub mod explore;
#[cfg(feature = "gui")]
pub mod export;
pub mod geometry;
pub mod grade;
#[cfg(feature = "oracle")]
pub mod oracle;
pub mod output;
pub mod platform;
pub mod render;
pub mod scene;

/// The scene the viewer shows when no file is given (also in `assets/default_scene.txt`).
pub const DEFAULT_SCENE_TEXT: &str = include_str!("../assets/default_scene.txt");

/// Name shown for the embedded default scene.
pub const DEFAULT_SCENE_NAME: &str = "default scene (embedded)";
