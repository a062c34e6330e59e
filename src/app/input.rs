//! Input that is not a widget's: keyboard shortcuts, files dropped on the window, the watched
//! file changing, navigation from the keyboard, and pointer gestures on the images — all turned
//! into [`crate::app::navigate`] calls or [`Action`]s.

use egui::{Key, KeyboardShortcut, Modifiers};
use glam::DVec2;

use super::ViewerApp;
use super::actions::Action;
use super::dialogs::DialogKind;
use super::reload::WatchState;
use super::ui::gestures::{ImageGestures, ORBIT_RAD_PER_POINT};
use crate::app::navigate;
use crate::app::probe::point_of_probe;

/// Keyboard pan step, as a fraction of the image's shorter side.
pub const KEY_PAN_FRACTION: f64 = 0.1;

/// Keyboard orbit step (Shift+arrow), radians.
pub const KEY_ORBIT_RAD: f64 = std::f64::consts::PI / 36.0;

/// Keyboard zoom step: `+` divides the size by this, `-` multiplies it.
pub const KEY_ZOOM_FACTOR: f64 = 1.25;

/// The keys navigation listens to.
const NAVIGATION_KEYS: [Key; 14] = [
    Key::ArrowLeft,
    Key::ArrowRight,
    Key::ArrowUp,
    Key::ArrowDown,
    Key::Plus,
    Key::Equals,
    Key::Minus,
    Key::F,
    Key::Home,
    Key::A,
    Key::D,
    Key::Num1,
    Key::Escape,
    Key::B,
];

impl ViewerApp {
    /// Shortcuts (Ctrl+O, Ctrl+S, Ctrl+R), dropped files, the watched file, and navigation keys.
    pub(super) fn handle_input(&mut self, ctx: &egui::Context) {
        let command_shift = Modifiers::COMMAND | Modifiers::SHIFT;
        // The more specific shortcut first: Ctrl+Shift+Z before Ctrl+Z.
        let shortcuts = [
            (command_shift, Key::Z, Action::Redo),
            (Modifiers::COMMAND, Key::Z, Action::Undo),
            (Modifiers::COMMAND, Key::Y, Action::Redo),
            (
                Modifiers::COMMAND,
                Key::O,
                Action::OpenDialog(DialogKind::Open),
            ),
            (
                Modifiers::COMMAND,
                Key::S,
                Action::OpenDialog(DialogKind::Export),
            ),
            (Modifiers::COMMAND, Key::R, Action::Reload),
            (Modifiers::COMMAND, Key::Num0, Action::ResetMagnifier),
            (Modifiers::NONE, Key::F1, Action::ToggleHelp),
        ];
        let (pressed, dropped) = ctx.input_mut(|input| {
            let pressed: Vec<Action> = shortcuts
                .into_iter()
                .filter(|(modifiers, key, _)| {
                    input.consume_shortcut(&KeyboardShortcut::new(*modifiers, *key))
                })
                .map(|(_, _, action)| action)
                .collect();
            let dropped = input.raw.dropped_files.first().cloned();
            (pressed, dropped)
        });
        for action in pressed {
            self.apply(action);
        }
        // The watcher wakes the window at each change; while the file settles, the window wakes
        // itself when it will have (no input need come).
        match self
            .scene
            .watcher
            .as_ref()
            .map(super::reload::FileWatcher::poll)
        {
            Some(WatchState::Changed) => self.reload(),
            Some(WatchState::Settling(wait)) => ctx.request_repaint_after(wait),
            _ => {}
        }
        if let Some(file) = dropped {
            self.open_dropped(file);
        }
        self.navigation_keys(ctx);
    }

