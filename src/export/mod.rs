//! Reproducible exports: everything one export from the viewer writes, and how to make the same
//! pictures again from the command line.
//!
//! An export to base path `dir/name.png` writes
//! * `name_colour.png`, `name_depth.png` (the depth through the chosen colour map) and optionally
//!   `name_both.png` (the two side by side);
//! * optionally the lossless depth `name_depth.pfm` / `name_depth.exr` (raw t) or the 16-bit
//!   `name_depth16.png`;
//! * `name_scene.txt`: the scene with the **current view's camera** (centre, direction, up, size),
//!   numbers written exactly, so the export does not depend on the original file staying as it
//!   was ("save view as scene" writes the same text);
//! * `name_command.sh`: the `raytracer` command line that renders `name_scene.txt` into the same
//!   colour and depth files, byte for byte (same size, depth range, colour map and
//!   supersampling flags). It `cd`s to its own folder, so it runs from anywhere.
//!
//! "Course files" ([`course`]) write instead what the course's own command line writes for the
//! scene file: `output1_04.tga`, `depth1_04.tga` at 200×200, and the command line that makes them.

pub(crate) mod command;
pub(crate) mod course;
mod legend;
pub(crate) mod numbers;

use std::path::{Path, PathBuf};

use image::RgbImage;

use crate::output::atomic::{Stage, stage_bytes};
use crate::output::depth_file::{RawDepthFormat, stage_depth_png16, stage_raw_depth};
use crate::output::image_file::stage_image;
use crate::output::{ImageFormat, WriteError};
use crate::render::depth_map::DepthColourMap;
use crate::render::{Frame, Quality, View};

use crate::scene::{OrthographicCamera, Scene, scene_to_text};
pub(crate) use command::{command_arguments, command_script};

/// The files one export writes, derived from a base path `dir/stem.ext`:
/// `dir/stem_colour.ext`, `dir/stem_depth.ext` and (optionally) `dir/stem_both.ext`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct ExportPaths {
    /// Colour image.
    pub(crate) colour: PathBuf,
    /// Depth image.
    pub(crate) depth: PathBuf,
    /// Colour and depth side by side.
    pub(crate) side_by_side: PathBuf,
}

/// The base name of an export into a folder when the scene has no file name (the embedded one).
pub const DEFAULT_EXPORT_NAME: &str = "raytracer";

/// Whether `path` names a folder to export into: an existing folder, or a path ending with a
/// separator (`/`, and `\` where that is one too).
pub(crate) fn names_a_folder(path: &Path) -> bool {
    let text = path.as_os_str().to_string_lossy();
    // `/` is a separator everywhere, a backslash on Windows too.
    path.is_dir() || text.chars().last().is_some_and(std::path::is_separator)
}

/// The base name of an export into a folder of the scene file `scene_path`: the file's stem
/// (`scene1_02.txt` gives `scene1_02`), or [`DEFAULT_EXPORT_NAME`] without a file.
pub(crate) fn name_in_folder(scene_path: Option<&Path>) -> String {
    scene_path
        .and_then(Path::file_stem)
        .map(|stem| stem.to_string_lossy().into_owned())
        .filter(|stem| !stem.is_empty())
        .unwrap_or_else(|| DEFAULT_EXPORT_NAME.to_owned())
}

/// The export path `export_path` once the scene `new_name` is opened in place of `old_name`
/// (each a [`name_in_folder`]): where its file stem was the old scene's name or
/// [`DEFAULT_EXPORT_NAME`], the new scene's name in its place (folder and extension kept), so
/// exports are named after the scene on screen (`scene1_04_colour.png`); `None` where the user
/// chose a name of their own.
pub(crate) fn export_path_following(
    export_path: &str,
    old_name: &str,
    new_name: &str,
) -> Option<String> {
    let path = Path::new(export_path.trim());
    if names_a_folder(path) {
        return None;
    }
    let stem = path.file_stem()?.to_string_lossy();
    if stem != old_name && stem != DEFAULT_EXPORT_NAME || stem == new_name {
        return None;
    }
    let file_name = match path.extension() {
        Some(extension) => format!("{new_name}.{}", extension.to_string_lossy()),
        None => new_name.to_owned(),
    };
    Some(path.with_file_name(file_name).display().to_string())
}

