//! Grading a class: every submission's images against the exact ones, each difference
//! explained, in one report (`raytracer grade ASSIGNMENT SUBMISSIONS -o REPORT`).
//!
//! The assignment is the course's own command lines ([`assignment`]); each exact image is
//! rendered once. Each submission folder ([`submission`]) is read for the files those lines name,
//! each image marked as `-compare_output` / `-compare_depth` would ([`mark`]); a missing, empty,
//! unreadable or wrong-sized file is a cell of the report, never a stop. Submissions are marked
//! in parallel, and the report ([`report`], written by [`files`]: an HTML table and a page per
//! submission, with the same as JSON and CSV) is made in a folder beside the destination and
//! moved into place when whole ([`staging`]), so a failed run leaves a previous report as it was.

pub mod assignment;
mod files;
mod html;
mod manifest;
pub mod mark;
mod plan;
pub mod report;
mod staging;
pub mod submission;
mod tables;

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use self::assignment::{AssignmentError, read_assignment};
use self::mark::{Answers, Exact, Mark, mark_line};
use self::report::{ClassReport, Graded};
use self::staging::Staging;
use self::submission::list_submissions;
use crate::cli::GradeRequest;
use crate::cli::progress::StepProgress;
use crate::platform::memory::available_memory_bytes;
use crate::render::depth_map::DepthRange;
use crate::render::memory::{BASELINE_BYTES, render_bound_bytes};
use crate::render::{View, ViewError, render};
use crate::scene::{LoadError, load_scene};

pub use self::staging::remove_unfinished_report;

/// Why a class could not be graded (a submission's problem is a cell of the report, never this).
#[derive(Debug, thiserror::Error)]
pub enum GradeError {
    /// The assignment file cannot be used.
    #[error(transparent)]
    Assignment(#[from] AssignmentError),
    /// A scene the assignment names cannot be read.
    #[error("{assignment}:{line}: {source}")]
    Scene {
        /// The assignment file.
        assignment: String,
        /// The line naming the scene.
        line: usize,
        /// Why.
        source: LoadError,
    },
    /// A command line's view cannot be rendered.
    #[error("{assignment}:{line}: {source}")]
    View {
        /// The assignment file.
        assignment: String,
        /// The line.
        line: usize,
        /// Why.
        source: ViewError,
    },
    /// The submissions folder cannot be listed.
    #[error("{path}: cannot list the submissions: {source}")]
    Submissions {
        /// The folder.
        path: String,
        /// Why.
        source: std::io::Error,
    },
    /// A line's exact images would not fit in the memory the program may still use (the
    /// render command's check; the exact frames of the lines before it are held).
    #[error(
        "{assignment}:{line}: the exact {width_px}×{height_px} images need about {needed_mb:.0} MB \
         more memory, and {available_mb:.0} MB is available: grade at a smaller -size"
    )]
    Memory {
        /// The assignment file.
        assignment: String,
        /// The line.
        line: usize,
        /// Its image width.
        width_px: u32,
        /// Its image height.
        height_px: u32,
        /// What its render adds, MB.
        needed_mb: f64,
        /// What the program may still use, MB.
        available_mb: f64,
    },
    /// The report cannot be written where asked.
    #[error("{0}")]
    Report(String),
}

