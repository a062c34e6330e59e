//! How many submissions are marked at once: as many as the machine has threads, and no more than
//! the memory budget holds (`--memory MB`, or by default what the machine has free and the
//! process's limits leave), each taking at most what marking one submission's largest line
//! needs: its two images read and decoded, and their comparison. Images of another size than a
//! line asks for are said from their headers, never decoded, so no file takes more.

use super::mark::Exact;
use crate::platform::memory::available_memory_bytes;
use crate::render::memory::compare_bound_bytes;

/// Per pixel of a line's images while a submission is marked, beside the comparison's bound:
/// two images (colour and depth), each decoded and copied to 8-bit RGB (3 + 3 bytes).
const READ_BYTES_PER_PIXEL: u64 = 2 * (3 + 3);

/// Beside the pixels: the file's bytes, the decoder's and the answer's own.
const SUBMISSION_SLACK_BYTES: u64 = 8 << 20;

/// What marking one submission of `exacts` may take at most, in bytes.
pub(super) fn submission_bound_bytes(exacts: &[Exact]) -> u64 {
    exacts
        .iter()
        .map(|exact| {
            let (width, height) = exact.task.size_px;
            compare_bound_bytes(width, height)
                + u64::from(width) * u64::from(height) * READ_BYTES_PER_PIXEL
        })
        .max()
        .unwrap_or(0)
        + SUBMISSION_SLACK_BYTES
}

/// The budget (`memory_mb`, or what the process may still use) and the submissions marked at
/// once within it: at least one, at most `threads`.
pub(super) fn marking_threads(
    exacts: &[Exact],
    memory_mb: Option<u64>,
    threads: usize,
) -> (Option<u64>, usize) {
    let budget = memory_mb
        .map(|mb| mb * 1_000_000)
        .or_else(available_memory_bytes);
    let each = submission_bound_bytes(exacts).max(1);
    let fitting = budget.map_or(threads, |budget| (budget / each) as usize);
    (budget, fitting.clamp(1, threads.max(1)))
}
