//! The `command_line` test suite: the command line as every platform runs it (CI's Windows and
//! macOS jobs run this suite and the library's tests): flags and messages, the course's reference
//! images, the compare command and its JSON.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../cli.rs"]
mod cli;
#[path = "../compare_command.rs"]
mod compare_command;
#[path = "../compare_json.rs"]
mod compare_json;
#[path = "../reference_images.rs"]
mod reference_images;
