//! The `diagnosis` test suite: the comparison's diagnosis: every known mistake named on the course
//! scenes and on generated ones, and every sentence it prints drawn and measured.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../compare.rs"]
mod compare;
#[path = "../course_mistakes.rs"]
mod course_mistakes;
#[path = "../generated.rs"]
mod generated;
#[path = "../statements.rs"]
mod statements;
