//! The fast path: spheres projected to screen discs, binned into bands of rows, rasterised band
//! by band in parallel.
//!
//! Each sphere's centre is moved into camera space once per frame, in f64 and relative to the
//! camera centre, so coordinates of 1e7 cost no precision. For a pixel at screen (u, v) and a disc
//! (c_u, c_v, r) the test is `du² + dv² ≤ r²` with `du = u − c_u`, `dv = v − c_v` — the same
//! expression everywhere, so hit/miss is decided once — and the visible depth is
//! `t = c_w − √(r² − du² − dv²)` (tmin = −∞: the front root even behind the camera centre).
//!
//! Cost: a disc is listed in the bands its rows touch; within a row only the columns its chord can
//! cover are tested. A frame costs in proportion to the discs plus the pixels they cover, not to
//! pixels × spheres. Ties keep the sphere that comes first in the file (bands list discs in file
//! order and a hit replaces the current one only when strictly nearer).
//!
//! The per-pixel arithmetic is generic over [`Real`]: f64 (exact mode) or f32 (fast mode); the
//! projection and the column spans are always f64.

use std::ops::{Add, Mul, Sub};

use rayon::prelude::*;

use super::{Frame, NO_HIT, Precision, View, ViewError};
use crate::geometry::camera::{CameraBasis, PixelGrid};
use crate::render::depth_map::quantize_f32;
use crate::scene::Scene;

/// Rows per band: the unit of binning and of parallel work.
pub const BAND_ROWS: usize = 8;

/// A sphere projected into camera space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Screen u of the centre (world units, relative to the camera centre).
    pub u: f64,
    /// Screen v of the centre.
    pub v: f64,
    /// Depth of the centre along the view direction (t of the centre).
    pub w: f64,
    /// r², the disc's squared radius.
    pub radius_sq: f64,
    /// Index of the sphere in file order.
    pub sphere: u32,
}

impl Disc {
    /// t of the front surface at screen (u, v), or `None` outside the disc. Tangent points hit.
    #[inline]
    pub fn hit_t(&self, u: f64, v: f64) -> Option<f64> {
        let du = u - self.u;
        let dv = v - self.v;
        let distance_sq = du * du + dv * dv;
        (distance_sq <= self.radius_sq).then(|| self.w - (self.radius_sq - distance_sq).sqrt())
    }
}

/// Projects every sphere of `scene` into the camera space of `view` (basis from
/// [`View::validate`]), in file order.
pub fn project_discs(scene: &Scene, view: &View, basis: &CameraBasis) -> Vec<Disc> {
    scene
        .spheres
        .iter()
        .zip(0u32..)
        .map(|(sphere, index)| {
            let center_camera = basis.to_camera(sphere.center_world - view.center_world);
            Disc {
                u: center_camera.x,
                v: center_camera.y,
                w: center_camera.z,
                radius_sq: sphere.radius_world * sphere.radius_world,
                sphere: index,
            }
        })
        .collect()
}

/// The visible hit at screen (u, v) among `discs`: (t, sphere), smallest t, first in file order
/// on a tie.
pub fn nearest_hit(discs: &[Disc], u: f64, v: f64) -> Option<(f64, u32)> {
    let mut best: Option<(f64, u32)> = None;
    for disc in discs {
        if let Some(t) = disc.hit_t(u, v)
            && best.is_none_or(|(best_t, _)| t < best_t)
        {
            best = Some((t, disc.sphere));
        }
    }
    best
}

/// Discs listed per band of [`BAND_ROWS`] rows, binned in parallel: the discs are split into
/// consecutive chunks, each chunk lists its discs per band (compressed rows), and a band's list is
/// the chunks' lists one after the other — file order, with no serial merge.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Bands {
    chunks: Vec<ChunkBands>,
}

/// One chunk's lists: band `b`'s discs are `indices[offsets[b]..offsets[b + 1]]`.
#[derive(Debug, Clone, PartialEq, Eq)]
struct ChunkBands {
    offsets: Vec<usize>,
    indices: Vec<u32>,
}

