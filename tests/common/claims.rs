//! The claims a statement's sentence makes, read from its words (`tests/statements.rs`): which
//! way the picture moves and by how much, zoomed in or out, how wide and tall a sphere is drawn,
//! upside down or mirrored, near white or black, what colour where nothing is hit, …
#![allow(dead_code)]

use glam::{DMat2, DVec2};

/// A claim a sentence makes, as this file reads it from the words.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Claim {
    /// The picture moves this many pixels right and up.
    Shifted {
        right: f64,
        up: f64,
    },
    /// Zoomed out (else in), each sphere this many times as wide.
    Zoomed {
        out: bool,
        width: Option<f64>,
    },
    /// Each sphere this many times as wide and as tall.
    Ellipse {
        wide: f64,
        tall: f64,
    },
    /// Circles drawn as ellipses longer along the image's longer side.
    LongerAlongLonger,
    UpsideDown,
    MirroredLeftRight,
    /// Mirrored across the diagonal from the lower left to the upper right.
    Transposed,
    /// A feature at exact pixel q is drawn at M⁻¹(q − c) + c (one pixel along x moves the first
    /// column of M, along y the second, in course pixels).
    Axes(DMat2),
    NearBlackFarWhite,
    /// Where no ray hits, the depth image is this colour.
    DepthNoHit([u8; 3]),
    /// These bytes are the scene's background colour.
    SceneBackground([u8; 3]),
    /// The colour image's background is the first, the scene's the second.
    Background([u8; 3], [u8; 3]),
    /// White at the first t, black at the second.
    Ramp {
        white: f64,
        black: f64,
    },
    /// The nearest and farthest hit and their greys.
    Extremes {
        near_t: f64,
        near_grey: f64,
        far_t: f64,
        far_grey: f64,
    },
    /// t grows by these per unit of the screen to the right and up.
    TRamp {
        right: f64,
        up: f64,
    },
    /// The first (else the last) sphere in the file that the ray hits is drawn.
    FileOrder {
        last: bool,
    },
    /// Only the lower-left block of these columns and rows is drawn.
    Block(u32, u32),
    /// What lies before this t is not drawn as the exact picture draws it.
    LostBefore(f64),
    /// Some values one level brighter, none otherwise.
    OneLevelBrighter,
    /// Every hit farther.
    Farther,
    /// Depth beyond the range striped (neither white nor black).
    Striped,
    /// What is nearer than DMIN is black.
    NearerThanMinBlack,
    /// On an exact tie the later sphere wins.
    LaterWinsTie,
    /// The picture's height divided by the length of up across the direction.
    VerticalByUp,
    /// Every t divided by the direction's length.
    DividedByDirection,
    /// The depth image maps |z| of each hit.
    MapsAbsZ,
    /// Depth outside the range drawn in this colour.
    OutsideColour([u8; 3]),
    /// Every sphere drawn larger: each pixel the exact picture lights is lit, and more.
    SilhouettesGrow,
    /// The depth wrong where a sphere is hit (and right where none is).
    DepthWrongWhereHit,
}

pub(crate) fn number_at(words: &[&str], at: usize) -> Option<f64> {
    let word = words.get(at)?;
    word.trim_matches(|c: char| !(c.is_ascii_digit() || c == '-' || c == '.'))
        .parse()
        .ok()
}

pub(crate) fn bytes_at(words: &[&str], at: usize) -> Option<[u8; 3]> {
    if words.get(at).is_some_and(|w| w.starts_with("black")) {
        return Some([0; 3]);
    }
    let byte = |i: usize| number_at(words, at + i).map(|v| v as u8);
    Some([byte(0)?, byte(1)?, byte(2)?])
}

/// The words after `phrase` in `sentence`, split on spaces.
pub(crate) fn after<'a>(sentence: &'a str, phrase: &str) -> Option<Vec<&'a str>> {
    sentence
        .find(phrase)
        .map(|at| sentence[at + phrase.len()..].split_whitespace().collect())
}

