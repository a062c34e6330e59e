//! The depth sort of a pass's discs: the discs each chunk kept, ordered by depth slice (front
//! to back), in chunk order within a slice, then placed on the image and binned, in parallel.

use std::ops::Range;

use rayon::prelude::*;

use super::placed::PlacedPart;
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

/// One chunk's discs of a pass: each disc's slice, the discs, and the positions of those kept.
pub(super) struct Kept<'a> {
    pub(super) slices: &'a [u16],
    pub(super) discs: &'a [Disc],
    pub(super) positions: &'a KeptPositions,
}

/// The positions of one chunk's kept discs in its pass list, as the sort takes them: on several
/// threads ordered by slice, with where each of the pass's slices starts, by the chunk's own cull
/// task (which has them at hand: no pass of their own); on one thread as the cull found them.
pub(super) struct KeptPositions {
    positions: Vec<u32>,
    /// Per slice of the pass, and one more: where its positions start in `positions`. Empty
    /// when they are not ordered (one thread).
    slice_starts: Vec<u32>,
}

impl KeptPositions {
    /// The positions `found` (in the order the cull found them) of discs whose slices are
    /// `slices` (by position), all within the pass's `pass_slices`.
    pub(super) fn of(found: Vec<u32>, slices: &[u16], pass_slices: Range<usize>) -> Self {
        if rayon::current_num_threads() == 1 {
            return Self {
                positions: found,
                slice_starts: Vec::new(),
            };
        }
        let first_slice = pass_slices.start;
        let slice_count = pass_slices.len();
        let mut starts = vec![0u32; slice_count + 1];
        for &at in &found {
            starts[usize::from(slices[at as usize]) - first_slice + 1] += 1;
        }
        for slice in 0..slice_count {
            starts[slice + 1] += starts[slice];
        }
        let mut cursor = starts.clone();
        let mut order = vec![0u32; found.len()];
        for &at in &found {
            let slot = &mut cursor[usize::from(slices[at as usize]) - first_slice];
            order[*slot as usize] = at;
            *slot += 1;
        }
        Self {
            positions: order,
            slice_starts: starts,
        }
    }

    /// Whether they are ordered by slice (made on several threads).
    fn is_ordered(&self) -> bool {
        !self.slice_starts.is_empty()
    }
}

