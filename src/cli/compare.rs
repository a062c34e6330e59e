//! The compare concept at the command line ([`crate::compare`] is the concept itself):
//! `-compare_output`, `-compare_depth` and `-diff` read the user's images, compare them with
//! the exact render of the request, name the mistakes behind a difference
//! ([`crate::compare::diagnose`]) and draw the difference picture.

use std::fmt::Write as _;
use std::path::Path;

use image::RgbImage;

use super::flags::Flag;
use super::request::CompareRequest;
use crate::compare::judge::{NoDepthRange, judge, their_depth_at};
use crate::compare::picture::{Row, difference_picture};
use crate::compare::tell_apart::tell_apart;
use crate::compare::their_image::{TheirImageError, read_their_image_sized};
use crate::compare::{Deviation, Diagnosis, Difference, Theirs};
use crate::explore::trace::PixelTrace;
use crate::render::Frame;
use crate::render::depth_map::DepthRange;
use crate::scene::Scene;

/// Why the images to compare cannot be compared.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// An image to compare could not be read.
    #[error("{flag} '{path}': cannot read the image: {message}")]
    ReadImage {
        /// The flag that named it.
        flag: Flag,
        /// Its path as given.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// Their depth image was given without a range, and none could be inferred from it.
    #[error(
        "{flag} '{path}': cannot infer the depth range it was made over (no grey ramp to fit): \
         give it as {flag} DMIN DMAX FILE"
    )]
    NoDepthRange {
        /// The flag that named the image.
        flag: Flag,
        /// Its path as given.
        path: String,
    },
    /// An image to compare is not the size of the render.
    #[error(
        "{flag} '{path}' is {}×{} pixels, but {expected_by} {}×{}: compare images of one size \
         (leave out -size to take it from the image)",
        found.0, found.1, expected.0, expected.1
    )]
    CompareSize {
        /// The flag that named the image.
        flag: Flag,
        /// Its path as given.
        path: String,
        /// Its size.
        found: (u32, u32),
        /// The size expected.
        expected: (u32, u32),
        /// What set the expected size: "-size asks for" or "-compare_output 'x.tga' is".
        expected_by: String,
    },
}

/// The user's images, read.
#[derive(Debug, Default)]
pub(crate) struct TheirImages {
    colour: Option<RgbImage>,
    depth: Option<RgbImage>,
}

impl TheirImages {
    /// Their colour and depth images, read.
    pub(crate) fn new(colour: Option<RgbImage>, depth: Option<RgbImage>) -> Self {
        Self { colour, depth }
    }

    /// The size of the images (all the same), if any was read.
    pub(crate) fn size_px(&self) -> Option<(u32, u32)> {
        self.colour
            .as_ref()
            .or(self.depth.as_ref())
            .map(RgbImage::dimensions)
    }
}

/// What a comparison found.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareReport {
    /// Their colour image against the exact one.
    pub(crate) colour: Option<Difference>,
    /// Their depth image against the exact one.
    pub(crate) depth: Option<Difference>,
    /// The mistakes named.
    pub(crate) diagnosis: Diagnosis,
    /// With a depth image given without a range: the range it was most likely made over
    /// (`None`: no ramp to fit). `None` when a range was given.
    pub(crate) depth_range_inferred: Option<Option<DepthRange>>,
    /// With a depth image given with a range (`-compare_depth DMIN DMAX FILE`): that range.
    pub(crate) depth_range_given: Option<DepthRange>,
    /// With a depth image: the range it was judged under (given, or read back).
    pub(crate) depth_range_used: Option<DepthRange>,
    /// With a tie: what would tell its answers apart.
    pub(crate) tell_apart: Option<String>,
}

impl CompareReport {
    /// Whether the images match by the course's rule (colour identical; depth within one level on
    /// at most 0.1% of the pixels).
    pub fn matches(&self) -> bool {
        self.colour.as_ref().is_none_or(Difference::colour_matches)
            && self.depth.as_ref().is_none_or(Difference::depth_matches)
    }