impl Bands {
    /// The discs (indices into the projected discs) listed in band `band`, in file order.
    pub fn band(&self, band: usize) -> impl Iterator<Item = u32> + '_ {
        self.chunks.iter().flat_map(move |chunk| {
            let listed = match chunk.offsets.get(band..=band + 1) {
                Some(&[start, end]) => &chunk.indices[start..end],
                _ => &[],
            };
            listed.iter().copied()
        })
    }

    /// How many (disc, band) entries the lists hold.
    pub fn listed(&self) -> usize {
        self.chunks.iter().map(|chunk| chunk.indices.len()).sum()
    }
}

/// Image rows (top row first) `[first, last]` whose centres a disc may cover; conservative by
/// one row.
fn row_span(grid: &PixelGrid, disc: &Disc) -> Option<(usize, usize)> {
    let radius = disc.radius_sq.sqrt();
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    // y_up (from the bottom) of a screen v: v = (y_up + ½ − height/2)·s.
    let offset = 0.5 * f64::from(grid.height_px) - 0.5;
    let max_row = grid.height_px as usize - 1;
    let (low, high) = pixel_span(
        (disc.v - radius) * inverse_pixel + offset,
        (disc.v + radius) * inverse_pixel + offset,
        max_row,
    )?;
    // Rows count from the top: row = height − 1 − y_up.
    Some((max_row - high, max_row - low))
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
/// `half_chord_px` pixels of column coordinate `center_column` (`u / s + width/2 − ½`).
/// Conservative by one pixel; the exact test decides.
#[inline]
fn column_span(grid: &PixelGrid, center_column: f64, half_chord_px: f64) -> Option<(usize, usize)> {
    pixel_span(
        center_column - half_chord_px,
        center_column + half_chord_px,
        grid.width_px as usize - 1,
    )
}

/// Smallest chunk of discs binned by one task.
const MIN_BIN_CHUNK: usize = 16_384;

/// Lists each disc in the bands its rows touch: chunks in parallel, each in two passes (count,
/// then fill).
pub fn bin_discs(discs: &[Disc], grid: &PixelGrid) -> Bands {
    let band_count = (grid.height_px as usize).div_ceil(BAND_ROWS);
    let chunk_len = discs
        .len()
        .div_ceil(4 * rayon::current_num_threads())
        .max(MIN_BIN_CHUNK);
    let chunks = discs
        .par_chunks(chunk_len)
        .enumerate()
        .map(|(chunk_index, chunk)| {
            // Sphere counts fit u32 (the parser's limit), so do disc indices.
            let first_index = u32::try_from(chunk_index * chunk_len).unwrap_or(u32::MAX);
            bin_chunk(chunk, first_index, grid, band_count)
        })
        .collect();
    Bands { chunks }
}

/// Bins `discs` (the first has index `first_index`) into `band_count` bands.
fn bin_chunk(discs: &[Disc], first_index: u32, grid: &PixelGrid, band_count: usize) -> ChunkBands {
    let spans: Vec<Option<(usize, usize)>> = discs
        .iter()
        .map(|disc| row_span(grid, disc).map(|(first, last)| (first / BAND_ROWS, last / BAND_ROWS)))
        .collect();
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
    for (index, span) in (first_index..).zip(&spans) {
        if let &Some((first, last)) = span {
            for band in first..=last {
                indices[cursor[band]] = index;
                cursor[band] += 1;
            }
        }
    }
    ChunkBands { offsets, indices }
}

/// The floating-point type of the per-pixel arithmetic.
pub trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// The mode this type implements.
    const PRECISION: Precision;
    /// Unit roundoff, if coarser than f64's (then uncertain decisions are re-made in f64); 0 for
    /// f64.
    const ROUNDOFF: f64;
    /// Zero.
    const ZERO: Self;
    /// +∞ (no hit).
    const INFINITY: Self;
    /// Rounds an f64 to this type.
    fn from_f64(value: f64) -> Self;
    /// Widens to f64.
    fn to_f64(self) -> f64;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// Division.
    fn div(self, other: Self) -> Self;
    /// The same buffer seen as this type, when it is f64 (so f64 kernels write in place).
    fn as_self_slice(buffer: &mut [f64]) -> Option<&mut [Self]>;
}

