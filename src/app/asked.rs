//! What a seam (`app/seam.rs`: the desktop's or a page's) asks of the viewer: the one way back
//! from a seam to the coordinator, which carries it out. Some are asked on one platform alone (a
//! page's files come as bytes, the desktop's by path).

use std::sync::Arc;

use super::actions::Action;
use super::compare::ImageKind;
use super::status::Status;

/// What a seam asks of the viewer.
#[derive(Debug)]
pub(crate) enum Asked {
    /// Open the scene file at this path.
    #[cfg_attr(
        target_arch = "wasm32",
        expect(dead_code, reason = "the desktop's files")
    )]
    Open(std::path::PathBuf),
    /// Carry out what the user asked for.
    Apply(Action),
    /// Show this in the status bar.
    Say(Status),
    /// Open the scene these bytes hold, named so (a page's file, or a scene built in).
    OpenBytes(String, Arc<[u8]>),
    /// Compare the image these bytes hold, named so, as this kind (a page's file).
    #[cfg_attr(
        not(target_arch = "wasm32"),
        expect(dead_code, reason = "a page's files")
    )]
    CompareBytes(String, ImageKind, Arc<[u8]>),
    /// The scene could not be opened: why (a page's file that could not be read).
    #[cfg_attr(
        not(target_arch = "wasm32"),
        expect(dead_code, reason = "a page's files")
    )]
    SceneError(String),
}
