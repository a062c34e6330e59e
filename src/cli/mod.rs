//! The course-compatible command line: one flag table ([`flags`]) from which parsing, the usage
//! text and writing a request back to arguments all come; the typed requests ([`request`]);
//! usage errors ([`error`]); running a render request without a window ([`run`]; the course's
//! own command strip by strip, [`streamed`]) and its
//! progress bars on a terminal ([`progress`]); comparing the user's images with the exact ones
//! ([`compare`]).
//!
//! Parsing goes in two stages: [`RawArgs::parse`] splits the arguments into known flags and their
//! values (arity, unknown and repeated flags), then [`RawArgs::validate`] turns them into a
//! typed [`Command`] (numbers, sizes, formats).

pub mod compare;
mod error;
mod flags;
mod grade_request;
mod outputs;
pub(crate) mod progress;
mod raw_args;
mod request;
pub mod run;
mod streamed;
#[cfg(test)]
mod tests;
mod to_arguments;

pub use error::UsageError;
pub use flags::{Flag, GRADE_SYNOPSIS, GRADE_WORD, VERSION_LINE, usage};
pub use grade_request::GradeRequest;
pub use outputs::{DepthOutput, Outputs};
pub use raw_args::RawArgs;
pub use request::{
    Command, CompareRequest, DEFAULT_SIZE_PX, RenderRequest, TheirDepth, ViewerRequest,
    parse_command,
};
