//! The pixel probe: what a pixel of a rendered frame shows — its screen position, the ray through
//! it, and for a hit the world position, t, the sphere's index (file order) and its material.
//!
//! The probe reads the frame's own t and sphere per pixel, so it reports exactly what is on
//! screen; the world position is the ray origin on the screen plane plus t along the unit view
//! direction (f64, relative to the camera centre).

use glam::{DVec2, DVec3, Vec3};

use crate::render::{Frame, NO_HIT, View};
use crate::scene::Scene;

/// What a ray through one pixel hits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProbeHit {
    /// t of the visible hit along the unit view direction, from the screen plane.
    pub t: f64,
    /// The hit point in world coordinates.
    pub point_world: DVec3,
    /// Index of the sphere in file order (0-based).
    pub sphere_index: u32,
    /// The sphere's `MaterialIndex`, `None` when no `MaterialIndex` preceded it.
    pub material_index: Option<u32>,
    /// The material's diffuse colour.
    pub(crate) diffuse_colour: Vec3,
}

/// One probed pixel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Probe {
    /// Pixel column, 0 at the left.
    pub x_px: u32,
    /// Pixel row, 0 at the **bottom** (the convention of docs/spec.md).
    pub y_up_px: u32,
    /// Screen coordinates (u, v) of the pixel centre relative to the camera centre, world units.
    pub(crate) screen_world: DVec2,
    /// The pixel centre on the screen plane, in world coordinates (the ray's origin at t = 0).
    pub(crate) ray_origin_world: DVec3,
    /// The hit, `None` where the ray sees the background.
    pub hit: Option<ProbeHit>,
    /// The pixel's 8-bit colour in the frame.
    pub colour_rgb: [u8; 3],
}

/// Probes pixel (`x_px`, `y_up_px`) of `frame`, which must have been rendered from `scene` through
/// `view`. `None` outside the frame, for an unusable view, or when the frame's size is not the
/// view's.
pub(crate) fn probe(
    scene: &Scene,
    view: &View,
    frame: &Frame,
    x_px: u32,
    y_up_px: u32,
) -> Option<Probe> {
    if x_px >= frame.width_px
        || y_up_px >= frame.height_px
        || (frame.width_px, frame.height_px) != (view.width_px, view.height_px)
    {
        return None;
    }
    let basis = view.validate().ok()?;
    let grid = view.grid();
    let u = grid.u_of_column(f64::from(x_px));
    let v = grid.v_of_row(f64::from(y_up_px));
    let ray_origin_world = view.center_world + u * basis.horizontal + v * basis.screen_up;
    let index = frame.index(x_px, y_up_px);
    let sphere_index = frame.sphere[index];
    let hit = if sphere_index == NO_HIT {
        None
    } else {
        let sphere = scene.spheres.get(sphere_index as usize)?;
        let t = frame.t[index];
        Some(ProbeHit {
            t,
            point_world: view.center_world
                + (u * basis.horizontal + v * basis.screen_up + t * basis.direction),
            sphere_index,
            material_index: sphere.material,
            diffuse_colour: scene.sphere_colour(sphere),
        })
    };
    Some(Probe {
        x_px,
        y_up_px,
        screen_world: DVec2::new(u, v),
        ray_origin_world,
        hit,
        colour_rgb: frame.colour[index],
    })
}

/// Where the world point `point_world` falls on the image of `view`: image pixels from the
/// bottom-left corner (continuous; pixel (x, y) spans [x, x + 1) × [y, y + 1)), whether or not
/// inside the image. `None` for an unusable view. A pinned point follows the view with it.
pub fn pixel_of_point(view: &View, point_world: DVec3) -> Option<DVec2> {
    let basis = view.validate().ok()?;
    let camera = basis.to_camera(point_world - view.center_world);
    let pixel_size = view.grid().pixel_size_world;
    let (width, height) = (f64::from(view.width_px), f64::from(view.height_px));
    let px = DVec2::new(
        camera.x / pixel_size + 0.5 * width,
        camera.y / pixel_size + 0.5 * height,
    );
    px.is_finite().then_some(px)
}

/// The world point a click on pixel position `px` pins: the hit point where the pixel shows a
/// sphere, else the point on the screen plane.
pub fn point_of_probe(probe: &Probe) -> DVec3 {
    probe
        .hit
        .map_or(probe.ray_origin_world, |hit| hit.point_world)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::depth_map::DepthRange;
    use crate::render::render;
    use crate::scene::parse_scene;

    #[test]
    fn probe_reports_what_the_straightforward_loop_sees() {
        let scene = parse_scene(include_str!("../../scenes/scene1_02.txt")).unwrap();
        let view = View::of_camera(&scene.camera, 200, 200, DepthRange::new(8.0, 12.0));
        let frame = render(&scene, &view).unwrap();
        // The oracle: one world-space ray per pixel through the careful ray–sphere routine.
        let oracle = crate::oracle::ray_loop::render_reference(&scene, &view).unwrap();
        let mut hits = 0;
        for (x, y) in [
            (100, 100),
            (150, 150),
            (50, 50),
            (0, 0),
            (199, 199),
            (20, 180),
            (137, 61),
        ] {
            let probe = probe(&scene, &view, &frame, x, y).unwrap();
            let index = oracle.index(x, y);
            let expected = (oracle.sphere[index] != NO_HIT).then_some(oracle.sphere[index]);
            assert_eq!(probe.hit.map(|h| h.sphere_index), expected, "({x}, {y})");
            if let Some(hit) = probe.hit {
                hits += 1;
                assert!(
                    (hit.t - oracle.t[index]).abs() <= 1e-12 * oracle.t[index].abs(),
                    "({x}, {y}): t {} against the loop's {}",
                    hit.t,
                    oracle.t[index]
                );
                let sphere = &scene.spheres[hit.sphere_index as usize];
                let distance = (hit.point_world - sphere.center_world).length();
                assert!(
                    (distance - sphere.radius_world).abs() < 1e-9,
                    "on the sphere"
                );
                assert_eq!(hit.material_index, sphere.material);
                let material = sphere.material.map(|m| scene.materials[m as usize]);
                assert_eq!(
                    hit.diffuse_colour,
                    material.map_or(crate::scene::DEFAULT_DIFFUSE, |m| m.diffuse_colour)
                );
            }
        }
        assert!(hits >= 3);
        assert!(probe(&scene, &view, &frame, 200, 0).is_none());
        assert!(probe(&scene, &view, &frame, 0, 200).is_none());
    }
}
