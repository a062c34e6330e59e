//! The `robustness` test suite: bad input, limits and hostile files: clear errors, never a panic,
//! nothing lost.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../hostile_images.rs"]
mod hostile_images;
#[path = "../hostile_input.rs"]
mod hostile_input;
#[path = "../robustness.rs"]
mod robustness;
#[path = "../robustness_destinations.rs"]
mod robustness_destinations;
#[path = "../robustness_limits.rs"]
mod robustness_limits;
#[path = "../robustness_set_limits.rs"]
mod robustness_set_limits;