/// The folder an export to `base_path` writes into, when it must exist first: `base_path`
/// itself when it names a folder, else its parent (`None` for a bare file name, which goes into
/// the working folder).
pub(crate) fn export_folder(base_path: &Path) -> Option<PathBuf> {
    if names_a_folder(base_path) {
        return Some(base_path.to_path_buf());
    }
    base_path
        .parent()
        .filter(|parent| !parent.as_os_str().is_empty())
        .map(Path::to_path_buf)
}

impl ExportPaths {
    /// Paths for base `path`; `format` applies when the path's extension names no format. A
    /// folder (see [`names_a_folder`]) means "into this folder" with the base name
    /// `name_in_folder` (the scene's, see [`name_in_folder`]).
    pub(crate) fn new(path: &Path, format: ImageFormat, name_in_folder: &str) -> Self {
        let into_folder;
        let path = if names_a_folder(path) {
            into_folder = path.join(name_in_folder);
            into_folder.as_path()
        } else {
            path
        };
        let format = ImageFormat::from_path(path).unwrap_or(format);
        let extension = match format {
            ImageFormat::Tga => "tga",
            ImageFormat::Png => "png",
        };
        let has_format = ImageFormat::from_path(path).is_ok();
        let stem = if has_format {
            path.file_stem()
        } else {
            path.file_name()
        }
        .map_or_else(|| "raytracer".into(), |s| s.to_string_lossy().into_owned());
        let with_suffix =
            |suffix: &str| path.with_file_name(format!("{stem}_{suffix}.{extension}"));
        Self {
            colour: with_suffix("colour"),
            depth: with_suffix("depth"),
            side_by_side: with_suffix("both"),
        }
    }
}

/// Extra depth output of an export, besides the 8-bit depth image.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum ExtraDepth {
    /// Nothing more.
    #[default]
    None,
    /// 16-bit grey PNG over the depth range (`name_depth16.png`).
    Png16,
    /// Raw t as 32-bit floats (`name_depth.pfm` or `name_depth.exr`).
    Raw(RawDepthFormat),
}

/// What one export writes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ExportPlan {
    /// Base path; see [`ExportPaths::new`].
    pub(crate) base_path: PathBuf,
    /// The base name of the files when `base_path` is a folder (the scene's name).
    pub(crate) name_in_folder: String,
    /// Format of the 8-bit images when the base path's extension names none.
    pub(crate) format: ImageFormat,
    /// Also write colour and depth side by side.
    pub(crate) side_by_side: bool,
    /// Under the side-by-side picture, the colour bar and the depth range.
    pub(crate) legend: bool,
    /// Colour map of the depth image.
    pub(crate) colour_map: DepthColourMap,
    /// Lossless or 16-bit depth, if any.
    pub(crate) extra_depth: ExtraDepth,
    /// The `raytracer` binary the command script runs (absolute path), if known.
    pub(crate) program: Option<PathBuf>,
}

/// Every file of one export.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct ExportFiles {
    /// The 8-bit images.
    pub(crate) images: ExportPaths,
    /// `name_depth16.png`.
    pub(crate) depth16: PathBuf,
    /// `name_depth.pfm` or `.exr` (the extension follows the chosen format).
    pub(crate) depth_raw: Option<PathBuf>,
    /// `name_scene.txt`.
    pub(crate) scene: PathBuf,
    /// `name_command.sh`.
    pub(crate) command: PathBuf,
}

impl ExportFiles {
    /// The files `plan` writes, in the order they are written.
    pub(crate) fn written_by(&self, plan: &ExportPlan) -> Vec<PathBuf> {
        let mut paths = vec![self.images.colour.clone(), self.images.depth.clone()];
        if plan.side_by_side {
            paths.push(self.images.side_by_side.clone());
        }
        match (plan.extra_depth, &self.depth_raw) {
            (ExtraDepth::Png16, _) => paths.push(self.depth16.clone()),
            (ExtraDepth::Raw(_), Some(path)) => paths.push(path.clone()),
            _ => {}
        }
        paths.extend([self.scene.clone(), self.command.clone()]);
        paths
    }

