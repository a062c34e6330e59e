//! Asking before a write replaces anything: an export or "save view as scene" whose files exist
//! waits for a yes in a modal window that lists them; the open scene file gets a warning of its
//! own. An export into a folder that does not exist offers to create it. Nothing is written (nor
//! created) on "Cancel", on Escape or a click outside the window.

use std::path::{Path, PathBuf};

use egui::RichText;

use crate::platform::files::same_file;

/// A write that waits for the user's yes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PendingReplace<A> {
    /// The export or save to carry out on yes.
    pub(crate) action: A,
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

/// What a write must wait for, if anything: the folder it would create (`missing_folder`), else
/// the files among `files` it would replace. `scene_on_screen` gets a warning of its own. `Ok`
/// hands the action back to be written now.
pub(crate) fn wait_for_yes<A>(
    action: A,
    missing_folder: Option<PathBuf>,
    files: Vec<PathBuf>,
    scene_on_screen: Option<&Path>,
) -> Result<A, PendingReplace<A>> {
    if let Some(folder) = missing_folder {
        return Err(PendingReplace {
            action,
            existing: Vec::new(),
            open_scene: false,
            missing_folder: Some(folder),
        });
    }
    let existing: Vec<PathBuf> = files.into_iter().filter(|path| path.exists()).collect();
    if existing.is_empty() {
        return Ok(action);
    }
    let open_scene =
        scene_on_screen.is_some_and(|scene| existing.iter().any(|path| same_file(path, scene)));
    Err(PendingReplace {
        action,
        existing,
        open_scene,
        missing_folder: None,
    })
}

/// The user's answer to the modal.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Answer<A> {
    /// Write (the files it replaces were shown).
    Write(A),
    /// Create the folder, then ask again about writing into it.
    CreateFolder(PathBuf, A),
}

/// Shows the modal of the write waiting in `pending` ([`PendingReplace::ui`]): the write to carry
/// out on yes; on "Cancel" the write is dropped.
pub(crate) fn answer<A>(
    pending: &mut Option<PendingReplace<A>>,
    ctx: &egui::Context,
) -> Option<Answer<A>> {
    let yes = pending.as_ref().and_then(|p| p.ui(ctx))?;
    let answered = pending.take()?;
    if !yes {
        return None;
    }
    Some(match answered.missing_folder {
        Some(folder) => Answer::CreateFolder(folder, answered.action),
        None => Answer::Write(answered.action),
    })
}

impl<A> PendingReplace<A> {
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
