//! The answer to "why does my picture differ?": a model of their program fitted to their images
//! ([`super::fit`]), said as statements ([`super::describe`]), each kept only when the images need
//! it — left out, it leaves more than 1% of the differing pixels (and one pixel at least)
//! unexplained — and its values rounded as far as the images allow.
//!
//! The statements *explain* the difference when they leave at most a tenth of the differing
//! pixels and at most 1% of all. When another model found on the way explains the images as well
//! (within 1% of the differing pixels) and says something else, the statements both models make
//! are kept and the rest is offered as alternatives: never a guess. When nothing explains the
//! whole difference (a program can do what the model does not know), the statements are given
//! as *partial* when they explain more than half of the differing pixels and each explains at
//! least a tenth on its own; the pixels they leave are counted as unexplained.

use super::describe::{describe, rebuild};
use super::deviation::{Deviation, PerImage};
use super::fit::fit;
use super::fit::score::{Scorer, Theirs, Unexplained};
use super::mistake::{Mistake, MistakeSet};
use super::model::{Model, Quantity};
use crate::render::View;
use crate::scene::Scene;

/// Share of the exact render's differing pixels the statements may leave unexplained.
const LEFT_SHARE_OF_DIFFERING: f64 = 0.1;

/// Share of all compared pixels the statements may leave unexplained.
const LEFT_SHARE_OF_ALL: f64 = 0.01;

/// Share of the exact render's differing pixels each statement must explain on its own (the
/// pixels that differ again when it is left out); one pixel at least.
const NEEDED_SHARE: f64 = 0.01;

/// Another model whose pixels left are within this share of the differing pixels is a rival.
const NEAR_SHARE: f64 = 0.01;

/// Share of the differing pixels each statement of a partial answer must explain on its own.
const PARTIAL_SHARE_EACH: f64 = 0.1;

/// Share of the differing pixels a partial answer must explain in all: more than half.
const PARTIAL_SHARE_ALL: f64 = 0.5;

/// Models seen on the way that are said and compared with the fitted one, at most.
const MAX_RIVALS: usize = 16;

/// What the answer says.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Their images are the exact ones (no pixel differs beyond the allowance).
    Same,
    /// The statements explain the difference.
    Explained,
    /// The statements explain it, and other models explain it as well: the statements all of
    /// them make, and the rest as alternatives (the answer's own first).
    Ambiguous(Vec<Vec<Deviation>>),
    /// The statements explain part of it.
    Partial,
    /// Nothing explains it.
    Unexplained,
}

/// What the diagnosis found.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    /// The verdict.
    pub verdict: Verdict,
    /// The statements made (with [`Verdict::Partial`], in part).
    pub statements: Vec<Deviation>,
    /// Other models, with values of their own, that draw exactly the same pixels as the
    /// statements (each the part where it differs): said beside them.
    pub same_pixels: Vec<Vec<Deviation>>,
    /// Pixels the exact render differs in from theirs (colour: any level; depth: beyond one).
    pub differing_exact: usize,
    /// Pixels the stated model's images still differ in.
    pub differing_left: usize,
    /// Where the pixels left are.
    pub unexplained: Unexplained,
    /// The model the statements describe.
    pub model: Model,
}

impl Diagnosis {
    /// The known mistakes named in full (none when the verdict is not [`Verdict::Explained`] or
    /// [`Verdict::Ambiguous`]).
    pub fn mistakes(&self) -> MistakeSet {
        match self.verdict {
            Verdict::Explained | Verdict::Ambiguous(_) => words_of(&self.statements),
            _ => MistakeSet::NONE,
        }
    }

    /// The statements made in full.
    pub fn stated(&self) -> &[Deviation] {
        match self.verdict {
            Verdict::Explained | Verdict::Ambiguous(_) => &self.statements,
            _ => &[],
        }
    }

    /// The statements made in part.
    pub fn partial(&self) -> &[Deviation] {
        match self.verdict {
            Verdict::Partial => &self.statements,
            _ => &[],
        }
    }

    /// The alternatives of a near tie (each the part where the rivals differ).
    pub fn alternatives(&self) -> &[Vec<Deviation>] {
        match &self.verdict {
            Verdict::Ambiguous(alternatives) => alternatives,
            _ => &[],
        }
    }

    /// The differing pixels no statement accounts for: all of them when nothing is stated.
    pub fn unexplained_pixels(&self) -> usize {
        match self.verdict {
            Verdict::Unexplained => self.differing_exact,
            Verdict::Same => 0,
            _ => self.differing_left,
        }
    }
}

/// The known mistakes among `statements`.
pub fn words_of(statements: &[Deviation]) -> MistakeSet {
    MistakeSet::of(
        &statements
            .iter()
            .filter_map(|d| match d {
                Deviation::Word(m) => Some(*m),
                _ => None,
            })
            .collect::<Vec<Mistake>>(),
    )
}

