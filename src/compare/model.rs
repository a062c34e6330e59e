//! A model of a student's ray caster: the parameters in which real programs of the assignment
//! differ from the course's, each with the course's value as one point. The diagnosis fits a
//! model to their images (the `fit` module) and says how it differs from the course's (the
//! `deviation` module); the fifteen words of [`super::mistake`] are named points of it
//! ([`Model::of_mistakes`]).
//!
//! Spaces: a pixel is `(x, y_up)`, column from the left and row from the bottom, as integers;
//! the screen is the camera's true frame, `(u, v)` in world units from the camera centre along
//! the unit horizontal `direction × up` and the unit screen up; t is along the unit direction.

use glam::{DMat2, DVec2, DVec3, Vec3};

use super::mistake::{Mistake, MistakeSet};
use crate::render::View;
use crate::render::depth_map::DepthRange;

/// Where each pixel's ray starts: the screen point of pixel `(x, y_up)` is
/// `axes_world · (x, y_up) + origin_world` (the columns of `axes_world` are one pixel's step
/// along x and along y_up, in world units on the screen).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelMap {
    /// One pixel's step along x (first column) and along y_up (second column), world units.
    pub axes_world: DMat2,
    /// Screen point of pixel (0, 0), world units.
    pub origin_world: DVec2,
}

impl PixelMap {
    /// The course's map: rays through pixel centres, a square screen `size` wide over the
    /// image's longer side, a non-square image a centred crop of it.
    pub fn course(width_px: u32, height_px: u32, size_world: f64) -> Self {
        let step = course_step(width_px, height_px, size_world);
        Self::of_relative(
            DMat2::IDENTITY,
            DVec2::splat(0.5),
            width_px,
            height_px,
            step,
        )
    }

    /// The map whose axes are `relative` times the course's pixel step, sampling each pixel at
    /// `offset_px` from its lower-left corner in its own axes (centre ½ ½, corner 0 0), about the
    /// image's centre.
    pub fn of_relative(
        relative: DMat2,
        offset_px: DVec2,
        width_px: u32,
        height_px: u32,
        step_world: f64,
    ) -> Self {
        let axes_world = relative * step_world;
        let half = DVec2::new(f64::from(width_px), f64::from(height_px)) * 0.5;
        Self {
            axes_world,
            origin_world: axes_world * (offset_px - half),
        }
    }

    /// The screen point of pixel point `(x, y_up)`.
    pub fn screen_of(&self, pixel: DVec2) -> DVec2 {
        self.axes_world * pixel + self.origin_world
    }

    /// The axes in units of the course's pixel step (the identity for the course).
    pub fn relative_axes(&self, step_world: f64) -> DMat2 {
        self.axes_world * (1.0 / step_world)
    }

    /// Where in its pixel each ray starts, in the map's own axes from the pixel's lower-left
    /// corner, taking the image's centre as the screen's (`None` when the axes are degenerate).
    pub fn sample_offset_px(&self, width_px: u32, height_px: u32) -> Option<DVec2> {
        let determinant = self.axes_world.determinant();
        if !determinant.is_finite() || determinant == 0.0 {
            return None;
        }
        let half = DVec2::new(f64::from(width_px), f64::from(height_px)) * 0.5;
        Some(self.axes_world.inverse() * self.origin_world + half)
    }
}

/// The course's pixel step: `size / max(W, H)` world units.
pub fn course_step(width_px: u32, height_px: u32, size_world: f64) -> f64 {
    size_world / f64::from(width_px.max(height_px).max(1))
}

/// Which of the spheres a ray hits is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Visible {
    /// The nearest hit (the course's).
    Nearest,
    /// No depth test: the first sphere in file order that is hit.
    FirstInFile,
    /// No depth test: every hit drawn in file order, so the last sphere hit wins.
    LastInFile,
}

/// How one ray meets the spheres: which roots count and which hit is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HitRule {
    /// Which hit is drawn.
    pub visible: Visible,
    /// With [`Visible::Nearest`]: on an exact tie of t the later sphere wins.
    pub later_wins_ties: bool,
    /// Hits below this t are refused (the course's: −∞).
    pub tmin: f64,
    /// When the near root is refused, the far one is tried (as `t > tmin` loops do).
    pub far_when_near_refused: bool,
    /// Only the far root is taken.
    pub far_only: bool,
    /// The half chord is `√(r² − d²)` (false: `r² − d²`, the root forgotten).
    pub square_root: bool,
}

