//! Which of the two images an image is: colour or depth, from its content and its name
//! ([`recognised_kind`]), against the kind the user chose.

use std::path::Path;

use image::RgbImage;

use crate::scene::Scene;

/// Which of the two images is compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ImageKind {
    /// The colour image.
    #[default]
    Colour,
    /// The depth image (grey, the view's depth range).
    Depth,
}

impl ImageKind {
    /// The index of the image on screen (0 colour, 1 depth).
    pub(crate) fn index(self) -> usize {
        match self {
            Self::Colour => 0,
            Self::Depth => 1,
        }
    }

    /// The other kind: the one an image of this kind is paired with.
    pub(crate) fn other(self) -> Self {
        match self {
            Self::Colour => Self::Depth,
            Self::Depth => Self::Colour,
        }
    }

    /// The kind in a word (`colour`, `depth`).
    pub(crate) fn word(self) -> &'static str {
        match self {
            Self::Colour => "colour",
            Self::Depth => "depth",
        }
    }
}

/// What a dropped image is compared as, by its name: `.png` and `.tga` files are images, and a
/// name that says "depth" is a depth image. `None` for anything else (a scene).
pub fn dropped_image_kind(name: &str) -> Option<ImageKind> {
    let lower = name.to_lowercase();
    let is_image = [".png", ".tga"].iter().any(|ext| lower.ends_with(ext));
    is_image.then(|| {
        if lower.contains("depth") {
            ImageKind::Depth
        } else {
            ImageKind::Colour
        }
    })
}

/// Which kind of image `theirs` (named `name`) is, where its content or its name says so against
/// `chosen`, with the reason said when it is not `chosen`. A depth image is grey: every pixel
/// grey but a single no-hit colour (their fill, where it is the scene's background), with a ramp
/// of at least three levels; a colour image of a scene with colours has two colours or more that
/// are not grey, or one that is a sphere's. Where the content cannot tell (a scene of grey spheres), a name that says
/// "depth", or "output" or "colour", does.
pub fn recognised_kind(
    scene: &Scene,
    name: &Path,
    theirs: &RgbImage,
    chosen: ImageKind,
) -> (ImageKind, Option<String>) {
    use std::collections::BTreeSet;
    let grey = |p: &image::Rgb<u8>| p.0[0] == p.0[1] && p.0[1] == p.0[2];
    let mut levels = BTreeSet::new();
    let mut colours = BTreeSet::new();
    for pixel in theirs.pixels() {
        if grey(pixel) {
            levels.insert(pixel.0[0]);
        } else if colours.len() < 3 {
            colours.insert(pixel.0);
        }
    }
    let background = crate::compare::model::colour_bytes(scene.background, false);
    let coloured = |c: glam::Vec3| c.x != c.y || c.y != c.z;
    let scene_has_colour = scene
        .spheres
        .iter()
        .any(|sphere| coloured(scene.sphere_colour(sphere)))
        || coloured(scene.background);
    let stem = name
        .file_stem()
        .map(|s| s.to_string_lossy().to_lowercase())
        .unwrap_or_default();
    let by_name = if stem.contains("depth") {
        Some(ImageKind::Depth)
    } else if ["output", "colour", "color"]
        .iter()
        .any(|w| stem.contains(w))
    {
        Some(ImageKind::Colour)
    } else {
        None
    };
    let looks_depth = levels.len() >= 3
        && (colours.is_empty() || (colours.len() == 1 && colours.contains(&background)));
    // Two colours, or one that is a sphere's (a lone red sphere on black): no depth image's.
    let sphere_colour = |c: &[u8; 3]| {
        scene.spheres.iter().any(|sphere| {
            let colour = scene.sphere_colour(sphere);
            [false, true]
                .map(|rounded| crate::compare::model::colour_bytes(colour, rounded))
                .contains(c)
        })
    };
    let looks_colour =
        colours.len() >= 2 || colours.iter().any(|c| *c != background && sphere_colour(c));
    let (kind, why) = if scene_has_colour && looks_depth {
        (
            ImageKind::Depth,
            format!(
                "every pixel is grey ({} levels{}) where the scene's spheres have colours",
                levels.len(),
                if colours.is_empty() {
                    ""
                } else {
                    ", and the scene's background where nothing is hit"
                }
            ),
        )
    } else if looks_colour {
        (
            ImageKind::Colour,
            "it has colours, which a depth image has not".to_owned(),
        )
    } else if let Some(kind) = by_name {
        (kind, format!("its name, {}", name.display()))
    } else {
        (chosen, String::new())
    };
    if kind == chosen {
        (kind, None)
    } else {
        let word = match kind {
            ImageKind::Colour => "a colour image",
            ImageKind::Depth => "a depth image",
        };
        (kind, Some(format!("judged as {word}: {why}")))
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::{ImageKind, recognised_kind};
    use crate::render::depth_map::DepthRange;
    use crate::render::{View, render};
    use crate::scene::bundled::BUNDLED_SCENES;
    use crate::scene::parse_scene;

    /// The course's scene1_01 (a red sphere on black) at 200×200 over its line's range, 9 … 10:
    /// its colour and depth images, as the course's program writes them.
    fn scene1_01() -> (crate::scene::Scene, image::RgbImage, image::RgbImage) {
        let text = BUNDLED_SCENES
            .iter()
            .find(|(name, _)| *name == "scene1_01.txt")
            .unwrap()
            .1;
        let scene = parse_scene(text).unwrap();
        let range = DepthRange::new(9.0, 10.0);
        let frame = render(&scene, &View::of_camera(&scene.camera, 200, 200, range)).unwrap();
        let (colour, depth) = (frame.colour_image(), frame.depth_image(range));
        (scene, colour, depth)
    }

    /// A red sphere on black is a colour image though it has one colour only (a sphere's), and
    /// its depth image a depth image; each said when it is not the kind chosen, and nothing said
    /// when it is.
    #[test]
    fn each_image_is_recognised_by_its_content_whatever_its_name() {
        let (scene, colour, depth) = scene1_01();
        let name = Path::new("mine.png");
        let (kind, said) = recognised_kind(&scene, name, &colour, ImageKind::Depth);
        assert_eq!(kind, ImageKind::Colour);
        assert!(
            said.unwrap()
                .starts_with("judged as a colour image: it has colours")
        );
        let (kind, said) = recognised_kind(&scene, name, &depth, ImageKind::Colour);
        assert_eq!(kind, ImageKind::Depth);
        assert!(
            said.unwrap()
                .starts_with("judged as a depth image: every pixel is grey")
        );
        assert_eq!(
            recognised_kind(&scene, name, &colour, ImageKind::Colour),
            (ImageKind::Colour, None)
        );
        // All black says nothing of its kind: the name, then the kind chosen, decide.
        let black = image::RgbImage::new(200, 200);
        let depth_name = Path::new("depth1_01.tga");
        assert_eq!(
            recognised_kind(&scene, depth_name, &black, ImageKind::Colour).0,
            ImageKind::Depth
        );
        assert_eq!(
            recognised_kind(&scene, name, &black, ImageKind::Depth),
            (ImageKind::Depth, None)
        );
    }
}
