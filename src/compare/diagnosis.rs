//! Naming the mistakes behind a picture: render the scene with each known mistake and each pair
//! (and grow the best set one mistake at a time), and report the set whose images match the given
//! ones best — only when it explains the difference: it leaves at most a tenth of the differing
//! pixels and at most 1% of all, and every mistake in it is needed (it explains more than 1% of
//! the differing pixels: a word that moves a pixel or two is noise, not evidence). Otherwise, or
//! when another set explains the images as well or within 1% of the differing pixels, nothing is
//! named: never a guess.
//!
//! When no set explains the whole difference (a program can make a mistake outside the
//! vocabulary), the best set is still given as a *partial* diagnosis when it explains more than
//! half of the differing pixels, every mistake in it explains at least a tenth on its own, and no
//! other set does as well; the pixels it leaves are counted as unexplained.

use std::collections::HashMap;

use image::RgbImage;

use super::difference::Difference;
use super::mistake::{Mistake, MistakeSet};
use super::variant::{Hits, colour_image, depth_image, render_hits};
use crate::render::View;
use crate::scene::Scene;

/// The images to explain (at least one), the size of `view`; the depth image over `view`'s
/// depth range.
#[derive(Debug, Clone, Copy)]
pub struct Theirs<'a> {
    /// Their colour image.
    pub colour: Option<&'a RgbImage>,
    /// Their depth image.
    pub depth: Option<&'a RgbImage>,
}

/// Levels a depth pixel may differ by and still count as the same (the course's depth rule).
const DEPTH_LEVELS_UNNOTICED: u8 = 1;

/// Largest set of mistakes the search grows to.
const MAX_MISTAKES: usize = 4;

/// Renders (t and sphere per pixel) the search keeps at once; more are made again when needed.
/// [`crate::render::memory::compare_bound_bytes`] counts them.
pub const MAX_CACHED_HITS: usize = 6;

/// How many of the best singles and pairs the search grows.
const GROWN_SETS: usize = 8;

/// Share of the exact render's differing pixels the named mistakes may leave unexplained.
const LEFT_SHARE_OF_DIFFERING: f64 = 0.1;

/// Share of all compared pixels the named mistakes may leave unexplained.
const LEFT_SHARE_OF_ALL: f64 = 0.01;

/// Share of the exact render's differing pixels each named mistake must explain on its own (the
/// pixels that differ again when it is left out); one pixel at least.
const NEEDED_SHARE: f64 = 0.01;

/// Another set whose pixels left are within this share of the exact render's differing pixels of
/// the best set's is a rival: the two explain the images equally well.
const NEAR_SHARE: f64 = 0.01;

/// Share of the exact render's differing pixels each mistake of a partial diagnosis must explain
/// on its own (the pixels that differ again when it is left out).
const PARTIAL_SHARE_EACH: f64 = 0.1;

/// Share of the exact render's differing pixels a partial diagnosis must explain in all: more
/// than half, so that what it names is most of the difference.
const PARTIAL_SHARE_ALL: f64 = 0.5;

/// Where the differing pixels lie that no named mistake accounts for: one flag per pixel, row
/// by row from the top, for each image given.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Unexplained {
    /// In the colour image (any level differs).
    pub colour: Option<Vec<bool>>,
    /// In the depth image (more than one level differs).
    pub depth: Option<Vec<bool>>,
}

/// What the diagnosis found.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    /// The mistakes named (empty: none explains the difference, or there was none).
    pub mistakes: MistakeSet,
    /// Pixels the exact render differs in from theirs (colour: any level; depth: beyond one).
    pub differing_exact: usize,
    /// Pixels the best set's render still differs in.
    pub differing_left: usize,
    /// Other sets that explain the images exactly as well as the best one (then nothing is named).
    pub alternatives: Vec<MistakeSet>,
    /// When no set explains the whole difference: the mistakes that explain part of it (see the
    /// module docs); `differing_left` pixels stay unexplained.
    pub partial: MistakeSet,
    /// Where the [`Self::unexplained_pixels`] are.
    pub unexplained: Unexplained,
}

impl Diagnosis {
    /// The mistakes the answer puts forward, in full or in part (none when ambiguous).
    pub fn put_forward(&self) -> MistakeSet {
        if self.mistakes.is_empty() {
            self.partial
        } else {
            self.mistakes
        }
    }

