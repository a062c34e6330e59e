//! The `viewer` test suite: the viewer: the app through egui_kittest, and the real window under
//! Xvfb.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../viewer.rs"]
mod viewer;
#[path = "../viewer_compare.rs"]
mod viewer_compare;
#[path = "../viewer_explore.rs"]
mod viewer_explore;
#[path = "../viewer_files.rs"]
mod viewer_files;
#[path = "../viewer_layout.rs"]
mod viewer_layout;
#[path = "../viewer_reload.rs"]
mod viewer_reload;
#[path = "../viewer_robustness.rs"]
mod viewer_robustness;
#[path = "../viewer_settings.rs"]
mod viewer_settings;
#[path = "../viewer_use.rs"]
mod viewer_use;
#[path = "../window_screenshot.rs"]
mod window_screenshot;
#[path = "../window_signals.rs"]
mod window_signals;
#[path = "../window_text.rs"]
mod window_text;
