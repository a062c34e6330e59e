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

/// Side of the cube [`dense_scene`] fills, world units.
pub const DENSE_CUBE_SIDE: f64 = 100.0;

/// `count` spheres of radius 0.2 to 1.0 in a cube of side [`DENSE_CUBE_SIDE`] seen whole (view
/// size 110) through the same skewed camera as [`random_scene`]: at 100,000 spheres a 1024×1024
/// image has every pixel covered about ten times over, at 1,000,000 about a hundred. The scene
/// where the cost should follow the visible work, not the discs piled up behind it.
pub fn dense_scene(seed: u64, count: usize) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let side = DENSE_CUBE_SIDE;
    let mut scene = random_scene(seed, 0);
    scene.spheres = (0..count)
        .map(|i| Sphere {
            center_world: DVec3::new(
                rng.uniform(-0.5, 0.5) * side,
                rng.uniform(-0.5, 0.5) * side,
                rng.uniform(-0.5, 0.5) * side,
            ),
            radius_world: rng.uniform(0.2, 1.0),
            material: Some((i % 16) as u32),
        })
        .collect();
    let direction = scene.camera.direction_world;
    scene.camera.center_world = -2.0 * side * direction.normalize();
    scene.camera.size_world = 110.0;
    scene
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