    /// The differing pixels no named mistake accounts for: all of them when nothing is named,
    /// in full or in part.
    pub fn unexplained_pixels(&self) -> usize {
        if self.mistakes.is_empty() && self.partial.is_empty() {
            self.differing_exact
        } else {
            self.differing_left
        }
    }
}

/// Renders and scores mistake sets, caching the hits of each hit-changing part.
struct Search<'a> {
    scene: &'a Scene,
    view: &'a View,
    theirs: Theirs<'a>,
    hits: HashMap<MistakeSet, Hits>,
    scores: HashMap<MistakeSet, usize>,
}

impl Search<'_> {
    /// `set` without the mistakes it does not need: each left explains more than
    /// [`NEEDED_SHARE`] of the `differing_exact` pixels, and one pixel at least, on its own. The
    /// cheapest to leave out goes first.
    fn needed(&mut self, mut set: MistakeSet, differing_exact: usize) -> MistakeSet {
        let needed_px = NEEDED_SHARE * differing_exact as f64;
        loop {
            let score = self.score(set);
            let cheapest = set
                .mistakes()
                .into_iter()
                .map(|mistake| (self.score(set.without(mistake)), mistake))
                .min();
            match cheapest {
                Some((without, mistake))
                    if without <= score || (without - score) as f64 <= needed_px =>
                {
                    set = set.without(mistake);
                }
                _ => return set,
            }
        }
    }

    /// Keeps at most [`MAX_CACHED_HITS`] renders, so that memory stays bounded whatever the
    /// search tries: one goes before `hit_part`'s is made (the exact render stays).
    fn make_room_for(&mut self, hit_part: MistakeSet) {
        if self.hits.len() >= MAX_CACHED_HITS && !self.hits.contains_key(&hit_part) {
            let evicted = self
                .hits
                .keys()
                .copied()
                .find(|&key| key != MistakeSet::NONE);
            if let Some(key) = evicted {
                self.hits.remove(&key);
            }
        }
    }

    /// How the images of `mistakes` differ from theirs (colour, depth), from the cached render of
    /// their hit-changing part.
    fn differences(&mut self, mistakes: MistakeSet) -> (Option<Difference>, Option<Difference>) {
        let (scene, view, theirs) = (self.scene, self.view, self.theirs);
        let hit_part = mistakes.hit_part();
        self.make_room_for(hit_part);
        let hits = self
            .hits
            .entry(hit_part)
            .or_insert_with(|| render_hits(scene, view, hit_part));
        (
            theirs
                .colour
                .map(|theirs| Difference::of(&colour_image(scene, hits, mistakes), theirs)),
            theirs
                .depth
                .map(|theirs| Difference::of(&depth_image(view, hits, mistakes), theirs)),
        )
    }

    /// Where the images of `mistakes` differ from theirs (colour: any level; depth: beyond
    /// [`DEPTH_LEVELS_UNNOTICED`]).
    fn unexplained(&mut self, mistakes: MistakeSet) -> Unexplained {
        let (colour, depth) = self.differences(mistakes);
        let flags = |difference: Difference, levels: u8| {
            difference.per_pixel.iter().map(|&d| d > levels).collect()
        };
        Unexplained {
            colour: colour.map(|difference| flags(difference, 0)),
            depth: depth.map(|difference| flags(difference, DEPTH_LEVELS_UNNOTICED)),
        }
    }

    /// Pixels the images of `mistakes` differ in from theirs (as [`Self::unexplained`] counts).
    fn score(&mut self, mistakes: MistakeSet) -> usize {
        if let Some(&score) = self.scores.get(&mistakes) {
            return score;
        }
        let (colour, depth) = self.differences(mistakes);
        let score = colour.map_or(0, |difference| difference.pixels_beyond(0))
            + depth.map_or(0, |difference| {
                difference.pixels_beyond(DEPTH_LEVELS_UNNOTICED)
            });
        self.scores.insert(mistakes, score);
        score
    }
}

/// Names the mistakes that explain how `theirs` differs from the exact picture of `scene`
/// through `view` (see the module docs), and says where the pixels they leave are.
pub fn diagnose(scene: &Scene, view: &View, theirs: Theirs<'_>) -> Diagnosis {
    let mut search = Search {
        scene,
        view,
        theirs,
        hits: HashMap::new(),
        scores: HashMap::new(),
    };
    let mut diagnosis = find(&mut search);
    diagnosis.unexplained = search.unexplained(diagnosis.put_forward());
    diagnosis
}