impl HitRule {
    /// The course's rule.
    pub const COURSE: Self = Self {
        visible: Visible::Nearest,
        later_wins_ties: false,
        tmin: f64::NEG_INFINITY,
        far_when_near_refused: true,
        far_only: false,
        square_root: true,
    };

    /// The t this rule takes of a sphere whose centre is `w` along the ray and `across_sq`
    /// (squared) from it, radius `radius`, with `shift` added to both roots (the ray's origin
    /// moved along the direction); `None` when it takes none.
    pub fn sphere_t(&self, w: f64, across_sq: f64, radius: f64, shift: f64) -> Option<f64> {
        let inside = radius * radius - across_sq;
        if inside.is_nan() || inside < 0.0 {
            return None;
        }
        let half_chord = if self.square_root {
            inside.sqrt()
        } else {
            inside
        };
        let (near, far) = (w - half_chord + shift, w + half_chord + shift);
        if self.far_only {
            return (far >= self.tmin).then_some(far);
        }
        if near >= self.tmin {
            Some(near)
        } else if self.far_when_near_refused && far >= self.tmin {
            Some(far)
        } else {
            None
        }
    }

    /// Whether a hit at `t` of a later sphere replaces the hit `best_t` drawn so far.
    pub fn replaces(&self, t: f64, best_t: f64, have_best: bool) -> bool {
        match self.visible {
            Visible::Nearest => t < best_t || (self.later_wins_ties && t == best_t),
            Visible::FirstInFile => !have_best,
            Visible::LastInFile => true,
        }
    }
}

/// What the depth image shows of a hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    /// t along the unit direction (the course's).
    T,
    /// |t|.
    AbsT,
    /// One world coordinate of the hit point (0 x, 1 y, 2 z).
    Coordinate(u8),
    /// The absolute value of one world coordinate of the hit point.
    AbsCoordinate(u8),
}

/// What a depth value outside the range is drawn as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Outside {
    /// Clamped to white or black (the course's).
    Clamp,
    /// Wrapped modulo 256.
    Wrap,
    /// Black.
    Black,
    /// A colour (as bytes), e.g. the scene's background.
    Colour([u8; 3]),
}

/// How the depth image is drawn from the hits: `value = white_at + per_unit · quantity`, 1 white
/// and 0 black, then made bytes as the colour is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DepthMap {
    /// What is mapped.
    pub quantity: Quantity,
    /// Value where the quantity is 0.
    pub at_zero: f64,
    /// Change of value per unit of the quantity (negative: near is white).
    pub per_unit: f64,
    /// Values outside 0 … 1.
    pub outside: Outside,
    /// The colour where no ray hits (the course's: black).
    pub no_hit: [u8; 3],
}

impl DepthMap {
    /// The course's map over `range`: t = min white … max black, clamped, no hit black.
    pub fn of_range(range: DepthRange) -> Self {
        let width = range.max_t - range.min_t;
        let (at_zero, per_unit) = if width == 0.0 {
            (f64::NAN, f64::NAN)
        } else {
            (range.max_t / width, -1.0 / width)
        };
        Self {
            quantity: Quantity::T,
            at_zero,
            per_unit,
            outside: Outside::Clamp,
            no_hit: [0; 3],
        }
    }

    /// The t drawn white and the t drawn black, when the quantity is t.
    pub fn white_black_t(&self) -> (f64, f64) {
        (
            (1.0 - self.at_zero) / self.per_unit,
            -self.at_zero / self.per_unit,
        )
    }

    /// The value (1 white, 0 black) of a hit whose quantity is `q`.
    pub fn value(&self, q: f64) -> f64 {
        self.at_zero + self.per_unit * q
    }
}

