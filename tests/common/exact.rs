//! Helpers shared by the exactness tests (`tests/exactness.rs`, `tests/exactness_seeded.rs`),
//! included by path: scenes and views made in code, and the pixel-by-pixel comparison with the
//! double-double reference within the stated f64 bounds (see `tests/exactness.rs`).
#![allow(dead_code)] // each test file uses its own share

use glam::{DVec3, Vec3};
use raytracer::explore::initial_depth_range;
use raytracer::oracle::high_precision::HighPrecision;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Frame, NO_HIT, View, render};
use raytracer::scene::{Material, OrthographicCamera, Scene, Sphere};

pub(crate) const EPSILON: f64 = f64::EPSILON / 2.0;

/// Pixels within this relative distance of a silhouette or a tie are ambiguous at f64 precision.
pub(crate) const AMBIGUOUS: f64 = 1e-12;

pub(crate) fn scene_with(camera: OrthographicCamera, spheres: &[(DVec3, f64)]) -> Scene {
    Scene {
        camera,
        background: Vec3::splat(0.2),
        materials: (0..4)
            .map(|i| Material {
                diffuse_colour: Vec3::new(0.2 * i as f32, 0.5, 0.9),
            })
            .collect(),
        spheres: spheres
            .iter()
            .zip(0u32..)
            .map(|(&(center_world, radius_world), i)| Sphere {
                center_world,
                radius_world,
                material: Some(i % 4),
            })
            .collect(),
    }
}

pub(crate) fn view_of(scene: &Scene, width_px: u32, height_px: u32) -> View {
    let mut view = View::of_camera(
        &scene.camera,
        width_px,
        height_px,
        DepthRange::new(0.0, 1.0),
    );
    view.depth_range = initial_depth_range(scene, &view);
    view
}

/// Compares `frame` with the reference on every pixel, within the f64 bounds; returns (pixels
/// compared, pixels hit).
pub(crate) fn compare_with_reference(scene: &Scene, view: &View, frame: &Frame) -> (usize, usize) {
    let reference = HighPrecision::new(scene, view).unwrap();
    let range = view.depth_range;
    let (mut compared, mut hits, mut depth_checked) = (0, 0, 0);
    for y_up in 0..view.height_px {
        for x in 0..view.width_px {
            let truth = reference.pixel(x, y_up);
            let index = frame.index(x, y_up);
            assert!(!frame.t[index].is_nan(), "NaN t at ({x}, {y_up})");
            if truth.silhouette_margin < AMBIGUOUS || truth.tie_margin < AMBIGUOUS {
                continue;
            }
            compared += 1;
            let expected = truth.hit.map_or(NO_HIT, |(s, _)| s);
            assert_eq!(
                frame.sphere[index], expected,
                "pixel ({x}, {y_up}): sphere (margin {:e})",
                truth.silhouette_margin
            );
            if let Some((_, t)) = truth.hit {
                hits += 1;
                let width = (range.max_t - range.min_t).abs();
                let magnification = 1.0 + truth.t_sensitivity / truth.radius.max(f64::MIN_POSITIVE);
                let t_bound =
                    32.0 * EPSILON * (t.abs() + truth.radius + view.size_world) * magnification;
                let level_bound =
                    255.0 * (t_bound + 2.0 * EPSILON * (t.abs() + range.max_t.abs())) / width;
                if level_bound < 0.25 {
                    depth_checked += 1;
                }
                let grey_error = (range.grey(frame.t[index]) - range.grey(t)).abs() * 255.0;
                assert!(
                    grey_error <= level_bound,
                    "pixel ({x}, {y_up}): grey off by {grey_error} levels (bound {level_bound}), \
                     t {} vs {t}",
                    frame.t[index]
                );
            }
        }
    }
    assert!(
        depth_checked * 10 >= hits * 8,
        "the f64 bound resolves a quarter grey level on only {depth_checked} of {hits} hit pixels"
    );
    (compared, hits)
}

/// Renders one sample per pixel and checks it against the reference, requiring a meaningful picture
/// (most pixels compared, some hit, some missed).
pub(crate) fn assert_exact(name: &str, scene: &Scene, view: &View) {
    let frame = render(scene, view).unwrap();
    let (compared, hits) = compare_with_reference(scene, view, &frame);
    let total = frame.pixel_count();
    assert!(
        compared * 10 >= total * 9,
        "{name}: only {compared} of {total} pixels unambiguous"
    );
    assert!(hits > total / 20, "{name}: only {hits} hits");
    assert!(
        hits < compared,
        "{name}: every pixel hit; the silhouette is not in view"
    );
}

/// A camera looking along a skewed direction at `target` from `distance`, with the screen centre
/// shifted by `offset` (screen units).
pub(crate) fn camera_at(
    target: DVec3,
    distance: f64,
    size: f64,
    offset: (f64, f64),
) -> OrthographicCamera {
    let direction = DVec3::new(-0.8, -0.5, -0.33);
    let up = DVec3::new(0.3, 1.7, 0.2);
    let basis = raytracer::geometry::camera::CameraBasis::new(direction, up).unwrap();
    OrthographicCamera {
        center_world: target - distance * basis.direction
            + offset.0 * basis.horizontal
            + offset.1 * basis.screen_up,
        direction_world: direction,
        up_world: up,
        size_world: size,
    }
}
