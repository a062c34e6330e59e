//! The toolbar: open, export, undo and redo, reset view, frame all, reload and save view as
//! scene — in narrow windows all but open and export are in a "More" menu, so every button stays
//! on screen — then the controls toggle and the shortcuts overlay. It only reports what was clicked,
//! as [`Action`]s.

use egui::Ui;

use crate::app::actions::Action;
use crate::app::dialogs::DialogKind;

/// Below this width the less used buttons move into a "More" menu.
pub(crate) const MENU_BELOW_POINTS: f32 = 760.0;

/// What the toolbar shows and edits.
pub(crate) struct ToolbarState<'a> {
    /// The controls panel (or drawer) is shown.
    pub(crate) show_controls: &'a mut bool,
    /// Undo has something to go back to.
    pub(crate) can_undo: bool,
    /// Redo has something to go forward to.
    pub(crate) can_redo: bool,
    /// The window is narrow.
    pub(crate) narrow: bool,
}

/// A button: its label, tooltip and action.
type Button = (&'static str, &'static str, Action);

/// The toolbar's buttons. Returns the actions clicked.
pub(crate) fn toolbar_ui(
    ui: &mut Ui,
    ToolbarState {
        show_controls,
        can_undo,
        can_redo,
        narrow,
    }: ToolbarState<'_>,
) -> Vec<Action> {
    let mut actions = Vec::new();
    let always: [Button; 2] = [
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
    ];
    let more: [Button; 3] = [
        (
            "Frame all",
            "Fit centre and size to the whole scene (F)",
            Action::FrameAll,
        ),
        (
            "Reload",
            "Read the scene file again (Ctrl+R); it also reloads by itself when it changes",
            Action::Reload,
        ),
        (
            "Save view as scene…",
            "Write the scene with the current camera to a file",
            Action::OpenDialog(DialogKind::SaveScene),
        ),
    ];
    ui.horizontal_wrapped(|ui| {
        for (label, tooltip, action) in always {
            if ui.button(label).on_hover_text(tooltip).clicked() {
                actions.push(action);
            }
        }
        let history_and_reset = |ui: &mut Ui, actions: &mut Vec<Action>| {
            let undo = ui.add_enabled(can_undo, egui::Button::new("Undo"));
            if undo
                .on_hover_text("Back to the view before (Ctrl+Z)")
                .clicked()
            {
                actions.push(Action::Undo);
            }
            let redo = ui.add_enabled(can_redo, egui::Button::new("Redo"));
            if redo
                .on_hover_text("Forward again (Ctrl+Shift+Z or Ctrl+Y)")
                .clicked()
            {
                actions.push(Action::Redo);
            }
            if ui
                .button("Reset view")
                .on_hover_text("Back to the file's camera; the depth range stays (Home)")
                .clicked()
            {
                actions.push(Action::ResetView);
            }
        };
        if narrow {
            ui.menu_button("More", |ui| {
                history_and_reset(ui, &mut actions);
                for (label, tooltip, action) in more {
                    if ui.button(label).on_hover_text(tooltip).clicked() {
                        actions.push(action);
                    }
                }
                if !actions.is_empty() {
                    ui.close();
                }
            })
            .response
            .on_hover_text("Undo, redo, reset view, frame all, reload, save view as scene");
        } else {
            history_and_reset(ui, &mut actions);
            for (label, tooltip, action) in more {
                if ui.button(label).on_hover_text(tooltip).clicked() {
                    actions.push(action);
                }
            }
        }
        ui.toggle_value(show_controls, "Controls")
            .on_hover_text("Show or hide the controls");
        if ui
            .button("?")
            .on_hover_text("Shortcuts and gestures (F1 or ?)")
            .clicked()
        {
            actions.push(Action::ToggleHelp);
        }
    });
    actions
}
