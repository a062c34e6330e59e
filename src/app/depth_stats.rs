//! Depth tuning from what a frame shows: the distribution of visible t (a histogram the viewer
//! draws under the depth image) and "auto range", a depth range fitted to the visible t with an
//! optional percentile cut against outliers.
//!
//! "Visible t" is the t of every pixel that hits a sphere in the frame (no-hit pixels, `+∞`,
//! are left out). Both functions work on the frame's raw, one-sample-per-pixel t.

use rayon::prelude::*;

use crate::render::Frame;
use crate::render::depth_map::DepthRange;

/// Pixels per parallel task when counting the histogram.
const PIXELS_PER_TASK: usize = 1 << 16;

/// Counters per histogram bin within a task, taken in turn by consecutive pixels.
const COUNTER_LANES: usize = 4;

/// Largest accepted percentile cut for [`auto_range`] (each end), in percent.
pub(crate) const MAX_PERCENTILE_CUT: f64 = 49.0;

/// The visible t of a frame (finite values only), in storage order.
pub fn visible_t(frame: &Frame) -> Vec<f64> {
    frame.t.iter().copied().filter(|t| t.is_finite()).collect()
}

/// A depth range that brackets the visible t of `frame`: from the `cut_percent` percentile to
/// the `100 − cut_percent` percentile (0 gives the exact nearest and farthest visible t). The
/// percentile is the nearest-rank one: the value at index `round(p/100 · (n − 1))` of the sorted
/// t. `None` when no pixel hits anything. `cut_percent` is clamped to
/// `[0, MAX_PERCENTILE_CUT]` (NaN counts as 0).
pub(crate) fn auto_range(frame: &Frame, cut_percent: f64) -> Option<DepthRange> {
    let mut t = visible_t(frame);
    if t.is_empty() {
        return None;
    }
    let cut = if cut_percent.is_nan() {
        0.0
    } else {
        cut_percent.clamp(0.0, MAX_PERCENTILE_CUT)
    };
    let last = t.len() - 1;
    let rank = |percent: f64| ((percent / 100.0) * last as f64).round() as usize;
    let low_index = rank(cut).min(last);
    let high_index = rank(100.0 - cut).clamp(low_index, last);
    let (_, &mut low, _) = t.select_nth_unstable_by(low_index, f64::total_cmp);
    let (_, &mut high, _) = t.select_nth_unstable_by(high_index, f64::total_cmp);
    Some(DepthRange::new(low, high))
}

/// Counts of visible t in equal-width bins over `[t_low, t_high]`.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthHistogram {
    /// Left edge of the first bin (the nearest visible t).
    pub(crate) t_low: f64,
    /// Right edge of the last bin (the farthest visible t).
    pub(crate) t_high: f64,
    /// Pixels per bin; bin `i` spans `[t_low + i·w, t_low + (i+1)·w)` with the last bin closed.
    pub(crate) counts: Vec<u32>,
    /// Pixels with no hit (not in any bin).
    pub(crate) no_hit: u32,
}

impl DepthHistogram {
    /// The histogram of `frame`'s visible t in `bins` bins (at least 1). `None` when no pixel
    /// hits anything. When every visible t is the same, all of them fall in one bin of a range
    /// of zero width.
    pub fn new(frame: &Frame, bins: usize) -> Option<Self> {
        let bins = bins.max(1);
        // Both passes run in parallel over the frame (a viewer frame has millions of pixels).
        let (low, high, no_hit) = frame
            .t
            .par_iter()
            .fold(
                || (f64::INFINITY, f64::NEG_INFINITY, 0u32),
                |(low, high, no_hit), &t| {
                    if t.is_finite() {
                        (low.min(t), high.max(t), no_hit)
                    } else {
                        (low, high, no_hit.saturating_add(1))
                    }
                },
            )
            .reduce(
                || (f64::INFINITY, f64::NEG_INFINITY, 0u32),
                |a, b| (a.0.min(b.0), a.1.max(b.1), a.2.saturating_add(b.2)),
            );
        if low > high {
            return None;
        }
        let width = high - low;
        // One multiplication per pixel, not a division (a t on a bin's edge may land in either
        // bin: the histogram is read by eye); four counters per bin, so that neighbouring
        // pixels of one depth (most of a dense frame) do not wait on each other's increments.
        let bins_per_t = if width > 0.0 {
            bins as f64 / width
        } else {
            0.0
        };
        let counts = frame
            .t
            .par_chunks(PIXELS_PER_TASK)
            .map(|chunk| {
                let mut lanes = vec![[0u32; COUNTER_LANES]; bins];
                for (index, &t) in chunk.iter().enumerate() {
                    if !t.is_finite() {
                        continue;
                    }
                    // In [0, bins] (NaN, from an infinite scale at t_low, to 0); the farthest
                    // t lands in the last bin. Through i64: a cheaper conversion than to usize.
                    // A task's pixels fit u32.
                    let bin = ((t - low) * bins_per_t) as i64 as usize;
                    lanes[bin.min(bins - 1)][index % COUNTER_LANES] += 1;
                }
                lanes
                    .iter()
                    .map(|lanes| lanes.iter().sum())
                    .collect::<Vec<u32>>()
            })
            .reduce(
                || vec![0u32; bins],
                |mut total, part| {
                    for (sum, count) in total.iter_mut().zip(part) {
                        *sum = sum.saturating_add(count);
                    }
                    total
                },
            );
        Some(Self {
            t_low: low,
            t_high: high,
            counts,
            no_hit,
        })
    }

