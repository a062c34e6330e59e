//! Oracles and study support: what the tests and the accuracy and trade-off studies compare the
//! renderer against. Nothing here is on the runtime path (feature `oracle`, which the tests,
//! benchmarks and examples turn on).
//!
//! * [`ray_loop`]: the straightforward loop — one world-space ray per pixel against every sphere
//!   through the careful ray–sphere routine, single-threaded; and the textbook f32 `b² − 4ac`
//!   baseline.
//! * [`high_precision`]: the double-double reference (≈ 106-bit arithmetic).
//! * [`area`]: each pixel's area average on a dense grid of rays (the anti-aliasing oracle).
//! * [`generate`]: seeded random scenes.
//! * [`mistaken`]: the pictures of a ray caster with known mistakes (the diagnosis's tests).

pub mod area;
pub(crate) mod generate;
pub mod high_precision;
pub mod mistaken;
pub mod ray_loop;

pub use generate::{DENSE_CUBE_SIDE, dense_scene, random_scene};
