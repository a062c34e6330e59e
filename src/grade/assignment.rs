//! The assignment: a text file of the course's command lines, one a line
//! (`raytracer -input scene1_01.txt -size 200 200 -output output1_01.tga -depth 9 10
//! depth1_01.tga`), parsed by the command line's own parser. Scene paths are relative to the
//! file; the output names are the files each submission holds. Blank lines and `#` comments are
//! skipped; a first word that is not a flag (the program's name) is left out.

use std::path::{Component, Path, PathBuf};

use crate::cli::{Command, Flag, parse_command};
use crate::render::depth_map::DepthRange;

/// The course's assignment 1 as shipped, `scenes/assignment1.commands`: the one table of the
/// course's seven command lines that the tests, the examples, the grader and the release share.
pub const COURSE_ASSIGNMENT: &str = include_str!("../../scenes/assignment1.commands");

/// The course's seven tasks ([`COURSE_ASSIGNMENT`]), in order, their scenes joined to
/// `scenes_folder` (the repository's `scenes/`, or wherever the course scenes are).
pub fn course_tasks(scenes_folder: &Path) -> Vec<Task> {
    // The text is compiled in and parsed by this module's unit test: it cannot fail here.
    parse_assignment(COURSE_ASSIGNMENT, scenes_folder).unwrap_or_default()
}

/// The most bytes of an assignment file read (the course's is 7 lines).
const MAX_ASSIGNMENT_BYTES: u64 = 1 << 20;

/// Why an assignment file cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum AssignmentError {
    /// The file could not be read.
    #[error("{path}: {message}")]
    Read {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// A line is not a command line the grader can use.
    #[error("{path}:{line}: {message}")]
    Line {
        /// The file.
        path: String,
        /// The line's number, from 1.
        line: usize,
        /// What is wrong with it.
        message: String,
    },
    /// No line names an image.
    #[error("{path}: no command line in it (one a line: raytracer -input SCENE -output FILE …)")]
    Empty {
        /// The file.
        path: String,
    },
}

/// One command line of the assignment: the images a submission holds for it.
#[derive(Debug, Clone, PartialEq)]
pub struct Task {
    /// The line's number in the file, from 1.
    pub line_number: usize,
    /// The command line as written.
    pub line: String,
    /// The scene file, relative to the assignment file's folder resolved.
    pub scene: PathBuf,
    /// The image size, pixels.
    pub size_px: (u32, u32),
    /// The colour image's name (`-output`), relative to a submission's folder.
    pub colour: Option<PathBuf>,
    /// The depth image's range and name (`-depth`).
    pub depth: Option<(DepthRange, PathBuf)>,
}

impl Task {
    /// The line's arguments as written: its words after the program's name.
    pub fn arguments(&self) -> Vec<&str> {
        arguments_of(&self.line)
    }

    /// The depth range as the line writes it (`-depth 14.5 19.5 …`), for passing on unchanged.
    pub fn depth_words(&self) -> Option<[&str; 2]> {
        let words = self.arguments();
        let at = words.iter().position(|word| *word == "-depth")?;
        Some([*words.get(at + 1)?, *words.get(at + 2)?])
    }

    /// A short name for the line: its scene's file stem (`scene1_01`).
    pub fn name(&self) -> String {
        self.scene.file_stem().map_or_else(
            || format!("line {}", self.line_number),
            |s| s.to_string_lossy().into_owned(),
        )
    }
}

/// Reads the assignment file at `path`.
pub fn read_assignment(path: &Path) -> Result<Vec<Task>, AssignmentError> {
    let shown = path.display().to_string();
    let read_error = |message: String| AssignmentError::Read {
        path: shown.clone(),
        message,
    };
    let metadata = std::fs::metadata(path).map_err(|e| read_error(e.to_string()))?;
    if !metadata.is_file() {
        return Err(read_error("not a regular file".to_owned()));
    }
    if metadata.len() > MAX_ASSIGNMENT_BYTES {
        return Err(read_error(format!(
            "larger than {} KiB: not a list of command lines",
            MAX_ASSIGNMENT_BYTES >> 10
        )));
    }
    let text = std::fs::read_to_string(path).map_err(|e| read_error(e.to_string()))?;
    let folder = path.parent().unwrap_or(Path::new(""));
    let tasks =
        parse_assignment(&text, folder).map_err(|(line, message)| AssignmentError::Line {
            path: shown.clone(),
            line,
            message,
        })?;
    if tasks.is_empty() {
        return Err(AssignmentError::Empty { path: shown });
    }
    Ok(tasks)
}

