//! The known mistakes of a first ray caster for this assignment, each a word the diagnosis prints,
//! and sets of them (a program can have several).

use std::fmt;

/// One known mistake. [`Mistake::word`] is what the command line prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Mistake {
    /// Rays through pixel corners `x/W` instead of centres `(x+½)/W`: a half-pixel shift.
    PixelCorners,
    /// `t = w − (r² − d²)` instead of `w − √(r² − d²)`: depth wrong where spheres are hit.
    NoSquareRoot,
    /// `tmin = 0`: what lies behind the camera centre is lost (or seen from inside).
    TminZero,
    /// `tmin = −1`, a finite negative tmin (as from `-FP_INFINITE`, which is the constant 1, not
    /// minus infinity): a sphere whose near root lies more than one unit behind the camera centre
    /// is lost (its other root is not tried).
    TminMinusOne,
    /// The larger root: the back of each sphere is seen.
    FarRoot,
    /// A non-square image stretched over the whole square screen instead of cropping it.
    Stretched,
    /// Rows written top row first while the file says bottom row first: upside down.
    FlippedVertically,
    /// Near black and far white.
    DepthReversed,
    /// Depth outside the range wraps around (`(v·255) mod 256`) instead of clamping.
    DepthNoClamp,
    /// Depth outside the range drawn black instead of clamped: what is nearer than DMIN is black,
    /// not white.
    DepthOutsideBlack,
    /// 8-bit values rounded instead of truncated.
    Rounded,
    /// On an exact tie of t the later object wins instead of the earlier.
    LastWins,
    /// The horizontal axis `up × direction` instead of `direction × up`: mirrored left to right.
    Mirrored,
    /// The camera's `up` used as the screen's vertical as written, neither made perpendicular to
    /// the direction nor unit length: the picture is sheared or stretched.
    RawUp,
    /// t measured along the direction as written, not along the unit direction: depth scaled by
    /// 1/|direction|.
    UnnormalizedDirection,
}

impl Mistake {
    /// Every mistake, in the order the diagnosis prints them.
    pub const ALL: [Self; 15] = [
        Self::PixelCorners,
        Self::NoSquareRoot,
        Self::TminZero,
        Self::TminMinusOne,
        Self::FarRoot,
        Self::Stretched,
        Self::FlippedVertically,
        Self::DepthReversed,
        Self::DepthNoClamp,
        Self::DepthOutsideBlack,
        Self::Rounded,
        Self::LastWins,
        Self::Mirrored,
        Self::RawUp,
        Self::UnnormalizedDirection,
    ];

