//! A comparison's pixels, computed off the UI thread: their image judged against the exact
//! render ([`compare_file`], through [`crate::compare::judge`] as the command line does), or the
//! chosen quality measured against it ([`compare_quality`]).

use std::path::{Path, PathBuf};

use image::RgbImage;
use web_time::Instant;

use crate::compare::judge::{NoDepthRange, explained_by_each, judge};
use crate::compare::model::Model;
use crate::compare::tell_apart::tell_apart;
use crate::compare::{Deviation, Difference, RangeFrom, Theirs};
use crate::render::depth_map::DepthRange;
use crate::render::sampling::Sampling;
use crate::render::{Quality, View, render_with};
use crate::scene::Scene;

use super::kind::ImageKind;

/// What the compared image shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CompareShow {
    /// The live render.
    #[default]
    Rendered,
    /// Their image (or the picture at the chosen quality).
    Theirs,
    /// The heat map of the difference.
    Difference,
}

/// Samples per pixel of the high-sample reference an anti-aliased picture is measured against.
pub(crate) const REFERENCE_SAMPLES: u32 = 256;

/// A picture is "off" where a channel differs from the exact one by more than this many levels.
pub(crate) const OFF_LEVELS: u8 = 8;

/// Where the compared picture came from.
#[derive(Debug, Clone, PartialEq)]
pub enum CompareSource {
    /// An image file the user opened.
    File(PathBuf),
    /// The current view at the chosen quality.
    Quality(QualityFigures),
}

/// The trade measured on the user's view: the chosen quality against the exact render.
#[derive(Debug, Clone, PartialEq)]
pub struct QualityFigures {
    /// The quality measured, in words.
    pub quality: String,
    /// Its frame time, milliseconds.
    pub frame_ms: f64,
    /// The exact render's frame time, milliseconds.
    pub exact_ms: f64,
    /// Mean difference from the exact render, levels (largest channel per pixel).
    pub mean_error_levels: f64,
    /// Share of pixels off the exact render by more than [`OFF_LEVELS`].
    pub share_off: f64,
    /// For anti-aliasing: the same two figures against a high-sample reference.
    pub against_reference: Option<(f64, f64)>,
}

/// A finished comparison (pixels on the CPU; the textures are made on the UI thread).
#[derive(Debug, Clone)]
pub struct ComparisonPixels {
    /// Where their picture came from.
    pub source: CompareSource,
    /// Which image it is.
    pub kind: ImageKind,
    /// Why it was judged as another kind than the one chosen (`None`: as chosen).
    pub kind_assumed: Option<String>,
    /// The view both pictures are of.
    pub view: View,
    /// Their picture.
    pub theirs: RgbImage,
    /// The exact picture.
    pub exact: RgbImage,
    /// How they differ.
    pub difference: Difference,
    /// The model of their program the answer states (`None`: it states nothing): what the trace
    /// asks what their program drew at a pixel.
    pub model: Option<Model>,
    /// Why no model of their program was fitted (`None`: one was, or none was looked for).
    pub not_fitted_because: Option<String>,
    /// The statements that explain the difference (empty: none does, or none was looked for).
    pub statements: Vec<Deviation>,
    /// With a near tie: what would tell its alternatives apart.
    pub tell_apart: Option<String>,
    /// The alternatives of a near tie, each a `+`-joined list of statements (empty: no tie).
    pub alternatives: Vec<String>,
    /// When nothing explains it all: the statements that explain part of it.
    pub partial: Vec<Deviation>,
    /// Differing pixels no word named accounts for.
    pub unexplained_pixels: usize,
    /// A depth image's range, read back from it (`None`: a colour image, or no ramp to fit).
    pub depth_range_inferred: Option<DepthRange>,
    /// Where they are, one flag per pixel from the top row (cyan over the heat map).
    pub unexplained: Option<Vec<bool>>,
    /// Where the depth range a depth image was judged under came from.
    pub range_source: RangeSource,
    /// For each statement shown (the statements, then the partial ones), the pixels it explains
    /// on its own, one flag per pixel from the top row (highlighted when it is pointed at).
    pub explained_by: Vec<Option<Vec<bool>>>,
    /// The other image of a pair judged together (the depth image beside a colour one, or the
    /// colour image beside a depth one), with its own pixels; the answer is the pair's, the same
    /// in both (`None`: their image was judged alone).
    pub paired: Option<Box<ComparisonPixels>>,
}

