//! Discs placed on the image for the tiles: each disc's nearest t and the rows
//! and columns its pixels may lie in, worked out once, and listed in the bands of rows it touches
//! — in parts, each part's discs placed and binned by one task, so that placing and binning are
//! one parallel step.

use rayon::prelude::*;

use super::bins::{ChunkBands, band_count, bin_chunk_len, bin_part, column_span, rows_of};
use super::screen_disc::Disc;
use crate::geometry::camera::PixelGrid;

/// A disc placed on the image: its nearest t and the image rows (top first) and columns its
/// pixels may lie in, conservative (the exact test decides).
#[derive(Clone, Copy)]
pub(super) struct Placed {
    pub(super) disc: Disc,
    pub(super) front_t: f64,
    pub(super) rows: (u32, u32),
    pub(super) columns: (u32, u32),
}

impl Placed {
    /// A disc off the image: binned nowhere (its first row is past its last).
    const OFF: Self = Self {
        disc: Disc::NONE,
        front_t: f64::INFINITY,
        rows: (1, 0),
        columns: (0, 0),
    };

    /// The image rows (top first) it is binned in; `None` off the image.
    pub(super) fn binned_rows(&self) -> Option<(usize, usize)> {
        let (first, last) = self.rows;
        (first <= last).then_some((first as usize, last as usize))
    }

    /// `disc` placed on `grid`; [`Self::OFF`] off the image (binned nowhere).
    pub(super) fn on(disc: &Disc, grid: &PixelGrid) -> Self {
        Self::of(disc, grid).unwrap_or(Self::OFF)
    }

    /// `disc` placed on `grid`; `None` off the image.
    fn of(disc: &Disc, grid: &PixelGrid) -> Option<Self> {
        let radius = disc.radius_sq.sqrt();
        let inverse_pixel = 1.0 / grid.pixel_size_world;
        let radius_px = radius * inverse_pixel;
        let centre_column = disc.u * inverse_pixel + 0.5 * f64::from(grid.width_px) - 0.5;
        let columns = column_span(grid, centre_column, radius_px, radius_px)?;
        let rows = rows_of(grid, disc.v, radius)?;
        // Image sides fit u32.
        Some(Self {
            disc: *disc,
            front_t: disc.front_t(),
            rows: (rows.0 as u32, rows.1 as u32),
            columns: (columns.0 as u32, columns.1 as u32),
        })
    }
}

/// Consecutive discs of a frame's list, placed, with the bands each is listed in (positions in
/// this part).
pub(super) struct PlacedPart {
    pub(super) placed: Vec<Placed>,
    bands: ChunkBands,
}

impl PlacedPart {
    /// `discs` placed on `grid` and binned, in the order they come (one task).
    pub(super) fn of(discs: &[Disc], grid: &PixelGrid) -> Self {
        let placed: Vec<Placed> = discs.iter().map(|disc| Placed::on(disc, grid)).collect();
        let bands = bin_part(&placed, 0, band_count(grid), Placed::binned_rows);
        Self { placed, bands }
    }

    /// The discs listed in band `band`, in the order they come.
    pub(super) fn band(&self, band: usize) -> impl Iterator<Item = &Placed> {
        self.bands
            .band(band)
            .iter()
            .map(|&at| &self.placed[at as usize])
    }

    /// How many discs band `band` lists.
    pub(super) fn band_len(&self, band: usize) -> usize {
        self.bands.band(band).len()
    }
}

/// `discs` placed on `grid` and binned, in consecutive parts in parallel (one step).
pub(super) fn place_in_parts(discs: &[Disc], grid: &PixelGrid) -> Vec<PlacedPart> {
    discs
        .par_chunks(bin_chunk_len(discs.len()))
        .map(|discs| PlacedPart::of(discs, grid))
        .collect()
}