    /// The files `plan` writes.
    pub(crate) fn of(plan: &ExportPlan) -> Self {
        let images = ExportPaths::new(&plan.base_path, plan.format, &plan.name_in_folder);
        let sibling = |suffix: &str| {
            let name = images
                .colour
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let stem = name.rsplit_once("_colour.").map_or("raytracer", |(s, _)| s);
            images.colour.with_file_name(format!("{stem}_{suffix}"))
        };
        Self {
            depth16: sibling("depth16.png"),
            depth_raw: match plan.extra_depth {
                ExtraDepth::Raw(format) => Some(sibling(match format {
                    RawDepthFormat::Pfm => "depth.pfm",
                    RawDepthFormat::Exr => "depth.exr",
                })),
                _ => None,
            },
            scene: sibling("scene.txt"),
            command: sibling("command.sh"),
            images,
        }
    }
}

/// `scene` with its camera replaced by `view`'s (image size and depth range are not part of a
/// scene file).
pub(crate) fn scene_with_view(scene: &Scene, view: &View) -> Scene {
    Scene {
        camera: OrthographicCamera {
            center_world: view.center_world,
            direction_world: view.direction_world,
            up_world: view.up_world,
            size_world: view.size_world,
        },
        ..scene.clone()
    }
}

/// "Save view as scene": stages `scene` with `view`'s camera as the file `path`, numbers in
/// Rust's shortest round-trip form so parsing it gives exactly this camera back.
pub(crate) fn stage_view_as_scene(
    set: &mut dyn Stage,
    scene: &Scene,
    view: &View,
    path: &Path,
) -> Result<(), WriteError> {
    stage_bytes(
        set,
        path,
        scene_to_text(&scene_with_view(scene, view)).as_bytes(),
    )
}

/// Stages every file of `plan` for `frame`, rendered from `scene` through `view` at `quality`, in
/// `set`: a [`FileSet`](crate::output::atomic::FileSet) writes them all or nothing (every file complete in a temporary file
/// before any is renamed over its destination), a
/// [`FilesInMemory`](crate::output::atomic::FilesInMemory) keeps them for a page's
/// downloads.
pub(crate) fn stage_export(
    set: &mut dyn Stage,
    scene: &Scene,
    view: &View,
    quality: &Quality,
    frame: &Frame,
    plan: &ExportPlan,
) -> Result<(), WriteError> {
    let files = ExportFiles::of(plan);
    let range = view.depth_range;
    let map = plan.colour_map;
    let colour = frame.colour_image();
    stage_image(set, &files.images.colour, &colour)?;
    let depth = frame.depth_image_mapped(range, map, DepthColourMap::FILE_NO_HIT);
    stage_image(set, &files.images.depth, &depth)?;
    if plan.side_by_side {
        let mut both = side_by_side(&colour, &depth);
        if plan.legend {
            both = legend::with_legend(&both, range, map);
        }
        stage_image(set, &files.images.side_by_side, &both)?;
    }
    match (plan.extra_depth, &files.depth_raw) {
        (ExtraDepth::Png16, _) => stage_depth_png16(set, frame, range, &files.depth16)?,
        (ExtraDepth::Raw(_), Some(path)) => stage_raw_depth(set, frame, path)?,
        _ => {}
    }
    let scene_text = scene_to_text(&scene_with_view(scene, view));
    stage_bytes(set, &files.scene, scene_text.as_bytes())?;
    let arguments = command_arguments(plan, &files, view, quality);
    let script = command_script(&arguments, plan.program.as_deref());
    set.stage_file(&files.command, true, &mut |out| {
        out.write_all(script.as_bytes())
            .map_err(|source| WriteError::Io {
                path: files.command.clone(),
                source,
            })
    })
}

/// Colour and depth images side by side in one picture (colour left), as users share them.
fn side_by_side(colour: &RgbImage, depth: &RgbImage) -> RgbImage {
    let width = colour.width();
    RgbImage::from_fn(width + depth.width(), colour.height(), |x, y| {
        if x < width {
            *colour.get_pixel(x, y)
        } else {
            *depth.get_pixel(x - width, y)
        }
    })
}

#[cfg(test)]
mod tests;
