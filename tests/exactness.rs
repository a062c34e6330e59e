//! Exactness at the extremes. Seeded random cases over magnitudes 1e-8..1e8 check invariants of
//! the renderer (f64) against the double-double reference of `oracle::high_precision`, and one
//! test per extreme compares the renderer with the reference pixel by pixel.
//!
//! Stated bounds:
//! * a hit point lies on its sphere within `8·ε₆₄·(|w| + r + size)` (w: the centre's distance along
//!   the view direction from the camera centre; ε₆₄ = 2⁻⁵³);
//! * hit/miss agrees with the reference on every pixel farther than 1e-12 (relative, `|r² − d²| /
//!   max(r², d²)`) from a silhouette and from a tie — the disc path is exact up to f64 rounding, so
//!   any pixel "outside the silhouette by that margin" misses and any inside hits;
//! * t agrees with the reference within `32·ε₆₄·(|t| + r + size)·(1 + r/√(r² − d²))` — backward
//!   stable: a few roundings of the camera basis and the projection, each relative to the
//!   coordinates involved, magnified near a silhouette where t's slope is infinite — and the grey
//!   value within that plus `2·ε₆₄·(|t| + |depth_max|)`, over the range's width (in levels); every
//!   extreme below keeps that under a quarter of a grey level on at least 80% of its hit pixels
//!   (the rest lie at silhouettes), so its 8-bit depth image can differ from the reference only
//!   where the exact grey value sits on a rounding boundary;

#[path = "common/exact.rs"]
mod exact;

use glam::{DVec3, Vec3};
use raytracer::oracle::high_precision::HighPrecision;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::rng::SplitMix64;
use raytracer::render::{NO_HIT, View, render};
use raytracer::scene::{OrthographicCamera, Scene, Sphere};

use exact::*;

#[test]
fn extreme_tiny_spheres_seen_from_very_far() {
    // distance / radius = 1e12: radius 1e-6 seen from 1e6 away.
    let target = DVec3::new(0.25, -0.5, 0.125);
    let scene = scene_with(
        camera_at(target, 1e6, 3e-6, (0.0, 0.0)),
        &[
            (target, 1e-6),
            (target + DVec3::new(7e-7, 1e-7, 2e-6), 4e-7),
        ],
    );
    // At 1e6, one ulp of t is 1.2e-10: a depth range of 1e-3 keeps a grey level 3e4 ulps wide.
    let mut view = view_of(&scene, 48, 48);
    view.depth_range = DepthRange::new(1e6 - 1e-3, 1e6 + 1e-3);
    assert_exact("tiny and far", &scene, &view);
}

#[test]
fn extreme_world_coordinates_in_the_millions() {
    let target = DVec3::new(3.25e6, -2.5e6, 7.75e6);
    let scene = scene_with(
        camera_at(target, 10.0, 3.0, (0.0, 0.0)),
        &[(target, 1.0), (target + DVec3::new(0.7, 0.1, 0.9), 0.5)],
    );
    assert_exact("millions", &scene, &view_of(&scene, 48, 48));
    // And in the billions.
    let target = DVec3::new(4.5e9, 1.25e9, -3e9);
    let scene = scene_with(
        camera_at(target, 10.0, 3.0, (0.0, 0.0)),
        &[(target, 1.0), (target + DVec3::new(0.7, 0.1, 0.9), 0.5)],
    );
    assert_exact("billions", &scene, &view_of(&scene, 48, 48));
}

#[test]
fn extreme_view_zoomed_to_a_millionth() {
    // A unit sphere's silhouette seen through a screen 1e-6 wide.
    let edge = std::f64::consts::FRAC_1_SQRT_2;
    let scene = scene_with(
        camera_at(DVec3::ZERO, 10.0, 1e-6, (edge, edge)),
        &[(DVec3::ZERO, 1.0)],
    );
    assert_exact("zoomed 1e-6", &scene, &view_of(&scene, 48, 48));
    let scene = scene_with(
        camera_at(DVec3::ZERO, 10.0, 1e-9, (edge, -edge)),
        &[(DVec3::ZERO, 1.0)],
    );
    assert_exact("zoomed 1e-9", &scene, &view_of(&scene, 48, 48));
}

