//! Views the viewer keeps: the **history** of view changes for undo and redo (a burst of slider
//! or drag changes is one step), the **named views** (bookmarks) of each scene file, and the view
//! each scene file was **last seen in**, restored when it is opened again. A view here is the
//! camera and the depth range; the image size is the window's.

use std::collections::BTreeMap;
use std::path::Path;
use web_time::{Duration, Instant};

use glam::DVec3;

use crate::render::View;
use crate::render::depth_map::DepthRange;

/// How long a view must stay unchanged to become a step of the history.
pub const HISTORY_QUIET: Duration = Duration::from_millis(400);

/// Steps the history keeps.
const HISTORY_STEPS: usize = 200;

/// A camera and a depth range, stored with plain numbers (the settings file is text).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SavedView {
    /// Camera centre.
    pub center: [f64; 3],
    /// View direction.
    pub direction: [f64; 3],
    /// Up.
    pub up: [f64; 3],
    /// Screen size, world units.
    pub size: f64,
    /// Depth range (t near, t far).
    pub depth: [f64; 2],
}

impl SavedView {
    /// The camera and depth range of `view`.
    pub fn of(view: &View) -> Self {
        Self {
            center: view.center_world.to_array(),
            direction: view.direction_world.to_array(),
            up: view.up_world.to_array(),
            size: view.size_world,
            depth: [view.depth_range.min_t, view.depth_range.max_t],
        }
    }

    /// `view` with this camera and depth range (its image size kept).
    pub fn applied_to(&self, view: &View) -> View {
        View {
            center_world: DVec3::from_array(self.center),
            direction_world: DVec3::from_array(self.direction),
            up_world: DVec3::from_array(self.up),
            size_world: self.size,
            depth_range: DepthRange::new(self.depth[0], self.depth[1]),
            ..*view
        }
    }
}

/// A view the user named.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct NamedView {
    /// The name given.
    pub name: String,
    /// The view.
    pub view: SavedView,
}

/// What the viewer keeps per scene file (keyed by the file's path as opened).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct SceneViews {
    /// The view each file was last seen in.
    pub last: BTreeMap<String, SavedView>,
    /// The named views of each file.
    pub named: BTreeMap<String, Vec<NamedView>>,
}

impl SceneViews {
    /// The key of a scene file.
    pub fn key(path: &Path) -> String {
        path.display().to_string()
    }

    /// Remembers `view` as the one the scene from `path` is in, to restore when it is opened
    /// again (a scene from no file has none).
    pub fn remember(&mut self, path: Option<&Path>, view: &View) {
        if let Some(path) = path {
            self.last.insert(Self::key(path), SavedView::of(view));
        }
    }
}

/// Undo and redo of view changes.
#[derive(Debug, Clone, Default)]
pub struct History {
    /// Earlier views, the latest last.
    past: Vec<SavedView>,
    /// Views undone, the latest undone last.
    future: Vec<SavedView>,
    /// The view the history last recorded (the current step).
    recorded: Option<SavedView>,
    /// When the view last changed, and to what.
    changed: Option<(Instant, SavedView)>,
}

impl History {
    /// Starts over at `view` (another scene was opened).
    pub fn reset(&mut self, view: &View) {
        *self = Self {
            recorded: Some(SavedView::of(view)),
            ..Self::default()
        };
    }

    /// Notes the current view; once it has stayed unchanged for [`HISTORY_QUIET`] after a
    /// change, the view before the change becomes a step to undo to.
    pub fn observe(&mut self, view: &View, now: Instant) {
        let current = SavedView::of(view);
        // A change that has been quiet long enough is a step, even if no frame came to see it
        // settle (an idle window draws nothing): the next change must not replace it.
        if let Some((at, pending)) = self.changed
            && pending != current
            && now.duration_since(at) >= HISTORY_QUIET
        {
            self.commit(pending);
        }
        let Some(recorded) = self.recorded else {
            self.recorded = Some(current);
            return;
        };
        if current == recorded {
            self.changed = None;
            return;
        }
        match self.changed {
            Some((_, last)) if last != current => self.changed = Some((now, current)),
            None => self.changed = Some((now, current)),
            Some((at, _)) if now.duration_since(at) >= HISTORY_QUIET => self.commit(current),
            Some(_) => {}
        }
    }

