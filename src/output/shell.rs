//! Words quoted for a POSIX shell: the command lines the program writes for a user to run (an
//! export's `name_command.sh`, the grading report's commands).

use std::fmt::Write as _;

/// Quotes a word for a POSIX shell (single quotes; words of safe characters stay bare).
pub(crate) fn shell_quote(word: &str) -> String {
    let safe = !word.is_empty()
        && word
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.,/+=:".contains(c));
    if safe {
        word.to_owned()
    } else {
        format!("'{}'", word.replace('\'', r"'\''"))
    }
}

/// `path` as one word of a POSIX shell that names it exactly: [`shell_quote`] where it is text
/// with no control character and no character that reorders text; else bash's and zsh's
/// `$'…'`, such characters written `\uXXXX` and (on Unix) bytes that are not UTF-8 `\xNN`.
pub(crate) fn shell_quote_path(path: &std::path::Path) -> String {
    let bytes = path.as_os_str().as_encoded_bytes();
    let plain = |c: char| {
        !c.is_control()
            && !matches!(c, '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
    };
    if let Some(text) = path.to_str()
        && text.chars().all(plain)
    {
        return shell_quote(text);
    }
    let mut word = String::from("$'");
    for chunk in bytes.utf8_chunks() {
        for c in chunk.valid().chars() {
            match c {
                '\\' => word.push_str("\\\\"),
                '\'' => word.push_str("\\'"),
                c if plain(c) => word.push(c),
                c => {
                    let _ = write!(word, "\\u{:04X}", u32::from(c));
                }
            }
        }
        for byte in chunk.invalid() {
            let _ = write!(word, "\\x{byte:02X}");
        }
    }
    word.push('\'');
    word
}

#[cfg(test)]
mod tests {
    use super::{shell_quote, shell_quote_path};

    #[test]
    fn a_path_that_is_not_plain_text_is_named_exactly_in_bash_quoting() {
        use std::path::Path;
        assert_eq!(shell_quote_path(Path::new("a b.tga")), "'a b.tga'");
        assert_eq!(
            shell_quote_path(Path::new("alice\u{202E}gnp.exe")),
            "$'alice\\u202Egnp.exe'"
        );
        assert_eq!(shell_quote_path(Path::new("it's\n")), "$'it\\'s\\u000A'");
    }

    #[test]
    fn words_are_quoted_only_where_a_shell_would_split_or_expand_them() {
        assert_eq!(shell_quote("a_b-1.png"), "a_b-1.png");
        assert_eq!(shell_quote("-0.25"), "-0.25");
        assert_eq!(shell_quote("my view.png"), "'my view.png'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
    }
}
