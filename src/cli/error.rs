//! [`UsageError`]: a command-line mistake; the program prints it and exits with status 2. Flags
//! are named through [`Flag`], so the messages follow the flag table.

use super::flags::{Flag, GRADE_SYNOPSIS, GRADE_WORD, OUTPUT_FLAGS, extensions_of};
use crate::render::sampling::SamplingError;
use crate::render::{MAX_PIXELS, MAX_SIDE_PX};

/// A command-line mistake.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UsageError {
    /// A flag the program does not know.
    #[error("unknown flag '{0}' (raytracer {help} lists the flags)", help = Flag::Help)]
    UnknownFlag(String),
    /// A word that is not a flag where a flag was expected.
    #[error(
        "unexpected argument '{0}': expected a flag such as {input} (raytracer {help} lists them)",
        input = Flag::Input,
        help = Flag::Help
    )]
    StrayArgument(String),
    /// A flag given twice.
    #[error("flag {0} is given twice")]
    Repeated(Flag),
    /// Too few values after a flag.
    #[error(
        "flag {flag} needs {} ({}); found {}",
        values(*needed),
        flag.synopsis(),
        found(*given, next.as_deref())
    )]
    MissingValue {
        /// The flag.
        flag: Flag,
        /// How many values it needs here.
        needed: usize,
        /// How many it was given before the next flag or the end.
        given: usize,
        /// The flag that came where a value belongs (`None`: the command ended).
        next: Option<String>,
    },
    /// A value that should be a number is not one.
    #[error("{flag}: expected {what}, found '{found}'")]
    BadNumber {
        /// The flag.
        flag: Flag,
        /// What kind of number.
        what: &'static str,
        /// The value as given.
        found: String,
    },
    /// A depth range whose width is beyond the largest number (`-depth -1e308 1e308`).
    #[error("{0}: DMAX − DMIN is beyond the largest number (1.8e308): give a narrower range")]
    DepthRangeTooWide(Flag),
    /// An image size outside the supported range.
    #[error(
        "{flag}: {width_px}×{height_px} is out of range: each side from 1 to {MAX_SIDE_PX} \
         pixels, at most {MAX_PIXELS} pixels in all",
        flag = Flag::Size
    )]
    BadSize {
        /// Requested width.
        width_px: u64,
        /// Requested height.
        height_px: u64,
    },
    /// An output whose extension names no format the flag writes.
    #[error("{flag}: {}", unknown_format(*flag, path))]
    UnknownFormat {
        /// The flag.
        flag: Flag,
        /// The path as given.
        path: String,
    },
    /// Two outputs name the same file.
    #[error("two outputs name the same file '{0}'")]
    SameOutput(String),
    /// An output is the scene file or another output, by another spelling or a link.
    #[error(
        "{second} '{second_path}' is the same file as {first} '{first_path}': refusing to \
         write over it"
    )]
    SameFile {
        /// The flag seen first (`-input` for the scene file).
        first: Flag,
        /// Its path as given.
        first_path: String,
        /// The output that names the same file.
        second: Flag,
        /// Its path as given.
        second_path: String,
    },
    /// A path given as the empty string.
    #[error("{0}: the path is empty")]
    EmptyPath(Flag),
    /// A depth colour map that does not exist.
    #[error("{flag}: expected {maps}, found '{0}'", flag = Flag::DepthColourMap, maps = crate::render::depth_map::DepthColourMap::names_listed())]
    BadColourMap(String),
    /// An argument that is not valid Unicode where text is needed.
    #[error("{0}: value is not valid text")]
    NotText(Flag),
    /// Rendering needs a scene.
    #[error(
        "{} need {}",
        OUTPUT_FLAGS.iter().chain(&[Flag::CompareOutput, Flag::CompareDepth])
            .map(|flag| flag.name())
            .collect::<Vec<_>>()
            .join(", "),
        Flag::Input.synopsis()
    )]
    MissingInput,
    /// `-compare_format` with a format that does not exist.
    #[error("{flag}: expected lines or json, found '{0}'", flag = Flag::CompareFormat)]
    BadCompareFormat(String),
    /// `-compare_format` without an image to compare.
    #[error("{format} needs {output} or {depth}", format = Flag::CompareFormat, output = Flag::CompareOutput.synopsis(), depth = Flag::CompareDepth.synopsis())]
    FormatWithoutComparison,
    /// `-diff` without an image to compare.
    #[error("{diff} needs {output} or {depth}", diff = Flag::Diff, output = Flag::CompareOutput.synopsis(), depth = Flag::CompareDepth.synopsis())]
    DiffWithoutComparison,
    /// Two flags that exclude each other.
    #[error("{0} and {1} exclude each other: give one")]
    Conflicting(Flag, Flag),
    /// Unusable sampling settings.
    #[error("{0}")]
    BadSampling(#[from] SamplingError),
    /// The grading command's words are wrong.
    #[error("{GRADE_WORD}: {0} (usage: raytracer {GRADE_SYNOPSIS})")]
    Grade(String),
}

impl UsageError {
    /// Whether the usage text should follow the message (the user may not know the flags).
    pub fn wants_usage(&self) -> bool {
        matches!(self, Self::UnknownFlag(_) | Self::StrayArgument(_))
    }
}

/// "2 values", "a value".
fn values(count: usize) -> String {
    match count {
        1 => "a value".to_owned(),
        n => format!("{n} values"),
    }
}

/// What came of a flag's values: "1, then '-output'", "none, then the end of the command".
fn found(given: usize, next: Option<&str>) -> String {
    let given = match given {
        0 => "none".to_owned(),
        n => n.to_string(),
    };
    match next {
        Some(next) => format!("{given}, then '{next}'"),
        None => format!("{given}, then the end of the command"),
    }
}

/// Why `path` cannot be used by `flag`: its extension names no format (or it is `-`, which
/// elsewhere means standard input or output).
fn unknown_format(flag: Flag, path: &str) -> String {
    let extensions = extensions_of(flag);
    if path == "-" {
        let (what, stream) = match flag {
            Flag::CompareOutput | Flag::CompareDepth => {
                ("images to compare are read from", "standard input")
            }
            _ => ("outputs are written to", "standard output"),
        };
        format!("'-': {what} files, not {stream}; name a file ending in one of {extensions}")
    } else {
        format!("'{path}' has an unknown format; use one of {extensions}")
    }
}
