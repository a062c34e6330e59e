//! Standard output and error for a program whose reader may go away: [`print_out`] tells a closed
//! pipe (end quietly) from another failure such as a full device (worth a one-line message);
//! [`print_err`] never fails. A closed pipe is `EPIPE` on Unix (the standard library ignores
//! SIGPIPE), and on Windows `ERROR_NO_DATA`, `ERROR_BROKEN_PIPE` or `ERROR_PIPE_NOT_CONNECTED`
//! (Wine gives the last, which the standard library does not count as a broken pipe).
//! [`one_line`] makes a message safe to print: what a user typed (a file name with a newline or an
//! escape sequence, a value of 100 KB) reaches the terminal escaped and shortened.

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

/// Longest word (a run without spaces) a message shows whole, in characters.
const MAX_WORD_CHARS: usize = 300;

/// Characters of a longer word shown before and after the cut.
const WORD_HEAD_CHARS: usize = 200;
const WORD_TAIL_CHARS: usize = 60;

/// `message` as one printable line: control characters (a newline, an escape sequence's ESC),
/// line separators and the characters that reorder text written as escapes (`\n`, `\u{1b}`,
/// `\u{202e}`), and each word longer than [`MAX_WORD_CHARS`] cut in the
/// middle with the count of characters left out.
pub fn one_line(message: &str) -> String {
    let escaped: String = message
        .chars()
        .flat_map(|c| {
            // Control characters, the line and paragraph separators, and the characters that
            // reorder text (bidirectional overrides and isolates) are shown as escapes.
            let reorders = matches!(c, '\u{2028}'..='\u{202E}' | '\u{2066}'..='\u{2069}');
            let escape = (c.is_control() || reorders).then(|| {
                if c.is_control() {
                    c.escape_default().collect::<String>()
                } else {
                    c.escape_unicode().collect::<String>()
                }
            });
            escape
                .unwrap_or_else(|| c.to_string())
                .chars()
                .collect::<Vec<_>>()
        })
        .collect();
    escaped
        .split(' ')
        .map(|word| {
            let count = word.chars().count();
            if count <= MAX_WORD_CHARS {
                return word.to_owned();
            }
            let head: String = word.chars().take(WORD_HEAD_CHARS).collect();
            let tail: String = word.chars().skip(count - WORD_TAIL_CHARS).collect();
            let left_out = count - WORD_HEAD_CHARS - WORD_TAIL_CHARS;
            format!("{head}…[{left_out} characters left out]…{tail}")
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_long_words_cut() {
        assert_eq!(
            one_line("cannot open 'a\nb\u{1b}[31m.txt'"),
            "cannot open 'a\\nb\\u{1b}[31m.txt'"
        );
        assert_eq!(one_line("plain text, é ü"), "plain text, é ü");
        assert_eq!(one_line("a\u{202E}b\u{2028}c"), "a\\u{202e}b\\u{2028}c");
        let long = "9".repeat(120_000);
        let shown = one_line(&format!("-size: expected a number, found '{long}'"));
        assert!(shown.len() < 400, "{} bytes", shown.len());
        assert!(shown.contains("[119742 characters left out]"), "{shown}");
        assert!(shown.starts_with("-size: expected a number, found '999"));
        assert!(shown.ends_with("999'"));
    }
}
