//! "Course files": the open scene's `output1_04.tga` and `depth1_04.tga` at the course's 200×200,
//! over the depth range in use, with the command line that makes them
//! ([`crate::export::course`]), written into the export path's folder (downloads in a page).

use std::path::PathBuf;
use std::sync::Arc;

use super::loaded_scene::LoadedScene;
use crate::export::course::{CourseFiles, course_view, stage_course_files};
use crate::export::{export_folder, name_in_folder};
use crate::output::atomic::Stage;
use crate::render::depth_map::DepthRange;
use crate::render::render;

/// The files "Course files" writes for `loaded`: into the folder of `export_path` (the export
/// path field), named after the scene.
pub(crate) fn course_files(export_path: &str, loaded: &LoadedScene) -> CourseFiles {
    let folder = export_folder(&PathBuf::from(export_path.trim())).unwrap_or_default();
    CourseFiles::new(&folder, &name_in_folder(loaded.path.as_deref()))
}

/// The scene file the command line of the course files reads: the open file (its full path), or
/// for a scene with no file (bundled, or a page's) its name, as the course's scenes are named.
fn course_input(loaded: &LoadedScene) -> PathBuf {
    match &loaded.path {
        Some(path) if !loaded.in_memory => {
            std::fs::canonicalize(path).unwrap_or_else(|_| path.clone())
        }
        Some(path) => PathBuf::from(path.file_name().unwrap_or_default()),
        None => PathBuf::from("scene.txt"),
    }
}

/// What writes the course files of `loaded` over `range` into a set of files (the user has
/// agreed to replace what they replace): the scene rendered at the course's size, the two TGA
/// files and the command line that makes them, which names `program`.
pub(crate) fn course_files_stage(
    loaded: &LoadedScene,
    export_path: &str,
    range: DepthRange,
    program: Option<PathBuf>,
) -> impl FnOnce(&mut dyn Stage) -> Result<(), String> + Send + 'static {
    let scene = Arc::clone(&loaded.scene);
    let files = course_files(export_path, loaded);
    let input = course_input(loaded);
    move |set: &mut dyn Stage| {
        let frame = render(&scene, &course_view(&scene, range)).map_err(|e| e.to_string())?;
        stage_course_files(set, &frame, range, &files, &input, program.as_deref())
            .map_err(|e| e.to_string())
    }
}
