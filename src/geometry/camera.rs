//! The orthographic camera's geometry: the orthonormal basis built from (direction, up), and the
//! mapping from pixels to screen coordinates.
//!
//! Spaces: *world* is the scene file's space. *Camera space* has its origin at the camera centre
//! and axes (u, v, w) = (`horizontal`, `screen_up`, `direction`); u and v are *screen
//! coordinates* in world units, w is the signed distance along the view direction (t).
//! Conventions (docs/spec.md): `d = normalize(direction)`, `horizontal = normalize(d × up)`,
//! `screen_up = horizontal × d`; pixel (x, y) with y = 0 the bottom row samples its centre; the
//! screen's `size` spans the longer side of a non-square image.

use glam::DVec3;

/// Why a (direction, up) pair gives no camera.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum CameraError {
    /// The direction has zero length (or is not finite).
    #[error("camera direction must be a non-zero, finite vector")]
    ZeroDirection,
    /// Up is zero, not finite, or parallel to the direction.
    #[error("camera up must not be zero or parallel to the direction")]
    UpParallel,
}

/// Smallest accepted sine of the angle between direction and up; below it they count as parallel
/// (the basis would be dominated by rounding).
pub(crate) const MIN_UP_SINE: f64 = 1e-12;

/// Unit vector along `v`, robust to very large and very small components.
fn unit(v: DVec3) -> Option<DVec3> {
    let scale = v.abs().max_element();
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    let scaled = v / scale;
    Some(scaled / scaled.length())
}

/// The camera's orthonormal basis in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraBasis {
    /// Unit +x of the image (u axis).
    pub horizontal: DVec3,
    /// Unit +y of the image (v axis).
    pub screen_up: DVec3,
    /// Unit view direction (w axis); t is measured along it.
    pub direction: DVec3,
}

impl CameraBasis {
    /// The basis of docs/spec.md for any non-zero direction and any up not parallel to it.
    pub fn new(direction: DVec3, up: DVec3) -> Result<Self, CameraError> {
        let direction = unit(direction).ok_or(CameraError::ZeroDirection)?;
        let up = unit(up).ok_or(CameraError::UpParallel)?;
        let cross = direction.cross(up);
        if cross.length() < MIN_UP_SINE {
            return Err(CameraError::UpParallel);
        }
        // Re-orthogonalise against rounding in the cross product, then normalise.
        let horizontal =
            unit(cross - cross.dot(direction) * direction).ok_or(CameraError::UpParallel)?;
        let screen_up = horizontal.cross(direction);
        Ok(Self {
            horizontal,
            screen_up,
            direction,
        })
    }

    /// World vector → camera-space (u, v, w) components.
    pub fn to_camera(&self, world_offset: DVec3) -> DVec3 {
        DVec3::new(
            world_offset.dot(self.horizontal),
            world_offset.dot(self.screen_up),
            world_offset.dot(self.direction),
        )
    }

    #[cfg(test)]
    /// Camera-space (u, v, w) → world vector.
    pub(crate) fn world_of(&self, camera_offset: DVec3) -> DVec3 {
        camera_offset.x * self.horizontal
            + camera_offset.y * self.screen_up
            + camera_offset.z * self.direction
    }
}

/// How an image's pixels sit on the camera's square screen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelGrid {
    /// Image width in pixels.
    pub(crate) width_px: u32,
    /// Image height in pixels.
    pub(crate) height_px: u32,
    /// Side of one (square) pixel in world units: `size / max(width, height)`.
    pub pixel_size_world: f64,
}

impl PixelGrid {
    /// The grid of a `width_px × height_px` image on a screen `size_world` wide.
    pub fn new(width_px: u32, height_px: u32, size_world: f64) -> Self {
        let longer = width_px.max(height_px).max(1);
        Self {
            width_px,
            height_px,
            pixel_size_world: size_world / f64::from(longer),
        }
    }

    /// Screen u of the centre of pixel column `x` (world units, 0 at the camera centre).
    pub fn u_of_column(&self, x: f64) -> f64 {
        (x + 0.5 - 0.5 * f64::from(self.width_px)) * self.pixel_size_world
    }

    /// Screen v of the centre of pixel row `y_up` (y = 0 the bottom row).
    pub fn v_of_row(&self, y_up: f64) -> f64 {
        (y_up + 0.5 - 0.5 * f64::from(self.height_px)) * self.pixel_size_world
    }