/// The search behind [`diagnose`], without the unexplained pixels' places.
fn find(search: &mut Search<'_>) -> Diagnosis {
    let (view, theirs) = (search.view, search.theirs);
    let differing_exact = search.score(MistakeSet::NONE);
    let nothing = Diagnosis {
        mistakes: MistakeSet::NONE,
        differing_exact,
        differing_left: differing_exact,
        alternatives: Vec::new(),
        partial: MistakeSet::NONE,
        unexplained: Unexplained::default(),
    };
    if differing_exact == 0 {
        return nothing;
    }
    // Every single mistake and every pair.
    let mut candidates = vec![MistakeSet::NONE];
    for (index, first) in Mistake::ALL.into_iter().enumerate() {
        candidates.push(MistakeSet::of(&[first]));
        for second in Mistake::ALL.into_iter().skip(index + 1) {
            let pair = MistakeSet::of(&[first, second]);
            if pair.is_possible() {
                candidates.push(pair);
            }
        }
    }
    let rank = |search: &mut Search<'_>, set: MistakeSet| (search.score(set), set.len(), set);
    let mut ranked: Vec<_> = candidates.iter().map(|&set| rank(search, set)).collect();
    ranked.sort_unstable();
    // Grow each of the best few sets while one more mistake explains more (the best pair is not
    // always part of the best triple), and keep the best set grown.
    let mut best = MistakeSet::NONE;
    for &(_, _, start) in ranked.iter().take(GROWN_SETS) {
        let mut set = start;
        while set.len() < MAX_MISTAKES {
            let grown = Mistake::ALL
                .into_iter()
                .filter(|m| !set.contains(*m) && set.with(*m).is_possible())
                .map(|m| rank(search, set.with(m)))
                .min();
            match grown {
                Some((score, _, bigger)) if score < search.score(set) => set = bigger,
                _ => break,
            }
        }
        if rank(search, set) < rank(search, best) {
            best = set;
        }
    }
    let best = search.needed(best, differing_exact);
    let left = search.score(best);
    let compared_pixels = (u64::from(view.width_px) * u64::from(view.height_px)) as f64
        * f64::from(u8::from(theirs.colour.is_some()) + u8::from(theirs.depth.is_some()));
    let explains = !best.is_empty()
        && left as f64 <= LEFT_SHARE_OF_DIFFERING * differing_exact as f64
        && left as f64 <= LEFT_SHARE_OF_ALL * compared_pixels;
    if !explains {
        // Part of the difference, each mistake needed for a real share of it, and no rival.
        let each_needed = best.mistakes().iter().all(|&mistake| {
            (search.score(best.without(mistake)) - left) as f64
                >= PARTIAL_SHARE_EACH * differing_exact as f64
        });
        let rivalled = search.scores.iter().any(|(&set, &score)| {
            set != best && !set.is_empty() && set.len() <= best.len() && score <= left
        });
        let explains_most = (left as f64) < (1.0 - PARTIAL_SHARE_ALL) * differing_exact as f64;
        let partial = !best.is_empty() && each_needed && explains_most && !rivalled;
        return Diagnosis {
            differing_left: left,
            partial: if partial { best } else { MistakeSet::NONE },
            ..nothing
        };
    }
    // Another set, no larger, that explains the images as well (within [`NEAR_SHARE`] of the
    // differing pixels) makes the answer ambiguous. Sets that hold the best one only add
    // mistakes it does not need.
    let near = left + (NEAR_SHARE * differing_exact as f64) as usize;
    let mut close: Vec<MistakeSet> = search
        .scores
        .iter()
        .filter(|&(&set, &score)| score <= near && !set.is_empty() && !set.includes(best))
        .map(|(&set, _)| set)
        .collect();
    close.sort_unstable();
    let mut alternatives = Vec::new();
    for set in close {
        let set = search.needed(set, differing_exact);
        if set != best
            && !set.is_empty()
            && set.len() <= best.len()
            && search.score(set) <= near
            && !alternatives.contains(&set)
        {
            alternatives.push(set);
        }
    }
    alternatives.sort();
    if alternatives.is_empty() {
        Diagnosis {
            mistakes: best,
            differing_exact,
            differing_left: left,
            alternatives,
            partial: MistakeSet::NONE,
            unexplained: Unexplained::default(),
        }
    } else {
        alternatives.insert(0, best);
        Diagnosis {
            differing_left: left,
            alternatives,
            ..nothing
        }
    }
}
