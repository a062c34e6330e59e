//! Binning: each disc is listed in the bands of [`BAND_ROWS`] rows its screen extent touches, so
//! a band tests only its own discs; and the conservative pixel spans (rows of a disc, columns of a
//! chord) that bound which pixels the exact test looks at.

use rayon::prelude::*;

use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

/// Rows per band: the unit of binning and of parallel work.
pub(crate) const BAND_ROWS: usize = 8;

/// Discs listed per band of [`BAND_ROWS`] rows, binned in parallel: the discs are split into
/// consecutive chunks, each chunk lists its discs per band (compressed rows), and a band's list is
/// the chunks' lists one after the other — the order the discs came in, with no serial merge.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Bands {
    chunks: Vec<ChunkBands>,
}

/// One chunk's lists: band `b`'s discs are `indices[offsets[b]..offsets[b + 1]]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct ChunkBands {
    offsets: Vec<usize>,
    indices: Vec<u32>,
}

impl ChunkBands {
    /// The indices listed in band `band` (none past the last band).
    pub(crate) fn band(&self, band: usize) -> &[u32] {
        match self.offsets.get(band..=band + 1) {
            Some(&[start, end]) => &self.indices[start..end],
            _ => &[],
        }
    }
}

impl Bands {
    /// The discs (indices into the projected discs) listed in band `band`, in the order they
    /// came in.
    pub(crate) fn band(&self, band: usize) -> impl Iterator<Item = u32> + '_ {
        self.chunks
            .iter()
            .flat_map(move |chunk| chunk.band(band).iter().copied())
    }

    #[cfg(test)]
    /// How many (disc, band) entries the lists hold.
    pub(crate) fn listed(&self) -> usize {
        self.chunks.iter().map(|chunk| chunk.indices.len()).sum()
    }
}

/// Image rows (top row first) `[first, last]` whose centres a disc may cover (conservative by
/// [`SPAN_MARGIN`]).
pub(super) fn row_span(grid: &PixelGrid, disc: &Disc) -> Option<(usize, usize)> {
    rows_of(grid, disc.v, disc.radius_sq.sqrt())
}

/// [`row_span`] of a disc at screen `v` with radius `radius` (its r², square-rooted).
#[inline]
pub(super) fn rows_of(grid: &PixelGrid, v: f64, radius: f64) -> Option<(usize, usize)> {
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    // y_up (from the bottom) of a screen v: v = (y_up + ½ − height/2)·s.
    let offset = 0.5 * f64::from(grid.height_px) - 0.5;
    let max_row = grid.height_px as usize - 1;
    let radius_px = radius * inverse_pixel;
    let centre_px = v * inverse_pixel + offset;
    let (low, high) = centre_span(
        centre_px - radius_px,
        centre_px + radius_px,
        radius_px,
        max_row,
    )?;
    // Rows count from the top: row = height − 1 − y_up.
    Some((max_row - high, max_row - low))
}

/// The margin of [`centre_span`], relative to the sizes in pixels involved. The exact test can
/// accept a pixel up to about √(2ε)·r ≈ 2·10⁻⁸ of the radius beyond where the f64 chord ends
/// (where a row grazes the rim, the chord's r² − dv² cancels), and the pixel's and the disc's
/// coordinates are each rounded to about 10⁻¹⁶ of their size: this margin is fifty times the
/// first and still a small part of a pixel in any view whose discs are under ten thousand
/// pixels across.
pub(super) const SPAN_MARGIN: f64 = 1e-6;

/// Whole pixel indices `[first, last]` within `[0, max_index]` whose centres lie within the
/// fractional pixel coordinates `[low, high]` widened by the margin [`SPAN_MARGIN`] of `reach_px`
/// (the disc's radius in pixels), of the coordinates and of the image; `None` when that misses
/// `[0, max_index]` or is NaN. For the centre samples of the disc renderer: a pixel outside cannot
/// pass the exact test, so it is not tested. Truncating conversions instead of `floor`/`ceil`
/// (library calls on baseline x86-64, in the hottest loop).
#[inline]
pub(super) fn centre_span(
    low: f64,
    high: f64,
    reach_px: f64,
    max_index: usize,
) -> Option<(usize, usize)> {
    let max = max_index as f64;
    let margin = SPAN_MARGIN * (1.0 + reach_px + low.abs() + high.abs() + max);
    let (low, high) = (low - margin, high + margin);
    // NaN fails both tests.
    let reaches_the_range = low <= max && high >= 0.0;
    if !reaches_the_range {
        return None;
    }
    // ceil(low) for low > 0: the truncation, plus one unless low is whole.
    let first = if low > 0.0 {
        let below = low as usize;
        below + usize::from((below as f64) < low)
    } else {
        0
    };
    // floor(high) = trunc(high) for high ≥ 0.
    let last = if high < max { high as usize } else { max_index };
    (first <= last).then_some((first, last))
}

