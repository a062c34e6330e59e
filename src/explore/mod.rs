//! Exploring a scene: the math behind the viewer's controls, free of any UI.
//!
//! * [`ranges`]: slider ranges and depth ranges derived from a scene
//! * [`trace`]: the course's computation behind one pixel, step by step, as text
//!
//! The math of the viewer's own controls (navigation, the probe, the depth histogram) is built
//! with the viewer only: `src/app/` (`navigate.rs`, `probe.rs`, `depth_stats.rs`).

pub(crate) mod ranges;
pub mod trace;

pub use ranges::{
    Reach, SIZE_REACH_FACTOR, SliderRanges, initial_depth_range, scene_extent, visible_depth_range,
    window_around,
};
