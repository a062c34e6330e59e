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

use glam::{DVec3, Vec3};
use raytracer::explore::initial_depth_range;
use raytracer::geometry::ray_sphere::{Ray, ray_sphere_nearest_t};
use raytracer::oracle::high_precision::HighPrecision;
use raytracer::oracle::ray_loop::render_reference;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::disc::{nearest_hit, project_discs};
use raytracer::render::rng::SplitMix64;
use raytracer::render::{Frame, NO_HIT, View, render};
use raytracer::scene::{Material, OrthographicCamera, Scene, Sphere};

const EPSILON: f64 = f64::EPSILON / 2.0;

/// Pixels within this relative distance of a silhouette or a tie are ambiguous at f64 precision.
const AMBIGUOUS: f64 = 1e-12;

fn scene_with(camera: OrthographicCamera, spheres: &[(DVec3, f64)]) -> Scene {
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

fn view_of(scene: &Scene, width_px: u32, height_px: u32) -> View {
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
fn compare_with_reference(scene: &Scene, view: &View, frame: &Frame) -> (usize, usize) {
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
fn assert_exact(name: &str, scene: &Scene, view: &View) {
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
fn camera_at(target: DVec3, distance: f64, size: f64, offset: (f64, f64)) -> OrthographicCamera {
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

/// A random scene with magnitudes drawn log-uniformly from 1e-8..1e8: a sphere, a camera at some
/// distance along a random direction, a view sized to the sphere, and a few other spheres.
fn random_case(rng: &mut SplitMix64) -> (Scene, View) {
    let signed = |rng: &mut SplitMix64, low: f64, high: f64| {
        let magnitude = rng.log_uniform(low, high);
        if rng.unit() < 0.5 {
            -magnitude
        } else {
            magnitude
        }
    };
    let center = DVec3::new(
        signed(rng, 1e-8, 1e8),
        signed(rng, 1e-8, 1e8),
        signed(rng, 1e-8, 1e8),
    );
    let radius = rng.log_uniform(1e-8, 1e8);
    let distance = radius * rng.log_uniform(1e-2, 1e6);
    let direction = DVec3::new(
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
    );
    let direction = if direction.length() < 0.1 {
        DVec3::NEG_Z
    } else {
        direction
    };
    let up = DVec3::new(rng.uniform(-1.0, 1.0), 1.0, rng.uniform(-1.0, 1.0));
    let size = radius * rng.log_uniform(0.5, 8.0);
    let basis = raytracer::geometry::camera::CameraBasis::new(direction, up).unwrap();
    let offset = radius * rng.uniform(-1.0, 1.0);
    let camera = OrthographicCamera {
        center_world: center - distance * basis.direction + offset * basis.horizontal,
        direction_world: direction,
        up_world: up,
        size_world: size,
    };
    let mut spheres = vec![(center, radius)];
    for _ in 0..3 {
        let other = center
            + radius
                * DVec3::new(
                    rng.uniform(-2.0, 2.0),
                    rng.uniform(-2.0, 2.0),
                    rng.uniform(-2.0, 2.0),
                );
        spheres.push((other, radius * rng.log_uniform(0.05, 1.0)));
    }
    let scene = scene_with(camera, &spheres);
    let view = view_of(&scene, 12, 10);
    (scene, view)
}

#[test]
fn seeded_cases_agree_with_the_reference_and_have_no_nan() {
    let mut rng = SplitMix64::new(0x5EED_0001);
    let (mut compared, mut hits, mut pixels) = (0, 0, 0);
    for case in 0..300 {
        let (scene, view) = random_case(&mut rng);
        let frame = render(&scene, &view).unwrap();
        for &t in &frame.t {
            assert!(
                !t.is_nan() && t != f64::NEG_INFINITY,
                "case {case}: t = {t}"
            );
        }
        for (&t, &sphere) in frame.t.iter().zip(&frame.sphere) {
            assert_eq!(
                t.is_finite(),
                sphere != NO_HIT,
                "case {case}: t finite iff hit"
            );
        }
        let (case_compared, case_hits) = compare_with_reference(&scene, &view, &frame);
        compared += case_compared;
        hits += case_hits;
        pixels += frame.pixel_count();
    }
    // Pixels within rounding of a silhouette or a tie are skipped; nearly all others count, and
    // many of them are hits.
    assert!(
        compared * 10 >= pixels * 9,
        "only {compared} of {pixels} pixels were compared"
    );
    assert!(
        hits * 4 >= compared,
        "only {hits} of {compared} compared pixels hit a sphere"
    );
}

#[test]
fn seeded_hit_points_lie_on_their_sphere() {
    let mut rng = SplitMix64::new(0x5EED_0002);
    let mut checked = 0;
    for _ in 0..300 {
        let (scene, view) = random_case(&mut rng);
        let frame = render(&scene, &view).unwrap();
        let reference = HighPrecision::new(&scene, &view).unwrap();
        let basis = view.validate().unwrap();
        for y_up in 0..view.height_px {
            for x in 0..view.width_px {
                let index = frame.index(x, y_up);
                let sphere_index = frame.sphere[index];
                if sphere_index == NO_HIT {
                    continue;
                }
                let sphere = &scene.spheres[sphere_index as usize];
                let w = (sphere.center_world - view.center_world).dot(basis.direction);
                let bound = 8.0 * EPSILON * (w.abs() + sphere.radius_world + view.size_world);
                let error = reference.distance_from_surface(sphere_index, x, y_up, frame.t[index]);
                assert!(
                    error <= bound,
                    "hit point off its sphere by {error:e} (bound {bound:e}), r = {:e}",
                    sphere.radius_world
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 5_000, "only {checked} hit points checked");
}

#[test]
fn seeded_rays_through_projected_centres_always_hit() {
    let mut rng = SplitMix64::new(0x5EED_0003);
    for _ in 0..1_000 {
        let (scene, view) = random_case(&mut rng);
        let basis = view.validate().unwrap();
        let discs = project_discs(&scene, &view, &basis);
        // The screen point of each sphere's centre, computed here without the renderer's
        // projection: a basis of our own (d, then d × up, then h × d, each normalised) and the
        // centre's offset from the camera centre dotted with it.
        let d = view.direction_world.normalize();
        let h = d.cross(view.up_world).normalize();
        let s = h.cross(d).normalize();
        for (index, sphere) in (0u32..).zip(&scene.spheres) {
            let offset = sphere.center_world - view.center_world;
            let (u, v, w) = (offset.dot(h), offset.dot(s), offset.dot(d));
            // The disc path hits there, and its t is the front of the sphere (w − r) within the
            // rounding of a projection (the camera is at most 1e6 radii away).
            let (t, _) = nearest_hit(&discs, u, v).expect("the centre always hits");
            let front = w - sphere.radius_world;
            let tolerance = 1e-9 * (offset.length() + sphere.radius_world);
            let own = discs[index as usize]
                .hit_t(u, v)
                .expect("its own disc hits");
            assert!(
                (own - front).abs() <= tolerance,
                "t {own} against w − r = {front} (±{tolerance})"
            );
            assert!(t <= own, "the nearest hit is no farther than this sphere's");
            let disc = &discs[index as usize];
            // The careful routine: a ray aimed at the centre from up to 1e12 radii away.
            let sphere = &scene.spheres[disc.sphere as usize];
            let distance = sphere.radius_world * rng.log_uniform(1.0, 1e12);
            let ray = Ray {
                origin_world: sphere.center_world - distance * basis.direction,
                direction_world: basis.direction,
            };
            assert!(
                ray_sphere_nearest_t(&ray, sphere.center_world, sphere.radius_world).is_some(),
                "careful routine missed the centre from {} radii",
                distance / sphere.radius_world
            );
        }
    }
}

#[test]
fn seeded_points_outside_the_silhouette_by_a_margin_never_hit() {
    let mut rng = SplitMix64::new(0x5EED_0004);
    for _ in 0..2_000 {
        let (scene, view) = random_case(&mut rng);
        let basis = view.validate().unwrap();
        let discs = project_discs(&scene, &view, &basis);
        let disc = discs[0];
        let radius = disc.radius_sq.sqrt();
        let angle = rng.uniform(0.0, std::f64::consts::TAU);
        // 1e-9 outside (relative to the radius): the disc path misses; 1e-9 inside: it hits.
        let (sin, cos) = angle.sin_cos();
        let outside = radius * (1.0 + 1e-9);
        let inside = radius * (1.0 - 1e-9);
        assert!(
            discs[0]
                .hit_t(disc.u + outside * cos, disc.v + outside * sin)
                .is_none()
        );
        assert!(
            discs[0]
                .hit_t(disc.u + inside * cos, disc.v + inside * sin)
                .is_some()
        );
        // The careful routine works in world space: a ray from up to 1e6 radii away misses when it
        // passes outside by 1e-6·r plus the rounding of its world coordinates, 16·ε·(|c| + L).
        let sphere = &scene.spheres[0];
        let distance = sphere.radius_world * rng.log_uniform(1.0, 1e6);
        let margin =
            1e-6 * sphere.radius_world + 16.0 * EPSILON * (sphere.center_world.length() + distance);
        let sideways = cos * basis.horizontal + sin * basis.screen_up;
        let ray = Ray {
            origin_world: sphere.center_world - distance * basis.direction
                + sideways * (sphere.radius_world + margin),
            direction_world: basis.direction,
        };
        assert!(ray_sphere_nearest_t(&ray, sphere.center_world, sphere.radius_world).is_none());
    }
}

#[test]
fn seeded_disc_path_and_careful_routine_agree_on_hit_and_miss() {
    // The oracle casts world-space rays: its own rounding grows with |coordinates| / radius, so the
    // cases keep the scene within 1e6 radii of the origin and compare away from silhouettes.
    let mut rng = SplitMix64::new(0x5EED_0005);
    let mut compared = 0;
    for _ in 0..300 {
        let (mut scene, _) = random_case(&mut rng);
        let scale = scene.spheres[0].radius_world;
        let shift = scene.spheres[0].center_world - scale * DVec3::new(0.3, -0.2, 0.1);
        for sphere in &mut scene.spheres {
            sphere.center_world -= shift;
        }
        scene.camera.center_world -= shift;
        let view = view_of(&scene, 12, 10);
        let fast = render(&scene, &view).unwrap();
        let oracle = render_reference(&scene, &view).unwrap();
        let reference = HighPrecision::new(&scene, &view).unwrap();
        for y_up in 0..view.height_px {
            for x in 0..view.width_px {
                let truth = reference.pixel(x, y_up);
                if truth.silhouette_margin < 1e-6 || truth.tie_margin < 1e-6 {
                    continue;
                }
                let index = fast.index(x, y_up);
                assert_eq!(
                    fast.sphere[index], oracle.sphere[index],
                    "pixel ({x}, {y_up})"
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 20_000, "only {compared} pixels compared");
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