    /// The report as `name: value` lines.
    pub fn lines(&self) -> String {
        let mut text = String::new();
        for (kind, difference) in [("colour", &self.colour), ("depth", &self.depth)] {
            if let Some(difference) = difference {
                let _ = writeln!(
                    text,
                    "{kind}_pixels_differing: {}",
                    difference.pixels_differing()
                );
                let _ = writeln!(
                    text,
                    "{kind}_max_difference: {}",
                    difference.max_difference()
                );
            }
        }
        if let Some(given) = self.depth_range_given {
            let _ = writeln!(text, "depth_range_given: {} {}", given.min_t, given.max_t);
        }
        if let Some(inferred) = self.depth_range_inferred {
            let _ = match inferred {
                Some(range) => writeln!(
                    text,
                    "depth_range_inferred: {} {}",
                    range.min_t, range.max_t
                ),
                None => writeln!(text, "depth_range_inferred: none"),
            };
        }
        let _ = writeln!(text, "match: {}", if self.matches() { "yes" } else { "no" });
        let stated = self.diagnosis.stated();
        if let Some(because) = self.diagnosis.not_fitted_because() {
            let _ = writeln!(text, "diagnosis: none (no model fitted: {because})");
        } else if stated.is_empty() {
            let _ = writeln!(text, "diagnosis: none");
        }
        for deviation in stated {
            let _ = writeln!(text, "diagnosis: {}", deviation.said());
        }
        let alternatives = self.diagnosis.alternatives();
        if !alternatives.is_empty() {
            let sets: Vec<String> = alternatives
                .iter()
                .map(|set| {
                    if set.is_empty() {
                        "none".to_owned()
                    } else {
                        set.iter()
                            .map(Deviation::name_and_values)
                            .collect::<Vec<_>>()
                            .join(" + ")
                    }
                })
                .collect();
            let _ = writeln!(text, "diagnosis_ambiguous: {}", sets.join(" | "));
        }
        if let Some(tell_apart) = &self.tell_apart {
            let _ = writeln!(text, "diagnosis_tell_apart: {tell_apart}");
        }
        for same in &self.diagnosis.same_pixels {
            let names: Vec<String> = same.iter().map(Deviation::name_and_values).collect();
            let _ = writeln!(text, "diagnosis_same_pixels: {}", names.join(" + "));
        }
        for deviation in self.diagnosis.partial() {
            let _ = writeln!(text, "diagnosis_partial: {}", deviation.said());
        }
        if !self.matches() {
            let _ = writeln!(
                text,
                "unexplained_pixels: {}",
                self.diagnosis.unexplained_pixels()
            );
        }
        text
    }
}

/// Version of the JSON form of the answer (docs/compare-json.md); raised when a field changes
/// meaning or goes.
pub const COMPARE_JSON_VERSION: u32 = 2;

/// What stands in the JSON document for the trace until its lines are written in.
const TRACE_SLOT: &str = "\u{1}trace";

/// Per line of a trace in the JSON answer, beside the line: its indent, quotes, comma and end
/// (8 bytes) and room for escapes.
pub(crate) const JSON_LINE_BYTES: u64 = 16;

