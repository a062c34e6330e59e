//! The pixel–disc test and its tie rule, written once. [`test`] is generic over [`Lanes`]: `f64`
//! tests one pixel, `f64x4` four in SIMD lanes, and both run the same operations in the same
//! order — `du² + dv² ≤ r²`, `t = w − √max(r² − du² − dv², 0)`, each correctly rounded — so a
//! pixel gets the same answer, bit for bit, whichever path draws it. [`wins_tie`] is the rule for
//! an equal t: the sphere first in the file.

use std::ops::{Add, Mul, Sub};

use wide::f64x4;

use super::screen_disc::Disc;

/// Numbers the test runs on: one pixel (`f64`, its masks `bool`) or four (`f64x4`, its masks
/// lanes of all ones or all zeros).
pub(super) trait Lanes:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// Which lanes a comparison holds in.
    type Mask: Copy;
    /// `value` in every lane.
    fn splat(value: f64) -> Self;
    /// `√max(self, 0)`: the root of what is left of r² (0 where nothing is, NaN included).
    fn root_of_rest(self) -> Self;
    /// `self ≤ other`, lane by lane.
    fn le(self, other: Self) -> Self::Mask;
    /// `self < other`, lane by lane.
    fn lt(self, other: Self) -> Self::Mask;
    /// `self == other`, lane by lane.
    fn eq(self, other: Self) -> Self::Mask;
    /// Both masks, lane by lane.
    fn both(a: Self::Mask, b: Self::Mask) -> Self::Mask;
}

impl Lanes for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(value: f64) -> Self {
        value
    }
    #[inline(always)]
    fn root_of_rest(self) -> Self {
        (if self > 0.0 { self } else { 0.0 }).sqrt()
    }
    #[inline(always)]
    fn le(self, other: Self) -> bool {
        self <= other
    }
    #[inline(always)]
    fn lt(self, other: Self) -> bool {
        self < other
    }
    #[inline(always)]
    fn eq(self, other: Self) -> bool {
        self == other
    }
    #[inline(always)]
    fn both(a: bool, b: bool) -> bool {
        a & b
    }
}