#[test]
fn extreme_huge_sphere_seen_edge_on() {
    // Radius 1e6; the screen (2 units) straddles its silhouette, the camera 2e6 away.
    let scene = scene_with(
        camera_at(DVec3::ZERO, 2e6, 2.0, (1e6, 0.3)),
        &[(DVec3::ZERO, 1e6), (DVec3::new(1e3, 5e5, 3e3), 1.0)],
    );
    assert_exact("huge edge-on", &scene, &view_of(&scene, 48, 48));
}

#[test]
fn extreme_camera_inside_spheres() {
    let scene = scene_with(
        camera_at(DVec3::ZERO, 0.0, 5.0, (0.0, 0.0)),
        &[
            (DVec3::new(-1.0, 0.0, -1.0), 1.0),
            (DVec3::ZERO, 1.0),
            (DVec3::new(1.0, 0.0, 1.0), 1.0),
            (DVec3::new(0.0, 0.2, 0.1), 1e-3),
        ],
    );
    let view = view_of(&scene, 48, 48);
    assert_exact("inside", &scene, &view);
    assert!(
        view.depth_range.min_t < 0.0,
        "the nearest surface is behind the camera centre"
    );
}

#[test]
fn extreme_non_square_and_skewed_cameras() {
    let mut camera = camera_at(DVec3::ZERO, 20.0, 6.0, (0.4, -0.2));
    camera.up_world = DVec3::new(5.0, 0.1, -3.0); // far from perpendicular, far from unit
    let spheres: Vec<(DVec3, f64)> = (0..12)
        .map(|i| {
            let a = f64::from(i) * 0.9;
            (
                DVec3::new(2.0 * a.cos(), 1.5 * a.sin(), 0.3 * a),
                0.4 + 0.05 * f64::from(i),
            )
        })
        .collect();
    let scene = scene_with(camera, &spheres);
    assert_exact("wide", &scene, &view_of(&scene, 61, 23));
    assert_exact("tall", &scene, &view_of(&scene, 19, 57));
}

#[test]
fn extreme_narrow_depth_range_far_away() {
    // The view at distance 1e5 with the depth range [99999.996, 100000.0015] of the issue.
    let target = DVec3::new(0.0, 0.0, 0.0);
    let scene = scene_with(
        OrthographicCamera {
            center_world: DVec3::new(0.0, 0.0, 1e5),
            direction_world: DVec3::NEG_Z,
            up_world: DVec3::Y,
            size_world: 0.02,
        },
        &[(target, 0.004), (DVec3::new(0.003, 0.002, 0.001), 0.003)],
    );
    let mut view = view_of(&scene, 48, 48);
    view.depth_range = DepthRange::new(99_999.996, 100_000.001_5);
    assert_exact("narrow far range", &scene, &view);
}

#[test]
fn degenerate_cases_are_defined() {
    let target = DVec3::ZERO;
    let mut scene = scene_with(
        OrthographicCamera {
            center_world: DVec3::new(0.0, 0.0, 10.0),
            direction_world: DVec3::NEG_Z,
            up_world: DVec3::Y,
            size_world: 2.0,
        },
        &[(target, 0.0), (DVec3::new(0.5, 0.5, 0.0), 0.25)],
    );
    // Radius 0: a point, hit only by the ray exactly through it (the centre pixel of an odd image).
    let view = view_of(&scene, 11, 11);
    let frame = render(&scene, &view).unwrap();
    assert_eq!(frame.sphere[frame.index(5, 5)], 0);
    assert_eq!(frame.t[frame.index(5, 5)], 10.0);
    assert_eq!(frame.sphere.iter().filter(|&&s| s == 0).count(), 1);
    // depth_min == depth_max: a step, no NaN.
    let mut flat = view;
    flat.depth_range = DepthRange::new(10.0, 10.0);
    let depth = frame.depth_image(flat.depth_range);
    assert_eq!(depth.get_pixel(5, 5).0, [255; 3]);
    // Zero direction, up parallel, size ≤ 0: errors.
    for broken in [
        View {
            direction_world: DVec3::ZERO,
            ..view
        },
        View {
            up_world: DVec3::new(0.0, 0.0, -3.0),
            ..view
        },
        View {
            size_world: 0.0,
            ..view
        },
        View {
            size_world: -1.0,
            ..view
        },
    ] {
        assert!(render(&scene, &broken).is_err(), "{broken:?}");
    }
    // The largest accepted magnitudes still give finite pixels.
    scene.spheres[1].center_world = DVec3::splat(1e150);
    scene.spheres[1].radius_world = 1e150;
    let frame = render(&scene, &view_of(&scene, 11, 11)).unwrap();
    assert!(
        frame
            .t
            .iter()
            .all(|t| !t.is_nan() && *t != f64::NEG_INFINITY)
    );
}

