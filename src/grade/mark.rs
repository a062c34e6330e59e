//! One image of one submission marked: found (letter case and `.tga`/`.png` forgiven), read
//! within the limits of [`read_their_image`], checked for size, and compared and explained as
//! `-compare_output` / `-compare_depth` would (a depth image under the assignment's range, the
//! range it was drawn over read from it where it differs). Students who make the same mistake
//! hand in the same picture: an answer is computed once per distinct image and shared.

use std::collections::HashMap;
use std::collections::hash_map::RandomState;
use std::fmt::Write as _;
use std::hash::{BuildHasher, Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use image::RgbImage;

use super::assignment::Task;
use super::submission::{Found, find_image};
use crate::cli::compare::{TheirImages, compare};
use crate::cli::{CompareRequest, TheirDepth};
use crate::compare::Difference;
use crate::compare::their_image::read_their_image;
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

/// What comparing one image found.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// Whether it matches by the course's rule.
    pub matches: bool,
    /// Pixels that differ at all.
    pub pixels_differing: usize,
    /// The largest difference of a channel, levels.
    pub max_difference: u8,
    /// The statements: (word, the word with its values, the sentence).
    pub statements: Vec<(String, String, String)>,
    /// Differing pixels no statement explains.
    pub unexplained_pixels: usize,
    /// The whole answer as `name: value` lines.
    pub lines: String,
    /// The whole answer as JSON (docs/compare-json.md).
    pub json: serde_json::Value,
    /// The difference picture (theirs, exact, difference, unexplained), a PNG file in the
    /// report's folder (relative path); differing only.
    pub picture: Option<String>,
    /// A name for this distinct image, shared by every submission that holds it.
    pub key: String,
}

impl Answer {
    /// The answer in a few words: "match", or the statements with their values.
    pub fn short(&self) -> String {
        if self.matches {
            return "match".to_owned();
        }
        let mut text = self
            .statements
            .iter()
            .map(|(_, values, _)| values.as_str())
            .collect::<Vec<_>>()
            .join(" + ");
        if text.is_empty() {
            text = "not explained".to_owned();
        } else if self.unexplained_pixels > 0 {
            let _ = write!(text, " ({} px unexplained)", self.unexplained_pixels);
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
    /// Compared.
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

/// The answers computed so far, by command line, image and picture; the difference pictures
/// are written to the report's folder as they are made, so no image is held after its
/// comparison.
pub struct Answers {
    known: Mutex<HashMap<(usize, ImageKind, u128), Arc<Answer>>>,
    hashers: (RandomState, RandomState),
    report: PathBuf,
}

/// Where the difference pictures go, inside the report's folder.
pub const PICTURES_FOLDER: &str = "pictures";

impl Answers {
    /// No answers yet; pictures go to [`PICTURES_FOLDER`] in `report` (made here).
    pub fn new(report: &Path) -> std::io::Result<Self> {
        std::fs::create_dir_all(report.join(PICTURES_FOLDER))?;
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

    /// How many distinct images were compared.
    pub fn distinct(&self) -> usize {
        self.known
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len()
    }
}

/// Marks the `kind` image of `exact` (command line number `index`) in the submission `folder`.
pub fn mark(
    folder: &Path,
    index: usize,
    exact: &Exact,
    kind: ImageKind,
    answers: &Answers,
) -> Mark {
    let wanted = match kind {
        ImageKind::Colour => exact.task.colour.clone(),
        ImageKind::Depth => exact.task.depth.as_ref().map(|d| d.1.clone()),
    }
    .unwrap_or_default();
    let mut mark = Mark {
        kind,
        wanted: wanted.clone(),
        renamed: None,
        path: None,
        outcome: Outcome::Missing,
    };
    let path = match find_image(folder, &wanted) {
        Found::Missing => return mark,
        Found::NotRead { name, why } => {
            mark.renamed = Some(name);
            mark.outcome = Outcome::Unreadable(why);
            return mark;
        }
        Found::File { path, renamed } => {
            mark.renamed = renamed;
            path
        }
    };
    mark.path = Some(path.clone());
    if std::fs::metadata(&path).is_ok_and(|m| m.len() == 0) {
        mark.outcome = Outcome::Unreadable("an empty file".to_owned());
        return mark;
    }
    mark.outcome = match read_their_image(&path) {
        Err(error) => Outcome::Unreadable(error.reason()),
        Ok(image) if image.dimensions() != exact.task.size_px => Outcome::WrongSize {
            found: image.dimensions(),
            expected: exact.task.size_px,
        },
        Ok(image) => match answer(index, exact, kind, image, &path, answers) {
            Ok(answer) => Outcome::Compared(answer),
            Err(why) => Outcome::Unreadable(why),
        },
    };
    mark
}

/// Compares `image`, or finds the answer for the same image given before.
fn answer(
    index: usize,
    exact: &Exact,
    kind: ImageKind,
    image: RgbImage,
    path: &Path,
    answers: &Answers,
) -> Result<Arc<Answer>, String> {
    let fingerprint = answers.fingerprint(&image);
    let key = (index, kind, fingerprint);
    if let Some(known) = answers
        .known
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .get(&key)
    {
        return Ok(Arc::clone(known));
    }
    let (request, theirs) = match kind {
        ImageKind::Colour => (
            CompareRequest {
                colour: Some(path.to_path_buf()),
                depth: None,
                diff: Some(PathBuf::new()),
                json: false,
            },
            TheirImages::new(Some(image), None),
        ),
        ImageKind::Depth => (
            CompareRequest {
                colour: None,
                depth: Some(TheirDepth {
                    range: exact.task.depth.as_ref().map(|d| d.0),
                    path: path.to_path_buf(),
                }),
                diff: Some(PathBuf::new()),
                json: false,
            },
            TheirImages::new(None, Some(image)),
        ),
    };
    let (report, picture) =
        compare(&exact.scene, &request, &theirs, &exact.frame).map_err(|e| e.to_string())?;
    let matches = report.matches();
    let difference = match kind {
        ImageKind::Colour => report.colour.as_ref(),
        ImageKind::Depth => report.depth.as_ref(),
    };
    let name = format!("{index}-{}-{fingerprint:032x}", kind.word());
    let picture = match picture.filter(|_| !matches) {
        Some(picture) => {
            let relative = format!("{PICTURES_FOLDER}/{name}.png");
            std::fs::write(answers.report.join(&relative), png_bytes(&picture)?)
                .map_err(|e| format!("cannot write the difference picture: {e}"))?;
            Some(relative)
        }
        None => None,
    };
    let answer = Arc::new(Answer {
        matches,
        pixels_differing: difference.map_or(0, Difference::pixels_differing),
        max_difference: difference.map_or(0, Difference::max_difference),
        statements: report
            .diagnosis
            .stated()
            .iter()
            .map(|d| (d.word().to_owned(), d.name_and_values(), d.said()))
            .collect(),
        unexplained_pixels: report.diagnosis.unexplained_pixels(),
        lines: report.lines(),
        json: serde_json::from_str(&report.json(None, None)).unwrap_or_default(),
        picture,
        key: name,
    });
    let mut known = answers.known.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(Arc::clone(known.entry(key).or_insert(answer)))
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
