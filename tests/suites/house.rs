//! The `house` test suite: the repository as a whole: its chores, its docs, their figures and
//! pictures, the layout of its code, what it carries.
//!
//! One test binary for several test files (each a module, named as its file), so that the test
//! profile links a few binaries, not one per file, and their tests run side by side. Every
//! `tests/*.rs` is in exactly one suite (tests/layout.rs checks; Cargo.toml lists the suites).

// Each file keeps the helpers it declares (tests/common/), so that it reads and builds alone as
// before; two files of a suite may declare the same helper, each its own copy.
#![allow(clippy::duplicate_mod)]

#[path = "../chores.rs"]
mod chores;
#[path = "../docs.rs"]
mod docs;
#[path = "../docs_figures.rs"]
mod docs_figures;
#[path = "../layout.rs"]
mod layout;
#[path = "../notice.rs"]
mod notice;
#[path = "../pictures.rs"]
mod pictures;
#[path = "../repository.rs"]
mod repository;
