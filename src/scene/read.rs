//! Reading scene text: the entry points (bytes or text, with or without progress), the byte-order
//! mark, and text that is not UTF-8. The grammar is [`super::parse`]'s; big files go through
//! [`super::split`].

use super::error::{Location, ParseError, ParseErrorKind};
use super::model::Scene;
use super::parse::BYTE_ORDER_MARK;
use super::split::{SPLIT_MIN_BYTES, parse_text};

/// Parses scene bytes; text that is not UTF-8 gets [`ParseErrorKind::NotText`] at the bad byte.
pub fn parse_scene_bytes(bytes: &[u8]) -> Result<Scene, ParseError> {
    parse_scene_bytes_with_progress(bytes, &|_| {})
}

/// [`parse_scene_bytes`], telling `progress` the share of the text parsed so far (0 to 1) every
/// few thousand spheres.
pub fn parse_scene_bytes_with_progress(
    bytes: &[u8],
    progress: &dyn Fn(f64),
) -> Result<Scene, ParseError> {
    match std::str::from_utf8(bytes) {
        Ok(text) => parse_scene_with_progress(text, progress),
        Err(error) => {
            // The location of the first byte that is not UTF-8.
            let valid = &bytes[..error.valid_up_to()];
            let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
            let line_start = valid.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
            let column = 1 + valid[line_start..]
                .iter()
                .filter(|&&b| (b & 0xC0) != 0x80)
                .count();
            let location = Location {
                line: u32::try_from(line).unwrap_or(u32::MAX),
                column: u32::try_from(column).unwrap_or(u32::MAX),
            };
            Err(ParseError::new(location, ParseErrorKind::NotText))
        }
    }
}

/// Parses the text of a scene file into a validated [`Scene`].
pub fn parse_scene(text: &str) -> Result<Scene, ParseError> {
    parse_scene_with_progress(text, &|_| {})
}

/// [`parse_scene`], telling `progress` the share of the text parsed so far (0 to 1) every
/// [`SPHERES_PER_REPORT`](super::parse::SPHERES_PER_REPORT) spheres.
pub fn parse_scene_with_progress(text: &str, progress: &dyn Fn(f64)) -> Result<Scene, ParseError> {
    let text = text.strip_prefix(BYTE_ORDER_MARK).unwrap_or(text);
    parse_text(text, progress, SPLIT_MIN_BYTES)
}

/// [`parse_scene`] on two threads from `split_min_bytes` of text on (files of 4 MB and more
/// otherwise), so that tests and the fuzz target reach the split parser with small inputs. The
/// result is the same whatever the threshold.
pub fn parse_scene_split_from(text: &str, split_min_bytes: usize) -> Result<Scene, ParseError> {
    let text = text.strip_prefix(BYTE_ORDER_MARK).unwrap_or(text);
    parse_text(text, &|_| {}, split_min_bytes)
}