    /// The word the diagnosis prints.
    pub fn word(self) -> &'static str {
        match self {
            Self::PixelCorners => "pixel-corners",
            Self::NoSquareRoot => "no-square-root",
            Self::TminZero => "tmin-zero",
            Self::TminMinusOne => "tmin-minus-one",
            Self::FarRoot => "far-root",
            Self::Stretched => "stretched",
            Self::FlippedVertically => "flipped-vertically",
            Self::DepthReversed => "depth-reversed",
            Self::DepthNoClamp => "depth-no-clamp",
            Self::DepthOutsideBlack => "depth-outside-black",
            Self::Rounded => "rounded",
            Self::LastWins => "last-wins",
            Self::Mirrored => "mirrored",
            Self::RawUp => "raw-up",
            Self::UnnormalizedDirection => "unnormalized-direction",
        }
    }

    /// The mistake named `word`.
    pub fn from_word(word: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|mistake| mistake.word() == word)
    }

    /// What the mistake is, in one line.
    pub fn description(self) -> &'static str {
        match self {
            Self::PixelCorners => "rays through pixel corners x/W instead of centres (x+½)/W",
            Self::NoSquareRoot => "t = w − (r² − d²) instead of w − √(r² − d²)",
            Self::TminZero => "tmin 0 instead of −∞: spheres behind the camera centre are lost",
            Self::TminMinusOne => {
                "tmin −1 instead of −∞: spheres more than 1 behind the camera centre are lost"
            }
            Self::FarRoot => "the larger root: the back of each sphere is seen",
            Self::Stretched => "a non-square image stretched instead of cropped",
            Self::FlippedVertically => "rows written top-down without saying so in the file",
            Self::DepthReversed => "near black, far white",
            Self::DepthNoClamp => "depth outside the range wraps instead of clamping",
            Self::DepthOutsideBlack => {
                "depth outside the range drawn black instead of clamped (nearer than DMIN too)"
            }
            Self::Rounded => "8-bit values rounded instead of truncated",
            Self::LastWins => "on equal t the later object wins",
            Self::Mirrored => "horizontal = up × direction: mirrored left to right",
            Self::RawUp => {
                "up used as the screen's vertical without making it perpendicular and unit"
            }
            Self::UnnormalizedDirection => {
                "t measured along the direction as written, not the unit one"
            }
        }
    }

    /// What the mistake means and what to look for in the code, in one sentence.
    pub fn advice(self) -> &'static str {
        match self {
            Self::PixelCorners => {
                "rays pass through pixel corners x/W instead of centres (x + ½)/W, so the \
                 picture is shifted half a pixel right and up: add ½ to x and y before \
                 dividing, in the point you give generateRay"
            }
            Self::NoSquareRoot => {
                "t = w − (r² − d²) instead of w − √(r² − d²), so the depth is wrong where a \
                 sphere is hit (and where spheres overlap, the nearer may lose): take the \
                 square root of the discriminant in Sphere::intersect"
            }
            Self::TminZero => {
                "tmin is 0 instead of −∞, so what lies behind the camera centre is lost, and a \
                 sphere around it is seen from inside (its far root): the orthographic camera's \
                 tmin is −∞ (-INFINITY), give that to Group::intersect"
            }
            Self::TminMinusOne => {
                "tmin is −1 (as -FP_INFINITE gives, the constant 1 negated) instead of −∞, so a \
                 sphere whose near root lies more than 1 behind the camera centre is lost: give \
                 -INFINITY (or -FLT_MAX) as the orthographic camera's tmin"
            }
            Self::FarRoot => {
                "the larger root is taken, so the back of each sphere is seen and every hit is \
                 farther than it should be: in Sphere::intersect keep the smaller root, \
                 t = −b − √disc"
            }
            Self::Stretched => {
                "a non-square image is stretched over the whole square screen instead of \
                 cropped from its middle, so spheres are drawn as ellipses, longer along the \
                 image's longer side: in generateRay use one pixel size, size/max(W, H), for \
                 both axes"
            }
            Self::FlippedVertically => {
                "the picture is upside down: rows are written top row first while the file \
                 says bottom row first (or the screen's up is reversed): SetPixel(x, y) with \
                 y = 0 the bottom row, and up = horizontal × direction"
            }
            Self::DepthReversed => {
                "near is black and far is white: the grey is (t − DMIN)/(DMAX − DMIN) instead \
                 of (DMAX − t)/(DMAX − DMIN); swap them in the depth formula"
            }
            Self::DepthNoClamp => {
                "depth outside the range wraps around ((v·255) mod 256) instead of clamping, so \
                 what lies beyond DMIN or DMAX is striped: clamp v to 0 … 1 in the depth \
                 formula before making a byte"
            }
            Self::DepthOutsideBlack => {
                "depth outside the range is drawn black instead of clamped, so what is nearer \
                 than DMIN is black where it should be white: clamp v to 0 … 1 in the depth \
                 formula instead of skipping it"
            }
            Self::Rounded => {
                "8-bit values are rounded instead of truncated, so some are one level brighter: \
                 the course writes (int)(v·255), without adding ½"
            }
            Self::LastWins => {
                "on an exact tie of t the later sphere wins instead of the earlier: in the \
                 group's loop replace the hit only when t is strictly smaller"
            }
            Self::Mirrored => {
                "the picture is mirrored left to right: the horizontal is up × direction \
                 instead of direction × up; swap the cross product's operands in the camera"
            }
            Self::RawUp => {
                "the camera's up is used as the screen's vertical as written, neither made \
                 perpendicular to the direction nor unit, so the picture's height is divided by \
                 the length of up across the direction (and, where up leans along the \
                 direction, depth ramps up the image): in the camera take horizontal = \
                 normalize(direction × up), then up = horizontal × direction"
            }
            Self::UnnormalizedDirection => {
                "t is measured along the direction as written, not the unit direction (or the \
                 depth range is scaled the same way), so every t is divided by the direction's \
                 length: normalise the direction in the camera's constructor"
            }
        }
    }

    /// Whether the mistake changes which sphere a pixel sees or its t (the rest change only how
    /// hits become bytes).
    pub fn changes_hits(self) -> bool {
        matches!(
            self,
            Self::PixelCorners
                | Self::NoSquareRoot
                | Self::TminZero
                | Self::TminMinusOne
                | Self::FarRoot
                | Self::Stretched
                | Self::FlippedVertically
                | Self::LastWins
                | Self::Mirrored
                | Self::RawUp
        )
    }

    fn bit(self) -> u16 {
        1 << (self as u16)
    }
}