/// Where the depth range a depth image is judged under comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RangeSource {
    /// Read back from their image (a new image is judged so).
    ReadBack,
    /// The viewer's depth range (set by the user after the image was read, or a colour image).
    Viewer,
    /// The viewer's: their image has no ramp to read a range from.
    Unreadable,
}

impl ComparisonPixels {
    /// Whether this image matches the exact one under the course's rule for its kind.
    pub fn matches(&self) -> bool {
        match self.kind {
            ImageKind::Colour => self.difference.colour_matches(),
            ImageKind::Depth => self.difference.depth_matches(),
        }
    }

    /// The image's name: its file, or the quality measured.
    pub fn name(&self) -> String {
        match &self.source {
            CompareSource::File(path) => path.display().to_string(),
            CompareSource::Quality(figures) => figures.quality.clone(),
        }
    }

    /// This image and the one paired with it, if any: the images on screen.
    pub fn images(&self) -> impl Iterator<Item = &ComparisonPixels> {
        std::iter::once(self).chain(self.paired.as_deref())
    }

    /// Each statement as its word and values (`zoom 1.118`).
    pub fn diagnosis(&self) -> Vec<String> {
        self.statements
            .iter()
            .map(Deviation::name_and_values)
            .collect()
    }
}

/// Compares `theirs` with the exact picture of the scene's own camera at their size, and
/// diagnoses the difference ([`judge`], as the command line does). With `partner` (the image of
/// the other kind, at the same size) the two are judged together, as the grader does: the answer
/// is the pair's, and the partner's pixels come back in [`ComparisonPixels::paired`]. A depth
/// image is judged under `range`, or with `None` under the range read back from it (`fallback`,
/// the viewer's, where it has no ramp to read one from).
pub fn compare_file(
    scene: &Scene,
    path: &Path,
    theirs: RgbImage,
    kind: ImageKind,
    partner: Option<(PathBuf, RgbImage)>,
    range: Option<DepthRange>,
    fallback: DepthRange,
) -> Result<ComparisonPixels, String> {
    let (width_px, height_px) = theirs.dimensions();
    let view = View::of_camera(&scene.camera, width_px, height_px, fallback);
    let frame = render_with(scene, &view, &Quality::default()).map_err(|e| e.to_string())?;
    let partner = partner.filter(|(_, image)| image.dimensions() == theirs.dimensions());
    let of_kind = |wanted: ImageKind| {
        if kind == wanted {
            Some(&theirs)
        } else {
            partner.as_ref().map(|(_, image)| image)
        }
    };
    let given = Theirs {
        colour: of_kind(ImageKind::Colour),
        depth: of_kind(ImageKind::Depth),
    };
    let (judged, range_source) = match (given.depth.is_some(), range) {
        (false, _) => (
            judge(scene, &frame, given, Some(fallback)),
            RangeSource::Viewer,
        ),
        (true, Some(range)) => (
            judge(scene, &frame, given, Some(range)),
            RangeSource::Viewer,
        ),
        (true, None) => match judge(scene, &frame, given, None) {
            Ok(judged) => (Ok(judged), RangeSource::ReadBack),
            Err(NoDepthRange) => (
                judge(scene, &frame, given, Some(fallback)),
                RangeSource::Unreadable,
            ),
        },
    };
    let mut judged = judged.map_err(|error| error.to_string())?;
    if range_source != RangeSource::ReadBack {
        // The range judged under is the viewer's, never one their program was given.
        judged.diagnosis = judged.diagnosis.with_range_from(RangeFrom::Viewer);
    }
    let diagnosis = &judged.diagnosis;
    // The pixels each statement shown explains (the answer's, or those that explain part).
    let shown: Vec<Deviation> = diagnosis
        .stated()
        .iter()
        .chain(diagnosis.partial())
        .cloned()
        .collect();
    let explained = explained_by_each(scene, &judged.view, given, &shown);
    let tell_apart = tell_apart(scene, &judged.view, diagnosis, given);
    let stated = !(diagnosis.stated().is_empty() && diagnosis.partial().is_empty());
    // One image's pixels: its exact picture, difference, unexplained and explained pixels.
    let side = |kind: ImageKind, path: &Path, theirs: RgbImage| {
        let (exact, difference, unexplained) = match kind {
            ImageKind::Colour => (
                judged.exact_colour.clone(),
                judged.colour.clone(),
                &diagnosis.unexplained.colour,
            ),
            ImageKind::Depth => (
                judged.exact_depth.clone(),
                judged.depth.clone(),
                &diagnosis.unexplained.depth,
            ),
        };
        let (Some(exact), Some(difference)) = (exact, difference) else {
            return Err("the exact image was not made".to_owned());
        };
        Ok(ComparisonPixels {
            source: CompareSource::File(path.to_path_buf()),
            kind,
            kind_assumed: None,
            view: judged.view,
            exact,
            difference,
            model: diagnosis.stated_model().copied(),
            tell_apart: tell_apart.clone(),
            not_fitted_because: diagnosis.not_fitted_because(),
            statements: diagnosis.stated().to_vec(),
            alternatives: diagnosis
                .alternatives()
                .iter()
                .map(|set| {
                    set.iter()
                        .map(Deviation::name_and_values)
                        .collect::<Vec<_>>()
                        .join(" + ")
                })
                .collect(),
            partial: diagnosis.partial().to_vec(),
            unexplained_pixels: diagnosis.unexplained_pixels(),
            unexplained: unexplained.clone().filter(|_| stated),
            depth_range_inferred: judged.depth_range_inferred.flatten(),
            range_source,
            explained_by: explained
                .iter()
                .map(|each| match kind {
                    ImageKind::Colour => each.colour.clone(),
                    ImageKind::Depth => each.depth.clone(),
                })
                .collect(),
            theirs,
            paired: None,
        })
    };
    let paired = match partner {
        Some((partner_path, image)) => Some(Box::new(side(kind.other(), &partner_path, image)?)),
        None => None,
    };
    let mut pixels = side(kind, path, theirs)?;
    pixels.paired = paired;
    Ok(pixels)
}