    /// Width of one bin in t.
    pub(crate) fn bin_width(&self) -> f64 {
        (self.t_high - self.t_low) / self.counts.len() as f64
    }

    /// The largest count (for scaling a plot); 0 for an empty histogram.
    pub(crate) fn max_count(&self) -> u32 {
        self.counts.iter().copied().max().unwrap_or(0)
    }

    /// Visible pixels counted.
    pub(crate) fn total(&self) -> u64 {
        self.counts.iter().map(|&c| u64::from(c)).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::NO_HIT;

    fn frame_of(t: Vec<f64>) -> Frame {
        let n = t.len();
        Frame {
            width_px: n as u32,
            height_px: 1,
            colour: vec![[0; 3]; n],
            sphere: t
                .iter()
                .map(|t| if t.is_finite() { 0 } else { NO_HIT })
                .collect(),
            t,
            depth_grey: None,
            disc_tests: 0,
        }
    }

    #[test]
    fn auto_range_brackets_the_visible_t() {
        let frame = frame_of(vec![f64::INFINITY, 3.0, -1.5, 7.25, 2.0, f64::INFINITY]);
        assert_eq!(auto_range(&frame, 0.0), Some(DepthRange::new(-1.5, 7.25)));
        assert_eq!(
            auto_range(&frame, f64::NAN),
            Some(DepthRange::new(-1.5, 7.25))
        );
        assert_eq!(auto_range(&frame_of(vec![f64::INFINITY; 4]), 1.0), None);
    }

    #[test]
    fn percentile_cut_drops_outliers() {
        // 1000 values 0..999 plus two far outliers.
        let mut t: Vec<f64> = (0..1000).map(f64::from).collect();
        t.push(1e6);
        t.push(-1e6);
        let frame = frame_of(t);
        let range = auto_range(&frame, 1.0).unwrap();
        // Nearest rank: index round(0.01 · 1001) = 10 → value 9; index 991 → value 990.
        assert_eq!(range, DepthRange::new(9.0, 990.0));
        let whole = auto_range(&frame, 0.0).unwrap();
        assert_eq!(whole, DepthRange::new(-1e6, 1e6));
        // The cut is clamped: 80% behaves as 49%.
        assert_eq!(auto_range(&frame, 80.0), auto_range(&frame, 49.0));
        let middle = auto_range(&frame, 49.0).unwrap();
        assert!(middle.min_t <= middle.max_t);
    }

    #[test]
    fn histogram_counts_every_visible_pixel_once() {
        let t = vec![0.0, 0.1, 0.5, 0.99, 1.0, f64::INFINITY, 1.0];
        let histogram = DepthHistogram::new(&frame_of(t), 4).unwrap();
        assert_eq!(histogram.t_low, 0.0);
        assert_eq!(histogram.t_high, 1.0);
        assert_eq!(histogram.counts, vec![2, 0, 1, 3]);
        assert_eq!(histogram.no_hit, 1);
        assert_eq!(histogram.total(), 6);
        assert_eq!(histogram.max_count(), 3);
        assert_eq!(histogram.bin_width(), 0.25);
        // One distinct t: one full bin.
        let flat = DepthHistogram::new(&frame_of(vec![2.0; 5]), 8).unwrap();
        assert_eq!(flat.counts[0], 5);
        assert_eq!(flat.total(), 5);
        assert!(DepthHistogram::new(&frame_of(vec![f64::INFINITY]), 8).is_none());
    }
}