/// Parses the assignment's text; scene paths are joined to `folder`. An error is the line's
/// number and what is wrong with it.
pub fn parse_assignment(text: &str, folder: &Path) -> Result<Vec<Task>, (usize, String)> {
    let mut tasks: Vec<Task> = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line_number = index + 1;
        let command = line.split('#').next().unwrap_or("").trim();
        if command.is_empty() {
            continue;
        }
        let words = arguments_of(command);
        let task = task_of(&words, folder, line_number, command).map_err(|m| (line_number, m))?;
        for earlier in &tasks {
            let named = |t: &Task| {
                t.colour
                    .iter()
                    .chain(t.depth.iter().map(|d| &d.1))
                    .map(|p| p.to_string_lossy().to_lowercase())
                    .collect::<Vec<_>>()
            };
            if let Some(name) = named(&task).iter().find(|n| named(earlier).contains(n)) {
                return Err((
                    line_number,
                    format!("'{name}' is also named on line {}", earlier.line_number),
                ));
            }
        }
        tasks.push(task);
    }
    Ok(tasks)
}

/// A command line's words after the program's name (a first word that is not a flag), its
/// `#` comment left out.
fn arguments_of(line: &str) -> Vec<&str> {
    let command = line.split('#').next().unwrap_or("");
    let mut words: Vec<&str> = command.split_whitespace().collect();
    if words.first().is_some_and(|word| !word.starts_with('-')) {
        words.remove(0);
    }
    words
}

/// The task of one line's words (after the program's name).
fn task_of(words: &[&str], folder: &Path, line_number: usize, line: &str) -> Result<Task, String> {
    let request = match parse_command(words.iter().copied()) {
        Ok(Command::Render(request)) => request,
        Ok(_) => {
            return Err(
                "not a command line that writes images (-input SCENE -output FILE …)".to_owned(),
            );
        }
        Err(error) => return Err(error.to_string()),
    };
    let outputs = request.outputs.each();
    let course_images = |flag: Flag| matches!(flag, Flag::Output | Flag::Depth);
    if request.compare.is_some()
        || request.trace.is_some()
        || outputs.iter().any(|output| !course_images(output.flag))
    {
        return Err(
            "grading reads the images of -output and -depth; leave out the other flags".to_owned(),
        );
    }
    if outputs.is_empty() {
        return Err("names no image (-output FILE, -depth DMIN DMAX FILE)".to_owned());
    }
    for name in outputs.iter().map(|output| output.path) {
        let inside = name
            .components()
            .all(|part| matches!(part, Component::Normal(_)));
        if !inside {
            return Err(format!(
                "'{}': an image's name must be a path inside a submission's folder",
                name.display()
            ));
        }
    }
    Ok(Task {
        line_number,
        line: line.to_owned(),
        scene: folder.join(&request.input),
        size_px: (request.width_px, request.height_px),
        colour: request.outputs.colour.clone(),
        depth: request
            .outputs
            .depth
            .as_ref()
            .map(|d| (d.range, d.path.clone())),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_course_assignment_is_the_handouts_seven_command_lines() {
        let tasks = course_tasks(Path::new("scenes"));
        let names: Vec<String> = tasks.iter().map(Task::name).collect();
        assert_eq!(
            names,
            (1..=7).map(|n| format!("scene1_0{n}")).collect::<Vec<_>>()
        );
        let depths: Vec<[&str; 2]> = tasks.iter().filter_map(Task::depth_words).collect();
        assert_eq!(
            depths,
            [
                ["9", "10"],
                ["8", "12"],
                ["8", "12"],
                ["12", "17"],
                ["14.5", "19.5"],
                ["3", "7"],
                ["-2", "2"]
            ]
        );
        let fifth = &tasks[4];
        assert_eq!(fifth.size_px, (200, 200));
        assert_eq!(fifth.scene, Path::new("scenes/scene1_05.txt"));
        assert_eq!(fifth.colour.as_deref(), Some(Path::new("output1_05.tga")));
        let (range, depth_file) = fifth.depth.as_ref().unwrap();
        assert_eq!((range.min_t, range.max_t), (14.5, 19.5));
        assert_eq!(depth_file, Path::new("depth1_05.tga"));
        assert_eq!(fifth.arguments()[..2], ["-input", "scene1_05.txt"]);
    }
}
