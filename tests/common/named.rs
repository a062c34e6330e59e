//! Helpers shared by the diagnosis tests on known mistakes (`tests/compare.rs`,
//! `tests/course_mistakes.rs`), included by path: both images as theirs, and the known mistakes a
//! diagnosis names in full, in part, or offers as a tie.
#![allow(dead_code)] // each test file uses its own share

use image::RgbImage;
use raytracer::compare::diagnosis::words_of;
use raytracer::compare::{Diagnosis, MistakeSet, Theirs};

/// Their colour and depth images, both given.
pub(crate) fn both(images: &(RgbImage, RgbImage)) -> Theirs<'_> {
    Theirs {
        colour: Some(&images.0),
        depth: Some(&images.1),
    }
}

/// The known mistakes a diagnosis names in full; every statement it makes must be one of them.
pub(crate) fn words_named(diagnosis: &Diagnosis) -> MistakeSet {
    let words = words_of(diagnosis.stated());
    assert_eq!(
        words.len(),
        diagnosis.stated().len(),
        "statements beyond the known mistakes: {diagnosis:?}"
    );
    words
}

/// The known mistakes a diagnosis names in part; every statement must be one of them.
pub(crate) fn named_in_part(diagnosis: &Diagnosis) -> MistakeSet {
    let words = words_of(diagnosis.partial());
    assert_eq!(words.len(), diagnosis.partial().len(), "{diagnosis:?}");
    words
}

/// The sets of known mistakes a near tie offers, each with the statements all of them make.
pub(crate) fn offered(diagnosis: &Diagnosis) -> Vec<MistakeSet> {
    diagnosis
        .alternatives()
        .iter()
        .map(|part| words_of(&[diagnosis.stated(), part.as_slice()].concat()))
        .collect()
}
