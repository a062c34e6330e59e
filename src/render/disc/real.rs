//! [`Real`]: the floating-point type of the per-pixel arithmetic — f64 (exact mode) or f32 (fast
//! mode) — with the unit roundoff that tells the rasteriser when an f32 decision is uncertain.

use std::ops::{Add, Mul, Sub};

use crate::render::Precision;

/// The floating-point type of the per-pixel arithmetic.
pub(crate) trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// The mode this type implements.
    const PRECISION: Precision;
    /// Unit roundoff, if coarser than f64's (then uncertain decisions are re-made in f64); 0 for
    /// f64.
    const ROUNDOFF: f64;
    /// Zero.
    const ZERO: Self;
    /// +∞ (no hit).
    const INFINITY: Self;
    /// Rounds an f64 to this type.
    fn from_f64(value: f64) -> Self;
    /// Widens to f64.
    fn to_f64(self) -> f64;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// Division.
    fn div(self, other: Self) -> Self;
    /// The same buffer seen as this type, when it is f64 (so f64 kernels write in place).
    fn as_self_slice(buffer: &mut [f64]) -> Option<&mut [Self]>;
}

impl Real for f64 {
    const PRECISION: Precision = Precision::F64;
    const ROUNDOFF: f64 = 0.0;
    const ZERO: Self = 0.0;
    const INFINITY: Self = f64::INFINITY;
    fn from_f64(value: f64) -> Self {
        value
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
    fn div(self, other: Self) -> Self {
        self / other
    }
    fn as_self_slice(buffer: &mut [f64]) -> Option<&mut [Self]> {
        Some(buffer)
    }
}

impl Real for f32 {
    const PRECISION: Precision = Precision::F32;
    const ROUNDOFF: f64 = 5.960_464_477_539_063e-8;
    const ZERO: Self = 0.0;
    const INFINITY: Self = f32::INFINITY;
    fn from_f64(value: f64) -> Self {
        value as f32
    }
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    fn sqrt(self) -> Self {
        f32::sqrt(self)
    }
    fn abs(self) -> Self {
        f32::abs(self)
    }
    fn div(self, other: Self) -> Self {
        self / other
    }
    fn as_self_slice(_buffer: &mut [f64]) -> Option<&mut [Self]> {
        None
    }
}
