//! Asking before a write replaces anything: an export, "save view as scene" or the course files
//! whose files exist wait for a yes in a modal window that names their folder and lists them;
//! the open scene file and the image being compared (their program's output) get a warning of
//! their own. "Cancel" has the focus, so Enter keeps the files. A write into a folder that does
//! not exist offers to create it. Nothing is written (nor created) on "Cancel", on Escape or a
//! click outside the window.

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
    /// One of them is the image being compared: their program's output.
    pub(crate) compared: bool,
    /// The folder the write goes into, which does not exist yet: yes creates it first.
    pub(crate) missing_folder: Option<PathBuf>,
}

/// Label of the button that replaces the files (tests find it by this).
pub(crate) const REPLACE_LABEL: &str = "Replace";

/// Label of the button that creates the missing folder and exports into it.
pub(crate) const CREATE_FOLDER_LABEL: &str = "Create the folder and export";

/// Files a write warns of by name when it would replace them.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Guarded<'a> {
    /// The scene file on screen.
    pub(crate) scene: Option<&'a Path>,
    /// The images being compared (one, or a colour and a depth image judged together).
    pub(crate) compared: [Option<&'a Path>; 2],
}

/// What a write must wait for, if anything: the folder it would create (`missing_folder`), else
/// the files among `files` it would replace. The `guarded` files get a warning of their own.
/// `Ok` hands the action back to be written now.
pub(crate) fn wait_for_yes<A>(
    action: A,
    missing_folder: Option<PathBuf>,
    files: Vec<PathBuf>,
    guarded: Guarded<'_>,
) -> Result<A, PendingReplace<A>> {
    if let Some(folder) = missing_folder {
        return Err(PendingReplace {
            action,
            existing: Vec::new(),
            open_scene: false,
            compared: false,
            missing_folder: Some(folder),
        });
    }
    let existing: Vec<PathBuf> = files.into_iter().filter(|path| path.exists()).collect();
    if existing.is_empty() {
        return Ok(action);
    }
    let among = |guarded: Option<&Path>| {
        guarded.is_some_and(|file| existing.iter().any(|path| same_file(path, file)))
    };
    let open_scene = among(guarded.scene);
    let compared = guarded.compared.into_iter().any(among);
    Err(PendingReplace {
        action,
        existing,
        open_scene,
        compared,
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
    ctx.data_mut(|data| data.remove::<bool>(focus_given()));
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
                ui.label("The files go into a folder that does not exist yet:");
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
            if self.compared {
                ui.label(
                    RichText::new(
                        "One of them is the image you are comparing, your program's output: \
                         it will be replaced by the exact one.",
                    )
                    .color(ui.visuals().warn_fg_color),
                );
            }
            // The folder, then the files' names in it.
            let folder = self.existing[0].parent().filter(|folder| {
                self.existing
                    .iter()
                    .all(|path| path.parent() == Some(folder))
            });
            if let Some(folder) = folder {
                let shown = std::path::absolute(folder).unwrap_or_else(|_| folder.to_path_buf());
                ui.label(format!("In the folder {}:", shown.display()));
            }
            for path in &self.existing {
                let name = match (folder, path.file_name()) {
                    (Some(_), Some(name)) => name.to_string_lossy().into_owned(),
                    _ => path.display().to_string(),
                };
                ui.label(RichText::new(name).monospace());
            }
            answer = yes_or_cancel(ui, REPLACE_LABEL);
        });
        if modal.should_close() && answer.is_none() {
            answer = Some(false);
        }
        answer
    }
}

/// Marks that "Cancel" of the modal on screen has been given the focus once.
fn focus_given() -> egui::Id {
    egui::Id::unique("replace files: Cancel focused")
}

/// A row of "Cancel" and the yes button (`yes_label`): `Some(true)` or `Some(false)` when one
/// is clicked. "Cancel" takes the focus as the modal opens (from a field typed in, too), so
/// Enter answers no.
fn yes_or_cancel(ui: &mut egui::Ui, yes_label: &str) -> Option<bool> {
    ui.horizontal(|ui| {
        let cancel = ui.button("Cancel");
        let first = ui.data_mut(|data| {
            let given = data.get_temp::<bool>(focus_given()).unwrap_or(false);
            data.insert_temp(focus_given(), true);
            !given
        });
        if first {
            cancel.request_focus();
        }
        let yes = ui.button(yes_label).clicked();
        (yes || cancel.clicked()).then_some(yes)
    })
    .inner
}
