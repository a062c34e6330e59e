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
//! order and a hit replaces the current one only when strictly nearer; drawn front to back, a
//! hit at an equal t replaces it only for a sphere earlier in the file).
//!
//! Everything is f64: an f32 mode was measured slower than f64 and less exact, and removed
//! (`docs/accuracy.md`).
//!
//! * this module: the projected [`Disc`] and the projection ([`project_discs`])
//! * [`bins`]: listing each disc in the bands of rows it touches; row and column spans
//! * [`hit`]: the pixel–disc test and its tie rule, once for one pixel and for four SIMD lanes
//! * [`chord`]: a disc's chord on a row, a band's discs gathered
//! * [`depth_order`]: discs sorted front to back, and the nearest ones that cover the image
//! * [`depth_sort`]: a pass's kept discs ordered by depth slice, in parallel
//! * [`placed`]: discs placed on the image (rows, columns, nearest t) and binned, in parts
//! * [`coarse_depth`]: discs behind what the nearest ones drew, culled frame-wide
//! * [`tiles`]: dense scenes drawn front to back tile by tile, each tile stopping where the rest
//!   is hidden
//! * [`raster`]: filling a band's pixels, and a whole frame
//! * [`strips`]: a frame drawn and handed on a strip of rows at a time
//! * [`shade`]: colours from the visible spheres

mod bins;
mod chord;
mod coarse_depth;
mod depth_order;
mod depth_sort;
mod hit;
mod placed;
mod raster;
mod shade;
mod strips;
mod tiles;

pub(crate) use bins::pixel_span;
pub(crate) use depth_order::Depths;
pub(crate) use raster::rasterise_frame;
pub(crate) use shade::Palette;
#[cfg(feature = "oracle")]
pub(crate) use shade::frame_from_hits;
pub(crate) use strips::{STRIP_ROWS, Strip, rasterise_strips};

use crate::geometry::camera::CameraBasis;
use crate::render::View;
use crate::scene::{Scene, Sphere};

/// A sphere projected into camera space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Screen u of the centre (world units, relative to the camera centre).
    pub u: f64,
    /// Screen v of the centre.
    pub v: f64,
    /// Depth of the centre along the view direction (t of the centre).
    pub(crate) w: f64,
    /// r², the disc's squared radius.
    pub radius_sq: f64,
    /// Index of the sphere in file order.
    pub sphere: u32,
}

impl Disc {
    /// A placeholder: at the origin, of radius 0.
    pub(crate) const NONE: Self = Self {
        u: 0.0,
        v: 0.0,
        w: 0.0,
        radius_sq: 0.0,
        sphere: 0,
    };

    /// The nearest t it can have anywhere: `w − r`, never above the t of a pixel it covers
    /// (correctly rounded square root and subtraction are monotonic).
    #[inline]
    pub(crate) fn front_t(&self) -> f64 {
        self.w - self.radius_sq.sqrt()
    }

    /// t of the front surface at screen (u, v), or `None` outside the disc. Tangent points hit.
    #[inline]
    pub fn hit_t(&self, u: f64, v: f64) -> Option<f64> {
        let (du, dv) = (u - self.u, v - self.v);
        let hit = hit::test(self, du * du, dv * dv, f64::INFINITY);
        hit.inside.then_some(hit.t)
    }
}

/// Projects every sphere of `scene` into the camera space of `view` (basis from
/// [`View::validate`]), in file order.
pub fn project_discs(scene: &Scene, view: &View, basis: &CameraBasis) -> Vec<Disc> {
    project_discs_with_depths(scene, view, basis).0
}

/// Discs whose depths one parallel task sums.
const PROJECT_CHUNK: usize = 16_384;

/// [`project_discs`], and their [`Depths`] on the view's grid.
pub(crate) fn project_discs_with_depths(
    scene: &Scene,
    view: &View,
    basis: &CameraBasis,
) -> (Vec<Disc>, Depths) {
    crate::render::phases::time("project", || project_in_parallel(scene, view, basis))
}

/// [`project_discs_with_depths`]'s work in parallel: the discs, then their depths chunk by chunk
/// (summed in file order, whatever the threads).
fn project_in_parallel(scene: &Scene, view: &View, basis: &CameraBasis) -> (Vec<Disc>, Depths) {
    use rayon::prelude::*;
    // Written where they land by an indexed collect: no placeholders written first (on one
    // thread, `vec![…; n]` was a serial part on many cores, found by the frame's phase table on 16 cores).
    let discs: Vec<Disc> = scene
        .spheres
        .par_iter()
        .zip(0..scene.spheres.len() as u32)
        .map(|(sphere, index)| project_sphere(sphere, index, view, basis))
        .collect();
    let grid = view.grid();
    let depths = discs
        .par_chunks(PROJECT_CHUNK)
        .map(|discs| {
            discs
                .iter()
                .fold(Depths::NONE, |depths, disc| depths.with(disc, &grid))
        })
        .collect::<Vec<Depths>>();
    (discs, merge_in_order(&depths))
}

