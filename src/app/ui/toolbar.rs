//! The toolbar: open, export, reload, frame all, reset view, save view as scene, and the
//! controls-panel toggle. It only reports what was clicked, as [`Action`]s.

use egui::Ui;

use crate::app::actions::Action;
use crate::app::dialogs::DialogKind;

/// The toolbar's buttons; `show_controls` is the panel toggle. Returns the actions clicked.
pub(crate) fn toolbar_ui(ui: &mut Ui, show_controls: &mut bool) -> Vec<Action> {
    let mut actions = Vec::new();
    ui.horizontal(|ui| {
        let buttons = [
            (
                "Open…",
                "Open a scene file (Ctrl+O)",
                Action::OpenDialog(DialogKind::Open),
            ),
            (
                "Export…",
                "Export colour and depth images (Ctrl+S)",
                Action::OpenDialog(DialogKind::Export),
            ),
            (
                "Reload",
                "Read the scene file again (Ctrl+R); it also reloads by itself when it changes",
                Action::Reload,
            ),
            (
                "Frame all",
                "Fit centre and size to the whole scene (F)",
                Action::FrameAll,
            ),
            (
                "Reset view",
                "Back to the file's camera (Home)",
                Action::ResetView,
            ),
            (
                "Save view as scene…",
                "Write the scene with the current camera to a file",
                Action::OpenDialog(DialogKind::SaveScene),
            ),
        ];
        for (label, tooltip, action) in buttons {
            if ui.button(label).on_hover_text(tooltip).clicked() {
                actions.push(action);
            }
        }
        ui.toggle_value(show_controls, "Controls").on_hover_text(
            "Drag an image to pan, wheel to zoom, right-drag or Shift-drag to orbit; \
             arrows, Shift+arrows, + and - do the same from the keyboard",
        );
    });
    actions
}
