//! The viewer's "writes" feature: exports, the course files and saved scenes. It works out the
//! files a write makes and stages them ([`StagedWrite`]); the platform's seam writes them in the
//! background ([`super::background::Task`]) or downloads them in a page, and the status bar says
//! how it went. A write that would replace files (or needs a folder made) waits for the user's
//! yes ([`super::confirm`]); a file dialog may be open to choose where it goes
//! ([`super::dialogs`]).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::actions::{Action, Write};
use super::background::{Poll, Task};
use super::confirm::{self, PendingReplace};
use super::course_files::{course_files, course_files_stage};
use super::dialogs::{DialogAnswer, DialogKind, PendingDialog};
use super::loaded_scene::LoadedScene;
use super::render_job::{DepthStyle, ViewerJob, prepare_frame};
use super::render_requests::Shown;
use super::scene_loading::OpenScene;
use super::settings::{ExportFormat, ExportSettings, Settings};
use super::status::Status;
use crate::export::{ExportFiles, ExportPlan, stage_export, stage_view_as_scene};
use crate::output::ImageFormat;
use crate::output::atomic::Stage;
use crate::render::{View, check_image_size};
use crate::scene::Scene;

/// Stages a write's files (into the file system's staging or a page's memory); why not, when it
/// cannot.
pub(crate) type Stager = Box<dyn FnOnce(&mut dyn Stage) -> Result<(), String> + Send>;

/// A write ready to start: what the status bar says while it runs and once it is done, and the
/// files it stages (the platform's seam writes them, or downloads them in a page).
pub(crate) struct StagedWrite {
    pub(crate) running: &'static str,
    pub(crate) done: String,
    pub(crate) stage: Stager,
}

/// A write asked for, with what it needs of the viewer's features: the files it writes are
/// worked out, the user asked before any is replaced or a folder made, and its files staged for
/// the seam to write.
pub(crate) struct Writer<'a> {
    pub(crate) writes: &'a mut Writes,
    pub(crate) settings: &'a Settings,
    /// The open scene (a write over its file is noted, so that its reload keeps the view).
    pub(crate) scene: &'a mut OpenScene,
    /// The files being compared, never replaced without being asked.
    pub(crate) compared: [Option<&'a Path>; 2],
    pub(crate) view: View,
    pub(crate) shown: Option<&'a Shown>,
}

impl Writer<'_> {
    /// `write`'s files staged, to write now if they replace nothing; else `None`, the user asked
    /// first ([`confirm::wait_for_yes`]: `missing_folder` is the folder it would make, the seam
    /// says). One that cannot start is refused before a folder it would make is offered: why.
    pub(crate) fn write_or_ask(
        self,
        write: Write,
        missing_folder: Option<PathBuf>,
    ) -> Option<Result<StagedWrite, Status>> {
        let written = self.written();
        let no_folder = missing_folder.is_some();
        let files = match self
            .writes
            .files_of(&write, no_folder, self.settings, &written)
        {
            Ok(files) => files,
            Err(refused) => return Some(Err(refused)),
        };
        let scene = self.scene.loaded.path.as_deref();
        let guarded = confirm::Guarded {
            scene,
            compared: self.compared,
        };
        match confirm::wait_for_yes(write, missing_folder, files, guarded) {
            Ok(write) => Some(self.write_now(write)),
            Err(pending) => {
                self.writes.pending_replace = Some(pending);
                None
            }
        }
    }

    /// `write`'s files staged (the user has agreed to replace what it replaces), or why not.
    pub(crate) fn write_now(self, write: Write) -> Result<StagedWrite, Status> {
        self.scene.note_write(&write);
        self.writes.stage(write, self.settings, &self.written())
    }

    /// What a write started now writes: the scene on screen in the view on screen.
    fn written(&self) -> Written<'_> {
        Written {
            loaded: &self.scene.loaded,
            epoch: self.scene.epoch,
            view: self.view,
            shown: self.shown,
        }
    }
}

/// The scene on screen at its load `epoch` and the view that is written; the frame on screen, if
/// any (reused when it is exactly what is written).
pub(crate) struct Written<'a> {
    pub(crate) loaded: &'a LoadedScene,
    pub(crate) epoch: u64,
    pub(crate) view: View,
    pub(crate) shown: Option<&'a Shown>,
}

