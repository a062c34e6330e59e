//! What the user can ask the viewer for, as [`Action`]s (the toolbar, the panels and the keyboard
//! report them; [`ViewerApp::apply`] carries them out), and the background writes (exports, the
//! view saved as a scene) and file dialogs they start.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::confirm::{self, Answer};
use super::course_files::{course_files, course_files_stage};
use super::dialogs::{DialogAnswer, DialogKind};
use super::render_job::{DepthStyle, ViewerJob, prepare_frame};
use super::settings::ExportFormat;
use super::status::Status;
use super::viewer::ViewerApp;
use crate::export::{ExportFiles, ExportPlan};
use crate::export::{stage_export, stage_view_as_scene};
use crate::output::ImageFormat;
use crate::platform::files::same_file;
use crate::render::{View, check_image_size};

/// Something the user asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Action {
    /// Show a file dialog.
    OpenDialog(DialogKind),
    /// Open the scene file at this path.
    Open(PathBuf),
    /// Open the bundled scene of this index (`scene::bundled::BUNDLED_SCENES`).
    OpenBundled(usize),
    /// Read the open scene file again.
    Reload,
    /// Fit centre and size to the scene.
    FrameAll,
    /// Back to the file's camera (the depth range stays).
    ResetView,
    /// Back to the depth range the file's view started with.
    ResetDepth,
    /// Fit the depth range to the visible t.
    AutoRange,
    /// Set the depth range (the one read back from their depth image).
    UseDepthRange(crate::render::depth_map::DepthRange),
    /// Back to the view before the last change.
    Undo,
    /// Forward again after an undo.
    Redo,
    /// Name the current view (for the open scene file).
    NameView(String),
    /// Go to the named view at this index.
    GoToView(usize),
    /// Forget the named view at this index.
    ForgetView(usize),
    /// Show or hide the shortcuts overlay.
    ToggleHelp,
    /// Magnifier back to the whole image.
    ResetMagnifier,
    /// Export the current view to this base path.
    ExportTo(PathBuf),
    /// Write the course's files (200×200 TGA pair and command line) into the export folder.
    ExportCourseFiles,
    /// Write the scene with the current camera to this path.
    SaveViewTo(PathBuf),
    /// Move the view or the magnifier.
    Navigate(super::viewing::Navigation),
    /// Pin the point seen at this image position (pixels, y up) of the frame on screen.
    Pin(glam::DVec2),
    /// Release the pinned probe.
    Unpin,
    /// Trace the pinned pixel into the trace window.
    Trace,
    /// Compare the image at this path with the exact render.
    CompareImage(PathBuf, crate::app::compare::ImageKind),
    /// Measure the chosen quality against the exact render on the current view.
    CompareQuality,
    /// What the compared image shows.
    CompareShow(crate::app::compare::CompareShow),
    /// The A/B flip: the render and their image in turn.
    CompareFlip,
    /// The difference view on and off.
    CompareDifference,
    /// Close the comparison.
    CompareClose,
}

impl ViewerApp {
    /// Carries out a write action (the user has agreed to replace what it replaces).
    pub(super) fn write_now(&mut self, action: Action) {
        match action {
            Action::ExportTo(path) => self.export_to(path),
            Action::SaveViewTo(path) => self.save_view_to(path),
            Action::ExportCourseFiles => self.export_course_files(),
            other => self.apply(other),
        }
    }

    /// Carries out a write action now if it replaces nothing; otherwise asks first
    /// ([`confirm::wait_for_yes`]).
    pub(super) fn write_or_ask(&mut self, action: Action) {
        // An export that cannot start is refused before anything is offered or created (the
        // typed size is kept valid by its field; this guards the state set another way).
        if let Action::ExportTo(_) = &action
            && let Some(problem) = self.export_size_problem()
        {
            self.status = Some(Status::error(problem));
            return;
        }
        // A folder the export would create is asked for first (a browser page has none).
        let missing_folder = self.missing_export_folder(&action);
        // The files the write would make: an export's (from its plan), a saved view's, the
        // course files'.
        let files = match &action {
            Action::ExportTo(base) if missing_folder.is_none() => self
                .export_plan(base.clone())
                .map(|(plan, _)| ExportFiles::of(&plan).written_by(&plan))
                .unwrap_or_default(),
            Action::SaveViewTo(path) => vec![path.clone()],
            Action::ExportCourseFiles => {
                course_files(&self.settings.export.path, &self.scene.loaded).all()
            }
            _ => Vec::new(),
        };
        let scene = self.scene.loaded.path.as_deref();
        match confirm::wait_for_yes(action, missing_folder, files, scene) {
            Ok(action) => self.write_now(action),
            Err(pending) => self.writes.pending_replace = Some(pending),
        }
    }

    /// The modal asking whether to replace files; on yes, the write goes ahead (into a folder
    /// created first when it was missing).
    pub(super) fn confirm_ui(&mut self, ctx: &egui::Context) {
        match confirm::answer(&mut self.writes.pending_replace, ctx) {
            Some(Answer::Write(action)) => self.write_now(action),
            // Into the new folder, asking again should anything be there meanwhile.
            Some(Answer::CreateFolder(folder, action)) => match std::fs::create_dir_all(&folder) {
                Ok(()) => self.write_or_ask(action),
                Err(error) => {
                    self.status = Some(Status::error(format!(
                        "export: cannot create the folder {}: {error}",
                        folder.display()
                    )));
                }
            },
            None => {}
        }
    }

