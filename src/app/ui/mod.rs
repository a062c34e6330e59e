//! The viewer's drawing: each part a `*_ui` function over plain state that reports what the user
//! asked for; the coordinator (`ViewerApp`) applies it.
//!
//! * [`toolbar`]: the buttons along the top
//! * [`view_controls`]: camera and depth-range sliders, the quality section
//! * [`depth_section`]: colour map, no-hit mark, auto range
//! * [`compare_section`]: their image or the chosen quality against the exact render
//! * [`file_sections`]: open a typed path, save the view, export options
//! * [`images`]: the two images (side by side or stacked), the probe and histogram under them
//! * [`gestures`]: pointer input on the images; [`magnifier`]: enlarging the images themselves
//! * [`probe_panel`]: the probe's lines with copy and unpin
//! * [`histogram`]: the histogram of visible t with the draggable range
//! * [`views_section`]: named views; [`help`]: the shortcuts overlay
//! * [`probe_text`]: what the probe says about a pixel
//! * [`status_bar`]: the status bar and the error banner
//! * [`hint`]: the small text under a control

pub(crate) mod compare_section;
pub(crate) mod depth_section;
pub(crate) mod file_sections;
pub mod gestures;
pub mod help;
pub(crate) mod hint;
pub mod histogram;
pub mod images;
pub mod magnifier;
pub(crate) mod probe_panel;
pub(crate) mod probe_text;
pub(crate) mod status_bar;
pub(crate) mod toolbar;
pub mod view_controls;
pub(crate) mod views_section;
