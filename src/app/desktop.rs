//! The desktop's side of what a browser page does its own way ([`super::web`]): a path opens the
//! file; the file dialogs are the system's (or, where none can be shown, the typed paths); the
//! files the viewer writes go into the file system, all or nothing, on a thread of their own;
//! and the window itself ([`window`]).

pub mod window;

use std::path::PathBuf;

use std::path::Path;

use super::actions::{Action, Write};
use super::background::Task;
use super::compare::{ImageKind, dropped_image_kind};
use super::dialogs::{DialogKind, PendingDialog};
use super::status::Status;
use super::viewer::ViewerApp;
use super::writes::{Stager, Writes};
use crate::output::atomic::FileSet;

impl ViewerApp {
    /// Opens the scene the command line names, or else the scene open when the viewer last
    /// closed.
    pub(super) fn open_first(&mut self, input: Option<PathBuf>) {
        if let Some(path) = input.or_else(|| self.settings.last_scene.clone()) {
            self.open(&path);
        }
    }

    /// The window loads the scene it was started on in the background and shows the default
    /// scene meanwhile: nothing to wait for.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(super) fn first_scene_on_its_way(&self) -> bool {
        false
    }

    /// The folder an export or the course files would have to create, which is asked for before
    /// it is.
    pub(super) fn missing_export_folder(&self, write: &Write) -> Option<PathBuf> {
        let base = match write {
            Write::ExportTo(base) => base.clone(),
            Write::CourseFiles => PathBuf::from(self.settings.export.path.trim()),
            Write::SaveViewTo(_) => return None,
        };
        crate::export::export_folder(&base).filter(|folder| !folder.is_dir())
    }

    /// Opens a file dropped on the window, by its path.
    #[expect(
        clippy::needless_pass_by_value,
        reason = "the page's side keeps the handle to read the file later"
    )]
    pub(super) fn open_dropped(&mut self, file: egui::DroppedFileHandle) {
        let path = file.path();
        if path.as_os_str().is_empty() {
            return;
        }
        // An image (`.png`, `.tga`) is compared: a depth image where its file name says so, else
        // as the kind chosen (its content decides unless that was clicked); anything else is
        // opened as a scene.
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        match dropped_image_kind(&name) {
            Some(ImageKind::Depth) => {
                self.apply(Action::CompareImage(path.to_path_buf(), ImageKind::Depth));
            }
            Some(ImageKind::Colour) => {
                let kind = self.compare.kind;
                self.apply(Action::CompareImage(path.to_path_buf(), kind));
            }
            None => self.open(path),
        }
    }

    /// Names the window `title`.
    pub(super) fn set_title(&self, title: &str) {
        self.ctx
            .send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
    }

    /// What comes in between frames on the desktop: a termination signal closes the window
    /// (eframe saves the settings on the way out). Files are opened by their paths.
    pub(super) fn poll_platform(&mut self) {
        if crate::platform::process::stop_requested().is_some() {
            self.ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }

    /// Opens the scene file at `path` (typed in the side panel or given on the command line).
    pub(super) fn open_path(&mut self, path: &Path) {
        self.open(path);
    }

    /// Shows a native file dialog, or says why none can be shown.
    pub(super) fn open_dialog(&mut self, kind: DialogKind) {
        if let Some(reason) = self.writes.dialog_note {
            self.without_dialog(kind, reason);
            return;
        }
        if self.writes.dialog.is_some() {
            return;
        }
        let suggested = match kind {
            DialogKind::SaveScene => &self.settings.export.scene_path,
            _ => &self.settings.export.path,
        };
        match spawn_dialog(kind, &self.ctx, suggested) {
            Ok(dialog) => self.writes.dialog = Some(dialog),
            Err(error) => {
                self.status = Some(Status::error(format!("cannot open a file dialog: {error}")));
            }
        }
    }

    /// Where no file dialog can be shown: export and save go to the side panel's typed paths (the
    /// section says so under them, and replacing a file is asked first); open and compare say
    /// that no dialog is available and do nothing else (reopening the typed scene would reset
    /// the view and its history).
    fn without_dialog(&mut self, kind: DialogKind, reason: &'static str) {
        let export = &self.settings.export;
        let typed = |text: &str| (!text.trim().is_empty()).then(|| PathBuf::from(text.trim()));
        let action = match kind {
            DialogKind::Export => typed(&export.path).map(Write::ExportTo),
            DialogKind::SaveScene => typed(&export.scene_path).map(Write::SaveViewTo),
            DialogKind::Open | DialogKind::CompareImage(_) => None,
        };
        match action {
            Some(write) => self.apply(Action::Write(write)),
            None => self.status = Some(Status::error(reason)),
        }
    }

    /// Writes the files `stage` stages, all or nothing, in the background: the status bar says
    /// `running` meanwhile, then `done` and the full path of each file written (or why none was).
    pub(super) fn write_files(&mut self, running: &str, done: String, stage: Stager) {
        let write = move || {
            let mut set = FileSet::new();
            stage(&mut set)?;
            let written = set.commit().map_err(|e| e.to_string())?;
            Ok(format!("{done} {}", full_names(&written)))
        };
        self.status = Some(start_write(&mut self.writes, running, write, &self.ctx));
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
