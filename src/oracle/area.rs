//! The anti-aliasing oracle: each pixel's **area average** — the mean colour and depth grey
//! over the pixel's square — estimated on a fixed dense grid of `n × n` points (the centres of
//! an n×n subdivision of the pixel), each point's ray going through the careful ray–sphere
//! routine against every sphere whose screen bounds reach the pixel (the oracle's own lists).
//!
//! It shares no code with the supersampler it checks: not the sample positions, not the disc
//! test, not the pixel grid, not the filter. Its own error is that of counting points in cells:
//! a pixel crossed by an edge is off by at most the share of its n² cells the edge crosses, about
//! `2·√2·n / n² = 2.8 / n` of the colour difference across the edge (and exact where a pixel is
//! one colour). The tests check it against the exact area of a disc in a square.

use glam::DVec3;
use rayon::prelude::*;

use crate::geometry::ray_sphere::{Ray, ray_sphere_nearest_t};
use crate::render::{View, ViewError};
use crate::scene::Scene;

/// Each pixel's area average, top row first.
#[derive(Debug, Clone, PartialEq)]
pub struct AreaAverage {
    /// Width in pixels.
    pub width_px: u32,
    /// Height in pixels.
    pub height_px: u32,
    /// Mean colour per pixel (linear, unquantised; each channel as the materials give it).
    pub colour: Vec<DVec3>,
    /// Mean depth grey per pixel over the view's depth range (no hit counts as 0).
    pub grey: Vec<f64>,
}

impl AreaAverage {
    /// The 8-bit colour of pixel `index` (`floor(c·255)`, clamped), as images store it.
    pub fn colour_u8(&self, index: usize) -> [u8; 3] {
        self.colour[index]
            .to_array()
            .map(|c| (c * 255.0).floor().clamp(0.0, 255.0) as u8)
    }
}

/// For each pixel (top row first), the spheres whose screen bounds reach it: the rays of a pixel
/// need test no others. A sphere's bounds are its centre's screen position ± its radius, widened
/// by a pixel; this is the oracle's own list, not the renderer's bins.
fn candidates(scene: &Scene, view: &View, pixel_world: f64) -> Result<Vec<Vec<u32>>, ViewError> {
    let basis = view.validate()?;
    let (width, height) = (i64::from(view.width_px), i64::from(view.height_px));
    let mut lists = vec![Vec::new(); (width * height) as usize];
    for (index, sphere) in (0u32..).zip(&scene.spheres) {
        let offset = sphere.center_world - view.center_world;
        // The centre in pixel units from the image's bottom-left corner.
        let x = offset.dot(basis.horizontal) / pixel_world + 0.5 * width as f64;
        let y = offset.dot(basis.screen_up) / pixel_world + 0.5 * height as f64;
        let reach = sphere.radius_world / pixel_world + 1.0;
        let clamp = |value: f64, limit: i64| (value.floor() as i64).clamp(0, limit - 1);
        if x + reach < 0.0
            || x - reach > width as f64
            || y + reach < 0.0
            || y - reach > height as f64
        {
            continue;
        }
        let (x0, x1) = (clamp(x - reach, width), clamp(x + reach, width));
        let (y0, y1) = (clamp(y - reach, height), clamp(y + reach, height));
        for y_up in y0..=y1 {
            let row = height - 1 - y_up;
            for column in x0..=x1 {
                lists[(row * width + column) as usize].push(index);
            }
        }
    }
    Ok(lists)
}

/// The area average of every pixel of `view` on an `n × n` grid of points per pixel.
pub fn area_average(scene: &Scene, view: &View, n: u32) -> Result<AreaAverage, ViewError> {
    let basis = view.validate()?;
    let (width, height) = (view.width_px, view.height_px);
    // Square pixels; the screen's size spans the longer side.
    let pixel_world = view.size_world / f64::from(width.max(height));
    let candidates = candidates(scene, view, pixel_world)?;
    let colour_of = |index: Option<usize>| match index {
        Some(index) => {
            let sphere = &scene.spheres[index];
            let material = sphere
                .material
                .and_then(|m| scene.materials.get(m as usize));
            material.map_or(crate::scene::DEFAULT_DIFFUSE, |m| m.diffuse_colour)
        }
        None => scene.background,
    };
    let pixel = |row: u32, x: u32| -> (DVec3, f64) {
        let y_up = height - 1 - row;
        let nearby = &candidates[(row * width + x) as usize];
        let (mut colour, mut grey) = (DVec3::ZERO, 0.0);
        for j in 0..n {
            for i in 0..n {
                // The point in pixel units from the image's bottom-left corner.
                let px = f64::from(x) + (f64::from(i) + 0.5) / f64::from(n);
                let py = f64::from(y_up) + (f64::from(j) + 0.5) / f64::from(n);
                let u = (px - 0.5 * f64::from(width)) * pixel_world;
                let v = (py - 0.5 * f64::from(height)) * pixel_world;
                let ray = Ray {
                    origin_world: view.center_world + u * basis.horizontal + v * basis.screen_up,
                    direction_world: basis.direction,
                };
                // In file order, so a tie keeps the first sphere.
                let mut best: Option<(f64, usize)> = None;
                for &index in nearby {
                    let sphere = &scene.spheres[index as usize];
                    if let Some(t) =
                        ray_sphere_nearest_t(&ray, sphere.center_world, sphere.radius_world)
                        && best.is_none_or(|(best_t, _)| t < best_t)
                    {
                        best = Some((t, index as usize));
                    }
                }
                colour += colour_of(best.map(|(_, index)| index)).as_dvec3();
                grey += best.map_or(0.0, |(t, _)| view.depth_range.grey(t));
            }
        }
        let points = f64::from(n * n);
        (colour / points, grey / points)
    };
    let pixels: Vec<(DVec3, f64)> = (0..height)
        .into_par_iter()
        .flat_map_iter(|row| (0..width).map(move |x| pixel(row, x)))
        .collect();
    Ok(AreaAverage {
        width_px: width,
        height_px: height,
        colour: pixels.iter().map(|(c, _)| *c).collect(),
        grey: pixels.iter().map(|(_, g)| *g).collect(),
    })
}

/// The exact area of the disc (centre `(cx, cy)`, radius `r`) inside the square
/// `[x0, x0 + side] × [y0, y0 + side]`, by integrating the disc's chord across the square
/// (midpoint rule on 200,000 strips: exact to about 1e-9 of the square). For checking
/// [`area_average`].
pub fn disc_area_in_square(cx: f64, cy: f64, r: f64, x0: f64, y0: f64, side: f64) -> f64 {
    const STRIPS: u32 = 200_000;
    let width = side / f64::from(STRIPS);
    (0..STRIPS)
        .map(|k| {
            let x = x0 + (f64::from(k) + 0.5) * width;
            let dx = x - cx;
            let half = (r * r - dx * dx).max(0.0).sqrt();
            let (low, high) = ((cy - half).max(y0), (cy + half).min(y0 + side));
            (high - low).max(0.0) * width
        })
        .sum()
}