/// A model of a ray caster: each field a way real programs differ, the course's values in
/// [`Model::course`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Model {
    /// Where each pixel's ray starts.
    pub pixels: PixelMap,
    /// Added to every t: t per world unit along the screen's u and v, counted from the camera
    /// centre (a ray origin that slides along the direction), and a constant.
    pub t_ramp: DVec3,
    /// Which roots count and which hit is drawn.
    pub hits: HitRule,
    /// The colour image's background as bytes (`None`: the scene's).
    pub background: Option<[u8; 3]>,
    /// 8-bit values rounded instead of truncated.
    pub rounded: bool,
    /// How the depth image is drawn.
    pub depth: DepthMap,
    /// Only the pixels with `x < .0` and `y_up < .1` are traced (loops that run to the wrong
    /// bound); the rest keep the background (`None`: every pixel).
    pub drawn_px: Option<(u32, u32)>,
    /// Several samples per pixel on a fixed grid over the screen, one of those that hit setting
    /// the pixel (`None`: one ray per pixel, through the pixel map).
    pub samples: Option<SampleGrid>,
}

/// A grid of samples over the camera's square screen, `per_side` a side, each written to the
/// pixel it falls in (`floor(i·W/per_side)`, `floor(j·H/per_side)`): where the pixel's samples
/// hit different spheres, or some miss, the last one that hits (rows bottom up, then columns
/// left to right) or the first sets the pixel, so silhouettes grow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SampleGrid {
    /// Samples along each side of the screen.
    pub per_side: u32,
    /// The last sample that hits sets the pixel (else the first).
    pub last_wins: bool,
}

impl SampleGrid {
    /// The grid's samples `[i0, i1)` along an axis of `pixels` pixels that fall in pixel `p`.
    pub fn samples_of(&self, p: u32, pixels: u32) -> (u32, u32) {
        let first = |q: u32| (u64::from(q) * u64::from(self.per_side)).div_ceil(u64::from(pixels));
        (first(p) as u32, first(p + 1) as u32)
    }

    /// The screen coordinate of sample `i` along an axis, world units from the camera centre.
    pub fn screen_of(&self, i: u32, size_world: f64) -> f64 {
        ((f64::from(i) + 0.5) / f64::from(self.per_side) - 0.5) * size_world
    }
}

impl Model {
    /// The course's ray caster for `view` (its size, camera and depth range).
    pub fn course(view: &View) -> Self {
        Self {
            pixels: PixelMap::course(view.width_px, view.height_px, view.size_world),
            t_ramp: DVec3::ZERO,
            hits: HitRule::COURSE,
            background: None,
            rounded: false,
            depth: DepthMap::of_range(view.depth_range),
            drawn_px: None,
            samples: None,
        }
    }

    /// The course's pixel step of `view`.
    pub fn step_world(view: &View) -> f64 {
        course_step(view.width_px, view.height_px, view.size_world)
    }

