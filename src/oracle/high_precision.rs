//! A higher-precision reference for single pixels: the same camera-space disc model evaluated in
//! double-double arithmetic (about 106 bits, [`twofloat`]) from the scene's f64 inputs — the
//! basis, the projection, the pixel's screen point, the hit test and t. Its own error is below
//! 1e-30 relative, so against it the error of the f64 and f32 paths is measured as if against
//! exact arithmetic.
//!
//! Each answer carries the **margin** of the hit test, `(r² − d²) / r²`, so a comparison can tell
//! a genuine error from a pixel whose centre lies within rounding of a silhouette.

use twofloat::TwoFloat;

use crate::render::{View, ViewError};
use crate::scene::Scene;

type Dd = TwoFloat;

#[derive(Debug, Clone, Copy)]
struct Vec3Dd {
    x: Dd,
    y: Dd,
    z: Dd,
}

impl Vec3Dd {
    fn from_f64(v: glam::DVec3) -> Self {
        Self {
            x: Dd::from(v.x),
            y: Dd::from(v.y),
            z: Dd::from(v.z),
        }
    }

    fn sub(self, other: Self) -> Self {
        Self {
            x: self.x - other.x,
            y: self.y - other.y,
            z: self.z - other.z,
        }
    }

    fn scale(self, factor: Dd) -> Self {
        Self {
            x: self.x * factor,
            y: self.y * factor,
            z: self.z * factor,
        }
    }

    fn dot(self, other: Self) -> Dd {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    fn cross(self, other: Self) -> Self {
        Self {
            x: self.y * other.z - self.z * other.y,
            y: self.z * other.x - self.x * other.z,
            z: self.x * other.y - self.y * other.x,
        }
    }

    fn normalized(self) -> Self {
        let length = self.dot(self).sqrt();
        self.scale(Dd::from(1.0) / length)
    }
}

/// The reference answer for one pixel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferencePixel {
    /// The visible sphere and its t (rounded to f64), if any.
    pub hit: Option<(u32, f64)>,
    /// The smallest `|r² − d²| / max(r², d²)` over all spheres: how close the pixel centre is to
    /// any silhouette, relative to the disc's size.
    pub silhouette_margin: f64,
    /// How strongly the visible t reacts to rounding of the inputs: `r² / √(r² − d²)` of the
    /// visible sphere (it grows without bound towards the silhouette, where t's slope is
    /// infinite); 0 without a hit. A backward-stable t is within a few ε times this plus `|t| + r`.
    pub t_sensitivity: f64,
    /// The visible sphere's radius (0 without a hit).
    pub radius: f64,
    /// The smallest relative gap in t between the visible sphere and any other sphere covering the
    /// pixel (ties: 0); `+∞` when only one sphere covers it.
    pub tie_margin: f64,
}

/// Evaluates the disc model in double-double for a set of pixels (x, y_up).
pub struct HighPrecision {
    discs: Vec<(Dd, Dd, Dd, Dd, u32)>,
    pixel_size: Dd,
    width: f64,
    height: f64,
}

impl HighPrecision {
    /// Prepares the reference for `scene` through `view`.
    pub fn new(scene: &Scene, view: &View) -> Result<Self, ViewError> {
        view.validate()?;
        let direction = Vec3Dd::from_f64(view.direction_world).normalized();
        let up = Vec3Dd::from_f64(view.up_world);
        let cross = direction.cross(up);
        // Re-orthogonalise as the f64 basis does (exact arithmetic needs no correction, but this
        // keeps the two constructions the same function of the inputs).
        let horizontal = cross
            .sub(direction.scale(cross.dot(direction)))
            .normalized();
        let screen_up = horizontal.cross(direction);
        let eye = Vec3Dd::from_f64(view.center_world);
        let discs = scene
            .spheres
            .iter()
            .zip(0u32..)
            .map(|(sphere, index)| {
                let offset = Vec3Dd::from_f64(sphere.center_world).sub(eye);
                let radius = Dd::from(sphere.radius_world);
                (
                    offset.dot(horizontal),
                    offset.dot(screen_up),
                    offset.dot(direction),
                    radius * radius,
                    index,
                )
            })
            .collect();
        let longer = f64::from(view.width_px.max(view.height_px));
        Ok(Self {
            discs,
            pixel_size: Dd::from(view.size_world) / Dd::from(longer),
            width: f64::from(view.width_px),
            height: f64::from(view.height_px),
        })
    }

    /// Screen (u, v) of pixel (x, y_up)'s centre.
    fn screen_point(&self, x: u32, y_up: u32) -> (Dd, Dd) {
        (
            Dd::from(f64::from(x) + 0.5 - 0.5 * self.width) * self.pixel_size,
            Dd::from(f64::from(y_up) + 0.5 - 0.5 * self.height) * self.pixel_size,
        )
    }

    /// `| |p − c| − r |` for the point p at parameter `t` on pixel (x, y_up)'s ray and sphere
    /// `sphere`: how far a claimed hit point lies from the sphere's surface.
    pub fn distance_from_surface(&self, sphere: u32, x: u32, y_up: u32, t: f64) -> f64 {
        let Some(&(cu, cv, cw, radius_sq, _)) = self.discs.get(sphere as usize) else {
            return f64::INFINITY;
        };
        let (u, v) = self.screen_point(x, y_up);
        let (du, dv, dw) = (u - cu, v - cv, Dd::from(t) - cw);
        let distance = (du * du + dv * dv + dw * dw).sqrt();
        (distance - radius_sq.sqrt()).hi().abs()
    }

    /// The reference answer at pixel (x, y_up).
    pub fn pixel(&self, x: u32, y_up: u32) -> ReferencePixel {
        let (u, v) = self.screen_point(x, y_up);
        let mut best: Option<(u32, Dd)> = None;
        let mut best_shape = (0.0, 0.0);
        let mut covering: Vec<(u32, Dd)> = Vec::new();
        let mut silhouette_margin = f64::INFINITY;
        for &(cu, cv, cw, radius_sq, index) in &self.discs {
            let du = u - cu;
            let dv = v - cv;
            let distance_sq = du * du + dv * dv;
            let gap = radius_sq - distance_sq;
            let scale = if radius_sq > distance_sq {
                radius_sq
            } else {
                distance_sq
            };
            if scale.hi() > 0.0 {
                silhouette_margin = silhouette_margin.min((gap / scale).hi().abs());
            }
            if gap.hi() >= 0.0 {
                let t = cw - gap.sqrt();
                covering.push((index, t));
                if best.is_none_or(|(_, best_t)| t < best_t) {
                    best = Some((index, t));
                    let sensitivity = radius_sq.hi() / gap.hi().sqrt();
                    best_shape = (sensitivity, radius_sq.hi().sqrt());
                }
            }
        }
        let tie_margin = match best {
            Some((best_index, best_t)) => covering
                .iter()
                .filter(|&&(index, _)| index != best_index)
                .map(|&(_, t)| {
                    let scale = best_t.hi().abs().max(t.hi().abs()).max(f64::MIN_POSITIVE);
                    (t - best_t).hi().abs() / scale
                })
                .fold(f64::INFINITY, f64::min),
            None => f64::INFINITY,
        };
        ReferencePixel {
            hit: best.map(|(index, t)| (index, t.hi() + t.lo())),
            silhouette_margin,
            t_sensitivity: best_shape.0,
            radius: best_shape.1,
            tie_margin,
        }
    }
}