impl CompareReport {
    /// The report as one JSON document (docs/compare-json.md), with the `-stats` lines when
    /// given (as numbers where they are).
    pub fn json(&self, stats: Option<&str>, trace: Option<&str>) -> String {
        use serde_json::{Value, json};
        let difference = |d: &Option<Difference>| {
            d.as_ref().map_or(Value::Null, |d| {
                json!({
                    "pixels_differing": d.pixels_differing(),
                    "max_difference": d.max_difference(),
                })
            })
        };
        let statements =
            |list: &[Deviation]| list.iter().map(Deviation::to_json).collect::<Vec<Value>>();
        let verdict = self.diagnosis.verdict_name();
        let mut document = json!({
            "format": "raytracer-compare",
            "version": COMPARE_JSON_VERSION,
            "match": self.matches(),
            "colour": difference(&self.colour),
            "depth": difference(&self.depth),
            "depth_range_given": self
                .depth_range_given
                .map_or(Value::Null, |range| json!([range.min_t, range.max_t])),
            "depth_range_inferred": match self.depth_range_inferred {
                None => Value::Null,
                Some(None) => json!("none"),
                Some(Some(range)) => json!([range.min_t, range.max_t]),
            },
            "verdict": verdict,
            "not_fitted_because": self.diagnosis.not_fitted_because(),
            "tell_apart": self.tell_apart,
            "statements": statements(self.diagnosis.stated()),
            "partial": statements(self.diagnosis.partial()),
            "alternatives": self.diagnosis.alternatives().iter().map(|a| statements(a)).collect::<Vec<_>>(),
            "same_pixels": self.diagnosis.same_pixels.iter().map(|a| statements(a)).collect::<Vec<_>>(),
            "pixels_differing_exact": self.diagnosis.differing_exact,
            "unexplained_pixels": self.diagnosis.unexplained_pixels(),
        });
        if let Some(stats) = stats {
            let mut object = serde_json::Map::new();
            for line in stats.lines() {
                if let Some((name, value)) = line.split_once(": ") {
                    let value = value
                        .parse::<f64>()
                        .ok()
                        .and_then(|v| serde_json::Number::from_f64(v).map(Value::Number))
                        .unwrap_or_else(|| Value::String(value.to_owned()));
                    object.insert(name.to_owned(), value);
                }
            }
            document["stats"] = Value::Object(object);
        }
        // The trace's lines (a million spheres: 150 MB) are written into the document's place
        // for them, not copied into a value of their own first.
        if trace.is_some() {
            document["trace"] = Value::from(TRACE_SLOT);
        }
        let mut text = serde_json::to_string_pretty(&document).unwrap_or_default();
        let slot = serde_json::to_string(TRACE_SLOT).unwrap_or_default();
        if let (Some(trace), Some(at)) = (trace, text.find(&slot)) {
            let lines = trace.lines().count();
            let mut spliced =
                String::with_capacity(text.len() + trace.len() + JSON_LINE_BYTES as usize * lines);
            spliced.push_str(&text[..at]);
            spliced.push('[');
            for (n, line) in trace.lines().enumerate() {
                spliced.push_str(if n == 0 { "\n    " } else { ",\n    " });
                spliced.push_str(&serde_json::to_string(line).unwrap_or_default());
            }
            spliced.push_str(if lines == 0 { "]" } else { "\n  ]" });
            spliced.push_str(&text[at + slot.len()..]);
            text = spliced;
        }
        text.push('\n');
        text
    }
}

/// Reads one image to compare (within the limits of
/// [`crate::compare::their_image::read_their_image`]); one whose header
/// announces another size than `expected` (the size and what asks for it) is refused before its
/// pixels are decoded.
fn read_image(
    flag: Flag,
    path: &Path,
    expected: Option<&((u32, u32), String)>,
) -> Result<RgbImage, CompareError> {
    read_their_image_sized(path, expected.map(|(size, _)| *size)).map_err(|error| match error {
        TheirImageError::OtherSize {
            found,
            expected: size,
            ..
        } => CompareError::CompareSize {
            flag,
            path: path.display().to_string(),
            found,
            expected: size,
            expected_by: expected.map(|(_, by)| by.clone()).unwrap_or_default(),
        },
        error => CompareError::ReadImage {
            flag,
            path: path.display().to_string(),
            message: error.reason(),
        },
    })
}

/// Reads the images of `compare`; each must be `size_px` when given (`-size`), and all the same
/// size.
pub(crate) fn read_theirs(
    compare: &CompareRequest,
    size_px: Option<(u32, u32)>,
) -> Result<TheirImages, CompareError> {
    let mut theirs = TheirImages::default();
    let mut expected = size_px.map(|size| (size, format!("{} asks for", Flag::Size)));
    let files = [
        (Flag::CompareOutput, compare.colour.as_deref()),
        (
            Flag::CompareDepth,
            compare.depth.as_ref().map(|d| d.path.as_path()),
        ),
    ];
    for (flag, path) in files {
        let Some(path) = path else { continue };
        let image = read_image(flag, path, expected.as_ref())?;
        match &expected {
            Some((size, by)) if image.dimensions() != *size => {
                return Err(CompareError::CompareSize {
                    flag,
                    path: path.display().to_string(),
                    found: image.dimensions(),
                    expected: *size,
                    expected_by: by.clone(),
                });
            }
            Some(_) => {}
            None => {
                expected = Some((
                    image.dimensions(),
                    format!("{flag} '{}' is", path.display()),
                ));
            }
        }
        match flag {
            Flag::CompareOutput => theirs.colour = Some(image),
            _ => theirs.depth = Some(image),
        }
    }
    Ok(theirs)
}

