//! The scene as plain, validated data: camera, background, materials and a flat list of spheres.
//!
//! The parser ([`crate::scene::parse_scene`]) is the only producer of a [`Scene`] from text; what it
//! returns has been checked (finite numbers, a usable camera, material indices in range), so the
//! renderer never re-validates.

use glam::{DVec3, Vec3};

/// Colour used for the background when a file has no `Background` block (docs/spec.md: 0.5 grey).
pub const DEFAULT_BACKGROUND: Vec3 = Vec3::splat(0.5);

/// Colour of a material without `diffuseColor`, and of spheres that no `MaterialIndex` precedes.
pub const DEFAULT_DIFFUSE: Vec3 = Vec3::ONE;

/// The scene's orthographic camera, exactly as written in the file (not normalised).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrthographicCamera {
    /// World point the square screen is centred on.
    pub center_world: DVec3,
    /// View direction; any non-zero length.
    pub direction_world: DVec3,
    /// Up hint; any length, not necessarily perpendicular to the direction (never parallel to it).
    pub up_world: DVec3,
    /// Width (= height) of the square screen, in world units; > 0.
    pub size_world: f64,
}

/// A flat-coloured material (`PhongMaterial` or `Material` block).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Linear colour; each channel as written (the 8-bit output clamps to [0, 1]).
    pub diffuse_colour: Vec3,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            diffuse_colour: DEFAULT_DIFFUSE,
        }
    }
}

/// A sphere of the scene, in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    /// Centre in world coordinates.
    pub center_world: DVec3,
    /// Radius in world units, finite and ≥ 0.
    pub radius_world: f64,
    /// Index into [`Scene::materials`]; `None` when no `MaterialIndex` preceded the sphere
    /// (it is then drawn in [`DEFAULT_DIFFUSE`]).
    pub material: Option<u32>,
}

/// An axis-aligned box in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Smallest corner.
    pub(crate) min_world: DVec3,
    /// Largest corner.
    pub(crate) max_world: DVec3,
}

impl Bounds {
    /// Centre of the box.
    pub(crate) fn center(&self) -> DVec3 {
        0.5 * (self.min_world + self.max_world)
    }

    /// Length of the box's diagonal.
    pub fn diagonal(&self) -> f64 {
        (self.max_world - self.min_world).length()
    }
}

/// A whole scene: everything the renderer needs, in file order.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The file's camera.
    pub camera: OrthographicCamera,
    /// Colour of pixels that no sphere covers.
    pub background: Vec3,
    /// Materials in file order.
    pub materials: Vec<Material>,
    /// Every sphere of every group, flattened in file order (the order decides ties).
    pub spheres: Vec<Sphere>,
}

impl Scene {
    /// The colour a sphere is drawn in.
    pub(crate) fn sphere_colour(&self, sphere: &Sphere) -> Vec3 {
        sphere
            .material
            .and_then(|index| self.materials.get(index as usize))
            .map_or(DEFAULT_DIFFUSE, |material| material.diffuse_colour)
    }

    /// The box around every sphere, or `None` for a scene without spheres.
    pub fn bounds(&self) -> Option<Bounds> {
        let mut spheres = self.spheres.iter();
        let first = spheres.next()?;
        let radius = DVec3::splat(first.radius_world);
        let mut bounds = Bounds {
            min_world: first.center_world - radius,
            max_world: first.center_world + radius,
        };
        for sphere in spheres {
            let radius = DVec3::splat(sphere.radius_world);
            bounds.min_world = bounds.min_world.min(sphere.center_world - radius);
            bounds.max_world = bounds.max_world.max(sphere.center_world + radius);
        }
        Some(bounds)
    }
}
