//! The side panel's named views (bookmarks) of the open scene file: name the current view, go to
//! or forget a named one. They are kept per scene file in the settings.

use egui::Ui;

use crate::app::actions::Action;
use crate::app::saved_views::NamedView;

/// The section; `name` is the field for a new view's name. Returns the actions asked for.
pub(crate) fn views_ui(
    ui: &mut Ui,
    named: &[NamedView],
    name: &mut String,
    has_file: bool,
) -> Vec<Action> {
    let mut actions = Vec::new();
    ui.heading("Named views");
    if !has_file {
        super::hint::hint(ui, "views are kept per scene file: open one to name views");
        return actions;
    }
    ui.horizontal(|ui| {
        let label = ui.label("name");
        let field = ui
            .add(egui::TextEdit::singleline(name).desired_width(140.0))
            .labelled_by(label.id)
            .on_hover_text("a name for the current camera and depth range");
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if (ui.button("Add view").clicked() || entered) && !name.trim().is_empty() {
            actions.push(Action::NameView(name.trim().to_owned()));
            name.clear();
        }
    });
    for (index, view) in named.iter().enumerate() {
        ui.horizontal(|ui| {
            if ui
                .button(format!("Go to {}", view.name))
                .on_hover_text("camera and depth range as named")
                .clicked()
            {
                actions.push(Action::GoToView(index));
            }
            if ui
                .small_button(format!("Forget {}", view.name))
                .on_hover_text("remove this named view")
                .clicked()
            {
                actions.push(Action::ForgetView(index));
            }
        });
    }
    actions
}
