//! The colour image's own parts of the model: the background their program fills with and how
//! it turns a colour into bytes (rounded or cut), known mistakes tried before fitted values.

use super::score::Scorer;
use crate::compare::model::{Model, colour_bytes};

/// The background and the rounding of bytes that draw their colour image best.
pub(super) fn fit_colour(
    scorer: &mut Scorer<'_>,
    model: &Model,
    seen_background: Option<[u8; 3]>,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    if scorer.theirs.colour.is_none() {
        return *model;
    }
    let scene_background = scorer.scene.background;
    let mut best: Option<(usize, Model)> = None;
    // Known mistakes before fitted values: on a tie the first is kept, the rest are seen. The
    // scene's own background, in the bytes of either rounding, is no other background: each
    // picture is tried once.
    let mut tried = Vec::new();
    for rounded in [false, true] {
        for background in [None, seen_background] {
            let mut candidate = *model;
            candidate.rounded = rounded;
            candidate.background =
                background.filter(|&c| c != colour_bytes(scene_background, rounded));
            if tried.contains(&candidate) {
                continue;
            }
            tried.push(candidate);
            let score = scorer.score(&candidate);
            seen.push((score, candidate));
            if best.is_none_or(|(least, _)| score < least) {
                best = Some((score, candidate));
            }
        }
    }
    best.map_or(*model, |(_, chosen)| chosen)
}
