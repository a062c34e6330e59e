//! The depth sort of a pass's discs: the discs each chunk kept, ordered by depth slice (front
//! to back), in chunk order within a slice, in parallel.

use std::ops::Range;

use rayon::prelude::*;

use super::Disc;

/// One chunk's discs of a pass: each disc's slice, the discs, and the positions of those kept.
pub(super) struct Kept<'a> {
    pub(super) slices: &'a [u16],
    pub(super) discs: &'a [Disc],
    pub(super) positions: &'a [u32],
}

/// The discs of `kept` (per chunk, its pass list and the positions in it of the discs kept)
/// ordered by slice, in chunk order within a slice: a counting sort, in parallel (on one thread
/// it held a dense frame's "pass discs" to 4.9× on 16 cores: docs/scaling-16-before.md). Every
/// kept disc's slice lies in `slices`, the pass's; the sort's tables span those alone. The
/// slices are split into as many groups of about equal discs as there are threads. Each chunk
/// orders the positions of its kept discs by slice; each group's task then moves, chunk by chunk,
/// the discs of its own slices into its own part of the result. The result is the same whatever the grouping; on one
/// thread, [`by_slice_on_one_thread`] makes it without the chunks' orders.
pub(super) fn by_slice(kept: &[Kept<'_>], slices: Range<usize>) -> Vec<Disc> {
    if rayon::current_num_threads() == 1 {
        return by_slice_on_one_thread(kept, slices);
    }
    let slice_count = slices.len();
    let first_slice = slices.start;
    // Per chunk: where each slice's kept discs start in its order, and their positions by slice.
    let orders: Vec<(Vec<u32>, Vec<u32>)> = kept
        .par_iter()
        .map(
            |&Kept {
                 slices, positions, ..
             }| {
                let mut starts = vec![0u32; slice_count + 1];
                for &at in positions {
                    starts[usize::from(slices[at as usize]) - first_slice + 1] += 1;
                }
                for slice in 0..slice_count {
                    starts[slice + 1] += starts[slice];
                }
                let mut cursor = starts.clone();
                let mut order = vec![0u32; positions.len()];
                for &at in positions {
                    let slot = &mut cursor[usize::from(slices[at as usize]) - first_slice];
                    order[*slot as usize] = at;
                    *slot += 1;
                }
                (starts, order)
            },
        )
        .collect();
    // Where each slice's discs start in the result.
    let mut starts = vec![0usize; slice_count + 1];
    for (chunk_starts, _) in &orders {
        for (slice, run) in chunk_starts.windows(2).enumerate() {
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
    // Written once in parallel, then each group's part filled by its own task.
    let mut all: Vec<Disc> = (0..total).into_par_iter().map(|_| Disc::NONE).collect();
    let mut parts = Vec::with_capacity(bounds.len() - 1);
    let mut rest = all.as_mut_slice();
    for group in bounds.windows(2) {
        let len = starts[group[1]] - starts[group[0]];
        let (part, after) = std::mem::take(&mut rest).split_at_mut(len);
        parts.push((group[0]..group[1], part));
        rest = after;
    }
    parts.into_par_iter().for_each(|(group, part)| {
        let first = group.start;
        let offset = starts[group.start];
        let mut cursor: Vec<usize> = starts[group.clone()]
            .iter()
            .map(|start| start - offset)
            .collect();
        for (kept, (chunk_starts, order)) in kept.iter().zip(&orders) {
            let mine = chunk_starts[group.start] as usize..chunk_starts[group.end] as usize;
            for &at in &order[mine] {
                let slice = usize::from(kept.slices[at as usize]) - first_slice;
                let slot = &mut cursor[slice - first];
                part[*slot] = kept.discs[at as usize];
                *slot += 1;
            }
        }
    });
    all
}

/// [`by_slice`] on one thread: each kept disc moved once, straight to its place (a slice's
/// cursor), in chunk order. The chunks' orders by slice, which let the threads' groups skip what
/// is not theirs, cost more than the sort itself on one thread.
fn by_slice_on_one_thread(kept: &[Kept<'_>], slices: Range<usize>) -> Vec<Disc> {
    let first_slice = slices.start;
    let mut cursor = vec![0usize; slices.len() + 1];
    for kept in kept {
        for &at in kept.positions {
            cursor[usize::from(kept.slices[at as usize]) - first_slice + 1] += 1;
        }
    }
    for slice in 0..slices.len() {
        cursor[slice + 1] += cursor[slice];
    }
    let mut all = vec![Disc::NONE; cursor[slices.len()]];
    for kept in kept {
        for &at in kept.positions {
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
    use crate::render::rng::SplitMix64;

    /// A chunk: each disc's slice (in `slices`), the discs (sphere ids from `first_id`) and the
    /// positions kept (about half, increasing, as the cull makes them).
    struct Chunk {
        slices: Vec<u16>,
        discs: Vec<Disc>,
        positions: Vec<u32>,
    }

    fn chunk(rng: &mut SplitMix64, len: usize, slices: &Range<usize>, first_id: u32) -> Chunk {
        let span = slices.len() as u64;
        let slice_of = |rng: &mut SplitMix64| (slices.start as u64 + rng.next_u64() % span) as u16;
        Chunk {
            slices: (0..len).map(|_| slice_of(rng)).collect(),
            discs: (first_id..first_id + len as u32)
                .map(|sphere| Disc {
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
    fn expected(chunks: &[Chunk]) -> Vec<u32> {
        let mut kept: Vec<(u16, u32)> = chunks
            .iter()
            .flat_map(|c| {
                c.positions
                    .iter()
                    .map(|&at| (c.slices[at as usize], c.discs[at as usize].sphere))
            })
            .collect();
        kept.sort_by_key(|&(slice, _)| slice);
        kept.into_iter().map(|(_, sphere)| sphere).collect()
    }

    #[test]
    fn the_sort_keeps_every_kept_disc_by_slice_then_chunk_on_any_thread_count() {
        let mut rng = SplitMix64::new(11);
        // (chunk lengths, the pass's slices): empty chunks, a range far from 0, one slice, and
        // fewer slices than threads.
        let cases: [(&[usize], Range<usize>); 4] = [
            (&[300, 0, 257, 1, 0, 999], 0..4096),
            (&[500, 500, 500], 3000..3017),
            (&[400, 0, 400], 77..78),
            (&[50, 60], 10..12),
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
            let kept: Vec<Kept<'_>> = chunks
                .iter()
                .map(|c| Kept {
                    slices: &c.slices,
                    discs: &c.discs,
                    positions: &c.positions,
                })
                .collect();
            let want = expected(&chunks);
            for threads in [1, 2, 5, 16] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                let got: Vec<u32> = pool
                    .install(|| by_slice(&kept, slices.clone()))
                    .iter()
                    .map(|disc| disc.sphere)
                    .collect();
                assert_eq!(got, want, "slices {slices:?}, {threads} threads");
            }
        }
    }
}
