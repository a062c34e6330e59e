//! A command line's images of one submission marked: each found (letter case and `.tga`/`.png`
//! forgiven), opened once without following a link or blocking on a pipe, read within the
//! limits of [`crate::compare::their_image::read_their_image`] and checked for size; those that
//! can be are compared and explained together, as `-compare_output` with `-compare_depth` would
//! (one program drew both; the depth image under the line's range, the range it was drawn over
//! read from it where it differs). Students who make the same mistake hand in the same
//! pictures: an answer is computed once per distinct pair of images and shared.

use std::collections::HashMap;
use std::collections::hash_map::RandomState;
use std::fmt::Write as _;
use std::hash::{BuildHasher, Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use image::RgbImage;

use super::assignment::Task;
use super::submission::{Found, NotRead, find_image, read_found_image};
use crate::cli::compare::{TheirImages, compare};
use crate::cli::{CompareRequest, TheirDepth};
use crate::compare::Deviation;
use crate::render::Frame;
use crate::scene::Scene;

/// Which image of a command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ImageKind {
    /// The colour image (`-output`).
    Colour,
    /// The depth image (`-depth`).
    Depth,
}

impl ImageKind {
    /// "colour" or "depth".
    pub fn word(self) -> &'static str {
        match self {
            Self::Colour => "colour",
            Self::Depth => "depth",
        }
    }
}

/// A command line's exact render, shared by every submission.
pub struct Exact {
    /// The command line.
    pub task: Task,
    /// Its scene.
    pub scene: Scene,
    /// The exact, one-sample f64 render of it.
    pub frame: Frame,
}

/// What comparing found about one image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ImageAnswer {
    /// Whether it matches by the course's rule.
    pub matches: bool,
    /// Pixels that differ at all.
    pub pixels_differing: usize,
    /// The largest difference of a channel, levels.
    pub max_difference: u8,
    /// Differing pixels no statement explains.
    pub unexplained_pixels: usize,
}

/// One statement of an answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Statement {
    /// Its word (`pixel-corners`, `zoom`).
    pub word: String,
    /// The word with its values (`zoom 0.9945`).
    pub values: String,
    /// The sentence.
    pub said: String,
    /// Whether it is about how the depth image is drawn (not said in a colour image's cell).
    pub about_depth: bool,
}

/// What comparing a command line's images found: their colour and depth images together, as
/// `-compare_output` with `-compare_depth` would (one program drew both).
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The colour image, when compared.
    pub colour: Option<ImageAnswer>,
    /// The depth image, when compared.
    pub depth: Option<ImageAnswer>,
    /// The statements.
    pub statements: Vec<Statement>,
    /// A near tie: one of these sets of statements is what the program does.
    pub alternatives: Vec<Vec<Statement>>,
    /// Statements that explain only part of the difference.
    pub partial: Vec<Statement>,
    /// The whole answer as `name: value` lines.
    pub lines: String,
    /// The whole answer as JSON (docs/compare-json.md).
    pub json: serde_json::Value,
    /// The difference picture (theirs, exact, difference, unexplained; a row per image), a PNG
    /// file in the report's folder (relative path); when an image differs.
    pub picture: Option<String>,
}

impl Answer {
    /// What was found about the `kind` image.
    pub fn image(&self, kind: ImageKind) -> Option<&ImageAnswer> {
        match kind {
            ImageKind::Colour => self.colour.as_ref(),
            ImageKind::Depth => self.depth.as_ref(),
        }
    }

    /// The statements that bear on the `kind` image (all of them for depth; those not about how
    /// depth is drawn for colour).
    pub fn statements_on(&self, kind: ImageKind) -> impl Iterator<Item = &Statement> {
        self.statements
            .iter()
            .filter(move |s| kind == ImageKind::Depth || !s.about_depth)
    }

    /// The `kind` image's answer in a few words: "match", or the statements with their values.
    pub fn short(&self, kind: ImageKind) -> String {
        let Some(image) = self.image(kind) else {
            return String::new();
        };
        if image.matches {
            return "match".to_owned();
        }
        let joined = |list: &mut dyn Iterator<Item = &Statement>| {
            list.map(|s| s.values.as_str())
                .collect::<Vec<_>>()
                .join(" + ")
        };
        let mut parts = Vec::new();
        let stated = joined(&mut self.statements_on(kind));
        if !stated.is_empty() {
            parts.push(stated);
        }
        if !self.alternatives.is_empty() {
            let sets: Vec<String> = self
                .alternatives
                .iter()
                .map(|set| joined(&mut set.iter()))
                .collect();
            parts.push(format!("one of: {}", sets.join(" | ")));
        }
        if !self.partial.is_empty() {
            parts.push(format!("in part: {}", joined(&mut self.partial.iter())));
        }
        let mut text = parts.join("; ");
        if text.is_empty() {
            text = "not explained".to_owned();
        } else if image.unexplained_pixels > 0 {
            let _ = write!(text, " ({} px unexplained)", image.unexplained_pixels);
        }
        text
    }
}

