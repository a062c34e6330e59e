//! The viewer's "writes" feature: exports and saved scenes. A write runs in the background
//! ([`super::background::Task`]) and says how it went in the status bar; one that would replace
//! files (or needs a folder made) waits for the user's yes ([`super::confirm`]); a file dialog may
//! be open to choose where it goes ([`super::dialogs`]).

use std::path::PathBuf;

use super::background::Task;
use super::confirm::PendingReplace;
use super::dialogs::PendingDialog;

/// The writes' state.
pub(crate) struct Writes {
    /// A background write (export or saved scene): its outcome message.
    pub(crate) task: Option<Task<Result<String, String>>>,
    /// A write that waits for the user to agree to replace files (or to make a folder).
    pub(crate) pending_replace: Option<PendingReplace>,
    /// A file dialog that is open.
    pub(crate) dialog: Option<PendingDialog>,
    /// Why no file dialog can be shown here, if none can.
    pub(crate) dialog_note: Option<&'static str>,
    /// The `raytracer` binary export scripts run.
    pub(crate) program: Option<PathBuf>,
}