    /// A one-shot change (Home, frame all, a named view, a fitted depth range): the view before
    /// it, whether settled or not, and the view after it are each a step of their own.
    pub fn one_shot(&mut self, before: &View, after: &View) {
        let (before, after) = (SavedView::of(before), SavedView::of(after));
        if self.recorded != Some(before) {
            self.commit(before);
        }
        if after != before {
            self.commit(after);
        }
    }

    /// Makes `current` a step now: the recorded view goes to the past, redo is forgotten.
    fn commit(&mut self, current: SavedView) {
        if let Some(recorded) = self.recorded.replace(current) {
            self.past.push(recorded);
            if self.past.len() > HISTORY_STEPS {
                self.past.remove(0);
            }
        }
        self.future.clear();
        self.changed = None;
    }

    /// The view to go back to from `view`, if any (a change still settling counts as a step).
    pub fn undo(&mut self, view: &View) -> Option<View> {
        let current = SavedView::of(view);
        if self.recorded != Some(current) {
            self.commit(current);
        }
        let previous = self.past.pop()?;
        if let Some(recorded) = self.recorded.replace(previous) {
            self.future.push(recorded);
        }
        Some(previous.applied_to(view))
    }

    /// The view undone last, if any.
    pub fn redo(&mut self, view: &View) -> Option<View> {
        let next = self.future.pop()?;
        if let Some(recorded) = self.recorded.replace(next) {
            self.past.push(recorded);
        }
        Some(next.applied_to(view))
    }

    /// Whether there is something to undo from `view`.
    pub fn can_undo(&self, view: &View) -> bool {
        !self.past.is_empty() || self.recorded != Some(SavedView::of(view))
    }

    /// Whether there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.future.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn view(x: f64) -> View {
        View {
            center_world: DVec3::new(x, 0.0, 10.0),
            direction_world: DVec3::NEG_Z,
            up_world: DVec3::Y,
            size_world: 5.0,
            width_px: 10,
            height_px: 10,
            depth_range: DepthRange::new(8.0, 12.0),
        }
    }

    #[test]
    fn a_burst_of_changes_is_one_step() {
        let start = Instant::now();
        let mut history = History::default();
        history.reset(&view(0.0));
        // A drag: many views 20 ms apart, then still.
        for step in 1..=10u32 {
            let at = start + Duration::from_millis(20 * u64::from(step));
            history.observe(&view(f64::from(step)), at);
        }
        history.observe(&view(10.0), start + Duration::from_millis(800));
        // Another change, still settling when undone.
        history.observe(&view(20.0), start + Duration::from_millis(900));
        assert_eq!(history.undo(&view(20.0)), Some(view(10.0)));
        assert_eq!(history.undo(&view(10.0)), Some(view(0.0)));
        assert_eq!(history.undo(&view(0.0)), None);
        assert_eq!(history.redo(&view(0.0)), Some(view(10.0)));
        assert_eq!(history.redo(&view(10.0)), Some(view(20.0)));
        assert_eq!(history.redo(&view(20.0)), None);
    }

    #[test]
    fn a_change_left_alone_is_a_step_even_when_no_frame_saw_it_settle() {
        // Drag, then nothing (an idle window draws no frame), then Home much later.
        let start = Instant::now();
        let mut history = History::default();
        history.reset(&view(0.0));
        history.observe(&view(5.0), start);
        history.observe(&view(0.0), start + Duration::from_secs(3));
        assert_eq!(history.undo(&view(0.0)), Some(view(5.0)));
        assert_eq!(history.undo(&view(5.0)), Some(view(0.0)));
        assert_eq!(history.redo(&view(0.0)), Some(view(5.0)));
    }

    #[test]
    fn a_one_shot_change_keeps_the_unsettled_view_before_it() {
        // Arrow keys (a change still settling), then Home at once.
        let start = Instant::now();
        let mut history = History::default();
        history.reset(&view(0.0));
        history.observe(&view(1.0), start);
        history.observe(&view(2.0), start + Duration::from_millis(50));
        history.one_shot(&view(2.0), &view(0.0));
        history.observe(&view(0.0), start + Duration::from_millis(60));
        assert_eq!(history.undo(&view(0.0)), Some(view(2.0)));
        assert_eq!(history.undo(&view(2.0)), Some(view(0.0)));
        assert_eq!(history.undo(&view(0.0)), None);
        assert_eq!(history.redo(&view(0.0)), Some(view(2.0)));
        assert_eq!(history.redo(&view(2.0)), Some(view(0.0)));
    }
}
