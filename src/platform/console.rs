//! Standard output and error for a program whose reader may go away: [`print_out`] tells a closed
//! pipe (end quietly) from another failure such as a full device (worth a one-line message);
//! [`print_err`] never fails. Rust reports a closed pipe as `BrokenPipe` on every system
//! (`EPIPE` on Unix, where the standard library ignores SIGPIPE; `ERROR_NO_DATA` on Windows).

use std::io::Write as _;

/// How a write to standard output or error ended.
#[derive(Debug)]
pub enum PrintError {
    /// The reader went away (a closed pipe): end quietly.
    Closed,
    /// Another failure (a full device): worth a one-line message.
    Failed(std::io::Error),
}

/// Writes `text` to standard output.
pub fn print_out(text: &str) -> Result<(), PrintError> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|error| match error.kind() {
            std::io::ErrorKind::BrokenPipe => PrintError::Closed,
            _ => PrintError::Failed(error),
        })
}

/// Writes `text` to standard error; a failure is ignored (there is nowhere left to say it).
pub fn print_err(text: &str) {
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}
