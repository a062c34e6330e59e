//! "Course files": the open scene's `output1_04.tga` and `depth1_04.tga` at the course's 200×200,
//! over the depth range in use, with the command line that makes them
//! ([`crate::export::course`]), written into the export path's folder (downloads in a page).

use std::path::PathBuf;
use std::sync::Arc;

use super::ViewerApp;
use crate::export::course::{CourseFiles, course_view, stage_course_files};
use crate::export::{export_folder, name_in_folder};
use crate::render::render;

impl ViewerApp {
    /// The files "Course files" writes: into the export path's folder, named after the scene.
    pub(crate) fn course_files(&self) -> CourseFiles {
        let folder =
            export_folder(&PathBuf::from(self.settings.export.path.trim())).unwrap_or_default();
        CourseFiles::new(&folder, &name_in_folder(self.scene.loaded.path.as_deref()))
    }

    /// The scene file the command line of the course files reads: the open file (its full
    /// path), or for a scene with no file (bundled, or a page's) its name, as the course's
    /// scenes are named.
    fn course_input(&self) -> PathBuf {
        let loaded = &self.scene.loaded;
        match &loaded.path {
            Some(path) if !loaded.in_memory => {
                std::fs::canonicalize(path).unwrap_or_else(|_| path.clone())
            }
            Some(path) => PathBuf::from(path.file_name().unwrap_or_default()),
            None => PathBuf::from("scene.txt"),
        }
    }

    /// Writes the course files (the user has agreed to replace what they replace).
    pub(crate) fn export_course_files(&mut self) {
        let scene = Arc::clone(&self.scene.loaded.scene);
        let range = self.viewing.view.depth_range;
        let files = self.course_files();
        let input = self.course_input();
        let program = self.writes.program.clone();
        let stage = move |set: &mut dyn crate::output::atomic::Stage| {
            let frame = render(&scene, &course_view(&scene, range)).map_err(|e| e.to_string())?;
            stage_course_files(set, &frame, range, &files, &input, program.as_deref())
                .map_err(|e| e.to_string())
        };
        #[cfg(target_arch = "wasm32")]
        {
            let mut memory = crate::output::atomic::FilesInMemory::default();
            let files = stage(&mut memory).map(|()| {
                memory
                    .files
                    .into_iter()
                    .map(|(path, bytes)| (super::actions::download_name(&path), bytes))
                    .collect()
            });
            self.download_files(files);
        }
        #[cfg(not(target_arch = "wasm32"))]
        self.write_in_background("writing the course files…", move || {
            let mut set = crate::output::atomic::FileSet::new();
            stage(&mut set)?;
            let written = set.commit().map_err(|e| e.to_string())?;
            let names: Vec<String> = written
                .iter()
                .map(|p| std::fs::canonicalize(p).unwrap_or_else(|_| p.clone()))
                .map(|p| p.display().to_string())
                .collect();
            Ok(format!("wrote the course files {}", names.join(", ")))
        });
    }
}
