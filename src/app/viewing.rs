//! What the user does to the view as a whole: auto range (and the "follow" mode that keeps
//! doing it), frame all, reset the camera or the depth range, undo and redo, and the named views
//! of the open scene file.

use std::path::Path;

use glam::{DVec2, DVec3};

use super::render_requests::Shown;
use super::saved_views::{History, NamedView, SavedView, SceneViews};
use super::status::Status;
use super::ui::magnifier::Magnifier;
use crate::app::depth_stats::auto_range;
use crate::app::navigate;
use crate::render::depth_map::DepthRange;
use crate::render::{Frame, View};
use crate::scene::Scene;

/// The pointer's position (image pixels, y up) and the pinned point (world coordinates, so the
/// pin stays on what was pinned while the view moves).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct ProbePoints {
    pub(crate) hover_px: Option<DVec2>,
    pub(crate) pinned_world: Option<DVec3>,
}

/// The viewer's "view and history" feature: the view the controls edit, its undo history, the
/// camera "follow" last fitted the depth range for, the probed points and the magnifier.
pub(crate) struct Viewing {
    /// The camera, depth range and image size on screen.
    pub(crate) view: View,
    /// Undo and redo of view changes.
    pub(crate) history: History,
    /// The camera the depth range was last fitted for in "follow" mode.
    pub(crate) followed: Option<SavedView>,
    /// The hovered and the pinned pixel.
    pub(crate) probe: ProbePoints,
    /// The images enlarged (the same pixels, no new render).
    pub(crate) magnifier: Magnifier,
}

impl Viewing {
    /// `view` on screen, with a history that starts there.
    pub(crate) fn new(view: View) -> Self {
        let mut history = History::default();
        history.reset(&view);
        Self {
            view,
            history,
            followed: None,
            probe: ProbePoints::default(),
            magnifier: Magnifier::default(),
        }
    }
}

impl Viewing {
    /// "Auto range": fits the depth range to the t visible in `shown` (the frame on screen),
    /// ignoring `cut_percent` at each end. Says so when no sphere is visible.
    pub(crate) fn auto_range(&mut self, shown: Option<&Frame>, cut_percent: f64) -> Option<Status> {
        match shown.and_then(|frame| auto_range(frame, cut_percent)) {
            Some(range) => {
                self.view.depth_range = range;
                None
            }
            None => Some(Status::info("auto range: no sphere is visible")),
        }
    }

    /// "Follow": once `shown` (the frame on screen, of a scene load `current_epoch` when it is of
    /// the open scene) is of a changed camera, fits the depth range to it. `follow` off forgets
    /// the camera last followed.
    pub(crate) fn follow_depth(
        &mut self,
        follow: bool,
        shown: Option<&Shown>,
        current_epoch: u64,
        cut_percent: f64,
    ) {
        if !follow {
            self.followed = None;
            return;
        }
        let Some(shown) = shown else {
            return;
        };
        let camera = SavedView::of(&View {
            depth_range: DepthRange::new(0.0, 0.0),
            ..shown.view
        });
        if self.followed == Some(camera) || shown.scene_epoch != current_epoch {
            return;
        }
        self.followed = Some(camera);
        if let Some(range) = auto_range(&shown.frame, cut_percent) {
            self.view.depth_range = range;
        }
    }

    /// "Frame all": fits centre and size to `scene`'s bounds (direction and up stay).
    pub(crate) fn frame_all(&mut self, scene: &Scene) {
        self.view = navigate::frame_all(scene, &self.view);
    }

    /// Restores the file's camera (`file_view`), keeping the image size and the depth range.
    pub(crate) fn reset_view(&mut self, file_view: &View) {
        self.view = View {
            width_px: self.view.width_px,
            height_px: self.view.height_px,
            depth_range: self.view.depth_range,
            ..*file_view
        };
    }

    /// Restores the depth range the file's view (`file_view`) started with.
    pub(crate) fn reset_depth(&mut self, file_view: &View) {
        self.view.depth_range = file_view.depth_range;
    }

    /// Back to the view before the last change (a burst of changes is one step).
    pub(crate) fn undo(&mut self) -> Option<Status> {
        let view = self.history.undo(&self.view);
        self.step_to(view, "nothing to undo")
    }

    /// Forward again after an undo.
    pub(crate) fn redo(&mut self) -> Option<Status> {
        let view = self.history.redo(&self.view);
        self.step_to(view, "nothing to redo")
    }

    /// Goes to `view`, an undo or redo step; says `none` when there was no step to take.
    fn step_to(&mut self, view: Option<View>, none: &str) -> Option<Status> {
        match view {
            Some(view) => {
                self.view = view;
                None
            }
            None => Some(Status::info(none)),
        }
    }

    /// Names the current view among `saved`'s named views of the scene file at `path`.
    pub(crate) fn name_view(
        &self,
        saved: &mut SceneViews,
        path: Option<&Path>,
        name: &str,
    ) -> Status {
        let Some(named) = named_views(saved, path) else {
            return Status::error("views are kept per scene file: open one first");
        };
        named.retain(|existing| existing.name != name);
        named.push(NamedView {
            name: name.to_owned(),
            view: SavedView::of(&self.view),
        });
        Status::info(format!("named the view '{name}'"))
    }

    /// Goes to the named view at `index` of the scene file at `path`.
    pub(crate) fn go_to_view(&mut self, saved: &mut SceneViews, path: Option<&Path>, index: usize) {
        if let Some(named) = named_views(saved, path).and_then(|views| views.get(index).cloned()) {
            self.view = named.view.applied_to(&self.view);
        }
    }
}

/// The named views of the scene file at `path` among `saved`, for changing; `None` for a scene
/// with no file.
fn named_views<'a>(
    saved: &'a mut SceneViews,
    path: Option<&Path>,
) -> Option<&'a mut Vec<NamedView>> {
    Some(saved.named.entry(SceneViews::key(path?)).or_default())
}

/// Forgets the named view at `index` of the scene file at `path`.
pub(crate) fn forget_view(saved: &mut SceneViews, path: Option<&Path>, index: usize) {
    if let Some(named) = named_views(saved, path)
        && index < named.len()
    {
        named.remove(index);
    }
}
