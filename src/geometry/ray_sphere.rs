//! General ray–sphere intersection, numerically careful: the reference semantics the fast
//! renderer is tested against.
//!
//! For a ray `o + t·d` with unit `d` and a sphere (c, r), let `f = o − c` and `b = f·d`. The
//! roots are `−b ± √Δ` with the discriminant computed as `Δ = r² − |f − b·d|²` (the squared
//! distance from the centre to the ray, subtracted from r²: no catastrophic cancellation of
//! `b² − (|f|² − r²)`), and the stable pair `q = −(b + sign(b)·√Δ)`, `t = q` and `t = (|f|² − r²)/q`
//! (Ray Tracing Gems, ch. 7; pbrt-v4 `Sphere::BasicIntersect`).

use glam::DVec3;

/// A ray in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Where t = 0.
    pub origin_world: DVec3,
    /// Unit direction.
    pub direction_world: DVec3,
}

/// Both roots (smaller first) of a ray with a sphere, or `None` if the ray misses.
/// A tangent ray (Δ = 0) hits, with both roots equal.
pub(crate) fn ray_sphere_roots(
    ray: &Ray,
    center_world: DVec3,
    radius_world: f64,
) -> Option<(f64, f64)> {
    let d = ray.direction_world;
    let f = ray.origin_world - center_world;
    let b = f.dot(d);
    let perpendicular = f - b * d;
    let discriminant = radius_world * radius_world - perpendicular.length_squared();
    if discriminant < 0.0 || discriminant.is_nan() {
        return None;
    }
    let root = discriminant.sqrt();
    let q = -(b + root.copysign(b));
    if q == 0.0 {
        // b = 0 and Δ = 0: the ray grazes the sphere at its origin.
        return Some((0.0, 0.0));
    }
    let c = f.length_squared() - radius_world * radius_world;
    let (t0, t1) = (c / q, q);
    Some(if t0 <= t1 { (t0, t1) } else { (t1, t0) })
}

/// The visible hit for the orthographic camera (tmin = −∞): the smaller root, if any.
pub fn ray_sphere_nearest_t(ray: &Ray, center_world: DVec3, radius_world: f64) -> Option<f64> {
    ray_sphere_roots(ray, center_world, radius_world).map(|(near, _)| near)
}

/// The textbook ray–sphere test in f32: `a = d·d`, `b = 2·(o − c)·d`, `c = |o − c|² − r²`,
/// discriminant `b² − 4ac`, `t = (−b − √disc) / 2a`. Kept only as the error study's baseline:
/// `b²` and `4ac` cancel catastrophically once distance/radius passes about 4000 (√ of f32's
/// epsilon⁻¹), and world coordinates far from the origin make `o − c` lose the sphere entirely.
#[cfg(any(test, feature = "oracle"))]
pub(crate) fn textbook_nearest_t_f32(
    origin: [f32; 3],
    direction: [f32; 3],
    center: [f32; 3],
    radius: f32,
) -> Option<f32> {
    let oc = [
        origin[0] - center[0],
        origin[1] - center[1],
        origin[2] - center[2],
    ];
    let dot = |p: [f32; 3], q: [f32; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    let a = dot(direction, direction);
    let b = 2.0 * dot(oc, direction);
    let c = dot(oc, oc) - radius * radius;
    let discriminant = b * b - 4.0 * a * c;
    if discriminant.is_nan() || discriminant < 0.0 {
        return None;
    }
    Some((-b - discriminant.sqrt()) / (2.0 * a))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(origin: [f64; 3], direction: [f64; 3]) -> Ray {
        Ray {
            origin_world: DVec3::from(origin),
            direction_world: DVec3::from(direction).normalize(),
        }
    }

    #[test]
    fn hits_in_front_with_both_roots() {
        let r = ray([0.0, 0.0, 10.0], [0.0, 0.0, -1.0]);
        assert_eq!(ray_sphere_roots(&r, DVec3::ZERO, 1.0), Some((9.0, 11.0)));
    }

    #[test]
    fn camera_inside_the_sphere_sees_the_negative_root() {
        let r = ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
        assert_eq!(ray_sphere_nearest_t(&r, DVec3::ZERO, 1.0), Some(-1.0));
    }

    #[test]
    fn sphere_behind_the_origin_is_still_hit() {
        let r = ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
        assert_eq!(
            ray_sphere_nearest_t(&r, DVec3::new(0.0, 0.0, 5.0), 1.0),
            Some(-6.0)
        );
    }

    #[test]
    fn tangent_ray_hits_once() {
        let r = ray([1.0, 0.0, 10.0], [0.0, 0.0, -1.0]);
        assert_eq!(ray_sphere_roots(&r, DVec3::ZERO, 1.0), Some((10.0, 10.0)));
        let r = ray([1.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
        assert_eq!(ray_sphere_roots(&r, DVec3::ZERO, 1.0), Some((0.0, 0.0)));
    }

    #[test]
    fn misses_just_outside() {
        let r = ray([1.0 + 1e-12, 0.0, 10.0], [0.0, 0.0, -1.0]);
        assert_eq!(ray_sphere_roots(&r, DVec3::ZERO, 1.0), None);
    }

    #[test]
    fn textbook_f32_is_right_up_close_and_wrong_far_away() {
        let near = textbook_nearest_t_f32([0.0, 0.5, 10.0], [0.0, 0.0, -1.0], [0.0; 3], 1.0);
        assert!((near.unwrap() - (10.0 - 0.75f32.sqrt())).abs() < 1e-5);
        // distance/radius = 1e6: the discriminant is pure rounding noise.
        let far = textbook_nearest_t_f32([0.0, 0.5, 1e6], [0.0, 0.0, -1.0], [0.0; 3], 1.0);
        let error = far.map_or(f32::INFINITY, |t| (t - (1e6 - 0.75f32.sqrt())).abs());
        assert!(error > 0.1, "textbook f32 should fail here, error {error}");
    }

    #[test]
    fn far_small_sphere_keeps_full_precision() {
        // distance/radius = 1e9: the textbook b² − 4ac in f32 cannot even tell hit from miss.
        let r = ray([0.0, 0.5e-3, 1e6], [0.0, 0.0, -1.0]);
        let (near, far) = ray_sphere_roots(&r, DVec3::ZERO, 1e-3).unwrap();
        let half_chord = (1e-6_f64 - 0.25e-6).sqrt();
        assert!((near - (1e6 - half_chord)).abs() <= 1e-9);
        assert!((far - (1e6 + half_chord)).abs() <= 1e-9);
    }
}