    /// The point of the model that a program with `mistakes` is (see [`Mistake`]).
    pub fn of_mistakes(view: &View, mistakes: MistakeSet) -> Self {
        let mut model = Self::course(view);
        let (width, height) = (view.width_px, view.height_px);
        let step = Self::step_world(view);
        let mut relative = DMat2::IDENTITY;
        if mistakes.contains(Mistake::Stretched) {
            let longer = f64::from(width.max(height).max(1));
            relative = DMat2::from_diagonal(DVec2::new(
                longer / f64::from(width.max(1)),
                longer / f64::from(height.max(1)),
            ));
        }
        let mut ramp_along = 0.0;
        let mut raw_up_length = 1.0;
        if mistakes.contains(Mistake::RawUp) {
            // The screen's vertical is `up` as written: its part across the direction scales v,
            // its part along the direction moves each row's ray origin along the rays.
            let direction = view.direction_world.normalize();
            ramp_along = view.up_world.dot(direction);
            raw_up_length = (view.up_world - ramp_along * direction).length();
            relative.y_axis *= raw_up_length;
        }
        if mistakes.contains(Mistake::Mirrored) {
            relative.x_axis = -relative.x_axis;
        }
        let mut offset = if mistakes.contains(Mistake::PixelCorners) {
            DVec2::ZERO
        } else {
            DVec2::splat(0.5)
        };
        if mistakes.contains(Mistake::FlippedVertically) {
            // Rows written top first: row y_up shows the program's row H − 1 − y_up.
            relative.y_axis = -relative.y_axis;
            offset.y = 1.0 - offset.y;
        }
        model.pixels = PixelMap::of_relative(relative, offset, width, height, step);
        // t from an origin moved by v_raw·(up·d) along the direction, where the screen's true v
        // is v_raw·|up across the direction|.
        model.t_ramp = DVec3::new(0.0, -ramp_along / raw_up_length, 0.0);
        model.hits = HitRule {
            visible: Visible::Nearest,
            later_wins_ties: mistakes.contains(Mistake::LastWins),
            tmin: if mistakes.contains(Mistake::TminZero) {
                0.0
            } else if mistakes.contains(Mistake::TminMinusOne) {
                -1.0
            } else {
                f64::NEG_INFINITY
            },
            far_when_near_refused: !mistakes.contains(Mistake::TminMinusOne)
                || mistakes.contains(Mistake::TminZero),
            far_only: mistakes.contains(Mistake::FarRoot),
            square_root: !mistakes.contains(Mistake::NoSquareRoot),
        };
        model.rounded = mistakes.contains(Mistake::Rounded);
        let mut depth = DepthMap::of_range(view.depth_range);
        if mistakes.contains(Mistake::UnnormalizedDirection) {
            depth.per_unit /= view.direction_world.length();
        }
        if mistakes.contains(Mistake::DepthReversed) {
            depth.at_zero = 1.0 - depth.at_zero;
            depth.per_unit = -depth.per_unit;
        }
        if mistakes.contains(Mistake::DepthNoClamp) {
            depth.outside = Outside::Wrap;
        } else if mistakes.contains(Mistake::DepthOutsideBlack) {
            depth.outside = Outside::Black;
        }
        model.depth = depth;
        model
    }
}

/// 8-bit bytes of a colour: each channel ×255, truncated (or rounded), clamped.
pub fn colour_bytes(colour: Vec3, rounded: bool) -> [u8; 3] {
    colour.to_array().map(|c| {
        let scaled = c * 255.0;
        let level = if rounded {
            scaled.round()
        } else {
            scaled.floor()
        };
        level.clamp(0.0, 255.0) as u8
    })
}

/// 8-bit level of a depth value (1 white): truncated (or rounded); clamped, or wrapped modulo
/// 256 when `wrap`.
pub fn depth_level(value: f64, rounded: bool, wrap: bool) -> u8 {
    let scaled = value * 255.0;
    if !rounded && !wrap {
        // The clamped floor without calling floor (a library call on the baseline x86-64):
        // below 0 (floor −1 or less) and up to 255 clamp; in between, truncation is the floor.
        return if !scaled.is_finite() || scaled < 0.0 {
            0
        } else if scaled >= 255.0 {
            255
        } else {
            scaled as u8
        };
    }
    let level = if rounded {
        scaled.round()
    } else {
        scaled.floor()
    };
    if !level.is_finite() {
        return 0;
    }
    if wrap {
        (level as i64).rem_euclid(256) as u8
    } else {
        level.clamp(0.0, 255.0) as u8
    }
}

#[cfg(test)]
mod tests {
    use super::depth_level;

    /// The grey level of the course's depth image, as the course's code computes it: the value
    /// times 255, floored, clamped to a byte; nothing finite is black.
    fn course_level(value: f64) -> u8 {
        let scaled = (value * 255.0).floor();
        if scaled.is_nan() || scaled.is_infinite() {
            0
        } else {
            scaled.clamp(0.0, 255.0) as u8
        }
    }

    #[test]
    fn a_truncated_level_is_the_clamped_floor_at_every_edge() {
        let mut values = vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN,
            -0.0,
            0.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            -1.0 / 255.0,
            -0.5 / 255.0,
            1.0,
            1.0 - f64::EPSILON,
            1.0 + f64::EPSILON,
            2.0,
            1e300,
        ];
        // Every level's edges, a hair either side.
        for level in 0..=256 {
            let edge = f64::from(level) / 255.0;
            values.extend([edge, edge.next_down(), edge.next_up()]);
        }
        for value in values {
            assert_eq!(
                depth_level(value, false, false),
                course_level(value),
                "{value:e}"
            );
        }
    }
}
