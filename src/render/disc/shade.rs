//! Shading: a frame's colours from its visible spheres — the material's flat colour, or the
//! background — quantised to 8 bits once per material.

use rayon::prelude::*;

use crate::render::depth_map::quantize_f32;
use crate::render::{Frame, View};
use crate::scene::Scene;

/// Pixels per sphere from which a frame colours its spheres once, in a table, rather than
/// reading each pixel's sphere.
const MIN_PIXELS_PER_SPHERE_FOR_TABLE: usize = 4;

/// Completes a frame from per-pixel t and sphere indices: colour from the sphere's material or
/// the background, quantised to 8 bits.
pub(crate) fn frame_from_hits(scene: &Scene, view: &View, t: Vec<f64>, sphere: Vec<u32>) -> Frame {
    // Colours per material (few), looked up per pixel: the cost follows the pixels, not the
    // sphere count.
    let material_rgb: Vec<[u8; 3]> = scene
        .materials
        .iter()
        .map(|material| material.diffuse_colour.to_array().map(quantize_f32))
        .collect();
    let default_rgb = crate::scene::DEFAULT_DIFFUSE.to_array().map(quantize_f32);
    let background = scene.background.to_array().map(quantize_f32);
    let rgb_of_sphere = |hit: &crate::scene::Sphere| {
        hit.material
            .and_then(|material| material_rgb.get(material as usize).copied())
            .unwrap_or(default_rgb)
    };
    // With far fewer spheres than pixels, each sphere's colour once, in a table small enough to
    // stay in cache, instead of a read of the sphere (scattered over the whole scene) per pixel.
    let colour = if scene.spheres.len() <= sphere.len() / MIN_PIXELS_PER_SPHERE_FOR_TABLE {
        let sphere_rgb: Vec<[u8; 3]> = scene.spheres.par_iter().map(rgb_of_sphere).collect();
        sphere
            .par_iter()
            .map(|&index| *sphere_rgb.get(index as usize).unwrap_or(&background))
            .collect()
    } else {
        sphere
            .par_iter()
            .map(|&index| {
                scene
                    .spheres
                    .get(index as usize)
                    .map_or(background, rgb_of_sphere)
            })
            .collect()
    };
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
