//! The desktop's seam ([`Desktop`]), which the coordinator holds and calls (the seam's methods are
//! listed in `app/seam.rs`): the desktop's side of what a browser page does its own way
//! (`app/web.rs`). A path opens the file; the file dialogs are the system's (or, where none can
//! be shown, the typed paths); the files the viewer writes go into the file system, all or
//! nothing, on a thread of their own. The window itself is opened by `app/start/window.rs`.

use std::path::{Path, PathBuf};

use super::actions::{Action, Write};
use super::asked::Asked;
use super::background::Task;
use super::compare::{ImageKind, dropped_image_kind};
use super::dialogs::{DialogKind, PendingDialog};
use super::settings::ExportSettings;
use super::status::Status;
use super::writes::{Stager, Writes};
use crate::output::atomic::FileSet;

/// The desktop's seam: files by their paths, the system's file dialogs, writes into the file
/// system on a thread of their own, a termination signal closing the window.
#[derive(Debug, Default)]
pub(crate) struct Desktop;

impl Desktop {
    /// The scene to open first: the one the command line names, or else the one open when the
    /// viewer last closed.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn first_scene(
        &self,
        input: Option<PathBuf>,
        last_scene: Option<&Path>,
    ) -> Option<PathBuf> {
        input.or_else(|| last_scene.map(Path::to_path_buf))
    }

    /// The window loads the scene it was started on in the background and shows the default
    /// scene meanwhile: nothing to wait for.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn first_scene_on_its_way(&self) -> bool {
        false
    }

    /// The folder an export or the course files would have to create (the course files go to
    /// `typed_folder`, the side panel's export path), which is asked for before it is.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn missing_export_folder(
        &self,
        write: &Write,
        typed_folder: &str,
    ) -> Option<PathBuf> {
        let base = match write {
            Write::ExportTo(base) => base.clone(),
            Write::CourseFiles => PathBuf::from(typed_folder.trim()),
            Write::SaveViewTo(_) => return None,
        };
        crate::export::export_folder(&base).filter(|folder| !folder.is_dir())
    }

    /// A file dropped on the window, by its path: an image (`.png`, `.tga`) is compared, a
    /// depth image where its file name says so, else as `chosen` (its content decides unless
    /// that was clicked); anything else is opened as a scene.
    #[expect(
        clippy::unused_self,
        clippy::needless_pass_by_value,
        reason = "a method, as each seam's are; the page's side keeps the handle to read the \
                  file later"
    )]
    pub(crate) fn dropped(
        &mut self,
        file: egui::DroppedFileHandle,
        chosen: ImageKind,
    ) -> Option<Asked> {
        let path = file.path();
        if path.as_os_str().is_empty() {
            return None;
        }
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        Some(match dropped_image_kind(&name) {
            Some(ImageKind::Depth) => {
                Asked::Apply(Action::CompareImage(path.to_path_buf(), ImageKind::Depth))
            }
            Some(ImageKind::Colour) => {
                Asked::Apply(Action::CompareImage(path.to_path_buf(), chosen))
            }
            None => Asked::Open(path.to_path_buf()),
        })
    }

    /// Names the window `title`.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn set_title(&self, ctx: &egui::Context, title: &str) {
        ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
    }

    /// What comes in between frames on the desktop: a termination signal closes the window
    /// (eframe saves the settings on the way out). Files are opened by their paths, so nothing
    /// comes in otherwise.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn poll(&mut self, ctx: &egui::Context, _compare_closes: u64) -> Vec<Asked> {
        if crate::platform::process::stop_requested().is_some() {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        Vec::new()
    }

    /// Opens the scene file at `path` (typed in the side panel): by its path.
    #[expect(
        clippy::unused_self,
        clippy::unnecessary_wraps,
        reason = "a method, as each seam's are: the caller names no seam; the page's asks nothing"
    )]
    pub(crate) fn open_path(&mut self, path: &Path) -> Option<Asked> {
        Some(Asked::Open(path.to_path_buf()))
    }

    /// Shows a native file dialog (its answer comes back through `writes`), or says why none
    /// can be shown.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn open_dialog(
        &mut self,
        kind: DialogKind,
        writes: &mut Writes,
        export: &ExportSettings,
        ctx: &egui::Context,
    ) -> Option<Asked> {
        if let Some(reason) = writes.dialog_note {
            return Some(without_dialog(kind, export, reason));
        }
        if writes.dialog.is_some() {
            return None;
        }
        let suggested = match kind {
            DialogKind::SaveScene => &export.scene_path,
            _ => &export.path,
        };
        match spawn_dialog(kind, ctx, suggested) {
            Ok(dialog) => {
                writes.dialog = Some(dialog);
                None
            }
            Err(error) => Some(Asked::Say(Status::error(format!(
                "cannot open a file dialog: {error}"
            )))),
        }
    }

    /// Writes the files `stage` stages, all or nothing, in the background (`writes` holds the
    /// write in flight): what the status bar says, `running` meanwhile, then `done` and the full
    /// path of each file written (or why none was).
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn write_files(
        &mut self,
        writes: &mut Writes,
        ctx: &egui::Context,
        (running, done): (&str, String),
        stage: Stager,
    ) -> Status {
        let write = move || {
            let mut set = FileSet::new();
            stage(&mut set)?;
            let written = set.commit().map_err(|e| e.to_string())?;
            Ok(format!("{done} {}", full_names(&written)))
        };
        start_write(writes, running, write, ctx)
    }
}

