//! Depth order for dense scenes: discs split into passes of depth slices, front to back, each
//! pass covering the image twice as many times over as the one before, so that a pass can be
//! culled against what the passes before it drew.
//!
//! The order only decides how much is culled, never the picture (a hidden disc stays hidden, and
//! ties go by file index whatever the order), so an approximate order does: a counting sort into
//! [`DEPTH_SLICES`] slices of the depth range, file order within a slice. Linear in the discs.

use rayon::prelude::*;

use super::Disc;
use crate::geometry::camera::PixelGrid;

/// Slices of the depth range the front-to-back order sorts discs into.
const DEPTH_SLICES: usize = 4096;

/// Discs handled per parallel task.
const CHUNK: usize = 32_768;

/// Below this many discs over a pixel on average, sorting costs more than culling saves (measured
/// with `examples/performance.rs`: the random scenes of 100,000 and 1,000,000 spheres lie about
/// three deep and were slower culled; the dense ones lie 10 and 100 deep and were 3 to 4× faster).
pub(super) const CULL_MIN_DISCS_PER_PIXEL: f64 = 6.0;

/// Below this many discs in a frame, occlusion culling does not pay for its sort.
pub(super) const CULL_MIN_DISCS: usize = 64;

/// How many discs lie over a pixel on average: their areas on the image (each at most the image's) summed,
/// over the image's area.
pub(super) fn discs_per_pixel(discs: &[Disc], grid: &PixelGrid) -> f64 {
    let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
    discs
        .par_iter()
        .map(|disc| covered_pixels(disc, grid, pixels))
        .sum::<f64>()
        / pixels
}

/// The pixels `disc` may cover: its area in pixels, at most the image's `pixels`, and none when
/// its bounding square lies off the image (zoomed-in views leave most discs off it).
fn covered_pixels(disc: &Disc, grid: &PixelGrid, pixels: f64) -> f64 {
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    let radius_px = disc.radius_sq.sqrt() * inverse_pixel;
    let (half_width, half_height) = (
        0.5 * f64::from(grid.width_px),
        0.5 * f64::from(grid.height_px),
    );
    // Centre in pixels from the image's centre; NaN counts as off the image.
    let (across, up) = (disc.u * inverse_pixel, disc.v * inverse_pixel);
    let on_image = across.abs() < half_width + radius_px && up.abs() < half_height + radius_px;
    if on_image {
        (std::f64::consts::PI * radius_px * radius_px).min(pixels)
    } else {
        0.0
    }
}

/// One disc's nearest t: `w − r`, never above the t of a pixel it covers (correctly rounded
/// square root and subtraction are monotonic).
#[inline]
pub(super) fn front_t(disc: &Disc) -> f64 {
    disc.w - disc.radius_sq.sqrt()
}

/// A frame's discs split into passes front to back: per chunk of the file, per pass, the discs
/// in file order with their depth slices.
pub(super) struct Passes {
    count: usize,
    chunks: Vec<ChunkPasses>,
}

/// One chunk's discs by pass.
struct ChunkPasses {
    discs: Vec<Vec<Disc>>,
    slices: Vec<Vec<u16>>,
}

impl Passes {
    /// `discs` split into passes on `grid`: the first holds the nearest slices whose discs cover
    /// the image `first_layers` times over, each next one twice as many layers. `None` when the
    /// nearest t do not span a finite, non-empty range (then any order is as good).
    pub(super) fn of(discs: &[Disc], grid: &PixelGrid, first_layers: f64) -> Option<Self> {
        let (nearest, farthest) = discs
            .par_iter()
            .map(front_t)
            .filter(|front| front.is_finite())
            .fold(
                || (f64::INFINITY, f64::NEG_INFINITY),
                |(low, high), front| (low.min(front), high.max(front)),
            )
            .reduce(
                || (f64::INFINITY, f64::NEG_INFINITY),
                |a, b| (a.0.min(b.0), a.1.max(b.1)),
            );
        let span = farthest - nearest;
        if !(span > 0.0 && span.is_finite()) {
            return None;
        }
        let scale = DEPTH_SLICES as f64 / span;
        let slice_of = |disc: &Disc| {
            let front = front_t(disc);
            let slice = if front.is_nan() {
                f64::INFINITY
            } else {
                (front - nearest) * scale
            };
            // The saturating conversion puts −∞ first.
            (slice as usize).min(DEPTH_SLICES - 1) as u16
        };
        let slices: Vec<u16> = discs.par_iter().map(slice_of).collect();
        let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
        let covered_px = discs
            .par_chunks(CHUNK)
            .zip(slices.par_chunks(CHUNK))
            .map(|(discs, slices)| {
                let mut covered = vec![0.0f64; DEPTH_SLICES];
                for (disc, &slice) in discs.iter().zip(slices) {
                    covered[usize::from(slice)] += covered_pixels(disc, grid, pixels);
                }
                covered
            })
            .reduce(
                || vec![0.0; DEPTH_SLICES],
                |mut covered, more| {
                    for (pixels, more) in covered.iter_mut().zip(more) {
                        *pixels += more;
                    }
                    covered
                },
            );
        // The pass of each slice.
        let mut pass_of_slice = vec![0u8; DEPTH_SLICES];
        let (mut pass, mut covered, mut wanted) = (0u8, 0.0, first_layers * pixels);
        for (slice, pixels_here) in covered_px.iter().enumerate() {
            pass_of_slice[slice] = pass;
            covered += pixels_here;
            if covered >= wanted && pass < u8::MAX {
                pass += 1;
                wanted *= 2.0;
            }
        }
        let count = usize::from(pass_of_slice[DEPTH_SLICES - 1]) + 1;
        let chunks = discs
            .par_chunks(CHUNK)
            .zip(slices.par_chunks(CHUNK))
            .map(|(discs, slices)| {
                let mut chunk = ChunkPasses {
                    discs: vec![Vec::new(); count],
                    slices: vec![Vec::new(); count],
                };
                for (disc, &slice) in discs.iter().zip(slices) {
                    let pass = usize::from(pass_of_slice[usize::from(slice)]);
                    chunk.discs[pass].push(*disc);
                    chunk.slices[pass].push(slice);
                }
                chunk
            })
            .collect();
        Some(Self { count, chunks })
    }

    /// How many passes there are.
    pub(super) fn count(&self) -> usize {
        self.count
    }

    /// The discs of pass `pass` that `may_show` keeps, front to back (file order within a
    /// slice), and the pass's memory released.
    pub(super) fn take(
        &mut self,
        pass: usize,
        may_show: impl Fn(&Disc) -> bool + Sync,
    ) -> Vec<Disc> {
        let mut kept: Vec<(u16, Disc)> = self
            .chunks
            .par_iter_mut()
            .flat_map_iter(|chunk| {
                let discs = std::mem::take(&mut chunk.discs[pass]);
                let slices = std::mem::take(&mut chunk.slices[pass]);
                slices
                    .into_iter()
                    .zip(discs)
                    .filter(|(_, disc)| may_show(disc))
                    .collect::<Vec<_>>()
            })
            .collect();
        // Stable: file order within a slice.
        kept.par_sort_by_key(|&(slice, _)| slice);
        kept.into_iter().map(|(_, disc)| disc).collect()
    }
}