/// `statements` without those the images do not need (the cheapest to leave out first), and the
/// pixels the rest leave.
fn needed(
    scorer: &mut Scorer<'_>,
    mut statements: Vec<Deviation>,
    differing_exact: usize,
) -> (Vec<Deviation>, usize) {
    let view = *scorer.view;
    let needed_px = (NEEDED_SHARE * differing_exact as f64).max(1.0);
    let mut left = scorer.score(&rebuild(&view, &statements));
    loop {
        let cheapest = (0..statements.len())
            .map(|i| {
                let mut without = statements.clone();
                without.remove(i);
                (scorer.score(&rebuild(&view, &without)), i)
            })
            .min();
        match cheapest {
            Some((without, i)) if without <= left || ((without - left) as f64) < needed_px => {
                statements.remove(i);
                left = without;
            }
            _ => return (statements, left),
        }
    }
}

/// The statements' values rounded as far as the pixels left allow.
fn rounded(scorer: &mut Scorer<'_>, mut statements: Vec<Deviation>, left: usize) -> Vec<Deviation> {
    let view = *scorer.view;
    let round = |v: f64, decimals: i32| {
        let scale = 10f64.powi(decimals);
        (v * scale).round() / scale
    };
    for i in 0..statements.len() {
        for decimals in 1..=6 {
            let candidate = match statements[i] {
                Deviation::SampleOffset { offset_px } => Deviation::SampleOffset {
                    offset_px: offset_px.map(|v| round(v, decimals)),
                },
                Deviation::CropNotCentred { offset_px } => Deviation::CropNotCentred {
                    offset_px: offset_px.map(|v| round(v, decimals)),
                },
                Deviation::Scaled { factor } => Deviation::Scaled {
                    factor: factor.map(|v| round(v, decimals)),
                },
                Deviation::Tilt { per_px } => Deviation::Tilt {
                    per_px: per_px.map(|v| round(v, decimals + 2)),
                },
                _ => break,
            };
            let mut with = statements.clone();
            with[i] = candidate;
            if scorer.score(&rebuild(&view, &with)) <= left {
                statements = with;
                break;
            }
        }
    }
    statements
}

