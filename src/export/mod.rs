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

mod command;
mod legend;

use std::path::{Path, PathBuf};

use crate::output::atomic::{FileSet, FilesInMemory, Stage, stage_bytes};
use crate::output::depth_file::{RawDepthFormat, stage_depth_png16, stage_raw_depth};
use crate::output::image_file::stage_image;
use crate::output::{ImageFormat, WriteError, write_atomically};
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

/// The folder an export to `base_path` writes into, when it must exist first: `base_path`
/// itself when it names a folder, else its parent (`None` for a bare file name, which goes into
/// the working folder).
#[cfg_attr(target_arch = "wasm32", allow(dead_code))]
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
                ExtraDepth::Raw(format) => Some(sibling(&format!("depth.{}", format.extension()))),
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

/// "Save view as scene": writes `scene` with `view`'s camera to `path` (atomically), numbers in
/// Rust's shortest round-trip form so parsing it gives exactly this camera back.
#[cfg_attr(target_arch = "wasm32", allow(dead_code))]
pub(crate) fn save_view_as_scene(
    scene: &Scene,
    view: &View,
    path: &Path,
) -> Result<(), WriteError> {
    write_atomically(
        path,
        scene_to_text(&scene_with_view(scene, view)).as_bytes(),
    )
}

/// Writes every file of `plan` for `frame`, rendered from `scene` through `view` at `quality`,
/// all or nothing: every file is complete in a temporary file before any is renamed over its
/// destination. Returns the paths written.
#[cfg_attr(target_arch = "wasm32", allow(dead_code))]
pub(crate) fn write_export(
    scene: &Scene,
    view: &View,
    quality: &Quality,
    frame: &Frame,
    plan: &ExportPlan,
) -> Result<Vec<PathBuf>, WriteError> {
    let mut set = FileSet::new();
    stage_export(&mut set, scene, view, quality, frame, plan)?;
    set.commit()
}

/// The files of `plan` as [`write_export`] writes them, kept in memory (a browser page's
/// downloads): each file's name and bytes.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub(crate) fn export_in_memory(
    scene: &Scene,
    view: &View,
    quality: &Quality,
    frame: &Frame,
    plan: &ExportPlan,
) -> Result<Vec<(PathBuf, Vec<u8>)>, WriteError> {
    let mut files = FilesInMemory::default();
    stage_export(&mut files, scene, view, quality, frame, plan)?;
    Ok(files.files)
}

