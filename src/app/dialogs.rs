//! Native file dialogs (rfd) without blocking the UI: each dialog runs as a [`Task`] and its
//! answer is polled. Where no dialog can be shown (no desktop portal on the
//! session bus and no zenity), [`dialog_unavailable_reason`] says so and the viewer's path fields
//! do the job instead.

use std::path::PathBuf;

use super::background::{Poll, Task};

/// Which dialog an answer belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum DialogKind {
    /// "Open scene".
    Open,
    /// "Export to".
    Export,
    /// "Save view as scene".
    SaveScene,
    /// "Open an image to compare" (colour or depth).
    CompareImage(crate::app::compare::ImageKind),
}

/// A dialog that is open (or whose answer has not been read yet).
#[derive(Debug)]
pub(crate) struct PendingDialog {
    pub(crate) kind: DialogKind,
    pub(crate) task: Task<Option<PathBuf>>,
}

/// The dialog's outcome.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum DialogAnswer {
    /// Not answered yet.
    Waiting,
    /// The user chose a file.
    Chosen(DialogKind, PathBuf),
    /// The user cancelled, or the dialog could not be shown.
    Cancelled(DialogKind),
}

impl PendingDialog {
    /// Checks for the answer without blocking.
    pub(crate) fn poll(&self) -> DialogAnswer {
        match self.task.poll() {
            Poll::Done(Some(path)) => DialogAnswer::Chosen(self.kind, path),
            Poll::Done(None) | Poll::Lost => DialogAnswer::Cancelled(self.kind),
            Poll::Running => DialogAnswer::Waiting,
        }
    }
}

/// What the window says where no native dialog can be shown.
pub(crate) const NO_DIALOG: &str = "no file dialog is available (no desktop portal on a session bus, no zenity): \
     type a path in the field instead";

/// Why no native dialog can be shown here, or `None` if one probably can: on Linux rfd needs a
/// desktop portal on the session bus, or zenity; Windows and macOS have their own.
pub(crate) fn dialog_unavailable_reason() -> Option<&'static str> {
    if !crate::platform::display::dialogs_need_a_desktop_portal() {
        return None;
    }
    let has_session_bus = std::env::var_os("DBUS_SESSION_BUS_ADDRESS").is_some();
    let has_zenity = std::env::var_os("PATH").is_some_and(|paths| {
        std::env::split_paths(&paths).any(|folder| folder.join("zenity").is_file())
    });
    unavailable_reason(has_session_bus, has_zenity)
}

/// [`dialog_unavailable_reason`] from what the environment has.
fn unavailable_reason(has_session_bus: bool, has_zenity: bool) -> Option<&'static str> {
    (!has_session_bus && !has_zenity).then_some(NO_DIALOG)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dialog_needs_a_session_bus_or_zenity() {
        assert_eq!(unavailable_reason(false, false), Some(NO_DIALOG));
        assert_eq!(unavailable_reason(true, false), None);
        assert_eq!(unavailable_reason(false, true), None);
    }
}
