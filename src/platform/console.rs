//! Standard output and error for a program whose reader may go away: [`print_out`] tells a closed
//! pipe (end quietly) from another failure such as a full device (worth a one-line message);
//! [`print_err`] never fails. A closed pipe is `EPIPE` on Unix (the standard library ignores
//! SIGPIPE), and on Windows `ERROR_NO_DATA`, `ERROR_BROKEN_PIPE` or `ERROR_PIPE_NOT_CONNECTED`
//! (Wine gives the last, which the standard library does not count as a broken pipe).

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
        .map_err(|error| {
            if is_closed_pipe(&error) {
                PrintError::Closed
            } else {
                PrintError::Failed(error)
            }
        })
}

/// Whether `error` says the reader of a pipe went away.
fn is_closed_pipe(error: &std::io::Error) -> bool {
    /// `ERROR_BROKEN_PIPE`, `ERROR_NO_DATA`, `ERROR_PIPE_NOT_CONNECTED`.
    const WINDOWS_CLOSED_PIPE: [i32; 3] = [109, 232, 233];
    error.kind() == std::io::ErrorKind::BrokenPipe
        || (cfg!(windows)
            && error
                .raw_os_error()
                .is_some_and(|code| WINDOWS_CLOSED_PIPE.contains(&code)))
}

/// Writes `text` to standard error; a failure is ignored (there is nowhere left to say it).
pub fn print_err(text: &str) {
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}
