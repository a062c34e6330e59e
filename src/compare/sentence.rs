//! What a statement says in words: [`Deviation::explanation`], the one sentence the lines, the
//! JSON, the viewer and the grader's report give after a statement's name and values — what their
//! picture shows (which way it moves and how far, how wide a sphere is drawn, upside down or
//! mirrored, what colour where nothing is hit) and what to change in their code, in the course's
//! terms (`generateRay`, the camera's horizontal and up, `SetPixel`, the depth formula).
//! `tests/statements.rs` reads each claim back from the words and measures it on a picture.

use glam::{DMat2, DVec2};

use super::deviation::{Deviation, RangeFrom, bytes, number, quantity_name};

impl Deviation {
    /// What it means and what to check in their code, in one sentence: the one text the lines,
    /// the JSON, the viewer and the grader's report give (`tests/statements.rs` measures each
    /// claim it makes on pictures).
    pub fn explanation(&self) -> String {
        match self {
            Self::Word(mistake) => mistake.advice().to_owned(),
            Self::SampleOffset { offset_px } if offset_px.abs().max_element() <= 1.5 => format!(
                "each ray starts at ({}, {}) within its pixel instead of the centre (½, ½), so \
                 the picture is shifted {}: give generateRay the pixel's centre, ((x + ½)/W, \
                 (y + ½)/H) for a square image",
                number(offset_px.x, 3),
                number(offset_px.y, 3),
                shift_words(*offset_px)
            ),
            Self::SampleOffset { offset_px } => format!(
                "pixel (0, 0) samples the screen at ({}, {}) of its own pixels instead of \
                 (½, ½), so the picture is shifted {} and its centre is not the screen's: \
                 check how x and y are centred (x + ½ − W/2, y + ½ − H/2)",
                number(offset_px.x, 3),
                number(offset_px.y, 3),
                shift_words(*offset_px)
            ),
            Self::CropNotCentred { offset_px } => format!(
                "the image shows a strip of the camera's square that is not its middle (pixel \
                 (0, 0) samples at ({}, {}) pixels), so the picture is shifted {}: measure a \
                 non-square image's rows and columns from the centre, with one pixel size, \
                 size/max(W, H)",
                number(offset_px.x, 3),
                number(offset_px.y, 3),
                shift_words(*offset_px)
            ),
            Self::Scaled { factor } if factor.x == factor.y => format!(
                "each pixel steps {}× the course's pixel size, so the picture is the right one \
                 zoomed {} about its centre (each sphere {}× as wide): are the horizontal and \
                 up vectors unit length, and is the pixel size size/max(W, H)?",
                number(factor.x, 4),
                if factor.x > 1.0 { "out" } else { "in" },
                number(1.0 / factor.x, 3)
            ),
            Self::Scaled { factor } => format!(
                "each pixel steps {}× the course's pixel size across and {}× up, so each sphere \
                 is drawn {}× as wide and {}× as tall (an ellipse): are the horizontal and up \
                 vectors unit length, and is one pixel size, size/max(W, H), used for both axes?",
                number(factor.x, 4),
                number(factor.y, 4),
                number(1.0 / factor.x, 3),
                number(1.0 / factor.y, 3)
            ),
            Self::SwappedAxes { relative } => format!(
                "x and y are swapped in the sampling: the column decides the screen's v and the \
                 row its u, so the picture is {}: check the loops, and which of x and y goes \
                 with W and with H in the point given to generateRay",
                swapped_picture(relative)
            ),
            Self::Axes { relative } => format!(
                "the screen's axes are sheared or turned (one pixel along x moves ({}, {}), \
                 along y ({}, {}) course pixels): is the up vector made perpendicular to the \
                 direction before the horizontal is taken?",
                number(relative.x_axis.x, 3),
                number(relative.x_axis.y, 3),
                number(relative.y_axis.x, 3),
                number(relative.y_axis.y, 3)
            ),
            Self::Tilt { per_unit } => format!(
                "t grows by {} per unit of the screen to the right and {} per unit up: the ray \
                 origins slide along the direction, so the horizontal or up vector is not \
                 perpendicular to it: take up = horizontal × direction with horizontal = \
                 normalize(direction × up)",
                number(per_unit.x, 4),
                number(per_unit.y, 4)
            ),
            Self::NoDepthTest { last_wins: true } => "the spheres are drawn in file order and \
                 the last one hit wins, nearer or not: in Group::intersect replace the hit only \
                 when the new t is smaller"
                .to_owned(),
            Self::NoDepthTest { last_wins: false } => "the first sphere in the file that the \
                 ray hits is drawn, nearer or not: in Group::intersect test every sphere and \
                 keep the smallest t"
                .to_owned(),
            Self::OnlyBlock { drawn_px } => format!(
                "only the lower-left {}×{} pixels are drawn and the rest keeps the background: \
                 the pixel loops run to min(W, H), or with W and H swapped",
                drawn_px.0, drawn_px.1
            ),
            Self::NearRootOnly { tmin } => format!(
                "hits before t = {} are refused and the far root is not tried, so a sphere \
                 whose near root lies before t = {} vanishes: the orthographic camera's tmin is \
                 −∞ (-INFINITY)",
                number(*tmin, 6),
                number(*tmin, 6)
            ),
            Self::SampleGrid {
                per_side,
                last_wins,
            } => format!(
                "each pixel is set from a {per_side}×{per_side} grid of samples over the screen, \
                 the {} of its samples that hits a sphere deciding it, so silhouettes grow by up \
                 to a pixel: trace one ray through each pixel's centre (or average its samples)",
                if *last_wins { "last" } else { "first" }
            ),
            Self::Tmin { tmin } => format!(
                "hits before t = {} are refused and the far root is taken there, so a sphere \
                 whose near root lies before t = {} is seen from inside (its back), or lost: \
                 the orthographic camera's tmin is −∞ (-INFINITY)",
                number(*tmin, 6),
                number(*tmin, 6)
            ),
            Self::Background { bytes: b, scene } => {
                if *b == [0; 3] {
                    format!(
                        "the background is black where the scene says {}: the image starts \
                         black and the background colour is never used; fill the image with \
                         the scene's background colour before tracing",
                        bytes(*scene)
                    )
                } else {
                    format!(
                        "the background is {} where the scene says {}: fill the image with the \
                         background colour the scene file gives (its Background block)",
                        bytes(*b),
                        bytes(*scene)
                    )
                }
            }
            Self::DepthRange {
                white_t,
                black_t,
                given,
                per_image: Some(p),
                from,
            } => format!(
                "the depth ramp runs from t = {} (grey {}) to t = {} (grey {}), the nearest and \
                 farthest hits in this image, white at t = {} and black at {}: you normalise \
                 per image {}",
                number(p.near_t, 4),
                number(p.near_grey, 0),
                number(p.far_t, 4),
                number(p.far_grey, 0),
                number(*white_t, 4),
                number(*black_t, 4),
                match from {
                    RangeFrom::Given => format!(
                        "and -depth {} {} is ignored: use DMIN and DMAX in the depth formula",
                        number(given.0, 4),
                        number(given.1, 4)
                    ),
                    RangeFrom::ReadBack | RangeFrom::Viewer => {
                        "instead of using DMIN and DMAX in the depth formula".to_owned()
                    }
                }
            ),
            Self::DepthRange {
                white_t,
                black_t,
                given,
                per_image: None,
                from,
            } => {
                let drawn = format!(
                    "the depth image is drawn with white at t = {} and black at t = {}",
                    number(*white_t, 4),
                    number(*black_t, 4)
                );
                match from {
                    RangeFrom::Given => format!(
                        "{drawn}, not over -depth {} {}: check how DMIN and DMAX are read and \
                         used in the depth formula",
                        number(given.0, 4),
                        number(given.1, 4)
                    ),
                    RangeFrom::ReadBack => format!(
                        "{drawn}: if your program was given other values of DMIN and DMAX, \
                         check how they are read and used in the depth formula"
                    ),
                    RangeFrom::Viewer => format!(
                        "{drawn}, not over the viewer's depth range {} … {}: set the depth \
                         range to theirs to judge it under its own",
                        number(given.0, 4),
                        number(given.1, 4)
                    ),
                }
            }
            Self::DepthQuantity { quantity } => format!(
                "the depth image maps {} of each hit, not its t along the ray: put the hit's t \
                 in the depth formula",
                quantity_name(*quantity)
            ),
            Self::DepthOutside { bytes: b } => format!(
                "depth outside the range is drawn {} instead of clamped to white or black: \
                 clamp v to 0 … 1 in the depth formula",
                bytes(*b)
            ),
            Self::DepthNoHit {
                bytes: b,
                scene_background,
            } if b == scene_background => format!(
                "where no ray hits, the depth image is {}, your scene's background colour, \
                 instead of black: the depth image starts filled with the background; fill it \
                 black (0 0 0) instead",
                bytes(*b)
            ),
            Self::DepthNoHit { bytes: b, .. } => format!(
                "where no ray hits, the depth image is {} instead of black: write 0 0 0 to the \
                 depth image where no ray hits",
                bytes(*b)
            ),
        }
    }
}