/// Whole pixel indices `[first, last]` within `[0, max_index]` covering the fractional pixel
/// coordinates `[low, high]` widened by at least one pixel each side (conservative: the exact
/// test decides); `None` when that misses `[0, max_index]` or is NaN. Truncating conversions
/// instead of `floor`/`ceil` (library calls on baseline x86-64, in the hottest loop) and no
/// division.
#[inline]
pub(crate) fn pixel_span(low: f64, high: f64, max_index: usize) -> Option<(usize, usize)> {
    let max = max_index as f64;
    // NaN fails both tests.
    let reaches_the_range = low < max + 2.0 && high > -2.0;
    if !reaches_the_range {
        return None;
    }
    // For low ≥ 1, (low − 1) truncated is floor(low) − 1; below, the first index is 0.
    let first = if low >= 1.0 { (low - 1.0) as usize } else { 0 };
    // trunc(high + 1) + 1 ≥ ceil(high) + 1 (high + 1 > −1 here).
    let last = if high + 1.0 < max {
        (high + 1.0) as usize + 1
    } else {
        max_index
    };
    (first <= last).then_some((first, last.min(max_index)))
}

/// Columns `[first, last]` (clamped to the image) whose pixel centres may lie within
/// `half_chord_px` pixels of column coordinate `center_column` (`u / s + width/2 − ½`), of a disc
/// of radius `radius_px` pixels. Conservative by [`SPAN_MARGIN`]; the exact test decides.
#[inline]
pub(super) fn column_span(
    grid: &PixelGrid,
    center_column: f64,
    half_chord_px: f64,
    radius_px: f64,
) -> Option<(usize, usize)> {
    centre_span(
        center_column - half_chord_px,
        center_column + half_chord_px,
        radius_px,
        grid.width_px as usize - 1,
    )
}

/// Smallest chunk of discs binned by one task: small enough that a few tens of thousands of discs
/// still bin on every thread.
const MIN_BIN_CHUNK: usize = 1024;

/// Discs binned by one task, of `len` ([`bin_by_rows`], and the parts of a frame drawn in any
/// order: `placed::place_in_parts`): about four tasks a thread, none under [`MIN_BIN_CHUNK`].
pub(super) fn bin_chunk_len(len: usize) -> usize {
    len.div_ceil(4 * rayon::current_num_threads())
        .max(MIN_BIN_CHUNK)
}

/// Lists each disc in the bands its rows touch: chunks in parallel, each in two passes (count,
/// then fill).
pub(crate) fn bin_discs(discs: &[Disc], grid: &PixelGrid) -> Bands {
    bin_by_rows(discs, grid, |disc| row_span(grid, disc))
}

/// Lists each of `items` in the bands of the image rows `rows` gives it (top row first, `None`:
/// off the image), in the order they come: chunks in parallel, each in two passes (count, then
/// fill).
pub(crate) fn bin_by_rows<T: Sync>(
    items: &[T],
    grid: &PixelGrid,
    rows: impl Fn(&T) -> Option<(usize, usize)> + Sync,
) -> Bands {
    let band_count = band_count(grid);
    let chunk_len = bin_chunk_len(items.len());
    let chunks = items
        .par_chunks(chunk_len)
        .enumerate()
        .map(|(chunk_index, chunk)| {
            // Sphere counts fit u32 (the parser's limit), so do disc indices.
            let first_index = u32::try_from(chunk_index * chunk_len).unwrap_or(u32::MAX);
            bin_part(chunk, first_index, band_count, &rows)
        })
        .collect();
    Bands { chunks }
}

