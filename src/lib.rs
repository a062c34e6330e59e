//! # raytracer
//!
//! Ray casting of MIT 6.837 assignment-1 scenes: an orthographic camera and flat-coloured spheres
//! in groups. The library has no UI dependency; the `raytracer` binary adds the course-compatible
//! command line and (feature `gui`) the desktop viewer.
//!
//! The pipeline: scene text → [`scene::parse_scene`] → [`scene::Scene`] (plain, validated data) →
//! [`render::render`] with a [`render::View`] → [`render::Frame`] (colour, t and sphere per pixel)
//! → 8-bit images ([`render::Frame::colour_image`], [`render::Frame::depth_image`]) → files
//! ([`export`]).
//!
//! Conventions (SPEC.md): `horizontal = normalize(d × up)`, `screen_up = horizontal × d`; pixel
//! (x, y), y = 0 the bottom row, samples its centre; `size` spans the longer image side; rays
//! start at t = −∞ (a sphere behind the camera centre is seen); t is measured along the unit
//! direction from the screen plane; ties go to the sphere first in the file.
//!
//! Module map:
//! * [`scene`]: model, tokenizer, parser, typed errors with line and column
//! * [`camera`]: orthonormal basis, camera space, pixel grid
//! * [`intersect`]: the careful general ray–sphere routine (the tests' reference)
//! * [`render`]: [`render::View`], [`render::Frame`], the fast disc path and the oracle loop
//! * [`depth`]: the t → grey mapping, colour maps (turbo, viridis), 8- and 16-bit quantisation
//! * [`export`]: TGA/PNG writers, atomic writes
//! * [`depth_file`]: lossless depth (PFM, OpenEXR) and 16-bit depth PNGs
//! * [`reproduce`]: everything one export writes, the scene of the current view and the command
//!   that renders the same pictures again
//! * [`explore`]: slider ranges and depth ranges derived from a scene
//! * [`navigate`]: pan, zoom at a point, orbit and "frame all" as math on a view
//! * [`depth_tuning`]: histogram of visible t and auto depth range
//! * [`probe`]: what one pixel of a frame shows (position, t, sphere, material)
//! * [`cli`]: command-line flags → typed request; [`headless`]: running that request;
//!   [`terminal_progress`]: its progress bars on long loads and renders
//! * `app` (feature `gui`): the desktop viewer

#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

#[cfg(feature = "gui")]
pub mod app;
pub mod camera;
pub mod cli;
pub mod depth;
pub mod depth_file;
pub mod depth_tuning;
pub mod explore;
pub mod export;
pub mod generate;
pub mod headless;
pub mod intersect;
pub mod navigate;
pub mod probe;
pub mod render;
pub mod reproduce;
pub mod scene;
pub mod terminal_progress;

/// The scene the viewer shows when no file is given (also in `assets/default_scene.txt`).
pub const DEFAULT_SCENE_TEXT: &str = include_str!("../assets/default_scene.txt");

/// Name shown for the embedded default scene.
pub const DEFAULT_SCENE_NAME: &str = "default scene (embedded)";
