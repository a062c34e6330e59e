//! The grading command's words: `raytracer grade ASSIGNMENT SUBMISSIONS -o REPORT [--memory MB]`
//! (the grading itself is the `grade` module). A subcommand, not a flag: it takes two folders and
//! a file where the course's flags take one scene, and none of the render flags apply to it.

use std::ffi::OsString;
use std::path::PathBuf;

use super::error::UsageError;

/// Grading a class: the course's command lines, a folder per student, where the report goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GradeRequest {
    /// A text file of the course's command lines, one a line.
    pub assignment: PathBuf,
    /// A folder holding one folder per submission.
    pub submissions: PathBuf,
    /// The folder the report is written to (made; a previous report there is replaced).
    pub report: PathBuf,
    /// The memory the grading may use, in MB (`--memory`); by default what the machine has
    /// free and the process's limits leave.
    pub memory_mb: Option<u64>,
}

/// Parses the words after `grade`.
pub(crate) fn parse_grade(words: &[OsString]) -> Result<GradeRequest, UsageError> {
    let mut positional = Vec::new();
    let mut report = None;
    let mut memory_mb = None;
    let mut words = words.iter();
    while let Some(word) = words.next() {
        match word.to_str() {
            Some("-o" | "-report" | "--report") => {
                let value = words.next().ok_or_else(|| {
                    UsageError::Grade("-o needs the folder to write the report to".to_owned())
                })?;
                if report.replace(PathBuf::from(value)).is_some() {
                    return Err(UsageError::Grade("-o is given twice".to_owned()));
                }
            }
            Some("-memory" | "--memory") => {
                let wrong = || {
                    UsageError::Grade(
                        "--memory needs the memory grading may use, in MB (a whole number, at \
                         least 1)"
                            .to_owned(),
                    )
                };
                let value = words.next().ok_or_else(wrong)?;
                let mb = value
                    .to_str()
                    .and_then(|text| text.parse::<u64>().ok())
                    .filter(|&mb| (1..=1 << 40).contains(&mb))
                    .ok_or_else(wrong)?;
                if memory_mb.replace(mb).is_some() {
                    return Err(UsageError::Grade("--memory is given twice".to_owned()));
                }
            }
            Some(flag) if flag.starts_with('-') && flag.len() > 1 => {
                return Err(UsageError::Grade(format!(
                    "unknown flag '{flag}' (grading takes -o REPORT and --memory MB)"
                )));
            }
            _ => positional.push(PathBuf::from(word)),
        }
    }
    let [assignment, submissions] = <[PathBuf; 2]>::try_from(positional).map_err(|found| {
        UsageError::Grade(format!(
            "expected ASSIGNMENT and SUBMISSIONS, found {} word{}",
            found.len(),
            if found.len() == 1 { "" } else { "s" }
        ))
    })?;
    let report = report.ok_or_else(|| {
        UsageError::Grade("-o REPORT is missing: name a folder for the report".to_owned())
    })?;
    if [&assignment, &submissions, &report]
        .iter()
        .any(|path| path.as_os_str().is_empty())
    {
        return Err(UsageError::Grade("a path is empty".to_owned()));
    }
    Ok(GradeRequest {
        assignment,
        submissions,
        report,
        memory_mb,
    })
}
