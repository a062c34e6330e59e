//! The shortcuts and gestures overlay (F1 or ?): every key and pointer gesture, and the
//! difference between the camera's zoom (a new render of a smaller part of the scene) and the
//! magnifier (the same pixels, enlarged).

use egui::RichText;

/// Title of the overlay (tests find it by this).
pub(crate) const HELP_TITLE: &str = "Shortcuts and gestures";

/// The rows of the overlay: what to press or do, and what it does.
pub(crate) const SHORTCUTS: [(&str, &str); 26] = [
    ("drag", "pan the camera (the picture follows the pointer)"),
    (
        "wheel",
        "zoom the camera at the pointer: a new render of a smaller or larger part of the scene",
    ),
    ("right-drag, Shift+drag", "orbit around the scene's centre"),
    (
        "Ctrl+wheel, pinch",
        "magnify the images themselves (the same pixels enlarged, no new render; a pixel grid from 8×)",
    ),
    ("Ctrl+drag, middle-drag", "move the magnified part"),
    ("1, Ctrl+0", "magnifier back to the whole image"),
    (
        "click",
        "pin the pixel (the pin stays on the point pinned while the view moves)",
    ),
    ("Escape", "unpin"),
    (
        "B",
        "comparing: flip between the render and the compared image (A/B)",
    ),
    ("Shift+B", "comparing: the difference heat map on and off"),
    ("arrows", "move the camera"),
    ("Shift+arrows", "orbit by 5°"),
    ("+, -", "zoom the camera at the centre"),
    ("F", "frame all: fit the whole scene"),
    (
        "Home",
        "reset view: the file's camera (the depth range stays)",
    ),
    ("D", "reset the depth range to the file's"),
    ("A", "auto range: fit the depth range to the visible t"),
    (
        "Ctrl+Z",
        "undo a view change (a drag or a burst of slider moves is one step)",
    ),
    ("Ctrl+Shift+Z, Ctrl+Y", "redo"),
    ("Ctrl+O", "open a scene"),
    (
        "Ctrl+S",
        "export (to the typed path where no file dialog can be shown)",
    ),
    ("Ctrl+R", "reload the scene file"),
    (
        "Shift or Alt while dragging a slider",
        "fine: a tenth of the speed",
    ),
    (
        "wheel on a focused slider",
        "nudge its value (Shift: finer)",
    ),
    (
        "drag a line on the histogram",
        "move that end of the depth range",
    ),
    ("F1, ?", "this overlay"),
];

/// The overlay; returns whether it stays open.
pub(crate) fn help_ui(ctx: &egui::Context) -> bool {
    let mut open = true;
    egui::Window::new(HELP_TITLE)
        .open(&mut open)
        .collapsible(false)
        .resizable(true)
        .default_width(560.0)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| {
                egui::Grid::new("shortcuts")
                    .num_columns(2)
                    .striped(true)
                    .show(ui, |ui| {
                        for (keys, what) in SHORTCUTS {
                            ui.label(RichText::new(keys).strong());
                            ui.label(what);
                            ui.end_row();
                        }
                    });
            });
        });
    let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape));
    open && !escape
}
