//! Words quoted for a POSIX shell: the command lines the program writes for a user to run (an
//! export's `name_command.sh`, the grading report's commands).

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

#[cfg(test)]
mod tests {
    use super::shell_quote;

    #[test]
    fn words_are_quoted_only_where_a_shell_would_split_or_expand_them() {
        assert_eq!(shell_quote("a_b-1.png"), "a_b-1.png");
        assert_eq!(shell_quote("-0.25"), "-0.25");
        assert_eq!(shell_quote("my view.png"), "'my view.png'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
    }
}