/// The chunks' [`Depths`] merged in file order: the same sum, bit for bit, however the chunks
/// were shared out between threads (a plan decided at a threshold must not depend on it).
fn merge_in_order(chunks: &[Depths]) -> Depths {
    chunks
        .iter()
        .fold(Depths::NONE, |all, &chunk| all.merge(chunk))
}

/// `sphere`, the `index`th of its scene, projected into the camera space of `view`.
#[inline]
fn project_sphere(sphere: &Sphere, index: u32, view: &View, basis: &CameraBasis) -> Disc {
    let center_camera = basis.to_camera(sphere.center_world - view.center_world);
    Disc {
        u: center_camera.x,
        v: center_camera.y,
        w: center_camera.z,
        radius_sq: sphere.radius_world * sphere.radius_world,
        sphere: index,
    }
}

/// Whether `scene` through `view` (basis from [`View::validate`]) is drawn in file order, strip
/// by strip when streamed ([`strips`]), rather than front to back over the whole frame: the
/// spheres' discs are projected and measured, not kept.
pub(crate) fn draws_in_file_order(scene: &Scene, view: &View, basis: &CameraBasis) -> bool {
    use rayon::prelude::*;
    let grid = view.grid();
    let depths = scene
        .spheres
        .par_chunks(PROJECT_CHUNK)
        .map(|spheres| {
            spheres.iter().fold(Depths::NONE, |depths, sphere| {
                // The index does not count here.
                depths.with(&project_sphere(sphere, 0, view, basis), &grid)
            })
        })
        .collect::<Vec<Depths>>();
    // Summed as the render sums them, so that both decide alike.
    depth_order::in_file_order(scene.spheres.len(), &merge_in_order(&depths), &grid)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::depth_map::DepthRange;
    use crate::render::rng::SplitMix64;
    use crate::scene::OrthographicCamera;
    use glam::{DVec3, Vec3};

    /// `count` spheres of radius up to `max_radius` in a 100-unit cube, seen whole.
    fn scene(count: usize, max_radius: f64) -> Scene {
        let mut rng = SplitMix64::new(count as u64);
        Scene {
            camera: OrthographicCamera {
                center_world: DVec3::new(0.0, 0.0, 200.0),
                direction_world: DVec3::NEG_Z,
                up_world: DVec3::Y,
                size_world: 100.0,
            },
            background: Vec3::ZERO,
            materials: Vec::new(),
            spheres: (0..count)
                .map(|_| Sphere {
                    center_world: DVec3::new(
                        rng.uniform(-50.0, 50.0),
                        rng.uniform(-50.0, 50.0),
                        rng.uniform(-50.0, 50.0),
                    ),
                    radius_world: rng.uniform(0.1, max_radius),
                    material: None,
                })
                .collect(),
        }
    }

    #[test]
    fn file_order_is_told_without_keeping_the_discs_as_the_plan_decides() {
        // Few discs, discs one or two deep, and discs many deep; a view zoomed in on a corner.
        let mut outcomes = Vec::new();
        for (count, max_radius, zoom) in [
            (20, 30.0, 1.0),
            (2_000, 2.0, 1.0),
            (20_000, 2.0, 1.0),
            (20_000, 2.0, 0.05),
        ] {
            let scene = scene(count, max_radius);
            let mut view = View::of_camera(&scene.camera, 120, 90, DepthRange::new(0.0, 1.0));
            view.size_world *= zoom;
            let basis = view.validate().unwrap();
            let (discs, depths) = project_discs_with_depths(&scene, &view, &basis);
            let plan = depth_order::Plan::of(&discs, &depths, &view.grid(), 4.0);
            let in_file_order = matches!(plan, depth_order::Plan::FileOrder);
            assert_eq!(
                draws_in_file_order(&scene, &view, &basis),
                in_file_order,
                "{count} spheres up to {max_radius}, zoom {zoom}"
            );
            outcomes.push(in_file_order);
        }
        assert!(
            outcomes.contains(&true) && outcomes.contains(&false),
            "{outcomes:?}"
        );
    }
}
