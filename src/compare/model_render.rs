//! The images a [`Model`] of a ray caster makes: each sphere projected once onto the camera's
//! true screen (an orthographic ray meets a sphere iff its screen point lies in the sphere's
//! disc), binned into tiles of the image through the model's pixel map, then one screen point
//! per pixel against its tile's discs, with the model's roots, tmin and rule for which hit is
//! drawn; then colour and depth bytes as the model makes them.

use glam::{DVec2, DVec3};
use image::{Rgb, RgbImage};
use rayon::prelude::*;

use super::model::{Model, Outside, Quantity, SampleGrid, Visible, colour_bytes, depth_level};
use crate::render::View;
use crate::scene::Scene;

/// Side of the square tiles the discs are binned into, pixels.
const TILE_PX: u32 = 16;

/// The camera's true frame: unit horizontal, unit screen up, unit direction.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    /// Unit `direction × up`.
    pub horizontal: DVec3,
    /// Unit screen up.
    pub screen_up: DVec3,
    /// Unit direction.
    pub direction: DVec3,
}

impl Frame {
    /// The frame of `view`'s camera (its up made perpendicular to the direction).
    pub fn of(view: &View) -> Self {
        let direction = view.direction_world.normalize();
        let horizontal = direction.cross(view.up_world).normalize();
        Self {
            horizontal,
            screen_up: horizontal.cross(direction),
            direction,
        }
    }

    /// (u, v, w) of a world offset from the camera centre.
    pub fn to_screen(&self, offset: DVec3) -> DVec3 {
        DVec3::new(
            offset.dot(self.horizontal),
            offset.dot(self.screen_up),
            offset.dot(self.direction),
        )
    }
}

/// A sphere seen from the camera: its centre's (u, v) on the screen, its w along the
/// direction, its radius.
#[derive(Debug, Clone, Copy)]
pub struct Disc {
    /// Screen point of the centre, world units from the camera centre.
    pub center_uv: DVec2,
    /// Distance of the centre along the direction from the camera's plane.
    pub w: f64,
    /// Radius, world units.
    pub radius: f64,
}

/// The discs of `scene`'s spheres through `view`'s camera, in file order.
pub fn discs(scene: &Scene, view: &View) -> Vec<Disc> {
    let frame = Frame::of(view);
    scene
        .spheres
        .iter()
        .map(|sphere| {
            let c = frame.to_screen(sphere.center_world - view.center_world);
            Disc {
                center_uv: DVec2::new(c.x, c.y),
                w: c.z,
                radius: sphere.radius_world,
            }
        })
        .collect()
}

/// The discs of a scene (in file order, indexed as its spheres), with their indices nearest
/// first: by `w − r`, the least t a ray can take of a sphere, its root taken or not, before any
/// shift. Tiles hold their discs in that order, so that the nearest hit is found without trying
/// the discs that lie wholly behind it.
#[derive(Debug, Clone)]
pub struct Discs {
    /// The discs, in file order.
    pub all: Vec<Disc>,
    /// Their indices, by `w − r` ascending (file order among equals).
    pub near_first: Vec<u32>,
}

impl Discs {
    /// The discs of `scene` through `view`.
    pub fn of(scene: &Scene, view: &View) -> Self {
        let all = discs(scene, view);
        let mut near_first: Vec<u32> = (0..all.len() as u32).collect();
        near_first.sort_by(|&a, &b| {
            let (a, b) = (&all[a as usize], &all[b as usize]);
            (a.w - a.radius).total_cmp(&(b.w - b.radius))
        });
        Self { all, near_first }
    }
}

impl std::ops::Deref for Discs {
    type Target = [Disc];

    fn deref(&self) -> &[Disc] {
        &self.all
    }
}

/// What each pixel's ray hit: top row first, t along the unit direction (`+∞`: no hit).
#[derive(Debug, Clone, PartialEq)]
pub struct Hits {
    /// Image width, pixels.
    pub width_px: u32,
    /// Image height, pixels.
    pub height_px: u32,
    /// t of the hit drawn per pixel (the model's ramp included), top row first; `+∞` where
    /// nothing is hit.
    pub t: Vec<f64>,
    /// Index of the sphere drawn per pixel, top row first; `u32::MAX` where nothing is hit.
    pub sphere: Vec<u32>,
}