/// The claims a sentence makes, read from its words.
pub(crate) fn claims_of(sentence: &str) -> Vec<Claim> {
    let mut claims = Vec::new();
    if let Some(words) = after(sentence, "shifted ") {
        let (mut right, mut up) = (0.0, 0.0);
        let mut at = 0;
        loop {
            let (amount, direction) = if words.get(at) == Some(&"half") {
                (0.5, words.get(at + 3))
            } else if let Some(amount) = number_at(&words, at) {
                (amount, words.get(at + 2))
            } else {
                break;
            };
            let step = if words.get(at) == Some(&"half") { 4 } else { 3 };
            match direction.map(|d| d.trim_end_matches([',', ':', ';'])) {
                Some("right") => right += amount,
                Some("left") => right -= amount,
                Some("up") => up += amount,
                Some("down") => up -= amount,
                other => panic!("a shift without a direction: {other:?} in {sentence}"),
            }
            // "… right and up": a second direction with the same amount.
            if words.get(at + step) == Some(&"and")
                && let Some(second) = words.get(at + step + 1)
                && ["up", "down", "up:", "down:"].contains(second)
            {
                match second.trim_end_matches(':') {
                    "up" => up += amount,
                    _ => up -= amount,
                }
                break;
            }
            if words.get(at + step) != Some(&"and") {
                break;
            }
            at += step + 1;
        }
        claims.push(Claim::Shifted { right, up });
    }
    if sentence.contains("zoomed out") || sentence.contains("zoomed in") {
        let width = after(sentence, "each sphere ")
            .and_then(|w| number_at(&w, 0))
            .filter(|_| sentence.contains("× as wide)"));
        claims.push(Claim::Zoomed {
            out: sentence.contains("zoomed out"),
            width,
        });
    }
    if let Some(words) = after(sentence, "is drawn ")
        && words.get(1) == Some(&"as")
        && words.get(2) == Some(&"wide")
    {
        claims.push(Claim::Ellipse {
            wide: number_at(&words, 0).unwrap(),
            tall: number_at(&words, 4).unwrap(),
        });
    }
    if sentence.contains("longer along the image's longer side") {
        claims.push(Claim::LongerAlongLonger);
    }
    if sentence.contains("upside down") {
        claims.push(Claim::UpsideDown);
    }
    if sentence.contains("mirrored left to right") {
        claims.push(Claim::MirroredLeftRight);
    }
    if sentence.contains("mirrored across its diagonal from the lower left to the upper right") {
        claims.push(Claim::Transposed);
    }
    if let Some(words) = after(sentence, "one pixel along x moves ") {
        let v = |i| number_at(&words, i).unwrap();
        // "(a, b), along y (c, d) course pixels"
        claims.push(Claim::Axes(DMat2::from_cols(
            DVec2::new(v(0), v(1)),
            DVec2::new(v(4), v(5)),
        )));
    }
    if sentence.contains("near is black and far is white") {
        claims.push(Claim::NearBlackFarWhite);
    }
    if let Some(words) = after(sentence, "where no ray hits, the depth image is ") {
        claims.push(Claim::DepthNoHit(bytes_at(&words, 0).unwrap()));
        if sentence.contains("your scene's background colour") {
            claims.push(Claim::SceneBackground(bytes_at(&words, 0).unwrap()));
        }
    }
    if let Some(words) = after(sentence, "the background is ") {
        let theirs = bytes_at(&words, 0).unwrap();
        let scene_at = words.iter().position(|w| *w == "says").unwrap() + 1;
        claims.push(Claim::Background(
            theirs,
            bytes_at(&words, scene_at).unwrap(),
        ));
    }
    if let Some(words) = after(sentence, "white at t = ") {
        let black_at = words.iter().position(|w| *w == "black").unwrap();
        let black_word = if words[black_at + 2] == "t" {
            black_at + 4
        } else {
            black_at + 2
        };
        claims.push(Claim::Ramp {
            white: number_at(&words, 0).unwrap(),
            black: number_at(&words, black_word).unwrap(),
        });
    }
    if let Some(words) = after(sentence, "the depth ramp runs from t = ") {
        // "a (grey g1) to t = b (grey g2)"
        claims.push(Claim::Extremes {
            near_t: number_at(&words, 0).unwrap(),
            near_grey: number_at(&words, 2).unwrap(),
            far_t: number_at(&words, 6).unwrap(),
            far_grey: number_at(&words, 8).unwrap(),
        });
    }
    if let Some(words) = after(sentence, "t grows by ") {
        let up_at = words.iter().position(|w| *w == "and").unwrap() + 1;
        claims.push(Claim::TRamp {
            right: number_at(&words, 0).unwrap(),
            up: number_at(&words, up_at).unwrap(),
        });
    }
    if sentence.contains("the first sphere in the file that the ray hits is drawn, nearer or not") {
        claims.push(Claim::FileOrder { last: false });
    }
    if sentence.contains("the last one hit wins, nearer or not") {
        claims.push(Claim::FileOrder { last: true });
    }
    if let Some(words) = after(sentence, "only the lower-left ") {
        let (w, h) = words[0].split_once('×').unwrap();
        claims.push(Claim::Block(w.parse().unwrap(), h.parse().unwrap()));
    }
    if let Some(words) = after(sentence, "whose near root lies before t = ") {
        claims.push(Claim::LostBefore(number_at(&words, 0).unwrap()));
    }
    if sentence.contains("near root lies more than 1 behind the camera centre is lost") {
        claims.push(Claim::LostBefore(-1.0));
    }
    if sentence.contains("what lies behind the camera centre is lost") {
        claims.push(Claim::LostBefore(0.0));
    }
    if sentence.contains("some are one level brighter") {
        claims.push(Claim::OneLevelBrighter);
    }
    if sentence.contains("every hit is farther than it should be") {
        claims.push(Claim::Farther);
    }
    if sentence.contains("is striped") {
        claims.push(Claim::Striped);
    }
    if sentence.contains("nearer than DMIN is black") {
        claims.push(Claim::NearerThanMinBlack);
    }
    if sentence.contains("on an exact tie of t the later sphere wins") {
        claims.push(Claim::LaterWinsTie);
    }
    if sentence.contains("height is divided by the length of up across the direction") {
        claims.push(Claim::VerticalByUp);
    }
    if sentence.contains("every t is divided by the direction's length") {
        claims.push(Claim::DividedByDirection);
    }
    if sentence.contains("maps |z| of each hit") {
        claims.push(Claim::MapsAbsZ);
    }
    if let Some(words) = after(sentence, "depth outside the range is drawn ")
        && number_at(&words, 0).is_some()
    {
        claims.push(Claim::OutsideColour(bytes_at(&words, 0).unwrap()));
    }
    if sentence.contains("silhouettes grow") {
        claims.push(Claim::SilhouettesGrow);
    }
    if sentence.contains("the depth is wrong where a sphere is hit") {
        claims.push(Claim::DepthWrongWhereHit);
    }
    claims
}
