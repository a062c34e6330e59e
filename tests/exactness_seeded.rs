//! Exactness over seeded random cases: magnitudes drawn log-uniformly over 1e-8..1e8, checked
//! against the double-double reference within the bounds stated in `tests/exactness.rs`
//! (invariants: no NaN, hit points on their sphere, rays through projected centres hit, points
//! outside a silhouette by a margin miss, the disc path and the careful routine agree).

#[path = "common/exact.rs"]
mod exact;

use glam::DVec3;
use raytracer::geometry::ray_sphere::{Ray, ray_sphere_nearest_t};
use raytracer::oracle::high_precision::HighPrecision;
use raytracer::oracle::ray_loop::render_reference;
use raytracer::render::disc::{nearest_hit, project_discs};
use raytracer::render::rng::SplitMix64;
use raytracer::render::{NO_HIT, View, render};
use raytracer::scene::{OrthographicCamera, Scene};

use exact::*;

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
