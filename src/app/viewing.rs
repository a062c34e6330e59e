//! What the user does to the view as a whole: auto range (and the "follow" mode that keeps
//! doing it), frame all, reset the camera or the depth range, undo and redo, and the named views
//! of the open scene file.

use glam::{DVec2, DVec3};

use super::ViewerApp;
use super::saved_views::{History, NamedView, SavedView, SceneViews};
use super::status::Status;
use super::ui::magnifier::Magnifier;
use crate::explore::depth_stats::auto_range;
use crate::explore::navigate;
use crate::render::View;

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

impl ViewerApp {
    /// "Auto range": fits the depth range to the t visible in the frame on screen, ignoring
    /// the settings' percentage at each end. Says so when no sphere is visible.
    pub fn auto_range(&mut self) {
        let cut = self.settings.depth.auto_cut_percent;
        match self
            .frames
            .shown
            .as_ref()
            .and_then(|s| auto_range(&s.frame, cut))
        {
            Some(range) => self.viewing.view.depth_range = range,
            None => self.status = Some(Status::info("auto range: no sphere is visible")),
        }
    }

    /// "Follow": once a frame of a changed camera is on screen, fits the depth range to it.
    pub(super) fn follow_depth(&mut self) {
        if !self.settings.depth.follow {
            self.viewing.followed = None;
            return;
        }
        let Some(shown) = &self.frames.shown else {
            return;
        };
        let camera = SavedView::of(&View {
            depth_range: crate::render::depth_map::DepthRange::new(0.0, 0.0),
            ..shown.view
        });
        if self.viewing.followed == Some(camera) || shown.scene_epoch != self.scene.epoch {
            return;
        }
        self.viewing.followed = Some(camera);
        let cut = self.settings.depth.auto_cut_percent;
        if let Some(range) = auto_range(&shown.frame, cut) {
            self.viewing.view.depth_range = range;
        }
    }

    /// "Frame all": fits centre and size to the scene's bounds (direction and up stay).
    pub fn frame_all(&mut self) {
        self.viewing.view = navigate::frame_all(&self.scene.loaded.scene, &self.viewing.view);
    }

    /// Restores the file's camera, keeping the image size and the depth range.
    pub(crate) fn reset_view(&mut self) {
        self.viewing.view = View {
            width_px: self.viewing.view.width_px,
            height_px: self.viewing.view.height_px,
            depth_range: self.viewing.view.depth_range,
            ..self.scene.loaded.file_view
        };
    }

    /// Restores the depth range the file's view started with.
    pub(crate) fn reset_depth(&mut self) {
        self.viewing.view.depth_range = self.scene.loaded.file_view.depth_range;
    }

    /// Back to the view before the last change (a burst of changes is one step).
    pub(crate) fn undo(&mut self) {
        match self.viewing.history.undo(&self.viewing.view) {
            Some(view) => self.viewing.view = view,
            None => self.status = Some(Status::info("nothing to undo")),
        }
    }

    /// Forward again after an undo.
    pub(crate) fn redo(&mut self) {
        match self.viewing.history.redo(&self.viewing.view) {
            Some(view) => self.viewing.view = view,
            None => self.status = Some(Status::info("nothing to redo")),
        }
    }

    /// The named views of the open scene file, for changing.
    fn named_views(&mut self) -> Option<&mut Vec<NamedView>> {
        let key = SceneViews::key(self.scene.loaded.path.as_ref()?);
        Some(self.settings.views.named.entry(key).or_default())
    }

    /// Names the current view.
    pub(crate) fn name_view(&mut self, name: &str) {
        let name = name.to_owned();
        let view = SavedView::of(&self.viewing.view);
        let Some(named) = self.named_views() else {
            self.status = Some(Status::error(
                "views are kept per scene file: open one first",
            ));
            return;
        };
        named.retain(|existing| existing.name != name);
        named.push(NamedView {
            name: name.clone(),
            view,
        });
        self.status = Some(Status::info(format!("named the view '{name}'")));
    }

    /// Goes to the named view at `index`.
    pub(crate) fn go_to_view(&mut self, index: usize) {
        let current = self.viewing.view;
        if let Some(named) = self
            .named_views()
            .and_then(|views| views.get(index).cloned())
        {
            self.viewing.view = named.view.applied_to(&current);
        }
    }

    /// Forgets the named view at `index`.
    pub(crate) fn forget_view(&mut self, index: usize) {
        if let Some(named) = self.named_views()
            && index < named.len()
        {
            named.remove(index);
        }
    }
}
