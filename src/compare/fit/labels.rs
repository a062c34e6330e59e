//! What each pixel of their image says about where the spheres are, for fitting the pixel map:
//! in a colour image, which sphere colour or the background it shows; in a depth image, that
//! a grey pixel was hit (black may be far as well as empty, so it says nothing).

use std::collections::HashMap;

use image::RgbImage;

use crate::compare::model::colour_bytes;
use crate::scene::Scene;

/// What one pixel shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Label {
    /// A sphere of colour class `n` (spheres of one colour share a class).
    Class(u32),
    /// The background: no sphere.
    Background,
    /// Some sphere, which one unknown (a grey pixel of a depth image).
    AnyHit,
    /// Nothing known.
    Unknown,
}

/// The labels of their image, and the spheres' colour classes.
#[derive(Debug, Clone)]
pub struct Labels {
    /// Image width, pixels.
    pub width_px: u32,
    /// Image height, pixels.
    pub height_px: u32,
    /// Per pixel, top row first.
    pub per_pixel: Vec<Label>,
    /// Colour class of each sphere, in file order.
    pub class_of_sphere: Vec<u32>,
    /// The spheres of each class.
    pub spheres_of_class: Vec<Vec<u32>>,
}

impl Labels {
    /// The label of pixel `(x, y_up)`.
    pub fn at(&self, x: u32, y_up: u32) -> Label {
        self.per_pixel[((self.height_px - 1 - y_up) * self.width_px + x) as usize]
    }

    /// The label the model's hit on `sphere` (or none) would give.
    pub fn of_hit(&self, sphere: Option<u32>) -> Label {
        match sphere {
            Some(index) => Label::Class(self.class_of_sphere[index as usize]),
            None => Label::Background,
        }
    }

    /// Whether a pixel labelled `label` agrees with the model's hit on `sphere`.
    pub fn agrees(&self, label: Label, sphere: Option<u32>) -> bool {
        match label {
            Label::Unknown => true,
            Label::AnyHit => sphere.is_some(),
            _ => label == self.of_hit(sphere),
        }
    }
}

/// The most common colour of `image` that no sphere of `scene` has (truncated or rounded), with
/// its count: the background their program drew, when the scene's is not it.
pub fn background_candidate(scene: &Scene, image: &RgbImage) -> Option<([u8; 3], usize)> {
    let sphere_colours: std::collections::HashSet<[u8; 3]> = scene
        .spheres
        .iter()
        .flat_map(|s| {
            let colour = scene.sphere_colour(s);
            [colour_bytes(colour, false), colour_bytes(colour, true)]
        })
        .collect();
    let mut counts: HashMap<[u8; 3], usize> = HashMap::new();
    for pixel in image.pixels() {
        if !sphere_colours.contains(&pixel.0) {
            *counts.entry(pixel.0).or_default() += 1;
        }
    }
    counts
        .into_iter()
        .max_by_key(|&(colour, count)| (count, colour))
}

/// Labels a colour image: each pixel of a sphere's colour (truncated or rounded) is that
/// colour's class; a pixel of `background` is the background; the rest unknown.
pub fn of_colour(scene: &Scene, image: &RgbImage, background: [u8; 3]) -> Labels {
    let mut classes: Vec<[u8; 3]> = Vec::new();
    let mut class_of_sphere = Vec::with_capacity(scene.spheres.len());
    for sphere in &scene.spheres {
        let bytes = colour_bytes(scene.sphere_colour(sphere), false);
        let class = classes.iter().position(|&c| c == bytes).unwrap_or_else(|| {
            classes.push(bytes);
            classes.len() - 1
        });
        class_of_sphere.push(class as u32);
    }
    let rounded: Vec<[u8; 3]> = {
        let mut rounded = vec![[0; 3]; classes.len()];
        for (sphere, &class) in scene.spheres.iter().zip(&class_of_sphere) {
            rounded[class as usize] = colour_bytes(scene.sphere_colour(sphere), true);
        }
        rounded
    };
    let mut spheres_of_class = vec![Vec::new(); classes.len()];
    for (index, &class) in (0u32..).zip(&class_of_sphere) {
        spheres_of_class[class as usize].push(index);
    }
    let per_pixel = image
        .pixels()
        .map(|pixel| {
            if let Some(class) = classes.iter().position(|&c| c == pixel.0) {
                Label::Class(class as u32)
            } else if let Some(class) = rounded.iter().position(|&c| c == pixel.0) {
                Label::Class(class as u32)
            } else if pixel.0 == background {
                Label::Background
            } else {
                Label::Unknown
            }
        })
        .collect();
    Labels {
        width_px: image.width(),
        height_px: image.height(),
        per_pixel,
        class_of_sphere,
        spheres_of_class,
    }
}

/// Labels a depth image: a grey pixel other than black (and other than `no_hit`) was hit; a
/// pixel of `no_hit`, when that is not black, is the background; black says nothing.
pub fn of_depth(scene: &Scene, image: &RgbImage, no_hit: [u8; 3]) -> Labels {
    let class_of_sphere = vec![0; scene.spheres.len()];
    let spheres_of_class = vec![(0..scene.spheres.len() as u32).collect()];
    let per_pixel = image
        .pixels()
        .map(|pixel| {
            let [r, g, b] = pixel.0;
            if pixel.0 == no_hit && no_hit != [0; 3] {
                Label::Background
            } else if r == g && g == b && g != 0 && pixel.0 != no_hit {
                Label::AnyHit
            } else {
                Label::Unknown
            }
        })
        .collect();
    Labels {
        width_px: image.width(),
        height_px: image.height(),
        per_pixel,
        class_of_sphere,
        spheres_of_class,
    }
}

/// Grey levels from which a pixel the model draws counts as clearly not black.
const CLEAR_GREY: u8 = 16;

/// `labels` of a depth image with its black pixels (other than `Unknown` ones already known)
/// taken for the background where `drawn`, the model's depth image so far, is clearly grey.
pub fn with_black_where_grey(labels: &Labels, theirs: &RgbImage, drawn: &RgbImage) -> Labels {
    let mut relabelled = labels.clone();
    for ((label, theirs), drawn) in relabelled
        .per_pixel
        .iter_mut()
        .zip(theirs.pixels())
        .zip(drawn.pixels())
    {
        if *label == Label::Unknown
            && theirs.0 == [0; 3]
            && drawn.0.iter().all(|&g| g >= CLEAR_GREY)
        {
            *label = Label::Background;
        }
    }
    relabelled
}

/// The most common colour of `image`.
pub fn most_common(image: &RgbImage) -> Option<[u8; 3]> {
    let mut counts: HashMap<[u8; 3], usize> = HashMap::new();
    for pixel in image.pixels() {
        *counts.entry(pixel.0).or_default() += 1;
    }
    counts
        .into_iter()
        .max_by_key(|&(colour, count)| (count, colour))
        .map(|(colour, _)| colour)
}
