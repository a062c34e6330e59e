//! The mistaken caster: the pictures a ray caster with a given [`MistakeSet`] makes, written
//! as such a program does it (one world-space ray per pixel from its own camera vectors, camera
//! relative f64, against the spheres whose screen footprint can reach the pixel, binned into
//! tiles) and sharing no code with the diagnosis's model renderer
//! (the comparison's `model_render`) nor the fast disc renderer: the tests make their "student"
//! images with it, so that a fit is never checked against itself; with no mistake it is a second
//! opinion on the exact renderer.

use glam::{DMat2, DVec2, DVec3};
use image::{Rgb, RgbImage};
use rayon::prelude::*;

use crate::compare::mistake::{Mistake, MistakeSet};
use crate::render::View;
use crate::scene::Scene;

/// Side of the square tiles the spheres are binned into, pixels.
const TILE_PX: u32 = 16;

/// What each pixel's ray hit: top row first, t along the unit direction (`+∞`: no hit).
#[derive(Debug, Clone, PartialEq)]
pub struct Hits {
    /// Image width, pixels.
    pub width_px: u32,
    /// Image height, pixels.
    pub height_px: u32,
    /// t of the visible hit per pixel, top row first; `+∞` where nothing is hit.
    pub t: Vec<f64>,
    /// Index of the sphere hit per pixel, top row first; `u32::MAX` where nothing is hit.
    pub sphere: Vec<u32>,
}

/// The camera as the mistaken program sets it up.
struct Rays {
    /// Unit view direction.
    direction: DVec3,
    /// World offset of one unit of screen u (the image's +x).
    horizontal: DVec3,
    /// World offset of one unit of screen v (the image's +y).
    vertical: DVec3,
    /// Screen point of pixel (x, y up): (u, v) in world units from the camera centre.
    pixel: PixelMapping,
}

/// From pixel indices to screen offsets (and back, for binning).
#[derive(Clone, Copy)]
struct PixelMapping {
    width: f64,
    height: f64,
    /// World units per pixel along x and y.
    step: DVec2,
    /// Added to the pixel index: ½ (centres) or 0 (corners).
    offset: f64,
}

impl PixelMapping {
    fn screen_of(&self, x: u32, y_up: u32) -> DVec2 {
        DVec2::new(
            (f64::from(x) + self.offset - 0.5 * self.width) * self.step.x,
            (f64::from(y_up) + self.offset - 0.5 * self.height) * self.step.y,
        )
    }

    /// The pixel index (fractional) whose screen point is `screen`.
    fn pixel_of(&self, screen: DVec2) -> DVec2 {
        DVec2::new(
            screen.x / self.step.x + 0.5 * self.width - self.offset,
            screen.y / self.step.y + 0.5 * self.height - self.offset,
        )
    }
}

impl Rays {
    fn new(view: &View, mistakes: MistakeSet) -> Self {
        let direction = view.direction_world.normalize();
        let true_horizontal = direction.cross(view.up_world).normalize();
        let horizontal = if mistakes.contains(Mistake::Mirrored) {
            -true_horizontal
        } else {
            true_horizontal
        };
        let vertical = if mistakes.contains(Mistake::RawUp) {
            view.up_world
        } else {
            true_horizontal.cross(direction)
        };
        let (width, height) = (f64::from(view.width_px), f64::from(view.height_px));
        let size = view.size_world;
        let step = if mistakes.contains(Mistake::Stretched) {
            DVec2::new(size / width, size / height)
        } else {
            DVec2::splat(size / width.max(height))
        };
        let offset = if mistakes.contains(Mistake::PixelCorners) {
            0.0
        } else {
            0.5
        };
        Self {
            direction,
            horizontal,
            vertical,
            pixel: PixelMapping {
                width,
                height,
                step,
                offset,
            },
        }
    }

    /// The ray origin of screen point `screen`, relative to the camera centre.
    fn origin(&self, screen: DVec2) -> DVec3 {
        screen.x * self.horizontal + screen.y * self.vertical
    }

