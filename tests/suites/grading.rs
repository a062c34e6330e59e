//! The `grading` test suite: grading a class: the grader's answers, its memory, its names, its
//! races and its stops.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../grade.rs"]
mod grade;
#[path = "../grade_memory.rs"]
mod grade_memory;
#[path = "../grade_names.rs"]
mod grade_names;
#[path = "../grade_races.rs"]
mod grade_races;
#[path = "../grade_stops.rs"]
mod grade_stops;
