//! Exploring a scene: the math behind the viewer's controls, free of any UI.
//!
//! * [`ranges`]: slider ranges and depth ranges derived from a scene
//! * [`navigate`]: pan, zoom at a point, orbit and "frame all" as math on a view
//! * [`depth_stats`]: the histogram of visible t and the auto depth range
//! * [`probe`]: what one pixel of a frame shows (position, t, sphere, material)
//! * [`trace`]: the course's computation behind one pixel, step by step, as text

pub mod depth_stats;
pub mod navigate;
pub mod probe;
pub(crate) mod ranges;
pub mod trace;

pub use ranges::{
    Reach, SIZE_REACH_FACTOR, SliderRanges, initial_depth_range, scene_extent, visible_depth_range,
    window_around,
};
