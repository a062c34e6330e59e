//! The gallery's pictures of the known mistakes (`docs/mistakes/*.png`, made by the `mistakes`
//! example), bundled with the viewer so that a statement of the answer shows its picture where it
//! is said, in the window and in the page alike.

use std::collections::HashMap;

use egui::{ColorImage, TextureHandle, TextureOptions};

use crate::compare::{Deviation, Mistake};

/// Each known mistake's gallery picture, PNG.
const PICTURES: [(Mistake, &[u8]); 15] = [
    (
        Mistake::PixelCorners,
        include_bytes!("../../../docs/mistakes/pixel-corners.png"),
    ),
    (
        Mistake::NoSquareRoot,
        include_bytes!("../../../docs/mistakes/no-square-root.png"),
    ),
    (
        Mistake::TminZero,
        include_bytes!("../../../docs/mistakes/tmin-zero.png"),
    ),
    (
        Mistake::TminMinusOne,
        include_bytes!("../../../docs/mistakes/tmin-minus-one.png"),
    ),
    (
        Mistake::FarRoot,
        include_bytes!("../../../docs/mistakes/far-root.png"),
    ),
    (
        Mistake::Stretched,
        include_bytes!("../../../docs/mistakes/stretched.png"),
    ),
    (
        Mistake::FlippedVertically,
        include_bytes!("../../../docs/mistakes/flipped-vertically.png"),
    ),
    (
        Mistake::DepthReversed,
        include_bytes!("../../../docs/mistakes/depth-reversed.png"),
    ),
    (
        Mistake::DepthNoClamp,
        include_bytes!("../../../docs/mistakes/depth-no-clamp.png"),
    ),
    (
        Mistake::DepthOutsideBlack,
        include_bytes!("../../../docs/mistakes/depth-outside-black.png"),
    ),
    (
        Mistake::Rounded,
        include_bytes!("../../../docs/mistakes/rounded.png"),
    ),
    (
        Mistake::LastWins,
        include_bytes!("../../../docs/mistakes/last-wins.png"),
    ),
    (
        Mistake::Mirrored,
        include_bytes!("../../../docs/mistakes/mirrored.png"),
    ),
    (
        Mistake::RawUp,
        include_bytes!("../../../docs/mistakes/raw-up.png"),
    ),
    (
        Mistake::UnnormalizedDirection,
        include_bytes!("../../../docs/mistakes/unnormalized-direction.png"),
    ),
];

/// The gallery's pictures decoded so far, as textures.
#[derive(Default)]
pub(crate) struct Gallery {
    textures: HashMap<Mistake, Option<TextureHandle>>,
}

impl Gallery {
    /// The gallery picture of `deviation`, if it is a known mistake (decoded once, through
    /// `ctx`).
    pub(crate) fn picture(
        &mut self,
        ctx: &egui::Context,
        deviation: &Deviation,
    ) -> Option<TextureHandle> {
        let Deviation::Word(mistake) = deviation else {
            return None;
        };
        self.textures
            .entry(*mistake)
            .or_insert_with(|| {
                let (_, bytes) = PICTURES.iter().find(|(m, _)| m == mistake)?;
                let image = image::load_from_memory(bytes).ok()?.to_rgb8();
                let size = [image.width() as usize, image.height() as usize];
                Some(ctx.load_texture(
                    format!("gallery {}", mistake.word()),
                    ColorImage::from_rgb(size, image.as_raw()),
                    TextureOptions::LINEAR,
                ))
            })
            .clone()
    }
}

#[cfg(test)]
mod tests {
    use super::PICTURES;
    use crate::compare::Mistake;

    /// Every known mistake has its picture, under its own word, and each decodes.
    #[test]
    fn every_mistake_has_its_own_picture() {
        for mistake in Mistake::ALL {
            let (_, bytes) = PICTURES
                .iter()
                .find(|(m, _)| *m == mistake)
                .unwrap_or_else(|| panic!("{} has no picture", mistake.word()));
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("docs/mistakes")
                .join(format!("{}.png", mistake.word()));
            assert_eq!(*bytes, std::fs::read(&path).unwrap().as_slice(), "{path:?}");
            image::load_from_memory(bytes).unwrap();
        }
    }
}
