//! The probe under the images: what the pinned and the hovered pixel show, a button to copy it
//! as text and one to release the pin.

use egui::{RichText, Sense, Ui, Vec2};

/// Font size of the probe's lines, in points.
const PROBE_FONT_POINTS: f32 = 11.0;

/// The probe's lines in a block `height` points high. Returns true when "Unpin" was clicked.
pub(crate) fn probe_ui(ui: &mut Ui, lines: &[String], has_pin: bool, height: f32) -> bool {
    let (rect, _) = ui.allocate_exact_size(Vec2::new(ui.available_width(), height), Sense::hover());
    let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect));
    let mut unpin = false;
    // The buttons first, so they stay put while the hover lines come and go.
    child.horizontal(|ui| {
        if has_pin
            && ui
                .small_button("Unpin")
                .on_hover_text("Release the pinned pixel (Escape)")
                .clicked()
        {
            unpin = true;
        }
        if !lines.is_empty()
            && ui
                .small_button("Copy")
                .on_hover_text("Copy the probe's lines as text")
                .clicked()
        {
            ui.ctx().copy_text(lines.join("\n"));
        }
    });
    if lines.is_empty() {
        child.weak("hover an image to probe a pixel; click to pin it");
    }
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(&mut child, |ui| {
            for line in lines {
                ui.add(
                    egui::Label::new(RichText::new(line).monospace().size(PROBE_FONT_POINTS))
                        .truncate(),
                );
            }
        });
    unpin
}
