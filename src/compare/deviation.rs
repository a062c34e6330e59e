//! The statements of an answer: each way the fitted model of their program differs from the
//! course's, with its fitted values, what it means and what to check in their code. The
//! fifteen known mistakes are statements without values ([`Deviation::Word`]).

use glam::{DMat2, DVec2};

use super::mistake::Mistake;
use super::model::Quantity;

/// One way their program differs from the course's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Deviation {
    /// A known mistake, a named point of the model.
    Word(Mistake),
    /// Each ray starts elsewhere in its pixel: at `offset_px` from the pixel's lower-left
    /// corner (the course's: ½ ½), in the program's own rows.
    SampleOffset {
        /// Where in the pixel, pixels.
        offset_px: DVec2,
    },
    /// A non-square image shows a part of the camera's square that is not its centre: the
    /// sample lies `offset_px` from the pixel's corner, a whole strip away.
    CropNotCentred {
        /// Where the program's pixel (0, 0) samples, in pixels from its corner.
        offset_px: DVec2,
    },
    /// The screen's axes scaled (a zoom when both are the same).
    Scaled {
        /// Factor along x and along y.
        factor: DVec2,
    },
    /// The screen's x taken from the pixel's row and y from its column.
    SwappedAxes {
        /// The axes in course pixel steps (columns: one pixel along x, along y).
        relative: DMat2,
    },
    /// The screen's axes sheared or turned.
    Axes {
        /// The axes in course pixel steps (columns: one pixel along x, along y).
        relative: DMat2,
    },
    /// t grows across the screen: the ray origins slide along the direction.
    Tilt {
        /// t per world unit across the screen (u) and up it (v).
        per_unit: DVec2,
    },
    /// No depth test: spheres in file order, the first (or the last) sphere hit drawn.
    NoDepthTest {
        /// The last sphere hit wins (all are drawn in turn); else the first.
        last_wins: bool,
    },
    /// Only a block of the image is drawn, from its lower-left corner; the rest keeps the
    /// background.
    OnlyBlock {
        /// Columns and rows drawn.
        drawn_px: (u32, u32),
    },
    /// Hits before `tmin` refused, and the far root not tried.
    NearRootOnly {
        /// The tmin.
        tmin: f64,
    },
    /// Several samples per pixel on a grid of the program's own over the screen, the last (or
    /// first) that hits setting the pixel.
    SampleGrid {
        /// Samples along each side of the screen.
        per_side: u32,
        /// The last sample that hits sets the pixel (else the first).
        last_wins: bool,
    },
    /// Hits before `tmin` refused, and the far root taken where the near one is (a tmin other
    /// than the course's −∞, 0 or −1).
    Tmin {
        /// The tmin.
        tmin: f64,
    },
    /// The colour image's background is not the scene's.
    Background {
        /// Their background, bytes.
        bytes: [u8; 3],
        /// The scene's, bytes.
        scene: [u8; 3],
    },
    /// The depth image is drawn over another range than the one asked for.
    DepthRange {
        /// t drawn white.
        white_t: f64,
        /// t drawn black.
        black_t: f64,
        /// The range asked for (white, black).
        given: (f64, f64),
        /// When the range runs from the nearest to the farthest hit in the image: those t
        /// and their greys.
        per_image: Option<PerImage>,
        /// Who chose the range the image was judged under.
        from: RangeFrom,
    },
    /// The depth image maps another quantity than t.
    DepthQuantity {
        /// What it maps.
        quantity: Quantity,
    },
    /// Depth outside the range drawn in a colour.
    DepthOutside {
        /// The colour, bytes.
        bytes: [u8; 3],
    },
    /// Where no ray hits, the depth image is not black.
    DepthNoHit {
        /// Its colour, bytes.
        bytes: [u8; 3],
        /// The scene's background colour, bytes (the clue when they are the same).
        scene_background: [u8; 3],
    },
}

/// Who chose the depth range a depth image was judged under: what a `depth-range` statement may
/// say of it (a range the viewer chose is never blamed on their code).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RangeFrom {
    /// Given with the image (`-compare_depth DMIN DMAX`, a course command line): the range their
    /// program was asked to draw over.
    #[default]
    Given,
    /// Read back from their image: nobody said which range their program was given.
    ReadBack,
    /// The viewer's own depth range.
    Viewer,
}

/// A depth ramp normalised per image: the nearest and farthest hit and their greys.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerImage {
    /// t of the nearest hit.
    pub near_t: f64,
    /// Its grey.
    pub near_grey: f64,
    /// t of the farthest hit.
    pub far_t: f64,
    /// Its grey.
    pub far_grey: f64,
}