    /// Keyboard navigation while no text field or slider has the keyboard: arrows move the
    /// camera, Shift+arrows orbit, `+`/`-` zoom at the image centre, F frames all, Home resets,
    /// A fits the depth range, Escape unpins the probe, B flips between the render and the compared
    /// image, Shift+B shows the difference.
    fn navigation_keys(&mut self, ctx: &egui::Context) {
        if ctx.memory(|memory| memory.focused().is_some()) {
            return;
        }
        let (shift, pressed, question) = ctx.input(|input| {
            let pressed: Vec<Key> = NAVIGATION_KEYS
                .into_iter()
                .filter(|&key| input.key_pressed(key))
                .collect();
            let question = input
                .events
                .iter()
                .any(|event| matches!(event, egui::Event::Text(text) if text == "?"));
            (input.modifiers.shift, pressed, question)
        });
        if question {
            self.apply(Action::ToggleHelp);
        }
        let (width, height) = (
            f64::from(self.viewing.view.width_px),
            f64::from(self.viewing.view.height_px),
        );
        let step_px = KEY_PAN_FRACTION * width.min(height);
        let centre_px = DVec2::new(0.5 * width, 0.5 * height);
        for key in pressed {
            let arrow = match key {
                Key::ArrowLeft => Some(DVec2::NEG_X),
                Key::ArrowRight => Some(DVec2::X),
                Key::ArrowUp => Some(DVec2::Y),
                Key::ArrowDown => Some(DVec2::NEG_Y),
                _ => None,
            };
            match (key, arrow) {
                (_, Some(direction)) if shift => {
                    let turn = direction * KEY_ORBIT_RAD;
                    self.orbit(turn.x, turn.y);
                }
                // The camera moves along the arrow: the picture moves the other way.
                (_, Some(direction)) => {
                    self.viewing.view = navigate::pan(&self.viewing.view, -direction * step_px);
                }
                (Key::Plus | Key::Equals, _) => {
                    self.viewing.view =
                        navigate::zoom_at(&self.viewing.view, 1.0 / KEY_ZOOM_FACTOR, centre_px);
                }
                (Key::Minus, _) => {
                    self.viewing.view =
                        navigate::zoom_at(&self.viewing.view, KEY_ZOOM_FACTOR, centre_px);
                }
                (Key::F, _) => self.apply(Action::FrameAll),
                (Key::Home, _) => self.apply(Action::ResetView),
                (Key::A, _) => self.apply(Action::AutoRange),
                (Key::D, _) => self.apply(Action::ResetDepth),
                (Key::Num1, _) => self.apply(Action::ResetMagnifier),
                (Key::B, _) if shift => self.apply(Action::CompareDifference),
                (Key::B, _) => self.apply(Action::CompareFlip),
                (Key::Escape, _) if self.panels.help_open => self.panels.help_open = false,
                (Key::Escape, _) => self.apply(Action::Unpin),
                _ => {}
            }
        }
    }

    /// Applies pointer gestures on the images: pan, orbit, zoom, hover and pin.
    pub(crate) fn apply_gestures(&mut self, gestures: &ImageGestures) {
        if gestures.pan_px != DVec2::ZERO {
            self.viewing.view = navigate::pan(&self.viewing.view, gestures.pan_px);
        }
        if gestures.orbit_points != DVec2::ZERO {
            let turn = gestures.orbit_points * ORBIT_RAD_PER_POINT;
            self.orbit(turn.x, turn.y);
        }
        if let Some((factor, anchor_px)) = gestures.zoom {
            self.viewing.view = navigate::zoom_at(&self.viewing.view, factor, anchor_px);
        }
        if let Some(size_px) = self
            .frames
            .shown
            .as_ref()
            .map(|s| [s.frame.width_px, s.frame.height_px])
        {
            if let Some((factor, anchor_px)) = gestures.magnify {
                self.viewing.magnifier.zoom_at(factor, anchor_px, size_px);
            }
            if gestures.magnifier_pan_px != DVec2::ZERO {
                self.viewing
                    .magnifier
                    .pan(gestures.magnifier_pan_px, size_px);
            }
        }
        self.viewing.probe.hover_px = gestures.hover_px;
        if let Some(px) = gestures.clicked_px
            && let Some(probe) = self.probe_at(px)
        {
            // The point itself is pinned, so the pin stays on it while the view moves.
            self.viewing.probe.pinned_world = Some(point_of_probe(&probe));
        }
        if gestures.unpin {
            self.apply(Action::Unpin);
        }
        if gestures.trace {
            self.open_trace();
        }
    }

    /// Orbits around the scene's centre: `yaw_rad` as a drag to the right, `pitch_rad` up.
    fn orbit(&mut self, yaw_rad: f64, pitch_rad: f64) {
        let pivot = navigate::orbit_pivot(&self.scene.loaded.scene);
        self.viewing.view = navigate::orbit(&self.viewing.view, pivot, yaw_rad, pitch_rad);
    }
}
