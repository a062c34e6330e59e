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
use super::deviation::{Deviation, RangeFrom};
use super::fit::fit;
use super::fit::score::{Scorer, Theirs, Unexplained};
use super::mistake::{Mistake, MistakeSet};
use super::model::Model;
use super::needed::{NEEDED_SHARE, needed, per_image, rounded};
use super::rival_maps::same_map_farther;
use super::shorter::{shorter_answers, without_turn_guesses};
use crate::render::View;
use crate::scene::Scene;

/// Share of the exact render's differing pixels the statements may leave unexplained.
const LEFT_SHARE_OF_DIFFERING: f64 = 0.1;

/// Share of all compared pixels the statements may leave unexplained.
const LEFT_SHARE_OF_ALL: f64 = 0.01;

/// Another model whose pixels left are within this share of the differing pixels is a rival.
const NEAR_SHARE: f64 = 0.01;

/// Share of the differing pixels each statement of a partial answer must explain on its own.
const PARTIAL_SHARE_EACH: f64 = 0.1;

/// Share of the differing pixels a partial answer must explain in all: more than half.
const PARTIAL_SHARE_ALL: f64 = 0.5;

/// Spheres beyond which no model of their program is fitted: the fit renders their scene some
/// hundreds of times, and this many random spheres keep the whole comparison to a few seconds on
/// two cores (docs/diagnosis-speed.md measures it, with the sizes around it); beyond, the
/// comparison counts the pixels and says why it stops there.
pub const MAX_FITTED_SPHERES: usize = 20_000;

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
    /// No model was fitted: the scene has more spheres than [`MAX_FITTED_SPHERES`].
    NotFitted {
        /// The scene's spheres.
        spheres: usize,
    },
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
            Verdict::NotFitted { .. } => "not-fitted",
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

    /// The model of their program the answer states, in full or in part (`None` when it states
    /// nothing).
    pub fn stated_model(&self) -> Option<&Model> {
        match self.verdict {
            Verdict::Explained | Verdict::Ambiguous(_) | Verdict::Partial => Some(&self.model),
            Verdict::Same | Verdict::Unexplained | Verdict::NotFitted { .. } => None,
        }
    }

    /// The alternatives of a near tie (each the part where the rivals differ).
    pub fn alternatives(&self) -> &[Vec<Deviation>] {
        match &self.verdict {
            Verdict::Ambiguous(alternatives) => alternatives,
            _ => &[],
        }
    }

    /// The answer with its depth-range statements said as chosen by `from` (who chose the range
    /// the depth image was judged under).
    #[must_use]
    pub fn with_range_from(mut self, from: RangeFrom) -> Self {
        let said = |list: &mut Vec<Deviation>| {
            for statement in list.iter_mut() {
                *statement = statement.with_range_from(from);
            }
        };
        said(&mut self.statements);
        for list in &mut self.same_pixels {
            said(list);
        }
        if let Verdict::Ambiguous(alternatives) = &mut self.verdict {
            for list in alternatives {
                said(list);
            }
        }
        self
    }

    /// Why no model was fitted, in a sentence (`None` when one was).
    pub fn not_fitted_because(&self) -> Option<String> {
        match self.verdict {
            Verdict::NotFitted { spheres } => Some(format!(
                "the scene has {spheres} spheres, and a model of your program is fitted to scenes \
                 of up to {MAX_FITTED_SPHERES} (beyond, the fit would take longer than a \
                 comparison may): the pixels are compared, nothing is said of why they differ"
            )),
            _ => None,
        }
    }

    /// The differing pixels no statement accounts for: all of them when nothing is stated.
    pub fn unexplained_pixels(&self) -> usize {
        match self.verdict {
            Verdict::Unexplained | Verdict::NotFitted { .. } => self.differing_exact,
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

/// How much the statements claim — the numbers they fit, a known mistake counting one — then
/// how many are fitted values: of two models that explain the images equally well, the one
/// that claims less is said.
fn complexity(statements: &[Deviation]) -> (usize, usize) {
    let words = words_of(statements).len();
    let numbers: usize = statements.iter().map(Deviation::numbers_fitted).sum();
    (numbers, statements.len() - words)
}

/// Says why `theirs` differs from the exact picture of `scene` through `view` (its depth range
/// the one their depth image was asked for), and where the pixels left are.
pub fn diagnose(scene: &Scene, view: &View, theirs: Theirs<'_>) -> Diagnosis {
    let mut scorer = Scorer::new(scene, view, theirs);
    if scene.spheres.len() > MAX_FITTED_SPHERES {
        let differing_exact = scorer.score(&Model::course(view));
        return Diagnosis {
            verdict: if differing_exact == 0 {
                Verdict::Same
            } else {
                Verdict::NotFitted {
                    spheres: scene.spheres.len(),
                }
            },
            statements: Vec::new(),
            same_pixels: Vec::new(),
            differing_exact,
            differing_left: differing_exact,
            unexplained: Unexplained::default(),
            model: Model::course(view),
        };
    }
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
    // Plainer models first: many models seen differ from the fitted one by a hair.
    let seen: Vec<&(usize, Model)> = fitted
        .plainer
        .iter()
        .filter(|(score, _)| *score <= fitted.left + near)
        .chain(seen)
        .collect();
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
    let order = |(statements, left): &(Vec<Deviation>, usize)| {
        (*left > fewest + needed_px, complexity(statements), *left)
    };
    options.sort_by_key(order);
    // Never a longer story while a shorter one draws their pixels as well: one or two known
    // mistakes are tried against the answer's length.
    if let Some((best, best_left)) = options.first().cloned() {
        for shorter in shorter_answers(&mut scorer, &best, best_left, near, differing_exact) {
            if !options.iter().any(|(s, _)| *s == shorter.0) {
                options.push(shorter);
            }
        }
        options.sort_by_key(order);
    }
    let (statements, left) = options.remove(0);
    // Where rays start as each model seen has it, with the rest of the answer: a symmetric
    // scene's other maps are rivals of the answer itself.
    let rest: Vec<Deviation> = statements
        .iter()
        .copied()
        .filter(|s| !s.is_about_geometry())
        .collect();
    let mut tried: Vec<Vec<Deviation>> = Vec::new();
    for (_, model) in seen.iter().take(MAX_RIVALS) {
        let geometry: Vec<Deviation> = describe(scene, view, model)
            .into_iter()
            .filter(Deviation::is_about_geometry)
            .collect();
        if tried.contains(&geometry) {
            continue;
        }
        tried.push(geometry.clone());
        let option = needed(
            &mut scorer,
            [geometry, rest.clone()].concat(),
            differing_exact,
        );
        if option.0 != statements && !options.iter().any(|(s, _)| *s == option.0) {
            options.push(option);
        }
    }
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
        for (rival, rival_left) in options {
            let holds_ours = statements.iter().all(|s| rival.contains(s));
            // The same statements with other values are the same answer: values are given as
            // far as the images tell them.
            if names(&rival) == names(&statements) {
                continue;
            }
            // Of two maps that differ only in where rays start (the other statements the same,
            // whatever their values), the one nearer the course's is said: a symmetric scene
            // looks the same turned, and the least change is the answer. Nor is the same map
            // said with more numbers an alternative.
            let rest_names = |list: &[Deviation]| {
                let rest: Vec<Deviation> = list
                    .iter()
                    .copied()
                    .filter(|s| !s.is_about_geometry())
                    .collect();
                names(&rest)
            };
            if rest_names(&rival) == rest_names(&statements)
                && same_map_farther(view, &rival, &statements)
            {
                continue;
            }
            // A matrix where the answer says a scale, the rest the same, is the answer with
            // more numbers: the scale draws their pixels as well (it was chosen so).
            let scale_only = |list: &[Deviation]| {
                let mut rest: Vec<&str> = names(list)
                    .into_iter()
                    .filter(|n| *n != "axes" && *n != "scaled")
                    .collect();
                rest.sort_unstable();
                rest
            };
            if rival.iter().any(|d| matches!(d, Deviation::Axes { .. }))
                && !statements
                    .iter()
                    .any(|d| matches!(d, Deviation::Axes { .. } | Deviation::SwappedAxes { .. }))
                && scale_only(&rival) == scale_only(&statements)
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
            } else if !alternatives.iter().any(|a| names(a) == names(&rival)) {
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
        if scorer.theirs.colour.is_none() {
            // A depth image alone: which hit is drawn shows only in its greys, which a partial
            // answer does not read right; only where rays start is said in part.
            statements.retain(Deviation::is_about_geometry);
        }
        statements = without_turn_guesses(&mut scorer, &statements, near);
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
