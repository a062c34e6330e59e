//! Depth order for dense scenes: discs split into passes of depth slices, front to back, each
//! pass covering the image twice as many times over as the one before, so that a pass can be
//! culled against what the passes before it drew ([`CoarseDepth`]) — whole cells of the screen at
//! once, then disc by disc.
//!
//! The order only decides how much is culled, never the picture (a hidden disc stays hidden, and
//! ties go by file index whatever the order), so an approximate order does: counting sorts by
//! pass and screen cell, then, in a pass, by [`DEPTH_SLICES`] slices of the depth range. Linear
//! in the discs.

use std::ops::Range;

use rayon::prelude::*;

use super::coarse_depth::{Cells, CoarseDepth};
use super::depth_sort::{Kept, KeptPositions, sort_place_and_bin};
use super::placed::PlacedPart;
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

/// Slices of the depth range the front-to-back order sorts discs into.
const DEPTH_SLICES: usize = 4096;

/// Discs handled per parallel task, for `discs` discs: about 32 tasks, from 4,096 to 32,768
/// discs each. It depends on the count alone, never on the threads: the per-slice sums, and so
/// the passes, come out the same whatever the machine (a plan decided at a threshold must not
/// change with it).
fn chunk_len(discs: usize) -> usize {
    (discs / 32).clamp(4096, 32_768)
}

/// Below this many discs over a pixel on average, sorting costs more than culling saves (measured
/// with `examples/performance.rs`: the random scenes of 100,000 and 1,000,000 spheres lie about
/// three deep and were slower culled; the dense ones lie 10 and 100 deep and were 3 to 4× faster).
pub(super) const CULL_MIN_DISCS_PER_PIXEL: f64 = 6.0;

/// Below this many discs in a frame, occlusion culling does not pay for its sort.
pub(super) const CULL_MIN_DISCS: usize = 64;

/// The pixels `disc` (radius `radius_px` in pixels) may cover: its area, at most the image's
/// `pixels`, and none when its bounding square lies off the image (zoomed-in views leave most
/// discs off it).
fn covered_pixels(disc: &Disc, radius_px: f64, grid: &PixelGrid, pixels: f64) -> f64 {
    let inverse_pixel = 1.0 / grid.pixel_size_world;
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

/// Whether `disc_count` discs with these `depths` on `grid` are drawn in file order
/// ([`Plan::FileOrder`]: few discs, or fewer than [`CULL_MIN_DISCS_PER_PIXEL`] over a pixel).
pub(super) fn in_file_order(disc_count: usize, depths: &Depths, grid: &PixelGrid) -> bool {
    let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
    disc_count < CULL_MIN_DISCS || depths.covered_px < CULL_MIN_DISCS_PER_PIXEL * pixels
}

/// How a frame's discs are drawn.
pub(super) enum Plan {
    /// In file order, no culling: few discs, or fewer than [`CULL_MIN_DISCS_PER_PIXEL`] over a
    /// pixel.
    FileOrder,
    /// Dense, but all at one depth: any order, culled per band.
    AnyOrder,
    /// Dense: in passes, front to back.
    Passes(Passes),
}

impl Plan {
    /// The plan for `discs` (with their `depth`) on `grid`; with passes, the first covers the
    /// image `first_layers` times over.
    pub(super) fn of(discs: &[Disc], depth: &Depths, grid: &PixelGrid, first_layers: f64) -> Self {
        if in_file_order(discs.len(), depth, grid) {
            return Self::FileOrder;
        }
        let span = depth.farthest_front - depth.nearest_front;
        if !(span > 0.0 && span.is_finite()) {
            return Self::AnyOrder;
        }
        Self::Passes(Passes::of(
            discs,
            grid,
            first_layers,
            depth.nearest_front,
            span,
        ))
    }
}

/// What the plan needs to know of all the discs, gathered as they are projected.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Depths {
    /// The nearest and farthest of the finite nearest t (`w − r`).
    nearest_front: f64,
    farthest_front: f64,
    /// The pixels the discs cover, summed (each disc at most the image).
    covered_px: f64,
}

impl Depths {
    /// Of no disc.
    pub(crate) const NONE: Self = Self {
        nearest_front: f64::INFINITY,
        farthest_front: f64::NEG_INFINITY,
        covered_px: 0.0,
    };

