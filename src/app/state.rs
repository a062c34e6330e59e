//! The viewer's state: the loaded scene and where it came from, the settings that survive a
//! restart (eframe storage), and the view the controls edit.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::explore::{SliderRanges, initial_depth_range};
use crate::export::ExtraDepth;
use crate::render::View;
use crate::render::depth_map::{DepthColourMap, NO_HIT_MARK};
use crate::scene::{LoadError, Scene, load_scene_with_progress, parse_scene};
use crate::{DEFAULT_SCENE_NAME, DEFAULT_SCENE_TEXT};

/// Image formats offered by the export panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ExportFormat {
    /// `.png`
    Png,
    /// `.tga`
    Tga,
}

/// Export options, remembered between runs.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct ExportSettings {
    /// Where to write: `<stem>_colour.<ext>`, `<stem>_depth.<ext>`, `<stem>_both.<ext>`.
    pub path: String,
    /// Image format.
    pub format: ExportFormat,
    /// Also write colour and depth side by side in one picture.
    pub side_by_side: bool,
    /// Under the side-by-side picture, a legend: the colour bar and the depth range.
    pub legend: bool,
    /// Export at the displayed size (`true`) or at `size_px`.
    pub displayed_size: bool,
    /// Export size when not the displayed size.
    pub size_px: [u32; 2],
    /// Lossless or 16-bit depth written besides the 8-bit images.
    pub extra_depth: ExtraDepth,
    /// Where "save view as scene" writes when no dialog is used.
    pub scene_path: String,
}

impl Default for ExportSettings {
    fn default() -> Self {
        Self {
            path: "raytracer.png".into(),
            format: ExportFormat::Png,
            side_by_side: true,
            legend: true,
            displayed_size: true,
            size_px: [1024, 1024],
            extra_depth: ExtraDepth::None,
            scene_path: "view.txt".into(),
        }
    }
}

/// Everything persisted in eframe's storage (window size is persisted by eframe itself).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    /// The last scene file opened successfully.
    pub(crate) last_scene: Option<PathBuf>,
    /// Whether the controls panel is open.
    pub(crate) show_controls: bool,
    /// Export options.
    pub export: ExportSettings,
    /// Rendering quality (samples per pixel).
    pub quality: crate::render::Quality,
    /// How the depth image is drawn.
    pub depth: DepthDisplay,
    /// Per scene file: the view it was last seen in, and the views the user named.
    pub views: super::views::SceneViews,
}

/// How the depth image is drawn on screen (and exported).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct DepthDisplay {
    /// Grey (the course's), turbo or viridis.
    pub colour_map: DepthColourMap,
    /// Show no-hit pixels in [`NO_HIT_MARK`] on screen instead of black, so they stand apart
    /// from far ones. Files keep black.
    pub mark_no_hit: bool,
    /// "Auto range" ignores this percentage of the visible t at each end (0: min to max).
    pub auto_cut_percent: f64,
    /// The histogram's bars on a logarithmic scale of the counts.
    pub log_counts: bool,
    /// Keep fitting the depth range to the visible t while the view changes.
    pub follow: bool,
}

impl Default for DepthDisplay {
    fn default() -> Self {
        Self {
            colour_map: DepthColourMap::Grey,
            mark_no_hit: true,
            auto_cut_percent: 1.0,
            log_counts: false,
            follow: false,
        }
    }
}

impl DepthDisplay {
    /// The on-screen colour of no-hit pixels.
    pub(crate) fn no_hit_rgb(&self) -> [u8; 3] {
        if self.mark_no_hit {
            NO_HIT_MARK
        } else {
            DepthColourMap::FILE_NO_HIT
        }
    }
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            last_scene: None,
            show_controls: true,
            export: ExportSettings::default(),
            quality: crate::render::Quality::default(),
            depth: DepthDisplay::default(),
            views: super::views::SceneViews::default(),
        }
    }
}

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
    /// The file's own camera at the initial depth range ("reset view" returns here).
    pub file_view: View,
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
        file_view.depth_range = initial_depth_range(&scene, &file_view);
        Self {
            scene: Arc::new(scene),
            path,
            in_memory: false,
            file_view,
        }
    }

    /// The embedded default scene.
    pub(crate) fn default_scene(size_px: (u32, u32)) -> Self {
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