/// What became of one image of one submission.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// No file by its name.
    Missing,
    /// A file that could not be read or compared, and why.
    Unreadable(String),
    /// An image of another size.
    WrongSize {
        /// Its size.
        found: (u32, u32),
        /// The command line's size.
        expected: (u32, u32),
    },
    /// Compared (with the line's other image, when that one could be read too).
    Compared(Arc<Answer>),
}

/// One image of one submission, marked.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// Which image.
    pub kind: ImageKind,
    /// Its name in the assignment.
    pub wanted: PathBuf,
    /// Its name in the submission, where it differs (letter case, `.tga`/`.png`).
    pub renamed: Option<String>,
    /// The file read, when one was.
    pub path: Option<PathBuf>,
    /// What became of it.
    pub outcome: Outcome,
}

impl Mark {
    /// What was found about this image, when it was compared.
    pub fn answer(&self) -> Option<(&Answer, &ImageAnswer)> {
        match &self.outcome {
            Outcome::Compared(answer) => answer.image(self.kind).map(|image| (&**answer, image)),
            _ => None,
        }
    }
}

/// The answers computed so far, by command line, image and picture; the difference pictures
/// are written to the report's folder as they are made, so no image is held after its
/// comparison.
pub struct Answers {
    known: Mutex<HashMap<AnswerKey, Arc<Answer>>>,
    hashers: (RandomState, RandomState),
    report: PathBuf,
}

/// Makes `folder`, a subfolder of the report being made; one there already is fine. Never
/// `create_dir_all`: a report folder removed by a stop must not be made again.
pub(super) fn make_subfolder(folder: &Path) -> std::io::Result<()> {
    match std::fs::create_dir(folder) {
        Err(error) if error.kind() == std::io::ErrorKind::AlreadyExists => Ok(()),
        other => other,
    }
}

/// An answer's key: the command line, and the fingerprints of the colour and depth images.
type AnswerKey = (usize, Option<u128>, Option<u128>);

/// Where the difference pictures go, inside the report's folder.
pub const PICTURES_FOLDER: &str = "pictures";

impl Answers {
    /// No answers yet; pictures go to [`PICTURES_FOLDER`] in `report` (made here).
    pub fn new(report: &Path) -> std::io::Result<Self> {
        make_subfolder(&report.join(PICTURES_FOLDER))?;
        Ok(Self {
            known: Mutex::default(),
            hashers: (RandomState::new(), RandomState::new()),
            report: report.to_path_buf(),
        })
    }

    /// A 128-bit fingerprint of an image (two independently keyed hashes).
    fn fingerprint(&self, image: &RgbImage) -> u128 {
        let one = |state: &RandomState| {
            let mut hasher = state.build_hasher();
            image.dimensions().hash(&mut hasher);
            image.as_raw().hash(&mut hasher);
            hasher.finish()
        };
        (u128::from(one(&self.hashers.0)) << 64) | u128::from(one(&self.hashers.1))
    }

    /// How many distinct comparisons were made (a line's images compared together count one).
    pub fn distinct(&self) -> usize {
        self.known
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len()
    }
}

/// Marks the images of command line number `index` (`exact`) in the submission `folder`: each
/// found and read (never a file another of the lines, `claimed`, names); those that can be
/// compared are compared together.
pub fn mark_line(
    folder: &Path,
    index: usize,
    exact: &Exact,
    answers: &Answers,
    claimed: &[PathBuf],
) -> Vec<Mark> {
    let named = [
        (ImageKind::Colour, exact.task.colour.clone()),
        (
            ImageKind::Depth,
            exact.task.depth.as_ref().map(|d| d.1.clone()),
        ),
    ];
    let mut marks = Vec::new();
    let mut images: Vec<(ImageKind, RgbImage, PathBuf)> = Vec::new();
    for (kind, wanted) in named {
        let Some(wanted) = wanted else { continue };
        let mut mark = Mark {
            kind,
            wanted: wanted.clone(),
            renamed: None,
            path: None,
            outcome: Outcome::Missing,
        };
        match find_image(folder, &wanted, claimed) {
            Found::Missing => {}
            Found::NotRead { name, why } => {
                mark.renamed = Some(name);
                mark.outcome = Outcome::Unreadable(why);
            }
            Found::File { path, renamed } => {
                mark.renamed = renamed;
                mark.path = Some(path.clone());
                match read_found_image(&path, exact.task.size_px) {
                    Ok(image) => images.push((kind, image, path)),
                    Err(NotRead::WrongSize { found, expected }) => {
                        mark.outcome = Outcome::WrongSize { found, expected };
                    }
                    Err(NotRead::Unreadable(why)) => mark.outcome = Outcome::Unreadable(why),
                }
            }
        }
        marks.push(mark);
    }
    if !images.is_empty() {
        let outcome = match answer(index, exact, images, answers) {
            Ok(answer) => Outcome::Compared(answer),
            Err(why) => Outcome::Unreadable(why),
        };
        for mark in &mut marks {
            if mark.path.is_some() && mark.outcome == Outcome::Missing {
                mark.outcome = outcome.clone();
            }
        }
    }
    marks
}

