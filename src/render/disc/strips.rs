//! A frame drawn a strip of rows at a time, top first, each strip handed on before the next is
//! drawn: the command line writes its images as they are made, and never holds the whole frame.
//!
//! In a new process every byte of a frame-sized buffer is memory the kernel must hand over (and
//! zero) on first touch, and on a virtual machine that costs more than drawing a course scene:
//! a frame holds 15 bytes per pixel and each 8-bit image 3 more, 84 MB at 2000×2000. A strip's buffers are a few hundred
//! kilobytes, reused from strip to strip. The pixels are the ones [`super::rasterise_frame`]
//! draws — each band is the same band, drawn by the same code — so the files are the same bytes.
//!
//! Frames drawn in file order (the course scenes, sparse scenes) go strip by strip. Dense
//! frames draw front to back, in passes that look at the whole frame drawn so far; they are drawn
//! whole and handed on in strips.

use rayon::prelude::*;

use super::Disc;
use super::bins::{BAND_ROWS, bin_discs};
use super::depth_order::{Depths, Plan};
use super::raster::{FIRST_PASS_LAYERS, rasterise_band, rasterise_hits};
use crate::geometry::camera::PixelGrid;
use crate::render::NO_HIT;

/// Rows per strip: sixteen bands, so that both cores have bands to draw (of 4, 8 and 16 bands,
/// 16 made the course command quickest at 2000×2000).
pub(crate) const STRIP_ROWS: usize = 16 * BAND_ROWS;

/// Rows of a frame, top row first: the t and the visible sphere ([`NO_HIT`] where none) of each
/// pixel, row-major.
pub(crate) struct Strip<'a> {
    /// Index of the strip's first row (0 the top row).
    pub(crate) first_row: usize,
    /// t per pixel (`+∞`: no hit).
    pub(crate) t: &'a [f64],
    /// Sphere index per pixel.
    pub(crate) sphere: &'a [u32],
}

/// The t and spheres of a strip being drawn or consumed.
struct StripBuffers {
    t: Vec<f64>,
    sphere: Vec<u32>,
}

impl StripBuffers {
    fn new(pixels: usize) -> Self {
        Self {
            t: vec![f64::INFINITY; pixels],
            sphere: vec![NO_HIT; pixels],
        }
    }
}

