//! The shortcuts and gestures overlay (F1 or ?): every key and pointer gesture, and the
//! difference between the camera's zoom (a new render of a smaller part of the scene) and the
//! magnifier (the same pixels, enlarged).

use egui::RichText;

/// Title of the overlay (tests find it by this).
pub(crate) const HELP_TITLE: &str = "Shortcuts and gestures";

/// The rows of the overlay: what to press or do, and what it does.
pub(crate) const SHORTCUTS: [(&str, &str); 26] = [
    // The pointer's gestures (the first POINTER_ROWS).
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
    (
        "click",
        "pin the pixel (the pin stays on the point pinned while the view moves)",
    ),
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
    // The keys.
    ("1, Ctrl+0", "magnifier back to the whole image"),
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
    ("F1, ?", "this overlay"),
];

/// How many of [`SHORTCUTS`] are pointer gestures (the first ones); the rest are keys.
const POINTER_ROWS: usize = 9;

/// From this window width the overlay shows the pointer's gestures and the keys side by side,
/// so that it fits a 900-point-high window without scrolling.
const TWO_COLUMNS_FROM_POINTS: f32 = 1000.0;

/// ... and from this window height: the two columns are not scrolled, so a lower window gets the
/// one scrolled column.
const TWO_COLUMNS_FROM_HEIGHT_POINTS: f32 = 560.0;

/// The overlay; returns whether it stays open.
pub(crate) fn help_ui(ctx: &egui::Context) -> bool {
    let mut open = true;
    let screen = ctx.content_rect();
    let two_columns = screen.width() >= TWO_COLUMNS_FROM_POINTS
        && screen.height() >= TWO_COLUMNS_FROM_HEIGHT_POINTS;
    let width = if two_columns {
        (screen.width() - 80.0).min(1100.0)
    } else {
        (screen.width() - 40.0).min(560.0)
    };
    // As wide as `width` and no wider: a window sized by its content grew past the screen's
    // edge, anchored at the centre, and cut off the gestures' names on the left.
    egui::Window::new(HELP_TITLE)
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .min_width(width)
        .max_width(width)
        .max_height(screen.height() - 40.0)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            let (pointer, keys) = SHORTCUTS.split_at(POINTER_ROWS);
            if two_columns {
                ui.columns(2, |columns| {
                    shortcuts_grid(&mut columns[0], "pointer", pointer);
                    shortcuts_grid(&mut columns[1], "keys", keys);
                });
                version_line(ui);
            } else {
                // One column: scrolled where the window is too low for it, the version line
                // with it (below the scrolled rows, it lay over them).
                egui::ScrollArea::vertical().show(ui, |ui| {
                    shortcuts_grid(ui, "pointer", pointer);
                    shortcuts_grid(ui, "keys", keys);
                    version_line(ui);
                });
            }
        });
    let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape));
    open && !escape
}

/// Which build this is, as `raytracer -version` says it (for a bug report).
fn version_line(ui: &mut egui::Ui) {
    ui.separator();
    ui.label(RichText::new(crate::cli::VERSION_LINE).weak());
}

/// One group of the overlay's rows as a striped two-column grid, each row's description wrapped
/// to the width left beside the keys (a grid's labels do not wrap by themselves: a long one ran
/// under the column beside it).
fn shortcuts_grid(ui: &mut egui::Ui, name: &str, rows: &[(&str, &str)]) {
    egui::Grid::new(name)
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            for (keys, what) in rows {
                ui.label(RichText::new(*keys).strong());
                ui.add(egui::Label::new(*what).wrap());
                ui.end_row();
            }
        });
}
