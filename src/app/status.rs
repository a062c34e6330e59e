//! [`Status`]: the one message the status bar shows — what kind it is, its text, and what clears
//! it — instead of strings matched by their prefix. Information goes stale after
//! [`INFO_LIFETIME`] and is no longer shown; errors stay until something replaces or clears them.

use web_time::{Duration, Instant};

/// How long an informational message stays in the status bar.
pub(crate) const INFO_LIFETIME: Duration = Duration::from_secs(12);

/// Whether a message reports a failure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum StatusKind {
    /// Something the user asked for happened (or is happening).
    Info,
    /// Something failed.
    Error,
}

/// What makes a message go away (besides being replaced by another).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Clears {
    /// It stays until another message replaces it.
    WhenReplaced,
    /// The view could not be rendered: the next frame that renders clears it.
    WhenAFrameRenders,
}

/// A status-bar message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Status {
    /// Info or error.
    pub(crate) kind: StatusKind,
    /// The text shown.
    pub(crate) text: String,
    /// What clears it.
    pub(crate) clears: Clears,
    /// When it was made.
    pub(crate) created: Instant,
}

/// Puts `said` in the status bar's `status`, if anything was said.
pub(crate) fn say(status: &mut Option<Status>, said: Option<Status>) {
    if said.is_some() {
        *status = said;
    }
}

impl Status {
    /// Information that stays until replaced.
    pub(crate) fn info(text: impl Into<String>) -> Self {
        Self {
            kind: StatusKind::Info,
            text: text.into(),
            clears: Clears::WhenReplaced,
            created: Instant::now(),
        }
    }

    /// An error that stays until replaced.
    pub(crate) fn error(text: impl Into<String>) -> Self {
        Self {
            kind: StatusKind::Error,
            text: text.into(),
            clears: Clears::WhenReplaced,
            created: Instant::now(),
        }
    }

    /// The view cannot be rendered; cleared once a frame renders again.
    pub(crate) fn view_error(text: impl std::fmt::Display) -> Self {
        Self {
            kind: StatusKind::Error,
            text: format!("view: {text}"),
            clears: Clears::WhenAFrameRenders,
            created: Instant::now(),
        }
    }

    /// Whether this is an error.
    pub(crate) fn is_error(&self) -> bool {
        self.kind == StatusKind::Error
    }

    /// Whether it is information old enough to no longer show.
    pub(crate) fn is_stale(&self) -> bool {
        self.kind == StatusKind::Info && self.created.elapsed() >= INFO_LIFETIME
    }
}
