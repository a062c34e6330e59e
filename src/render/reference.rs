//! The oracle: the straightforward per-pixel loop over all spheres, one world-space ray per pixel
//! through [`crate::intersect::ray_sphere_nearest_t`], single-threaded. Slow and obviously right;
//! the fast path is tested and benchmarked against it.

use super::disc::frame_from_hits;
use super::{Frame, NO_HIT, View, ViewError};
use crate::intersect::{Ray, ray_sphere_nearest_t};
use crate::scene::Scene;

/// Renders `scene` through `view` ray by ray (see the module docs).
pub fn render_reference(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    let basis = view.validate()?;
    let grid = view.grid();
    let (width, height) = (view.width_px, view.height_px);
    let mut t = Vec::with_capacity(width as usize * height as usize);
    let mut sphere = Vec::with_capacity(t.capacity());
    for row in 0..height {
        let y_up = height - 1 - row;
        for x in 0..width {
            let u = grid.u_of_column(f64::from(x));
            let v = grid.v_of_row(f64::from(y_up));
            let ray = Ray {
                origin_world: view.center_world + u * basis.horizontal + v * basis.screen_up,
                direction_world: basis.direction,
            };
            let mut best = (f64::INFINITY, NO_HIT);
            for (index, s) in (0u32..).zip(&scene.spheres) {
                if let Some(hit_t) = ray_sphere_nearest_t(&ray, s.center_world, s.radius_world)
                    && hit_t < best.0
                {
                    best = (hit_t, index);
                }
            }
            t.push(best.0);
            sphere.push(best.1);
        }
    }
    Ok(frame_from_hits(scene, view, t, sphere))
}