/// Stages every file of `plan` in `set`.
fn stage_export(
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
    stage_image(set, &files.images.colour, &frame.colour_image())?;
    let depth = frame.depth_image_mapped(range, map, DepthColourMap::FILE_NO_HIT);
    stage_image(set, &files.images.depth, &depth)?;
    if plan.side_by_side {
        let mut both = frame.side_by_side_mapped(range, map);
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

#[cfg(test)]
mod tests {
    use super::command::shell_quote;
    use super::*;
    use crate::render::depth_map::DepthRange;
    use crate::render::{Filter, Sampler, Sampling, render_with};
    use crate::scene::{load_scene, parse_scene};

    #[test]
    fn export_paths_add_suffixes_and_keep_the_folder() {
        let paths = ExportPaths::new(Path::new("shots/view.tga"), ImageFormat::Png, "s");
        assert_eq!(paths.colour, Path::new("shots/view_colour.tga"));
        assert_eq!(paths.depth, Path::new("shots/view_depth.tga"));
        assert_eq!(paths.side_by_side, Path::new("shots/view_both.tga"));
        let paths = ExportPaths::new(Path::new("view"), ImageFormat::Png, "s");
        assert_eq!(paths.colour, Path::new("view_colour.png"));
        let paths = ExportPaths::new(Path::new("view.v2"), ImageFormat::Tga, "s");
        assert_eq!(paths.depth, Path::new("view.v2_depth.tga"));
        // Into a folder: named after the scene.
        let paths = ExportPaths::new(Path::new("shots/"), ImageFormat::Png, "scene1_02");
        assert_eq!(paths.colour, Path::new("shots/scene1_02_colour.png"));
    }

    #[test]
    fn a_folder_export_is_named_after_the_scene_and_needs_its_folder() {
        assert_eq!(
            name_in_folder(Some(Path::new("scenes/scene1_02.txt"))),
            "scene1_02"
        );
        assert_eq!(name_in_folder(None), DEFAULT_EXPORT_NAME);
        assert_eq!(
            export_folder(Path::new("shots/new/")),
            Some(PathBuf::from("shots/new/"))
        );
        assert_eq!(
            export_folder(Path::new("shots/view.png")),
            Some(PathBuf::from("shots"))
        );
        assert_eq!(export_folder(Path::new("view.png")), None);
    }

    #[test]
    fn shell_quoting() {
        assert_eq!(shell_quote("a_b-1.png"), "a_b-1.png");
        assert_eq!(shell_quote("-0.25"), "-0.25");
        assert_eq!(shell_quote("my view.png"), "'my view.png'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
    }

    #[test]
    fn saved_view_parses_back_to_the_same_camera() {
        let scene = parse_scene(include_str!("../../scenes/scene1_03.txt")).unwrap();
        let mut view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(0.0, 1.0));
        view.center_world += glam::DVec3::new(0.1, 1.0 / 3.0, -7e-9);
        view.size_world = std::f64::consts::PI;
        view.direction_world = glam::DVec3::new(0.3, -0.2, -1.0 / 7.0);
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("view.txt");
        save_view_as_scene(&scene, &view, &path).unwrap();
        let back = load_scene(&path).unwrap();
        assert_eq!(back, scene_with_view(&scene, &view));
        assert_eq!(back.camera.center_world, view.center_world);
        assert_eq!(back.camera.size_world, view.size_world);
    }

    #[test]
    fn command_names_every_setting() {
        let plan = ExportPlan {
            base_path: PathBuf::from("shots/my view.png"),
            name_in_folder: DEFAULT_EXPORT_NAME.to_owned(),
            format: ImageFormat::Png,
            side_by_side: true,
            legend: true,
            colour_map: DepthColourMap::Turbo,
            extra_depth: ExtraDepth::Raw(RawDepthFormat::Exr),
            program: Some(PathBuf::from("/opt/it's/raytracer")),
        };
        let files = ExportFiles::of(&plan);
        assert_eq!(files.scene, Path::new("shots/my view_scene.txt"));
        assert_eq!(files.command, Path::new("shots/my view_command.sh"));
        assert_eq!(
            files.depth_raw.as_deref(),
            Some(Path::new("shots/my view_depth.exr"))
        );
        let scene = parse_scene(include_str!("../../scenes/scene1_01.txt")).unwrap();
        let view = View::of_camera(&scene.camera, 64, 48, DepthRange::new(9.0, 10.5));
        let quality = Quality {
            sampling: Some(Sampling {
                sampler: Sampler::Jittered,
                samples: 16,
                filter: Filter::Tent { radius: 1.5 },
                seed: 0,
            }),
        };
        let arguments = command_arguments(&plan, &files, &view, &quality);
        let line = arguments.join(" ");
        assert!(
            line.starts_with("-input my view_scene.txt -size 64 48"),
            "{line}"
        );
        for part in [
            "-depth 9 10.5 my view_depth.png",
            "-depth_colormap turbo",
            "-depth_raw my view_depth.exr",
            "-jittered_samples 16",
            "-tent_filter 1.5",
        ] {
            assert!(line.contains(part), "{part} in {line}");
        }
        let script = command_script(&arguments, plan.program.as_deref());
        assert!(
            script.contains(r"raytracer='/opt/it'\''s/raytracer'"),
            "{script}"
        );
        assert!(script.contains("'my view_scene.txt'"), "{script}");
        // The arguments are a valid command line.
        assert!(crate::cli::parse_command(arguments).is_ok());
    }

    #[test]
    fn export_writes_every_file_and_the_command_reproduces_them() {
        let scene = parse_scene(include_str!("../../scenes/scene1_02.txt")).unwrap();
        let mut view = View::of_camera(&scene.camera, 48, 32, DepthRange::new(8.5, 11.0));
        view.center_world.x += 0.37;
        let quality = Quality::default();
        let frame = render_with(&scene, &view, &quality).unwrap();
        let folder = tempfile::tempdir().unwrap();
        for (colour_map, extra_depth) in [
            (DepthColourMap::Grey, ExtraDepth::Png16),
            (
                DepthColourMap::Viridis,
                ExtraDepth::Raw(RawDepthFormat::Pfm),
            ),
        ] {
            let plan = ExportPlan {
                base_path: folder
                    .path()
                    .join(format!("shot {}.tga", colour_map.name())),
                name_in_folder: DEFAULT_EXPORT_NAME.to_owned(),
                format: ImageFormat::Png,
                side_by_side: true,
                legend: false,
                colour_map,
                extra_depth,
                program: None,
            };
            let written = write_export(&scene, &view, &quality, &frame, &plan).unwrap();
            assert_eq!(written.len(), 6, "{written:?}");
            assert!(written.iter().all(|p| p.exists()));
            // Run the command's arguments (from the export folder) into a second folder.
            let files = ExportFiles::of(&plan);
            let arguments = command_arguments(&plan, &files, &view, &quality);
            let again = tempfile::tempdir().unwrap();
            let rebased: Vec<String> = arguments
                .iter()
                .enumerate()
                .map(|(i, a)| {
                    let is_input = i > 0 && arguments[i - 1] == "-input";
                    let extension = Path::new(a).extension().and_then(|e| e.to_str());
                    if matches!(extension, Some("tga" | "png" | "pfm")) {
                        again.path().join(a).display().to_string()
                    } else if is_input {
                        folder.path().join(a).display().to_string()
                    } else {
                        a.clone()
                    }
                })
                .collect();
            let crate::cli::Command::Render(request) = crate::cli::parse_command(rebased).unwrap()
            else {
                panic!("a render command");
            };
            crate::cli::run::run(&request).unwrap();
            for path in [&files.images.colour, &files.images.depth]
                .into_iter()
                .chain(files.depth_raw.as_ref())
            {
                let name = path.file_name().unwrap();
                assert_eq!(
                    std::fs::read(path).unwrap(),
                    std::fs::read(again.path().join(name)).unwrap(),
                    "{name:?} is reproduced byte for byte"
                );
            }
            if extra_depth == ExtraDepth::Png16 {
                let name = files.depth16.file_name().unwrap();
                assert_eq!(
                    std::fs::read(&files.depth16).unwrap(),
                    std::fs::read(again.path().join(name)).unwrap()
                );
            }
        }
    }
}
