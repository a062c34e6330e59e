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

use glam::DVec2;

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

/// Share of all compared pixels a fitted value (not a known mistake) must explain on its own,
/// besides [`NEEDED_SHARE`] of the differing ones (or half of those, when they are fewer).
const FITTED_SHARE_OF_ALL: f64 = 0.001;

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
    /// The verdict's name, as the JSON form gives it.
    pub fn verdict_name(&self) -> &'static str {
        match self.verdict {
            Verdict::Same => "same",
            Verdict::Explained => "explained",
            Verdict::Ambiguous(_) => "ambiguous",
            Verdict::Partial => "partial",
            Verdict::Unexplained => "unexplained",
        }
    }

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
    // A fitted value must also explain a share of the image itself: any value can be tuned to
    // catch a handful of pixels.
    let fitted_px = needed_px.max(
        (FITTED_SHARE_OF_ALL * scorer.compared_pixels() as f64).min(0.5 * differing_exact as f64),
    );
    let mut left = scorer.score(&rebuild(&view, &statements));
    loop {
        // Each statement left out, or a fitted value replaced by the known mistake nearest it;
        // with the pixels it must explain to stay.
        let mut simpler: Vec<(usize, f64, Vec<Deviation>)> = Vec::new();
        for (i, statement) in statements.iter().enumerate() {
            let threshold = if matches!(statement, Deviation::Word(_)) {
                needed_px
            } else {
                fitted_px
            };
            let mut without = statements.clone();
            without.remove(i);
            if let Some(named) = nearest_word(statement) {
                let mut replaced = without.clone();
                replaced.insert(i, named);
                simpler.push((0, threshold, replaced));
            }
            simpler.push((1, threshold, without));
        }
        let cheapest = simpler
            .into_iter()
            .map(|(order, threshold, candidate)| {
                let score = scorer.score(&rebuild(&view, &candidate));
                (score, order, threshold, candidate)
            })
            .filter(|(score, _, threshold, _)| {
                *score <= left || ((*score - left) as f64) < *threshold
            })
            .min_by_key(|(score, order, _, _)| (*score, *order));
        match cheapest {
            Some((score, _, _, candidate)) => {
                statements = candidate;
                left = score;
            }
            None => return (statements, left),
        }
    }
}

/// The known mistake a fitted statement comes nearest to, where it has one: a sample offset
/// near a pixel's corner is `pixel-corners`.
fn nearest_word(statement: &Deviation) -> Option<Deviation> {
    match statement {
        Deviation::SampleOffset { offset_px } if offset_px.abs().max_element() < 0.25 => {
            Some(Deviation::Word(Mistake::PixelCorners))
        }
        _ => None,
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
                Deviation::Scaled { factor } => {
                    // The same factor on both axes first (a zoom), then each its own.
                    let mean = 0.5 * (factor.x + factor.y);
                    let mut with = statements.clone();
                    with[i] = Deviation::Scaled {
                        factor: DVec2::splat(round(mean, decimals + 1)),
                    };
                    if factor.x != factor.y && scorer.score(&rebuild(&view, &with)) <= left {
                        statements = with;
                        break;
                    }
                    Deviation::Scaled {
                        factor: factor.map(|v| round(v, decimals)),
                    }
                }
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

/// How far the pixel map `statements` describe lies from the course's (its axes, in course
/// pixel steps).
fn off_course(view: &View, statements: &[Deviation]) -> f64 {
    let model = rebuild(view, statements);
    let relative = model.pixels.relative_axes(Model::step_world(view)) - glam::DMat2::IDENTITY;
    relative.x_axis.length() + relative.y_axis.length()
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
    let statements = rounded(&mut scorer, statements, left);
    // Said again from the model they make: a value rounded onto a named point is its word.
    let mut statements = describe(scene, view, &rebuild(view, &statements));
    let left = scorer.score(&rebuild(view, &statements));
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
            // The same statements with other values are the same answer: values are given as
            // far as the images tell them.
            let names = |list: &[Deviation]| {
                let mut names: Vec<&str> = list
                    .iter()
                    .map(|d| match d {
                        Deviation::Word(m) => m.word(),
                        other => other.kind(),
                    })
                    .collect();
                names.sort_unstable();
                names
            };
            if names(&rival) == names(&statements) {
                continue;
            }
            // Of two maps that differ only in where rays start, the one nearer the course's is
            // said: a symmetric scene looks the same turned, and the least change is the answer.
            let only_geometry = rival
                .iter()
                .chain(&statements)
                .filter(|s| !(rival.contains(s) && statements.contains(s)))
                .all(Deviation::is_about_geometry);
            let fitted_geometry = rival.iter().any(Deviation::is_geometric);
            if only_geometry
                && fitted_geometry
                && off_course(view, &rival) >= off_course(view, &statements)
            {
                continue;
            }
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