    /// What an export to `base_path` writes and the view it renders; `None` when the export
    /// size is unusable.
    pub(super) fn export_plan(&self, base_path: PathBuf) -> Option<(ExportPlan, View)> {
        let export = &self.settings.export;
        let format = match export.format {
            ExportFormat::Png => ImageFormat::Png,
            ExportFormat::Tga => ImageFormat::Tga,
        };
        let mut view = self.viewing.view;
        if !export.displayed_size {
            view.width_px = export.size_px[0];
            view.height_px = export.size_px[1];
            check_image_size(view.width_px, view.height_px).ok()?;
        }
        let plan = ExportPlan {
            base_path,
            name_in_folder: crate::export::name_in_folder(self.scene.loaded.path.as_deref()),
            format,
            side_by_side: export.side_by_side,
            legend: export.legend,
            colour_map: self.settings.depth.colour_map,
            extra_depth: export.extra_depth,
            program: self.writes.program.clone(),
        };
        Some((plan, view))
    }

    /// Why an export at the chosen size cannot start, if it cannot (asked before anything is
    /// offered or created).
    pub(super) fn export_size_problem(&self) -> Option<String> {
        let export = &self.settings.export;
        if !export.displayed_size
            && let Err(error) = check_image_size(export.size_px[0], export.size_px[1])
        {
            return Some(format!("export: {error}"));
        }
        None
    }

    /// Why an export to `base_path` cannot start, if it cannot.
    fn export_problem(&self, base_path: &Path) -> Option<String> {
        if let Some(problem) = self.export_size_problem() {
            return Some(problem);
        }
        if crate::export::names_a_folder(base_path) && !base_path.is_dir() {
            return Some(format!(
                "export: the folder {} does not exist",
                base_path.display()
            ));
        }
        None
    }

    /// Exports the current view to `base_path` (see [`crate::export::ExportPaths`]) on a
    /// background thread; the outcome appears in the status bar.
    fn export_to(&mut self, base_path: PathBuf) {
        if let Some(problem) = self.export_problem(&base_path) {
            self.status = Some(Status::error(problem));
            return;
        }
        let Some((plan, view)) = self.export_plan(base_path) else {
            return;
        };
        let quality = self.settings.quality;
        // Reuse the frame on screen when it is exactly what would be exported.
        let ready = self
            .frames
            .shown
            .as_ref()
            .filter(|s| s.view == view && s.scene_epoch == self.scene.epoch && s.quality == quality)
            .map(|s| Arc::clone(&s.frame));
        let job = ViewerJob {
            scene: Arc::clone(&self.scene.loaded.scene),
            view,
            scene_epoch: self.scene.epoch,
            quality,
            depth_style: DepthStyle::default(),
        };
        self.write_files("exporting…", "exported", move |set| {
            let frame = match ready {
                Some(frame) => frame,
                None => prepare_frame(&job).map_err(|e| e.to_string())?.frame,
            };
            stage_export(set, &job.scene, &view, &quality, &frame, &plan).map_err(|e| e.to_string())
        });
    }

    /// Writes the course files (the user has agreed to replace what they replace): downloaded in
    /// a page, written in the background on the desktop.
    fn export_course_files(&mut self) {
        let stage = course_files_stage(
            &self.scene.loaded,
            &self.settings.export.path,
            self.viewing.view.depth_range,
            self.writes.program.clone(),
        );
        self.write_files("writing the course files…", "wrote the course files", stage);
    }

    /// "Save view as scene": writes the scene with the current camera to `path` (downloaded in a
    /// page, written in the background on the desktop; the outcome appears in the status bar).
    fn save_view_to(&mut self, path: PathBuf) {
        // Saving over the open scene reloads it; the message should stay the save's.
        self.scene.saving_over = self
            .scene
            .loaded
            .path
            .as_deref()
            .is_some_and(|open| same_file(open, &path));
        let scene = Arc::clone(&self.scene.loaded.scene);
        let view = self.viewing.view;
        self.write_files("saving the view…", "saved the view as", move |set| {
            stage_view_as_scene(set, &scene, &view, &path).map_err(|e| e.to_string())
        });
    }

    /// Takes a dialog's answer and a finished write.
    pub(super) fn poll_background(&mut self) {
        if let Some(dialog) = &self.writes.dialog {
            match dialog.poll() {
                DialogAnswer::Waiting => {}
                DialogAnswer::Cancelled(_) => self.writes.dialog = None,
                DialogAnswer::Chosen(kind, path) => {
                    self.writes.dialog = None;
                    match kind {
                        DialogKind::Open => self.open(&path),
                        DialogKind::Export => {
                            self.settings.export.path = path.display().to_string();
                            self.write_or_ask(Action::ExportTo(path));
                        }
                        DialogKind::SaveScene => {
                            self.settings.export.scene_path = path.display().to_string();
                            self.write_or_ask(Action::SaveViewTo(path));
                        }
                        DialogKind::CompareImage(kind) => {
                            self.compare.path_text = path.display().to_string();
                            self.apply(Action::CompareImage(path, kind));
                        }
                    }
                }
            }
        }
        let Some(finished) = self.writes.poll() else {
            return;
        };
        if finished.is_error() {
            // Nothing was written, so no reload of our own follows.
            self.scene.saving_over = false;
        }
        self.status = Some(finished);
    }
}