    /// With `disc` on `grid` added.
    #[inline]
    pub(crate) fn with(self, disc: &Disc, grid: &PixelGrid) -> Self {
        let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
        let radius = disc.radius_sq.sqrt();
        let front = disc.front_t();
        let covered_px =
            self.covered_px + covered_pixels(disc, radius / grid.pixel_size_world, grid, pixels);
        if front.is_finite() {
            Self {
                nearest_front: self.nearest_front.min(front),
                farthest_front: self.farthest_front.max(front),
                covered_px,
            }
        } else {
            Self { covered_px, ..self }
        }
    }

    /// Both together.
    pub(crate) fn merge(self, other: Self) -> Self {
        Self {
            nearest_front: self.nearest_front.min(other.nearest_front),
            farthest_front: self.farthest_front.max(other.farthest_front),
            covered_px: self.covered_px + other.covered_px,
        }
    }
}

/// A frame's discs split into passes front to back: per chunk of the file, per pass, the discs
/// grouped by cell.
pub(super) struct Passes {
    /// Per pass, the depth slices it takes (one range per pass).
    slices: Vec<Range<usize>>,
    cells: Cells,
    chunks: Vec<Vec<PassList>>,
}

/// One chunk's discs' keys: per disc its (slice, cell); per slice the pixels its discs cover.
struct ChunkKeys {
    keys: Vec<(u16, u16)>,
    covered: Vec<f64>,
}

/// One chunk's discs of one pass, by cell: cell `c`'s are `discs[starts[c]..starts[c + 1]]`
/// (file order), with their slices.
#[derive(Default)]
struct PassList {
    discs: Vec<Disc>,
    slices: Vec<u16>,
    starts: Vec<usize>,
    /// Per cell: the nearest t of its discs.
    nearest_t: Vec<f64>,
    /// Per cell: the largest r² of its discs.
    largest_radius_sq: Vec<f64>,
}

impl Passes {
    /// `discs` (nearest t from `nearest` over `span`) split into passes on `grid`: the first holds
    /// the nearest slices whose discs cover the image `first_layers` times over, each next one
    /// twice as many layers.
    fn of(discs: &[Disc], grid: &PixelGrid, first_layers: f64, nearest: f64, span: f64) -> Self {
        let scale = DEPTH_SLICES as f64 / span;
        let slice_of = |front: f64| {
            let slice = if front.is_nan() {
                f64::INFINITY
            } else {
                (front - nearest) * scale
            };
            // The saturating conversion puts −∞ first.
            (slice as usize).min(DEPTH_SLICES - 1) as u16
        };
        let pixels = f64::from(grid.width_px) * f64::from(grid.height_px);
        let inverse_pixel = 1.0 / grid.pixel_size_world;
        let cells = Cells::of(grid);
        // Per chunk: each disc's slice and cell, and the pixels each slice covers.
        let chunk = chunk_len(discs.len());
        let chunks: Vec<ChunkKeys> = discs
            .par_chunks(chunk)
            .map(|discs| {
                let mut covered = vec![0.0f64; DEPTH_SLICES];
                let keys = discs
                    .iter()
                    .map(|disc| {
                        let radius = disc.radius_sq.sqrt();
                        let slice = slice_of(disc.front_t());
                        covered[usize::from(slice)] +=
                            covered_pixels(disc, radius * inverse_pixel, grid, pixels);
                        // CELLS² cells fit u16.
                        (slice, cells.of_disc(disc) as u16)
                    })
                    .collect();
                ChunkKeys { keys, covered }
            })
            .collect();
        let mut covered_px = vec![0.0; DEPTH_SLICES];
        for chunk in &chunks {
            for (pixels, more) in covered_px.iter_mut().zip(&chunk.covered) {
                *pixels += more;
            }
        }
        // The pass of each slice.
        let mut pass_of_slice = vec![0u8; DEPTH_SLICES];
        let (mut pass, mut covered, mut wanted) = (0u8, 0.0, first_layers * pixels);
        for (slice, pixels_here) in covered_px.iter().enumerate() {
            pass_of_slice[slice] = pass;
            covered += pixels_here;
            if covered >= wanted && pass < u8::MAX {
                pass += 1;
                // Twice what is covered now: one slice may have covered many layers at once.
                wanted = 2.0 * covered;
            }
        }
        let count = usize::from(pass_of_slice[DEPTH_SLICES - 1]) + 1;
        // Passes take consecutive slices.
        let slices: Vec<Range<usize>> = (0..count)
            .map(|pass| {
                let first = pass_of_slice.partition_point(|&p| usize::from(p) < pass);
                let end = pass_of_slice.partition_point(|&p| usize::from(p) <= pass);
                first..end
            })
            .collect();
        let cell_count = cells.across * cells.down;
        let chunks = discs
            .par_chunks(chunk)
            .zip(chunks)
            .map(|(discs, ChunkKeys { keys, .. })| {
                let pass_of = |slice: u16| usize::from(pass_of_slice[usize::from(slice)]);
                // A counting sort by (pass, cell), file order within.
                let mut lists: Vec<PassList> = (0..count)
                    .map(|_| PassList {
                        starts: vec![0; cell_count + 1],
                        nearest_t: vec![f64::INFINITY; cell_count],
                        largest_radius_sq: vec![f64::NEG_INFINITY; cell_count],
                        ..PassList::default()
                    })
                    .collect();
                for &(slice, cell) in &keys {
                    lists[pass_of(slice)].starts[usize::from(cell) + 1] += 1;
                }
                for list in &mut lists {
                    for cell in 0..cell_count {
                        list.starts[cell + 1] += list.starts[cell];
                    }
                    let len = list.starts[cell_count];
                    list.discs = vec![Disc::NONE; len];
                    list.slices = vec![0; len];
                }
                let mut cursors: Vec<Vec<usize>> =
                    lists.iter().map(|list| list.starts.clone()).collect();
                for (disc, &(slice, cell)) in discs.iter().zip(&keys) {
                    let (pass, cell) = (pass_of(slice), usize::from(cell));
                    let list = &mut lists[pass];
                    let slot = &mut cursors[pass][cell];
                    list.discs[*slot] = *disc;
                    list.slices[*slot] = slice;
                    *slot += 1;
                    let front = disc.front_t();
                    // NaN fronts and radii never draw; min/max skip them.
                    list.nearest_t[cell] = list.nearest_t[cell].min(front);
                    list.largest_radius_sq[cell] = list.largest_radius_sq[cell].max(disc.radius_sq);
                }
                lists
            })
            .collect();
        Self {
            slices,
            cells,
            chunks,
        }
    }

