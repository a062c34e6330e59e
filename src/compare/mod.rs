//! Comparing a picture with the exact one and saying why it differs: the compare concept
//! itself, which the command line's and the viewer's `compare` modules put in front of the user.
//!
//! * [`mistake`]: the known mistakes of a first ray caster, each a word.
//! * [`model`]: a model of a student's ray caster, the course's as one point of it.
//! * [`model_render`]: the images a model makes.
//! * [`difference`]: how two images differ, and the course's rule for "the same picture".
//! * [`fit`]: a model of their program fitted to their images.
//! * [`describe`]: a model said as statements, and back.
//! * [`deviation`]: the statements, with their values and what to check in code.
//! * [`diagnosis`]: the answer: the statements the images need, and how far they explain them.
//! * [`judge`]: their images against the exact ones, under a depth range given or read back.
//! * [`depth_range`]: the depth range a depth image was most likely made over.
//! * `shorter`: the shortest true story, tried against a longer answer.
//! * [`sentence`]: what a statement says in words, and what to change in code.
//! * [`tell_apart`]: what would tell a tie apart (their other image, the course's lines).
//! * [`picture`]: the difference picture (theirs, exact, heat map, legend).
//! * [`their_image`]: reading the image a user compares.

pub mod depth_range;
pub mod describe;
pub mod deviation;
pub mod diagnosis;
pub mod difference;
pub mod fit;
mod image_head;
pub mod judge;
pub mod mistake;
pub mod model;
pub mod model_render;
pub mod needed;
pub mod picture;
mod rival_maps;
pub mod sentence;
mod shorter;
pub mod tell_apart;
pub mod their_image;

pub use depth_range::infer_depth_range;
pub use deviation::{Deviation, RangeFrom};
pub use diagnosis::{Diagnosis, Verdict, diagnose};
pub use difference::Difference;
pub use fit::score::{Theirs, Unexplained};
pub use mistake::{Mistake, MistakeSet};
