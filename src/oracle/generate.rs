//! Seeded scene generation for tests, benchmarks and studies: N spheres scattered in a cube, seen
//! through a skewed camera, the same scene for the same (seed, count) on every machine.

use glam::{DVec3, Vec3};

use crate::render::rng::SplitMix64;
use crate::scene::{Material, OrthographicCamera, Scene, Sphere};

/// `count` spheres in a cube of side `10·count^(1/3)`, radii chosen so that they cover the view
/// about a few times over, 16 materials, a camera looking at the cube's centre along
/// (−1, −0.6, −0.8) with a non-unit up. Same (seed, count) → same scene.
pub fn random_scene(seed: u64, count: usize) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let side = 10.0 * (count.max(1) as f64).cbrt();
    // Mean disc area ≈ side² · coverage / count.
    let mean_radius = side * (2.0 / (std::f64::consts::PI * count.max(1) as f64)).sqrt();
    let materials = (0..16)
        .map(|i| {
            let hue = i as f32 / 16.0;
            Material {
                diffuse_colour: Vec3::new(
                    0.5 + 0.5 * (std::f32::consts::TAU * hue).cos(),
                    0.5 + 0.5 * (std::f32::consts::TAU * (hue + 0.33)).cos(),
                    0.5 + 0.5 * (std::f32::consts::TAU * (hue + 0.67)).cos(),
                ),
            }
        })
        .collect();
    let spheres = (0..count)
        .map(|i| Sphere {
            center_world: DVec3::new(
                rng.uniform(-0.5, 0.5) * side,
                rng.uniform(-0.5, 0.5) * side,
                rng.uniform(-0.5, 0.5) * side,
            ),
            radius_world: mean_radius * rng.uniform(0.3, 1.7),
            material: Some((i % 16) as u32),
        })
        .collect();
    let direction = DVec3::new(-1.0, -0.6, -0.8);
    Scene {
        camera: OrthographicCamera {
            center_world: -2.0 * side * direction.normalize(),
            direction_world: direction,
            up_world: DVec3::new(0.1, 2.0, 0.0),
            size_world: 1.2 * side,
        },
        background: Vec3::new(0.1, 0.1, 0.12),
        materials,
        spheres,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_scene, scene_to_text};

    #[test]
    fn same_seed_same_scene_and_text_round_trips() {
        let scene = random_scene(42, 500);
        assert_eq!(scene, random_scene(42, 500));
        assert_ne!(scene, random_scene(43, 500));
        let parsed = parse_scene(&scene_to_text(&scene)).unwrap();
        assert_eq!(parsed, scene);
    }
}
