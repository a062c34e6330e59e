//! Searching which hits their program draws: the depth test (nearest, or file order), ties, tmin
//! and which roots it tries, the square root. These are discrete, so each choice is tried: one
//! change at a time from the current rule, the best change kept, until none helps.

use super::depth::fit_depth_quickly;
use super::score::Scorer;
use crate::compare::model::{HitRule, Model, Visible};

/// The roots a program may take: (tmin, the far root tried when the near one is refused, only
/// the far root).
const ROOTS: [(f64, bool, bool); 7] = [
    (f64::NEG_INFINITY, true, false),
    (f64::NEG_INFINITY, true, true),
    (0.0, true, false),
    (0.0, true, true),
    (0.0, false, false),
    (-1.0, false, false),
    (-1.0, false, true),
];

/// The rules one change away from `rule`.
fn neighbours(rule: HitRule) -> Vec<HitRule> {
    let mut rules = Vec::new();
    for visible in [Visible::Nearest, Visible::FirstInFile, Visible::LastInFile] {
        if visible != rule.visible {
            rules.push(HitRule {
                visible,
                later_wins_ties: false,
                ..rule
            });
        }
    }
    if rule.visible == Visible::Nearest {
        rules.push(HitRule {
            later_wins_ties: !rule.later_wins_ties,
            ..rule
        });
    }
    for (tmin, far_when_near_refused, far_only) in ROOTS {
        let with = HitRule {
            tmin,
            far_when_near_refused,
            far_only,
            ..rule
        };
        if with != rule {
            rules.push(with);
        }
    }
    rules.push(HitRule {
        square_root: !rule.square_root,
        ..rule
    });
    rules
}

/// How many of a round's rules get their depth map fitted in full.
const FULLY_FITTED: usize = 2;

/// A model with `rule`, its depth map fitted again (quickly).
fn with_rule(scorer: &mut Scorer<'_>, model: &Model, rule: HitRule) -> Model {
    let mut with = *model;
    with.hits = rule;
    fit_depth_quickly(scorer, &with)
}

/// The model with the hit rule that explains their images best, reached one change at a time
/// from `model`'s (at most `rounds` changes); every model scored is reported to `seen`.
pub fn search_hit_rule(
    scorer: &mut Scorer<'_>,
    model: &Model,
    rounds: usize,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    let mut best = (scorer.score(model), *model);
    for round in 0..rounds {
        // Past the first round, only while pixels are left: the first also shows the rules
        // that explain the images as well (a simpler answer may be among them).
        if best.0 == 0 && round > 0 {
            break;
        }
        // Each rule scored (on a large image, those far behind on a sample are left out).
        let candidates: Vec<Model> = neighbours(best.1.hits)
            .into_iter()
            .map(|rule| with_rule(scorer, &best.1, rule))
            .collect();
        let scores = scorer.scores_of(&candidates);
        let mut tried: Vec<(usize, Model)> = Vec::new();
        for (candidate, score) in candidates.into_iter().zip(scores) {
            if let Some(score) = score {
                seen.push((score, candidate));
                tried.push((score, candidate));
            }
        }
        // The depth map in full for the best few: a rule can need its own tilt or range before
        // it shows what it explains.
        tried.sort_by_key(|&(score, _)| score);
        let mut improved: Option<(usize, Model)> = None;
        for (_, candidate) in tried.into_iter().take(FULLY_FITTED) {
            let fitted = super::depth::fit_depth(scorer, &candidate);
            let score = scorer.score(&fitted);
            seen.push((score, fitted));
            if score < improved.map_or(best.0, |(s, _)| s) {
                improved = Some((score, fitted));
            }
        }
        match improved {
            Some(better) => best = better,
            None => break,
        }
    }
    best.1
}
