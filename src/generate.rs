//! Seeded scene generation for tests and benchmarks: N spheres scattered in a cube, seen through
//! a skewed camera, the same scene for the same (seed, count) on every machine; and writing any
//! scene back as scene-file text.

use std::fmt::Write as _;

use glam::{DVec3, Vec3};

use crate::scene::{Material, OrthographicCamera, Scene, Sphere};

/// SplitMix64: a small, fast, well-mixed generator; enough for reproducible test data.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [low, high).
    pub fn uniform(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.unit()
    }

    /// Log-uniform in [low, high) (both > 0): every decade equally likely.
    pub fn log_uniform(&mut self, low: f64, high: f64) -> f64 {
        (low.ln() + (high.ln() - low.ln()) * self.unit()).exp()
    }
}

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

/// The scene as scene-file text (numbers written exactly: Rust's shortest round-trip form).
pub fn scene_to_text(scene: &Scene) -> String {
    let mut text = String::new();
    let camera = &scene.camera;
    let v = |v: DVec3| format!("{} {} {}", v.x, v.y, v.z);
    let c = |c: Vec3| format!("{} {} {}", c.x, c.y, c.z);
    // Writing to a String cannot fail.
    let _ = write!(
        text,
        "OrthographicCamera {{\n    center {}\n    direction {}\n    up {}\n    size {}\n}}\n\n\
         Background {{ color {} }}\n\nMaterials {{\n    numMaterials {}\n",
        v(camera.center_world),
        v(camera.direction_world),
        v(camera.up_world),
        camera.size_world,
        c(scene.background),
        scene.materials.len()
    );
    for material in &scene.materials {
        let _ = writeln!(
            text,
            "    PhongMaterial {{ diffuseColor {} }}",
            c(material.diffuse_colour)
        );
    }
    let _ = write!(
        text,
        "}}\n\nGroup {{\n    numObjects {}\n",
        scene.spheres.len()
    );
    let mut current = None;
    for sphere in &scene.spheres {
        if sphere.material != current
            && let Some(index) = sphere.material
        {
            let _ = writeln!(text, "    MaterialIndex {index}");
            current = sphere.material;
        }
        let _ = writeln!(
            text,
            "    Sphere {{ center {} radius {} }}",
            v(sphere.center_world),
            sphere.radius_world
        );
    }
    text.push_str("}\n");
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;

    #[test]
    fn same_seed_same_scene_and_text_round_trips() {
        let scene = random_scene(42, 500);
        assert_eq!(scene, random_scene(42, 500));
        assert_ne!(scene, random_scene(43, 500));
        let parsed = parse_scene(&scene_to_text(&scene)).unwrap();
        assert_eq!(parsed, scene);
    }

    #[test]
    fn log_uniform_covers_the_decades() {
        let mut rng = SplitMix64::new(1);
        let values: Vec<f64> = (0..10_000).map(|_| rng.log_uniform(1e-8, 1e8)).collect();
        assert!(values.iter().all(|&v| (1e-8..1e8).contains(&v)));
        let below_one = values.iter().filter(|&&v| v < 1.0).count();
        assert!((4_000..6_000).contains(&below_one), "{below_one}");
    }
}