impl Real for f64 {
    const PRECISION: Precision = Precision::F64;
    const ROUNDOFF: f64 = 0.0;
    const ZERO: Self = 0.0;
    const INFINITY: Self = f64::INFINITY;
    fn from_f64(value: f64) -> Self {
        value
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
    fn div(self, other: Self) -> Self {
        self / other
    }
    fn as_self_slice(buffer: &mut [f64]) -> Option<&mut [Self]> {
        Some(buffer)
    }
}

impl Real for f32 {
    const PRECISION: Precision = Precision::F32;
    const ROUNDOFF: f64 = 5.960_464_477_539_063e-8;
    const ZERO: Self = 0.0;
    const INFINITY: Self = f32::INFINITY;
    fn from_f64(value: f64) -> Self {
        value as f32
    }
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    fn sqrt(self) -> Self {
        f32::sqrt(self)
    }
    fn abs(self) -> Self {
        f32::abs(self)
    }
    fn div(self, other: Self) -> Self {
        self / other
    }
    fn as_self_slice(_buffer: &mut [f64]) -> Option<&mut [Self]> {
        None
    }
}

/// A disc in the per-pixel type.
#[derive(Debug, Clone, Copy)]
struct DiscIn<R> {
    u: R,
    v: R,
    w: R,
    radius_sq: R,
}

/// The disc test at one pixel, in the per-pixel type.
struct PixelHit<R> {
    /// Squared screen distance from the disc's centre.
    distance_sq: R,
    /// r² − distance²: ≥ 0 inside the disc.
    rest: R,
    /// √max(rest, 0).
    root: R,
    /// t of the front surface (meaningful inside the disc).
    t: R,
}

/// Tests pixel column `u` (screen) against `disc` on a row `dv_sq` = (v − c_v)² away.
#[inline(always)]
fn pixel_hit<R: Real>(disc: &DiscIn<R>, u: R, dv_sq: R) -> PixelHit<R> {
    let du = u - disc.u;
    let distance_sq = du * du + dv_sq;
    let rest = disc.radius_sq - distance_sq;
    let root = (if rest > R::ZERO { rest } else { R::ZERO }).sqrt();
    PixelHit {
        distance_sq,
        rest,
        root,
        t: disc.w - root,
    }
}

/// One band's output buffers.
struct BandOut<'a, R> {
    /// t per pixel.
    t: &'a mut [R],
    /// Sphere per pixel.
    sphere: &'a mut [u32],
    /// Error bound of the stored t per pixel (only for types with [`Real::ROUNDOFF`] > 0).
    t_error: &'a mut [R],
}

