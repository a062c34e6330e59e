//! A scene's spheres projected to screen discs, in parallel, with their [`Depths`] (how much of
//! the image the nearest ones cover), and whether a scene is drawn in file order.

use super::depth_order::{self, Depths};
use super::screen_disc::{Disc, project_sphere};
use crate::geometry::camera::CameraBasis;
use crate::render::view::View;
use crate::scene::Scene;

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::depth_map::DepthRange;
    use crate::render::rng::SplitMix64;
    use crate::scene::{OrthographicCamera, Sphere};
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