    /// Screen (u, v) of a point given in pixel units from the bottom-left corner of the image
    /// (pixel (x, y)'s centre is at (x + ½, y + ½)).
    pub fn screen_of_pixel_point(&self, x: f64, y_up: f64) -> (f64, f64) {
        (self.u_of_column(x - 0.5), self.v_of_row(y_up - 0.5))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_orthonormal(basis: &CameraBasis) {
        for (a, b) in [
            (basis.horizontal, basis.screen_up),
            (basis.horizontal, basis.direction),
            (basis.screen_up, basis.direction),
        ] {
            assert!(a.dot(b).abs() < 1e-15, "not orthogonal: {a} {b}");
        }
        for v in [basis.horizontal, basis.screen_up, basis.direction] {
            assert!((v.length() - 1.0).abs() < 1e-15, "not unit: {v}");
        }
    }

    #[test]
    fn course_camera_has_x_right_y_up() {
        let basis = CameraBasis::new(DVec3::new(0.0, 0.0, -1.0), DVec3::Y).unwrap();
        assert_eq!(basis.horizontal, DVec3::X);
        assert_eq!(basis.screen_up, DVec3::Y);
        assert_eq!(basis.direction, DVec3::NEG_Z);
    }

    #[test]
    fn non_unit_direction_and_non_orthogonal_up_give_an_orthonormal_basis() {
        // scene1_03: up (0.5, 1, 0) is not unit; scene1_04: direction not unit nor orthogonal to up.
        let basis =
            CameraBasis::new(DVec3::new(0.0, 0.0, -7.0), DVec3::new(0.5, 1.0, 0.0)).unwrap();
        assert_orthonormal(&basis);
        assert_eq!(basis.direction, DVec3::NEG_Z);
        // screen_up lies in the plane of up and direction, on up's side.
        let up = DVec3::new(0.5, 1.0, 0.0).normalize();
        assert!((basis.screen_up - up).length() < 1e-15);

        let basis =
            CameraBasis::new(DVec3::new(-1.0, -0.5, -1.0), DVec3::new(0.0, 3.0, 0.0)).unwrap();
        assert_orthonormal(&basis);
        assert!(basis.screen_up.y > 0.0);
        assert!(basis.horizontal.y.abs() < 1e-15, "horizontal stays level");
    }

    #[test]
    fn up_parallel_to_direction_is_an_error() {
        assert_eq!(
            CameraBasis::new(DVec3::new(0.0, 0.0, -1.0), DVec3::new(0.0, 0.0, 2.0)),
            Err(CameraError::UpParallel)
        );
        assert_eq!(
            CameraBasis::new(DVec3::new(1.0, 1.0, 1.0), DVec3::new(3.0, 3.0, 3.0)),
            Err(CameraError::UpParallel)
        );
        assert_eq!(
            CameraBasis::new(DVec3::new(1.0, 0.0, 0.0), DVec3::ZERO),
            Err(CameraError::UpParallel)
        );
        assert_eq!(
            CameraBasis::new(DVec3::ZERO, DVec3::Y),
            Err(CameraError::ZeroDirection)
        );
    }

    #[test]
    fn huge_and_tiny_vectors_still_give_a_basis() {
        for scale in [1e-300, 1e-8, 1e8, 1e300] {
            let basis = CameraBasis::new(
                DVec3::new(-scale, -scale, -scale),
                DVec3::new(0.0, scale, 0.0),
            )
            .unwrap();
            assert_orthonormal(&basis);
        }
    }

    #[test]
    fn camera_space_round_trips() {
        let basis =
            CameraBasis::new(DVec3::new(-1.0, -0.5, -1.0), DVec3::new(0.2, 1.0, 0.0)).unwrap();
        let p = DVec3::new(1.5, -2.0, 3.25);
        assert!((basis.world_of(basis.to_camera(p)) - p).length() < 1e-14);
    }

    #[test]
    fn pixel_centres_are_symmetric_about_the_screen_centre() {
        let grid = PixelGrid::new(200, 200, 5.0);
        // Pixel 0's centre is 99.5 pixels left of the screen centre; 199's is 99.5 right.
        assert_eq!(grid.u_of_column(0.0), -99.5 * 0.025);
        assert_eq!(grid.u_of_column(199.0), 99.5 * 0.025);
        assert_eq!(grid.v_of_row(0.0), -99.5 * 0.025);
        assert_eq!(grid.u_of_column(99.5), 0.0);
    }

    #[test]
    fn longer_side_spans_the_screen_on_non_square_images() {
        let wide = PixelGrid::new(400, 100, 4.0);
        assert_eq!(wide.pixel_size_world, 0.01);
        assert_eq!(wide.u_of_column(0.0), -199.5 * 0.01);
        assert_eq!(wide.v_of_row(0.0), -49.5 * 0.01);
        let tall = PixelGrid::new(100, 400, 4.0);
        assert_eq!(tall.v_of_row(399.0), 199.5 * 0.01);
        assert_eq!(tall.u_of_column(99.0), 49.5 * 0.01);
    }
}
