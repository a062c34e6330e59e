//! Supersampling with the course's samplers and reconstruction filters (6.837 assignment 7):
//! `uniform` (an n×n grid), `random` and `jittered` (one random point in each cell of an n×n grid)
//! sample positions, and `box`, `tent` and `gaussian` filters whose radius (sigma) is in pixels.
//!
//! A pixel's colour is the filter-weighted mean of every sample within the filter's support —
//! its own and its neighbours' — normalised so the weights sum to 1. Where every contributing
//! sample shows the same colour, the pixel gets exactly that colour (interior pixels equal the
//! one-sample render). The depth image filters the **grey values** of the samples (a grey edge is
//! the mean of the greys, as the course's depth images are); the frame's raw t stays one centre
//! sample per pixel, so t, the pixel probe and lossless depth export are never blurred.
//!
//! Sample positions are seeded from (seed, pixel), so a render is the same whatever the thread
//! count, and the same flags give the same bytes.

pub(crate) mod settings;
mod supersample;

pub use settings::{Filter, Sampler, Sampling, SamplingError};
pub(crate) use supersample::{supersample, working_bytes};