/// The t shift of the model's tilt at screen point `screen` (the ray origin moved along the
/// direction in proportion to its place on the screen).
pub fn ramp_at(model: &Model, screen: DVec2) -> f64 {
    model.t_ramp.x * screen.x + model.t_ramp.y * screen.y + model.t_ramp.z
}

/// The pixels `[x0, x1, y0, y1]` (inclusive, y up) whose screen points may lie in `disc`, or an
/// empty box; everything when the map is degenerate.
fn footprint(model: &Model, disc: &Disc, width: u32, height: u32) -> [u32; 4] {
    let everything = [0, width - 1, 0, height - 1];
    let axes = model.pixels.axes_world;
    let determinant = axes.determinant();
    let scale = axes.x_axis.length() * axes.y_axis.length();
    if !determinant.is_finite() || determinant.abs() <= 1e-12 * scale {
        return everything;
    }
    let inverse = axes.inverse();
    let centre = inverse * (disc.center_uv - model.pixels.origin_world);
    let half = DVec2::new(
        inverse.row(0).length() * disc.radius,
        inverse.row(1).length() * disc.radius,
    );
    let (low, high) = (centre - half, centre + half);
    if !(low.is_finite() && high.is_finite()) {
        return everything;
    }
    if high.x < -1.0 || high.y < -1.0 || low.x > f64::from(width) || low.y > f64::from(height) {
        return [1, 0, 1, 0];
    }
    let clamp = |value: f64, last: u32| value.clamp(0.0, f64::from(last)) as u32;
    [
        clamp((low.x - 1.0).floor(), width - 1),
        clamp((high.x + 1.0).ceil(), width - 1),
        clamp((low.y - 1.0).floor(), height - 1),
        clamp((high.y + 1.0).ceil(), height - 1),
    ]
}

/// The discs binned into the image's tiles, in file order.
pub struct Tiles {
    tiles_x: u32,
    tiles: Vec<Vec<u32>>,
}

impl Tiles {
    /// Bins `discs` by the pixels `model` maps into them, each tile's discs nearest first.
    pub fn of(model: &Model, discs: &Discs, width: u32, height: u32) -> Self {
        let tiles_x = width.div_ceil(TILE_PX);
        let tiles_y = height.div_ceil(TILE_PX);
        let mut tiles: Vec<Vec<u32>> = vec![Vec::new(); (tiles_x * tiles_y) as usize];
        for &index in &discs.near_first {
            let disc = &discs.all[index as usize];
            let [x0, x1, y0, y1] = footprint(model, disc, width, height);
            if x0 > x1 || y0 > y1 {
                continue;
            }
            for ty in y0 / TILE_PX..=y1 / TILE_PX {
                for tx in x0 / TILE_PX..=x1 / TILE_PX {
                    tiles[(ty * tiles_x + tx) as usize].push(index);
                }
            }
        }
        Self { tiles_x, tiles }
    }

    /// The discs that may cover pixel `(x, y_up)`, nearest first.
    pub fn at(&self, x: u32, y_up: u32) -> &[u32] {
        &self.tiles[((y_up / TILE_PX) * self.tiles_x + x / TILE_PX) as usize]
    }
}

/// The hit `model` draws at screen point `screen` with t shifted by `shift`: (t, sphere), of the
/// discs `candidates`, nearest first as [`Discs::near_first`] orders them (a tile's discs are):
/// the search for the nearest hit stops at the first disc wholly behind it. Among hits of equal
/// t, and for the rules without a depth test, the spheres' order in the file decides, as the
/// model's rule says.
pub fn hit_at(
    model: &Model,
    discs: &[Disc],
    candidates: &[u32],
    screen: DVec2,
    shift: f64,
) -> Option<(f64, u32)> {
    let rule = &model.hits;
    // With the root taken, no t of a sphere is less than w − r (plus the shift).
    let stops = rule.visible == Visible::Nearest && rule.square_root;
    let mut best: Option<(f64, u32)> = None;
    for &index in candidates {
        let disc = &discs[index as usize];
        if stops && best.is_some_and(|(best_t, _)| disc.w - disc.radius + shift > best_t) {
            break;
        }
        let across_sq = (screen - disc.center_uv).length_squared();
        let Some(t) = rule.sphere_t(disc.w, across_sq, disc.radius, shift) else {
            continue;
        };
        let replaces = match (best, rule.visible) {
            (None, _) => true,
            (Some((_, best_index)), Visible::FirstInFile) => index < best_index,
            (Some((_, best_index)), Visible::LastInFile) => index > best_index,
            (Some((best_t, best_index)), Visible::Nearest) => {
                t < best_t
                    || (t == best_t
                        && if rule.later_wins_ties {
                            index > best_index
                        } else {
                            index < best_index
                        })
            }
        };
        if replaces {
            best = Some((t, index));
        }
    }
    best
}

