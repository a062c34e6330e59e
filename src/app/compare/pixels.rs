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

/// Which of the two images is compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ImageKind {
    /// The colour image.
    #[default]
    Colour,
    /// The depth image (grey, the view's depth range).
    Depth,
}

impl ImageKind {
    /// The index of the image on screen (0 colour, 1 depth).
    pub(crate) fn index(self) -> usize {
        match self {
            Self::Colour => 0,
            Self::Depth => 1,
        }
    }
}

/// Which kind of image `theirs` (named `name`) is, where its content or its name says so against
/// `chosen`, with the reason said when it is not `chosen`. A depth image is grey: every pixel
/// grey but a single no-hit colour (their fill, where it is the scene's background), with a ramp
/// of at least three levels; a colour image of a scene with colours has two colours or more that
/// are not grey, or one that is a sphere's. Where the content cannot tell (a scene of grey spheres), a name that says
/// "depth", or "output" or "colour", does.
pub fn recognised_kind(
    scene: &Scene,
    name: &Path,
    theirs: &RgbImage,
    chosen: ImageKind,
) -> (ImageKind, Option<String>) {
    use std::collections::BTreeSet;
    let grey = |p: &image::Rgb<u8>| p.0[0] == p.0[1] && p.0[1] == p.0[2];
    let mut levels = BTreeSet::new();
    let mut colours = BTreeSet::new();
    for pixel in theirs.pixels() {
        if grey(pixel) {
            levels.insert(pixel.0[0]);
        } else if colours.len() < 3 {
            colours.insert(pixel.0);
        }
    }
    let background = crate::compare::model::colour_bytes(scene.background, false);
    let coloured = |c: glam::Vec3| c.x != c.y || c.y != c.z;
    let scene_has_colour = scene
        .spheres
        .iter()
        .any(|sphere| coloured(scene.sphere_colour(sphere)))
        || coloured(scene.background);
    let stem = name
        .file_stem()
        .map(|s| s.to_string_lossy().to_lowercase())
        .unwrap_or_default();
    let by_name = if stem.contains("depth") {
        Some(ImageKind::Depth)
    } else if ["output", "colour", "color"]
        .iter()
        .any(|w| stem.contains(w))
    {
        Some(ImageKind::Colour)
    } else {
        None
    };
    let looks_depth = levels.len() >= 3
        && (colours.is_empty() || (colours.len() == 1 && colours.contains(&background)));
    // Two colours, or one that is a sphere's (a lone red sphere on black): no depth image's.
    let sphere_colour = |c: &[u8; 3]| {
        scene.spheres.iter().any(|sphere| {
            let colour = scene.sphere_colour(sphere);
            [false, true]
                .map(|rounded| crate::compare::model::colour_bytes(colour, rounded))
                .contains(c)
        })
    };
    let looks_colour =
        colours.len() >= 2 || colours.iter().any(|c| *c != background && sphere_colour(c));
    let (kind, why) = if scene_has_colour && looks_depth {
        (
            ImageKind::Depth,
            format!(
                "every pixel is grey ({} levels{}) where the scene's spheres have colours",
                levels.len(),
                if colours.is_empty() {
                    ""
                } else {
                    ", and the scene's background where nothing is hit"
                }
            ),
        )
    } else if looks_colour {
        (
            ImageKind::Colour,
            "it has colours, which a depth image has not".to_owned(),
        )
    } else if let Some(kind) = by_name {
        (kind, format!("its name, {}", name.display()))
    } else {
        (chosen, String::new())
    };
    if kind == chosen {
        (kind, None)
    } else {
        let word = match kind {
            ImageKind::Colour => "a colour image",
            ImageKind::Depth => "a depth image",
        };
        (kind, Some(format!("judged as {word}: {why}")))
    }
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
    /// Each statement as its word and values (`zoom 1.118`).
    pub fn diagnosis(&self) -> Vec<String> {
        self.statements
            .iter()
            .map(Deviation::name_and_values)
            .collect()
    }
}

