//! A sphere as the render sees it: a disc on the screen ([`Disc`]: its centre and squared radius
//! in screen units, its depth along the view), and one sphere projected to one.

use crate::geometry::camera::CameraBasis;
use crate::render::view::View;
use crate::scene::Sphere;

/// A sphere projected into camera space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Screen u of the centre (world units, relative to the camera centre).
    pub u: f64,
    /// Screen v of the centre.
    pub v: f64,
    /// Depth of the centre along the view direction (t of the centre).
    pub(crate) w: f64,
    /// r², the disc's squared radius.
    pub radius_sq: f64,
    /// Index of the sphere in file order.
    pub sphere: u32,
}

impl Disc {
    /// A placeholder: at the origin, of radius 0.
    pub(crate) const NONE: Self = Self {
        u: 0.0,
        v: 0.0,
        w: 0.0,
        radius_sq: 0.0,
        sphere: 0,
    };

    /// The nearest t it can have anywhere: `w − r`, never above the t of a pixel it covers
    /// (correctly rounded square root and subtraction are monotonic).
    #[inline]
    pub(crate) fn front_t(&self) -> f64 {
        self.w - self.radius_sq.sqrt()
    }
}

/// `sphere`, the `index`th of its scene, projected into the camera space of `view`.
#[inline]
pub(super) fn project_sphere(
    sphere: &Sphere,
    index: u32,
    view: &View,
    basis: &CameraBasis,
) -> Disc {
    let center_camera = basis.to_camera(sphere.center_world - view.center_world);
    Disc {
        u: center_camera.x,
        v: center_camera.y,
        w: center_camera.z,
        radius_sq: sphere.radius_world * sphere.radius_world,
        sphere: index,
    }
}