/// The hit `model`'s sample grid sets pixel `(x, y_up)` to: of the samples that fall in it, in
/// the order the program loops (rows bottom up, then columns left to right), the last that hits
/// or the first. Every disc is a candidate (the grid ignores the pixel map's tiles).
fn grid_hit_at(
    model: &Model,
    discs: &Discs,
    grid: &SampleGrid,
    view: &View,
    x: u32,
    y_up: u32,
) -> Option<(f64, u32)> {
    let (i0, i1) = grid.samples_of(x, view.width_px);
    let (j0, j1) = grid.samples_of(y_up, view.height_px);
    let mut chosen = None;
    for j in j0..j1 {
        for i in i0..i1 {
            let screen = DVec2::new(
                grid.screen_of(i, view.size_world),
                grid.screen_of(j, view.size_world),
            );
            let shift = ramp_at(model, screen);
            if let Some(hit) = hit_at(model, discs, &discs.near_first, screen, shift) {
                if !grid.last_wins {
                    return Some(hit);
                }
                chosen = Some(hit);
            }
        }
    }
    chosen
}

/// Renders what each pixel's ray hits under `model`.
pub fn render_hits(scene: &Scene, view: &View, model: &Model) -> Hits {
    render_hits_every(scene, view, model, 1)
}

/// Renders what the rays of the pixels of every `stride`th row and column hit under `model`
/// (rows and columns 0, `stride`, 2·`stride`… of the image, top row first): hits of an image
/// `stride` times smaller in each axis.
pub fn render_hits_every(scene: &Scene, view: &View, model: &Model, stride: u32) -> Hits {
    render_hits_of(&Discs::of(scene, view), view, model, stride)
}

/// [`render_hits_every`] of the discs `discs` (a scene's, through `view`), made once by the
/// caller.
pub fn render_hits_of(discs: &Discs, view: &View, model: &Model, stride: u32) -> Hits {
    let stride = stride.max(1);
    let (width, height) = (view.width_px.max(1), view.height_px.max(1));
    let (sampled_width, sampled_height) = (width.div_ceil(stride), height.div_ceil(stride));
    let tiles = Tiles::of(model, discs, width, height);
    let pixels = (sampled_width * sampled_height) as usize;
    let mut t = vec![f64::INFINITY; pixels];
    let mut sphere = vec![u32::MAX; pixels];
    t.par_chunks_mut(sampled_width as usize)
        .zip(sphere.par_chunks_mut(sampled_width as usize))
        .enumerate()
        .for_each(|(sampled_row, (t_row, sphere_row))| {
            let y_up = height - 1 - sampled_row as u32 * stride;
            for sampled_x in 0..sampled_width {
                let x = sampled_x * stride;
                if model
                    .drawn_px
                    .is_some_and(|(columns, rows)| x >= columns || y_up >= rows)
                {
                    continue;
                }
                let hit = if let Some(grid) = model.samples {
                    grid_hit_at(model, discs, &grid, view, x, y_up)
                } else {
                    let pixel = DVec2::new(f64::from(x), f64::from(y_up));
                    let screen = model.pixels.screen_of(pixel);
                    let shift = ramp_at(model, screen);
                    hit_at(model, discs, tiles.at(x, y_up), screen, shift)
                };
                if let Some((hit_t, index)) = hit {
                    t_row[sampled_x as usize] = hit_t;
                    sphere_row[sampled_x as usize] = index;
                }
            }
        });
    Hits {
        width_px: sampled_width,
        height_px: sampled_height,
        t,
        sphere,
    }
}

/// The hit `model` draws at pixel `(x, y_up)` of `view` (t with the model's ramp, and the sphere),
/// or `None` where its ray hits nothing or the pixel is not drawn: one pixel, every sphere tried.
pub fn hit_of_pixel(
    scene: &Scene,
    view: &View,
    model: &Model,
    x: u32,
    y_up: u32,
) -> Option<(f64, u32)> {
    if model
        .drawn_px
        .is_some_and(|(columns, rows)| x >= columns || y_up >= rows)
    {
        return None;
    }
    let discs = Discs::of(scene, view);
    let screen = model
        .pixels
        .screen_of(DVec2::new(f64::from(x), f64::from(y_up)));
    hit_at(
        model,
        &discs,
        &discs.near_first,
        screen,
        ramp_at(model, screen),
    )
}

