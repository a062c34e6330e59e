//! Judging a diagnosis's statements against what a program does (its truth: read from its code
//! for the real corpus, the knobs turned for the generated one). A statement is *right* when a
//! behaviour of the program draws it: its own name, or a behaviour the statement is a true
//! description of (a non-unit vector is a zoom; t measured along the direction as written draws
//! the same pixels as a range scaled the same way). Anything else is *wrong*. The table is the
//! whole rule, and `docs/diagnosis.md` prints it.

#![allow(dead_code)]

/// Per statement name, the behaviours of a program that make it true.
pub(crate) const JUSTIFIED_BY: &[(&str, &[&str])] = &[
    ("pixel-corners", &["pixel-corners", "sample-offset"]),
    (
        "sample-offset",
        &[
            "sample-offset",
            "pixel-corners",
            "crop-strip",
            "square-block",
            "swapped-normalisers",
        ],
    ),
    ("crop-not-centred", &["crop-strip", "swapped-normalisers"]),
    // The width used for both axes of a tall image is a zoom by H/W.
    (
        "zoom",
        &[
            "zoom",
            "raw-up",
            "square-block",
            "swapped-normalisers",
            "crop-strip",
        ],
    ),
    (
        "axes-scaled",
        &[
            "zoom",
            "raw-up",
            "stretched",
            "swapped-normalisers",
            "square-block",
            "crop-strip",
        ],
    ),
    ("stretched", &["stretched"]),
    ("swapped-axes", &["swapped-axes", "transposed-write"]),
    // A whole matrix: a mirror or a flip among the rest.
    (
        "axes",
        &[
            "raw-up",
            "axes",
            "zoom",
            "swapped-axes",
            "mirrored",
            "flipped-vertically",
        ],
    ),
    ("mirrored", &["mirrored"]),
    ("flipped-vertically", &["flipped-vertically"]),
    ("raw-up", &["raw-up"]),
    ("t-ramp", &["raw-up", "t-ramp"]),
    ("only-block", &["square-block", "loops-swapped", "loops-to"]),
    (
        "no-depth-test",
        &["no-depth-test-first", "no-depth-test-last"],
    ),
    ("last-wins", &["last-wins", "no-depth-test-last"]),
    ("tmin-zero", &["tmin-zero", "near-root-only"]),
    (
        "near-root-only",
        &["near-root-only", "tmin-zero", "tmin-minus-one"],
    ),
    ("tmin-minus-one", &["tmin-minus-one"]),
    ("tmin", &["tmin", "tmin-zero"]),
    ("sample-grid", &["sample-grid"]),
    ("far-root", &["far-root"]),
    ("no-square-root", &["no-square-root"]),
    ("background", &["background"]),
    ("rounded", &["rounded"]),
    ("depth-reversed", &["depth-reversed"]),
    (
        "depth-range",
        &[
            "depth-range",
            "depth-per-image",
            "depth-quantity",
            "ray-march",
            "unnormalized-direction",
        ],
    ),
    ("depth-per-image", &["depth-per-image"]),
    (
        "unnormalized-direction",
        &["unnormalized-direction", "depth-quantity", "depth-range"],
    ),
    ("depth-quantity", &["depth-quantity"]),
    ("depth-no-clamp", &["depth-no-clamp"]),
    ("depth-outside-black", &["depth-outside-black"]),
    (
        "depth-outside",
        &[
            "depth-outside-background",
            "depth-outside-black",
            "depth-outside-colour",
        ],
    ),
    ("depth-no-hit", &["depth-no-hit"]),
];

/// The name of a truth item (`zoom=1.118` → `zoom`).
pub(crate) fn behaviour(item: &str) -> &str {
    item.split('=').next().unwrap_or(item)
}

/// Whether a program doing `truth` makes the statement named `statement` true.
pub(crate) fn justified(statement: &str, truth: &[String]) -> bool {
    JUSTIFIED_BY
        .iter()
        .find(|(name, _)| *name == statement)
        .is_some_and(|(_, by)| truth.iter().any(|item| by.contains(&behaviour(item))))
}

/// How an image's answer fares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Verdict {
    /// The images match by the course's rule.
    Match,
    /// Every statement is right and the pixels left are at most 1% of the image.
    Explained,
    /// Every statement is right, more than 1% of the image is left.
    Partial,
    /// A statement the program does not make.
    Wrong,
}

/// The verdict of an answer that made `statements` (names, in full or in part), offered
/// `alternatives` (a near tie: one of them must be right) and left `unexplained` of `pixels`.
pub(crate) fn judge(
    matched: bool,
    statements: &[String],
    alternatives: &[Vec<String>],
    unexplained: u64,
    pixels: u64,
    truth: &[String],
) -> Verdict {
    let alternative_right = alternatives.is_empty()
        || alternatives
            .iter()
            .any(|set| set.iter().all(|s| justified(s, truth)));
    if statements.iter().any(|s| !justified(s, truth)) || !alternative_right {
        Verdict::Wrong
    } else if matched {
        Verdict::Match
    } else if unexplained * 100 <= pixels {
        Verdict::Explained
    } else {
        Verdict::Partial
    }
}