/// The writes' state; it starts a write in the background and takes its outcome in.
pub(crate) struct Writes {
    /// A background write (export or saved scene): its outcome message.
    pub(crate) task: Option<Task<Result<String, String>>>,
    /// A write that waits for the user to agree to replace files (or to make a folder).
    pub(crate) pending_replace: Option<PendingReplace<Write>>,
    /// A file dialog that is open.
    pub(crate) dialog: Option<PendingDialog>,
    /// Why no file dialog can be shown here, if none can.
    pub(crate) dialog_note: Option<&'static str>,
    /// The `raytracer` binary export scripts run.
    pub(crate) program: Option<PathBuf>,
}

impl Writes {
    /// Nothing written yet; export scripts run `program`. Knows whether file dialogs can show.
    pub(crate) fn new(program: Option<PathBuf>) -> Self {
        Self {
            task: None,
            pending_replace: None,
            dialog: None,
            dialog_note: super::dialogs::dialog_unavailable_reason(),
            program,
        }
    }

    /// The finished write's message (an error when it failed); `None` while none finished.
    fn poll(&mut self) -> Option<Status> {
        let finished = match self.task.as_ref().map(Task::poll)? {
            Poll::Running => return None,
            Poll::Done(Ok(done)) => Status::info(done),
            Poll::Done(Err(error)) => Status::error(format!("writing failed: {error}")),
            Poll::Lost => Status::error("writing failed: the writing thread stopped"),
        };
        self.task = None;
        Some(finished)
    }
}

impl Writes {
    /// What an export to `base_path` writes and the view it renders; why not, when the chosen
    /// export size is unusable.
    fn export_plan(
        &self,
        base_path: PathBuf,
        settings: &Settings,
        written: &Written,
    ) -> Result<(ExportPlan, View), Status> {
        let export = &settings.export;
        let format = match export.format {
            ExportFormat::Png => ImageFormat::Png,
            ExportFormat::Tga => ImageFormat::Tga,
        };
        let mut view = written.view;
        if !export.displayed_size {
            view.width_px = export.size_px[0];
            view.height_px = export.size_px[1];
            check_image_size(view.width_px, view.height_px)
                .map_err(|error| Status::error(format!("export: {error}")))?;
        }
        let plan = ExportPlan {
            base_path,
            name_in_folder: crate::export::name_in_folder(written.loaded.path.as_deref()),
            format,
            side_by_side: export.side_by_side,
            legend: export.legend,
            colour_map: settings.depth.colour_map,
            extra_depth: export.extra_depth,
            program: self.program.clone(),
        };
        Ok((plan, view))
    }

    /// The files `write` would make: an export's (from its plan; none yet when its folder is
    /// missing, `no_folder`), a saved view's, the course files'. An export at an unusable size is
    /// refused, before anything is offered or created.
    pub(crate) fn files_of(
        &self,
        write: &Write,
        no_folder: bool,
        settings: &Settings,
        written: &Written,
    ) -> Result<Vec<PathBuf>, Status> {
        Ok(match write {
            Write::ExportTo(base) => {
                let (plan, _) = self.export_plan(base.clone(), settings, written)?;
                if no_folder {
                    Vec::new()
                } else {
                    ExportFiles::of(&plan).written_by(&plan)
                }
            }
            Write::SaveViewTo(path) => vec![path.clone()],
            Write::CourseFiles => course_files(&settings.export.path, written.loaded).all(),
        })
    }

    /// Stages `write` of `written` with `settings`; why not, when it cannot start.
    pub(crate) fn stage(
        &self,
        write: Write,
        settings: &Settings,
        written: &Written,
    ) -> Result<StagedWrite, Status> {
        match write {
            Write::ExportTo(base) => self.export(base, settings, written),
            Write::CourseFiles => Ok(self.course_files(settings, written)),
            Write::SaveViewTo(path) => Ok(save_view(&written.loaded.scene, written.view, path)),
        }
    }

