//! [`LoadedScene`]: the scene on screen, where it came from (a file, bytes, or the embedded
//! default) and what the controls derive from it (the file's view, the slider ranges).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::explore::{SliderRanges, initial_depth_range};
use crate::render::View;
use crate::scene::{LoadError, Scene, load_scene_with_progress, parse_scene};
use crate::{DEFAULT_SCENE_NAME, DEFAULT_SCENE_TEXT};

/// A scene on screen, with its origin and what the controls derive from it.
#[derive(Debug, Clone)]
pub struct LoadedScene {
    /// The scene.
    pub scene: Arc<Scene>,
    /// The file it came from; `None` for the embedded default scene. For a scene that came as
    /// bytes (`in_memory`), only its name.
    pub path: Option<PathBuf>,
    /// The scene came as bytes (a browser page's dropped, picked or fetched file), not from a
    /// file the viewer can read again: there is nothing to reload or watch.
    pub in_memory: bool,
    /// The file's own camera at the initial depth range ("reset view" returns here): the
    /// course's range for a course scene, else the range of what the camera sees.
    pub file_view: View,
    /// The depth range of the course's command line, for a scene named as one of the course's
    /// (`scene1_04.txt`): what it opens with and what "Course files" writes over.
    pub course_range: Option<crate::render::depth_map::DepthRange>,
}

impl LoadedScene {
    /// Wraps a parsed scene; `size_px` is the image size to start with.
    pub fn new(scene: Scene, path: Option<PathBuf>, size_px: (u32, u32)) -> Self {
        let mut file_view = View::of_camera(
            &scene.camera,
            size_px.0,
            size_px.1,
            crate::render::depth_map::DepthRange::new(0.0, 1.0),
        );
        let course_range = path
            .as_deref()
            .and_then(Path::file_name)
            .and_then(|name| crate::scene::bundled::course_range_of(&name.to_string_lossy()))
            .map(|(min, max)| crate::render::depth_map::DepthRange::new(min, max));
        file_view.depth_range =
            course_range.unwrap_or_else(|| initial_depth_range(&scene, &file_view));
        Self {
            scene: Arc::new(scene),
            path,
            in_memory: false,
            file_view,
            course_range,
        }
    }

    /// The embedded default scene, at the image size used until the first layout tells the
    /// real one.
    pub(crate) fn default_scene() -> Self {
        let size_px = (512, 512);
        match parse_scene(DEFAULT_SCENE_TEXT) {
            Ok(scene) => Self::new(scene, None, size_px),
            // The embedded scene is parsed by a test; this arm only guards against a bad build.
            Err(_) => Self::new(empty_scene(), None, size_px),
        }
    }

    /// Parses a scene that came as bytes named `name` (see [`Self::in_memory`]).
    pub(crate) fn from_bytes(
        name: &str,
        bytes: &[u8],
        size_px: (u32, u32),
    ) -> Result<Self, LoadError> {
        let scene = crate::scene::load_scene_from_bytes(name, bytes)?;
        Ok(Self {
            in_memory: true,
            ..Self::new(scene, Some(PathBuf::from(name)), size_px)
        })
    }

    /// Reads a scene file, telling `progress` the share done (0 to 1) as it goes.
    pub(crate) fn load_with_progress(
        path: &Path,
        size_px: (u32, u32),
        progress: &(dyn Fn(f64) + Sync),
    ) -> Result<Self, LoadError> {
        Ok(Self::new(
            load_scene_with_progress(path, progress)?,
            Some(path.to_path_buf()),
            size_px,
        ))
    }

    /// The name shown in the status bar.
    pub fn name(&self) -> String {
        self.path.as_ref().map_or_else(
            || DEFAULT_SCENE_NAME.to_owned(),
            |p| p.display().to_string(),
        )
    }

    /// Slider ranges for this scene and `view`.
    pub(crate) fn ranges(&self, view: &View) -> SliderRanges {
        SliderRanges::new(&self.scene, view)
    }
}

fn empty_scene() -> Scene {
    Scene {
        camera: crate::scene::OrthographicCamera {
            center_world: glam::DVec3::new(0.0, 0.0, 10.0),
            direction_world: glam::DVec3::NEG_Z,
            up_world: glam::DVec3::Y,
            size_world: 5.0,
        },
        background: crate::scene::DEFAULT_BACKGROUND,
        materials: Vec::new(),
        spheres: Vec::new(),
    }
}
