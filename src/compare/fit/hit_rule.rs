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

/// The largest tmin a search tries, either way from the camera's plane: a program's tmin is a
/// small constant (0, an epsilon, −1, −0.81, …), and a large one would say that a program
/// refuses what it plainly sees (a scene's front spheres refused make another scene's picture).
const TMIN_REACH: f64 = 2.0;

/// Thresholds a tmin search tries in one pass.
const TMIN_STEPS: usize = 24;

/// The model with the tmin (any value within [`TMIN_REACH`] of the camera's plane; the far root
/// tried where the near one is refused, or not) that explains their images best. A tmin changes what is drawn only where it passes a
/// near root, so it is searched among the near roots `model` would draw with no tmin: a pass
/// over thresholds between their quantiles, then a second between the neighbours of the best.
pub fn search_tmin(
    scorer: &mut Scorer<'_>,
    model: &Model,
    seen: &mut Vec<(usize, Model)>,
) -> Model {
    let mut open = *model;
    open.hits.tmin = f64::NEG_INFINITY;
    open.hits.far_when_near_refused = true;
    open.hits.far_only = false;
    let hits = scorer.hits(&open);
    let mut near: Vec<f64> = hits
        .t
        .iter()
        .copied()
        .filter(|t| (-TMIN_REACH..=TMIN_REACH).contains(t))
        .collect();
    near.sort_by(f64::total_cmp);
    near.dedup();
    if near.len() < 2 {
        return *model;
    }
    let mut best = (scorer.score(model), *model);
    let (mut lo, mut hi) = (0, near.len() - 1);
    for _ in 0..2 {
        let span = hi - lo;
        let thresholds: Vec<(usize, f64)> = (1..=TMIN_STEPS)
            .map(|k| lo + span * k / (TMIN_STEPS + 1))
            .filter(|&i| i > 0)
            .map(|i| (i, 0.5 * (near[i - 1] + near[i])))
            .collect();
        let mut candidates = Vec::new();
        for &(_, tmin) in &thresholds {
            for far in [true, false] {
                let mut rule = open.hits;
                rule.tmin = tmin;
                rule.far_when_near_refused = far;
                candidates.push(with_rule(scorer, &open, rule));
            }
        }
        let scores = scorer.scores_of(&candidates);
        let mut best_at = None;
        for (k, (candidate, score)) in candidates.into_iter().zip(scores).enumerate() {
            if let Some(score) = score {
                seen.push((score, candidate));
                if score < best.0 {
                    best = (score, candidate);
                    best_at = Some(k / 2);
                }
            }
        }
        let Some(at) = best_at else { break };
        // Between the thresholds either side of the best.
        lo = if at == 0 { lo } else { thresholds[at - 1].0 };
        hi = thresholds.get(at + 1).map_or(hi, |&(i, _)| i);
        if hi <= lo + 1 {
            break;
        }
    }
    best.1
}
