//! Single-pass tokenizer over the bytes of a scene file: whitespace-separated words, with `{` and `}`
//! always tokens of their own. Tokens borrow the text (no allocation per token) and carry their
//! line and column.

use super::error::Location;

/// One word of the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Token<'a> {
    /// The word as written.
    pub(crate) text: &'a str,
    /// Where it starts.
    pub(crate) location: Location,
}

/// Bytes that end a word: ASCII whitespace and the braces.
const ENDS_A_WORD: [bool; 256] = {
    let mut table = [false; 256];
    let mut byte = 0;
    while byte < 256 {
        let b = byte as u8;
        table[byte] = b.is_ascii_whitespace() || b == b'{' || b == b'}';
        byte += 1;
    }
    table
};

/// Iterator over the tokens of a text.
#[derive(Debug, Clone)]
pub(crate) struct Lexer<'a> {
    text: &'a str,
    offset: usize,
    line: u32,
    /// Characters (not bytes) between the start of the current line and `offset`.
    column_chars: usize,
}

impl<'a> Lexer<'a> {
    /// A lexer at the start of `text`.
    pub(super) fn new(text: &'a str) -> Self {
        Self {
            text,
            offset: 0,
            line: 1,
            column_chars: 0,
        }
    }

    /// Share of the text consumed so far, 0 to 1 (1 for an empty text).
    pub(crate) fn share_consumed(&self) -> f64 {
        if self.text.is_empty() {
            1.0
        } else {
            self.offset as f64 / self.text.len() as f64
        }
    }

    /// Bytes of the text consumed so far, and bytes left.
    pub(crate) fn bytes_consumed_and_left(&self) -> (usize, usize) {
        (self.offset, self.text.len() - self.offset)
    }

    /// Byte offset of `token` (one of this lexer's) in the text.
    pub(crate) fn offset_of(&self, token: &Token<'_>) -> usize {
        token.text.as_ptr() as usize - self.text.as_ptr() as usize
    }

    /// Continues where `run` (a lexer over the text from byte `line_start`, the start of line
    /// `line` here) stopped.
    pub(crate) fn continue_after(&mut self, line_start: usize, line: u32, run: &Lexer<'_>) {
        self.offset = line_start + run.offset;
        self.line = line.saturating_add(run.line - 1);
        self.column_chars = run.column_chars;
    }

    /// The location the next character would have (used for "end of file" errors).
    pub(crate) fn here(&self) -> Location {
        Location {
            line: self.line,
            column: u32::try_from(self.column_chars.saturating_add(1)).unwrap_or(u32::MAX),
        }
    }
}

impl<'a> Iterator for Lexer<'a> {
    type Item = Token<'a>;

    fn next(&mut self) -> Option<Token<'a>> {
        let bytes = self.text.as_bytes();
        // Skip whitespace, counting lines.
        while let Some(&byte) = bytes.get(self.offset) {
            if byte == b'\n' {
                self.line = self.line.saturating_add(1);
                self.offset += 1;
                self.column_chars = 0;
            } else if byte.is_ascii_whitespace() {
                self.offset += 1;
                self.column_chars += 1;
            } else {
                break;
            }
        }
        let start = self.offset;
        let first = *bytes.get(start)?;
        let location = self.here();
        let end = if first == b'{' || first == b'}' {
            self.column_chars += 1;
            start + 1
        } else {
            // One pass: where the word ends, and how many of its bytes continue a UTF-8
            // sequence (columns count characters, and counting as the lexer moves keeps long
            // lines linear).
            let mut end = start;
            let mut continuing = 0;
            while let Some(&byte) = bytes.get(end) {
                if ENDS_A_WORD[usize::from(byte)] {
                    break;
                }
                continuing += usize::from((byte & 0xC0) == 0x80);
                end += 1;
            }
            self.column_chars += end - start - continuing;
            end
        };
        self.offset = end;
        // Token boundaries are ASCII bytes, so they are char boundaries too.
        let text = self.text.get(start..end)?;
        Some(Token { text, location })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(text: &str) -> Vec<(&str, u32, u32)> {
        Lexer::new(text)
            .map(|t| (t.text, t.location.line, t.location.column))
            .collect()
    }

    #[test]
    fn splits_on_whitespace_and_braces_with_positions() {
        assert_eq!(
            words("Group {\n\tnumObjects 1\n}"),
            vec![
                ("Group", 1, 1),
                ("{", 1, 7),
                ("numObjects", 2, 2),
                ("1", 2, 13),
                ("}", 3, 1)
            ]
        );
        assert_eq!(
            words("a{b}c"),
            vec![
                ("a", 1, 1),
                ("{", 1, 2),
                ("b", 1, 3),
                ("}", 1, 4),
                ("c", 1, 5)
            ]
        );
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        assert_eq!(words("é x"), vec![("é", 1, 1), ("x", 1, 3)]);
    }

    #[test]
    fn crlf_line_endings_count_once() {
        assert_eq!(words("a\r\nb"), vec![("a", 1, 1), ("b", 2, 1)]);
    }
}