/// Fills one band (rows `first_row..first_row + rows`, top first) of t and sphere indices.
///
/// In a type with rounding coarser than f64 (f32), a pixel whose decision that type cannot make
/// with certainty — within its error bound of a silhouette (`r² − d²`) or of a tie with the sphere
/// already there — is re-decided in f64, so coverage is exact in every mode and only t carries
/// the coarser rounding.
fn rasterise_band<R: Real>(
    discs: &[Disc],
    list: impl Iterator<Item = u32>,
    grid: &PixelGrid,
    first_row: usize,
    out: BandOut<'_, R>,
) -> u64 {
    let mut disc_tests = 0u64;
    let width = grid.width_px as usize;
    let height = grid.height_px as usize;
    let pixel_size = R::from_f64(grid.pixel_size_world);
    let column_offset = R::from_f64(0.5 - 0.5 * f64::from(grid.width_px));
    let refine = R::ROUNDOFF > 0.0;
    // The band's discs gathered once, contiguous and in file order: the rows below read them
    // sequentially instead of chasing indices across the whole scene (cache misses dominated).
    // With each, its centre's column coordinate (u / s + width/2 − ½) for the column spans.
    let inverse_pixel = 1.0 / grid.pixel_size_world;
    let centre_column_offset = 0.5 * f64::from(grid.width_px) - 0.5;
    let band_discs: Vec<(Disc, f64)> = list
        .map(|index| {
            let disc = discs[index as usize];
            (disc, disc.u * inverse_pixel + centre_column_offset)
        })
        .collect();
    for (row_in_band, (t_row, sphere_row)) in out
        .t
        .chunks_mut(width)
        .zip(out.sphere.chunks_mut(width))
        .enumerate()
    {
        let error_row: &mut [R] = if refine {
            &mut out.t_error[row_in_band * width..(row_in_band + 1) * width]
        } else {
            &mut []
        };
        let y_up = (height - 1 - (first_row + row_in_band)) as f64;
        let v = grid.v_of_row(y_up);
        let v_in = R::from_f64(v);
        for (disc, centre_column) in &band_discs {
            // Span in f64 (conservative); the per-pixel test in R decides.
            let dv = v - disc.v;
            let chord_sq = disc.radius_sq - dv * dv;
            if chord_sq.is_nan() || chord_sq < -disc.radius_sq * 1e-6 {
                continue;
            }
            let half_chord_px = chord_sq.max(0.0).sqrt() * inverse_pixel;
            let Some((first, last)) = column_span(grid, *centre_column, half_chord_px) else {
                continue;
            };
            disc_tests += (last - first + 1) as u64;
            // The disc in the per-pixel type (free for f64).
            let disc_in = DiscIn {
                u: R::from_f64(disc.u),
                v: R::from_f64(disc.v),
                w: R::from_f64(disc.w),
                radius_sq: R::from_f64(disc.radius_sq),
            };
            let dv_in = v_in - disc_in.v;
            let dv_sq = dv_in * dv_in;
            // Error bounds of R's arithmetic for this disc on this row (f64 types: zero).
            let (coverage_tolerance, t_error_flat, t_error_steep) = if refine {
                let radius = disc.radius_sq.sqrt();
                let largest = disc
                    .u
                    .abs()
                    .max(disc.v.abs())
                    .max(v.abs())
                    .max(grid.u_of_column(first as f64).abs())
                    .max(grid.u_of_column(last as f64).abs())
                    + radius;
                let coverage = 32.0 * R::ROUNDOFF * largest * largest;
                (
                    R::from_f64(coverage),
                    R::from_f64(8.0 * R::ROUNDOFF * (disc.w.abs() + radius)),
                    R::from_f64(coverage),
                )
            } else {
                (R::ZERO, R::ZERO, R::ZERO)
            };
            if !refine {
                // The exact types' loop: over slices (no bounds checks), branch-free selects.
                let t_span = &mut t_row[first..last + 1];
                let sphere_span = &mut sphere_row[first..last + 1];
                for ((x, t_px), sphere_px) in (first..).zip(t_span).zip(sphere_span) {
                    let u = (R::from_f64(x as f64) + column_offset) * pixel_size;
                    let PixelHit { distance_sq, t, .. } = pixel_hit(&disc_in, u, dv_sq);
                    let closer = distance_sq <= disc_in.radius_sq && t < *t_px;
                    *t_px = if closer { t } else { *t_px };
                    *sphere_px = if closer { disc.sphere } else { *sphere_px };
                }
                continue;
            }
            for x in first..last + 1 {
                let u = (R::from_f64(x as f64) + column_offset) * pixel_size;
                let PixelHit { rest, root, t, .. } = pixel_hit(&disc_in, u, dv_sq);
                // t's error: flat part plus the part that grows towards the silhouette.
                let t_error = t_error_flat + t_error_steep.div(root);
                let uncertain_coverage = rest.abs() <= coverage_tolerance;
                let uncertain_order =
                    sphere_row[x] != NO_HIT && (t - t_row[x]).abs() <= t_error + error_row[x];
                if uncertain_coverage || uncertain_order {
                    decide_in_f64(discs, disc, grid, x, v, &mut t_row[x], &mut sphere_row[x]);
                    if sphere_row[x] == disc.sphere {
                        error_row[x] = R::ZERO;
                    }
                    continue;
                }
                let closer = rest >= R::ZERO && t < t_row[x];
                if closer {
                    t_row[x] = t;
                    sphere_row[x] = disc.sphere;
                    error_row[x] = t_error;
                }
            }
        }
    }
    disc_tests
}