/// The band lists of `items`, consecutive items of a frame's list whose first has index
/// `first_index`, in `band_count` bands by the image rows `rows` gives each (the lists of a
/// chunk of [`bin_by_rows`], or of a part of placed discs: `placed::PlacedPart`).
pub(crate) fn bin_part<T>(
    items: &[T],
    first_index: u32,
    band_count: usize,
    rows: impl Fn(&T) -> Option<(usize, usize)>,
) -> ChunkBands {
    let spans: Vec<Option<(usize, usize)>> = items
        .iter()
        .map(|item| rows(item).map(|(first, last)| (first / BAND_ROWS, last / BAND_ROWS)))
        .collect();
    bin_chunk(&spans, first_index, band_count)
}

/// The bands of `grid`.
pub(crate) fn band_count(grid: &PixelGrid) -> usize {
    (grid.height_px as usize).div_ceil(BAND_ROWS)
}

/// Bins items by their band spans (the first item has index `first_index`) into `band_count`
/// bands.
fn bin_chunk(spans: &[Option<(usize, usize)>], first_index: u32, band_count: usize) -> ChunkBands {
    let mut offsets = vec![0usize; band_count + 1];
    for &(first, last) in spans.iter().flatten() {
        for count in &mut offsets[first + 1..=last + 1] {
            *count += 1;
        }
    }
    for band in 0..band_count {
        offsets[band + 1] += offsets[band];
    }
    let mut cursor = offsets.clone();
    let mut indices = vec![0u32; offsets[band_count]];
    for (index, span) in (first_index..).zip(spans) {
        if let &Some((first, last)) = span {
            for band in first..=last {
                indices[cursor[band]] = index;
                cursor[band] += 1;
            }
        }
    }
    ChunkBands { offsets, indices }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_spans_hold_every_index_within_a_pixel_of_the_range() {
        let mut rng = crate::render::rng::SplitMix64::new(5);
        let max_index = 99usize;
        for case in 0..100_000 {
            let centre = rng.uniform(-110.0, 210.0);
            let half = if case % 7 == 0 {
                0.0
            } else {
                rng.log_uniform(1e-6, 300.0)
            };
            let (low, high) = (centre - half, centre + half);
            // What floor/ceil with a one-pixel margin would cover.
            let wanted_first = (low.floor() - 1.0).max(0.0);
            let wanted_last = (high.ceil() + 1.0).min(max_index as f64);
            match pixel_span(low, high, max_index) {
                Some((first, last)) => {
                    assert!(first as f64 <= wanted_first && last as f64 >= wanted_last);
                    assert!(first <= last && last <= max_index);
                }
                None => assert!(wanted_first > wanted_last, "{low} {high}"),
            }
        }
        assert_eq!(pixel_span(f64::NAN, 5.0, max_index), None);
        assert_eq!(pixel_span(1.0, f64::NAN, max_index), None);
        assert_eq!(
            pixel_span(f64::NEG_INFINITY, f64::INFINITY, max_index),
            Some((0, 99))
        );
        assert_eq!(pixel_span(1e300, 2e300, max_index), None);
    }

    #[test]
    fn bands_list_each_disc_where_its_rows_are_in_file_order() {
        let grid = PixelGrid::new(32, 32, 32.0); // one world unit per pixel
        let disc = |v: f64, r: f64, sphere| Disc {
            u: 0.0,
            v,
            w: 0.0,
            radius_sq: r * r,
            sphere,
        };
        // Top band holds rows 0..8 (v from 16 down to 8); the disc at v = 12 sits in it.
        let discs = [disc(12.0, 1.0, 0), disc(-100.0, 1.0, 1), disc(0.0, 20.0, 2)];
        let bands = bin_discs(&discs, &grid);
        let band = |b: usize| bands.band(b).collect::<Vec<_>>();
        assert_eq!(band(0), [0, 2]);
        assert!(band(4).is_empty(), "four bands of eight rows");
        assert!(
            (0..4).all(|b| !band(b).contains(&1)),
            "off-screen disc listed nowhere"
        );
        assert_eq!(bands.listed(), 5);
        for b in 1..4 {
            assert!(band(b).contains(&2), "the big disc is in every band");
        }
    }
}
