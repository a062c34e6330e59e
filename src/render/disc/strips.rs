//! A frame drawn a strip of rows at a time and handed on strip by strip: the command line
//! writes its images as they are made, and never holds the whole frame.
//!
//! In a new process every byte of a frame-sized buffer is memory the kernel must hand over (and
//! zero) on first touch, and on a virtual machine that costs more than drawing a course scene:
//! a frame holds 15 bytes per pixel and each 8-bit image 3 more, 84 MB at 2000×2000. A strip's
//! buffers are a few hundred kilobytes, one set per thread, reused from strip to strip. The
//! strips go in parallel and in no fixed order, each drawn and handed on by the same thread while
//! it is in that thread's cache. The pixels are the ones [`rasterise_frame`](super::raster::rasterise_frame) draws — each
//! band is the same band, drawn by the same code — so the files are the same bytes.
//!
//! Frames drawn in file order (the course scenes, sparse scenes) go strip by strip. Dense
//! frames draw front to back, in passes that look at the whole frame drawn so far; they are drawn
//! whole and handed on in strips.

use std::cell::RefCell;

use rayon::prelude::*;

use super::bins::{BAND_ROWS, bin_discs};
use super::depth_order::{Depths, Plan};
use super::raster::{FIRST_PASS_LAYERS, rasterise_band, rasterise_hits};
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;
use crate::render::frame::NO_HIT;

/// Rows per strip: four bands (of 2, 4 and 8 bands, none was measurably quicker for the course
/// command at 2000×2000).
pub(crate) const STRIP_ROWS: usize = 32;
const _: () = assert!(
    STRIP_ROWS.is_multiple_of(BAND_ROWS),
    "a strip holds whole bands"
);

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

thread_local! {
    /// Each thread's strip: its t and spheres, kept from strip to strip.
    static STRIP: RefCell<(Vec<f64>, Vec<u32>)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

/// Runs `draw` on this thread's strip buffers, `pixels` long (or on new ones, should they be in
/// use already: a consumer that started parallel work of its own on this thread).
fn with_strip<R>(pixels: usize, draw: impl FnOnce(&mut [f64], &mut [u32]) -> R) -> R {
    STRIP.with(|strip| match strip.try_borrow_mut() {
        Ok(mut strip) => {
            let (t, sphere) = &mut *strip;
            t.resize(pixels, f64::INFINITY);
            sphere.resize(pixels, NO_HIT);
            draw(&mut t[..pixels], &mut sphere[..pixels])
        }
        Err(_) => draw(&mut vec![f64::INFINITY; pixels], &mut vec![NO_HIT; pixels]),
    })
}

/// Draws `discs` (with their `depths`) on `grid` and hands `consume` the frame's strips of
/// [`STRIP_ROWS`] rows (the last may be shorter), each once, in parallel and in no fixed order.
/// Stops early at an error `consume` returns (which one, when several fail at once, is not
/// fixed). Returns the pixel–disc tests made.
pub(crate) fn rasterise_strips<E: Send>(
    grid: &PixelGrid,
    discs: &[Disc],
    depths: &Depths,
    consume: impl Fn(Strip<'_>) -> Result<(), E> + Sync,
) -> Result<u64, E> {
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let strip_pixels = width * STRIP_ROWS;
    let plan = Plan::of(discs, depths, grid, FIRST_PASS_LAYERS);
    if !matches!(plan, Plan::FileOrder) {
        let (t, sphere, disc_tests) = rasterise_hits(grid, discs, plan);
        t.par_chunks(strip_pixels)
            .zip(sphere.par_chunks(strip_pixels))
            .enumerate()
            .try_for_each(|(index, (t, sphere))| {
                let first_row = index * STRIP_ROWS;
                consume(Strip {
                    first_row,
                    t,
                    sphere,
                })
            })?;
        return Ok(disc_tests);
    }
    let bands = bin_discs(discs, grid);
    (0..height.div_ceil(STRIP_ROWS))
        .into_par_iter()
        .map(|index| {
            let first_row = index * STRIP_ROWS;
            let pixels = width * STRIP_ROWS.min(height - first_row);
            with_strip(pixels, |t, sphere| {
                t.fill(f64::INFINITY);
                sphere.fill(NO_HIT);
                let first_band = first_row / BAND_ROWS;
                let band_pixels = width * BAND_ROWS;
                let mut disc_tests = 0;
                let bands_out = t
                    .chunks_mut(band_pixels)
                    .zip(sphere.chunks_mut(band_pixels));
                for (band, out) in (first_band..).zip(bands_out) {
                    disc_tests +=
                        rasterise_band(discs, bands.band(band), grid, band * BAND_ROWS, out);
                }
                consume(Strip {
                    first_row,
                    t,
                    sphere,
                })
                .map(|()| disc_tests)
            })
        })
        .try_reduce(|| 0, |a, b| Ok(a + b))
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
    fn the_strips_together_make_the_whole_frame_in_every_plan() {
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
                let drawn_as = |plan: &Plan| match plan {
                    Plan::Passes(_) => Some(true),
                    Plan::FileOrder => Some(false),
                    Plan::AnyOrder => None,
                };
                assert_eq!(drawn_as(&plan), Some(passes), "{count} discs");
                let (t, sphere, tests) = rasterise_hits(&grid, &discs, plan);
                let strips = std::sync::Mutex::new(Vec::new());
                let streamed_tests = rasterise_strips(&grid, &discs, &depths, |strip| {
                    let copy = (strip.first_row, strip.t.to_vec(), strip.sphere.to_vec());
                    strips.lock().unwrap().push(copy);
                    Ok::<_, ()>(())
                })
                .unwrap();
                let mut strips = strips.into_inner().unwrap();
                strips.sort_by_key(|(first_row, _, _)| *first_row);
                let rows: Vec<usize> = strips.iter().map(|(row, _, _)| *row).collect();
                let strip_t: Vec<f64> = strips.iter().flat_map(|(_, t, _)| t.clone()).collect();
                let strip_sphere: Vec<u32> = strips
                    .iter()
                    .flat_map(|(_, _, sphere)| sphere.clone())
                    .collect();
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
        // Two hundred strips, the second fails; sparse discs (strip by strip) and dense ones
        // (drawn whole, then handed on).
        let grid = PixelGrid::new(40, 200 * STRIP_ROWS as u32, 100.0);
        let pixels = (grid.width_px * grid.height_px) as usize;
        for count in [pixels / 50, 2 * pixels] {
            let discs = discs(count, 3.0, &grid, 1);
            let depths = depths_of(&discs, &grid);
            let seen = std::sync::atomic::AtomicUsize::new(0);
            let result = rasterise_strips(&grid, &discs, &depths, |strip| {
                seen.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                if strip.first_row == STRIP_ROWS {
                    Err("full")
                } else {
                    Ok(())
                }
            });
            assert_eq!(result, Err("full"));
            // Strips in flight when the error came may still finish; few start after it.
            let seen = seen.into_inner();
            assert!(seen < 50, "{count} discs: {seen} strips consumed");
        }
    }
}