/// Decides pixel `x` of the row at screen v in f64: `disc` against the sphere already there.
fn decide_in_f64<R: Real>(
    discs: &[Disc],
    disc: &Disc,
    grid: &PixelGrid,
    x: usize,
    v: f64,
    t_out: &mut R,
    sphere_out: &mut u32,
) {
    let u = grid.u_of_column(x as f64);
    let Some(t) = disc.hit_t(u, v) else {
        return;
    };
    let current = discs
        .get(*sphere_out as usize)
        .and_then(|d| d.hit_t(u, v))
        .unwrap_or(f64::INFINITY);
    if t < current {
        *t_out = R::from_f64(t);
        *sphere_out = disc.sphere;
    } else if current.is_finite() {
        *t_out = R::from_f64(current);
    }
}

/// Renders one centre sample per pixel from projected `discs`, per-pixel arithmetic in `R`.
pub(crate) fn rasterise_frame<R: Real>(
    scene: &Scene,
    view: &View,
    grid: &PixelGrid,
    discs: &[Disc],
) -> Result<Frame, ViewError> {
    let grid = *grid;
    let bands = bin_discs(discs, &grid);
    let width = view.width_px as usize;
    let height = view.height_px as usize;
    // "No hit" everywhere, written in parallel (a `vec![…; n]` fills serially).
    let mut t: Vec<f64> = (0..width * height)
        .into_par_iter()
        .map(|_| f64::INFINITY)
        .collect();
    let mut sphere: Vec<u32> = (0..width * height)
        .into_par_iter()
        .map(|_| NO_HIT)
        .collect();
    let disc_tests = t
        .par_chunks_mut(width * BAND_ROWS)
        .zip(sphere.par_chunks_mut(width * BAND_ROWS))
        .enumerate()
        .map(|(band, (t_band, sphere_band))| {
            let list = bands.band(band);
            let first_row = band * BAND_ROWS;
            match R::as_self_slice(t_band) {
                Some(t_in_place) => {
                    let out = BandOut {
                        t: t_in_place,
                        sphere: sphere_band,
                        t_error: &mut [],
                    };
                    rasterise_band(discs, list, &grid, first_row, out)
                }
                None => {
                    let mut scratch = vec![R::INFINITY; t_band.len()];
                    let mut t_error = vec![R::ZERO; t_band.len()];
                    let out = BandOut {
                        t: &mut scratch,
                        sphere: sphere_band,
                        t_error: &mut t_error,
                    };
                    let tests = rasterise_band(discs, list, &grid, first_row, out);
                    for (out, value) in t_band.iter_mut().zip(&scratch) {
                        *out = value.to_f64();
                    }
                    tests
                }
            }
        })
        .sum::<u64>();
    let mut frame = frame_from_hits(scene, view, t, sphere, R::PRECISION);
    frame.disc_tests = disc_tests;
    Ok(frame)
}

/// Completes a frame from per-pixel t and sphere indices: colour from the sphere's material or
/// the background, quantised to 8 bits.
pub(crate) fn frame_from_hits(
    scene: &Scene,
    view: &View,
    t: Vec<f64>,
    sphere: Vec<u32>,
    precision: Precision,
) -> Frame {
    // Colours per material (few), looked up per pixel: the cost follows the pixels, not the
    // sphere count.
    let material_rgb: Vec<[u8; 3]> = scene
        .materials
        .iter()
        .map(|material| material.diffuse_colour.to_array().map(quantize_f32))
        .collect();
    let default_rgb = crate::scene::DEFAULT_DIFFUSE.to_array().map(quantize_f32);
    let background = scene.background.to_array().map(quantize_f32);
    let colour = sphere
        .par_iter()
        .map(|&index| match scene.spheres.get(index as usize) {
            Some(hit) => hit
                .material
                .and_then(|material| material_rgb.get(material as usize).copied())
                .unwrap_or(default_rgb),
            None => background,
        })
        .collect();
    Frame {
        width_px: view.width_px,
        height_px: view.height_px,
        colour,
        t,
        sphere,
        precision,
        depth_grey: None,
        disc_tests: 0,
    }
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
