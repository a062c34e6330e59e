//! What the statements' measurements read off an image (`tests/statements.rs`): the centroid
//! and spread of what is lit, flips, mirrors and the transpose, pixels that differ, and a
//! least-squares fit.
#![allow(dead_code)]

use glam::{DVec2, DVec3};
use image::RgbImage;

/// The lit pixels of an image (those unlike its top-left corner, the background in every case
/// that measures shapes): their count, centroid (x right, y up, pixels) and standard deviations.
pub(crate) fn shape(image: &RgbImage) -> (f64, DVec2, DVec2) {
    let corner = *image.get_pixel(0, 0);
    let (w, h) = image.dimensions();
    let mut points = Vec::new();
    for row in 0..h {
        for x in 0..w {
            if *image.get_pixel(x, row) != corner {
                points.push(DVec2::new(f64::from(x), f64::from(h - 1 - row)));
            }
        }
    }
    let n = points.len().max(1) as f64;
    let mean = points.iter().copied().sum::<DVec2>() / n;
    let var = points
        .iter()
        .map(|p| (*p - mean) * (*p - mean))
        .sum::<DVec2>()
        / n;
    (
        points.len() as f64,
        mean,
        DVec2::new(var.x.sqrt(), var.y.sqrt()),
    )
}

/// Pixels in which two images differ.
pub(crate) fn differing(a: &RgbImage, b: &RgbImage) -> usize {
    a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
}

pub(crate) fn flipped(image: &RgbImage) -> RgbImage {
    image::imageops::flip_vertical(image)
}

pub(crate) fn mirrored(image: &RgbImage) -> RgbImage {
    image::imageops::flip_horizontal(image)
}

/// The image transposed about its lower-left to upper-right diagonal: (x, y up) ↦ (y up, x).
pub(crate) fn transposed(image: &RgbImage) -> RgbImage {
    let (w, h) = image.dimensions();
    RgbImage::from_fn(h, w, |x, row| {
        let y_up = w - 1 - row;
        *image.get_pixel(y_up, h - 1 - x)
    })
}

/// The least-squares solution x of rows (a, b): a·x ≈ b, three unknowns (the normal equations).
pub(crate) fn least_squares(rows: &[([f64; 3], f64)]) -> [f64; 3] {
    let mut normal = glam::DMat3::ZERO;
    let mut right = DVec3::ZERO;
    for (a, b) in rows {
        let a = DVec3::from_array(*a);
        normal += glam::DMat3::from_cols(a * a.x, a * a.y, a * a.z);
        right += a * *b;
    }
    (normal.inverse() * right).to_array()
}
