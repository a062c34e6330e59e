//! The course's files for the open scene: what the course's own command line
//! (`raytracer -input scene1_04.txt -size 200 200 -output output1_04.tga -depth 12 17
//! depth1_04.tga`) writes, with the depth range in use, and a script holding that command line.
//! The images are those the command line writes, byte for byte: the exact render of the scene
//! file's own camera at 200×200, grey depth.

use std::path::{Path, PathBuf};

use super::command::command_script;
use crate::cli::{DepthOutput, Outputs, RenderRequest};
use crate::output::WriteError;
use crate::output::atomic::Stage;
use crate::output::image_file::stage_image;
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::{Frame, Quality, View};
use crate::scene::Scene;

/// The course's image size, pixels (both sides).
pub(crate) const COURSE_SIZE_PX: u32 = 200;

/// The files of a "course files" export.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct CourseFiles {
    /// The colour image (`output1_04.tga`).
    pub(crate) colour: PathBuf,
    /// The depth image (`depth1_04.tga`).
    pub(crate) depth: PathBuf,
    /// The script with the command line (`command1_04.sh`).
    pub(crate) command: PathBuf,
}

impl CourseFiles {
    /// The files for the scene named `scene_name` (a file stem, `scene1_04`) in `folder`: the
    /// course's names where the scene is one of the course's (`sceneN_MM` gives `outputN_MM.tga`,
    /// `depthN_MM.tga`), else `name_output.tga`, `name_depth.tga`.
    pub(crate) fn new(folder: &Path, scene_name: &str) -> Self {
        let (colour, depth, command) = match scene_name.strip_prefix("scene") {
            Some(number) if !number.is_empty() => (
                format!("output{number}.tga"),
                format!("depth{number}.tga"),
                format!("command{number}.sh"),
            ),
            _ => (
                format!("{scene_name}_output.tga"),
                format!("{scene_name}_depth.tga"),
                format!("{scene_name}_command.sh"),
            ),
        };
        Self {
            colour: folder.join(colour),
            depth: folder.join(depth),
            command: folder.join(command),
        }
    }

    /// Every file, in the order they are written.
    pub(crate) fn all(&self) -> Vec<PathBuf> {
        vec![
            self.colour.clone(),
            self.depth.clone(),
            self.command.clone(),
        ]
    }

    /// The course's command line that writes these files from `scene_input` over `range` (file
    /// names relative to their folder).
    pub(crate) fn command_arguments(&self, scene_input: &Path, range: DepthRange) -> Vec<String> {
        let name = |path: &Path| PathBuf::from(path.file_name().unwrap_or_default());
        RenderRequest {
            input: scene_input.to_path_buf(),
            width_px: COURSE_SIZE_PX,
            height_px: COURSE_SIZE_PX,
            size_given: true,
            compare: None,
            outputs: Outputs {
                colour: Some(name(&self.colour)),
                depth: Some(DepthOutput {
                    range,
                    path: name(&self.depth),
                }),
                ..Outputs::default()
            },
            depth_colour_map: DepthColourMap::default(),
            quality: Quality::default(),
            stats: false,
            trace: None,
        }
        .to_arguments()
        .into_iter()
        .map(|word| word.to_string_lossy().into_owned())
        .collect()
    }
}

/// The view the course's command renders: the scene file's own camera at 200×200, over `range`.
pub(crate) fn course_view(scene: &Scene, range: DepthRange) -> View {
    View::of_camera(&scene.camera, COURSE_SIZE_PX, COURSE_SIZE_PX, range)
}

/// Stages the course's files in `set`: the two images of `frame` (the exact render of
/// [`course_view`]) over `range`, and the script running `program` (or the `raytracer` on PATH)
/// on `scene_input`.
pub(crate) fn stage_course_files(
    set: &mut dyn Stage,
    frame: &Frame,
    range: DepthRange,
    files: &CourseFiles,
    scene_input: &Path,
    program: Option<&Path>,
) -> Result<(), WriteError> {
    stage_image(set, &files.colour, &frame.colour_image())?;
    let depth = frame.depth_image_mapped(
        range,
        DepthColourMap::default(),
        DepthColourMap::FILE_NO_HIT,
    );
    stage_image(set, &files.depth, &depth)?;
    let script = command_script(&files.command_arguments(scene_input, range), program);
    set.stage_file(&files.command, true, &mut |out| {
        out.write_all(script.as_bytes())
            .map_err(|source| WriteError::Io {
                path: files.command.clone(),
                source,
            })
    })
}
