//! Shading: pixels' colours from their visible spheres — the material's flat colour, or the
//! background — quantised to 8 bits once per material ([`Palette`]), for a whole frame or for a
//! strip of one.

use rayon::prelude::*;

use crate::render::depth_map::quantize_f32;
use crate::render::frame::Frame;
use crate::render::view::View;
use crate::scene::{Scene, Sphere};

/// Pixels per sphere from which a frame colours its spheres once, in a table, rather than
/// reading each pixel's sphere.
const MIN_PIXELS_PER_SPHERE_FOR_TABLE: usize = 4;

/// The 8-bit colour of every sphere index a pixel can hold ([`NO_HIT`](crate::render::frame::NO_HIT): the
/// background).
pub(crate) struct Palette<'a> {
    spheres: &'a [Sphere],
    /// Each material's colour (few), looked up per sphere: the cost follows the pixels, not the
    /// sphere count.
    material_rgb: Vec<[u8; 3]>,
    default_rgb: [u8; 3],
    background_rgb: [u8; 3],
    /// With far fewer spheres than pixels, each sphere's colour once, in a table small enough to
    /// stay in cache, instead of a read of the sphere (scattered over the whole scene) per pixel.
    sphere_rgb: Option<Vec<[u8; 3]>>,
}

impl<'a> Palette<'a> {
    /// The palette of `scene` for frames of `pixel_count` pixels.
    pub(crate) fn of(scene: &'a Scene, pixel_count: usize) -> Self {
        let mut palette = Self {
            spheres: &scene.spheres,
            material_rgb: scene
                .materials
                .iter()
                .map(|material| material.diffuse_colour.to_array().map(quantize_f32))
                .collect(),
            default_rgb: crate::scene::DEFAULT_DIFFUSE.to_array().map(quantize_f32),
            background_rgb: scene.background.to_array().map(quantize_f32),
            sphere_rgb: None,
        };
        if scene.spheres.len() <= pixel_count / MIN_PIXELS_PER_SPHERE_FOR_TABLE {
            let table = scene
                .spheres
                .par_iter()
                .map(|sphere| palette.rgb_of_sphere(sphere))
                .collect();
            palette.sphere_rgb = Some(table);
        }
        palette
    }

    fn rgb_of_sphere(&self, sphere: &Sphere) -> [u8; 3] {
        sphere
            .material
            .and_then(|material| self.material_rgb.get(material as usize).copied())
            .unwrap_or(self.default_rgb)
    }

    /// The colour of a pixel whose visible sphere is `sphere` ([`NO_HIT`](crate::render::frame::NO_HIT): none).
    /// Whether the table is there is the same for every pixel, so that branch is always
    /// predicted.
    #[inline]
    fn rgb_of_index(&self, sphere: u32) -> [u8; 3] {
        match &self.sphere_rgb {
            Some(table) => *table.get(sphere as usize).unwrap_or(&self.background_rgb),
            None => self
                .spheres
                .get(sphere as usize)
                .map_or(self.background_rgb, |sphere| self.rgb_of_sphere(sphere)),
        }
    }

    /// The colours of pixels whose visible spheres are `sphere`, in parallel.
    pub(crate) fn colours(&self, sphere: &[u32]) -> Vec<[u8; 3]> {
        const PIXELS_PER_TASK: usize = 16_384;
        sphere
            .par_iter()
            .with_min_len(PIXELS_PER_TASK)
            .map(|&sphere| self.rgb_of_index(sphere))
            .collect()
    }

    /// The colours of pixels whose visible spheres are `sphere` into `rgb` (as long), on this
    /// thread.
    pub(crate) fn colour(&self, sphere: &[u32], rgb: &mut [[u8; 3]]) {
        for (rgb, &sphere) in rgb.iter_mut().zip(sphere) {
            *rgb = self.rgb_of_index(sphere);
        }
    }
}

/// Completes a frame from per-pixel t and sphere indices: colour from the sphere's material or
/// the background, quantised to 8 bits.
pub(crate) fn frame_from_hits(scene: &Scene, view: &View, t: Vec<f64>, sphere: Vec<u32>) -> Frame {
    let colour = Palette::of(scene, sphere.len()).colours(&sphere);
    Frame {
        width_px: view.width_px,
        height_px: view.height_px,
        colour,
        t,
        sphere,
        depth_grey: None,
        disc_tests: 0,
    }
}
