//! The class's report: what each submission's images came to and the totals of the class
//! (the `files` module writes it: `index.html`, a page per submission in `pages/`, the exact
//! images in `exact/`, the difference pictures in `pictures/`, `report.json` and `report.csv`).

use super::assignment::Task;
use super::mark::{ImageKind, Mark, Outcome};
use super::submission::Submission;
use crate::cli::GradeRequest;
use std::collections::BTreeMap;

/// The `format` field of `report.json`.
pub const REPORT_FORMAT: &str = "raytracer-grade";

/// One submission, marked.
#[derive(Debug, Clone)]
pub struct Graded {
    /// The submission.
    pub submission: Submission,
    /// Its page in the report (relative path).
    pub page: String,
    /// Each image: the index of its command line, and its mark.
    pub marks: Vec<(usize, Mark)>,
}

impl Graded {
    /// The marks of submission number `number` (from 0, in name order).
    pub fn new(number: usize, submission: Submission, marks: Vec<(usize, Mark)>) -> Self {
        Self {
            submission,
            page: format!("pages/{:04}.html", number + 1),
            marks,
        }
    }

    /// The deviations stated for any of its images, by word.
    pub fn words(&self) -> Vec<String> {
        let mut words: Vec<String> = self
            .marks
            .iter()
            .filter_map(|(_, mark)| mark.answer())
            .flat_map(|(answer, _)| answer.statements.iter().map(|s| s.word.clone()))
            .collect();
        words.sort();
        words.dedup();
        words
    }

    /// How many of its images match.
    pub fn matching(&self) -> usize {
        self.marks
            .iter()
            .filter(|(_, mark)| status(mark) == "match")
            .count()
    }
}

/// A cell's status: "match", "differs", "missing", "unreadable" or "wrong size".
pub fn status(mark: &Mark) -> &'static str {
    match (&mark.outcome, mark.answer()) {
        (Outcome::Missing, _) => "missing",
        (Outcome::Unreadable(_), _) => "unreadable",
        (Outcome::WrongSize { .. }, _) => "wrong size",
        (Outcome::Compared(_), Some((_, image))) if image.matches => "match",
        (Outcome::Compared(_), _) => "differs",
    }
}

/// A cell's text in a few words.
pub fn short(mark: &Mark) -> String {
    match &mark.outcome {
        Outcome::Missing => "missing".to_owned(),
        Outcome::Unreadable(why) => format!("unreadable: {why}"),
        Outcome::WrongSize { found, expected } => format!(
            "wrong size: {}×{}, not {}×{}",
            found.0, found.1, expected.0, expected.1
        ),
        Outcome::Compared(answer) => answer.short(mark.kind),
    }
}

/// The whole class, graded.
#[derive(Debug, Clone)]
pub struct ClassReport {
    /// The assignment file, as given.
    pub assignment: String,
    /// The submissions folder, as given.
    pub submissions_folder: String,
    /// The command lines.
    pub tasks: Vec<Task>,
    /// The submissions, in name order.
    pub graded: Vec<Graded>,
    /// How many distinct comparisons were made (the same images handed in twice are compared
    /// once).
    pub distinct_images: usize,
    /// How many submissions were marked at once.
    pub threads: usize,
    /// The memory budget they were marked within, where one is known.
    pub memory_budget_bytes: Option<u64>,
}

impl ClassReport {
    /// The class of `request`.
    pub fn new(
        request: &GradeRequest,
        tasks: Vec<Task>,
        graded: Vec<Graded>,
        distinct_images: usize,
    ) -> Self {
        Self {
            assignment: request.assignment.display().to_string(),
            submissions_folder: request.submissions.display().to_string(),
            tasks,
            graded,
            distinct_images,
            threads: 1,
            memory_budget_bytes: None,
        }
    }

    /// The images of a submission, in order: (command line, kind, name).
    pub fn columns(&self) -> Vec<(usize, ImageKind, String)> {
        let mut columns = Vec::new();
        for (index, task) in self.tasks.iter().enumerate() {
            if let Some(colour) = &task.colour {
                columns.push((index, ImageKind::Colour, colour.display().to_string()));
            }
            if let Some((_, depth)) = &task.depth {
                columns.push((index, ImageKind::Depth, depth.display().to_string()));
            }
        }
        columns
    }

    /// The submissions graded (not skipped).
    pub fn graded_count(&self) -> usize {
        self.graded
            .iter()
            .filter(|g| g.submission.skipped.is_none())
            .count()
    }

    /// For each deviation stated anywhere, how many submissions it is stated for.
    pub fn deviation_totals(&self) -> BTreeMap<String, usize> {
        let mut totals = BTreeMap::new();
        for graded in &self.graded {
            for word in graded.words() {
                *totals.entry(word).or_insert(0) += 1;
            }
        }
        totals
    }

    /// For each status, how many cells have it.
    pub fn status_totals(&self) -> BTreeMap<&'static str, usize> {
        let mut totals = BTreeMap::new();
        for graded in &self.graded {
            for (_, mark) in &graded.marks {
                *totals.entry(status(mark)).or_insert(0) += 1;
            }
        }
        totals
    }

    /// One line for the terminal.
    pub fn summary(&self) -> String {
        let totals = self.status_totals();
        let cells: Vec<String> = ["match", "differs", "missing", "unreadable", "wrong size"]
            .iter()
            .filter_map(|s| totals.get(s).map(|n| format!("{n} {s}")))
            .collect();
        format!(
            "graded {} submission{} × {} image{}: {}",
            self.graded_count(),
            if self.graded_count() == 1 { "" } else { "s" },
            self.columns().len(),
            if self.columns().len() == 1 { "" } else { "s" },
            if cells.is_empty() {
                "nothing to mark".to_owned()
            } else {
                cells.join(", ")
            }
        )
    }
}

/// The exact images' file (relative path) of command line `index`.
pub fn exact_image(index: usize, kind: ImageKind) -> String {
    format!("exact/{}-{}.png", index + 1, kind.word())
}