/// How the picture moves when each ray starts at `offset_px` in its pixel instead of its centre:
/// a feature the exact picture draws at pixel x is drawn at x + ½ − offset (`0.3 px right and
/// 0.2 px up`; an axis that does not move is left out).
fn shift_words(offset_px: DVec2) -> String {
    let moved = DVec2::splat(0.5) - offset_px;
    let along = |amount: f64, positive: &str, negative: &str| {
        let shown = number(amount.abs(), 3);
        (shown != "0").then(|| {
            let unit = if shown == "1" { "pixel" } else { "pixels" };
            format!(
                "{shown} {unit} {}",
                if amount > 0.0 { positive } else { negative }
            )
        })
    };
    let parts: Vec<String> = [
        along(moved.x, "right", "left"),
        along(moved.y, "up", "down"),
    ]
    .into_iter()
    .flatten()
    .collect();
    if parts.is_empty() {
        "by less than a thousandth of a pixel".to_owned()
    } else {
        parts.join(" and ")
    }
}

/// What a swapped sampling does to the picture, by the signs of the swapped axes.
fn swapped_picture(relative: &DMat2) -> &'static str {
    match (relative.y_axis.x > 0.0, relative.x_axis.y > 0.0) {
        (true, true) => "mirrored across its diagonal from the lower left to the upper right",
        (false, false) => "mirrored across its diagonal from the upper left to the lower right",
        _ => "turned a quarter",
    }
}
