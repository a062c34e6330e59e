//! The command line of an export: the render request that makes the export's colour and depth
//! files again from its scene file, written back to arguments through the command line's flag
//! table ([`RenderRequest::to_arguments`]), and the `name_command.sh` script that runs it.

use std::path::{Path, PathBuf};

use super::{ExportFiles, ExportPlan, ExtraDepth};
use crate::cli::{DepthOutput, Outputs, RenderRequest};
use crate::output::shell::shell_quote;
use crate::render::{Quality, View};

/// The render request that draws `files.scene` into the same colour and depth files as the
/// export, file names relative to the export's folder.
pub(crate) fn export_request(
    plan: &ExportPlan,
    files: &ExportFiles,
    view: &View,
    quality: &Quality,
) -> RenderRequest {
    let name = |path: &Path| PathBuf::from(path.file_name().unwrap_or_default());
    let depth_output = |path: &Path| DepthOutput {
        range: view.depth_range,
        path: name(path),
    };
    // An output the export does not make (a new output flag) stays empty.
    #[allow(clippy::needless_update)]
    let outputs = Outputs {
        colour: Some(name(&files.images.colour)),
        depth: Some(depth_output(&files.images.depth)),
        depth16: (plan.extra_depth == ExtraDepth::Png16).then(|| depth_output(&files.depth16)),
        depth_raw: files.depth_raw.as_deref().map(name),
        ..Outputs::default()
    };
    RenderRequest {
        input: name(&files.scene),
        width_px: view.width_px,
        height_px: view.height_px,
        size_given: true,
        compare: None,
        outputs,
        depth_colour_map: plan.colour_map,
        quality: *quality,
        stats: false,
        trace: None,
    }
}

/// The command-line arguments (after the program name) of [`export_request`], as text.
pub(crate) fn command_arguments(
    plan: &ExportPlan,
    files: &ExportFiles,
    view: &View,
    quality: &Quality,
) -> Vec<String> {
    export_request(plan, files, view, quality)
        .to_arguments()
        .into_iter()
        .map(|word| word.to_string_lossy().into_owned())
        .collect()
}

/// The `name_command.sh` text for `arguments`.
///
/// It runs `program` (the binary that exported, by its absolute path) where that still exists,
/// else the `raytracer` on PATH; it `cd`s to its own folder first, so it runs from anywhere.
pub(crate) fn command_script(arguments: &[String], program: Option<&Path>) -> String {
    let words: Vec<String> = arguments.iter().map(|a| shell_quote(a)).collect();
    let program = program.map_or_else(
        || "raytracer".to_owned(),
        |path| shell_quote(&path.display().to_string()),
    );
    format!(
        "#!/bin/sh\n# Renders this export's colour and depth images again from its scene file.\n\
         cd \"$(dirname \"$0\")\" || exit 1\n\
         # The raytracer that exported; where it is gone, the one on PATH.\n\
         raytracer={program}\n\
         [ -x \"$raytracer\" ] || raytracer=raytracer\n\
         exec \"$raytracer\" {}\n",
        words.join(" ")
    )
}