    /// Exports `written` to `base_path` (see [`crate::export::ExportPaths`]) at `settings`'
    /// quality; why not, when it cannot start.
    fn export(
        &self,
        base_path: PathBuf,
        settings: &Settings,
        written: &Written,
    ) -> Result<StagedWrite, Status> {
        let (plan, view) = self.export_plan(base_path, settings, written)?;
        let base_path = &plan.base_path;
        if crate::export::names_a_folder(base_path) && !base_path.is_dir() {
            return Err(Status::error(format!(
                "export: the folder {} does not exist",
                base_path.display()
            )));
        }
        let quality = settings.quality;
        // Reuse the frame on screen when it is exactly what would be exported.
        let ready = written
            .shown
            .filter(|s| s.view == view && s.scene_epoch == written.epoch && s.quality == quality)
            .map(|s| Arc::clone(&s.frame));
        let job = ViewerJob {
            scene: Arc::clone(&written.loaded.scene),
            view,
            scene_epoch: written.epoch,
            quality,
            depth_style: DepthStyle::default(),
        };
        let stage = move |set: &mut dyn Stage| {
            let frame = match ready {
                Some(frame) => frame,
                None => prepare_frame(&job).map_err(|e| e.to_string())?.frame,
            };
            stage_export(set, &job.scene, &view, &quality, &frame, &plan).map_err(|e| e.to_string())
        };
        Ok(StagedWrite {
            running: "exporting…",
            done: "exported".to_owned(),
            stage: Box::new(stage),
        })
    }

    /// The course files of `written` into the export folder of `settings`: over the course's
    /// range for a course scene, else over the range in use, which the message then names.
    fn course_files(&self, settings: &Settings, written: &Written) -> StagedWrite {
        let (range, done) = if let Some(range) = written.loaded.course_range {
            let name = written
                .loaded
                .path
                .as_deref()
                .and_then(std::path::Path::file_name)
                .map(|name| name.to_string_lossy().into_owned())
                .unwrap_or_default();
            let done = format!(
                "wrote the course's files for {name} (its line's -size 200 200 -depth {} {}):",
                range.min_t, range.max_t
            );
            (range, done)
        } else {
            let range = written.view.depth_range;
            let done = format!(
                "wrote course-style files at the course's size with the depth range in use \
                 (-size 200 200 -depth {} {}; not a course scene, so no course line gives its \
                 range):",
                range.min_t, range.max_t
            );
            (range, done)
        };
        let stage = course_files_stage(
            written.loaded,
            &settings.export.path,
            range,
            self.program.clone(),
        );
        StagedWrite {
            running: "writing the course files…",
            done,
            stage: Box::new(stage),
        }
    }

    /// Takes a finished write in (its message into `status`; a failed one wrote nothing, so the
    /// save over the open scene, `saving_over`, ends) and a file dialog's answer: the action it
    /// asks for (see [`Self::take_dialog`]).
    pub(crate) fn take_in(
        &mut self,
        export: &mut ExportSettings,
        compare_path: &mut String,
        saving_over: &mut bool,
        status: &mut Option<Status>,
    ) -> Option<Action> {
        if let Some(finished) = self.poll() {
            *saving_over &= !finished.is_error();
            *status = Some(finished);
        }
        self.take_dialog(export, compare_path)
    }

    /// Takes a file dialog's answer: the action it asks for (the path it chose also fills the
    /// field it belongs to: the export's, the saved scene's, the compared image's).
    fn take_dialog(
        &mut self,
        export: &mut ExportSettings,
        compare_path: &mut String,
    ) -> Option<Action> {
        let (kind, path) = match self.dialog.as_ref()?.poll() {
            DialogAnswer::Waiting => return None,
            DialogAnswer::Cancelled(_) => {
                self.dialog = None;
                return None;
            }
            DialogAnswer::Chosen(kind, path) => (kind, path),
        };
        self.dialog = None;
        let typed = path.display().to_string();
        Some(match kind {
            DialogKind::Open => Action::Open(path),
            DialogKind::Export => {
                export.path = typed;
                Action::Write(Write::ExportTo(path))
            }
            DialogKind::SaveScene => {
                export.scene_path = typed;
                Action::Write(Write::SaveViewTo(path))
            }
            DialogKind::CompareImage(kind) => {
                *compare_path = typed;
                Action::CompareImage(path, kind)
            }
        })
    }
}

/// "Save view as scene": the scene with the `view`'s camera, written to `path`.
fn save_view(scene: &Arc<Scene>, view: View, path: PathBuf) -> StagedWrite {
    let scene = Arc::clone(scene);
    StagedWrite {
        running: "saving the view…",
        done: "saved the view as".to_owned(),
        stage: Box::new(move |set: &mut dyn Stage| {
            stage_view_as_scene(set, &scene, &view, &path).map_err(|e| e.to_string())
        }),
    }
}

/// Makes the `folder` a write goes into (the user agreed to); why not, when it cannot.
pub(crate) fn create_folder(folder: &Path) -> Result<(), Status> {
    std::fs::create_dir_all(folder).map_err(|error| {
        Status::error(format!(
            "export: cannot create the folder {}: {error}",
            folder.display()
        ))
    })
}