/// The discs of `kept` (per chunk, its pass list and the positions in it of the discs kept)
/// ordered by slice, in chunk order within a slice, placed on `grid` and binned, in consecutive
/// parts: a counting sort, in parallel (on one thread it held a dense frame's "pass discs" to 4.9×
/// on 16 cores in the frame's phase table). Every kept disc's slice lies in `slices`, the pass's;
/// the sort's tables span those alone. The slices are split into as many groups of about equal
/// discs as there are threads; each group's task moves, chunk by chunk, the discs of its own
/// slices (their positions ordered by slice in each chunk: [`KeptPositions`]) into its own part,
/// then places and bins that part: one parallel step. The discs come out the same whatever the
/// grouping; on one thread, or when a chunk's positions are not ordered,
/// [`sorted_serially`] makes them without the chunks' orders.
pub(super) fn sort_place_and_bin(
    kept: &[Kept<'_>],
    slices: Range<usize>,
    grid: &PixelGrid,
) -> Vec<PlacedPart> {
    let ordered = kept.iter().all(|chunk| chunk.positions.is_ordered());
    if rayon::current_num_threads() == 1 || !ordered {
        return vec![PlacedPart::of(&sorted_serially(kept, slices), grid)];
    }
    let slice_count = slices.len();
    let first_slice = slices.start;
    // Where each slice's discs start in the result.
    let mut starts = vec![0usize; slice_count + 1];
    for chunk in kept {
        for (slice, run) in chunk.positions.slice_starts.windows(2).enumerate() {
            starts[slice + 1] += (run[1] - run[0]) as usize;
        }
    }
    for slice in 0..slice_count {
        starts[slice + 1] += starts[slice];
    }
    let total = starts[slice_count];
    // Groups of slices `[first, end)`, each about `total / groups` discs.
    let groups = rayon::current_num_threads().max(1);
    let mut bounds = vec![0usize];
    for group in 1..groups {
        let wanted = total * group / groups;
        let slice = starts
            .partition_point(|&start| start < wanted)
            .min(slice_count);
        if slice > *bounds.last().unwrap_or(&0) {
            bounds.push(slice);
        }
    }
    bounds.push(slice_count);
    let groups: Vec<Range<usize>> = bounds.windows(2).map(|group| group[0]..group[1]).collect();
    groups
        .into_par_iter()
        .map(|group| {
            let first = group.start;
            let offset = starts[group.start];
            let mut part = vec![Disc::NONE; starts[group.end] - offset];
            let mut cursor: Vec<usize> = starts[group.clone()]
                .iter()
                .map(|start| start - offset)
                .collect();
            for kept in kept {
                let KeptPositions {
                    positions,
                    slice_starts,
                } = kept.positions;
                let mine = slice_starts[group.start] as usize..slice_starts[group.end] as usize;
                for &at in &positions[mine] {
                    let slice = usize::from(kept.slices[at as usize]) - first_slice;
                    let slot = &mut cursor[slice - first];
                    part[*slot] = kept.discs[at as usize];
                    *slot += 1;
                }
            }
            PlacedPart::of(&part, grid)
        })
        .collect()
}

/// [`sort_place_and_bin`]'s discs on one thread: each kept disc moved once, straight to its place (a
/// slice's cursor), in chunk order. The chunks' orders by slice, which let the threads' groups
/// skip what is not theirs, cost more than the sort itself on one thread.
fn sorted_serially(kept: &[Kept<'_>], slices: Range<usize>) -> Vec<Disc> {
    let first_slice = slices.start;
    let mut cursor = vec![0usize; slices.len() + 1];
    for kept in kept {
        for &at in &kept.positions.positions {
            cursor[usize::from(kept.slices[at as usize]) - first_slice + 1] += 1;
        }
    }
    for slice in 0..slices.len() {
        cursor[slice + 1] += cursor[slice];
    }
    let mut all = vec![Disc::NONE; cursor[slices.len()]];
    for kept in kept {
        for &at in &kept.positions.positions {
            let slot = &mut cursor[usize::from(kept.slices[at as usize]) - first_slice];
            all[*slot] = kept.discs[at as usize];
            *slot += 1;
        }
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::disc::placed::Placed;
    use crate::render::rng::SplitMix64;

    /// A chunk: each disc's slice (in `slices`), the discs (sphere ids from `first_id`, somewhere
    /// on or beside a 40 × 30 image of a screen 4 wide) and the positions kept (about half,
    /// increasing, as the cull makes them).
    struct Chunk {
        slices: Vec<u16>,
        discs: Vec<Disc>,
        positions: Vec<u32>,
    }

    fn chunk(rng: &mut SplitMix64, len: usize, slices: &Range<usize>, first_id: u32) -> Chunk {
        let span = slices.len() as u64;
        let slice_of = |rng: &mut SplitMix64| (slices.start as u64 + rng.next_u64() % span) as u16;
        let at = |rng: &mut SplitMix64, reach: f64| {
            (rng.next_u64() % 1000) as f64 / 1000.0 * 2.0 * reach - reach
        };
        Chunk {
            slices: (0..len).map(|_| slice_of(rng)).collect(),
            discs: (first_id..first_id + len as u32)
                .map(|sphere| Disc {
                    u: at(rng, 2.5),
                    v: at(rng, 2.0),
                    radius_sq: at(rng, 0.5).abs().powi(2),
                    sphere,
                    ..Disc::NONE
                })
                .collect(),
            positions: (0..len as u32)
                .filter(|_| rng.next_u64().is_multiple_of(2))
                .collect(),
        }
    }

    /// The oracle: every kept disc in chunk order, then stably sorted by slice.
    fn expected(chunks: &[Chunk]) -> Vec<Disc> {
        let mut kept: Vec<(u16, Disc)> = chunks
            .iter()
            .flat_map(|c| {
                c.positions
                    .iter()
                    .map(|&at| (c.slices[at as usize], c.discs[at as usize]))
            })
            .collect();
        kept.sort_by_key(|&(slice, _)| slice);
        kept.into_iter().map(|(_, disc)| disc).collect()
    }

    /// The oracle of the band lists: per band of 8 rows, the positions whose rows (as placed)
    /// meet it, in order.
    fn expected_bands(placed: &[Placed], grid: &PixelGrid) -> Vec<Vec<u32>> {
        (0..=grid.height_px as usize / 8)
            .map(|band| {
                (0u32..)
                    .zip(placed)
                    .filter(|(_, placed)| {
                        placed
                            .binned_rows()
                            .is_some_and(|(first, last)| first / 8 <= band && band <= last / 8)
                    })
                    .map(|(at, _)| at)
                    .collect()
            })
            .collect()
    }

    #[test]
    fn the_sort_keeps_every_kept_disc_by_slice_then_chunk_placed_and_binned_on_any_thread_count() {
        let mut rng = SplitMix64::new(11);
        let grid = PixelGrid::new(40, 30, 4.0);
        // (chunk lengths, the pass's slices): empty chunks, a range far from 0, one slice, fewer
        // slices than threads, and no disc at all.
        let cases: [(&[usize], Range<usize>); 5] = [
            (&[300, 0, 257, 1, 0, 999], 0..4096),
            (&[500, 500, 500], 3000..3017),
            (&[400, 0, 400], 77..78),
            (&[50, 60], 10..12),
            (&[0, 0], 5..9),
        ];
        for (lens, slices) in cases {
            let mut first_id = 0;
            let chunks: Vec<Chunk> = lens
                .iter()
                .map(|&len| {
                    let made = chunk(&mut rng, len, &slices, first_id);
                    first_id += len as u32;
                    made
                })
                .collect();
            let want = expected(&chunks);
            // The positions as the cull makes them on `made_on` threads, sorted on `sorted_on`.
            let sort = |made_on: usize, sorted_on: usize| {
                let pool = |threads| {
                    rayon::ThreadPoolBuilder::new()
                        .num_threads(threads)
                        .build()
                        .unwrap()
                };
                let positions: Vec<KeptPositions> = pool(made_on).install(|| {
                    chunks
                        .iter()
                        .map(|c| KeptPositions::of(c.positions.clone(), &c.slices, slices.clone()))
                        .collect()
                });
                let kept: Vec<Kept<'_>> = chunks
                    .iter()
                    .zip(&positions)
                    .map(|(c, positions)| Kept {
                        slices: &c.slices,
                        discs: &c.discs,
                        positions,
                    })
                    .collect();
                pool(sorted_on).install(|| sort_place_and_bin(&kept, slices.clone(), &grid))
            };
            // The same pool, as in a frame; and positions left unordered (made on one thread)
            // sorted on several.
            for (made_on, threads) in [(1, 1), (2, 2), (5, 5), (16, 16), (1, 4)] {
                let parts = sort(made_on, threads);
                let case = format!("slices {slices:?}, made on {made_on}, {threads} threads");
                let placed: Vec<Placed> = parts.iter().flat_map(|p| p.placed.clone()).collect();
                assert_eq!(placed.len(), want.len(), "{case}");
                let mut on_image = 0;
                for (placed, disc) in placed.iter().zip(&want) {
                    // Off the image, a disc is placed nowhere (and keeps no id).
                    if placed.binned_rows().is_some() {
                        assert_eq!(placed.disc.sphere, disc.sphere, "{case}");
                        on_image += 1;
                    } else {
                        assert!(Placed::on(disc, &grid).binned_rows().is_none(), "{case}");
                    }
                }
                assert!(
                    want.is_empty() || on_image > want.len() / 2,
                    "{case}: {on_image}"
                );
                // Each band lists, part after part, the discs (by sphere) that meet it.
                let got_bands: Vec<Vec<u32>> = (0..=grid.height_px as usize / 8)
                    .map(|band| {
                        parts
                            .iter()
                            .flat_map(|part| part.band(band).map(|placed| placed.disc.sphere))
                            .collect()
                    })
                    .collect();
                let want_bands: Vec<Vec<u32>> = expected_bands(&placed, &grid)
                    .into_iter()
                    .map(|band| {
                        band.into_iter()
                            .map(|at| placed[at as usize].disc.sphere)
                            .collect()
                    })
                    .collect();
                assert_eq!(got_bands, want_bands, "{case}");
            }
        }
    }
}
