//! Typed scene-file errors. Every error carries the 1-based line and column of the token at fault
//! and says what was expected and what was found.

use std::fmt;

/// Where in the text something is: 1-based line and column (columns count characters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Location {
    /// 1-based line number.
    pub line: u32,
    /// 1-based column number, in characters.
    pub column: u32,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// What went wrong while reading a scene file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParseErrorKind {
    /// A different token was required here.
    #[error("expected {expected}, found '{found}'")]
    Expected {
        /// What the grammar allows here, e.g. `'radius'`.
        expected: String,
        /// The token in the file (shortened if long).
        found: String,
    },
    /// The file ended in the middle of something.
    #[error("expected {expected}, found end of file")]
    UnexpectedEnd {
        /// What the grammar allows here.
        expected: String,
    },
    /// A keyword of the course's later assignments.
    #[error(
        "'{keyword}' is not supported: this program reads the assignment-1 format \
         (OrthographicCamera, Background, Materials, Group, MaterialIndex, Sphere)"
    )]
    Unsupported {
        /// The keyword as written.
        keyword: String,
    },
    /// A token that should be a number is not one.
    #[error("expected a number ({what}), found '{found}'")]
    NotANumber {
        /// Which value, e.g. `sphere radius`.
        what: &'static str,
        /// The token in the file.
        found: String,
    },
    /// A number that is infinite, NaN, or too large for its type.
    #[error("{what} must be a finite number, found '{found}'")]
    NotFinite {
        /// Which value.
        what: &'static str,
        /// The token in the file.
        found: String,
    },
    /// A number beyond [`crate::scene::MAX_MAGNITUDE`].
    #[error("{what} must be at most 1e150 in magnitude, found '{found}'")]
    OutOfRange {
        /// Which value.
        what: &'static str,
        /// The token in the file.
        found: String,
    },
    /// A count (`numObjects`, `numMaterials`, `MaterialIndex`) that is not a non-negative integer.
    #[error("{what} must be a non-negative integer, found '{found}'")]
    NotACount {
        /// Which count.
        what: &'static str,
        /// The token in the file.
        found: String,
    },
    /// A sphere with a negative radius.
    #[error("sphere radius must be ≥ 0, found {radius}")]
    NegativeRadius {
        /// The radius as read.
        radius: f64,
    },
    /// A block that declares a count and holds a different number of items.
    #[error("{block} declares {declared} {items} but holds {found}")]
    CountMismatch {
        /// `Group` or `Materials`.
        block: &'static str,
        /// `objects` or `materials`.
        items: &'static str,
        /// The declared count.
        declared: u64,
        /// How many the block holds.
        found: u64,
    },
    /// `MaterialIndex` beyond the `Materials` list.
    #[error("MaterialIndex {index} is out of range: the scene has {count} materials")]
    MaterialIndexOutOfRange {
        /// The index as written.
        index: u64,
        /// Number of materials in the scene.
        count: usize,
    },
    /// A top-level block given twice.
    #[error("a second '{block}' block; a scene has at most one")]
    Duplicate {
        /// The block's keyword.
        block: &'static str,
    },
    /// The file holds nothing but whitespace.
    #[error("the file is empty: a scene needs at least an OrthographicCamera block")]
    Empty,
    /// The file has no camera.
    #[error("the scene has no OrthographicCamera block")]
    MissingCamera,
    /// The camera's direction has zero length.
    #[error("camera direction must not be zero")]
    ZeroDirection,
    /// The camera's up is zero or parallel to its direction.
    #[error("camera up must not be zero or parallel to the direction")]
    UpParallel,
    /// The camera's size is not positive.
    #[error("camera size must be > 0, found {size}")]
    NonPositiveSize {
        /// The size as read.
        size: f64,
    },
    /// The camera's size is too small for the arithmetic to resolve its pixels.
    #[error(
        "camera size must be at least 1e-150 (the squares of smaller pixels underflow), \
         found {size:e}"
    )]
    SizeTooSmall {
        /// The size as read.
        size: f64,
    },
    /// Something that looks like a comment.
    #[error("'{found}' looks like a comment, but the scene format has no comments: remove it")]
    Comment {
        /// The token as written.
        found: String,
    },
    /// Groups nested deeper than the parser allows.
    #[error("groups are nested deeper than {max} levels")]
    TooDeep {
        /// The limit.
        max: usize,
    },
    /// The file is not UTF-8 text.
    #[error("not a text file: invalid UTF-8")]
    NotText,
}

/// A scene-file error: where (file, line, column) and what.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct ParseError {
    /// Name of the file (as the user gave it), if the text came from a file.
    pub(crate) file: Option<String>,
    /// Position of the offending token.
    pub location: Location,
    /// What went wrong.
    pub kind: ParseErrorKind,
}

impl ParseError {
    /// An error at `location`, not yet attributed to a file.
    pub(crate) fn new(location: Location, kind: ParseErrorKind) -> Self {
        Self {
            file: None,
            location,
            kind,
        }
    }

    /// The same error, attributed to a named file.
    pub(crate) fn in_file(mut self, file: impl Into<String>) -> Self {
        self.file = Some(file.into());
        self
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(file) = &self.file {
            write!(f, "{file}:")?;
        }
        write!(f, "{}: {}", self.location, self.kind)
    }
}