    /// How many passes there are.
    pub(super) fn count(&self) -> usize {
        self.slices.len()
    }

    /// Whether pass `pass` holds no disc.
    pub(super) fn is_empty(&self, pass: usize) -> bool {
        self.chunks.iter().all(|lists| lists[pass].discs.is_empty())
    }

    /// The discs of pass `pass` front to back (by slice), placed on `grid` and binned in
    /// consecutive parts, and the pass's memory released. With `coarse`, what is drawn so far:
    /// only the discs that may show in front of it.
    pub(super) fn take(
        &mut self,
        pass: usize,
        coarse: Option<&CoarseDepth>,
        grid: &PixelGrid,
    ) -> Vec<PlacedPart> {
        let around = coarse.map(|coarse| coarse.farthest_around_cells(&self.cells));
        let reach_sq = self.cells.reaching_neighbours_radius_sq;
        let pass_slices = self.slices[pass].clone();
        // Per chunk, its pass list and the positions in it of the discs kept, ordered by slice
        // while at hand (the discs are moved once, by the depth sort).
        let kept: Vec<(PassList, KeptPositions)> = crate::render::phases::time("cull", || {
            self.chunks
                .par_iter_mut()
                .map(|lists| {
                    let list = std::mem::take(&mut lists[pass]);
                    let mut positions = Vec::with_capacity(list.discs.len());
                    for cell in 0..list.starts.len().saturating_sub(1) {
                        // Every disc of the cell reaches only the cells around it, and lies behind
                        // everything drawn there.
                        let cell_hidden = around.as_ref().is_some_and(|around| {
                            list.largest_radius_sq[cell] <= reach_sq
                                && list.nearest_t[cell] > around[cell]
                        });
                        if cell_hidden {
                            continue;
                        }
                        // A chunk's discs fit u32 (a sphere count does).
                        for at in list.starts[cell]..list.starts[cell + 1] {
                            if coarse.is_none_or(|coarse| coarse.may_show(&list.discs[at])) {
                                positions.push(at as u32);
                            }
                        }
                    }
                    let positions = KeptPositions::of(positions, &list.slices, pass_slices.clone());
                    (list, positions)
                })
                .collect()
        });
        let kept: Vec<Kept<'_>> = kept
            .iter()
            .map(|(list, positions)| Kept {
                slices: &list.slices,
                discs: &list.discs,
                positions,
            })
            .collect();
        crate::render::phases::time("sort and bin", || {
            sort_place_and_bin(&kept, pass_slices, grid)
        })
    }
}

#[cfg(test)]
#[path = "depth_order_tests.rs"]
mod tests;