/// The colour image `model` draws of `hits`: each sphere's colour, else the background.
pub fn colour_image(scene: &Scene, hits: &Hits, model: &Model) -> RgbImage {
    let colours: Vec<[u8; 3]> = scene
        .spheres
        .iter()
        .map(|s| colour_bytes(scene.sphere_colour(s), model.rounded))
        .collect();
    let background = model
        .background
        .unwrap_or_else(|| colour_bytes(scene.background, model.rounded));
    RgbImage::from_fn(hits.width_px, hits.height_px, |x, row| {
        let index = (row * hits.width_px + x) as usize;
        Rgb(colours
            .get(hits.sphere[index] as usize)
            .copied()
            .unwrap_or(background))
    })
}

/// The quantity `model`'s depth image maps at the pixel in column `x` and row `row` (top row
/// first) of `view`'s image, whose ray hit at `t` (NaN where no ray hits: `t` is `+∞`).
pub fn depth_quantity(view: &View, frame: &Frame, model: &Model, t: f64, x: u32, row: u32) -> f64 {
    if t == f64::INFINITY {
        return f64::NAN;
    }
    let coordinate = |axis: u8| {
        let pixel = DVec2::new(f64::from(x), f64::from(view.height_px.max(1) - 1 - row));
        let screen = model.pixels.screen_of(pixel);
        let t_plane = t - ramp_at(model, screen);
        let hit = view.center_world
            + screen.x * frame.horizontal
            + screen.y * frame.screen_up
            + t_plane * frame.direction;
        hit[usize::from(axis.min(2))]
    };
    match model.depth.quantity {
        Quantity::T => t,
        Quantity::AbsT => t.abs(),
        Quantity::Coordinate(axis) => coordinate(axis),
        Quantity::AbsCoordinate(axis) => coordinate(axis).abs(),
    }
}

/// The quantity `model`'s depth image maps, per pixel (top row first; NaN where no ray hits).
pub fn depth_quantities(view: &View, hits: &Hits, model: &Model) -> Vec<f64> {
    let frame = Frame::of(view);
    let width = hits.width_px;
    (0..hits.t.len())
        .into_par_iter()
        .with_min_len(4096)
        .map(|index| {
            let (x, row) = (index as u32 % width, index as u32 / width);
            depth_quantity(view, &frame, model, hits.t[index], x, row)
        })
        .collect()
}

/// The bytes of one depth pixel whose quantity is `q` (NaN: no hit).
pub fn depth_pixel(model: &Model, q: f64) -> [u8; 3] {
    let map = &model.depth;
    if q.is_nan() {
        return map.no_hit;
    }
    let value = map.value(q);
    let outside = !(0.0..=1.0).contains(&value);
    match map.outside {
        Outside::Black if outside => [0; 3],
        Outside::Colour(colour) if outside => colour,
        Outside::Wrap => [depth_level(value, model.rounded, true); 3],
        _ => [depth_level(value, model.rounded, false); 3],
    }
}

/// The depth image `model` draws of `hits`.
pub fn depth_image(view: &View, hits: &Hits, model: &Model) -> RgbImage {
    let quantities = depth_quantities(view, hits, model);
    let (at_zero, per_unit) = (model.depth.at_zero, model.depth.per_unit);
    RgbImage::from_fn(hits.width_px, hits.height_px, |x, row| {
        let q = quantities[(row * hits.width_px + x) as usize];
        if at_zero.is_nan() || per_unit.is_nan() {
            // A zero-width range: a step at its one t (t at or before it white).
            let white_t = view.depth_range.min_t;
            return Rgb(if q.is_nan() {
                model.depth.no_hit
            } else if q <= white_t {
                [255; 3]
            } else {
                [0; 3]
            });
        }
        Rgb(depth_pixel(model, q))
    })
}

/// The colour and depth images `model` makes of `scene` through `view`.
pub fn render_model(scene: &Scene, view: &View, model: &Model) -> (RgbImage, RgbImage) {
    let hits = render_hits(scene, view, model);
    (
        colour_image(scene, &hits, model),
        depth_image(view, &hits, model),
    )
}