/// Compares `theirs` with `exact` (the exact, one-sample f64 frame of `request`'s view) and
/// diagnoses the difference ([`judge`]); returns the report and, with `-diff`, the difference
/// picture. A depth image given without its range is compared over the range read back from it.
pub(crate) fn compare(
    scene: &Scene,
    compare: &CompareRequest,
    theirs: &TheirImages,
    exact: &Frame,
) -> Result<(CompareReport, Option<RgbImage>), CompareError> {
    let given = Theirs {
        colour: theirs.colour.as_ref(),
        depth: theirs.depth.as_ref(),
    };
    let range = compare.depth.as_ref().and_then(|depth| depth.range);
    let judged =
        judge(scene, exact, given, range).map_err(|NoDepthRange| CompareError::NoDepthRange {
            flag: Flag::CompareDepth,
            path: compare
                .depth
                .as_ref()
                .map(|depth| depth.path.display().to_string())
                .unwrap_or_default(),
        })?;
    let picture = compare.diff.as_ref().map(|_| {
        let mut rows = Vec::new();
        for (kind, theirs, exact, difference, unexplained) in [
            (
                "colour",
                &theirs.colour,
                &judged.exact_colour,
                &judged.colour,
                &judged.diagnosis.unexplained.colour,
            ),
            (
                "depth",
                &theirs.depth,
                &judged.exact_depth,
                &judged.depth,
                &judged.diagnosis.unexplained.depth,
            ),
        ] {
            if let (Some(theirs), Some(exact), Some(difference)) = (theirs, exact, difference) {
                rows.push(Row {
                    kind,
                    theirs,
                    exact,
                    difference,
                    unexplained: unexplained.as_deref(),
                });
            }
        }
        difference_picture(&rows)
    });
    let tell_apart = tell_apart(scene, &judged.view, &judged.diagnosis, given);
    Ok((
        CompareReport {
            colour: judged.colour,
            depth: judged.depth,
            diagnosis: judged.diagnosis,
            depth_range_inferred: judged.depth_range_inferred.filter(|_| range.is_none()),
            depth_range_given: range.filter(|_| theirs.depth.is_some()),
            depth_range_used: theirs.depth.as_ref().map(|_| judged.view.depth_range),
            tell_apart,
        },
        picture,
    ))
}

/// Their pixel beside the trace of it: their colour and depth bytes at the traced pixel, and
/// what their grey stands for: as the answer's model of their program draws it (their no-hit grey,
/// a hit outside their range, a t over their range), else the t over the range the depth image
/// was judged under.
pub(crate) fn their_pixel_lines(
    scene: &Scene,
    theirs: &TheirImages,
    traced: &PixelTrace,
    report: Option<&CompareReport>,
) -> String {
    let row = traced.size_px.1 - 1 - traced.y_up_px;
    let colour = theirs
        .colour
        .as_ref()
        .map(|image| traced.their_colour_line(image.get_pixel(traced.x_px, row).0));
    let depth = theirs.depth.as_ref().map(|image| {
        let grey = image.get_pixel(traced.x_px, row).0[0];
        let drew = report.and_then(|report| {
            let view = crate::render::View::of_camera(
                &scene.camera,
                traced.size_px.0,
                traced.size_px.1,
                report.depth_range_used?,
            );
            their_depth_at(
                scene,
                &view,
                report.diagnosis.stated_model()?,
                (traced.x_px, traced.y_up_px),
                grey,
            )
        });
        traced.their_depth_line(grey, drew)
    });
    colour.into_iter().chain(depth).collect()
}