/// The colour image of `view` at `quality` against the exact one (and, with anti-aliasing, a
/// high-sample reference of the same sampler and filter).
pub fn compare_quality(
    scene: &Scene,
    view: &View,
    quality: &Quality,
) -> Result<ComparisonPixels, String> {
    let timed = |quality: &Quality| {
        let started = Instant::now();
        let frame = render_with(scene, view, quality).map_err(|e| e.to_string())?;
        Ok::<_, String>((frame.colour_image(), started.elapsed().as_secs_f64() * 1e3))
    };
    let (theirs, frame_ms) = timed(quality)?;
    let (exact, exact_ms) = timed(&Quality::default())?;
    let difference = Difference::of(&theirs, &exact);
    let figures = |difference: &Difference| {
        let total = difference.per_pixel.len().max(1) as f64;
        (
            difference.mean_difference(),
            difference.pixels_beyond(OFF_LEVELS) as f64 / total,
        )
    };
    let (mean_error_levels, share_off) = figures(&difference);
    let against_reference = match quality.sampling {
        Some(sampling) => {
            let reference_quality = Quality {
                sampling: Some(Sampling {
                    samples: REFERENCE_SAMPLES,
                    ..sampling
                }),
            };
            let (reference, _) = timed(&reference_quality)?;
            Some(figures(&Difference::of(&theirs, &reference)))
        }
        None => None,
    };
    Ok(ComparisonPixels {
        source: CompareSource::Quality(QualityFigures {
            quality: quality.describe(),
            frame_ms,
            exact_ms,
            mean_error_levels,
            share_off,
            against_reference,
        }),
        kind: ImageKind::Colour,
        kind_assumed: None,
        view: *view,
        theirs,
        exact,
        difference,
        model: None,
        tell_apart: None,
        not_fitted_because: None,
        statements: Vec::new(),
        alternatives: Vec::new(),
        partial: Vec::new(),
        unexplained_pixels: 0,
        unexplained: None,
        depth_range_inferred: None,
        range_source: RangeSource::Viewer,
        explained_by: Vec::new(),
        paired: None,
    })
}
