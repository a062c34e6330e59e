//! The shortest true story: of two answers that draw their pixels equally well, the one with
//! fewer statements is said. The fit follows the pixels, and on a scene that looks alike under
//! a mirror or a flip it can settle on a longer story (the far root and no depth test, say, for
//! a mirrored depth image) that draws their pixels as well as one known mistake does. Here the
//! answer's own length is challenged: every single known mistake (and, against an answer of three
//! or more statements, every possible pair) — alone, with the answer's statements about how depth
//! and colour become bytes, and with a depth map fitted again under it (beside the answer's rule
//! for which hit is drawn, its offset within the pixel and its scale, or not) — is scored against
//! their images; those that leave no more pixels
//! than the answer (within the near-tie allowance) are offered as answers, and the diagnosis
//! states the shortest.

use super::describe::{describe, rebuild};
use super::deviation::Deviation;
use super::fit::depth::fit_depth_quickly;
use super::fit::score::Scorer;
use super::mistake::{Mistake, MistakeSet};
use super::needed::needed;

/// Statements of `answer` that say how hits become bytes (the depth map, the colour's bytes),
/// kept beside a shorter story of where rays go and which hit is drawn.
fn byte_statements(answer: &[Deviation]) -> Vec<Deviation> {
    answer
        .iter()
        .copied()
        .filter(|statement| match statement {
            Deviation::Word(mistake) => !mistake.changes_hits(),
            Deviation::Tilt { .. } => false,
            other => {
                (!other.is_about_geometry() && other.is_about_depth())
                    || matches!(other, Deviation::Background { .. })
            }
        })
        .collect()
}

/// Statements of `answer` that say which hit is drawn and are not known mistakes (no depth test,
/// a tmin with the near root only, a block of the image drawn), kept beside a shorter story of
/// where rays go.
fn hit_statements(answer: &[Deviation]) -> Vec<Deviation> {
    answer
        .iter()
        .copied()
        .filter(|statement| {
            matches!(
                statement,
                Deviation::NoDepthTest { .. }
                    | Deviation::NearRootOnly { .. }
                    | Deviation::Tmin { .. }
                    | Deviation::OnlyBlock { .. }
            )
        })
        .collect()
}

/// Answers shorter than `answer` (which leaves `left` pixels) made of one or two known mistakes,
/// alone or with `answer`'s statements about bytes, that leave at most `left + near` pixels: each
/// pruned to the statements the images need, with the pixels it leaves.
pub(super) fn shorter_answers(
    scorer: &mut Scorer<'_>,
    answer: &[Deviation],
    left: usize,
    near: usize,
    differing_exact: usize,
) -> Vec<(Vec<Deviation>, usize)> {
    if answer.len() < 2 {
        return Vec::new();
    }
    let view = *scorer.view;
    let mut sets: Vec<MistakeSet> = Mistake::ALL
        .iter()
        .map(|&mistake| MistakeSet::of(&[mistake]))
        .collect();
    if answer.len() >= 3 {
        for (i, &first) in Mistake::ALL.iter().enumerate() {
            for &second in &Mistake::ALL[i + 1..] {
                let pair = MistakeSet::of(&[first, second]);
                if pair.is_possible() {
                    sets.push(pair);
                }
            }
        }
    }
    let bytes = byte_statements(answer);
    let rules = hit_statements(answer);
    // The answer's fitted values of where rays start that a known mistake keeps its meaning
    // beside (an offset within the pixel, a scale): a mirror said with the answer's offset.
    let placed: Vec<Deviation> = answer
        .iter()
        .copied()
        .filter(|statement| {
            matches!(
                statement,
                Deviation::SampleOffset { .. }
                    | Deviation::CropNotCentred { .. }
                    | Deviation::Scaled { .. }
            )
        })
        .collect();
    // A mirror or a flip said in the answer's stead counts a sample's offset within the pixel
    // from the other side: each way is tried.
    let mut placings: Vec<Vec<Deviation>> = Vec::new();
    if !placed.is_empty() {
        for (mirror_x, mirror_y) in [(false, false), (true, false), (false, true), (true, true)] {
            let turned: Vec<Deviation> = placed
                .iter()
                .map(|statement| match *statement {
                    Deviation::SampleOffset { offset_px } => Deviation::SampleOffset {
                        offset_px: glam::DVec2::new(
                            if mirror_x {
                                1.0 - offset_px.x
                            } else {
                                offset_px.x
                            },
                            if mirror_y {
                                1.0 - offset_px.y
                            } else {
                                offset_px.y
                            },
                        ),
                    },
                    other => other,
                })
                .collect();
            if !placings.contains(&turned) {
                placings.push(turned);
            }
        }
    }
    let mut candidates: Vec<Vec<Deviation>> = Vec::new();
    for set in sets {
        let words: Vec<Deviation> = set.mistakes().into_iter().map(Deviation::Word).collect();
        let mut each = vec![words.clone(), [words.clone(), bytes.clone()].concat()];
        if scorer.theirs.depth.is_some() {
            // With their depth image: the depth map fitted again under the shorter story (a
            // mirror can need the range the other way round from the longer one's), with the
            // answer's rule for which hit is drawn or without it.
            let mut rule_sets = vec![Vec::new()];
            if !rules.is_empty() {
                rule_sets.push(rules.clone());
            }
            for placed in &placings {
                rule_sets.push(placed.clone());
                rule_sets.push([placed.clone(), rules.clone()].concat());
            }
            rule_sets.dedup();
            for with_rules in rule_sets {
                let model = rebuild(&view, &[words.clone(), with_rules].concat());
                let fitted = fit_depth_quickly(scorer, &model);
                each.push(describe(scorer.scene, &view, &fitted));
            }
        }
        for candidate in each {
            let mut unique: Vec<Deviation> = Vec::new();
            for statement in candidate {
                if !unique.contains(&statement) {
                    unique.push(statement);
                }
            }
            if unique.len() < answer.len() && !candidates.contains(&unique) {
                candidates.push(unique);
            }
        }
    }
    let models: Vec<_> = candidates.iter().map(|c| rebuild(&view, c)).collect();
    let scores = scorer.scores_of(&models);
    let mut shorter = Vec::new();
    for (candidate, score) in candidates.into_iter().zip(scores) {
        if score.is_some_and(|score| score <= left + near) {
            let pruned = needed(scorer, candidate, differing_exact);
            if pruned.0.len() < answer.len() && !shorter.iter().any(|(s, _)| *s == pruned.0) {
                shorter.push(pruned);
            }
        }
    }
    shorter
}

/// `statements` (a partial answer's) without a flip or a mirror that the other explains as well
/// (within `near` pixels): on a scene that looks alike both ways, naming one is a guess.
pub(super) fn without_turn_guesses(
    scorer: &mut Scorer<'_>,
    statements: &[Deviation],
    near: usize,
) -> Vec<Deviation> {
    let view = *scorer.view;
    let left = scorer.score(&rebuild(&view, statements));
    let turns = [Mistake::FlippedVertically, Mistake::Mirrored];
    statements
        .iter()
        .copied()
        .filter(|statement| {
            let Deviation::Word(word) = statement else {
                return true;
            };
            let Some(other) = turns
                .iter()
                .copied()
                .find(|t| turns.contains(word) && t != word)
            else {
                return true;
            };
            let swapped: Vec<Deviation> = statements
                .iter()
                .map(|s| {
                    if s == statement {
                        Deviation::Word(other)
                    } else {
                        *s
                    }
                })
                .collect();
            scorer.score(&rebuild(&view, &swapped)) > left + near
        })
        .collect()
}
