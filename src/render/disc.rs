//! The fast path: spheres projected to screen discs, rasterised row by row in parallel.
//!
//! Each sphere's centre is moved into camera space once per frame, in f64 and relative to the
//! camera centre, so coordinates of 1e7 cost no precision. For a pixel at screen (u, v) and a disc
//! (c_u, c_v, r) the test is `du² + dv² ≤ r²` with `du = u − c_u`, `dv = v − c_v` — the same
//! expression everywhere, so hit/miss is decided once — and the visible depth is
//! `t = c_w − √(r² − du² − dv²)` (tmin = −∞: the front root even behind the camera centre).
//! Within a row only the pixels a disc's chord can cover are tested; ties keep the sphere that
//! comes first in the file.

use glam::Vec3;
use rayon::prelude::*;

use super::{Frame, NO_HIT, View, ViewError};
use crate::camera::{CameraBasis, PixelGrid};
use crate::scene::Scene;

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

/// Columns `[first, last]` (clamped to the image) whose pixel centres may lie within `half_chord`
/// of screen u `center_u`. Conservative by one pixel; the exact test decides.
fn column_span(grid: &PixelGrid, center_u: f64, half_chord: f64) -> Option<(usize, usize)> {
    let offset = 0.5 * f64::from(grid.width_px) - 0.5;
    let first = ((center_u - half_chord) / grid.pixel_size_world + offset).floor() - 1.0;
    let last = ((center_u + half_chord) / grid.pixel_size_world + offset).ceil() + 1.0;
    let max_column = f64::from(grid.width_px - 1);
    if first.is_nan() || last.is_nan() || first > max_column || last < 0.0 {
        return None;
    }
    // Both ends are finite here and clamped into [0, width − 1].
    Some((first.max(0.0) as usize, last.min(max_column) as usize))
}

/// Fills one image row (screen v = `v`) of t and sphere indices.
fn rasterise_row(
    discs: &[Disc],
    grid: &PixelGrid,
    v: f64,
    t_row: &mut [f64],
    sphere_row: &mut [u32],
) {
    for disc in discs {
        let dv = v - disc.v;
        let chord_sq = disc.radius_sq - dv * dv;
        if chord_sq.is_nan() || chord_sq < 0.0 {
            continue;
        }
        let Some((first, last)) = column_span(grid, disc.u, chord_sq.sqrt()) else {
            continue;
        };
        for x in first..=last {
            let u = grid.u_of_column(x as f64);
            if let Some(t) = disc.hit_t(u, v)
                && t < t_row[x]
            {
                t_row[x] = t;
                sphere_row[x] = disc.sphere;
            }
        }
    }
}

/// Renders with projected discs, rows in parallel (see the module docs).
pub fn render_discs(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    let basis = view.validate()?;
    let grid = view.grid();
    let discs = project_discs(scene, view, &basis);
    let width = view.width_px as usize;
    let height = view.height_px as usize;
    let mut t = vec![f64::INFINITY; width * height];
    let mut sphere = vec![NO_HIT; width * height];
    t.par_chunks_mut(width)
        .zip(sphere.par_chunks_mut(width))
        .enumerate()
        .for_each(|(row, (t_row, sphere_row))| {
            let y_up = (height - 1 - row) as f64;
            rasterise_row(&discs, &grid, grid.v_of_row(y_up), t_row, sphere_row);
        });
    Ok(frame_from_hits(scene, view, t, sphere))
}

/// Completes a frame from per-pixel t and sphere indices: colour from the sphere's material or
/// the background.
pub(crate) fn frame_from_hits(scene: &Scene, view: &View, t: Vec<f64>, sphere: Vec<u32>) -> Frame {
    let sphere_colours: Vec<Vec3> = scene
        .spheres
        .iter()
        .map(|s| scene.sphere_colour(s))
        .collect();
    let colour = sphere
        .par_iter()
        .map(|&index| {
            sphere_colours
                .get(index as usize)
                .copied()
                .unwrap_or(scene.background)
        })
        .collect();
    Frame {
        width_px: view.width_px,
        height_px: view.height_px,
        colour,
        t,
        sphere,
    }
}