impl fmt::Display for Mistake {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.word())
    }
}

/// A set of mistakes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct MistakeSet(u16);

impl MistakeSet {
    /// No mistake: the exact picture.
    pub const NONE: Self = Self(0);

    /// The set of `mistakes`.
    pub fn of(mistakes: &[Mistake]) -> Self {
        Self(mistakes.iter().fold(0, |bits, m| bits | m.bit()))
    }

    /// Whether `mistake` is in the set.
    pub fn contains(self, mistake: Mistake) -> bool {
        self.0 & mistake.bit() != 0
    }

    /// The set with `mistake` added.
    #[must_use]
    pub fn with(self, mistake: Mistake) -> Self {
        Self(self.0 | mistake.bit())
    }

    /// The set without `mistake`.
    #[must_use]
    pub fn without(self, mistake: Mistake) -> Self {
        Self(self.0 & !mistake.bit())
    }

    /// How many mistakes the set holds.
    pub fn len(self) -> usize {
        self.0.count_ones() as usize
    }

    /// Whether one program can make all the set's mistakes: a program has one tmin
    /// (`tmin-zero`, `tmin-minus-one`) and one rule for depth outside the range
    /// (`depth-no-clamp`, `depth-outside-black`).
    pub fn is_possible(self) -> bool {
        const ONE_OF: [[Mistake; 2]; 2] = [
            [Mistake::TminZero, Mistake::TminMinusOne],
            [Mistake::DepthNoClamp, Mistake::DepthOutsideBlack],
        ];
        !ONE_OF
            .iter()
            .any(|&[first, second]| self.contains(first) && self.contains(second))
    }

    /// Whether every mistake of `other` is in the set.
    pub fn includes(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether the set is empty.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The mistakes in the set, in [`Mistake::ALL`] order.
    pub fn mistakes(self) -> Vec<Mistake> {
        Mistake::ALL
            .into_iter()
            .filter(|m| self.contains(*m))
            .collect()
    }

    /// The part of the set that changes hits ([`Mistake::changes_hits`]).
    pub fn hit_part(self) -> Self {
        Self::of(
            &self
                .mistakes()
                .into_iter()
                .filter(|m| m.changes_hits())
                .collect::<Vec<_>>(),
        )
    }
}

impl fmt::Display for MistakeSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_empty() {
            return f.write_str("none");
        }
        let words: Vec<&str> = self.mistakes().into_iter().map(Mistake::word).collect();
        f.write_str(&words.join(" + "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_word_is_distinct_and_reads_back() {
        for mistake in Mistake::ALL {
            assert_eq!(Mistake::from_word(mistake.word()), Some(mistake));
        }
        let set = MistakeSet::of(&Mistake::ALL);
        assert_eq!(set.len(), Mistake::ALL.len());
        assert_eq!(set.mistakes(), Mistake::ALL.to_vec());
    }
}