/// Where no file dialog can be shown: export and save go to the side panel's typed paths (the
/// section says so under them, and replacing a file is asked first); open and compare say that
/// no dialog is available and do nothing else (reopening the typed scene would reset the view
/// and its history).
fn without_dialog(kind: DialogKind, export: &ExportSettings, reason: &'static str) -> Asked {
    let typed = |text: &str| (!text.trim().is_empty()).then(|| PathBuf::from(text.trim()));
    let write = match kind {
        DialogKind::Export => typed(&export.path).map(Write::ExportTo),
        DialogKind::SaveScene => typed(&export.scene_path).map(Write::SaveViewTo),
        DialogKind::Open | DialogKind::CompareImage(_) => None,
    };
    match write {
        Some(write) => Asked::Apply(Action::Write(write)),
        None => Asked::Say(Status::error(reason)),
    }
}

/// The full path of each file written, so that a message says where they are.
fn full_names(written: &[PathBuf]) -> String {
    let names: Vec<String> = written
        .iter()
        .map(|p| std::fs::canonicalize(p).unwrap_or_else(|_| p.clone()))
        .map(|p| p.display().to_string())
        .collect();
    names.join(", ")
}

/// Starts `write` in the background with [`Writes`] (`ctx` repaints when it is done), unless a write is still
/// running: what the status bar says meanwhile.
fn start_write(
    writes: &mut Writes,
    running: &str,
    write: impl FnOnce() -> Result<String, String> + Send + 'static,
    ctx: &egui::Context,
) -> Status {
    if writes.task.is_some() {
        return Status::error("wait: a file is still being written");
    }
    match Task::spawn("export", ctx, move |_| write()) {
        Ok(task) => {
            writes.task = Some(task);
            Status::info(running)
        }
        Err(error) => Status::error(format!("cannot start writing: {error}")),
    }
}

/// Opens a native dialog (rfd) on its own thread.
fn spawn_dialog(
    kind: DialogKind,
    ctx: &egui::Context,
    suggested_name: &str,
) -> std::io::Result<PendingDialog> {
    let suggested_name = suggested_name.to_owned();
    let task = Task::spawn("file-dialog", ctx, move |_| {
        let dialog = rfd::FileDialog::new();
        match kind {
            DialogKind::Open => dialog
                .add_filter("6.837 scene", &["txt"])
                .add_filter("any file", &["*"])
                .set_title("Open scene")
                .pick_file(),
            DialogKind::Export => dialog
                .add_filter("PNG", &["png"])
                .add_filter("TGA", &["tga"])
                .set_title("Export images")
                .set_file_name(suggested_name)
                .save_file(),
            DialogKind::SaveScene => dialog
                .add_filter("6.837 scene", &["txt"])
                .set_title("Save view as scene")
                .set_file_name(suggested_name)
                .save_file(),
            DialogKind::CompareImage(_) => dialog
                .add_filter("image", &["tga", "png"])
                .add_filter("any file", &["*"])
                .set_title("Open an image to compare")
                .pick_file(),
        }
    })?;
    Ok(PendingDialog { kind, task })
}
