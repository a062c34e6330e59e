//! The course's seven command lines as the tests and the examples take them, read from the one
//! table of them, `scenes/assignment1.commands` (through [`course_tasks`], as the grader reads an
//! assignment). Included by path.
#![allow(dead_code)] // each file that includes it uses its own share

use std::path::Path;
use std::sync::OnceLock;

use raytracer::grade::assignment::{Task, course_tasks};

/// The course's seven tasks, their scenes in the repository's `scenes/`.
pub(crate) fn tasks() -> Vec<Task> {
    let tasks = course_tasks(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes"));
    assert_eq!(tasks.len(), 7, "the course's seven command lines");
    tasks
}

/// (scene number 1–7, depth min, depth max), the range as the line writes it (`14.5`), to be
/// passed on to the program unchanged.
pub(crate) fn runs() -> Vec<(u32, String, String)> {
    tasks()
        .iter()
        .map(|task| {
            let number = task.name().trim_start_matches("scene1_0").parse().unwrap();
            let [min, max] = task.depth_words().unwrap();
            (number, min.to_owned(), max.to_owned())
        })
        .collect()
}

/// (scene name, depth min, depth max) of each line: `("scene1_05", 14.5, 19.5)`.
pub(crate) fn ranges() -> &'static [(&'static str, f64, f64)] {
    static RANGES: OnceLock<Vec<(&'static str, f64, f64)>> = OnceLock::new();
    RANGES.get_or_init(|| {
        tasks()
            .iter()
            .map(|task| {
                let (range, _) = task.depth.as_ref().unwrap();
                // Seven short names, made once and kept for the run.
                let name: &'static str = Box::leak(task.name().into_boxed_str());
                (name, range.min_t, range.max_t)
            })
            .collect()
    })
}