/// A `depth-range` statement whose ends are the nearest and farthest hits of the image at round
/// greys (multiples of a tenth of white) is said as normalised per image.
fn per_image(scorer: &mut Scorer<'_>, statements: &mut [Deviation], model: &Model) {
    if model.depth.quantity != Quantity::T {
        return;
    }
    let hits = scorer.hits(model);
    let (near_t, far_t) = hits
        .t
        .iter()
        .filter(|t| t.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    if !(near_t < far_t) {
        return;
    }
    let grey = |t: f64| 255.0 * model.depth.value(t);
    let round_grey = |g: f64| (g / 25.5 - (g / 25.5).round()).abs() * 25.5 <= 1.0;
    for statement in statements.iter_mut() {
        if let Deviation::DepthRange { per_image, .. } = statement {
            let (near_grey, far_grey) = (grey(near_t), grey(far_t));
            if round_grey(near_grey) && round_grey(far_grey) && (near_grey - far_grey).abs() > 25.0
            {
                *per_image = Some(PerImage {
                    near_t,
                    near_grey: (near_grey / 25.5).round() * 25.5,
                    far_t,
                    far_grey: (far_grey / 25.5).round() * 25.5,
                });
            }
        }
    }
}

/// How many statements are fitted values, then how many are known mistakes: of two models
/// that explain the images equally well, the one with the lower count is said.
fn complexity(statements: &[Deviation]) -> (usize, usize) {
    let words = words_of(statements).len();
    (statements.len() - words, words)
}

/// Says why `theirs` differs from the exact picture of `scene` through `view` (its depth range
/// the one their depth image was asked for), and where the pixels left are.
pub fn diagnose(scene: &Scene, view: &View, theirs: Theirs<'_>) -> Diagnosis {
    let mut scorer = Scorer::new(scene, view, theirs);
    let fitted = fit(&mut scorer);
    let differing_exact = fitted.differing_exact;
    let course = Model::course(view);
    let mut answer = Diagnosis {
        verdict: Verdict::Same,
        statements: Vec::new(),
        same_pixels: Vec::new(),
        differing_exact,
        differing_left: differing_exact,
        unexplained: Unexplained::default(),
        model: course,
    };
    if differing_exact == 0 {
        return answer;
    }
    // The fitted model and those seen on the way that come near it, each said with the
    // statements the images need; the one with the fewest pixels left, then the simplest.
    let near = (NEAR_SHARE * differing_exact as f64) as usize;
    let mut seen: Vec<&(usize, Model)> = fitted
        .seen
        .iter()
        .filter(|(score, _)| *score <= fitted.left + near)
        .collect();
    seen.sort_by_key(|(score, _)| *score);
    let mut said: Vec<Vec<Deviation>> = Vec::new();
    for model in std::iter::once(&fitted.model).chain(seen.iter().map(|(_, m)| m)) {
        let described = describe(scene, view, model);
        if !said.contains(&described) && said.len() <= MAX_RIVALS {
            said.push(described);
        }
    }
    let mut options: Vec<(Vec<Deviation>, usize)> = Vec::new();
    for described in said {
        let option = needed(&mut scorer, described, differing_exact);
        if !options.iter().any(|(s, _)| *s == option.0) {
            options.push(option);
        }
    }
    // The simplest of those that leave no more than the fewest left and the pixels a statement
    // must explain to be needed.
    let fewest = options.iter().map(|(_, left)| *left).min().unwrap_or(0);
    let needed_px = (NEEDED_SHARE * differing_exact as f64).max(1.0) as usize;
    options.sort_by_key(|(statements, left)| {
        (*left > fewest + needed_px, complexity(statements), *left)
    });
    let (statements, left) = options.remove(0);
    let mut statements = rounded(&mut scorer, statements, left);
    let model = rebuild(view, &statements);
    per_image(&mut scorer, &mut statements, &model);
    answer.differing_left = left;
    answer.model = model;
    let compared = scorer.compared_pixels() as f64;
    let explains = !statements.is_empty()
        && left as f64 <= LEFT_SHARE_OF_DIFFERING * differing_exact as f64
        && left as f64 <= LEFT_SHARE_OF_ALL * compared;
    if explains {
        // Rivals: other models as good or nearly, that say something else. One that draws
        // exactly the same pixels as an answer of known mistakes alone, with values of its own,
        // is said beside it; any other makes the answer ambiguous.
        let all_words = |s: &[Deviation]| words_of(s).len() == s.len();
        let mut alternatives = vec![statements.clone()];
        for (rival, rival_left) in options {
            let holds_ours = statements.iter().all(|s| rival.contains(s));
            if rival_left > left + near
                || rival.is_empty()
                || holds_ours
                || rival.len() > statements.len()
            {
                continue;
            }
            if all_words(&statements) && !all_words(&rival) {
                // Known mistakes come before fitted values. A rival with values of its own that
                // draws exactly the same pixels is said beside them, unless what it changes is
                // where rays start (a symmetric scene turned some way, a fit a hair off a
                // named point: no news).
                if rival_left == left && !rival.iter().any(Deviation::is_geometric) {
                    answer.same_pixels.push(rival);
                }
            } else {
                alternatives.push(rival);
            }
        }
        alternatives.sort_by_key(|a| (words_of(a), a.len()));
        answer.verdict = if alternatives.len() > 1 {
            let common: Vec<Deviation> = statements
                .iter()
                .copied()
                .filter(|s| alternatives.iter().all(|a| a.contains(s)))
                .collect();
            let parts = alternatives
                .iter()
                .map(|a| a.iter().copied().filter(|s| !common.contains(s)).collect())
                .collect();
            statements = common;
            Verdict::Ambiguous(parts)
        } else {
            Verdict::Explained
        };
        let stated = statements.clone();
        for other in &mut answer.same_pixels {
            other.retain(|s| !stated.contains(s));
        }
    } else {
        // In part, only what a fit of where rays start cannot fake: a mapping of six numbers can
        // lay one disc over any other, so a fitted map is said only when it explains it all.
        statements.retain(|s| !s.is_geometric());
        // And what it says of the depth image only where the colour image shows the hits
        // right: a depth map read off wrong hits means nothing.
        let colour_left = scorer.unexplained(&rebuild(view, &statements)).colour;
        let hits_right = colour_left.is_some_and(|flags| {
            flags.iter().filter(|&&f| f).count() as f64 <= LEFT_SHARE_OF_ALL * flags.len() as f64
        });
        if !hits_right {
            statements.retain(|s| !s.is_about_depth());
        }
        let left = scorer.score(&rebuild(view, &statements));
        let each_needed = statements.iter().enumerate().all(|(i, _)| {
            let mut without = statements.clone();
            without.remove(i);
            let score = scorer.score(&rebuild(view, &without));
            score.saturating_sub(left) as f64 >= PARTIAL_SHARE_EACH * differing_exact as f64
        });
        let most = (left as f64) < (1.0 - PARTIAL_SHARE_ALL) * differing_exact as f64;
        answer.verdict = if !statements.is_empty() && each_needed && most {
            answer.differing_left = left;
            answer.model = rebuild(view, &statements);
            Verdict::Partial
        } else {
            Verdict::Unexplained
        };
    }
    answer.statements = statements;
    let shown = match answer.verdict {
        Verdict::Unexplained => course,
        _ => answer.model,
    };
    answer.unexplained = scorer.unexplained(&shown);
    answer
}