/// Compares `theirs` with the exact picture of the scene's own camera at their size, and
/// diagnoses the difference ([`judge`], as the command line does). A depth image is judged under
/// `range`, or with `None` under the range read back from it (`fallback`, the viewer's, where it
/// has no ramp to read one from).
pub fn compare_file(
    scene: &Scene,
    path: &Path,
    theirs: RgbImage,
    kind: ImageKind,
    range: Option<DepthRange>,
    fallback: DepthRange,
) -> Result<ComparisonPixels, String> {
    let (width_px, height_px) = theirs.dimensions();
    let view = View::of_camera(&scene.camera, width_px, height_px, fallback);
    let frame = render_with(scene, &view, &Quality::default()).map_err(|e| e.to_string())?;
    let given = match kind {
        ImageKind::Colour => Theirs {
            colour: Some(&theirs),
            depth: None,
        },
        ImageKind::Depth => Theirs {
            colour: None,
            depth: Some(&theirs),
        },
    };
    let (judged, range_source) = match (kind, range) {
        (ImageKind::Colour, _) => (
            judge(scene, &frame, given, Some(fallback)),
            RangeSource::Viewer,
        ),
        (ImageKind::Depth, Some(range)) => (
            judge(scene, &frame, given, Some(range)),
            RangeSource::Viewer,
        ),
        (ImageKind::Depth, None) => match judge(scene, &frame, given, None) {
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
    let unexplained = if diagnosis.stated().is_empty() && diagnosis.partial().is_empty() {
        None
    } else {
        unexplained.clone()
    };
    // The pixels each statement shown explains (the answer's, or those that explain part).
    let shown: Vec<Deviation> = diagnosis
        .stated()
        .iter()
        .chain(diagnosis.partial())
        .cloned()
        .collect();
    let explained_by = explained_by_each(scene, &judged.view, given, &shown)
        .into_iter()
        .map(|each| match kind {
            ImageKind::Colour => each.colour,
            ImageKind::Depth => each.depth,
        })
        .collect();
    Ok(ComparisonPixels {
        source: CompareSource::File(path.to_path_buf()),
        kind,
        kind_assumed: None,
        view: judged.view,
        exact,
        difference,
        model: diagnosis.stated_model().copied(),
        tell_apart: tell_apart(scene, &judged.view, diagnosis, given),
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
        unexplained,
        depth_range_inferred: judged.depth_range_inferred.flatten(),
        range_source,
        explained_by,
        theirs,
    })
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
    })
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::{ImageKind, recognised_kind};
    use crate::render::depth_map::DepthRange;
    use crate::render::{View, render};
    use crate::scene::bundled::BUNDLED_SCENES;
    use crate::scene::parse_scene;

    /// The course's scene1_01 (a red sphere on black) at 200×200 over its line's range, 9 … 10:
    /// its colour and depth images, as the course's program writes them.
    fn scene1_01() -> (crate::scene::Scene, image::RgbImage, image::RgbImage) {
        let text = BUNDLED_SCENES
            .iter()
            .find(|(name, _)| *name == "scene1_01.txt")
            .unwrap()
            .1;
        let scene = parse_scene(text).unwrap();
        let range = DepthRange::new(9.0, 10.0);
        let frame = render(&scene, &View::of_camera(&scene.camera, 200, 200, range)).unwrap();
        let (colour, depth) = (frame.colour_image(), frame.depth_image(range));
        (scene, colour, depth)
    }

    /// A red sphere on black is a colour image though it has one colour only (a sphere's), and
    /// its depth image a depth image; each said when it is not the kind chosen, and nothing said
    /// when it is.
    #[test]
    fn each_image_is_recognised_by_its_content_whatever_its_name() {
        let (scene, colour, depth) = scene1_01();
        let name = Path::new("mine.png");
        let (kind, said) = recognised_kind(&scene, name, &colour, ImageKind::Depth);
        assert_eq!(kind, ImageKind::Colour);
        assert!(
            said.unwrap()
                .starts_with("judged as a colour image: it has colours")
        );
        let (kind, said) = recognised_kind(&scene, name, &depth, ImageKind::Colour);
        assert_eq!(kind, ImageKind::Depth);
        assert!(
            said.unwrap()
                .starts_with("judged as a depth image: every pixel is grey")
        );
        assert_eq!(
            recognised_kind(&scene, name, &colour, ImageKind::Colour),
            (ImageKind::Colour, None)
        );
        // All black says nothing of its kind: the name, then the kind chosen, decide.
        let black = image::RgbImage::new(200, 200);
        let depth_name = Path::new("depth1_01.tga");
        assert_eq!(
            recognised_kind(&scene, depth_name, &black, ImageKind::Colour).0,
            ImageKind::Depth
        );
        assert_eq!(
            recognised_kind(&scene, name, &black, ImageKind::Depth),
            (ImageKind::Depth, None)
        );
    }
}
