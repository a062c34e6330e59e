//! What would tell a tie apart: where two stories draw one picture of their scene alike (a
//! symmetric scene mirrored or flipped, a depth image alone), which of their other images, and
//! which of the course's command lines, draw the stories' pictures differently. An answer that
//! cannot choose says so, and says what to run next.

use image::RgbImage;

use super::describe::rebuild;
use super::deviation::Deviation;
use super::diagnosis::Diagnosis;
use super::fit::score::Theirs;
use super::model_render::render_model;
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::bundled::{BUNDLED_SCENES, course_lines};
use crate::scene::{Scene, load_scene_from_bytes};

/// Image size of the course's command lines.
const COURSE_SIZE_PX: u32 = 200;

/// Whether the pictures of the tie's answers differ somewhere: each answer (its own part with the
/// statements all make) drawn through `view` of `scene`, colour or depth.
fn differ(scene: &Scene, view: &View, answers: &[Vec<Deviation>], depth: bool) -> bool {
    let pictures: Vec<RgbImage> = answers
        .iter()
        .map(|answer| {
            let (colour, depth_image) = render_model(scene, view, &rebuild(view, answer));
            if depth { depth_image } else { colour }
        })
        .collect();
    pictures.windows(2).any(|pair| pair[0] != pair[1])
}

/// The sentence that says what would tell the answer's tie apart, `None` without a tie: their
/// other image (when one was given alone) where the answers draw it differently, and the course's
/// command lines whose images they draw differently.
pub fn tell_apart(
    scene: &Scene,
    view: &View,
    diagnosis: &Diagnosis,
    theirs: Theirs<'_>,
) -> Option<String> {
    let alternatives = diagnosis.alternatives();
    if alternatives.len() < 2 {
        return None;
    }
    let answers: Vec<Vec<Deviation>> = alternatives
        .iter()
        .map(|own| [diagnosis.stated(), own.as_slice()].concat())
        .collect();
    let mut by = Vec::new();
    match (theirs.colour.is_some(), theirs.depth.is_some()) {
        (true, false) if differ(scene, view, &answers, true) => {
            by.push("your depth image (compare it too)".to_owned());
        }
        (false, true) if differ(scene, view, &answers, false) => {
            by.push("your colour image (compare it too)".to_owned());
        }
        _ => {}
    }
    let mut lines = Vec::new();
    for (file, min_t, max_t) in course_lines() {
        let Some((_, text)) = BUNDLED_SCENES.iter().find(|(name, _)| *name == file) else {
            continue;
        };
        let Ok(course_scene) = load_scene_from_bytes(file, text.as_bytes()) else {
            continue;
        };
        let course_view = View::of_camera(
            &course_scene.camera,
            COURSE_SIZE_PX,
            COURSE_SIZE_PX,
            DepthRange::new(min_t, max_t),
        );
        if differ(&course_scene, &course_view, &answers, false)
            || differ(&course_scene, &course_view, &answers, true)
        {
            lines.push(file.trim_end_matches(".txt"));
        }
    }
    if !lines.is_empty() {
        by.push(format!(
            "your images of the course's {} (their pictures differ there)",
            lines.join(", ")
        ));
    }
    Some(if by.is_empty() {
        "nothing the course draws tells these apart: each draws every picture alike".to_owned()
    } else {
        format!("{} would tell these apart", by.join("; or "))
    })
}