/// Grades the class of `request` and writes its report; returns what was found.
pub fn grade(request: &GradeRequest) -> Result<ClassReport, GradeError> {
    let tasks = read_assignment(&request.assignment)?;
    let listed = |source| GradeError::Submissions {
        path: request.submissions.display().to_string(),
        source,
    };
    if !std::fs::metadata(&request.submissions)
        .map_err(listed)?
        .is_dir()
    {
        return Err(listed(std::io::Error::other("not a folder")));
    }
    if let Some(why) = nested(&request.report, &request.submissions) {
        return Err(GradeError::Report(why));
    }
    let staging = Staging::begin(&request.report).map_err(GradeError::Report)?;
    let folder = staging.folder().to_path_buf();
    let assignment = request.assignment.display().to_string();
    let mut exacts = Vec::new();
    let threads = rayon::current_num_threads();
    for task in tasks {
        let line = task.line_number;
        let scene = load_scene(&task.scene).map_err(|source| GradeError::Scene {
            assignment: assignment.clone(),
            line,
            source,
        })?;
        let range = task.depth.as_ref().map_or(DepthRange::UNUSED, |d| d.0);
        let view = View::of_camera(&scene.camera, task.size_px.0, task.size_px.1, range);
        // The render command's check (what the frames made before it hold is used already).
        let (width_px, height_px) = task.size_px;
        let bound = render_bound_bytes(width_px, height_px, scene.spheres.len(), None, threads);
        let needed = bound.saturating_sub(BASELINE_BYTES);
        if let Some(available) = available_memory_bytes()
            && needed > available
        {
            return Err(GradeError::Memory {
                assignment: assignment.clone(),
                line,
                width_px,
                height_px,
                needed_mb: needed as f64 / 1e6,
                available_mb: available as f64 / 1e6,
            });
        }
        let frame = render(&scene, &view).map_err(|source| GradeError::View {
            assignment: assignment.clone(),
            line,
            source,
        })?;
        exacts.push(Exact { task, scene, frame });
    }
    files::write_exact_images(&folder, &exacts).map_err(GradeError::Report)?;
    let submissions = list_submissions(&request.submissions).map_err(listed)?;
    let answers = Answers::new(&folder).map_err(|e| GradeError::Report(e.to_string()))?;
    let images: usize = exacts
        .iter()
        .map(|e| usize::from(e.task.colour.is_some()) + usize::from(e.task.depth.is_some()))
        .sum();
    // Every file the lines name: one line's file is never graded as another's.
    let claimed: Vec<std::path::PathBuf> = exacts
        .iter()
        .flat_map(|e| {
            [
                e.task.colour.clone(),
                e.task.depth.as_ref().map(|d| d.1.clone()),
            ]
        })
        .flatten()
        .collect();
    let total = (submissions.len() * images).max(1);
    let done = AtomicUsize::new(0);
    // Within the memory budget: as many submissions at once as it holds.
    let (budget, threads) =
        plan::marking_threads(&exacts, request.memory_mb, rayon::current_num_threads());
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|index| format!("grade-{index}"))
        .build();
    let bar = StepProgress::start("grading");
    let mark_all = || -> Vec<Graded> {
        submissions
            .into_par_iter()
            .enumerate()
            .map(|(number, submission)| {
                let mut marks: Vec<(usize, Mark)> = Vec::new();
                if submission.skipped.is_none() {
                    for (index, exact) in exacts.iter().enumerate() {
                        let line = mark_line(&submission.folder, index, exact, &answers, &claimed);
                        let finished = done.fetch_add(line.len(), Ordering::Relaxed) + line.len();
                        bar.report(finished as f64 / total as f64);
                        marks.extend(line.into_iter().map(|mark| (index, mark)));
                    }
                }
                Graded::new(number, submission, marks)
            })
            .collect()
    };
    // Where no pool can be started (a process limit), the global one, which may be one thread.
    let graded = match &pool {
        Ok(pool) => pool.install(mark_all),
        Err(_) => mark_all(),
    };
    drop(bar);
    let mut class = ClassReport::new(
        request,
        exacts.into_iter().map(|e| e.task).collect(),
        graded,
        answers.distinct(),
    );
    class.threads = if pool.is_ok() {
        threads
    } else {
        rayon::current_num_threads()
    };
    class.memory_budget_bytes = budget;
    files::write_report(&folder, &class).map_err(GradeError::Report)?;
    staging.commit().map_err(GradeError::Report)?;
    Ok(class)
}

/// Why `report` may not be written where it is asked, when it lies inside `submissions` or holds
/// them: a report replaced would take the class with it, and a class would grade its own report.
fn nested(report: &std::path::Path, submissions: &std::path::Path) -> Option<String> {
    let submissions_real = submissions.canonicalize().ok()?;
    // The report's folder may not exist yet: where it would be.
    let report_real = report.canonicalize().ok().or_else(|| {
        let parent = match report.parent() {
            Some(parent) if !parent.as_os_str().is_empty() => parent,
            _ => std::path::Path::new("."),
        };
        Some(parent.canonicalize().ok()?.join(report.file_name()?))
    })?;
    let (shown, class) = (report.display(), submissions.display());
    if report_real.starts_with(&submissions_real) {
        Some(format!(
            "-o '{shown}' is inside the submissions folder '{class}': name a folder outside it \
             (nothing was written)"
        ))
    } else if submissions_real.starts_with(&report_real) {
        Some(format!(
            "-o '{shown}' holds the submissions folder '{class}': name another folder (nothing \
             was written)"
        ))
    } else {
        None
    }
}
