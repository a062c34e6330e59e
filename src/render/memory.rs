//! How much memory a render takes at most, from the request alone, so that a request that
//! cannot fit is refused before any work, with the figure.
//!
//! The bound adds, in bytes:
//! * the program itself: [`BASELINE_BYTES`];
//! * the scene: [`SPHERE_BYTES`] per sphere (the sphere, its projected disc, its band lists);
//! * the frame: [`FRAME_BYTES_PER_PIXEL`] per pixel (colour, t, sphere), and
//!   [`SUPERSAMPLED_BYTES_PER_PIXEL`] more with supersampling (the filtered depth grey, and the
//!   supersampled colour until it replaces the frame's);
//! * the larger of the supersampler's working memory (a bounded tile of samples per thread) and
//!   the outputs being encoded ([`OUTPUT_BYTES_PER_PIXEL`] per pixel: two outputs at a time).
//!
//! The course's own command, drawn and written strip by strip, holds far less
//! ([`streamed_bound_bytes`]): a strip and its pixels per thread, and the whole frame's t and
//! spheres only when a dense frame is drawn whole first.
//!
//! Loading a scene file is bounded separately: the file's bytes and the spheres parsed from them.
//! So is comparing the user's images with the exact ones ([`compare_bound_bytes`]), and a
//! pixel's trace ([`trace_bound_bytes`]).

use super::sampling::Sampling;
use super::sampling::working_bytes;

/// The program's own memory (code, libraries, thread stacks, allocator), generously.
pub const BASELINE_BYTES: u64 = 96 << 20;

/// Per sphere: the parsed sphere (40 bytes) and its projected disc (40); for dense frames, its
/// copy in the front-to-back passes (42 with its depth slice) and, while its pass is culled and
/// sorted, its position and its place in its chunk's order (4 + 4) and the sorted disc (40);
/// once the pass's copies are gone, the sorted disc (40), its placed copy for the tiles (64) and,
/// generously, its entries in the band lists and the band gathers (48). At most
/// 40 + 40 + max(42 + 8 + 40, 40 + 64 + 48) = 232. (It was 178 until the placed copy was
/// counted.)
pub const SPHERE_BYTES: u64 = 232;

/// Per pixel of a frame: 8-bit colour (3), t as f64 (8) and the sphere index (4).
pub const FRAME_BYTES_PER_PIXEL: u64 = 15;

/// Per pixel more when supersampling: the filtered grey (4) and the supersampled colour (3)
/// beside the one-sample colour until it replaces it.
pub const SUPERSAMPLED_BYTES_PER_PIXEL: u64 = 7;

/// Per pixel of the outputs being written: two at a time (the colour and the depth side), each an
/// 8-bit RGB image (3) or, for lossless depth, t as f32 with its encoded copy (8).
pub const OUTPUT_BYTES_PER_PIXEL: u64 = 14;

/// The bound, in bytes, of rendering and writing a `width_px × height_px` picture of
/// `sphere_count` spheres with `sampling` on `threads` threads.
pub fn render_bound_bytes(
    width_px: u32,
    height_px: u32,
    sphere_count: usize,
    sampling: Option<&Sampling>,
    threads: usize,
) -> u64 {
    let pixels = u64::from(width_px) * u64::from(height_px);
    let spheres = sphere_count as u64 * SPHERE_BYTES;
    let frame = pixels * FRAME_BYTES_PER_PIXEL;
    let output = pixels * OUTPUT_BYTES_PER_PIXEL;
    // The supersampled grey and colour stay while the outputs are encoded; the samples' working
    // memory is gone by then.
    let supersampled = sampling.map_or(0, |_| pixels * SUPERSAMPLED_BYTES_PER_PIXEL);
    let working = sampling.map_or(0, |sampling| working_bytes(sampling, threads) as u64);
    BASELINE_BYTES + spheres + frame + supersampled + working.max(output)
}

/// Per sphere of a pixel's trace (`-trace`), checked before it is made: its record (80 bytes)
/// and a line of text of some 300 bytes, every number printed to 17 digits. Once it is made, its
/// text is counted, and the count with its records is the bound (`PixelTrace::text_bytes`): a
/// number far from 1 prints in full, hundreds of digits.
pub const TRACE_BYTES_PER_SPHERE: u64 = 384;

/// The bound, in bytes, that a pixel's trace adds for `sphere_count` spheres.
pub fn trace_bound_bytes(sphere_count: usize) -> u64 {
    sphere_count as u64 * TRACE_BYTES_PER_SPHERE
}

/// Per pixel of a frame drawn whole before it is streamed (a dense frame): t as f64 (8), the
/// sphere index (4) and, rounded up to a byte, the coarse depth of what is drawn between passes
/// (8 bytes per tile of 8×8 pixels, and per block of tiles).
pub const HITS_BYTES_PER_PIXEL: u64 = 13;

/// Per pixel of a strip streamed, per thread: its t and sphere (12) and its pixels being written
/// (3), twice (a thread that starts another strip while its own waits takes fresh ones).
pub const STRIP_BYTES_PER_PIXEL: u64 = 30;

/// The bound, in bytes, of the streamed command (`render_strips`) for a
/// `width_px × height_px` picture of `sphere_count` spheres on `threads` threads; `whole_frame`
/// when the frame is dense and drawn whole first (`renders_strip_by_strip` says).
pub fn streamed_bound_bytes(
    width_px: u32,
    height_px: u32,
    sphere_count: usize,
    whole_frame: bool,
    threads: usize,
) -> u64 {
    let pixels = u64::from(width_px) * u64::from(height_px);
    let spheres = sphere_count as u64 * SPHERE_BYTES;
    let strip_pixels = u64::from(width_px) * super::disc::STRIP_ROWS as u64;
    let hits = if whole_frame {
        pixels * HITS_BYTES_PER_PIXEL
    } else {
        0
    };
    BASELINE_BYTES + spheres + hits + threads as u64 * strip_pixels * STRIP_BYTES_PER_PIXEL
}

/// The bound, in bytes, of loading a scene file of `file_bytes` bytes: the bytes, and the
/// spheres parsed from them (a sphere takes at least 30 bytes of text; the parsed list may
/// briefly hold twice its length while it grows).
pub fn load_bound_bytes(file_bytes: u64) -> u64 {
    BASELINE_BYTES + file_bytes + 2 * (file_bytes / 30) * 40
}

/// Renders the comparison's search keeps at once (`compare::fit::score::MAX_CACHED_HITS`), and
/// the one being made.
pub const COMPARE_HITS_HELD: u64 = 7;

/// Per pixel of a comparison, beside the render's own frame and outputs: their two images and
/// the exact two (3 bytes each), the two differences (1 each), the diagnosis's renders (t and
/// sphere, 12 bytes each, [`COMPARE_HITS_HELD`] of them) with the two images of the set being
/// scored (3 each) and the unexplained pixels' flags (1 each, two images), the depth range's fit
/// (two renders of 12 and its points, 16), and the difference picture (four panels of 3 bytes
/// in each of two rows, with the heat map and the unexplained panel being drawn, 6 more).
pub const COMPARE_BYTES_PER_PIXEL: u64 =
    4 * 3 + 2 + COMPARE_HITS_HELD * 12 + 2 * 3 + 2 + 2 * 12 + 16 + 2 * 4 * 3 + 6;

/// The bound, in bytes, that comparing images of `width_px × height_px` adds to the render's.
pub fn compare_bound_bytes(width_px: u32, height_px: u32) -> u64 {
    u64::from(width_px) * u64::from(height_px) * COMPARE_BYTES_PER_PIXEL
}
