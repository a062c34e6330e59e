//! [`View`]: everything about a picture that the viewer's controls and the command line change —
//! camera centre, direction, up, size, image width and height, depth range — and its validation.

use glam::DVec3;

use crate::geometry::camera::{CameraBasis, CameraError, PixelGrid};
use crate::render::depth_map::DepthRange;
use crate::scene::OrthographicCamera;

/// Largest accepted image side, in pixels.
pub const MAX_SIDE_PX: u32 = 16_384;

/// Largest accepted pixel count of one image: 64 Mpx. A frame costs 24 bytes a
/// pixel (colour, t, sphere index), so this bounds a frame at about 1.5 GiB.
pub const MAX_PIXELS: u64 = 64 * 1024 * 1024;

/// Why a [`View`] cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ViewError {
    /// Direction or up are unusable.
    #[error(transparent)]
    Camera(#[from] CameraError),
    /// The screen size is below 1e-150, not finite or above 1e150.
    #[error("view size must be a number in [1e-150, 1e150], found {0:e}")]
    BadSize(f64),
    /// The camera centre is not finite or beyond 1e150.
    #[error("view centre must be finite and at most 1e150 in magnitude")]
    BadCenter,
    /// The image is empty or larger than [`MAX_SIDE_PX`] / [`MAX_PIXELS`].
    #[error(
        "image size {width_px}×{height_px} is out of range: each side from 1 to {MAX_SIDE_PX} px, \
         at most {MAX_PIXELS} px in all"
    )]
    BadImageSize {
        /// Requested width.
        width_px: u32,
        /// Requested height.
        height_px: u32,
    },
    /// A depth-range end is not finite.
    #[error("depth range ends must be finite")]
    BadDepthRange,
    /// Supersampling settings are unusable.
    #[error(transparent)]
    Sampling(#[from] super::sampling::SamplingError),
}

/// Checks an image size against [`MAX_SIDE_PX`] and [`MAX_PIXELS`].
pub fn check_image_size(width_px: u32, height_px: u32) -> Result<(), ViewError> {
    let side_ok = |side| (1..=MAX_SIDE_PX).contains(&side);
    if side_ok(width_px)
        && side_ok(height_px)
        && u64::from(width_px) * u64::from(height_px) <= MAX_PIXELS
    {
        Ok(())
    } else {
        Err(ViewError::BadImageSize {
            width_px,
            height_px,
        })
    }
}

/// A camera placement plus an image size and a depth range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// World point the screen is centred on.
    pub center_world: DVec3,
    /// View direction, any non-zero length.
    pub direction_world: DVec3,
    /// Up hint, not parallel to the direction.
    pub up_world: DVec3,
    /// Width of the square screen in world units (spans the image's longer side).
    pub size_world: f64,
    /// Image width in pixels.
    pub width_px: u32,
    /// Image height in pixels.
    pub height_px: u32,
    /// t range mapped to white (min) … black (max) in the depth image.
    pub depth_range: DepthRange,
}

impl View {
    /// The view of a scene's own camera at the given image size and depth range.
    pub fn of_camera(
        camera: &OrthographicCamera,
        width_px: u32,
        height_px: u32,
        depth_range: DepthRange,
    ) -> Self {
        Self {
            center_world: camera.center_world,
            direction_world: camera.direction_world,
            up_world: camera.up_world,
            size_world: camera.size_world,
            width_px,
            height_px,
            depth_range,
        }
    }

    /// Checks every field; the basis of a valid view.
    pub fn validate(&self) -> Result<CameraBasis, ViewError> {
        let limit = crate::scene::MAX_MAGNITUDE;
        if !(self.center_world.is_finite() && self.center_world.abs().max_element() <= limit) {
            return Err(ViewError::BadCenter);
        }
        if !(self.size_world >= crate::scene::MIN_VIEW_SIZE && self.size_world <= limit) {
            return Err(ViewError::BadSize(self.size_world));
        }
        if !(self.depth_range.min_t.is_finite() && self.depth_range.max_t.is_finite()) {
            return Err(ViewError::BadDepthRange);
        }
        check_image_size(self.width_px, self.height_px)?;
        Ok(CameraBasis::new(self.direction_world, self.up_world)?)
    }

    /// The pixel grid of this view's image on its screen.
    pub fn grid(&self) -> PixelGrid {
        PixelGrid::new(self.width_px, self.height_px, self.size_world)
    }
}
