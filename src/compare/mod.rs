//! Comparing a picture with the exact one and saying why it differs: the compare concept
//! itself, which the command line's and the viewer's `compare` modules put in front of the user.
//!
//! * [`mistake`]: the known mistakes of a first ray caster, each a word.
//! * [`variant`]: the variant renderer, the picture a ray caster with a set of mistakes makes.
//! * [`difference`]: how two images differ, and the course's rule for "the same picture".
//! * [`diagnosis`]: which set of mistakes explains a difference, if any does.
//! * [`depth_range`]: the depth range a depth image was most likely made over.
//! * [`picture`]: the difference picture (theirs, exact, heat map, legend).
//! * [`their_image`]: reading the image a user compares.

pub mod depth_range;
pub mod diagnosis;
pub mod difference;
pub mod mistake;
pub mod picture;
pub mod their_image;
pub mod variant;

pub use depth_range::infer_depth_range;
pub use diagnosis::{Diagnosis, Theirs, Unexplained, diagnose};
pub use difference::Difference;
pub use mistake::{Mistake, MistakeSet};
pub use variant::render_variant;