/// Compares `images` (a line's colour and/or depth image) together, or finds the answer for
/// the same images given before.
fn answer(
    index: usize,
    exact: &Exact,
    images: Vec<(ImageKind, RgbImage, PathBuf)>,
    answers: &Answers,
) -> Result<Arc<Answer>, String> {
    let mut key = (index, None, None);
    let mut request = CompareRequest {
        colour: None,
        depth: None,
        diff: Some(PathBuf::new()),
        json: false,
    };
    let (mut colour, mut depth) = (None, None);
    for (kind, image, path) in images {
        let fingerprint = Some(answers.fingerprint(&image));
        match kind {
            ImageKind::Colour => {
                key.1 = fingerprint;
                request.colour = Some(path);
                colour = Some(image);
            }
            ImageKind::Depth => {
                key.2 = fingerprint;
                request.depth = Some(TheirDepth {
                    range: exact.task.depth.as_ref().map(|d| d.0),
                    path,
                });
                depth = Some(image);
            }
        }
    }
    if let Some(known) = answers
        .known
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .get(&key)
    {
        return Ok(Arc::clone(known));
    }
    let theirs = TheirImages::new(colour, depth);
    let (report, picture) =
        compare(&exact.scene, &request, &theirs, &exact.frame).map_err(|e| e.to_string())?;
    let unexplained = &report.diagnosis.unexplained;
    let count = |flags: &Option<Vec<bool>>| {
        flags
            .as_ref()
            .map_or(0, |f| f.iter().filter(|&&u| u).count())
    };
    let colour = report.colour.as_ref().map(|d| ImageAnswer {
        matches: d.colour_matches(),
        pixels_differing: d.pixels_differing(),
        max_difference: d.max_difference(),
        unexplained_pixels: count(&unexplained.colour),
    });
    let depth = report.depth.as_ref().map(|d| ImageAnswer {
        matches: d.depth_matches(),
        pixels_differing: d.pixels_differing(),
        max_difference: d.max_difference(),
        unexplained_pixels: count(&unexplained.depth),
    });
    let fingerprints =
        [key.1, key.2].map(|f| f.map_or_else(|| "none".to_owned(), |f| format!("{f:032x}")));
    let name = format!("{}-{}-{}", index + 1, fingerprints[0], fingerprints[1]);
    let picture = match picture.filter(|_| !report.matches()) {
        Some(picture) => {
            let relative = format!("{PICTURES_FOLDER}/{name}.png");
            std::fs::write(answers.report.join(&relative), png_bytes(&picture)?)
                .map_err(|e| format!("cannot write the difference picture: {e}"))?;
            Some(relative)
        }
        None => None,
    };
    let answer = Arc::new(Answer {
        colour,
        depth,
        statements: statements(report.diagnosis.stated()),
        alternatives: report
            .diagnosis
            .alternatives()
            .iter()
            .map(|set| statements(set))
            .collect(),
        partial: statements(report.diagnosis.partial()),
        lines: report.lines(),
        json: serde_json::from_str(&report.json(None, None)).unwrap_or_default(),
        picture,
    });
    let mut known = answers.known.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(Arc::clone(known.entry(key).or_insert(answer)))
}

/// The diagnosis's statements, as the report keeps them.
fn statements(list: &[Deviation]) -> Vec<Statement> {
    list.iter()
        .map(|d| Statement {
            word: d.word().to_owned(),
            values: d.name_and_values(),
            said: d.said(),
            about_depth: d.is_about_depth(),
        })
        .collect()
}

/// An image as PNG bytes.
pub(crate) fn png_bytes(image: &RgbImage) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .map_err(|e| e.to_string())?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn statement(word: &str, values: &str, about_depth: bool) -> Statement {
        Statement {
            word: word.to_owned(),
            values: values.to_owned(),
            said: String::new(),
            about_depth,
        }
    }

    #[test]
    fn a_cell_says_a_near_tie_and_leaves_depth_statements_out_of_colour() {
        let differs = ImageAnswer {
            matches: false,
            pixels_differing: 100,
            max_difference: 255,
            unexplained_pixels: 0,
        };
        let mut answer = Answer {
            colour: Some(differs),
            depth: Some(ImageAnswer {
                unexplained_pixels: 3,
                ..differs
            }),
            statements: vec![],
            alternatives: vec![
                vec![statement("mirrored", "mirrored", false)],
                vec![statement("flipped-vertically", "flipped-vertically", false)],
            ],
            partial: vec![],
            lines: String::new(),
            json: serde_json::Value::Null,
            picture: None,
        };
        assert_eq!(
            answer.short(ImageKind::Colour),
            "one of: mirrored | flipped-vertically"
        );
        answer.alternatives.clear();
        assert_eq!(answer.short(ImageKind::Colour), "not explained");
        answer.statements = vec![
            statement("zoom", "zoom 0.9", false),
            statement("depth-range", "depth-range 8 13", true),
        ];
        assert_eq!(answer.short(ImageKind::Colour), "zoom 0.9");
        assert_eq!(
            answer.short(ImageKind::Depth),
            "zoom 0.9 + depth-range 8 13 (3 px unexplained)"
        );
    }
}