impl Lanes for f64x4 {
    type Mask = f64x4;
    #[inline(always)]
    fn splat(value: f64) -> Self {
        f64x4::splat(value)
    }
    #[inline(always)]
    fn root_of_rest(self) -> Self {
        // `max` takes the zero where the rest is NaN, as the one-pixel test does.
        self.max(f64x4::ZERO).sqrt()
    }
    #[inline(always)]
    fn le(self, other: Self) -> f64x4 {
        self.simd_le(other)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> f64x4 {
        self.simd_lt(other)
    }
    #[inline(always)]
    fn eq(self, other: Self) -> f64x4 {
        self.simd_eq(other)
    }
    #[inline(always)]
    fn both(a: f64x4, b: f64x4) -> f64x4 {
        a & b
    }
}

/// What one disc does to pixels that hold t `t_old`.
pub(super) struct Test<L: Lanes> {
    /// t of the disc's front surface at each pixel (meaningful where `inside`).
    pub(super) t: L,
    /// The disc covers the pixel.
    pub(super) inside: L::Mask,
    /// It covers the pixel and is strictly nearer than what the pixel holds: it takes it.
    pub(super) nearer: L::Mask,
    /// It covers the pixel at the same t: [`wins_tie`] decides.
    pub(super) tied: L::Mask,
}

/// The pixel–disc test: pixels `du_sq` (du²) and `dv_sq` (dv²) from `disc`'s centre on screen,
/// holding t `t_old`.
#[inline(always)]
pub(super) fn test<L: Lanes>(disc: &Disc, du_sq: L, dv_sq: L, t_old: L) -> Test<L> {
    let radius_sq = L::splat(disc.radius_sq);
    let distance_sq = du_sq + dv_sq;
    let inside = distance_sq.le(radius_sq);
    let t = L::splat(disc.w) - (radius_sq - distance_sq).root_of_rest();
    Test {
        t,
        inside,
        nearer: L::both(inside, t.lt(t_old)),
        tied: L::both(inside, t.eq(t_old)),
    }
}

/// The tie rule: at an equal t, the disc of sphere `disc_sphere` takes a pixel that holds
/// `pixel_sphere` when its sphere comes first in the file (so the picture does not depend on the
/// order the discs are drawn in).
#[inline(always)]
pub(super) fn wins_tie(disc_sphere: u32, pixel_sphere: u32) -> bool {
    disc_sphere < pixel_sphere
}

/// One pixel: whether `disc` takes the pixel holding (`t_px`, `sphere_px`) `du_sq` and `dv_sq`
/// from its centre, and the t it would put there.
#[inline(always)]
pub(super) fn takes_pixel(
    disc: &Disc,
    (du_sq, dv_sq): (f64, f64),
    (t_px, sphere_px): (f64, u32),
) -> (bool, f64) {
    let hit = test(disc, du_sq, dv_sq, t_px);
    (
        hit.nearer | (hit.tied & wins_tie(disc.sphere, sphere_px)),
        hit.t,
    )
}

/// Lanes of pixels (bit `i` of the masks for `sphere_px[i]`): applies the tie rule to the lanes
/// in `tied` — those holding a sphere later in the file join `taken` and get the disc's own t,
/// `t_of(lane)` (which differs from an equal one at most in the sign of a zero). Ties are rare:
/// the caller's masks stay branch-free, and only a tie comes here.
#[inline(always)]
pub(super) fn take_ties(
    disc_sphere: u32,
    (tied, t_of): (u32, impl Fn(usize) -> f64),
    sphere_px: &[u32],
    (taken, t_new): (&mut u32, &mut [f64]),
) {
    if tied == 0 {
        return;
    }
    for (lane, &sphere) in sphere_px.iter().enumerate() {
        if tied >> lane & 1 == 1 && wins_tie(disc_sphere, sphere) {
            *taken |= 1 << lane;
            t_new[lane] = t_of(lane);
        }
    }
}

impl Disc {
    /// t of the front surface at screen (u, v), or `None` outside the disc. Tangent points hit.
    #[inline]
    pub fn hit_t(&self, u: f64, v: f64) -> Option<f64> {
        let (du, dv) = (u - self.u, v - self.v);
        let hit = test(self, du * du, dv * dv, f64::INFINITY);
        hit.inside.then_some(hit.t)
    }
}

/// The visible hit at screen (u, v) among `discs`: (t, sphere), smallest t, first in file order
/// on a tie.
pub fn nearest_hit(discs: &[Disc], u: f64, v: f64) -> Option<(f64, u32)> {
    let mut best: Option<(f64, u32)> = None;
    for disc in discs {
        if let Some(t) = disc.hit_t(u, v)
            && best.is_none_or(|(best_t, _)| t < best_t)
        {
            best = Some((t, disc.sphere));
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four-lane test gives every lane what the one-pixel test gives that pixel, bit for bit,
    /// over hostile values too (on the edge, NaN, infinities, zeros of both signs).
    #[test]
    fn four_lanes_answer_as_four_single_pixels() {
        let disc = Disc {
            u: 0.25,
            v: -0.5,
            w: 10.0,
            radius_sq: 2.0,
            sphere: 3,
        };
        let values = [
            0.0,
            -0.0,
            1.0,
            2.0,
            1.999_999_999_999_999_8,
            0.5,
            4.0,
            1e-300,
            f64::NAN,
            f64::INFINITY,
            1e300,
        ];
        let t_olds = [10.0 - 2f64.sqrt(), 9.0, 10.0, f64::INFINITY, -0.0, f64::NAN];
        for &dv_sq in &values {
            for du in values.windows(4) {
                for &t_old in &t_olds {
                    let du_sq = [du[0], du[1], du[2], du[3]];
                    let lanes = test(
                        &disc,
                        f64x4::new(du_sq),
                        f64x4::splat(dv_sq),
                        f64x4::splat(t_old),
                    );
                    let t = lanes.t.to_array();
                    let (inside, nearer, tied) = (
                        lanes.inside.to_bitmask(),
                        lanes.nearer.to_bitmask(),
                        lanes.tied.to_bitmask(),
                    );
                    for (lane, &du_sq) in du_sq.iter().enumerate() {
                        let one = test(&disc, du_sq, dv_sq, t_old);
                        assert_eq!(one.t.to_bits(), t[lane].to_bits(), "{du_sq} {dv_sq}");
                        assert_eq!(one.inside, inside >> lane & 1 == 1);
                        assert_eq!(one.nearer, nearer >> lane & 1 == 1);
                        assert_eq!(one.tied, tied >> lane & 1 == 1);
                    }
                }
            }
        }
    }

    #[test]
    fn the_test_is_the_course_formula_and_ties_go_to_the_first_sphere() {
        let disc = Disc {
            u: 0.0,
            v: 0.0,
            w: 10.0,
            radius_sq: 1.0,
            sphere: 3,
        };
        // At the centre: t = w − r; on the edge: t = w; outside: not covered.
        let centre = test(&disc, 0.0, 0.0, f64::INFINITY);
        assert!(centre.inside && centre.nearer && centre.t == 9.0);
        let edge = test(&disc, 0.36, 0.64, f64::INFINITY);
        assert!(edge.inside && edge.t == 10.0);
        assert!(!test(&disc, 0.36, 0.640_000_000_000_001, f64::INFINITY).inside);
        // An equal t: the disc takes a pixel of a later sphere, not of an earlier one.
        assert_eq!(takes_pixel(&disc, (0.0, 0.0), (9.0, 4)), (true, 9.0));
        assert_eq!(takes_pixel(&disc, (0.0, 0.0), (9.0, 2)), (false, 9.0));
        assert!(
            !takes_pixel(&disc, (0.0, 0.0), (8.5, 4)).0,
            "a nearer pixel stays"
        );
    }
}