#[test]
fn the_double_double_reference_is_exact_on_integer_geometry() {
    // Integer coordinates, an axis-aligned camera and unit pixels: every quantity is a
    // half-integer, so exact integer arithmetic (i128) gives the true hit and t. The discs are huge
    // (radius 2^20..2^31) with their edge across the 16-pixel image: r² and d² need up to 64 bits
    // and differ in the last ones, where f64 (53 bits) has nothing left; the reference must still
    // decide every pixel and give t to within two units in the last place.
    let mut rng = SplitMix64::new(0x5EED_00DD);
    let side = 16i64;
    let (mut hits, mut misses) = (0, 0);
    for case in 0..300 {
        let integer = |rng: &mut SplitMix64, low: f64, high: f64| rng.uniform(low, high).round();
        let camera = DVec3::new(
            integer(&mut rng, -1e12, 1e12),
            integer(&mut rng, -1e12, 1e12),
            integer(&mut rng, -1e12, 1e12),
        );
        let radius = rng.uniform(2f64.powi(20), 2f64.powi(31)).round();
        // The disc's centre (u0, v0) from the camera centre: its left edge crosses the image.
        let u0 = -radius + integer(&mut rng, -8.0, 8.0);
        let v0 = integer(&mut rng, -8.0, 8.0);
        let w = integer(&mut rng, -1e9, 1e9);
        let scene = Scene {
            camera: OrthographicCamera {
                center_world: camera,
                direction_world: DVec3::NEG_Z,
                up_world: DVec3::Y,
                size_world: side as f64,
            },
            background: Vec3::ZERO,
            materials: Vec::new(),
            spheres: vec![Sphere {
                center_world: camera + DVec3::new(u0, v0, -w),
                radius_world: radius,
                material: None,
            }],
        };
        let view = View::of_camera(&scene.camera, 16, 16, DepthRange::new(0.0, 1.0));
        let reference = HighPrecision::new(&scene, &view).unwrap();
        for y_up in 0..16i64 {
            for x in 0..16i64 {
                // Twice the pixel centre's offset from the disc's centre, exactly.
                let a = i128::from(2 * x + 1 - side) - 2 * (u0 as i128);
                let b = i128::from(2 * y_up + 1 - side) - 2 * (v0 as i128);
                let four_r_sq = 4 * (radius as i128) * (radius as i128);
                // 4·(r² − d²), exactly.
                let n = four_r_sq - a * a - b * b;
                let truth = reference.pixel(x as u32, y_up as u32);
                if n < 0 {
                    misses += 1;
                    assert_eq!(truth.hit, None, "case {case} ({x}, {y_up}): a miss");
                    continue;
                }
                hits += 1;
                // t = w − √n / 2, with √n to 30 binary places.
                let root = ((n as u128) << 60).isqrt();
                let t = w - root as f64 / 2f64.powi(31);
                let (_, got) = truth.hit.expect("a hit");
                let ulp = f64::EPSILON * t.abs().max(1.0);
                assert!(
                    (got - t).abs() <= 2.0 * ulp,
                    "case {case} ({x}, {y_up}): t {got} against {t}"
                );
            }
        }
    }
    assert!(
        hits > 10_000 && misses > 10_000,
        "{hits} hits, {misses} misses"
    );
}

#[test]
fn a_camera_3e73_away_still_shows_its_spheres() {
    // Found by the `scene` fuzz target (when an f32 mode existed, every sphere vanished from its
    // frame: the depth overflowed f32). The f64 path must keep the spheres and finite depths.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/regressions/fuzz-scene-f32-overflow.txt");
    let scene = raytracer::scene::load_scene(&path).unwrap();
    let view = View::of_camera(&scene.camera, 8, 6, DepthRange::new(0.0, 1.0));
    let exact = render(&scene, &view).unwrap();
    assert!(
        exact.sphere.iter().any(|&s| s != NO_HIT),
        "the spheres are in view"
    );
    for (&t, &sphere) in exact.t.iter().zip(&exact.sphere) {
        assert_eq!(t.is_finite(), sphere != NO_HIT, "t finite iff hit");
    }
}
