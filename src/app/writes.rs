//! The viewer's "writes" feature: exports and saved scenes. A write runs in the background
//! ([`super::background::Task`]) and says how it went in the status bar; one that would replace
//! files (or needs a folder made) waits for the user's yes ([`super::confirm`]); a file dialog may
//! be open to choose where it goes ([`super::dialogs`]).

use std::path::PathBuf;

use super::actions::Action;
use super::background::{Poll, Task};
use super::confirm::PendingReplace;
use super::dialogs::PendingDialog;
use super::status::Status;

/// The writes' state; it starts a write in the background and takes its outcome in.
pub(crate) struct Writes {
    /// A background write (export or saved scene): its outcome message.
    pub(crate) task: Option<Task<Result<String, String>>>,
    /// A write that waits for the user to agree to replace files (or to make a folder).
    pub(crate) pending_replace: Option<PendingReplace<Action>>,
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
    pub(crate) fn poll(&mut self) -> Option<Status> {
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