    /// The pixels (x range, y-up range, inclusive) whose rays can reach a sphere at `center`
    /// (camera-relative) of `radius`, or everything when the screen axes are degenerate.
    fn footprint(&self, center: DVec3, radius: f64, width: u32, height: u32) -> [u32; 4] {
        let everything = [0, width - 1, 0, height - 1];
        // An orthonormal frame of the plane across the rays, and the screen axes in it.
        let e1 = self.direction.any_orthonormal_vector();
        let e2 = self.direction.cross(e1);
        let axes = DMat2::from_cols(
            DVec2::new(self.horizontal.dot(e1), self.horizontal.dot(e2)),
            DVec2::new(self.vertical.dot(e1), self.vertical.dot(e2)),
        );
        let determinant = axes.determinant();
        let scale = axes.col(0).length() * axes.col(1).length();
        if determinant.is_nan() || determinant.abs() <= 1e-12 * scale {
            return everything;
        }
        let inverse = axes.inverse();
        let centre_screen = inverse * DVec2::new(center.dot(e1), center.dot(e2));
        // The disc of `radius` maps to an ellipse; its box's half sides are the row lengths.
        let half = DVec2::new(
            inverse.row(0).length() * radius,
            inverse.row(1).length() * radius,
        );
        let low = self.pixel.pixel_of(centre_screen - half);
        let high = self.pixel.pixel_of(centre_screen + half);
        let (low, high) = (low.min(high), low.max(high));
        let clamp = |value: f64, last: u32| -> Option<u32> {
            if value.is_nan() {
                return None;
            }
            Some(value.clamp(0.0, f64::from(last)) as u32)
        };
        if high.x < -1.0
            || high.y < -1.0
            || low.x > f64::from(width) + 1.0
            || low.y > f64::from(height) + 1.0
        {
            return [1, 0, 1, 0];
        }
        match (
            clamp((low.x - 1.0).floor(), width - 1),
            clamp((high.x + 1.0).ceil(), width - 1),
            clamp((low.y - 1.0).floor(), height - 1),
            clamp((high.y + 1.0).ceil(), height - 1),
        ) {
            (Some(x0), Some(x1), Some(y0), Some(y1)) => [x0, x1, y0, y1],
            _ => everything,
        }
    }
}

/// The visible t of one sphere along one ray, or `None`: `w` is the distance along the ray to
/// the point nearest the centre, `across_sq` the squared distance of the ray from the centre.
fn sphere_t(w: f64, across_sq: f64, radius: f64, mistakes: MistakeSet) -> Option<f64> {
    let inside = radius * radius - across_sq;
    if inside.is_nan() || inside < 0.0 {
        return None;
    }
    let half_chord = if mistakes.contains(Mistake::NoSquareRoot) {
        inside
    } else {
        inside.sqrt()
    };
    let (near, far) = (w - half_chord, w + half_chord);
    let far_only = mistakes.contains(Mistake::FarRoot);
    if mistakes.contains(Mistake::TminMinusOne) && !mistakes.contains(Mistake::TminZero) {
        // The one root the program takes, kept only at t ≥ −1 (no second root tried).
        let t = if far_only { far } else { near };
        return (t >= -1.0).then_some(t);
    }
    if mistakes.contains(Mistake::TminZero) {
        let tmin = 0.0;
        if !far_only && near >= tmin {
            Some(near)
        } else if far >= tmin {
            Some(far)
        } else {
            None
        }
    } else if far_only {
        Some(far)
    } else {
        Some(near)
    }
}

/// Renders what each pixel's ray hits, with the hit-changing part of `mistakes`.
pub fn render_hits(scene: &Scene, view: &View, mistakes: MistakeSet) -> Hits {
    let (width, height) = (view.width_px.max(1), view.height_px.max(1));
    let rays = Rays::new(view, mistakes);
    let centers: Vec<DVec3> = scene
        .spheres
        .iter()
        .map(|s| s.center_world - view.center_world)
        .collect();
    // Bin the spheres (in file order, which decides ties) into tiles of the image.
    let tiles_x = width.div_ceil(TILE_PX);
    let tiles_y = height.div_ceil(TILE_PX);
    let mut tiles: Vec<Vec<u32>> = vec![Vec::new(); (tiles_x * tiles_y) as usize];
    for (index, (sphere, center)) in (0u32..).zip(scene.spheres.iter().zip(&centers)) {
        let [x0, x1, y0, y1] = rays.footprint(*center, sphere.radius_world, width, height);
        if x0 > x1 || y0 > y1 {
            continue;
        }
        for ty in y0 / TILE_PX..=y1 / TILE_PX {
            for tx in x0 / TILE_PX..=x1 / TILE_PX {
                tiles[(ty * tiles_x + tx) as usize].push(index);
            }
        }
    }
    let last_wins = mistakes.contains(Mistake::LastWins);
    let pixels = (width * height) as usize;
    let mut t = vec![f64::INFINITY; pixels];
    let mut sphere = vec![u32::MAX; pixels];
    t.par_chunks_mut(width as usize)
        .zip(sphere.par_chunks_mut(width as usize))
        .enumerate()
        .for_each(|(row, (t_row, sphere_row))| {
            let y_up = height - 1 - row as u32;
            for x in 0..width {
                let origin = rays.origin(rays.pixel.screen_of(x, y_up));
                let tile = &tiles[((y_up / TILE_PX) * tiles_x + x / TILE_PX) as usize];
                let mut best = (f64::INFINITY, u32::MAX);
                for &index in tile {
                    let to_center = centers[index as usize] - origin;
                    let w = to_center.dot(rays.direction);
                    let across = to_center - w * rays.direction;
                    let radius = scene.spheres[index as usize].radius_world;
                    if let Some(hit) = sphere_t(w, across.length_squared(), radius, mistakes)
                        && (hit < best.0 || (last_wins && hit == best.0))
                    {
                        best = (hit, index);
                    }
                }
                t_row[x as usize] = best.0;
                sphere_row[x as usize] = best.1;
            }
        });
    Hits {
        width_px: width,
        height_px: height,
        t,
        sphere,
    }
}

