//! The `rendering` test suite: what the renderer draws: exactness against the high-precision
//! oracle, sampling, scenes, the streamed command (the render's phases are timed by a recorder the
//! whole process shares: tests/phases.rs is a binary of its own).
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../exactness.rs"]
mod exactness;
#[path = "../exactness_seeded.rs"]
mod exactness_seeded;
#[path = "../render.rs"]
mod render;
#[path = "../sampling.rs"]
mod sampling;
#[path = "../scenes.rs"]
mod scenes;
#[path = "../streamed_command.rs"]
mod streamed_command;