/// A number as the answer prints it: at most `decimals` decimals, no trailing zeros.
pub fn number(value: f64, decimals: usize) -> String {
    let text = format!("{value:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    };
    if text == "-0" { "0".to_owned() } else { text }
}

pub(crate) fn bytes(b: [u8; 3]) -> String {
    format!("{} {} {}", b[0], b[1], b[2])
}

pub(crate) fn quantity_name(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::T => "t",
        Quantity::AbsT => "|t|",
        Quantity::Coordinate(0) => "x",
        Quantity::Coordinate(1) => "y",
        Quantity::Coordinate(_) => "z",
        Quantity::AbsCoordinate(0) => "|x|",
        Quantity::AbsCoordinate(1) => "|y|",
        Quantity::AbsCoordinate(_) => "|z|",
    }
}

impl Deviation {
    /// The statement's name: a known mistake's word, or the name of the part of the model.
    pub fn word(&self) -> &'static str {
        match self {
            Self::Word(mistake) => mistake.word(),
            Self::SampleOffset { .. } => "sample-offset",
            Self::CropNotCentred { .. } => "crop-not-centred",
            Self::Scaled { factor } if factor.x == factor.y => "zoom",
            Self::Scaled { .. } => "axes-scaled",
            Self::SwappedAxes { .. } => "swapped-axes",
            Self::Axes { .. } => "axes",
            Self::Tilt { .. } => "t-ramp",
            Self::NoDepthTest { .. } => "no-depth-test",
            Self::OnlyBlock { .. } => "only-block",
            Self::NearRootOnly { .. } => "near-root-only",
            Self::Tmin { .. } => "tmin",
            Self::SampleGrid { .. } => "sample-grid",
            Self::Background { .. } => "background",
            Self::DepthRange {
                per_image: Some(_), ..
            } => "depth-per-image",
            Self::DepthRange { .. } => "depth-range",
            Self::DepthQuantity { .. } => "depth-quantity",
            Self::DepthOutside { .. } => "depth-outside",
            Self::DepthNoHit { .. } => "depth-no-hit",
        }
    }

    /// The part of the model the statement is about, whatever its values (`scaled` for a zoom
    /// and for axes scaled apart).
    pub fn kind(&self) -> &'static str {
        match self {
            Self::Scaled { .. } => "scaled",
            Self::DepthRange { .. } => "depth-range",
            other => other.word(),
        }
    }

    /// How many numbers the statement fits (a known mistake counts one): what it claims.
    pub fn numbers_fitted(&self) -> usize {
        match self {
            Self::Scaled { factor } if factor.x == factor.y => 1,
            // A whole matrix: four numbers, and the least likely of programs.
            Self::SwappedAxes { .. } | Self::Axes { .. } => 5,
            Self::SampleOffset { .. }
            | Self::CropNotCentred { .. }
            | Self::Scaled { .. }
            | Self::Tilt { .. }
            | Self::OnlyBlock { .. }
            | Self::SampleGrid { .. }
            | Self::DepthRange { .. } => 2,
            Self::Background { .. } | Self::DepthOutside { .. } | Self::DepthNoHit { .. } => 3,
            _ => 1,
        }
    }

    /// Whether it is about where rays start, a known mistake or a fitted value.
    pub fn is_about_geometry(&self) -> bool {
        self.is_geometric()
            || matches!(
                self,
                Self::SampleGrid { .. }
                    | Self::Word(
                        Mistake::PixelCorners
                            | Mistake::Stretched
                            | Mistake::FlippedVertically
                            | Mistake::Mirrored
                            | Mistake::RawUp
                    )
            )
    }

    /// Whether it is about where rays start (not a known mistake).
    pub fn is_geometric(&self) -> bool {
        matches!(
            self,
            Self::OnlyBlock { .. }
                | Self::SampleOffset { .. }
                | Self::CropNotCentred { .. }
                | Self::Scaled { .. }
                | Self::SwappedAxes { .. }
                | Self::Axes { .. }
                | Self::Tilt { .. }
        )
    }

    /// Whether it is about how the depth image is drawn from the hits.
    pub fn is_about_depth(&self) -> bool {
        matches!(
            self,
            Self::Word(
                Mistake::DepthReversed
                    | Mistake::DepthNoClamp
                    | Mistake::DepthOutsideBlack
                    | Mistake::UnnormalizedDirection
            ) | Self::DepthRange { .. }
                | Self::DepthQuantity { .. }
                | Self::DepthOutside { .. }
                | Self::DepthNoHit { .. }
                | Self::Tilt { .. }
        )
    }

    /// The fitted values, as printed after the word (empty for a known mistake).
    pub fn values(&self) -> String {
        let matrix = |m: &DMat2| {
            let a = m.to_cols_array();
            format!(
                "{} {} {} {}",
                number(a[0], 3),
                number(a[2], 3),
                number(a[1], 3),
                number(a[3], 3)
            )
        };
        match self {
            Self::Word(_) => String::new(),
            Self::SampleOffset { offset_px } | Self::CropNotCentred { offset_px } => {
                format!("{} {}", number(offset_px.x, 3), number(offset_px.y, 3))
            }
            Self::Scaled { factor } if factor.x == factor.y => number(factor.x, 4),
            Self::Scaled { factor } => format!("{} {}", number(factor.x, 4), number(factor.y, 4)),
            Self::SwappedAxes { relative } | Self::Axes { relative } => matrix(relative),
            Self::Tilt { per_unit } => {
                format!("{} {}", number(per_unit.x, 4), number(per_unit.y, 4))
            }
            Self::NoDepthTest { last_wins } => {
                (if *last_wins { "last" } else { "first" }).to_owned()
            }
            Self::NearRootOnly { tmin } | Self::Tmin { tmin } => number(*tmin, 6),
            Self::SampleGrid {
                per_side,
                last_wins,
            } => format!("{per_side} {}", if *last_wins { "last" } else { "first" }),
            Self::OnlyBlock { drawn_px } => format!("{} {}", drawn_px.0, drawn_px.1),
            Self::Background { bytes: b, .. }
            | Self::DepthOutside { bytes: b }
            | Self::DepthNoHit { bytes: b, .. } => bytes(*b),
            Self::DepthRange {
                white_t, black_t, ..
            } => format!("{} {}", number(*white_t, 4), number(*black_t, 4)),
            Self::DepthQuantity { quantity } => quantity_name(*quantity).to_owned(),
        }
    }

    /// The statement as JSON: its name, whether it is a known mistake, its values (numbers,
    /// or the quantity's name), and the sentence (docs/compare-json.md).
    pub fn to_json(&self) -> serde_json::Value {
        let pair = |v: DVec2| vec![v.x.into(), v.y.into()];
        let matrix = |m: &DMat2| {
            vec![
                m.x_axis.x.into(),
                m.y_axis.x.into(),
                m.x_axis.y.into(),
                m.y_axis.y.into(),
            ]
        };
        let bytes = |b: &[u8; 3]| b.iter().map(|&v| u64::from(v).into()).collect();
        let values: Vec<serde_json::Value> = match self {
            Self::Word(_) => Vec::new(),
            Self::SampleOffset { offset_px } | Self::CropNotCentred { offset_px } => {
                pair(*offset_px)
            }
            Self::Scaled { factor } if factor.x == factor.y => vec![factor.x.into()],
            Self::Scaled { factor } => pair(*factor),
            Self::SwappedAxes { relative } | Self::Axes { relative } => matrix(relative),
            Self::Tilt { per_unit } => pair(*per_unit),
            Self::NoDepthTest { last_wins } => {
                vec![(if *last_wins { "last" } else { "first" }).into()]
            }
            Self::NearRootOnly { tmin } | Self::Tmin { tmin } => vec![(*tmin).into()],
            Self::SampleGrid {
                per_side,
                last_wins,
            } => vec![
                (*per_side).into(),
                (if *last_wins { "last" } else { "first" }).into(),
            ],
            Self::OnlyBlock { drawn_px } => vec![drawn_px.0.into(), drawn_px.1.into()],
            Self::Background { bytes: b, .. }
            | Self::DepthOutside { bytes: b }
            | Self::DepthNoHit { bytes: b, .. } => bytes(b),
            Self::DepthRange {
                white_t, black_t, ..
            } => vec![(*white_t).into(), (*black_t).into()],
            Self::DepthQuantity { quantity } => vec![quantity_name(*quantity).into()],
        };
        serde_json::json!({
            "name": self.word(),
            "known_mistake": matches!(self, Self::Word(_)),
            "values": values,
            "text": self.explanation(),
        })
    }

    /// The statement as the command line prints it after `diagnosis: `: its name, values and
    /// what it means (`zoom 1.118: each pixel steps …`).
    pub fn said(&self) -> String {
        format!("{}: {}", self.name_and_values(), self.explanation())
    }

    /// The word and its values, as one token list (`zoom 1.118`).
    pub fn name_and_values(&self) -> String {
        let values = self.values();
        if values.is_empty() {
            self.word().to_owned()
        } else {
            format!("{} {values}", self.word())
        }
    }

    /// The statement with the depth range it speaks of said as chosen by `from`.
    #[must_use]
    pub fn with_range_from(self, from: RangeFrom) -> Self {
        match self {
            Self::DepthRange {
                white_t,
                black_t,
                given,
                per_image,
                ..
            } => Self::DepthRange {
                white_t,
                black_t,
                given,
                per_image,
                from,
            },
            other => other,
        }
    }
}