/// 8-bit quantisation of `value` (in [0, 1] when right) by truncation, or by rounding with
/// [`Mistake::Rounded`]; clamped, or wrapped modulo 256 when `wrap`.
fn quantise(value: f64, rounded: bool, wrap: bool) -> u8 {
    let scaled = value * 255.0;
    let level = if rounded {
        scaled.round()
    } else {
        scaled.floor()
    };
    if !level.is_finite() {
        return 0;
    }
    if wrap {
        (level as i64).rem_euclid(256) as u8
    } else {
        level.clamp(0.0, 255.0) as u8
    }
}

/// The colour image of `hits`: each hit sphere's colour, else the background.
pub fn colour_image(scene: &Scene, hits: &Hits, mistakes: MistakeSet) -> RgbImage {
    let rounded = mistakes.contains(Mistake::Rounded);
    let bytes = |colour: glam::Vec3| -> [u8; 3] {
        colour.to_array().map(|c| {
            let scaled = c * 255.0;
            let level = if rounded {
                scaled.round()
            } else {
                scaled.floor()
            };
            level.clamp(0.0, 255.0) as u8
        })
    };
    let background = bytes(scene.background);
    let mut image = RgbImage::from_fn(hits.width_px, hits.height_px, |x, row| {
        let index = (row * hits.width_px + x) as usize;
        match scene.spheres.get(hits.sphere[index] as usize) {
            Some(sphere) => Rgb(bytes(scene.sphere_colour(sphere))),
            None => Rgb(background),
        }
    });
    if mistakes.contains(Mistake::FlippedVertically) {
        image::imageops::flip_vertical_in_place(&mut image);
    }
    image
}

/// The depth image of `hits` over `view`'s depth range.
pub fn depth_image(view: &View, hits: &Hits, mistakes: MistakeSet) -> RgbImage {
    let range = view.depth_range;
    let scale = if mistakes.contains(Mistake::UnnormalizedDirection) {
        1.0 / view.direction_world.length()
    } else {
        1.0
    };
    let reversed = mistakes.contains(Mistake::DepthReversed);
    let wrap = mistakes.contains(Mistake::DepthNoClamp);
    let outside_black = mistakes.contains(Mistake::DepthOutsideBlack);
    let rounded = mistakes.contains(Mistake::Rounded);
    let width = range.max_t - range.min_t;
    let mut image = RgbImage::from_fn(hits.width_px, hits.height_px, |x, row| {
        let t = hits.t[(row * hits.width_px + x) as usize];
        if t == f64::INFINITY {
            return Rgb([0; 3]);
        }
        let t = t * scale;
        if outside_black && !(range.min_t..=range.max_t).contains(&t) {
            return Rgb([0; 3]);
        }
        let near_is_one = if width == 0.0 {
            if t <= range.min_t { 1.0 } else { 0.0 }
        } else {
            (range.max_t - t) / width
        };
        let value = if reversed {
            1.0 - near_is_one
        } else {
            near_is_one
        };
        Rgb([quantise(value, rounded, wrap); 3])
    });
    if mistakes.contains(Mistake::FlippedVertically) {
        image::imageops::flip_vertical_in_place(&mut image);
    }
    image
}

/// The colour and depth images a ray caster with `mistakes` makes of `scene` through `view`.
pub fn render_variant(scene: &Scene, view: &View, mistakes: MistakeSet) -> (RgbImage, RgbImage) {
    let hits = render_hits(scene, view, mistakes.hit_part());
    (
        colour_image(scene, &hits, mistakes),
        depth_image(view, &hits, mistakes),
    )
}
