//! What a run of sphere statements parsed ahead on another thread hands the main parser
//! (the `split` module): its spheres, its material references, and where it stopped.

use std::sync::mpsc::Receiver;

use super::error::Location;
use super::lexer::Lexer;
use super::model::Sphere;

/// The run parsed ahead.
#[derive(Debug)]
pub(super) struct Run<'a> {
    /// The spheres in file order; the first `inheriting` take the material in effect before the
    /// run.
    pub(super) spheres: Vec<Sphere>,
    pub(super) inheriting: usize,
    /// The material in effect after the run, if the run set one.
    pub(super) material_after: Option<Option<u32>>,
    /// `MaterialIndex` references, lines counted from the run's first line (1).
    pub(super) material_references: Vec<(u64, Location)>,
    /// The lexer just after the run, in the run's text.
    pub(super) end: Lexer<'a>,
}

/// Where the run starts and how to get it.
pub(super) struct Ahead<'a> {
    /// Byte offset of the run's first token (`Sphere`) in the whole text.
    pub(super) token_offset: usize,
    /// Byte offset of the start of its line.
    pub(super) line_start: usize,
    /// The run, once parsed.
    pub(super) run: Receiver<Run<'a>>,
}
