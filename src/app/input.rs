//! Input that is not a widget's: keyboard shortcuts, files dropped on the window, the watched
//! file changing, navigation from the keyboard, and pointer gestures on the images, all read into
//! [`Action`]s (navigation as [`Navigation`]s, which [`super::viewing::Viewing`] carries out).

use egui::{Key, KeyboardShortcut, Modifiers};
use glam::DVec2;

use super::actions::Action;
use super::compare::dropped_image_kind;
use super::dialogs::DialogKind;
use super::navigate::Navigation;
use super::reload::{FileWatcher, WatchState};
use super::status::Status;
use super::ui::gestures::{ImageGestures, ORBIT_RAD_PER_POINT};
use crate::render::View;

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

/// Ctrl+plus and Ctrl+minus zoom the camera in `ctx`'s window; the interface keeps its size.
pub(super) fn claim_zoom_keys(ctx: &egui::Context) {
    ctx.options_mut(|options| options.zoom_with_keyboard = false);
}

/// What the window's input asks for this frame.
pub(super) struct Input {
    /// Shortcuts, the watched file's reload and navigation keys, in that order.
    pub(super) actions: Vec<Action>,
    /// The files dropped on the window (opened by the platform's seam): a scene, or their
    /// images (two at once are judged together).
    pub(super) dropped: Vec<egui::DroppedFileHandle>,
    /// Why the images dropped were not compared: more than two came at once
    /// ([`at_most_a_pair`]).
    pub(super) refused: Option<Status>,
}

/// Reads the shortcuts (Ctrl+O, Ctrl+S, Ctrl+R), a dropped file, the watched file and the
/// navigation keys; `help_open` makes Escape close the shortcuts overlay, and `view` sizes the
/// keyboard's pan and zoom steps.
pub(super) fn read(
    ctx: &egui::Context,
    watcher: Option<&FileWatcher>,
    help_open: bool,
    view: &View,
) -> Input {
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
    let (mut actions, dropped) = ctx.input_mut(|input| {
        let pressed: Vec<Action> = shortcuts
            .into_iter()
            .filter(|(modifiers, key, _)| {
                input.consume_shortcut(&KeyboardShortcut::new(*modifiers, *key))
            })
            .map(|(_, _, action)| action)
            .collect();
        let dropped = input.raw.dropped_files.clone();
        (pressed, dropped)
    });
    // The watcher wakes the window at each change; while the file settles, the window wakes
    // itself when it will have (no input need come).
    match watcher.map(FileWatcher::poll) {
        Some(WatchState::Changed) => actions.push(Action::Reload),
        Some(WatchState::Settling(wait)) => ctx.request_repaint_after(wait),
        _ => {}
    }
    actions.extend(navigation_keys(ctx, help_open, view));
    let (dropped, refused) = at_most_a_pair(dropped);
    Input {
        actions,
        dropped,
        refused,
    }
}

/// The files of one drop that are opened: all of them when at most two are images (`.png`,
/// `.tga`: one colour and one depth image are judged together); else only the others (a scene),
/// with the error that says why no image was compared: which of three or more images would make
/// the pair is the user's to say, never guessed.
fn at_most_a_pair(
    dropped: Vec<egui::DroppedFileHandle>,
) -> (Vec<egui::DroppedFileHandle>, Option<Status>) {
    let name = |file: &egui::DroppedFileHandle| {
        let name = file.path().file_name().unwrap_or_default();
        name.to_string_lossy().into_owned()
    };
    let is_image = |file: &egui::DroppedFileHandle| dropped_image_kind(&name(file)).is_some();
    let images: Vec<String> = dropped.iter().filter(|f| is_image(f)).map(name).collect();
    if images.len() <= 2 {
        return (dropped, None);
    }
    let refused = Status::error(format!(
        "{} images dropped at once ({}): none was compared; the viewer judges one colour image \
         and its depth image together: drop those two, or one image alone",
        images.len(),
        images.join(", ")
    ));
    let others = dropped.into_iter().filter(|file| !is_image(file)).collect();
    (others, Some(refused))
}

/// Keyboard navigation while no text field or slider has the keyboard: arrows move the camera,
/// Shift+arrows orbit, `+`/`-` zoom at the image centre, F frames all, Home resets, A fits the
/// depth range, Escape unpins the probe (or closes the shortcuts overlay), B flips between the
/// render and the compared image, Shift+B shows the difference.
fn navigation_keys(ctx: &egui::Context, help_open: bool, view: &View) -> Vec<Action> {
    if ctx.memory(|memory| memory.focused().is_some()) {
        return Vec::new();
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
    let mut actions = Vec::new();
    if question {
        actions.push(Action::ToggleHelp);
    }
    let (width, height) = (f64::from(view.width_px), f64::from(view.height_px));
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
        let action = match (key, arrow) {
            (_, Some(direction)) if shift => {
                Action::Navigate(Navigation::Orbit(direction * KEY_ORBIT_RAD))
            }
            // The camera moves along the arrow: the picture moves the other way.
            (_, Some(direction)) => Action::Navigate(Navigation::Pan(-direction * step_px)),
            (Key::Plus | Key::Equals, _) => {
                Action::Navigate(Navigation::ZoomAt(1.0 / KEY_ZOOM_FACTOR, centre_px))
            }
            (Key::Minus, _) => Action::Navigate(Navigation::ZoomAt(KEY_ZOOM_FACTOR, centre_px)),
            (Key::F, _) => Action::FrameAll,
            (Key::Home, _) => Action::ResetView,
            (Key::A, _) => Action::AutoRange,
            (Key::D, _) => Action::ResetDepth,
            (Key::Num1, _) => Action::ResetMagnifier,
            (Key::B, _) if shift => Action::CompareDifference,
            (Key::B, _) => Action::CompareFlip,
            (Key::Escape, _) if help_open => Action::ToggleHelp,
            (Key::Escape, _) => Action::Unpin,
            _ => continue,
        };
        actions.push(action);
    }
    actions
}

/// The pointer gestures made on the images, as actions: pan, orbit, zoom, the magnifier, hover,
/// pin, unpin and trace.
pub(super) fn gesture_actions(gestures: &ImageGestures) -> Vec<Action> {
    let mut navigation = Vec::new();
    if gestures.pan_px != DVec2::ZERO {
        navigation.push(Navigation::Pan(gestures.pan_px));
    }
    if gestures.orbit_points != DVec2::ZERO {
        navigation.push(Navigation::Orbit(
            gestures.orbit_points * ORBIT_RAD_PER_POINT,
        ));
    }
    if let Some((factor, anchor_px)) = gestures.zoom {
        navigation.push(Navigation::ZoomAt(factor, anchor_px));
    }
    if let Some((factor, anchor_px)) = gestures.magnify {
        navigation.push(Navigation::Magnify(factor, anchor_px));
    }
    if gestures.magnifier_pan_px != DVec2::ZERO {
        navigation.push(Navigation::PanMagnifier(gestures.magnifier_pan_px));
    }
    navigation.push(Navigation::Hover(gestures.hover_px));
    let mut actions: Vec<Action> = navigation.into_iter().map(Action::Navigate).collect();
    if let Some(px) = gestures.clicked_px {
        actions.push(Action::Pin(px));
    }
    if gestures.unpin {
        actions.push(Action::Unpin);
    }
    if gestures.trace {
        actions.push(Action::Trace);
    }
    actions
}
