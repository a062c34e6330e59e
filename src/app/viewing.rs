//! What the user does to the view as a whole: auto range (and the "follow" mode that keeps
//! doing it), frame all, reset the camera or the depth range, undo and redo, and the named views
//! of the open scene file.

use std::path::Path;

use glam::{DVec2, DVec3};

use super::actions::Action;
use super::loaded_scene::LoadedScene;
use super::probe::pixel_of_point;
use super::render_requests::Shown;
use super::saved_views::{History, NamedView, SavedView, SceneViews};
use super::settings::DepthDisplay;
use super::status::Status;
use super::ui::magnifier::Magnifier;
use crate::app::depth_stats::auto_range;
use crate::app::navigate::{self, Navigation};
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
    /// Lets the history see the view as it is now (a burst of changes is one step).
    pub(crate) fn observe(&mut self) {
        self.history.observe(&self.view, web_time::Instant::now());
    }

    /// A scene was opened (its file's camera already in `view`): in the view it was `last` seen
    /// in, if it was, with a history that starts there, the whole image and nothing pinned.
    pub(crate) fn opened(&mut self, last: Option<&SavedView>) {
        if let Some(last) = last {
            self.view = last.applied_to(&self.view);
        }
        self.history.reset(&self.view);
        self.magnifier = Magnifier::default();
        self.probe.pinned_world = None;
    }

    /// Carries out `navigation` on `scene`; the magnifier moves over the frame on screen,
    /// `shown_size_px` (none: it stays).
    pub(crate) fn navigate(
        &mut self,
        navigation: Navigation,
        scene: &Scene,
        shown_size_px: Option<[u32; 2]>,
    ) {
        match (navigation, shown_size_px) {
            (Navigation::Pan(px), _) => self.view = navigate::pan(&self.view, px),
            (Navigation::Orbit(turn_rad), _) => {
                let pivot = navigate::orbit_pivot(scene);
                self.view = navigate::orbit(&self.view, pivot, turn_rad.x, turn_rad.y);
            }
            (Navigation::ZoomAt(factor, anchor_px), _) => {
                self.view = navigate::zoom_at(&self.view, factor, anchor_px);
            }
            (Navigation::Magnify(factor, anchor_px), Some(size_px)) => {
                self.magnifier.zoom_at(factor, anchor_px, size_px);
            }
            (Navigation::PanMagnifier(px), Some(size_px)) => self.magnifier.pan(px, size_px),
            (Navigation::Hover(px), _) => self.probe.hover_px = px,
            (Navigation::Magnify(..) | Navigation::PanMagnifier(_), None) => {}
        }
    }

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
    /// the open scene) is of a changed camera, fits the depth range to it (`depth`'s cut at each
    /// end). "Follow" off in `depth` forgets the camera last followed.
    pub(crate) fn follow_depth(
        &mut self,
        depth: &DepthDisplay,
        shown: Option<&Shown>,
        current_epoch: u64,
    ) {
        let (follow, cut_percent) = (depth.follow, depth.auto_cut_percent);
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

    /// Where the pinned point is on the frame on screen, `shown` (image pixels, y up), if it is
    /// in view.
    pub(crate) fn pinned_px(&self, shown: Option<&Shown>) -> Option<DVec2> {
        let shown = shown?;
        let px = pixel_of_point(&shown.view, self.probe.pinned_world?)?;
        let inside = px.x >= 0.0
            && px.y >= 0.0
            && px.x < f64::from(shown.view.width_px)
            && px.y < f64::from(shown.view.height_px);
        inside.then_some(px)
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

/// What the view's actions read besides the view: the open scene, the frame on screen, the named
/// views the settings keep, and the auto range's cut at each end (percent).
pub(crate) struct ViewInputs<'a> {
    pub(crate) loaded: &'a LoadedScene,
    pub(crate) shown: Option<&'a Shown>,
    pub(crate) views: &'a mut SceneViews,
    pub(crate) auto_cut_percent: f64,
}

impl Viewing {
    /// Carries out `action` where it is the view's (navigation, resets, ranges, history, named
    /// views, unpinning, the magnifier): what the status bar says. Any other action is not the
    /// view's, and does nothing here.
    pub(crate) fn carry_out(&mut self, action: Action, inputs: ViewInputs<'_>) -> Option<Status> {
        let ViewInputs {
            loaded,
            shown,
            views,
            auto_cut_percent,
        } = inputs;
        let path = loaded.path.as_deref();
        match action {
            Action::AutoRange => {
                return self.auto_range(shown.map(|shown| &*shown.frame), auto_cut_percent);
            }
            Action::Undo => return self.undo(),
            Action::Redo => return self.redo(),
            Action::NameView(name) => return Some(self.name_view(views, path, &name)),
            Action::FrameAll => self.frame_all(&loaded.scene),
            Action::ResetView => self.reset_view(&loaded.file_view),
            Action::ResetDepth => self.reset_depth(&loaded.file_view),
            Action::UseDepthRange(range) => self.view.depth_range = range,
            Action::GoToView(index) => self.go_to_view(views, path, index),
            Action::ForgetView(index) => forget_view(views, path, index),
            Action::Navigate(navigation) => {
                let size_px = shown.map(|s| [s.frame.width_px, s.frame.height_px]);
                self.navigate(navigation, &loaded.scene, size_px);
            }
            Action::Unpin => self.probe.pinned_world = None,
            Action::ResetMagnifier => self.magnifier = Magnifier::default(),
            _ => {}
        }
        None
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
fn forget_view(saved: &mut SceneViews, path: Option<&Path>, index: usize) {
    if let Some(named) = named_views(saved, path)
        && index < named.len()
    {
        named.remove(index);
    }
}
