//! The oracle: the straightforward per-pixel loop over all spheres, one world-space ray per pixel
//! through [`crate::geometry::ray_sphere::ray_sphere_nearest_t`], single-threaded. Slow and obviously right;
//! the fast path is tested and benchmarked against it.

use crate::geometry::ray_sphere::{Ray, ray_sphere_nearest_t, textbook_nearest_t_f32};
use crate::render::disc::frame_from_hits;
use crate::render::{Frame, NO_HIT, View, ViewError};
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

/// The error study's baseline: world-space rays in f32 through the textbook `b² − 4ac`
/// ([`crate::geometry::ray_sphere::textbook_nearest_t_f32`]), the way a first ray tracer is written. Not a
/// rendering mode; it shows what the camera-relative disc path avoids.
pub fn render_textbook_f32(scene: &Scene, view: &View) -> Result<Frame, ViewError> {
    let basis = view.validate()?;
    let grid = view.grid();
    let f32x3 = |v: glam::DVec3| [v.x as f32, v.y as f32, v.z as f32];
    let (center, horizontal, screen_up, direction) = (
        f32x3(view.center_world),
        f32x3(basis.horizontal),
        f32x3(basis.screen_up),
        f32x3(basis.direction),
    );
    let spheres: Vec<([f32; 3], f32)> = scene
        .spheres
        .iter()
        .map(|s| (f32x3(s.center_world), s.radius_world as f32))
        .collect();
    let (width, height) = (view.width_px, view.height_px);
    let mut t = Vec::with_capacity(width as usize * height as usize);
    let mut sphere = Vec::with_capacity(t.capacity());
    for row in 0..height {
        let v = grid.v_of_row(f64::from(height - 1 - row)) as f32;
        for x in 0..width {
            let u = grid.u_of_column(f64::from(x)) as f32;
            let origin = [0, 1, 2].map(|i| center[i] + u * horizontal[i] + v * screen_up[i]);
            let mut best = (f32::INFINITY, NO_HIT);
            for (index, &(sphere_center, radius)) in (0u32..).zip(&spheres) {
                if let Some(hit_t) =
                    textbook_nearest_t_f32(origin, direction, sphere_center, radius)
                    && hit_t < best.0
                {
                    best = (hit_t, index);
                }
            }
            t.push(f64::from(best.0));
            sphere.push(best.1);
        }
    }
    Ok(frame_from_hits(scene, view, t, sphere))
}
