//! Asking before a write replaces anything: an export or "save view as scene" whose files exist
//! waits for a yes in a modal window that lists them; the open scene file gets a warning of its
//! own. An export into a folder that does not exist offers to create it. Nothing is written (nor
//! created) on "Cancel", on Escape or a click outside the window.

use std::path::PathBuf;

use egui::RichText;

use super::ViewerApp;
use super::actions::Action;
use super::course_files::course_files;
use crate::export::{ExportFiles, ExportPlan};
use crate::platform::files::same_file;

/// A write that waits for the user's yes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PendingReplace {
    /// The export or save to carry out on yes.
    pub(crate) action: Action,
    /// The files it would replace.
    pub(crate) existing: Vec<PathBuf>,
    /// One of them is the scene file on screen.
    pub(crate) open_scene: bool,
    /// The folder the write goes into, which does not exist yet: yes creates it first.
    pub(crate) missing_folder: Option<PathBuf>,
}

/// Label of the button that replaces the files (tests find it by this).
pub(crate) const REPLACE_LABEL: &str = "Replace";

/// Label of the button that creates the missing folder and exports into it.
pub(crate) const CREATE_FOLDER_LABEL: &str = "Create the folder and export";

impl ViewerApp {
    /// The files a write action would make.
    fn files_of(&self, action: &Action) -> Vec<PathBuf> {
        match action {
            Action::ExportTo(base) => match self.export_plan(base.clone()) {
                Some((plan, _)) => files_of_plan(&plan),
                None => Vec::new(),
            },
            Action::SaveViewTo(path) => vec![path.clone()],
            Action::ExportCourseFiles => {
                course_files(&self.settings.export.path, &self.scene.loaded).all()
            }
            _ => Vec::new(),
        }
    }

    /// Carries out a write action now if it replaces nothing; otherwise asks first.
    pub(super) fn write_or_ask(&mut self, action: Action) {
        // An export that cannot start is refused before anything is offered or created (the
        // typed size is kept valid by its field; this guards the state set another way).
        if let Action::ExportTo(_) = &action
            && let Some(problem) = self.export_size_problem()
        {
            self.status = Some(super::status::Status::error(problem));
            return;
        }
        // A folder the export would create is asked for first (a browser page has none).
        if let Some(folder) = self.missing_export_folder(&action) {
            self.writes.pending_replace = Some(PendingReplace {
                action,
                existing: Vec::new(),
                open_scene: false,
                missing_folder: Some(folder),
            });
            return;
        }
        let existing: Vec<PathBuf> = self
            .files_of(&action)
            .into_iter()
            .filter(|path| path.exists())
            .collect();
        if existing.is_empty() {
            self.write_now(action);
            return;
        }
        let open_scene = self
            .scene
            .loaded
            .path
            .as_deref()
            .is_some_and(|scene| existing.iter().any(|path| same_file(path, scene)));
        self.writes.pending_replace = Some(PendingReplace {
            action,
            existing,
            open_scene,
            missing_folder: None,
        });
    }

    /// The modal asking whether to replace files ([`PendingReplace::ui`]); on yes, the write goes
    /// ahead (into a folder created first when it was missing).
    pub(super) fn confirm_ui(&mut self, ctx: &egui::Context) {
        let answer = self.writes.pending_replace.as_ref().and_then(|p| p.ui(ctx));
        match answer {
            Some(true) => match self.writes.pending_replace.take() {
                Some(PendingReplace {
                    action,
                    missing_folder: Some(folder),
                    ..
                }) => match std::fs::create_dir_all(&folder) {
                    // Into the new folder, asking again should anything be there meanwhile.
                    Ok(()) => self.write_or_ask(action),
                    Err(error) => {
                        self.status = Some(super::status::Status::error(format!(
                            "export: cannot create the folder {}: {error}",
                            folder.display()
                        )));
                    }
                },
                Some(pending) => self.write_now(pending.action),
                None => {}
            },
            Some(false) => self.writes.pending_replace = None,
            None => {}
        }
    }
}

impl PendingReplace {
    /// The modal window asking for the yes: `Some(true)` on yes, `Some(false)` on "Cancel",
    /// Escape or a click outside, `None` while it waits.
    pub(crate) fn ui(&self, ctx: &egui::Context) -> Option<bool> {
        let mut answer = None;
        let modal = egui::Modal::new(egui::Id::unique("replace files")).show(ctx, |ui| {
            ui.set_max_width(520.0);
            if let Some(folder) = &self.missing_folder {
                ui.heading("Create this folder?");
                ui.label("The export goes into a folder that does not exist yet:");
                ui.label(RichText::new(folder.display().to_string()).monospace());
                answer = yes_or_cancel(ui, CREATE_FOLDER_LABEL);
                return;
            }
            let count = self.existing.len();
            let title = match count {
                1 => "Replace this file?".to_owned(),
                _ => format!("Replace these {count} files?"),
            };
            ui.heading(title);
            if self.open_scene {
                ui.label(
                    RichText::new(
                        "One of them is the scene file on screen: its text will be replaced \
                         by the scene with the current camera.",
                    )
                    .color(ui.visuals().warn_fg_color),
                );
            }
            for path in &self.existing {
                ui.label(RichText::new(path.display().to_string()).monospace());
            }
            answer = yes_or_cancel(ui, REPLACE_LABEL);
        });
        if modal.should_close() && answer.is_none() {
            answer = Some(false);
        }
        answer
    }
}

/// A row of the yes button (`yes_label`) and "Cancel": `Some(true)` or `Some(false)` when one
/// is clicked.
fn yes_or_cancel(ui: &mut egui::Ui, yes_label: &str) -> Option<bool> {
    ui.horizontal(|ui| {
        let yes = ui.button(yes_label).clicked();
        let cancel = ui.button("Cancel").clicked();
        (yes || cancel).then_some(yes)
    })
    .inner
}

/// The files an export plan writes.
fn files_of_plan(plan: &ExportPlan) -> Vec<PathBuf> {
    ExportFiles::of(plan).written_by(plan)
}
