//! What the user can ask the viewer for, as [`Action`]s: the toolbar, the panels, the keyboard
//! and the pointer report them, and the coordinator (`ViewerApp::apply`) hands each to the
//! feature that carries it out.

use std::path::PathBuf;

use super::compare::ImageKind;
use super::confirm::Answer;
use super::dialogs::DialogKind;

/// Something the user asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Action {
    /// Show a file dialog.
    OpenDialog(DialogKind),
    /// Open the scene file at this path.
    Open(PathBuf),
    /// Open the bundled scene of this index (`scene::bundled::BUNDLED_SCENES`).
    OpenBundled(usize),
    /// Read the open scene file again.
    Reload,
    /// Fit centre and size to the scene.
    FrameAll,
    /// Back to the file's camera (the depth range stays).
    ResetView,
    /// Back to the depth range the file's view started with.
    ResetDepth,
    /// Fit the depth range to the visible t.
    AutoRange,
    /// Set the depth range (the one read back from their depth image).
    UseDepthRange(crate::render::depth_map::DepthRange),
    /// Back to the view before the last change.
    Undo,
    /// Forward again after an undo.
    Redo,
    /// Name the current view (for the open scene file).
    NameView(String),
    /// Go to the named view at this index.
    GoToView(usize),
    /// Forget the named view at this index.
    ForgetView(usize),
    /// Show or hide the shortcuts overlay.
    ToggleHelp,
    /// Magnifier back to the whole image.
    ResetMagnifier,
    /// Write files: ask first when they would replace any.
    Write(Write),
    /// The user's yes to a write that waited (the files it replaces were shown), or to making
    /// its folder first.
    Confirmed(Answer<Write>),
    /// Move the view or the magnifier.
    Navigate(super::navigate::Navigation),
    /// Pin the point seen at this image position (pixels, y up) of the frame on screen.
    Pin(glam::DVec2),
    /// Release the pinned probe.
    Unpin,
    /// Trace the pinned pixel into the trace window.
    Trace,
    /// Compare the image at this path with the exact render.
    CompareImage(PathBuf, ImageKind),
    /// Measure the chosen quality against the exact render on the current view.
    CompareQuality,
    /// What the compared image shows.
    CompareShow(crate::app::compare::CompareShow),
    /// The A/B flip: the render and their image in turn.
    CompareFlip,
    /// The difference view on and off.
    CompareDifference,
    /// Close the comparison.
    CompareClose,
}

impl Action {
    /// Whether the view carries it out (`Viewing::carry_out`): navigation, resets, ranges,
    /// history, named views, unpinning, the magnifier.
    pub(crate) fn is_the_views(&self) -> bool {
        matches!(
            self,
            Self::AutoRange
                | Self::Undo
                | Self::Redo
                | Self::NameView(_)
                | Self::FrameAll
                | Self::ResetView
                | Self::ResetDepth
                | Self::UseDepthRange(_)
                | Self::GoToView(_)
                | Self::ForgetView(_)
                | Self::Navigate(_)
                | Self::Unpin
                | Self::ResetMagnifier
        )
    }

    /// Whether it changes the view at once: a step of the view's history of its own.
    pub(crate) fn is_one_shot(&self) -> bool {
        matches!(
            self,
            Self::FrameAll
                | Self::ResetView
                | Self::ResetDepth
                | Self::AutoRange
                | Self::UseDepthRange(_)
                | Self::GoToView(_)
        )
    }
}

/// A write the user asked for: files the viewer makes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Write {
    /// Export the current view to this base path.
    ExportTo(PathBuf),
    /// Write the course's files (200×200 TGA pair and command line) into the export folder.
    CourseFiles,
    /// Write the scene with the current camera to this path.
    SaveViewTo(PathBuf),
}