/// Draws `discs` (with their `depths`) on `grid` and hands `consume` the frame's strips of
/// [`STRIP_ROWS`] rows (the last may be shorter) in order, top first; in file order, the next
/// strip is drawn while `consume` has the last. Stops at the first error `consume` returns.
/// Returns the pixel–disc tests made.
pub(crate) fn rasterise_strips<E: Send>(
    grid: &PixelGrid,
    discs: &[Disc],
    depths: &Depths,
    mut consume: impl FnMut(Strip<'_>) -> Result<(), E> + Send,
) -> Result<u64, E> {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let plan = Plan::of(discs, depths, grid, FIRST_PASS_LAYERS);
    if !matches!(plan, Plan::FileOrder) {
        let (t, sphere, disc_tests) = rasterise_hits(grid, discs, plan);
        let strip_pixels = width * STRIP_ROWS;
        let strips = t.chunks(strip_pixels).zip(sphere.chunks(strip_pixels));
        for (index, (t, sphere)) in strips.enumerate() {
            let first_row = index * STRIP_ROWS;
            consume(Strip {
                first_row,
                t,
                sphere,
            })?;
        }
        return Ok(disc_tests);
    }
    let bands = bin_discs(discs, grid);
    // Two strips' buffers: the next strip is drawn while the last one is consumed.
    let strip_pixels = width * STRIP_ROWS.min(height);
    let mut drawn = StripBuffers::new(strip_pixels);
    let mut drawing = StripBuffers::new(strip_pixels);
    let draw = |first_row: usize, buffers: &mut StripBuffers| {
        let pixels = width * STRIP_ROWS.min(height - first_row);
        let (t, sphere) = (&mut buffers.t[..pixels], &mut buffers.sphere[..pixels]);
        t.fill(f64::INFINITY);
        sphere.fill(NO_HIT);
        let first_band = first_row / BAND_ROWS;
        t.par_chunks_mut(width * BAND_ROWS)
            .zip(sphere.par_chunks_mut(width * BAND_ROWS))
            .enumerate()
            .map(|(index, out)| {
                let band = first_band + index;
                rasterise_band(discs, bands.band(band), grid, band * BAND_ROWS, out)
            })
            .sum::<u64>()
    };
    // The loop runs on a thread of the pool: from outside it, every join would hand its work
    // over to the pool and wait to be woken, twice a strip.
    rayon::scope(|_| {
        let mut disc_tests = draw(0, &mut drawn);
        for first_row in (0..height).step_by(STRIP_ROWS) {
            let next_row = first_row + STRIP_ROWS;
            let pixels = width * STRIP_ROWS.min(height - first_row);
            let strip = Strip {
                first_row,
                t: &drawn.t[..pixels],
                sphere: &drawn.sphere[..pixels],
            };
            let (consumed, tests) = rayon::join(
                || consume(strip),
                || (next_row < height).then(|| draw(next_row, &mut drawing)),
            );
            consumed?;
            disc_tests += tests.unwrap_or(0);
            std::mem::swap(&mut drawn, &mut drawing);
        }
        Ok(disc_tests)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::disc::depth_order::Depths;
    use crate::render::rng::SplitMix64;

    /// `count` discs of radius up to `max_radius` pixels over a `grid`, at random depths.
    fn discs(count: usize, max_radius: f64, grid: &PixelGrid, seed: u64) -> Vec<Disc> {
        let mut rng = SplitMix64::new(seed);
        let half_width = 0.5 * f64::from(grid.width_px) * grid.pixel_size_world;
        let half_height = 0.5 * f64::from(grid.height_px) * grid.pixel_size_world;
        (0..count)
            .map(|index| {
                let radius = rng.uniform(0.2, max_radius) * grid.pixel_size_world;
                Disc {
                    u: rng.uniform(-half_width, half_width),
                    v: rng.uniform(-half_height, half_height),
                    w: rng.uniform(-50.0, 50.0),
                    radius_sq: radius * radius,
                    sphere: index as u32,
                }
            })
            .collect()
    }

    fn depths_of(discs: &[Disc], grid: &PixelGrid) -> Depths {
        discs
            .iter()
            .fold(Depths::NONE, |depths, disc| depths.with(disc, grid))
    }

    #[test]
    fn strips_in_order_make_the_whole_frame_in_every_plan() {
        // Heights of less than a strip, of whole strips and of a ragged end; sparse discs
        // (drawn strip by strip) and discs many deep (drawn whole, in passes, then handed on).
        let strip = STRIP_ROWS as u32;
        for (width, height) in [(37, 11), (64, 2 * strip), (101, 3 * strip + 5)] {
            let grid = PixelGrid::new(width, height, f64::from(width.max(height)));
            let pixels = (width * height) as usize;
            // Discs of up to 3 pixels' radius cover about 11 pixels each.
            for (count, passes) in [(pixels / 50, false), (2 * pixels, true)] {
                let discs = discs(count, 3.0, &grid, u64::from(width));
                let depths = depths_of(&discs, &grid);
                let plan = Plan::of(&discs, &depths, &grid, FIRST_PASS_LAYERS);
                assert_eq!(matches!(plan, Plan::Passes(_)), passes, "{count} discs");
                let (t, sphere, tests) = rasterise_hits(&grid, &discs, plan);
                let mut rows = Vec::new();
                let (mut strip_t, mut strip_sphere) = (Vec::new(), Vec::new());
                let streamed_tests = rasterise_strips(&grid, &discs, &depths, |strip| {
                    rows.push(strip.first_row);
                    strip_t.extend_from_slice(strip.t);
                    strip_sphere.extend_from_slice(strip.sphere);
                    Ok::<_, ()>(())
                })
                .unwrap();
                let wanted_rows: Vec<usize> = (0..height as usize).step_by(STRIP_ROWS).collect();
                assert_eq!(rows, wanted_rows);
                assert_eq!(strip_sphere, sphere, "{width}×{height}, {count} discs");
                let same_t = strip_t
                    .iter()
                    .zip(&t)
                    .all(|(a, b)| a.to_bits() == b.to_bits());
                assert!(same_t && strip_t.len() == t.len());
                assert_eq!(streamed_tests, tests);
            }
        }
    }

    #[test]
    fn an_error_of_the_consumer_stops_the_strips() {
        let grid = PixelGrid::new(40, 5 * STRIP_ROWS as u32, 100.0);
        let discs = discs(200, 5.0, &grid, 1);
        let depths = depths_of(&discs, &grid);
        let mut seen = 0;
        let result = rasterise_strips(&grid, &discs, &depths, |strip| {
            seen += 1;
            if strip.first_row == STRIP_ROWS {
                Err("full")
            } else {
                Ok(())
            }
        });
        assert_eq!(result, Err("full"));
        assert_eq!(seen, 2);
    }
}
